//! ISO 2631-5:2018 Annex C: from the daily dose to a risk of injury of the
//! lumbar spine.
//!
//! - daily compressive stress Sd = m_z·Dzd (Formula C.1), m_z by sex;
//! - static stress S_stat = m_z·9.81 m/s² (the body's own weight);
//! - ultimate strength in year i, Su_i = 6.75 − S_age·(b + i) MPa (C.4),
//!   b the age when the exposure starts, i = 1..n;
//! - R = [Σ_{i=1..n} (Sd·N^⅙ / (Su_i − S_stat))⁶]^⅙ (C.3), N days a year;
//! - P(R) = 1 − exp(−(R/α)^β) (C.5, Weibull, Table C.1), by sex;
//! - the bands of Table C.2: R at 10 %, 50 % and 90 % risk.

use super::error::SpineError;
use crate::io::excerpt::short_quote;
use std::fmt;

/// Sex, for Annex C's constants.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Sex {
    Male,
    Female,
}

/// Annex C's constants for one sex.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Constants {
    /// m_z, MPa per m/s² (Formula C.2).
    pub mz: f64,
    /// S_age, MPa a year (Formula C.4).
    pub s_age: f64,
    /// Weibull α and β (Table C.1).
    pub alpha: f64,
    pub beta: f64,
    /// R at 10 %, 50 % and 90 % risk (Table C.2).
    pub r_at: [f64; 3],
}

/// Ultimate strength of the young spine, MPa (Formula C.4).
pub const SU_0: f64 = 6.75;

/// The acceleration of gravity Annex C takes for the static stress, m/s².
pub const GRAVITY: f64 = 9.81;

impl Sex {
    pub const ALL: [Sex; 2] = [Sex::Male, Sex::Female];

    pub fn name(self) -> &'static str {
        match self {
            Sex::Male => "male",
            Sex::Female => "female",
        }
    }

    pub fn parse(s: &str) -> Option<Sex> {
        Sex::ALL
            .into_iter()
            .find(|x| x.name().eq_ignore_ascii_case(s.trim()))
    }

    /// ISO 2631-5:2018 Annex C, Formulae C.2 and C.4, Tables C.1 and C.2.
    pub fn constants(self) -> Constants {
        match self {
            Sex::Male => Constants {
                mz: 0.029,
                s_age: 0.052,
                alpha: 1.613,
                beta: 2.799,
                r_at: [0.72, 1.42, 2.17],
            },
            Sex::Female => Constants {
                mz: 0.025,
                s_age: 0.039,
                alpha: 0.959,
                beta: 3.709,
                r_at: [0.52, 0.87, 1.20],
            },
        }
    }
}

impl fmt::Display for Sex {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Youngest starting age taken, years: Annex C's strength model is for the
/// adult working spine.
pub const MIN_AGE: f64 = 14.0;

/// Oldest age the exposure may reach, years: the strength model is a
/// straight line fitted to working ages; past 100 it is extrapolation.
pub const MAX_AGE: f64 = 100.0;

/// Who is exposed, and for how long: what Annex C needs beyond the dose.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Person {
    /// b: age when the exposure starts, years.
    pub age: f64,
    /// n: years of exposure.
    pub years: u32,
    /// N: exposure days a year.
    pub days: u32,
    pub sex: Sex,
}

impl Person {
    /// Checks the ranges: age from 14, at most 100 at the end of the
    /// exposure; at least one year; 1 to 366 days a year.
    pub fn new(age: f64, years: u32, days: u32, sex: Sex) -> Result<Person, SpineError> {
        if !(age.is_finite() && (MIN_AGE..MAX_AGE).contains(&age)) {
            return Err(SpineError::Age(age));
        }
        if years == 0 {
            return Err(SpineError::Years(years.to_string()));
        }
        if age + f64::from(years) > MAX_AGE {
            return Err(SpineError::PastMaxAge { age, years });
        }
        if !(1..=366).contains(&days) {
            return Err(SpineError::Days(days.to_string()));
        }
        Ok(Person {
            age,
            years,
            days,
            sex,
        })
    }

    /// `age=A,years=N,days=D,sex=male|female`, every key once, in any order.
    pub fn parse(spec: &str) -> Result<Person, SpineError> {
        let (mut age, mut years, mut days, mut sex) = (None, None, None, None);
        for part in spec.split(',').map(str::trim) {
            let Some((k, v)) = part.split_once('=') else {
                return Err(SpineError::Part(short_quote(part)));
            };
            let (k, v) = (k.trim(), v.trim());
            let twice = |set: bool| {
                if set {
                    Err(SpineError::Twice(short_quote(k)))
                } else {
                    Ok(())
                }
            };
            match k {
                "age" => {
                    twice(age.is_some())?;
                    age = Some(v.parse::<f64>().map_err(|_| SpineError::Number {
                        key: "age",
                        value: short_quote(v),
                    })?);
                }
                "years" => {
                    twice(years.is_some())?;
                    years = Some(whole(v).ok_or_else(|| SpineError::Years(short_quote(v)))?);
                }
                "days" => {
                    twice(days.is_some())?;
                    days = Some(whole(v).ok_or_else(|| SpineError::Days(short_quote(v)))?);
                }
                "sex" => {
                    twice(sex.is_some())?;
                    sex = Some(Sex::parse(v).ok_or_else(|| SpineError::Sex(short_quote(v)))?);
                }
                _ => return Err(SpineError::Key(short_quote(k))),
            }
        }
        let missing: Vec<&str> = [
            ("age", age.is_none()),
            ("years", years.is_none()),
            ("days", days.is_none()),
            ("sex", sex.is_none()),
        ]
        .iter()
        .filter(|m| m.1)
        .map(|m| m.0)
        .collect();
        match (age, years, days, sex) {
            (Some(a), Some(y), Some(d), Some(s)) => Person::new(a, y, d, s),
            _ => Err(SpineError::Missing(missing.join(", "))),
        }
    }
}

impl Person {
    /// The form [`Person::parse`] reads: `age=25,years=10,days=240,sex=male`.
    pub fn spec(&self) -> String {
        format!(
            "age={},years={},days={},sex={}",
            self.age, self.years, self.days, self.sex
        )
    }
}

/// A whole number of at most 9 digits (years, days).
fn whole(v: &str) -> Option<u32> {
    (!v.is_empty() && v.len() <= 9 && v.bytes().all(|b| b.is_ascii_digit()))
        .then(|| v.parse().ok())
        .flatten()
}

impl fmt::Display for Person {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} from age {} for {} years, {} days a year",
            self.sex, self.age, self.years, self.days
        )
    }
}

/// Annex C's risk band for R (Table C.2).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Band {
    /// Below the R of 10 % risk.
    Low,
    /// 10 % to 50 %.
    Moderate,
    /// 50 % to 90 %.
    High,
    /// Above 90 %.
    VeryHigh,
}

impl Band {
    pub fn words(self) -> &'static str {
        match self {
            Band::Low => "low probability of an adverse health effect (risk of injury < 10 %)",
            Band::Moderate => {
                "moderate probability of an adverse health effect (10 % < risk of injury < 50 %)"
            }
            Band::High => {
                "high probability of an adverse health effect (50 % < risk of injury < 90 %)"
            }
            Band::VeryHigh => {
                "very high probability of an adverse health effect (risk of injury > 90 %)"
            }
        }
    }

    /// Short name, for JSON.
    pub fn name(self) -> &'static str {
        match self {
            Band::Low => "low",
            Band::Moderate => "moderate",
            Band::High => "high",
            Band::VeryHigh => "very high",
        }
    }
}

/// What Annex C says of one daily dose for one person.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Risk {
    /// Sd = m_z·Dzd, MPa.
    pub sd: f64,
    /// S_stat = m_z·g, MPa.
    pub s_stat: f64,
    pub r: f64,
    /// P(R), 0–1.
    pub probability: f64,
    pub band: Band,
}

/// Annex C for a daily dose `dzd` (m/s²) and `person`.
pub fn risk(dzd: f64, person: &Person) -> Risk {
    let c = person.sex.constants();
    let sd = c.mz * dzd;
    let s_stat = c.mz * GRAVITY;
    let n6 = f64::from(person.days).powf(1.0 / 6.0);
    // R = (Σ_i (Sd·N^⅙/(S_u,i − S_stat))⁶)^⅙, overflow-safe (a huge Sd
    // gives a huge R, not inf).
    let r = crate::iso2631::power_sum::power_root(
        6,
        (1..=person.years).map(|i| {
            let su = SU_0 - c.s_age * (person.age + f64::from(i));
            sd * n6 / (su - s_stat)
        }),
    );
    let probability = 1.0 - (-(r / c.alpha).powf(c.beta)).exp();
    let band = match r {
        r if r < c.r_at[0] => Band::Low,
        r if r < c.r_at[1] => Band::Moderate,
        r if r < c.r_at[2] => Band::High,
        _ => Band::VeryHigh,
    };
    Risk {
        sd,
        s_stat,
        r,
        probability,
        band,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn male(age: f64, years: u32, days: u32) -> Person {
        Person::new(age, years, days, Sex::Male).unwrap()
    }

    /// ISO 2631-5:2018 Annex C's example: Dzd 55.97 m/s² gives Sd 1.62 MPa,
    /// R 1.22 and P 0.37 for a man exposed from age 25 for 10 years,
    /// 240 days a year (the inputs that reproduce the example's R to its
    /// two decimals), in the moderate band.
    #[test]
    fn the_annex_c_example() {
        let r = risk(55.97, &male(25.0, 10, 240));
        assert_eq!((r.sd * 100.0).round() / 100.0, 1.62);
        assert_eq!((r.r * 100.0).round() / 100.0, 1.22);
        assert_eq!((r.probability * 100.0).round() / 100.0, 0.37);
        assert_eq!(r.band, Band::Moderate);
    }

    /// R and P by hand for one year and for a woman.
    #[test]
    fn r_and_p_by_hand() {
        // One year from 40, 200 days: Su = 6.75 − 0.052·41 = 4.618,
        // S_stat = 0.029·9.81 = 0.28449, Sd = 0.029·50 = 1.45.
        let r = risk(50.0, &male(40.0, 1, 200));
        let hand = 1.45 * 200f64.powf(1.0 / 6.0) / (4.618 - 0.28449);
        assert!((r.r - hand).abs() < 1e-12, "{} vs {hand}", r.r);
        let p = 1.0 - (-(hand / 1.613).powf(2.799)).exp();
        assert!((r.probability - p).abs() < 1e-12);
        // Woman, two years from 30, 100 days: m_z 0.025, S_age 0.039.
        let w = Person::new(30.0, 2, 100, Sex::Female).unwrap();
        let r = risk(40.0, &w);
        let t = |age: f64| (1.0 * 100f64.powf(1.0 / 6.0) / (6.75 - 0.039 * age - 0.24525)).powi(6);
        let hand = (t(31.0) + t(32.0)).powf(1.0 / 6.0);
        assert!((r.r - hand).abs() < 1e-12);
        assert!((r.probability - (1.0 - (-(hand / 0.959).powf(3.709)).exp())).abs() < 1e-12);
    }

    /// Table C.2's R values are the Weibull's 10 %, 50 % and 90 % points
    /// (to the table's two decimals), so bands by R and by P agree.
    #[test]
    fn table_c2_is_the_weibulls_quantiles() {
        for sex in Sex::ALL {
            let c = sex.constants();
            for (r, p) in c.r_at.iter().zip([0.1, 0.5, 0.9]) {
                let q = c.alpha * (-(1.0f64 - p).ln()).powf(1.0 / c.beta);
                assert!((q - r).abs() < 0.006, "{sex}: {q} vs {r}");
            }
        }
    }

    /// Table C.2's four bands, each reached by a dose whose R lies inside
    /// it (R is proportional to Dzd, so the dose for an R is R over the R
    /// of 1 m/s²), with the JSON name and the wording of the band.
    #[test]
    fn each_band_of_table_c2_is_reached_and_named() {
        let who = male(25.0, 10, 240);
        let per_unit = risk(1.0, &who).r;
        for (r, band, name, words) in [
            (0.5, Band::Low, "low", "< 10 %"),
            (
                1.0,
                Band::Moderate,
                "moderate",
                "10 % < risk of injury < 50 %",
            ),
            (1.8, Band::High, "high", "50 % < risk of injury < 90 %"),
            (3.0, Band::VeryHigh, "very high", "> 90 %"),
        ] {
            let got = risk(r / per_unit, &who);
            assert!((got.r - r).abs() < 1e-9, "{} vs {r}", got.r);
            assert_eq!(got.band, band, "R {r}");
            assert_eq!(got.band.name(), name);
            assert!(got.band.words().contains(words), "{}", got.band.words());
        }
    }

    #[test]
    fn the_spec_parses_and_refuses() {
        let p = Person::parse("age=25,years=10,days=240,sex=male").unwrap();
        assert_eq!(p, male(25.0, 10, 240));
        assert_eq!(Person::parse(&p.spec()), Ok(p));
        // In words, as the reports print it.
        assert_eq!(
            p.to_string(),
            format!("{} from age 25 for 10 years, 240 days a year", p.sex)
        );
        let p = Person::parse(" sex=Female , days=100,years=2, age=30.5").unwrap();
        assert_eq!((p.sex, p.age), (Sex::Female, 30.5));
        for (bad, what) in [
            ("age=-3,years=10,days=240,sex=male", "age"),
            ("age=25,years=0,days=240,sex=male", "years"),
            ("age=25,years=1.5,days=240,sex=male", "years"),
            // Digits only, at most nine: no sign, no padding past nine.
            ("age=25,years=+5,days=240,sex=male", "years"),
            ("age=25,years=10,days=0000000005,sex=male", "days"),
            ("age=25,years=10,days=400,sex=male", "days"),
            ("age=25,years=10,days=240,sex=x", "sex"),
            ("age=25,years=10,days=240", "missing"),
            ("age=25,years=10,days=240,sex=male,height=2", "key"),
            ("age=25,age=26,years=10,days=240,sex=male", "twice"),
            ("age=nan,years=10,days=240,sex=male", "age"),
            ("age=abc,years=10,days=240,sex=male", "number"),
            ("age=90,years=20,days=240,sex=male", "past"),
            ("age", "part"),
            ("age=1e308,years=1,days=1,sex=male", "age"),
        ] {
            let e = Person::parse(bad).unwrap_err();
            let kind = match e {
                SpineError::Age(_) => "age",
                SpineError::Years(_) => "years",
                SpineError::Days(_) => "days",
                SpineError::Sex(_) => "sex",
                SpineError::Missing(_) => "missing",
                SpineError::Key(_) => "key",
                SpineError::Twice(_) => "twice",
                SpineError::Number { .. } => "number",
                SpineError::PastMaxAge { .. } => "past",
                SpineError::Part(_) => "part",
                _ => "other",
            };
            assert_eq!(kind, what, "{bad}: {e}");
            assert!(e.to_string().len() < 200, "{e}");
        }
        // What was typed is quoted with its control characters escaped.
        let e = Person::parse("age=25,\u{1b}[31mx=1")
            .unwrap_err()
            .to_string();
        assert!(!e.contains('\u{1b}') && e.contains("\\u{1b}"), "{e}");
    }
}
