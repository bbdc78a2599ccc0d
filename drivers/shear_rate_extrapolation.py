#!/usr/bin/env python3
"""The Navier-Stokes viscosity as the limit a* -> 0 of the sheared steady state (000 Figs. 7-8).

Usage: /usr/bin/python3 drivers/shear_rate_extrapolation.py SWEEP.toml [SWEEP.toml ...]
           [--granmc build/bin/granmc] [--out results/000_fig8_shear_rate] [--target fig-000-8-shear-rate]

Each sweep file (drivers/scenes/000_fig8_shear_rate/omega*.toml, 000_fig7_shear_rate/mu10.toml) runs one mixture at several restitutions
alpha and shear rates a with `granmc sweep` (so a rerun resumes and skips what is done). Uniform shear flow
is non-Newtonian: eta*(a*) = eta*_NS + c a*^2 + O(a*^4) (the stress is odd in a, so eta is even), and c grows
with dissipation. Per alpha this fits eta* against a*^2 (weighted least squares over the rates, a* the mean
reduced shear rate over the averaging window) and reports the intercept, its ratio to the elastic
intercept, and the first-Sonine theory (`granmc theory`); "steady" says whether every rate's run passed
granmc's plateau test (the summary's viscosity.steady). CIs follow granmc's replica convention
(3.2 standard errors, p = 0.999); the ratio's CI treats the two intercepts as independent, which
overstates it (the runs share their seed). Writes OUT/<sweep stem>/ (the sweep's outputs), OUT/table.md
and OUT/shear_rate.png.
"""
import argparse
import json
import os
import subprocess

import numpy as np

from granmc import LAMBDA_P, open_results, theory_of_text
from granmc.plotting import pyplot, save
from granmc.zero_shear import fit_intercept, window_mean_shear_rate


def points_of(sweep_dir):
    """(alpha, a*, eta*, sigma of eta*, HDF5 file, plateau test passed) per finished scene of a sweep's index."""
    with open(os.path.join(sweep_dir, "index.json")) as f:
        index = json.load(f)
    points = []
    for s in index["scenes"]:
        if s["status"] != "done":
            raise SystemExit(f"{sweep_dir}: scene {s['name']} did not finish; rerun to resume")
        with open(os.path.join(sweep_dir, s["summary"])) as f:
            v = json.load(f)["viscosity"]
        points.append((s["values"]["collision.restitution"], window_mean_shear_rate(v), v["eta_star"]["mean"],
                       v["eta_star"]["ci"] / LAMBDA_P, os.path.join(sweep_dir, s["hdf5"]), v["steady"]))
    return points


def builds_of(sweep_dir):
    """The granmc builds that made a sweep's scenes, as its index records them."""
    with open(os.path.join(sweep_dir, "index.json")) as f:
        return {s.get("build", "not recorded") for s in json.load(f)["scenes"]}


def first_sonine(granmc, hdf5):
    """First-Sonine eta* and eta(alpha)/eta(1) of the scene a sweep ran (the text its HDF5 file stores)."""
    with open_results(hdf5) as h:
        text = h.attrs["scene_text"]
    fs = theory_of_text(granmc, text if isinstance(text, str) else text.decode())["viscosity"]["first_sonine"]
    return fs["eta_star"], fs["eta_over_eta_elastic"]


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("sweeps", nargs="+")
    p.add_argument("--granmc", default="build/bin/granmc")
    p.add_argument("--out", default="results/000_fig8_shear_rate")
    p.add_argument("--target", default="fig-000-8-shear-rate", help="the make target named in the table")
    args = p.parse_args()
    os.makedirs(args.out, exist_ok=True)

    plt = pyplot()

    fig, axes = plt.subplots(1, len(args.sweeps), figsize=(5.5 * len(args.sweeps), 4.5), squeeze=False)
    lines = [f"# eta* against the shear rate, extrapolated to a* -> 0 (`make {args.target}`)", "",
             "CI: 3.2 standard errors (p = 0.999). eta*(0): weighted fit eta* = eta*(0) + c a*^2 over the rates.", ""]
    builds = set()
    for sweep, ax in zip(args.sweeps, axes[0]):
        stem = os.path.splitext(os.path.basename(sweep))[0]
        sweep_dir = os.path.join(args.out, stem)
        subprocess.run([args.granmc, "sweep", sweep, "--out-dir", sweep_dir], check=True)
        points = points_of(sweep_dir)
        builds |= builds_of(sweep_dir)
        alphas = sorted({pt[0] for pt in points}, reverse=True)
        lines += [f"## {stem}", "",
                  "| alpha | a* at each rate | eta* at each rate (CI) | steady | c | eta*(a*->0) | CI | first Sonine eta* "
                  "| eta(alpha)/eta(1) at the largest rate | extrapolated | CI | first Sonine | gap |",
                  "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
        fits = {}
        for alpha in alphas:
            pts = sorted([pt for pt in points if pt[0] == alpha], key=lambda pt: pt[1])
            a_star, eta, sig = [pt[1] for pt in pts], [pt[2] for pt in pts], [pt[3] for pt in pts]
            b0, s0, c = fit_intercept(a_star, eta, sig)
            th_star, th_ratio = first_sonine(args.granmc, pts[0][4])
            fits[alpha] = (b0, s0, c, th_star, th_ratio, pts)
            x = np.asarray(a_star) ** 2
            shown = ax.errorbar(x, eta, yerr=LAMBDA_P * np.asarray(sig), fmt="o", label=f"alpha = {alpha}")
            xs = np.linspace(0.0, max(x) * 1.05, 50)
            ax.plot(xs, b0 + c * xs, "-", color=shown[0].get_color())
            ax.plot([0.0], [th_star], "*", ms=12, color=shown[0].get_color())
        ref = fits[1.0] if 1.0 in fits else None
        for alpha in alphas:
            b0, s0, c, th_star, th_ratio, pts = fits[alpha]
            rates = ", ".join(f"{pt[1]:.3f}" for pt in pts)
            etas = ", ".join(f"{pt[2]:.4f} ({LAMBDA_P * pt[3]:.4f})" for pt in pts)
            if ref:
                top = pts[-1][2] / ref[5][-1][2]
                ratio = b0 / ref[0]
                ratio_ci = LAMBDA_P * ratio * np.hypot(s0 / b0, ref[1] / ref[0]) if alpha != 1.0 else 0.0
                gap = (f"{100 * (ratio / th_ratio - 1):+.1f} % ({abs(ratio - th_ratio) / ratio_ci:.1f} CI)"
                       if alpha != 1.0 else "-")
                tail = f"{top:.4f} | {ratio:.4f} | {ratio_ci:.4f} | {th_ratio:.4f} | {gap}"
            else:
                tail = "- | - | - | - | -"
            steady = "yes" if all(pt[5] for pt in pts) else "no at a* = " + ", ".join(
                f"{pt[1]:.3f}" for pt in pts if not pt[5])
            lines.append(f"| {alpha} | {rates} | {etas} | {steady} | {c:.2f} | {b0:.4f} | {LAMBDA_P * s0:.4f} "
                         f"| {th_star:.4f} | {tail} |")
        lines.append("")
        ax.set_xlabel("a*^2 (mean over the averaging window)")
        ax.set_ylabel("eta*")
        ax.set_title(f"{stem}: eta* vs a*^2; lines: fits, stars: first Sonine", fontsize=9)
        ax.legend(fontsize=8)
    save(fig, os.path.join(args.out, "shear_rate.png"))
    lines[4:4] = [f"Made by granmc {', '.join(sorted(builds))} (`granmc --version`); another build reruns every "
                  "scene and may give another realization of the same law.", ""]
    with open(os.path.join(args.out, "table.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
