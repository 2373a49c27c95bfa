//! `biodyn completions SHELL`: the shell's completion script, generated from
//! the same clap definitions as the parser (`clap_complete`), so it cannot
//! drift from the subcommands and flags.

use super::Cli;
use anyhow::{Context, Result};
use clap::CommandFactory;
use clap_complete::Shell;

#[derive(Debug, clap::Args)]
#[command(
    after_help = "Examples:\n  biodyn completions bash > ~/.local/share/bash-completion/completions/biodyn\n  biodyn completions zsh > ~/.zfunc/_biodyn\n  biodyn completions fish > ~/.config/fish/completions/biodyn.fish"
)]
pub struct CompletionsArgs {
    /// The shell to write the script for.
    #[arg(value_enum)]
    pub shell: Shell,
}

/// The completion script for `args.shell`.
pub fn run(args: &CompletionsArgs) -> Result<String> {
    let mut cmd = Cli::command();
    let mut script = Vec::new();
    clap_complete::generate(args.shell, &mut cmd, "biodyn", &mut script);
    String::from_utf8(script).context("the completion script is not UTF-8")
}
