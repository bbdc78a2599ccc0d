"""make_figure end to end on a small copy of 002 Fig. 3 (the 1D Gillespie intruder, T/T_B against alpha, against
the exact result): the plot, the table and the numbers come out with one point per x value, a second call reuses
the sweep's points, and only_theory runs none.

Run by ctest (test_python: pytest, with PYTHONPATH=python and GRANMC_EXECUTABLE set)."""
import json
import math
import os
import shutil

import pytest

from granmc import make_figure
from granmc.figures import FigureError

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
X_VALUES = [0.2, 0.8]
X_THEORY = 3


def edit(path, old, new):
    """Replaces `old` in the file; fails if it is not there (the copied figure has changed)."""
    text = path.read_text()
    assert old in text, f"{path.name} lacks {old!r}"
    path.write_text(text.replace(old, new, 1))


@pytest.fixture(scope="module")
def figure(tmp_path_factory):
    """002 Fig. 3 shrunk to two alphas, 4 replicas of 2000 time units and a theory grid of 3 points, made once:
    its figure file and its output folder."""
    where = tmp_path_factory.mktemp("granmc_figure")
    shutil.copytree(os.path.join(ROOT, "drivers", "scenes", "002_fig3"), where / "002_fig3")
    spec, base = where / "002_fig3" / "figure.toml", where / "002_fig3" / "base.toml"
    edit(spec, "x_values = [0.0, 0.2, 0.4, 0.6, 0.8, 1.0]", f"x_values = {X_VALUES}")
    edit(spec, "x_theory = [0.0, 1.0, 51]", f"x_theory = [0.0, 1.0, {X_THEORY}]")
    edit(base, "replicas = 10", "replicas = 4")
    edit(base, "t_end = 200000.0", "t_end = 2000.0")
    edit(base, "samples = 200000", "samples = 2000")
    out = make_figure(spec, os.environ["GRANMC_EXECUTABLE"], out=where / "out")
    return spec, out


def numbers(out):
    with open(os.path.join(out, "figure.json")) as f:
        return json.load(f)


def point_files(out):
    """Each point's HDF5 file and summary (the sweep's NAME.h5 and NAME.json) with its modification time."""
    paths = [os.path.join(out, pt["hdf5"]) for c in numbers(out)["curves"] for pt in c["points"]]
    paths += [os.path.splitext(p)[0] + ".json" for p in paths]
    return {p: os.stat(p).st_mtime_ns for p in paths}


def test_writes_the_plot_the_table_and_the_numbers(figure):
    _, out = figure
    for name in ("figure.png", "table.md", "figure.json"):
        assert os.path.getsize(os.path.join(out, name)) > 0, name
    table = open(os.path.join(out, "table.md")).read()
    assert table.startswith("# 002 Fig. 3: ")
    assert "| curve | x | quantity | granmc | CI | exact | seed | run (s) |" in table
    for x in X_VALUES:
        assert f"| M = m | {x:g} | intruder_temperature_ratio | " in table


def test_one_point_per_x_value_with_simulation_and_theory(figure):
    _, out = figure
    curves = numbers(out)["curves"]
    assert [c["label"] for c in curves] == ["M = m"]
    points = curves[0]["points"]
    assert [pt["x"] for pt in points] == X_VALUES
    for pt in points:
        [(suffix, mean, ci)] = pt["sim"]
        assert suffix == "" and math.isfinite(mean) and math.isfinite(ci) and ci > 0
        [exact] = pt["theory"]["exact"]
        assert math.isfinite(exact)
        assert abs(mean - exact) < 0.2 * exact  # T/T_B near the exact result even from a short run
        assert pt["seed"] == 2003
        assert os.path.exists(os.path.join(out, pt["hdf5"]))
    assert len(curves[0]["theory_x"]) == len(curves[0]["theory"]) == X_THEORY


def test_a_second_call_reuses_the_points(figure):
    spec, out = figure
    before, numbers_before = point_files(out), numbers(out)
    assert len(before) == 2 * len(X_VALUES)
    assert make_figure(spec, os.environ["GRANMC_EXECUTABLE"], out=out) == out
    assert point_files(out) == before  # no point ran again
    assert numbers(out) == numbers_before


def test_only_theory_runs_no_point(figure, tmp_path):
    spec, _ = figure
    out = make_figure(spec, os.environ["GRANMC_EXECUTABLE"], out=tmp_path / "theory", only_theory=True)
    assert not os.path.exists(os.path.join(out, "points"))
    [curve] = numbers(out)["curves"]
    assert curve["points"] == []
    assert len(curve["theory"]) == X_THEORY
    assert all(math.isfinite(line["exact"][0]) for line in curve["theory"])
    assert os.path.getsize(os.path.join(out, "figure.png")) > 0


def test_a_figure_file_with_an_unknown_quantity_is_refused_by_name(figure, tmp_path):
    spec, _ = figure
    bad = tmp_path / "002_fig3"
    shutil.copytree(spec.parent, bad)
    edit(bad / "figure.toml", 'y = "intruder_temperature_ratio"', 'y = "temperature_of_the_moon"')
    with pytest.raises(FigureError, match="unknown y 'temperature_of_the_moon'"):
        make_figure(bad / "figure.toml", os.environ["GRANMC_EXECUTABLE"], out=tmp_path / "out", only_theory=True)
