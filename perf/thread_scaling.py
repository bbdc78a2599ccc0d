#!/usr/bin/env python3
"""Wall time of `granmc run` on one thread and on two, for the tables of docs/developer-guide/scaling.md
("Concurrent collision rounds", "The event scheme's rounds"): one replica of 10^7, 10^6, 4 10^5, 2 10^5 and 10^5
particles with its two threads inside it (--threads-per-replica 2), and two replicas of 10^7 and of 10^6 with one
thread each; the event scheme's one replica of 10^7, 10^6 and 10^5 with two threads inside it and two replicas of
10^7. The sizes below 10^6 (10^5 for the event scheme) are where two threads stop paying, which sets the default
(kernel/schemes/replica_runner.hpp, share_threads).

Usage: /usr/bin/python3 perf/thread_scaling.py [--granmc build/bin/granmc] [--runs 3] [--work DIR]
       (`make bench-threads`; about 5 minutes per run on this 2-core host)

The figure is the summary's wall_seconds (granmc's own wall time, set-up included). The one- and two-thread
runs of a scene alternate, so that they share the state of the (shared, noisy) machine; the script prints
every run, the speed-up of the medians, the median and range of the pairs' ratios (run k on one thread over run k
on two, which made back to back share the machine's state of the moment), and for the runs with threads inside the
replica the rounds' counts; where a size's one-replica and two-replica scenes both ran, the share of the two
replicas' speed-up that one replica reaches (the ceiling: docs/developer-guide/scaling.md, "What two cores allow").
--only REGEX keeps the scenes whose file name matches. It also checks that the two-thread files hold the bits of the one-thread files
(tests/same_bits.py --files), and exits with status 1 if they do not.
"""
import os
import re
import statistics
import subprocess
import sys

from whole_runs import ROOT, parser, run, work_directory

SCENES = os.path.join(ROOT, "drivers", "scenes", "scaling")
CASES = [  # scene, the two-thread run's extra arguments, what it measures
    ("one_replica_1e7.toml", ["--threads-per-replica", "2"], "one replica of 10^7, 2 threads inside it"),
    ("one_replica_1e6.toml", ["--threads-per-replica", "2"], "one replica of 10^6, 2 threads inside it"),
    ("one_replica_4e5.toml", ["--threads-per-replica", "2"], "one replica of 4 10^5, 2 threads inside it"),
    ("one_replica_2e5.toml", ["--threads-per-replica", "2"], "one replica of 2 10^5, 2 threads inside it"),
    ("one_replica_1e5.toml", ["--threads-per-replica", "2"], "one replica of 10^5, 2 threads inside it"),
    ("two_replicas_1e7.toml", [], "two replicas of 10^7, one thread each"),
    ("two_replicas_1e6.toml", [], "two replicas of 10^6, one thread each"),
    ("event_one_replica_1e7.toml", ["--threads-per-replica", "2"], "event scheme, one replica of 10^7, 2 threads inside it"),
    ("event_two_replicas_1e7.toml", [], "event scheme, two replicas of 10^7, one thread each"),
    ("event_one_replica_1e6.toml", ["--threads-per-replica", "2"], "event scheme, one replica of 10^6, 2 threads inside it"),
    ("event_one_replica_1e5.toml", ["--threads-per-replica", "2"], "event scheme, one replica of 10^5, 2 threads inside it"),
]


def main():
    p = parser(__doc__)
    p.add_argument("--only", default="", help="run only the scenes whose file name matches this regular expression")
    args = p.parse_args()
    work = work_directory(args, "granmc-threads-")
    same = True
    speedups = {}  # scene file stem -> (speed-up of the medians, median of the paired ratios)
    print("| scene | 1 thread (s) | 2 threads (s) | speed-up of the medians | paired ratios: median [range] "
          "| rounds, deferred, rerun in order |")
    print("|---|---|---|---|---|---|")
    for name, extra, what in CASES:
        if not re.search(args.only, name):
            continue
        scene = os.path.join(SCENES, name)
        stem = os.path.join(work, os.path.splitext(name)[0])
        one, two = [], []
        for k in range(args.runs):
            one.append(run(args.granmc, scene, 1, [], f"{stem}.t1.{k}"))
            two.append(run(args.granmc, scene, 2, extra, f"{stem}.t2.{k}"))
        check = subprocess.run([sys.executable, os.path.join(ROOT, "tests", "same_bits.py"), "--files",
                                f"{stem}.t1.0.h5", f"{stem}.t2.0.h5"], capture_output=True, text=True)
        same = same and check.returncode == 0
        w1 = sorted(s["wall_seconds"] for s in one)
        w2 = sorted(s["wall_seconds"] for s in two)
        paired = sorted(a["wall_seconds"] / b["wall_seconds"] for a, b in zip(one, two))
        rounds = "-"
        if "collision_rounds" in two[0]:
            s = two[0]
            rounds = f"{s['collision_rounds']}, {s['collision_rounds_deferred']}, {s['collision_rounds_in_order']}"
        of_medians, of_pairs = statistics.median(w1) / statistics.median(w2), statistics.median(paired)
        speedups[os.path.splitext(name)[0]] = (of_medians, of_pairs)
        print(f"| {what} | {', '.join(f'{w:.2f}' for w in w1)} | {', '.join(f'{w:.2f}' for w in w2)} | "
              f"{of_medians:.2f} | {of_pairs:.2f} [{paired[0]:.2f}, {paired[-1]:.2f}] | {rounds} |")
    # Two replicas share nothing but the memory system: their speed-up is the ceiling for one replica's rounds.
    for scheme, size in (("", "1e7"), ("", "1e6"), ("event_", "1e7")):
        one, two = speedups.get(f"{scheme}one_replica_{size}"), speedups.get(f"{scheme}two_replicas_{size}")
        if one and two:
            print(f"{scheme.replace('_', ' scheme, ')}one replica of {size} on two threads reaches {one[0] / two[0]:.2f} "
                  f"of the two replicas' speed-up (medians), {one[1] / two[1]:.2f} (paired ratios)")
    print("two-thread files hold the one-thread bits" if same else "two-thread files DIFFER from the one-thread files")
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
