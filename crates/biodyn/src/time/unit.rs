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

    /// `m/s2` (also `m/s²`, `m/s^2`, `ms2`), `g`, `mm/s2` (also `mm/s²`).
    pub fn parse(s: &str) -> Option<Unit> {
        let t = s
            .trim()
            .to_ascii_lowercase()
            .replace(['²'], "2")
            .replace("^2", "2");
        match t.as_str() {
            "m/s2" | "ms2" | "m_s2" => Some(Unit::MetrePerSecondSquared),
            "g" => Some(Unit::G),
            "mm/s2" | "mms2" | "mm_s2" => Some(Unit::MillimetrePerSecondSquared),
            _ => None,
        }
    }

    /// Splits a unit suffix off a header (any case): `az_g` → (`az`, G).
    pub fn split_suffix(header: &str) -> (&str, Option<Unit>) {
        let lower = header.to_ascii_lowercase();
        for (suffix, unit) in SUFFIXES {
            if lower.len() > suffix.len() && lower.ends_with(suffix) {
                return (&header[..header.len() - suffix.len()], Some(unit));
            }
        }
        (header, None)
    }
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
}
