#!/usr/bin/env python3
"""What a collision costs in each model: smooth and rough spheres and disks, whole `granmc run` on one thread.

Usage: /usr/bin/python3 perf/model_cost.py [--granmc build/bin/granmc] [--runs 3] [--work DIR]
       (`make bench-models`; about 20 s per run of 10^7 particles on this host, 4 x runs runs)

Scenes: drivers/scenes/model_cost/ (one replica of 10^7 particles, the cooling state at alpha = 0.9, rough ones
with beta = 0; disks run twice as long, so that every scene has about the same number of collisions). Each
pair below runs its two scenes alternately, so that they share the state of the (shared, noisy) machine. The
figure is the summary's wall_seconds per collision (set-up included); the script prints every run's
collisions per second and, per pair, the ratio of the median costs per collision and the range of the
run-by-run ratios. Results: docs/developer-guide/performance.md, "Rough particles against smooth ones".
"""
import os
import statistics
import sys

from whole_runs import ROOT, parser, run, work_directory

SCENES = os.path.join(ROOT, "drivers", "scenes", "model_cost")
PAIRS = [  # the model, its reference
    ("rough_spheres", "spheres"),
    ("rough_disks", "disks"),
    ("disks", "spheres"),
]


def main():
    args = parser(__doc__).parse_args()
    work = work_directory(args, "granmc-models-")
    print("| model / reference | collisions/s, model | collisions/s, reference | cost per collision, ratio of the "
          "medians | run-by-run ratios |")
    print("|---|---|---|---|---|")
    for model, reference in PAIRS:
        cost = {model: [], reference: []}
        for k in range(args.runs):
            for name in (model, reference):
                s = run(args.granmc, os.path.join(SCENES, name + ".toml"), 1, [], os.path.join(work, f"{name}.{k}"))
                cost[name].append(s["wall_seconds"] / s["collisions"])
        ratios = [a / b for a, b in zip(cost[model], cost[reference])]
        rate = {name: ", ".join(f"{1.0 / c:.2e}" for c in cost[name]) for name in cost}
        print(f"| {model} / {reference} | {rate[model]} | {rate[reference]} | "
              f"{statistics.median(cost[model]) / statistics.median(cost[reference]):.2f} | "
              f"{min(ratios):.2f} - {max(ratios):.2f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
