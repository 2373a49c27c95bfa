//! The assessment as the Vibration tab shows it: the ISO 2631-1 table with
//! a column per seat axis and one for the head, and the EU verdicts and
//! comfort words, each naming the axis they are of.
//!
//! Per axis (ISO 2631-1 §7.2, Directive 2002/44/EC Annex B) a_w, peak,
//! crest factor, MTVV and VDV are of the weighted signal before k; A(8) =
//! k·a_w·√(T_exp/8 h) and VDV over the exposure = k·VDV·(T_exp/T)^¼ after
//! it, so the A(8) row is what the Directive compares: the highest is the
//! day's (marked `*`). The head column is the model's, driven by z (Wk, no
//! k: the Directive judges the seat).

use super::compute::Outcome;
use super::glyphs::{fix, fix_lines};
use crate::tui::theme::Theme;
use crate::tui::widgets::{block, glued, unglue};
use crate::view::format::num;
use crate::view::report::day::hours_cell;
use biodyn::exposure::AxisReach;
use biodyn::iso2631::spine::Band;
use biodyn::iso2631::{A8_ACTION, A8_LIMIT, AxisResult, Channel, VDV_ACTION, VDV_LIMIT, Verdict};
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Style;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget, Wrap};

/// Width of the row labels and of each column: 12 + 4 × 8 = 44, the inner
/// width of the narrowest panel the table is drawn in.
const LABEL_W: usize = 12;
const COL_W: usize = 8;

/// One metric row: its label, the value of an axis, of the head, decimals.
struct Metric {
    label: String,
    axis: fn(&AxisResult) -> f64,
    head: fn(&Channel) -> f64,
    decimals: usize,
}

fn metric(
    label: &str,
    axis: fn(&AxisResult) -> f64,
    head: fn(&Channel) -> f64,
    decimals: usize,
) -> Metric {
    Metric {
        label: label.to_string(),
        axis,
        head,
        decimals,
    }
}

/// The table: a column per axis the record has (x, y, z order), then the
/// head; the axis with the day's A(8) marked when there are several.
pub(super) fn assessment(o: Option<&Outcome>, th: Theme, area: Rect, buf: &mut Buffer) {
    let Some(o) = o else {
        Paragraph::new("")
            .block(block("ISO 2631-1", th))
            .render(area, buf);
        return;
    };
    let r = &o.assessment;
    let axes: Vec<_> = r.axes.iter().collect();
    let several = axes.len() > 1;
    let cell = |s: String| format!("{s:>COL_W$}");
    let mut head = vec![Span::raw(format!("{:<LABEL_W$}", ""))];
    for (a, _) in &axes {
        let mark = if several && *a == r.health.a8_axis {
            " *"
        } else {
            ""
        };
        head.push(Span::raw(cell(format!("{a}{mark}"))));
    }
    head.push(Span::raw(cell("head".into())));
    let mut lines = vec![Line::from(head).style(th.heading())];
    let mut rule = vec![Span::raw(format!("{:<LABEL_W$}", "weighting, k"))];
    for (_, x) in &axes {
        let w = x.rule.weighting.name();
        rule.push(Span::raw(cell(format!("{w} {:.1}", x.rule.k_health))));
    }
    rule.push(Span::raw(cell(r.weighting.name().into())));
    lines.push(Line::from(rule));
    let exp = format!("VDV {} h", num(r.exposure_h, 4));
    let metrics = [
        metric("a_w m/s²", |x| x.metrics.aw, |c| c.metrics.aw, 3),
        metric("peak m/s²", |x| x.metrics.peak, |c| c.metrics.peak, 3),
        metric("crest factor", |x| x.metrics.crest, |c| c.metrics.crest, 2),
        metric("MTVV m/s²", |x| x.metrics.mtvv, |c| c.metrics.mtvv, 3),
        metric("VDV m/s^1.75", |x| x.metrics.vdv, |c| c.metrics.vdv, 2),
        metric("A(8) m/s²", |x| x.a8, |c| c.exposure.a8, 3),
        metric(&exp, |x| x.vdv_exposure, |c| c.exposure.vdv, 2),
    ];
    for m in &metrics {
        let d = m.decimals;
        // Fixed before padding: m/s² is one column longer as m/s^2.
        let label = fix(th, &m.label);
        let mut spans = vec![Span::raw(format!("{label:<LABEL_W$}"))];
        for (a, x) in &axes {
            let v = (m.axis)(x);
            // The Directive's figures in the verdict's colour on the axis
            // that sets them.
            let style = match m.label.as_str() {
                "A(8) m/s²" if several && *a == r.health.a8_axis => verdict_style(r.eu.a8, th),
                l if l == exp && several && *a == r.health.vdv_axis => {
                    verdict_style(r.eu.vdv, th)
                }
                _ => Style::default(),
            };
            spans.push(Span::styled(cell(format!("{v:.d$}")), style));
        }
        spans.push(Span::raw(cell(format!("{:.d$}", (m.head)(&r.head)))));
        lines.push(Line::from(spans));
    }
    let mark = if several { ", * highest A(8)" } else { "" };
    let title = format!("ISO 2631-1, {} h/day{mark}", num(r.exposure_h, 4));
    Paragraph::new(lines)
        .block(block(&title, th))
        .render(area, buf);
}

/// A verdict's style: the words carry the meaning, colour only adds to it.
fn verdict_style(v: Verdict, th: Theme) -> Style {
    match v {
        Verdict::BelowAction => th.ok(),
        Verdict::AboveAction => th.heading(),
        Verdict::AboveLimit => th.error(),
    }
}

/// The verdicts, comfort words and warnings; `brief` (a narrow left
/// column) keeps the verdicts short and counts the warnings, `s` shows
/// them all with the comfort vector sum.
pub(super) fn verdict_lines(
    o: Option<&Outcome>,
    th: Theme,
    area: Rect,
    buf: &mut Buffer,
    brief: bool,
) {
    let Some(o) = o else {
        Paragraph::new("")
            .block(block("EU 2002/44/EC (seat)", th))
            .render(area, buf);
        return;
    };
    let r = &o.assessment;
    let h = &r.health;
    // As `biodyn assess` words them; brief: the axis first, no unit.
    let (a8, vdv) = if brief {
        (
            format!("A(8) {} {:.3}: ", h.a8_axis, h.a8),
            format!("VDV {} {:.2}: ", h.vdv_axis, h.vdv_exposure),
        )
    } else {
        (
            format!("A(8) {:.3} m/s² ({}): ", h.a8, h.a8_axis),
            format!("VDV {:.2} m/s^1.75 ({}): ", h.vdv_exposure, h.vdv_axis),
        )
    };
    let mut lines = vec![
        Line::from(vec![
            Span::raw(a8),
            Span::styled(h.eu.a8.words(), verdict_style(h.eu.a8, th)),
        ]),
        Line::from(vec![
            Span::raw(vdv),
            Span::styled(h.eu.vdv.words(), verdict_style(h.eu.vdv, th)),
        ]),
    ];
    let n = r.warnings.len();
    if brief && n > 0 {
        let line = format!("! {n} warning{}: s shows", if n == 1 { "" } else { "s" });
        lines.push(Line::styled(line, th.heading()));
    } else if !brief {
        lines.extend(
            r.warnings
                .iter()
                .map(|w| Line::styled(format!("! {w}"), th.heading())),
        );
    }
    lines.extend(spine_lines(r, th, brief));
    let seat = if brief {
        format!("comfort seat: {}", r.comfort_seat.join(" / "))
    } else {
        format!(
            "comfort seat, vector sum {:.3} m/s²: {}",
            r.comfort_vector,
            r.comfort_seat.join(" / ")
        )
    };
    lines.push(Line::raw(seat));
    lines.push(Line::raw(format!(
        "comfort head: {}",
        r.comfort_head.join(" / ")
    )));
    if !brief {
        lines.push(Line::raw(sickness_line(&r.sickness_seat, r.exposure_h)));
        lines.push(Line::styled(
            format!(
                "EU action/limit: A(8) {A8_ACTION}/{A8_LIMIT} m/s², VDV {VDV_ACTION}/{VDV_LIMIT} m/s^1.75"
            ),
            th.dim(),
        ));
        // The HSE reading, as `biodyn assess` prints it (exposure::AxisReach).
        lines.push(Line::raw("HSE points; hours to EAV/ELV; VDV EAV/ELV:"));
        for (a, x) in r.axes.iter() {
            let h = AxisReach::of(x);
            lines.push(Line::raw(format!(
                "{a} {:.0} pts; {}/{} h; {}/{} h",
                h.points,
                hours_cell(h.hours_to_eav),
                hours_cell(h.hours_to_elv),
                hours_cell(h.vdv.to_eav),
                hours_cell(h.vdv.to_elv),
            )));
        }
    }
    Paragraph::new(glued(fix_lines(th, lines)))
        .wrap(Wrap { trim: true })
        .block(block(&fix(th, "EU 2002/44/EC (seat), comfort"), th))
        .render(area, buf);
    unglue(area, buf);
}

/// ISO 2631-5's lines when the spine is asked for: R, P and the band in
/// words (brief: R, P and the band's name), or why it cannot be judged.
/// The seat's motion sickness in one line. The share first: with "MSDV
/// 32.14 m/s^1.5" kept on one row the line still takes two rows in the
/// panel's 44 columns. Past ISO 2631-1 Annex D's 70 %, its words, not the
/// number.
pub(super) fn sickness_line(sk: &biodyn::iso2631::Sickness, exposure_h: f64) -> String {
    let share = if sk.beyond_annex_d {
        format!("{} (past Annex D's range)", sk.vomit_share())
    } else {
        format!("{:.1} %", sk.vomit_pct)
    };
    format!(
        "motion sickness (Wf, seat z): {share} may vomit, MSDV {:.2} m/s^1.5 over {} h",
        sk.msdv_exposure,
        num(exposure_h, 4)
    )
}

fn spine_lines(r: &biodyn::iso2631::Assessment, th: Theme, brief: bool) -> Vec<Line<'static>> {
    let style = |b: Band| match b {
        Band::Low => th.ok(),
        Band::Moderate => th.heading(),
        Band::High | Band::VeryHigh => th.error(),
    };
    match &r.spine {
        None => Vec::new(),
        Some(Err(e)) => vec![Line::styled(format!("! ISO 2631-5: {e}"), th.error())],
        Some(Ok(sp)) if brief => vec![Line::from(vec![
            Span::raw(format!("spine R {:.2} P {:.2}: ", sp.risk.r, sp.risk.probability)),
            Span::styled(sp.risk.band.name(), style(sp.risk.band)),
        ])],
        Some(Ok(sp)) => {
            let mut v = vec![
                Line::raw(format!(
                    "ISO 2631-5 (spine, {}): {} peaks, Dz {:.2}, Dzd {:.2} m/s², Sd {:.3} MPa",
                    sp.person,
                    sp.dose.count,
                    sp.dose.dz,
                    sp.dzd,
                    sp.risk.sd
                )),
                Line::from(vec![
                    Span::raw(format!("R {:.2}, P {:.2}: ", sp.risk.r, sp.risk.probability)),
                    Span::styled(sp.risk.band.words(), style(sp.risk.band)),
                ]),
            ];
            v.extend(sp.notes.iter().map(|n| Line::styled(format!("! spine: {n}"), th.heading())));
            v
        }
    }
}
