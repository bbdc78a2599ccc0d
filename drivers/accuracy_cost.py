#!/usr/bin/env python3
"""Work-precision study on a problem with an exact answer (docs/user-guide/accuracy-cost.md, `make accuracy-cost`).

Usage: /usr/bin/python3 drivers/accuracy_cost.py [--granmc build/bin/granmc] [--out results/accuracy_cost]
                                                  [--threads 0]

The problem: 001 Example 3 (Maxwell pseudomolecules heated by white noise, drivers/scenes/accuracy/
maxwell_relaxation.toml), whose temperature relaxation is exact (001 eqs. 16-17). The error of a run is
the relative deviation of its late-time mean temperature (samples with t >= t_end / 2, averaged per
replica, then over replicas) from the exact value, with the replica CI (lambda_p = 3.2). One knob varies at
a time:
  - particles n (event scheme, n N fixed): the systematic error, exactly 1/n for this kernel;
  - replicas N (event scheme, n fixed): the statistical error, ~ N^-1/2 (its CI is what is fitted);
  - time step dt (time-stepped scheme): the splitting error, measured against the exact n-particle law
    (1 - 1/n) T(t) so that the 1/n part does not mix in;
  - method: the event scheme against the time-stepped one at dt values, error against wall time;
  - storage precision (run.storage, event scheme): double against float velocities at n = 64 and n = 2^20,
    with the paired difference float - double of the same seeds, which resolves the rounding far below
    the statistical error;
  - early-time Haff (time-stepped scheme, hard spheres, drivers/scenes/accuracy/hcs_early.toml): the
    initial slope of ln T, exactly -zeta_M (the Maxwellian's cooling rate), against particles n and dt.
Each knob's order is the least-squares slope of log error against log knob, with a CI from resampling
every point within its own CI (1000 draws, lambda_p = 3.2). Writes OUT/table.md, OUT/figure.png, and
OUT/study.json; runs are cached per scene text (granmc.scenes.run_point).
"""
import argparse
import copy
import json
import math
import os
import tomllib

import numpy as np

from granmc import LAMBDA_P, mean_ci, open_results, run_point
from granmc.plotting import pyplot, save

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "scenes", "accuracy")


def exact_temperature(t, beta, rate, alpha, t0=1.0):
    kappa = math.pi * rate * (1.0 - alpha * alpha)  # 001 eq. (16)
    return t0 * math.exp(-kappa * t) + 2.0 * beta / kappa * (1.0 - math.exp(-kappa * t))


def late_deviations(stem, scene, n_particle_law):
    """Per replica, the relative deviation of the late-time mean T from the exact value."""
    with open_results(stem + ".h5") as h:
        times = h["/times"][()]
        temperature = h["/temperature/replicas"][()]
    beta = scene["thermostat"]["beta"]
    rate = scene["collision"]["rate"]
    alpha = scene["collision"]["restitution"]
    n = scene["species"][0]["particles"]
    late = times >= 0.5 * times[-1]
    exact = np.array([exact_temperature(t, beta, rate, alpha) for t in times[late]])
    if n_particle_law:
        exact = exact * (1.0 - 1.0 / n)
    return (temperature[:, late] / exact - 1.0).mean(axis=1)


def early_slope_deviations(stem):
    """Per replica, the relative deviation of the initial slope of ln T from -zeta_M: ln T(t)/T(0) = s t + b t^2
    fitted by least squares over the samples (the curvature b is left free: it depends on how fast a2
    builds up), deviation -s / zeta_M - 1."""
    with open_results(stem + ".h5") as h:
        times = h["/times"][()]
        temperature = h["/temperature/replicas"][()]
        zeta_m = h["/theory"].attrs["cooling_rate0_maxwell"]
    log_t = np.log(temperature / temperature[:, :1])
    design = np.vstack([times, times * times]).T
    slope = np.linalg.lstsq(design, log_t.T, rcond=None)[0][0]
    return -slope / zeta_m - 1.0


def fitted_order(x, e, ci, rng):
    """Slope of log|e| against log x, with a CI from resampling each e within its CI."""
    x, e, ci = np.log(np.asarray(x)), np.asarray(e), np.asarray(ci)
    slope = np.polyfit(x, np.log(np.abs(e)), 1)[0]
    draws = []
    for _ in range(1000):
        sample = np.abs(e + rng.normal(0.0, 1.0, len(e)) * ci / LAMBDA_P)
        if np.all(sample > 0):
            draws.append(np.polyfit(x, np.log(sample), 1)[0])
    return float(slope), float(LAMBDA_P * np.std(draws))


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--granmc", default="build/bin/granmc")
    p.add_argument("--out", default="results/accuracy_cost")
    p.add_argument("--threads", type=int, default=0)
    args = p.parse_args()
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(HERE, "maxwell_relaxation.toml"), "rb") as f:
        base = tomllib.load(f)
    rng = np.random.default_rng(1)

    def run(name, scene, n_particle_law=False):
        stem = os.path.join(args.out, name)
        summary = run_point(args.granmc, scene, stem, args.threads)
        per_replica = late_deviations(stem, scene, n_particle_law)
        err, ci = mean_ci(per_replica)
        return {"name": name, "error": err, "ci": ci, "wall": summary["wall_seconds"],
                "candidates": summary["candidates"], "per_replica": per_replica}

    study = {}
    # 1. particles, event scheme, n N = 2^18 particle-replicas
    rows = []
    for n in (16, 32, 64, 128, 256):
        s = copy.deepcopy(base)
        s["species"][0]["particles"] = n
        s["run"]["replicas"] = 2 ** 18 // n
        rows.append(dict(run(f"particles_n{n}", s), knob=n))
    study["particles"] = rows
    # 2. replicas, event scheme, n = 256
    rows = []
    for replicas in (64, 256, 1024, 4096):
        s = copy.deepcopy(base)
        s["species"][0]["particles"] = 256
        s["run"]["replicas"] = replicas
        rows.append(dict(run(f"replicas_N{replicas}", s, n_particle_law=True), knob=replicas))
    study["replicas"] = rows
    # 3. time step, time-stepped scheme, n = 64, N = 2000, against the n-particle law
    rows = []
    for dt in (0.5, 0.25, 0.125, 0.0625):
        s = copy.deepcopy(base)
        s["run"]["method"] = "dsmc"
        s["run"]["dt"] = dt
        s["species"][0]["particles"] = 64
        s["run"]["replicas"] = 2000
        rows.append(dict(run(f"dt_{dt:g}", s, n_particle_law=True), knob=dt))
    event = copy.deepcopy(base)
    event["species"][0]["particles"] = 64
    event["run"]["replicas"] = 2000
    study["dt"] = rows
    study["dt_event"] = dict(run("dt_event", event, n_particle_law=True), knob=0.0)
    # 4. storage precision, event scheme, against the n-particle law; same seeds for both precisions
    rows = []
    for n, replicas in ((64, 2000), (2 ** 20, 8)):
        pair = {}
        for storage in ("double", "float"):
            s = copy.deepcopy(base)
            s["run"]["storage"] = storage
            s["species"][0]["particles"] = n
            s["run"]["replicas"] = replicas
            pair[storage] = run(f"storage_{storage}_n{n}", s, n_particle_law=True)
        diff, diff_ci = mean_ci(pair["float"]["per_replica"] - pair["double"]["per_replica"])
        for storage in ("double", "float"):
            rows.append(dict(pair[storage], knob=storage, n=n, replicas=replicas,
                             bytes=(32 if storage == "double" else 16), paired=(diff, diff_ci)))
    study["storage"] = rows
    # 5. early-time Haff, time-stepped scheme: the initial slope against n (n N = 2^25) and dt (n = 2^16)
    with open(os.path.join(HERE, "hcs_early.toml"), "rb") as f:
        early = tomllib.load(f)

    def run_early(name, scene, knob):
        stem = os.path.join(args.out, name)
        summary = run_point(args.granmc, scene, stem, args.threads)
        err, ci = mean_ci(early_slope_deviations(stem))
        return {"name": name, "knob": knob, "error": err, "ci": ci, "wall": summary["wall_seconds"],
                "n": scene["species"][0]["particles"], "replicas": scene["run"]["replicas"], "dt": scene["run"]["dt"]}

    rows = []
    for n in (1024, 8192, 65536):
        s = copy.deepcopy(early)
        s["species"][0]["particles"] = n
        s["run"]["replicas"] = 2 ** 25 // n
        rows.append(run_early(f"early_n{n}", s, n))
    study["early_particles"] = rows
    rows = []
    for dt in (0.005, 0.0025, 0.00125):
        s = copy.deepcopy(early)
        s["run"]["dt"] = dt
        s["species"][0]["particles"] = 65536
        s["run"]["replicas"] = 2 ** 25 // 65536
        rows.append(run_early(f"early_dt{dt:g}", s, dt))
    study["early_dt"] = rows
    # 6. recommendations for a target error e, from the measured CI constant and cost; the two cheapest
    #    are run to check that their total error (against T itself, 1/n included) stays below e
    study["recommend"] = recommend(study)
    for r in study["recommend"][:2]:
        s = copy.deepcopy(base)
        s["species"][0]["particles"] = r["n"]
        s["run"]["replicas"] = r["replicas"]
        r["check"] = run(f"recommend_e{r['target']:g}", s)
    for key in ("particles", "replicas", "dt", "storage"):
        for r in study[key]:
            r.pop("per_replica")
    for r in study["recommend"][:2]:
        r["check"].pop("per_replica")
    study["dt_event"].pop("per_replica")

    orders = {
        "particles": fitted_order([r["knob"] for r in study["particles"]], [r["error"] for r in study["particles"]],
                                  [r["ci"] for r in study["particles"]], rng),
        # the CI estimated from N replicas is itself uncertain by about CI / sqrt(2 (N - 1))
        "replicas": fitted_order([r["knob"] for r in study["replicas"]], [r["ci"] for r in study["replicas"]],
                                 [LAMBDA_P * r["ci"] / math.sqrt(2.0 * (r["knob"] - 1)) for r in study["replicas"]], rng),
        "dt": fitted_order([r["knob"] for r in study["dt"]], [r["error"] for r in study["dt"]],
                           [r["ci"] for r in study["dt"]], rng),
    }
    study["orders"] = orders
    with open(os.path.join(args.out, "study.json"), "w") as f:
        json.dump(study, f, indent=1)
    study["kappa"] = math.pi * base["collision"]["rate"] * (1.0 - base["collision"]["restitution"] ** 2)
    write_table(study, os.path.join(args.out, "table.md"))
    plot(study, os.path.join(args.out, "figure.png"))
    print(open(os.path.join(args.out, "table.md")).read())


def recommend(study):
    """The cheapest event-scheme settings for target relative errors e: n, the smallest power of two with
    1/n <= e/2, then N with CI <= e/2, using CI = c / sqrt(n N) with c measured over the particle and
    replica rows (median), and the wall seconds per particle-replica of the largest runs (median)."""
    c = [r["ci"] * math.sqrt(r["knob"] * 2 ** 18 // r["knob"]) for r in study["particles"]]
    c += [r["ci"] * math.sqrt(256 * r["knob"]) for r in study["replicas"]]
    c = float(np.median(c))
    big = [study["replicas"][-1]] + [r for r in study["storage"] if r["n"] > 64 and r["knob"] == "double"]
    per = float(np.median([r["wall"] / (r["n"] * r["replicas"]) if "n" in r else r["wall"] / (256 * r["knob"])
                           for r in big]))
    rows = []
    for e in (1e-2, 3e-3, 1e-3, 3e-4):
        n = 2 ** math.ceil(math.log2(2.0 / e))
        replicas = max(2, math.ceil((2.0 * c / e) ** 2 / n))
        rows.append({"target": e, "n": n, "replicas": replicas, "c": c, "wall_per": per,
                     "wall": per * n * replicas})
    return rows


def write_table(study, path):
    o = study["orders"]
    with open(path, "w") as f:
        f.write("# Work-precision, 001 Example 3 (Maxwell, white noise): late-time relative error of T\n\n")
        f.write(f"## Particles n (event scheme, n N = 2^18): order {o['particles'][0]:.3f} +- {o['particles'][1]:.3f} "
                "(exact: -1, error = -1/n)\n\n")
        f.write("| n | N | error | CI | -1/n | wall (s) |\n|---|---|---|---|---|---|\n")
        for r in study["particles"]:
            f.write(f"| {r['knob']} | {2 ** 18 // r['knob']} | {r['error']:+.5f} | {r['ci']:.5f} | {-1 / r['knob']:+.5f} | "
                    f"{r['wall']:.1f} |\n")
        f.write(f"\n## Replicas N (event scheme, n = 256, against (1 - 1/n) T): CI order {o['replicas'][0]:.3f} "
                f"+- {o['replicas'][1]:.3f} (statistical: -1/2)\n\n")
        f.write("| N | error | CI | wall (s) |\n|---|---|---|---|\n")
        for r in study["replicas"]:
            f.write(f"| {r['knob']} | {r['error']:+.5f} | {r['ci']:.5f} | {r['wall']:.1f} |\n")
        kappa = study["kappa"]  # pi rate (1 - alpha^2), 001 eq. (16)
        f.write(f"\n## Time step dt (time-stepped scheme, n = 64, N = 2000, against (1 - 1/n) T): order "
                f"{o['dt'][0]:.3f} +- {o['dt'][1]:.3f} (first-order splitting: 1)\n\n")
        f.write("| scheme | dt | error | CI | splitting law kappa dt / (1 - e^-kappa dt) - 1 (steady) | wall (s) |\n"
                "|---|---|---|---|---|---|\n")
        for r in study["dt"]:
            law = kappa * r["knob"] / -math.expm1(-kappa * r["knob"]) - 1.0
            f.write(f"| dsmc | {r['knob']:g} | {r['error']:+.5f} | {r['ci']:.5f} | {law:+.5f} | {r['wall']:.1f} |\n")
        r = study["dt_event"]
        f.write(f"| event | - | {r['error']:+.5f} | {r['ci']:.5f} | 0 | {r['wall']:.1f} |\n")
        f.write("\n## Storage precision (event scheme, against (1 - 1/n) T; float - double paired over the same "
                "seeds)\n\n")
        f.write("| n | N | storage | bytes per particle | error | CI | float - double (paired) | wall (s) |\n"
                "|---|---|---|---|---|---|---|---|\n")
        for r in study["storage"]:
            d, dci = r["paired"]
            paired = f"{d:+.2e} +- {dci:.1e}" if r["knob"] == "float" else "-"
            f.write(f"| {r['n']} | {r['replicas']} | {r['knob']} | {r['bytes']} | {r['error']:+.5f} | {r['ci']:.5f} | "
                    f"{paired} | {r['wall']:.1f} |\n")
        f.write("\n## Early-time Haff (time-stepped scheme, hard spheres, alpha = 1/2): initial slope of ln T "
                "against -zeta_M\n\n")
        f.write("| knob | n | N | dt | relative error of the slope | CI | wall (s) |\n|---|---|---|---|---|---|---|\n")
        for key, label in (("early_particles", "n"), ("early_dt", "dt")):
            for r in study[key]:
                f.write(f"| {label} | {r['n']} | {r['replicas']} | {r['dt']:g} | {r['error']:+.5f} | {r['ci']:.5f} | "
                        f"{r['wall']:.1f} |\n")
        rec = study["recommend"]
        f.write(f"\n## Cheapest settings for a target relative error e (event scheme; CI = c / sqrt(n N) with "
                f"c = {rec[0]['c']:.2f}, {rec[0]['wall_per'] * 1e6:.2f} us per particle-replica on this run's threads)\n\n")
        f.write("| target e | n (1/n <= e/2) | N (CI <= e/2) | storage | est. wall (s) | checked: error vs T | CI | wall (s) |\n"
                "|---|---|---|---|---|---|---|---|\n")
        for r in rec:
            check = (f"{r['check']['error']:+.5f} | {r['check']['ci']:.5f} | {r['check']['wall']:.1f}" if "check" in r
                     else "- | - | -")
            f.write(f"| {r['target']:g} | {r['n']} | {r['replicas']} | double | {r['wall']:.1f} | {check} |\n")


def plot(study, path):
    plt = pyplot()
    fig, axes = plt.subplots(1, 3, figsize=(14, 4.2))
    ax = axes[0]
    n = np.array([r["knob"] for r in study["particles"]])
    ax.errorbar(n, [-r["error"] for r in study["particles"]], yerr=[r["ci"] for r in study["particles"]], fmt="o",
                label="granmc (event), -error")
    ax.plot(n, 1.0 / n, "k--", label="1/n (exact law)")
    ax.set_xscale("log"), ax.set_yscale("log"), ax.set_xlabel("particles n"), ax.set_ylabel("relative error of T")
    ax.legend(fontsize="small")
    ax = axes[1]
    w = np.array([r["wall"] for r in study["replicas"]])
    ax.plot(w, [r["ci"] for r in study["replicas"]], "o-", label="CI (event, n = 256)")
    ax.plot(w, study["replicas"][0]["ci"] * np.sqrt(w[0] / w), "k--", label="~ seconds^-1/2")
    ax.set_xscale("log"), ax.set_yscale("log"), ax.set_xlabel("wall seconds"), ax.set_ylabel("statistical error (CI)")
    ax.legend(fontsize="small")
    ax = axes[2]
    for r in study["dt"]:
        ax.errorbar(r["wall"], r["error"], yerr=r["ci"], fmt="s", color="C1")
        ax.annotate(f"dt = {r['knob']:g}", (r["wall"], r["error"]), fontsize="x-small")
    r = study["dt_event"]
    ax.errorbar(r["wall"], abs(r["error"]) + 1e-6, yerr=r["ci"], fmt="o", color="C0", label="event (no dt)")
    ax.set_xscale("log"), ax.set_yscale("log"), ax.set_xlabel("wall seconds"), ax.set_ylabel("error vs (1 - 1/n) T")
    ax.legend(fontsize="small")
    fig.suptitle("Work-precision: 001 Example 3 (Maxwell pseudomolecules, white noise)", fontsize="small")
    save(fig, path)


if __name__ == "__main__":
    main()
