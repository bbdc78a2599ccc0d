#!/usr/bin/python3
"""Plot a cooling run from its granmc HDF5 file.

    /usr/bin/python3 drivers/plot_cooling.py results/default.h5 results/default.png

(a) T(t)/T(0): the replica mean with its confidence band (lambda_p = 3.2) and Haff's law, with a strip
    below it showing T/T_Haff and its band (on a log axis the two curves overlap);
(b) a2(t) of each species with its confidence band and the first-Sonine HCS a2.
Both panels share the time axis: logarithmic when the positive sample times span more than two decades
(log-spaced samples), linear otherwise. Without a /theory group only the simulation is drawn.

Uses Debian's python3-h5py and python3-matplotlib (hence /usr/bin/python3).
"""
import importlib.util
import os
import sys

import numpy as np

from granmc.plotting import pyplot, save


def fail(message):
    print(f"plot_cooling: {message}", file=sys.stderr)
    sys.exit(1)


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def read(path):
    from granmc import FormatError, open_results

    try:
        f = open_results(path)
    except OSError as e:
        fail(f"cannot open '{path}' as HDF5: {e}")
    except FormatError as e:
        fail(str(e))
    with f:
        for name in ("times", "temperature/mean", "temperature/ci", "species"):
            if name not in f:
                fail(f"'{path}' has no /{name}; is it a granmc gas result file?")
        run = {
            "scene": text(f.attrs.get("scene", os.path.basename(path))),
            "replicas": int(f.attrs.get("replicas", 0)),
            "method": text(f.attrs.get("method", "simulation")).upper(),
            "particles": int(f.attrs["particles"]) if "particles" in f.attrs else None,
            "times": f["times"][()],
            "T": f["temperature/mean"][()],
            "T_ci": f["temperature/ci"][()],
            "species": [],
            "theory": None,
        }
        groups = sorted(f["species"].values(), key=lambda g: int(g.attrs.get("index", 0)))
        for g in groups:
            run["species"].append({
                "name": text(g.attrs.get("name", g.name.rsplit("/", 1)[-1])),
                "a2": g["a2/mean"][()],
                "a2_ci": g["a2/ci"][()],
            })
        if "theory" in f and "haff_temperature" in f["theory"]:
            th = f["theory"]
            a2 = th.attrs.get("a2")
            a2_2 = th.attrs.get("a2_second_sonine")
            run["theory"] = {"T": th["haff_temperature"][()], "a2": None if a2 is None else float(a2),
                             "a2_second": None if a2_2 is None else float(a2_2)}
    return run


def plot(run, out):
    plt = pyplot()

    t = run["times"]
    positive = t[t > 0]
    log_time = positive.size > 1 and positive.max() / positive.min() > 100.0
    shown = t > 0 if log_time else np.ones_like(t, dtype=bool)

    theory = run["theory"]
    t_ref = theory["T"][0] if theory is not None else run["T"][0]  # T(0): the scene's initial temperature

    # Panel (a) is the temperature with, when the theory applies, a ratio strip T/T_Haff below it: on a log
    # axis the simulation and Haff's law overlap, the strip shows their difference against the band.
    rows = 3 if theory is not None else 2
    heights = [3.0, 1.2, 3.0] if theory is not None else [3.0, 3.0]
    fig, axes = plt.subplots(rows, 1, figsize=(7.0, 8.5 if theory is not None else 7.5), sharex=True,
                             gridspec_kw={"height_ratios": heights}, constrained_layout=True)
    ax_t, ax_a = axes[0], axes[-1]

    y = run["T"] / t_ref
    dy = run["T_ci"] / t_ref
    lower = np.where(y - dy > 0, y - dy, np.nan)  # a band reaching zero cannot be drawn on a log axis
    ax_t.fill_between(t[shown], lower[shown], (y + dy)[shown], color="C0", alpha=0.3, linewidth=0,
                      label="confidence band ($\\lambda_p = 3.2$)")
    ax_t.plot(t[shown], y[shown], color="C0", label=f"{run['method']}, replica mean")
    if theory is not None:
        haff = theory["T"]
        ax_t.plot(t[shown], (haff / t_ref)[shown], color="k", linestyle="--", linewidth=1.0,
                  label="Haff's law (second-Sonine cooling rate)")
        ax_r = axes[1]
        ratio, dratio = run["T"] / haff, run["T_ci"] / haff
        ax_r.fill_between(t[shown], (ratio - dratio)[shown], (ratio + dratio)[shown], color="C0", alpha=0.3,
                          linewidth=0)
        ax_r.plot(t[shown], ratio[shown], color="C0", linewidth=1.0)
        ax_r.axhline(1.0, color="k", linestyle="--", linewidth=1.0)
        ax_r.set_ylabel("$T/T_\\mathrm{Haff}$")
    ax_t.set_yscale("log")
    ax_t.set_ylabel("$T(t)/T(0)$")
    ax_t.set_title("(a) temperature", loc="left", fontsize="medium")
    ax_t.legend(fontsize="small")

    for i, sp in enumerate(run["species"]):
        colour = f"C{i}"
        a2, da2 = sp["a2"], sp["a2_ci"]
        ax_a.fill_between(t[shown], (a2 - da2)[shown], (a2 + da2)[shown], color=colour, alpha=0.3, linewidth=0)
        ax_a.plot(t[shown], a2[shown], color=colour, label=f"{run['method']}, species {sp['name']}")
    if theory is not None and theory["a2"] is not None:
        ax_a.axhline(theory["a2"], color="k", linestyle="--", linewidth=1.0,
                     label=f"first Sonine $a_2 = {theory['a2']:.4g}$")
    if theory is not None and theory.get("a2_second") is not None:
        ax_a.axhline(theory["a2_second"], color="k", linestyle=":", linewidth=1.2,
                     label=f"second Sonine $a_2 = {theory['a2_second']:.4g}$")
    ax_a.axhline(0.0, color="0.6", linewidth=0.5)
    ax_a.set_ylabel("$a_2(t)$ (dimensionless)")
    ax_a.set_xlabel("time $t$ (scene time unit)")
    ax_a.set_title("(b) kurtosis cumulant", loc="left", fontsize="medium")
    ax_a.legend(fontsize="small")
    if log_time:
        ax_a.set_xscale("log")

    title = run["scene"]
    details = [f"{run['replicas']} replicas"]
    if run["particles"] is not None:
        details.append(f"{run['particles']} particles")
    fig.suptitle(f"{title}: " + ", ".join(details))

    directory = os.path.dirname(os.path.abspath(out))
    if not os.path.isdir(directory):
        fail(f"output directory '{directory}' does not exist")
    save(fig, out)


def main(argv):
    if len(argv) != 3 or argv[1] in ("-h", "--help"):
        print(__doc__.strip(), file=sys.stderr)
        return 2
    source, out = argv[1], argv[2]
    if not os.path.isfile(source):
        fail(f"no such file: '{source}' (run `granmc run SCENE.toml --out {source}` first)")
    for module in ("h5py", "matplotlib"):
        if importlib.util.find_spec(module) is None:
            fail(f"no module named '{module}'; run this script with /usr/bin/python3 (Debian python3-h5py, "
                 "python3-matplotlib)")
    plot(read(source), out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
