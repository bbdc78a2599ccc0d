"""granmc's Python side: result files, replica statistics, scenes run through the `granmc` command.

    from granmc import mean_ci, open_results
    with open_results("results/default.h5") as f:
        T = f["temperature/mean"][()]

The modules: `results` (opening an HDF5 result file after checking its format version), `replicas` (the mean and
confidence interval over replicas, with the convention of the C++ code), `scenes` (a scene dict as TOML text,
running it through `granmc run` unless its result is cached, and `granmc theory` for it). The scripts in drivers/ import the package through
the link drivers/granmc; elsewhere put python/ on PYTHONPATH.
"""
from granmc.replicas import LAMBDA_P, mean_ci
from granmc.results import FORMAT_MAJOR, FormatError, open_results
from granmc.scenes import run_point, theory, theory_of_text, toml_text

__all__ = ["FORMAT_MAJOR", "FormatError", "LAMBDA_P", "mean_ci", "open_results", "run_point", "theory", "theory_of_text",
           "toml_text"]
