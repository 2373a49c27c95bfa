//! `biodyn completions SHELL`: the shell's completion script, generated from
//! the same clap definitions as the parser (`clap_complete`), so it cannot
//! drift from the subcommands and flags.

use super::command::{Cli, CompletionsArgs};
use anyhow::{Context, Result};
use clap::CommandFactory;

/// The completion script for `args.shell`.
pub fn run(args: &CompletionsArgs) -> Result<String> {
    let mut cmd = Cli::command();
    let mut script = Vec::new();
    clap_complete::generate(args.shell, &mut cmd, "biodyn", &mut script);
    String::from_utf8(script).context("the completion script is not UTF-8")
}
