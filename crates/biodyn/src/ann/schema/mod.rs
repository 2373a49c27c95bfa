//! Every training setting described once: its name, help, how its text is
//! read and shown, its valid range, and which trainers use it. The command
//! line builds its `train` flags from this table, the TUI its settings rows,
//! and `Settings::validate` checks a whole set with it.
//!
//! ```
//! use biodyn::ann::{Settings, Trainer, Case, SETTINGS};
//! let mut s = Settings::lm(Case::K4Stht);
//! s.set("weight_decay", "1e-5").unwrap();
//! let rows: Vec<_> = SETTINGS.iter().filter(|x| x.applies_to(Trainer::Lm)).collect();
//! assert!(rows.iter().any(|x| x.key == "ensemble"));
//! assert!(!rows.iter().any(|x| x.key == "learning_rate"));
//! assert_eq!(s.get("weight_decay").unwrap(), "1e-5");
//! ```

mod setting;
mod table;

pub use setting::{Setting, SettingKind};
pub use table::SETTINGS;

use super::case::Case;
use super::error::AnnError;
use super::settings::Settings;
use crate::io::excerpt::short_quote;

impl Setting {
    /// The setting named `name`: its key, flag or label.
    pub fn find(name: &str) -> Option<&'static Setting> {
        let n = name.trim();
        SETTINGS
            .iter()
            .find(|s| s.key == n || s.flag == n || s.label == n)
    }
}

impl Settings {
    /// Checks the base body, then every setting against the case, then
    /// that the sizes fit (`bounds`); the first problem is returned.
    pub fn validate(&self, case: Case) -> Result<(), AnnError> {
        case.check_base(self.base.as_ref())?;
        SETTINGS.iter().try_for_each(|s| s.check(self, case))?;
        super::bounds::check(self, case)
    }

    /// The setting named `name` (key, flag or label) as text.
    pub fn get(&self, name: &str) -> Result<String, AnnError> {
        Ok(lookup(name)?.get(self))
    }

    /// Reads `text` into the setting named `name`. The value is not
    /// range-checked: call `validate` on the whole set.
    pub fn set(&mut self, name: &str, text: &str) -> Result<(), AnnError> {
        lookup(name)?.set(self, text)
    }
}

fn lookup(name: &str) -> Result<&'static Setting, AnnError> {
    Setting::find(name).ok_or_else(|| AnnError::UnknownSetting(short_quote(name)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ann::settings::Trainer;

    /// Every setting's text reads back to the same value, for both trainers' defaults.
    #[test]
    fn get_then_set_round_trips() {
        for case in Case::ALL {
            for kind in Trainer::ALL {
                let base = Settings::for_trainer(case, kind);
                for s in &SETTINGS {
                    let mut t = base.clone();
                    s.set(&mut t, &s.get(&base)).unwrap();
                    assert_eq!(t, base, "{}", s.key);
                }
            }
        }
    }

    /// Extreme values are shown short (a TUI column is ~20 wide; a plain
    /// 1e30 has 31 digits) and still read back to the same bits.
    #[test]
    fn extreme_values_are_short_and_still_round_trip() {
        let mut base = Settings::paper(Case::K4Apms);
        base.learning_rate = 1e30;
        base.momentum = 1e-320;
        base.gain = 1e300;
        base.init_range = 0.1 + 0.2;
        base.rms_target = Some(1e-300);
        base.train_values = vec![54_000.0, 90_000.0, 1.26e5, 1e-7];
        base.grid = crate::band::Band {
            from: 1e-6,
            to: 2e6,
            step: 0.125,
        };
        for (key, want) in [
            ("learning_rate", "1e30"),
            ("momentum", "1e-320"),
            ("gain", "1e300"),
            ("rms_target", "1e-300"),
            ("train_values", "54000,9e4,126000,1e-7"),
            ("grid", "1e-6:2e6:0.125"),
        ] {
            assert_eq!(base.get(key).unwrap(), want, "{key}");
        }
        for s in &SETTINGS {
            let mut t = Settings::paper(Case::MassStht);
            t.layers = base.layers.clone();
            s.set(&mut t, &s.get(&base)).unwrap();
            assert_eq!(s.get(&t), s.get(&base), "{}", s.key);
        }
        let mut t = base.clone();
        for s in &SETTINGS {
            s.set(&mut t, &s.get(&base)).unwrap();
        }
        assert_eq!(t, base);
        assert_eq!(t.init_range.to_bits(), (0.1f64 + 0.2).to_bits());
    }

    #[test]
    fn names_are_unique_and_found_by_key_flag_and_label() {
        for (i, a) in SETTINGS.iter().enumerate() {
            for b in &SETTINGS[i + 1..] {
                assert!(a.key != b.key && a.flag != b.flag && a.label != b.label);
            }
            for n in [a.key, a.flag, a.label] {
                assert_eq!(Setting::find(n).map(|s| s.key), Some(a.key));
            }
        }
    }

    #[test]
    fn lm_lists_its_own_options_and_not_the_backprop_ones() {
        let lm: Vec<&str> = SETTINGS
            .iter()
            .filter(|s| s.applies_to(Trainer::Lm))
            .map(|s| s.key)
            .collect();
        for k in ["ensemble", "log_target", "weight_decay"] {
            assert!(lm.contains(&k), "{k}");
        }
        for k in ["learning_rate", "momentum", "input_noise"] {
            assert!(!lm.contains(&k), "{k}");
        }
        assert!(
            !SETTINGS
                .iter()
                .any(|s| s.key == "weight_decay" && s.applies_to(Trainer::Backprop))
        );
    }

    #[test]
    fn a_number_that_is_not_a_whole_one_says_why() {
        let mut s = Settings::paper(Case::K4Stht);
        let e = s.set("epochs", "1e30").unwrap_err().to_string();
        assert!(e.contains("written in digits"), "{e}");
        let e = s.set("epochs", "2.5").unwrap_err().to_string();
        assert!(e.contains("no fraction"), "{e}");
        let e = s.set("epochs", "many").unwrap_err().to_string();
        assert!(e.contains("whole number ≥ 0"), "{e}");
    }

    #[test]
    fn bad_text_names_the_setting_and_quotes_a_short_excerpt() {
        let mut s = Settings::paper(Case::K4Stht);
        let e = s.set("lr", "fast").unwrap_err().to_string();
        assert_eq!(e, "learning rate: 'fast' is not a number");
        let long = "x".repeat(10_000);
        let e = s.set("momentum", &long).unwrap_err().to_string();
        assert!(e.len() < 120, "{e}");
        assert!(
            s.set("layers", "5--1").is_err(),
            "an empty layer is refused"
        );
        assert!(s.set("no-such", "1").is_err());
        s.set("epochs", "7").unwrap();
        assert_eq!(s.epochs, 7);
        s.set("RMS target", "none").unwrap();
        assert_eq!(s.rms_target, None);
    }

    #[test]
    fn validate_reports_the_first_bad_setting_in_table_order() {
        let c = Case::K4Stht;
        let mut s = Settings::paper(c);
        s.momentum = 1.0;
        s.ensemble = 0;
        assert!(matches!(s.validate(c), Err(AnnError::BadMomentum(m)) if m == 1.0));
        s.momentum = 0.5;
        assert!(matches!(s.validate(c), Err(AnnError::ZeroEnsemble)));
    }
}
