//! Library-level preset tests: shipped files, exact round trips, errors that
//! name the file and the line, and atomic saves.

use biodyn::body::{Origin, SHIPPED};
use biodyn::{Band, Body, End, Link, Preset, Segment};
use std::fs;
use std::path::{Path, PathBuf};

// ---- helpers ---------------------------------------------------------------

/// The crate's `presets/` folder.
fn presets_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../presets")
}

/// Writes `bytes` to `dir/name` and returns the path.
fn write(dir: &Path, name: &str, bytes: impl AsRef<[u8]>) -> PathBuf {
    let p = dir.join(name);
    fs::write(&p, bytes).unwrap();
    p
}

/// Loads `text` from a fresh file named `name`; returns the error message
/// and the path it was loaded from.
fn load_err_named(name: &str, text: impl AsRef<[u8]>) -> (String, PathBuf, tempfile::TempDir) {
    let dir = tempfile::tempdir().unwrap();
    let p = write(dir.path(), name, text);
    match Preset::load(&p) {
        Ok(_) => panic!("{name}: loaded, but an error was expected"),
        Err(e) => (e.to_string(), p, dir),
    }
}

/// Loads `text` from a file called `bad-preset.toml` and returns the error
/// message, after checking that it starts with the file's path.
fn load_err(text: impl AsRef<[u8]>) -> String {
    let (msg, path, _dir) = load_err_named("bad-preset.toml", text);
    let shown = path.display().to_string();
    assert!(
        msg.starts_with(&shown),
        "message does not start with the file path {shown}: {msg}"
    );
    msg
}

/// 1-based number of the first line of `text` containing `needle`.
fn line_of(text: &str, needle: &str) -> usize {
    text.lines()
        .position(|l| l.contains(needle))
        .unwrap_or_else(|| panic!("'{needle}' not in text"))
        + 1
}

/// The `path:LINE:` or `path:LINE:COL:` prefix of an error, parsed.
fn line_col_in(msg: &str, path_shown: &str) -> (Option<usize>, Option<usize>) {
    let rest = msg
        .strip_prefix(path_shown)
        .unwrap_or_else(|| panic!("no path prefix in {msg}"));
    let mut parts = rest.splitn(4, ':');
    assert_eq!(parts.next(), Some(""), "no ':' after the path in {msg}");
    let line = parts.next().and_then(|s| s.parse().ok());
    let col = parts.next().and_then(|s| s.parse().ok());
    (line, col)
}

/// A valid two-segment chain with a body mass and shares: each bad-input
/// test changes one line of it.
const BASE: &str = r#"schema = 1
name = "base"
description = "two segments"
head = "top"
body_mass_kg = 70.0

[band]
from_hz = 0.5
to_hz = 20.0
step_hz = 0.1

[[segment]]
name = "top"
share = 0.2

[[segment]]
name = "bottom"
mass_kg = 40.0

[[link]]
name = "top-bottom"
upper = "top"
lower = "bottom"
k_n_per_m = 100000.0
c_ns_per_m = 1000.0

[[link]]
name = "bottom-seat"
upper = "bottom"
lower = "seat"
k_n_per_m = 90000.0
c_ns_per_m = 2000.0
"#;

/// BASE with the one line containing `from` replaced by `to` (which may be
/// several lines or empty).
fn base_with(from: &str, to: &str) -> String {
    assert_eq!(BASE.matches(from).count(), 1, "'{from}' must be unique");
    BASE.replacen(from, to, 1)
}

/// Asserts an error is `path:LINE: ...` (semantic) with LINE = `line`, and
/// that it mentions each of `words`.
fn assert_field_error(text: &str, line: usize, words: &[&str]) {
    let (msg, path, _dir) = load_err_named("bad-preset.toml", text);
    let shown = path.display().to_string();
    let (l, _) = line_col_in(&msg, &shown);
    assert_eq!(l, Some(line), "wrong line in: {msg}");
    for w in words {
        assert!(msg.contains(w), "'{w}' missing from: {msg}");
    }
}

/// Asserts an error is `path:LINE:COL: ...` (syntax) on `line`, col ≥ 1.
fn assert_syntax_error(text: &str, line: usize, words: &[&str]) -> String {
    let (msg, path, _dir) = load_err_named("bad-preset.toml", text);
    let shown = path.display().to_string();
    let (l, c) = line_col_in(&msg, &shown);
    assert_eq!(l, Some(line), "wrong line in: {msg}");
    assert!(c.is_some_and(|c| c >= 1), "no column in: {msg}");
    for w in words {
        assert!(msg.contains(w), "'{w}' missing from: {msg}");
    }
    msg
}

/// Every f64 of a preset, in a fixed order, for bitwise comparison.
fn floats(p: &Preset) -> Vec<u64> {
    let mut v = vec![p.band.from, p.band.to, p.band.step];
    v.extend(p.body.body_mass);
    for s in &p.body.segments {
        v.push(s.mass);
        v.extend(s.share);
    }
    for l in &p.body.links {
        v.push(l.k);
        v.push(l.c);
    }
    v.into_iter().map(f64::to_bits).collect()
}

/// Saves into a fresh folder, loads back, and checks the result is equal
/// and bitwise identical in every number.
fn round_trip(p: &Preset) -> Preset {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join(format!("{}.toml", p.name));
    p.save(&path).unwrap();
    let back = Preset::load(&path).unwrap_or_else(|e| {
        panic!(
            "saved preset does not load: {e}\n{}",
            fs::read_to_string(&path).unwrap()
        )
    });
    assert_eq!(&back, p, "round trip changed the preset");
    assert_eq!(floats(&back), floats(p), "round trip changed some bits");
    // And a second save gives the same bytes.
    let again = dir.path().join("again.toml");
    back.save(&again).unwrap();
    assert_eq!(fs::read(&path).unwrap(), fs::read(&again).unwrap());
    back
}

fn entries(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

// ---- shipped presets -------------------------------------------------------

#[test]
fn shipped_files_parse_and_equal_compiled_in_copies() {
    let mut on_disk: Vec<String> = fs::read_dir(presets_dir())
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .map(|p| p.file_stem().unwrap().to_string_lossy().into_owned())
        .collect();
    on_disk.sort();
    let mut shipped: Vec<String> = SHIPPED.iter().map(|(n, _)| n.to_string()).collect();
    shipped.sort();
    assert_eq!(on_disk, shipped, "presets/*.toml and SHIPPED differ");

    for (name, text) in SHIPPED {
        let path = presets_dir().join(format!("{name}.toml"));
        assert_eq!(fs::read_to_string(&path).unwrap(), text, "{name}: text");
        let from_file = Preset::load(&path).unwrap();
        let builtin = Preset::parse(text, &Origin::Builtin(name.into())).unwrap();
        assert_eq!(from_file, builtin, "{name}");
        assert_eq!(from_file.name, name);
        assert!(!from_file.description.is_empty(), "{name}: no description");
        assert!(!from_file.source.is_empty(), "{name}: no source");
        // open() by name and by path agree too.
        assert_eq!(Preset::open(name).unwrap(), builtin);
        assert_eq!(Preset::open(path.to_str().unwrap()).unwrap(), builtin);
    }
}

#[test]
fn paper_presets_equal_the_paper_body() {
    for kg in [65.0, 75.0, 85.0] {
        let p = Preset::open(&format!("paper-{kg}kg")).unwrap();
        assert_eq!(p.body, Body::paper(kg).unwrap(), "{kg} kg");
        let q = Preset {
            body: Body::paper(kg).unwrap(),
            ..p.clone()
        };
        assert_eq!(floats(&p), floats(&q), "{kg} kg: bits");
        assert_eq!(p.band, Band::default());
    }
    assert_eq!(Preset::builtin_default().body, Body::paper(75.0).unwrap());
}

#[test]
fn boileau_rakheja_preset_has_the_published_masses() {
    let p = Preset::open("boileau-rakheja-1998").unwrap();
    let m: Vec<f64> = p.body.segments.iter().map(|s| s.mass).collect();
    assert_eq!(m, [5.31, 28.49, 8.62, 12.78]);
    assert_eq!(p.body.body_mass, None);
    assert!(p.body.segments.iter().all(|s| s.share.is_none()));
    let k: Vec<f64> = p.body.links.iter().map(|l| l.k).collect();
    assert_eq!(k, biodyn::body::PAPER_K);
    let c: Vec<f64> = p.body.links.iter().map(|l| l.c).collect();
    assert_eq!(c, biodyn::body::PAPER_C);
    assert_eq!(p.body.links[3].lower, End::Seat);
}

// ---- round trips -----------------------------------------------------------

#[test]
fn shipped_presets_round_trip_exactly() {
    for (name, _) in SHIPPED {
        round_trip(&Preset::open(name).unwrap());
    }
}

#[test]
fn to_toml_parses_back_to_the_same_preset() {
    for (name, _) in SHIPPED {
        let p = Preset::open(name).unwrap();
        let back = Preset::parse(&p.to_toml(), &Origin::Builtin(name.into())).unwrap();
        assert_eq!(back, p);
        assert_eq!(floats(&back), floats(&p));
    }
}

#[test]
fn awkward_numbers_round_trip_bitwise() {
    let mut p = Preset::open("paper-75kg").unwrap();
    p.name = "awkward".into();
    p.body.links[0].k = 0.1 + 0.2;
    p.body.links[0].c = 1e-300;
    p.body.links[1].k = 123456.789e3;
    p.body.links[1].c = -0.0; // a valid damping whose sign bit must survive
    p.body.links[2].k = f64::MIN_POSITIVE / 8.0; // subnormal
    p.body.links[2].c = 1.0 / 3.0;
    p.body.links[3].k = 999_999_999_999.999_9; // just under the 1e12 limit
    p.body.links[3].c = 9_999_999_999.999_998; // just under the 1e10 limit
    p.band = Band::new(0.1 + 0.2, 19.999_999_999_999_996, 0.07).unwrap();
    p.body.validate().unwrap();
    round_trip(&p);
}

#[test]
fn masses_set_directly_while_shares_exist_round_trip() {
    let mut p = Preset::open("paper-75kg").unwrap();
    p.name = "direct".into();
    // One mass off its share × body mass, by a single ulp; another far off.
    p.body.segments[1].mass = f64::from_bits((0.402f64 * 75.0).to_bits() + 1);
    p.body.segments[2].mass = 1.000_000_000_000_000_2e-3; // just over the 1 g limit
    p.body.validate().unwrap();
    let back = round_trip(&p);
    assert_eq!(back.body.segments[1].share, Some(0.402));
    // An odd body mass whose share products are inexact.
    let mut q = Preset::open("paper-75kg").unwrap();
    q.body.set_body_mass(70.123_456_789_012_34).unwrap();
    round_trip(&q);
}

#[test]
fn branched_model_with_second_seat_link_round_trips() {
    let seg = Segment::new;
    let link = Link::new;
    let body = Body {
        segments: vec![
            seg("head", 5.5),
            seg("torso", 30.25),
            seg("viscera", 0.1 + 0.2),
            seg("pelvis", 12.0),
        ],
        links: vec![
            link("neck", 0, End::Segment(1), 3.1e5, 400.0),
            link("gut", 2, End::Segment(1), 0.1 + 0.7, 1e-300),
            link("spine", 1, End::Segment(3), 1.83e5, 4750.0),
            link("pelvis-seat", 3, End::Seat, 9e4, 2064.0),
            link("torso-seat", 1, End::Seat, 1234.5678, 0.0),
        ],
        head: 0,
        body_mass: None,
        seat: None,
    };
    body.validate().unwrap();
    assert!(!body.is_tridiagonal());
    let p = Preset {
        name: "branched".into(),
        description: "a \"quoted\" description\nwith a newline, a tab\t and ünïcödé".into(),
        source: "here 'and' there \\ backslash".into(),
        body,
        band: Band::new(1.0, 2.0, 0.25).unwrap(),
    };
    round_trip(&p);
}

#[test]
fn head_other_than_the_first_segment_round_trips() {
    let mut p = Preset::open("boileau-rakheja-1998").unwrap();
    p.body.head = 2;
    round_trip(&p);
}

#[test]
fn empty_name_round_trips() {
    let dir = tempfile::tempdir().unwrap();
    let src = write(
        dir.path(),
        "orig.toml",
        base_with("name = \"base\"", "name = \"\""),
    );
    let p = Preset::load(&src).unwrap();
    assert_eq!(p.name, "");
    let out = dir.path().join("copy.toml");
    p.save(&out).unwrap();
    assert_eq!(Preset::load(&out).unwrap(), p);
}

#[test]
fn base_text_is_valid() {
    // Every bad-input test below edits BASE; it must itself load.
    let p = Preset::parse(BASE, &Origin::Builtin("base".into())).unwrap();
    assert_eq!(p.body.segments[0].mass, 0.2 * 70.0);
    assert_eq!(p.body.segments[1].mass, 40.0);
}

// ---- bad input: files that are not presets at all ---------------------------

#[test]
fn malformed_toml_gives_line_and_column() {
    let text = base_with("share = 0.2", "share = = 0.2");
    let msg = assert_syntax_error(&text, line_of(&text, "share = = 0.2"), &[]);
    assert!(msg.contains(":14:"), "{msg}");

    let text = base_with("[band]", "[band");
    assert_syntax_error(&text, line_of(&text, "[band"), &[]);

    let text = base_with("name = \"top\"", "name = \"top");
    assert_syntax_error(&text, line_of(&text, "name = \"top"), &[]);
}

#[test]
fn malformed_toml_column_is_exact() {
    // "mass_kg = 1.2.3": the value spans columns 11..=15; the error must
    // point into it.
    let text = base_with("mass_kg = 40.0", "mass_kg = 1.2.3");
    let (msg, path, _dir) = load_err_named("bad-preset.toml", &text);
    let (l, c) = line_col_in(&msg, &path.display().to_string());
    assert_eq!(l, Some(line_of(&text, "1.2.3")), "{msg}");
    assert!(c.is_some_and(|c| (11..=15).contains(&c)), "{msg}");
    // A bad key at the start of a line points at column 1.
    let text = base_with("share = 0.2", "= 0.2");
    let (msg, path, _dir) = load_err_named("bad-preset.toml", &text);
    let (l, c) = line_col_in(&msg, &path.display().to_string());
    assert_eq!((l, c), (Some(line_of(&text, "= 0.2")), Some(1)), "{msg}");
}

#[test]
fn empty_file_is_named() {
    let msg = load_err("");
    assert!(msg.contains("empty"), "{msg}");
}

#[test]
fn whitespace_only_file_is_empty() {
    let msg = load_err(" \n\t\r\n   \n");
    assert!(msg.contains("empty"), "{msg}");
}

#[test]
fn comments_only_file_says_what_is_missing() {
    let msg = load_err("# just a comment\n# and another\n");
    assert!(msg.contains("schema") || msg.contains("segment"), "{msg}");
}

#[test]
fn binary_file_is_refused_with_offset() {
    let mut bytes = b"schema = 1\n".to_vec();
    bytes.extend([0u8, 1, 2, 3, 0xff, 0xfe]);
    let msg = load_err(&bytes);
    assert!(msg.contains("not a text file"), "{msg}");
    assert!(msg.contains("byte 11"), "{msg}");
}

#[test]
fn invalid_utf8_is_refused_with_offset() {
    let mut bytes = b"schema = 1\nname = \"".to_vec();
    let at = bytes.len();
    bytes.extend([0xc3, 0x28, b'"', b'\n']);
    let msg = load_err(&bytes);
    assert!(msg.contains("not a text file"), "{msg}");
    assert!(msg.contains(&format!("byte {at}")), "{msg}");
}

#[test]
fn directory_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let sub = dir.path().join("a-folder.toml");
    fs::create_dir(&sub).unwrap();
    let msg = Preset::load(&sub).unwrap_err().to_string();
    assert!(msg.starts_with(&sub.display().to_string()), "{msg}");
    assert!(msg.contains("directory"), "{msg}");
    let msg = Preset::open(sub.to_str().unwrap()).unwrap_err().to_string();
    assert!(msg.contains("directory"), "{msg}");
}

#[test]
fn missing_path_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("no-such-preset.toml");
    let msg = Preset::load(&p).unwrap_err().to_string();
    assert!(msg.starts_with(&p.display().to_string()), "{msg}");
    assert!(msg.contains("cannot read"), "{msg}");
    let msg = Preset::open(p.to_str().unwrap()).unwrap_err().to_string();
    assert!(msg.contains("no-such-preset.toml"), "{msg}");
    // A bare word that is neither a file nor a built-in lists the built-ins.
    let msg = Preset::open("no-such-builtin").unwrap_err().to_string();
    assert!(msg.contains("no-such-builtin"), "{msg}");
    assert!(msg.contains("paper-75kg"), "{msg}");
}

// ---- bad input: wrong shape --------------------------------------------------

#[test]
fn wrong_type_names_line_and_field() {
    let text = base_with("mass_kg = 40.0", "mass_kg = \"heavy\"");
    assert_syntax_error(&text, line_of(&text, "heavy"), &[]);

    let text = base_with("schema = 1", "schema = \"one\"");
    assert_syntax_error(&text, 1, &[]);

    let text = base_with("k_n_per_m = 90000.0", "k_n_per_m = [1, 2]");
    assert_syntax_error(&text, line_of(&text, "[1, 2]"), &[]);
}

#[test]
fn missing_field_names_the_field() {
    let text = base_with("k_n_per_m = 90000.0\n", "");
    let msg = load_err(&text);
    assert!(msg.contains("k_n_per_m"), "{msg}");
    // The error points into the second link table.
    let (l, _) = line_col_in(
        &msg,
        &msg[..msg.find("bad-preset.toml").unwrap() + "bad-preset.toml".len()],
    );
    let first = line_of(&text, "name = \"bottom-seat\"") - 1;
    let last = line_of(&text, "c_ns_per_m = 2000.0");
    assert!(
        l.is_some_and(|l| (first..=last).contains(&l)),
        "line {l:?} not within the link at {first}..={last}: {msg}"
    );
}

#[test]
fn missing_schema_is_named() {
    let text = base_with("schema = 1\n", "");
    let msg = load_err(&text);
    assert!(msg.contains("schema"), "{msg}");
}

#[test]
fn unknown_field_names_the_typo() {
    let text = base_with("mass_kg = 40.0", "mas_kg = 40.0");
    let msg = assert_syntax_error(&text, line_of(&text, "mas_kg"), &["mas_kg"]);
    assert!(msg.contains("unknown field"), "{msg}");

    let text = base_with("schema = 1", "schema = 1\ncolour = \"red\"");
    assert_syntax_error(&text, 2, &["colour"]);

    let text = base_with("step_hz = 0.1", "step_hz = 0.1\nstepp_hz = 0.2");
    assert_syntax_error(&text, line_of(&text, "stepp_hz"), &["stepp_hz"]);
}

#[test]
fn wrong_schema_version_names_line() {
    let text = base_with("schema = 1", "schema = 2");
    assert_field_error(&text, 1, &["schema = 2"]);
}

// ---- bad input: bad values ----------------------------------------------------

/// The line of the `[[segment]]` or `[[link]]` header above `needle`, and
/// the line of `needle` itself: a semantic error about a table may point at
/// either.
fn table_lines(text: &str, needle: &str) -> (usize, usize) {
    let at = line_of(text, needle);
    let header = text.lines().take(at).collect::<Vec<_>>();
    let h = header.iter().rposition(|l| l.starts_with("[[")).unwrap() + 1;
    (h, at)
}

fn assert_table_error(text: &str, needle: &str, words: &[&str]) {
    let (msg, path, _dir) = load_err_named("bad-preset.toml", text);
    let shown = path.display().to_string();
    let (l, _) = line_col_in(&msg, &shown);
    let (h, at) = table_lines(text, needle);
    assert!(
        l.is_some_and(|l| (h..=at).contains(&l)),
        "line {l:?} is not the table at {h}..={at}: {msg}"
    );
    for w in words {
        assert!(msg.contains(w), "'{w}' missing from: {msg}");
    }
}

#[test]
fn bad_masses_name_line_and_segment() {
    for bad in ["-1.0", "0.0", "-0.0", "nan", "inf", "-inf"] {
        let text = base_with("mass_kg = 40.0", &format!("mass_kg = {bad}"));
        assert_table_error(
            &text,
            &format!("mass_kg = {bad}"),
            &["bottom", "mass_kg", "> 0"],
        );
    }
}

#[test]
fn bad_body_mass_and_share_name_line() {
    for bad in ["-70.0", "0.0", "nan", "inf"] {
        let text = base_with("body_mass_kg = 70.0", &format!("body_mass_kg = {bad}"));
        assert_field_error(&text, line_of(&text, "body_mass_kg"), &["body_mass_kg"]);
    }
    for bad in ["-0.2", "0.0", "nan"] {
        let text = base_with("share = 0.2", &format!("share = {bad}"));
        assert_table_error(&text, &format!("share = {bad}"), &["top", "share"]);
    }
}

#[test]
fn bad_stiffness_and_damping_name_line_and_field() {
    for bad in ["-1.0", "nan", "inf"] {
        let text = base_with("k_n_per_m = 90000.0", &format!("k_n_per_m = {bad}"));
        assert_table_error(
            &text,
            &format!("k_n_per_m = {bad}"),
            &["bottom-seat", "k_n_per_m"],
        );
        let text = base_with("c_ns_per_m = 1000.0", &format!("c_ns_per_m = {bad}"));
        assert_table_error(
            &text,
            &format!("c_ns_per_m = {bad}"),
            &["top-bottom", "c_ns_per_m"],
        );
    }
}

#[test]
fn link_to_unknown_segment_names_line_and_name() {
    let text = base_with("lower = \"bottom\"", "lower = \"botom\"");
    assert_table_error(&text, "botom", &["botom", "lower"]);
    let text = base_with("upper = \"bottom\"", "upper = \"pelvis\"");
    assert_table_error(&text, "\"pelvis\"", &["pelvis", "upper"]);
    let text = base_with("head = \"top\"", "head = \"hed\"");
    assert_field_error(&text, 4, &["hed", "head"]);
}

#[test]
fn no_link_to_the_seat_is_named() {
    let text = base_with("lower = \"seat\"", "lower = \"top\"");
    let msg = load_err(&text);
    assert!(msg.contains("seat"), "{msg}");
    assert!(msg.contains("lower"), "{msg}");
}

#[test]
fn floating_segment_is_named() {
    // A third segment with no link at all.
    let text = base_with(
        "[[link]]\nname = \"top-bottom\"",
        "[[segment]]\nname = \"loose\"\nmass_kg = 3.0\n\n[[link]]\nname = \"top-bottom\"",
    );
    let msg = load_err(&text);
    assert!(msg.contains("'loose'"), "{msg}");
    assert!(msg.contains("not tied to the seat"), "{msg}");
    // Two segments linked to each other, neither to the seat or the rest.
    let text = format!(
        "{}\n[[segment]]\nname = \"a\"\nmass_kg = 1.0\n\n[[segment]]\nname = \"b\"\nmass_kg = 1.0\n\n[[link]]\nupper = \"a\"\nlower = \"b\"\nk_n_per_m = 1.0\nc_ns_per_m = 1.0\n",
        BASE
    );
    // Segments after links are still array-of-tables entries: TOML allows it.
    let msg = load_err(&text);
    assert!(msg.contains("'a'") || msg.contains("'b'"), "{msg}");
    assert!(msg.contains("not tied to the seat"), "{msg}");
}

#[test]
fn duplicate_segment_names_are_named() {
    let text = format!("{BASE}\n[[segment]]\nname = \"bottom\"\nmass_kg = 1.0\n");
    let msg = load_err(&text);
    assert!(msg.contains("'bottom'"), "{msg}");
    assert!(msg.contains("twice") || msg.contains("duplicate"), "{msg}");
}

#[test]
fn duplicate_link_names_are_named() {
    let text = base_with("name = \"bottom-seat\"", "name = \"top-bottom\"");
    let msg = load_err(&text);
    assert!(msg.contains("'top-bottom'"), "{msg}");
    assert!(msg.contains("twice"), "{msg}");
}

#[test]
fn share_without_body_mass_names_line() {
    let text = base_with("body_mass_kg = 70.0\n", "");
    assert_table_error(&text, "share = 0.2", &["top", "body_mass_kg"]);
}

#[test]
fn segment_without_mass_or_share_names_line() {
    let text = base_with("mass_kg = 40.0\n", "");
    assert_table_error(&text, "name = \"bottom\"", &["bottom", "mass_kg", "share"]);
}

#[test]
fn no_segments_at_all_is_named() {
    let msg = load_err("schema = 1\n");
    assert!(msg.contains("segment"), "{msg}");
}

#[test]
fn bad_bands_name_the_band() {
    for (from, to, step, word) in [
        ("5.0", "5.0", "0.1", "from"),
        ("5.0", "1.0", "0.1", "from"),
        ("0.5", "20.0", "0.0", "step"),
        ("0.5", "20.0", "-0.1", "step"),
        ("0.5", "20.0", "nan", "step"),
        ("0.5", "20.0", "1e-6", "10"),
        ("-1.0", "20.0", "0.1", "from"),
        ("0.5", "inf", "0.1", "to"),
    ] {
        let text = base_with(
            "from_hz = 0.5\nto_hz = 20.0\nstep_hz = 0.1",
            &format!("from_hz = {from}\nto_hz = {to}\nstep_hz = {step}"),
        );
        let msg = load_err(&text);
        assert!(msg.contains("[band]"), "{from} {to} {step}: {msg}");
        assert!(msg.contains(word), "{from} {to} {step}: '{word}' in {msg}");
    }
}

#[test]
fn band_of_exactly_a_million_points_loads_one_more_does_not() {
    // 1 Hz on at step 1/16 (exact in binary) to 62500.9375 Hz: exactly 10^6
    // points is allowed (inside the 100 kHz limit).
    let band = |to: &str| {
        base_with(
            "from_hz = 0.5\nto_hz = 20.0\nstep_hz = 0.1",
            &format!("from_hz = 1.0\nto_hz = {to}\nstep_hz = 0.0625"),
        )
    };
    let p = Preset::parse(&band("62500.9375"), &Origin::Builtin("x".into())).unwrap();
    assert_eq!(p.band.len(), 1_000_000);
    let msg = load_err(band("62501.0"));
    assert!(msg.contains("[band]"), "{msg}");
    assert!(msg.contains("1000001 points"), "{msg}");
    assert!(msg.contains("more than 1000000"), "{msg}");
}

#[test]
fn builtin_origin_labels_errors() {
    let msg = Preset::parse("schema = 1\nx = 1\n", &Origin::Builtin("mine".into()))
        .unwrap_err()
        .to_string();
    assert!(msg.starts_with("<built-in mine>:2:"), "{msg}");
}

// ---- atomic save -------------------------------------------------------------

#[test]
fn save_into_missing_directory_fails_and_creates_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let missing = dir.path().join("no-such-dir");
    let target = missing.join("x.toml");
    let err = Preset::builtin_default().save(&target).unwrap_err();
    let msg = err.to_string();
    assert!(msg.contains(&target.display().to_string()), "{msg}");
    assert!(msg.contains("cannot save"), "{msg}");
    assert!(!missing.exists());
    assert!(entries(dir.path()).is_empty(), "{:?}", entries(dir.path()));
}

#[test]
fn saving_onto_a_directory_fails_and_leaves_it_and_no_temp_file() {
    let dir = tempfile::tempdir().unwrap();
    let target = dir.path().join("target.toml");
    fs::create_dir(&target).unwrap();
    fs::write(target.join("inside.txt"), b"keep me").unwrap();
    let msg = Preset::builtin_default()
        .save(&target)
        .unwrap_err()
        .to_string();
    assert!(msg.contains("target.toml"), "{msg}");
    assert!(target.is_dir());
    assert_eq!(fs::read(target.join("inside.txt")).unwrap(), b"keep me");
    assert_eq!(entries(dir.path()), ["target.toml"]);
}

#[test]
fn successful_save_replaces_and_leaves_no_temp_file() {
    let dir = tempfile::tempdir().unwrap();
    let target = dir.path().join("p.toml");
    fs::write(&target, b"old contents").unwrap();
    let p = Preset::open("paper-85kg").unwrap();
    p.save(&target).unwrap();
    assert_eq!(entries(dir.path()), ["p.toml"]);
    assert_eq!(fs::read_to_string(&target).unwrap(), p.to_toml());
    assert_eq!(Preset::load(&target).unwrap(), p);
}

#[test]
fn save_to_a_path_without_a_file_name_fails() {
    let dir = tempfile::tempdir().unwrap();
    let target = dir.path().join("..");
    let msg = Preset::builtin_default()
        .save(&target)
        .unwrap_err()
        .to_string();
    assert!(msg.contains("cannot save"), "{msg}");
    assert!(entries(dir.path()).is_empty());
}

#[test]
fn zero_stiffness_and_damping_seat_link_does_not_tie() {
    let text = base_with(
        "k_n_per_m = 90000.0\nc_ns_per_m = 2000.0",
        "k_n_per_m = 0.0\nc_ns_per_m = 0.0",
    );
    let msg = load_err(&text);
    assert!(msg.contains("seat"), "{msg}");
}

#[test]
fn syntax_error_column_counts_characters() {
    let text = base_with(
        "description = \"two segments\"",
        "description = \"ééééé\" oops",
    );
    let (msg, path, _dir) = load_err_named("bad-preset.toml", &text);
    let (l, c) = line_col_in(&msg, &path.display().to_string());
    assert_eq!((l, c), (Some(3), Some(23)), "{msg}");
}

#[test]
fn concurrent_saves_to_one_path_leave_a_whole_preset() {
    let dir = tempfile::tempdir().unwrap();
    let target = dir.path().join("shared.toml");
    let a = Preset::open("paper-75kg").unwrap();
    let mut b = Preset::open("boileau-rakheja-1998").unwrap();
    b.description = "x".repeat(20_000);
    std::thread::scope(|s| {
        for p in [&a, &b, &a, &b] {
            let target = &target;
            s.spawn(move || {
                for _ in 0..200 {
                    p.save(target).unwrap();
                }
            });
        }
    });
    let back = Preset::load(&target).unwrap();
    assert!(back == a || back == b);
    assert_eq!(entries(dir.path()), ["shared.toml"]);
}

// ---- issue 8: limits, names, bounded errors, safe files ---------------------------

#[test]
fn body_mass_out_of_range_names_body_mass_kg_at_its_line() {
    for bad in ["1e-308", "1e308", "5e-4", "2e6"] {
        let text = base_with("body_mass_kg = 70.0", &format!("body_mass_kg = {bad}"));
        assert_field_error(
            &text,
            line_of(&text, "body_mass_kg"),
            &[&format!("body_mass_kg = {bad}"), "1e-3", "1e6"],
        );
    }
    // A share that makes a segment lighter than a gram: the share's line,
    // naming the body mass it multiplies.
    let text = base_with("share = 0.2", "share = 1e-6");
    assert_field_error(
        &text,
        line_of(&text, "share = 1e-6"),
        &["top", "body_mass_kg 70", "1e-3"],
    );
    let text = base_with("mass_kg = 40.0", "mass_kg = 1e-4");
    assert_field_error(&text, line_of(&text, "mass_kg = 1e-4"), &["bottom", "1e-4"]);
}

#[test]
fn names_that_mislead_are_refused_at_their_line() {
    for bad in [
        r#""top\nx""#,
        r#""top\u001b[31m""#,
        r#""m2""#,
        r#""K1""#,
        r#""top.k""#,
        r#""body_mass""#,
        r#"" top""#,
    ] {
        let text = base_with("name = \"top\"", &format!("name = {bad}"));
        // Links and head refer to "top" by name: rename them too so the
        // name itself is the first problem.
        let text = text
            .replace("upper = \"top\"", &format!("upper = {bad}"))
            .replace("head = \"top\"", &format!("head = {bad}"));
        let line = line_of(&text, &format!("name = {bad}"));
        let msg = load_err(&text);
        assert!(
            msg.contains(&format!(":{line}: segment 1: name")),
            "{bad}: {msg}"
        );
        assert!(!msg.contains('\u{1b}') && !msg.contains('\n'), "{msg:?}");
        let text = base_with("name = \"top-bottom\"", &format!("name = {bad}"));
        let line = line_of(&text, bad);
        let msg = load_err(&text);
        assert!(
            msg.contains(&format!(":{line}: link 1: name")),
            "{bad}: {msg}"
        );
    }
    let text = base_with("name = \"base\"", "name = \"a\\u001b[2Jb\"");
    let msg = load_err(&text);
    assert!(
        msg.contains(":2: name = ") && msg.contains("control"),
        "{msg}"
    );
}

#[test]
fn errors_quote_a_short_excerpt_and_short_numbers() {
    let huge = format!("body_mass_kg = \"{}\"", "y".repeat(2_000_000));
    let msg = load_err(base_with("body_mass_kg = 70.0", &huge));
    assert!(msg.len() < 1000, "{} bytes", msg.len());
    let deep = format!("x = {}1{}", "[".repeat(100_000), "]".repeat(100_000));
    let msg = load_err(base_with("description = \"two segments\"", &deep));
    assert!(msg.len() < 1000, "{} bytes", msg.len());
    let long = format!("1{}.0", "0".repeat(300));
    let msg = load_err(base_with(
        "k_n_per_m = 90000.0",
        &format!("k_n_per_m = {long}"),
    ));
    assert!(
        msg.contains("1e300") && !msg.contains("0000000000"),
        "{msg}"
    );
    let msg = load_err(base_with("schema = 1", "schema = 1e300"));
    assert!(
        msg.contains("1e300") && !msg.contains("0000000000"),
        "{msg}"
    );
    let long_name = format!("name = \"{}\"", "n".repeat(100_000));
    let msg = load_err(base_with("name = \"bottom\"", &long_name));
    assert!(msg.len() < 1000 && msg.contains("too long"), "{msg}");
}

#[test]
fn a_deep_dotted_header_is_placed_at_its_line_and_column() {
    let text = format!(
        "# first\n{BASE}\n   [{}]\nx = 1\n",
        vec!["a"; 100].join(".")
    );
    let line = line_of(&text, "[a.a.a");
    assert_syntax_error(&text, line, &["levels deep"]);
    let (msg, path, _dir) = load_err_named("bad-preset.toml", &text);
    let (_, c) = line_col_in(&msg, &path.display().to_string());
    assert_eq!(c, Some(4), "{msg}");
    // A dotted key, not a header.
    let text = format!("{BASE}\n{} = 1\n", vec!["k"; 90].join("."));
    assert_syntax_error(&text, line_of(&text, "k.k.k"), &["levels deep"]);
}

#[test]
fn a_value_error_names_the_line_of_its_key() {
    let text = base_with("c_ns_per_m = 2000.0", "c_ns_per_m = -3.0");
    assert_field_error(
        &text,
        line_of(&text, "c_ns_per_m = -3.0"),
        &["bottom-seat", "-3"],
    );
    let text = base_with("lower = \"seat\"", "lower = \"floor\"");
    assert_field_error(
        &text,
        line_of(&text, "\"floor\""),
        &["floor", "no [seat] table", "lower = \"seat\""],
    );
}

#[cfg(unix)]
#[test]
fn special_files_are_refused_on_load_and_save() {
    use std::os::unix::fs::{FileTypeExt, PermissionsExt, symlink};
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("f.toml");
    assert!(
        std::process::Command::new("mkfifo")
            .arg(&fifo)
            .status()
            .unwrap()
            .success()
    );
    let msg = Preset::load(&fifo).unwrap_err().to_string();
    assert!(
        msg.contains("FIFO") && msg.contains("not a regular file"),
        "{msg}"
    );
    let msg = Preset::builtin_default()
        .save(&fifo)
        .unwrap_err()
        .to_string();
    assert!(msg.contains("FIFO") && msg.contains("cannot save"), "{msg}");
    assert!(fs::symlink_metadata(&fifo).unwrap().file_type().is_fifo());
    let msg = Preset::load(Path::new("/dev/zero"))
        .unwrap_err()
        .to_string();
    assert!(msg.contains("character device"), "{msg}");
    // Over the cap: refused from the size alone.
    let big = dir.path().join("big.toml");
    fs::File::create(&big)
        .unwrap()
        .set_len((4 << 20) + 1)
        .unwrap();
    let msg = Preset::load(&big).unwrap_err().to_string();
    assert!(msg.contains("4 MiB cap"), "{msg}");
    // A link is followed; the mode of the file it names is kept.
    let real = write(dir.path(), "real.toml", "old");
    fs::set_permissions(&real, fs::Permissions::from_mode(0o600)).unwrap();
    symlink("real.toml", dir.path().join("link.toml")).unwrap();
    let p = Preset::open("paper-65kg").unwrap();
    p.save(&dir.path().join("link.toml")).unwrap();
    assert_eq!(Preset::load(&real).unwrap(), p);
    assert_eq!(
        fs::metadata(&real).unwrap().permissions().mode() & 0o777,
        0o600
    );
    assert!(
        fs::symlink_metadata(dir.path().join("link.toml"))
            .unwrap()
            .file_type()
            .is_symlink()
    );
}

#[test]
fn a_preset_that_would_not_load_back_is_not_saved() {
    let dir = tempfile::tempdir().unwrap();
    let target = write(dir.path(), "keep.toml", "old");
    let mut p = Preset::builtin_default();
    p.name = "tab\there".into(); // the loader refuses a tab in a preset name
    let msg = p.save(&target).unwrap_err().to_string();
    assert!(
        msg.contains("would not load back") && msg.contains("name"),
        "{msg}"
    );
    let mut p = Preset::builtin_default();
    p.body.segments[3].name = "seat".into(); // valid as a Body, ambiguous in a file
    let msg = p.save(&target).unwrap_err().to_string();
    assert!(
        msg.contains("would not load back") && msg.contains("seat"),
        "{msg}"
    );
    assert_eq!(fs::read(&target).unwrap(), b"old");
    assert_eq!(entries(dir.path()), ["keep.toml"]);
}
