"""The scripts in drivers/ over the package: each starts (its imports resolve through the link drivers/granmc,
from any working directory), and the default study's plot and table come out of a small run.

Run by ctest (test_python) with GRANMC_EXECUTABLE set."""
import glob
import os
import subprocess
import sys

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DRIVERS = sorted(glob.glob(os.path.join(ROOT, "drivers", "*.py")))
CLEAN_ENV = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}  # as a user runs them


def driver(name, *args, cwd):
    return subprocess.run([sys.executable, os.path.join(ROOT, "drivers", name), *args], cwd=cwd, env=CLEAN_ENV,
                          capture_output=True, text=True)


@pytest.mark.parametrize("path", DRIVERS, ids=os.path.basename)
def test_every_driver_starts(path, tmp_path):
    """--help after every import: argparse's usage (status 0), a script's docstring for wrong arguments (1 or 2),
    or nothing from a module of functions; never a traceback."""
    run = driver(os.path.basename(path), "--help", cwd=tmp_path)
    assert run.returncode in (0, 1, 2), run.stderr
    assert "Traceback" not in run.stderr, run.stderr


def test_the_default_study_plots_and_tabulates(tmp_path):
    scene = tmp_path / "scene.toml"
    scene.write_text("[run]\nt_end = 1.0\ndt = 0.01\nsamples = 20\nreplicas = 4\n"
                     "[[species]]\nparticles = 2000\n[collision]\nrestitution = 0.8\n")
    subprocess.run([os.environ["GRANMC_EXECUTABLE"], "run", str(scene), "--out", str(tmp_path / "run.h5"),
                    "--quiet"], check=True)
    plot = driver("plot_cooling.py", "run.h5", "run.png", cwd=tmp_path)
    assert plot.returncode == 0, plot.stderr
    assert (tmp_path / "run.png").stat().st_size > 10000
    table = driver("cooling_table.py", "run.h5", "--relaxed-after", "0.5", cwd=tmp_path)
    assert table.returncode == 0, table.stderr
    assert "| a2 (HCS) |" in table.stdout
