#!/usr/bin/env python3
"""Run 001 tail scenes with weighted particles (drivers/scenes/001_tails_weighted/, and in the plane
drivers/scenes/tails_disks_weighted/) and report granmc's own
tail fit (the summary's tail.exponent, kernel/analysis/tail_fit.hpp) against the theory: b = 1 + lambda/2 heated
by white noise, b = lambda freely cooling (`granmc theory`).

Usage: /usr/bin/python3 drivers/tails_weighted.py SCENE.toml [SCENE.toml ...] [--out DIR]
                                                  [--granmc build/bin/granmc] [--replicas R]

Per scene: DIR/<name>.{toml,h5,json} (the run, reused when the scene text is unchanged) and DIR/<name>.png:
the weighted density f(|v|) with its CI, and b against the fit window's inner edge (the HDF5 file's
tail/profile) with the theory; where b levels off the window has left the pre-asymptotic region.
DIR/table.md: one row per scene.
"""
import argparse
import os
import tomllib

import h5py

from granmc import run_point, theory  # cached by scene text
from granmc.plotting import pyplot, save

plt = pyplot()


def theory_exponent(granmc, scene_path):
    out = theory(granmc, scene_path)
    for state in ("white_noise", "free_cooling"):
        if "tail_exponent" in out.get(state, {}):
            return out[state]["tail_exponent"]
    return None


def plot(name, h5_path, summary, b_theory, speed, png):
    with h5py.File(h5_path, "r") as f:
        profile = f["tail/profile"][()] if "tail/profile" in f else None
    edges = summary["speed_shell_edges"]
    centres = [0.5 * (a + b) for a, b in zip(edges[:-1], edges[1:])]
    dist = summary["species"][0]["speed_distribution"]
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    mean, ci = dist["mean"], dist["ci"]
    left.semilogy(centres, mean, lw=1, label="weighted particles")
    left.fill_between(centres, [max(m - c, 1e-300) for m, c in zip(mean, ci)], [m + c for m, c in zip(mean, ci)],
                      alpha=0.3)
    positive = [m for m in mean if m > 0]
    left.set_ylim(0.1 * min(positive), 10 * max(positive))  # a band reaching below 0 stays inside the frame
    lo, hi = summary["tail"]["fit_range"]
    left.axvspan(lo, hi, color="grey", alpha=0.15, label="fit window")
    left.set_xlabel(speed)
    left.set_ylabel(f"f({speed}) per unit velocity volume")
    left.legend()
    if profile is not None and len(profile):
        right.errorbar(profile[:, 0], profile[:, 2], yerr=profile[:, 3], fmt="o", ms=3, capsize=2,
                       label="b, fit from the inner edge to the reach")
    if b_theory is not None:
        right.axhline(b_theory, color="k", lw=0.8, label=f"theory b = {b_theory:g}")
    right.set_xlabel(f"inner edge of the fit window, {speed}")
    right.set_ylabel("tail exponent b")
    right.legend()
    fig.suptitle(name)
    save(fig, png)
    plt.close(fig)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("scenes", nargs="+")
    p.add_argument("--out", default="results/001_tails_weighted")
    p.add_argument("--granmc", default="build/bin/granmc")
    p.add_argument("--replicas", type=int, default=None)
    p.add_argument("--threads", type=int, default=0)
    args = p.parse_args()
    os.makedirs(args.out, exist_ok=True)
    rows = ["| scene | b | CI | theory | (b - theory) / CI | fit range | replicas | particles (max) | wall s |",
            "|---|---|---|---|---|---|---|---|---|"]
    for path in args.scenes:
        with open(path, "rb") as f:
            scene = tomllib.load(f)
        if args.replicas:
            scene["run"]["replicas"] = args.replicas
        name = os.path.splitext(os.path.basename(path))[0]
        stem = os.path.join(args.out, name)
        summary = run_point(args.granmc, scene, stem, args.threads)
        b_theory = theory_exponent(args.granmc, stem + ".toml")
        tail = summary.get("tail")
        if tail is None:
            rows.append(f"| {name} | (no tail fit) | | {b_theory} | | | {scene['run']['replicas']} | | |")
            continue
        b, ci = tail["exponent"]["mean"], tail["exponent"]["ci"]
        off = (b - b_theory) / ci if b_theory is not None and ci > 0 else float("nan")
        rows.append(f"| {name} | {b:.3f} | {ci:.3f} | {b_theory:g} | {off:+.2f} | "
                    f"[{tail['fit_range'][0]:g}, {tail['fit_range'][1]:g}] | {summary['replicas']} | "
                    f"{summary['weights']['particles_max']:.0f} | {summary['wall_seconds']:.0f} |")
        default_speed = "velocity" if scene["run"]["method"] == "event" else "scaled"
        scaled = scene.get("output", {}).get("histogram", {}).get("speed", default_speed) == "scaled"
        plot(name, stem + ".h5", summary, b_theory, "v* = |V| / v0" if scaled else "|v|", stem + ".png")
        print(rows[-1], flush=True)
    with open(os.path.join(args.out, "table.md"), "w") as f:
        f.write("\n".join(rows) + "\n")
    print("\n".join(rows))


if __name__ == "__main__":
    main()
