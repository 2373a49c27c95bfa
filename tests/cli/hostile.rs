//! What a hostile pass found: two outputs on one file by another path,
//! names that carry terminal escapes, and the like. Each test runs the
//! real binary on the trap.

use super::common::{root, run};

/// `--plot` and `--report` on one file by another spelling (`./`) or
/// through a symlink: refused before the work, and the figure kept.
#[test]
fn plot_and_report_on_one_file_by_another_path_are_refused() {
    let dir = tempfile::tempdir().expect("a temp dir");
    let svg = dir.path().join("s2.svg");
    let dotted = dir.path().join(".").join("s2.svg");
    let link = dir.path().join("link.svg");
    #[cfg(unix)]
    std::os::unix::fs::symlink(&svg, &link).expect("a symlink");
    let day = root().join("examples/day.toml");
    let day = day.to_str().expect("utf-8");
    let signal = [
        "--signal",
        "random:rms=0.8,band=1-20,seed=1",
        "--duration",
        "5",
    ];
    let s = svg.to_str().expect("utf-8");
    for other in [&dotted, &link] {
        let o = other.to_str().expect("utf-8");
        for exists in [false, true] {
            if exists {
                std::fs::write(&svg, "<svg/>").expect("a figure");
            } else {
                let _ = std::fs::remove_file(&svg);
            }
            let mut assess = vec!["assess"];
            assess.extend(signal);
            for args in [
                [&assess[..], &["--plot", s, "--report", o]].concat(),
                vec!["day", day, "--plot", o, "--report", s],
            ] {
                let (code, _, err) = run(&args);
                assert_eq!(code, Some(1), "{args:?}: {err}");
                assert!(err.contains("the same file"), "{args:?}: {err}");
                if exists {
                    assert_eq!(std::fs::read_to_string(&svg).expect("kept"), "<svg/>");
                } else {
                    assert!(!svg.exists(), "{args:?} wrote {s}");
                }
            }
        }
    }
}
