//! The paper's three response functions and what both fronts need to
//! know about each: name, unit, CSV columns and JSON keys. Every loop over
//! functions runs over `Function::ALL`; a fourth function is one variant
//! here plus its value in `Response`.

use serde::Serialize;

/// The three response functions of the paper.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Function {
    Stht,
    Dpmi,
    Apms,
}

impl Function {
    pub const ALL: [Function; 3] = [Function::Stht, Function::Dpmi, Function::Apms];

    /// Lower-case key as used on the command line and in CSV headers.
    pub fn key(self) -> &'static str {
        match self {
            Function::Stht => "stht",
            Function::Dpmi => "dpmi",
            Function::Apms => "apms",
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Function::Stht => "STHT",
            Function::Dpmi => "DPMI",
            Function::Apms => "APMS",
        }
    }

    pub fn long_name(self) -> &'static str {
        match self {
            Function::Stht => "seat-to-head transmissibility",
            Function::Dpmi => "driving-point mechanical impedance",
            Function::Apms => "apparent mass",
        }
    }

    /// Unit of the magnitude.
    pub fn unit(self) -> &'static str {
        match self {
            Function::Stht => "-",
            Function::Dpmi => "N·s/m",
            Function::Apms => "kg",
        }
    }

    /// Position in `ALL` (per-function arrays are indexed by it).
    pub fn index(self) -> usize {
        match self {
            Function::Stht => 0,
            Function::Dpmi => 1,
            Function::Apms => 2,
        }
    }

    /// CSV column and JSON key of the magnitude: `stht_mag`.
    pub fn mag_column(self) -> &'static str {
        match self {
            Function::Stht => "stht_mag",
            Function::Dpmi => "dpmi_mag",
            Function::Apms => "apms_mag",
        }
    }

    /// CSV column and JSON key of the phase: `stht_phase_deg`.
    pub fn phase_column(self) -> &'static str {
        match self {
            Function::Stht => "stht_phase_deg",
            Function::Dpmi => "dpmi_phase_deg",
            Function::Apms => "apms_phase_deg",
        }
    }

    /// The unit for a label, empty for the dimensionless STHT.
    pub fn unit_label(self) -> &'static str {
        match self.unit() {
            "-" => "",
            u => u,
        }
    }

    pub fn parse(s: &str) -> Option<Function> {
        match s.trim().to_ascii_lowercase().as_str() {
            "stht" => Some(Function::Stht),
            "dpmi" => Some(Function::Dpmi),
            "apms" => Some(Function::Apms),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn index_columns_and_keys_follow_all() {
        for (i, f) in Function::ALL.into_iter().enumerate() {
            assert_eq!(f.index(), i);
            assert_eq!(f.mag_column(), format!("{}_mag", f.key()));
            assert_eq!(f.phase_column(), format!("{}_phase_deg", f.key()));
            assert_eq!(Function::parse(f.name()), Some(f));
        }
    }
}
