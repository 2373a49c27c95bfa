//! What the model predicts in `assess`'s page, kept apart from what was
//! measured: the head beside the seat, every segment, and the head's bands,
//! each boxed or titled as the model's prediction (nobody measured them).

use super::{AS_TYPED, Doc, SIG3, metric_cells, metric_head, section, table};

/// The seat's measured values beside the model's prediction at the head,
/// and every segment's.
pub fn prediction(d: &Doc, head: &str) -> String {
    let row = |name: &str, unit: &str, key: &str, dec| {
        vec![
            name.to_string(),
            unit.to_string(),
            d.num(&format!("/seat/{key}"), dec),
            d.num(&format!("/head/{key}"), dec),
        ]
    };
    let rows = vec![
        row("weighted r.m.s. a_w", "m/s²", "aw_m_s2", 3),
        row("peak", "m/s²", "peak_m_s2", 3),
        row("crest factor", "", "crest_factor", 2),
        row("MTVV (1 s running r.m.s.)", "m/s²", "mtvv_m_s2", 3),
        row("VDV", "m/s^1.75", "vdv_m_s175", 2),
        row("A(8)", "m/s²", "a8_m_s2", 3),
        row(
            "VDV over the exposure",
            "m/s^1.75",
            "vdv_exposure_m_s175",
            2,
        ),
        row("motion sickness a_wf (Wf)", "m/s²", "awf_m_s2", 4),
        row("MSDV over the record", "m/s^1.5", "msdv_m_s15", 3),
        row(
            "MSDV over the exposure",
            "m/s^1.5",
            "msdv_exposure_m_s15",
            2,
        ),
        row("unadapted adults who may vomit", "%", "vomit_pct", 1),
    ];
    // Past the 70 % ISO 2631-1 Annex D's estimate rests on: its words.
    let mut rows = rows;
    for (col, who) in [(2, "seat"), (3, "head")] {
        if d.get(&format!("/{who}/vomit_beyond_annex_d")) == Some(&serde_json::Value::Bool(true))
            && let Some(r) = rows.last_mut()
        {
            r[col] = d.text(&format!("/{who}/vomit_words"));
        }
    }
    let mut s = format!(
        "<p><span class=\"model-tag\">The head's column is the model's prediction, not a measurement:</span> the model <code>{}</code> driven by the seat's measured z gives the motion of the head ({head}). It is what such a body would feel; nobody measured it.</p>\n",
        d.text("/model")
    );
    s.push_str(&table(
        "predict",
        &[
            "",
            "unit",
            "seat z (measured)",
            &format!("head, {head} (model's prediction)"),
        ],
        &rows,
    ));
    let segs: Vec<Vec<String>> = (0..d.len("/segments"))
        .map(|i| {
            let k = format!("/segments/{i}");
            let mut row = vec![d.text(&format!("{k}/name"))];
            row.extend(metric_cells(d, &k));
            row
        })
        .collect();
    s.push_str("<h3>Every segment (the model's prediction; weighted absolute acceleration)</h3>\n");
    s.push_str(&table("segments", &metric_head(&["segment"]), &segs));
    section(
        "prediction",
        "The seat and the head: the model's prediction",
        &format!("<div class=\"model\">\n{s}</div>\n"),
    )
}

/// The one-third-octave bands of the seat and, with the `model`, the
/// predicted head.
pub fn bands(d: &Doc, model: bool) -> String {
    let n = d.len("/bands");
    if n == 0 {
        return String::new();
    }
    let rows: Vec<Vec<String>> = (0..n)
        .map(|i| {
            let k = format!("/bands/{i}");
            let mut row = vec![
                d.num(&format!("{k}/f_hz"), AS_TYPED),
                d.num(&format!("{k}/seat_m_s2"), SIG3),
            ];
            if model {
                row.push(d.num(&format!("{k}/head_m_s2"), SIG3));
            }
            row
        })
        .collect();
    let head = [
        "f Hz",
        "seat m/s² (measured)",
        "head m/s² (model's prediction)",
    ];
    let t = table("bands", &head[..if model { 3 } else { 2 }], &rows);
    section("bands", "One-third-octave bands (unweighted r.m.s., z)", &t)
}
