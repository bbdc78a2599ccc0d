#!/usr/bin/env python3
"""The long stability study (`make stability`): hard cases at full size, each checked.

Usage: /usr/bin/python3 drivers/stability.py [--granmc build/bin/granmc] [--out results/stability]

Runs every scene in drivers/scenes/stability/ and checks its HDF5 file (the series at every sample time)
and its summary (the headline figures): every reported temperature finite
and positive; for gases, the total momentum at rounding level (|P| / sqrt(M 2E) < 1e-10) unless white
noise drives it (001 Remark 1: then it is reported); with the Gaussian thermostat compensating the cooling
(and no shear) T(t) = T(0) to 1e-9; for the time-stepped gas the energy bookkeeping against a direct sum
to 1e-10 (docs/methods/physics.md, "Energy balance"); under shear P_xy < 0 and finite; the event scheme's majorant
violations reported; the needle's bisection fallbacks reported. Writes OUT/table.md and exits 1 if a check
fails. The fast versions of the same cases are `ctest -L stability`.
"""
import argparse
import glob
import json
import math
import os
import subprocess
import sys
import tomllib

from granmc import open_results


def finite(xs):
    return all(x is not None and math.isfinite(x) for x in xs)


def series(path):
    """The replica means over every sample time, from the HDF5 file at `path` (the summary holds at most 101)."""
    names = ["temperature", "log_temperature", "momentum_relative", "viscosity/pressure_xy",
             "viscosity/reduced_shear_rate"]
    with open_results(path) as f:
        return {n: list(f[n + "/mean"][()]) for n in names if n in f}


def check(scene, s, h):
    """[(check, passed, detail)] for one run: its summary `s` and its series `h` (series())."""
    out = []
    t = h["temperature"]
    out.append(("T finite and > 0", finite(t) and min(t) > 0.0, f"T(end)/T(0) = {t[-1] / t[0]:.3g}"))
    lt = h["log_temperature"]
    decades = (lt[0] - lt[-1]) / math.log(10.0)
    if "species" in scene and scene.get("run", {}).get("method", "dsmc") != "gillespie":
        p = max(h["momentum_relative"])
        noise = scene.get("thermostat", {}).get("kind") == "white-noise"
        out.append(("momentum" + (" (white noise: reported)" if noise else " < 1e-10"), noise or p < 1e-10,
                    f"max |P|/sqrt(M 2E) = {p:.2g}"))
        out.append(("a2 finite", all(finite(sp["a2"]["mean"]) for sp in s["species"]),
                    ", ".join(f"a2_{sp['name']} = {sp['a2_last_half']['mean']:.4f}" for sp in s["species"])))
        th = scene.get("thermostat", {})
        if th.get("kind") == "gaussian" and th.get("zeta", "cooling-rate") == "cooling-rate" and "shear" not in scene:
            dev = max(abs(x / t[0] - 1.0) for x in t)
            out.append(("HSS: T(t) = T(0) to 1e-9", dev < 1e-9, f"max |T/T(0) - 1| = {dev:.2g}"))
        if "shear" in scene:
            pxy = h["viscosity/pressure_xy"][1:]
            out.append(("shear: P_xy < 0, finite", finite(pxy) and max(pxy) < 0.0,
                        f"P_xy/nT (end) = {pxy[-1]:.4f}, a* = {h['viscosity/reduced_shear_rate'][-1]:.3f}"))
        if "energy_residual_max" in s:  # time-stepped gas: kernel/observe/gas_series.hpp, energy_balance_tolerance
            r = s["energy_residual_max"]
            out.append(("energy balance < 1e-10", r is not None and r < 1e-10, f"max |E_tracked/E_summed - 1| = {r:.2g}"))
        if s.get("method") == "event":
            out.append(("majorant violations (reported)", True, f"{s['majorant_violations']} of {s['candidates']}"))
        if decades > 1.0:
            out.append(("cooling (reported)", True, f"{decades:.1f} decades, {s['rescales']} rescalings"))
    if "intruder" in s:
        r = s["intruder"]["temperature_ratio"]
        out.append(("intruder T/T_B finite", finite([r["mean"]]), f"T/T_B = {r['mean']:.4f} +- {r['ci']:.4f}"
                    + (f" (exact {s['intruder']['temperature_ratio_exact']:.4f})"
                       if "temperature_ratio_exact" in s["intruder"] else "")))
        if "newton_iterations" in s["intruder"]:
            out.append(("needle event times (reported)", True, f"{s['intruder']['newton_iterations']} Newton steps, "
                        f"{s['intruder']['bisection_fallbacks']} bisection fallbacks"))
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--granmc", default="build/bin/granmc")
    p.add_argument("--out", default="results/stability")
    args = p.parse_args()
    os.makedirs(args.out, exist_ok=True)
    lines = ["# Stability study (`make stability`)\n", "| scene | check | passed | measured | run (s) |",
             "|---|---|---|---|---|"]
    failed = 0
    for path in sorted(glob.glob("drivers/scenes/stability/*.toml")):
        name = os.path.splitext(os.path.basename(path))[0]
        with open(path, "rb") as f:
            scene = tomllib.load(f)
        summary, hdf5 = os.path.join(args.out, name + ".json"), os.path.join(args.out, name + ".h5")
        print("  run", name, flush=True)
        subprocess.run([args.granmc, "run", path, "--out", hdf5, "--summary", summary, "--quiet"], check=True)
        with open(summary) as f:
            s = json.load(f)
        for what, ok, detail in check(scene, s, series(hdf5)):
            failed += not ok
            detail = detail.replace("|", "\\|")  # markdown cells
            lines.append(f"| {name} | {what} | {'yes' if ok else '**NO**'} | {detail} | {s['wall_seconds']:.0f} |")
    with open(os.path.join(args.out, "table.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
