//! Decimal numbers as records write them (`-0.123456`, `12.5`, `3e-2`),
//! parsed without a detour through `str`: the digits into a u64 mantissa
//! m and a power of ten e, and where m < 2^53 and |e| ≤ 22 the value is
//! m·10^e in one correctly rounded multiplication or division (Clinger's
//! fast path: both operands are exact doubles). Everything else (more
//! digits, larger exponents, `inf`, text) is left to `str::parse`, so the
//! result is always what `str::parse::<f64>` gives.

/// Exact powers of ten as doubles: 10^0 … 10^22.
const POW10: [f64; 23] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
    1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
];

/// The digits from `i`: (mantissa, digits read, next index); the
/// mantissa wraps past 19 digits, which the caller refuses.
#[inline(always)]
fn digits(b: &[u8], mut i: usize, mut m: u64) -> (u64, usize, usize) {
    let start = i;
    while let Some(&c) = b.get(i) {
        let d = c.wrapping_sub(b'0');
        if d > 9 {
            break;
        }
        m = m.wrapping_mul(10).wrapping_add(u64::from(d));
        i += 1;
    }
    (m, i - start, i)
}

/// The number in `b` by the fast path, or None where it does not apply.
#[inline]
fn fast(b: &[u8]) -> Option<f64> {
    let (neg, i) = match b.first()? {
        b'-' => (true, 1),
        b'+' => (false, 1),
        _ => (false, 0),
    };
    let (mut m, int, mut i) = digits(b, i, 0);
    let mut frac = 0;
    if b.get(i) == Some(&b'.') {
        (m, frac, i) = digits(b, i + 1, m);
    }
    // At most 19 digits cannot wrap a u64; m ≤ 2^53 is an exact double.
    if int + frac == 0 || int + frac > 19 || m > 1 << 53 {
        return None;
    }
    let mut exp = -(frac as i32);
    if let Some(b'e' | b'E') = b.get(i) {
        i += 1;
        let eneg = match b.get(i) {
            Some(b'-') => {
                i += 1;
                true
            }
            Some(b'+') => {
                i += 1;
                false
            }
            _ => false,
        };
        let (e, n, j) = digits(b, i, 0);
        if n == 0 || n > 4 {
            return None;
        }
        i = j;
        exp += if eneg { -(e as i32) } else { e as i32 };
    }
    if i != b.len() {
        return None;
    }
    let v = m as f64;
    let v = match exp {
        0 => v,
        1..=22 => v * POW10[exp as usize],
        -22..=-1 => v / POW10[(-exp) as usize],
        _ if m == 0 => 0.0,
        _ => return None,
    };
    Some(if neg { -v } else { v })
}

/// `b` (already trimmed) as `str::parse::<f64>` reads it; None where that
/// fails (not UTF-8, not a number).
#[inline]
pub fn parse(b: &[u8]) -> Option<f64> {
    fast(b).or_else(|| std::str::from_utf8(b).ok()?.parse().ok())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Rng;

    fn same(s: &str) {
        let want = s.parse::<f64>().ok();
        let got = parse(s.as_bytes());
        assert_eq!(got.map(f64::to_bits), want.map(f64::to_bits), "{s:?}");
    }

    /// Every form a record holds, and the forms std refuses, read alike.
    #[test]
    fn reads_as_std_does() {
        for s in [
            "0",
            "-0",
            "-0.0",
            "+5",
            "5.",
            ".5",
            "-.5",
            "1e5",
            "1E-5",
            "2.5e+3",
            "1e22",
            "1e23",
            "1e-22",
            "1e-23",
            "123456789012345",
            "1234567890123456",
            "0.1",
            "0.3",
            "9007199254740993",
            "1e308",
            "1e309",
            "0e400",
            "inf",
            "-inf",
            "NaN",
            "nan",
            "",
            "-",
            ".",
            "e5",
            "1e",
            "1e+",
            "1.2.3",
            "1,5",
            "0x10",
            "1_000",
            "٣",
            "1e-400",
            "00000000000000000001.5",
            "0.000000000000000000000000001",
            "12345.678901234567890",
        ] {
            same(s);
        }
    }

    /// Random decimals as records write them (fixed and exponent forms,
    /// 1 to 19 digits): the same bits as std.
    #[test]
    fn random_decimals_read_as_std_does() {
        let mut rng = Rng::new(7);
        for _ in 0..200_000 {
            let v = (rng.next_f64() - 0.5) * 10f64.powi((rng.next_f64() * 40.0) as i32 - 20);
            let digits = 1 + (rng.next_f64() * 18.0) as usize;
            for s in [
                format!("{v:.digits$}"),
                format!("{v:.digits$e}"),
                format!("{v}"),
            ] {
                same(&s);
            }
        }
    }
}
