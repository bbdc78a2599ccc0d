#!/usr/bin/env python3
"""Paper 003's evolution: the modified shear flow from its start to the approach to the cooling state.

Usage: /usr/bin/python3 drivers/evolution_003.py SCENE.toml [--restitution A ...] [--t-end T]
                                                  [--particles N] [--replicas R] [--granmc build/bin/granmc]
                                                  [--out results/003_evolution] [--threads N]

003 (Results, "Evolution"; Conclusions I): "After a short transient period, the system reaches first a
non-Newtonian hydrodynamic regime, then a Navier-Stokes regime, and finally tends asymptotically to the HCS
(even with an increasing temperature!)". The thermostat of the modified shear flow compensates only the
collisional cooling, so viscous heating raises T without end and the reduced shear rate a* = a / nu falls
as 1 / sqrt(T): the state slides towards the HCS (a* -> 0) while eta* = -P_xy / (n T a*) settles on its
Navier-Stokes value.

The scene (by default drivers/scenes/003_viscosity/base.toml) is run once per restitution coefficient
(cached by scene text, python/granmc/scenes.py) with --t-end, --particles and --replicas replacing its own.
Writes OUT/figure.png (eta*(t) with its CI and the first-Sonine Navier-Stokes value of `granmc theory`;
a*(t); T(t)/T(0)) and OUT/table.md: per restitution, T, a* and eta* averaged over consecutive windows of
the run, and checks computed from them: T rises and a* falls from each window to the next, and eta* is
steady over the last half (the summary's viscosity/steady: its drift within its CI), where a* is smallest.
"""
import argparse
import copy
import math
import os
import tomllib

import numpy as np

from granmc import run_point, theory  # cached by scene text
from granmc.plotting import pyplot, save

WINDOWS = 5  # consecutive windows of the run in the table


def first_sonine_eta(granmc, scene_path):
    return theory(granmc, scene_path)["viscosity"]["first_sonine"]["eta_star"]


def series(summary, path):
    node = summary
    for key in path.split("/"):
        node = node[key]
    mean = np.array([math.nan if v is None else v for v in node["mean"]])
    ci = np.array([math.nan if v is None else v for v in node["ci"]])
    return mean, ci


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("scene")
    p.add_argument("--restitution", type=float, nargs="+", default=[0.8])
    p.add_argument("--t-end", type=float, default=None)
    p.add_argument("--particles", type=int, default=None)
    p.add_argument("--replicas", type=int, default=None)
    p.add_argument("--granmc", default="build/bin/granmc")
    p.add_argument("--out", default="results/003_evolution")
    p.add_argument("--threads", type=int, default=0)
    args = p.parse_args()
    with open(args.scene, "rb") as f:
        base = tomllib.load(f)
    os.makedirs(args.out, exist_ok=True)

    rows = []
    for alpha in args.restitution:
        scene = copy.deepcopy(base)
        scene["collision"]["restitution"] = alpha
        if args.t_end is not None:
            scene["run"]["t_end"] = args.t_end
        if args.particles is not None:
            scene["species"][0]["particles"] = args.particles
        if args.replicas is not None:
            scene["run"]["replicas"] = args.replicas
        stem = os.path.join(args.out, f"alpha{alpha:g}")
        summary = run_point(args.granmc, scene, stem, args.threads)
        times = np.array(summary["times"])
        temperature, _ = series(summary, "temperature")
        eta, eta_ci = series(summary, "viscosity/eta_star_series")
        shear, _ = series(summary, "viscosity/reduced_shear_rate")
        rows.append({"alpha": alpha, "times": times, "temperature": temperature, "eta": eta, "eta_ci": eta_ci,
                     "shear": shear, "theory": first_sonine_eta(args.granmc, stem + ".toml"),
                     "window": summary["viscosity"]["eta_star"], "steady": summary["viscosity"]["steady"],
                     "replicas": summary["replicas"], "seed": summary["seed"],
                     "wall_seconds": summary["wall_seconds"]})
        print(f"  alpha = {alpha:g}: {summary['wall_seconds']:.0f} s", flush=True)
    write_table(rows, args, os.path.join(args.out, "table.md"))
    plot(rows, os.path.join(args.out, "figure.png"))
    print(f"wrote {args.out}/table.md, {args.out}/figure.png")


def window_means(r):
    """T, a*, eta* and the median per-sample CI of eta* over WINDOWS consecutive windows (t > 0)."""
    t = r["times"]
    edges = np.linspace(t[1], t[-1], WINDOWS + 1)
    out = []
    for w in range(WINDOWS):
        sel = (t >= edges[w]) & (t <= edges[w + 1]) & np.isfinite(r["eta"])
        out.append({"from": edges[w], "to": edges[w + 1], "temperature": np.mean(r["temperature"][sel]),
                    "shear": np.mean(r["shear"][sel]), "eta": np.mean(r["eta"][sel]),
                    "eta_ci": np.median(r["eta_ci"][sel])})
    return out


def write_table(rows, args, path):
    with open(path, "w") as f:
        f.write(f"# 003 evolution: {args.scene}\n\n")
        f.write("T/T(0), a* and eta* (replica means) averaged over consecutive windows of the run, with the median "
                "CI of one sample of eta* (the window's mean is steadier, its samples are correlated in time); "
                "the first-Sonine Navier-Stokes eta* of the cooling state (granmc theory).\n\n")
        f.write("| alpha | window (t) | T / T(0) | a* | eta* | CI of one sample | first Sonine |\n"
                "|---|---|---|---|---|---|---|\n")
        for r in rows:
            r["windows"] = window_means(r)
            for w in r["windows"]:
                f.write(f"| {r['alpha']:g} | [{w['from']:.1f}, {w['to']:.1f}] | "
                        f"{w['temperature'] / r['temperature'][0]:.4f} | {w['shear']:.4f} | {w['eta']:.4f} | "
                        f"{w['eta_ci']:.4f} | {r['theory']:.4f} |\n")
        f.write("\nChecks: T rises and a* falls from each window to the next; eta* over the last half of the run "
                "(per-replica time average, then the replica mean and CI) and the plateau test.\n\n")
        f.write("| alpha | T(t_end)/T(0) | T rises | a* falls | eta* over the last half | CI | steady | "
                "first Sonine | replicas | seed | run (s) |\n")
        f.write("|---|---|---|---|---|---|---|---|---|---|---|\n")
        for r in rows:
            rises = bool(np.all(np.diff([w["temperature"] for w in r["windows"]]) > 0))
            falls = bool(np.all(np.diff([w["shear"] for w in r["windows"]]) < 0))
            f.write(f"| {r['alpha']:g} | {r['temperature'][-1] / r['temperature'][0]:.3f} | {yes(rises)} | "
                    f"{yes(falls)} | {r['window']['mean']:.4f} | {r['window']['ci']:.4f} | {yes(r['steady'])} | "
                    f"{r['theory']:.4f} | {r['replicas']} | {r['seed']} | {r['wall_seconds']:.0f} |\n")


def yes(flag):
    return "yes" if flag else "no"


def plot(rows, path):
    plt = pyplot()

    fig, (top, middle, bottom) = plt.subplots(3, 1, figsize=(6.4, 8.4), sharex=True)
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for k, r in enumerate(rows):
        col = colours[k % len(colours)]
        t, eta, ci = r["times"], r["eta"], r["eta_ci"]
        top.plot(t, eta, color=col, lw=1, label=f"alpha = {r['alpha']:g}")
        top.fill_between(t, eta - ci, eta + ci, color=col, alpha=0.25)
        top.axhline(r["theory"], color=col, ls="--", lw=0.8)
        middle.plot(t, r["shear"], color=col, lw=1)
        bottom.plot(t, r["temperature"] / r["temperature"][0], color=col, lw=1)
    top.set_ylabel("eta* (dashed: first Sonine, NS)")
    top.legend(fontsize=8)
    middle.set_ylabel("a* = a / nu")
    bottom.set_ylabel("T(t) / T(0)")
    bottom.set_xlabel("t")
    fig.suptitle("003: modified shear flow, evolution")
    save(fig, path)


if __name__ == "__main__":
    main()
