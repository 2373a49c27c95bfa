//! `biodyn man`: the roff man page, generated from the same clap definitions
//! as the parser (`clap_mangen`), so it cannot drift from the flags.
//!
//! One page for the whole command: the top command's sections, then one
//! section per subcommand (`BIODYN RESPONSE`, `BIODYN PRESET LIST`, …) with
//! its description, synopsis, options and examples as subsections. One page
//! installs as one file (`biodyn man > biodyn.1`) and `man biodyn` then
//! finds every flag; clap_mangen's one-page-per-subcommand layout would need
//! a folder of files.

use super::command::{Cli, ManArgs};
use anyhow::{Context, Result};
use clap::CommandFactory;
use clap_mangen::Man;

/// The whole man page as roff text.
pub fn run(_: &ManArgs) -> Result<String> {
    let mut cmd = Cli::command();
    cmd.build();
    let top = Man::new(cmd.clone());
    let mut page = Vec::new();
    top.render_title(&mut page)?;
    top.render_name_section(&mut page)?;
    top.render_synopsis_section(&mut page)?;
    top.render_description_section(&mut page)?;
    top.render_options_section(&mut page)?;
    for sub in visible(&cmd) {
        subcommand(&mut page, sub)?;
    }
    if cmd.get_after_help().is_some() {
        top.render_extra_section(&mut page)?;
    }
    top.render_version_section(&mut page)?;
    let page = String::from_utf8(page).context("the man page is not UTF-8")?;
    Ok(one_preamble(&page))
}

/// The roff writer starts every rendered part with the two lines that
/// define `\*(Aq` (an apostrophe for groff and others); keep one pair,
/// right after `.TH`, so the page opens with its title as man pages do.
fn one_preamble(page: &str) -> String {
    const AQ: [&str; 2] = [".ie \\n(.g .ds Aq \\(aq", ".el .ds Aq '"];
    let mut out = String::with_capacity(page.len());
    for line in page.lines().filter(|l| !AQ.contains(l)) {
        out.push_str(line);
        out.push('\n');
        if line.starts_with(".TH ") {
            for aq in AQ {
                out.push_str(aq);
                out.push('\n');
            }
        }
    }
    out
}

/// The subcommands a reader can run (clap's own `help` is left out).
fn visible(cmd: &clap::Command) -> impl Iterator<Item = &clap::Command> {
    cmd.get_subcommands()
        .filter(|s| !s.is_hide_set() && s.get_name() != "help")
}

/// One subcommand's section, then its own subcommands' (`preset list`, …).
fn subcommand(page: &mut Vec<u8>, cmd: &clap::Command) -> Result<()> {
    let name = cmd.get_bin_name().unwrap_or(cmd.get_name()).to_uppercase();
    page.extend_from_slice(format!(".SH \"{name}\"\n").as_bytes());
    let man = Man::new(cmd.clone());
    let mut body = Vec::new();
    man.render_description_section(&mut body)?;
    man.render_synopsis_section(&mut body)?;
    if cmd.get_arguments().any(|a| !a.is_hide_set()) {
        man.render_options_section(&mut body)?;
    }
    if cmd.get_after_help().is_some() {
        man.render_extra_section(&mut body)?;
    }
    page.extend_from_slice(demote(&String::from_utf8_lossy(&body)).as_bytes());
    for sub in visible(cmd) {
        subcommand(page, sub)?;
    }
    Ok(())
}

/// A subcommand's sections become subsections of its own section: `.SH X`
/// control lines turn into `.SS X` (text lines starting with a dot are
/// escaped by the roff writer, so only control lines match).
fn demote(roff: &str) -> String {
    roff.lines()
        .map(|l| match l.strip_prefix(".SH ") {
            Some(rest) => format!(".SS {rest}\n"),
            None => format!("{l}\n"),
        })
        .collect()
}
