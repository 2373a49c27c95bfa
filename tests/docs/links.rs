//! Relative links between the Markdown files: the file exists, and the
//! `#anchor` is a heading of it (GitHub's slugs).

use std::collections::HashSet;
use std::path::{Path, PathBuf};

/// The text outside fenced blocks and inline code, line by line.
fn prose(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut fence: Option<String> = None;
    for l in text.lines() {
        let t = l.trim_start();
        let tick = ['`', '~']
            .into_iter()
            .find(|&c| t.starts_with(&c.to_string().repeat(3)));
        if let Some(c) = tick {
            let n = t.chars().take_while(|&x| x == c).count();
            let m = c.to_string().repeat(n);
            match &fence {
                None => fence = Some(m),
                Some(f) if t.starts_with(f.as_str()) && t[f.len()..].trim().is_empty() => {
                    fence = None
                }
                _ => {}
            }
            continue;
        }
        if fence.is_some() {
            continue;
        }
        // Drop inline code spans.
        let mut s = String::new();
        let mut in_code = false;
        for ch in l.chars() {
            if ch == '`' {
                in_code = !in_code;
            } else if !in_code {
                s.push(ch);
            }
        }
        out.push(s);
    }
    out
}

/// GitHub's anchor of a heading: lower case, spaces to dashes, and only
/// letters, digits, `-` and `_` kept.
pub fn slug(heading: &str) -> String {
    heading
        .chars()
        .filter_map(|c| match c {
            ' ' => Some('-'),
            '-' | '_' => Some(c),
            c if c.is_alphanumeric() => Some(c),
            _ => None,
        })
        .flat_map(char::to_lowercase)
        .collect()
}

/// Every heading's anchor in a file (a repeated heading gets `-1`, `-2`).
fn anchors(path: &Path) -> HashSet<String> {
    let text = std::fs::read_to_string(path).unwrap_or_default();
    let mut seen = HashSet::new();
    let mut fence = false;
    for l in text.lines() {
        if l.trim_start().starts_with("```") {
            fence = !fence;
            continue;
        }
        if fence || !l.starts_with('#') {
            continue;
        }
        let h = l.trim_start_matches('#').trim();
        let base = slug(h);
        let mut s = base.clone();
        let mut n = 0;
        while seen.contains(&s) {
            n += 1;
            s = format!("{base}-{n}");
        }
        seen.insert(s);
    }
    seen
}

/// The targets of `[text](target)` links in a line.
fn targets(line: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = line;
    while let Some(i) = rest.find("](") {
        let after = &rest[i + 2..];
        match after.find(')') {
            Some(j) => {
                out.push(after[..j].trim().to_string());
                rest = &after[j..];
            }
            None => break,
        }
    }
    out
}

/// Every relative link that leads nowhere, as `file:line: target (why)`.
pub fn broken(root: &Path, files: &[PathBuf]) -> Vec<String> {
    let mut bad = Vec::new();
    for f in files {
        let text = std::fs::read_to_string(f).unwrap_or_default();
        let name = f.strip_prefix(root).unwrap_or(f).display().to_string();
        for (n, l) in prose(&text).iter().enumerate() {
            for t in targets(l) {
                if t.contains("://") || t.starts_with("mailto:") {
                    continue;
                }
                let (file, anchor) = t.split_once('#').unwrap_or((t.as_str(), ""));
                let dest = if file.is_empty() {
                    f.clone()
                } else {
                    f.parent().unwrap_or(root).join(file)
                };
                if !dest.exists() {
                    // docs/keys.md is written by a test from the key tables.
                    if !dest.ends_with("docs/keys.md") {
                        bad.push(format!("{name}:{}: {t} (no such file)", n + 1));
                    }
                    continue;
                }
                if !anchor.is_empty() && dest.is_file() && !anchors(&dest).contains(anchor) {
                    bad.push(format!("{name}:{}: {t} (no such heading)", n + 1));
                }
            }
        }
    }
    bad
}

#[cfg(test)]
mod tests {
    use super::slug;

    #[test]
    fn slugs_are_githubs() {
        assert_eq!(
            slug("`biodyn fit` — fit a model to measurements"),
            "biodyn-fit--fit-a-model-to-measurements"
        );
        assert_eq!(
            slug("Neural-network surrogates (paper §5–7)"),
            "neural-network-surrogates-paper-57"
        );
        assert_eq!(slug("Mouse (`M`)"), "mouse-m");
    }
}
