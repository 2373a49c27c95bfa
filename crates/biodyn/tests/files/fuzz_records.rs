//! Fuzz harness for the readers of user data in the time domain and the fit:
//! the vibration-record reader (`biodyn simulate --input`), the `--signal`
//! grammar (and sampling what parses) and the measured-data reader
//! (`biodyn fit --data`). Not part of CI: every test is `#[ignore]`.
//!
//! ```text
//! # 256 cases per target (PROPTEST_CASES sets the count):
//! cargo test --release -p biodyn --test files -- --ignored --test-threads=1 fuzz_records::
//! # time-boxed: one target for 10 minutes
//! FUZZ_SECONDS=600 nice -n 10 cargo test --release -p biodyn --test files \
//!     -- --ignored --nocapture fuzz_records::records
//! ```
//!
//! Inputs are proptest strategies (structure-aware: valid files mutated,
//! grammar-aware specs, plus arbitrary bytes and strings). Each case must not
//! panic, must finish within [`SLOW`] (a hang guard; a watchdog aborts the
//! process, printing the case, past [`HANG`]), and every error's message must
//! be non-empty, one line, free of control characters and at most
//! [`MAX_MSG`] characters. What parses must hold its invariants (finite
//! samples, a sampling rate in (0, 1e6], increasing positive frequencies).
//!
//! A failing case does not stop the run: each kind of failure is shrunk once
//! (proptest's value tree) and counted, so a time-boxed run surveys every
//! kind it meets; the test fails at the end with the list.

use biodyn::fit::Measured;
use biodyn::time::{Generator, MAX_FS, Record, RecordOptions, Signal, sample_count};
use proptest::collection::vec;
use proptest::prelude::*;
use proptest::sample::select;
use proptest::strategy::ValueTree;
use proptest::test_runner::{Config, TestRunner};
use std::cell::Cell;
use std::collections::BTreeMap;
use std::fmt::{self, Write as _};
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::Path;
use std::sync::{Arc, Mutex, Once};
use std::time::{Duration, Instant};

/// Longest acceptable error message, in characters (path included).
const MAX_MSG: usize = 400;
/// A case slower than this is a finding (a hang guard, not a speed test).
const SLOW: Duration = Duration::from_secs(10);
/// A case running this long is a hang: the watchdog prints it and aborts.
const HANG: Duration = Duration::from_secs(120);
/// Most samples generated from a parsed `--signal` per case.
const MAX_GEN: f64 = 50_000.0;

// ---------------------------------------------------------------- runner --

/// Why a case failed; cases with the same `kind` are one finding.
#[derive(Debug, Clone)]
struct Finding {
    kind: String,
    detail: String,
}

fn finding(kind: impl Into<String>, detail: impl Into<String>) -> Finding {
    Finding {
        kind: kind.into(),
        detail: detail.into(),
    }
}

/// At most `n` characters of `s`, escaped, with the full length when cut.
fn excerpt(s: &str, n: usize) -> String {
    let mut out: String = s.chars().take(n).flat_map(char::escape_debug).collect();
    let len = s.chars().count();
    if len > n {
        let _ = write!(out, "…({len} chars)");
    }
    out
}

/// The variant name at the front of an error's Debug text (`Text`, `Read(Io`).
fn variant<E: fmt::Debug>(e: &E) -> String {
    let d = format!("{e:?}");
    let head: String = d
        .chars()
        .take_while(|c| c.is_alphanumeric() || *c == '(' || *c == '_')
        .take(40)
        .collect();
    head.trim_end_matches('(').to_string()
}

/// The message rules, applied to an error and every source under it.
fn check_error<E: std::error::Error>(e: &E) -> Result<(), Finding> {
    let name = variant(e);
    let mut cur: Option<&dyn std::error::Error> = Some(e);
    while let Some(err) = cur {
        let msg = err.to_string();
        let n = msg.chars().count();
        if msg.trim().is_empty() {
            return Err(finding(format!("empty message ({name})"), ""));
        }
        if msg.contains(['\n', '\r']) {
            return Err(finding(
                format!("multi-line message ({name})"),
                excerpt(&msg, 300),
            ));
        }
        if msg.chars().any(char::is_control) {
            return Err(finding(
                format!("control character in message ({name})"),
                excerpt(&msg, 300),
            ));
        }
        if n > MAX_MSG {
            return Err(finding(
                format!("message over {MAX_MSG} chars ({name})"),
                format!("{n} chars: {}", excerpt(&msg, 300)),
            ));
        }
        cur = err.source();
    }
    Ok(())
}

thread_local! {
    /// Set while a case runs: its panics are caught and reported, not printed.
    static IN_CASE: Cell<bool> = const { Cell::new(false) };
    static PANIC: std::cell::RefCell<Option<String>> = const { std::cell::RefCell::new(None) };
}

fn install_panic_hook() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        let default = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            if IN_CASE.with(Cell::get) {
                let msg = info
                    .payload()
                    .downcast_ref::<&str>()
                    .map(|s| s.to_string())
                    .or_else(|| info.payload().downcast_ref::<String>().cloned())
                    .unwrap_or_default();
                let at = info
                    .location()
                    .map(|l| format!("{}:{}", l.file(), l.line()))
                    .unwrap_or_default();
                PANIC.with(|p| *p.borrow_mut() = Some(format!("{at}: {msg}")));
            } else {
                default(info);
            }
        }));
    });
}

/// A `fmt::Write` that keeps the first `cap` bytes and then stops formatting.
struct Bounded {
    s: String,
    cap: usize,
}

impl fmt::Write for Bounded {
    fn write_str(&mut self, s: &str) -> fmt::Result {
        for c in s.chars() {
            if self.s.len() >= self.cap {
                self.s.push('…');
                return Err(fmt::Error);
            }
            self.s.push(c);
        }
        Ok(())
    }
}

fn bounded_debug<T: fmt::Debug>(v: &T, cap: usize) -> String {
    let mut b = Bounded {
        s: String::new(),
        cap,
    };
    let _ = write!(b, "{v:?}");
    b.s
}

/// Runs `check` on one value: a panic, a slow case or an `Err` is a finding.
fn run_one<T: fmt::Debug>(
    v: &T,
    check: &dyn Fn(&T) -> Result<(), Finding>,
    watch: &Mutex<(Instant, String)>,
) -> Result<(), Finding> {
    if let Ok(mut w) = watch.lock() {
        *w = (Instant::now(), bounded_debug(v, 4000));
    }
    let start = Instant::now();
    IN_CASE.with(|c| c.set(true));
    let r = catch_unwind(AssertUnwindSafe(|| check(v)));
    IN_CASE.with(|c| c.set(false));
    let took = start.elapsed();
    match r {
        Err(_) => {
            let msg = PANIC.with(|p| p.borrow_mut().take()).unwrap_or_default();
            let at = msg.split(": ").next().unwrap_or("").to_string();
            Err(finding(format!("panic at {at}"), msg))
        }
        Ok(Err(f)) => Err(f),
        Ok(Ok(())) if took > SLOW => Err(finding(
            "slow case",
            format!("{:.1} s (bound {} s)", took.as_secs_f64(), SLOW.as_secs()),
        )),
        Ok(Ok(())) => Ok(()),
    }
}

struct Seen {
    count: usize,
    example: String,
    detail: String,
}

/// Generates cases from `strategy` — `PROPTEST_CASES` of them (default
/// 256), or as many as fit in `FUZZ_SECONDS` — and checks each. Each new kind
/// of finding is shrunk, for at most 30 s; the test fails at the end listing
/// every kind with its smallest example.
fn fuzz<S>(target: &str, strategy: S, check: impl Fn(&S::Value) -> Result<(), Finding>)
where
    S: Strategy,
    S::Value: fmt::Debug,
{
    install_panic_hook();
    let seconds: Option<f64> = std::env::var("FUZZ_SECONDS")
        .ok()
        .and_then(|s| s.parse().ok());
    let cases: u64 = std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(256);
    let watch = Arc::new(Mutex::new((Instant::now(), String::new())));
    let done = Arc::new(std::sync::atomic::AtomicBool::new(false));
    {
        let (watch, done, target) = (watch.clone(), done.clone(), target.to_string());
        std::thread::spawn(move || {
            while !done.load(std::sync::atomic::Ordering::Relaxed) {
                std::thread::sleep(Duration::from_secs(1));
                if let Ok(w) = watch.lock()
                    && w.0.elapsed() > HANG
                {
                    eprintln!(
                        "fuzz {target}: HANG: a case has run for over {} s; aborting. Case: {}",
                        HANG.as_secs(),
                        w.1
                    );
                    std::process::abort();
                }
            }
        });
    }
    let mut runner = TestRunner::new(Config::default());
    let start = Instant::now();
    let mut seen: BTreeMap<String, Seen> = BTreeMap::new();
    let mut n = 0u64;
    loop {
        match seconds {
            Some(s) if start.elapsed().as_secs_f64() >= s => break,
            None if n >= cases => break,
            _ => {}
        }
        n += 1;
        let Ok(mut tree) = strategy.new_tree(&mut runner) else {
            continue;
        };
        let Err(first) = run_one(&tree.current(), &check, &watch) else {
            continue;
        };
        if let Some(s) = seen.get_mut(&first.kind) {
            s.count += 1;
            continue;
        }
        // Shrink: keep simplifying while the same kind still fails.
        let mut best = (bounded_debug(&tree.current(), 1500), first.detail.clone());
        let t0 = Instant::now();
        if tree.simplify() {
            while t0.elapsed() < Duration::from_secs(30) {
                let again = run_one(&tree.current(), &check, &watch);
                let stepped = match again {
                    Err(f) if f.kind == first.kind => {
                        best = (bounded_debug(&tree.current(), 1500), f.detail);
                        tree.simplify()
                    }
                    _ => tree.complicate(),
                };
                if !stepped {
                    break;
                }
            }
        }
        eprintln!(
            "fuzz {target}: NEW FINDING [{}] after {n} cases: {}\n    case: {}",
            first.kind, best.1, best.0
        );
        seen.insert(
            first.kind.clone(),
            Seen {
                count: 1,
                example: best.0,
                detail: best.1,
            },
        );
    }
    done.store(true, std::sync::atomic::Ordering::Relaxed);
    let secs = start.elapsed().as_secs_f64();
    eprintln!(
        "fuzz {target}: {n} cases in {secs:.0} s, {} kind(s) of finding",
        seen.len()
    );
    if !seen.is_empty() {
        let mut report = format!("fuzz {target}: {n} cases in {secs:.0} s; findings:\n");
        for (kind, s) in &seen {
            let _ = writeln!(
                report,
                "- [{kind}] ×{}: {}\n    smallest case: {}",
                s.count, s.detail, s.example
            );
        }
        panic!("{report}");
    }
}

// ------------------------------------------------------------ CSV pieces --

/// Number-ish cell text: ordinary values, the edges of f64, and non-numbers.
fn number_text() -> impl Strategy<Value = String> {
    prop_oneof![
        1 => select(vec![
            "NaN", "nan", "-NaN", "inf", "-inf", "+inf", "infinity", "1e308",
            "1.7976931348623157e308", "1e309", "-1e309", "5e-324", "2.2e-308", "1e-310",
            "0", "-0", "+0", "0.0", "1e", "e5", ".", "-", ".5", "5.", "1_0", "0x10", "1,5",
            "１", " 1.5 ", "\t2", "abc", "", "1e-9999999", "1e99999999999", "\u{0}",
            "\u{1b}[31m", "\u{feff}1", "١", "1.5\u{0}", "--1", "1e+3", "\u{a0}1",
        ])
        .prop_map(String::from),
        1 => any::<f64>().prop_map(|v| format!("{v}")),
        1 => any::<f64>().prop_map(|v| format!("{v:e}")),
        1 => (1usize..100_000, select(vec!['9', 'a', '\u{1b}', '\n', ' ', '"', 'é']))
            .prop_map(|(n, c)| std::iter::repeat_n(c, n).collect()),
        1 => "[ -~]{0,12}",
        1 => any::<String>(),
    ]
}

/// A cell: its text and whether it is written quoted.
#[derive(Debug, Clone)]
struct CellText {
    text: String,
    quoted: bool,
}

fn cell(text: impl Strategy<Value = String>) -> impl Strategy<Value = CellText> {
    (text, prop::bool::weighted(0.1)).prop_map(|(text, quoted)| CellText { text, quoted })
}

/// How a table is written out, and byte-level damage done afterwards.
#[derive(Debug, Clone)]
struct Render {
    bom: bool,
    crlf: bool,
    trailing_newline: bool,
    sep: char,
    /// (position, op, byte): op 0 overwrite, 1 insert, 2 delete, 3 duplicate a slice.
    damage: Vec<(usize, u8, u8)>,
}

fn render_opts() -> impl Strategy<Value = Render> {
    (
        prop::bool::weighted(0.1),
        prop::bool::weighted(0.2),
        prop::bool::weighted(0.9),
        prop_oneof![20 => Just(','), 1 => Just(';'), 1 => Just('\t'), 1 => Just(' ')],
        prop_oneof![
            4 => Just(Vec::new()),
            1 => vec((any::<usize>(), 0u8..4, any::<u8>()), 1..6),
        ],
    )
        .prop_map(|(bom, crlf, trailing_newline, sep, damage)| Render {
            bom,
            crlf,
            trailing_newline,
            sep,
            damage,
        })
}

fn render(rows: &[Vec<CellText>], r: &Render) -> Vec<u8> {
    let mut s = String::new();
    if r.bom {
        s.push('\u{feff}');
    }
    let eol = if r.crlf { "\r\n" } else { "\n" };
    for (i, row) in rows.iter().enumerate() {
        for (j, c) in row.iter().enumerate() {
            if j > 0 {
                s.push(r.sep);
            }
            if c.quoted {
                s.push('"');
                s.push_str(&c.text.replace('"', "\"\""));
                s.push('"');
            } else {
                s.push_str(&c.text);
            }
        }
        if i + 1 < rows.len() || r.trailing_newline {
            s.push_str(eol);
        }
    }
    let mut b = s.into_bytes();
    for &(pos, op, byte) in &r.damage {
        let len = b.len();
        let at = if len == 0 { 0 } else { pos % len };
        match op {
            0 if len > 0 => b[at] = byte,
            1 => b.insert(at, byte),
            2 if len > 0 => {
                b.remove(at);
            }
            3 if len > 0 => {
                let end = (at + 1 + byte as usize).min(len);
                let slice = b[at..end].to_vec();
                b.splice(at..at, slice);
            }
            _ => {}
        }
    }
    b
}

/// Bytes shown as text, escaped and cut.
struct Bytes<'a>(&'a [u8]);

impl fmt::Debug for Bytes<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let s = String::from_utf8_lossy(self.0);
        write!(f, "\"{}\" ({} bytes)", excerpt(&s, 600), self.0.len())
    }
}

/// Arbitrary bytes, and bytes from a CSV-ish alphabet.
fn raw_bytes() -> impl Strategy<Value = Vec<u8>> {
    prop_oneof![
        vec(any::<u8>(), 0..2048),
        "[t_sacfhzmgd,0-9.eE+\\-\n\r\" ]{0,400}".prop_map(String::into_bytes),
    ]
}

fn write_case(dir: &Path, name: &str, bytes: &[u8]) -> std::path::PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, bytes).expect("write the case to the temp dir");
    p
}

// --------------------------------------------------------- record target --

#[derive(Clone)]
struct RecordCase {
    bytes: Vec<u8>,
    column: Option<String>,
    fs: Option<f64>,
    duration: Option<f64>,
}

impl fmt::Debug for RecordCase {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("RecordCase")
            .field("bytes", &Bytes(&self.bytes))
            .field("column", &self.column.as_deref().map(|c| excerpt(c, 80)))
            .field("fs", &self.fs)
            .field("duration", &self.duration)
            .finish()
    }
}

fn column_name() -> impl Strategy<Value = String> {
    prop_oneof![
        4 => select(vec![
            "t_s", "acc_m_s2", "z_m_s2", " t_s ", "T_S", "", "\u{feff}t_s", "a\nb", "\"q\"",
            "head\u{1b}[31mneck", "x\ry", "tab\there", "ü", "t_s,", "#", "\u{0}",
        ])
        .prop_map(String::from),
        1 => "[a-z_]{1,8}",
        1 => (1usize..50_000).prop_map(|n| "c".repeat(n)),
        1 => any::<String>(),
    ]
}

/// A valid record (header, uniform time, values), then damaged.
fn structured_record() -> impl Strategy<Value = Vec<u8>> {
    let shape = prop_oneof![
        8 => (1usize..4, 0usize..40),
        1 => (4usize..40, 0usize..20),
        1 => (1000usize..3000, 2usize..4),
        1 => (1usize..3, 1000usize..5000),
    ];
    shape
        .prop_flat_map(|(ncols, nrows)| {
            let header = vec(cell(column_name()), ncols);
            let t0 = select(vec![0.0, -1.0, 1e9, -1e308, 1e308, 1e-300, 123.456]);
            let dt = select(vec![
                1e-3,
                1.0 / 1024.0,
                1e-6,
                1e-7,
                1.0,
                0.0,
                -1e-3,
                1e300,
                5e-324,
                1e-320,
                f64::MAX,
            ]);
            let jitter = prop_oneof![
                12 => Just(0.0),
                2 => -1e-4..1e-4f64,
                1 => select(vec![0.99e-3, 1.01e-3, -0.5, 1.0, 1e300]),
            ];
            let value = prop_oneof![8 => -50.0..50.0f64, 1 => any::<f64>()];
            let over = prop_oneof![10 => Just(None), 1 => number_text().prop_map(Some)];
            let arity = prop_oneof![12 => Just(0i8), 1 => Just(-1i8), 1 => Just(1i8)];
            let row = (
                jitter,
                vec((value, over.clone()), ncols),
                over,
                arity,
                prop::bool::weighted(0.05),
            );
            (header, 0..ncols, t0, dt, vec(row, nrows), render_opts())
        })
        .prop_map(|(header, time_at, t0, dt, rows, r)| {
            let ncols = header.len();
            let mut table = vec![header];
            for (i, (jitter, values, t_over, arity, quote_all)) in rows.into_iter().enumerate() {
                let t = t0 + (i as f64 + jitter) * dt;
                let mut row: Vec<CellText> = values
                    .into_iter()
                    .map(|(v, o)| CellText {
                        text: o.unwrap_or_else(|| format!("{v}")),
                        quoted: quote_all,
                    })
                    .collect();
                if let Some(c) = row.get_mut(time_at) {
                    c.text = t_over.unwrap_or_else(|| format!("{t}"));
                }
                match arity {
                    -1 if ncols > 0 => {
                        row.pop();
                    }
                    1 => row.push(CellText {
                        text: "1".into(),
                        quoted: false,
                    }),
                    _ => {}
                }
                table.push(row);
            }
            render(&table, &r)
        })
}

fn record_case() -> impl Strategy<Value = RecordCase> {
    let bytes = prop_oneof![6 => structured_record(), 1 => raw_bytes()];
    let column = prop_oneof![4 => Just(None), 1 => column_name().prop_map(Some)];
    let fs = prop_oneof![
        4 => Just(None),
        1 => select(vec![
            1000.0, 1024.0, 1e6, 0.0, -1.0, f64::NAN, f64::INFINITY, 1e7, 5e-324, 1e-300,
        ])
        .prop_map(Some),
    ];
    let duration = prop_oneof![
        4 => Just(None),
        1 => select(vec![0.01, 1.0, 0.0, -1.0, f64::NAN, 1e300, 5e-324]).prop_map(Some),
    ];
    (bytes, column, fs, duration).prop_map(|(bytes, column, fs, duration)| RecordCase {
        bytes,
        column,
        fs,
        duration,
    })
}

/// Reads a record as `biodyn simulate --input` does (cli/simulate.rs):
/// `Record::open`, `sample_count` for `--duration`, then every sample.
fn check_record(dir: &Path, c: &RecordCase) -> Result<(), Finding> {
    let path = write_case(dir, "r.csv", &c.bytes);
    let mut opts = c
        .column
        .as_deref()
        .map_or_else(RecordOptions::default, RecordOptions::z_column);
    opts.fs = c.fs;
    let rec = match Record::open(&path, &opts) {
        Ok(r) => r,
        Err(e) => return check_error(&e),
    };
    let fs = rec.fs();
    if !(fs.is_finite() && fs > 0.0 && fs <= MAX_FS) {
        return Err(finding(
            "record opened with a sampling rate outside (0, 1e6]",
            format!("fs = {fs:e}, t0 = {:e}", rec.t0()),
        ));
    }
    if !rec.t0().is_finite() {
        return Err(finding("record t0 not finite", format!("{}", rec.t0())));
    }
    let limit = match c.duration {
        Some(d) => match sample_count(d, fs) {
            Ok(n) => n,
            Err(e) => return check_error(&e),
        },
        None => usize::MAX,
    };
    for s in rec.take(limit) {
        match s {
            Ok(v) if v.iter().all(|a| a.is_finite()) => {}
            Ok(v) => return Err(finding("record sample not finite", format!("{v:?}"))),
            Err(e) => return check_error(&e),
        }
    }
    Ok(())
}

#[test]
#[ignore = "fuzz: run with --ignored (FUZZ_SECONDS or PROPTEST_CASES)"]
fn records() {
    let dir = tempfile::tempdir().expect("temp dir");
    fuzz("records", record_case(), |c| check_record(dir.path(), c));
}

// --------------------------------------------------------- signal target --

#[derive(Debug, Clone)]
struct SignalCase {
    spec: String,
    fs: f64,
    duration: f64,
}

/// Numbers that should parse, from the ordinary to the edges of f64.
fn spec_number() -> impl Strategy<Value = String> {
    prop_oneof![
        6 => (0.01..400.0f64).prop_map(|v| format!("{v}")),
        2 => select(vec![
            "1", "5", "0", "-1", "1e+3", "1e-3", "1e308", "1.7976931348623157e308", "5e-324",
            "1e-308", "2.2250738585072014e-308", "-0", "1e-300", "0.5", "100000", "1e6",
        ])
        .prop_map(String::from),
        1 => any::<f64>().prop_map(|v| format!("{v}")),
        1 => number_text(),
    ]
}

fn spec_band() -> impl Strategy<Value = String> {
    prop_oneof![
        4 => (spec_number(), spec_number()).prop_map(|(a, b)| format!("{a}-{b}")),
        1 => select(vec![
            "1-20", "-1-20", "1e-5-1e5", "1e-1-2", "20-1", "1--2", "1-", "-", "", "1-2-3",
            "1e-300-1e-299", "5e-324-1e-323", "0.1-0.2", "1-1",
        ])
        .prop_map(String::from),
    ]
}

/// One part that is well formed (keys of its kind, values that may be bad).
fn spec_part_valid() -> impl Strategy<Value = String> {
    let seed = prop_oneof![
        4 => any::<u64>().prop_map(|s| s.to_string()),
        1 => select(vec!["-1", "18446744073709551616", "1.5", "", "0x1"]).prop_map(String::from),
    ];
    prop_oneof![
        (
            spec_number(),
            spec_number(),
            prop::option::of(spec_number())
        )
            .prop_map(|(f, a, p)| {
                match p {
                    Some(p) => format!("sine:freq={f},amp={a},phase={p}"),
                    None => format!("sine:freq={f},amp={a}"),
                }
            }),
        (spec_number(), spec_number(), spec_number())
            .prop_map(|(f, t, a)| format!("sweep:from={f},to={t},amp={a}")),
        (spec_number(), spec_band(), seed)
            .prop_map(|(r, b, s)| format!("random:rms={r},band={b},seed={s}")),
        (spec_number(), spec_number(), spec_number())
            .prop_map(|(p, w, a)| format!("shock:peak={p},width={w},at={a}")),
    ]
}

/// A part from the grammar's pieces in any order: kinds, keys, separators.
fn spec_part_soup() -> impl Strategy<Value = String> {
    let kind = prop_oneof![
        8 => select(vec!["sine", "sweep", "random", "shock"]).prop_map(String::from),
        1 => select(vec!["SINE", " sine ", "saw", "", "sine:sine", "\u{1b}", "\n"])
            .prop_map(String::from),
        1 => "[a-z]{0,6}",
    ];
    let key = prop_oneof![
        8 => select(vec![
            "freq", "amp", "phase", "from", "to", "rms", "band", "seed", "peak", "width", "at",
        ])
        .prop_map(String::from),
        1 => select(vec!["", " freq ", "FREQ", "=", "amp=amp", "\u{0}"]).prop_map(String::from),
        1 => "[a-z]{0,5}",
    ];
    let value = prop_oneof![4 => spec_number(), 1 => spec_band(), 1 => ".{0,20}"];
    let item =
        (key, select(vec!["=", "==", "", " = "]), value).prop_map(|(k, e, v)| format!("{k}{e}{v}"));
    (
        kind,
        select(vec![":", "::", " : ", ""]),
        vec(item, 0..5),
        select(vec![",", ", ", ",,", ";"]),
    )
        .prop_map(|(k, c, items, sep)| format!("{k}{c}{}", items.join(sep)))
}

fn signal_case() -> impl Strategy<Value = SignalCase> {
    let part = prop_oneof![3 => spec_part_valid(), 1 => spec_part_soup()];
    let spec = prop_oneof![
        8 => (vec(part, 1..4), select(vec!["+", " + ", "++", "+1"]))
            .prop_map(|(parts, j)| parts.join(j)),
        1 => any::<String>(),
        1 => ".{0,100}",
        1 => (1usize..100_000, select(vec!["+a", "sine:", ",", "=", "+sine:freq=1,amp=1"]))
            .prop_map(|(n, s)| s.repeat(n)),
    ];
    let fs = select(vec![
        1.0, 2.0, 3.0, 10.0, 100.0, 256.0, 1000.0, 1e4, 1e5, 1e6, 0.5, 1e-3,
    ]);
    let duration = select(vec![
        0.001, 0.01, 0.1, 1.0, 2.0, 10.0, 60.0, 1e-300, 5e-324, 1e9,
    ]);
    (spec, fs, duration).prop_map(|(spec, fs, duration)| SignalCase { spec, fs, duration })
}

/// Parses as `biodyn simulate --signal` does; what parses must print back
/// to itself, and for small duration × fs it is sampled: every sample
/// finite, or a clear error.
fn check_signal(c: &SignalCase) -> Result<(), Finding> {
    let sig = match Signal::parse(&c.spec) {
        Ok(s) => s,
        Err(e) => return check_error(&e),
    };
    let printed = sig.to_string();
    match Signal::parse(&printed) {
        Ok(back) if back == sig => {}
        other => {
            return Err(finding(
                "signal does not round-trip through its Display",
                format!("printed {} -> {other:?}", excerpt(&printed, 200)),
            ));
        }
    }
    if c.duration * c.fs > MAX_GEN {
        return Ok(());
    }
    let g = match Generator::new(&sig, c.fs, c.duration) {
        Ok(g) => g,
        Err(e) => return check_error(&e),
    };
    for (k, v) in g.enumerate() {
        if !v.is_finite() {
            return Err(finding(
                "generated sample not finite",
                format!("sample {k} = {v} for {}", excerpt(&printed, 200)),
            ));
        }
    }
    Ok(())
}

#[test]
#[ignore = "fuzz: run with --ignored (FUZZ_SECONDS or PROPTEST_CASES)"]
fn signals() {
    fuzz("signals", signal_case(), check_signal);
}

// ------------------------------------------------------- measured target --

#[derive(Clone)]
struct MeasuredCase {
    bytes: Vec<u8>,
}

impl fmt::Debug for MeasuredCase {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("MeasuredCase")
            .field("bytes", &Bytes(&self.bytes))
            .finish()
    }
}

fn measured_name() -> impl Strategy<Value = String> {
    prop_oneof![
        8 => select(vec![
            "f_hz", "stht_mag", "stht_phase_deg", "dpmi_mag", "dpmi_phase_deg", "apms_mag",
            "apms_phase_deg", "apms_mag_sd", "stht_mag_sd", "apms_phase_deg_sd", "dpmi_mag_sd",
            "F_HZ", " f_hz ", "apms_mg", "", "a;b", "a\tb", "\u{feff}f_hz", "f_hz_sd",
        ])
        .prop_map(String::from),
        1 => column_name(),
    ]
}

/// A valid measured file (increasing frequencies, positive magnitudes,
/// some empty cells), then damaged.
fn structured_measured() -> impl Strategy<Value = Vec<u8>> {
    let shape = prop_oneof![
        8 => (1usize..6, 0usize..30),
        1 => (6usize..40, 0usize..10),
        1 => (1usize..4, 1000usize..5000),
    ];
    shape
        .prop_flat_map(|(ncols, nrows)| {
            let header = vec(cell(measured_name()), ncols);
            let f0 = select(vec![0.5, 1.0, 1e-300, 5e-324, 1e300, 0.0, -1.0]);
            let df = select(vec![0.5, 0.25, 1e-9, 0.0, -0.5, 1e300, 5e-324]);
            let value = prop_oneof![8 => 0.01..200.0f64, 1 => -180.0..180.0f64, 1 => any::<f64>()];
            let over = prop_oneof![
                10 => Just(None),
                2 => Just(Some(String::new())),
                1 => number_text().prop_map(Some),
            ];
            let arity = prop_oneof![12 => Just(0i8), 1 => Just(-1i8), 1 => Just(1i8)];
            let row = (vec((value, over.clone()), ncols), over, arity);
            (header, f0, df, vec(row, nrows), render_opts())
        })
        .prop_map(|(header, f0, df, rows, r)| {
            let f_at = header
                .iter()
                .position(|c| c.text.trim().eq_ignore_ascii_case("f_hz"))
                .unwrap_or(0);
            let mut table = vec![header];
            for (i, (values, f_over, arity)) in rows.into_iter().enumerate() {
                let mut row: Vec<CellText> = values
                    .into_iter()
                    .map(|(v, o)| CellText {
                        text: o.unwrap_or_else(|| format!("{v}")),
                        quoted: false,
                    })
                    .collect();
                if let Some(c) = row.get_mut(f_at) {
                    c.text = f_over.unwrap_or_else(|| format!("{}", f0 + i as f64 * df));
                }
                match arity {
                    -1 => {
                        row.pop();
                    }
                    1 => row.push(CellText {
                        text: "1".into(),
                        quoted: false,
                    }),
                    _ => {}
                }
                table.push(row);
            }
            render(&table, &r)
        })
}

fn measured_case() -> impl Strategy<Value = MeasuredCase> {
    prop_oneof![6 => structured_measured(), 1 => raw_bytes()]
        .prop_map(|bytes| MeasuredCase { bytes })
}

/// Loads as `biodyn fit --data` does (`Measured::load`); what loads must
/// hold the documented checks.
fn check_measured(dir: &Path, c: &MeasuredCase) -> Result<(), Finding> {
    let path = write_case(dir, "d.csv", &c.bytes);
    let m = match Measured::load(&path) {
        Ok(m) => m,
        Err(e) => return check_error(&e),
    };
    let bad = |what: &str| Err(finding(format!("loaded data breaks: {what}"), ""));
    if m.f_hz.is_empty() || m.columns.is_empty() {
        return bad("no rows or no columns");
    }
    if m.f_hz.iter().any(|f| !(f.is_finite() && *f > 0.0)) {
        return bad("a frequency not finite and > 0");
    }
    if m.f_hz.windows(2).any(|w| w[1] <= w[0]) {
        return bad("frequencies not increasing");
    }
    for col in &m.columns {
        if col.values.len() != m.f_hz.len() {
            return bad("a column's length differs from f_hz");
        }
        if col.values.iter().all(Option::is_none) {
            return bad("a column with no value");
        }
        for v in col.values.iter().flatten() {
            let mag = col.channel.quantity == biodyn::fit::Quantity::Mag;
            if !v.is_finite() || (mag && *v <= 0.0) {
                return bad("a value not finite, or a magnitude not > 0");
            }
        }
        if let Some(sd) = &col.sd {
            if sd.len() != m.f_hz.len() {
                return bad("an sd column's length differs from f_hz");
            }
            for (v, s) in col.values.iter().zip(sd) {
                match (v, s) {
                    (Some(_), None) => return bad("a weighted value without its sd"),
                    (_, Some(s)) if !(s.is_finite() && *s > 0.0) => {
                        return bad("an sd not finite and > 0");
                    }
                    _ => {}
                }
            }
        }
    }
    Ok(())
}

#[test]
#[ignore = "fuzz: run with --ignored (FUZZ_SECONDS or PROPTEST_CASES)"]
fn measured() {
    let dir = tempfile::tempdir().expect("temp dir");
    fuzz("measured", measured_case(), |c| {
        check_measured(dir.path(), c)
    });
}

// ------------------------------------------------- regressions (not ignored) --

/// Found by `records`: a first time step that overflows to infinity
/// (t = -1e308 then 1.7e308) gave fs = 1/inf = 0 and the record opened;
/// `simulate` then blamed "sampling rate 0.0 Hz" and hinted at --fs.
#[test]
fn an_infinite_first_time_step_is_refused_at_open() {
    let dir = tempfile::tempdir().expect("temp dir");
    let path = write_case(dir.path(), "r.csv", b"t_s,acc\n-1e308,1\n1.7e308,1\n");
    let e = Record::open(&path, &RecordOptions::default()).expect_err("fs would be 0");
    let msg = e.to_string();
    assert!(msg.contains("line 3") && msg.contains("time step"), "{msg}");
    assert!(check_error(&e).is_ok(), "{msg}");
}

/// Regression: hostile names and cells, huge values and steps give short,
/// printable, one-line errors (no ESC, BEL, newline; numbers short).
#[test]
fn record_errors_are_short_printable_and_values_capped() {
    let dir = tempfile::tempdir().expect("temp dir");
    let long = "x".repeat(50_000);
    let cases: Vec<(Vec<u8>, Option<&str>, &str)> = vec![
        (
            b"t_s,\"acc\x1b[31mred\x07\na\"\n0,1\n1,1\n".to_vec(),
            Some("acc"),
            "no column named",
        ),
        (
            format!("t_s,acc\n0,1\n1,{long}\n").into_bytes(),
            None,
            "is not a number",
        ),
        (b"t_s,acc\n0,1\n1,1e308\n".to_vec(), None, "cap"),
        (b"t_s,acc\n0,-2e4\n1,1\n".to_vec(), None, "cap"),
        (b"t_s,acc\n0,1\n1e-300,1\n".to_vec(), None, "1e-300"),
        (
            b"t_s,acc\n0,\x1b]0;x\x07\n1,1\n".to_vec(),
            None,
            "not a number",
        ),
    ];
    for (i, (bytes, column, want)) in cases.into_iter().enumerate() {
        let path = write_case(dir.path(), &format!("r{i}.csv"), &bytes);
        let opts = column.map_or_else(RecordOptions::default, RecordOptions::z_column);
        let e = match Record::open(&path, &opts) {
            Err(e) => e,
            Ok(rec) => rec
                .filter_map(Result::err)
                .next()
                .expect("an error while reading"),
        };
        let msg = e.to_string();
        assert!(msg.contains(want), "case {i}: {msg}");
        assert!(check_error(&e).is_ok(), "case {i}: {msg}");
        assert!(msg.len() < 400, "case {i}: {} bytes", msg.len());
    }
}

/// Regression: a file of NUL bytes with no newline is refused at the line
/// cap, not buffered whole (1 GiB used 3 GB of memory).
#[test]
fn a_line_over_the_cap_is_refused_with_its_number() {
    let dir = tempfile::tempdir().expect("temp dir");
    let mut bytes = b"t_s,acc\n0,1\n".to_vec();
    bytes.extend(std::iter::repeat_n(0u8, 1 << 20));
    let path = write_case(dir.path(), "nul.csv", &bytes);
    let e = Record::open(&path, &RecordOptions::default()).expect_err("line too long");
    let msg = e.to_string();
    assert!(msg.contains("line 3 is over 64 KiB"), "{msg}");
    assert!(check_error(&e).is_ok(), "{msg}");
    // A line just under the cap still reads.
    let mut ok = b"t_s,acc\n0,1\n1,1\n".to_vec();
    ok.extend(format!("2,1{}\n", " ".repeat(60_000)).bytes());
    let path = write_case(dir.path(), "ok.csv", &ok);
    let rec = Record::open(&path, &RecordOptions::default()).expect("opens");
    let samples: Vec<f64> = rec
        .vertical()
        .expect("z")
        .collect::<Result<_, _>>()
        .expect("reads");
    assert_eq!(samples, [1.0, 1.0, 1.0]);
}

/// Regression: a random band below what the filter represents, or huge
/// amplitudes, are refused rather than generating NaN or inf.
#[test]
fn signals_that_would_print_nan_or_inf_are_refused() {
    for spec in [
        "random:rms=0.01,band=1e-300-1e-299,seed=0",
        "sine:freq=1,amp=1e308+sine:freq=1,amp=1e308",
        "shock:peak=1e308,width=0.1,at=0",
    ] {
        let e = Signal::parse(spec).expect_err(spec);
        let msg = e.to_string();
        assert!(check_error(&e).is_ok(), "{msg}");
        assert!(!msg.contains("000000"), "{msg}");
    }
    // The largest allowed parts, summed many times, stay finite.
    let spec = vec!["sine:freq=1,amp=1e4"; 1000].join("+");
    let sig = Signal::parse(&spec).expect("parses");
    let g = Generator::new(&sig, 8.0, 2.0).expect("generates");
    assert!(g.into_iter().all(f64::is_finite));
    let sig = Signal::parse("random:rms=1e4,band=1e-3-1,seed=3").expect("parses");
    let g = Generator::new(&sig, 4.0, 1.0).expect("generates");
    assert!(g.into_iter().all(f64::is_finite));
}

/// Regression: measured-data errors quote names and cells bounded and
/// escaped (ESC, BEL, tab, newline never reach the message), and a line
/// over 64 KiB is refused with its number.
#[test]
fn measured_errors_are_short_and_printable() {
    let dir = tempfile::tempdir().expect("temp dir");
    let long = "y".repeat(20_000);
    let cases: Vec<(Vec<u8>, &str)> = vec![
        (
            b"f_hz,apms\x1b[31mmag\x07\n1,2\n".to_vec(),
            "unknown column",
        ),
        (b"f_hz,\"apms\nsplit\"\n1,2\n".to_vec(), "unknown column"),
        (
            b"f_hz,apms_mag\n1,\"6.5\t1\"\n".to_vec(),
            "not a finite number",
        ),
        (
            format!("f_hz,apms_mag\n1,{long}\n").into_bytes(),
            "not a finite number",
        ),
        (
            format!("f_hz,apms_mag,{long}_sd\n1,2,1\n").into_bytes(),
            "column",
        ),
        (b"f_hz,apms_mag,apms_mag\n1,2,3\n".to_vec(), "twice"),
        (
            format!("f_hz,apms_mag\n1,{}\n", "1".repeat(70_000)).into_bytes(),
            "line 2",
        ),
    ];
    for (i, (bytes, want)) in cases.into_iter().enumerate() {
        let path = write_case(dir.path(), &format!("d{i}.csv"), &bytes);
        let e = Measured::load(&path).expect_err("refused");
        let msg = e.to_string();
        assert!(msg.contains(want), "case {i}: {msg}");
        assert!(check_error(&e).is_ok(), "case {i}: {msg}");
        assert!(msg.len() < 400, "case {i}: {} bytes", msg.len());
    }
}
