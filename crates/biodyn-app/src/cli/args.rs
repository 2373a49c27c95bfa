//! Arguments shared by every command: which model, which band, which format.

use anyhow::{Context, Result, bail};
use biodyn::{Band, Preset};
use clap::{Args, ValueEnum};

/// Which model to use: a preset, then a body mass, then individual settings.
#[derive(Debug, Clone, Default, Args)]
pub struct ModelArgs {
    /// Preset file, or a built-in name (paper-75kg, paper-65kg, paper-85kg,
    /// boileau-rakheja-1998). Default: the built-in paper-75kg.
    #[arg(long, value_name = "FILE")]
    pub preset: Option<String>,
    /// Total body mass in kg; segment masses become share × body mass.
    #[arg(long, value_name = "KG", allow_negative_numbers = true)]
    pub body_mass: Option<f64>,
    /// Set one parameter, repeatable: m1..mN, k1..kN, c1..cN (top to bottom),
    /// a segment name (its mass) or LINK.k / LINK.c. Example: --set k4=54000
    #[arg(long = "set", value_name = "NAME=VALUE", allow_hyphen_values = true)]
    pub set: Vec<String>,
}

impl ModelArgs {
    /// The preset with --body-mass and every --set applied, in that order.
    pub fn load(&self) -> Result<Preset> {
        let mut preset = match &self.preset {
            Some(p) => Preset::open(p)?,
            None => Preset::builtin_default(),
        };
        if let Some(kg) = self.body_mass {
            preset.body.set_body_mass(kg).context("--body-mass")?;
        }
        for s in &self.set {
            let (name, value) = parse_set(s)?;
            let param = preset
                .body
                .param(name)
                .with_context(|| format!("--set {s}"))?;
            preset
                .body
                .set(param, value)
                .with_context(|| format!("--set {s}"))?;
        }
        Ok(preset)
    }
}

/// Splits NAME=VALUE and parses the value as a finite number.
pub fn parse_set(s: &str) -> Result<(&str, f64)> {
    let Some((name, value)) = s.split_once('=') else {
        bail!("--set {s}: expected NAME=VALUE, e.g. --set k4=54000");
    };
    let name = name.trim();
    if name.is_empty() {
        bail!("--set {s}: the parameter name is empty; e.g. --set m1=5.6");
    }
    let v: f64 = value
        .trim()
        .parse()
        .map_err(|_| anyhow::anyhow!("--set {s}: '{}' is not a number", value.trim()))?;
    if !v.is_finite() {
        bail!("--set {s}: the value must be a finite number");
    }
    Ok((name, v))
}

/// Frequency band options; unset ones fall back to the preset's band.
#[derive(Debug, Clone, Default, Args)]
pub struct BandArgs {
    /// Lowest frequency, Hz.
    #[arg(long, value_name = "HZ", allow_negative_numbers = true)]
    pub from: Option<f64>,
    /// Highest frequency, Hz (included when it falls on the grid).
    #[arg(long, value_name = "HZ", allow_negative_numbers = true)]
    pub to: Option<f64>,
    /// Grid step, Hz.
    #[arg(long, value_name = "HZ", allow_negative_numbers = true)]
    pub step: Option<f64>,
}

impl BandArgs {
    pub fn band(&self, preset_band: Band) -> Result<Band> {
        let b = Band::new(
            self.from.unwrap_or(preset_band.from),
            self.to.unwrap_or(preset_band.to),
            self.step.unwrap_or(preset_band.step),
        )?;
        Ok(b)
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum, Default)]
pub enum Format {
    /// Aligned columns, rounded for reading.
    #[default]
    Table,
    /// Comma-separated, every number in shortest round-trip form.
    Csv,
    /// JSON, every number in shortest round-trip form.
    Json,
}

/// Table or JSON only (commands whose output is not a grid).
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum, Default)]
pub enum TableOrJson {
    #[default]
    Table,
    Json,
}
