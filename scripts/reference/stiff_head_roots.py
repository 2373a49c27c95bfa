#!/usr/bin/env python3
"""The mpmath roots behind two tests in crates/biodyn/tests/physics/big_models.rs.

`stiff_light_head_modes_are_right` (60 digits) and
`stiff_light_head_on_a_heavy_chest_is_right` (80 digits) hold the library's
modes against the roots of det(K + λC + λ²M) of the paper's 75 kg chain with
the head at 1e-6 kg on k1 = 1e12 N/m (and, in the second, the chest at
1e6 kg). The determinant is expanded here as a polynomial in λ with mpmath's
arbitrary precision and its roots found with mpmath.polyroots; nothing of the
crate is used. Each mode's natural frequency is |λ|/2π (a complex pair is one
mode, a real root one mode), sorted as the library sorts them (ascending).

Needs: python3 with mpmath (`python3 -m venv /tmp/mp && /tmp/mp/bin/pip install
mpmath`). Run: `/tmp/mp/bin/python scripts/reference/stiff_head_roots.py`.
It prints each case's frequencies beside the test's constants and the
largest relative difference, and exits non-zero if one exceeds the test's
tolerance.
"""

import sys

import mpmath as mp

# The paper's Table 1 (crates/biodyn/src/body, presets/paper-75kg.toml):
# shares of the body mass, top to bottom, and the links k (N/m), c (N·s/m),
# link i joining segment i to i+1, the last one to the seat (held still).
SHARES = [0.075, 0.402, 0.122, 0.182]
K = [310000.0, 183000.0, 162800.0, 90000.0]
C = [400.0, 4750.0, 4585.0, 2064.0]

# The constants in big_models.rs and each test's relative tolerance.
CASES = [
    (
        "stiff_light_head_modes_are_right",
        60,
        {},
        [5.3239824, 6.0215432, 7.2434168, 46.635377, 200.71864, 1.5915495e8],
        2e-7,
    ),
    (
        "stiff_light_head_on_a_heavy_chest_is_right",
        80,
        {1: 1e6},
        [0.033391224, 6.024030983, 7.930541254, 34.15326809, 191.7909338, 1.591549431e8],
        1e-8,
    ),
]


def poly_mul(a, b):
    out = [mp.mpf(0)] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        for j, y in enumerate(b):
            out[i + j] += x * y
    return out


def poly_add(a, b):
    n = max(len(a), len(b))
    a = a + [mp.mpf(0)] * (n - len(a))
    b = b + [mp.mpf(0)] * (n - len(b))
    return [x + y for x, y in zip(a, b)]


def det_poly(m, k, c):
    """det(K + λC + λ²M) of the chain by the continuant (three-term) recurrence,
    as coefficients in ascending powers of λ."""
    n = len(m)
    z = [[mp.mpf(k[i]), mp.mpf(c[i])] for i in range(n)]  # k + λc of link i
    diag = []
    for i in range(n):
        d = poly_add([mp.mpf(0), mp.mpf(0), mp.mpf(m[i])], z[i])
        if i > 0:
            d = poly_add(d, z[i - 1])
        diag.append(d)
    # D_i = diag_i · D_{i-1} − z_{i-1}² · D_{i-2}; the off-diagonals are −z.
    prev, cur = [mp.mpf(1)], diag[0]
    for i in range(1, n):
        nxt = poly_add(poly_mul(diag[i], cur), [-x for x in poly_mul(poly_mul(z[i - 1], z[i - 1]), prev)])
        prev, cur = cur, nxt
    return cur


def modes_hz(m, k, c):
    coeffs = det_poly(m, k, c)
    roots = mp.polyroots(list(reversed(coeffs)), maxsteps=2000, extraprec=4 * mp.mp.prec)
    out = []
    for r in roots:
        if mp.im(r) < 0:
            continue  # the conjugate's twin stands for the pair
        kind = "pair" if mp.im(r) > 0 else "real"
        out.append((abs(r) / (2 * mp.pi), kind, r))
    out.sort(key=lambda t: t[0])
    return out


def main():
    worst_ok = True
    for name, dps, overrides, want, tol in CASES:
        mp.mp.dps = dps
        # The masses as the crate computes them: share × 75.0 in f64, then
        # the test's direct settings.
        m = [s * 75.0 for s in SHARES]
        m[0] = 1e-6
        for i, v in overrides.items():
            m[i] = v
        k = list(K)
        k[0] = 1e12
        got = modes_hz(m, k, C)
        print(f"{name} (mpmath {dps} digits, {len(got)} modes):")
        worst = mp.mpf(0)
        for (hz, kind, r), w in zip(got, want):
            rel = abs(hz - w) / w
            worst = max(worst, rel)
            extra = ""
            if kind == "pair":
                extra = f", damped {mp.nstr(mp.im(r) / (2 * mp.pi), 10)} Hz"
            print(f"  {mp.nstr(hz, 12):>20} Hz ({kind}{extra})   test {w!r:<14} rel {mp.nstr(rel, 2)}")
        ok = len(got) == len(want) and worst <= tol
        worst_ok &= ok
        print(f"  largest relative difference {mp.nstr(worst, 2)} (test tolerance {tol}): {'ok' if ok else 'MISMATCH'}")
    sys.exit(0 if worst_ok else 1)


if __name__ == "__main__":
    main()
