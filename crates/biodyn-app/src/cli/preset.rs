//! `biodyn preset list|show|check|save`.

use super::args::ModelArgs;
use super::out::{emit, fx, table};
use anyhow::{Context, Result};
use biodyn::Preset;
use biodyn::body::preset::SHIPPED;
use clap::Subcommand;
use std::path::PathBuf;

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
    },
}

pub fn run(cmd: &PresetCommand) -> Result<()> {
    match cmd {
        PresetCommand::List => list(),
        PresetCommand::Show { preset } => {
            let name = preset
                .as_deref()
                .unwrap_or(biodyn::body::preset::DEFAULT_NAME);
            let builtin = SHIPPED.iter().find(|(n, _)| *n == name);
            match builtin {
                Some((_, text)) if !std::path::Path::new(name).exists() => emit(text),
                _ => emit(&Preset::open(name)?.to_toml()),
            }
        }
        PresetCommand::Check { file } => {
            let p = Preset::open(file)?;
            let b = &p.body;
            emit(&format!(
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
        PresetCommand::Save { out, model } => {
            let p = model.load()?;
            p.save(out)?;
            eprintln!("saved {} to {}", p.name, out.display());
            Ok(())
        }
    }
}

fn list() -> Result<()> {
    let mut rows = Vec::new();
    for (name, text) in SHIPPED {
        let p = Preset::parse(text, &biodyn::body::preset::Origin::Builtin(name.into()))?;
        rows.push(vec![
            name.to_string(),
            "built-in".into(),
            fx(p.body.seated_mass(), 2),
            p.description.clone(),
        ]);
    }
    if let Ok(dir) = std::fs::read_dir("presets") {
        let mut files: Vec<PathBuf> = dir
            .flatten()
            .map(|e| e.path())
            .filter(|p| p.extension().is_some_and(|e| e == "toml"))
            .collect();
        files.sort();
        for f in files {
            let shown = f.display().to_string();
            match Preset::load(&f).with_context(|| shown.clone()) {
                Ok(p) => rows.push(vec![
                    shown,
                    "file".into(),
                    fx(p.body.seated_mass(), 2),
                    p.description,
                ]),
                Err(e) => rows.push(vec![
                    shown,
                    "file".into(),
                    "-".into(),
                    format!("BROKEN: {e:#}"),
                ]),
            }
        }
    }
    emit(&table(
        &["preset", "where", "seated kg", "description"],
        &rows,
    ))
}
