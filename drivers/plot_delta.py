#!/usr/bin/env python3
"""Delta_i(v*) of paper 000 eq. 19 from a granmc run, against the first Sonine polynomial (eq. 20).

Usage: /usr/bin/python3 drivers/plot_delta.py RESULT.h5 OUT.png [--species 0] [--theory-json THEORY.json]

Phi_i(v*) = (lambda_i/pi)^(3/2) exp(-lambda_i v*^2) [1 + (c_i/2) Delta_i(v*)], lambda_i = T / (T_i mu_ji),
(the first Sonine term gives Delta_i = S2(lambda_i v*^2), eq. 20; the next one adds (a3_i/a2_i) S3, drawn with
the measured a3_i),
c_i = 2 a2_i. Per replica: Phi_i from the speed histogram (shell averages), c_i and T/T_i from the time
averages over the same samples (the last half), and the Maxwellian averaged over each shell exactly (erf),
so binning does not bias Delta; then the replica mean and CI (lambda_p = 3.2, 001 eq. 31). The theory line
is eq. 20 with lambda_i of the first-Sonine temperature ratio (from `granmc theory`, optional).
"""
import argparse
import json
import math
import sys

import numpy as np

from granmc import mean_ci
from granmc.plotting import pyplot, save


def shell_maxwell(lam, edges):
    """Average over each shell of (lam/pi)^(3/2) exp(-lam v^2), per d^3 v."""
    def cumulative(v):  # integral of 4 pi v^2 (lam/pi)^1.5 exp(-lam v^2) from 0 to v
        x = math.sqrt(lam) * v
        return math.erf(x) - 2.0 / math.sqrt(math.pi) * x * math.exp(-x * x)
    volumes = 4.0 * math.pi / 3.0 * (edges[1:] ** 3 - edges[:-1] ** 3)
    return np.array([cumulative(b) - cumulative(a) for a, b in zip(edges[:-1], edges[1:])]) / volumes


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("result")
    p.add_argument("out")
    p.add_argument("--species", type=int, default=0)
    p.add_argument("--theory-json", help="output of `granmc theory` for the scene")
    p.add_argument("--table", help="write a Markdown table of Delta here")
    args = p.parse_args()
    from granmc import open_results
    with open_results(args.result) as f:
        edges = f["speed_shell_edges"][()]
        groups = sorted(f["species"].values(), key=lambda g: int(g.attrs["index"]))
        if len(groups) != 2:
            sys.exit("plot_delta.py: needs a two-species run (000 eq. 19 uses mu_ji)")
        i, j = args.species, 1 - args.species
        gi = groups[i]
        m = [float(g.attrs["mass"]) for g in groups]
        n_particles = [int(g.attrs["particles"]) for g in groups]
        x = [n / sum(n_particles) for n in n_particles]  # mole fractions (N_i/N = n_i/n)
        counts = gi["speed_distribution/counts"][()]          # R x K
        samples = f["counters/histogram_samples"][()]          # R
        times = f["times"][()]
        first = (len(times) - 1) // 2
        t_i = gi["temperature/replicas"][()][:, first:].mean(axis=1)
        t_j = groups[j]["temperature/replicas"][()][:, first:].mean(axis=1)
        a2 = gi["a2/replicas"][()][:, first:].mean(axis=1)
        a3 = gi["a3/replicas"][()][:, first:].mean(axis=1) if "a3" in gi else None
        scene = f.attrs["scene"]
    mu_ji = m[j] / (m[i] + m[j])
    volumes = 4.0 * np.pi / 3.0 * (edges[1:] ** 3 - edges[:-1] ** 3)
    centres = 0.5 * (edges[1:] + edges[:-1])
    deltas, lams, cs = [], [], []
    for r in range(counts.shape[0]):
        t_mix = x[i] * t_i[r] + x[j] * t_j[r]
        lam = t_mix / (t_i[r] * mu_ji)                      # 000 after eq. (19)
        phi = counts[r] / (n_particles[i] * samples[r] * volumes)
        c = 2.0 * a2[r]
        deltas.append((phi / shell_maxwell(lam, edges) - 1.0) * 2.0 / c)
        lams.append(lam)
        cs.append(c)
    deltas = np.array(deltas)
    mean, ci = mean_ci(deltas)
    lam = float(np.mean(lams))
    c = float(np.mean(cs))
    _, c_ci = mean_ci(cs)

    lam_theory = None
    if args.theory_json:
        with open(args.theory_json) as fh:
            th = json.load(fh)["mixture"]
        gamma = th["temperature_ratio_sonine"] if i == 0 else 1.0 / th["temperature_ratio_sonine"]
        lam_theory = (x[i] + x[j] / gamma) / mu_ji           # T/T_i = x_i + x_j T_j/T_i
    v = np.linspace(0.0, edges[-1], 200)
    sonine = lambda l: 0.5 * l * l * v ** 4 - 2.5 * l * v ** 2 + 15.0 / 8.0   # 000 eq. (20)
    s3 = lambda z: -z ** 3 / 6.0 + 7.0 * z ** 2 / 4.0 - 35.0 * z / 8.0 + 35.0 / 16.0  # Sonine S3, z = lambda v*^2

    plt = pyplot()
    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    shown = counts.sum(axis=0) > 100  # shells with enough particles to say anything
    ax.errorbar(centres[shown], mean[shown], yerr=ci[shown], fmt="o", ms=3, capsize=2,
                label=f"granmc, species {i + 1} (c = {c:.4f} +- {c_ci:.4f})")
    ax.plot(v, sonine(lam), "k--", linewidth=1.0, label=f"eq. 20 with measured lambda = {lam:.3f}")
    if a3 is not None:
        # With the third Sonine coefficient: Phi/Phi_M - 1 = a2 S2 + a3 S3, so Delta = S2 + (a3/a2) S3.
        ratio = float(np.mean(a3)) / float(np.mean(a2))
        ax.plot(v, sonine(lam) + ratio * s3(lam * v ** 2), "C3-", linewidth=1.0,
                label=f"S2 + (a3/a2) S3 with measured a3/a2 = {ratio:.3f}")
    if lam_theory is not None:
        ax.plot(v, sonine(lam_theory), "k:", linewidth=1.0, label=f"eq. 20 with Sonine lambda = {lam_theory:.3f}")
    ax.set_ylim(-4, 8)
    ax.set_xlabel("scaled speed v* = |V| / v0")
    ax.set_ylabel(f"Delta_{i + 1}(v*)")
    ax.set_title(f"000 Fig. 2: {scene}", fontsize="small")
    ax.axhline(0.0, color="0.6", linewidth=0.5)
    ax.legend(fontsize="small")
    save(fig, args.out)
    if args.table:
        with open(args.table, "w") as fh:
            fh.write(f"# 000 Fig. 2: Delta_{i + 1}(v*), lambda = {lam:.4f}, c = {c:.4f} +- {c_ci:.4f}\n\n")
            fh.write("| v* | granmc Delta | CI | eq. 20 (measured lambda) |\n|---|---|---|---|\n")
            for k in np.nonzero(shown)[0]:
                s = 0.5 * lam * lam * centres[k] ** 4 - 2.5 * lam * centres[k] ** 2 + 15.0 / 8.0
                fh.write(f"| {centres[k]:.3f} | {mean[k]:.3f} | {ci[k]:.3f} | {s:.3f} |\n")
    print(f"wrote {args.out}; lambda = {lam:.4f}, c = {c:.4f} +- {c_ci:.4f}")


if __name__ == "__main__":
    main()
