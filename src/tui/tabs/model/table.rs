//! The Model tab's tables: body mass, segments (mass, share, head mark),
//! links (k, c, ends) and the description, scrolled to keep the selection
//! in view, so a model of hundreds of segments stays usable. `build` lays
//! the lines out once, with where each selectable cell sits, for both
//! drawing and the mouse's hit test.

use super::ModelTab;
use crate::tui::shared::Shared;
use crate::tui::widgets::{block, cell};
use crate::view::format::{NBSP, clip, fit, glue_units, num, wrap};
use biodyn::{End, Param};
use ratatui::buffer::Buffer;
use ratatui::layout::{Position, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget};

/// What a click on a part of a table line is about.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Target {
    /// A value cell: the selection's row and column (see `ModelTab`).
    Cell { row: usize, col: usize },
    /// A segment's or link's index and name (its row).
    Name(usize),
}

/// The tables as drawn: the lines, and per line the targets on it as
/// (first column, past-the-end column, target) from the line's start.
pub struct Tables {
    pub lines: Vec<Line<'static>>,
    pub targets: Vec<Vec<(u16, u16, Target)>>,
    pub title: String,
}

/// One line being built: its spans and the columns of its targets.
#[derive(Default)]
struct LineBuilder {
    spans: Vec<Span<'static>>,
    targets: Vec<(u16, u16, Target)>,
    x: u16,
}

impl LineBuilder {
    fn push(mut self, span: Span<'static>, target: Option<Target>) -> Self {
        let w = u16::try_from(span.width()).unwrap_or(u16::MAX);
        if let Some(t) = target {
            self.targets.push((self.x, self.x.saturating_add(w), t));
        }
        self.x = self.x.saturating_add(w);
        self.spans.push(span);
        self
    }
}

impl Tables {
    fn push(&mut self, l: LineBuilder) {
        self.lines.push(Line::from(l.spans));
        self.targets.push(l.targets);
    }

    fn plain(&mut self, l: Line<'static>) {
        self.lines.push(l);
        self.targets.push(Vec::new());
    }
}

/// The line a table row is drawn on: the body mass first, a blank and the
/// segment heading, the segments, a blank and the link heading, the links.
pub fn line_of(row: usize, segments: usize) -> usize {
    match row {
        0 => 0,
        r if r <= segments => 2 + r,
        r => 4 + r,
    }
}

/// The first line shown: `top` (where the view was left) moved the least
/// that shows the selected row, with the heading of the first segment or
/// link when it is the one selected; never past the last page.
pub fn scroll(t: &ModelTab, segments: usize, lines: usize, inner_h: usize) -> usize {
    let sel = line_of(t.row, segments);
    let inner_h = inner_h.max(1);
    let top = t.top.min(lines.saturating_sub(inner_h));
    if sel < top {
        // The first segment comes with the body mass and its heading, the
        // first link with its heading, where they fit.
        let context = if t.row == 1 {
            0
        } else if t.row == 1 + segments {
            sel - 1
        } else {
            sel
        };
        if sel < context + inner_h {
            context
        } else {
            sel
        }
    } else if sel >= top + inner_h {
        sel + 1 - inner_h
    } else {
        top
    }
}

pub fn build(t: &ModelTab, s: &Shared, area: Rect) -> Tables {
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
    let mut out = Tables {
        lines: Vec::new(),
        targets: Vec::new(),
        title: format!(
            "model: {}{}",
            s.preset.name,
            if s.modified() { " (modified)" } else { "" }
        ),
    };
    let body_cell = Some(Target::Cell { row: 0, col: 0 });
    out.push(
        LineBuilder::default()
            .push(Span::styled("body mass ", th.heading()), body_cell)
            .push(cell(fit(body_mass, 5, 8), 8, sel.row == 0, th), body_cell)
            .push(Span::raw(" kg"), body_cell)
            .push(
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
                None,
            ),
    );
    out.plain(Line::raw(""));
    out.plain(Line::styled(
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
        let row = i + 1;
        let head = match (&b.seat, seg.seat) {
            _ if i == b.head => "*",
            (Some(seat), true) if seat.pan == i => "P",
            (_, true) => "S",
            _ => " ",
        };
        let share_sel = sel.row == row && sel.col == 1;
        let share = match (share_col, seg.share) {
            (true, Some(sh)) => cell(format!("{}%", fit(sh * 100.0, 3, 6)), 7, share_sel, th),
            (true, None) => cell("–".into(), 7, share_sel, th),
            (false, _) => Span::raw(format!("{:>7}", "")),
        };
        out.push(
            LineBuilder::default()
                .push(
                    Span::raw(format!(
                        "m{:<seg_w$}{:<name_w$}",
                        i + 1,
                        clip(&seg.name, name_w)
                    )),
                    Some(Target::Name(row)),
                )
                .push(Span::raw(" "), None)
                .push(
                    cell(fit(seg.mass, 5, 10), 10, sel.row == row && sel.col == 0, th),
                    Some(Target::Cell { row, col: 0 }),
                )
                .push(Span::raw(" "), None)
                .push(share, share_col.then_some(Target::Cell { row, col: 1 }))
                .push(Span::raw(head), None),
        );
    }
    out.plain(Line::raw(""));
    out.plain(Line::styled(
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
            End::Seat if b.has_seat() => "floor".to_string(),
            End::Seat => "seat".to_string(),
            End::Segment(j) => b.segments.get(j).map_or("?".into(), |s| s.name.clone()),
        };
        let mut line = LineBuilder::default()
            .push(
                Span::raw(format!(
                    "{:<link_w$}{:<name_w$}",
                    i + 1,
                    clip(&l.name, name_w)
                )),
                Some(Target::Name(row)),
            )
            .push(Span::raw(" "), None)
            .push(
                cell(fit(l.k, 6, 10), 10, sel.row == row && sel.col == 0, th),
                Some(Target::Cell { row, col: 0 }),
            )
            .push(Span::raw(" "), None)
            .push(
                cell(fit(l.c, 6, 9), 9, sel.row == row && sel.col == 1, th),
                Some(Target::Cell { row, col: 1 }),
            );
        if let Some(seat) = &b.seat {
            let mark = if seat.suspension == i { "~" } else { " " };
            line = line.push(Span::raw(mark), None);
        }
        if wide {
            let upper = b.segments.get(l.upper).map_or("?", |s| s.name.as_str());
            line = line.push(Span::styled(format!("  {upper}–{lower}"), th.dim()), None);
        }
        out.push(line);
    }
    out.plain(Line::raw(""));
    out.plain(Line::styled(
        "* head (STHT). Masses: kg; k: N/m; c: N·s/m.",
        th.dim(),
    ));
    if b.has_seat() {
        out.plain(Line::styled(
            "P seat pan, S seat part (not body mass), ~ suspension",
            th.dim(),
        ));
    }
    if !s.preset.description.is_empty() {
        // Wrapped into the rows left free under the tables; cut (its last
        // row ending in "…") only where they run out.
        let room = usize::from(area.width.saturating_sub(2)).max(1);
        let free = usize::from(inner(s, area).height).saturating_sub(out.lines.len());
        let about = glue_units(&format!("about: {}", s.preset.description));
        let rows: Vec<String> = wrap(&about, room, true)
            .into_iter()
            .map(|r| r.replace(NBSP, " "))
            .collect();
        let keep = rows.len().min(free.max(1));
        for (i, row) in rows.iter().take(keep).enumerate() {
            let row = if i + 1 == keep && keep < rows.len() {
                clip(&rows[i..].join(" "), room)
            } else {
                row.clone()
            };
            out.plain(Line::styled(row, th.dim()));
        }
    }
    out
}

/// The area inside the tables' frame.
fn inner(s: &Shared, area: Rect) -> Rect {
    block("", s.theme).inner(area)
}

/// The first line shown in `area` (as `render_tables` draws it).
pub fn scroll_in(t: &ModelTab, s: &Shared, area: Rect) -> usize {
    let lines = build(t, s, area).lines.len();
    scroll(
        t,
        s.body.segments.len(),
        lines,
        usize::from(inner(s, area).height),
    )
}

/// The target under a screen position, as `render_tables` drew `area`.
pub fn hit(t: &ModelTab, s: &Shared, area: Rect, at: Position) -> Option<Target> {
    let inside = inner(s, area);
    if !inside.contains(at) {
        return None;
    }
    let tables = build(t, s, area);
    let top = scroll(
        t,
        s.body.segments.len(),
        tables.lines.len(),
        usize::from(inside.height),
    );
    let line = usize::from(at.y - inside.y) + top;
    let x = at.x - inside.x;
    tables
        .targets
        .get(line)?
        .iter()
        .find(|(from, to, _)| (*from..*to).contains(&x))
        .map(|&(_, _, target)| target)
}

pub fn render_tables(t: &ModelTab, s: &Shared, area: Rect, buf: &mut Buffer) {
    let tables = build(t, s, area);
    let inner_h = usize::from(inner(s, area).height);
    let top = scroll(t, s.body.segments.len(), tables.lines.len(), inner_h);
    Paragraph::new(tables.lines)
        .scroll((u16::try_from(top).unwrap_or(u16::MAX), 0))
        .block(block(&tables.title, s.theme))
        .render(area, buf);
}

/// Every segment of the body has a share of its mass (so the body mass is
/// editable); a seat's parts are not the body's and keep their masses.
pub(super) fn has_shares(b: &biodyn::Body) -> bool {
    b.segments.iter().filter(|s| !s.seat).all(|s| s.share.is_some())
}
