//! Issue 8's hard edges, against the real `biodyn` binary: saves that never
//! clobber, reads that never hang, one set of limits, names that cannot
//! mislead, and errors of bounded length.

#![cfg(unix)]

use std::fs;
use std::os::unix::fs::{FileTypeExt, PermissionsExt, symlink};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

// ---- helpers ---------------------------------------------------------------

/// A hang guard, not a speed check: a command that has not finished after
/// this long is killed and the test fails with what it printed.
const HANG: Duration = Duration::from_secs(120);

struct Out {
    code: Option<i32>,
    stdout: String,
    stderr: String,
}

/// Runs biodyn in `dir` with stdin closed; kills it after [`HANG`].
fn run_in(dir: &Path, args: &[&str]) -> Out {
    let mut child = Command::new(env!("CARGO_BIN_EXE_biodyn"))
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("biodyn starts");
    let start = Instant::now();
    loop {
        if child.try_wait().expect("wait").is_some() {
            break;
        }
        if start.elapsed() > HANG {
            let _ = child.kill();
            let out = child.wait_with_output().expect("output");
            panic!(
                "{args:?} hung; stderr so far: {}",
                String::from_utf8_lossy(&out.stderr)
            );
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    let out = child.wait_with_output().expect("output");
    Out {
        code: out.status.code(),
        stdout: String::from_utf8_lossy(&out.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
    }
}

/// Expects success; returns stdout.
fn ok_in(dir: &Path, args: &[&str]) -> String {
    let o = run_in(dir, args);
    assert_eq!(o.code, Some(0), "{args:?} failed: {}", o.stderr);
    o.stdout
}

/// Expects a biodyn error: status 1, empty stdout, exactly an error line and
/// a hint line, neither longer than `MAX_LINE`. Returns the error line.
fn fails_in(dir: &Path, args: &[&str]) -> String {
    let o = run_in(dir, args);
    assert_eq!(
        o.code,
        Some(1),
        "{args:?}: status {:?}: {}",
        o.code,
        o.stderr
    );
    assert!(o.stdout.is_empty(), "{args:?}: stdout: {}", o.stdout);
    assert!(!o.stderr.contains("panicked"), "{args:?}: {}", o.stderr);
    let lines: Vec<&str> = o.stderr.lines().collect();
    assert_eq!(lines.len(), 2, "{args:?}: not error + hint: {}", o.stderr);
    assert!(lines[0].starts_with("biodyn: error: "), "{}", o.stderr);
    assert!(lines[1].starts_with("  hint: "), "{}", o.stderr);
    for l in &lines {
        assert!(
            l.chars().count() <= MAX_LINE,
            "{args:?}: a {} character line: {}",
            l.chars().count(),
            &l[..l.len().min(400)]
        );
        assert!(!l.contains('\u{1b}'), "{args:?}: escape sequence in {l:?}");
    }
    assert!(!has_long_digit_run(&o.stderr), "{args:?}: {}", o.stderr);
    lines[0].to_string()
}

/// No error line is longer than this, whatever the input.
const MAX_LINE: usize = 600;

/// True if `s` holds a run of more than 25 digits (a number printed in full).
fn has_long_digit_run(s: &str) -> bool {
    let mut run = 0;
    for c in s.chars() {
        run = if c.is_ascii_digit() { run + 1 } else { 0 };
        if run > 25 {
            return true;
        }
    }
    false
}

fn sorted(mut v: Vec<&str>) -> Vec<&str> {
    v.sort();
    v
}

/// Names in `dir`, sorted (temp files included).
fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = fs::read_dir(dir)
        .unwrap()
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

fn mkfifo(p: &Path) {
    let st = Command::new("mkfifo").arg(p).status().expect("mkfifo runs");
    assert!(st.success());
}

/// The shipped default preset as text.
fn base_preset(dir: &Path) -> String {
    ok_in(dir, &["preset", "show"])
}

/// Writes `text` to `dir/name`.
fn write(dir: &Path, name: &str, text: impl AsRef<[u8]>) -> PathBuf {
    let p = dir.join(name);
    fs::write(&p, text).unwrap();
    p
}

/// A quickly trained network saved as `dir/name` (two LM iterations).
fn quick_net(dir: &Path, case: &str, name: &str) -> PathBuf {
    let o = run_in(
        dir,
        &[
            "train",
            "--case",
            case,
            "--epochs",
            "2",
            "--ensemble",
            "1",
            "--save",
            name,
        ],
    );
    assert_eq!(o.code, Some(0), "train failed: {}", o.stderr);
    dir.join(name)
}

fn is_temp(name: &str) -> bool {
    name.contains("biodyn-tmp") || name.ends_with(".tmp")
}

// ---- saves that never clobber ------------------------------------------------

#[test]
fn preset_save_through_a_symlink_replaces_the_target_and_keeps_the_link() {
    let d = tempfile::tempdir().unwrap();
    let dir = d.path();
    ok_in(dir, &["preset", "save", "real.toml"]);
    symlink("real.toml", dir.join("link.toml")).unwrap();
    ok_in(dir, &["preset", "save", "link.toml", "--set", "k4=54000"]);
    assert!(
        fs::symlink_metadata(dir.join("link.toml"))
            .unwrap()
            .file_type()
            .is_symlink()
    );
    let text = fs::read_to_string(dir.join("real.toml")).unwrap();
    assert!(text.contains("k_n_per_m = 54000.0"), "{text}");
    assert_eq!(names(dir), ["link.toml", "real.toml"]);
    // And a link into another folder: the temp file goes there, not here.
    let other = tempfile::tempdir().unwrap();
    ok_in(other.path(), &["preset", "save", "far.toml"]);
    symlink(other.path().join("far.toml"), dir.join("far-link.toml")).unwrap();
    ok_in(
        dir,
        &["preset", "save", "far-link.toml", "--set", "k3=1000"],
    );
    let far = fs::read_to_string(other.path().join("far.toml")).unwrap();
    assert!(far.contains("k_n_per_m = 1000.0"), "{far}");
    assert_eq!(names(other.path()), ["far.toml"]);
}

#[test]
fn saving_over_a_0600_file_keeps_0600() {
    let d = tempfile::tempdir().unwrap();
    let dir = d.path();
    let p = write(dir, "private.toml", "old");
    fs::set_permissions(&p, fs::Permissions::from_mode(0o600)).unwrap();
    ok_in(
        dir,
        &["preset", "save", "private.toml", "--set", "k4=60000"],
    );
    assert_eq!(
        fs::metadata(&p).unwrap().permissions().mode() & 0o7777,
        0o600
    );
    assert!(fs::read_to_string(&p).unwrap().contains("60000"));
    // A network file too.
    let n = write(dir, "net.json", "old");
    fs::set_permissions(&n, fs::Permissions::from_mode(0o640)).unwrap();
    quick_net(dir, "k4-stht", "net.json");
    assert_eq!(
        fs::metadata(&n).unwrap().permissions().mode() & 0o7777,
        0o640
    );
}

/// Each special file: refused by `preset save` and `train --save`, and
/// still there, of the same kind, afterwards.
#[test]
fn saves_refuse_fifo_directory_socket_and_device_and_leave_them() {
    let d = tempfile::tempdir().unwrap();
    let dir = d.path();
    mkfifo(&dir.join("fifo.toml"));
    fs::create_dir(dir.join("folder.toml")).unwrap();
    fs::write(dir.join("folder.toml/inside"), "keep").unwrap();
    let _sock = std::os::unix::net::UnixListener::bind(dir.join("sock.toml")).unwrap();
    // A real device node where we may make one (root), else a link to one.
    let made = Command::new("mknod")
        .args([dir.join("dev.toml").to_str().unwrap(), "c", "1", "3"])
        .stderr(Stdio::null())
        .status()
        .is_ok_and(|s| s.success());
    if !made {
        symlink("/dev/null", dir.join("dev.toml")).unwrap();
    }
    symlink("/dev/null", dir.join("null-link.toml")).unwrap();
    let cases = [
        ("fifo.toml", "FIFO"),
        ("folder.toml", "directory"),
        ("sock.toml", "socket"),
        ("dev.toml", "character device"),
        ("null-link.toml", "character device"),
    ];
    for (name, what) in cases {
        let e = fails_in(dir, &["preset", "save", name]);
        assert!(e.contains(name) && e.contains(what), "{e}");
        let e = fails_in(
            dir,
            &[
                "train",
                "--case",
                "k4-stht",
                "--epochs",
                "1",
                "--ensemble",
                "1",
                "--save",
                name,
            ],
        );
        assert!(e.contains(what), "{e}");
    }
    let ft = |n: &str| fs::symlink_metadata(dir.join(n)).unwrap().file_type();
    assert!(ft("fifo.toml").is_fifo());
    assert!(ft("folder.toml").is_dir());
    assert_eq!(
        fs::read_to_string(dir.join("folder.toml/inside")).unwrap(),
        "keep"
    );
    assert!(ft("sock.toml").is_socket());
    assert!(if made {
        ft("dev.toml").is_char_device()
    } else {
        ft("dev.toml").is_symlink()
    });
    assert!(ft("null-link.toml").is_symlink());
    assert!(
        fs::metadata("/dev/null")
            .unwrap()
            .file_type()
            .is_char_device()
    );
    assert!(!names(dir).iter().any(|n| is_temp(n)), "{:?}", names(dir));
}

#[test]
fn stale_temp_files_are_cleaned_by_the_next_save_and_live_ones_kept() {
    let d = tempfile::tempdir().unwrap();
    let dir = d.path();
    // 2147483646 is above any Linux pid_max: no such process.
    let dead = ".p.toml.biodyn-tmp.2147483646.0";
    let legacy = ".p.toml.2147483646-3.tmp";
    let legacy_net = ".net.json.2147483646.tmp";
    // This test's own pid is alive: its temp file must stay.
    let live = format!(".p.toml.biodyn-tmp.{}.7", std::process::id());
    let unrelated = ".notes.tmp";
    for n in [dead, legacy, legacy_net, &live, unrelated] {
        write(dir, n, "x");
    }
    ok_in(dir, &["preset", "save", "p.toml"]);
    assert_eq!(names(dir), sorted(vec![&live, unrelated, "p.toml"]));
    // A network save cleans too.
    write(dir, dead, "x");
    quick_net(dir, "k4-stht", "net.json");
    assert_eq!(
        names(dir),
        sorted(vec![&live, unrelated, "net.json", "p.toml"])
    );
}

// ---- reads that never hang ----------------------------------------------------

#[test]
fn dev_zero_and_fifos_are_refused_at_once() {
    let d = tempfile::tempdir().unwrap();
    let dir = d.path();
    mkfifo(&dir.join("f.toml"));
    mkfifo(&dir.join("f.json"));
    symlink("/dev/zero", dir.join("zero.toml")).unwrap();
    for args in [
        &["preset", "check", "/dev/zero"][..],
        &["preset", "check", "/dev/urandom"],
        &["preset", "check", "f.toml"],
        &["preset", "check", "zero.toml"],
        &["preset", "show", "f.toml"],
        &["response", "--preset", "f.toml"],
        &["modes", "--preset", "zero.toml"],
        &["predict", "--net", "/dev/zero"],
        &["predict", "--net", "f.json"],
    ] {
        let e = fails_in(dir, args);
        assert!(
            e.contains("FIFO") || e.contains("character device"),
            "{args:?}: {e}"
        );
        assert!(e.contains("not a regular file"), "{e}");
    }
}

/// `preset list` and the TUI go through the same library calls: a FIFO or a
/// link to a device in ./presets, or given as --preset, must not stall them.
#[test]
fn preset_list_and_tui_do_not_stall_on_special_files() {
    let d = tempfile::tempdir().unwrap();
    let dir = d.path();
    fs::create_dir(dir.join("presets")).unwrap();
    mkfifo(&dir.join("presets/fifo.toml"));
    symlink("/dev/zero", dir.join("presets/zero.toml")).unwrap();
    ok_in(dir, &["preset", "save", "presets/good.toml"]);
    let o = run_in(dir, &["preset", "list"]);
    let all = format!("{}{}", o.stdout, o.stderr);
    assert!(!all.contains("panicked"), "{all}");
    for name in ["fifo.toml", "zero.toml", "good.toml"] {
        assert!(all.contains(name), "{name} not listed: {all}");
    }
    assert!(
        all.contains("FIFO") && all.contains("character device"),
        "{all}"
    );
    // The TUI refuses before it touches the terminal (stdin is not one here
    // either; whichever it reports, it must exit, not hang).
    let o = run_in(dir, &["tui", "--preset", "presets/fifo.toml"]);
    assert_eq!(o.code, Some(1), "{}", o.stderr);
    assert!(!o.stderr.contains("panicked"), "{}", o.stderr);
}

#[test]
fn files_over_their_cap_are_refused_naming_the_cap() {
    let d = tempfile::tempdir().unwrap();
    let dir = d.path();
    // Sparse files: the size is all that is read before refusing.
    let big = fs::File::create(dir.join("big.toml")).unwrap();
    big.set_len((4 << 20) + 1).unwrap();
    let e = fails_in(dir, &["preset", "check", "big.toml"]);
    assert!(e.contains("big.toml") && e.contains("4 MiB cap"), "{e}");
    let big = fs::File::create(dir.join("big.json")).unwrap();
    big.set_len((16 << 20) + 1).unwrap();
    let e = fails_in(dir, &["predict", "--net", "big.json"]);
    assert!(e.contains("big.json") && e.contains("16 MiB cap"), "{e}");
}

// ---- one set of limits ----------------------------------------------------------

#[test]
fn body_mass_out_of_range_is_refused_by_every_command_naming_it() {
    let d = tempfile::tempdir().unwrap();
    let dir = d.path();
    let net = quick_net(dir, "k4-stht", "k4.json");
    let net = net.to_str().unwrap();
    for cmd in [
        &["response"][..],
        &["modes"],
        &["peaks"],
        &["plot", "stht"],
        &["preset", "save", "out.toml"],
        &["study", "k4", "40000,50000"],
        &["predict", "--net", net],
    ] {
        for (typed, shown) in [("1e7", "1e7"), ("1e-300", "1e-300")] {
            let mut args = cmd.to_vec();
            args.extend(["--body-mass", typed]);
            let e = fails_in(dir, &args);
            assert!(
                e.contains("--body-mass") && e.contains(shown),
                "{args:?}: {e}"
            );
            assert!(e.contains("body mass"), "{args:?}: {e}");
            assert!(!e.contains("study value"), "{args:?}: {e}");
        }
    }
    assert!(!dir.join("out.toml").exists());
    // A segment mass below a gram, however it is set.
    let e = fails_in(dir, &["modes", "--set", "m1=1e-6"]);
    assert!(e.contains("m1=1e-6") && e.contains("1e-3"), "{e}");
    let e = fails_in(dir, &["predict", "--net", net, "--set", "m1=1e-9"]);
    assert!(e.contains("head-neck") && e.contains("1e-9"), "{e}");
}

#[test]
fn preset_check_refuses_a_tiny_or_huge_body_mass_at_its_line() {
    let d = tempfile::tempdir().unwrap();
    let dir = d.path();
    let base = base_preset(dir);
    let line = base
        .lines()
        .position(|l| l.starts_with("body_mass_kg"))
        .unwrap()
        + 1;
    for bad in ["1e-308", "1e308", "5e-4"] {
        write(
            dir,
            "bm.toml",
            base.replace("body_mass_kg = 75.0", &format!("body_mass_kg = {bad}")),
        );
        let e = fails_in(dir, &["preset", "check", "bm.toml"]);
        assert!(
            e.contains(&format!("bm.toml:{line}: body_mass_kg = {bad}")),
            "{e}"
        );
    }
    // A share that makes a segment lighter than a gram names the share's line.
    write(
        dir,
        "share.toml",
        base.replace("share = 0.075", "share = 1e-9"),
    );
    let share_line = base.lines().position(|l| l == "share = 0.075").unwrap() + 1;
    let e = fails_in(dir, &["preset", "check", "share.toml"]);
    assert!(e.contains(&format!("share.toml:{share_line}:")), "{e}");
    assert!(e.contains("body_mass_kg") && e.contains("1e-3"), "{e}");
}

// ---- names -------------------------------------------------------------------

#[test]
fn names_with_control_characters_or_parameter_shapes_are_refused() {
    let d = tempfile::tempdir().unwrap();
    let dir = d.path();
    let base = base_preset(dir);
    let bad_names = [
        r#""head\nneck""#,
        r#""head\u001b[31mneck""#,
        r#""head\u202eneck""#,
        r#""m2""#,
        r#""K3""#,
        r#""c1""#,
        r#""pelvis-seat.k""#,
        r#""any.c""#,
        r#""body_mass""#,
        r#""body-mass""#,
        r#"" chest""#,
    ];
    for name in bad_names {
        write(
            dir,
            "n.toml",
            base.replacen("name = \"chest\"", &format!("name = {name}"), 1),
        );
        let e = fails_in(dir, &["preset", "check", "n.toml"]);
        assert!(e.contains("segment 2: name"), "{name}: {e}");
        // Link names too.
        write(
            dir,
            "l.toml",
            base.replacen("name = \"chest-lower-torso\"", &format!("name = {name}"), 1),
        );
        let e = fails_in(dir, &["preset", "check", "l.toml"]);
        assert!(e.contains("link 2: name"), "{name}: {e}");
    }
}

#[test]
fn set_with_a_non_ascii_name_is_a_one_line_error() {
    let d = tempfile::tempdir().unwrap();
    for name in ["é", "éé1", "ß2", "€"] {
        let arg = format!("{name}=1");
        let e = fails_in(d.path(), &["response", "--set", &arg]);
        assert!(e.contains("unknown parameter"), "{e}");
    }
}

// ---- bounded error messages -------------------------------------------------------

#[test]
fn huge_or_deep_user_content_gives_a_short_error() {
    let d = tempfile::tempdir().unwrap();
    let dir = d.path();
    let base = base_preset(dir);
    let net = quick_net(dir, "k4-stht", "good.json");
    let good = fs::read_to_string(&net).unwrap();
    // A 10 MB string where the format tag belongs.
    write(
        dir,
        "huge.json",
        good.replace(
            "\"biodyn-network\"",
            &format!("\"{}\"", "x".repeat(10_000_000)),
        ),
    );
    fails_in(dir, &["predict", "--net", "huge.json"]);
    // A 10 MB string where a number belongs.
    write(
        dir,
        "huge-num.json",
        good.replacen(
            "\"version\": 1",
            &format!("\"version\": \"{}\"", "9".repeat(10_000_000)),
            1,
        ),
    );
    fails_in(dir, &["predict", "--net", "huge-num.json"]);
    // 100 000-deep arrays.
    let deep = format!("{}1{}", "[".repeat(100_000), "]".repeat(100_000));
    write(dir, "deep.json", &deep);
    fails_in(dir, &["predict", "--net", "deep.json"]);
    write(dir, "deep.toml", format!("{base}\nx = {deep}\n"));
    fails_in(dir, &["preset", "check", "deep.toml"]);
    // A 3 MB string and a 300-digit number in a preset.
    write(
        dir,
        "str.toml",
        base.replace(
            "body_mass_kg = 75.0",
            &format!("body_mass_kg = \"{}\"", "y".repeat(3_000_000)),
        ),
    );
    fails_in(dir, &["preset", "check", "str.toml"]);
    write(
        dir,
        "num.toml",
        base.replace("schema = 1", "schema = 1e300"),
    );
    let e = fails_in(dir, &["preset", "check", "num.toml"]);
    assert!(e.contains("1e300"), "{e}");
    let long = format!("1{}.0", "0".repeat(300));
    write(
        dir,
        "num2.toml",
        base.replace("k_n_per_m = 90000.0", &format!("k_n_per_m = {long}")),
    );
    let e = fails_in(dir, &["preset", "check", "num2.toml"]);
    assert!(e.contains("1e300"), "{e}");
    // A band whose point count has 301 digits.
    write(
        dir,
        "band.toml",
        base.replace("to_hz = 20.0", "to_hz = 1e300"),
    );
    let e = fails_in(dir, &["preset", "check", "band.toml"]);
    assert!(e.contains("1e300 Hz"), "{e}");
    // A very long segment name is refused, and quoted short.
    write(
        dir,
        "long-name.toml",
        base.replacen(
            "name = \"chest\"",
            &format!("name = \"{}\"", "n".repeat(100_000)),
            1,
        ),
    );
    let e = fails_in(dir, &["preset", "check", "long-name.toml"]);
    assert!(e.contains("too long"), "{e}");
}

#[test]
fn a_deep_dotted_header_is_reported_at_its_own_line_and_column() {
    let d = tempfile::tempdir().unwrap();
    let dir = d.path();
    let base = base_preset(dir);
    let text = format!(
        "# a comment first\n{base}\n  [{}]\nx = 1\n",
        vec!["a"; 100].join(".")
    );
    let line = text.lines().position(|l| l.starts_with("  [a.a")).unwrap() + 1;
    write(dir, "deep-header.toml", &text);
    let e = fails_in(dir, &["preset", "check", "deep-header.toml"]);
    assert!(e.contains(&format!("deep-header.toml:{line}:3:")), "{e}");
    assert!(e.contains("levels deep"), "{e}");
}

#[test]
fn a_value_error_names_its_own_key_line() {
    let d = tempfile::tempdir().unwrap();
    let dir = d.path();
    let base = base_preset(dir);
    let text = base.replacen("c_ns_per_m = 2064.0", "c_ns_per_m = -1.0", 1);
    let line = text.lines().position(|l| l == "c_ns_per_m = -1.0").unwrap() + 1;
    write(dir, "c.toml", &text);
    let e = fails_in(dir, &["preset", "check", "c.toml"]);
    assert!(e.contains(&format!("c.toml:{line}: link 4")), "{e}");
    assert!(e.contains("c_ns_per_m = -1"), "{e}");
}

// ---- network files --------------------------------------------------------------

#[test]
fn a_network_with_unusable_output_scaling_is_refused() {
    let d = tempfile::tempdir().unwrap();
    let dir = d.path();
    let net = quick_net(dir, "k4-stht", "good.json");
    let good: serde_json::Value = serde_json::from_str(&fs::read_to_string(net).unwrap()).unwrap();
    let out = &good["network"]["scaling"]["output"];
    let min = out["min"].as_f64().unwrap();
    for (field, value) in [
        ("max", serde_json::json!(min)),
        ("max", serde_json::json!(min - 1.0)),
        ("min", serde_json::json!(null)),
        ("max", serde_json::json!(1e300)),
    ] {
        let mut v = good.clone();
        v["network"]["scaling"]["output"][field] = value.clone();
        write(dir, "bad.json", v.to_string());
        let e = fails_in(dir, &["predict", "--net", "bad.json"]);
        assert!(e.contains("bad.json"), "{field}={value}: {e}");
    }
    let mut v = good.clone();
    v["network"]["scaling"]["output"]["max"] = serde_json::json!(min);
    write(dir, "flat.json", v.to_string());
    let e = fails_in(dir, &["predict", "--net", "flat.json"]);
    assert!(
        e.contains("output scaling") && e.contains("min < max"),
        "{e}"
    );
    // The untouched file still predicts.
    ok_in(dir, &["predict", "--net", "good.json", "--format", "csv"]);
}
