"""granmc's Python side: result files, replica statistics, scenes run through the `granmc` command, paper figures.

    from granmc import mean_ci, open_results
    with open_results("results/default.h5") as f:
        T = f["temperature/mean"][()]

The modules:
- `results`: an HDF5 result file opened after its format version is checked;
- `replicas`: the mean and confidence interval over replicas, with the convention of the C++ code;
- `scenes`: a scene dict as TOML text; runs through `granmc run` cached by that text, many scenes as one
  `granmc sweep`; what `granmc theory` prints for a scene;
- `plotting`: matplotlib in one style;
- `figures`: a paper figure from its figure.toml (make_figure: the points as sweeps, theory, plot, table);
- `zero_shear`: the Navier-Stokes viscosity as the limit a* -> 0 of runs at several shear rates.
The scripts in drivers/ import the package through the link drivers/granmc; elsewhere put python/ on PYTHONPATH
or install it: `python3 -m pip install ./python` (python/pyproject.toml).
"""
from granmc.figures import make_figure
from granmc.replicas import LAMBDA_P, mean_ci
from granmc.results import FORMAT_MAJOR, FormatError, open_results
from granmc.scenes import run_point, run_sweep, theory, theory_of_text, toml_text

__all__ = ["FORMAT_MAJOR", "FormatError", "LAMBDA_P", "make_figure", "mean_ci", "open_results", "run_point",
           "run_sweep", "theory", "theory_of_text", "toml_text"]
