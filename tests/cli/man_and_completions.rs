//! `biodyn man` and `biodyn completions SHELL` as real processes: the page
//! and the scripts name every subcommand, render or parse where the tool is
//! installed, and write to stdout under the same rules as every command.

use crate::common::{ok, root, run};
use std::io::Write as _;
use std::process::{Command, Stdio};

/// Every subcommand `biodyn --help` lists (clap's `help` aside).
fn subcommands() -> Vec<String> {
    let help = ok(&["--help"]);
    let list: Vec<String> = help
        .lines()
        .skip_while(|l| !l.starts_with("Commands:"))
        .skip(1)
        .take_while(|l| l.starts_with("  "))
        .filter_map(|l| l.split_whitespace().next())
        .filter(|name| *name != "help")
        .map(str::to_string)
        .collect();
    for name in ["response", "preset", "man", "completions"] {
        assert!(
            list.iter().any(|n| n == name),
            "{name} not in --help: {help}"
        );
    }
    list
}

/// A check left out for a missing tool says so (a failure under
/// `BIODYN_REQUIRE_TOOLS=1`, as in CI).
fn say(why: &str) {
    crate::common::skip(why);
}

/// Whether `tool` runs here (`tool --version`).
fn have(tool: &str) -> bool {
    Command::new(tool)
        .arg("--version")
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok_and(|s| s.success())
}

/// Runs `program args` with `input` on stdin: (success, stdout, stderr).
fn pipe(program: &str, args: &[&str], input: &str) -> (bool, String, String) {
    let mut child = Command::new(program)
        .args(args)
        .current_dir(root())
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the tool starts");
    let mut stdin = child.stdin.take().expect("stdin");
    let text = input.to_string();
    let writer = std::thread::spawn(move || stdin.write_all(text.as_bytes()));
    let out = child.wait_with_output().expect("the tool ends");
    writer.join().expect("writer").expect("input written");
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn the_man_page_is_roff_with_a_section_per_subcommand_and_the_flags() {
    let page = ok(&["man"]);
    assert!(
        page.starts_with(".TH biodyn 1"),
        "{}",
        &page[..80.min(page.len())]
    );
    for section in ["NAME", "SYNOPSIS", "DESCRIPTION", "OPTIONS", "VERSION"] {
        assert!(page.contains(&format!("\n.SH {section}\n")), "no {section}");
    }
    for name in subcommands() {
        let header = format!("\n.SH \"BIODYN {}\"\n", name.to_uppercase());
        assert!(page.contains(&header), "no section {header:?}");
    }
    // The nested ones: `biodyn preset list`, …
    for name in ["LIST", "SHOW", "CHECK", "SAVE"] {
        assert!(
            page.contains(&format!("\n.SH \"BIODYN PRESET {name}\"\n")),
            "preset {name}"
        );
    }
    // Flags of the top command and of subcommands (roff escapes dashes).
    for flag in [
        "--ascii",
        "--format",
        "--body-mass",
        "--signal",
        "--free",
        "--exposure",
    ] {
        assert!(page.contains(&flag.replace('-', "\\-")), "no {flag}");
    }
    // Closed sets of values are listed: the shells of `completions`.
    let shells = page
        .split("\n.SH \"BIODYN COMPLETIONS\"\n")
        .nth(1)
        .unwrap_or("");
    for shell in ["bash", "elvish", "fish", "powershell", "zsh"] {
        assert!(shells.contains(&format!("\n{shell}\n")), "no {shell}");
    }
}

#[test]
fn the_man_page_renders_without_warnings() {
    let page = ok(&["man"]);
    if have("groff") {
        // -k: preconv, for the page's UTF-8 (², ·, —); -ww -z: every warning, no output.
        let (fine, _, err) = pipe("groff", &["-k", "-man", "-Tutf8", "-ww", "-z"], &page);
        assert!(fine && err.is_empty(), "groff warns: {err}");
        let (fine, text, err) = pipe("groff", &["-k", "-man", "-Tutf8", "-P-cbou"], &page);
        assert!(fine, "{err}");
        for want in [
            "BIODYN RESPONSE",
            "BIODYN PRESET LIST",
            "--body-mass",
            "Examples:",
        ] {
            assert!(text.contains(want), "rendered page lacks {want:?}");
        }
    } else if have("man") {
        let (fine, text, err) = pipe("man", &["-l", "-"], &page);
        assert!(fine, "{err}");
        assert!(text.contains("RESPONSE"), "{text}");
    } else {
        say("neither groff nor man is installed: the man page was not rendered");
    }
}

#[test]
fn every_shells_script_names_the_subcommands() {
    let names = subcommands();
    for shell in ["bash", "zsh", "fish", "elvish", "powershell"] {
        let script = ok(&["completions", shell]);
        assert!(script.len() > 1000, "{shell}: {} bytes", script.len());
        for name in &names {
            assert!(script.contains(name.as_str()), "{shell}: no {name}");
        }
        assert!(script.contains("body-mass"), "{shell}: no --body-mass");
    }
}

#[test]
fn the_bash_script_defines_its_function_and_parses() {
    let script = ok(&["completions", "bash"]);
    assert!(script.contains("_biodyn() {"), "no completion function");
    assert!(script.contains("complete -F _biodyn"), "not registered");
    if have("bash") {
        let (fine, _, err) = pipe("bash", &["-n"], &script);
        assert!(fine, "bash -n refuses the script: {err}");
        // Sourced in a shell with no completion library, it registers itself.
        let (fine, out, err) = pipe(
            "bash",
            &["-c", "source /dev/stdin && complete -p biodyn"],
            &script,
        );
        assert!(fine && out.contains("_biodyn"), "{out}{err}");
    } else {
        say("bash is not installed: the bash script was not parsed");
    }
}

#[test]
fn a_bad_shell_is_a_usage_error() {
    let (code, out, err) = run(&["completions", "tcsh"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(out.is_empty());
    assert!(err.contains("invalid value 'tcsh'"), "{err}");
    assert!(err.contains("bash, elvish, fish, powershell, zsh"), "{err}");
}

/// `| head -1` and `> /dev/full`, as for every other command.
#[cfg(unix)]
#[test]
fn a_closed_pipe_is_quiet_and_a_full_disk_an_error() {
    let bin = env!("CARGO_BIN_EXE_biodyn");
    for args in [
        &["man"][..],
        &["completions", "bash"],
        &["completions", "zsh"],
    ] {
        let (reader, writer) = std::os::unix::net::UnixStream::pair().expect("socket pair");
        drop(reader);
        let out = Command::new(bin)
            .args(args)
            .stdout(Stdio::from(std::os::fd::OwnedFd::from(writer)))
            .stderr(Stdio::piped())
            .output()
            .expect("biodyn runs");
        assert_eq!(out.status.code(), Some(0), "{args:?}");
        assert!(
            out.stderr.is_empty(),
            "{args:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );

        let Ok(full) = std::fs::OpenOptions::new().write(true).open("/dev/full") else {
            crate::common::skip("no /dev/full on this system");
            continue;
        };
        let out = Command::new(bin)
            .args(args)
            .stdout(full)
            .stderr(Stdio::piped())
            .output()
            .expect("biodyn runs");
        assert_eq!(out.status.code(), Some(1), "{args:?}");
        let e = String::from_utf8_lossy(&out.stderr);
        assert!(
            e.starts_with("biodyn: error: cannot write to standard output"),
            "{e}"
        );
        assert_eq!(e.lines().count(), 1, "{e}");
    }
}
