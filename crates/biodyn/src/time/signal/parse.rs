//! The signal grammar read from text: `KIND:KEY=VALUE,...` parts joined by
//! `+` (the parent module's docs list the kinds and keys).

use super::{Component, MIN_BAND_HZ, Signal, SignalError};
use crate::io::excerpt::num;
use crate::time::limits::MAX_ACC;

impl Signal {
    /// Parses the signal grammar (module docs). Values are checked for
    /// sign and finiteness here; against a rate and duration by [`Signal::check`].
    pub fn parse(spec: &str) -> Result<Signal, SignalError> {
        let spec = spec.trim();
        if spec.is_empty() {
            return Err(SignalError::Empty);
        }
        let parts = split_parts(spec)
            .into_iter()
            .map(parse_part)
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Signal { parts })
    }
}

fn keys_of(kind: &str) -> (&'static str, &'static [&'static str], &'static str) {
    match kind {
        "sine" => (
            "sine",
            &["freq", "amp", "phase"],
            "freq=HZ,amp=M_S2[,phase=DEG]",
        ),
        "sweep" => ("sweep", &["from", "to", "amp"], "from=HZ,to=HZ,amp=M_S2"),
        "random" => (
            "random",
            &["rms", "band", "seed"],
            "rms=M_S2,band=LO-HI,seed=N",
        ),
        _ => ("shock", &["peak", "width", "at"], "peak=M_S2,width=S,at=S"),
    }
}

/// Splits on `+` that starts a new part (followed by a letter), so that
/// `amp=1e+3` stays whole.
fn split_parts(spec: &str) -> Vec<&str> {
    let mut parts = Vec::new();
    let mut start = 0;
    let b = spec.as_bytes();
    for i in 0..b.len() {
        if b[i] == b'+' && b.get(i + 1).is_some_and(|c| c.is_ascii_alphabetic()) {
            parts.push(&spec[start..i]);
            start = i + 1;
        }
    }
    parts.push(&spec[start..]);
    parts
}

fn parse_part(part: &str) -> Result<Component, SignalError> {
    let p = part.trim();
    let owned = || p.to_string();
    let Some((kind, rest)) = p.split_once(':') else {
        return Err(SignalError::NoKind { part: owned() });
    };
    let kind = kind.trim().to_ascii_lowercase();
    if kind == "class" {
        return parse_class(p, rest);
    }
    if !matches!(kind.as_str(), "sine" | "sweep" | "random" | "shock") {
        return Err(SignalError::UnknownKind {
            part: owned(),
            kind,
        });
    }
    let (kname, allowed, usage) = keys_of(&kind);
    let mut vals: Vec<(&'static str, &str)> = Vec::new();
    for item in rest.split(',') {
        let item = item.trim();
        let Some((k, v)) = item.split_once('=') else {
            return Err(SignalError::NotKeyValue {
                part: owned(),
                item: item.to_string(),
            });
        };
        let k = k.trim();
        let Some(&key) = allowed.iter().find(|a| **a == k) else {
            return Err(SignalError::UnknownKey {
                part: owned(),
                kind: kname,
                key: k.to_string(),
                keys: usage,
            });
        };
        if vals.iter().any(|(x, _)| *x == key) {
            return Err(SignalError::Duplicate {
                part: owned(),
                key: key.to_string(),
            });
        }
        vals.push((key, v.trim()));
    }
    let raw = |key: &'static str| -> Result<&str, SignalError> {
        vals.iter()
            .find(|(k, _)| *k == key)
            .map(|(_, v)| *v)
            .ok_or(SignalError::Missing {
                part: owned(),
                kind: kname,
                key,
                keys: usage,
            })
    };
    let number = |key: &'static str, v: &str| -> Result<f64, SignalError> {
        match v.parse::<f64>() {
            Ok(x) if x.is_finite() => Ok(x),
            _ => Err(SignalError::NotNumber {
                part: owned(),
                key: key.to_string(),
                value: v.to_string(),
            }),
        }
    };
    let positive = |key: &'static str, unit: &str| -> Result<f64, SignalError> {
        let v = raw(key)?;
        let x = number(key, v)?;
        if x > 0.0 {
            Ok(x)
        } else {
            Err(SignalError::Bad {
                part: owned(),
                key,
                value: v.to_string(),
                why: format!("{unit}: it must be > 0"),
            })
        }
    };
    // An acceleration above MAX_ACC is a unit slip, and would overflow the sum.
    let capped = |key: &'static str, x: f64| -> Result<f64, SignalError> {
        if x.abs() <= MAX_ACC {
            Ok(x)
        } else {
            Err(SignalError::Bad {
                part: owned(),
                key,
                value: num(x),
                why: format!(
                    "m/s² is over the {} m/s² cap (≈ 1000 g, beyond any seat vibration or shock): check the unit",
                    num(MAX_ACC)
                ),
            })
        }
    };
    let accel = |key: &'static str| positive(key, "m/s²").and_then(|x| capped(key, x));
    // A frequency below the models' band floor (0.001 Hz, a period of
    // 17 min) is no seat vibration; 5e-324 Hz made a sweep's samples NaN.
    let freq = |key: &'static str| {
        positive(key, "Hz").and_then(|x| {
            if x >= crate::band::MIN_HZ {
                Ok(x)
            } else {
                Err(SignalError::Bad {
                    part: owned(),
                    key,
                    value: num(x),
                    why: format!(
                        "Hz is below {} Hz, the lowest frequency a model is computed at",
                        crate::band::MIN_HZ
                    ),
                })
            }
        })
    };
    Ok(match kind.as_str() {
        "sine" => Component::Sine {
            freq: freq("freq")?,
            amp: accel("amp")?,
            phase_deg: match vals.iter().find(|(k, _)| *k == "phase") {
                Some((_, v)) => number("phase", v)?,
                None => 0.0,
            },
        },
        "sweep" => Component::Sweep {
            from: freq("from")?,
            to: freq("to")?,
            amp: accel("amp")?,
        },
        "random" => {
            let rms = accel("rms")?;
            let band = raw("band")?;
            let (lo, hi) = parse_band(band).ok_or_else(|| SignalError::Bad {
                part: owned(),
                key: "band",
                value: band.to_string(),
                why: "is not LO-HI in Hz, e.g. band=1-20".into(),
            })?;
            if !(lo > 0.0 && hi > lo) {
                return Err(SignalError::Bad {
                    part: owned(),
                    key: "band",
                    value: band.to_string(),
                    why: "Hz: it needs 0 < LO < HI, e.g. band=1-20".into(),
                });
            }
            if lo < MIN_BAND_HZ {
                return Err(SignalError::Bad {
                    part: owned(),
                    key: "band",
                    value: num(lo) + "-" + &num(hi),
                    why: format!(
                        "Hz: LO must be at least {} Hz (a 1000 s period; the band filter cannot represent lower edges), e.g. band=0.5-80",
                        num(MIN_BAND_HZ)
                    ),
                });
            }
            let seed = seed(p, raw("seed")?)?;
            Component::Random { rms, lo, hi, seed }
        }
        _ => {
            let peak_text = raw("peak")?;
            let peak = capped("peak", number("peak", peak_text)?)?;
            if peak == 0.0 {
                return Err(SignalError::Bad {
                    part: owned(),
                    key: "peak",
                    value: peak_text.to_string(),
                    why: "m/s²: a shock needs a non-zero peak".into(),
                });
            }
            let width = positive("width", "s")?;
            let at_text = raw("at")?;
            let at = number("at", at_text)?;
            if at < 0.0 {
                return Err(SignalError::Bad {
                    part: owned(),
                    key: "at",
                    value: at_text.to_string(),
                    why: "s: the start time must be ≥ 0".into(),
                });
            }
            Component::Shock { peak, width, at }
        }
    })
}

/// `LO-HI`, where a minus sign may start LO or follow an exponent's `e`.
fn parse_band(s: &str) -> Option<(f64, f64)> {
    let b = s.as_bytes();
    let cut = (1..b.len()).find(|&i| b[i] == b'-' && !matches!(b[i - 1], b'e' | b'E'))?;
    let lo = s[..cut].trim().parse::<f64>().ok()?;
    let hi = s[cut + 1..].trim().parse::<f64>().ok()?;
    (lo.is_finite() && hi.is_finite()).then_some((lo, hi))
}

/// `class:NAME,seed=N`: an input spectral class by name (`time::class`).
fn parse_class(part: &str, rest: &str) -> Result<Component, SignalError> {
    let owned = || part.to_string();
    const USAGE: &str = "NAME,seed=N (or name=NAME,seed=N) with NAME an input spectral class";
    let mut items = rest.split(',').map(str::trim);
    // The class first, bare (`class:EM6,seed=1`) or as a key (`name=EM6`).
    let first = items.next().unwrap_or_default();
    let name = match first.split_once('=') {
        Some((k, v)) if k.trim() == "name" => v.trim(),
        Some(_) => {
            return Err(SignalError::Missing {
                part: owned(),
                kind: "class",
                key: "name",
                keys: USAGE,
            });
        }
        None => first,
    };
    let class = crate::time::class::InputClass::parse(name).ok_or_else(|| SignalError::Bad {
        part: owned(),
        key: "class",
        value: name.to_string(),
        why: format!(
            "is not an input spectral class; the classes are {}",
            crate::time::class::InputClass::names()
        ),
    })?;
    let mut given = None;
    for item in items {
        let Some((k, v)) = item.split_once('=') else {
            return Err(SignalError::NotKeyValue {
                part: owned(),
                item: item.to_string(),
            });
        };
        if k.trim() == "name" {
            return Err(SignalError::Duplicate {
                part: owned(),
                key: "name".into(),
            });
        }
        if k.trim() != "seed" {
            return Err(SignalError::UnknownKey {
                part: owned(),
                kind: "class",
                key: k.trim().to_string(),
                keys: USAGE,
            });
        }
        if given.is_some() {
            return Err(SignalError::Duplicate {
                part: owned(),
                key: "seed".into(),
            });
        }
        given = Some(seed(part, v.trim())?);
    }
    let seed = given.ok_or(SignalError::Missing {
        part: owned(),
        kind: "class",
        key: "seed",
        keys: USAGE,
    })?;
    Ok(Component::Class { class, seed })
}

/// A noise seed: a whole number in 0..2^64.
fn seed(part: &str, text: &str) -> Result<u64, SignalError> {
    text.parse::<u64>().map_err(|_| SignalError::Bad {
        part: part.to_string(),
        key: "seed",
        value: text.to_string(),
        why: "is not a whole number in 0..2^64".into(),
    })
}
