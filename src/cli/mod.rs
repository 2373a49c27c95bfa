//! Command-line front end (minimal here: train and predict).

use clap::{Parser, Subcommand};
use std::process::ExitCode;

pub mod predict;
pub mod train;

#[derive(Parser, Debug)]
#[command(name = "biodyn", version, about)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Subcommand, Debug)]
#[allow(clippy::large_enum_variant)] // parsed once; boxing buys nothing
pub enum Command {
    /// Train the paper's networks and report them beside Table 5.
    Train(train::TrainArgs),
    /// Predict a response with a trained network beside the analytic one.
    Predict(predict::PredictArgs),
}

pub fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match &cli.command {
        Command::Train(a) => train::run(a),
        Command::Predict(a) => predict::run(a),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::FAILURE
        }
    }
}
