//! What `biodyn assess` prints, as text and JSON, from the library's
//! assessment: the command line and the TUI's Vibration export (`x`) write
//! the same bytes for the same record and model.

use super::axes;
use super::input::Source;
use super::points;
use super::spine;
use super::table::{fx, table};
use biodyn::iso2631::spine::Spine;
use biodyn::iso2631::{Assessment, Channel, K_M, MIN_SICKNESS_S, Sickness};
use serde_json::{Value, json};

/// Without `--spine`: a crest factor above 9 on the seat's z sends the
/// record to ISO 2631-5 too.
pub fn shock_note(r: &Assessment) -> Option<String> {
    let crest = r.seat.metrics.crest;
    (crest > 9.0).then(|| {
        format!(
            "seat z crest factor {} is above 9: ISO 2631-5 (multiple shocks) applies; add --spine age=A,years=N,days=D,sex=male|female for the spinal dose and risk",
            biodyn::iso2631::above(crest, 9.0, 1)
        )
    })
}

fn metrics_json(c: &Channel) -> serde_json::Map<String, Value> {
    let m = &c.metrics;
    let mut o = serde_json::Map::new();
    for (k, v) in [
        ("aw_m_s2", m.aw),
        ("peak_m_s2", m.peak),
        ("crest_factor", m.crest),
        ("mtvv_m_s2", m.mtvv),
        ("vdv_m_s175", m.vdv),
        ("a8_m_s2", c.exposure.a8),
        ("vdv_exposure_m_s175", c.exposure.vdv),
    ] {
        o.insert(k.into(), json!(v));
    }
    o
}

/// The JSON document `biodyn assess --format json` prints.
pub fn json(r: &Assessment, model: &str, source: &Source) -> Value {
    let segments: Vec<Value> = r
        .segments
        .iter()
        .map(|(name, c)| {
            let mut o = metrics_json(c);
            o.insert("name".into(), json!(name));
            Value::Object(o)
        })
        .collect();
    let bands: Vec<Value> = r
        .bands
        .iter()
        .map(|b| json!({"f_hz": b.f_hz, "seat_m_s2": b.seat, "head_m_s2": b.head}))
        .collect();
    let mut seat = metrics_json(&r.seat);
    sickness_json(&mut seat, &r.sickness_seat);
    let mut head = metrics_json(&r.head);
    sickness_json(&mut head, &r.sickness_head);
    let spine = match &r.spine {
        Some(Ok(s)) => spine_json(s),
        _ => Value::Null,
    };
    let mut v = json!({
        "model": model,
        "input": source.json(r.fs),
        "fs_hz": r.fs,
        "duration_s": r.duration_s,
        "exposure_h": r.exposure_h,
        "seat": Value::Object(seat),
        "head": Value::Object(head),
        "segments": segments,
        "axes": axes::json(&r.axes),
        "health": axes::health_json(&r.health),
        "eu": {"a8": r.eu.a8.words(), "vdv": r.eu.vdv.words()},
        "comfort": {
            "vector_sum_m_s2": r.comfort_vector,
            "seat": r.comfort_seat,
            "head": r.comfort_head,
        },
        "spine": spine,
        "bands": bands,
        "warnings": r.warnings,
    });
    if let Some(p) = &r.points {
        points::comfort_json(&mut v["comfort"], p);
    }
    super::pan::json(r, &mut v, metrics_json);
    v
}

/// MSDV (Wf, ISO 2631-1 Annex D) beside a channel's metrics.
fn sickness_json(o: &mut serde_json::Map<String, Value>, s: &Sickness) {
    o.insert("awf_m_s2".into(), json!(s.aw));
    o.insert("msdv_m_s15".into(), json!(s.msdv));
    o.insert("msdv_exposure_m_s15".into(), json!(s.msdv_exposure));
    o.insert("vomit_pct".into(), json!(s.vomit_pct));
    o.insert("vomit_beyond_annex_d".into(), json!(s.beyond_annex_d));
    o.insert("vomit_words".into(), json!(s.vomit_words()));
}

/// The ISO 2631-5 block: the dose, the daily dose, Annex C's risk.
fn spine_json(s: &Spine) -> Value {
    let largest: Vec<Value> = s
        .largest(5)
        .iter()
        .map(|&(t, v)| json!({"t_s": t, "m_s2": v}))
        .collect();
    let mut o = spine::annex_c(&s.person, s.dzd, &s.risk);
    for (k, v) in [
        ("measured_s", json!(s.duration_s)),
        ("exposure_h", json!(s.exposure_h)),
        ("peaks", json!(s.dose.count)),
        ("largest_peaks", json!(largest)),
        ("dz_m_s2", json!(s.dose.dz)),
        ("mean_m_s2", json!(s.mean_m_s2)),
        ("notes", json!(s.notes)),
    ] {
        o.insert(k.into(), v);
    }
    Value::Object(o)
}

fn hours(h: f64) -> String {
    crate::view::format::typed(h)
}

/// The text `biodyn assess` prints (its table format); `head` is the
/// head segment's name.
pub fn text(r: &Assessment, model: &str, source: &Source, head: &str) -> String {
    let mut s = format!(
        "{model}: {}\n{} s at {} Hz; exposure {} h a day\n\n",
        source.line(),
        fx(r.duration_s, 3)
            .trim_end_matches('0')
            .trim_end_matches('.'),
        r.fs,
        hours(r.exposure_h)
    );
    let at = if r.floor.is_some() {
        "At the seat pan"
    } else {
        "At the seat"
    };
    s.push_str(&axes::text(&r.axes, &r.health, r.exposure_h, at));
    s.push_str(&format!(
        "comfort (ISO 2631-1 Annex C): seat vector sum {:.3} m/s²: {}; head {}\n",
        r.comfort_vector,
        r.comfort_seat.join(" / "),
        r.comfort_head.join(" / ")
    ));
    if let Some(p) = &r.points {
        s.push_str(&points::comfort_table(p));
    }
    s.push_str(&super::pan::text(r));

    s.push_str(&sickness_text(r, head));
    if let Some(Ok(sp)) = &r.spine {
        s.push_str(&spine_text(sp));
    }
    s.push_str(&format!(
        "\nThe body, driven by z ({} weighting):\n",
        r.weighting.name()
    ));
    let (se, he) = (&r.seat, &r.head);
    let row = |name: &str, unit: &str, f: &dyn Fn(&Channel) -> f64, d: usize| {
        vec![
            name.to_string(),
            unit.to_string(),
            fx(f(se), d),
            fx(f(he), d),
        ]
    };
    let exp = format!("VDV over {} h", hours(r.exposure_h));
    let rows = vec![
        row("weighted r.m.s. a_w", "m/s²", &|c| c.metrics.aw, 3),
        row("peak", "m/s²", &|c| c.metrics.peak, 3),
        row("crest factor", "", &|c| c.metrics.crest, 2),
        row("MTVV (1 s running r.m.s.)", "m/s²", &|c| c.metrics.mtvv, 3),
        row("VDV", "m/s^1.75", &|c| c.metrics.vdv, 2),
        row("A(8)", "m/s²", &|c| c.exposure.a8, 3),
        row(&exp, "m/s^1.75", &|c| c.exposure.vdv, 2),
    ];
    let head_col = format!("head ({head})");
    s.push_str(&table(&["", "unit", "seat z", &head_col], &rows));

    s.push_str("\nEvery segment (weighted absolute acceleration):\n");
    let seg_rows: Vec<Vec<String>> = r
        .segments
        .iter()
        .map(|(n, c)| {
            vec![
                n.clone(),
                fx(c.metrics.aw, 3),
                fx(c.metrics.peak, 3),
                fx(c.metrics.crest, 2),
                fx(c.metrics.mtvv, 3),
                fx(c.metrics.vdv, 2),
                fx(c.exposure.a8, 3),
            ]
        })
        .collect();
    s.push_str(&table(
        &[
            "segment",
            "a_w m/s²",
            "peak m/s²",
            "crest",
            "MTVV m/s²",
            "VDV m/s^1.75",
            "A(8) m/s²",
        ],
        &seg_rows,
    ));

    s.push_str("\nOne-third-octave bands (unweighted r.m.s.):\n");
    let opt = |v: Option<f64>, d| v.map_or("-".to_string(), |v| fx(v, d));
    let band_rows: Vec<Vec<String>> = r
        .bands
        .iter()
        .map(|b| {
            let ratio = match (b.seat, b.head) {
                (Some(s), Some(h)) if s > 0.0 => fx(h / s, 2),
                _ => "-".into(),
            };
            vec![format!("{}", b.f_hz), opt(b.seat, 4), opt(b.head, 4), ratio]
        })
        .collect();
    s.push_str(&table(
        &["f Hz", "seat m/s²", "head m/s²", "head/seat"],
        &band_rows,
    ));
    if !r.warnings.is_empty() {
        s.push_str("\nwarnings:\n");
        for w in &r.warnings {
            s.push_str(&format!("  - {w}\n"));
        }
    }
    s
}

/// Motion sickness in two lines: the seat's (the input) and the head's
/// (the model's prediction).
fn sickness_text(r: &Assessment, head: &str) -> String {
    let line = |who: &str, x: &Sickness| {
        format!(
            "  {who}: a_wf {} m/s², MSDV {} m/s^1.5 over the record, {} over {} h: {}\n",
            fx(x.aw, 4),
            fx(x.msdv, 3),
            fx(x.msdv_exposure, 2),
            hours(r.exposure_h),
            x.vomit_words()
        )
    };
    let mut s = format!("\nMotion sickness (ISO 2631-1 Annex D, Wf on z; K_m = {K_M:.3}):\n");
    s.push_str(&line("seat z", &r.sickness_seat));
    s.push_str(&line(
        &format!("head ({head}), the model's"),
        &r.sickness_head,
    ));
    if r.sickness_seat.short {
        s.push_str(&format!(
            "  (the record is under {MIN_SICKNESS_S} s: Wf's 0.1 Hz band is barely in it)\n"
        ));
    }
    s
}

/// The ISO 2631-5 block.
fn spine_text(sp: &Spine) -> String {
    let mut s = format!(
        "\nMultiple shocks, the spine (ISO 2631-5:2018, seat z; {}):\n",
        sp.person
    );
    let rows = vec![
        vec![
            "positive response peaks".into(),
            "".into(),
            format!("{}", sp.dose.count),
        ],
        vec![
            "acceleration dose Dz".into(),
            "m/s²".into(),
            fx(sp.dose.dz, 2),
        ],
        vec![
            format!("daily dose Dzd ({} h a day)", hours(sp.exposure_h)),
            "m/s²".into(),
            fx(sp.dzd, 2),
        ],
        vec![
            "daily compressive stress Sd".into(),
            "MPa".into(),
            fx(sp.risk.sd, 3),
        ],
        vec!["risk factor R".into(), "".into(), fx(sp.risk.r, 2)],
        vec![
            "probability of injury P(R)".into(),
            "".into(),
            fx(sp.risk.probability, 2),
        ],
    ];
    s.push_str(&table(&["", "unit", "value"], &rows));
    s.push_str(&format!("  {}\n", sp.risk.band.words()));
    let top = sp.largest(3);
    if !top.is_empty() {
        let list: Vec<String> = top
            .iter()
            .map(|(t, v)| format!("{} m/s² at {} s", fx(*v, 1), fx(*t, 2)))
            .collect();
        s.push_str(&format!("  largest peaks: {}\n", list.join(", ")));
    }
    for n in &sp.notes {
        s.push_str(&format!("  note: {n}\n"));
    }
    s
}
