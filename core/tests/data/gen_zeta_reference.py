# Generates high-precision reference values for the Hurwitz zeta tests:
#   zeta_reference.csv        -- columns s,a,zeta  : zeta(s, a) = sum_{k>=0} (a+k)^(-s)
#   partial_sum_reference.csv -- columns s,a,n,sum : S(s,a,n) = sum_{k=0}^{n} (a+k)^(-s)
# Values are computed by mpmath at 50 significant digits (mp.dps = 50) and
# written with 25 significant digits. s and a are written with repr(float) and
# the reference is computed for exactly that binary f64 value.
# Rerun from the repo root with:  python3 core/tests/data/gen_zeta_reference.py
# (requires `pip install mpmath`)

import os

import mpmath
from mpmath import mp, mpf

mp.dps = 50

HERE = os.path.dirname(os.path.abspath(__file__))

S_VALUES = [1.0000001, 1.000001, 1.001, 1.01, 1.05, 1.1, 1.2, 1.25, 1.3, 1.32,
            1.4, 1.48, 1.5, 1.5224, 2.0, 2.5, 3.0, 3.5, 4.0]
A_VALUES = [1e-6, 0.001, 0.1, 0.5, 1.0, 1.5, 2.0, 3.0, 7.25, 10.0, 100.0,
            12345.678, 1e6]

ZETA_PAIRS = [
    # awkward corners
    (1.0000001, 1e-6), (1.0000001, 1e6), (1.001, 1.0), (4.0, 1e-6),
    (4.0, 1e6), (1.3, 1.0), (2.0, 1.0), (4.0, 1.0), (1.5, 1e6),
    (1.01, 0.001), (3.0, 0.5),
    # coverage
    (1.0000001, 1.0), (1.000001, 0.1), (1.000001, 100.0), (1.001, 12345.678),
    (1.01, 7.25), (1.05, 0.5), (1.05, 10.0), (1.1, 1.5), (1.1, 1e6),
    (1.1, 10.0), (1.2, 0.001), (1.2, 3.0), (1.25, 2.0), (1.25, 100.0),
    (1.3, 1e-6), (1.32, 0.1), (1.32, 12345.678), (1.4, 7.25), (1.4, 1.0),
    (1.48, 0.5), (1.48, 2.0), (1.5, 1.0), (1.5, 1.5), (1.5224, 3.0),
    (1.5224, 10.0), (2.0, 0.5), (2.0, 1e6), (2.0, 1e-6), (2.5, 0.001),
    (2.5, 1.5), (3.0, 1.0), (3.0, 100.0), (3.5, 0.1), (3.5, 12345.678),
    (4.0, 7.25),
]

PARTIAL_CASES = [
    (0.6, 1.0, 0), (0.6, 1.0, 1000000), (0.62, 2.0, 10),
    (0.62, 0.5, 10000000), (0.66, 1.0, 1000), (0.66, 3.5, 1000000),
    (0.7, 0.5, 1), (0.7, 1.0, 10000000), (0.74, 2.0, 1000), (0.74, 3.5, 10),
    (1.0, 1.0, 10), (1.0, 1.0, 10000000), (1.0, 0.5, 1000000),
    (1.3, 3.5, 0), (1.3, 1.0, 1000000), (2.0, 2.0, 10000000),
    (2.0, 0.5, 1000),
]


def check_coverage():
    for s in S_VALUES:
        assert sum(1 for p in ZETA_PAIRS if p[0] == s) >= 2, s
    for a in A_VALUES:
        assert sum(1 for p in ZETA_PAIRS if p[1] == a) >= 2, a
    assert len(set(ZETA_PAIRS)) == len(ZETA_PAIRS)


def hurwitz(s, a):
    return mpmath.zeta(mpf(float(s)), mpf(float(a)))


def partial_sum(s, a, n):
    s, a = mpf(float(s)), mpf(float(a))
    if s == 1:
        return mpmath.digamma(a + n + 1) - mpmath.digamma(a)
    return mpmath.zeta(s, a) - mpmath.zeta(s, a + n + 1)


def direct_sum(s, a, n):
    s, a = mpf(float(s)), mpf(float(a))
    return mpmath.fsum((a + k) ** (-s) for k in range(n + 1))


def main():
    check_coverage()

    # Sanity checks against closed forms.
    assert abs(hurwitz(2.0, 1.0) - mp.pi ** 2 / 6) < mpf(10) ** -45
    assert abs(hurwitz(4.0, 1.0) - mp.pi ** 4 / 90) < mpf(10) ** -45
    assert abs(hurwitz(3.0, 0.5) - 7 * mpmath.zeta(3)) < mpf(10) ** -45

    with open(os.path.join(HERE, "zeta_reference.csv"), "w") as f:
        f.write("s,a,zeta\n")
        for s, a in ZETA_PAIRS:
            s, a = float(s), float(a)
            v = hurwitz(s, a)
            # Cross-check at higher precision.
            with mp.workdps(80):
                w = hurwitz(s, a)
            assert abs(v - w) <= abs(w) * mpf(10) ** -40, (s, a)
            f.write("%r,%r,%s\n" % (s, a, mpmath.nstr(v, 25)))

    with open(os.path.join(HERE, "partial_sum_reference.csv"), "w") as f:
        f.write("s,a,n,sum\n")
        for s, a, n in PARTIAL_CASES:
            s, a = float(s), float(a)
            v = partial_sum(s, a, n)
            with mp.workdps(80):
                w = partial_sum(s, a, n)
            assert abs(v - w) <= abs(w) * mpf(10) ** -40, (s, a, n)
            if n <= 1000:
                d = direct_sum(s, a, n)
                assert abs(v - d) <= abs(d) * mpf(10) ** -40, (s, a, n, v, d)
            f.write("%r,%r,%d,%s\n" % (s, a, n, mpmath.nstr(v, 25)))


if __name__ == "__main__":
    main()
