//! The figures docs/figures.md shows are what the commands beside them
//! write today: each is regenerated here and compared byte for byte
//! (`BIODYN_DOCS_BLESS=1` rewrites them after a deliberate change).

use std::path::Path;
use std::process::Command;

/// Where an argument names the figure's file (`assess --plot OUT`): a
/// temp file is put there, and read instead of standard output.
const OUT: &str = "OUT.svg";

/// Each committed figure and the `biodyn` arguments that draw it (run from
/// the workspace root, standard output taken).
pub const FIGURES: [(&str, &[&str]); 6] = [
    (
        "docs/figures/apms-study.svg",
        &[
            "plot",
            "apms",
            "--study",
            "mass=65,75,85",
            "--format",
            "svg",
        ],
    ),
    (
        "docs/figures/stht-data.svg",
        &[
            "plot",
            "stht",
            "--data",
            "examples/synthetic-stht-apms-3pct-2deg.csv",
            "--compare",
            "paper-85kg",
            "--format",
            "svg",
        ],
    ),
    (
        "docs/figures/assess-tractor.svg",
        &[
            "assess",
            "--input",
            "examples/tractor-seat-xyz-g.csv",
            "--format",
            "json",
            "--plot",
            OUT,
        ],
    ),
    (
        "docs/figures/seat-em6.svg",
        &[
            "seat",
            "--preset",
            "paper-75kg-suspension-seat",
            "--class",
            "EM6",
            "--plot",
            OUT,
        ],
    ),
    (
        "docs/figures/seat-design.svg",
        &[
            "seat",
            "--preset",
            "paper-75kg-suspension-seat",
            "--class",
            "EM6",
            "--vary",
            "suspension.k=4000..40000",
            "--vary",
            "suspension.c=200..4000",
            "--stroke-rms-max",
            "0.0012",
            "--plot",
            OUT,
        ],
    ),
    (
        "docs/figures/day.svg",
        &["day", "examples/day.toml", "--plot", OUT],
    ),
];

#[test]
fn the_docs_figures_are_what_the_commands_draw() {
    let root = super::root();
    let bless = std::env::var("BIODYN_DOCS_BLESS").is_ok_and(|v| v == "1");
    let mut stale = Vec::new();
    for (file, args) in FIGURES {
        let svg = draw(root, args);
        let path = root.join(file);
        if bless {
            std::fs::write(&path, &svg).expect("the figure is written");
        } else if std::fs::read_to_string(&path).ok().as_deref() != Some(svg.as_str()) {
            stale.push(file);
        }
    }
    assert!(
        stale.is_empty(),
        "{stale:?} differ from what their commands draw now: look at the change, then BIODYN_DOCS_BLESS=1 cargo test --test docs"
    );
}

/// The figure `args` draw: standard output, or the file put for `OUT`.
fn draw(root: &Path, args: &[&str]) -> String {
    let dir = tempfile::tempdir().expect("a temp dir");
    let out = dir.path().join("f.svg");
    let o = out.to_str().expect("utf-8").to_string();
    let args: Vec<&str> = args
        .iter()
        .map(|a| if *a == OUT { o.as_str() } else { a })
        .collect();
    let run = Command::new(env!("CARGO_BIN_EXE_biodyn"))
        .args(&args)
        .current_dir(root)
        .output()
        .expect("biodyn runs");
    assert!(
        run.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&run.stderr)
    );
    if args.contains(&o.as_str()) {
        std::fs::read_to_string(&out).expect("the figure")
    } else {
        String::from_utf8(run.stdout).expect("UTF-8")
    }
}
