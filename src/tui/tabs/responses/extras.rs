//! The Responses tab's export (`x`), readout copy (`y`), go-to frequency
//! (`g`) and mouse: what the command line would print, and the cursor put
//! exactly where the user asks.

use super::{ResponsesTab, view};
use crate::tui::component::{Cx, Mouse, MouseKind};
use crate::tui::effect::{Effect, Export, Format};
use crate::tui::shared::Shared;
use crate::tui::input::frequency_in_band;
use crate::view::figure::{self, response::ResponseFigure};
use crate::view::format::num;
use crate::view::report::plot::{PLOT_HEIGHT, PLOT_WIDTH, PlotText};
use crate::view::report::{csv, plot};
use biodyn::Function;
use ratatui::layout::{Position, Rect};

impl ResponsesTab {
    /// The shown function (`f`, a click, `n`, what `z` and `.txt` show).
    pub fn function(&self) -> Function {
        Function::ALL
            .get(self.func)
            .copied()
            .unwrap_or(Function::Stht)
    }

    /// The curves as `biodyn response --format csv` prints them, or (a
    /// `.txt` name) the current function's chart as `biodyn plot <f>
    /// --width 100 --height 30` prints it, with `--phase` in phase mode
    /// and `--log-x --log-y` (only `--log-x` with `--phase`) on log axes.
    pub(super) fn export(&self, s: &Shared) -> Vec<Effect> {
        let Some(d) = &s.derived else {
            return vec![Effect::Error("no curves to export yet (computing)".into())];
        };
        let o = PlotText {
            function: self.function(),
            log_x: self.log,
            log_y: self.log && !self.phase,
            ascii: s.theme.ascii,
            width: PLOT_WIDTH,
            height: PLOT_HEIGHT,
        };
        let series = plot::series(&s.preset.name, &d.curve, &o, self.phase);
        let marks = match d.functions.get(self.func) {
            Some(c) if !self.phase => c.peaks.iter().map(|p| (p.f_hz, p.mag)).collect(),
            _ => Vec::new(),
        };
        let svg = self.figure(&series, &marks);
        vec![Effect::Export(Export {
            what: "responses".into(),
            path_hint: format!("{}-responses.csv", s.preset.name),
            formats: vec![
                Format {
                    ext: "csv",
                    what: "curves",
                    contents: csv::curve(&d.curve),
                },
                Format {
                    ext: "txt",
                    what: "text chart",
                    contents: plot::chart_text(&[series], marks, self.phase, &o),
                },
                Format {
                    ext: "svg",
                    what: "figure",
                    contents: svg,
                },
            ],
        })]
    }

    /// The chart as `biodyn plot <f> --format svg` writes it, with the
    /// same flags as the `.txt` and, when laid over, `--data FILE` and
    /// `--compare PRESET`.
    fn figure(
        &self,
        series: &crate::view::chart::Series,
        marks: &[(f64, f64)],
    ) -> String {
        let f = self.function();
        let model = &series.points;
        let data = self.data.as_ref().and_then(|d| {
            let pts = figure::response::measured(&d.data, f, self.phase, model)?;
            Some((figure::response::data_name(&d.data.path), pts))
        });
        let reference = self
            .compare
            .as_ref()
            .map(|c| plot::curve_series(&c.name, &c.curve, f, self.phase));
        figure::response::figure(&ResponseFigure {
            function: f,
            phase: self.phase,
            log_x: self.log,
            log_y: self.log && !self.phase,
            series: std::slice::from_ref(series),
            marks,
            data: data.as_ref().map(|(n, p)| (n.as_str(), p.as_slice())),
            reference: reference.as_ref(),
            size: figure::PANEL_PX,
        })
        .svg()
    }

    /// The readout at the cursor as one CSV row (the columns of `biodyn
    /// response --format csv`, shortest round-trip numbers).
    pub(super) fn copy_line(&mut self, s: &Shared) -> Vec<Effect> {
        let Some(r) = view::at_cursor(self, s) else {
            return vec![Effect::Error("no readout to copy yet (computing)".into())];
        };
        let mut line = String::new();
        csv::curve_rows(&mut line, "", std::slice::from_ref(r));
        let line = line.trim_end().to_string();
        let width = usize::from(self.drawn_width.get());
        let say = if width == 0 || line.chars().count() < width {
            line.clone()
        } else {
            // Cut at the screen's edge it would be a wrong number: the tab
            // shows it whole, broken only after commas.
            "CSV row above the charts (breaks only after commas)".to_string()
        };
        self.copied = Some(line);
        vec![Effect::Status(say)]
    }

    /// The `g` field was committed: the cursor at exactly that frequency,
    /// computed there by the solver. Err keeps the field open.
    pub(super) fn go_to(&mut self, text: &str, s: &Shared) -> Result<Vec<Effect>, String> {
        let Some(d) = &s.derived else {
            return Err("the curves are not computed yet: try again in a moment".into());
        };
        let f = frequency_in_band(text, s.band())?;
        let r = d.solver.at(f);
        self.cursor = s.index_of(f);
        self.exact = Some(r);
        Ok(vec![Effect::Status(format!(
            "cursor at {} Hz, computed there (y copies the readout)",
            num(f, 8)
        ))])
    }

    /// A click in a chart puts the cursor on the grid frequency nearest the
    /// clicked column and makes that chart's function the current one; the
    /// wheel moves the cursor one step.
    pub(super) fn mouse(&mut self, m: Mouse, area: Rect, cx: &Cx) -> Vec<Effect> {
        let s = cx.shared;
        match m.kind {
            MouseKind::WheelUp => return self.act(super::Action::Right, s),
            MouseKind::WheelDown => return self.act(super::Action::Left, s),
            MouseKind::Click | MouseKind::DoubleClick => {}
        }
        let at = Position::new(m.column, m.row);
        let a = view::areas(self, s, area, m.zoomed);
        let alone = a.charts.len() == 1;
        let Some(&(i, cell)) = a.charts.iter().find(|(_, r)| r.contains(at)) else {
            return Vec::new();
        };
        let Some(c) = view::chart(self, s, i, cell, alone) else {
            return Vec::new();
        };
        self.func = i;
        let f = crate::view::chart::layout(cell, &c.series, &c.opts)
            .and_then(|l| l.x_at(m.column, c.opts.log_x));
        if let Some(f) = f {
            self.cursor = s.index_of(f);
            self.exact = None;
        }
        Vec::new()
    }
}
