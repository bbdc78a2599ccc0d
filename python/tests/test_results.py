"""The package against a file granmc writes: the format check of open_results (docs/formats/output-format.md), mean_ci
against the file's own intervals (the C++ convention), scenes written as TOML and run once, sweeps, and their
theory.

Run by ctest (test_python: pytest, with PYTHONPATH=python and GRANMC_EXECUTABLE set)."""
import os
import shutil
import subprocess
import tomllib

import h5py
import numpy as np
import pytest

from granmc import (FORMAT_MAJOR, LAMBDA_P, FormatError, mean_ci, open_results, run_point, run_sweep, theory,
                    theory_of_text, toml_text)

SCENE = {
    "run": {"t_end": 0.2, "dt": 0.01, "samples": 3, "replicas": 6, "seed": 11},
    "species": [{"name": "gas", "particles": 200}],
    "collision": {"restitution": 0.9},
}


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    """One small run through run_point: its directory, its path stem and its summary."""
    where = tmp_path_factory.mktemp("granmc_results")
    stem = str(where / "run")
    summary = run_point(os.environ["GRANMC_EXECUTABLE"], SCENE, stem, threads=1)
    return where, stem, summary


def copy_with(run, version):
    """A copy of the run's file with its format_version set to `version` (None: removed, as in format 1)."""
    where, stem, _ = run
    path = str(where / f"copy-{version}.h5")
    shutil.copy(stem + ".h5", path)
    with h5py.File(path, "r+") as f:
        del f.attrs["format_version"]
        if version is not None:
            f.attrs["format_version"] = version
    return path


def test_reads_its_own_format(run):
    with open_results(run[1] + ".h5") as f:
        assert f.attrs["format_version"].split(".")[0] == f"{FORMAT_MAJOR}"
        assert f["temperature/mean"].shape == (SCENE["run"]["samples"] + 1,)  # the start, then each sample


def test_accepts_a_newer_minor_version(run):
    with open_results(copy_with(run, f"{FORMAT_MAJOR}.7")) as f:
        assert "temperature" in f


@pytest.mark.parametrize("version", [f"{FORMAT_MAJOR + 1}.0", None])
def test_refuses_another_major_version(run, version):
    with pytest.raises(FormatError, match="output format"):
        open_results(copy_with(run, version))


def test_mean_ci_is_the_interval_of_the_file(run):
    """The replicas' mean and CI as the C++ code writes them (variance over N, lambda_p = 3.2): to rounding,
    and not the other convention (over N - 1), which differs by sqrt(6 / 5) - 1 = 10 % at 6 replicas."""
    with open_results(run[1] + ".h5") as f:
        replicas = f["temperature/replicas"][()]
        mean, ci = mean_ci(replicas)
        assert replicas.shape[0] == 6
        np.testing.assert_allclose(mean, f["temperature/mean"][()], rtol=1e-12)
        np.testing.assert_allclose(ci, f["temperature/ci"][()], rtol=1e-9)
        assert np.all(ci[1:] > 0)  # the check above compares intervals, not zeros
        other = LAMBDA_P * replicas.std(axis=0, ddof=1) / np.sqrt(replicas.shape[0])
        assert np.all(np.abs(other[1:] / f["temperature/ci"][1:] - 1) > 0.05)


def test_mean_ci_of_one_dimension_gives_floats():
    mean, ci = mean_ci([1.0, 2.0, 3.0, 4.0])
    assert isinstance(mean, float) and isinstance(ci, float)
    assert mean == 2.5
    assert ci == pytest.approx(LAMBDA_P * np.sqrt(1.25 / 4))
    with pytest.raises(ValueError, match="no replicas"):
        mean_ci([])


def test_scene_text_reads_back_as_the_scene():
    assert tomllib.loads(toml_text(SCENE)) == SCENE


def test_a_scene_already_run_is_not_run_again(run):
    """run_point returns the cached summary of the same scene text without calling granmc (here a path that
    does not exist), and runs again once the text changes."""
    _, stem, summary = run
    assert run_point("/nonexistent/granmc", SCENE, stem, threads=1) == summary
    changed = {**SCENE, "run": {**SCENE["run"], "seed": 12}}
    with pytest.raises((FileNotFoundError, subprocess.CalledProcessError)):
        run_point("/nonexistent/granmc", changed, stem, threads=1)


def test_theory_of_a_scene_dict_path_or_text_is_the_same(run):
    granmc, path = os.environ["GRANMC_EXECUTABLE"], run[1] + ".toml"
    from_path = theory(granmc, path)
    assert from_path.pop("scene") == path
    assert len(from_path) > 1  # granmc theory has something to say about a cooling gas
    assert theory(granmc, SCENE) == from_path
    with open(path) as f:
        assert theory_of_text(granmc, f.read()) == from_path


def test_a_sweep_runs_each_distinct_table_once_and_answers_in_order(tmp_path):
    base = tmp_path / "base.toml"
    base.write_text(toml_text(SCENE))
    tables = [{"collision.restitution": 0.5}, {"collision.restitution": 0.7}, {"collision.restitution": 0.5}]
    ran = run_sweep(os.environ["GRANMC_EXECUTABLE"], str(base), tables, str(tmp_path / "sweep"), threads=1)
    assert [summary["theory"]["alpha"] for summary, _ in ran] == [0.5, 0.7, 0.5]
    assert ran[0][1] == ran[2][1]  # the same scene, one run
    assert len({h5 for _, h5 in ran}) == 2
    with open_results(ran[1][1]) as f:
        assert "temperature" in f
