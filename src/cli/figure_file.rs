//! `--plot FILE.svg` of `assess`, `seat` and `day`: the command's figure,
//! written beside its usual output. The name must end in `.svg` (the one
//! format written: no PNG without a font to embed), and the file passes
//! the save guard before the work, as `--report` does: not a folder or a
//! FIFO, not one of the command's inputs, not the report's own file.

use super::refused::Refused;
use super::report::Pending;
use anyhow::Result;
use biodyn::io::Guard;
use std::path::{Path, PathBuf};

/// Checks `plot` against the command's `inputs` and its `--report` file
/// now; `None` without `--plot`. `example` names a file for the hint.
pub fn check<P: AsRef<Path>>(
    plot: Option<&PathBuf>,
    inputs: impl IntoIterator<Item = P>,
    report: Option<&PathBuf>,
    example: &str,
) -> Result<Option<Pending>> {
    let Some(path) = plot else {
        return Ok(None);
    };
    let svg = path
        .extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("svg"));
    if !svg {
        return Err(Refused::error(
            format!(
                "--plot {}: the figure is SVG, and the name does not end in .svg",
                path.display()
            ),
            format!("name it e.g. {example} (`rsvg-convert {example} -o figure.png` makes a PNG)"),
        ));
    }
    if report.is_some_and(|r| biodyn::io::same_target(r, path)) {
        anyhow::bail!(
            "--plot and --report name the same file {}: give each its own",
            path.display()
        );
    }
    let guard = Guard::reading(inputs, false);
    guard.check(path)?;
    Ok(Some(Pending::silent(path.clone(), guard)))
}
