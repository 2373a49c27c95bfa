//! A second model laid over the Responses charts (`c`): a preset file, or
//! the model as last saved. Its sweep is kept while the model on screen is
//! edited, and redone on the new grid when the band changes.

use crate::tui::paths;
use crate::tui::shared::Shared;
use crate::view::format::{clip, num, unit};
use biodyn::{Response, Band, Body, Function, Preset, Solver};
use biodyn::freq::{self, Peak};

#[derive(Debug, Clone)]
pub struct Compare {
    /// The legend's name: the preset's, or "as last saved".
    pub name: String,
    body: Body,
    band: Band,
    pub curve: Vec<Response>,
    /// The main peak of each function, in `Function::ALL` order.
    pub peaks: Vec<Option<Peak>>,
    /// The preset file compared against, if one (not "as last saved" or a
    /// built-in): a file the app has open.
    pub path: Option<std::path::PathBuf>,
}

impl Compare {
    /// Sweeps `body` over `band`; Err names what the library refused.
    pub fn new(name: String, body: Body, band: Band) -> Result<Compare, String> {
        band.check_work(body.n()).map_err(|e| e.to_string())?;
        let solver = Solver::try_new(&body).map_err(|e| format!("{name}: {e}"))?;
        let curve = solver.sweep(&band);
        let peaks = Function::ALL
            .iter()
            .map(|&f| freq::main_peak(&solver, &curve, f).filter(|p| !p.at_edge))
            .collect();
        Ok(Compare {
            name,
            body,
            band,
            curve,
            peaks,
            path: None,
        })
    }

    /// What the field typed names: empty or `saved` is the model as last
    /// saved (or loaded); anything else a preset file (`~` expanded) or a
    /// built-in preset's name.
    pub fn load(text: &str, s: &Shared) -> Result<Compare, String> {
        let t = text.trim();
        if t.is_empty() || t.eq_ignore_ascii_case("saved") {
            return Compare::new("as last saved".into(), s.saved.clone(), *s.band());
        }
        let path = paths::expand(t);
        let p = Preset::open(&path.to_string_lossy()).map_err(|e| e.to_string())?;
        let mut c = Compare::new(p.name.clone(), p.body, *s.band())?;
        c.path = path.is_file().then_some(path);
        Ok(c)
    }

    /// Sweeps again when the band changed (the grid must match the model's).
    pub fn follow(&mut self, band: &Band) -> Result<(), String> {
        if self.band == *band {
            return Ok(());
        }
        let path = self.path.take();
        *self = Compare::new(self.name.clone(), self.body.clone(), *band)?;
        self.path = path;
        Ok(())
    }

    /// `peak_line` in at most `width` characters: when the whole line is
    /// too long the ref's own values go first ("STHT peak 4.561 Hz 1.815,
    /// Δ −0.149 Hz +1.4 % vs ref"), then the model's ("STHT peak Δ −0.149
    /// Hz +1.4 % vs ref"): the differences are what the line is for.
    pub fn peak_line_in(&self, f: Function, model: Option<Peak>, width: usize) -> String {
        let full = self.peak_line(f, model);
        let r = self.peaks.get(f.index()).copied().flatten();
        let (Some(m), Some(r)) = (model, r) else {
            return clip(&full, width);
        };
        let u = unit(f);
        let u = if u.is_empty() {
            String::new()
        } else {
            format!(" {u}")
        };
        let delta = format!(
            "Δ {} Hz {} % vs ref",
            signed(m.f_hz - r.f_hz, 3),
            signed((m.mag / r.mag - 1.0) * 100.0, 2)
        );
        let shorter = [
            full,
            format!(
                "{} peak {} Hz {}{u}, {delta}",
                f.name(),
                num(m.f_hz, 4),
                num(m.mag, 4)
            ),
            format!("{} peak {delta}", f.name()),
            format!("{} {delta}", f.name()),
        ];
        let fits = shorter.iter().find(|l| l.chars().count() <= width);
        clip(fits.unwrap_or(&shorter[3]), width)
    }

    /// "STHT peak 4.561 Hz 1.815 (ref 4.71 Hz 1.79, Δ −0.149 Hz +1.4 %)".
    pub fn peak_line(&self, f: Function, model: Option<Peak>) -> String {
        let u = unit(f);
        let u = if u.is_empty() {
            String::new()
        } else {
            format!(" {u}")
        };
        let r = self.peaks.get(f.index()).copied().flatten();
        match (model, r) {
            (Some(m), Some(r)) => {
                let df = m.f_hz - r.f_hz;
                let dm = (m.mag / r.mag - 1.0) * 100.0;
                format!(
                    "{} peak {} Hz {}{u} (ref {} Hz {}{u}, Δ {} Hz {} %)",
                    f.name(),
                    num(m.f_hz, 4),
                    num(m.mag, 4),
                    num(r.f_hz, 4),
                    num(r.mag, 4),
                    signed(df, 3),
                    signed(dm, 2),
                )
            }
            (Some(m), None) => format!(
                "{} peak {} Hz {}{u} (ref: no peak inside the band)",
                f.name(),
                num(m.f_hz, 4),
                num(m.mag, 4)
            ),
            (None, Some(r)) => format!(
                "{} no peak inside the band (ref {} Hz {}{u})",
                f.name(),
                num(r.f_hz, 4),
                num(r.mag, 4)
            ),
            (None, None) => format!("{}: no peak inside the band in either model", f.name()),
        }
    }
}

/// How the compared model's curves differ from the model's, in words for
/// the legend and the status line: grey dots in colour; without colour
/// (NO_COLOR) the dots alone, as nothing is dimmed there.
pub fn drawn_as(mono: bool) -> &'static str {
    if mono { "dotted" } else { "grey, dotted" }
}

/// "+1.4" or "−0.149": a sign always, a true minus sign.
fn signed(v: f64, sig: usize) -> String {
    let t = num(v.abs(), sig);
    if v < 0.0 {
        format!("−{t}")
    } else {
        format!("+{t}")
    }
}
