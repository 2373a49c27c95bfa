//! Checks on the library's own source that keep its seams where they are:
//! no string names a command-line flag (the library names the field and the
//! value; the fronts add their words), and no module imports one that
//! imports it back. Both read `src/` as text, outside comments and
//! `#[cfg(test)]` code.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// A source file with its comments removed and every string and char
/// literal blanked (so braces and `use` inside them do not count), plus the
/// literals' contents with their offsets in that text.
struct Lexed {
    code: String,
    strings: Vec<(usize, String)>,
}

fn lex(src: &str) -> Lexed {
    let c: Vec<char> = src.chars().collect();
    let (mut code, mut strings) = (String::new(), Vec::new());
    let mut i = 0;
    let ident = |ch: char| ch.is_alphanumeric() || ch == '_';
    while i < c.len() {
        let next = c.get(i + 1).copied();
        if c[i] == '/' && next == Some('/') {
            while i < c.len() && c[i] != '\n' {
                i += 1;
            }
        } else if c[i] == '/' && next == Some('*') {
            let mut depth = 0;
            while i < c.len() {
                if c[i] == '/' && c.get(i + 1) == Some(&'*') {
                    depth += 1;
                    i += 2;
                } else if c[i] == '*' && c.get(i + 1) == Some(&'/') {
                    depth -= 1;
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    i += 1;
                }
            }
        } else if c[i] == 'r'
            && (i == 0 || !ident(c[i - 1]) || c[i - 1] == 'b')
            && matches!(next, Some('"' | '#'))
            && {
                let mut j = i + 1;
                while c.get(j) == Some(&'#') {
                    j += 1;
                }
                c.get(j) == Some(&'"')
            }
        {
            let mut j = i + 1;
            let mut hashes = 0;
            while c[j] == '#' {
                hashes += 1;
                j += 1;
            }
            let start = j + 1;
            let mut k = start;
            while k < c.len() {
                if c[k] == '"' && (0..hashes).all(|h| c.get(k + 1 + h) == Some(&'#')) {
                    break;
                }
                k += 1;
            }
            strings.push((code.len(), c[start..k.min(c.len())].iter().collect()));
            code.push_str("\"\"");
            i = k + 1 + hashes;
        } else if c[i] == '"' {
            let mut k = i + 1;
            let mut s = String::new();
            while k < c.len() && c[k] != '"' {
                if c[k] == '\\' {
                    s.push(c[k]);
                    k += 1;
                }
                if k < c.len() {
                    s.push(c[k]);
                }
                k += 1;
            }
            strings.push((code.len(), s));
            code.push_str("\"\"");
            i = k + 1;
        } else if c[i] == '\'' {
            // A char literal ('x', '\n', '\u{1b}') or a lifetime ('a).
            if next == Some('\\') {
                let mut k = i + 2;
                while k < c.len() && c[k] != '\'' {
                    k += 1;
                }
                code.push_str("' '");
                i = k + 1;
            } else if c.get(i + 2) == Some(&'\'') {
                code.push_str("' '");
                i += 3;
            } else {
                code.push('\'');
                i += 1;
            }
        } else {
            code.push(c[i]);
            i += 1;
        }
    }
    Lexed { code, strings }
}

/// Byte ranges of `code` that are `#[cfg(test)]` items.
fn test_ranges(code: &str) -> Vec<(usize, usize)> {
    let b = code.as_bytes();
    let mut out = Vec::new();
    let mut from = 0;
    while let Some(at) = code[from..].find("#[cfg(test)]").map(|p| p + from) {
        let mut k = at + "#[cfg(test)]".len();
        while k < b.len() && b[k] != b';' && b[k] != b'{' {
            k += 1;
        }
        if k < b.len() && b[k] == b'{' {
            let mut depth = 0;
            while k < b.len() {
                match b[k] {
                    b'{' => depth += 1,
                    b'}' => {
                        depth -= 1;
                        if depth == 0 {
                            break;
                        }
                    }
                    _ => {}
                }
                k += 1;
            }
        }
        out.push((at, k + 1));
        from = k + 1;
    }
    out
}

/// `code` without its test items.
fn outside_tests(code: &str) -> String {
    let mut out = String::new();
    let mut last = 0;
    for (a, b) in test_ranges(code) {
        out.push_str(&code[last..a]);
        last = b.min(code.len());
    }
    out.push_str(&code[last..]);
    out
}

fn sources() -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        let mut entries: Vec<_> = std::fs::read_dir(dir)
            .expect("src/ is readable")
            .map(|e| e.expect("a directory entry").path())
            .collect();
        entries.sort();
        for p in entries {
            if p.is_dir() {
                walk(&p, out);
            } else if p.extension().is_some_and(|e| e == "rs") {
                out.push(p);
            }
        }
    }
    let mut out = Vec::new();
    walk(&Path::new(env!("CARGO_MANIFEST_DIR")).join("src"), &mut out);
    out
}

/// Whether `s` names a long flag: `--` then a lowercase letter, not inside
/// a longer run of dashes or a word.
fn names_a_flag(s: &str) -> bool {
    let b = s.as_bytes();
    (0..b.len().saturating_sub(2)).any(|i| {
        b[i] == b'-'
            && b[i + 1] == b'-'
            && b[i + 2].is_ascii_lowercase()
            && (i == 0 || !(b[i - 1] == b'-' || b[i - 1].is_ascii_alphanumeric()))
    })
}

#[test]
fn no_library_string_names_a_command_line_flag() {
    let mut found = Vec::new();
    for path in sources() {
        let src = std::fs::read_to_string(&path).expect("a source file");
        if path
            .file_name()
            .is_some_and(|n| n == "tests.rs" || n == "seams.rs")
        {
            continue;
        }
        let lexed = lex(&src);
        let tests = test_ranges(&lexed.code);
        for (at, s) in &lexed.strings {
            let in_test = tests.iter().any(|&(a, b)| (a..b).contains(at));
            if !in_test && names_a_flag(s) {
                found.push(format!("{}: \"{s}\"", path.display()));
            }
        }
    }
    assert!(
        found.is_empty(),
        "library strings name a flag (name the field and the value; the CLI adds the flag):\n{}",
        found.join("\n")
    );
}

#[test]
fn the_checks_see_what_they_look_for() {
    assert!(names_a_flag("e.g. --fs 1000"));
    assert!(names_a_flag("--free: empty"));
    assert!(!names_a_flag("a --- b"));
    assert!(!names_a_flag("x--y"));
    let l =
        lex("// \"--no\"\nlet a = \"--yes\"; let c = '\"'; /* \"--no\" */ let r = r#\"--raw\"#;");
    let s: Vec<&str> = l.strings.iter().map(|(_, s)| s.as_str()).collect();
    assert_eq!(s, ["--yes", "--raw"]);
    let code = outside_tests("fn a() {}\n#[cfg(test)]\nmod tests { fn b() { {} } }\nfn c() {}");
    assert!(code.contains("fn a") && code.contains("fn c") && !code.contains("fn b"));
    let g = graph(&[
        (vec!["a".to_string()], "use crate::b::X;".to_string()),
        (vec!["b".to_string()], "use super::a::Y;".to_string()),
    ]);
    assert!(cycle(&g).is_some());
}

/// A module path: `["fit", "error"]`; the crate root is `[]`.
type Module = Vec<String>;

fn module_of(path: &Path) -> Module {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let rel = path
        .strip_prefix(&root)
        .expect("under src/")
        .with_extension("");
    let mut m: Module = rel
        .components()
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect();
    if matches!(m.last().map(String::as_str), Some("mod" | "lib")) {
        m.pop();
    }
    m
}

/// `a::{b, c::{d, e}}` → `a::b`, `a::c::d`, `a::c::e`.
fn expand(tree: &str) -> Vec<String> {
    let tree = tree.trim();
    let Some(open) = tree.find('{') else {
        return vec![tree.to_string()];
    };
    let (prefix, inner) = (
        &tree[..open],
        &tree[open + 1..tree.rfind('}').unwrap_or(tree.len())],
    );
    let (mut parts, mut depth, mut cur) = (Vec::new(), 0, String::new());
    for ch in inner.chars() {
        match ch {
            ',' if depth == 0 => {
                parts.push(std::mem::take(&mut cur));
                continue;
            }
            '{' => depth += 1,
            '}' => depth -= 1,
            _ => {}
        }
        cur.push(ch);
    }
    parts.push(cur);
    parts
        .iter()
        .filter(|p| !p.trim().is_empty())
        .flat_map(|p| expand(p).into_iter().map(move |x| format!("{prefix}{x}")))
        .collect()
}

/// Every `use` in `code`: (is it `pub`, the path).
fn uses(code: &str) -> Vec<(bool, String)> {
    let mut out = Vec::new();
    let b = code.as_bytes();
    let mut from = 0;
    while let Some(at) = code[from..].find("use ").map(|p| p + from) {
        from = at + 4;
        if at > 0 && (b[at - 1].is_ascii_alphanumeric() || b[at - 1] == b'_') {
            continue;
        }
        let Some(end) = code[at..].find(';').map(|p| p + at) else {
            break;
        };
        let before = code[..at].trim_end();
        let public = before.ends_with("pub") || before.ends_with(')') && before.contains("pub(");
        let body: String = code[at + 4..end]
            .split_whitespace()
            .collect::<Vec<_>>()
            .join(" ");
        out.extend(expand(&body).into_iter().map(|p| (public, p)));
        from = end;
    }
    out
}

/// `crate::…`, `super::…` or `self::…` paths anywhere in `code`.
fn inline_paths(code: &str) -> Vec<String> {
    let mut out = Vec::new();
    let b = code.as_bytes();
    for start in ["crate::", "super::", "self::"] {
        let mut from = 0;
        while let Some(at) = code[from..].find(start).map(|p| p + from) {
            let mut k = at;
            while k < b.len() && (b[k].is_ascii_alphanumeric() || b[k] == b'_' || b[k] == b':') {
                k += 1;
            }
            if at == 0
                || !(b[at - 1].is_ascii_alphanumeric() || b[at - 1] == b'_' || b[at - 1] == b':')
            {
                out.push(code[at..k].trim_end_matches(':').to_string());
            }
            from = k.max(at + 1);
        }
    }
    out
}

/// Edges between modules: module → the modules whose items it names,
/// re-exports followed to where an item is defined.
fn graph(files: &[(Module, String)]) -> BTreeMap<Module, BTreeSet<Module>> {
    let known: BTreeSet<Module> = files.iter().map(|f| f.0.clone()).collect();
    let absolute = |m: &Module, path: &str| -> Option<Vec<String>> {
        let segs: Vec<String> = path
            .split("::")
            .map(|s| s.split(" as ").next().unwrap_or(s).trim().to_string())
            .collect();
        let mut out: Vec<String>;
        let mut rest = &segs[..];
        match segs.first().map(String::as_str) {
            Some("crate") => {
                out = Vec::new();
                rest = &segs[1..];
            }
            Some("self") => {
                out = m.clone();
                rest = &segs[1..];
            }
            Some("super") => {
                out = m.clone();
                while rest.first().is_some_and(|s| s == "super") {
                    out.pop();
                    rest = &rest[1..];
                }
            }
            Some(first) => {
                let mut child = m.clone();
                child.push(first.to_string());
                if !known.contains(&child) {
                    return None;
                }
                out = m.clone();
            }
            None => return None,
        }
        out.extend(rest.iter().filter(|s| *s != "*" && *s != "self").cloned());
        Some(out)
    };
    let mut reexports: BTreeMap<(Module, String), Vec<String>> = BTreeMap::new();
    for (m, code) in files {
        for (public, p) in uses(code) {
            if let (true, Some(a)) = (public, absolute(m, &p)) {
                let name = p.rsplit(" as ").next().unwrap_or(&p);
                let name = name.rsplit("::").next().unwrap_or(name).trim().to_string();
                reexports.insert((m.clone(), name), a);
            }
        }
    }
    let resolve = |a: Vec<String>| -> Module {
        let mut a = a;
        for _ in 0..10 {
            let n = (0..=a.len())
                .rev()
                .find(|&n| known.contains(&a[..n]))
                .unwrap_or(0);
            let module = a[..n].to_vec();
            match a
                .get(n)
                .and_then(|item| reexports.get(&(module.clone(), item.clone())))
            {
                Some(target) if *target != a => {
                    let mut next = target.clone();
                    next.extend(a[n + 1..].iter().cloned());
                    a = next;
                }
                _ => return module,
            }
        }
        a
    };
    let mut edges: BTreeMap<Module, BTreeSet<Module>> = BTreeMap::new();
    for (m, code) in files {
        let mut paths: Vec<String> = uses(code).into_iter().map(|(_, p)| p).collect();
        paths.extend(inline_paths(code));
        for p in paths {
            if let Some(a) = absolute(m, &p) {
                let target = resolve(a);
                if target != *m && !target.is_empty() {
                    edges.entry(m.clone()).or_default().insert(target);
                }
            }
        }
    }
    edges
}

/// One cycle of the graph, if there is one: the modules along it.
fn cycle(edges: &BTreeMap<Module, BTreeSet<Module>>) -> Option<Vec<Module>> {
    fn visit(
        v: &Module,
        edges: &BTreeMap<Module, BTreeSet<Module>>,
        state: &mut BTreeMap<Module, u8>,
        stack: &mut Vec<Module>,
    ) -> Option<Vec<Module>> {
        state.insert(v.clone(), 1);
        stack.push(v.clone());
        for w in edges.get(v).into_iter().flatten() {
            match state.get(w).copied().unwrap_or(0) {
                1 => {
                    let from = stack.iter().position(|x| x == w).unwrap_or(0);
                    let mut c = stack[from..].to_vec();
                    c.push(w.clone());
                    return Some(c);
                }
                0 => {
                    if let Some(c) = visit(w, edges, state, stack) {
                        return Some(c);
                    }
                }
                _ => {}
            }
        }
        stack.pop();
        state.insert(v.clone(), 2);
        None
    }
    let mut state = BTreeMap::new();
    for v in edges.keys() {
        if state.get(v).copied().unwrap_or(0) == 0
            && let Some(c) = visit(v, edges, &mut state, &mut Vec::new())
        {
            return Some(c);
        }
    }
    None
}

#[test]
fn no_module_imports_one_that_imports_it_back() {
    let files: Vec<(Module, String)> = sources()
        .iter()
        .filter(|p| p.file_name().is_some_and(|n| n != "tests.rs"))
        .map(|p| {
            let src = std::fs::read_to_string(p).expect("a source file");
            (module_of(p), outside_tests(&lex(&src).code))
        })
        .collect();
    let edges = graph(&files);
    assert!(
        edges.len() > 40,
        "the graph is too small to be read right: {}",
        edges.len()
    );
    if let Some(c) = cycle(&edges) {
        let names: Vec<String> = c.iter().map(|m| m.join("::")).collect();
        panic!("an import circle: {}", names.join(" → "));
    }
}
