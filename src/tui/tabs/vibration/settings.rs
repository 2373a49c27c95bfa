//! The Vibration tab's settings: the signal kind and parameters (the library's
//! `Signal`, through its parser), or a CSV record (axes and unit, as `--axes`
//! and `--unit`); duration, fs, exposure. One row per thing the user edits.

use super::compute::{Input, Source};
use biodyn::iso2631::spine::{Person, Sex};
use biodyn::time::{Axis, Component, PerAxis, Signal, Unit, parse_axes};
use std::path::PathBuf;

/// The kinds ←→ step through.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    Sine,
    Sweep,
    Random,
    Shock,
    Class,
    File,
}

pub const KINDS: [Kind; 6] = [
    Kind::Sine,
    Kind::Sweep,
    Kind::Random,
    Kind::Shock,
    Kind::Class,
    Kind::File,
];

impl Kind {
    pub fn name(self) -> &'static str {
        match self {
            Kind::Sine => "sine",
            Kind::Sweep => "sweep",
            Kind::Random => "random",
            Kind::Shock => "shock",
            Kind::Class => "class",
            Kind::File => "file",
        }
    }

    fn index(self) -> usize {
        KINDS.iter().position(|&k| k == self).unwrap_or(0)
    }

    /// The signal a kind starts with: the paper's sine, a sweep over Wk's
    /// band, broadband noise, a shock at 5 s, the crawler class EM6.
    fn default_spec(self) -> &'static str {
        match self {
            Kind::Sine | Kind::File => "sine:freq=5,amp=5",
            Kind::Sweep => "sweep:from=0.5,to=80,amp=1",
            Kind::Random => "random:rms=1,band=0.5-80,seed=1",
            Kind::Shock => "shock:peak=15,width=0.1,at=5",
            Kind::Class => "class:EM6,seed=1",
        }
    }
}

/// A component's kind.
pub fn kind_of(c: &Component) -> Kind {
    match c {
        Component::Sine { .. } => Kind::Sine,
        Component::Sweep { .. } => Kind::Sweep,
        Component::Random { .. } => Kind::Random,
        Component::Shock { .. } => Kind::Shock,
        Component::Class { .. } => Kind::Class,
    }
}

/// A component's keys as the grammar names them, with unit and value text.
pub fn params(c: &Component) -> Vec<(&'static str, &'static str, String)> {
    match *c {
        Component::Sine {
            freq,
            amp,
            phase_deg,
        } => vec![
            ("freq", "Hz", format!("{freq}")),
            ("amp", "m/s²", format!("{amp}")),
            ("phase", "deg", format!("{phase_deg}")),
        ],
        Component::Sweep { from, to, amp } => vec![
            ("from", "Hz", format!("{from}")),
            ("to", "Hz", format!("{to}")),
            ("amp", "m/s²", format!("{amp}")),
        ],
        Component::Random { rms, lo, hi, seed } => vec![
            ("rms", "m/s²", format!("{rms}")),
            ("band", "Hz", format!("{lo}-{hi}")),
            ("seed", "", format!("{seed}")),
        ],
        Component::Shock { peak, width, at } => vec![
            ("peak", "m/s²", format!("{peak}")),
            ("width", "s", format!("{width}")),
            ("at", "s", format!("{at}")),
        ],
        Component::Class { class, seed } => vec![
            ("name", "", class.name.to_string()),
            ("seed", "", format!("{seed}")),
        ],
    }
}

/// `sig` with part `part`'s `key` set to `text`, by the library's parser.
pub fn with_param(sig: &Signal, part: usize, key: &str, text: &str) -> Result<Signal, String> {
    let spec: Vec<String> = sig
        .parts
        .iter()
        .enumerate()
        .map(|(i, c)| {
            let kv: Vec<String> = params(c)
                .into_iter()
                .map(|(k, _, v)| {
                    let v = if i == part && k == key {
                        text.trim().to_string()
                    } else {
                        v
                    };
                    format!("{k}={v}")
                })
                .collect();
            format!("{}:{}", kind_of(c).name(), kv.join(","))
        })
        .collect();
    Signal::parse(&spec.join("+")).map_err(|e| e.to_string())
}

/// One editable row.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Row {
    Kind,
    Spec,
    Param(usize, &'static str),
    Path,
    /// `x=COL,y=COL,z=COL`, as `--axes`; a bare name is z, as `--column`.
    Axes,
    /// ←→ step it: from the header (a suffix, else m/s²), m/s², g, mm/s².
    Unit,
    Duration,
    /// Each channel's mean kept or removed (←→).
    Mean,
    Fs,
    Exposure,
    /// ISO 2631-5's person, or off (`p` toggles it).
    Spine,
}

#[derive(Debug, Clone, PartialEq)]
pub struct Settings {
    pub kind: Kind,
    /// The last signal of each generated kind (a sum under its first part's).
    pub signals: [Signal; 5],
    pub path: String,
    /// As typed; empty: the axes the header names.
    pub axes: String,
    /// None: a column's suffix, else m/s² (a suffix can then never clash).
    pub unit: Option<Unit>,
    /// Each channel's mean removed before judging (a gravity offset).
    pub remove_mean: bool,
    pub duration_s: f64,
    pub fs_hz: f64,
    pub exposure_h: f64,
    /// The spine block asked for, and for whom (kept while it is off).
    pub spine_on: bool,
    pub person: Person,
}

/// Annex C's example person: a man from 25, ten years, 240 days a year.
fn example_person() -> Person {
    Person {
        age: 25.0,
        years: 10,
        days: 240,
        sex: Sex::Male,
    }
}

impl Default for Settings {
    fn default() -> Self {
        let sig = |k: Kind| Signal::parse(k.default_spec()).unwrap_or(Signal { parts: Vec::new() });
        Settings {
            kind: Kind::Sine,
            signals: [Kind::Sine, Kind::Sweep, Kind::Random, Kind::Shock, Kind::Class].map(sig),
            path: String::new(),
            axes: String::new(),
            unit: None,
            remove_mean: false,
            duration_s: 10.0,
            fs_hz: 1000.0,
            exposure_h: 8.0,
            spine_on: false,
            person: example_person(),
        }
    }
}

impl Settings {
    /// The current generated signal (None for a file).
    pub fn signal(&self) -> Option<&Signal> {
        self.signals
            .get(self.kind.index())
            .filter(|_| self.kind != Kind::File)
    }

    /// Stores `sig` as the current signal, under the kind of its first part.
    pub fn set_signal(&mut self, sig: Signal) {
        let kind = sig.parts.first().map_or(Kind::Sine, kind_of);
        if let Some(slot) = self.signals.get_mut(kind.index()) {
            *slot = sig;
        }
        self.kind = kind;
    }

    /// Steps the kind by `d` (±1), wrapping.
    pub fn step_kind(&mut self, d: isize) {
        let n = KINDS.len() as isize;
        let i = (self.kind.index() as isize + d).rem_euclid(n) as usize;
        self.kind = KINDS[i];
    }

    /// "sine", or "random + shock" for a sum.
    pub fn kind_label(&self) -> String {
        match self.signal() {
            Some(s) if s.parts.len() > 1 => s
                .parts
                .iter()
                .map(|c| kind_of(c).name())
                .collect::<Vec<_>>()
                .join(" + "),
            _ => self.kind.name().to_string(),
        }
    }

    pub fn rows(&self) -> Vec<Row> {
        let mut r = vec![Row::Kind];
        match self.signal() {
            Some(sig) => {
                r.push(Row::Spec);
                for (i, c) in sig.parts.iter().enumerate() {
                    r.extend(params(c).into_iter().map(|(k, _, _)| Row::Param(i, k)));
                }
                r.extend([Row::Duration, Row::Fs]);
            }
            None => r.extend([Row::Path, Row::Axes, Row::Unit, Row::Mean, Row::Fs]),
        }
        r.extend([Row::Exposure, Row::Spine]);
        r
    }

    /// The row's label, unit and value text.
    pub fn row_text(&self, row: Row) -> (String, &'static str, String) {
        let sig = self.signal();
        match row {
            Row::Kind => ("signal".into(), "", self.kind_label()),
            Row::Spec => (
                "spec".into(),
                "",
                sig.map(|s| s.to_string()).unwrap_or_default(),
            ),
            Row::Param(i, key) => {
                let c = sig.and_then(|s| s.parts.get(i));
                let (unit, v) = c
                    .and_then(|c| params(c).into_iter().find(|p| p.0 == key))
                    .map_or(("", String::new()), |p| (p.1, p.2));
                let many = sig.is_some_and(|s| s.parts.len() > 1);
                let label = match c {
                    Some(c) if many => format!("{} {key}", kind_of(c).name()),
                    _ => key.to_string(),
                };
                (label, unit, v)
            }
            Row::Path => ("file".into(), "", self.path.clone()),
            Row::Axes => (
                "axes".into(),
                "",
                if self.axes.trim().is_empty() {
                    "(from the header)".into()
                } else {
                    self.axes.trim().to_string()
                },
            ),
            Row::Unit => ("unit".into(), "", unit_label(self.unit).into()),
            Row::Mean => ("mean".into(), "", mean_label(self.remove_mean).into()),
            Row::Duration => ("duration".into(), "s", format!("{}", self.duration_s)),
            Row::Fs if self.kind == Kind::File => {
                ("fs if no t_s".into(), "Hz", format!("{}", self.fs_hz))
            }
            Row::Fs => ("fs".into(), "Hz", format!("{}", self.fs_hz)),
            Row::Exposure => ("exposure".into(), "h/day", format!("{}", self.exposure_h)),
            Row::Spine if self.spine_on => ("spine".into(), "", self.person.spec()),
            Row::Spine => ("spine".into(), "", "off (p: on)".into()),
        }
    }

    /// The text a field for `row` starts with.
    pub fn edit_text(&self, row: Row) -> String {
        match row {
            Row::Axes => self.axes.clone(),
            Row::Spine => self.person.spec(),
            _ => self.row_text(row).2,
        }
    }

    /// What the computation gets.
    pub fn input(&self) -> Input {
        let source = match self.signal() {
            Some(s) => Source::Signal(s.clone()),
            None => Source::File {
                path: PathBuf::from(self.path.trim()),
                // Committed text always parses (`commit` checks it).
                axes: axes_of(&self.axes).unwrap_or_default(),
                unit: self.unit,
                remove_mean: self.remove_mean,
            },
        };
        Input {
            source,
            duration_s: self.duration_s,
            fs_hz: self.fs_hz,
            exposure_h: self.exposure_h,
            spine: self.spine_on.then_some(self.person),
        }
    }

    /// Applies a committed field; Err keeps it open with the library's reason.
    pub fn commit(&mut self, row: Row, text: &str) -> Result<(), String> {
        let t = text.trim();
        let number = |what: &str, eg: &str| -> Result<f64, String> {
            t.parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| format!("{what}: '{t}' is not a number; e.g. {eg}"))
        };
        let mut next = self.clone();
        match row {
            Row::Kind => {}
            Row::Spec => next.set_signal(Signal::parse(t).map_err(|e| e.to_string())?),
            Row::Param(i, key) => {
                let sig = self.signal().ok_or("no signal to edit")?;
                next.set_signal(with_param(sig, i, key, t)?);
            }
            Row::Path => {
                if t.is_empty() {
                    return Err("give the path of a CSV record, e.g. data/seat.csv".into());
                }
                next.path = t.to_string();
            }
            Row::Axes => {
                axes_of(t)?;
                next.axes = t.to_string();
            }
            Row::Unit | Row::Mean => {}
            Row::Duration => next.duration_s = number("duration", "10")?,
            Row::Fs => next.fs_hz = number("fs", "1000")?,
            Row::Exposure => next.exposure_h = number("exposure", "8")?,
            Row::Spine if t.is_empty() || t.eq_ignore_ascii_case("off") => next.spine_on = false,
            Row::Spine => {
                next.person = Person::parse(t).map_err(|e| e.to_string())?;
                next.spine_on = true;
            }
        }
        let input = next.input();
        super::compute::check(&input)?;
        let file = next.kind == Kind::File && !next.path.trim().is_empty();
        if matches!(row, Row::Path | Row::Axes | Row::Fs) && file {
            // Opening reads the header and two rows: cheap, and the
            // library's error (FIFO, size, columns, steps) shows in full.
            // A path refused only for its columns is kept: the axes and
            // unit rows fix that, and the run shows the library's reason.
            if let Err(e) = super::compute::open(&input)
                && !(row == Row::Path && super::compute::refused_for_columns(&input))
            {
                return Err(e);
            }
        }
        *self = next;
        Ok(())
    }
}

/// The unit choices ←→ step through, in order.
pub const UNITS: [Option<Unit>; 4] = [
    None,
    Some(Unit::MetrePerSecondSquared),
    Some(Unit::G),
    Some(Unit::MillimetrePerSecondSquared),
];

/// The unit row's value: None is the header's word.
pub fn unit_label(u: Option<Unit>) -> &'static str {
    match u {
        None => "from header",
        Some(u) => u.name(),
    }
}

/// The axes of the axes row: empty is the header's; a bare column name is
/// z, as `--column C` is `--axes z=C`; else the library's `x=COL,…`.
pub fn axes_of(text: &str) -> Result<PerAxis<String>, String> {
    let t = text.trim();
    if t.is_empty() {
        return Ok(PerAxis::default());
    }
    if !t.contains('=') && !t.contains(',') {
        let mut z = PerAxis::default();
        z.set(Axis::Z, t.to_string());
        return Ok(z);
    }
    parse_axes(t).map_err(|e| e.to_string())
}

impl Settings {
    /// Steps the unit by `d` (±1), wrapping.
    pub fn toggle_mean(&mut self) {
        self.remove_mean = !self.remove_mean;
    }

    pub fn step_unit(&mut self, d: isize) {
        let n = UNITS.len() as isize;
        let i = UNITS.iter().position(|&u| u == self.unit).unwrap_or(0) as isize;
        self.unit = UNITS[(i + d).rem_euclid(n) as usize];
    }
}

/// The mean row's value: a record's mean kept (judged, and refused when
/// it is far beyond vibration) or removed before judging.
pub fn mean_label(remove: bool) -> &'static str {
    if remove { "removed" } else { "kept" }
}

#[cfg(test)]
mod tests;
