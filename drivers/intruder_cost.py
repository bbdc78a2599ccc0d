#!/usr/bin/env python3
"""Cost of the two 1D intruder methods for the same accuracy (docs/user-guide/accuracy-cost.md).

Usage: /usr/bin/python3 drivers/intruder_cost.py [--granmc build/bin/granmc] [--out results/intruder_cost]
                                                  [--threads 1] [--target-ci 0.005] [--dt 0.1 1 10]

Runs drivers/scenes/accuracy/intruder_gillespie.toml and intruder_dsmc.toml (the DSMC one at each --dt)
on --threads threads and tabulates, per method: collisions per second of wall time, the stationary
T/T_B with its CI against the exact 0.6 (002 eq. 22), and the wall time to reach a CI half-width of
--target-ci, wall x (CI / target)^2 (the CI of a time average falls as 1/sqrt(time)). Writes OUT/table.md.
"""
import argparse
import copy
import os
import tomllib

from granmc import run_point  # cached by scene text

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "scenes", "accuracy")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--granmc", default="build/bin/granmc")
    p.add_argument("--out", default="results/intruder_cost")
    p.add_argument("--threads", type=int, default=1)
    p.add_argument("--target-ci", type=float, default=0.005)
    p.add_argument("--dt", type=float, nargs="+", default=[0.1, 1.0, 10.0])
    args = p.parse_args()
    os.makedirs(args.out, exist_ok=True)
    runs = []
    with open(os.path.join(HERE, "intruder_gillespie.toml"), "rb") as f:
        runs.append(("Gillespie", tomllib.load(f)))
    with open(os.path.join(HERE, "intruder_dsmc.toml"), "rb") as f:
        dsmc = tomllib.load(f)
    for dt in args.dt:
        scene = copy.deepcopy(dsmc)
        scene["run"]["dt"] = dt
        runs.append((f"DSMC, dt = {dt:g}", scene))
    rows = []
    for name, scene in runs:
        stem = os.path.join(args.out, name.replace(" ", "").replace(",", "_").replace("=", ""))
        s = run_point(args.granmc, scene, stem, args.threads)
        r = s["intruder"]["temperature_ratio"]
        exact = s["intruder"]["temperature_ratio_exact"]
        wall = s["wall_seconds"]
        rows.append((name, s["intruder"]["events"] / wall, r["mean"] - exact, r["ci"], wall,
                     wall * (r["ci"] / args.target_ci) ** 2))
    with open(os.path.join(args.out, "table.md"), "w") as f:
        f.write(f"# 1D intruder, Gaussian bath, M = 1, alpha = 0.5: Gillespie against DSMC ({args.threads} thread(s))\n\n")
        f.write(f"| method | collisions/s | T/T_B - exact | CI | wall (s) | wall to CI {args.target_ci:g} (s) |\n")
        f.write("|---|---|---|---|---|---|\n")
        for name, rate, bias, ci, wall, to_target in rows:
            f.write(f"| {name} | {rate / 1e6:.2f} M | {bias:+.4f} | {ci:.4f} | {wall:.1f} | {to_target:.2f} |\n")
    print(open(os.path.join(args.out, "table.md")).read())


if __name__ == "__main__":
    main()
