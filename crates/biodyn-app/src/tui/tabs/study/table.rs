//! The Study tab's table: each variant's main peak per function (the
//! chart's legend, marker glyphs included) and the trends, in words.

use crate::tui::theme::Theme;
use crate::tui::widgets::block;
use crate::view::chart;
use crate::view::trend::sentence;
use crate::view::format::{clip, num, unit};
use biodyn::Function;
use biodyn::freq::study::{Study, Trend};
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget};

/// Two or more different values: something to compare.
pub fn comparable(study: &Study) -> bool {
    study
        .variants
        .iter()
        .any(|v| study.variants.first().is_some_and(|f| f.value != v.value))
}

/// The peak rows from variant `top` on, as many as fit (the legend
/// scrolls, ↑↓), then the trends or why there are none. A short tab
/// draws it without its frame (two more rows).
pub fn render(
    study: &Study,
    area: Rect,
    buf: &mut Buffer,
    th: Theme,
    sentences: bool,
    top: usize,
    framed: bool,
) {
    let compare = comparable(study);
    // Below 100 columns "body mass = 65 kg" reads "65 kg": the heading
    // above names the parameter.
    let narrow = area.width < 100;
    let label = |l: &str| -> String {
        match l.split_once(" = ") {
            Some((_, v)) if narrow => v.to_string(),
            _ => l.to_string(),
        }
    };
    let label_w = study
        .variants
        .iter()
        .map(|v| label(&v.label).chars().count())
        .max()
        .unwrap_or(10)
        .clamp(if narrow { 10 } else { 14 }, 26)
        + 2;
    let [mag, freq, share] = if area.width < 70 {
        ["  peak mag", "  peak f", "  up/down"]
    } else {
        ["  peak magnitude", "  peak frequency", "  band share up/down"]
    };
    // The trend rows' names share the first column with the variants.
    let label_w = label_w.max(share.chars().count() + 1);
    let frame_rows = if framed { 2 } else { 0 };
    let inner = (area.width as usize).saturating_sub(frame_rows);
    let nf = Function::ALL.len();
    let col_w = (inner.saturating_sub(label_w) / nf)
        .saturating_sub(1)
        .clamp(12, 30);
    let n = study.variants.len();
    let below = if compare { 4 } else { 1 } + if sentences && compare { 4 } else { 0 };
    let rows = (area.height as usize)
        .saturating_sub(1 + frame_rows + below)
        .max(1)
        .min(n);
    let top = top.min(n - rows.min(n));
    let scrolled = if rows < n {
        format!(" — {}–{}/{n} ↑↓", top + 1, top + rows)
    } else {
        String::new()
    };
    // Without a frame the scroll position goes in the first heading cell.
    let first = if !framed && rows < n {
        format!("↑↓{}–{}/{n}", top + 1, top + rows)
    } else {
        "peak".to_string()
    };
    let mut head = vec![Span::styled(
        format!("{:<label_w$}", clip(&first, label_w)),
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
    for (i, v) in study.variants.iter().enumerate().skip(top).take(rows) {
        // The marker glyph makes this table the legend, also in NO_COLOR.
        let mut spans = vec![
            Span::styled(
                format!("{} ", chart::legend_glyph(i, th.ascii)),
                chart::series_style(i, th.mono),
            ),
            Span::raw(format!(
                "{:<w$}",
                clip(&label(&v.label), label_w - 2),
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
    if !compare {
        let what = if n == 1 { "one value" } else { "the values are all the same" };
        lines.push(Line::styled(
            format!(
                "{what}: nothing to compare. Enter gives two or more different values, e.g. 65,75,85 or -40%,0%,+40%."
            ),
            th.error(),
        ));
        let p = Paragraph::new(lines).wrap(ratatui::widgets::Wrap { trim: true });
        if framed {
            p.block(block(&format!("peaks{scrolled}"), th))
                .render(area, buf);
        } else {
            p.render(area, buf);
        }
        return;
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
    lines.push(row(mag, &|t| t.peak_mag.word().to_string()));
    lines.push(row(freq, &|t| t.peak_f.word().to_string()));
    lines.push(row(share, &|t| {
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
    let p = Paragraph::new(lines);
    if framed {
        p.block(block(&format!("main peaks and trends{scrolled}"), th))
            .render(area, buf);
    } else {
        p.render(area, buf);
    }
}
