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

/// The report cannot be written after the figure was (a file-size limit
/// stands in for a full disk: bash's `ulimit -f`, in KiB, with SIGXFSZ
/// ignored so the write fails with EFBIG): the error names the figure as
/// written and the report as not, and no hint says "nothing was written".
#[test]
fn a_failed_report_after_the_figure_says_which_files_were_written() {
    if std::process::Command::new("bash")
        .arg("-c")
        .arg("true")
        .status()
        .is_err()
    {
        return super::common::skip("bash");
    }
    let dir = tempfile::tempdir().expect("a temp dir");
    let (svg, html) = (dir.path().join("a.svg"), dir.path().join("a.html"));
    let (s, h) = (svg.to_str().expect("utf-8"), html.to_str().expect("utf-8"));
    let (code, _, err) = run(&["day", "examples/day.toml", "--plot", s, "--report", h]);
    assert_eq!(code, Some(0), "{err}");
    let kib = |p: &std::path::Path| std::fs::metadata(p).expect("written").len() / 1024;
    let limit = kib(&svg) + 1;
    assert!(limit < kib(&html), "the page is no larger than the figure");
    let (svg, html) = (dir.path().join("b.svg"), dir.path().join("b.html"));
    let out = std::process::Command::new("bash")
        .arg("-c")
        .arg(format!(
            "trap '' XFSZ; ulimit -f {limit}; exec \"$0\" day examples/day.toml --plot {} --report {}",
            svg.display(),
            html.display()
        ))
        .arg(env!("CARGO_BIN_EXE_biodyn"))
        .current_dir(root())
        .output()
        .expect("bash runs");
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(svg.exists() && !html.exists(), "{err}");
    assert!(
        err.contains(&format!(
            "{} was written; {} was not written",
            svg.display(),
            html.display()
        )),
        "{err}"
    );
    assert!(!err.contains("nothing was written"), "{err}");
    assert!(!out.stdout.is_empty(), "the results are printed first");
}

/// A day file and a fit data file whose names clear the screen and set
/// the window title: `day`, `day --week`, `--report`'s note and `fit`
/// print the names escaped (`\u{1b}`), never the raw ESC or BEL.
#[test]
fn names_with_terminal_escapes_are_printed_escaped() {
    let dir = tempfile::tempdir().expect("a temp dir");
    let day = dir.path().join("x\u{1b}[2J\u{1b}]0;owned\u{7}y.toml");
    std::fs::copy(root().join("examples/day.toml"), &day).expect("a day file");
    let data = dir.path().join("f\u{1b}[2Jg.csv");
    std::fs::copy(
        root().join("examples/synthetic-stht-apms-3pct-2deg.csv"),
        &data,
    )
    .expect("a data file");
    let page = dir.path().join("p\u{1b}[2J.html");
    let (d, p) = (day.to_str().expect("utf-8"), page.to_str().expect("utf-8"));
    for args in [
        vec!["day", d, "--report", p],
        vec!["day", d, d, "--week"],
        vec!["fit", "--data", data.to_str().expect("utf-8")],
    ] {
        let (code, out, err) = run(&args);
        assert_eq!(code, Some(0), "{args:?}: {err}");
        for text in [&out, &err] {
            assert!(!text.contains(['\u{1b}', '\u{7}']), "{args:?}: {text:?}");
        }
        assert!(out.contains("\\u{1b}[2J"), "{args:?}: {out}");
    }
}

/// `-q` silences "wrote the report to …" as it silences every other note;
/// without it the note is there.
#[test]
fn quiet_silences_the_report_note() {
    let dir = tempfile::tempdir().expect("a temp dir");
    let page = dir.path().join("r.html");
    let p = page.to_str().expect("utf-8");
    let (code, _, err) = run(&["day", "examples/day.toml", "--report", p]);
    assert_eq!(code, Some(0), "{err}");
    assert!(err.contains("wrote the report to"), "{err}");
    for args in [
        vec!["day", "examples/day.toml", "--report", p, "-q"],
        vec![
            "-q",
            "assess",
            "--signal",
            "random:rms=0.8,band=1-20,seed=1",
            "--duration",
            "5",
            "--report",
            p,
        ],
    ] {
        let (code, _, err) = run(&args);
        assert_eq!(code, Some(0), "{args:?}: {err}");
        assert!(err.is_empty(), "{args:?}: {err}");
    }
}

/// A day file whose name carries ESC and BEL: the HTML report shows them as
/// text (`\u{1b}`) and the figure as U+FFFD (XML forbids them); neither
/// file holds a raw control character.
#[test]
fn names_with_control_characters_never_reach_the_page_raw() {
    let dir = tempfile::tempdir().expect("a temp dir");
    let day = dir.path().join("x\u{1b}]0;owned\u{7}y.toml");
    std::fs::copy(root().join("examples/day.toml"), &day).expect("a day file");
    let (page, svg) = (dir.path().join("r.html"), dir.path().join("f.svg"));
    let (code, _, err) = run(&[
        "day",
        day.to_str().expect("utf-8"),
        "--report",
        page.to_str().expect("utf-8"),
        "--plot",
        svg.to_str().expect("utf-8"),
    ]);
    assert_eq!(code, Some(0), "{err}");
    let html = std::fs::read_to_string(&page).expect("the page");
    let figure = std::fs::read_to_string(&svg).expect("the figure");
    for text in [&html, &figure] {
        let raw = text
            .chars()
            .find(|&c| c.is_control() && !"\n\t\r".contains(c));
        assert_eq!(raw, None, "a raw control character");
    }
    assert!(
        html.contains("x\\u{1b}]0;owned\\u{7}y.toml"),
        "the name as text"
    );
}

/// `--plot x.svg/` (a trailing slash) is refused before the work: no
/// results printed, exit 1.
#[test]
fn an_output_path_with_a_trailing_slash_is_refused_before_the_work() {
    let dir = tempfile::tempdir().expect("a temp dir");
    let bad = format!("{}/x.svg/", dir.path().display());
    for args in [
        vec!["day", "examples/day.toml", "--plot", &bad],
        vec!["day", "examples/day.toml", "--report", &bad],
    ] {
        let (code, out, err) = run(&args);
        assert_eq!(code, Some(1), "{args:?}: {err}");
        assert!(
            out.is_empty(),
            "{args:?}: results printed before the refusal: {out}"
        );
        assert!(err.contains("ends in '/'"), "{args:?}: {err}");
    }
}
