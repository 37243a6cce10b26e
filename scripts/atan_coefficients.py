#!/usr/bin/env python3
"""Derives the polynomial of core/src/util/atan2_pair.h and reports its error.

atan(w) = w + w s P(s) with s = w^2 and |w| <= 1/2. P interpolates
(atan(w) / w - 1) / s at the Chebyshev points of s in [0, 1/4]; its
coefficients are solved for in 60 digits and rounded to double, and the
error of w + w s P(s) with those rounded coefficients (evaluated exactly)
is reported in units of 2^-53 relative to atan(w).

Needs Debian's python3-mpmath. Prints the coefficients as C hex literals.
"""
import mpmath as mp

mp.mp.dps = 60
TERMS = 12
S_MAX = mp.mpf(1) / 4


def reduced(s):
    w = mp.sqrt(s)
    return (mp.atan(w) / w - 1) / s


def main():
    nodes = [S_MAX / 2 * (1 + mp.cos(mp.pi * (k + mp.mpf(1) / 2) / TERMS)) for k in range(TERMS)]
    system = mp.matrix([[s**j for j in range(TERMS)] for s in nodes])
    values = mp.matrix([reduced(s) for s in nodes])
    coefficients = [float(c) for c in mp.lu_solve(system, values)]

    worst = 0
    for i in range(1, 4001):
        s = S_MAX * i / 4000
        w = mp.sqrt(s)
        p = sum(mp.mpf(c) * s**j for j, c in enumerate(coefficients))
        worst = max(worst, abs((w + w * s * p) / mp.atan(w) - 1))
    print(",\n".join(c.hex() for c in coefficients))
    print(f"largest relative error: {float(worst / mp.mpf(2)**-53):.3f} x 2^-53")


if __name__ == "__main__":
    main()
