"""E2 = ∫s² dt and E4^¼ = (∫s⁴ dt)^¼ of the ISO 2631-1 Annex A weightings'
responses s(t) to a unit step, from the analog formula with scipy (an
independent check of crates/biodyn/src/iso2631/judgeable.rs; run by hand:
python3 scripts/reference/step_energies.py)."""
import numpy as np
import scipy.signal as sig
from math import pi, sqrt


def poly(f1, f2, f3, f4, q4, f5, q5, f6, q6):
    w = lambda f: 2 * pi * f
    q = 1 / sqrt(2)
    hp = ([1, 0, 0], [1, w(f1) / q, w(f1) ** 2])
    lp = ([w(f2) ** 2], [1, w(f2) / q, w(f2) ** 2])
    # (1 + s/ω3) / (1 + s/(Q4 ω4) + (s/ω4)²)
    av = (np.array([1 / w(f3), 1]) * w(f4) ** 2, [1, w(f4) / q4, w(f4) ** 2])
    st = ([1], [1])
    if f5 is not None:
        # (1 + s/(Q5 ω5) + (s/ω5)²) / (1 + s/(Q6 ω6) + (s/ω6)²) · (ω5/ω6)²
        num = np.array([1 / w(f5) ** 2, 1 / (q5 * w(f5)), 1]) * w(f6) ** 2 * (w(f5) / w(f6)) ** 2
        st = (num, [1, w(f6) / q6, w(f6) ** 2])
    n = np.polymul(np.polymul(hp[0], lp[0]), np.polymul(av[0], st[0]))
    d = np.polymul(np.polymul(hp[1], lp[1]), np.polymul(av[1], st[1]))
    return n, d


for name, args in [
    ("Wk", (0.4, 100, 12.5, 12.5, 0.63, 2.37, 0.91, 3.35, 0.91)),
    ("Wd", (0.4, 100, 2, 2, 0.63, None, 0, 0, 0)),
]:
    n, d = poly(*args)
    w, h = sig.freqs(n, d, worN=[2 * pi * 1, 2 * pi * 6.31, 2 * pi * 10])
    t = np.linspace(0, 200, 400001)
    t, y = sig.step((n, d), T=t)
    dt = t[1] - t[0]
    print(name, "|W| at 1, 6.31, 10 Hz", np.round(abs(h), 4),
          "E2 %.5f" % (np.sum(y ** 2) * dt), "E4^1/4 %.5f" % ((np.sum(y ** 4) * dt) ** 0.25))
