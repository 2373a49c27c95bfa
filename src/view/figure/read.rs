//! Reading a figure back: the SVG's elements, the pixel ↔ value map of a
//! panel's axes from its tick labels, and a legend entry's colour. The
//! tests and the docs' figure check use it to prove that a curve's
//! vertices, mapped through the printed tick labels, are the plotted values.

/// One SVG element: its name, attributes and text content.
#[derive(Debug, Clone, PartialEq)]
pub struct Element {
    pub name: String,
    pub attrs: Vec<(String, String)>,
    pub text: String,
}

impl Element {
    pub fn attr(&self, key: &str) -> Option<&str> {
        self.attrs
            .iter()
            .find(|(k, _)| k == key)
            .map(|(_, v)| v.as_str())
    }

    pub fn num(&self, key: &str) -> Option<f64> {
        self.attr(key)?.parse().ok()
    }

    /// A polyline's vertices.
    pub fn points(&self) -> Vec<(f64, f64)> {
        self.attr("points")
            .unwrap_or("")
            .split_whitespace()
            .filter_map(|p| {
                let (x, y) = p.split_once(',')?;
                Some((x.parse().ok()?, y.parse().ok()?))
            })
            .collect()
    }
}

/// Markup's character references back to text (plotters' and the report
/// page's: `&lt;` `&gt;` `&quot;` `&apos;` `&#39;` `&amp;`).
pub fn unescape(s: &str) -> String {
    s.replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&quot;", "\"")
        .replace("&apos;", "'")
        .replace("&#39;", "'")
        .replace("&amp;", "&")
}

/// Every element of `svg` in document order (a flat list: nesting is not
/// kept; a text element's content is its text).
pub fn elements(svg: &str) -> Result<Vec<Element>, String> {
    let mut out = Vec::new();
    let mut rest = svg;
    while let Some(i) = rest.find('<') {
        rest = &rest[i + 1..];
        if rest.starts_with('/') || rest.starts_with('?') || rest.starts_with('!') {
            let Some(j) = rest.find('>') else { break };
            rest = &rest[j + 1..];
            continue;
        }
        let end = rest.find('>').ok_or("an unclosed tag")?;
        let tag = &rest[..end];
        let self_closing = tag.ends_with('/');
        let tag = tag.trim_end_matches('/');
        let (name, mut attrs_text) = tag.split_once(char::is_whitespace).unwrap_or((tag, ""));
        let mut attrs = Vec::new();
        while let Some(eq) = attrs_text.find('=') {
            let key = attrs_text[..eq].trim().to_string();
            let after = attrs_text[eq + 1..].trim_start();
            let q = after.chars().next().ok_or("an attribute without a value")?;
            let close = after[1..].find(q).ok_or("an unclosed attribute value")?;
            attrs.push((key, unescape(&after[1..=close])));
            attrs_text = &after[close + 2..];
        }
        rest = &rest[end + 1..];
        let mut text = String::new();
        if !self_closing && name == "text" {
            let close = rest.find("</text>").ok_or("an unclosed text element")?;
            text = unescape(rest[..close].trim());
            rest = &rest[close..];
        }
        out.push(Element {
            name: name.to_string(),
            attrs,
            text,
        });
    }
    Ok(out)
}

/// Pixel ↔ value along one axis, from its tick labels.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AxisMap {
    /// Two labels' pixel positions and values (axis units: log10 on a log axis).
    pub px: (f64, f64),
    pub at: (f64, f64),
    pub log: bool,
    /// How many labels the map was read from.
    pub labels: usize,
    /// The largest distance, pixels, of any label from the line through the
    /// two outermost: > 1 means the ticks are not where their labels say.
    pub worst_px: f64,
}

impl AxisMap {
    fn from(labels: &[(f64, f64)], log: bool) -> Result<AxisMap, String> {
        let pts: Vec<(f64, f64)> = labels
            .iter()
            .map(|&(px, v)| (px, if log { v.log10() } else { v }))
            .collect();
        let (Some(a), Some(b)) = (
            pts.iter().min_by(|p, q| p.0.total_cmp(&q.0)),
            pts.iter().max_by(|p, q| p.0.total_cmp(&q.0)),
        ) else {
            return Err("no tick labels".into());
        };
        if (b.0 - a.0).abs() < 1.0 || (b.1 - a.1) == 0.0 {
            return Err(format!("fewer than two distinct tick labels: {labels:?}"));
        }
        let m = AxisMap {
            px: (a.0, b.0),
            at: (a.1, b.1),
            log,
            labels: pts.len(),
            worst_px: 0.0,
        };
        let worst_px = pts
            .iter()
            .map(|&(px, v)| (m.pixel_of_axis(v) - px).abs())
            .fold(0.0, f64::max);
        Ok(AxisMap { worst_px, ..m })
    }

    fn pixel_of_axis(&self, at: f64) -> f64 {
        self.px.0 + (at - self.at.0) / (self.at.1 - self.at.0) * (self.px.1 - self.px.0)
    }

    /// The value (data units) at pixel `px`.
    pub fn value(&self, px: f64) -> f64 {
        let at = self.at.0 + (px - self.px.0) / (self.px.1 - self.px.0) * (self.at.1 - self.at.0);
        if self.log { 10f64.powf(at) } else { at }
    }

    /// The pixel of `v` (data units).
    pub fn pixel(&self, v: f64) -> f64 {
        self.pixel_of_axis(if self.log { v.log10() } else { v })
    }
}

/// A rectangle of the figure, pixels: (left, top, right, bottom).
pub type Region = (f64, f64, f64, f64);

/// The numeric tick labels inside `region` anchored `anchor` (x labels
/// are centred, y labels end at the axis): (position along the axis, value).
fn labels(els: &[Element], region: Region, anchor: &str, along: &str) -> Vec<(f64, f64)> {
    let inside = |e: &Element| {
        let (x, y) = (
            e.num("x").unwrap_or(f64::NAN),
            e.num("y").unwrap_or(f64::NAN),
        );
        x >= region.0 && x <= region.2 && y >= region.1 && y <= region.3
    };
    els.iter()
        .filter(|e| e.name == "text" && e.attr("text-anchor") == Some(anchor) && inside(e))
        .filter_map(|e| Some((e.num(along)?, e.text.trim().parse::<f64>().ok()?)))
        .collect()
}

/// The axes of the panel in `region`: x from its numeric labels centred on
/// one row (text-anchor middle), y from those ending in one column
/// (text-anchor end).
pub fn axes(
    els: &[Element],
    region: Region,
    log_x: bool,
    log_y: bool,
) -> Result<(AxisMap, AxisMap), String> {
    let xs = labels(els, region, "middle", "x");
    Ok((AxisMap::from(&xs, log_x)?, y_axis(els, region, log_y)?))
}

/// The y axis alone, for a panel whose x axis names categories.
pub fn y_axis(els: &[Element], region: Region, log: bool) -> Result<AxisMap, String> {
    AxisMap::from(&labels(els, region, "end", "y"), log)
}

/// The category names under a panel's x axis, left to right: (x, name),
/// the centred texts of the row that has most of them (the caption and
/// the axis title are rows of one).
pub fn categories(els: &[Element], region: Region) -> Vec<(f64, String)> {
    let texts: Vec<(f64, f64, String)> = els
        .iter()
        .filter(|e| e.name == "text" && e.attr("text-anchor") == Some("middle"))
        .filter_map(|e| Some((e.num("x")?, e.num("y")?, unescape(&e.text))))
        .filter(|&(x, y, _)| x >= region.0 && x <= region.2 && y >= region.1 && y <= region.3)
        .collect();
    let on = |row: f64| texts.iter().filter(|t| (t.1 - row).abs() < 0.5).count();
    let Some(row) = texts.iter().map(|t| t.1).max_by_key(|&y| on(y)) else {
        return Vec::new();
    };
    let mut out: Vec<(f64, String)> = texts
        .into_iter()
        .filter(|t| (t.1 - row).abs() < 0.5)
        .map(|(x, _, t)| (x, t))
        .collect();
    out.sort_by(|a, b| a.0.total_cmp(&b.0));
    out
}

/// Whether `pts` lie where plotters puts a legend sample for a text at
/// (tx, ty): a short run just left of it, level with it.
fn beside(pts: &[(f64, f64)], (tx, ty): (f64, f64)) -> bool {
    !pts.is_empty()
        && pts
            .iter()
            .all(|&(x, y)| x <= tx && x >= tx - 48.0 && y >= ty - 4.0 && y <= ty + 18.0)
}

fn shape_points(e: &Element) -> Vec<(f64, f64)> {
    match e.name.as_str() {
        "polyline" => e.points(),
        "line" => [("x1", "y1"), ("x2", "y2")]
            .iter()
            .filter_map(|(x, y)| Some((e.num(x)?, e.num(y)?)))
            .collect(),
        "circle" => e.num("cx").zip(e.num("cy")).into_iter().collect(),
        "rect" => e.num("x").zip(e.num("y")).into_iter().collect(),
        _ => Vec::new(),
    }
}

/// The stroke (or fill) colour of the legend sample beside the legend text
/// `name`.
pub fn legend_colour(els: &[Element], name: &str) -> Option<String> {
    let t = els
        .iter()
        .find(|e| e.name == "text" && e.text == name && e.attr("text-anchor") == Some("start"))?;
    let at = (t.num("x")?, t.num("y")?);
    els.iter()
        .filter(|e| e.name != "text")
        .find(|e| beside(&shape_points(e), at))
        .and_then(|e| {
            e.attr("stroke")
                .filter(|s| *s != "none")
                .or_else(|| e.attr("fill"))
                .map(str::to_string)
        })
}

/// Every vertex of the polylines stroked in `colour` inside `region`
/// (a dashed curve is many), legend samples left out (a short level line
/// just left of a legend text).
pub fn vertices(els: &[Element], colour: &str, region: Region) -> Vec<(f64, f64)> {
    let legend: Vec<(f64, f64)> = els
        .iter()
        .filter(|e| e.name == "text" && e.attr("text-anchor") == Some("start"))
        .filter_map(|e| Some((e.num("x")?, e.num("y")?)))
        .collect();
    let is_sample = |pts: &[(f64, f64)]| legend.iter().any(|&at| beside(pts, at));
    els.iter()
        .filter(|e| e.name == "polyline" && e.attr("stroke") == Some(colour))
        .map(Element::points)
        .filter(|pts| !is_sample(pts))
        .flatten()
        .filter(|&(x, y)| x >= region.0 && x <= region.2 && y >= region.1 && y <= region.3)
        .collect()
}
