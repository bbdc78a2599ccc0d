#!/usr/bin/env python3
"""High-velocity tail exponent b of f ~ exp(-a |v|^b) from speed-shell histograms (001 sec. 5.3, eqs. 37-38).

Usage: /usr/bin/python3 drivers/tail_fit.py RUN.h5 OUT_DIR [--k0 1] [--window X0 X1] [--min-count 20]
                                             [--quantity density|counts] [--theory B] [--label TEXT]

RUN.h5 is an event-scheme run (method "event"): its /species/<name>/speed_distribution/counts hold, per
replica, the particles counted in each shell r_{k-1} <= |v| < r_k, r_k = k R / K (001 eq. 37), summed over
the histogram samples. With f_k the shell fractions, 001 eq. (38) assumes f_k = c exp(-a (r_k - r_k0)^b)
for k >= k0 and plots x_k = ln(r_k - r_k0) against y_k = ln(ln f_k0 - ln f_k); the slope is b.

What is fitted (--quantity). The paper applies eq. 38 to the shell fractions f_k, which carry the shell
volume ~ r^2: with k0 = 1, ln f_k0 - ln f_k changes sign where f_k falls below the tiny innermost shell,
y_k runs to -infinity there, and the r^2 factor adds -2 ln r to a r^b. Both bias b unless the window lies
far beyond that crossing (the paper's 10^9 samples put it at k - k0 = 70 ... 99). The default fits the
density per unit velocity volume, f_k / (4 pi (r_k^3 - r_(k-1)^3) / 3), which is what the tail law
f ~ exp(-a |v|^b) (001 eq. 19) is about and which is largest at the origin, so y_k is finite everywhere;
--quantity counts reproduces the paper's recipe.

The fit window. The paper fits "on the interval [4.25, 4.6]", which no x_k = ln(r_k - r_k0) reaches
(ln(40 - 40/128) = 3.68 for its largest radius R = 40). Since r_k - r_k0 = (R/K)(k - k0), ln(r_k - r_k0)
= ln(R/K) + ln(k - k0): the slope is the same in either variable, and [4.25, 4.6] is a window in
ln(k - k0), i.e. shells k - k0 = 70 ... 99 of 128. granmc's window option --window X0 X1 is in that
variable, ln(k - k0). Default: the same width 0.35 ending at the last shell where every replica still
counts at least --min-count particles, so that each y_k of each replica has a relative error of at most
about 1/sqrt(min-count); the paper's window is where its 10^9 samples gave such counts.

Two estimates of b on the same window, each fitted per replica and reported as the replica mean with its
confidence half-width (lambda_p = 3.2, 001 eq. 31), and on the pooled histogram:
- eq38: the paper's, least squares of y_k on x_k. It is biased even for an exact tail: if f = C exp(-a r^b)
  holds only in the tail, ln f_k0 - ln f_k = a r^b + D with D = ln f_k0 - ln C, so y_k = ln(a r^b + D),
  whose slope in ln r is b a r^b / (a r^b + D), not b, until a r^b >> |D|. An overpopulated tail lies above
  the core (C > f_k0 for the density), D < 0, and eq38 reads b too high (Example 7 at the paper's size:
  1.33 where theory says 1).
- free offset (the headline b): ln f_k = c - a r_k^b fitted on the window with c, a and b free (weighted
  least squares, weights the shell counts; b by a grid then a fine search), so the core's offset D does not
  enter. On a narrow window b is correlated with a and its CI is wider.
Writes OUT_DIR/tail.json, OUT_DIR/table.md, OUT_DIR/figure.png (y_k against x_k as in 001 Figs. 5-7, with
the lines y = x - c, 1.25 x - c, 1.5 x - c for comparison, and the histogram), and OUT_DIR/histograms.png
(001 Fig. 4: the shell fractions of the final state against those of the initial Maxwellian, exact at the
run's initial temperature, on [0, R/4] and, in log scale, the overpopulated tail on [R/20, R/4]; the
paper's [0, 10] and [2, 10] for its R = 40).
"""
import argparse
import json
import math
import os

import numpy as np

from granmc import mean_ci, open_results
from granmc.plotting import pyplot, save



def load_run(path):
    """The shell counts [replicas, shells], the shell edges, the method, T at the first sample (t = 0, the
    replica mean) and the mass of the (first) species."""
    with open_results(path) as h:
        species = [k for k in h["/species"].keys()]
        g = h[f"/species/{species[0]}/speed_distribution"]
        counts = g["counts"][()]  # [replicas, shells]
        edges = h["/speed_shell_edges"][()]
        method = h["/"].attrs["method"]
        method = method.decode() if isinstance(method, bytes) else str(method)
        mass = float(h[f"/species/{species[0]}"].attrs["mass"])
        temperature0 = math.exp(float(h["/log_temperature/mean"][0]))
    return counts, edges, method, temperature0, mass


def maxwell_shell_fractions(edges, temperature, mass):
    """P(r_(k-1) <= |v| < r_k) for a Maxwellian with <v_i^2> = T / m: the chi law with 3 degrees of freedom,
    F(r) = erf(r / (s sqrt 2)) - sqrt(2 / pi) (r / s) exp(-r^2 / (2 s^2)), s^2 = T / m."""
    s = math.sqrt(temperature / mass)
    cdf = np.array([math.erf(r / (s * math.sqrt(2.0))) - math.sqrt(2.0 / math.pi) * (r / s) * math.exp(-0.5 * (r / s) ** 2)
                    for r in edges])
    return np.diff(cdf)


def shell_centres(edges):
    return 0.5 * (edges[1:] + edges[:-1])


def shell_volumes(edges):
    """The velocity-space volume of each shell r_{k-1} <= |v| < r_k."""
    return 4.0 * math.pi / 3.0 * (edges[1:] ** 3 - edges[:-1] ** 3)


def xy(counts, edges, k0, quantity):
    """x_k = ln(k - k0) (the paper's window variable) and y_k = ln(ln f_k0 - ln f_k) for shells k > k0 with
    counts > 0 (1-based shell index k as in 001 eq. 37), f_k the shell fraction ("counts") or the density
    per unit velocity volume ("density"). Empty shells and shells with f_k >= f_k0 are dropped."""
    shells = len(counts)
    k = np.arange(1, shells + 1)
    f = counts / counts.sum()
    if quantity == "density":
        f = f / shell_volumes(edges)
    fk0 = f[k0 - 1]
    sel = (k > k0) & (f > 0) & (f < fk0)
    x = np.log(k[sel] - k0)
    y = np.log(np.log(fk0) - np.log(f[sel]))
    return k[sel], x, y


def free_offset_exponent(counts, edges, k0, window):
    """b of ln f_k = c - a r_k^b on the shells k with ln(k - k0) in the window, f_k the density per unit
    velocity volume at the shell centre r_k, c, a, b free; weighted least squares with weights the counts
    (the inverse variance of ln f_k). NaN if fewer than 4 shells have counts."""
    shells = len(counts)
    k = np.arange(1, shells + 1)
    ln_k = np.log(np.maximum(k - k0, 1e-300))
    sel = (k > k0) & (ln_k >= window[0]) & (ln_k <= window[1]) & (counts > 0)
    if sel.sum() < 4:
        return float("nan")
    volume = shell_volumes(edges)
    r = shell_centres(edges)[sel]
    y = np.log(counts[sel] / volume[sel])
    w = np.sqrt(counts[sel].astype(float))

    def misfit(b):
        design = np.vstack([np.ones_like(r), -(r ** b)]).T
        coef = np.linalg.lstsq(design * w[:, None], y * w, rcond=None)[0]
        return float(np.sum((w * (y - design @ coef)) ** 2))

    grid = np.linspace(0.3, 3.0, 271)
    best = grid[int(np.argmin([misfit(b) for b in grid]))]
    fine = np.linspace(best - 0.01, best + 0.01, 201)
    return float(fine[int(np.argmin([misfit(b) for b in fine]))])


def finite_mean_ci(values):
    """Mean and CI over the replicas whose fit is finite, and how many they are."""
    ok = np.isfinite(values)
    mean, ci = mean_ci(values[ok]) if ok.sum() > 1 else (float("nan"), float("nan"))
    return mean, ci, int(ok.sum())


def slope(x, y):
    if len(x) < 3:
        return float("nan")
    return float(np.polyfit(x, y, 1)[0])


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("run")
    p.add_argument("out")
    p.add_argument("--k0", type=int, default=1)
    p.add_argument("--window", type=float, nargs=2, default=None, help="fit window in ln(k - k0)")
    p.add_argument("--min-count", type=float, default=20.0)
    p.add_argument("--quantity", choices=("density", "counts"), default="density",
                   help="fit the density f(|v|) per unit velocity volume (default) or the shell fractions")
    p.add_argument("--theory", type=float, default=None, help="the expected exponent, 1 + lambda/2")
    p.add_argument("--label", default="")
    args = p.parse_args()
    os.makedirs(args.out, exist_ok=True)

    counts, edges, method, temperature0, mass = load_run(args.run)
    if method != "event":
        raise SystemExit(f"tail_fit.py: {args.run} is a method {method!r} run; the shells are in velocity units "
                         "only for method \"event\"")
    replicas, shells = counts.shape
    k0 = args.k0
    if args.window:
        window = tuple(args.window)
    else:
        populated = np.all(counts >= args.min_count, axis=0)
        last = shells
        while last > k0 + 1 and not populated[last - 1]:
            last -= 1
        x1 = math.log(last - k0)
        window = (x1 - 0.35, x1)

    per_replica = []
    for r in range(replicas):
        k, x, y = xy(counts[r], edges, k0, args.quantity)
        sel = (x >= window[0]) & (x <= window[1])
        per_replica.append(slope(x[sel], y[sel]))
    b = np.array(per_replica)
    b_mean, b_ci, fitted = finite_mean_ci(b)
    free = np.array([free_offset_exponent(counts[r], edges, k0, window) for r in range(replicas)])
    free_mean, free_ci, free_fitted = finite_mean_ci(free)

    pooled = counts.sum(axis=0)
    k, x, y = xy(pooled, edges, k0, args.quantity)
    sel = (x >= window[0]) & (x <= window[1])
    b_pooled = slope(x[sel], y[sel])
    free_pooled = free_offset_exponent(pooled, edges, k0, window)
    h = edges[1] - edges[0]
    r_window = [k0 * h + h * math.exp(window[0]), k0 * h + h * math.exp(window[1])]

    result = {"run": args.run, "quantity": args.quantity, "k0": k0, "window_ln_k_minus_k0": list(window), "window_speed": r_window,
              "shells_in_window": int(sel.sum()), "replicas": replicas, "replicas_fitted": fitted,
              "exponent": {"mean": free_mean, "ci": free_ci, "pooled": free_pooled, "replicas_fitted": free_fitted,
                           "method": "free offset: ln f = c - a r^b on the window (density)"},
              "exponent_eq38": {"mean": b_mean, "ci": b_ci, "pooled": b_pooled, "quantity": args.quantity},
              "theory": args.theory,
              "per_replica": [None if not math.isfinite(v) else v for v in free],
              "per_replica_eq38": [None if not math.isfinite(v) else v for v in b]}
    with open(os.path.join(args.out, "tail.json"), "w") as f:
        json.dump(result, f, indent=1)
    with open(os.path.join(args.out, "table.md"), "w") as f:
        f.write(f"# Tail exponent (001 eq. 38): {args.label or args.run}\n\n")
        f.write("| fit | k0 | window ln(k - k0) | speeds | shells | replicas | b granmc | CI | b pooled | b theory |\n")
        f.write("|---|---|---|---|---|---|---|---|---|---|\n")
        th = "-" if args.theory is None else f"{args.theory:g}"
        where = f"{k0} | [{window[0]:.3f}, {window[1]:.3f}] | [{r_window[0]:.2f}, {r_window[1]:.2f}] | {int(sel.sum())}"
        f.write(f"| free offset (density) | {where} | {free_fitted}/{replicas} | {free_mean:.4f} | {free_ci:.4f} | "
                f"{free_pooled:.4f} | {th} |\n")
        f.write(f"| eq38 ({args.quantity}) | {where} | {fitted}/{replicas} | {b_mean:.4f} | {b_ci:.4f} | "
                f"{b_pooled:.4f} | {th} |\n")
    plot(args, counts, edges, k0, window, b_mean, b_ci, free_mean, free_ci, os.path.join(args.out, "figure.png"))
    plot_histograms(args, counts, edges, temperature0, mass, os.path.join(args.out, "histograms.png"))
    if not math.isfinite(b_mean):
        print("tail_fit.py: no shell of the window has 0 < f_k < f_k0 in every replica; widen the window or run more "
              "particles")
    print(f"b = {free_mean:.4f} +- {free_ci:.4f} (pooled {free_pooled:.4f}; eq38: {b_mean:.4f} +- {b_ci:.4f}, pooled "
          f"{b_pooled:.4f}) on ln(k - k0) in [{window[0]:.3f}, {window[1]:.3f}] (|v| in [{r_window[0]:.2f}, "
          f"{r_window[1]:.2f}]); wrote {args.out}/figure.png, table.md, tail.json")


def plot(args, counts, edges, k0, window, b_mean, b_ci, free_mean, free_ci, path):
    plt = pyplot()

    pooled = counts.sum(axis=0)
    k, x, y = xy(pooled, edges, k0, args.quantity)
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.5))
    centres = shell_centres(edges)
    f = pooled / pooled.sum()
    if args.quantity == "density":
        f = f / shell_volumes(edges)
    ax1.semilogy(centres[f > 0], f[f > 0], "k-", lw=1)
    ax1.set_xlabel("|v|")
    ax1.set_ylabel("f(|v|) per unit velocity volume" if args.quantity == "density" else "f_k (shell fraction, 001 eq. 37)")
    ax1.set_title("histogram, all replicas")
    ax2.plot(x, y, "k-", lw=1.5, label="granmc, all replicas")
    c = y[np.argmin(np.abs(x - window[0]))] - window[0] if len(x) else 0.0
    xs = np.linspace(x.min(), x.max(), 10) if len(x) else np.array([0, 1])
    for s, style in ((1.0, ":"), (1.25, "--"), (1.5, "-.")):
        ax2.plot(xs, s * xs + (c + window[0] - s * window[0]), "C0" + style, lw=0.8, label=f"slope {s}")
    ax2.axvspan(*window, color="C1", alpha=0.2,
                label=f"window: eq38 b = {b_mean:.3f} +- {b_ci:.3f}, free offset b = {free_mean:.3f} +- {free_ci:.3f}")
    ax2.set_xlabel("x_k = ln(k - k0)  (= ln(r_k - r_k0) - ln(R/K))")
    ax2.set_ylabel("y_k = ln(ln f_k0 - ln f_k)")
    ax2.legend(fontsize="small")
    fig.suptitle(f"001 sec. 5.3: {args.label or args.run}", fontsize="small")
    save(fig, path)


def plot_histograms(args, counts, edges, temperature0, mass, path):
    plt = pyplot()

    final = counts.sum(axis=0) / counts.sum()
    initial = maxwell_shell_fractions(edges, temperature0, mass)
    centres = shell_centres(edges)
    radius = edges[-1]
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.5))
    for ax, (lo, hi), log in ((ax1, (0.0, radius / 4), False), (ax2, (radius / 20, radius / 4), True)):
        sel = (centres >= lo) & (centres <= hi)
        ax.plot(centres[sel], initial[sel], "k-", lw=2.2, label=f"initial Maxwellian, T = {temperature0:.4g} (exact)")
        keep = sel & (final > 0)
        ax.plot(centres[keep], final[keep], "k-", lw=0.9, label="final, all replicas")
        if log:
            ax.set_yscale("log")
        ax.set_xlim(lo, hi)
        ax.set_xlabel("r = |v|")
        ax.set_ylabel("f_k (shell fraction, 001 eq. 37)")
        ax.legend(fontsize="small")
    ax2.set_title("the overpopulated tail")
    fig.suptitle(f"001 Fig. 4: initial and final histograms, {args.label or args.run}", fontsize="small")
    save(fig, path)


if __name__ == "__main__":
    main()
