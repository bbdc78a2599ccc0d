#!/usr/bin/env python3
"""Monte Carlo check of the d-general first-Sonine coefficients behind the shear viscosity of disks.

Run:   /usr/bin/python3 docs/methods/derivations/viscosity_disks_mc.py [--batches 200] [--nper 1000000] [--seed 11]
       (needs numpy; about 10 minutes of one core with the defaults, which print the table of
       docs/methods/derivations/viscosity.md sec. 9; the a2 parts have heavy-tailed integrands, so fewer batches give
       a rougher standard error)

What it checks (docs/methods/derivations/viscosity.md sec. 9, kernel/theory/viscosity.cpp shear_viscosity in d = 2,
kernel/theory/steady_shear.cpp), one species, dilute, in d = 3 (as a control: the forms there are derived
exactly in sec. 3) and d = 2, alpha in {1, 0.7}:

  nu_eta* = (3 / (4 d)) (1 - alpha + 2 d / 3)(1 + alpha)(1 - a2 / 32),
  zeta*   = ((d + 2) / (4 d)) (1 - alpha^2)(1 + 3 a2 / 16),

in units of nu0 = n T / eta0, eta0 = ((d + 2) / 8) Gamma(d / 2) pi^(-(d - 1) / 2) sigma^(1 - d) sqrt(m T): the
Maxwellian parts (a2 = 0) and the coefficients of a2, each as a ratio to the Maxwellian part.

Monte Carlo straight from the collision rule, no project formula in the MC numbers.  Units n = sigma = m = T = 1.
v1, v2 ~ N(0, 1) per component, sig uniform on the unit sphere (circle), g = v1 - v2,
v1' = v1 - ((1 + alpha) / 2) (g.sig) sig.  Particle 1 collides at the rate S_d Theta(g.sig) (g.sig) per unit
solid angle fraction (S_3 = 4 pi, S_2 = 2 pi).  With f0 = fM (1 + a2 S2(V^2 / 2)), S2(x) = x^2 / 2 - (d + 2) x / 2
+ d (d + 2) / 8, and the shear part f1 = eps fM V_x V_y (<V_x V_y>_f1 = eps):

  nu_eta = -E[S_d Theta (g.sig) Delta(v1x v1y) (W(v1) phi(v2) + phi(v1) W(v2))],  phi = v_x v_y, W = 1 + a2 S2,
  zeta   = -(1 / d) E[S_d Theta (g.sig) Delta(|v1|^2) W(v1) W(v2)]  (to first order in a2).

Each expectation is linear in a2: its a2^0 and a2^1 parts are estimated separately, with standard errors from
the batches.  The script prints z = (MC - formula) / standard error and exits 1 if any |z| > 4.
"""
import argparse
import math
import sys

import numpy as np


def estimates(d, alpha, rng, batches, nper):
    area = 2 * math.pi if d == 2 else 4 * math.pi
    nu0 = 1.0 / (((d + 2) / 8) * math.gamma(d / 2) * math.pi ** (-(d - 1) / 2))
    rows = []
    for _ in range(batches):
        v1 = rng.standard_normal((nper, d))
        v2 = rng.standard_normal((nper, d))
        sig = rng.standard_normal((nper, d))
        sig /= np.linalg.norm(sig, axis=1)[:, None]
        gs = ((v1 - v2) * sig).sum(1)
        rate = area * np.where(gs > 0, gs, 0.0)
        v1p = v1 - ((1 + alpha) / 2) * gs[:, None] * sig

        def s2(v):
            x = 0.5 * (v ** 2).sum(1)
            return x * x / 2 - (d + 2) * x / 2 + d * (d + 2) / 8

        phi1, phi2 = v1[:, 0] * v1[:, 1], v2[:, 0] * v2[:, 1]
        dpsi = v1p[:, 0] * v1p[:, 1] - phi1
        de = (v1p ** 2).sum(1) - (v1 ** 2).sum(1)
        rows.append([-np.mean(rate * dpsi * (phi1 + phi2)) / nu0,
                     -np.mean(rate * dpsi * (s2(v1) * phi2 + phi1 * s2(v2))) / nu0,
                     -np.mean(rate * de) / d / nu0,
                     -np.mean(rate * de * (s2(v1) + s2(v2))) / d / nu0])
    rows = np.array(rows)
    return rows.mean(0), rows.std(0, ddof=1) / math.sqrt(batches)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--batches", type=int, default=200)
    p.add_argument("--nper", type=int, default=1_000_000)
    p.add_argument("--seed", type=int, default=11)
    args = p.parse_args()
    rng = np.random.default_rng(args.seed)
    worst = 0.0
    print("| d | alpha | quantity | Monte Carlo | SE | formula | z |")
    print("|---|---|---|---|---|---|---|")
    for d in (3, 2):
        for alpha in (1.0, 0.7):
            m, se = estimates(d, alpha, rng, args.batches, args.nper)
            nu = 3 / (4 * d) * (1 - alpha + 2 * d / 3) * (1 + alpha)
            zeta = (d + 2) / (4 * d) * (1 - alpha ** 2)
            # The a2 parts against the formula's: nu_eta's is -nu / 32, zeta's 3 zeta / 16.
            checks = [("nu_eta*, a2^0", m[0], se[0], nu), ("nu_eta*, a2^1", m[1], se[1], -nu / 32),
                      ("zeta*, a2^0", m[2], se[2], zeta), ("zeta*, a2^1", m[3], se[3], 3 * zeta / 16)]
            for name, value, error, formula in checks:
                z = (value - formula) / error
                worst = max(worst, abs(z))
                print(f"| {d} | {alpha} | {name} | {value:.5f} | {error:.5f} | {formula:.5f} | {z:+.2f} |")
    print(f"largest |z| = {worst:.2f}")
    sys.exit(0 if worst <= 4.0 else 1)


if __name__ == "__main__":
    main()
