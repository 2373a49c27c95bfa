//! `biodyn seat --psd FILE` as a real process on the files a fixed grid got
//! wrong: the figures against a brute-force integration computed here (each
//! row interval cut into 200 Simpson pieces, the library's Solver and W_k
//! at every point), the lower limit said, no NaN anywhere.

use crate::common::{fails, run};
use biodyn::iso2631::Weighting;
use biodyn::{Preset, Solver};
use serde_json::Value;
use std::f64::consts::PI;
use std::path::Path;

const SUSPENSION: &str = "paper-75kg-suspension-seat";

/// Writes `rows` as a PSD file.
fn psd_file(dir: &Path, name: &str, rows: &[(f64, f64)]) -> String {
    let mut text = String::from("f_hz,psd_m2_s4_hz\n");
    for (f, g) in rows {
        text += &format!("{f:e},{g:e}\n");
    }
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path.display().to_string()
}

/// (stdout as JSON, stderr) of a seat run that succeeds.
fn seat_json(psd: &str) -> (Value, String) {
    let (code, out, err) = run(&[
        "seat", "--preset", SUSPENSION, "--psd", psd, "--format", "json",
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        !out.contains("NaN") && !out.contains("null") && !out.contains("inf"),
        "{out}"
    );
    (serde_json::from_str(&out).expect("JSON"), err)
}

fn num(v: &Value, key: &str) -> f64 {
    v[key]
        .as_f64()
        .unwrap_or_else(|| panic!("{key} missing in {v}"))
}

/// (floor a_w, pan a_w, r.m.s. stroke) by brute force from `lo` Hz up.
fn brute(rows: &[(f64, f64)], lo: f64) -> (f64, f64, f64) {
    let body = Preset::open(SUSPENSION).expect("shipped").body;
    let seat = body.seat.as_ref().expect("a seat");
    let upper = body.links[seat.suspension].upper;
    let solver = Solver::new(&body);
    let mut sum = [0.0; 3];
    for w in rows.windows(2) {
        let ((f0, g0), (f1, g1)) = (w[0], w[1]);
        if f1 <= lo {
            continue;
        }
        let a = f0.max(lo);
        // Pieces of at most 2 mHz and 0.1 % of f, at least 200 a row interval.
        let n = 2 * (((f1 - a) / (2e-3f64).min(1e-3 * a)).ceil() as usize / 2).max(100);
        let h = (f1 - a) / n as f64;
        for i in 0..=n {
            let f = a + h * i as f64;
            let g = g0 + (g1 - g0) * (f - f0) / (f1 - f0);
            let c = [1.0, 4.0, 2.0][if i == 0 || i == n { 0 } else { 2 - i % 2 }];
            let t = solver.transfer(f);
            let wk2 = Weighting::Wk.analog(f).norm_sqr();
            let w2 = (2.0 * PI * f).powi(2);
            let k = c * h / 3.0 * g;
            sum[0] += k * wk2;
            sum[1] += k * wk2 * t[seat.pan].norm_sqr();
            sum[2] += k * (t[upper] - 1.0).norm_sqr() / (w2 * w2);
        }
    }
    (sum[0].sqrt(), sum[1].sqrt(), sum[2].sqrt())
}

fn agrees(v: &Value, b: (f64, f64, f64), tol: f64) {
    let close = |k: &str, want: f64| {
        let got = num(v, k);
        assert!(
            (got / want - 1.0).abs() < tol,
            "{k}: {got} vs brute force {want}"
        );
    };
    close("floor_aw_m_s2", b.0);
    close("pan_aw_m_s2", b.1);
    close("stroke_rms_m", b.2);
    close("seat_pct", 100.0 * b.1 / b.0);
}

/// Zero rows around a narrow peak (the fixed grid read the floor 24 % low)
/// and a peak 2 mHz wide (refused as "weighted r.m.s. 0") count in full.
#[test]
fn narrow_peaks_count_in_full() {
    let d = tempfile::tempdir().unwrap();
    let wk5 = Weighting::Wk.analog(5.0).norm();
    for (half, name) in [(0.1, "zeros.csv"), (0.001, "narrow.csv")] {
        let rows = [
            (0.5, 0.0),
            (5.0 - half, 0.0),
            (5.0, 1.0),
            (5.0 + half, 0.0),
            (20.0, 0.0),
        ];
        let (v, err) = seat_json(&psd_file(d.path(), name, &rows));
        assert!(err.is_empty(), "{err}");
        agrees(&v, brute(&rows, 0.1), 1e-5);
        // The triangle's area is `half` (m/s²)², weighted by about |W_k(5 Hz)|².
        let floor = num(&v, "floor_aw_m_s2");
        assert!(
            (floor / (half.sqrt() * wk5) - 1.0).abs() < 1e-3,
            "{name}: {floor}"
        );
    }
}

/// A measured PSD (512 rows at 100/1024 Hz, scattered as an estimate is):
/// the fixed grid read it 2.7 % low; now as the brute force.
#[test]
fn a_measured_psd_reads_as_its_rows() {
    let d = tempfile::tempdir().unwrap();
    let em6 = biodyn::time::InputClass::parse("EM6").unwrap();
    let mut rng = biodyn::Rng::new(11);
    let rows: Vec<(f64, f64)> = (1..=512)
        .map(|i| {
            let f = 100.0 / 1024.0 * f64::from(i);
            (f, em6.psd(f) * (1.0 + rng.symmetric(0.3)))
        })
        .collect();
    let (v, err) = seat_json(&psd_file(d.path(), "cab.csv", &rows));
    // Its first row is at 0.098 Hz: below the limit, said.
    assert!(
        err.contains("the rows below 0.1 Hz (from 0.09765625 Hz) are left out"),
        "{err}"
    );
    assert_eq!(v["integrated_hz"], serde_json::json!([0.1, 50.0]));
    agrees(&v, brute(&rows, 0.1), 1e-5);
}

/// A band from 1e-300 Hz: integrated from 0.1 Hz, said on stderr and in the
/// table's title; no NaN stroke (the fixed grid gave SEAT 144 % and NaN), and
/// a design search on it names a finite least stroke.
#[test]
fn a_band_from_1e_300_hz_is_integrated_from_the_lower_limit() {
    let d = tempfile::tempdir().unwrap();
    let rows = [(1e-300, 1.0), (100.0, 1.0)];
    let p = psd_file(d.path(), "wide.csv", &rows);
    let (v, err) = seat_json(&p);
    assert!(
        err.contains("wide.csv: the rows below 0.1 Hz (from 1e-300 Hz) are left out"),
        "{err}"
    );
    agrees(&v, brute(&rows, 0.1), 1e-5);
    let (code, out, _) = run(&["seat", "--preset", SUSPENSION, "--psd", &p]);
    assert_eq!(code, Some(0));
    assert!(
        out.contains("(2 rows, 1e-300–100 Hz, integrated over 0.1–100 Hz)"),
        "{out}"
    );
    let (code, _, e) = run(&[
        "seat",
        "--preset",
        SUSPENSION,
        "--psd",
        &p,
        "--vary",
        "suspension.c=200..4000",
        "--stroke-rms-max",
        "1e-9",
    ]);
    assert_eq!(code, Some(1), "{e}");
    assert!(
        e.contains("the least is 0.0065") && !e.contains("NaN"),
        "{e}"
    );
    // A file wholly below the limit is refused, naming its range.
    let low = psd_file(d.path(), "low.csv", &[(0.01, 1.0), (0.05, 1.0)]);
    let e = fails(&["seat", "--preset", SUSPENSION, "--psd", &low]);
    assert!(
        e.contains("the PSD's rows span 0.01 to 0.05 Hz, outside the 0.1 to 1000 Hz"),
        "{e}"
    );
}

/// A seat model under a tri-axial record is refused with the hint about
/// its axes, not one about --exposure.
#[test]
fn a_seat_refusing_horizontal_axes_hints_at_the_axes() {
    let e = fails(&[
        "assess",
        "--preset",
        SUSPENSION,
        "--input",
        "examples/tractor-seat-xyz-g.csv",
    ]);
    assert!(e.contains("the seat model is vertical"), "{e}");
    let hint = e.lines().nth(1).unwrap();
    assert!(
        hint.contains("--axes z=COL") && !hint.contains("--exposure"),
        "{e}"
    );
}
