#!/usr/bin/env python3
"""Run a 001 tail scene (drivers/scenes/001_tails/) at a chosen size and fit its tail exponent.

Usage: /usr/bin/python3 drivers/tails.py SCENE.toml [--particles N] [--replicas R] [--storage float]
                                          [--out DIR] [--granmc build/bin/granmc] [tail_fit.py options after --]

Writes the scene at that size to DIR/run.toml, runs granmc (skipped when DIR/run.json holds the result of
exactly that scene text), then drivers/tail_fit.py on DIR/run.h5 with the theory exponent
1 + lambda/2 from `granmc theory`.
"""
import argparse
import os
import subprocess
import sys
import tomllib

from granmc import run_point, theory  # cached by scene text


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("scene")
    p.add_argument("--particles", type=int, default=None)
    p.add_argument("--replicas", type=int, default=None)
    p.add_argument("--storage", choices=["double", "float"], default=None,
                   help="run.storage: float halves the memory (docs/formats/scenes.md, docs/user-guide/accuracy-cost.md)")
    p.add_argument("--out", default=None)
    p.add_argument("--granmc", default="build/bin/granmc")
    p.add_argument("--threads", type=int, default=0)
    args, fit_args = p.parse_known_args()
    with open(args.scene, "rb") as f:
        scene = tomllib.load(f)
    if args.particles:
        scene["species"][0]["particles"] = args.particles
    if args.replicas:
        scene["run"]["replicas"] = args.replicas
    if args.storage:
        scene["run"]["storage"] = args.storage
    name = os.path.splitext(os.path.basename(args.scene))[0]
    n, r = scene["species"][0]["particles"], scene["run"]["replicas"]
    storage = "_float" if scene["run"].get("storage") == "float" else ""
    out = args.out or os.path.join("results", f"001_tails_{name}_n{n}_N{r}{storage}")
    os.makedirs(out, exist_ok=True)
    summary = run_point(args.granmc, scene, os.path.join(out, "run"), args.threads)
    b = theory(args.granmc, os.path.join(out, "run.toml")).get("white_noise", {}).get("tail_exponent")
    fit = [sys.executable, os.path.join(os.path.dirname(os.path.abspath(__file__)), "tail_fit.py"),
           os.path.join(out, "run.h5"), out, "--label", f"{name}, n = {n}, N = {r}"] + fit_args
    if b is not None:
        fit += ["--theory", str(b)]
    subprocess.run(fit, check=True)
    print(f"{name}: {summary['wall_seconds']:.0f} s, {summary['collisions']:.3g} collisions, "
          f"{summary['candidates']:.3g} candidates, majorant violations {summary.get('majorant_violations', 0)}")


if __name__ == "__main__":
    main()
