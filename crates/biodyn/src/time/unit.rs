//! Units of acceleration a record may be written in, and the header
//! suffixes that name them.

use std::fmt;

/// Standard acceleration of gravity, m/s² (ISO 80000-3; CGPM 1901).
pub const G_N: f64 = 9.80665;

/// A unit of acceleration.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Unit {
    /// m/s², the unit every result is in.
    #[default]
    MetrePerSecondSquared,
    /// Standard gravity, 9.80665 m/s².
    G,
    /// mm/s².
    MillimetrePerSecondSquared,
}

/// Header suffixes naming a column's unit; `_mm_s2` before `_m_s2`, which
/// it ends with.
const SUFFIXES: [(&str, Unit); 4] = [
    ("_mm_s2", Unit::MillimetrePerSecondSquared),
    ("_m_s2", Unit::MetrePerSecondSquared),
    ("_ms2", Unit::MetrePerSecondSquared),
    ("_g", Unit::G),
];

impl Unit {
    pub const ALL: [Unit; 3] = [
        Unit::MetrePerSecondSquared,
        Unit::G,
        Unit::MillimetrePerSecondSquared,
    ];

    /// The name as written on the command line and in files.
    pub fn name(self) -> &'static str {
        match self {
            Unit::MetrePerSecondSquared => "m/s2",
            Unit::G => "g",
            Unit::MillimetrePerSecondSquared => "mm/s2",
        }
    }

    /// m/s² per unit.
    pub fn to_m_s2(self) -> f64 {
        match self {
            Unit::MetrePerSecondSquared => 1.0,
            Unit::G => G_N,
            Unit::MillimetrePerSecondSquared => 1e-3,
        }
    }

    /// `m/s2` (also `m/s²`, `m/s^2`, `m/s**2`, `m/s/s`, `m s-2`, `ms2`),
    /// `g` (also `gn`), `mm/s2` (and the same forms): what instruments and
    /// spreadsheets write in a header's brackets and on the command line.
    pub fn parse(s: &str) -> Option<Unit> {
        let t = s
            .trim()
            .to_ascii_lowercase()
            .replace('²', "2")
            .replace("**2", "2")
            .replace("^2", "2")
            .replace("/s/s", "/s2")
            .replace(" s-2", "/s2")
            .replace("s^-2", "/s2");
        match t.as_str() {
            "m/s2" | "ms2" | "m_s2" | "m/sec2" => Some(Unit::MetrePerSecondSquared),
            "g" | "gn" => Some(Unit::G),
            "mm/s2" | "mms2" | "mm_s2" | "mm/sec2" => Some(Unit::MillimetrePerSecondSquared),
            _ => None,
        }
    }

    /// Splits a unit off a header (any case): `az_g` → (`az`, G), and the
    /// forms instruments write, `Acc Z [g]`, `Acc Z (m/s²)`, `Acc Z in g`.
    /// A unit it does not know is None here: [`split_unit`] tells it apart
    /// from no unit at all.
    pub fn split_suffix(header: &str) -> (&str, Option<Unit>) {
        match split_unit(header) {
            (base, HeaderUnit::Known(u)) => (base, Some(u)),
            _ => (header, None),
        }
    }
}

/// What a header's name says of its unit.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum HeaderUnit<'a> {
    /// Nothing: the name has no unit.
    None,
    /// A unit of acceleration.
    Known(Unit),
    /// A unit written in brackets (or after ` in `) that is no acceleration
    /// this reader knows, as written: `V`, `ft/s²`, `ms`.
    Other(&'a str),
}

/// The unit written at the end of a header, bracketed or after ` in `:
/// `Acc Z [g]` → (`Acc Z`, `g`); `Time (ms)` → (`Time`, `ms`); `z in g`.
pub fn bracketed(header: &str) -> Option<(&str, &str)> {
    let h = header.trim_end();
    for (open, close) in [('[', ']'), ('(', ')')] {
        if let Some(inner) = h.strip_suffix(close)
            && let Some(i) = inner.rfind(open)
        {
            let base = inner[..i].trim_end();
            let unit = inner[i + open.len_utf8()..].trim();
            if !base.is_empty() && !unit.is_empty() {
                return Some((base, unit));
            }
        }
    }
    let lower = h.to_ascii_lowercase();
    let i = lower.rfind(" in ")?;
    let (base, unit) = (h[..i].trim_end(), h[i + 4..].trim());
    (!base.is_empty() && !unit.is_empty() && !unit.contains(' ')).then_some((base, unit))
}

/// Splits the unit off a header: a bracketed unit or ` in UNIT` first,
/// else a suffix (`_m_s2`, `_ms2`, `_mm_s2`, `_g`).
pub fn split_unit(header: &str) -> (&str, HeaderUnit<'_>) {
    if let Some((base, unit)) = bracketed(header) {
        return match Unit::parse(unit) {
            Some(u) => (base, HeaderUnit::Known(u)),
            None => (base, HeaderUnit::Other(unit)),
        };
    }
    let lower = header.to_ascii_lowercase();
    for (suffix, unit) in SUFFIXES {
        if lower.len() > suffix.len() && lower.ends_with(suffix) {
            return (
                &header[..header.len() - suffix.len()],
                HeaderUnit::Known(unit),
            );
        }
    }
    (header, HeaderUnit::None)
}

impl fmt::Display for Unit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn suffixes_split_and_units_convert() {
        assert_eq!(
            Unit::split_suffix("seat_x_m_s2"),
            ("seat_x", Some(Unit::MetrePerSecondSquared))
        );
        assert_eq!(Unit::split_suffix("az_g"), ("az", Some(Unit::G)));
        assert_eq!(Unit::split_suffix("AZ_G"), ("AZ", Some(Unit::G)));
        assert_eq!(
            Unit::split_suffix("z_mm_s2"),
            ("z", Some(Unit::MillimetrePerSecondSquared))
        );
        assert_eq!(Unit::split_suffix("acc_z"), ("acc_z", None));
        assert_eq!(Unit::split_suffix("zms2"), ("zms2", None));
        assert_eq!(Unit::split_suffix("_g"), ("_g", None));
        assert_eq!(Unit::G.to_m_s2(), 9.80665);
        assert_eq!(Unit::MillimetrePerSecondSquared.to_m_s2(), 0.001);
        for u in Unit::ALL {
            assert_eq!(Unit::parse(u.name()), Some(u));
        }
        assert_eq!(Unit::parse("m/s²"), Some(Unit::MetrePerSecondSquared));
        assert_eq!(Unit::parse("ft/s2"), None);
    }

    /// The forms instruments and spreadsheets write (issue 30's list).
    #[test]
    fn bracketed_units_are_read() {
        let g = HeaderUnit::Known(Unit::G);
        let m = HeaderUnit::Known(Unit::MetrePerSecondSquared);
        let mm = HeaderUnit::Known(Unit::MillimetrePerSecondSquared);
        for (h, base, u) in [
            ("Acc Z [g]", "Acc Z", g),
            ("Acc Z (g)", "Acc Z", g),
            ("az [m/s²]", "az", m),
            ("az [m/s^2]", "az", m),
            ("az [m/s2]", "az", m),
            ("az[mm/s²]", "az", mm),
            ("Acc Z in g", "Acc Z", g),
            ("az_g", "az", g),
            ("Acc Z [V]", "Acc Z", HeaderUnit::Other("V")),
            ("Acc Z (ft/s²)", "Acc Z", HeaderUnit::Other("ft/s²")),
            ("Acc Z", "Acc Z", HeaderUnit::None),
            ("[g]", "[g]", HeaderUnit::None),
        ] {
            assert_eq!(split_unit(h), (base, u), "{h}");
        }
        assert_eq!(Unit::split_suffix("Acc Z [g]"), ("Acc Z", Some(Unit::G)));
        assert_eq!(Unit::split_suffix("Acc Z [V]"), ("Acc Z [V]", None));
    }
}
