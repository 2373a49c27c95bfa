#!/usr/bin/env python3
"""The scipy figures docs/speed.md sets beside the library's: what the same
work costs through scipy.signal.lsim and scipy.optimize.least_squares.

  1. lsim of the paper's 75 kg 4-DOF chain under a seat acceleration, 4096
     samples at 1 kHz, every state as an output (the library's bench:
     simulate/paper_4dof_every_output);
  2. lsim of the ISO 2631-1 Wk weighting (its four filters as one transfer
     function), 4096 samples at 1 kHz (the library's weighting/Wk);
  3. least_squares (its defaults: trf, 2-point Jacobian) on the fit bench's
     problem: the 8 links' k and c (in ln p) from STHT and APMS magnitude
     (ln) and phase (rad) at 0.5–20 Hz in 0.1 Hz steps (196 frequencies),
     one start at the paper's values. The data are made as the bench makes
     them (the same changed chain, 3 % magnitude and 2° phase noise) but
     with numpy's random numbers, so the problem is the same kind, not the
     same bits (crates/biodyn/benches/fit.rs: fit/links_stht_apms_phase_196f_8starts).

Each is timed REPEATS times (default 7) and the median printed. Needs:
python3 with numpy and scipy (`python3 -m venv /tmp/sv && /tmp/sv/bin/pip
install scipy`). Run: `/tmp/sv/bin/python scripts/speed/scipy_compare.py`.
"""

import os
import statistics
import time

import numpy as np
import scipy
from scipy import optimize, signal

REPEATS = int(os.environ.get("REPEATS", "7"))
SHARES = np.array([0.075, 0.402, 0.122, 0.182])
K = np.array([310000.0, 183000.0, 162800.0, 90000.0])
C = np.array([400.0, 4750.0, 4585.0, 2064.0])
M = SHARES * 75.0


def median_time(fn):
    times = []
    for _ in range(REPEATS):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def chain_state_space(m, k, c):
    """x = displacement relative to the seat, input the seat's acceleration:
    M x'' + C x' + K x = −M 1 a."""
    n = len(m)
    kk = np.zeros((n, n))
    cc = np.zeros((n, n))
    for i in range(n):
        j = i + 1  # link i joins segment i to i+1, the last to the seat
        for mat, v in ((kk, k[i]), (cc, c[i])):
            mat[i, i] += v
            if j < n:
                mat[j, j] += v
                mat[i, j] -= v
                mat[j, i] -= v
    minv = np.diag(1.0 / m)
    a = np.block([[np.zeros((n, n)), np.eye(n)], [-minv @ kk, -minv @ cc]])
    b = np.concatenate([np.zeros(n), -np.ones(n)])[:, None]
    return a, b, np.eye(2 * n), np.zeros((2 * n, 1))


def wk():
    w = lambda f: 2 * np.pi * f  # noqa: E731
    w1, w2, w3, w4, w5, w6 = w(0.4), w(100.0), w(12.5), w(12.5), w(2.37), w(3.35)
    q1 = q2 = 1 / np.sqrt(2)
    q4, q5, q6 = 0.63, 0.91, 0.91
    parts = [
        ([1, 0, 0], [1, w1 / q1, w1**2]),
        ([w2**2], [1, w2 / q2, w2**2]),
        ([1 / w3, 1], [1 / w4**2, 1 / (w4 * q4), 1]),
        (np.array([1, w5 / q5, w5**2]) * w6**2 / w5**2, [1, w6 / q6, w6**2]),
    ]
    num, den = np.array([1.0]), np.array([1.0])
    for n_, d_ in parts:
        num, den = np.polymul(num, n_), np.polymul(den, d_)
    return num, den


def responses(m, k, c, f):
    """STHT and APMS of the chain at the frequencies f (a batched solve)."""
    n = len(m)
    wv = 2 * np.pi * f
    z = k[None, :] + 1j * wv[:, None] * c[None, :]
    a = np.zeros((len(f), n, n), complex)
    rhs = np.zeros((len(f), n), complex)
    for i in range(n):
        a[:, i, i] += -(wv**2) * m[i] + z[:, i]
        if i + 1 < n:
            a[:, i + 1, i + 1] += z[:, i]
            a[:, i, i + 1] -= z[:, i]
            a[:, i + 1, i] -= z[:, i]
        else:
            rhs[:, i] += z[:, i]  # the seat moves with amplitude 1
    x = np.linalg.solve(a, rhs[..., None])[..., 0]
    return x[:, 0], x @ m  # head/seat, Σ m X (APMS)


def main():
    print(f"python {os.sys.version.split()[0]}, numpy {np.__version__}, scipy {scipy.__version__}")
    fs, n = 1000.0, 4096
    t = np.arange(n) / fs
    rng = np.random.default_rng(1)
    u = rng.standard_normal(n)

    sys4 = chain_state_space(M, K, C)
    s = median_time(lambda: signal.lsim(sys4, u, t))
    print(f"lsim, 4-DOF chain, every state, {n} samples: {s * 1e3:.1f} ms median, {s / n * 1e6:.2f} µs a sample")
    num, den = wk()
    s = median_time(lambda: signal.lsim((num, den), u, t))
    print(f"lsim, Wk weighting, {n} samples: {s * 1e3:.1f} ms median, {s / n * 1e6:.2f} µs a sample")

    f = np.round(np.arange(0.5, 20.0 + 1e-9, 0.1), 10)
    kt, ct = K.copy(), C.copy()
    kt[0] *= 1.6
    kt[1] *= 0.7
    kt[3] *= 2.0
    ct[1] *= 0.5
    ct[2] *= 1.5
    h, a = responses(M, kt, ct, f)
    cols = []
    for y in (h, a):
        cols.append(np.abs(y) * (1 + 0.03 * rng.standard_normal(len(f))))
        cols.append(np.angle(y) + np.radians(2.0) * rng.standard_normal(len(f)))
    target = np.concatenate([np.log(cols[0]), cols[1], np.log(cols[2]), cols[3]])

    def residual(lp):
        p = np.exp(lp)
        h, a = responses(M, p[:4], p[4:], f)
        model = np.concatenate([np.log(np.abs(h)), np.angle(h), np.log(np.abs(a)), np.angle(a)])
        r = model - target
        r[len(f):2 * len(f)] = np.angle(np.exp(1j * r[len(f):2 * len(f)]))
        r[3 * len(f):] = np.angle(np.exp(1j * r[3 * len(f):]))
        return r

    start = np.log(np.concatenate([K, C]))
    res = optimize.least_squares(residual, start)
    s = median_time(lambda: optimize.least_squares(residual, start))
    print(f"least_squares, 8 parameters, {len(target)} residuals, one start: {s * 1e3:.1f} ms median "
          f"({res.nfev} evaluations, cost {res.cost:.4g}, status {res.status})")


if __name__ == "__main__":
    main()
