//! The clap definition of the command line: the top command, its
//! subcommands and the terminal app's flags, with the args of `man` and
//! `completions`, which render this definition. Its own file, so `man.rs`
//! and `completions.rs` take it from a sibling, not from the `mod.rs` that
//! uses them; `mod.rs` re-exports it, so `cli::Cli` stays.

use clap::{Parser, Subcommand};
use clap_complete::Shell;

#[derive(Debug, Parser)]
#[command(
    name = "biodyn",
    version,
    about = "Biodynamics of the seated human body under vertical whole-body vibration",
    long_about = "Biodynamics of the seated human body under vertical whole-body vibration.\n\nWith no command, opens the full-screen terminal app on the built-in paper-75kg model.",
    after_help = "Examples:\n  biodyn                               the terminal app\n  biodyn response --format csv         STHT, DPMI, APMS over 0.5-20 Hz\n  biodyn study k4 -40%,0%,+40%         the paper's pelvic-stiffness study\n  biodyn plot stht --study mass=65,75,85\n  biodyn modes --preset boileau-rakheja-1998\n  biodyn assess --signal random:rms=0.8,band=1-20,seed=1 --duration 60\n                                       ISO 2631-1 and EU verdict, seat and head\n  biodyn simulate --input seat.csv --format csv > run.csv\n  biodyn fit --data apms.csv --free k4,c4,body-mass\n  biodyn train --case mass-apms --save net.json"
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,
    /// With no command: the terminal app's options (as `biodyn tui`).
    #[command(flatten)]
    pub tui: TuiArgs,
    /// No progress line, no "saved …" notes and no closing summary on
    /// stderr (warnings and errors still show). Anywhere on the line.
    #[arg(long, short = 'q', global = true)]
    pub quiet: bool,
}

#[derive(Debug, Subcommand)]
#[allow(clippy::large_enum_variant)] // parsed once; boxing buys nothing
pub enum Command {
    /// Open the full-screen terminal app (also the default with no command).
    Tui(TuiArgs),
    /// STHT, DPMI and APMS (magnitude and phase) over a frequency band.
    Response(super::response::ResponseArgs),
    /// Natural and damped frequencies, damping ratios and shapes of the modes.
    Modes(super::modes::ModesArgs),
    /// Resonance peaks of each function, refined off the grid.
    Peaks(super::modes::PeaksArgs),
    /// Vary one parameter (body mass, k4, c4, any m/k/c) and compare.
    Study(super::study::StudyArgs),
    /// Draw a response chart as text (like the TUI's), for SSH and pipes.
    Plot(super::plot::PlotArgs),
    /// Train the paper's networks and report them beside its Table 5.
    Train(super::train::TrainArgs),
    /// Predict a response with a trained network beside the analytic one.
    Predict(super::predict::PredictArgs),
    /// Fit free parameters of a model to measured APMS, DPMI or STHT.
    Fit(super::fit::FitArgs),
    /// The body under a seat-acceleration record (signal or CSV): every output, every sample.
    Simulate(super::simulate::SimulateArgs),
    /// ISO 2631-1 and EU 2002/44/EC assessment of a seat record on 1–3 axes, and of the head.
    Assess(super::assess::AssessArgs),
    /// A seat's SEAT %, pan a_w and r.m.s. stroke under a floor PSD; a suspension's design.
    Seat(super::seat::SeatArgs),
    /// A working day's exposure from a day file (HSE calculator, EU verdicts).
    Day(super::day::DayArgs),
    /// A frequency weighting of ISO 8041-1 (Wb … Wm): its definition and response.
    Weighting(super::weighting::WeightingArgs),
    /// List, show, check or save presets.
    #[command(
        subcommand,
        after_help = "Examples:\n  biodyn preset list\n  biodyn preset show paper-75kg > mine.toml\n  biodyn preset check mine.toml"
    )]
    Preset(super::preset::PresetCommand),
    /// Print the man page (roff), generated from these definitions.
    Man(ManArgs),
    /// Print a shell's completion script (bash, zsh, fish, elvish, powershell).
    Completions(CompletionsArgs),
}

impl Cli {
    /// The app's options given before a command: `--preset` goes to a
    /// command that takes a model (`biodyn --preset mine.toml response`),
    /// any of them to `tui`; elsewhere, or given twice, it is an error.
    /// `name` is the subcommand as typed (for the messages).
    pub fn hoist(mut self, name: &str) -> Result<Cli, String> {
        let Some(command) = self.command.as_mut() else {
            return Ok(self);
        };
        let top = std::mem::take(&mut self.tui);
        if let Command::Tui(t) = command {
            let twice = (top.preset.is_some() && t.preset.is_some())
                || (top.day.is_some() && t.day.is_some());
            if twice {
                return Err("an option is given both before and after `tui`: give it once".into());
            }
            t.preset = t.preset.take().or(top.preset);
            t.day = t.day.take().or(top.day);
            t.ascii |= top.ascii;
            return Ok(self);
        }
        if top.day.is_some() || top.ascii {
            let flag = if top.ascii { "--ascii" } else { "--day" };
            return Err(format!(
                "{flag} is the terminal app's option, not `{name}`'s: `biodyn tui {flag} …`"
            ));
        }
        if let Some(p) = top.preset {
            match command.model_mut() {
                Some(m) if m.preset.is_none() => m.preset = Some(p),
                Some(_) => {
                    return Err(format!(
                        "--preset is given both before and after `{name}`: give it once"
                    ));
                }
                None => {
                    return Err(format!(
                        "`{name}` takes no --preset (it reads no body model)"
                    ));
                }
            }
        }
        Ok(self)
    }
}

impl Command {
    /// The model options of a command that reads a body model.
    pub fn model_mut(&mut self) -> Option<&mut super::args::ModelArgs> {
        match self {
            Command::Response(a) => Some(&mut a.model),
            Command::Modes(a) => Some(&mut a.model),
            Command::Peaks(a) => Some(&mut a.model),
            Command::Study(a) => Some(&mut a.model),
            Command::Plot(a) => Some(&mut a.model),
            Command::Train(a) => Some(&mut a.model),
            Command::Predict(a) => Some(&mut a.model),
            Command::Fit(a) => Some(&mut a.model),
            Command::Simulate(a) => Some(&mut a.model),
            Command::Assess(a) => Some(&mut a.model),
            Command::Seat(a) => Some(&mut a.model),
            Command::Preset(super::preset::PresetCommand::Save { model, .. }) => Some(model),
            _ => None,
        }
    }
}

#[derive(Debug, Clone, Default, clap::Args)]
#[command(
    after_help = "Examples:\n  biodyn tui\n  biodyn tui --preset presets/paper-85kg.toml --ascii\n  biodyn tui --day examples/day.toml"
)]
pub struct TuiArgs {
    /// Preset file (or built-in name) to open.
    #[arg(long)]
    pub preset: Option<String>,
    /// Day file (TOML) to open on the Day tab (6).
    #[arg(long, value_name = "DAY.toml")]
    pub day: Option<std::path::PathBuf>,
    /// ASCII chart markers and borders, for fonts without braille.
    #[arg(long)]
    pub ascii: bool,
}

#[derive(Debug, clap::Args)]
#[command(
    after_help = "Examples:\n  biodyn man | man -l -\n  biodyn man > ~/.local/share/man/man1/biodyn.1"
)]
pub struct ManArgs {}

#[derive(Debug, clap::Args)]
#[command(
    after_help = "Examples:\n  biodyn completions bash > ~/.local/share/bash-completion/completions/biodyn\n  biodyn completions zsh > ~/.zfunc/_biodyn\n  biodyn completions fish > ~/.config/fish/completions/biodyn.fish"
)]
pub struct CompletionsArgs {
    /// The shell to write the script for.
    #[arg(value_enum)]
    pub shell: Shell,
}
