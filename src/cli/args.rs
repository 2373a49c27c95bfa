//! Argument groups shared by every command: which model (`--preset
//! --body-mass --set`), which band (`--from --to --step`), which format.

use anyhow::{Context, Result, bail};
use biodyn::{Band, Function, Param, Preset};
use clap::Args;

pub use crate::view::report::Format;

/// A whole number ≥ 0 (a seed, a count): a negative or fractional one is
/// told the range, not "invalid digit".
pub fn whole(text: &str) -> Result<u64, String> {
    text.trim().parse::<u64>().map_err(|_| {
        format!(
            "'{}' is not a whole number from 0 to {}",
            quote(text),
            u64::MAX
        )
    })
}

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
    /// The preset file this model is read from, if it is a file (not a
    /// built-in name): an input a save must not replace.
    pub fn input_file(&self) -> Option<std::path::PathBuf> {
        self.preset
            .as_deref()
            .map(std::path::Path::new)
            .filter(|p| p.exists())
            .map(std::path::Path::to_path_buf)
    }

    /// The preset with --body-mass and every --set applied, in that order.
    pub fn load(&self) -> Result<Preset> {
        Ok(self.load_with(&mut |_, _| {})?.0)
    }

    /// As `load`, calling `seen` with each parameter --set changes; also
    /// returns those parameters.
    pub fn load_with(&self, seen: &mut dyn FnMut(&Preset, Param)) -> Result<(Preset, Vec<Param>)> {
        let mut preset = match &self.preset {
            Some(p) => Preset::open(p)?,
            None => Preset::builtin_default(),
        };
        self.refuse_twice(&preset.body)?;
        if let Some(kg) = self.body_mass {
            preset.body.set_body_mass(kg).context("--body-mass")?;
        }
        let mut params = Vec::with_capacity(self.set.len());
        for s in &self.set {
            let (name, value) = parse_set(s)?;
            let s = quote(s);
            let param = preset
                .body
                .param(name)
                .with_context(|| format!("--set {s}"))?;
            preset
                .body
                .set(param, value)
                .with_context(|| format!("--set {s}"))?;
            seen(&preset, param);
            params.push(param);
        }
        Ok((preset, params))
    }
}

impl ModelArgs {
    /// Refuses two values for one parameter of `body`: the same parameter
    /// --set twice (by any of its names: `k4`, `pelvis-seat.k`), or the body
    /// mass by --set and by --body-mass. Which one wins would be a rule of
    /// order the reader cannot see; both values are named.
    pub fn refuse_twice(&self, body: &biodyn::Body) -> Result<()> {
        let mut seen: Vec<(Param, String)> = Vec::with_capacity(self.set.len() + 1);
        if let Some(kg) = self.body_mass {
            seen.push((
                Param::BodyMass,
                format!("--body-mass {}", biodyn::io::num(kg)),
            ));
        }
        for s in &self.set {
            let (name, _) = parse_set(s)?;
            // An unknown name is refused where it is applied, with its hint.
            let Ok(param) = body.param(name) else {
                continue;
            };
            let this = format!("--set {}", quote(s));
            if let Some((_, first)) = seen.iter().find(|(p, _)| *p == param) {
                return Err(super::refused::Refused::error(
                    format!(
                        "{} is given twice, {first} and {this}: which to use is ambiguous",
                        body.label(param)
                    ),
                    "give each parameter once (--body-mass or --set body_mass=KG, not both)",
                ));
            }
            seen.push((param, this));
        }
        Ok(())
    }
}

/// Splits NAME=VALUE and parses the value as a finite number.
pub fn parse_set(arg: &str) -> Result<(&str, f64)> {
    let s = quote(arg);
    let Some((name, value)) = arg.split_once('=') else {
        bail!("--set {s}: expected NAME=VALUE, e.g. --set k4=54000");
    };
    let name = name.trim();
    if name.is_empty() {
        bail!("--set {s}: the parameter name is empty; e.g. --set m1=5.6");
    }
    let v: f64 = value
        .trim()
        .parse()
        .map_err(|_| anyhow::anyhow!("--set {s}: '{}' is not a number", quote(value.trim())))?;
    if !v.is_finite() {
        bail!("--set {s}: the value must be a finite number");
    }
    Ok((name, v))
}

/// User text as an error quotes it: at most a short excerpt.
pub fn quote(s: &str) -> String {
    biodyn::io::short_quote(s)
}

/// Frequency band options; unset ones fall back to the command's default
/// band (the preset's, or the networks' training grid).
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
    pub fn band(&self, default: Band) -> Result<Band> {
        let b = Band::new(
            self.from.unwrap_or(default.from),
            self.to.unwrap_or(default.to),
            self.step.unwrap_or(default.step),
        )?;
        Ok(b)
    }

    pub fn is_set(&self) -> bool {
        self.from.is_some() || self.to.is_some() || self.step.is_some()
    }
}

/// `--format` for commands whose result is not a grid: table or json only
/// (csv is refused by clap and not listed).
pub fn table_or_json() -> impl clap::builder::TypedValueParser<Value = Format> {
    use clap::builder::TypedValueParser;
    clap::builder::PossibleValuesParser::new(["table", "json"]).map(|s| {
        if s == "json" {
            Format::Json
        } else {
            Format::Table
        }
    })
}

/// A response function on the command line: its values come from
/// `Function::EVERY`, so `--help` lists every function there is (a seat's
/// two are refused by the command on a model without a seat).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FunctionArg(pub Function);

impl clap::ValueEnum for FunctionArg {
    fn value_variants<'a>() -> &'a [Self] {
        const ALL: [FunctionArg; Function::EVERY.len()] = {
            let mut out = [FunctionArg(Function::EVERY[0]); Function::EVERY.len()];
            let mut i = 0;
            while i < out.len() {
                out[i] = FunctionArg(Function::EVERY[i]);
                i += 1;
            }
            out
        };
        &ALL
    }

    fn to_possible_value(&self) -> Option<clap::builder::PossibleValue> {
        Some(clap::builder::PossibleValue::new(self.0.key()))
    }
}
