"""Reproduce a paper figure: run granmc over a parameter sweep, compare with theory, plot, tabulate.

    from granmc import make_figure
    make_figure("drivers/scenes/002_fig3/figure.toml", "build/bin/granmc", out="results/002_fig3")

The command line is drivers/figure.py:
    /usr/bin/python3 drivers/figure.py FIGURE.toml [--granmc build/bin/granmc] [--out results/NAME]
                                       [--threads N] [--mpi R] [--only-theory]

A figure file (drivers/scenes/<paper>_fig<k>/figure.toml) names a base scene (a valid granmc scene in the
same folder), the swept parameter, its simulated values, the curves (per curve: species overrides,
`set` of dotted scene keys, or a base scene of its own) and what is plotted. make_figure makes the scene of
every simulated point, then runs all the points of one base scene as one `granmc sweep`
(docs/user-guide/parallel-runs.md, "Sweeps"): each point is a [[scenes]] table of the dotted keys where its scene differs
from the base (`"collision.restitution" = 0.7`, `"species[0].diameter" = 0.5`), written to
OUT/points/sweep.toml with a copy of the base beside it (a curve with a base of its own gets
OUT/points/<base stem>/). The sweep writes NAME.h5, NAME.json and index.json there; a rerun skips the
points done with the same scene, and a killed run leaves no half-written point. Each point's summary is
found through index.json by its values. `mpi = R` (`--mpi R`) runs the sweeps as `mpirun -np R
--oversubscribe granmc sweep ...`, spreading each point's replicas over R ranks; it needs the MPI build
(`make mpi`, then `--granmc build-mpi/bin/granmc`). Theory lines come from `granmc theory` on a fine grid;
`only_theory` (`--only-theory`) draws them alone and runs no point. Output: OUT/figure.png, OUT/table.md
(simulation with CI against theory, each point's seed, and what a seed shared by all points means for
reading it) and OUT/figure.json (all numbers, and each point's HDF5 file relative to OUT).

Swept parameters: "alpha" (every restitution coefficient), "phi" (collision.packing_fraction), and for two
species "mu" (m_1/m_2), "omega" (sigma_1/sigma_2), "delta" (n_1/n_2, total density and particles kept).
`y_log = true` draws the y axis logarithmic. `reference_curve = LABEL` divides every other curve by that one at the same x (000 Figs. 7-9: eta(alpha)/eta(1)).
Plotted quantities (y): "temperature_ratio" (gamma = T_1/T_2), "temperature_ratio_relative"
(gamma(x)/gamma(x = 0) of the same curve, 000 Fig. 5), "cumulants" (c_i = 2 a2_i per species, 000 Fig. 1),
"intruder_temperature_ratio" (T/T_B of a Gillespie intruder, 002 Figs. 3-4; "alpha" then sets
intruder.restitution), "needle_correlation" (R of the 2D needle, 002 eq. 34 and Fig. 7),
"viscosity_over_eta0" (eta/eta0 of one species under shear, 000 Fig. 6 and 003), "viscosity_kinetic_over_eta0",
"viscosity_star" and "viscosity_kinetic_star" (eta* and eta^k* = nu eta / n T, 000 Figs. 10-12),
"viscosity_parts_over_eta0" (eta^k/eta0 and eta/eta0 together, 003), "viscosity_parts_star" (eta^k* and
eta* together, 000 Figs. 10-11), "steady_shear" (a* and eta* of the steady shear flow without a thermostat,
000 sec. 5; a* is the mean over the viscosity window, its CI the mean of the samples' CIs, a bound on the CI
of the mean). Under shear, "phi" also sets the
densities to match phi and scales the time with the collision frequency (dense_shear_units).

A viscosity figure with a table `[figure.zero_shear]` (`rate_factors = [0.25, 0.5, 0.708, 1.0]`,
`replica_factors = [4, 1, 1, 1]`) runs every point at each rate factor times its shear rate, with that many
times its replicas, and plots the Navier-Stokes limit a* -> 0 (granmc.zero_shear: eta against a*^2,
weighted least squares, CI = 3.2 standard errors of the intercept); the table also lists the value at the
point's own rate (factor 1), the fitted slope c, the a* of each rate, and whether every run passed granmc's
plateau test (viscosity.steady).
"""
import copy
import json
import os
import tomllib

import numpy as np

from granmc.plotting import pyplot, save
from granmc.replicas import LAMBDA_P
from granmc.scenes import run_sweep as granmc_sweep
from granmc.scenes import theory
from granmc.zero_shear import fit_intercept, window_mean_shear_rate


class FigureError(ValueError):
    """A figure file that cannot be made: the message names what is wrong."""

__all__ = ["FigureError", "make_figure"]


# ---- scenes ---------------------------------------------------------------------------------------------

def point_scene(bases, curve, x_name, x):
    scene = copy.deepcopy(bases[curve.get("base", "")])
    for sp, override in zip(scene.get("species", []), curve.get("species", [])):
        sp.update(override)
    for dotted, value in curve.get("set", {}).items():  # e.g. "collision.restitution" = 0.6
        table, key = dotted.split(".")
        scene.setdefault(table, {})[key] = value
    if x_name == "alpha" and "intruder" in scene:
        scene["intruder"]["restitution"] = float(x)
    elif x_name == "alpha":
        scene.setdefault("collision", {})["restitution"] = float(x)
    elif x_name == "phi":
        scene.setdefault("collision", {})["packing_fraction"] = float(x)
        if scene.get("shear", {}).get("rate", 0.0) != 0.0 and x > 0.0:
            dense_shear_units(scene, float(x))
    elif x_name in ("mu", "omega", "delta") and len(scene.get("species", [])) == 2:
        a, b = scene["species"]
        if x_name == "mu":  # m_1 / m_2
            a["mass"] = float(x) * b.get("mass", 1.0)
        elif x_name == "omega":  # sigma_1 / sigma_2
            a["diameter"] = float(x) * b.get("diameter", 1.0)
        else:  # delta = n_1 / n_2 at the same total density and particle number
            n, N = a.get("density", 1.0) + b.get("density", 1.0), a["particles"] + b["particles"]
            a["density"], b["density"] = n * x / (1.0 + x), n / (1.0 + x)
            a["particles"] = int(round(N * x / (1.0 + x)))
            b["particles"] = N - a["particles"]
    else:
        raise FigureError(f"unknown swept parameter {x_name!r}; allowed: alpha, phi, and for two species mu, "
                 "omega, delta")
    return scene


def dense_shear_units(scene, phi):
    """Under shear an Enskog scene must have sum_i pi n_i sigma_i^3 / 6 = phi (granmc checks it). Sets the
    densities to that (fractions and diameters kept), and scales the shear rate up and dt, t_end down by the
    growth f = n chi(phi) / n_base of the collision frequency (chi of one species, Carnahan-Starling), so
    every phi runs the same number of collisions at the same a / (collision frequency) as the dilute base."""
    species = scene["species"]
    n_base = sum(sp.get("density", 1.0) for sp in species)
    moment = sum(sp.get("density", 1.0) / n_base * sp.get("diameter", 1.0) ** 3 for sp in species)
    n = 6.0 * phi / (np.pi * moment)
    for sp in species:
        sp["density"] = sp.get("density", 1.0) / n_base * n
    f = n * (1.0 - phi / 2.0) / (1.0 - phi) ** 3 / n_base
    scene["shear"]["rate"] *= f
    scene["run"]["dt"] /= f
    scene["run"]["t_end"] /= f


# ---- running granmc: the points as one sweep per base scene, and theory -----------------------------------

def same_value(a, b):
    """Equal and of the same TOML type: 1 and 1.0, or true and 1, are different values in a scene."""
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(same_value(x, y) for x, y in zip(a, b))
    return type(a) is type(b) and a == b


def is_table_array(v):
    return isinstance(v, list) and len(v) > 0 and all(isinstance(t, dict) for t in v)


def sweep_values(base, scene, prefix=""):
    """The dotted keys where `scene` differs from `base`, each with its value in `scene`: what a [[scenes]]
    table of a sweep file sets on the base to make the scene (docs/formats/scenes.md, "Sweep files"). Tables are
    followed key by key (collision.restitution), [[species]] tables by index (species[1].mass), any other
    value, an array too, is set whole. A difference no sweep can make stops the script."""
    def cannot(what):
        raise FigureError(f"a point's scene {what}; a sweep only sets values on the base scene")
    values = {}
    for key in base:
        if key not in scene:
            cannot(f"lacks {prefix}{key} of the base")
    for key, v in scene.items():
        dotted, old = prefix + key, base.get(key)
        if isinstance(v, dict) and (old is None or isinstance(old, dict)):
            if not v and old is None:
                cannot(f"adds the empty table {dotted}")
            values.update(sweep_values(old or {}, v, dotted + "."))
        elif is_table_array(v) or is_table_array(old):
            if not (is_table_array(v) and is_table_array(old) and len(v) == len(old)):
                cannot(f"has another number of [[{dotted}]] tables than the base")
            for i, (o, t) in enumerate(zip(old, v)):
                values.update(sweep_values(o, t, f"{dotted}[{i}]."))
        elif key not in base or not same_value(old, v):
            values[dotted] = v
    return values


def run_sweep(run, base_path, scenes, base, sweep_dir):
    """Runs the scenes (point -> scene dict) as [[scenes]] of one sweep on the base scene file `base_path`
    (parsed: `base`) in sweep_dir; `run`: granmc.scenes.run_sweep's granmc, threads, mpi and writer. Returns
    point -> (summary, HDF5 path)."""
    points = list(scenes)
    ran = granmc_sweep(run["granmc"], base_path, [sweep_values(base, scenes[p]) for p in points], sweep_dir,
                       threads=run["threads"], mpi=run["mpi"], writer=run["writer"])
    return dict(zip(points, ran))


def run_points(run, here, fig, curves, bases, scenes, out):
    """Runs every point (curve index, x[, rate index]) -> scene: one sweep per base scene file, the figure's in
    OUT/points, a curve's own in OUT/points/<its stem>; `run` as for run_sweep. Returns point -> (summary, HDF5
    path)."""
    groups = {}  # base file -> (name in `bases`, {point: scene})
    for point, scene in scenes.items():  # point: (curve index, x) or (curve index, x, rate index)
        name = curves[point[0]].get("base", "")
        path = os.path.normpath(os.path.join(here, name or fig["base"]))
        groups.setdefault(path, (name, {}))[1][point] = scene
    figure_base = os.path.normpath(os.path.join(here, fig["base"]))
    results, dirs = {}, set()
    for path, (name, group) in groups.items():
        sweep_dir = os.path.join(out, "points")
        if path != figure_base:
            sweep_dir = os.path.join(sweep_dir, os.path.splitext(os.path.basename(path))[0])
        if sweep_dir in dirs:
            raise FigureError(f"two curves' base scenes have the stem of {path}; rename one")
        dirs.add(sweep_dir)
        results.update(run_sweep(run, path, group, bases[name], sweep_dir))
    return results


# ---- quantities -------------------------------------------------------------------------------------------

# y -> the key of the summary's and the theory's viscosity blocks
VISCOSITY_KEYS = {"viscosity_over_eta0": "eta_over_eta0", "viscosity_kinetic_over_eta0": "eta_kinetic_over_eta0",
                  "viscosity_star": "eta_star", "viscosity_kinetic_star": "eta_kinetic_star"}


# every plotted quantity y that simulated() and theoretical() know
QUANTITIES = {"temperature_ratio", "temperature_ratio_relative", "intruder_temperature_ratio", "needle_correlation",
              "viscosity_parts_over_eta0", "viscosity_parts_star", "steady_shear", "cumulants"} | set(VISCOSITY_KEYS)


def simulated(summary, y):
    """[(label suffix, mean, ci)] for one point."""
    if y in ("temperature_ratio", "temperature_ratio_relative"):
        r = summary["temperature_ratio"]
        return [("", r["mean"], r["ci"])]
    if y == "intruder_temperature_ratio":
        r = summary["intruder"]["temperature_ratio"]
        return [("", r["mean"], r["ci"])]
    if y == "needle_correlation":
        r = summary["intruder"]["R"]
        return [("", r["mean"], r["ci"])]
    if y in ("viscosity_parts_over_eta0", "viscosity_parts_star"):
        v = summary["viscosity"]
        k, t = ("eta_kinetic_over_eta0", "eta_over_eta0") if y.endswith("eta0") else ("eta_kinetic_star", "eta_star")
        return [(", kinetic", v[k]["mean"], v[k]["ci"]), (", total", v[t]["mean"], v[t]["ci"])]
    if y in VISCOSITY_KEYS:
        r = summary["viscosity"][VISCOSITY_KEYS[y]]
        return [("", r["mean"], r["ci"])]
    if y == "steady_shear":
        v = summary["viscosity"]
        a_ci = np.asarray(v["reduced_shear_rate"]["ci"], dtype=float)
        return [(", a*", window_mean_shear_rate(v), float(np.mean(a_ci[len(a_ci) // 2:]))),
                (", eta*", v["eta_star"]["mean"], v["eta_star"]["ci"])]
    if y == "cumulants":
        species = summary["species"]
        return [(f", species {sp['name']}" if len(species) > 1 else "", 2.0 * sp["a2_last_half"]["mean"],
                 2.0 * sp["a2_last_half"]["ci"]) for sp in species]
    raise FigureError(f"unknown y {y!r}")


def theoretical(th, y):
    """{approximation: [values per series]} for one point."""
    out = {}
    if y in ("temperature_ratio", "temperature_ratio_relative"):
        m = th.get("mixture")
        if m:
            out["Maxwellian"] = [m["temperature_ratio_maxwell"]]
            out["first Sonine"] = [m["temperature_ratio_sonine"]]
    elif y == "intruder_temperature_ratio":
        i = th.get("intruder", {})
        if "temperature_ratio_exact" in i:
            out["exact"] = [i["temperature_ratio_exact"]]
        if i.get("bath") == "power-law":  # the Gaussian-bath result as the reference line (002 Fig. 4)
            out["Gaussian bath, eq. 22"] = [i["temperature_ratio_gaussian_bath"]]
    elif y == "needle_correlation":
        out["equilibrium, R = 1"] = [1.0]
    elif y in ("viscosity_parts_over_eta0", "viscosity_parts_star") and "viscosity" in th:
        v = th["viscosity"]["first_sonine"]
        k, t = ("eta_kinetic_over_eta0", "eta_over_eta0") if y.endswith("eta0") else ("eta_kinetic_star", "eta_star")
        if k in v:
            out["first Sonine"] = [v[k], v[t]]
    elif y in VISCOSITY_KEYS and "viscosity" in th:
        key = VISCOSITY_KEYS[y]
        v = th["viscosity"]
        if "first_sonine_gaussian_thermostat" in v:  # one species: both reference states (000 Fig. 6 a, b)
            out["first Sonine, HSS"] = [v["first_sonine_gaussian_thermostat"][key]]
            out["first Sonine, HCS"] = [v["first_sonine_cooling_state"][key]]
        elif key in v.get("first_sonine", {}):
            out["first Sonine"] = [v["first_sonine"][key]]
    elif y == "steady_shear" and "steady_shear" in th:
        out["Grad"] = [th["steady_shear"]["reduced_shear_rate"], th["steady_shear"]["eta_star"]]
    elif y == "cumulants":
        m = th.get("mixture")
        if m and "a2_sonine" in m:
            out["first Sonine"] = [2.0 * a for a in m["a2_sonine"]]
        one = th.get("scaled_state")
        if one:
            out["first Sonine"] = [2.0 * one["a2"]]
            out["second Sonine"] = [2.0 * one["a2_second_sonine"]]
    return out


# ---- the figure -------------------------------------------------------------------------------------------

def make_figure(figure_path, granmc, out=None, threads=0, mpi=0, only_theory=False):
    """Makes the figure of the figure file `figure_path` (the format: this module's docstring) with the granmc
    executable `granmc`: runs its points (unless only_theory), asks theory, and writes OUT/figure.png,
    OUT/table.md and OUT/figure.json; raises FigureError on a figure file it cannot make. out: the output
    folder (default results/<figure folder name>, relative to the working directory); threads: OpenMP threads
    per process (0: all cores); mpi: run the sweeps under `mpirun -np mpi --oversubscribe` (0: without mpirun;
    needs the MPI build). A rerun reuses the points done with the same scene. Returns the output folder."""
    figure_path = os.fspath(figure_path)
    run = {"granmc": granmc, "threads": threads, "mpi": mpi, "writer": f"granmc.figures {figure_path}"}
    with open(figure_path, "rb") as f:
        spec = tomllib.load(f)
    fig = spec["figure"]
    here = os.path.dirname(os.path.abspath(figure_path))
    bases = {}  # the figure's base scene under "", and any a curve names with its own `base`
    for name in [""] + [c["base"] for c in spec["curve"] if "base" in c]:
        with open(os.path.join(here, name or fig["base"]), "rb") as f:
            bases[name] = tomllib.load(f)
    out = os.fspath(out or os.path.join("results", os.path.basename(here)))
    os.makedirs(out, exist_ok=True)
    x_name, y = fig["x"], fig["y"]
    if y not in QUANTITIES:
        raise FigureError(f"unknown y {y!r}; allowed: {', '.join(sorted(QUANTITIES))}")
    x_values = [float(v) for v in fig["x_values"]]
    x_theory = np.linspace(*fig["x_theory"][:2], int(fig["x_theory"][2]))
    curves = spec["curve"]

    zero_shear = fig.get("zero_shear")
    if zero_shear and y not in VISCOSITY_KEYS and y not in ("viscosity_parts_over_eta0", "viscosity_parts_star"):
        raise FigureError(f"[figure.zero_shear] needs a viscosity quantity, not y = {y!r}")
    runs = {}  # (curve index, x) or (curve index, x, rate index) -> (summary, HDF5 path)
    if not only_theory:
        scenes = {(ci_, x): point_scene(bases, curve, x_name, x) for ci_, curve in enumerate(curves) for x in x_values}
        if zero_shear:
            scenes = {point + (k,): at_rate(scene, f, r) for point, scene in scenes.items()
                      for k, (f, r) in enumerate(zip(zero_shear["rate_factors"], zero_shear["replica_factors"]))}
        runs = run_points(run, here, fig, curves, bases, scenes, out)

    results = []
    for ci_, curve in enumerate(curves):
        print(f"{fig['paper']}: {curve['label']}", flush=True)
        pts = []
        if not only_theory:
            for x in x_values:
                if zero_shear:
                    pt = extrapolated([runs[(ci_, x, k)] for k in range(len(zero_shear["rate_factors"]))],
                                      zero_shear["rate_factors"], y, out)
                else:
                    summary, hdf5 = runs[(ci_, x)]
                    pt = {"sim": simulated(summary, y), "wall_seconds": summary["wall_seconds"],
                          "hdf5": os.path.relpath(hdf5, out), "builds": [build_of(summary)]}
                pt.update({"x": x, "seed": next(sc for p_, sc in scenes.items() if p_[:2] == (ci_, x))["run"]["seed"],
                           "theory": theoretical(theory(granmc, point_scene(bases, curve, x_name, x)), y)})
                pts.append(pt)
        lines = [theoretical(theory(granmc, point_scene(bases, curve, x_name, x)), y) for x in x_theory]
        results.append({"label": curve["label"], "points": pts, "theory_x": list(x_theory), "theory": lines})

    if y == "temperature_ratio_relative":
        normalise(results)
    if "reference_curve" in fig:
        results = relative_to_curve(results, fig["reference_curve"])
    with open(os.path.join(out, "figure.json"), "w") as f:
        json.dump({"figure": fig, "curves": results}, f, indent=1)
    write_table(fig, results, os.path.join(out, "table.md"))
    plot(fig, results, os.path.join(out, "figure.png"))
    print(f"wrote {out}/figure.png, {out}/table.md, {out}/figure.json")
    return out


def at_rate(scene, rate_factor, replica_factor):
    """A point's scene at rate_factor times its shear rate, with replica_factor times its replicas."""
    scene = copy.deepcopy(scene)
    scene["shear"]["rate"] *= rate_factor
    scene["run"]["replicas"] *= replica_factor
    return scene


def extrapolated(runs, rate_factors, y, out):
    """One point from its runs at several shear rates: per series, the intercept of eta against a*^2
    (granmc.zero_shear) with its CI, and what the table shows beside it."""
    sims = [simulated(summary, y) for summary, _ in runs]
    viscosities = [summary["viscosity"] for summary, _ in runs]
    a_star = [window_mean_shear_rate(v) for v in viscosities]
    sim, slopes = [], []
    for s, (suffix, _, _) in enumerate(sims[0]):
        b0, sigma0, c = fit_intercept(a_star, [r[s][1] for r in sims], [r[s][2] / LAMBDA_P for r in sims])
        sim.append((suffix, b0, LAMBDA_P * sigma0))
        slopes.append(c)
    own = rate_factors.index(1.0)
    return {"sim": sim, "wall_seconds": sum(summary["wall_seconds"] for summary, _ in runs),
            "hdf5": [os.path.relpath(h, out) for _, h in runs], "builds": [build_of(summary) for summary, _ in runs],
            "zero_shear": {"a_star": a_star, "c": slopes, "at_own_rate": sims[own],
                           "steady": all(v["steady"] for v in viscosities)}}


def normalise(results):
    """gamma(x)/gamma(x = first value) per curve; CIs of the two runs combined as for independent runs (runs
    with one seed are correlated instead: table.md says which)."""
    for c in results:
        if c["points"]:
            _, g0, e0 = c["points"][0]["sim"][0]
            theory0 = c["points"][0]["theory"]
            for n, pt in enumerate(c["points"]):
                _, g, e = pt["sim"][0]
                r = g / g0
                pt["sim"] = [("", r, 0.0 if n == 0 else r * np.hypot(e / g, e0 / g0))]  # the reference is exactly 1
                pt["theory"] = {k: [v[0] / theory0[k][0]] for k, v in pt["theory"].items()}
        if c["theory"]:
            ref = c["theory"][0]
            c["theory"] = [{k: [v[0] / ref[k][0]] for k, v in line.items()} for line in c["theory"]]


def relative_to_curve(results, label):
    """Every other curve divided, point by point and line by line, by the curve `label` at the same x (e.g.
    eta(alpha)/eta(1) of 000 Figs. 7-9); CIs combined as for independent runs (runs with one seed are correlated
    instead: table.md says which). The reference curve is dropped."""
    ref = next(c for c in results if c["label"] == label)
    out = []
    for c in results:
        if c is ref:
            continue
        for pt, r in zip(c["points"], ref["points"]):
            pt["sim"] = ratio_series(pt["sim"], r["sim"])
            if "zero_shear" in pt:  # a ratio is steady when both its runs are
                pt["zero_shear"]["at_own_rate"] = ratio_series(pt["zero_shear"]["at_own_rate"],
                                                               r["zero_shear"]["at_own_rate"])
                pt["zero_shear"]["steady"] = pt["zero_shear"]["steady"] and r["zero_shear"]["steady"]
            pt["theory"] = {k: [v / w for v, w in zip(vals, r["theory"][k])] for k, vals in pt["theory"].items()}
        c["theory"] = [{k: [v / w for v, w in zip(vals, rl[k])] for k, vals in line.items()}
                       for line, rl in zip(c["theory"], ref["theory"])]
        out.append(c)
    return out


def ratio_series(sim, ref):
    """[(suffix, m / m_ref, CI)] with the CIs combined as for independent runs."""
    return [(suf, m / rm, abs(m / rm) * np.hypot(e / m, re / rm))  # a half-width, >= 0
            for (suf, m, e), (_, rm, re) in zip(sim, ref)]


def seed_note(results):
    """What the points' seeds mean for reading the table: one shared seed makes the points correlated."""
    seeds = sorted({pt["seed"] for c in results for pt in c["points"]})
    if len(seeds) == 1:
        return (f"Every point runs with seed {seeds[0]}: the points share their random numbers, so they are "
                "correlated. Differences between points are resolved better than each CI says, and an offset "
                "common to neighbouring points is one realization, not a bias.\n\n")
    return f"Seeds: {', '.join(str(s) for s in seeds)} (column seed); points with different seeds are independent.\n\n"


def build_of(summary):
    """The granmc build that wrote a summary (its `build` record, format 2.4 on)."""
    return summary.get("build", "not recorded")


def build_note(results):
    """Which granmc build made the points: a later build may draw other random numbers (the same law)."""
    builds = sorted({b for c in results for pt in c["points"] for b in pt.get("builds", [])})
    return (f"Made by granmc {', '.join(builds)} (`granmc --version`); another build reruns every point and may give "
            "another realization of the same law.\n\n")


def write_table(fig, results, path):
    with open(path, "w") as f:
        f.write(f"# {fig['paper']}: {fig['caption']}\n\n")
        if any(c["points"] for c in results):
            f.write(seed_note(results))
            f.write(build_note(results))
        zero_shear = "zero_shear" in fig
        if zero_shear:
            z = fig["zero_shear"]
            f.write(f"granmc: the limit a* -> 0 of runs at {', '.join(f'{r:g}' for r in z['rate_factors'])} times the "
                    f"point's shear rate ({', '.join(str(r) for r in z['replica_factors'])} times its replicas), "
                    "fitted as eta = eta(0) + c a*^2 (c of the curve's own eta, before any division by a reference curve); \"own rate\": the run at the point's rate; a*: each rate's "
                    "mean over the window; steady: every run passed the plateau test.\n\n")
        extra = " own rate | CI | c | a* | steady |" if zero_shear else ""
        f.write("| curve | x | quantity | granmc | CI | " + " | ".join(approximations(results)) + f" |{extra} seed "
                "| run (s) |\n")
        f.write("|---|---|---|---|---|" + "---|" * (len(approximations(results)) + (5 if zero_shear else 0))
                + "---|---|\n")
        for c in results:
            for pt in c["points"]:
                for s, (suffix, m, e) in enumerate(pt["sim"]):
                    th = [fmt(pt["theory"].get(a, [None] * (s + 1))[s] if s < len(pt["theory"].get(a, [])) else None)
                          for a in approximations(results)]
                    cells = ""
                    if zero_shear:
                        zs = pt["zero_shear"]
                        _, m1, e1 = zs["at_own_rate"][s]
                        cells = (f" {m1:.4f} | {e1:.4f} | {zs['c'][s]:.2f} | "
                                 f"{', '.join(f'{a:.3f}' for a in zs['a_star'])} | {'yes' if zs['steady'] else 'no'} |")
                    f.write(f"| {c['label']} | {pt['x']:g} | {fig['y']}{suffix} | {m:.4f} | {e:.4f} | "
                            + " | ".join(th) + f" |{cells} {pt['seed']} | {pt['wall_seconds']:.0f} |\n")


def approximations(results):
    names = []
    for c in results:
        for line in c["theory"]:
            for k in line:
                if k not in names:
                    names.append(k)
    return names


def fmt(v):
    return "-" if v is None else f"{v:.4f}"


def plot(fig, results, path):
    plt = pyplot()

    styles = {"equilibrium, R = 1": ":", "Maxwellian": ":", "first Sonine": "-", "second Sonine": "--", "exact": "-",
              "Gaussian bath, eq. 22": "--", "first Sonine, HSS": "-", "first Sonine, HCS": "--", "Grad": "-"}
    markers = ["o", "s", "^", "D", "v"]
    f, ax = plt.subplots(figsize=(6.4, 4.8))
    series = 0
    for ci_, c in enumerate(results):
        n_series = max([len(pt["sim"]) for pt in c["points"]] + [len(line.get(k, [])) for line in c["theory"]
                                                                   for k in line] + [1])
        for s in range(n_series):
            colour = f"C{series % 10}"
            series += 1
            suffix = c["points"][0]["sim"][s][0] if c["points"] and s < len(c["points"][0]["sim"]) else ""
            if c["points"] and s < len(c["points"][0]["sim"]):
                xs = [pt["x"] for pt in c["points"]]
                ms = [pt["sim"][s][1] for pt in c["points"]]
                es = [pt["sim"][s][2] for pt in c["points"]]
                own = "zero_shear" in c["points"][0]
                ax.errorbar(xs, ms, yerr=es, fmt=markers[ci_ % len(markers)], color=colour, capsize=3,
                            label=f"granmc{', a* -> 0' if own else ''}, {c['label']}{suffix}")
                if own:
                    ax.plot(xs, [pt["zero_shear"]["at_own_rate"][s][1] for pt in c["points"]],
                            markers[ci_ % len(markers)], mfc="none", color=colour,
                            label=f"granmc at the point's rate, {c['label']}{suffix}")
            for approx in approximations(results):
                ys = [line[approx][s] if approx in line and s < len(line[approx]) else np.nan for line in c["theory"]]
                if np.all(np.isnan(ys)):
                    continue
                ax.plot(c["theory_x"], ys, styles.get(approx, "-."), color=colour, linewidth=1.0,
                        label=f"{approx}, {c['label']}{suffix}")
    ax.set_xlabel(fig.get("x_label", fig["x"]))
    ax.set_ylabel(fig.get("y_label", fig["y"]))
    if fig.get("y_log"):
        ax.set_yscale("log")
    ax.set_title(f"{fig['paper']}: {fig['caption']}", fontsize="small")
    ax.legend(fontsize="x-small")
    save(f, path)
