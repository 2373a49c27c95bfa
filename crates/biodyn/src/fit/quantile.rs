//! Student's t and Fisher's F quantiles, for intervals from few degrees
//! of freedom.
//!
//! The distribution function of t with ν degrees of freedom is, for t ≥ 0,
//!
//! ```text
//! P(T ≤ t) = 1 − ½ I_x(ν/2, ½),   x = ν / (ν + t²)
//! ```
//!
//! with I the regularized incomplete beta function (Abramowitz & Stegun
//! 26.7.1 and 26.5.27). I is evaluated by its continued fraction (A&S
//! 26.5.8, by the modified Lentz method) with ln Γ from Lanczos' series
//! (g = 7, nine terms: about 1e-15 relative), and the quantile is found by
//! bisection on the distribution function, so it is as exact as the
//! function itself: no asymptotic series that would fail at ν = 1. The
//! profile threshold F(0.95; 1, ν) is t(0.975; ν)². F with (d₁, d₂) degrees
//! of freedom has P(F ≤ x) = I_y(d₁/2, d₂/2), y = d₁x / (d₁x + d₂)
//! (A&S 26.6.2), inverted the same way.

/// ln Γ(x) for x > 0, Lanczos' approximation (g = 7, n = 9).
fn ln_gamma(x: f64) -> f64 {
    const G: f64 = 7.0;
    const C: [f64; 9] = [
        0.999_999_999_999_809_9,
        676.520_368_121_885_1,
        -1_259.139_216_722_402_8,
        771.323_428_777_653_1,
        -176.615_029_162_140_6,
        12.507_343_278_686_905,
        -0.138_571_095_265_720_12,
        9.984_369_578_019_572e-6,
        1.505_632_735_149_311_6e-7,
    ];
    if x < 0.5 {
        // Reflection: Γ(x)Γ(1 − x) = π / sin(πx).
        let pi = std::f64::consts::PI;
        return (pi / (pi * x).sin()).ln() - ln_gamma(1.0 - x);
    }
    let x = x - 1.0;
    let mut a = C[0];
    let t = x + G + 0.5;
    for (i, &c) in C.iter().enumerate().skip(1) {
        a += c / (x + i as f64);
    }
    0.5 * (2.0 * std::f64::consts::PI).ln() + (x + 0.5) * t.ln() - t + a.ln()
}

/// The continued fraction of I_x(a, b) (valid, and fast, for x < (a+1)/(a+b+2)),
/// by the modified Lentz method.
fn beta_fraction(a: f64, b: f64, x: f64) -> f64 {
    const TINY: f64 = 1e-300;
    let floor = |v: f64| if v.abs() < TINY { TINY } else { v };
    let (qab, qap, qam) = (a + b, a + 1.0, a - 1.0);
    let mut c = 1.0;
    let mut d = 1.0 / floor(1.0 - qab * x / qap);
    let mut h = d;
    // One Lentz step with coefficient `aa`: the factor it multiplies h by.
    let mut step = |aa: f64| {
        d = 1.0 / floor(1.0 + aa * d);
        c = floor(1.0 + aa / c);
        d * c
    };
    for m in 1..=300 {
        let m = m as f64;
        let m2 = 2.0 * m;
        h *= step(m * (b - m) * x / ((qam + m2) * (a + m2)));
        let del = step(-(a + m) * (qab + m) * x / ((a + m2) * (qap + m2)));
        h *= del;
        if (del - 1.0).abs() < 1e-16 {
            break;
        }
    }
    h
}

/// The regularized incomplete beta function I_x(a, b), 0 ≤ x ≤ 1.
fn incomplete_beta(a: f64, b: f64, x: f64) -> f64 {
    if x <= 0.0 {
        return 0.0;
    }
    if x >= 1.0 {
        return 1.0;
    }
    let front =
        (ln_gamma(a + b) - ln_gamma(a) - ln_gamma(b) + a * x.ln() + b * (1.0 - x).ln()).exp();
    if x < (a + 1.0) / (a + b + 2.0) {
        front * beta_fraction(a, b, x) / a
    } else {
        1.0 - front * beta_fraction(b, a, 1.0 - x) / b
    }
}

/// P(T > t) for t ≥ 0, Student's t with `dof` degrees of freedom.
fn upper_tail(t: f64, dof: f64) -> f64 {
    0.5 * incomplete_beta(0.5 * dof, 0.5, dof / (dof + t * t))
}

/// The two-sided quantile: t with P(|T| ≤ t) = `level` (0.95 gives
/// t(0.975; ν)), for `dof` ≥ 1 degrees of freedom (fractional allowed);
/// `level` in (0, 1).
pub fn student_t(level: f64, dof: f64) -> f64 {
    let tail = 0.5 * (1.0 - level);
    // The upper tail falls from ½ at 0; bracket, then bisect on it.
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    while upper_tail(hi, dof) > tail && hi < 1e300 {
        lo = hi;
        hi *= 2.0;
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if upper_tail(mid, dof) > tail {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// The quantile x of F(d₁, d₂) with P(F ≤ x) = `level`, `level` in (0, 1).
pub fn fisher_f(level: f64, d1: f64, d2: f64) -> f64 {
    let cdf = |x: f64| incomplete_beta(0.5 * d1, 0.5 * d2, d1 * x / (d1 * x + d2));
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    while cdf(hi) < level && hi < 1e300 {
        lo = hi;
        hi *= 2.0;
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if cdf(mid) < level {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// NIST/SEMATECH e-Handbook of Statistical Methods, §1.3.6.7.2,
    /// "Critical values of the Student's t distribution", column
    /// 0.975 (upper tail 0.025), printed to three decimals.
    #[test]
    fn matches_the_nist_table() {
        for (dof, want) in [
            (1.0, 12.706),
            (2.0, 4.303),
            (3.0, 3.182),
            (5.0, 2.571),
            (10.0, 2.228),
            (30.0, 2.042),
            (100.0, 1.984),
        ] {
            let t = student_t(0.95, dof);
            assert!(
                (t - want).abs() < 5e-4,
                "t(0.975; {dof}) = {t}, table {want}"
            );
        }
        // One-sided 0.95 column (two-sided 0.90): 6.314 at 1, 1.697 at 30.
        assert!((student_t(0.90, 1.0) - 6.314).abs() < 5e-4);
        assert!((student_t(0.90, 30.0) - 1.697).abs() < 5e-4);
    }

    /// Closed forms: ν = 1 is Cauchy, t = tan(π(p − ½)); ν = 2 has
    /// t = (2p − 1) / √(2p(1 − p)); ν → ∞ is the normal, 1.959 964.
    #[test]
    fn matches_the_closed_forms() {
        let p: f64 = 0.975;
        let cauchy = (std::f64::consts::PI * (p - 0.5)).tan();
        assert!((student_t(0.95, 1.0) / cauchy - 1.0).abs() < 1e-12);
        let two = (2.0 * p - 1.0) / (2.0 * p * (1.0 - p)).sqrt();
        assert!((student_t(0.95, 2.0) / two - 1.0).abs() < 1e-12);
        let z = 1.959_963_984_540_054;
        assert!((student_t(0.95, 1e9) - z).abs() < 1e-6);
        assert!(student_t(0.95, 784.0) > z && student_t(0.95, 784.0) < 1.963);
    }

    /// NIST/SEMATECH e-Handbook §1.3.6.7.3, upper 5 % points of F; and
    /// F(1, ν) = t(0.975; ν)², d₁·F(d₁, ∞) = χ²(d₁) (15.507 for 8, §1.3.6.7.4).
    #[test]
    fn f_matches_the_nist_table_and_t_squared() {
        for (d1, d2, want) in [
            (1.0, 10.0, 4.965),
            (5.0, 10.0, 3.326),
            (10.0, 10.0, 2.978),
            (2.0, 30.0, 3.316),
        ] {
            let f = fisher_f(0.95, d1, d2);
            assert!(
                (f - want).abs() < 5e-4,
                "F(0.95; {d1}, {d2}) = {f}, table {want}"
            );
        }
        for nu in [1.0, 3.0, 50.0] {
            let t = student_t(0.95, nu);
            assert!((fisher_f(0.95, 1.0, nu) / (t * t) - 1.0).abs() < 1e-9);
        }
        assert!((8.0 * fisher_f(0.95, 8.0, 1e9) - 15.507).abs() < 1e-3);
    }

    #[test]
    fn ln_gamma_is_exact_at_integers_a_half_and_below_a_half() {
        assert!(ln_gamma(1.0).abs() < 1e-14);
        assert!((ln_gamma(5.0) - 24f64.ln()).abs() < 1e-13);
        assert!((ln_gamma(0.5) - std::f64::consts::PI.sqrt().ln()).abs() < 1e-14);
        // Below ½ by the reflection Γ(x)Γ(1 − x) = π / sin(πx): Γ(¼) =
        // 3.625 609 908 221 908… and Γ(0.1) = 9.513 507 698 668 732… (values as in
        // Python's math.lgamma, an independent implementation), their logarithms.
        assert!((ln_gamma(0.25) - 1.288_022_524_698_077_4).abs() < 1e-13);
        assert!((ln_gamma(0.1) - 2.252_712_651_734_206).abs() < 1e-13);
    }
}
