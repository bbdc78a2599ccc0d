#!/usr/bin/env python3
"""Reproduce a paper figure: run granmc over a parameter sweep, compare with theory, plot, tabulate.

Usage: /usr/bin/python3 drivers/figure.py FIGURE.toml [--granmc build/bin/granmc] [--out results/NAME]
                                          [--threads N] [--mpi R] [--only-theory]

The command line of granmc.figures.make_figure (python/granmc/figures.py), whose docstring documents the
figure file (drivers/scenes/<paper>_fig<k>/figure.toml), the swept parameters, the plotted quantities and
the outputs OUT/figure.png, OUT/table.md and OUT/figure.json.
"""
import argparse
import sys

from granmc.figures import FigureError, make_figure


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0],
                                epilog="The figure file's format: python/granmc/figures.py (pydoc granmc.figures).")
    p.add_argument("figure")
    p.add_argument("--granmc", default="build/bin/granmc")
    p.add_argument("--out", default=None, help="output folder (default results/<figure folder name>)")
    p.add_argument("--threads", type=int, default=0, help="OpenMP threads per process (default: all cores)")
    p.add_argument("--mpi", type=int, default=0, metavar="R",
                   help="run the sweeps under `mpirun -np R --oversubscribe`; needs the MPI build (`make mpi`, "
                        "then --granmc build-mpi/bin/granmc)")
    p.add_argument("--only-theory", action="store_true", help="plot theory lines only, run nothing")
    args = p.parse_args()
    try:
        make_figure(args.figure, args.granmc, out=args.out, threads=args.threads, mpi=args.mpi,
                    only_theory=args.only_theory)
    except (FigureError, OSError) as e:
        sys.exit(f"figure.py: {args.figure}: {e}")


if __name__ == "__main__":
    main()
