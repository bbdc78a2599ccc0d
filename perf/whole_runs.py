"""Whole `granmc run` processes, for the benchmarks that time them (perf/thread_scaling.py, model_cost.py and
naive_ratio.py): the options they share (--granmc, --runs, --work), their working directory, and one run read
back from its JSON summary, whose wall_seconds is granmc's own wall time, set-up included."""
import argparse
import json
import os
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def parser(doc):
    """The argument parser of a whole-run benchmark whose help is its module docstring `doc`."""
    p = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--granmc", default=os.path.join(ROOT, "build", "bin", "granmc"))
    p.add_argument("--runs", type=int, default=3)
    p.add_argument("--work", default=None, help="directory for granmc's files (default: a temporary one)")
    return p


def work_directory(args, prefix):
    """--work, created if missing, or a new temporary directory named with `prefix`."""
    work = args.work or tempfile.mkdtemp(prefix=prefix)
    os.makedirs(work, exist_ok=True)
    return work


def run(granmc, scene, threads, extra, out):
    """Runs `scene` on `threads` threads with the extra arguments `extra`, writing out.h5 and out.json, and
    returns the summary."""
    subprocess.run([granmc, "run", scene, "--threads", str(threads), "--quiet", "--out", out + ".h5",
                    "--summary", out + ".json"] + extra, check=True)
    with open(out + ".json") as f:
        return json.load(f)
