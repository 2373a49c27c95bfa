//! Structural edits of a body: add and remove segments and links, rename,
//! choose the head, set a share. Each returns the new body (the app checks
//! it as a preset is checked before it replaces the model) and a name for
//! the undo step. Indices in links and the head follow every removal.

use crate::view::format::num;
use biodyn::{Body, End, Link, Segment};

/// Stiffness and damping a new link gets when none is typed: the paper's
/// pelvis–seat link (k4, c4), a plausible soft seated-body joint.
pub const NEW_K: f64 = 90_000.0;
pub const NEW_C: f64 = 2_064.0;

/// A number typed in a structure field, or why not.
fn number(t: &str, what: &str) -> Result<f64, String> {
    t.parse()
        .map_err(|_| format!("{what} '{t}' is not a number (write e.g. 5 or 1.5e5)"))
}

/// The segment index of a name, or the base ("seat", or "floor" under a
/// seat model, as the preset file names it).
fn end_of(body: &Body, name: &str) -> Result<End, String> {
    if name == "seat" || name == "floor" {
        return Ok(End::Seat);
    }
    body.segments
        .iter()
        .position(|s| s.name == name)
        .map(End::Segment)
        .ok_or_else(|| format!("'{name}' is neither a segment name nor \"seat\""))
}

fn end_name(body: &Body, e: End) -> String {
    match e {
        End::Seat if body.has_seat() => "floor".into(),
        End::Seat => "seat".into(),
        End::Segment(j) => body.segments.get(j).map_or("?".into(), |s| s.name.clone()),
    }
}

/// A name not yet taken, `stem`, `stem2`, `stem3`, …
pub fn free_name(taken: impl Fn(&str) -> bool, stem: &str) -> String {
    (1..)
        .map(|i| {
            if i == 1 {
                stem.to_string()
            } else {
                format!("{stem}{i}")
            }
        })
        .find(|n| !taken(n))
        .unwrap_or_else(|| stem.to_string())
}

/// The pre-filled text of the add-segment field: a free name, 5 kg, hung
/// on `on` (a segment name or "seat") with the default link.
pub fn add_segment_template(body: &Body, on: &str) -> String {
    let name = free_name(|n| body.segments.iter().any(|s| s.name == n), "segment");
    format!("{name} 5 {on} {NEW_K} {NEW_C}")
}

/// `name mass_kg lower [k c]`: a new segment (last in the table) and the
/// link that ties it to `lower`. With a body mass and shares on every
/// segment, it gets the share its mass is of the body mass, so the body
/// mass stays editable.
pub fn add_segment(body: &Body, text: &str) -> Result<(Body, String), String> {
    let words: Vec<&str> = text.split_whitespace().collect();
    let [name, mass, lower, rest @ ..] = words.as_slice() else {
        return Err("write: name mass_kg lower [k c], e.g. arm 5 chest 90000 2064".into());
    };
    let mass = number(mass, "mass")?;
    let lower = end_of(body, lower)?;
    let (k, c) = match rest {
        [] => (NEW_K, NEW_C),
        [k, c] => (number(k, "k")?, number(c, "c")?),
        _ => return Err("give both k and c, or neither".into()),
    };
    let mut next = body.clone();
    let shares = body.body_mass.is_some() && body.segments.iter().all(|s| s.share.is_some());
    next.segments.push(Segment {
        name: (*name).to_string(),
        mass,
        share: match (shares, body.body_mass) {
            (true, Some(bm)) => Some(mass / bm),
            _ => None,
        },
        seat: false,
    });
    let upper = next.segments.len() - 1;
    let link = free_name(
        |n| next.links.iter().any(|l| l.name == n),
        &format!("{name}-{}", end_name(&next, lower)),
    );
    next.links.push(Link::new(&link, upper, lower, k, c));
    Ok((next, format!("add segment '{name}' (link '{link}')")))
}

/// `upper lower k c [name]`: a new link (last in the table).
pub fn add_link(body: &Body, text: &str) -> Result<(Body, String), String> {
    let words: Vec<&str> = text.split_whitespace().collect();
    let [upper, lower, k, c, name @ ..] = words.as_slice() else {
        return Err("write: upper lower k c [name], e.g. arm pelvis 1e5 500".into());
    };
    let End::Segment(up) = end_of(body, upper)? else {
        return Err("the upper end must be a segment; the seat can only be the lower end".into());
    };
    let lower = end_of(body, lower)?;
    let (k, c) = (number(k, "k")?, number(c, "c")?);
    let name = match name {
        [] => free_name(
            |n| body.links.iter().any(|l| l.name == n),
            &format!("{upper}-{lower}", lower = end_name(body, lower)),
        ),
        words => words.join(" "),
    };
    let mut next = body.clone();
    next.links.push(Link::new(&name, up, lower, k, c));
    Ok((next, format!("add link '{name}'")))
}

/// How a removed segment's links are handled.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Removal {
    /// Links that hang on the segment move to what it hangs on (its first
    /// link's lower end), so a chain stays joined; its own links go.
    Rejoin,
    /// Every link that touches the segment goes with it.
    WithLinks,
}

/// Where the links hanging on segment `i` move to on `Rejoin`: the lower
/// end of the first link that goes down from `i`.
pub fn rejoin_target(body: &Body, i: usize) -> Option<End> {
    body.links
        .iter()
        .find(|l| l.upper == i && l.lower != End::Segment(i))
        .map(|l| l.lower)
}

/// Removes segment `i`; links and the head are re-indexed.
pub fn remove_segment(body: &Body, i: usize, how: Removal) -> Result<(Body, String), String> {
    let name = body
        .segments
        .get(i)
        .map(|s| s.name.clone())
        .ok_or("no such segment")?;
    if body.segments.len() == 1 {
        return Err("the model has one segment: a model needs at least one".into());
    }
    if body.seat.as_ref().is_some_and(|s| s.pan == i) {
        return Err(format!(
            "'{name}' is the seat's pan, where SEAT is measured: a seat model keeps it (make another seat segment the pan in the preset file first)"
        ));
    }
    let target = match how {
        Removal::Rejoin => rejoin_target(body, i),
        Removal::WithLinks => None,
    };
    let shift = |j: usize| if j > i { j - 1 } else { j };
    let mut next = body.clone();
    next.segments.remove(i);
    let mut moved = 0;
    // Old link index → new, for the seat's suspension.
    let mut kept: Vec<Option<usize>> = Vec::with_capacity(body.links.len());
    next.links = Vec::with_capacity(body.links.len());
    for l in &body.links {
        let mut l = l.clone();
        let mut keep = l.upper != i;
        if keep && l.lower == End::Segment(i) {
            match target {
                Some(t) if t != End::Segment(l.upper) => {
                    l.lower = t;
                    moved += 1;
                }
                _ => keep = false,
            }
        }
        if !keep {
            kept.push(None);
            continue;
        }
        l.upper = shift(l.upper);
        if let End::Segment(j) = l.lower {
            l.lower = End::Segment(shift(j));
        }
        kept.push(Some(next.links.len()));
        next.links.push(l);
    }
    if let Some(seat) = next.seat.as_mut() {
        let Some(Some(suspension)) = kept.get(seat.suspension).copied() else {
            let link = body.links.get(seat.suspension).map_or("?", |l| l.name.as_str());
            return Err(format!(
                "removing '{name}' would remove the seat's suspension link '{link}': a seat model keeps it"
            ));
        };
        seat.suspension = suspension;
        seat.pan = shift(seat.pan);
    }
    next.head = if body.head == i { 0 } else { shift(body.head) };
    let what = match (how, moved) {
        (Removal::Rejoin, n) if n > 0 => format!(
            "remove segment '{name}' ({n} link{} moved to '{}')",
            if n == 1 { "" } else { "s" },
            target.map_or("?".into(), |t| end_name(body, t))
        ),
        _ => format!(
            "remove segment '{name}' and its {} link(s)",
            body.links.len() - next.links.len()
        ),
    };
    Ok((next, what))
}

pub fn remove_link(body: &Body, i: usize) -> Result<(Body, String), String> {
    let mut next = body.clone();
    if i >= next.links.len() {
        return Err("no such link".into());
    }
    if let Some(seat) = next.seat.as_mut() {
        if seat.suspension == i {
            return Err(format!(
                "'{}' is the seat's suspension, whose travel is the stroke: a seat model keeps it",
                body.links[i].name
            ));
        }
        if seat.suspension > i {
            seat.suspension -= 1;
        }
    }
    let l = next.links.remove(i);
    Ok((next, format!("remove link '{}'", l.name)))
}

/// Renames segment or link; an empty name is refused here (a link name is
/// how `--set <link>.k` finds it).
pub fn rename(
    body: &Body,
    seg: Option<usize>,
    link: Option<usize>,
    text: &str,
) -> Result<(Body, String), String> {
    let new = text.trim();
    let mut next = body.clone();
    let old = match (seg, link) {
        (Some(i), _) => next
            .segments
            .get_mut(i)
            .map(|s| std::mem::replace(&mut s.name, new.to_string())),
        (_, Some(i)) => {
            if new.is_empty() {
                return Err("a link needs a name: --set and presets find it by it".into());
            }
            next.links
                .get_mut(i)
                .map(|l| std::mem::replace(&mut l.name, new.to_string()))
        }
        _ => None,
    }
    .ok_or("select a segment or a link to rename")?;
    let kind = if seg.is_some() { "segment" } else { "link" };
    Ok((next, format!("rename {kind} '{old}' → '{new}'")))
}

pub fn set_head(body: &Body, i: usize) -> Result<(Body, String), String> {
    let name = body
        .segments
        .get(i)
        .map(|s| s.name.clone())
        .ok_or("select a segment to make it the head")?;
    let mut next = body.clone();
    next.head = i;
    Ok((next, format!("head → '{name}'")))
}

/// Sets the share (typed in %) of segment `i`: its mass becomes share ×
/// body mass. Needs a body mass (a model of plain masses has none).
pub fn set_share(body: &Body, i: usize, text: &str) -> Result<(Body, String), String> {
    let t = text.trim().trim_end_matches('%').trim();
    let pct = number(t, "share")?;
    let Some(bm) = body.body_mass else {
        return Err(
            "this model gives masses, not shares of a body mass: edit the mass instead".into(),
        );
    };
    let mut next = body.clone();
    let seg = next.segments.get_mut(i).ok_or("select a segment")?;
    let old = seg
        .share
        .map_or("none".into(), |s| format!("{} %", num(s * 100.0, 4)));
    seg.share = Some(pct / 100.0);
    // A share the library refuses keeps the mass, so its message is the share's.
    if pct.is_finite() && pct > 0.0 {
        seg.mass = pct / 100.0 * bm;
    }
    let what = format!("share of '{}' {old} → {} %", seg.name, num(pct, 4));
    Ok((next, what))
}
