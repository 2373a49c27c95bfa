//! Tab Study: one parameter varied over a list of values, the curves
//! overlaid with a legend (the paper's Figures 2–4), the peak table, and the
//! direction of change of each function spelled out from `Study::trends`.

use crate::tui::component::{Change, Cx, Tab};
use crate::tui::derived::in_background;
use crate::tui::effect::Effect;
use crate::tui::field::{Field, Purpose};
use crate::tui::keys::{self, Binding, Doc, b, code, k};
use crate::tui::shared::Shared;
use crate::tui::theme::Theme;
use crate::tui::widgets::{SIDE_BY_SIDE, block};
use crate::view::chart::{self, ChartOpts, Series};
use crate::view::format::{clip, magnitude_axis, num, unit};
use biodyn::freq::study::{self, Direction, Study, Trend};
use biodyn::{Band, Body, Function, Param};
use ratatui::buffer::Buffer;
use ratatui::crossterm::event::{KeyCode as KC, KeyEvent};
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget, Wrap};
use std::any::Any;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Action {
    Left,
    Right,
    Paper(PaperStudy),
    Edit,
    Reset,
    NextFunction,
    ToggleLog,
}

/// The paper's three studies.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum PaperStudy {
    BodyMass,
    SeatK,
    SeatC,
}

static KEYS: &[Binding<Action>] = &[
    b(
        &[code(KC::Left), k('h')],
        Action::Left,
        "previous parameter",
        Some("←→ parameter"),
    ),
    b(
        &[code(KC::Right), k('l')],
        Action::Right,
        "next parameter",
        None,
    ),
    b(
        &[k('m')],
        Action::Paper(PaperStudy::BodyMass),
        "the paper's body-mass study: 65,75,85 kg",
        Some("m/k/c paper"),
    ),
    b(
        &[k('k')],
        Action::Paper(PaperStudy::SeatK),
        "the paper's k4 study (seat link): -40%,0%,+40%",
        None,
    ),
    b(
        &[k('c')],
        Action::Paper(PaperStudy::SeatC),
        "the paper's c4 study (seat link): -40%,0%,+40%",
        None,
    ),
    b(
        &[code(KC::Enter), k('e')],
        Action::Edit,
        "edit the values: 65,75,85 or -40%,0%,+40%",
        Some("Enter values"),
    ),
    b(
        &[k('r')],
        Action::Reset,
        "reset the value list to the paper's",
        Some("r reset"),
    ),
    b(
        &[k('f')],
        Action::NextFunction,
        "next function (when one chart is shown)",
        Some("f function"),
    ),
    b(
        &[k('a')],
        Action::ToggleLog,
        "linear / log axes",
        Some("a lin/log"),
    ),
];

/// The field tag of the value list.
const VALUES: usize = 0;

/// A study computed in the background, for model generation `generation`.
struct Done {
    generation: u64,
    result: Result<Study, String>,
}

#[derive(Debug, Clone)]
pub struct StudyTab {
    /// Body mass, then m1.., k1.., c1.. of the current model.
    pub params: Vec<Param>,
    pub sel: usize,
    /// The value list as typed: "65,75,85" or "-40%,0%,+40%".
    pub values: String,
    /// None while a large model's study runs in the background.
    pub result: Option<Result<Study, String>>,
    /// Curves per function (`Function::ALL` order), one series per variant.
    pub series: Vec<Vec<Series>>,
    /// The function shown when only one chart fits.
    pub func: usize,
    pub log: bool,
    /// Counts the runs, so a late background result for an older one is dropped.
    generation: u64,
}

/// The paper's lists: 65/75/85 kg, and base value ±40 % for k4 and c4.
pub fn default_values(p: Param) -> &'static str {
    match p {
        Param::BodyMass => "65,75,85",
        _ => "-40%,0%,+40%",
    }
}

impl StudyTab {
    pub fn for_body(body: &Body) -> StudyTab {
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
        let values = params.get(sel).map_or("", |&p| default_values(p)).into();
        StudyTab {
            sel,
            values,
            params,
            result: Some(Err("not run yet".into())),
            series: Vec::new(),
            func: 0,
            log: false,
            generation: 0,
        }
    }

    pub fn param(&self) -> Param {
        self.params
            .get(self.sel)
            .copied()
            .unwrap_or(Param::BodyMass)
    }

    /// Runs the study on the current body: at once for a small model, on a
    /// thread for a large one (the result comes back through the mailbox).
    fn rerun(&mut self, cx: &Cx) {
        self.generation += 1;
        let s = cx.shared;
        let (body, p, values, band) = (s.body.clone(), self.param(), self.values.clone(), *s.band());
        if in_background(&body)
            && let Some((tx, wrap)) = cx.mailbox.wrap::<Done>()
        {
            self.result = None;
            self.series.clear();
            let generation = self.generation;
            let spawned = std::thread::Builder::new()
                .name("study".into())
                .spawn(move || {
                    let result = compute(&body, p, &values, &band);
                    let _ = tx.send(wrap(Done { generation, result }));
                });
            if let Err(e) = spawned {
                self.set_result(Err(format!("cannot start the study: {e}")));
            }
            return;
        }
        self.set_result(compute(&body, p, &values, &band));
    }

    fn set_result(&mut self, result: Result<Study, String>) {
        self.series = match &result {
            Ok(st) => Function::ALL
                .iter()
                .map(|&f| {
                    st.variants
                        .iter()
                        .map(|v| Series {
                            name: v.label.clone(),
                            points: v.curve.iter().map(|r| (r.f_hz, r.mag(f))).collect(),
                        })
                        .collect()
                })
                .collect(),
            Err(_) => Vec::new(),
        };
        self.result = Some(result);
    }

    fn select(&mut self, i: usize, cx: &Cx) {
        self.sel = i;
        self.values = default_values(self.param()).into();
        self.rerun(cx);
    }

    fn act(&mut self, a: Action, cx: &Cx) -> Vec<Effect> {
        let n = self.params.len().max(1);
        match a {
            Action::Left => self.select((self.sel + n - 1) % n, cx),
            Action::Right => self.select((self.sel + 1) % n, cx),
            Action::Paper(which) => {
                let body = &cx.shared.body;
                let seat = body.links.iter().position(|l| l.lower == biodyn::End::Seat);
                let want = match (which, seat) {
                    (PaperStudy::BodyMass, _) => Some(Param::BodyMass),
                    (PaperStudy::SeatK, Some(i)) => Some(Param::Stiffness(i)),
                    (PaperStudy::SeatC, Some(i)) => Some(Param::Damping(i)),
                    _ => None,
                };
                if let Some(i) = want.and_then(|p| self.params.iter().position(|&q| q == p)) {
                    self.select(i, cx);
                }
            }
            Action::Reset => {
                self.values = default_values(self.param()).into();
                self.rerun(cx);
            }
            Action::Edit => {
                let label = format!("values of {}", cx.shared.body.label(self.param()));
                return vec![Effect::OpenField(Field::new(
                    Purpose::Tab(VALUES),
                    label,
                    self.values.clone(),
                ))];
            }
            Action::NextFunction => self.func = (self.func + 1) % Function::ALL.len(),
            Action::ToggleLog => self.log = !self.log,
        }
        Vec::new()
    }
}

fn compute(body: &Body, p: Param, values: &str, band: &Band) -> Result<Study, String> {
    let steps = study::parse_steps(values).map_err(|e| e.to_string())?;
    study::run(body, p, &steps, band).map_err(|e| e.to_string())
}

impl Tab for StudyTab {
    fn new(shared: &Shared) -> Self {
        StudyTab::for_body(&shared.body)
    }

    fn title(&self) -> &'static str {
        "Study"
    }

    fn keys(&self) -> Vec<&'static Doc> {
        keys::docs(KEYS)
    }

    fn on_key(&mut self, ev: &KeyEvent, cx: &Cx) -> Option<Vec<Effect>> {
        keys::lookup(KEYS, ev).map(|a| self.act(a, cx))
    }

    /// Takes a new value list if it parses (and, for a small model, runs);
    /// otherwise says why and keeps the old one.
    fn commit(&mut self, _tag: usize, text: &str, cx: &Cx) -> Result<Vec<Effect>, String> {
        let s = cx.shared;
        if in_background(&s.body) {
            study::parse_steps(text).map_err(|e| e.to_string())?;
        } else {
            compute(&s.body, self.param(), text, s.band())?;
        }
        self.values = text.trim().to_string();
        self.rerun(cx);
        Ok(Vec::new())
    }

    fn on_change(&mut self, change: Change, cx: &Cx) {
        match change {
            Change::Loaded => {
                *self = StudyTab::for_body(&cx.shared.body);
                self.rerun(cx);
            }
            Change::Edited => self.rerun(cx),
            Change::Derived => {}
        }
    }

    fn on_msg(&mut self, msg: Box<dyn Any + Send>, _cx: &Cx) -> Vec<Effect> {
        if let Ok(done) = msg.downcast::<Done>()
            && done.generation == self.generation
        {
            self.set_result(done.result);
        }
        Vec::new()
    }

    fn render(&self, s: &Shared, area: Rect, buf: &mut Buffer) {
        render(self, s, area, buf);
    }
}

fn header(t: &StudyTab, s: &Shared) -> Line<'static> {
    let th = s.theme;
    let p = t.param();
    Line::from(vec![
        Span::styled("vary ", th.heading()),
        Span::styled(format!("◀ {} ▶", s.describe(p)), th.selected()),
        Span::raw(format!("  base {}  ", num(s.body.get(p), 5))),
        Span::styled("values ", th.heading()),
        Span::styled(t.values.clone(), th.field()),
    ])
}

fn render(t: &StudyTab, s: &Shared, area: Rect, buf: &mut Buffer) {
    let th = s.theme;
    let study = match &t.result {
        Some(Ok(st)) => st,
        other => {
            let [h, rest] =
                Layout::vertical([Constraint::Length(1), Constraint::Min(1)]).areas(area);
            Paragraph::new(header(t, s)).render(h, buf);
            let lines = match other {
                Some(Err(e)) => vec![
                    Line::styled(format!("the study cannot run: {e}"), th.error()),
                    Line::raw(
                        "Enter edits the values; r resets them; ←→ picks another parameter.",
                    ),
                ],
                _ => vec![Line::styled(
                    format!(
                        "computing the study of {} segments in the background… (q quits)",
                        s.body.segments.len()
                    ),
                    th.dim(),
                )],
            };
            Paragraph::new(lines)
                .wrap(Wrap { trim: true })
                .render(rest, buf);
            return;
        }
    };
    let sentences = area.height >= 34;
    let table_h = u16::try_from(study.variants.len())
        .unwrap_or(u16::MAX)
        .saturating_add(7 + if sentences { 4 } else { 0 });
    let [h, charts, table] = Layout::vertical([
        Constraint::Length(1),
        Constraint::Min(6),
        Constraint::Length(table_h),
    ])
    .areas(area);
    Paragraph::new(header(t, s)).render(h, buf);
    let shown: Vec<usize> = if area.width >= SIDE_BY_SIDE {
        (0..Function::ALL.len()).collect()
    } else {
        vec![t.func]
    };
    let n = u32::try_from(shown.len()).unwrap_or(1);
    let areas = Layout::horizontal(vec![Constraint::Ratio(1, n); shown.len()]).split(charts);
    for (&fi, &cell) in shown.iter().zip(areas.iter()) {
        let (Some(&f), Some(series)) = (Function::ALL.get(fi), t.series.get(fi)) else {
            continue;
        };
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
                .filter_map(|v| v.peaks.get(fi).copied().flatten())
                .filter(|p| !p.at_edge)
                .map(|p| (p.f_hz, p.mag))
                .collect(),
            y_range: None,
        };
        chart::render(cell, buf, series, &opts);
    }
    render_table(study, table, buf, th, sentences);
}

fn render_table(study: &Study, area: Rect, buf: &mut Buffer, th: Theme, sentences: bool) {
    let label_w = study
        .variants
        .iter()
        .map(|v| v.label.chars().count())
        .max()
        .unwrap_or(10)
        .clamp(14, 26)
        + 2;
    let inner = (area.width as usize).saturating_sub(2);
    let nf = Function::ALL.len();
    let col_w = (inner.saturating_sub(label_w) / nf)
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
        clip(&rising, label_w + nf * (col_w + 1)),
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
    Paragraph::new(lines)
        .block(block("peaks and trends", th))
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
