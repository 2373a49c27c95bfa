//! Seat-acceleration signals and their text grammar:
//! `sine:freq=HZ,amp=M_S2[,phase=DEG]`, `sweep:from=HZ,to=HZ,amp=M_S2`,
//! `random:rms=M_S2,band=LO-HI,seed=N`, `shock:peak=M_S2,width=S,at=S`,
//! `class:NAME,seed=N` (an input spectral class: EM1–EM9, IT1–IT4,
//! AG1–AG3), joined with `+` to add them.

use crate::io::excerpt::{num, quote};
use std::fmt;

mod parse;

/// Lowest band edge of `random`, Hz: a 1000 s period, far below whole-body
/// vibration (0.5–80 Hz); much lower edges overflow the Butterworth design.
pub const MIN_BAND_HZ: f64 = 1e-3;

/// One part of a signal.
#[derive(Debug, Clone, PartialEq)]
pub enum Component {
    /// amp · sin(2π f t + phase).
    Sine { freq: f64, amp: f64, phase_deg: f64 },
    /// Logarithmic (exponential) sweep from `from` to `to` Hz over the record.
    Sweep { from: f64, to: f64, amp: f64 },
    /// Gaussian noise band-limited to [lo, hi] Hz, scaled to exactly `rms`.
    Random {
        rms: f64,
        lo: f64,
        hi: f64,
        seed: u64,
    },
    /// A half-sine pulse of `peak` m/s² lasting `width` s, starting at `at` s.
    Shock { peak: f64, width: f64, at: f64 },
    /// Gaussian noise whose PSD is an input spectral class's (`time::class`):
    /// the floor vibration of a seat test.
    Class {
        class: &'static crate::time::class::InputClass,
        seed: u64,
    },
}

/// A sum of components.
#[derive(Debug, Clone, PartialEq)]
pub struct Signal {
    pub parts: Vec<Component>,
}

/// What is wrong with a signal spec; `part` is the text of the offending part.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SignalError {
    #[error("signal spec is empty: e.g. sine:freq=5,amp=5")]
    Empty,
    #[error("signal part '{}': expected KIND:KEY=VALUE,..., e.g. sine:freq=5,amp=5", quote(.part))]
    NoKind { part: String },
    #[error("signal part '{}': unknown kind '{}'; kinds are sine, sweep, random, shock, class", quote(.part), quote(.kind))]
    UnknownKind { part: String, kind: String },
    #[error("signal part '{}': '{}' is not KEY=VALUE", quote(.part), quote(.item))]
    NotKeyValue { part: String, item: String },
    #[error("signal part '{}': unknown key '{}'; {kind} takes {keys}", quote(.part), quote(.key))]
    UnknownKey {
        part: String,
        kind: &'static str,
        key: String,
        keys: &'static str,
    },
    #[error("signal part '{}': key '{}' is given twice", quote(.part), quote(.key))]
    Duplicate { part: String, key: String },
    #[error("signal part '{}': missing key '{key}'; {kind} takes {keys}", quote(.part))]
    Missing {
        part: String,
        kind: &'static str,
        key: &'static str,
        keys: &'static str,
    },
    #[error("signal part '{}': {}='{}' is not a number", quote(.part), quote(.key), quote(.value))]
    NotNumber {
        part: String,
        key: String,
        value: String,
    },
    #[error("signal part '{}': {key}={} {why}", quote(.part), quote(.value))]
    Bad {
        part: String,
        key: &'static str,
        value: String,
        why: String,
    },
}

impl Signal {
    /// Checks every part against the sampling rate and the duration: each
    /// frequency below fs/2, a shock inside the record and at least two samples wide.
    pub fn check(&self, fs: f64, duration: f64) -> Result<(), SignalError> {
        let nyq = fs / 2.0;
        for c in &self.parts {
            let part = c.to_string();
            let bad = |key: &'static str, value: f64, why: String| SignalError::Bad {
                part: part.clone(),
                key,
                value: num(value),
                why,
            };
            match *c {
                Component::Sine { freq, .. } if freq >= nyq => {
                    return Err(bad("freq", freq, above(nyq, fs)));
                }
                Component::Sweep { from, to, .. } => {
                    for (key, v) in [("from", from), ("to", to)] {
                        if v >= nyq {
                            return Err(bad(key, v, above(nyq, fs)));
                        }
                    }
                }
                Component::Class { class, .. } if fs < crate::time::class::CLASS_MIN_FS => {
                    return Err(SignalError::Bad {
                        part: part.clone(),
                        key: "class",
                        value: class.name.to_string(),
                        why: format!(
                            "needs a sampling rate of at least {} Hz (now {}): raise the rate",
                            num(crate::time::class::CLASS_MIN_FS),
                            num(fs)
                        ),
                    });
                }
                Component::Random { hi, .. } if hi >= nyq => {
                    let s = SignalError::Bad {
                        part: part.clone(),
                        key: "band",
                        value: format!("..-{}", num(hi)),
                        why: above(nyq, fs),
                    };
                    return Err(s);
                }
                Component::Shock { width, at, .. } => {
                    if width * fs < 2.0 {
                        return Err(bad(
                            "width",
                            width,
                            format!(
                                "s is under two samples at {} Hz: make it at least {} s",
                                num(fs),
                                num(2.0 / fs)
                            ),
                        ));
                    }
                    if at >= duration {
                        return Err(bad(
                            "at",
                            at,
                            format!("s is past the end of the {} s record", num(duration)),
                        ));
                    }
                    // A shock cut by the record's end would vanish or shrink
                    // without a word: the whole shock is in the record, or
                    // it is refused.
                    if width > duration {
                        return Err(bad(
                            "width",
                            width,
                            format!(
                                "s is longer than the {} s record: make the shock narrower or the record longer",
                                num(duration)
                            ),
                        ));
                    }
                    if at + width > duration * (1.0 + 1e-12) {
                        return Err(bad(
                            "width",
                            width,
                            format!(
                                "s from at={} s ends at {} s, past the end of the {} s record: start it by {} s or make the record longer",
                                num(at),
                                num(at + width),
                                num(duration),
                                num(duration - width)
                            ),
                        ));
                    }
                }
                _ => {}
            }
        }
        Ok(())
    }
}

fn above(nyq: f64, fs: f64) -> String {
    format!(
        "Hz is at or above fs/2 = {} Hz: raise the sampling rate (now {}) or lower the frequency",
        num(nyq),
        num(fs)
    )
}

impl fmt::Display for Component {
    /// Numbers in short form ([`num`]): exact, and `1e308` not 309 digits.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Component::Sine {
                freq,
                amp,
                phase_deg,
            } => {
                write!(f, "sine:freq={},amp={}", num(freq), num(amp))?;
                if phase_deg != 0.0 {
                    write!(f, ",phase={}", num(phase_deg))?;
                }
                Ok(())
            }
            Component::Sweep { from, to, amp } => write!(
                f,
                "sweep:from={},to={},amp={}",
                num(from),
                num(to),
                num(amp)
            ),
            Component::Random { rms, lo, hi, seed } => write!(
                f,
                "random:rms={},band={}-{},seed={seed}",
                num(rms),
                num(lo),
                num(hi)
            ),
            Component::Shock { peak, width, at } => write!(
                f,
                "shock:peak={},width={},at={}",
                num(peak),
                num(width),
                num(at)
            ),
            Component::Class { class, seed } => write!(f, "class:{},seed={seed}", class.name),
        }
    }
}

impl fmt::Display for Signal {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, p) in self.parts.iter().enumerate() {
            if i > 0 {
                f.write_str("+")?;
            }
            write!(f, "{p}")?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_issue_example_parses_and_prints_back() {
        let s = "random:rms=0.8,band=1-20,seed=1+shock:peak=15,width=0.1,at=30";
        let sig = Signal::parse(s).unwrap();
        assert_eq!(sig.parts.len(), 2);
        assert_eq!(sig.to_string(), s);
        let sig = Signal::parse("sine:freq=5,amp=1e+0,phase=-90").unwrap();
        assert_eq!(
            sig.parts[0],
            Component::Sine {
                freq: 5.0,
                amp: 1.0,
                phase_deg: -90.0
            }
        );
    }

    /// Issue 19 item 10: a shock is wholly inside the record or refused,
    /// never cut or lost without a word; one ending at the last instant is
    /// taken.
    #[test]
    fn a_shock_past_the_record_is_refused() {
        let check = |spec: &str, fs: f64, d: f64| Signal::parse(spec).unwrap().check(fs, d);
        let e = check("shock:peak=15,width=0.5,at=9.8", 1000.0, 10.0)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("ends at 10.3 s, past the end of the 10 s record: start it by 9.5 s"),
            "{e}"
        );
        let e = check("shock:peak=15,width=20,at=0", 1000.0, 10.0)
            .unwrap_err()
            .to_string();
        assert!(e.contains("longer than the 10 s record"), "{e}");
        let e = check("shock:peak=15,width=0.1,at=9.9999", 100.0, 10.0).unwrap_err();
        assert!(matches!(e, SignalError::Bad { key: "width", .. }), "{e}");
        assert!(check("shock:peak=15,width=0.1,at=9.9", 1000.0, 10.0).is_ok());
        assert!(
            check(
                "random:rms=1,band=1-20,seed=1+shock:peak=15,width=0.1,at=5",
                1000.0,
                10.0
            )
            .is_ok()
        );
    }

    #[test]
    fn errors_name_the_part() {
        let e = Signal::parse("sine:freq=5,amp=5+sine:freq=x,amp=1").unwrap_err();
        assert!(e.to_string().contains("'sine:freq=x,amp=1'"), "{e}");
        assert!(matches!(
            Signal::parse("saw:freq=1"),
            Err(SignalError::UnknownKind { .. })
        ));
        assert!(matches!(
            Signal::parse("sine:freq=5"),
            Err(SignalError::Missing { key: "amp", .. })
        ));
        assert!(matches!(
            Signal::parse("sine"),
            Err(SignalError::NoKind { .. })
        ));
        assert!(matches!(
            Signal::parse("random:rms=1,band=-1-20,seed=1"),
            Err(SignalError::Bad { key: "band", .. })
        ));
        assert!(matches!(
            Signal::parse("random:rms=1,band=20-1,seed=1"),
            Err(SignalError::Bad { key: "band", .. })
        ));
        assert!(matches!(
            Signal::parse("shock:peak=1,width=0,at=1"),
            Err(SignalError::Bad { key: "width", .. })
        ));
        let s = Signal::parse("random:rms=1,band=1-600,seed=1").unwrap();
        // Regression (fuzz): tiny band edges, huge amplitudes, long or
        // hostile parts are refused in one short, printable line.
        for spec in [
            "random:rms=0.01,band=1e-300-1e-299,seed=0",
            "sine:freq=1,amp=1e308",
            "sweep:from=1,to=2,amp=2e4",
            "random:rms=1e5,band=1-20,seed=0",
            "shock:peak=-1e308,width=1,at=0",
        ] {
            let e = Signal::parse(spec).unwrap_err().to_string();
            assert!(e.contains("cap") || e.contains("LO must be"), "{e}");
            assert!(e.len() < 300, "{e}");
        }
        let hostile = format!("sine:freq=\u{1b}[31m{}\u{7},amp=1", "9".repeat(100_000));
        let e = Signal::parse(&hostile).unwrap_err().to_string();
        assert!(e.len() < 300 && !e.chars().any(char::is_control), "{e}");
        // Below the 0.001 Hz floor a frequency is refused, in short form.
        let e = Signal::parse("sine:freq=1e-300,amp=1")
            .unwrap_err()
            .to_string();
        assert!(e.contains("1e-300 Hz is below 0.001 Hz"), "{e}");
        assert!(!e.contains("00000000"), "{e}");
        let e = Signal::parse("sine:freq=0.001,amp=1")
            .unwrap()
            .check(1.0, 1e-300);
        assert!(!format!("{e:?}").contains("00000000"), "{e:?}");
        assert_eq!(
            Signal::parse("sine:freq=0.001,amp=1e4")
                .unwrap()
                .to_string(),
            "sine:freq=1e-3,amp=1e4"
        );
        assert!(
            s.check(1000.0, 10.0)
                .unwrap_err()
                .to_string()
                .contains("fs/2")
        );
    }
}
