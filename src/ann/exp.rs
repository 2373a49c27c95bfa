//! e^x for the logistic neuron, written out rather than taken from the
//! platform's libm, for two reasons:
//!
//! * speed: it inlines into the training loops (no call, no `errno`
//!   bookkeeping on overflow), which the paper's trainer calls nine to
//!   thirteen times per pattern;
//! * reproducibility: libm's `exp` may differ in the last bit between C
//!   libraries and their versions, and online back-propagation amplifies one
//!   bit into a different network after enough epochs. With this function a
//!   seed gives the same bits on every platform and libm.
//!
//! The method is the classic one of Sun's fdlibm `e_exp.c` (Cody & Waite
//! argument reduction, a rational approximation on |r| ≤ ln2/2), without its
//! table of special cases: x = k·ln2 + r with k = round(x/ln2) and
//! r = hi − lo carried in two parts, then
//! e^r = 1 − ((lo − r·c/(2 − c)) − hi) with c = r − r²·P(r²), and the result
//! is scaled by 2^k in two exact steps (so that subnormal results round only
//! once). Error below 1 ulp; the tests hold it to within 1 ulp of `f64::exp`
//! (itself within 1 ulp) over millions of points and all special values.

/// ln 2 split so that k·LN2_HI is exact for |k| < 2^11.
const LN2_HI: f64 = 6.931_471_803_691_238_164_90e-1; // 0x3fe62e42_fee00000
const LN2_LO: f64 = 1.908_214_929_270_587_700_02e-10; // 0x3dea39ef_35793c76
const INV_LN2: f64 = 1.442_695_040_888_963_387_00;
/// Adding then subtracting 1.5·2^52 rounds to the nearest integer, which
/// is then also found in the low bits of the sum.
const SHIFT: f64 = 6_755_399_441_055_744.0;
/// Coefficients of fdlibm's rational approximation (Remez, |error| < 2^-59).
const P1: f64 = 1.666_666_666_666_660_190_37e-1;
const P2: f64 = -2.777_777_777_701_559_338_42e-3;
const P3: f64 = 6.613_756_321_437_934_361_17e-5;
const P4: f64 = -1.653_390_220_546_525_153_90e-6;
const P5: f64 = 4.138_136_797_057_238_460_39e-8;
/// Above this e^x overflows; below `UNDERFLOW` it rounds to 0.
const OVERFLOW: f64 = 7.097_827_128_933_839_730_96e2;
const UNDERFLOW: f64 = -7.451_332_191_019_411_084_20e2;

/// 2^k for −1022 ≤ k ≤ 1023.
#[inline(always)]
fn pow2(k: i64) -> f64 {
    f64::from_bits(((k + 1023) as u64) << 52)
}

/// e^x, within 1 ulp of the exact value for every f64; e^(+∞) = +∞,
/// e^(−∞) = 0, NaN in gives NaN out.
#[inline(always)]
pub fn exp(x: f64) -> f64 {
    if x > OVERFLOW {
        return f64::INFINITY;
    }
    if x < UNDERFLOW {
        return 0.0;
    }
    // From here |x| < 746 (or x is NaN, which flows through to the result):
    // |k| ≤ 1075, far inside the range where SHIFT rounds exactly.
    let z = x * INV_LN2 + SHIFT;
    let k = z.to_bits() as i64 - SHIFT.to_bits() as i64;
    let kf = z - SHIFT;
    let hi = x - kf * LN2_HI;
    let lo = kf * LN2_LO;
    let r = hi - lo;
    let t = r * r;
    let c = r - t * (P1 + t * (P2 + t * (P3 + t * (P4 + t * P5))));
    let y = 1.0 - ((lo - (r * c) / (2.0 - c)) - hi);
    // y ∈ [0.7, 1.42]; k ∈ [−1075, 1024]: both halves of 2^k are normal and
    // y·2^k1 is exact, so only the last product rounds (for subnormals).
    let k1 = k >> 1;
    y * pow2(k1) * pow2(k - k1)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ann::rng::Rng;

    /// Distance in units in the last place between two finite doubles of
    /// the same sign (0 and −0 count as equal).
    fn ulps(a: f64, b: f64) -> u64 {
        if a == b {
            return 0;
        }
        assert!(a.is_finite() && b.is_finite(), "{a} vs {b}");
        assert!(a >= 0.0 && b >= 0.0, "{a} vs {b}");
        a.to_bits().abs_diff(b.to_bits())
    }

    /// The double `n` steps further from zero (n < 0: towards zero); x ≠ 0.
    fn up(x: f64, n: i64) -> f64 {
        f64::from_bits((x.to_bits() as i64 + n) as u64)
    }

    fn check(x: f64) -> u64 {
        let (got, want) = (exp(x), x.exp());
        if want.is_nan() {
            assert!(got.is_nan(), "exp({x:e}) = {got:e}, want NaN");
            return 0;
        }
        if want.is_infinite() || want == 0.0 {
            assert_eq!(got, want, "exp({x:e})");
            return 0;
        }
        let d = ulps(got, want);
        assert!(d <= 1, "exp({x:e}) = {got:e}, libm {want:e}: {d} ulp apart");
        d
    }

    #[test]
    fn special_values_and_saturation_are_exact() {
        assert!(exp(f64::NAN).is_nan());
        assert!(exp(-f64::NAN).is_nan());
        assert_eq!(exp(f64::INFINITY), f64::INFINITY);
        assert_eq!(exp(f64::NEG_INFINITY), 0.0);
        assert_eq!(exp(f64::MAX), f64::INFINITY);
        assert_eq!(exp(f64::MIN), 0.0);
        assert_eq!(exp(0.0), 1.0);
        assert_eq!(exp(-0.0), 1.0);
        assert!(ulps(exp(1.0), std::f64::consts::E) <= 1);
        assert_eq!(exp(f64::MIN_POSITIVE), 1.0);
        assert_eq!(exp(5e-324), 1.0);
        assert_eq!(exp(-5e-324), 1.0);
        // The edges: the last finite result and the first infinite one, the
        // last non-zero (subnormal) result and the first zero.
        for x in [OVERFLOW, UNDERFLOW, 709.0, -708.0, -708.4, -709.0, -740.0] {
            for y in [up(x, -1), x, up(x, 1)] {
                check(y);
            }
        }
        assert!(exp(OVERFLOW).is_finite());
        assert_eq!(exp(up(OVERFLOW, 1)), f64::INFINITY);
        assert!(exp(UNDERFLOW) > 0.0);
        assert_eq!(exp(up(UNDERFLOW, 1)), 0.0);
        assert_eq!(exp(-745.0), 5e-324);
    }

    #[test]
    fn within_one_ulp_of_libm_over_the_whole_range() {
        let mut rng = Rng::new(11);
        let mut worst = 0;
        let mut n = 0u64;
        // Uniform over the whole finite-result range, then over the range a
        // neuron sees, then a dense walk across the reduction's k steps.
        for _ in 0..1_000_000 {
            worst = worst.max(check(rng.symmetric(750.0)));
            worst = worst.max(check(rng.symmetric(40.0)));
            n += 2;
        }
        for k in -1080i32..=1030 {
            let mid = (k as f64 + 0.5) * std::f64::consts::LN_2;
            let mut x = mid;
            for _ in 0..64 {
                worst = worst.max(check(x));
                worst = worst.max(check(-x));
                x = up(x, 1);
                n += 2;
            }
        }
        // Every exponent of the input: random bit patterns, tiny to huge.
        for _ in 0..1_000_000 {
            let x = f64::from_bits(rng.next_u64());
            worst = worst.max(check(x));
            // Magnitudes from the smallest subnormal to 2048, either sign.
            let mag = (1.0 + rng.next_f64()) * 2f64.powi(rng.below(1085) as i32 - 1074);
            let y = if rng.next_u64() & 1 == 1 { -mag } else { mag };
            worst = worst.max(check(y));
            n += 2;
        }
        assert!(n > 3_000_000);
        assert!(worst <= 1, "worst {worst} ulp");
    }
}
