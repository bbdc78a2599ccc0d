#!/usr/bin/python3
"""theta = T_rot / T_tr of white-noise-heated rough hard disks against the published DSMC and EDMD.

    /usr/bin/python3 drivers/rough_split_noise.py [--granmc build/bin/granmc] [--out results/rough_disks]

For each row of drivers/scenes/rough_disks/published_theta.csv (Megias and Santos, Front. Phys. 10 (2022)
971671: alpha, beta, the share epsilon of the noise's power on rotation, theta and its error) the scene
drivers/scenes/rough_disks/scene.toml runs at dt and dt / 2. White noise acts after the collisions (a first-order
splitting), so theta moves linearly with dt; per replica, theta(0) = 2 theta(dt/2) - theta(dt), with theta the
time average of T_rot / T over the last half of the samples, then the replica mean and its confidence half-width
lambda_p sqrt(Var / R), lambda_p = 3.2, Var with 1/R as granmc's own statistics (kernel/analysis). The rows with
most of the power on rotation (epsilon >= 0.8) relax slowly, the translation being heated only through the
collisions' tangential coupling: theta overshoots and settles over tens of time units, so they run LONG times
the scene's t_end. Writes
OUT/table.md (granmc, the published value, the Maxwellian approximation of `granmc theory`, and the deviation
over CI plus lambda_p times the published error) and OUT/figure.png (theta against epsilon, and both granmc and
the Maxwellian approximation relative to the published values).

Uses Debian's python3-h5py, python3-numpy and python3-matplotlib (hence /usr/bin/python3).
"""
import argparse
import copy
import csv
import os
import tomllib

import numpy as np

from granmc import LAMBDA_P, mean_ci, open_results, run_point, theory
from granmc.plotting import pyplot, save

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "scenes", "rough_disks")
LONG = 4  # t_end factor of the rows with epsilon >= 0.8


def published_rows():
    with open(os.path.join(HERE, "published_theta.csv")) as f:
        lines = [line for line in f if not line.startswith("#")]
    return [{k: (v if k == "method" else float(v)) for k, v in row.items()} for row in csv.DictReader(lines)]


def stationary_theta(path):
    """Per replica, the time average of T_rot / T over the last half of the samples (k >= S / 2)."""
    with open_results(path) as h:
        species = next(iter(h["species"].values()))
        t_rot = species["rotational_temperature/replicas"][()]
        t_tr = species["temperature/replicas"][()]
    first = t_tr.shape[1] // 2
    return (t_rot[:, first:] / t_tr[:, first:]).mean(axis=1)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--granmc", default="build/bin/granmc")
    p.add_argument("--out", default=os.path.join("results", "rough_disks"))
    p.add_argument("--threads", type=int, default=0)
    args = p.parse_args()
    with open(os.path.join(HERE, "scene.toml"), "rb") as f:
        base = tomllib.load(f)
    os.makedirs(os.path.join(args.out, "points"), exist_ok=True)
    dt = base["run"]["dt"]

    rows = []
    for ref in published_rows():
        thetas, stems = [], []
        for step in (dt, dt / 2):
            scene = copy.deepcopy(base)
            scene["run"]["dt"] = step
            if ref["epsilon"] >= 0.8:
                scene["run"]["t_end"] = LONG * base["run"]["t_end"]
            scene["collision"]["restitution"] = ref["alpha"]
            scene["collision"]["tangential_restitution"] = ref["beta"]
            scene["thermostat"]["rotational_share"] = ref["epsilon"]
            stem = os.path.join(args.out, "points",
                                f"a{ref['alpha']}_b{ref['beta']}_e{ref['epsilon']}_dt{step}")
            run_point(args.granmc, scene, stem, args.threads)
            thetas.append(stationary_theta(stem + ".h5"))
            stems.append(stem)
        predicted = theory(args.granmc, stems[0] + ".toml")
        mean, ci = mean_ci(2.0 * thetas[1] - thetas[0])
        tolerance = ci + LAMBDA_P * ref["error"]
        rows.append({**ref, "granmc": mean, "ci": ci, "at_dt": float(thetas[0].mean()),
                     "maxwellian": predicted["rough"]["theta_white_noise"],
                     "ratio": abs(mean - ref["theta"]) / tolerance})
        print(f"  alpha {ref['alpha']}, beta {ref['beta']}, epsilon {ref['epsilon']}: {mean:.5f} +- {ci:.5f} "
              f"(published {ref['theta']:.5f})", flush=True)

    write_table(rows, os.path.join(args.out, "table.md"))
    plot(rows, os.path.join(args.out, "figure.png"))
    worst = max(r["ratio"] for r in rows)
    print(f"wrote {args.out}/table.md, {args.out}/figure.png; worst |granmc - published| / (CI + lambda_p error) "
          f"= {worst:.2f} over {len(rows)} rows")


def write_table(rows, path):
    with open(path, "w") as f:
        f.write("# theta = T_rot / T_tr of rough hard disks (kappa = 1/2) under split white noise\n\n")
        f.write("granmc: theta at dt -> 0 (2 theta(dt/2) - theta(dt) per replica) with its CI (lambda_p = 3.2); "
                "theta(dt) at the scene's dt; published: Megias and Santos, Front. Phys. 10 (2022) 971671 (their "
                "error is one standard error); Maxwellian: `granmc theory`; ratio: |granmc - published| / (CI + "
                "lambda_p error).\n\n")
        f.write("| alpha | beta | epsilon | granmc | CI | theta(dt) | published | error | method | Maxwellian | "
                "ratio |\n|---|---|---|---|---|---|---|---|---|---|---|\n")
        for r in rows:
            f.write(f"| {r['alpha']:g} | {r['beta']:g} | {r['epsilon']:g} | {r['granmc']:.5g} | {r['ci']:.3g} | "
                    f"{r['at_dt']:.5g} | {r['theta']:.5g} | {r['error']:.1g} | {r['method']} | "
                    f"{r['maxwellian']:.5g} | {r['ratio']:.2f} |\n")


def plot(rows, path):
    """(a) theta against epsilon, log axis; (b) granmc and the Maxwellian approximation relative to the published
    value, with granmc's CI."""
    plt = pyplot()

    fig, (ax, dev) = plt.subplots(2, 1, figsize=(6.4, 7.2), sharex=True, gridspec_kw={"height_ratios": [3, 2]})
    pairs = sorted({(r["alpha"], r["beta"]) for r in rows}, reverse=True)
    for k, ((alpha, beta), colour) in enumerate(zip(pairs, ["C0", "C1", "C2", "C3"])):
        rs = [r for r in rows if (r["alpha"], r["beta"]) == (alpha, beta)]
        eps = np.array([r["epsilon"] for r in rs])
        published = np.array([r["theta"] for r in rs])
        ax.errorbar(eps, [r["granmc"] for r in rs], yerr=[r["ci"] for r in rs], fmt="o", color=colour,
                    label=f"granmc, alpha = {alpha:g}, beta = {beta:g}")
        ax.plot(eps, published, "x", color=colour, markersize=9)
        ax.plot(eps, [r["maxwellian"] for r in rs], "-", color=colour, linewidth=0.8)
        shift = 0.006 * (k - 1.5)  # side by side
        dev.errorbar(eps + shift, 100 * (np.array([r["granmc"] for r in rs]) / published - 1),
                     yerr=100 * np.array([r["ci"] for r in rs]) / published, fmt="o", color=colour, markersize=4)
        dev.plot(eps, 100 * (np.array([r["maxwellian"] for r in rs]) / published - 1), "-", color=colour,
                 linewidth=0.8)
    ax.plot([], [], "kx", label="Megias and Santos (2022), DSMC / EDMD")
    ax.plot([], [], "k-", linewidth=0.8, label="Maxwellian approximation")
    ax.set_yscale("log")
    ax.set_ylabel("theta = T_rot / T_tr")
    ax.set_title("Rough hard disks, kappa = 1/2, steady state under split white noise")
    ax.legend(fontsize=7)
    dev.axhline(0.0, color="k", linewidth=0.6)
    dev.set_xlabel("share of the noise power on rotation, epsilon")
    dev.set_ylabel("theta / published - 1 (%)")
    save(fig, path)


if __name__ == "__main__":
    main()
