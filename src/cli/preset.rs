//! `biodyn preset list|show|check|save`.

use super::args::ModelArgs;
use crate::view::report::table::{fx, table};
use anyhow::Result;
use biodyn::Preset;
use biodyn::body::SHIPPED;
use biodyn::io::{FileKind, open_regular};
use clap::Subcommand;
use std::path::{Path, PathBuf};

#[derive(Debug, Subcommand)]
pub enum PresetCommand {
    /// List the built-in presets and the .toml files in ./presets.
    #[command(after_help = "Example:\n  biodyn preset list")]
    List,
    /// Print a preset as TOML (a built-in with its comments, a file as loaded).
    #[command(
        after_help = "Examples:\n  biodyn preset show paper-75kg\n  biodyn preset show my-body.toml"
    )]
    Show {
        /// Preset file or built-in name (default: paper-75kg).
        preset: Option<String>,
    },
    /// Validate a preset file; exit status 0 when it loads.
    #[command(after_help = "Example:\n  biodyn preset check presets/paper-85kg.toml")]
    Check {
        /// Preset file to check.
        file: String,
    },
    /// Save the model (after --preset, --body-mass and --set) as a preset file.
    #[command(after_help = "Example:\n  biodyn preset save stiff.toml --set k4=126000")]
    Save {
        /// Where to write; replaced atomically.
        out: PathBuf,
        #[command(flatten)]
        model: ModelArgs,
        /// Replace a read-only file (its mode is kept).
        #[arg(long)]
        force: bool,
    },
}

pub fn run(cmd: &PresetCommand) -> Result<String> {
    match cmd {
        PresetCommand::List => list(),
        PresetCommand::Show { preset } => {
            let name = preset.as_deref().unwrap_or(biodyn::body::DEFAULT_NAME);
            let builtin = SHIPPED.iter().find(|(n, _)| *n == name);
            match builtin {
                Some((_, text)) if !std::path::Path::new(name).exists() => Ok(text.to_string()),
                _ => Ok(Preset::open(name)?.to_toml()),
            }
        }
        PresetCommand::Check { file } => {
            let p = Preset::open(file)?;
            let b = &p.body;
            Ok(format!(
                "ok: {file}: '{}', {} segments, {} links, seated mass {} kg, band {}–{} Hz step {} Hz\n",
                p.name,
                b.n(),
                b.links.len(),
                fx(b.seated_mass(), 3),
                p.band.from,
                p.band.to,
                p.band.step
            ))
        }
        PresetCommand::Save { out, model, force } => {
            let guard = biodyn::io::Guard::reading(model.input_file(), *force);
            guard.check(out)?;
            let p = model.load()?;
            p.save_guarded(out, &guard)?;
            super::out::status!("saved {} to {}", p.name, out.display());
            Ok(String::new())
        }
    }
}

fn list() -> Result<String> {
    let mut rows = Vec::new();
    for (name, text) in SHIPPED {
        let p = Preset::parse(text, &biodyn::body::Origin::Builtin(name.into()))?;
        rows.push(vec![
            name.to_string(),
            "built-in".into(),
            fx(p.body.seated_mass(), 2),
            first_line(&p.description),
        ]);
    }
    {
        // The files the terminal app's Ctrl-O offers: presets/*.toml and
        // the preset files beside it.
        for f in biodyn::body::listed_presets(Path::new(".")) {
            let shown = f.display().to_string();
            match load_listed(&f) {
                Ok(p) => rows.push(vec![
                    shown,
                    "file".into(),
                    fx(p.body.seated_mass(), 2),
                    first_line(&p.description),
                ]),
                Err(e) => rows.push(vec![
                    shown.clone(),
                    "file".into(),
                    "-".into(),
                    format!("BROKEN: {}", without_path(&e, &shown)),
                ]),
            }
        }
    }
    Ok(table(
        &["preset", "where", "seated kg", "description"],
        &rows,
    ))
}

/// A listed file, loaded only when it is a regular file under the preset
/// cap: a FIFO, a device or a link to /dev/zero is reported, never opened.
fn load_listed(path: &Path) -> Result<Preset> {
    drop(open_regular(path, FileKind::Preset)?);
    Ok(Preset::load(path)?)
}

/// The error's text without the path the row already shows: `path: why`
/// becomes `why`, `path:3:7: why` becomes `line 3:7: why`.
fn without_path(e: &anyhow::Error, path: &str) -> String {
    let text = super::words::one_line(&super::words::chain(e));
    match text.strip_prefix(path) {
        Some(rest) if rest.starts_with(": ") => rest[2..].to_string(),
        Some(rest) if rest.starts_with(':') => format!("line {}", &rest[1..]),
        _ => text,
    }
}

/// A description's first line: a table row is one line.
fn first_line(s: &str) -> String {
    s.lines().next().unwrap_or("").to_string()
}
