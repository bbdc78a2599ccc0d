#!/usr/bin/env python3
"""Paper 002 Figs. 1-2: the collision flux phi(v1) of a surface moving at v1 through a Gaussian bath, and the
velocity law g_+(v; v1) of the bath particles that hit its right side, from granmc against 002's formulas.

Usage: /usr/bin/python3 drivers/plot_bath.py SCENE.toml [--granmc build/bin/granmc] [--out results/002_fig1]

`granmc bath` prints the fluxes phi_+(v1), phi_-(v1) that the Gillespie intruder uses and draws from g_+ with
its rejection sampler (kernel/analysis/bath_probe.hpp). This script evaluates 002 eq. (20),
phi(v1) = rho (exp(-a v1^2) / sqrt(pi a) + v1 erf(sqrt(a) v1)), for a = 0.5, 1, 2, 4 (Fig. 1), and eq. (14),
g_+(v; v1) = (v1 - v) f(v) / phi_+(v1) on v <= v1 with f of eq. (18), for v1 = -2 .. 2 at the scene's a
(Fig. 2), independently of granmc's code. Table (OUT/table.md): the largest relative flux difference per a,
and per v1 the histogram's chi^2 against the exact bin probabilities (bins with at least 5 expected draws),
its degrees of freedom and p-value. Figure: OUT/figure.png.
"""
import argparse
import json
import math
import os
import subprocess
import tempfile
import tomllib

import numpy as np
from scipy import integrate, stats

from granmc.plotting import pyplot, save


def flux_eq20(v1, a, rho):
    return rho * (math.exp(-a * v1 * v1) / math.sqrt(math.pi * a) + v1 * math.erf(math.sqrt(a) * v1))


def flux_right_eq19(v1, a, rho):
    return 0.5 * rho * (v1 + math.exp(-a * v1 * v1) / math.sqrt(math.pi * a) + v1 * math.erf(math.sqrt(a) * v1))


def g_right_eq14(v, v1, a):
    """002 eq. (14) with f of eq. (18); rho cancels."""
    f = math.sqrt(a / math.pi) * math.exp(-a * v * v)
    return (v1 - v) * f / flux_right_eq19(v1, a, 1.0) if v <= v1 else 0.0


def probe(granmc, scene_text, a, v1s, samples, bins, lo, hi):
    """`granmc bath` on the scene with intruder.bath_a = a."""
    with tempfile.NamedTemporaryFile("w", suffix=".toml", delete=False) as f:
        f.write(scene_text.replace(scene_text[scene_text.index("bath_a"):].splitlines()[0], f"bath_a = {a!r}"))
    try:
        cmd = [granmc, "bath", f.name, "--samples", str(samples), "--bins", str(bins), "--range", str(lo), str(hi),
               "--v1"] + [repr(float(v)) for v in v1s]
        return json.loads(subprocess.run(cmd, check=True, capture_output=True, text=True).stdout)
    finally:
        os.unlink(f.name)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("scene")
    p.add_argument("--granmc", default="build/bin/granmc")
    p.add_argument("--out", default="results/002_fig1")
    p.add_argument("--samples", type=int, default=1000000, help="draws from g_+ per v1 (Fig. 2)")
    args = p.parse_args()
    os.makedirs(args.out, exist_ok=True)
    with open(args.scene) as f:
        text = f.read()
    scene = tomllib.loads(text)
    a0, rho = scene["intruder"]["bath_a"], scene["intruder"]["bath_density"]

    plt = pyplot()
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.5))
    lines = ["# 002 Figs. 1-2: the Gaussian bath as the intruder sees it (`make fig-002-1`)", "",
             f"Scene {args.scene}: rho = {rho}; Fig. 2 at a = {a0}, {args.samples} draws per v1, seed "
             f"{scene['run']['seed']}.", "",
             "| a | v1 range | points | max \\|phi_granmc / phi_eq20 - 1\\| |", "|---|---|---|---|"]
    v1_grid = np.linspace(-3.0, 3.0, 61)
    for a in (0.5, 1.0, 2.0, 4.0):
        out = probe(args.granmc, text, a, v1_grid, 1, 1, -1.0, 1.0)
        mine = np.array([pt["flux_right"] + pt["flux_left"] for pt in out["points"]])
        exact = np.array([flux_eq20(v, a, rho) for v in v1_grid])
        lines.append(f"| {a:g} | [-3, 3] | {len(v1_grid)} | {np.max(np.abs(mine / exact - 1)):.1e} |")
        shown = ax1.plot(v1_grid, mine, "-", label=f"granmc, a = {a:g}")
        ax1.plot(v1_grid[::4], exact[::4], "o", mfc="none", color=shown[0].get_color(), label=f"eq. 20, a = {a:g}")
    ax1.set_xlabel("v1")
    ax1.set_ylabel("phi(v1) = phi_+ + phi_-")
    ax1.set_title("002 Fig. 1: collision rate of a surface moving at v1", fontsize=9)
    ax1.legend(fontsize=7)

    lines += ["", "| v1 | phi_+ granmc | eq. 19 | acceptance | chi^2 | dof | p | draws outside the range |",
              "|---|---|---|---|---|---|---|---|"]
    v1s = [-2.0, -1.0, 0.0, 1.0, 2.0]
    lo, hi, bins = -4.0, 4.0, 160
    out = probe(args.granmc, text, a0, v1s, args.samples, bins, lo, hi)
    edges = np.asarray(out["edges"])
    for pt in out["points"]:
        v1 = pt["v1"]
        dens = np.asarray(pt["g_right_density"])
        counts = dens * np.diff(edges) * args.samples
        expected = np.array([integrate.quad(g_right_eq14, e0, min(e1, v1), args=(v1, a0))[0] if e0 < v1 else 0.0
                             for e0, e1 in zip(edges[:-1], edges[1:])]) * args.samples
        keep = expected >= 5.0
        chi2 = float(np.sum((counts[keep] - expected[keep]) ** 2 / expected[keep]))
        dof = int(np.sum(keep)) - 1
        pval = float(stats.chi2.sf(chi2, dof))
        lines.append(f"| {v1:g} | {pt['flux_right']:.6f} | {flux_right_eq19(v1, a0, rho):.6f} | {pt['acceptance']:.3f} "
                     f"| {chi2:.1f} | {dof} | {pval:.3f} | {pt['g_right_outside']} |")
        centres = 0.5 * (edges[:-1] + edges[1:])
        shown = ax2.step(centres, dens, where="mid", label=f"granmc, v1 = {v1:g}")
        vs = np.linspace(lo, v1, 200)
        ax2.plot(vs, [g_right_eq14(v, v1, a0) for v in vs], "--", color=shown[0].get_color(), linewidth=0.8)
    ax2.set_xlabel("v (bath particle hitting the right side)")
    ax2.set_ylabel("g_+(v; v1)")
    ax2.set_title(f"002 Fig. 2: g_+ (histograms) against eq. 14 (dashed), a = {a0:g}", fontsize=9)
    ax2.legend(fontsize=7)
    save(fig, os.path.join(args.out, "figure.png"))
    with open(os.path.join(args.out, "table.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
