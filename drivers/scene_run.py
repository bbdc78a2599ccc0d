"""Run granmc on one scene (a dict, as tomllib reads it) unless its result is already there.

The single-scene drivers (tails.py, relaxation.py, accuracy_cost.py, intruder_cost.py) use this; the figure
targets run their points as sweeps instead (figure.py). The cache key is the scene text itself: a summary
is reused only when PATH_STEM.toml holds exactly the text this scene would be written as.
"""
import json
import os
import subprocess

from figure import toml_text


def run_point(granmc, scene, path_stem, threads):
    """Runs granmc on the scene unless the summary of this exact scene text exists; returns the summary."""
    text = toml_text(scene)
    scene_path, summary_path = path_stem + ".toml", path_stem + ".json"
    if os.path.exists(summary_path) and os.path.exists(scene_path):
        with open(scene_path) as f:
            if f.read() == text:
                with open(summary_path) as g:
                    return json.load(g)
    with open(scene_path, "w") as f:
        f.write(text)
    # Not --quiet: granmc's progress line (after 2 s, with the time left) is how a long tail run shows it moves.
    cmd = [granmc, "run", scene_path, "--out", path_stem + ".h5", "--summary", summary_path]
    if threads:
        cmd += ["--threads", str(threads)]
    print("  run", os.path.basename(scene_path), flush=True)
    subprocess.run(cmd, check=True)
    with open(summary_path) as g:
        return json.load(g)
