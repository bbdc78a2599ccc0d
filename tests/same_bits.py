#!/usr/bin/env python3
"""Do two granmc builds give the same bits? Runs every scene under drivers/scenes/ with both executables and
compares the HDF5 files object by object: every dataset's type, shape and bytes, every attribute but the few
that describe the machine or the build (wall_seconds, threads, version).

    tests/same_bits.py --reference OLD/bin/granmc --candidate build/bin/granmc [--particles 3000]
                       [--replicas 3] [--threads 2] [--threads-per-replica 1] [--work DIR] [SCENE.toml ...]

A scene is shrunk to at most --particles particles over all species (each species by the same factor, so the
density ratio holds) and --replicas replicas through a one-scene sweep file (`granmc sweep`), so the whole set
takes minutes; the kernel, effects and storage that run are the scene's own. Scene files are the files with a
[run] table (figure and sweep files are skipped: their points are these scenes with other values). A scene that
one system over several ranks can run (`--spread particles`, the rank-wave backend) is run that way too, in one
process.
Exit status 0 when every file pair is identical, 1 otherwise, with one line per difference.

Two files can also be compared directly: tests/same_bits.py --files A.h5 B.h5
"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import tomllib

import h5py
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MACHINE_ATTRIBUTES = {"wall_seconds", "threads", "threads_per_replica", "collision_rounds", "collision_rounds_deferred",
                      "collision_rounds_in_order", "version", "build"}


def scene_files(paths):
    """The scene files among `paths` (default: everything under drivers/scenes/), sorted."""
    if not paths:
        paths = []
        for folder, _, names in os.walk(os.path.join(ROOT, "drivers", "scenes")):
            paths += [os.path.join(folder, n) for n in names if n.endswith(".toml")]
    scenes = []
    for p in sorted(paths):
        with open(p, "rb") as f:
            if "run" in tomllib.load(f):
                scenes.append(p)
    return scenes


def shrunk_sweep(scene_path, particles, replicas, folder):
    """Writes a one-scene sweep file that runs `scene_path` at most at the given size; returns its path."""
    with open(scene_path, "rb") as f:
        scene = tomllib.load(f)
    lines = [f"base = {os.path.abspath(scene_path)!r}".replace("'", '"'), "", "[[scenes]]"]
    species = scene.get("species", [])
    total = sum(s.get("particles", 0) for s in species)
    if total > particles:
        for i, s in enumerate(species):
            lines.append(f'"species[{i}].particles" = {max(2, round(s["particles"] * particles / total))}')
    if scene["run"].get("replicas", 1) > replicas:
        lines.append(f'"run.replicas" = {replicas}')
    if len(lines) == 3:  # nothing to shrink: the sweep still needs one key
        lines.append(f'"run.seed" = {scene["run"].get("seed", 1)}')
    path = os.path.join(folder, "sweep.toml")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return path


def run(granmc, sweep, out_dir, threads, reuse, threads_per_replica=1):
    """The HDF5 file of the sweep's one scene run by `granmc` in out_dir; with `reuse`, a file already there
    from the same sweep text is kept (the reference build's files, between calls with the same --work).
    threads_per_replica is passed on as --threads-per-replica."""
    done = os.path.join(out_dir, "sweep.toml")
    with open(sweep) as f:
        text = f.read()
    if reuse and os.path.exists(done) and open(done).read() == text:
        (h5,) = [os.path.join(out_dir, n) for n in os.listdir(out_dir) if n.endswith(".h5")]
        return h5
    shutil.rmtree(out_dir, ignore_errors=True)
    subprocess.run([granmc, "sweep", sweep, "--out-dir", out_dir, "--threads", str(threads), "--quiet",
                    "--threads-per-replica", str(threads_per_replica)], check=True)
    (h5,) = [os.path.join(out_dir, n) for n in os.listdir(out_dir) if n.endswith(".h5")]
    with open(done, "w") as f:
        f.write(text)
    return h5


def scene_text(h5):
    """The text of the scene a result file ran (attribute scene_text; format 1 called it scene)."""
    with h5py.File(h5, "r") as f:
        text = f.attrs["scene_text"] if "format_version" in f.attrs else f.attrs["scene"]
    return text.decode() if isinstance(text, bytes) else str(text)


def run_spread(granmc, scene, out):
    """The scene run as one system over the ranks (one process here), or None when granmc refuses that."""
    explain = subprocess.run([granmc, "run", scene, "--spread", "particles", "--explain"], capture_output=True)
    if explain.returncode != 0:
        return None
    subprocess.run([granmc, "run", scene, "--spread", "particles", "--out", out, "--quiet"], check=True)
    return out


def differences(a_path, b_path):
    """Lines naming every object or attribute that differs between two HDF5 files (empty: the same bits)."""
    out = []
    with h5py.File(a_path, "r") as a, h5py.File(b_path, "r") as b:
        names_a, names_b = [], []
        a.visit(names_a.append)
        b.visit(names_b.append)
        for name in sorted(set(names_a) ^ set(names_b)):
            out.append(f"{name}: only in {'the first' if name in names_a else 'the second'} file")
        for name in ["/"] + sorted(set(names_a) & set(names_b)):
            x, y = a[name], b[name]
            if isinstance(x, h5py.Dataset) != isinstance(y, h5py.Dataset):
                out.append(f"{name}: a dataset in one file, a group in the other")
                continue
            if isinstance(x, h5py.Dataset):
                u, v = x[()], y[()]
                if x.dtype != y.dtype or np.shape(u) != np.shape(v):
                    out.append(f"{name}: {x.dtype}{np.shape(u)} against {y.dtype}{np.shape(v)}")
                elif np.asarray(u).tobytes() != np.asarray(v).tobytes():
                    out.append(f"{name}: values differ")
            for key in sorted(set(x.attrs) | set(y.attrs)):
                if key in MACHINE_ATTRIBUTES and name == "/":
                    continue
                if key not in x.attrs or key not in y.attrs:
                    out.append(f"{name}@{key}: only in {'the first' if key in x.attrs else 'the second'} file")
                elif np.asarray(x.attrs[key]).tobytes() != np.asarray(y.attrs[key]).tobytes():
                    out.append(f"{name}@{key}: {x.attrs[key]!r} against {y.attrs[key]!r}")
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("scenes", nargs="*", help="scene files (default: every scene under drivers/scenes/)")
    p.add_argument("--reference", help="the granmc executable of the reference build")
    p.add_argument("--candidate", default=os.path.join(ROOT, "build", "bin", "granmc"))
    p.add_argument("--particles", type=int, default=3000, help="at most this many particles per replica")
    p.add_argument("--replicas", type=int, default=3)
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--threads-per-replica", type=int, default=1,
                   help="the candidate's threads inside a replica (granmc sweep --threads-per-replica; the "
                   "time-stepped scheme's concurrent collision rounds, docs/developer-guide/scaling.md)")
    p.add_argument("--work", help="keep the files here (default: a temporary directory); the reference build's "
                   "files found there from the same sweep are reused")
    p.add_argument("--files", nargs=2, metavar="H5", help="compare two existing files instead")
    args = p.parse_args()
    if args.files:
        diff = differences(*args.files)
        print("\n".join(diff) if diff else "same bits")
        return 1 if diff else 0
    if not args.reference:
        p.error("--reference is required (or --files)")
    work = args.work or tempfile.mkdtemp(prefix="same_bits-")
    failed = 0
    scenes = scene_files(args.scenes)
    for k, scene in enumerate(scenes):
        name = os.path.relpath(scene, ROOT).replace(os.sep, "_").removesuffix(".toml")
        folder = os.path.join(work, name)
        os.makedirs(folder, exist_ok=True)
        sweep = shrunk_sweep(scene, args.particles, args.replicas, folder)
        files = [run(exe, sweep, os.path.join(folder, tag), args.threads, reuse=tag == "reference",
                     threads_per_replica=args.threads_per_replica if tag == "candidate" else 1)
                 for tag, exe in (("reference", args.reference), ("candidate", args.candidate))]
        diff = differences(*files)
        shrunk = os.path.join(folder, "shrunk.toml")
        with open(shrunk, "w") as f:
            f.write(scene_text(files[0]))
        spread = [run_spread(exe, shrunk, os.path.join(folder, f"spread-{tag}.h5"))
                  for tag, exe in (("reference", args.reference), ("candidate", args.candidate))]
        if spread[0] and spread[1]:
            diff += ["--spread particles: " + line for line in differences(*spread)]
        elif spread[0] or spread[1]:
            diff.append("--spread particles: runs with one build only")
        failed += bool(diff)
        print(f"[{k + 1}/{len(scenes)}] {os.path.relpath(scene, ROOT)}: {'same bits' if not diff else 'DIFFERENT'}"
              f"{', also spread over ranks' if spread[0] else ''}", flush=True)
        for line in diff:
            print("    " + line)
    print(f"{len(scenes) - failed} of {len(scenes)} scenes give the same bits ({work})")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
