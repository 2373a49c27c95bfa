//! The day's spine, ISO 2631-5:2018 §5.3 Formula 5 and Annex C: each
//! operation j's z dose Dz_j, measured over t_mj and lasting t_dj a day,
//! gives the daily dose Dzd = (Σ Dz_j⁶·t_dj/t_mj)^⅙; Annex C then judges it
//! for the day file's person.

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

impl DaySpine {
    /// From each operation's (index, Dz, t_m s, hours).
    pub fn of(person: Person, doses: &[(usize, f64, f64, f64)]) -> DaySpine {
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
        DaySpine {
            person,
            parts,
            dzd,
            risk: risk(dzd, &person),
        }
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
        let d = DaySpine::of(who, &[(0, 30.0, 600.0, 2.0), (1, 50.0, 300.0, 1.0)]);
        let hand =
            (30f64.powi(6) * 7200.0 / 600.0 + 50f64.powi(6) * 3600.0 / 300.0).powf(1.0 / 6.0);
        assert!((d.dzd - hand).abs() < 1e-9 * hand, "{} vs {hand}", d.dzd);
        assert!((d.parts[1].dzd - 50.0 * 12f64.powf(1.0 / 6.0)).abs() < 1e-9);
        assert_eq!(d.risk, risk(hand, &who));
        let one = DaySpine::of(who, &[(0, 30.0, 600.0, 2.0)]);
        assert!((one.dzd - one.parts[0].dzd).abs() < 1e-12);
    }
}
