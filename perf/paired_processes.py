#!/usr/bin/env python3
"""The paired ratios of bench_effects over several processes (docs/developer-guide/performance.md, effects).

Usage: /usr/bin/python3 perf/paired_processes.py [--bin build/bin] [--processes K] [--scenes REGEX]
                                                  [--paired-rounds R] [--one-at-a-time]

Within one process, bench_effects' paired ratios (each scene against plain, one step of each back to back)
have confidence intervals of +-0.5-2 %, but the ratio itself moves by up to +-8 % from one process to the
next (measured: plain / hand_specialised 0.936 to 1.094 in three processes whose intervals were
+-0.5 %). The memory placement of each process (address-space randomisation, which physical pages back
the particle buffers and the stack arrays of a batch) decides it, and it favours one code or the other at
random. So a ratio of two codes is a mean over placements, and this script samples placements: it runs
bench_effects K times (`--benchmark_filter` from --scenes, which must match plain; the Google Benchmark
part kept short) and reports, per scene, the median over processes of the per-process median ratio, with
the distribution-free 95 % confidence interval of that median (order statistics chosen from the exact
binomial(K, 1/2) law), and the range.

--one-at-a-time runs each scene of --scenes in processes of its own with plain alone (K processes per
scene), not all scenes in one process. In processes holding all ten gases of bench_effects (320 MB) the
plain scene measured slow against scenes that run the identical code (11 processes: median
ratio to plain 0.98 for enskog_chi, 0.95 for the Gaussian thermostat's one log1p per step, plain /
hand-specialised 1.10), and not with one other gas per process (0.97-1.04 and 1.02), for a reason not
found; so the ratios in docs/developer-guide/performance.md are measured one scene at a time.
"""
import argparse
import math
import re
import subprocess
import sys

LINE = re.compile(r"^\| (\w+) \| ([0-9.]+) \| \[([0-9.]+), ([0-9.]+)\] \|")


def median_interval(values, level=0.95):
    """The median of `values` and the order statistics (l, u) with P(x_(l) <= median <= x_(u)) >= level
    under the binomial(n, 1/2) law, the narrowest such symmetric pair (the whole range if none is)."""
    x = sorted(values)
    n = len(x)
    med = 0.5 * (x[(n - 1) // 2] + x[n // 2])
    cdf = lambda k: sum(math.comb(n, i) for i in range(k + 1)) / 2.0**n  # P(B <= k)
    # coverage of [x_(j), x_(n+1-j)] (1-based) is 1 - 2 P(B <= j - 1)
    best = 1
    for j in range(1, n // 2 + 1):
        if 1.0 - 2.0 * cdf(j - 1) >= level:
            best = j
    return med, x[best - 1], x[n - best]


def run_once(binary, scenes, rounds):
    out = subprocess.run(
        [binary, f"--benchmark_filter=^({scenes})$", "--benchmark_repetitions=1", "--benchmark_min_time=0.3",
         f"--paired_rounds={rounds}"],
        check=True, capture_output=True, text=True).stdout
    section = out.split("Paired:", 1)
    if len(section) != 2:
        sys.exit("paired_processes: bench_effects printed no paired section (does --scenes match plain?)")
    return {m.group(1): float(m.group(2)) for m in map(LINE.match, section[1].splitlines()) if m}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", default="build/bin")
    ap.add_argument("--processes", type=int, default=11)
    ap.add_argument("--scenes", default="plain|hand_specialised|two_species",
                    help="regex alternatives of bench_effects scene names; must include plain")
    ap.add_argument("--paired-rounds", type=int, default=301)
    ap.add_argument("--one-at-a-time", action="store_true", help="each scene in processes of its own with plain")
    a = ap.parse_args()
    ratios = {}
    groups = [a.scenes]
    if a.one_at_a_time:
        groups = [f"plain|{s}" for s in a.scenes.split("|") if s != "plain"]
    for group in groups:
        for p in range(a.processes):
            for scene, r in run_once(f"{a.bin}/bench_effects", group, a.paired_rounds).items():
                ratios.setdefault(scene, []).append(r)
            print(f"{group}, process {p + 1}/{a.processes}: " +
                  ", ".join(f"{s} {v[-1]:.3f}" for s, v in ratios.items() if f"|{s}" in f"|{group}"),
                  file=sys.stderr, flush=True)
    print(f"\nRatio to plain over {a.processes} processes ({a.paired_rounds} paired rounds each): median of the "
          "per-process medians, its 95 % CI (order statistics), range")
    print("| scene | ratio to plain | 95 % CI | range |\n|---|---|---|---|")
    for scene, v in ratios.items():
        med, lo, hi = median_interval(v)
        print(f"| {scene} | {med:.3f} | [{lo:.3f}, {hi:.3f}] | {min(v):.3f} - {max(v):.3f} |")
    if "hand_specialised" in ratios:
        med, lo, hi = median_interval([1.0 / r for r in ratios["hand_specialised"]])
        print(f"\nplain / hand_specialised: {med:.3f}, 95 % CI [{lo:.3f}, {hi:.3f}] (target: within 3 %)")


if __name__ == "__main__":
    main()
