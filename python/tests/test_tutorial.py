"""docs/user-guide/tutorial.md and outputs.md, executed: their ```sh blocks with bash and their ```python blocks
with /usr/bin/python3, in order, in a directory laid out as the checkout (build/bin/granmc, drivers/, python/,
results/), each of which must succeed. Run by ctest (test_python) with GRANMC_EXECUTABLE set."""
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TUTORIAL = os.path.join(ROOT, "docs", "user-guide", "tutorial.md")
OUTPUTS = os.path.join(ROOT, "docs", "user-guide", "outputs.md")


def blocks(text):
    """The fenced blocks of a Markdown text whose language is sh or python, as (language, code), in order."""
    return [(m.group(1), m.group(2)) for m in re.finditer(r"^```(sh|python)\n(.*?)^```$", text, re.M | re.S)]


def test_the_page_has_the_steps_it_promises():
    with open(TUTORIAL) as f:
        found = blocks(f.read())
    assert [lang for lang, _ in found].count("python") >= 2
    assert any("granmc run" in code for lang, code in found if lang == "sh")
    assert any("granmc theory" in code for lang, code in found if lang == "sh")


def run_blocks(page, where):
    """Runs the page's blocks in order in `where`, laid out as the checkout; returns the last block's run."""
    os.makedirs(where / "build" / "bin")
    os.symlink(os.environ["GRANMC_EXECUTABLE"], where / "build" / "bin" / "granmc")
    for name in ("drivers", "python"):
        os.symlink(os.path.join(ROOT, name), where / name)
    os.makedirs(where / "results")
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}  # the page sets the path itself
    with open(page) as f:
        found = blocks(f.read())
    for k, (lang, code) in enumerate(found):
        cmd = ["bash", "-euo", "pipefail", "-c", code] if lang == "sh" else [sys.executable, "-c", code]
        run = subprocess.run(cmd, cwd=where, env=env, capture_output=True, text=True)
        assert run.returncode == 0, \
            f"{os.path.basename(page)} block {k + 1} ({lang}) failed:\n{code}\n{run.stdout}\n{run.stderr}"
    return run


def test_every_block_of_the_tutorial_runs_in_order(tmp_path):
    run = run_blocks(TUTORIAL, tmp_path)
    assert (tmp_path / "results" / "a2.png").stat().st_size > 10000
    assert "| 0.6 |" in run.stdout  # the last block's table, with the changed scene's row


def test_every_block_of_the_outputs_page_runs_in_order(tmp_path):
    with open(OUTPUTS) as f:
        assert [lang for lang, _ in blocks(f.read())] == ["sh", "python", "python"]
    run = run_blocks(OUTPUTS, tmp_path)
    assert "16 101 sample times; grains a2 =" in run.stdout  # the summary's block, on the default study
