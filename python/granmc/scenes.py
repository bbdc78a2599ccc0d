"""Scenes as TOML text, runs of `granmc run` cached by that text, and `granmc theory`.

A scene is a dict as tomllib reads it: tables of plain values, and an array of [[species]] tables. toml_text writes
it back; run_point runs it unless the summary of exactly that text is already there; run_sweep runs many scenes
made from one base scene file as one `granmc sweep`; theory returns what `granmc theory` prints for a scene.
"""
import json
import os
import shutil
import subprocess
import tempfile


def toml_value(v):
    """A plain value (bool, number, string, list, inline table) as TOML."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (int, float)):
        return repr(v)
    if isinstance(v, str):
        return json.dumps(v)
    if isinstance(v, list):
        return "[" + ", ".join(toml_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{ " + ", ".join(f"{k} = {toml_value(x)}" for k, x in v.items()) + " }"
    raise TypeError(f"cannot write {v!r} to TOML")


def toml_text(scene):
    """A scene dict (tables, an array of [[species]] tables, plain values) as TOML text."""
    lines = []
    for table, body in scene.items():
        if table == "species":
            for sp in body:
                lines.append("[[species]]")
                lines += [f"{k} = {toml_value(v)}" for k, v in sp.items()]
                lines.append("")
        else:
            lines.append(f"[{table}]")
            lines += [f"{k} = {toml_value(v)}" for k, v in body.items()]
            lines.append("")
    return "\n".join(lines)


def run_point(granmc, scene, path_stem, threads):
    """Runs granmc on the scene unless the summary of this exact scene text exists; returns the summary.

    Writes PATH_STEM.toml, .h5 and .json. The cache key is the scene text itself: a summary is reused only when
    PATH_STEM.toml holds exactly the text this scene would be written as.
    """
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


def theory(granmc, scene):
    """What `granmc theory` prints for a scene (a path to its TOML file, or a scene dict), as a dict."""
    if isinstance(scene, dict):
        return theory_of_text(granmc, toml_text(scene))
    out = subprocess.run([granmc, "theory", os.fspath(scene)], check=True, capture_output=True, text=True).stdout
    return json.loads(out)


def theory_of_text(granmc, text):
    """theory for a scene given as TOML text (for example the scene_text a result file stores), without the
    "scene" entry (which names the file)."""
    with tempfile.NamedTemporaryFile("w", suffix=".toml", delete=False) as f:
        f.write(text)
    try:
        out = theory(granmc, f.name)
    finally:
        os.unlink(f.name)
    out.pop("scene", None)  # the temporary file's name
    return out


def values_key(values):
    """The same text for a [[scenes]] table's values and for those its sweep's index.json records."""
    return json.dumps(sorted(values.items()))


def run_sweep(granmc, base_path, tables, sweep_dir, threads=None, mpi=None, writer="python/granmc"):
    """Runs `granmc sweep` in sweep_dir on the base scene file `base_path` with one [[scenes]] table per entry of
    `tables` (each a dict of dotted keys to values, docs/formats/scenes.md, "Sweep files"); `mpi`: that many ranks under
    mpirun. granmc skips the scenes a previous call finished. Returns, in the order of `tables`, each scene's
    summary (a dict) and the path of its HDF5 file; exits naming the scene if one did not finish."""
    os.makedirs(sweep_dir, exist_ok=True)
    base_name = os.path.basename(base_path)
    shutil.copyfile(base_path, os.path.join(sweep_dir, base_name))  # `base` is relative to the sweep file
    unique = {values_key(v): v for v in tables}  # equal tables run once
    lines = [f"# Written by {writer}: one [[scenes]] table per scene.", f"base = {json.dumps(base_name)}"]
    for v in unique.values():
        lines += ["", "[[scenes]]"] + [f"{json.dumps(k)} = {toml_value(x)}" for k, x in v.items()]
    sweep_path = os.path.join(sweep_dir, "sweep.toml")
    with open(sweep_path, "w") as f:
        f.write("\n".join(lines) + "\n")
    cmd = ["mpirun", "-np", str(mpi), "--oversubscribe"] if mpi else []
    cmd += [granmc, "sweep", sweep_path, "--out-dir", sweep_dir]
    if threads:
        cmd += ["--threads", str(threads)]
    print("  " + " ".join(cmd), flush=True)
    subprocess.run(cmd, check=True)
    with open(os.path.join(sweep_dir, "index.json")) as f:
        index = {values_key(s["values"]): s for s in json.load(f)["scenes"]}
    out = []
    for v in tables:
        s = index.get(values_key(v), {"name": json.dumps(v), "status": "missing from index.json"})
        if s["status"] != "done":
            raise SystemExit(f"{sweep_dir}: scene {s['name']} did not finish; rerun to resume")
        with open(os.path.join(sweep_dir, s["summary"])) as f:
            out.append((json.load(f), os.path.join(sweep_dir, s["hdf5"])))
    return out
