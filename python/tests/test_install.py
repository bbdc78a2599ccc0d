"""The package installs with pip from the checkout (python/pyproject.toml) and imports from outside it: into a
fresh virtual environment that sees the system's numpy and h5py, without the network (no dependencies fetched,
no isolated build)."""
import os
import shutil
import subprocess
import sys

PYTHON_DIR = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def test_pip_installs_the_package_from_the_checkout(tmp_path):
    source = tmp_path / "source"  # a copy: pip's build leaves files beside pyproject.toml
    shutil.copytree(PYTHON_DIR, source, ignore=shutil.ignore_patterns("tests", "__pycache__"))
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", str(venv)], check=True)
    python = str(venv / "bin" / "python")
    subprocess.run([python, "-m", "pip", "install", "--quiet", "--no-deps", "--no-build-isolation", str(source)],
                   check=True)
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    out = subprocess.run([python, "-c", "import granmc; print(granmc.__file__); print(granmc.mean_ci([1.0, 3.0])[0])"],
                         cwd=tmp_path, env=env, check=True, capture_output=True, text=True).stdout.split()
    assert out[0].startswith(str(venv)), out[0]
    assert float(out[1]) == 2.0
