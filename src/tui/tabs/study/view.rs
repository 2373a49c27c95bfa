//! Drawing the Study tab: the header, one chart per shown function with
//! every variant's curve, their peaks and the frequency cursor, and the
//! legend table with the values at the cursor (zoomed: one readout line
//! instead). `chart` is shared with the mouse, so a click lands on what
//! was drawn. Reads state; changes nothing.

use super::layout::layout;
use super::{StudyTab, table};
use crate::tui::keys;
use crate::tui::shared::Shared;
use crate::view::chart::{self, ChartOpts, Series};
use crate::view::format::{axis_title, clip, num, unit};
use biodyn::Function;
use biodyn::freq::Study;
use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget, Wrap};

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

/// The series and options of function `fi`'s chart; `one` when it is the
/// only chart shown (its title then says `f` shows the next).
pub(super) fn chart<'a>(
    t: &'a StudyTab,
    s: &Shared,
    study: &Study,
    fi: usize,
    one: bool,
) -> Option<(&'a [Series], ChartOpts)> {
    let (f, series) = (Function::ALL.get(fi)?, t.series.get(fi)?);
    let title = if one {
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
        y_title: axis_title(*f, false),
        log_x: t.log,
        log_y: t.log,
        ascii: s.theme.ascii,
        mono: s.theme.mono,
        cursor_x: t.cursor.f_hz,
        marks: study
            .variants
            .iter()
            .filter_map(|v| v.peaks.get(fi).copied().flatten())
            .filter(|p| !p.at_edge)
            .map(|p| (p.f_hz, p.mag))
            .collect(),
        y_range: None,
    };
    Some((series, opts))
}

/// "f 4.6 Hz  STHT  ⣿ 65 kg 1.734  • 75 kg 1.815 …": the current chart's
/// values at the cursor, from the legend's first shown variant on (zoomed,
/// or too narrow for the legend's cursor column). Names as short as the
/// legend's glyphs allow ("-40%" of "k4 B.V. -40% (54000)"), the unit once.
fn readout_line(t: &StudyTab, s: &Shared, study: &Study, width: u16) -> Line<'static> {
    let th = s.theme;
    let Some(f_hz) = t.cursor.f_hz else {
        return Line::raw("");
    };
    let f = Function::ALL.get(t.func).copied().unwrap_or(Function::Stht);
    let u = unit(f);
    let mut spans = vec![
        Span::styled(format!("f {} Hz", num(f_hz, 6)), th.heading()),
        Span::raw("  "),
        Span::styled(
            if u.is_empty() {
                f.name().to_string()
            } else {
                format!("{}, {u}", f.name())
            },
            th.key(),
        ),
    ];
    let mut used = spans.iter().map(|s| s.content.chars().count()).sum::<usize>();
    let top = t.legend_top.min(study.variants.len().saturating_sub(1));
    let more_text = keys::arrows(MORE, th.ascii);
    for (i, v) in study.variants.iter().enumerate().skip(top) {
        let value = t
            .cursor
            .at
            .get(i)
            .copied()
            .flatten()
            .map_or("-".into(), |r| num(r.mag(f), 4));
        let text = format!(" {} {value}", tag(&v.label, &study.param_label));
        let n = 2 + chart::legend_glyph(i, th.ascii).chars().count() + text.chars().count();
        // The rest are a ↓ away (the line starts at the legend's first row);
        // keep room to say so unless this is the last.
        let more = if i + 1 < study.variants.len() { more_text.chars().count() } else { 0 };
        if used + n + more > usize::from(width) {
            spans.push(Span::styled(
                clip(&more_text, usize::from(width).saturating_sub(used)),
                th.dim(),
            ));
            break;
        }
        spans.push(Span::raw("  "));
        spans.push(Span::styled(
            chart::legend_glyph(i, th.ascii),
            chart::series_style(i, th.mono),
        ));
        spans.push(Span::raw(text));
        used += n;
    }
    Line::from(spans)
}

/// A variant's name at its shortest: "65 kg" of "body mass = 65 kg",
/// "-40%" of "k4 B.V. -40% (54000)", "B.V." of "k4 B.V. (90000)".
fn tag<'a>(label: &'a str, param: &str) -> &'a str {
    let l = table::row_label(label, param, true, true);
    match l.strip_prefix("B.V. ") {
        Some(rest) if rest.starts_with(['+', '-']) => {
            rest.split_whitespace().next().unwrap_or(l)
        }
        Some(_) => "B.V.",
        None => l,
    }
}

/// What ends the readout line when the rest of the variants do not fit
/// (the key that shows them; spelt out in ASCII).
const MORE: &str = "  ↓ more";

/// The tab; `zoom` gives the chart everything below the header and the
/// readout line.
pub(super) fn render(t: &StudyTab, s: &Shared, area: Rect, buf: &mut Buffer, zoom: bool) {
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
                    Line::raw(keys::arrows(
                        "Enter edits the values; r resets them; ←→ picks another parameter.",
                        th.ascii,
                    )),
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
    let l = layout(t, study, area, zoom);
    Paragraph::new(header(t, s)).render(l.header, buf);
    if l.readout.height > 0 {
        Paragraph::new(readout_line(t, s, study, l.readout.width)).render(l.readout, buf);
    }
    let one = l.charts.len() == 1;
    for &(fi, cell) in &l.charts {
        if let Some((series, opts)) = chart(t, s, study, fi, one) {
            chart::render(cell, buf, series, &opts);
        }
    }
    if !zoom {
        let in_table = t.cursor.f_hz.filter(|_| l.readout.height == 0);
        let readout = in_table.map(|f_hz| table::Readout {
            f_hz,
            functions: l
                .charts
                .iter()
                .filter_map(|&(fi, _)| Function::ALL.get(fi).copied())
                .collect(),
            at: &t.cursor.at,
        });
        let shape = table::Shape {
            sentences: l.sentences,
            top: t.legend_top,
            framed: l.framed,
        };
        table::render(study, l.table, buf, th, shape, readout);
    }
}
