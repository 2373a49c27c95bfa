//! `biodyn day --report FILE.html`: the working day (or, with `--week`,
//! each day and the week) as a page, read from the JSON document `day
//! --format json` prints (see `super` for why): the day's verdicts first,
//! then the HSE calculator's sheet behind them (each operation and axis,
//! each axis for the day) and the spine where the day file asks for it.

use super::{AS_TYPED, Doc, HOURS, direction, esc, page, section, seg, table, verdict_box};
use biodyn::iso2631::{A8_ACTION, A8_LIMIT, VDV_ACTION, VDV_LIMIT};
use serde_json::Value;

/// The page for the document `json` (one day, or `{days, week}`);
/// `figures` complete inline `<svg>` elements (none: no Figures section).
pub fn page_of(json: &Value, figures: &[String]) -> String {
    let d = Doc::new(json);
    let mut b = super::meta::block(&d, "/meta");
    let week = d.get("/week").is_some();
    let (subtitle, spine) = if week {
        let n = d.len("/days");
        b.push_str(&week_block(&d));
        for i in 0..n {
            b.push_str(&day_block(&d, &format!("/days/{i}"), Some(i + 1)));
        }
        let spine = (0..n).any(|i| d.get(&format!("/days/{i}/spine")).is_some());
        (
            format!("{n} day file{}", if n == 1 { "" } else { "s" }),
            spine,
        )
    } else {
        b.push_str(&day_block(&d, "", None));
        (
            format!(
                "<code>{}</code> · {}",
                d.text("/file"),
                d.num("/hours", HOURS)
            ),
            d.get("/spine").is_some(),
        )
    };
    let notes = d.strings("/notes");
    if !notes.is_empty() {
        let items: String = notes.iter().map(|n| format!("<li>{n}</li>\n")).collect();
        b.push_str(&section(
            "notes",
            "Notes on the records",
            &format!("<ul>\n{items}</ul>\n"),
        ));
    }
    let mut cited = vec![
        "Directive 2002/44/EC (Art. 3, Annex B): the daily exposure A(8) and VDV of the highest axis, the action and limit values",
        "ISO 2631-1:1997 (with Amd 1:2010): k = 1.4 on x and y, 1 on z (§7.2.3); a_w and VDV",
        "UK SI 2005/1093 (the Control of Vibration at Work Regulations 2005), Schedule 2, and the HSE's whole-body calculator: partial exposures, points, hours to the EAV and ELV",
    ];
    if week {
        cited.push("UK SI 2005/1093 Schedule 2: the weekly A(8) = √(⅕ Σ A(8)day²)");
    }
    if spine {
        cited.push("ISO 2631-5:2018: the daily spinal dose and the risk of injury (Annex C)");
    }
    let title = if week {
        "Whole-body vibration: the working week"
    } else {
        "Whole-body vibration: the working day"
    };
    page(title, &subtitle, &b, figures, &cited)
}

/// The week's exposure per axis and its verdict.
fn week_block(d: &Doc) -> String {
    let axis = d.text("/week/a8_axis");
    let mut s = String::from("<div class=\"verdicts\">\n");
    s.push_str(&verdict_box(
        &format!(
            "weekly A(8), the highest axis: {axis} ({}); action {A8_ACTION}, limit {A8_LIMIT} m/s²",
            direction(&axis)
        ),
        &format!(
            "A(8) = {} m/s², {} points",
            d.num("/week/a8_m_s2", 3),
            d.num("/week/points", 0)
        ),
        &d.text("/week/eu_a8"),
    ));
    s.push_str("</div>\n");
    let rows: Vec<Vec<String>> = d
        .keys("/week/axes")
        .iter()
        .map(|a| {
            vec![
                format!("{} ({})", esc(a), direction(a)),
                d.num(&format!("/week/axes/{}/a8_m_s2", seg(a)), 3),
            ]
        })
        .collect();
    s.push_str(&table("week", &["axis", "A(8)week m/s²"], &rows));
    s.push_str(&week_vdv(d));
    section("week", "The week (UK SI 2005/1093 Schedule 2)", &s)
}

/// The days whose VDV passes a value (the VDV is a day's; the week has
/// none), and those whose VDV verdict is open.
fn week_vdv(d: &Doc) -> String {
    let rows: Vec<Vec<String>> = (0..d.len("/week/vdv_days"))
        .map(|i| {
            let k = |f: &str| format!("/week/vdv_days/{i}/{f}");
            let (value, words) = match d.get(&k("vdv_exposure_m_s175")) {
                Some(_) => (d.num(&k("vdv_exposure_m_s175"), 2), d.text(&k("eu_vdv"))),
                None => (
                    format!("≥ {}", d.num(&k("vdv_at_least_m_s175"), 2)),
                    match d.get(&k("eu_vdv")) {
                        Some(_) => d.text(&k("eu_vdv")),
                        None => {
                            format!("{}; above limit value open", d.text(&k("eu_vdv_at_least")))
                        }
                    },
                ),
            };
            vec![
                d.num(&k("day"), 0),
                format!("<code>{}</code>", d.text(&k("file"))),
                d.text(&k("vdv_axis")),
                value,
                words,
            ]
        })
        .collect();
    let mut s = String::from(
        "<h3>Days over a VDV value</h3>\n<p class=\"note\">The VDV is a day's: the week has none. A value with ≥ is the known part of a day whose operations do not all have a VDV, a lower bound.</p>\n",
    );
    if rows.is_empty() {
        s.push_str("<p>None.</p>\n");
    } else {
        s.push_str(&table(
            "week-vdv",
            &["day", "file", "axis", "VDV m/s^1.75", "EU 2002/44/EC"],
            &rows,
        ));
    }
    let open: Vec<String> = (0..d.len("/week/vdv_open_days"))
        .map(|i| d.num(&format!("/week/vdv_open_days/{i}"), 0))
        .collect();
    if !open.is_empty() {
        s.push_str(&format!(
            "<p>The VDV verdict is open on day {}: operations without a measured VDV.</p>\n",
            open.join(", ")
        ));
    }
    s
}

/// One day at `p` (a JSON pointer prefix: "" or "/days/i").
fn day_block(d: &Doc, p: &str, nth: Option<usize>) -> String {
    let k = |s: &str| format!("{p}{s}");
    let mut s = String::new();
    let facts = vec![
        vec![
            "day file".into(),
            format!("<code>{}</code>", d.text(&k("/file"))),
        ],
        vec!["operations".into(), d.len(&k("/operations")).to_string()],
        vec!["hours of exposure".into(), d.num(&k("/hours"), HOURS)],
    ];
    s.push_str(&table("facts", &["", ""], &facts).replacen(
        "<thead><tr><th></th><th></th></tr></thead>\n",
        "",
        1,
    ));
    // A week's day keeps its own [report]; one day's is the page's.
    if nth.is_some() {
        s.push_str(&super::meta::facts(d, &k("/meta")));
    }
    s.push_str(&verdicts(d, p));
    s.push_str(&operations(d, p));
    s.push_str(&per_axis(d, p));
    s.push_str(&spine(d, p));
    let title = match nth {
        Some(i) => format!("Day {i}: {}", d.text(&k("/file"))),
        None => "The day".into(),
    };
    let id = nth.map_or("day".to_string(), |i| format!("day-{i}"));
    section(&id, &title, &s)
}

/// The day's highest axis and the EU verdicts in words.
fn verdicts(d: &Doc, p: &str) -> String {
    let k = |s: &str| format!("{p}/daily{s}");
    let axis = d.text(&k("/a8_axis"));
    let mut s = String::from("<div class=\"verdicts\">\n");
    s.push_str(&verdict_box(
        &format!("daily exposure A(8), the highest axis: {axis} ({}); action {A8_ACTION}, limit {A8_LIMIT} m/s²", direction(&axis)),
        &format!("A(8) = {} m/s², {} points", d.num(&k("/a8_m_s2"), 3), d.num(&k("/points"), 0)),
        &d.text(&k("/eu_a8")),
    ));
    s.push_str(&vdv_verdict(d, p));
    s.push_str("</div>\n<p class=\"note\">Directive 2002/44/EC sets both values for the whole body; each Member State bases its rules on A(8) or, at its choice, on the VDV (Art. 3(2)). Points (HSE): 100 at the action value, 529 at the limit value.</p>\n");
    s
}

/// Hours to a value as the sheet prints them: two decimals, "<0.01"
/// rather than a 0.00 that reads as no time, "never" for null.
pub(super) fn hours(d: &Doc, key: &str) -> String {
    match d.f(key) {
        Some(h) if h < 0.005 => d.num(key, 2).replacen(">0.00<", ">&lt;0.01<", 1),
        Some(_) => d.num(key, 2),
        None => "never".into(),
    }
}

/// The day's VDV verdict: exact; or the known part, a lower bound (a
/// missing VDV only raises (Σ VDV_i⁴)^¼), judged as such, the verdict open
/// only below the limit value; the operations without one named.
fn vdv_verdict(d: &Doc, p: &str) -> String {
    let k = |s: &str| format!("{p}/daily{s}");
    let axis = d.text(&k("/vdv_axis"));
    let what = format!(
        "daily VDV, the highest axis: {axis} ({}); action {VDV_ACTION}, limit {VDV_LIMIT} m/s^1.75",
        direction(&axis)
    );
    let lacking: Vec<String> = d
        .keys(&k("/axes"))
        .iter()
        .filter_map(|a| {
            let names = d.strings(&k(&format!("/axes/{}/vdv_lacking", seg(a))));
            (!names.is_empty()).then(|| format!("{}: {}", esc(a), names.join(", ")))
        })
        .collect();
    let lacking = format!(
        "<p class=\"note\">Without a measured VDV: {}. A missing VDV only raises the day's (a sum of fourth powers only grows), so the VDV of the operations that have one is a lower bound of the day's.</p>\n",
        lacking.join("; ")
    );
    if d.get(&k("/vdv_exposure_m_s175")).is_some() {
        return verdict_box(
            &what,
            &format!("VDV = {} m/s^1.75", d.num(&k("/vdv_exposure_m_s175"), 2)),
            &d.text(&k("/eu_vdv")),
        );
    }
    if d.get(&k("/vdv_at_least_m_s175")).is_none() {
        return format!(
            "<div class=\"verdict none\">\n<div class=\"what\">daily VDV</div>\n<div class=\"words\">not judged</div>\n<p>No operation has a measured VDV: the day's VDV is not known. Measure it, or judge by A(8).</p>\n{lacking}</div>\n"
        );
    }
    let value = format!(
        "VDV ≥ {} m/s^1.75 (the known part)",
        d.num(&k("/vdv_at_least_m_s175"), 2)
    );
    let at_least = d.text(&k("/eu_vdv_at_least"));
    if d.get(&k("/eu_vdv")).is_some() {
        // Above the limit by the known part alone: decided.
        let mut b = verdict_box(&what, &value, &d.text(&k("/eu_vdv")));
        b.insert_str(b.len() - "</div>\n".len(), &lacking);
        return b;
    }
    if at_least == "below action value" {
        return format!(
            "<div class=\"verdict none\">\n<div class=\"what\">{what}</div>\n<div class=\"value\">{value}</div>\n<div class=\"words\">not judged</div>\n<p>The known part is below the action value; the operations without a VDV could take the day's over it. Measure them, or judge by A(8).</p>\n{lacking}</div>\n"
        );
    }
    // Above the action value by the known part; the limit open.
    let mut b = verdict_box(&what, &value, &at_least);
    b.insert_str(
        b.len() - "</div>\n".len(),
        &format!("<p><strong>Whether the limit value is exceeded is open</strong> until the operations below have a VDV.</p>\n{lacking}"),
    );
    b
}

/// Each operation on each axis: k·a_w, partial A(8), points, hours to the
/// EAV and ELV, the VDV over the operation and the hours to its EAV and
/// ELV ("-" without a measured VDV: not judged).
fn operations(d: &Doc, p: &str) -> String {
    let mut rows = Vec::new();
    for i in 0..d.len(&format!("{p}/operations")) {
        let o = format!("{p}/operations/{i}");
        let mut name = d.text(&format!("{o}/name"));
        if d.get(&format!("{o}/record")).is_some() {
            name.push_str(&format!(
                "<br><span class=\"note\">record <code>{}</code></span>",
                d.text(&format!("{o}/record"))
            ));
        }
        for (j, a) in d.keys(&format!("{o}/axes")).iter().enumerate() {
            let k = format!("{o}/axes/{}", seg(a));
            let n = |f: &str, dec| d.num(&format!("{k}/{f}"), dec);
            let hours = |f: &str| hours(d, &format!("{k}/{f}"));
            // A VDV's hours: absent without a VDV, null when never.
            let vdv_hours = |f: &str| match d.root.pointer(&format!("{k}/{f}")) {
                None => "–".to_string(),
                Some(_) => hours(f),
            };
            rows.push(vec![
                if j == 0 { name.clone() } else { String::new() },
                if j == 0 {
                    d.num(&format!("{o}/hours"), HOURS)
                } else {
                    String::new()
                },
                esc(a),
                n("kaw_m_s2", 3),
                n("a8_m_s2", 3),
                n("points", 1),
                hours("hours_to_eav"),
                hours("hours_to_elv"),
                n("vdv_exposure_m_s175", 2),
                vdv_hours("hours_to_vdv_eav"),
                vdv_hours("hours_to_vdv_elv"),
            ]);
        }
    }
    format!(
        "<h3>Each operation (partial exposure A(8) = k·a_w·√(T/8 h))</h3>\n{}",
        table(
            "operations",
            &crate::view::report::day::OPERATION_HEADINGS,
            &rows,
        )
    )
}

/// Each axis for the day: A(8) = √Σ partial A(8)², the points, the VDV.
fn per_axis(d: &Doc, p: &str) -> String {
    let rows: Vec<Vec<String>> = d
        .keys(&format!("{p}/daily/axes"))
        .iter()
        .map(|a| {
            let k = format!("{p}/daily/axes/{}", seg(a));
            vec![
                format!("{} ({})", esc(a), direction(a)),
                d.num(&format!("{k}/a8_m_s2"), 3),
                d.num(&format!("{k}/points"), 1),
                match d.get(&format!("{k}/vdv_at_least_m_s175")) {
                    Some(_) => format!("≥ {}", d.num(&format!("{k}/vdv_at_least_m_s175"), 2)),
                    None => d.num(&format!("{k}/vdv_exposure_m_s175"), 2),
                },
            ]
        })
        .collect();
    format!(
        "<h3>The day, per axis (A(8) = √Σ partial A(8)²; points add)</h3>\n{}",
        table(
            "daily",
            &["axis", "A(8) m/s²", "points", "VDV m/s^1.75"],
            &rows
        )
    )
}

/// The day's ISO 2631-5 block, when the day file names the person.
fn spine(d: &Doc, p: &str) -> String {
    let sp = format!("{p}/spine");
    if d.get(&sp).is_none() {
        return String::new();
    }
    let n = |f: &str, dec| d.num(&format!("{sp}/{f}"), dec);
    let rows: Vec<Vec<String>> = (0..d.len(&format!("{sp}/operations")))
        .map(|i| {
            let o = format!("operations/{i}");
            vec![
                d.text(&format!("{sp}/{o}/operation")),
                n(&format!("{o}/dz_m_s2"), 2),
                n(&format!("{o}/measured_s"), AS_TYPED),
                n(&format!("{o}/hours"), HOURS),
                n(&format!("{o}/dzd_m_s2"), 2),
            ]
        })
        .collect();
    let mut s = format!(
        "<div class=\"keep\">\n<h3>The spine (ISO 2631-5:2018, z)</h3>\n<p>The person: age {} at the start, {} years of it, {} days a year, {}.</p>\n",
        n("person/age", AS_TYPED),
        n("person/years", 0),
        n("person/days", 0),
        d.text(&format!("{sp}/person/sex"))
    );
    s.push_str(&table(
        "spine",
        &["operation", "Dz m/s²", "over s", "hours", "Dzd alone m/s²"],
        &rows,
    ));
    s.push_str(&format!(
        "<p>The day: Dzd = (Σ Dz⁶·t_d/t_m)^⅙ = {} m/s², Sd {} MPa (static {} MPa), R {}, P {}.</p>\n<p><strong>{}</strong></p>\n</div>\n",
        n("dzd_m_s2", 2),
        n("sd_mpa", 3),
        n("static_mpa", 5),
        n("r", 2),
        n("probability", 2),
        d.text(&format!("{sp}/words"))
    ));
    s
}
