//! Chart axes whose ticks sit where their values are.
//!
//! ratatui's `Axis::labels` spreads labels evenly whatever they say, so a
//! label "15" could sit where 13.7 Hz is drawn. Here ticks are round numbers
//! (1, 2, 5 × 10ⁿ; on a log axis 0.5, 1, 2, 5, 10, 20, …) and each is placed
//! in the cell its value maps to, by the same rule ratatui's Canvas uses for
//! the data points (`Mapping::cell`).

/// How values on one axis map to terminal cells: ratatui's Canvas rule
/// (`Painter::get_point`) for a grid of `sub` dots per cell (braille: 2
/// across, 4 down; one-glyph markers: 1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Mapping {
    pub lo: f64,
    pub hi: f64,
    /// Cells along the axis (columns, or rows).
    pub cells: u16,
    /// Dots per cell of the reference grid.
    pub sub: u16,
    /// Rows count down from the top: `hi` is cell 0.
    pub flip: bool,
}

impl Mapping {
    /// Position of `v` from 0 (cell 0's edge) to 1 (the last cell's edge).
    pub fn norm(&self, v: f64) -> f64 {
        let t = (v - self.lo) / (self.hi - self.lo);
        if self.flip { 1.0 - t } else { t }
    }

    /// The cell `v` lands in, None outside the axis.
    pub fn cell(&self, v: f64) -> Option<u16> {
        // A tick computed as log10(m × 10ⁿ) may miss its bound by an ulp.
        let t = self.norm(v);
        if !(-EDGE..=1.0 + EDGE).contains(&t) || self.cells == 0 {
            return None;
        }
        let t = t.clamp(0.0, 1.0);
        let res = f64::from(self.cells) * f64::from(self.sub.max(1));
        let dot = (t * (res - 1.0)).round() as u32;
        Some((dot / u32::from(self.sub.max(1))) as u16)
    }

    /// The position on a grid of `k` dots per cell that lands in the same
    /// cell as position `t` does on this one: markers of every resolution
    /// then agree with the ticks to the column.
    pub fn renorm(&self, t: f64, k: u16) -> f64 {
        let (n, kr, kk) = (
            f64::from(self.cells),
            f64::from(self.sub.max(1)),
            f64::from(k.max(1)),
        );
        if k.max(1) == self.sub.max(1) || kk * n - 1.0 <= 0.0 || kr * n - 1.0 <= 0.0 {
            return if (-EDGE..=1.0 + EDGE).contains(&t) {
                t.clamp(0.0, 1.0)
            } else {
                t
            };
        }
        // Cell coordinate: cell c spans [c, c + 1).
        let c = (t * (kr * n - 1.0) + 0.5) / kr;
        let tk = (kk * c - 0.5) / (kk * n - 1.0);
        if (-EDGE..=1.0 + EDGE).contains(&t) {
            tk.clamp(0.0, 1.0)
        } else {
            tk
        }
    }
}

/// How far past an end (as a share of the axis) a value still counts as
/// on it: rounding slack, far below a dot.
const EDGE: f64 = 1e-9;

/// One tick: its value in axis units (log10 of the value on a log axis) and
/// its label in data units.
#[derive(Debug, Clone, PartialEq)]
pub struct Tick {
    pub at: f64,
    pub label: String,
}

/// An axis's bounds (axis units) and ticks.
#[derive(Debug, Clone, PartialEq)]
pub struct Plan {
    pub lo: f64,
    pub hi: f64,
    pub ticks: Vec<Tick>,
}

/// How an axis is scaled.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Scale {
    /// Bounds rounded out to the tick step after padding by `pad` of the
    /// span; `floor_zero` starts the axis at 0 (a magnitude is never
    /// negative, so its axis does not go below 0 either).
    Linear { pad: f64, floor_zero: bool },
    /// Data in log10 units; bounds rounded out to 1, 2, 5 × 10ⁿ.
    Log,
    /// Bounds as given (axis units), ticks inside them.
    Fixed { log: bool },
}

/// Checks whether a candidate plan's labels fit: (lo, hi, ticks).
pub type Fits<'a> = &'a dyn Fn(f64, f64, &[Tick]) -> bool;

/// Bounds and ticks for data over [lo, hi] (axis units): the densest round
/// tick set whose labels `fits` accepts; with none, the bounds of the
/// coarsest set and as many end labels as fit.
pub fn plan(lo: f64, hi: f64, scale: Scale, fits: Fits) -> Plan {
    let (lo, hi) = if lo.is_finite() && hi.is_finite() && lo <= hi {
        (lo, hi)
    } else {
        (0.0, 1.0)
    };
    match scale {
        Scale::Linear { pad, floor_zero } => {
            let floor = floor_zero && lo >= 0.0;
            let (mut a, mut b) = (if floor { 0.0 } else { lo }, hi);
            if b <= a {
                let d = if a == 0.0 { 1.0 } else { a.abs() * 0.1 };
                if !floor {
                    a -= d;
                }
                b += d;
            }
            let p = pad * (b - a);
            b += p;
            if !floor {
                a -= p;
            }
            linear(a, b, false, fits)
        }
        Scale::Fixed { log: false } => {
            let b = if hi > lo { hi } else { lo + 1.0 };
            linear(lo, b, true, fits)
        }
        Scale::Log => {
            let (a, b) = if hi > lo {
                (floor125(lo), ceil125(hi))
            } else {
                (floor125(lo - 1e-9), ceil125(hi + 1e-9))
            };
            log(a, b, fits)
        }
        Scale::Fixed { log: true } => {
            let b = if hi > lo { hi } else { lo + 1.0 };
            log(lo, b, fits)
        }
    }
}

/// Linear ticks at multiples of 1, 2 or 5 × 10ⁿ; bounds rounded out to the
/// step unless `fixed`.
fn linear(a: f64, b: f64, fixed: bool, fits: Fits) -> Plan {
    let bounds = |step: f64| {
        if fixed {
            (a, b)
        } else {
            (
                (a / step).floor() * step + 0.0,
                (b / step).ceil() * step + 0.0,
            )
        }
    };
    let ticks = |lo: f64, hi: f64, step: f64| -> Option<Vec<Tick>> {
        let (k0, k1) = ((lo / step - 1e-9).ceil(), (hi / step + 1e-9).floor());
        (k1 - k0 <= 200.0 && hi > lo).then(|| {
            (k0 as i64..=k1 as i64)
                .map(|k| {
                    let v = k as f64 * step + 0.0;
                    Tick {
                        at: v,
                        label: tick_text(v, step),
                    }
                })
                .collect()
        })
    };
    // Three ticks or more, densest first. Each round at least doubles the
    // step, so the loop ends well within 64 rounds for any f64 span.
    // No axis here holds more than 40 labels (200 columns at 10 apart).
    let mut step = nice_step((b - a) / 40.0);
    for _ in 0..64 {
        if !(step.is_finite() && step > 0.0) {
            break;
        }
        let (lo, hi) = bounds(step);
        match ticks(lo, hi, step) {
            Some(t) if t.len() < 3 => break,
            Some(t) if fits(lo, hi, &t) => return Plan { lo, hi, ticks: t },
            _ => {}
        }
        step = nice_step(step * 1.5);
    }
    // Too short for three: tight bounds, labelled at the ends.
    let step = nice_step((b - a) / 10.0);
    let (lo, hi) = bounds(step);
    let t = ticks(lo, hi, step).unwrap_or_default();
    ends_only(Plan { lo, hi, ticks: t }, fits)
}

/// Log ticks (axis in log10 units): 1-2-5 per decade, thinner when crowded;
/// under a decade with fewer than three of those, linear round steps.
fn log(a: f64, b: f64, fits: Fits) -> Plan {
    let set = |mantissas: &[f64], every: i64| -> Vec<Tick> {
        let mut out = Vec::new();
        let (e0, e1) = (a.floor() as i64 - 1, b.ceil() as i64 + 1);
        if e1 - e0 > 1000 {
            return out;
        }
        for e in e0..=e1 {
            if e.rem_euclid(every) != 0 {
                continue;
            }
            for &m in mantissas {
                let v = m * 10f64.powi(e as i32);
                let at = v.log10();
                if at >= a - 1e-9 && at <= b + 1e-9 {
                    out.push(Tick {
                        at,
                        label: super::format::num(v, 3),
                    });
                }
            }
        }
        out
    };
    let full = set(&[1.0, 2.0, 5.0], 1);
    if full.len() < 3 {
        // Under a decade: round linear steps placed at their log positions.
        let (va, vb) = (10f64.powf(a), 10f64.powf(b));
        let mut step = nice_step((vb - va) / 40.0);
        for _ in 0..12 {
            let (k0, k1) = ((va / step - 1e-9).ceil(), (vb / step + 1e-9).floor());
            let ticks: Vec<Tick> = (k0 as i64..=k1 as i64)
                .map(|k| k as f64 * step)
                .filter(|v| *v > 0.0)
                .map(|v| Tick {
                    at: v.log10(),
                    label: tick_text(v, step),
                })
                .collect();
            if ticks.len() >= 3 && fits(a, b, &ticks) {
                return Plan {
                    lo: a,
                    hi: b,
                    ticks,
                };
            }
            step = nice_step(step * 1.5);
        }
    }
    let mut sets = vec![full, set(&[1.0, 5.0], 1), set(&[1.0], 1)];
    for every in [2, 3, 5, 10, 20, 50, 100] {
        sets.push(set(&[1.0], every));
    }
    for ticks in sets {
        if ticks.len() >= 2 && fits(a, b, &ticks) {
            return Plan {
                lo: a,
                hi: b,
                ticks,
            };
        }
    }
    ends_only(
        Plan {
            lo: a,
            hi: b,
            ticks: vec![
                Tick {
                    at: a,
                    label: super::format::num(10f64.powf(a), 3),
                },
                Tick {
                    at: b,
                    label: super::format::num(10f64.powf(b), 3),
                },
            ],
        },
        fits,
    )
}

/// The plan with only its end ticks, or one, or none: whatever fits.
fn ends_only(p: Plan, fits: Fits) -> Plan {
    let n = p.ticks.len();
    let mut tries: Vec<Vec<Tick>> = Vec::new();
    if n >= 2 {
        tries.push(vec![p.ticks[0].clone(), p.ticks[n - 1].clone()]);
    }
    tries.extend(p.ticks.first().map(|t| vec![t.clone()]));
    tries.extend(p.ticks.last().map(|t| vec![t.clone()]));
    for ticks in tries {
        if fits(p.lo, p.hi, &ticks) {
            return Plan { ticks, ..p };
        }
    }
    Plan {
        ticks: Vec::new(),
        ..p
    }
}

/// The round step (1, 2 or 5 × 10ⁿ) at or above `raw`.
pub fn nice_step(raw: f64) -> f64 {
    if !(raw.is_finite() && raw > 0.0) {
        return 1.0;
    }
    let e = raw.log10().floor();
    let base = 10f64.powf(e);
    let m = raw / base;
    let n = if m <= 1.0 + 1e-9 {
        1.0
    } else if m <= 2.0 + 1e-9 {
        2.0
    } else if m <= 5.0 + 1e-9 {
        5.0
    } else {
        10.0
    };
    n * base
}

/// log10 of the largest 1, 2, 5 × 10ⁿ at or below 10^`x`.
fn floor125(x: f64) -> f64 {
    let e = x.floor();
    let m = 10f64.powf(x - e);
    let m = [5.0, 2.0, 1.0]
        .into_iter()
        .find(|&c| m >= c * (1.0 - 1e-9))
        .unwrap_or(1.0);
    // The same expression as the ticks', so the end tick is the bound.
    (m * 10f64.powi(e as i32)).log10()
}

/// log10 of the smallest 1, 2, 5 × 10ⁿ at or above 10^`x`.
fn ceil125(x: f64) -> f64 {
    let e = x.floor();
    let m = 10f64.powf(x - e);
    let m = [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .find(|&c| m <= c * (1.0 + 1e-9))
        .unwrap_or(10.0);
    (m * 10f64.powi(e as i32)).log10()
}

/// A tick label: as many decimals as the step needs; past a million or
/// below 1e-4, scientific (`2.5e6`) so labels stay short.
pub fn tick_text(v: f64, step: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return if v.is_finite() {
            "0".into()
        } else {
            format!("{v}")
        };
    }
    let step_exp = step.abs().log10().floor();
    if v.abs() >= 1e6 || step.abs() < 1e-4 {
        let e = v.abs().log10().floor();
        let digits = ((e - step_exp).max(0.0) as usize).min(6);
        return super::format::sci(v, digits + 1);
    }
    let decimals = (-(step.abs().log10() + 1e-9).floor()).max(0.0) as usize;
    let s = format!("{v:.decimals$}");
    let s = if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    };
    if s == "-0" { "0".into() } else { s }
}

#[cfg(test)]
#[path = "axis_tests.rs"]
mod tests;
