//! The day's spine, ISO 2631-5:2018 §5.3 Formula 5 and Annex C: each
//! operation j's z dose Dz_j, measured over t_mj and lasting t_dj a day,
//! gives the daily dose Dzd = (Σ Dz_j⁶·t_dj/t_mj)^⅙; Annex C then judges it
//! for the day file's person. A day whose dose is past the largest float is
//! refused ([`DoseOverflow`]), never judged as `inf`.

use crate::io::excerpt::num;
use crate::iso2631::spine::{Person, Risk, daily, daily_of, risk};

/// One operation's part of the day's dose.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpinePart {
    /// Index into the day's operations.
    pub operation: usize,
    /// Dz over `measured_s`, m/s².
    pub dz: f64,
    pub measured_s: f64,
    pub hours: f64,
    /// This operation alone over its hours, Dz·(t_d/t_m)^⅙, m/s².
    pub dzd: f64,
}

/// The day's daily dose and Annex C's risk for its person.
#[derive(Debug, Clone, PartialEq)]
pub struct DaySpine {
    pub person: Person,
    pub parts: Vec<SpinePart>,
    /// Formula 5, m/s².
    pub dzd: f64,
    pub risk: Risk,
}

/// The day's dose Dzd is past the largest float (about 1.8e308 m/s²): no
/// body meets such a dose, so a unit slipped; the operation whose own Dzd is
/// the largest is named, with its Dz.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
#[error(
    "Dz = {} m/s² over {} s for {} h a day gives a daily dose Dzd past 1.8e308 m/s², the largest number held: check the dose and its unit (m/s²)",
    num(*.dz), num(*.measured_s), num(*.hours)
)]
pub struct DoseOverflow {
    /// Index into the day's operations.
    pub operation: usize,
    pub dz: f64,
    pub measured_s: f64,
    pub hours: f64,
}

impl DaySpine {
    /// From each operation's (index, Dz, t_m s, hours); refused when the
    /// day's dose (or one operation's) is past the largest float.
    pub fn of(person: Person, doses: &[(usize, f64, f64, f64)]) -> Result<DaySpine, DoseOverflow> {
        let parts: Vec<SpinePart> = doses
            .iter()
            .map(|&(operation, dz, measured_s, hours)| SpinePart {
                operation,
                dz,
                measured_s,
                hours,
                dzd: daily(dz, hours * 3600.0, measured_s),
            })
            .collect();
        let conditions: Vec<(f64, f64, f64)> = parts
            .iter()
            .map(|p| (p.dz, p.hours * 3600.0, p.measured_s))
            .collect();
        let dzd = daily_of(&conditions);
        if !dzd.is_finite() {
            let worst = parts
                .iter()
                .max_by(|a, b| a.dzd.total_cmp(&b.dzd))
                .copied()
                .unwrap_or(SpinePart {
                    operation: 0,
                    dz: f64::NAN,
                    measured_s: f64::NAN,
                    hours: f64::NAN,
                    dzd,
                });
            return Err(DoseOverflow {
                operation: worst.operation,
                dz: worst.dz,
                measured_s: worst.measured_s,
                hours: worst.hours,
            });
        }
        Ok(DaySpine {
            person,
            parts,
            dzd,
            risk: risk(dzd, &person),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::iso2631::spine::Sex;

    /// Two operations by hand: Dzd⁶ = Σ Dz⁶·t_d/t_m, and one operation alone
    /// is Formula 4.
    #[test]
    fn formula_5_by_hand() {
        let who = Person::new(25.0, 10, 240, Sex::Male).unwrap();
        let d = DaySpine::of(who, &[(0, 30.0, 600.0, 2.0), (1, 50.0, 300.0, 1.0)]).unwrap();
        let hand =
            (30f64.powi(6) * 7200.0 / 600.0 + 50f64.powi(6) * 3600.0 / 300.0).powf(1.0 / 6.0);
        assert!((d.dzd - hand).abs() < 1e-9 * hand, "{} vs {hand}", d.dzd);
        assert!((d.parts[1].dzd - 50.0 * 12f64.powf(1.0 / 6.0)).abs() < 1e-9);
        assert_eq!(d.risk, risk(hand, &who));
        let one = DaySpine::of(who, &[(0, 30.0, 600.0, 2.0)]).unwrap();
        assert!((one.dzd - one.parts[0].dzd).abs() < 1e-12);
    }

    /// A dose of 1e60 m/s² is a number, and so is the day's (Formula 5 in
    /// sixth powers would be inf); Annex C's R and P follow from it. A day
    /// past the largest float is refused, naming the operation.
    #[test]
    fn huge_doses_are_numbers_or_refused() {
        let who = Person::new(25.0, 10, 220, Sex::Male).unwrap();
        let d = DaySpine::of(who, &[(0, 30.0, 600.0, 2.0), (1, 1e60, 600.0, 2.0)]).unwrap();
        let alone = 1e60 * 12f64.powf(1.0 / 6.0);
        assert!((d.parts[1].dzd / alone - 1.0).abs() < 1e-15);
        assert!((d.dzd / alone - 1.0).abs() < 1e-15, "{}", d.dzd);
        assert!(
            d.risk.r.is_finite() && d.risk.sd.is_finite(),
            "{:?}",
            d.risk
        );
        assert_eq!(d.risk.probability, 1.0);
        let e = DaySpine::of(who, &[(0, 30.0, 600.0, 2.0), (1, 1e308, 1.0, 8.0)]).unwrap_err();
        assert_eq!(e.operation, 1);
        assert_eq!(e.dz, 1e308);
        assert!(
            e.to_string().contains("Dz = 1e308 m/s² over 1 s for 8 h"),
            "{e}"
        );
    }
}
