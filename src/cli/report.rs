//! `--report FILE.html` of `assess` and `day`: the page a hygienist hands
//! over, written beside the usual output (the table or JSON still prints).
//!
//! The file goes through the save guard every save uses, checked before
//! the work (not a folder or a FIFO, not one of the command's own inputs by
//! any path to it, a folder that takes a new file, a read-only file only
//! with `--force`), and is written atomically after it. If the write fails
//! after all, the results are printed first and the error follows, so the
//! work is not lost.
//!
//! `--meta FILE.toml` (who, where, when, with what) is an input of the
//! command: the report, the figure and any save may not land on it.
//! `--no-model` leaves the body model's part out of the page.

use anyhow::Result;
use biodyn::exposure::{DayError, META_KEYS, Meta, MetaError};
use biodyn::io::Guard;
use clap::Args;
use std::path::{Path, PathBuf};

#[derive(Debug, Clone, Args)]
pub struct ReportArgs {
    /// Also write a printable HTML page of the result (self-contained: no
    /// scripts, nothing fetched; prints on A4); the output still prints.
    #[arg(long, value_name = "FILE.html")]
    pub report: Option<PathBuf>,
    /// Replace a read-only --report file (its mode is kept).
    #[arg(long, requires = "report")]
    pub force: bool,
    /// Who, where, when, with what: a TOML file of site, worker, machine,
    /// task, date, instrument, calibrated (its last calibration), assessor
    /// and notes, all optional; shown at the top of the table, the report
    /// and in the JSON's "meta".
    #[arg(long, value_name = "FILE.toml")]
    pub meta: Option<PathBuf>,
    /// Leave the body model's part (the head, the segments, the model's
    /// predicted values) out of the --report page.
    #[arg(long, requires = "report")]
    pub no_model: bool,
}

/// A file (the report, a figure) that passed the guard's checks, to be
/// written after the work.
pub struct Pending {
    path: PathBuf,
    guard: Guard,
    /// The note said once it is written ("wrote the report to …"); a
    /// figure is written silently, as `plot --output` writes one.
    note: Option<&'static str>,
}

impl ReportArgs {
    /// The command's `inputs` and the `--meta` file: what no output may
    /// replace.
    pub fn inputs<P: AsRef<Path>>(&self, inputs: impl IntoIterator<Item = P>) -> Vec<PathBuf> {
        inputs
            .into_iter()
            .map(|p| p.as_ref().to_path_buf())
            .chain(self.meta.clone())
            .collect()
    }

    /// The `--meta` file's details (empty without it), read now so a bad
    /// file is refused before the work.
    pub fn meta(&self) -> Result<Meta> {
        Ok(match &self.meta {
            Some(p) => Meta::load(p)?,
            None => Meta::default(),
        })
    }

    /// Checks the report file against the command's `inputs` (and the
    /// `--meta` file) now, before the work; `None` without `--report`.
    pub fn check<P: AsRef<Path>>(
        &self,
        inputs: impl IntoIterator<Item = P>,
    ) -> Result<Option<Pending>> {
        let Some(path) = &self.report else {
            return Ok(None);
        };
        let guard = Guard::reading(self.inputs(inputs), self.force);
        guard.check(path)?;
        Ok(Some(Pending {
            path: path.clone(),
            guard,
            note: Some("wrote the report to"),
        }))
    }
}

impl Pending {
    /// A file checked by `guard`, written later without a note.
    pub fn silent(path: PathBuf, guard: Guard) -> Pending {
        Pending {
            path,
            guard,
            note: None,
        }
    }

    /// Writes `contents`; on failure prints `printed` (the command's
    /// output) first, then fails naming the file. The path written is
    /// returned.
    pub fn write(self, contents: &str, printed: &str) -> Result<PathBuf> {
        self.write_after(contents, printed, &[])
    }

    /// [`Pending::write`] after the command wrote `written` (the figure
    /// before the report): a failure says exactly which files were
    /// written and which was not, never "nothing was written" after a
    /// figure was replaced.
    pub fn write_after(
        self,
        contents: &str,
        printed: &str,
        written: &[PathBuf],
    ) -> Result<PathBuf> {
        if let Err(e) = biodyn::io::save_guarded(&self.path, &self.guard, contents.as_bytes()) {
            super::emit(printed)?;
            let done = if written.is_empty() {
                String::new()
            } else {
                let names: Vec<String> = written.iter().map(|p| p.display().to_string()).collect();
                format!(", {} was written", names.join(" and "))
            };
            return Err(anyhow::Error::new(e).context(format!(
                "the results are printed above{done}; {} was not written",
                self.path.display()
            )));
        }
        if let Some(said) = self.note {
            super::out::status!("{said} {}", self.path.display());
        }
        Ok(self.path)
    }
}

/// What to try after the report's details (`--meta`, a day file's
/// `[report]`) are refused.
pub fn hint(cause: &(dyn std::error::Error + 'static)) -> Option<String> {
    let meta = cause.downcast_ref::<MetaError>().is_some()
        || matches!(cause.downcast_ref::<DayError>(), Some(DayError::Report(_)));
    meta.then(|| {
        format!(
            "the keys are {}, all optional, each a text in quotes on one line (notes may have several), e.g. site = \"North quarry\"; see docs/cli-simulate-assess.md",
            META_KEYS.join(", ")
        )
    })
}
