//! The Model tab's tables: body mass, segments (mass, share, head mark),
//! links (k, c, ends) and the description, scrolled to keep the selection
//! in view, so a model of hundreds of segments stays usable.

use super::{ModelTab, has_shares};
use crate::tui::shared::Shared;
use crate::tui::widgets::{block, cell};
use crate::view::format::{clip, num};
use biodyn::{End, Param};
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget};

pub fn render_tables(t: &ModelTab, s: &Shared, area: Rect, buf: &mut Buffer) {
    let th = s.theme;
    let b = &s.body;
    let sel = t;
    let wide = area.width >= 70;
    let name_w = b
        .segments
        .iter()
        .map(|s| s.name.chars().count())
        .chain(b.links.iter().map(|l| l.name.chars().count()))
        .max()
        .unwrap_or(4)
        .clamp(4, if wide { 24 } else { 18 });
    // Row labels as wide as the largest index needs: "m1 ", "m400 ".
    let digits = |n: usize| n.max(1).to_string().len();
    let seg_w = digits(b.segments.len()) + 1;
    let link_w = digits(b.links.len()) + 2;
    let body_mass = b.get(Param::BodyMass);
    let seated = b.seated_mass();
    let shares = has_shares(b);
    // Shares are shown (and editable) whenever the model has a body mass.
    let share_col = shares || b.body_mass.is_some();
    let mut lines = vec![Line::from(vec![
        Span::styled("body mass ", th.heading()),
        cell(num(body_mass, 5), 8, sel.row == 0, th),
        Span::raw(" kg"),
        Span::styled(
            match (shares, wide) {
                (true, true) => {
                    format!("  seated {} kg; an edit rescales by share", num(seated, 4))
                }
                (true, false) => format!("  seated {} kg", num(seated, 4)),
                (false, _) => format!("  = m1+…+m{} (no shares)", b.segments.len()),
            },
            th.dim(),
        ),
    ])];
    lines.push(Line::raw(""));
    lines.push(Line::styled(
        format!(
            "{:w$}{:<name_w$} {:>10} {:>7}",
            "",
            "segment",
            "mass kg",
            if share_col { "share" } else { "" },
            w = seg_w + 1
        ),
        th.heading(),
    ));
    for (i, seg) in b.segments.iter().enumerate() {
        let head = if i == b.head { "*" } else { " " };
        let share_sel = sel.row == i + 1 && sel.col == 1;
        lines.push(Line::from(vec![
            Span::raw(format!(
                "m{:<seg_w$}{:<name_w$}",
                i + 1,
                clip(&seg.name, name_w)
            )),
            Span::raw(" "),
            cell(num(seg.mass, 5), 10, sel.row == i + 1 && sel.col == 0, th),
            Span::raw(" "),
            match (share_col, seg.share) {
                (true, Some(sh)) => cell(format!("{}%", num(sh * 100.0, 3)), 7, share_sel, th),
                (true, None) => cell("–".into(), 7, share_sel, th),
                (false, _) => Span::raw(format!("{:>7}", "")),
            },
            Span::raw(head),
        ]));
    }
    lines.push(Line::raw(""));
    lines.push(Line::styled(
        format!(
            "{:link_w$}{:<name_w$} {:>10} {:>9}{}",
            "",
            "link",
            "k N/m",
            "c N·s/m",
            if wide { "  joins" } else { "" }
        ),
        th.heading(),
    ));
    let n = b.segments.len();
    for (i, l) in b.links.iter().enumerate() {
        let row = 1 + n + i;
        let lower = match l.lower {
            End::Seat => "seat".to_string(),
            End::Segment(j) => b.segments.get(j).map_or("?".into(), |s| s.name.clone()),
        };
        let mut spans = vec![
            Span::raw(format!(
                "{:<link_w$}{:<name_w$}",
                i + 1,
                clip(&l.name, name_w)
            )),
            Span::raw(" "),
            cell(num(l.k, 6), 10, sel.row == row && sel.col == 0, th),
            Span::raw(" "),
            cell(num(l.c, 6), 9, sel.row == row && sel.col == 1, th),
        ];
        if wide {
            let upper = b.segments.get(l.upper).map_or("?", |s| s.name.as_str());
            spans.push(Span::styled(format!("  {upper}–{lower}"), th.dim()));
        }
        lines.push(Line::from(spans));
    }
    lines.push(Line::raw(""));
    lines.push(Line::styled(
        "* head (STHT). Masses: kg; k: N/m; c: N·s/m.",
        th.dim(),
    ));
    if !s.preset.description.is_empty() {
        let room = usize::from(area.width.saturating_sub(2));
        lines.push(Line::styled(
            clip(&format!("about: {}", s.preset.description), room),
            th.dim(),
        ));
    }
    let title = format!(
        "model: {}{}",
        s.preset.name,
        if s.modified() { " (modified)" } else { "" }
    );
    // Keep the selected row in view on a short terminal.
    let sel_line = match sel.row {
        0 => 0,
        r if r <= n => 2 + r,
        r => 4 + r,
    };
    let inner = area.height.saturating_sub(2) as usize;
    let scroll = (sel_line + 1).saturating_sub(inner);
    Paragraph::new(lines)
        .scroll((u16::try_from(scroll).unwrap_or(u16::MAX), 0))
        .block(block(&title, th))
        .render(area, buf);
}

