//! The figure `biodyn assess --plot FILE.svg` writes: per axis of the seat
//! record, its frequency-weighted acceleration over time and its
//! one-third-octave bands; then the head's (the model's prediction).
//!
//! The traces are recorded beside the assessment in one pass (`Recorder`
//! is fed the same rows): the body is simulated again here, as the TUI's
//! Vibration tab does, so the library's streaming assessment keeps its
//! bounded memory. Traces keep a (min, max) per column (`Envelope`), so no
//! peak is lost however long the record. The z and head bands are the
//! assessment's own (`Assessment::bands`, the JSON's `bands`); x and y are
//! banded here with the same filters.

use super::model::{Axis as FigAxis, Bars, Curve, Figure, Panel};
use super::style::{Fill, Look};
use crate::view::envelope::Envelope;
use biodyn::Body;
use biodyn::iso2631::{Assessment, BandBank, Weighting, WeightingFilter, rule};
use biodyn::time::{Axis, Frame, PerAxis, Row, Simulator};

/// Columns a trace is drawn with.
const COLUMNS: usize = 1000;
/// One panel's size in the grid.
const PANEL: (u32, u32) = (640, 300);

/// The weighted traces of one run, as it goes.
pub struct Recorder {
    sim: Simulator,
    y: Vec<f64>,
    pan: Option<usize>,
    fs: f64,
    /// Per seat axis present: its weighting filter, trace, and (x, y) bands.
    axes: Vec<(Axis, WeightingFilter, Envelope, Option<BandBank>)>,
    head: (WeightingFilter, Envelope),
}

impl Recorder {
    pub fn new(body: &Body, fs: f64, present: &PerAxis<()>) -> Result<Recorder, String> {
        let sim = Simulator::new(body, fs).map_err(|e| e.to_string())?;
        let y = vec![0.0; sim.layout().len()];
        let axes = [Axis::X, Axis::Y, Axis::Z]
            .into_iter()
            .filter(|a| present.has(*a))
            .map(|a| {
                let w = if a == Axis::Z {
                    Weighting::Wk
                } else {
                    rule(a).weighting
                };
                let bands = (a != Axis::Z).then(|| BandBank::new(fs));
                (a, w.digital(fs), Envelope::default(), bands)
            })
            .collect();
        Ok(Recorder {
            pan: body.pan(),
            head: (Weighting::Wk.digital(fs), Envelope::default()),
            sim,
            y,
            fs,
            axes,
        })
    }

    /// One row of the record (m/s², x y z).
    pub fn push(&mut self, row: &Row) {
        let floor = row[Axis::Z.index()];
        self.sim.step(floor, &mut self.y);
        let head = self.y.get(self.sim.head()).copied().unwrap_or(0.0);
        // Under a seat the seat's z is the pan's, as `assess` judges it.
        let z = self
            .pan
            .and_then(|p| self.y.get(p).copied())
            .unwrap_or(floor);
        for (a, w, env, bands) in &mut self.axes {
            let v = if *a == Axis::Z { z } else { row[a.index()] };
            env.push(w.process(v));
            if let Some(b) = bands {
                b.push([v]);
            }
        }
        self.head.1.push(self.head.0.process(head));
    }

    /// `rows` passed on unchanged, each one read pushed into `rec` when
    /// there is a recorder (the figure is drawn beside the assessment).
    pub fn tee<'a, E: 'a>(
        rec: &'a mut Option<Recorder>,
        rows: impl Iterator<Item = Result<Row, E>> + 'a,
    ) -> impl Iterator<Item = Result<Row, E>> + 'a {
        rows.inspect(move |r| {
            if let (Some(rec), Ok(row)) = (rec.as_mut(), r) {
                rec.push(row);
            }
        })
    }

    /// [`Recorder::tee`] for frames: the seat's row of each.
    pub fn tee_frames<'a, E: 'a>(
        rec: &'a mut Option<Recorder>,
        frames: impl Iterator<Item = Result<Frame, E>> + 'a,
    ) -> impl Iterator<Item = Result<Frame, E>> + 'a {
        frames.inspect(move |f| {
            if let (Some(rec), Ok(frame)) = (rec.as_mut(), f) {
                rec.push(&frame.0);
            }
        })
    }

    /// The figure, with the z and head bands from `r`; `head` names the
    /// model's head segment.
    pub fn figure(&self, r: &Assessment, head: &str) -> Figure {
        self.figure_of(r, Some(head))
    }

    /// [`figure`](Self::figure), the head's panels (the model's) left out
    /// when `head` is None.
    pub fn figure_of(&self, r: &Assessment, head: Option<&str>) -> Figure {
        let mut panels = Vec::new();
        let seated = r.floor.is_some();
        for (i, (a, _, env, bands)) in self.axes.iter().enumerate() {
            let w = if *a == Axis::Z {
                r.weighting
            } else {
                rule(*a).weighting
            };
            let name = if *a == Axis::Z && seated {
                "seat pan z".to_string()
            } else {
                format!("seat {}", a.name())
            };
            panels.push(trace(
                &format!("{name}, weighted ({})", w.name()),
                env,
                self.fs,
                i,
            ));
            let levels: Vec<(f64, Option<f64>)> = match bands {
                Some(b) => b
                    .levels()
                    .into_iter()
                    .map(|(f, l)| (f, l.map(|v| v[0])))
                    .collect(),
                None => r.bands.iter().map(|b| (b.f_hz, b.seat)).collect(),
            };
            panels.push(bands_panel(
                &format!("{name}: one-third-octave bands"),
                &levels,
            ));
        }
        let Some(head) = head else {
            return Figure {
                panels,
                columns: 2,
                panel_px: PANEL,
            };
        };
        let n = self.axes.len();
        panels.push(trace(
            &format!("{head} z, weighted (Wk): the model's prediction"),
            &self.head.1,
            self.fs,
            n,
        ));
        let levels: Vec<(f64, Option<f64>)> = r.bands.iter().map(|b| (b.f_hz, b.head)).collect();
        panels.push(bands_panel(
            &format!("{head} z: one-third-octave bands (model)"),
            &levels,
        ));
        Figure {
            panels,
            columns: 2,
            panel_px: PANEL,
        }
    }
}

/// A weighted trace over time: each column's min and max in turn.
fn trace(title: &str, env: &Envelope, fs: f64, i: usize) -> Panel {
    let cols = env.columns(0, env.len, COLUMNS.min(env.len.max(1)));
    let per = env.len as f64 / cols.len().max(1) as f64;
    let points = cols
        .iter()
        .enumerate()
        .flat_map(|(c, &(lo, hi))| {
            let t = (c as f64 + 0.5) * per / fs;
            [(t, lo), (t, hi)]
        })
        .collect();
    Panel {
        title: title.into(),
        x: FigAxis {
            title: "t (s)".into(),
            log: false,
            floor_zero: true,
            names: Vec::new(),
        },
        y: FigAxis {
            title: "a_w (m/s²)".into(),
            log: false,
            floor_zero: false,
            names: Vec::new(),
        },
        curves: vec![Curve {
            name: title.into(),
            points,
            look: Look::Trace(i),
        }],
        ..Panel::default()
    }
}

/// Band r.m.s. as bars one third of an octave wide on a log axis.
fn bands_panel(title: &str, levels: &[(f64, Option<f64>)]) -> Panel {
    let edge = 2f64.powf(1.0 / 6.0);
    Panel {
        title: title.into(),
        x: FigAxis {
            title: "f (Hz)".into(),
            log: true,
            floor_zero: false,
            names: Vec::new(),
        },
        y: FigAxis {
            title: "r.m.s. (m/s², unweighted)".into(),
            log: false,
            floor_zero: true,
            names: Vec::new(),
        },
        bars: vec![Bars {
            name: "band r.m.s.".into(),
            bars: levels
                .iter()
                .filter_map(|&(f, l)| Some((f / edge, f * edge, l?)))
                .collect(),
            fill: Fill::Plain,
        }],
        ..Panel::default()
    }
}
