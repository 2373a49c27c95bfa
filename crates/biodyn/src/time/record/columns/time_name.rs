//! A time column and its unit, from its name. The unit is never assumed
//! where the name could mean another: `t`, `time`, `sec` are seconds
//! (SI's, and what a bare `time` means in every logger's export we know);
//! a unit in the name (`t_ms`, `Time [ms]`, `time (us)`) sets it; a unit the
//! reader does not know is refused. A clock read in the wrong unit is also
//! caught after the fact: its rate cannot carry the weighting's band.

use crate::time::bracketed;

/// A time unit: its name as printed and seconds per unit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TimeUnit {
    pub name: &'static str,
    pub seconds: f64,
}

pub const SECOND: TimeUnit = TimeUnit {
    name: "s",
    seconds: 1.0,
};
const MILLISECOND: TimeUnit = TimeUnit {
    name: "ms",
    seconds: 1e-3,
};
const MICROSECOND: TimeUnit = TimeUnit {
    name: "µs",
    seconds: 1e-6,
};

/// Names of a time unit (lower case), as a suffix, in brackets or alone.
/// (`µs` is the micro sign U+00B5, `μs` the Greek mu U+03BC: both are written.)
const UNITS: [(&str, TimeUnit); 13] = [
    ("s", SECOND),
    ("sec", SECOND),
    ("secs", SECOND),
    ("seconds", SECOND),
    ("ms", MILLISECOND),
    ("msec", MILLISECOND),
    ("millis", MILLISECOND),
    ("milliseconds", MILLISECOND),
    ("us", MICROSECOND),
    ("µs", MICROSECOND),
    ("μs", MICROSECOND),
    ("usec", MICROSECOND),
    ("microseconds", MICROSECOND),
];

/// Names of a time column before its unit (lower case).
const TIME_WORDS: [&str; 3] = ["t", "time", "zeit"];

fn unit_named(s: &str) -> Option<TimeUnit> {
    let l = s.trim().to_lowercase();
    UNITS.iter().find(|(n, _)| *n == l).map(|&(_, u)| u)
}

/// What a header says of time.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TimeName<'a> {
    /// Not a time column's name.
    No,
    /// A time column in this unit.
    Unit(TimeUnit),
    /// A time column's name with a unit this reader does not know.
    Unknown(&'a str),
}

/// Reads `header` as a time column's name: `t`, `time`, `t_s`, `time_ms`,
/// `Time [s]`, `Time (ms)`, `t in us`, `sec`, `ms` …
pub fn time_name(header: &str) -> TimeName<'_> {
    let h = header.trim();
    if let Some((base, unit)) = bracketed(h) {
        if !TIME_WORDS.contains(&base.to_lowercase().as_str()) {
            return TimeName::No;
        }
        return unit_named(unit).map_or(TimeName::Unknown(unit), TimeName::Unit);
    }
    let lower = h.to_lowercase();
    if TIME_WORDS.contains(&lower.as_str()) {
        return TimeName::Unit(SECOND);
    }
    if let Some(u) = unit_named(&lower) {
        return TimeName::Unit(u);
    }
    match lower.split_once('_') {
        Some((base, unit)) if TIME_WORDS.contains(&base) => {
            let at = h.len() - unit.len();
            unit_named(unit).map_or(TimeName::Unknown(&h[at..]), TimeName::Unit)
        }
        _ => TimeName::No,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn time_units_are_read_from_the_name() {
        for (h, unit) in [
            ("t", SECOND),
            ("Time", SECOND),
            ("t_s", SECOND),
            ("time_s", SECOND),
            ("sec", SECOND),
            ("time_ms", MILLISECOND),
            ("t_ms", MILLISECOND),
            ("Time [ms]", MILLISECOND),
            ("Time (ms)", MILLISECOND),
            ("time [s]", SECOND),
            ("t_us", MICROSECOND),
            ("Time [µs]", MICROSECOND),
            ("t [μs]", MICROSECOND),
            ("ms", MILLISECOND),
        ] {
            assert_eq!(time_name(h), TimeName::Unit(unit), "{h}");
        }
        assert_eq!(time_name("Time [min]"), TimeName::Unknown("min"));
        assert_eq!(time_name("time_h"), TimeName::Unknown("h"));
        for h in ["az", "Acc Z [g]", "speed", "0.000", "times"] {
            assert_eq!(time_name(h), TimeName::No, "{h}");
        }
    }
}
