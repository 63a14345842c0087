#!/usr/bin/env python3
"""Reference values of the exact motion's precession angle ψ(t) for
tests/physics/exact_solution_test.cpp (ExactSolutionPrecession.MatchesMpmath), computed with
mpmath at 40 digits independently of the C++ code's closed form: ω's amplitudes, k and λ from
docs/physics.md §8, sn from mpmath's ellipfun, and ψ(t) = ∫_0^t ψ̇ dt' by mpmath's quad of
ψ̇ = |L| (2E − I_r ω_r²)/(|L|² − I_r² ω_r²), split at every quarter period K of u.
Not run by the tests (minutes per motion); run it to regenerate the table:

    python3 tests/physics/exact_mpmath_reference.py "2 1 3" "0.3 -0.5 0.7" …

Each pair of arguments is the principal moments (body x, y, z) and ω0 (body frame); each output
line one row of the test's table, ψ at t = 0.7, 13.1, 104.4, 1234.5.

With --quarter first, the rows of ExactSolutionPrecession.MatchesMpmathNearTheQuarterPeriod
instead: t where u = λt + u0 is at the multiples QUARTER of K (after two half periods, mostly
near |sn u| = 1, where the code takes S(u) from the base point nearest K; t rounded to a double
and printed exactly), ψ there.
"""
import sys

import mpmath as mp

mp.mp.dps = 40
TIMES = ["0.7", "13.1", "104.4", "1234.5"]
QUARTER = ["4.5", "4.9", "4.97", "4.99", "4.999", "4.999999", "5", "5.000001", "5.01", "5.5", "6.7"]


def precession(I, w):
    """ψ(t) (a function of an mpf t) for moments I and body-frame ω0 w."""
    I = [mp.mpf(x) for x in I]
    w = [mp.mpf(x) for x in w]
    order = sorted(range(3), key=lambda i: I[i])
    Is = [I[i] for i in order]
    ws = [w[i] for i in order]
    # A proper rotation (det +1) sorts the axes: an odd permutation negates the third component.
    inversions = sum(1 for a in range(3) for b in range(a + 1, 3) if order[a] > order[b])
    if inversions % 2:
        ws[2] = -ws[2]
    I1, I2, I3 = Is
    w1, w2, w3 = ws
    L2 = sum(a * a * b * b for a, b in zip(Is, ws))
    E2 = sum(a * b * b for a, b in zip(Is, ws))
    L = mp.sqrt(L2)
    d3 = I1 * (I3 - I1) * w1 ** 2 + I2 * (I3 - I2) * w2 ** 2
    d1 = I2 * (I2 - I1) * w2 ** 2 + I3 * (I3 - I1) * w3 ** 2
    d2 = I3 * (I3 - I2) * w3 ** 2 - I1 * (I2 - I1) * w1 ** 2
    if d2 > 0:  # case A: ω circles axis 3
        c, r = 0, 2
        m = (I2 - I1) * d3 / ((I3 - I2) * d1)
        lam = mp.sqrt((I3 - I2) * d1 / (I1 * I2 * I3))
        amp = [mp.sqrt(d3 / (I1 * (I3 - I1))), mp.sqrt(d3 / (I2 * (I3 - I2))), mp.sqrt(d1 / (I3 * (I3 - I1)))]
    else:  # case B: ω circles axis 1
        c, r = 2, 0
        m = (I3 - I2) * d1 / ((I2 - I1) * d3)
        lam = mp.sqrt((I2 - I1) * d3 / (I1 * I2 * I3))
        amp = [mp.sqrt(d3 / (I1 * (I3 - I1))), mp.sqrt(d1 / (I2 * (I2 - I1))), mp.sqrt(d1 / (I3 * (I3 - I1)))]
    s_dn = -1 if ws[r] < 0 else 1
    cn0 = ws[c] / (amp[c] * s_dn)
    sn0 = ws[1] / amp[1]
    u0 = mp.ellipf(mp.atan2(sn0, cn0), m)
    K = mp.ellipk(m)

    def rate(u):
        wr2 = amp[r] ** 2 * (1 - m * mp.ellipfun("sn", u, m=m) ** 2)
        return L * (E2 - Is[r] * wr2) / (L2 - Is[r] ** 2 * wr2)

    def psi(t):
        u = lam * t + u0
        points = [u0]
        q = mp.ceil(u0 / K)
        while q * K < u:
            points.append(q * K)
            q += 1
        points.append(u)
        return mp.quad(rate, points) / lam

    psi.time_at = lambda f: (f * K - u0) / lam  # t where u = f K
    return psi


def main(args):
    quarter = bool(args) and args[0] == "--quarter"
    if quarter:
        args = args[1:]
    for I, w in zip(args[0::2], args[1::2]):
        if quarter:
            psi = precession([float(x) for x in I.split()], [float(x) for x in w.split()])
            rows = []
            for f in QUARTER:
                t = float(psi.time_at(mp.mpf(f)))  # the double the test evaluates at
                rows.append(f"{{{t!r}, {mp.nstr(psi(mp.mpf(t)), 22)}}}")
            print(f'{{"({I.replace(" ", ", ")}) ω0 ({w.replace(" ", ", ")})", {{{I.replace(" ", ", ")}}}, '
                  f'{{{w.replace(" ", ", ")}}}, {{{", ".join(rows)}}}}},', flush=True)
            continue
        psi = precession([float(x) for x in I.split()], [float(x) for x in w.split()])
        values = ", ".join(mp.nstr(psi(mp.mpf(t)), 22) for t in TIMES)
        print(f'{{"({I.replace(" ", ", ")}) ω0 ({w.replace(" ", ", ")})", {{{I.replace(" ", ", ")}}}, '
              f'{{{w.replace(" ", ", ")}}}, {{{values}}}}},', flush=True)


if __name__ == "__main__":
    main(sys.argv[1:])
