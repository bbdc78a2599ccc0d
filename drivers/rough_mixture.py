#!/usr/bin/python3
"""A binary mixture of rough particles, cooling and under white noise, against the Maxwellian theory of `granmc theory`.

    /usr/bin/python3 drivers/rough_mixture.py [--granmc build/bin/granmc] [--out results/rough_mixture]

drivers/scenes/rough_mixture/scene.toml (light and heavy rough spheres or disks, the Gaussian thermostat holding
the cooling state's scaled state) runs at alpha = 0.8 for each beta and dimension below, and so does its light
species alone (one species at the total density); the rows at beta = -0.5 run LONG times the scene's t_end. For
each run: T_1 / T_2 and theta_i = T_rot,i / T_i, each the per-replica average over the last half of the samples,
then the replica mean and its confidence half-width (the summary's `temperature_ratio` and `rotational_ratio`),
beside the Maxwellian approximation (docs/methods/derivations/rough-hcs.md, "Mixtures") and the deviation from it in per
cent. Then the same scenes heated by white noise on translation (beta_wn = 1) instead of the thermostat: white
noise acts after the collisions (a first-order splitting), so each runs at DT and DT / 2 and the values are taken
at dt -> 0 per replica (2 x(dt/2) - x(dt)), as drivers/rough_split_noise.py does. Writes OUT/table.md.
"""
import argparse
import copy
import os
import tomllib

from granmc import mean_ci, open_results, run_point, theory

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "scenes", "rough_mixture")
ALPHA = 0.8
BETAS = (-0.5, 0.0, 0.5, 1.0)
LONG = 4  # t_end factor at beta = -0.5: the weakly coupled spins heat up over tens of time units
DT = 0.005  # the white-noise runs' coarser step


def rough_theory(granmc, stem):
    return theory(granmc, stem + ".toml")["rough"]


def row_scenes(base, dimension, beta):
    """The scene of a row (dimension, alpha = ALPHA, beta) and its light species alone at the total density."""
    scene = copy.deepcopy(base)
    scene["run"]["dimension"] = dimension
    scene["collision"]["restitution"] = ALPHA
    scene["collision"]["tangential_restitution"] = beta
    one = copy.deepcopy(scene)
    one["species"] = [dict(scene["species"][0], density=1.0,
                           particles=sum(s["particles"] for s in scene["species"]))]
    return scene, one


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--granmc", default="build/bin/granmc")
    p.add_argument("--out", default=os.path.join("results", "rough_mixture"))
    p.add_argument("--threads", type=int, default=0)
    args = p.parse_args()
    with open(os.path.join(HERE, "scene.toml"), "rb") as f:
        base = tomllib.load(f)
    os.makedirs(os.path.join(args.out, "points"), exist_ok=True)

    rows = []
    for dimension in (3, 2):
        for beta in BETAS:
            scene, one = row_scenes(base, dimension, beta)
            if beta < 0.0:
                scene["run"]["t_end"] = one["run"]["t_end"] = LONG * base["run"]["t_end"]
            stem = os.path.join(args.out, "points", f"d{dimension}_b{beta}")
            mixture, single = (run_point(args.granmc, s, stem + suffix, args.threads)
                               for s, suffix in ((scene, ""), (one, "_one")))
            rows.append({"d": dimension, "beta": beta, "mixture": mixture, "single": single,
                         "theory": rough_theory(args.granmc, stem), "theory_one": rough_theory(args.granmc, stem + "_one")})
            print(f"  d = {dimension}, beta = {beta}: done", flush=True)
    heated = []
    for dimension in (3, 2):
        for beta in BETAS:
            scene, one = row_scenes(base, dimension, beta)
            for s in (scene, one):  # theta settles within t = 10 at any beta
                s["thermostat"] = {"kind": "white-noise", "beta": 1.0}
            names = [s["name"] for s in scene["species"]]
            row = {"d": dimension, "beta": beta}
            for label, s, species in (("mixture", scene, names), ("single", one, names[:1])):
                per_dt = []
                for step in (DT, DT / 2):
                    s["run"]["dt"] = step
                    stem = os.path.join(args.out, "points", f"noise_d{dimension}_b{beta}_{label}_dt{step}")
                    run_point(args.granmc, s, stem, args.threads)
                    per_dt.append(last_half_ratios(stem + ".h5", species))
                row[label] = {k: mean_and_ci(2.0 * per_dt[1][k] - per_dt[0][k]) for k in per_dt[0]}
                row["theory_" + label] = rough_theory(args.granmc, stem)
            heated.append(row)
            print(f"  white noise, d = {dimension}, beta = {beta}: done", flush=True)
    write_table(rows, heated, os.path.join(args.out, "table.md"))
    print(f"wrote {args.out}/table.md")


def last_half_ratios(path, species):
    """Per replica, the time averages over the last half of the samples of theta_i = T_rot,i / T_i and (two species)
    of T_1 / T_2."""
    with open_results(path) as h:
        t_tr = [h[f"species/{name}/temperature/replicas"][()] for name in species]
        t_rot = [h[f"species/{name}/rotational_temperature/replicas"][()] for name in species]
    first = t_tr[0].shape[1] // 2
    out = {f"theta_{i}": (t_rot[i][:, first:] / t_tr[i][:, first:]).mean(axis=1) for i in range(len(species))}
    if len(species) == 2:
        out["ratio"] = (t_tr[0][:, first:] / t_tr[1][:, first:]).mean(axis=1)
    return out


def mean_and_ci(values):
    """The replica mean and its confidence half-width, as a row of the table."""
    mean, ci = mean_ci(values)
    return {"mean": mean, "ci": ci}


def cell(measured, maxwellian):
    """granmc +- CI, the Maxwellian value, and granmc's deviation from it in per cent."""
    return (f"{measured['mean']:.4f} +- {measured['ci']:.4f} | {maxwellian:.4f} | "
            f"{100 * (measured['mean'] / maxwellian - 1):+.1f}")


def write_table(rows, heated, path):
    header = ("| d | beta | T_1/T_2 | Maxwellian | dev % | theta_1 | Maxwellian | dev % | theta_2 | Maxwellian | "
              "dev % | one species: theta | Maxwellian | dev % |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n")
    with open(path, "w") as f:
        f.write("# Rough mixture: granmc against the Maxwellian approximation\n\n")
        f.write(f"drivers/scenes/rough_mixture/scene.toml at alpha = {ALPHA}: species 1 light (m = sigma = 1), "
                "species 2 heavy (m = 4, sigma = 1.5), equal densities; kappa = 2/5 spheres, 1/2 disks. granmc: "
                "replica mean +- CI (lambda_p = 3.2) of the last-half averages; Maxwellian: `granmc theory`; dev: "
                "granmc over Maxwellian minus 1, per cent. One species: the light species alone at the total "
                "density.\n\n")
        f.write("## Cooling state (Gaussian thermostat)\n\n" + header)
        for r in rows:
            m, th = r["mixture"], r["theory"]
            f.write(f"| {r['d']} | {r['beta']:g} | {cell(m['temperature_ratio'], th['temperature_ratio_hcs'])} | "
                    f"{cell(m['species'][0]['rotational_ratio'], th['theta_hcs'][0])} | "
                    f"{cell(m['species'][1]['rotational_ratio'], th['theta_hcs'][1])} | "
                    f"{cell(r['single']['species'][0]['rotational_ratio'], r['theory_one']['theta_hcs'])} |\n")
        f.write(f"\n## White noise on translation (at dt -> 0 from dt = {DT} and {DT / 2})\n\n" + header)
        for r in heated:
            m, th, one = r["mixture"], r["theory_mixture"], r["theory_single"]
            f.write(f"| {r['d']} | {r['beta']:g} | {cell(m['ratio'], th['temperature_ratio_white_noise'])} | "
                    f"{cell(m['theta_0'], th['theta_white_noise'][0])} | "
                    f"{cell(m['theta_1'], th['theta_white_noise'][1])} | "
                    f"{cell(r['single']['theta_0'], one['theta_white_noise'])} |\n")


if __name__ == "__main__":
    main()
