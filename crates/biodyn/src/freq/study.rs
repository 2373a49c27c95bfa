//! Parametric studies (SPEC §3): one parameter varied over a list of values or
//! ± percentages of its base value, the three functions overlaid, and a
//! summary that says where "the response rises with the parameter" holds.

use crate::band::Band;
use crate::body::model::{Body, ModelError, Param};
use crate::freq::function::{Function, Response};
use crate::freq::peaks::{self, Peak};
use crate::freq::response::{SolveError, Solver};
use serde::Serialize;

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum StudyError {
    #[error("study value '{entry}' (entry {index}): {why}")]
    BadEntry {
        entry: String,
        index: usize,
        why: String,
    },
    #[error(
        "the study has no values: give a comma-separated list such as 65,75,85 or -40%,0%,+40%"
    )]
    Empty,
    #[error(
        "a study of {values} values over {points} frequency points asks for {cells} response points (about {mb} MB), over the limit of {max}: use fewer values, a narrower band or a step of at least {step_hint} Hz",
        max = MAX_STUDY_POINTS
    )]
    TooBig {
        values: usize,
        points: usize,
        cells: u128,
        mb: u128,
        step_hint: f64,
    },
    #[error(
        "a study of {values} values of a {segments}-segment model over {points} frequency points is {work:.1e} segment-points of work, over the limit of {max:.0e} (about 10 s): use fewer values, a larger step or a narrower band",
        max = crate::band::MAX_SWEEP_WORK
    )]
    TooMuchWork {
        values: usize,
        segments: usize,
        points: usize,
        work: f64,
    },
    #[error(transparent)]
    Solve(#[from] SolveError),
    #[error("study value {label}: {source}")]
    Model {
        label: String,
        #[source]
        source: ModelError,
    },
}

/// Most response points (values × frequencies) one study computes and keeps:
/// 56 bytes each, so the curves stay under about 60 MB.
pub const MAX_STUDY_POINTS: usize = 1_000_000;

/// Refuses a study whose curves would not fit `MAX_STUDY_POINTS`, before
/// anything is allocated; the error says how to narrow it.
pub fn check_study_size(values: usize, band: &Band) -> Result<(), StudyError> {
    let points = band.len();
    let cells = values as u128 * points as u128;
    if cells <= MAX_STUDY_POINTS as u128 {
        return Ok(());
    }
    // values × (span / step + 1) ≤ max gives the smallest step that fits;
    // with more values than the limit, no step does (∞: fewer values).
    let per_value = (MAX_STUDY_POINTS / values.max(1)) as f64 - 1.0;
    let span = band.to - band.from;
    let step_hint = if per_value >= 1.0 {
        let raw = span / per_value;
        // Round up to two significant digits so the hint reads well and fits.
        let scale = 10f64.powf(raw.log10().floor() - 1.0);
        (raw / scale).ceil() * scale
    } else {
        f64::INFINITY
    };
    Err(StudyError::TooBig {
        values,
        points,
        cells,
        mb: cells * std::mem::size_of::<Response>() as u128 / 1_000_000,
        step_hint,
    })
}

/// One entry of a study: an absolute value or a percentage change of the base.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub enum Step {
    Value(f64),
    Percent(f64),
}

impl Step {
    pub fn resolve(self, base: f64) -> f64 {
        match self {
            Step::Value(v) => v,
            Step::Percent(p) => base * (1.0 + p / 100.0),
        }
    }
}

/// The paper's lists (its §3 studies): body masses 65/75/85 kg, and the
/// base value ±40 % for k4, c4 and any other parameter.
pub fn paper_steps(p: Param) -> &'static str {
    match p {
        Param::BodyMass => "65,75,85",
        _ => "-40%,0%,+40%",
    }
}

/// Parses "65,75,85" or "-40%,0%,+40%" (mixing is allowed).
pub fn parse_steps(text: &str) -> Result<Vec<Step>, StudyError> {
    let mut steps = Vec::new();
    for (index, raw) in text.split(',').enumerate() {
        let entry = raw.trim();
        let bad = |why: &str| StudyError::BadEntry {
            entry: entry.to_string(),
            index: index + 1,
            why: why.to_string(),
        };
        if entry.is_empty() {
            return Err(bad("empty entry; separate values with single commas"));
        }
        let (num, pct) = match entry.strip_suffix('%') {
            Some(n) => (n.trim(), true),
            None => (entry, false),
        };
        let v: f64 = num
            .parse()
            .map_err(|_| bad("not a number; write e.g. 75 or +40%"))?;
        if !v.is_finite() {
            return Err(bad("not a finite number"));
        }
        if pct && v <= -100.0 {
            return Err(bad(
                "a change of -100 % or less leaves nothing; use a value above -100%",
            ));
        }
        steps.push(if pct {
            Step::Percent(v)
        } else {
            Step::Value(v)
        });
    }
    if steps.is_empty() {
        return Err(StudyError::Empty);
    }
    Ok(steps)
}

/// One curve of a study.
#[derive(Debug, Clone)]
pub struct Variant {
    pub label: String,
    pub value: f64,
    pub body: Body,
    pub curve: Vec<Response>,
    /// Main peak of STHT, DPMI, APMS in that order.
    pub peaks: [Option<Peak>; 3],
}

/// How a quantity moves as the parameter increases across the variants.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Direction {
    Rises,
    Falls,
    Mixed,
    Flat,
}

impl Direction {
    pub fn word(self) -> &'static str {
        match self {
            Direction::Rises => "rises",
            Direction::Falls => "falls",
            Direction::Mixed => "mixed",
            Direction::Flat => "flat",
        }
    }

    fn of(values: &[f64]) -> Direction {
        let tol = 1e-12 * values.iter().fold(0.0f64, |a, v| a.max(v.abs()));
        let up = values.windows(2).all(|w| w[1] > w[0] + tol);
        let down = values.windows(2).all(|w| w[1] < w[0] - tol);
        let flat = values.windows(2).all(|w| (w[1] - w[0]).abs() <= tol);
        match (up, down, flat) {
            (_, _, true) => Direction::Flat,
            (true, _, _) => Direction::Rises,
            (_, true, _) => Direction::Falls,
            _ => Direction::Mixed,
        }
    }
}

/// Per function: the direction of the main peak's magnitude and frequency
/// as the parameter increases, and the share of the band where the
/// magnitude rises or falls at every step.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Trend {
    pub function: Function,
    pub peak_mag: Direction,
    pub peak_f: Direction,
    pub rises_share: f64,
    pub falls_share: f64,
}

#[derive(Debug, Clone)]
pub struct Study {
    pub param: Param,
    pub param_label: String,
    pub band: Band,
    pub base_value: f64,
    /// In the order given by the user.
    pub variants: Vec<Variant>,
}

/// Runs the study: every variant validated, swept and its peaks refined.
pub fn run_study(
    base: &Body,
    param: Param,
    steps: &[Step],
    band: &Band,
) -> Result<Study, StudyError> {
    run_study_with(base, param, steps, band, &mut |_, _| {})
}

/// [`run_study`], calling `progress(done, total)` as the frequencies of
/// all the variants are solved (`total` = variants × band points; see
/// [`Solver::sweep_with`]). The same bits as [`run_study`].
pub fn run_study_with(
    base: &Body,
    param: Param,
    steps: &[Step],
    band: &Band,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<Study, StudyError> {
    if steps.is_empty() {
        return Err(StudyError::Empty);
    }
    check_study_size(steps.len(), band)?;
    let work = (steps.len() * base.n()) as f64 * band.len() as f64;
    if work > crate::band::MAX_SWEEP_WORK {
        return Err(StudyError::TooMuchWork {
            values: steps.len(),
            segments: base.n(),
            points: band.len(),
            work,
        });
    }
    let base_value = base.get(param);
    let param_label = base.label(param);
    let mut variants = Vec::with_capacity(steps.len());
    for step in steps {
        let value = step.resolve(base_value);
        let label = match step {
            Step::Value(_) => format!("{param_label} = {} {}", round_sig(value), param.unit()),
            Step::Percent(p) if *p == 0.0 => format!("{param_label} B.V. ({})", round_sig(value)),
            Step::Percent(p) => format!("{param_label} B.V. {p:+}% ({})", round_sig(value)),
        };
        let mut body = base.clone();
        body.set(param, value).map_err(|source| StudyError::Model {
            label: label.clone(),
            source,
        })?;
        let solver = Solver::try_new(&body)?;
        let before = variants.len() * band.len();
        let total = steps.len() * band.len();
        let curve = solver.sweep_with(band, &mut |done, _| progress(before + done, total));
        let peaks = Function::ALL.map(|f| peaks::main_peak(&solver, &curve, f));
        variants.push(Variant {
            label,
            value,
            body,
            curve,
            peaks,
        });
    }
    Ok(Study {
        param,
        param_label,
        band: *band,
        base_value,
        variants,
    })
}

impl Study {
    /// Trends of the three functions with the variants sorted by value.
    pub fn trends(&self) -> Vec<Trend> {
        let mut order: Vec<&Variant> = self.variants.iter().collect();
        order.sort_by(|a, b| a.value.total_cmp(&b.value));
        Function::ALL
            .iter()
            .enumerate()
            .map(|(fi, &function)| {
                let pk: Vec<Peak> = order.iter().filter_map(|v| v.peaks[fi]).collect();
                let mags: Vec<f64> = pk.iter().map(|p| p.mag).collect();
                let freqs: Vec<f64> = pk.iter().map(|p| p.f_hz).collect();
                let points = order.first().map_or(0, |v| v.curve.len());
                let (mut up, mut down) = (0usize, 0usize);
                for i in 0..points {
                    let col: Vec<f64> = order.iter().map(|v| v.curve[i].mag(function)).collect();
                    match Direction::of(&col) {
                        Direction::Rises => up += 1,
                        Direction::Falls => down += 1,
                        _ => {}
                    }
                }
                let share = |c: usize| {
                    if points == 0 {
                        0.0
                    } else {
                        c as f64 / points as f64
                    }
                };
                Trend {
                    function,
                    peak_mag: Direction::of(&mags),
                    peak_f: Direction::of(&freqs),
                    rises_share: share(up),
                    falls_share: share(down),
                }
            })
            .collect()
    }
}

/// Four significant digits for labels (the exact value goes to CSV/JSON).
pub fn round_sig(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    if !(1e-4..1e7).contains(&v.abs()) {
        // 1e300 as 1e300, not 301 digits.
        return crate::io::excerpt::num(v);
    }
    let digits = (4 - 1 - v.abs().log10().floor() as i32).max(0) as usize;
    let s = format!("{v:.digits$}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_values_and_percentages() {
        assert_eq!(
            parse_steps("65, 75,85").unwrap(),
            vec![Step::Value(65.0), Step::Value(75.0), Step::Value(85.0)]
        );
        assert_eq!(
            parse_steps("-40%,0%,+40%").unwrap(),
            vec![
                Step::Percent(-40.0),
                Step::Percent(0.0),
                Step::Percent(40.0)
            ]
        );
        for bad in ["", "65,,85", "65,abc", "nan", "-100%", "inf"] {
            assert!(parse_steps(bad).is_err(), "{bad}");
        }
        let e = parse_steps("65,7x5").unwrap_err().to_string();
        assert!(e.contains("7x5") && e.contains("entry 2"), "{e}");
    }

    #[test]
    fn mass_study_trends_match_direct_count() {
        let base = Body::paper(75.0).unwrap();
        let steps = parse_steps("65,75,85").unwrap();
        let s = run_study(&base, Param::BodyMass, &steps, &Band::default()).unwrap();
        assert_eq!(s.variants.len(), 3);
        let t = s.trends();
        assert_eq!(t[2].peak_mag, Direction::Rises);
        // The paper says APMS rises with body mass; above resonance a heavier
        // body moves less, so it holds on part of the band only. Count directly.
        let mut up = 0;
        for f in Band::default().freqs() {
            let a: Vec<f64> = [65.0, 75.0, 85.0]
                .iter()
                .map(|&m| Solver::new(&Body::paper(m).unwrap()).at(f).apms.norm())
                .collect();
            if a[0] < a[1] && a[1] < a[2] {
                up += 1;
            }
        }
        assert_eq!(t[2].rises_share, up as f64 / 196.0);
        assert!(t[2].rises_share > 0.2 && t[2].rises_share < 1.0);
        // Heavier body, same springs: resonances move down.
        assert_eq!(t[2].peak_f, Direction::Falls);
    }

    #[test]
    fn percent_steps_resolve_against_base_and_bad_value_is_named() {
        let base = Body::paper(75.0).unwrap();
        let s = run_study(
            &base,
            Param::Stiffness(3),
            &parse_steps("-40%,0%,+40%").unwrap(),
            &Band::default(),
        )
        .unwrap();
        assert!((s.variants[0].value - 54_000.0).abs() < 1e-9);
        assert!((s.variants[2].value - 126_000.0).abs() < 1e-9);
        let e = run_study(
            &base,
            Param::Mass(0),
            &[Step::Value(-3.0)],
            &Band::default(),
        )
        .unwrap_err();
        assert!(e.to_string().contains("m1"), "{e}");
    }

    #[test]
    fn round_sig_is_readable() {
        assert_eq!(round_sig(54000.0), "54000");
        assert_eq!(round_sig(5.625), "5.625");
        assert_eq!(round_sig(0.0123456), "0.01235");
    }
}
