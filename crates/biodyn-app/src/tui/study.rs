//! Tab 3, Study: one parameter varied over a list of values, the curves
//! overlaid with a legend (the paper's Figures 2–4), the peak table, and the
//! direction of change of each function spelled out from `Study::trends`.

use super::app::App;
use super::field::{Field, Purpose};
use super::keys::Action;
use super::responses::SIDE_BY_SIDE;
use super::theme::Theme;
use crate::view::chart::{self, ChartOpts, Series};
use crate::view::format::{clip, magnitude_axis, num, unit};
use biodyn::freq::study::{self, Direction, Study, Trend};
use biodyn::{Band, Body, Function, Param};
use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Paragraph, Widget, Wrap};

#[derive(Debug, Clone)]
pub struct StudyTab {
    /// Body mass, then m1.., k1.., c1.. of the current model.
    pub params: Vec<Param>,
    pub sel: usize,
    /// The value list as typed: "65,75,85" or "-40%,0%,+40%".
    pub values: String,
    pub result: Result<Study, String>,
    /// Curves per function, one series per variant, built once per run.
    pub series: [Vec<Series>; 3],
    /// The function shown when only one chart fits.
    pub func: usize,
    pub log: bool,
}

/// The paper's lists: 65/75/85 kg, and base value ±40 % for k4 and c4.
pub fn default_values(p: Param) -> &'static str {
    match p {
        Param::BodyMass => "65,75,85",
        _ => "-40%,0%,+40%",
    }
}

impl StudyTab {
    pub fn new(body: &Body) -> StudyTab {
        let n = body.segments.len();
        let l = body.links.len();
        let mut params = vec![Param::BodyMass];
        params.extend((0..n).map(Param::Mass));
        params.extend((0..l).map(Param::Stiffness));
        params.extend((0..l).map(Param::Damping));
        // Body mass needs shares; without them start on the seat link's k
        // (k4 in the paper's chain), the paper's second study.
        let shares = body.segments.iter().all(|s| s.share.is_some());
        let sel = if shares || l == 0 { 0 } else { 1 + n + l - 1 };
        StudyTab {
            sel,
            values: default_values(params[sel]).into(),
            params,
            result: Err("not run yet".into()),
            series: Default::default(),
            func: 0,
            log: false,
        }
    }

    pub fn param(&self) -> Param {
        self.params
            .get(self.sel)
            .copied()
            .unwrap_or(Param::BodyMass)
    }

    /// Runs the study on the current body.
    pub fn rerun(&mut self, body: &Body, band: &Band) {
        self.result = compute(body, self.param(), &self.values, band);
        self.series = match &self.result {
            Ok(s) => Function::ALL.map(|f| {
                s.variants
                    .iter()
                    .map(|v| Series {
                        name: v.label.clone(),
                        points: v.curve.iter().map(|r| (r.f_hz, r.mag(f))).collect(),
                    })
                    .collect()
            }),
            Err(_) => Default::default(),
        };
    }

    /// Takes a new value list if it parses and runs; otherwise says why and
    /// keeps the old one.
    pub fn set_values(&mut self, text: &str, body: &Body, band: &Band) -> Result<(), String> {
        compute(body, self.param(), text, band)?;
        self.values = text.trim().to_string();
        self.rerun(body, band);
        Ok(())
    }
}

fn compute(body: &Body, p: Param, values: &str, band: &Band) -> Result<Study, String> {
    let steps = study::parse_steps(values).map_err(|e| e.to_string())?;
    study::run(body, p, &steps, band).map_err(|e| e.to_string())
}

pub fn on_action(app: &mut App, a: Action) {
    let t = &mut app.study;
    let n = t.params.len().max(1);
    match a {
        Action::Left | Action::Right => {
            t.sel = if a == Action::Left {
                (t.sel + n - 1) % n
            } else {
                (t.sel + 1) % n
            };
            t.values = default_values(t.param()).into();
            t.rerun(&app.body, &app.preset.band);
        }
        Action::PaperStudy(which) => {
            let seat = app
                .body
                .links
                .iter()
                .position(|l| l.lower == biodyn::End::Seat);
            let want = match (which, seat) {
                (0, _) => Some(Param::BodyMass),
                (1, Some(i)) => Some(Param::Stiffness(i)),
                (2, Some(i)) => Some(Param::Damping(i)),
                _ => None,
            };
            if let Some(i) = want.and_then(|p| t.params.iter().position(|&q| q == p)) {
                t.sel = i;
                t.values = default_values(t.param()).into();
                t.rerun(&app.body, &app.preset.band);
            }
        }
        Action::ResetValues => {
            t.values = default_values(t.param()).into();
            t.rerun(&app.body, &app.preset.band);
        }
        Action::Edit => {
            let label = format!("values of {}", app.body.label(t.param()));
            app.field = Some(Field::new(Purpose::StudyValues, label, t.values.clone()));
        }
        Action::NextFunction => t.func = (t.func + 1) % 3,
        Action::ToggleLog => t.log = !t.log,
        _ => {}
    }
}

fn header(app: &App) -> Line<'static> {
    let th = app.theme;
    let t = &app.study;
    let p = t.param();
    let what = super::model::describe(&app.body, p);
    Line::from(vec![
        Span::styled("vary ", th.heading()),
        Span::styled(format!("◀ {what} ▶"), th.selected()),
        Span::raw(format!("  base {}  ", num(app.body.get(p), 5))),
        Span::styled("values ", th.heading()),
        Span::styled(t.values.clone(), th.field()),
    ])
}

pub fn render(app: &App, area: Rect, buf: &mut Buffer) {
    let th = app.theme;
    let t = &app.study;
    let study = match &t.result {
        Ok(s) => s,
        Err(e) => {
            let [h, rest] =
                Layout::vertical([Constraint::Length(1), Constraint::Min(1)]).areas(area);
            Paragraph::new(header(app)).render(h, buf);
            Paragraph::new(vec![
                Line::styled(format!("the study cannot run: {e}"), th.error()),
                Line::raw("Enter edits the values; r resets them; ←→ picks another parameter."),
            ])
            .wrap(Wrap { trim: true })
            .render(rest, buf);
            return;
        }
    };
    let sentences = area.height >= 34;
    let table_h = study.variants.len() as u16 + 7 + if sentences { 4 } else { 0 };
    let [h, charts, table] = Layout::vertical([
        Constraint::Length(1),
        Constraint::Min(6),
        Constraint::Length(table_h),
    ])
    .areas(area);
    Paragraph::new(header(app)).render(h, buf);
    let shown: Vec<usize> = if area.width >= SIDE_BY_SIDE {
        vec![0, 1, 2]
    } else {
        vec![t.func]
    };
    let areas = Layout::horizontal(vec![Constraint::Ratio(1, shown.len() as u32); shown.len()])
        .split(charts);
    for (slot, &fi) in shown.iter().enumerate() {
        let f = Function::ALL[fi];
        let title = if shown.len() == 1 {
            format!(
                "{} magnitude as {} varies (f: next function)",
                f.name(),
                study.param_label
            )
        } else {
            format!("{} magnitude", f.name())
        };
        let opts = ChartOpts {
            title,
            x_title: "f Hz".into(),
            y_title: magnitude_axis(f),
            log_x: t.log,
            log_y: t.log,
            ascii: th.ascii,
            mono: th.mono,
            cursor_x: None,
            marks: study
                .variants
                .iter()
                .filter_map(|v| v.peaks[fi])
                .filter(|p| !p.at_edge)
                .map(|p| (p.f_hz, p.mag))
                .collect(),
            y_range: None,
        };
        chart::render(areas[slot], buf, &t.series[fi], &opts);
    }
    render_table(app, study, table, buf, th, sentences);
}

fn render_table(
    app: &App,
    study: &Study,
    area: Rect,
    buf: &mut Buffer,
    th: Theme,
    sentences: bool,
) {
    let label_w = study
        .variants
        .iter()
        .map(|v| v.label.chars().count())
        .max()
        .unwrap_or(10)
        .clamp(14, 26)
        + 2;
    let inner = (area.width as usize).saturating_sub(2);
    let col_w = (inner.saturating_sub(label_w) / 3)
        .saturating_sub(1)
        .clamp(12, 30);
    let mut head = vec![Span::styled(
        format!("{:<label_w$}", "main peak"),
        th.heading(),
    )];
    for f in Function::ALL {
        let u = unit(f);
        let h = format!(
            "{} Hz, {}",
            f.name(),
            if u.is_empty() { "ratio" } else { u }
        );
        head.push(Span::styled(format!(" {h:>col_w$}"), th.heading()));
    }
    let mut lines = vec![Line::from(head)];
    for (i, v) in study.variants.iter().enumerate() {
        // The marker glyph makes this table the legend, also in NO_COLOR.
        let mut spans = vec![
            Span::styled(
                format!("{} ", chart::legend_glyph(i, th.ascii)),
                chart::series_style(i, th.mono),
            ),
            Span::raw(format!(
                "{:<w$}",
                clip(&v.label, label_w - 2),
                w = label_w - 2
            )),
        ];
        for p in &v.peaks {
            let text = match p {
                Some(p) if p.at_edge => format!("edge {}", num(p.mag, 4)),
                Some(p) => format!("{} Hz {}", num(p.f_hz, 3), num(p.mag, 4)),
                None => "-".into(),
            };
            spans.push(Span::raw(format!(" {text:>col_w$}")));
        }
        lines.push(Line::from(spans));
    }
    let trends = study.trends();
    let rising = format!("as {} rises:", study.param_label);
    lines.push(Line::styled(
        clip(&rising, label_w + 3 * (col_w + 1)),
        th.heading(),
    ));
    let row = |label: &str, cell: &dyn Fn(&Trend) -> String| {
        let mut spans = vec![Span::raw(format!("{label:<label_w$}"))];
        for t in &trends {
            spans.push(Span::raw(format!(" {:>col_w$}", cell(t))));
        }
        Line::from(spans)
    };
    lines.push(row("  peak magnitude", &|t| t.peak_mag.word().to_string()));
    lines.push(row("  peak frequency", &|t| t.peak_f.word().to_string()));
    lines.push(row("  band share up/down", &|t| {
        format!(
            "{}% / {}%",
            num(t.rises_share * 100.0, 2),
            num(t.falls_share * 100.0, 2)
        )
    }));
    if sentences {
        lines.push(Line::raw(""));
        for t in &trends {
            lines.push(Line::raw(sentence(&study.param_label, t)));
        }
    }
    let _ = app;
    Paragraph::new(lines)
        .block(
            Block::bordered()
                .border_set(th.border_set())
                .title(Span::styled(" peaks and trends ", th.heading())),
        )
        .render(area, buf);
}

/// "As k4 rises, the STHT peak rises and moves up in frequency; the curve
/// rises over 62 % of the band and falls over 30 %."
pub fn sentence(param: &str, t: &Trend) -> String {
    let mag = match t.peak_mag {
        Direction::Rises => "rises",
        Direction::Falls => "falls",
        Direction::Mixed => "goes up and down",
        Direction::Flat => "stays put",
    };
    let f = match t.peak_f {
        Direction::Rises => "moves up in frequency",
        Direction::Falls => "moves down in frequency",
        Direction::Mixed => "moves back and forth in frequency",
        Direction::Flat => "stays at the same frequency",
    };
    format!(
        "As {param} rises, the {} peak {mag} and {f}; the curve rises over {}% of the band and falls over {}%.",
        t.function.name(),
        num(t.rises_share * 100.0, 2),
        num(t.falls_share * 100.0, 2)
    )
}
