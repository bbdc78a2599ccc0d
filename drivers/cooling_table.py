#!/usr/bin/env python3
"""Validation rows for a cooling-state run: the stationary a2 and Haff's law against theory.

Usage: /usr/bin/python3 drivers/cooling_table.py RESULT.h5 [--relaxed-after COLLISIONS]

a2: per replica, the time average of a2 over the samples after COLLISIONS collisions per particle
(default 15: a2 relaxes within a few), then the replica mean with its half-width lambda_p sqrt(Var/R)
(001 eq. 31, lambda_p = 3.2). Haff: the largest |T/T_Haff - 1| over the samples, next to the replica CI
and the cooling-rate model error of docs/methods/physics.md at that time. Prints Markdown rows.
"""
import argparse
import sys

from granmc import mean_ci


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("result")
    p.add_argument("--relaxed-after", type=float, default=15.0, help="collisions per particle before averaging a2")
    args = p.parse_args()
    try:
        from granmc import open_results
    except ImportError:
        sys.exit("cooling_table.py: needs h5py (Debian python3-h5py); run it with /usr/bin/python3")
    with open_results(args.result) as f:
        if "theory" not in f:
            sys.exit(f"cooling_table.py: {args.result} has no /theory group: not a monodisperse cooling state")
        th = f["theory"]
        times = f["times"][()]
        name = next(iter(f["species"]))
        a2_rep = f[f"species/{name}/a2/replicas"][()]           # R x S
        t_rep = f["temperature/replicas"][()]                    # R x S
        particles = int(f.attrs["particles"])
        coll = f["collisions/replicas"][()] * 2.0 / particles    # collisions per particle, R x S
        haff = th["haff_temperature"][()]
        zeta0 = float(th.attrs["cooling_rate0"])
        delta = float(th.attrs["cooling_rate_model_error"])
        wall = float(f.attrs["wall_seconds"])
        replicas = a2_rep.shape[0]

        relaxed = coll.mean(axis=0) >= args.relaxed_after
        a2_m, a2_ci = mean_ci(a2_rep[:, relaxed].mean(axis=1))
        a2_1 = float(th.attrs["a2"])
        a2_2 = float(th.attrs["a2_second_sonine"])
        a2_err = float(th.attrs["a2_model_error"])

        ratio = t_rep / haff
        worst, worst_k = 0.0, 0
        for k in range(1, len(times)):
            m, ci = mean_ci(ratio[:, k])
            x = 0.5 * zeta0 * times[k]
            allowed = ci + 2.0 * delta * x / (1.0 + x)
            if abs(m - 1.0) / allowed > worst:
                worst, worst_k = abs(m - 1.0) / allowed, k
        m, ci = mean_ci(ratio[:, worst_k])
        x = 0.5 * zeta0 * times[worst_k]

    print(f"{args.result}: {replicas} replicas x {particles} particles, {wall:.1f} s; "
          f"a2 averaged over {relaxed.sum()} samples after {args.relaxed_after:g} collisions per particle")
    print("| quantity | theory | granmc | CI (lambda_p = 3.2) | model error |")
    print("|---|---|---|---|---|")
    print(f"| a2 (HCS) | {a2_1:.5f} (1st Sonine), {a2_2:.5f} (2nd Sonine) | {a2_m:.5f} | {a2_ci:.5f} | {a2_err:.5f} |")
    print(f"| T/T_Haff - 1, worst sample (t = {times[worst_k]:.3g}) | 0 | {m - 1.0:+.5f} | {ci:.5f} | "
          f"{2.0 * delta * x / (1.0 + x):.5f} |")
    print(f"worst |T/T_Haff - 1| / (CI + model error) = {worst:.2f} (pass if <= 1)")


if __name__ == "__main__":
    main()
