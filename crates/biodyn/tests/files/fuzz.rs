//! Fuzz harness for the preset parser and the network-file parser (issue 8).
//! cargo-fuzz needs a nightly toolchain; this is the same idea on stable,
//! with proptest: valid files mutated with knowledge of their structure,
//! plus arbitrary bytes. Every case must finish without a panic, within
//! [`PER_CASE`], and an error must be one non-empty, bounded, printable line.
//! A preset that loads must be solvable and survive its own save:
//! `parse(to_toml(p)) == p`.
//!
//! Not part of the normal test run (every test is `#[ignore]`). Run with
//!
//! ```text
//! PROPTEST_CASES=100000000 FUZZ_SECONDS=600 \
//!   cargo test --release -p biodyn --test files -- --ignored --nocapture fuzz::
//! ```
//!
//! `PROPTEST_CASES` is the number of cases per batch (default 256), and
//! `FUZZ_SECONDS`, if set, keeps running batches until that much time has
//! passed; each test prints how many cases it ran. `FUZZ_SEED` fixes the
//! first batch's seed to replay a run.

use biodyn::body::{Origin, SHIPPED};
use biodyn::{Preset, ann};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestCaseError, TestRng, TestRunner};
use std::path::Path;
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::{Duration, Instant};

/// The most time one case may take (release build); a slower case is a
/// failure, since a real file of that shape would stall the program.
const PER_CASE: Duration = Duration::from_secs(2);

/// The longest error line accepted: errors quote short excerpts only.
const MAX_ERROR: usize = 1000;

// ---- the driver --------------------------------------------------------------

/// Runs `test` on values of `strategy` for `PROPTEST_CASES` cases, repeated
/// in fresh batches until `FUZZ_SECONDS` have passed. Panics on the first
/// failure with the (shrunk) input's description.
fn fuzz<S: Strategy>(name: &str, strategy: S, test: impl Fn(S::Value) -> Result<(), TestCaseError>)
where
    S::Value: std::fmt::Debug,
{
    let env = |k: &str| std::env::var(k).ok().and_then(|v| v.parse::<u64>().ok());
    let cases = env("PROPTEST_CASES").unwrap_or(256).max(1);
    let budget = env("FUZZ_SECONDS").map(Duration::from_secs);
    let mut seed = env("FUZZ_SEED").unwrap_or_else(|| {
        std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(1, |d| d.as_nanos() as u64)
    });
    let start = Instant::now();
    let mut total = 0u64;
    loop {
        let config = Config {
            cases: u32::try_from(cases).unwrap_or(u32::MAX),
            failure_persistence: None,
            max_shrink_iters: 2000,
            ..Config::default()
        };
        let mut bytes = [0u8; 32];
        bytes[..8].copy_from_slice(&seed.to_le_bytes());
        let rng = TestRng::from_seed(RngAlgorithm::ChaCha, &bytes);
        let mut runner = TestRunner::new_with_rng(config, rng);
        let ran = std::cell::Cell::new(0u64);
        let result = runner.run(&strategy, |v| {
            ran.set(ran.get() + 1);
            test(v)
        });
        total += ran.get();
        if let Err(e) = result {
            panic!("{name}: failed after {total} cases (batch seed {seed}): {e}");
        }
        match budget {
            Some(b) if start.elapsed() < b => seed = seed.wrapping_add(0x9e37_79b9_7f4a_7c15),
            _ => break,
        }
    }
    println!(
        "{name}: {total} cases in {:.1} s, no failure (so far in this process: {} loaded, {} refused)",
        start.elapsed().as_secs_f64(),
        LOADED.load(Ordering::Relaxed),
        REFUSED.load(Ordering::Relaxed),
    );
}

/// Cases that loaded, and cases refused with an error, over the run: a
/// harness whose mutations never load tests only the error paths.
static LOADED: AtomicU64 = AtomicU64::new(0);
static REFUSED: AtomicU64 = AtomicU64::new(0);

/// An error message fit to print: non-empty, one line, bounded, printable.
fn check_message(msg: &str) -> Result<(), TestCaseError> {
    REFUSED.fetch_add(1, Ordering::Relaxed);
    prop_assert!(!msg.trim().is_empty(), "empty error message");
    prop_assert!(
        !msg.contains('\n') && !msg.contains('\r'),
        "multi-line: {msg:?}"
    );
    prop_assert!(
        msg.chars().count() <= MAX_ERROR,
        "{} characters: {:?}",
        msg.chars().count(),
        msg.chars().take(300).collect::<String>()
    );
    prop_assert!(
        !msg.chars().any(|c| c.is_control()),
        "control character in {msg:?}"
    );
    Ok(())
}

fn timed<T>(f: impl FnOnce() -> T) -> Result<T, TestCaseError> {
    let start = Instant::now();
    let out = f();
    let took = start.elapsed();
    prop_assert!(took < PER_CASE, "one case took {took:?}");
    Ok(out)
}

// ---- mutations of text -----------------------------------------------------------

/// One edit to a text; positions are taken modulo its length.
#[derive(Debug, Clone)]
enum Edit {
    /// Overwrite one byte (the result may not be UTF-8).
    Byte(usize, u8),
    /// Delete up to `n` bytes.
    Delete(usize, usize),
    /// Insert a token.
    Insert(usize, String),
    /// Replace the value of the n-th `key = value` line.
    Value(usize, String),
    /// Duplicate, or delete, the n-th line.
    DupLine(usize),
    DropLine(usize),
}

/// Tokens of the preset format and values that have broken parsers before.
fn toml_tokens() -> Vec<String> {
    let mut v: Vec<String> = [
        "[[segment]]\n",
        "[[link]]\n",
        "[band]\n",
        "name = ",
        "mass_kg = ",
        "share = ",
        "body_mass_kg = ",
        "upper = ",
        "lower = ",
        "\"seat\"",
        "k_n_per_m = ",
        "c_ns_per_m = ",
        "head = ",
        "schema = ",
        "from_hz = ",
        "to_hz = ",
        "step_hz = ",
        "=",
        "\"",
        "'''",
        "\"\"\"",
        "[",
        "]",
        "{",
        "}",
        ".",
        ",",
        "\n",
        "#",
        "\\",
        "\\u0000",
        "\\u001b",
        "é",
        "\u{202e}",
        "\u{0}",
        "\r",
        "\t",
        "a.b.c = 1\n",
        "x = { y = { z = 1 } }\n",
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    v.extend(nasty_values());
    v.push(format!("[{}]\n", vec!["a"; 100].join(".")));
    v.push(format!("{} = 1\n", vec!["k"; 90].join(".")));
    v.push(format!("x = {}1{}\n", "[".repeat(5000), "]".repeat(5000)));
    v.push(format!("x = {}\n", "{a=".repeat(500)));
    v
}

/// Values for a `key = value` line.
fn nasty_values() -> Vec<String> {
    let mut v: Vec<String> = [
        "0",
        "-0.0",
        "1",
        "-1",
        "1e308",
        "1e-308",
        "1e-320",
        "5e-324",
        "1e400",
        "nan",
        "-nan",
        "inf",
        "-inf",
        "0.001",
        "0.000999",
        "1000000",
        "1000000.0001",
        "1e12",
        "1.0000001e12",
        "1e10",
        "18446744073709551616",
        "9223372036854775807",
        "-9223372036854775808",
        "0x10",
        "1_000",
        "true",
        "\"\"",
        "\"seat\"",
        "\"m2\"",
        "\"K3\"",
        "\"body_mass\"",
        "\"x.k\"",
        "\"head\\nneck\"",
        "\"head\\u001b[31m\"",
        "\" chest\"",
        "\"head-neck\"",
        "\"chest\"",
        "\"pelvis\"",
        "\"pelvis-seat\"",
        "[]",
        "[1, 2]",
        "{}",
        "1979-05-27",
        "'lit'",
        // Band mutations (issue 19 item 9): past the physical limits and
        // just inside them.
        "1e100",
        "1e-13",
        "0.001",
        "0.00099999",
        "100000",
        "100000.00001",
        "1e-7",
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    v.push(format!("1{}.0", "0".repeat(400)));
    v.push(format!("\"{}\"", "n".repeat(5000)));
    v.push(format!("\"{}\"", "é".repeat(70)));
    v
}

fn edit_strategy(tokens: Vec<String>, values: Vec<String>) -> impl Strategy<Value = Edit> {
    prop_oneof![
        (any::<usize>(), any::<u8>()).prop_map(|(p, b)| Edit::Byte(p, b)),
        (any::<usize>(), 1usize..40).prop_map(|(p, n)| Edit::Delete(p, n)),
        (any::<usize>(), prop::sample::select(tokens)).prop_map(|(p, t)| Edit::Insert(p, t)),
        (any::<usize>(), prop::sample::select(values)).prop_map(|(n, v)| Edit::Value(n, v)),
        any::<usize>().prop_map(Edit::DupLine),
        any::<usize>().prop_map(Edit::DropLine),
    ]
}

/// Applies edits to bytes (which may stop being UTF-8).
fn apply(text: &str, edits: &[Edit]) -> Vec<u8> {
    let mut b = text.as_bytes().to_vec();
    for e in edits {
        let len = b.len().max(1);
        match e {
            Edit::Byte(p, x) => {
                if !b.is_empty() {
                    let i = p % b.len();
                    b[i] = *x;
                }
            }
            Edit::Delete(p, n) => {
                let i = p % len;
                let j = (i + n).min(b.len());
                if i < j {
                    b.drain(i..j);
                }
            }
            Edit::Insert(p, t) => {
                let i = p % (b.len() + 1);
                b.splice(i..i, t.bytes());
            }
            Edit::Value(n, v) => {
                let s = String::from_utf8_lossy(&b).into_owned();
                let mut lines: Vec<String> = s.split('\n').map(str::to_string).collect();
                let with_value: Vec<usize> = (0..lines.len())
                    .filter(|&i| lines[i].contains(" = "))
                    .collect();
                if !with_value.is_empty() {
                    let i = with_value[n % with_value.len()];
                    let key = lines[i].split(" = ").next().unwrap_or("").to_string();
                    lines[i] = format!("{key} = {v}");
                }
                b = lines.join("\n").into_bytes();
            }
            Edit::DupLine(n) | Edit::DropLine(n) => {
                let s = String::from_utf8_lossy(&b).into_owned();
                let mut lines: Vec<String> = s.split('\n').map(str::to_string).collect();
                let i = n % lines.len();
                if matches!(e, Edit::DupLine(_)) {
                    let l = lines[i].clone();
                    lines.insert(i, l);
                } else {
                    lines.remove(i);
                }
                b = lines.join("\n").into_bytes();
            }
        }
    }
    b
}

// ---- presets -----------------------------------------------------------------------

/// Parses preset bytes as `Preset::load` would see them (the text part) and
/// checks the outcome.
fn check_preset_bytes(bytes: &[u8]) -> Result<(), TestCaseError> {
    let Ok(text) = std::str::from_utf8(bytes) else {
        return Ok(()); // covered by the file-level test below
    };
    let origin = Origin::File("fuzz.toml".into());
    match timed(|| Preset::parse(text, &origin))? {
        Err(e) => check_message(&e.to_string()),
        Ok(p) => {
            LOADED.fetch_add(1, Ordering::Relaxed);
            p.body
                .validate()
                .map_err(|e| TestCaseError::fail(format!("loaded but invalid: {e}")))?;
            // Its band is within the physical limits (no NaN rows).
            p.band
                .validate()
                .map_err(|e| TestCaseError::fail(format!("loaded with a bad band: {e}")))?;
            // What loads must be solvable without a panic, at its band's
            // ends too.
            let solver = biodyn::Solver::new(&p.body);
            for f in [4.5, p.band.from, p.band.to] {
                let r = timed(|| solver.at(f))?;
                let _ = r.mag(biodyn::Function::Apms);
            }
            // What loads must save and load back unchanged.
            let again = timed(|| Preset::parse(&p.to_toml(), &origin))?;
            match again {
                Ok(q) => prop_assert_eq!(q, p),
                Err(e) => prop_assert!(false, "loaded, saved, then refused: {e}"),
            }
            Ok(())
        }
    }
}

#[test]
#[ignore = "fuzz: run with --ignored (see the file's header)"]
fn fuzz_preset_mutations() {
    let bases: Vec<String> = SHIPPED.iter().map(|(_, t)| t.to_string()).collect();
    let edits = prop::collection::vec(edit_strategy(toml_tokens(), nasty_values()), 1..8);
    fuzz(
        "preset mutations",
        (prop::sample::select(bases), edits),
        |(base, edits)| check_preset_bytes(&apply(&base, &edits)),
    );
}

#[test]
#[ignore = "fuzz: run with --ignored (see the file's header)"]
fn fuzz_preset_arbitrary_bytes() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("fuzz.toml");
    fuzz(
        "preset arbitrary bytes",
        prop::collection::vec(any::<u8>(), 0..2000),
        |bytes| {
            check_preset_bytes(&bytes)?;
            // The whole door: a real file through Preset::load.
            std::fs::write(&path, &bytes).map_err(|e| TestCaseError::fail(e.to_string()))?;
            if let Err(e) = timed(|| Preset::load(&path))? {
                check_message(&e.to_string())?;
            }
            Ok(())
        },
    );
}

// ---- network files -------------------------------------------------------------------

/// A valid network file's text: a small network trained for a few epochs,
/// on the paper's body (file version 1) or on a 5-segment chain (version 2,
/// the body stored in the file).
fn network_text(on_a_model: bool) -> String {
    use biodyn::ann::{Case, Flow, Settings, Trainer, train};
    let (case, mut s) = if on_a_model {
        let segs = ["a", "b", "c", "d", "e"]
            .iter()
            .zip([4.0, 20.0, 8.0, 10.0, 6.0])
            .map(|(n, m)| biodyn::Segment::new(n, m))
            .collect();
        let base = biodyn::Body::chain(
            segs,
            &[3e5, 2e5, 1.6e5, 9e4, 5e4],
            &[400.0, 4000.0, 4000.0, 2000.0, 1000.0],
        );
        let c = Case::MassApms;
        (
            c,
            Settings::for_trainer_on(c, Trainer::Lm, Some(base)).expect("a valid base"),
        )
    } else {
        (Case::K4Stht, Settings::lm(Case::K4Stht))
    };
    s.epochs = 2;
    s.ensemble = 2;
    let out = train(case, &s, &mut |_| Flow::Continue).expect("a quick training runs");
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("net.json");
    ann::save_network(&p, &out.net).expect("saved");
    std::fs::read_to_string(&p).unwrap()
}

/// One edit to a JSON document, at the n-th node (depth-first).
#[derive(Debug, Clone)]
enum JsonEdit {
    Replace(usize, serde_json::Value),
    /// Remove the node from its object or array.
    Remove(usize),
    /// Repeat an array's first element `k` times more.
    Grow(usize, usize),
}

fn nasty_json() -> impl Strategy<Value = serde_json::Value> {
    use serde_json::{Value, json};
    let deep = (1usize..300).prop_map(|d| {
        let mut v = json!(1);
        for _ in 0..d {
            v = Value::Array(vec![v]);
        }
        v
    });
    prop_oneof![
        prop::sample::select(vec![
            json!(0),
            json!(-1),
            json!(0.0),
            json!(-0.0),
            json!(1e308),
            json!(-1e308),
            json!(1e-308),
            json!(5e-324),
            json!(u64::MAX),
            json!(i64::MIN),
            json!(10_001),
            json!(100_000_000),
            json!(null),
            json!(true),
            json!(""),
            json!("k4-stht"),
            json!("mass-apms"),
            json!("lm"),
            json!("backprop"),
            json!("biodyn-network"),
            json!("x\u{1b}[31m\ny"),
            json!([]),
            json!({}),
            json!([0, 0]),
            json!([2, 1]),
            json!([2, 10000, 1]),
            json!([5, 6, 4, 1]),
            json!({"log": true, "min": 1.0, "max": 1.0}),
            json!({"log": true, "min": -1e300, "max": 1e300}),
            // Network values (issue 19 item 8): weights and biases that
            // overflow a prediction, an output bias of 700 (e^700).
            json!(700.0),
            json!(-700.0),
            json!(710.0),
            json!(1e300),
            json!(-1e300),
            json!({"log": true, "min": 10.89, "max": 1e308}),
        ]),
        any::<f64>()
            .prop_map(|f| serde_json::Number::from_f64(f).map_or(Value::Null, Value::Number)),
        any::<i64>().prop_map(|i| json!(i)),
        "\\PC{0,40}".prop_map(Value::String),
        (1usize..2000).prop_map(|n| Value::String("s".repeat(n * 50))),
        deep,
        (0usize..3000).prop_map(|n| Value::Array(vec![json!(0.5); n])),
    ]
}

fn json_edit_strategy() -> impl Strategy<Value = JsonEdit> {
    prop_oneof![
        3 => (any::<usize>(), nasty_json()).prop_map(|(n, v)| JsonEdit::Replace(n, v)),
        1 => any::<usize>().prop_map(JsonEdit::Remove),
        1 => (any::<usize>(), 1usize..50).prop_map(|(n, k)| JsonEdit::Grow(n, k)),
    ]
}

/// Number of nodes under (and including) `v`.
fn count(v: &serde_json::Value) -> usize {
    1 + match v {
        serde_json::Value::Array(a) => a.iter().map(count).sum(),
        serde_json::Value::Object(o) => o.values().map(count).sum(),
        _ => 0,
    }
}

/// Applies `f` to the n-th node below the root (depth-first), giving it the
/// parent container and the child's key or index.
fn at_nth(v: &mut serde_json::Value, n: &mut usize, e: &JsonEdit) -> bool {
    use serde_json::Value;
    match v {
        Value::Array(a) => {
            for i in 0..a.len() {
                if *n == 0 {
                    match e {
                        JsonEdit::Replace(_, x) => a[i] = x.clone(),
                        JsonEdit::Remove(_) => {
                            a.remove(i);
                        }
                        JsonEdit::Grow(_, k) => {
                            if let Value::Array(inner) = &mut a[i]
                                && let Some(first) = inner.first().cloned()
                            {
                                inner.extend(std::iter::repeat_n(first, *k));
                            }
                        }
                    }
                    return true;
                }
                *n -= 1;
                if at_nth(&mut a[i], n, e) {
                    return true;
                }
            }
        }
        Value::Object(o) => {
            let keys: Vec<String> = o.keys().cloned().collect();
            for k in keys {
                if *n == 0 {
                    match e {
                        JsonEdit::Replace(_, x) => {
                            o.insert(k, x.clone());
                        }
                        JsonEdit::Remove(_) => {
                            o.remove(&k);
                        }
                        JsonEdit::Grow(_, g) => {
                            if let Some(Value::Array(inner)) = o.get_mut(&k)
                                && let Some(first) = inner.first().cloned()
                            {
                                inner.extend(std::iter::repeat_n(first, *g));
                            }
                        }
                    }
                    return true;
                }
                *n -= 1;
                if let Some(child) = o.get_mut(&k)
                    && at_nth(child, n, e)
                {
                    return true;
                }
            }
        }
        _ => {}
    }
    false
}

/// Parses a network file's bytes and checks the outcome; a net that loads
/// must predict without a panic.
fn check_network_bytes(bytes: &[u8]) -> Result<(), TestCaseError> {
    let Ok(text) = std::str::from_utf8(bytes) else {
        return Ok(());
    };
    match timed(|| ann::parse_network(text, Path::new("fuzz.json")))? {
        Err(e) => check_message(&e.to_string()),
        Ok(net) => {
            LOADED.fetch_add(1, Ordering::Relaxed);
            let paper = biodyn::Body::paper(biodyn::ann::K4_BODY_MASS)
                .map_err(|e| TestCaseError::fail(e.to_string()))?;
            let body = net.base().cloned().unwrap_or(paper);
            // A prediction is finite numbers or an error naming the file,
            // never inf or NaN with success.
            if let Ok(values) = timed(|| net.predict_body(&body, &[0.5, 4.5, 20.0]))? {
                prop_assert!(
                    values.iter().all(|v| v.is_finite()),
                    "a loaded network predicts {values:?}"
                );
            }
            Ok(())
        }
    }
}

#[test]
#[ignore = "fuzz: run with --ignored (see the file's header)"]
fn fuzz_network_mutations() {
    let seeds: Vec<serde_json::Value> = [false, true]
        .iter()
        .map(|&on_a_model| serde_json::from_str(&network_text(on_a_model)).unwrap())
        .collect();
    let text_edits = prop::collection::vec(
        edit_strategy(
            [
                "{", "}", "[", "]", ",", ":", "\"", "NaN", "1e400", "-", "null", "\\u0000",
            ]
            .iter()
            .map(|s| s.to_string())
            .collect(),
            vec!["0".into()],
        ),
        0..3,
    );
    fuzz(
        "network mutations",
        (
            prop::sample::select(seeds),
            prop::collection::vec(json_edit_strategy(), 1..5),
            text_edits,
        ),
        |(seed, edits, text_edits)| {
            let mut v = seed;
            for e in &edits {
                let n = match e {
                    JsonEdit::Replace(n, _) | JsonEdit::Remove(n) | JsonEdit::Grow(n, _) => *n,
                };
                let mut n = n % count(&v).saturating_sub(1).max(1);
                at_nth(&mut v, &mut n, e);
            }
            let pretty = serde_json::to_string_pretty(&v).unwrap_or_default();
            check_network_bytes(&apply(&pretty, &text_edits))
        },
    );
}

#[test]
#[ignore = "fuzz: run with --ignored (see the file's header)"]
fn fuzz_network_arbitrary_bytes() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("fuzz.json");
    fuzz(
        "network arbitrary bytes",
        prop::collection::vec(any::<u8>(), 0..2000),
        |bytes| {
            check_network_bytes(&bytes)?;
            std::fs::write(&path, &bytes).map_err(|e| TestCaseError::fail(e.to_string()))?;
            if let Err(e) = timed(|| ann::load_network(&path))? {
                check_message(&e.to_string())?;
            }
            Ok(())
        },
    );
}

/// The harness itself: a mutation can fail the checks (so the fuzz tests
/// can fail), and the shipped files pass them untouched.
#[test]
fn the_checks_can_fail_and_pass() {
    for (_, text) in SHIPPED {
        check_preset_bytes(text.as_bytes()).unwrap();
    }
    assert!(check_message("two\nlines").is_err());
    assert!(check_message("").is_err());
    assert!(check_message(&"x".repeat(MAX_ERROR + 1)).is_err());
    assert!(check_message("a \u{1b}[31m b").is_err());
    let text = SHIPPED[0].1;
    let edited = apply(text, &[Edit::Value(0, "1e308".into())]);
    assert_ne!(edited, text.as_bytes());
}
