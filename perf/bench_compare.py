#!/usr/bin/env python3
"""Regression check of the benchmark suite by ratios (docs/developer-guide/performance.md, Regression benchmarks).

Usage: /usr/bin/python3 perf/bench_compare.py [--bin build/bin] [--save] [--threshold 0.10] [--rounds K]
                        [--repetitions R] [--json-dir DIR] [--from-json DIR] [--baseline FILE] [--self-test]

Runs perf's Google Benchmark programs with --benchmark_out=DIR/<program>.<part>.json (JSON), takes the median
of the repetitions of each counter, and forms a few named ratios whose two sides ran close together in time,
so that they share the state of the (shared, noisy) machine:

  granmc_over_naive/1e5, /1e6, /1e7    granmc_collide / naive_collide candidates/s at N = 10^5, 10^6, 10^7
                                       (bench_collisions, one size at a time, repetitions interleaved at
                                       random between the two)                                (higher is better)
  granmc_over_packed_limit/1e5, /1e7   granmc_collide candidates/s over limit_collide pairs/s at the same N:
                                       the collision kernel against the packed-record gather/scatter limit
                                       (perf/gather_scatter_limit.hpp), both in the same bench_collisions run,
                                       repetitions interleaved at random            (higher is better)
  event_maxwell_over_packed_limit/1e5, /1e7
  event_hard_sphere_over_packed_limit/1e5, /1e7
                                       bench_event: the event scheme of 001 (examples 7 and 8, one replica)
                                       event_maxwell or event_hard_sphere candidates/s over limit_pairs
                                       pairs/s at the same N, the limit kernel in the same bench_event run
                                                                                          (higher is better)
  swpm_over_event/maxwell, /hard_sphere
                                       bench_swpm: the weighted particles of 001 (examples 7 and 8, one
                                       replica) against the equal-weight event scheme holding as many
                                       particles, swpm_<kernel> / event_<kernel> collisions/s in the same run
                                                                                          (higher is better)
  effect_over_plain/<scene>            bench_effects: time per candidate of a scene / of plain (one run, 5
                                       repetitions interleaved at random), one per scene     (lower is better)
  plain_over_hand                      bench_effects: plain / hand_specialised time per candidate
                                                                                               (lower is better)

Order of one round: bench_collisions (granmc, naive and the limit kernel) at 10^5, bench_event
(event_maxwell, event_hard_sphere and the limit kernel, not the event_sync_* parts) at 10^5,
bench_collisions at 10^6 (granmc and naive), the same two at 10^7, bench_swpm (all four), then bench_effects (all
scenes). Repetitions: each program's default (3, 3, 3, 3 and 5) unless --repetitions.
--rounds K runs K rounds (DIR/round1 ... DIR/roundK) and takes each ratio's median over the rounds.

Without --save it compares the ratios with the baseline (perf/baselines/baseline.json) and prints a table; a
"higher is better" ratio that fell by more than its threshold, a "lower is better" one that rose by more than
its threshold, or a baseline ratio that is missing now, is flagged ("improved" past the threshold is shown
but not flagged), and the exit status is 1 if any is flagged, 0 otherwise. The threshold is --threshold
(default: the baseline's "threshold", 0.10); a ratio that matches an entry of the baseline's "thresholds" (a
name or an fnmatch pattern such as "effect_over_plain/*") uses the largest of those and the default: they are
floors set by each ratio's measured noise.

--save writes the baseline instead: the ratios (and each round's), the date, the git commit, the CPU model
from /proc/cpuinfo and the raw medians with the load averages (for reference); it keeps the per-ratio
thresholds of the baseline it replaces. --from-json DIR compares (or saves) the JSON of an earlier run
(DIR/<program>*.json, or DIR/round*/) without running anything. --self-test checks the comparison logic on
synthetic numbers (a few seconds, runs no benchmark).
"""
import argparse
import datetime
import fnmatch
import glob
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_BASELINE = os.path.join(REPO, "perf", "baselines", "baseline.json")
PROGRAMS = ("bench_collisions", "bench_event", "bench_swpm", "bench_effects")
INTERLEAVE = "--benchmark_enable_random_interleaving=true"
# One round: (program, part, --benchmark_filter or None, extra flags), in this order. One size at a time, so
# that no program rebuilds its 10^7-particle state between interleaved repetitions.
ROUND = (
    ("bench_collisions", "1e5", "^(granmc|naive|limit)_collide/100000$", (INTERLEAVE,)),
    ("bench_event", "1e5", "^(event_(maxwell|hard_sphere)|limit_pairs)/100000$", ()),
    ("bench_collisions", "1e6", "^(granmc|naive)_collide/1000000$", (INTERLEAVE,)),
    ("bench_collisions", "1e7", "^(granmc|naive|limit)_collide/10000000$", (INTERLEAVE,)),
    ("bench_event", "1e7", "^(event_(maxwell|hard_sphere)|limit_pairs)/10000000$", ()),  # not interleaved: one 10^7 gas at a time
    ("bench_swpm", "all", None, ()),
    ("bench_effects", "all", None, ()),  # its defaults: 5 repetitions, interleaved
)
DEFAULT_THRESHOLD = 0.10
# Per-ratio thresholds (floors; keys are names or fnmatch patterns) written into a new baseline, which keeps
# those of the baseline it replaces. Set from the spread between rounds measured on the project machine under
# load 4-5.5 on its 2 vCPUs, for the median of 3 rounds against the median of 5 (docs/developer-guide/performance.md,
# Regression benchmarks): about the 95th percentile of the change the wrong way with nothing changed.
DEFAULT_RATIO_THRESHOLDS = {
    "granmc_over_naive/1e7": 0.40,
    "granmc_over_packed_limit/*": 0.30,
    "event_*_over_packed_limit/*": 0.30,
    "swpm_over_event/*": 0.20,
    "effect_over_plain/*": 0.20,
    "plain_over_hand": 0.20,
}

SIZES = {"1e5": "100000", "1e7": "10000000"}
NAIVE_SIZES = {"1e5": "100000", "1e6": "1000000", "1e7": "10000000"}  # bench_collisions only
EVENT_KERNELS = ("maxwell", "hard_sphere")  # bench_event's event_<kernel>/N
SWPM_KERNELS = ("maxwell", "hard_sphere")  # bench_swpm's swpm_<kernel> and event_<kernel>
EFFECT_COUNTER = "time/cand"
EFFECT_PLAIN = "plain"
EFFECT_HAND = "hand_specialised"


# ---- reading Google Benchmark JSON --------------------------------------------------------------------

def medians_of(report):
    """{run_name: {counter: median}} of one Google Benchmark JSON report.

    The "median" aggregate where there is one (repetitions > 1); otherwise the median of the single runs
    (one run, or a file written with --benchmark_report_aggregates_only=false and no aggregates)."""
    aggregated, single = {}, {}
    skip = {"family_index", "per_family_instance_index", "repetitions", "repetition_index", "threads",
            "iterations", "real_time", "cpu_time"}
    for b in report.get("benchmarks", []):
        if b.get("error_occurred"):
            continue
        name = b.get("run_name", b["name"])
        counters = {k: v for k, v in b.items() if k not in skip and isinstance(v, (int, float))
                    and not isinstance(v, bool)}
        if isinstance(b.get("cpu_time"), (int, float)):
            counters["cpu_time"] = b["cpu_time"]  # in the report's time_unit, for reference
        if b.get("run_type") == "aggregate":
            if b.get("aggregate_name") == "median":
                aggregated[name] = counters
        else:
            for k, v in counters.items():
                single.setdefault(name, {}).setdefault(k, []).append(v)
    out = {name: {k: statistics.median(v) for k, v in c.items()} for name, c in single.items()}
    out.update(aggregated)
    return out


def load_dir(directory):
    """{program: {"medians": ..., "context": [...]}} from DIR/<program>.json and DIR/<program>.<part>.json
    (the parts' benchmarks merged); a program with no file is left out."""
    runs = {}
    for prog in PROGRAMS:
        paths = sorted(glob.glob(os.path.join(glob.escape(directory), prog + ".json")) +
                       glob.glob(os.path.join(glob.escape(directory), prog + ".*.json")))
        for path in paths:
            with open(path) as f:
                report = json.load(f)
            ctx = report.get("context", {})
            r = runs.setdefault(prog, {"medians": {}, "context": []})
            r["medians"].update(medians_of(report))
            r["context"].append({"file": os.path.basename(path),
                                 **{k: ctx.get(k) for k in ("date", "executable", "load_avg", "library_build_type")}})
    return runs


def round_dirs(directory):
    """DIR/round1, DIR/round2, ... if there are any, else [DIR]."""
    subs = [d for d in glob.glob(os.path.join(glob.escape(directory), "round*")) if os.path.isdir(d)
            and os.path.basename(d)[5:].isdigit()]
    return sorted(subs, key=lambda d: int(os.path.basename(d)[5:])) or [directory]


# ---- the ratios ----------------------------------------------------------------------------------------

def _get(runs, prog, bench, counter):
    try:
        v = runs[prog]["medians"][bench][counter]
    except KeyError:
        return None
    return v if v is not None and math.isfinite(v) and v > 0 else None


def _ratio(runs, num, den):
    a, b = _get(runs, *num), _get(runs, *den)
    return None if a is None or b is None else a / b


def compute_ratios(runs):
    """{name: {"value", "better", "what"}}; a ratio whose inputs are missing is left out."""
    out = {}

    def put(name, value, better, what):
        if value is not None:
            out[name] = {"value": value, "better": better, "what": what}

    for tag, n in NAIVE_SIZES.items():
        put(f"granmc_over_naive/{tag}",
            _ratio(runs, ("bench_collisions", f"granmc_collide/{n}", "candidates/s"),
                   ("bench_collisions", f"naive_collide/{n}", "candidates/s")),
            "higher", f"granmc_collide / naive_collide candidates/s at N = {tag} (bench_collisions)")
    for tag, n in SIZES.items():
        put(f"granmc_over_packed_limit/{tag}",
            _ratio(runs, ("bench_collisions", f"granmc_collide/{n}", "candidates/s"),
                   ("bench_collisions", f"limit_collide/{n}", "pairs/s")),
            "higher", f"granmc_collide candidates/s / limit_collide pairs/s at N = {tag} (bench_collisions, same run)")
    for kernel in EVENT_KERNELS:
        for tag, n in SIZES.items():
            put(f"event_{kernel}_over_packed_limit/{tag}",
                _ratio(runs, ("bench_event", f"event_{kernel}/{n}", "candidates/s"),
                       ("bench_event", f"limit_pairs/{n}", "pairs/s")),
                "higher", f"event_{kernel} candidates/s / limit_pairs pairs/s at N = {tag} (bench_event, same run)")
    for kernel in SWPM_KERNELS:
        put(f"swpm_over_event/{kernel}",
            _ratio(runs, ("bench_swpm", f"swpm_{kernel}", "collisions/s"),
                   ("bench_swpm", f"event_{kernel}", "collisions/s")),
            "higher", f"swpm_{kernel} / event_{kernel} collisions/s at the same particle count (bench_swpm, same run)")
    effects = runs.get("bench_effects", {}).get("medians", {})
    for scene in sorted(effects):
        if scene in (EFFECT_PLAIN, EFFECT_HAND) or EFFECT_COUNTER not in effects[scene]:
            continue
        put(f"effect_over_plain/{scene}",
            _ratio(runs, ("bench_effects", scene, EFFECT_COUNTER), ("bench_effects", EFFECT_PLAIN, EFFECT_COUNTER)),
            "lower", f"{scene} / plain time per candidate (bench_effects)")
    put("plain_over_hand",
        _ratio(runs, ("bench_effects", EFFECT_PLAIN, EFFECT_COUNTER), ("bench_effects", EFFECT_HAND, EFFECT_COUNTER)),
        "lower", "plain / hand_specialised time per candidate (bench_effects)")
    return out


def combine_rounds(per_round):
    """Each ratio's median over the rounds where it was formed (per_round: [compute_ratios(...), ...])."""
    out = {}
    for ratios in per_round:
        for name, r in ratios.items():
            out.setdefault(name, {"better": r["better"], "what": r["what"], "values": []})["values"].append(r["value"])
    return {name: {"value": statistics.median(r["values"]), "better": r["better"], "what": r["what"],
                   **({"rounds": r["values"]} if len(per_round) > 1 else {})}
            for name, r in out.items()}


# ---- comparing -----------------------------------------------------------------------------------------

def compare(baseline, current, threshold=None):
    """Rows (name, better, threshold, base, cur, change, status, current rounds or None) and whether any
    is flagged.

    change = cur / base - 1. status: "ok", "REGRESSION" (the wrong way by more than the threshold),
    "improved" (the right way by more than the threshold: a new baseline may be due), "MISSING" (in the
    baseline, not measured now: flagged), "new" (measured now, not in the baseline: not flagged)."""
    default = baseline.get("threshold", DEFAULT_THRESHOLD) if threshold is None else threshold
    own = baseline.get("thresholds", {})
    base_ratios = baseline.get("ratios", {})
    rows, flagged = [], False
    for name in list(base_ratios) + [n for n in current if n not in base_ratios]:
        b = base_ratios.get(name)
        c = current.get(name)
        better = (b or c)["better"]
        thr = max([default] + [t for key, t in own.items() if fnmatch.fnmatchcase(name, key)])  # own: floors
        if b is None:
            rows.append((name, better, thr, None, c["value"], None, "new", c.get("rounds")))
            continue
        if c is None:
            rows.append((name, better, thr, b["value"], None, None, "MISSING", None))
            flagged = True
            continue
        change = c["value"] / b["value"] - 1.0
        worse = -change if better == "higher" else change
        status = "REGRESSION" if worse > thr else "improved" if -worse > thr else "ok"
        flagged |= status == "REGRESSION"
        rows.append((name, better, thr, b["value"], c["value"], change, status, c.get("rounds")))
    return rows, flagged


def print_table(rows, out=sys.stdout):
    def f(x, fmt):
        return "-" if x is None else fmt.format(x)
    spread = any(r[7] for r in rows)  # several rounds: each one's change against the baseline
    print("| ratio | better | threshold | baseline | current | change | status |" +
          (" rounds: change of each |" if spread else ""), file=out)
    print("|---|---|---|---|---|---|---|" + ("---|" if spread else ""), file=out)
    for name, better, thr, b, c, change, status, rounds in rows:
        line = (f"| {name} | {better} | {thr:.0%} | {f(b, '{:.4g}')} | {f(c, '{:.4g}')} | "
                f"{f(None if change is None else 100 * change, '{:+.1f} %')} | {status} |")
        if spread:
            each = ", ".join(f"{100 * (v / b - 1):+.0f}" for v in rounds) + " %" if rounds and b else "-"
            line += f" {each} |"
        print(line, file=out)


# ---- running and saving --------------------------------------------------------------------------------

def run_round(bin_dir, json_dir, repetitions):
    os.makedirs(json_dir, exist_ok=True)
    for prog, part, pattern, flags in ROUND:
        exe = os.path.join(bin_dir, prog)
        if not os.access(exe, os.X_OK):
            sys.exit(f"bench_compare: {exe} not found: build it (make bench-compare, or cmake --build BUILD "
                     f"--target {' '.join(PROGRAMS)}) or pass --bin")
        stem = os.path.join(json_dir, f"{prog}.{part}")
        cmd = [exe, f"--benchmark_out={stem}.json", "--benchmark_out_format=json", *flags]
        if pattern:
            cmd.append(f"--benchmark_filter={pattern}")
        if repetitions:
            cmd.append(f"--benchmark_repetitions={repetitions}")
        print(f"  {prog} ({part}) ...", end="", flush=True)
        t0 = time.monotonic()
        with open(stem + ".txt", "w") as f:
            rc = subprocess.run(cmd, stdout=f, stderr=subprocess.STDOUT).returncode
        print(f" {time.monotonic() - t0:.0f} s", flush=True)
        if rc != 0:
            sys.exit(f"bench_compare: {prog} exited with status {rc}, see {stem}.txt")


def clear_old_output(json_dir):
    """Removes what an earlier run left in json_dir (its rounds and files), so that none is read again."""
    if not os.path.isdir(json_dir):
        return
    for d in dict.fromkeys([json_dir] + round_dirs(json_dir)):
        for path in glob.glob(os.path.join(glob.escape(d), "bench_*.json")) + \
                glob.glob(os.path.join(glob.escape(d), "bench_*.txt")) + \
                glob.glob(os.path.join(glob.escape(d), "commit.txt")):
            os.remove(path)
        if d != json_dir:
            try:
                os.rmdir(d)
            except OSError as e:
                sys.exit(f"bench_compare: cannot clear {d} of an earlier run ({e}); remove it or use --json-dir")


def git_commit():
    try:
        head = subprocess.run(["git", "-C", REPO, "rev-parse", "HEAD"], capture_output=True, text=True,
                              check=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", REPO, "status", "--porcelain", "--untracked-files=no"],
                               capture_output=True, text=True, check=True).stdout.strip() != ""
        return head + ("-dirty" if dirty else "")
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return "unknown"


def make_baseline(rounds, ratios, old=None, threshold=None, commit=None):
    """rounds: [load_dir(...), ...]; ratios: combine_rounds(...); commit: HEAD when the benchmarks started
    (DIR/commit.txt), else HEAD now."""
    thresholds = dict(DEFAULT_RATIO_THRESHOLDS)
    if old:
        thresholds.update(old.get("thresholds", {}))
    written = datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds")
    dates = [c["date"] for runs in rounds for r in runs.values() for c in r["context"]
             if isinstance(c, dict) and isinstance(c.get("date"), str) and c["date"][:1].isdigit()]
    measured = min(dates) if dates else None
    binaries = {}
    for runs in rounds:
        for r in runs.values():
            for c in r["context"]:
                exe = c.get("executable") if isinstance(c, dict) else None
                if exe and os.path.exists(exe):
                    binaries[exe] = datetime.datetime.fromtimestamp(
                        os.path.getmtime(exe), datetime.timezone.utc).isoformat(timespec="seconds")
    return {
        "what": "perf/bench_compare.py baseline: ratios of medians within one run (docs/developer-guide/performance.md, "
                "Regression benchmarks)",
        "date": measured or written,  # of the first benchmark run (the context of its JSON)
        "written": written,
        "commit": commit or git_commit(),  # "-dirty": the working tree had uncommitted changes
        "cpu": cpu_model(),
        "binaries": binaries,  # modification time of each program, when this file was written
        "threshold": threshold if threshold is not None else (old or {}).get("threshold", DEFAULT_THRESHOLD),
        "thresholds": thresholds,
        "ratios": ratios,
        "runs": [{prog: {"context": r["context"], "medians": r["medians"]} for prog, r in runs.items()}
                 for runs in rounds],
    }


# ---- self-test -----------------------------------------------------------------------------------------

def synthetic_report(medians, aggregates=True):
    """A Google Benchmark JSON report whose medians are `medians` ({run_name: {counter: value}})."""
    rows = []
    for name, counters in medians.items():
        if aggregates:
            for agg, scale in (("mean", 1.01), ("median", 1.0), ("stddev", 0.05)):
                rows.append({"name": f"{name}_{agg}", "run_name": name, "run_type": "aggregate",
                             "aggregate_name": agg, "repetitions": 3, "iterations": 3, "cpu_time": 1.0,
                             **{k: v * scale for k, v in counters.items()}})
        else:  # three single runs whose median is the value
            for scale in (0.9, 1.0, 1.3):
                rows.append({"name": name, "run_name": name, "run_type": "iteration", "iterations": 10,
                             "cpu_time": 1.0, **{k: v * scale for k, v in counters.items()}})
    return {"context": {"date": "synthetic", "load_avg": [0, 0, 0]}, "benchmarks": rows}


def load_dir_synthetic(medians):
    return {prog: {"medians": m, "context": {"date": "synthetic"}} for prog, m in medians.items()}


def self_test():
    medians = {
        "bench_collisions": {"granmc_collide/100000": {"candidates/s": 11e6},
                             "naive_collide/100000": {"candidates/s": 13e6},
                             "granmc_collide/10000000": {"candidates/s": 10e6},
                             "naive_collide/10000000": {"candidates/s": 5e6},
                             "limit_collide/100000": {"pairs/s": 140e6},
                             "limit_collide/10000000": {"pairs/s": 36e6}},
        "bench_event": {"event_maxwell/100000": {"candidates/s": 15e6, "collisions/s": 15e6, "acceptance": 1.0},
                        "event_hard_sphere/100000": {"candidates/s": 10e6, "collisions/s": 1.8e6,
                                                     "acceptance": 0.18},
                        "event_maxwell/10000000": {"candidates/s": 6.65e6, "collisions/s": 6.65e6,
                                                   "acceptance": 1.0},
                        "event_hard_sphere/10000000": {"candidates/s": 7.6e6, "collisions/s": 1.3e6,
                                                       "acceptance": 0.17},
                        "event_sync_maxwell/10000000": {"particles/s": 66e6},
                        "limit_pairs/100000": {"pairs/s": 150e6},
                        "limit_pairs/10000000": {"pairs/s": 38e6}},
        "bench_swpm": {"swpm_maxwell": {"candidates/s": 1.7e6, "collisions/s": 1.2e6, "particles": 39e3},
                       "event_maxwell": {"candidates/s": 15e6, "collisions/s": 15e6, "particles": 41e3},
                       "swpm_hard_sphere": {"candidates/s": 2.6e6, "collisions/s": 0.4e6, "particles": 49e3},
                       "event_hard_sphere": {"candidates/s": 12e6, "collisions/s": 2e6, "particles": 47e3}},
        "bench_effects": {"plain": {"time/cand": 80e-9}, "white_noise": {"time/cand": 840e-9},
                          "shear": {"time/cand": 100e-9}, "hand_specialised": {"time/cand": 78e-9},
                          "white_noise_apply": {"time/particle": 74e-9}},
    }
    failures = []

    def check(cond, what):
        print(("ok   " if cond else "FAIL ") + what)
        if not cond:
            failures.append(what)

    def ratios_of(m, aggregates=True):
        with tempfile.TemporaryDirectory() as d:
            for prog, med in m.items():
                with open(os.path.join(d, prog + ".json"), "w") as f:
                    json.dump(synthetic_report(med, aggregates), f)
            return compute_ratios(load_dir(d))

    def altered(prog, bench, counter, factor):
        m = json.loads(json.dumps(medians))
        m[prog][bench][counter] *= factor
        return m

    base_ratios = ratios_of(medians)
    names = {"granmc_over_naive/1e5", "granmc_over_naive/1e7", "granmc_over_packed_limit/1e5",
             "granmc_over_packed_limit/1e7", "effect_over_plain/white_noise", "effect_over_plain/shear",
             "plain_over_hand"}
    event_names = {f"event_{k}_over_packed_limit/{tag}" for k in EVENT_KERNELS for tag in SIZES}
    swpm_names = {f"swpm_over_event/{k}" for k in SWPM_KERNELS}
    names |= event_names | swpm_names
    check(set(base_ratios) == names, f"the ratios are {sorted(names)} (got {sorted(base_ratios)})")
    check(abs(base_ratios["event_hard_sphere_over_packed_limit/1e7"]["value"] - 0.2) < 1e-12 and
          abs(base_ratios["event_maxwell_over_packed_limit/1e5"]["value"] - 0.1) < 1e-12,
          "event_hard_sphere_over_packed_limit/1e7 = 7.6e6 / 38e6, "
          "event_maxwell_over_packed_limit/1e5 = 15e6 / 150e6")
    check(abs(base_ratios["granmc_over_naive/1e7"]["value"] - 2.0) < 1e-12, "granmc_over_naive/1e7 = 10e6 / 5e6")
    check(abs(base_ratios["swpm_over_event/hard_sphere"]["value"] - 0.2) < 1e-12 and
          abs(base_ratios["swpm_over_event/maxwell"]["value"] - 0.08) < 1e-12,
          "swpm_over_event/hard_sphere = 0.4e6 / 2e6, swpm_over_event/maxwell = 1.2e6 / 15e6 (collisions/s)")
    check(abs(base_ratios["effect_over_plain/white_noise"]["value"] - 10.5) < 1e-12,
          "effect_over_plain/white_noise = 840 / 80")
    check(base_ratios == ratios_of(medians, aggregates=False), "median of single runs = median aggregate")
    baseline = make_baseline([load_dir_synthetic(medians)], base_ratios)
    check(baseline["thresholds"] == DEFAULT_RATIO_THRESHOLDS, "a new baseline gets the default per-ratio thresholds")
    baseline["thresholds"] = {}  # the tests below use the 10 % threshold alone, then their own

    _, flagged = compare(baseline, base_ratios)
    check(not flagged, "an unchanged run is not flagged")
    cases = [
        (("bench_collisions", "granmc_collide/10000000", "candidates/s", 0.80), True,
         "granmc 20 % slower at 1e7: both 1e7 ratios flagged", {"granmc_over_naive/1e7", "granmc_over_packed_limit/1e7"}),
        (("bench_collisions", "granmc_collide/10000000", "candidates/s", 0.95), False, "granmc 5 % slower: not flagged",
         set()),
        (("bench_collisions", "naive_collide/100000", "candidates/s", 1.15), True,
         "naive 15 % faster at 1e5: granmc_over_naive/1e5 flagged", {"granmc_over_naive/1e5"}),
        (("bench_collisions", "granmc_collide/100000", "candidates/s", 1.5), False, "granmc 50 % faster: improved, "
         "not flagged", set()),
        (("bench_event", "limit_pairs/10000000", "pairs/s", 1.2), True,
         "bench_event's limit 20 % faster (event the same): the two event 1e7 limit ratios flagged",
         {"event_maxwell_over_packed_limit/1e7", "event_hard_sphere_over_packed_limit/1e7"}),
        (("bench_collisions", "limit_collide/10000000", "pairs/s", 1.2), True,
         "bench_collisions' limit 20 % faster (granmc the same): granmc_over_packed_limit/1e7 flagged",
         {"granmc_over_packed_limit/1e7"}),
        (("bench_event", "event_hard_sphere/10000000", "candidates/s", 0.8), True,
         "event hard spheres 20 % slower at 1e7: flagged", {"event_hard_sphere_over_packed_limit/1e7"}),
        (("bench_event", "event_maxwell/100000", "candidates/s", 0.8), True,
         "event Maxwell 20 % slower at 1e5: flagged", {"event_maxwell_over_packed_limit/1e5"}),
        (("bench_event", "event_maxwell/100000", "collisions/s", 0.5), False,
         "event collisions/s halved, candidates/s the same: not flagged", set()),
        (("bench_event", "event_sync_maxwell/10000000", "particles/s", 0.5), False,
         "event_sync_* 50 % slower: no ratio, not flagged", set()),
        (("bench_swpm", "swpm_maxwell", "collisions/s", 0.8), True, "swpm Maxwell 20 % slower: flagged",
         {"swpm_over_event/maxwell"}),
        (("bench_swpm", "event_hard_sphere", "collisions/s", 1.2), True,
         "bench_swpm's event hard spheres 20 % faster (swpm the same): swpm_over_event/hard_sphere flagged",
         {"swpm_over_event/hard_sphere"}),
        (("bench_swpm", "swpm_hard_sphere", "candidates/s", 0.5), False,
         "swpm candidates/s halved, collisions/s the same: not flagged", set()),
        (("bench_effects", "shear", "time/cand", 1.2), True, "shear 20 % slower than plain: flagged",
         {"effect_over_plain/shear"}),
        (("bench_effects", "shear", "time/cand", 0.8), False, "shear 20 % faster: not flagged", set()),
        (("bench_effects", "plain", "time/cand", 1.2), True,
         "plain 20 % slower: plain_over_hand flagged (the effect ratios fall: not flagged)", {"plain_over_hand"}),
        (("bench_effects", "white_noise", "time/cand", 1.09), False, "white noise 9 % slower: not flagged", set()),
    ]
    for (prog, bench, counter, factor), want, what, which in cases:
        rows, flagged = compare(baseline, ratios_of(altered(prog, bench, counter, factor)))
        got = {r[0] for r in rows if r[6] == "REGRESSION"}
        check(flagged == want and got == which, f"{what} (flagged: {sorted(got)})")

    slow = ratios_of(altered("bench_collisions", "granmc_collide/10000000", "candidates/s", 0.85))
    check(compare(baseline, slow, threshold=0.20)[1] is False, "15 % drop, --threshold 0.20: not flagged")
    check(compare(baseline, slow, threshold=0.10)[1] is True, "15 % drop, --threshold 0.10: flagged")
    own = dict(baseline, thresholds={"granmc_over_naive/1e7": 0.25, "granmc_over_packed_limit/1e7": 0.25})
    check(compare(own, slow)[1] is False, "15 % drop, per-ratio threshold 25 % in the baseline: not flagged")
    pattern = dict(baseline, thresholds={"granmc_over_*/1e7": 0.25})
    check(compare(pattern, slow)[1] is False, "15 % drop, threshold 25 % by an fnmatch pattern: not flagged")
    check(compare(own, slow, threshold=0.05)[1] is False, "a per-ratio threshold wins over a smaller --threshold")
    slower = ratios_of(altered("bench_collisions", "granmc_collide/10000000", "candidates/s", 0.70))
    check(compare(own, slower)[1] is True, "30 % drop, per-ratio threshold 25 %: flagged")
    check(compare(own, slower, threshold=0.35)[1] is False, "a larger --threshold wins over a per-ratio one")
    check(own["thresholds"].items() <= make_baseline([], base_ratios, old=own)["thresholds"].items(),
          "--save keeps the per-ratio thresholds of the baseline it replaces")
    defaults = dict(baseline, thresholds=DEFAULT_RATIO_THRESHOLDS)
    for factor, want in ((0.75, False), (0.65, True)):
        rows, flagged = compare(defaults, ratios_of(altered("bench_event", "event_hard_sphere/100000",
                                                            "candidates/s", factor)))
        thr = {r[0]: r[2] for r in rows}["event_hard_sphere_over_packed_limit/1e5"]
        check(flagged is want and thr == 0.30, f"event hard spheres {100 * (1 - factor):.0f} % slower at 1e5, "
              f"default threshold of the event limit ratios 30 %: flagged {want} (threshold {thr})")
    # A baseline recorded before bench_event (no event ratios, no threshold for them): they are new.
    before_event = dict(baseline, ratios={k: v for k, v in baseline["ratios"].items() if k not in event_names},
                        thresholds={k: v for k, v in DEFAULT_RATIO_THRESHOLDS.items() if not k.startswith("event")})
    rows, flagged = compare(before_event, base_ratios)
    status = {r[0]: r[6] for r in rows}
    check(not flagged and all(status[n] == "new" for n in event_names) and len(rows) == len(names),
          "a baseline without the event ratios: they are shown as new, nothing flagged")
    m = json.loads(json.dumps(medians))
    del m["bench_event"]
    rows, flagged = compare(before_event, ratios_of(m))
    check(not flagged and not any(r[0] in event_names for r in rows),
          "no bench_event JSON and a baseline without the event ratios: not flagged")
    rows, flagged = compare(baseline, ratios_of(m))
    check(flagged and {r[0] for r in rows if r[6] == "MISSING"} == event_names,
          "no bench_event JSON but the event ratios in the baseline: the four are MISSING, flagged")

    m = json.loads(json.dumps(medians))
    del m["bench_effects"]["shear"]
    rows, flagged = compare(baseline, ratios_of(m))
    check(flagged and any(r[0] == "effect_over_plain/shear" and r[6] == "MISSING" for r in rows),
          "a ratio of the baseline that is missing now is flagged")
    m = json.loads(json.dumps(medians))
    m["bench_effects"]["new_scene"] = {"time/cand": 90e-9}
    rows, flagged = compare(baseline, ratios_of(m))
    check(not flagged and any(r[0] == "effect_over_plain/new_scene" and r[6] == "new" for r in rows),
          "a ratio that is not in the baseline is shown as new, not flagged")

    # Parts of one program in separate files are merged; rounds give each ratio's median over them.
    with tempfile.TemporaryDirectory() as d:
        for part, n in SIZES.items():
            with open(os.path.join(d, f"bench_collisions.{part}.json"), "w") as f:
                json.dump(synthetic_report({k: v for k, v in medians["bench_collisions"].items()
                                            if k.endswith("/" + n)}), f)
        check(set(compute_ratios(load_dir(d))) == {"granmc_over_naive/1e5", "granmc_over_naive/1e7",
                                                   "granmc_over_packed_limit/1e5", "granmc_over_packed_limit/1e7"},
              "bench_collisions.1e5.json and bench_collisions.1e7.json are merged")
        for k, factor in enumerate((1.0, 0.5, 1.1, 1.2), start=1):  # round 2: a 50 % outlier
            r = os.path.join(d, f"round{k}")
            os.makedirs(r)
            for prog, med in altered("bench_collisions", "granmc_collide/10000000", "candidates/s",
                                     factor).items():
                with open(os.path.join(r, prog + ".json"), "w") as f:
                    json.dump(synthetic_report(med), f)
        dirs = round_dirs(d)
        check([os.path.basename(x) for x in dirs] == ["round1", "round2", "round3", "round4"], "round dirs in order")
        combined = combine_rounds([compute_ratios(load_dir(x)) for x in dirs])
        check(abs(combined["granmc_over_naive/1e7"]["value"] - 2.0 * 1.05) < 1e-12 and
              len(combined["granmc_over_naive/1e7"]["rounds"]) == 4, "median over rounds (1, 0.5, 1.1, 1.2 -> 1.05)")
        check(not compare(baseline, combined)[1], "one outlier round of four is not flagged")
        clear_old_output(d)
        check(os.listdir(d) == [], "a new run clears the rounds and files of the previous one")

    # The whole command line: --save, then a comparison, from JSON files (exit status 0, then 1).
    with tempfile.TemporaryDirectory() as d:
        same, worse = os.path.join(d, "same"), os.path.join(d, "worse")
        for directory, m in ((same, medians), (worse, altered("bench_effects", "shear", "time/cand", 1.3))):
            os.makedirs(directory)
            for prog, med in m.items():
                with open(os.path.join(directory, prog + ".json"), "w") as f:
                    json.dump(synthetic_report(med), f)
        base = os.path.join(d, "baseline.json")
        me = [sys.executable, os.path.abspath(__file__), "--baseline", base]
        quiet = {"stdout": subprocess.DEVNULL, "stderr": subprocess.DEVNULL}
        rc_save = subprocess.run(me + ["--from-json", same, "--save"], **quiet).returncode
        rc_same = subprocess.run(me + ["--from-json", same], **quiet).returncode
        rc_worse = subprocess.run(me + ["--from-json", worse], **quiet).returncode
        rc_loose = subprocess.run(me + ["--from-json", worse, "--threshold", "0.5"], **quiet).returncode
        check((rc_save, rc_same, rc_worse, rc_loose) == (0, 0, 1, 0),
              f"command line: --save 0, same 0, 30 % worse 1, --threshold 0.5 0 (got {rc_save}, {rc_same}, "
              f"{rc_worse}, {rc_loose})")

    print(f"self-test: {len(failures)} failure(s)")
    return 1 if failures else 0



# ---- main ----------------------------------------------------------------------------------------------

def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter,
                                epilog="\n".join(__doc__.splitlines()[1:]))
    p.add_argument("--bin", default=os.path.join(REPO, "build", "bin"),
                   help="directory of the benchmark programs (default: build/bin)")
    p.add_argument("--baseline", default=DEFAULT_BASELINE, help="default: perf/baselines/baseline.json")
    p.add_argument("--save", action="store_true", help="write the baseline instead of comparing")
    p.add_argument("--threshold", type=float, default=None,
                   help="relative change that is flagged (default: the baseline's, 0.10); a ratio with its "
                        "own threshold in the baseline uses the larger of the two")
    p.add_argument("--from-json", metavar="DIR",
                   help="read DIR/<program>*.json (or DIR/round*/<program>*.json) instead of running the programs")
    p.add_argument("--rounds", type=int, default=1,
                   help="run the whole sequence K times and take each ratio's median over the rounds (default 1)")
    p.add_argument("--json-dir", metavar="DIR",
                   help="where the programs write their JSON and console output (default: BIN/../bench-json)")
    p.add_argument("--repetitions", type=int, default=None,
                   help="--benchmark_repetitions for every program (default: each program's own, 3 or 5)")
    p.add_argument("--self-test", action="store_true", help="check the comparison logic on synthetic numbers")
    args = p.parse_args()

    if args.self_test:
        return self_test()

    if args.from_json:
        json_dir = args.from_json
    else:
        json_dir = args.json_dir or os.path.join(os.path.dirname(os.path.abspath(args.bin)), "bench-json")
        clear_old_output(json_dir)
        os.makedirs(json_dir, exist_ok=True)
        with open(os.path.join(json_dir, "commit.txt"), "w") as f:  # HEAD when the run started
            f.write(git_commit() + "\n")
        for k in range(1, args.rounds + 1):
            d = os.path.join(json_dir, f"round{k}") if args.rounds > 1 else json_dir
            print(f"round {k} of {args.rounds}: JSON and console output in {d}", flush=True)
            run_round(args.bin, d, args.repetitions)
    rounds = [load_dir(d) for d in round_dirs(json_dir)]
    for d, runs in zip(round_dirs(json_dir), rounds):
        missing = [prog for prog in PROGRAMS if prog not in runs]
        if missing:
            print(f"bench_compare: no JSON from {', '.join(missing)} in {d}", file=sys.stderr)
    ratios = combine_rounds([compute_ratios(runs) for runs in rounds])
    if not ratios:
        sys.exit(f"bench_compare: no ratio could be formed from {json_dir}")

    old = None
    if os.path.exists(args.baseline):
        with open(args.baseline) as f:
            old = json.load(f)

    if args.save:
        commit_file = os.path.join(json_dir, "commit.txt")
        commit = open(commit_file).read().strip() if os.path.exists(commit_file) else None
        baseline = make_baseline(rounds, ratios, old, args.threshold, commit)
        os.makedirs(os.path.dirname(os.path.abspath(args.baseline)), exist_ok=True)
        tmp = args.baseline + ".tmp"
        with open(tmp, "w") as f:
            json.dump(baseline, f, indent=1, sort_keys=False)
            f.write("\n")
        os.replace(tmp, args.baseline)
        print(f"baseline written: {args.baseline} ({len(ratios)} ratios, commit {baseline['commit']})")
        for name, r in ratios.items():
            spread = ""
            if "rounds" in r:
                lo, hi = min(r["rounds"]), max(r["rounds"])
                spread = f"  rounds {lo:.4g} .. {hi:.4g} ({100 * (lo / r['value'] - 1):+.0f} / {100 * (hi / r['value'] - 1):+.0f} %)"
            print(f"  {name:40s} {r['value']:.4g}  ({r['better']} is better){spread}")
        return 0

    if old is None:
        sys.exit(f"bench_compare: no baseline at {args.baseline}: make one with --save (make bench-baseline)")
    rows, flagged = compare(old, ratios, args.threshold)
    print(f"\nbaseline: {args.baseline} ({old.get('date')}, commit {old.get('commit')}, {old.get('cpu')})")
    print(f"current:  {json_dir}\n")
    print_table(rows)
    bad = [r[0] for r in rows if r[6] in ("REGRESSION", "MISSING")]
    if flagged:
        print(f"\nflagged: {', '.join(bad)}")
    else:
        print("\nno ratio moved the wrong way by more than its threshold")
    return 1 if flagged else 0


if __name__ == "__main__":
    sys.exit(main())
