#!/usr/bin/env python3
"""Paper 002 Fig. 8: the needle's angular-velocity distribution against its best Gaussian.

Usage: /usr/bin/python3 drivers/plot_needle_angular.py RUN.h5 OUT_DIR

Reads the density of |omega| (replica mean and CI, last half of the run) and the sampled omega of each
replica; writes OUT_DIR/figure.png (linear and log density of omega with two Gaussians: the one with the
measured <omega^2>, and the least-squares fit of the density) and OUT_DIR/table.md with the kurtosis
<omega^4>/<omega^2>^2 (3 for a Gaussian) per replica, mean and CI (lambda_p = 3.2).
"""
import math
import os
import sys

import numpy as np

from granmc import mean_ci, open_results
from granmc.plotting import pyplot, save


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    path, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    with open_results(path) as h:
        edges = h["/intruder/angular_shell_edges"][()]
        mean = h["/intruder/angular_distribution/mean"][()]
        ci = h["/intruder/angular_distribution/ci"][()]
        omega = h["/intruder/angular_velocity"][()]  # [replicas, samples]
    first = omega.shape[1] // 2  # the last half, as the summary (first_stationary_sample)
    w = omega[:, first:]
    m2 = (w ** 2).mean(axis=1)
    kurt = (w ** 4).mean(axis=1) / m2 ** 2
    k_mean, k_ci = mean_ci(kurt)
    var, var_ci = mean_ci(m2)

    centres = 0.5 * (edges[1:] + edges[:-1])
    density = 0.5 * mean  # |omega| density -> omega density (symmetric)
    err = 0.5 * ci

    def gauss(x, s2):
        return np.exp(-x * x / (2 * s2)) / math.sqrt(2 * math.pi * s2)

    # Least-squares fit of the density over the populated shells, weighted by the CI.
    ok = (mean > 0) & (ci > 0)
    grid = var * np.exp(np.linspace(-1.0, 1.0, 2001))
    resid = [np.sum(((density[ok] - gauss(centres[ok], s2)) / err[ok]) ** 2) for s2 in grid]
    s2_fit = grid[int(np.argmin(resid))]

    with open(os.path.join(out, "table.md"), "w") as f:
        f.write("# 002 Fig. 8: the needle's angular velocity, M/m = 0.1, alpha = 0.1\n\n")
        f.write("| quantity | granmc | CI | Gaussian |\n|---|---|---|---|\n")
        f.write(f"| kurtosis <w^4>/<w^2>^2 | {k_mean:.4f} | {k_ci:.4f} | 3 |\n")
        f.write(f"| <w^2> | {var:.5f} | {var_ci:.5f} | - |\n")
        f.write(f"| best-fit Gaussian variance | {s2_fit:.5f} | - | - |\n")
        f.write(f"\nreplicas: {omega.shape[0]}, samples per replica in the average: {w.shape[1]}\n")

    plt = pyplot()
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    reach = edges[1:][ok].max()  # the populated shells only
    x = np.linspace(0, reach, 400)
    floor = 0.3 * density[ok].min()
    for ax, log in zip(axes, (False, True)):
        lower = np.minimum(err[ok], density[ok] - floor) if log else err[ok]  # keep log error bars above 0
        ax.errorbar(centres[ok], density[ok], yerr=[lower, err[ok]], fmt=".", ms=3, color="k", label="granmc (CI)")
        ax.plot(x, gauss(x, var), "C0-", label=f"Gaussian, <w^2> = {var:.4f}")
        ax.plot(x, gauss(x, s2_fit), "C3--", label=f"best-fit Gaussian, var = {s2_fit:.4f}")
        ax.set_xlabel("|omega|")
        ax.set_ylabel("density of omega")
        ax.set_xlim(0, reach)
        if log:
            ax.set_yscale("log")
            ax.set_ylim(floor, 2 * density[ok].max())
    axes[0].legend(fontsize="small")
    fig.suptitle(f"002 Fig. 8: needle M/m = 0.1, alpha = 0.1; kurtosis {k_mean:.3f} +- {k_ci:.3f} (Gaussian 3)",
                 fontsize="small")
    save(fig, os.path.join(out, "figure.png"))
    print(f"wrote {out}/figure.png, {out}/table.md")


if __name__ == "__main__":
    main()
