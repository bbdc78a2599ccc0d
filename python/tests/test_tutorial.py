"""docs/user-guide/tutorial.md, executed: its ```sh blocks with bash and its ```python blocks with /usr/bin/python3, in order,
in a directory laid out as the checkout (build/bin/granmc, drivers/, python/, results/), each of which must
succeed. Run by ctest (test_python) with GRANMC_EXECUTABLE set."""
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TUTORIAL = os.path.join(ROOT, "docs", "user-guide", "tutorial.md")


def blocks(text):
    """The fenced blocks of a Markdown text whose language is sh or python, as (language, code), in order."""
    return [(m.group(1), m.group(2)) for m in re.finditer(r"^```(sh|python)\n(.*?)^```$", text, re.M | re.S)]


def test_the_page_has_the_steps_it_promises():
    with open(TUTORIAL) as f:
        found = blocks(f.read())
    assert [lang for lang, _ in found].count("python") >= 2
    assert any("granmc run" in code for lang, code in found if lang == "sh")
    assert any("granmc theory" in code for lang, code in found if lang == "sh")


def test_every_block_runs_in_order(tmp_path):
    os.makedirs(tmp_path / "build" / "bin")
    os.symlink(os.environ["GRANMC_EXECUTABLE"], tmp_path / "build" / "bin" / "granmc")
    for name in ("drivers", "python"):
        os.symlink(os.path.join(ROOT, name), tmp_path / name)
    os.makedirs(tmp_path / "results")
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}  # the page sets the path itself
    with open(TUTORIAL) as f:
        found = blocks(f.read())
    for k, (lang, code) in enumerate(found):
        cmd = ["bash", "-euo", "pipefail", "-c", code] if lang == "sh" else [sys.executable, "-c", code]
        run = subprocess.run(cmd, cwd=tmp_path, env=env, capture_output=True, text=True)
        assert run.returncode == 0, f"block {k + 1} ({lang}) failed:\n{code}\n{run.stdout}\n{run.stderr}"
    assert (tmp_path / "results" / "a2.png").stat().st_size > 10000
    assert "| 0.6 |" in run.stdout  # the last block's table, with the changed scene's row
