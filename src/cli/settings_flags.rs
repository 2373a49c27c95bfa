//! The `train` flags of every training setting, built from the library's
//! one description of them (`biodyn::ann::SETTINGS`): a setting added there
//! is a flag here, with its help, its range and its trainers.

use biodyn::ann::{SETTINGS, Setting, SettingKind, Settings, Trainer};
use clap::builder::PossibleValuesParser;
use clap::{Arg, ArgAction, ArgMatches, Args, Command, FromArgMatches};

/// The settings given on the command line, as typed, in table order.
#[derive(Debug, Clone, Default)]
pub struct SettingFlags {
    pub given: Vec<(&'static Setting, String)>,
}

/// Settings the command line sets another way (the grid: --from/--to/--step).
fn has_flag(s: &Setting) -> bool {
    s.kind != SettingKind::Band
}

fn arg(s: &'static Setting) -> Arg {
    let who = match s.trainers {
        [t] => format!(" [{} only]", t.key()),
        _ => String::new(),
    };
    let a = Arg::new(s.key)
        .long(s.flag)
        .help(format!("{}: {}{who}", s.help, s.range))
        .action(ArgAction::Set)
        .allow_negative_numbers(true);
    match s.kind {
        SettingKind::Real | SettingKind::OptionalReal => {
            a.value_parser(clap::value_parser!(f64)).value_name("X")
        }
        SettingKind::Whole => a.value_parser(super::args::whole).value_name("N"),
        SettingKind::Flag => a.value_parser(clap::value_parser!(bool)).value_name("BOOL"),
        SettingKind::Layers => a.value_name("N-N-..."),
        SettingKind::Values => a
            .value_parser(clap::value_parser!(f64))
            .value_delimiter(',')
            .action(ArgAction::Append)
            .value_name("X,X,..."),
        SettingKind::Choice(words) => a
            .value_parser(PossibleValuesParser::new(words.iter().copied()))
            .value_name("WORD"),
        SettingKind::Band => a,
    }
}

impl Args for SettingFlags {
    fn augment_args(cmd: Command) -> Command {
        SETTINGS
            .iter()
            .filter(|s| has_flag(s))
            .fold(cmd, |c, s| c.arg(arg(s)))
    }

    fn augment_args_for_update(cmd: Command) -> Command {
        Self::augment_args(cmd)
    }
}

impl FromArgMatches for SettingFlags {
    fn from_arg_matches(m: &ArgMatches) -> Result<Self, clap::Error> {
        let mut given = Vec::new();
        for s in SETTINGS.iter().filter(|s| has_flag(s)) {
            if let Some(raw) = m.get_raw(s.key) {
                let parts: Vec<String> = raw.map(|v| v.to_string_lossy().into_owned()).collect();
                given.push((s, parts.join(",")));
            }
        }
        Ok(SettingFlags { given })
    }

    fn update_from_arg_matches(&mut self, m: &ArgMatches) -> Result<(), clap::Error> {
        *self = Self::from_arg_matches(m)?;
        Ok(())
    }
}

impl SettingFlags {
    /// Applies every given flag to `s`; the whole set is checked later.
    pub fn apply(&self, s: &mut Settings) -> anyhow::Result<()> {
        for (setting, text) in &self.given {
            setting
                .set(s, text)
                .map_err(|e| anyhow::anyhow!("--{}: {e}", setting.flag))?;
        }
        Ok(())
    }

    /// The flags given that `trainer` ignores.
    pub fn ignored_by(&self, trainer: Trainer) -> Vec<&'static str> {
        self.given
            .iter()
            .filter(|(s, _)| !s.applies_to(trainer))
            .map(|(s, _)| s.flag)
            .collect()
    }
}
