#!/usr/bin/env python3
"""Monte Carlo check of the Maxwellian temperature ratio of a binary mixture of hard disks.

Run:   /usr/bin/python3 docs/methods/derivations/mixture_disks_mc.py [--batches 40] [--nper 1000000] [--seed 3]
       (needs numpy and the granmc binary, default build/bin/granmc from the repository root, or GRANMC=...;
       about 5 minutes of one core)

What it checks (docs/methods/derivations/mixture-hcs.md, "Disks"; kernel/theory/mixture_hcs.cpp with dimension 2): at
the gamma = T_1 / T_2 that `granmc theory` prints for a cooling mixture of disks (temperature_ratio_maxwell)
and its chi_ij (jenkins_mancini_chi when dense), the Maxwellian partial cooling rates of the two species,
computed here by Monte Carlo straight from the collision rule in the plane, are equal:

  zeta_i = -(m_i / (2 T_i)) sum_j n_j 2 pi sigma_ij chi_ij E[Theta(g.sig) (g.sig) (|v1'|^2 - |v1|^2)],
  v1 ~ N(0, T_i / m_i), v2 ~ N(0, T_j / m_j) per component, sig uniform on the unit circle,
  v1' = v1 - mu_ji (1 + alpha_ij) (g.sig) sig.

It prints zeta_1 / zeta_2 - 1 with its standard error (from the batches) and exits 1 if |z| > 4.  No project
formula enters the Monte Carlo numbers; granmc's gamma and chi_ij are the inputs under test.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

import numpy as np

MIXTURES = [  # mass, diameter, density of the two species; alpha; packing fraction
    {"m": (2.0, 1.0), "s": (1.0, 1.0), "n": (1.0, 1.0), "alpha": 0.7, "phi": 0.0},
    {"m": (4.0, 1.0), "s": (1.5, 1.0), "n": (0.5, 1.0), "alpha": 0.8, "phi": 0.0},
    {"m": (0.5, 1.0), "s": (2.0, 1.0), "n": (0.2, 1.0), "alpha": 0.6, "phi": 0.3},
]


def theory(granmc, mix):
    species = "".join(f"[[species]]\nname = \"s{k}\"\nmass = {mix['m'][k]}\ndiameter = {mix['s'][k]}\n"
                      f"density = {mix['n'][k]}\nparticles = {round(1000 * mix['n'][k])}\n\n" for k in range(2))
    text = (f"[run]\ndimension = 2\nt_end = 1.0\ndt = 0.01\n\n{species}"
            f"[collision]\nrestitution = {mix['alpha']}\npacking_fraction = {mix['phi']}\n")
    with tempfile.NamedTemporaryFile("w", suffix=".toml", delete=False) as f:
        f.write(text)
    try:
        out = json.loads(subprocess.run([granmc, "theory", f.name], check=True, capture_output=True, text=True).stdout)
    finally:
        os.unlink(f.name)
    chi = out.get("jenkins_mancini_chi", [[1.0, 1.0], [1.0, 1.0]])
    return out["mixture"]["temperature_ratio_maxwell"], chi


def rates(mix, gamma, chi, rng, nper):
    T = (gamma, 1.0)
    zeta = []
    for i in range(2):
        total = 0.0
        for j in range(2):
            mi, mj = mix["m"][i], mix["m"][j]
            v1 = rng.standard_normal((nper, 2)) * math.sqrt(T[i] / mi)
            v2 = rng.standard_normal((nper, 2)) * math.sqrt(T[j] / mj)
            a = rng.uniform(0.0, 2.0 * math.pi, nper)
            sig = np.stack([np.cos(a), np.sin(a)], axis=1)
            gs = ((v1 - v2) * sig).sum(1)
            w = np.where(gs > 0, gs, 0.0)
            v1p = v1 - (mj / (mi + mj)) * (1 + mix["alpha"]) * gs[:, None] * sig
            de = (v1p ** 2).sum(1) - (v1 ** 2).sum(1)
            sij = 0.5 * (mix["s"][i] + mix["s"][j])
            total += mix["n"][j] * 2 * math.pi * sij * chi[i][j] * np.mean(w * de)
        zeta.append(-mix["m"][i] / (2 * T[i]) * total)
    return zeta


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--batches", type=int, default=40)
    p.add_argument("--nper", type=int, default=1_000_000)
    p.add_argument("--seed", type=int, default=3)
    args = p.parse_args()
    granmc = os.environ.get("GRANMC", "build/bin/granmc")
    rng = np.random.default_rng(args.seed)
    worst = 0.0
    print("| m_1/m_2 | sigma_1/sigma_2 | n_1/n_2 | alpha | phi | gamma (granmc) | zeta_1 / zeta_2 - 1 | SE | z |")
    print("|---|---|---|---|---|---|---|---|---|")
    for mix in MIXTURES:
        gamma, chi = theory(granmc, mix)
        r = np.array([np.divide(*rates(mix, gamma, chi, rng, args.nper)) - 1.0 for _ in range(args.batches)])
        mean, se = r.mean(), r.std(ddof=1) / math.sqrt(args.batches)
        worst = max(worst, abs(mean / se))
        print(f"| {mix['m'][0] / mix['m'][1]:g} | {mix['s'][0] / mix['s'][1]:g} | {mix['n'][0] / mix['n'][1]:g} | "
              f"{mix['alpha']} | {mix['phi']} | {gamma:.5f} | {mean:+.5f} | {se:.5f} | {mean / se:+.2f} |")
    print(f"largest |z| = {worst:.2f}")
    sys.exit(0 if worst <= 4.0 else 1)


if __name__ == "__main__":
    main()
