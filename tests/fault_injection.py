#!/usr/bin/env python3
"""Kill granmc at random moments and resume it: the files in the end are those of an uninterrupted run.

    tests/fault_injection.py [--granmc build/bin/granmc] [--kills 25] [--seed 1] [--work DIR]

For each of four scenes (the time-stepped scheme, the event scheme under white noise, weighted particles,
the Gillespie intruder; a few seconds each on 2 cores), runs it once uninterrupted, then again with
--checkpoint-every 0 (a checkpoint at every sample: the gas schemes' replicas are kept mid-run, the
intruder's whole), killing it with SIGKILL after a random 0.1-1.5 s and resuming it each time (--resume, alternating 2
threads and 1), until a run completes (the last of --kills attempts runs to the end); then compares the two HDF5 files object by object
(tests/same_bits.py: every dataset and attribute but those of the machine and the build) and the two
summaries.

Then a full disk: the run writes into a tmpfs of 256 kB (root only; skipped with a note otherwise), so
that its checkpoints stop fitting after a few replicas. The run must say that a checkpoint could not be
written, that the previous one is intact and that it goes on; the checkpoint left on the tmpfs must resume
elsewhere to the uninterrupted run's files.

`make stability` runs it (about 40 s). Exit status 1 when a file pair differs or a check fails.
"""
import argparse
import json
import os
import random
import shutil
import signal
import subprocess
import sys
import tempfile
import time

from same_bits import MACHINE_ATTRIBUTES, differences

SCENES = {
    "dsmc": """[run]
seed = 5
replicas = 4
t_end = 100.0
dt = 0.01
samples = 10
[[species]]
particles = 200000
[collision]
restitution = 0.8
""",
    "event": """[run]
method = "event"
seed = 7
replicas = 8
t_end = 30.0
samples = 4
[[species]]
particles = 100000
[collision]
kernel = "maxwell"
rate = 1.2732395447351628
restitution = 0.1
[thermostat]
kind = "white-noise"
beta = 30.0
[output]
histogram = { shells = 64, radius = 40.0 }
""",
    "weighted": """[run]
method = "event"
seed = 7
replicas = 8
t_end = 1.5
samples = 4
[[species]]
particles = 20000
[collision]
kernel = "maxwell"
rate = 1.2732395447351628
restitution = 0.1
[thermostat]
kind = "white-noise"
beta = 30.0
[output]
histogram = { shells = 128, radius = 80.0 }
[weights]
scheme = "swpm"
particles_per_shell = 128
""",
    "intruder": """[run]
method = "gillespie"
seed = 7
replicas = 8
t_end = 8000000.0
samples = 2000
[intruder]
dimension = 1
mass = 1.0
restitution = 0.5
bath = "gaussian"
bath_a = 1.0
bath_density = 1.0
[output]
histogram = { shells = 100, radius = 5.0 }
""",
}

# The full-disk case: 16 replicas whose series (400 samples) take tens of kB each in a checkpoint, and
# whose state in flight (2000 particles) takes 48 kB: the first checkpoints fit in 256 kB, and those with
# a few finished replicas no longer do. (With a state in flight larger than the disk, a write would fit
# only at the moments when no replica is in flight.)
FULL_DISK_SCENE = """[run]
seed = 3
replicas = 16
t_end = 4.0
dt = 0.01
samples = 400
[[species]]
particles = 2000
[collision]
restitution = 0.9
"""


def summary_numbers(path):
    with open(path) as f:
        s = json.load(f)
    return {k: v for k, v in s.items() if k not in MACHINE_ATTRIBUTES and k != "wall_seconds"}


def same_files(a, b):
    """Lines naming what differs between runs a and b (paths without extension); empty: the same."""
    out = differences(a + ".h5", b + ".h5")
    if summary_numbers(a + ".json") != summary_numbers(b + ".json"):
        out.append("the summaries differ")
    return out


def killed_and_resumed(granmc, scene, work, rng, max_kills):
    """Runs `scene` killed at random and resumed until it completes; returns the number of kills."""
    out = os.path.join(work, "cut")
    checkpoint = out + ".h5.checkpoint"
    for kills in range(max_kills + 1):
        cmd = [granmc, "run", scene, "--out", out + ".h5", "--summary", out + ".json", "--quiet",
               "--checkpoint-every", "0", "--threads", str(2 - kills % 2)]
        if os.path.exists(checkpoint):
            cmd += ["--resume", checkpoint]
        p = subprocess.Popen(cmd, stderr=subprocess.PIPE, text=True)
        try:
            p.wait(timeout=rng.uniform(0.1, 1.5) if kills < max_kills else None)
        except subprocess.TimeoutExpired:
            p.send_signal(signal.SIGKILL)
            p.wait()
            continue
        if p.returncode != 0:
            raise SystemExit(f"{scene}: granmc exited with {p.returncode}: {p.stderr.read()}")
        return kills
    return max_kills


def full_disk(granmc, work, reference):
    """The full-disk check; lines naming what failed (empty: passed), or None when it cannot run here."""
    disk = os.path.join(work, "disk")
    os.makedirs(disk)
    if subprocess.run(["mount", "-t", "tmpfs", "-o", "size=256k", "tmpfs", disk], capture_output=True).returncode:
        return None
    try:
        scene = os.path.join(work, "full_disk.toml")
        run = subprocess.run([granmc, "run", scene, "--out", os.path.join(disk, "run.h5"), "--quiet",
                              "--checkpoint-every", "0"], capture_output=True, text=True)
        problems = []
        said = "the previous checkpoint, if any, is intact; the run goes on"
        if said not in run.stderr:
            problems.append(f"no line saying '{said}' (stderr: {run.stderr.strip()[:300]})")
        left = os.path.join(disk, "run.h5.checkpoint")
        if not os.path.exists(left):
            problems.append("no checkpoint left on the full disk")
            return problems
        elsewhere = os.path.join(work, "resumed")
        shutil.copy(left, elsewhere + ".h5.checkpoint")
        resumed = subprocess.run([granmc, "run", scene, "--out", elsewhere + ".h5", "--summary", elsewhere + ".json",
                                  "--quiet", "--resume", elsewhere + ".h5.checkpoint"], capture_output=True, text=True)
        if resumed.returncode != 0:
            return problems + [f"the checkpoint left on the full disk did not resume: {resumed.stderr.strip()}"]
        return problems + same_files(elsewhere, reference)
    finally:
        subprocess.run(["umount", disk], capture_output=True)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--granmc", default="build/bin/granmc")
    p.add_argument("--kills", type=int, default=25, help="at most this many kills per scene")
    p.add_argument("--seed", type=int, default=1, help="of the random kill times")
    p.add_argument("--work", help="directory for the runs (default: a temporary one, removed)")
    args = p.parse_args()
    granmc = os.path.abspath(args.granmc)
    work = args.work or tempfile.mkdtemp(prefix="granmc_faults_")
    rng = random.Random(args.seed)
    failed = False
    for name, text in SCENES.items():
        here = os.path.join(work, name)
        os.makedirs(here, exist_ok=True)
        scene = os.path.join(here, name + ".toml")
        with open(scene, "w") as f:
            f.write(text)
        start = time.monotonic()
        subprocess.run([granmc, "run", scene, "--out", os.path.join(here, "whole.h5"), "--summary",
                        os.path.join(here, "whole.json"), "--quiet", "--no-checkpoints"], check=True)
        whole = time.monotonic() - start
        kills = killed_and_resumed(granmc, scene, here, rng, args.kills)
        diff = same_files(os.path.join(here, "cut"), os.path.join(here, "whole"))
        failed |= bool(diff) or kills == 0
        print(f"{name}: uninterrupted {whole:.1f} s; {kills} kills, then resumed to "
              + ("the same files" if not diff else "DIFFERENT files: " + "; ".join(diff[:5]))
              + (" (no kill landed: the check proved nothing)" if kills == 0 else ""), flush=True)
    with open(os.path.join(work, "full_disk.toml"), "w") as f:
        f.write(FULL_DISK_SCENE)
    reference = os.path.join(work, "reference")
    subprocess.run([granmc, "run", os.path.join(work, "full_disk.toml"), "--out", reference + ".h5", "--summary",
                    reference + ".json", "--quiet", "--no-checkpoints"], check=True)
    problems = full_disk(granmc, work, reference)
    if problems is None:
        print("full disk: skipped (mounting a tmpfs needs root)")
    else:
        failed |= bool(problems)
        print("full disk: " + ("the failed checkpoint write was reported, the previous checkpoint resumed to the "
                               "same files" if not problems else "FAILED: " + "; ".join(problems[:5])))
    if not args.work:
        shutil.rmtree(work)
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
