//! `biodyn assess --report FILE.html`: the assessment as a page, read from
//! the JSON document `assess --format json` prints (see `super` for why).
//!
//! Its order is the hygienist's: what was measured, the verdicts, the
//! per-axis numbers behind them, comfort, the spine where asked, then what
//! the model predicts at the head (boxed and labelled as a prediction: it
//! was not measured), the bands and the warnings.

use super::{
    AS_TYPED, Doc, SIG3, direction, esc, metric_cells, metric_head, page, section, seg, table,
    verdict_box,
};
use biodyn::iso2631::{A8_ACTION, A8_LIMIT, VDV_ACTION, VDV_LIMIT};
use serde_json::Value;

/// The page for the document `json`; `head` is the head segment's name,
/// None to leave the body model's part out (`--no-model`: the head, the
/// segments, the model's predicted values); `figures` complete inline
/// `<svg>` elements (none: no Figures section).
pub fn page_of(json: &Value, head: Option<&str>, figures: &[String]) -> String {
    let d = Doc::new(json);
    let mut b = String::new();
    b.push_str(&super::meta::block(&d, "/meta"));
    b.push_str(&measured(&d, head.is_some()));
    b.push_str(&verdicts(&d));
    b.push_str(&per_axis(&d));
    b.push_str(&comfort(&d, head.is_some()));
    b.push_str(&pan(&d));
    b.push_str(&spine(&d));
    if let Some(head) = head {
        b.push_str(&super::predicted::prediction(&d, &esc(head)));
    }
    b.push_str(&super::predicted::bands(&d, head.is_some()));
    b.push_str(&warnings(&d));
    let what = match d.get("/input/file") {
        Some(_) => format!("<code>{}</code>", d.text("/input/file")),
        None => format!("generated signal <code>{}</code>", d.text("/input/signal")),
    };
    let subtitle = match head {
        Some(_) => format!(
            "{what} · model <code>{}</code> · {} h a day",
            d.text("/model"),
            d.num("/exposure_h", AS_TYPED)
        ),
        None => format!("{what} · {} h a day", d.num("/exposure_h", AS_TYPED)),
    };
    let mut cited = vec![
        "ISO 2631-1:1997 (with Amd 1:2010): the frequency weightings' use, k factors, a_w, MTVV, VDV, comfort (Annex C), motion sickness (Annex D)",
        "ISO 8041-1:2017: the frequency weighting filters",
        "Directive 2002/44/EC (Art. 3, Annex B): the daily exposure A(8) and VDV, the action and limit values",
    ];
    if d.get("/spine").is_some() {
        cited
            .push("ISO 2631-5:2018: the spinal acceleration dose and the risk of injury (Annex C)");
    }
    if d.get("/seat_value").is_some() {
        cited.push("ISO 10326-1:2016: SEAT (seat effective amplitude transmissibility)");
    }
    page(
        "Whole-body vibration assessment",
        &subtitle,
        &b,
        figures,
        &cited,
    )
}

/// What was measured: the record or signal, its axes and units, how long,
/// at what rate, the model (unless left out) and the exposure.
fn measured(d: &Doc, model: bool) -> String {
    let mut rows: Vec<Vec<String>> = Vec::new();
    match d.get("/input/file") {
        Some(_) => {
            rows.push(vec![
                "record".into(),
                format!("<code>{}</code>", d.text("/input/file")),
            ]);
            let t = d.text("/input/time_column");
            rows.push(vec![
                "time column".into(),
                if t.is_empty() {
                    "none (the sampling rate given)".into()
                } else {
                    format!("<code>{t}</code>, in {}", d.text("/input/time_unit"))
                },
            ]);
        }
        None => rows.push(vec![
            "signal".into(),
            format!(
                "generated, vertical (z): <code>{}</code>",
                d.text("/input/signal")
            ),
        ]),
    }
    rows.push(vec![
        "duration".into(),
        format!("{} s", d.num("/duration_s", AS_TYPED)),
    ]);
    rows.push(vec![
        "sampling rate".into(),
        format!("{} Hz", d.num("/fs_hz", AS_TYPED)),
    ]);
    rows.push(vec![
        "exposure".into(),
        format!("{} h a day", d.num("/exposure_h", AS_TYPED)),
    ]);
    if model {
        rows.push(vec![
            "model (the body)".into(),
            format!("<code>{}</code>, driven by the seat's z", d.text("/model")),
        ]);
    }
    let mut s = super::table("facts", &["", ""], &rows).replacen(
        "<thead><tr><th></th><th></th></tr></thead>\n",
        "",
        1,
    );
    let mut ch: Vec<Vec<String>> = Vec::new();
    for a in d.keys("/input/axes") {
        let k = format!("/input/axes/{}", seg(&a));
        let col = d.text(&format!("{k}/column"));
        ch.push(vec![
            esc(&a),
            direction(&a).into(),
            if col.is_empty() {
                "(generated)".into()
            } else {
                format!("<code>{col}</code>")
            },
            unit_cell(d, &k),
            d.text(&format!("{k}/named_by")),
            d.num(&format!("{k}/mean_removed"), SIG3),
        ]);
    }
    for p in d.keys("/input/points") {
        let k = format!("/input/points/{}", seg(&p));
        ch.push(vec![
            esc(&p),
            "other point".into(),
            format!("<code>{}</code>", d.text(&format!("{k}/column"))),
            unit_cell(d, &k),
            d.text(&format!("{k}/named_by")),
            d.num(&format!("{k}/mean_removed"), SIG3),
        ]);
    }
    s.push_str("<h3>Channels</h3>\n");
    s.push_str(&table(
        "channels",
        &[
            "axis",
            "direction",
            "column",
            "unit",
            "named by",
            "mean removed",
        ],
        &ch,
    ));
    section("measured", "What was measured", &s)
}

/// A channel's unit and where it came from: "g (header)", and an assumed
/// m/s² said in words (issue 30: never silently).
fn unit_cell(d: &Doc, k: &str) -> String {
    let unit = d.text(&format!("{k}/unit"));
    match d.text(&format!("{k}/unit_from")).as_str() {
        "assumed" => format!("{unit} (<strong>assumed</strong>: no unit in the header)"),
        "" => unit,
        from => format!("{unit} ({from})"),
    }
}

/// The day's exposure at the seat (the highest axis after k) and the EU
/// 2002/44/EC verdicts in words.
fn verdicts(d: &Doc) -> String {
    let a8_axis = d.text("/health/a8_axis");
    let vdv_axis = d.text("/health/vdv_axis");
    let mut s = String::from("<div class=\"verdicts\">\n");
    s.push_str(&verdict_box(
        &format!("daily exposure A(8), the highest axis: {a8_axis} ({}); action {A8_ACTION}, limit {A8_LIMIT} m/s²", direction(&a8_axis)),
        &format!("A(8) = {} m/s²", d.num("/health/a8_m_s2", 3)),
        &d.text("/health/eu_a8"),
    ));
    s.push_str(&verdict_box(
        &format!("VDV over the exposure, the highest axis: {vdv_axis} ({}); action {VDV_ACTION}, limit {VDV_LIMIT} m/s^1.75", direction(&vdv_axis)),
        &format!("VDV = {} m/s^1.75", d.num("/health/vdv_exposure_m_s175", 2)),
        &d.text("/health/eu_vdv"),
    ));
    s.push_str("</div>\n<p class=\"note\">Directive 2002/44/EC sets both values for the whole body; each Member State bases its rules on A(8) or, at its choice, on the VDV (Art. 3(2)). The exposure is extrapolated from this record to the hours a day given above.</p>\n");
    section("verdicts", "The daily exposure: EU 2002/44/EC verdicts", &s)
}

/// The per-axis table at the seat (ISO 2631-1 seated): a_w and VDV before
/// k, A(8) and VDV over the exposure after it; the highest axis in bold.
fn per_axis(d: &Doc) -> String {
    let top = d.text("/health/a8_axis");
    let mut rows = Vec::new();
    let mut marks = Vec::new();
    for a in d.keys("/axes") {
        let k = format!("/axes/{}", seg(&a));
        let n = |f: &str, dec| d.num(&format!("{k}/{f}"), dec);
        marks.push(a == top);
        let mut row = vec![
            format!("{} ({})", esc(&a), direction(&a)),
            d.text(&format!("{k}/weighting")),
            n("k_health", 1),
            n("k_comfort", 1),
        ];
        row.extend(metric_cells(d, &k));
        rows.push(row);
    }
    let mut t = table(
        "axes",
        &metric_head(&["axis", "weighting", "k health", "k comfort"]),
        &rows,
    );
    for (i, top) in marks.iter().enumerate() {
        if *top {
            t = mark_row(&t, i);
        }
    }
    let at = if d.get("/floor").is_some() {
        "At the seat pan"
    } else {
        "At the seat"
    };
    let s = format!(
        "<p>{at}, per axis (ISO 2631-1 seated). a_w, peak, crest factor, MTVV (the largest 1 s running r.m.s.) and VDV are of the weighted record, before k; A(8) and the VDV over the day are after k. The row in bold is the highest A(8): the day's exposure.</p>\n{t}{}",
        reach(d)
    );
    section("axes", "Per axis", &s)
}

/// The HSE calculator's reading per axis: the points of the A(8) over the
/// exposure, the hours a day of this vibration that reach each value.
fn reach(d: &Doc) -> String {
    let rows: Vec<Vec<String>> = d
        .keys("/axes")
        .iter()
        .map(|a| {
            let k = format!("/axes/{}", seg(a));
            let hours = |f: &str| super::day::hours(d, &format!("{k}/{f}"));
            vec![
                format!("{} ({})", esc(a), direction(a)),
                d.num(&format!("{k}/points"), 1),
                hours("hours_to_eav"),
                hours("hours_to_elv"),
                hours("hours_to_vdv_eav"),
                hours("hours_to_vdv_elv"),
            ]
        })
        .collect();
    format!(
        "<h3>Hours a day to reach each value</h3>\n<p>As the HSE calculators give them: points = 100·(A(8)/0.5)² of the A(8) over the exposure (100 at the action value, 529 at the limit); the hours a day of this vibration that reach the A(8) values, 8 h·(V/(k·a_w))², and the VDV values, T·(V/(k·VDV))⁴ with T the record's length (the VDV grows as the fourth root of time).</p>\n{}",
        table(
            "reach",
            &[
                "axis",
                "points",
                "to EAV h",
                "to ELV h",
                "to VDV EAV h",
                "to VDV ELV h"
            ],
            &rows
        )
    )
}

/// Bolds the `i`-th body row of a table.
fn mark_row(t: &str, i: usize) -> String {
    let Some(body) = t.find("<tbody>") else {
        return t.to_string();
    };
    let mut at = body;
    for _ in 0..=i {
        match t[at..].find("<tr>") {
            Some(p) => at += p + 4,
            None => return t.to_string(),
        }
    }
    format!("{}<tr class=\"top\">{}", &t[..at - 4], &t[at..])
}

/// Comfort (ISO 2631-1 Annex C) in words, and at the other points; the
/// head's (the model's) unless the model is left out.
fn comfort(d: &Doc, model: bool) -> String {
    let mut s = format!(
        "<p>At the seat: vector sum a_v = {} m/s²: <strong>{}</strong>.</p>\n",
        d.num("/comfort/vector_sum_m_s2", 3),
        d.strings("/comfort/seat").join(" / "),
    );
    if model {
        s.push_str(&format!(
            "<p>At the head, the model's prediction: <strong>{}</strong>.</p>\n",
            d.strings("/comfort/head").join(" / ")
        ));
    }
    if d.get("/comfort/points").is_some() {
        let mut rows = Vec::new();
        for p in d.keys("/comfort/points") {
            let pk = format!("/comfort/points/{}", seg(&p));
            for a in d.keys(&pk) {
                if a == "total_m_s2" {
                    continue;
                }
                let k = format!("{pk}/{}", seg(&a));
                let aw = if d.get(&format!("{k}/aw_rad_s2")).is_some() {
                    format!("{} rad/s²", d.num(&format!("{k}/aw_rad_s2"), 3))
                } else {
                    format!("{} m/s²", d.num(&format!("{k}/aw_m_s2"), 3))
                };
                rows.push(vec![
                    esc(&p),
                    d.text(&format!("{k}/channel")),
                    d.text(&format!("{k}/weighting")),
                    d.num(&format!("{k}/k"), 2),
                    aw,
                    d.num(&format!("{k}/weighted_m_s2"), 3),
                    d.num(&format!("{pk}/total_m_s2"), 3),
                ]);
            }
        }
        s.push_str("<h3>Other points (ISO 2631-1 §8.2.2–8.2.3)</h3>\n");
        s.push_str(&table(
            "points",
            &crate::view::report::points::POINT_HEADINGS,
            &rows,
        ));
        s.push_str(&format!(
            "<p>Overall vibration total value: {} m/s²: <strong>{}</strong>.</p>\n",
            d.num("/comfort/overall_m_s2", 3),
            d.strings("/comfort/overall_words").join(" / ")
        ));
    }
    section("comfort", "Comfort (ISO 2631-1 Annex C)", &s)
}

/// With a seat under the body: SEAT and the suspension's travel.
fn pan(d: &Doc) -> String {
    if d.get("/seat_value").is_none() {
        return String::new();
    }
    let mm = |k: &str| d.num(k, 4);
    let s = format!(
        "<p>The record is the floor; the verdicts above judge the seat pan, as the model of the seat predicts it.</p>\n<ul>\n<li>SEAT {} % (a_w pan {} / floor {} m/s²); VDV pan/floor {} %</li>\n<li>suspension travel: r.m.s. {} m, peak {} m, of {} m between the end-stops; {} excursion(s) past an end-stop</li>\n</ul>\n",
        d.num("/seat_value/seat_pct", 1),
        d.num("/seat/aw_m_s2", 3),
        d.num("/floor/aw_m_s2", 3),
        d.num("/seat_value/vdv_pct", 1),
        mm("/stroke/rms_m"),
        mm("/stroke/peak_m"),
        mm("/stroke/available_m"),
        d.num("/stroke/hits", 0)
    );
    section(
        "seat",
        "The seat (ISO 10326-1)",
        &format!("<div class=\"model\">{s}</div>\n"),
    )
}

/// The ISO 2631-5 block, where `--spine` asked for it.
fn spine(d: &Doc) -> String {
    if d.get("/spine").is_none() {
        return String::new();
    }
    let n = |k: &str, dec| d.num(&format!("/spine/{k}"), dec);
    let rows = vec![
        vec!["positive response peaks".into(), "".into(), n("peaks", 0)],
        vec![
            "acceleration dose Dz".into(),
            "m/s²".into(),
            n("dz_m_s2", 2),
        ],
        vec![
            format!("daily dose Dzd ({} h a day)", n("exposure_h", AS_TYPED)),
            "m/s²".into(),
            n("dzd_m_s2", 2),
        ],
        vec![
            "daily compressive stress Sd".into(),
            "MPa".into(),
            n("sd_mpa", 3),
        ],
        vec!["static stress".into(), "MPa".into(), n("static_mpa", 5)],
        vec!["risk factor R".into(), "".into(), n("r", 2)],
        vec![
            "probability of injury P(R)".into(),
            "".into(),
            n("probability", 2),
        ],
    ];
    let mut s = format!(
        "<p>Seat z, over {} s of record; the person: age {} at the start, {} years of it, {} days a year, {}.</p>\n",
        n("measured_s", AS_TYPED),
        n("person/age", AS_TYPED),
        n("person/years", 0),
        n("person/days", 0),
        d.text("/spine/person/sex")
    );
    s.push_str(&table("spine", &["", "unit", "value"], &rows));
    s.push_str(&format!(
        "<p><strong>{}</strong></p>\n",
        d.text("/spine/words")
    ));
    let peaks: Vec<String> = (0..d.len("/spine/largest_peaks").min(3))
        .map(|i| {
            format!(
                "{} m/s² at {} s",
                n(&format!("largest_peaks/{i}/m_s2"), 1),
                n(&format!("largest_peaks/{i}/t_s"), 2)
            )
        })
        .collect();
    if !peaks.is_empty() {
        s.push_str(&format!("<p>Largest peaks: {}.</p>\n", peaks.join(", ")));
    }
    for note in d.strings("/spine/notes") {
        s.push_str(&format!("<p class=\"note\">Note: {note}</p>\n"));
    }
    section("spine", "Multiple shocks: the spine (ISO 2631-5:2018)", &s)
}

fn warnings(d: &Doc) -> String {
    let w = d.strings("/warnings");
    if w.is_empty() {
        return String::new();
    }
    let items: String = w.iter().map(|w| format!("<li>{w}</li>\n")).collect();
    section("warnings", "Warnings", &format!("<ul>\n{items}</ul>\n"))
}
