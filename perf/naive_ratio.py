#!/usr/bin/env python3
"""Whole-run accepted collisions per second of `granmc run` against the plain scalar code of perf/naive_run.cpp,
one thread each, set-up included.

Usage: /usr/bin/python3 perf/naive_ratio.py [--granmc build/bin/granmc] [--naive build/bin/naive_run] [--runs 3]
       [--work DIR]   (`make bench-naive`; about 4 minutes per run on this host)

Scenes: drivers/scenes/scaling/one_replica_1e6.toml and one_replica_1e7.toml (one replica of elastic hard spheres,
n = sigma = 1, T(0) = 1, dt = 0.1, 200 and 20 steps); naive_run runs the same gas, steps and seed-free physics
with Bird's no-time-counter scheme. The granmc figure is the summary's collisions over its wall_seconds; the
naive one its own. Runs of the two alternate, so that they share the state of the (shared, noisy) machine. The
script prints every run's rate, the ratio of the median rates, the range of the run-by-run ratios, and the
collisions per particle and step of both in the last run: the same physics, so they agree within the noise of
their initial temperatures (neither rescales its Maxwellian sample to T = 1: the rate moves by about
sqrt(2 / (3 N)) / 2, 4 10^-4 at N = 10^6, in each).
"""
import json
import os
import statistics
import subprocess
import sys
import tomllib

from whole_runs import ROOT, parser, run, work_directory

SCENES = os.path.join(ROOT, "drivers", "scenes", "scaling")


def naive(binary, scene):
    r, species = scene["run"], scene["species"][0]
    out = subprocess.run([binary, "--particles", str(species["particles"]), "--t-end", str(r["t_end"]),
                          "--dt", str(r["dt"]), "--seed", str(r.get("seed", 7))],
                         check=True, capture_output=True, text=True).stdout
    return json.loads(out)


def main():
    p = parser(__doc__)
    p.add_argument("--naive", default=os.path.join(ROOT, "build", "bin", "naive_run"))
    args = p.parse_args()
    work = work_directory(args, "granmc-naive-")
    print("| particles | granmc collisions/s | naive collisions/s | ratio of the medians | run-by-run ratios "
          "| collisions per particle and step, granmc / naive |")
    print("|---|---|---|---|---|---|")
    for name in ("one_replica_1e6", "one_replica_1e7"):
        path = os.path.join(SCENES, name + ".toml")
        with open(path, "rb") as f:
            scene = tomllib.load(f)
        ours, theirs, per = [], [], None
        for k in range(args.runs):
            s = run(args.granmc, path, 1, [], os.path.join(work, f"{name}.{k}"))
            b = naive(args.naive, scene)
            ours.append(s["collisions"] / s["wall_seconds"])
            theirs.append(b["collisions"] / b["wall_seconds"])
            n, steps = b["particles"], b["steps"]
            per = (s["collisions"] / (n * steps), b["collisions"] / (n * steps))
        ratios = sorted(a / b for a, b in zip(ours, theirs))
        print(f"| {scene['species'][0]['particles']:.0e} | {', '.join(f'{x:.3g}' for x in ours)} | "
              f"{', '.join(f'{x:.3g}' for x in theirs)} | {statistics.median(ours) / statistics.median(theirs):.2f} | "
              f"{ratios[0]:.2f} - {ratios[-1]:.2f} | {per[0]:.5f} / {per[1]:.5f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
