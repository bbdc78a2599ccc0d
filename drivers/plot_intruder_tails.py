#!/usr/bin/env python3
"""Paper 002 Fig. 5: the intruder's velocity distributions from a sweep over alpha, and their tail exponents.

Usage: /usr/bin/python3 drivers/plot_intruder_tails.py results/002_fig5 [--fit 10 100]

Reads the points of the sweep that drivers/figure.py ran (OUT/figure.json and OUT/points/*.h5). For each
alpha: the density of v1, f(v) = (counts of |v1| per shell) / (2 samples shell width), over the last half of
each run; and the tail exponent b of f ~ |v|^-b in the fit window, by maximum likelihood on the shell counts
(the law of |v| restricted to the window is taken as c |v|^-b; a least-squares fit of ln(counts) is biased
where counts are few), per replica, then the replica mean and CI (lambda_p = 3.2, 001 eq. 31). 002 finds
b = 4 for every alpha. Writes OUT/tails.png and OUT/tails.md.
"""
import argparse
import json
import math
import os

import numpy as np

from granmc import mean_ci
from granmc.plotting import pyplot, save


def tail_exponent(counts, left, right):
    """Maximum-likelihood b for shell counts of a density ~ |v|^-b on [left[0], right[-1]]."""
    def log_likelihood(b):
        mass = (left ** (1.0 - b) - right ** (1.0 - b)) / (b - 1.0)       # int over each shell of v^-b
        total = (left[0] ** (1.0 - b) - right[-1] ** (1.0 - b)) / (b - 1.0)
        return float(np.sum(counts * np.log(mass / total)))
    lo_b, hi_b = 1.05, 12.0  # golden-section search; the likelihood is concave in b
    g = (math.sqrt(5.0) - 1.0) / 2.0
    for _ in range(100):
        m1, m2 = hi_b - g * (hi_b - lo_b), lo_b + g * (hi_b - lo_b)
        if log_likelihood(m1) < log_likelihood(m2):
            lo_b = m1
        else:
            hi_b = m2
    return 0.5 * (lo_b + hi_b)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("out")
    p.add_argument("--fit", nargs=2, type=float, default=[10.0, 100.0], help="|v| window of the tail fit")
    args = p.parse_args()
    from granmc import open_results
    with open(os.path.join(args.out, "figure.json")) as f:
        fig = json.load(f)
    lo, hi = args.fit
    rows = []
    reference = 0.05
    plt = pyplot()
    fig_plot, (ax, ax_log) = plt.subplots(1, 2, figsize=(11, 4.5))
    for n, pt in enumerate(fig["curves"][0]["points"]):
        alpha = pt["x"]
        path = os.path.join(args.out, pt["hdf5"])  # the sweep's output of this point (figure.py)
        with open_results(path) as h:
            edges = h["intruder/speed_shell_edges"][()]
            counts = h["intruder/speed_distribution/counts"][()]          # R x K
            samples = h["counters/histogram_samples"][()]    # R
        width = edges[1] - edges[0]
        centres = 0.5 * (edges[1:] + edges[:-1])
        density = counts.sum(axis=0) / (2.0 * samples.sum() * width)  # f(v), both signs
        colour = plt.cm.viridis(n / max(1, len(fig["curves"][0]["points"]) - 1))
        shown = (centres < 4.0) & (density > 0)
        ax.plot(np.concatenate([-centres[shown][::-1], centres[shown]]),
                np.concatenate([density[shown][::-1], density[shown]]), color=colour, label=f"alpha = {alpha:g}")
        inside = (edges[:-1] >= lo) & (edges[1:] <= hi)
        e = np.array([tail_exponent(counts[r, inside], edges[:-1][inside], edges[1:][inside])
                      for r in range(counts.shape[0])])
        b_mean, b_ci = mean_ci(e)
        rows.append((alpha, b_mean, b_ci, len(e)))
        # The tail panel merges the shells into logarithmic bins from 1 to the histogram's radius.
        bins = np.exp(np.linspace(0.0, math.log(edges[-1]), 31))
        total = counts.sum(axis=0)
        xs, ys = [], []
        for a, b in zip(bins[:-1], bins[1:]):
            sel = (edges[:-1] >= a) & (edges[1:] <= b)
            if sel.any() and total[sel].sum() > 0:
                xs.append(math.sqrt(a * b))
                ys.append(total[sel].sum() / (2.0 * samples.sum() * width * sel.sum()))
        ax_log.loglog(xs, ys, "o-", ms=3, color=colour, label=f"alpha = {alpha:g}: b = {b_mean:.2f} +- {b_ci:.2f}")
        if abs(alpha - 0.5) < 1e-9:
            reference = ys[int(np.argmin(np.abs(np.array(xs) - lo)))] * lo ** 4  # |v|^-4 through this curve at lo
    v = np.array([1.0, edges[-1]])
    ax_log.loglog(v, reference * v ** -4.0, "k--", label="|v|^-4")
    ax.set_xlabel("intruder velocity v")
    ax.set_ylabel("f(v)")
    ax.set_title("002 Fig. 5: M = 1/2, power-law bath", fontsize="small")
    ax.legend(fontsize="x-small")
    ax_log.set_xlabel("|v|")
    ax_log.set_ylabel("f(v)")
    ax_log.set_title(f"tails; exponent fitted on {lo:g} <= |v| <= {hi:g}", fontsize="small")
    ax_log.legend(fontsize="x-small")
    save(fig_plot, os.path.join(args.out, "tails.png"))
    with open(os.path.join(args.out, "tails.md"), "w") as f:
        f.write(f"# 002 Fig. 5: tail exponent b of f(v) ~ |v|^-b, fit on {lo:g} <= |v| <= {hi:g}\n\n")
        f.write("| alpha | b | CI | replicas |\n|---|---|---|---|\n")
        for alpha, b, ci, n in rows:
            f.write(f"| {alpha:g} | {b:.3f} | {ci:.3f} | {n} |\n")
    print(f"wrote {args.out}/tails.png and tails.md")
    for alpha, b, ci, n in rows:
        print(f"alpha = {alpha:g}: b = {b:.3f} +- {ci:.3f}")


if __name__ == "__main__":
    main()
