#!/usr/bin/env python3
"""Paper 001 sec. 5.2: temperature relaxation against the particle number (Tables 1-2, Figs. 1-3).

Usage: /usr/bin/python3 drivers/relaxation.py SCENE.toml --particles 64 256 ... [--plot-particles ...]
                                               [--granmc build/bin/granmc] [--out results/NAME]
                                               [--paper-table 1|2] [--window T0 T1] [--threads N]

Runs the scene (method "event") once per particle number n (cached: a run is skipped when its summary
exists for exactly that scene text), reads the per-replica temperatures and momenta from the HDF5 files,
and writes OUT/table.md, OUT/figure.png and OUT/relaxation.json:
  - E_max = max_m |T_m - T(t_m)| / T(t_m) (001 eq. 35) against the exact Maxwell relaxation (001 eqs.
    16-17), the convergence factor CF (ratio of consecutive E_max), and ||V||_inf = max_m |V(t_m)| with V the
    ensemble mean of the bulk velocity;
  - the same error against the exact law of the n-particle system, (1 - 1/n) T(t) (docs/methods/physics.md), and
    the largest relative confidence half-width (lambda_p = 3.2), which bounds the statistical error;
  - E_max of 001's own estimator, T = (1/3) <|v|^2> without removing the bulk velocity (the summary's
    temperature_uncentred; the scenes keep the initial sample's mean, initial.zero_momentum = false, as 001
    step 1.2), beside its expected value from the n-particle law, (T(0) + 2 beta t - T(t)) / n above T(t)
    (docs/methods/physics.md, "001's temperature estimator"): the paper's Tables 1-2 measure this;
  - the figure: confidence bands of T(t) for each n with the exact curve (Figs. 1-2), or, for a kernel
    without an exact solution (hard spheres, Fig. 3), the mean curves for each n, of T and of 001's
    estimator (the paper's Fig. 3 plots the latter: its n = 64 curve is the highest).
"""
import argparse
import copy
import json
import os
import tomllib

import numpy as np

from granmc import mean_ci, open_results, run_point, theory
from granmc.plotting import pyplot, save

PAPER_TABLES = {  # 001 Tables 1 and 2: n -> (E_max, ||V||_inf)
    "1": {64: (0.895e-1, 0.672e-2), 256: (0.235e-1, 0.516e-2), 1024: (0.571e-2, 0.211e-2),
          4096: (0.150e-2, 0.141e-2), 16384: (0.305e-3, 0.355e-3)},
    "2": {64: (0.130, 0.306e-2), 256: (0.336e-1, 0.188e-2), 1024: (0.823e-2, 0.874e-2),
          4096: (0.211e-2, 0.581e-2), 16384: (0.455e-3, 0.148e-2)},
}


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("scene")
    p.add_argument("--particles", type=int, nargs="+", required=True)
    p.add_argument("--plot-particles", type=int, nargs="*", default=None)
    p.add_argument("--granmc", default="build/bin/granmc")
    p.add_argument("--out", default=None)
    p.add_argument("--paper-table", choices=sorted(PAPER_TABLES), default=None)
    p.add_argument("--window", type=float, nargs=2, default=None, help="time window of the plot")
    p.add_argument("--threads", type=int, default=0)
    args = p.parse_args()

    with open(args.scene, "rb") as f:
        base = tomllib.load(f)
    name = os.path.splitext(os.path.basename(args.scene))[0]
    out = args.out or os.path.join("results", "001_" + name)
    os.makedirs(os.path.join(out, "points"), exist_ok=True)

    rows = []
    for n in args.particles:
        scene = copy.deepcopy(base)
        scene["species"][0]["particles"] = n
        stem = os.path.join(out, "points", f"n{n}")
        summary = run_point(args.granmc, scene, stem, args.threads)
        th = theory(args.granmc, stem + ".toml")
        with open_results(stem + ".h5") as h:
            times = h["/times"][()]
            temperature = h["/temperature/replicas"][()]          # [replicas, samples]
            momentum = h["/momentum/replicas"][()]                # [replicas, samples, 3]
        replicas = temperature.shape[0]
        uncentred = np.array(summary["temperature_uncentred"]["mean"])
        mean, ci = mean_ci(temperature)
        bulk = np.linalg.norm(momentum.mean(axis=0) / n, axis=1)  # |ensemble mean of V|, unit mass
        row = {"n": n, "replicas": replicas, "times": times.tolist(), "mean": mean.tolist(), "ci": ci.tolist(),
               "bulk_inf": float(bulk.max()), "wall_seconds": summary["wall_seconds"],
               "uncentred": uncentred.tolist(),
               "collisions": summary["collisions"], "candidates": summary["candidates"],
               "majorant_violations": summary.get("majorant_violations", 0)}
        exact = th.get("maxwell_relaxation")
        if exact:
            t_exact = np.array(exact["temperature"])
            t_particles = np.array(exact["temperature_particles"])
            row["e_max"] = float(np.max(np.abs(mean - t_exact) / t_exact))
            row["e_max_particles"] = float(np.max(np.abs(mean - t_particles) / t_exact))
            row["ci_max"] = float(np.max(ci / t_exact))
            row["exact"] = t_exact.tolist()
            t_uncentred = np.array(exact["temperature_uncentred_particles"])
            row["e_max_uncentred"] = float(np.max(np.abs(uncentred - t_exact) / t_exact))
            row["e_max_uncentred_expected"] = float(np.max(np.abs(t_uncentred - t_exact) / t_exact))
            uncentred_ci = np.array(summary["temperature_uncentred"]["ci"])
            row["uncentred_within_ci"] = bool(np.all(np.abs(uncentred - t_uncentred) <= uncentred_ci))
        rows.append(row)
        print(f"  n = {n}: {summary['wall_seconds']:.0f} s", flush=True)

    with open(os.path.join(out, "relaxation.json"), "w") as f:
        json.dump({"scene": args.scene, "rows": rows}, f, indent=1)
    write_table(rows, args, os.path.join(out, "table.md"))
    plot(rows, args, os.path.join(out, "figure.png"))
    print(f"wrote {out}/table.md, {out}/figure.png, {out}/relaxation.json")


def write_table(rows, args, path):
    paper = PAPER_TABLES.get(args.paper_table, {})
    with open(path, "w") as f:
        f.write(f"# 001 sec. 5.2: {args.scene}\n\n")
        if "e_max" in rows[0]:
            f.write("E_max = max_m |T_m - T(t_m)| / T(t_m) against the exact relaxation (001 eq. 35), T_m of the "
                    "peculiar velocity (bulk velocity removed); CF = ratio of consecutive E_max; n E_max; E_max "
                    "against (1 - 1/n) T(t), the exact law of the n-particle system; the largest relative CI "
                    "half-width (lambda_p = 3.2). Then 001's estimator, T_m = (1/3) <|v|^2> without removing the "
                    "bulk velocity (temperature_uncentred): its E_max, the E_max its exact n-particle law predicts, "
                    "(T(0) + 2 beta t - T(t)) / (n T(t)) at the worst sample, and whether every sample is within its "
                    "CI of that law. ||V||_inf = max_m |<V>(t_m)|.\n\n")
            f.write("| n | N | E_max paper | E_max granmc | CF | n E_max | E_max vs (1-1/n) T | max CI / T | "
                    "E_max, 001's estimator | its expected E_max | within CI | "
                    "norm V paper | norm V granmc | collisions | run (s) |\n")
            f.write("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n")
            prev = None
            for r in rows:
                pe, pv = paper.get(r["n"], (None, None))
                cf = f"{prev / r['e_max']:.2f}" if prev else "-"
                f.write(f"| {r['n']} | {r['replicas']} | {fmt(pe)} | {r['e_max']:.3e} | {cf} | {r['n'] * r['e_max']:.2f} | "
                        f"{r['e_max_particles']:.3e} | {r['ci_max']:.3e} | {r['e_max_uncentred']:.3e} | "
                        f"{r['e_max_uncentred_expected']:.3e} | {'yes' if r['uncentred_within_ci'] else 'no'} | "
                        f"{fmt(pv)} | {r['bulk_inf']:.3e} | {r['collisions']:.3g} | {r['wall_seconds']:.0f} |\n")
                prev = r["e_max"]
        else:
            last = rows[-1]
            f.write(f"No exact solution: the mean temperature for each n, and its difference from the largest n "
                    f"({last['n']}), which should fall as 1/n (times n in brackets); the same for 001's estimator "
                    f"(1/3) <|v|^2> without removing the bulk velocity, which the paper plots.\n\n")
            f.write("| n | N | T(t_end) | CI | T - T_largest at t_end (x n) | 001's estimator at t_end | "
                    "its difference from the largest n (x n) | candidates | acceptance | violations | run (s) |\n")
            f.write("|---|---|---|---|---|---|---|---|---|---|---|\n")
            for r in rows:
                d = r["mean"][-1] - last["mean"][-1]
                du = r["uncentred"][-1] - last["uncentred"][-1]
                f.write(f"| {r['n']} | {r['replicas']} | {r['mean'][-1]:.5f} | {r['ci'][-1]:.5f} | {d:+.5f} ({d * r['n']:+.2f}) | "
                        f"{r['uncentred'][-1]:.5f} | {du:+.5f} ({du * r['n']:+.2f}) | "
                        f"{r['candidates']:.3g} | {r['collisions'] / r['candidates']:.3f} | {r['majorant_violations']} | "
                        f"{r['wall_seconds']:.0f} |\n")


def fmt(v):
    return "-" if v is None else f"{v:.3e}"


def plot(rows, args, path):
    plt = pyplot()

    shown = [r for r in rows if args.plot_particles is None or r["n"] in args.plot_particles]
    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for k, r in enumerate(shown):
        t, m, c = np.array(r["times"]), np.array(r["mean"]), np.array(r["ci"])
        sel = np.ones_like(t, dtype=bool) if args.window is None else (t >= args.window[0]) & (t <= args.window[1])
        col = colours[k % len(colours)]
        if "exact" in r:
            ax.plot(t[sel], (m - c)[sel], "-", color=col, lw=0.9, label=f"n = {r['n']} (CI, lambda_p = 3.2)")
            ax.plot(t[sel], (m + c)[sel], "-", color=col, lw=0.9)
        else:
            ax.plot(t[sel], m[sel], "-", color=col, label=f"n = {r['n']}: T")
            ax.plot(t[sel], np.array(r["uncentred"])[sel], "--", color=col, lw=0.9,
                    label=f"n = {r['n']}: (1/3) <|v|^2>, 001's estimator")
    if "exact" in rows[-1]:
        t = np.array(rows[-1]["times"])
        sel = np.ones_like(t, dtype=bool) if args.window is None else (t >= args.window[0]) & (t <= args.window[1])
        ax.plot(t[sel], np.array(rows[-1]["exact"])[sel], "k--", lw=1.2, label="exact, 001 eqs. 16-17")
    ax.set_xlabel("t")
    ax.set_ylabel("T")
    ax.set_title(f"001 sec. 5.2: {os.path.basename(args.scene)}")
    ax.legend(fontsize=8)
    save(fig, path)


if __name__ == "__main__":
    main()
