"""drivers/results.py opens a result file of the format it knows and refuses any other major version
(docs/output-format.md). Run by ctest (test_results_reader) with GRANMC_EXECUTABLE set."""
import os
import shutil
import subprocess
import tempfile
import unittest

import h5py

from results import FORMAT_MAJOR, FormatError, open_results

SCENE = """[run]
t_end = 0.2
dt = 0.01
samples = 2
replicas = 2
[[species]]
name = "gas"
particles = 200
[collision]
restitution = 0.9
"""


class ResultsReader(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.mkdtemp(prefix="granmc_reader_")
        scene = os.path.join(cls.dir, "scene.toml")
        with open(scene, "w") as f:
            f.write(SCENE)
        cls.h5 = os.path.join(cls.dir, "run.h5")
        subprocess.run([os.environ["GRANMC_EXECUTABLE"], "run", scene, "--out", cls.h5, "--quiet"], check=True)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.dir)

    def copy_with(self, version):
        """A copy of the run's file with its format_version set to `version` (None: removed, as in format 1)."""
        path = os.path.join(self.dir, f"copy-{version}.h5")
        shutil.copy(self.h5, path)
        with h5py.File(path, "r+") as f:
            del f.attrs["format_version"]
            if version is not None:
                f.attrs["format_version"] = version
        return path

    def test_reads_its_own_format(self):
        with open_results(self.h5) as f:
            self.assertEqual(f.attrs["format_version"].split(".")[0], f"{FORMAT_MAJOR}")
            self.assertEqual(f["temperature/mean"].shape, (3,))

    def test_accepts_a_newer_minor_version(self):
        with open_results(self.copy_with(f"{FORMAT_MAJOR}.7")) as f:
            self.assertIn("temperature", f)

    def test_refuses_another_major_version(self):
        for version in (f"{FORMAT_MAJOR + 1}.0", None):
            with self.assertRaises(FormatError) as e:
                open_results(self.copy_with(version))
            self.assertIn("output format", str(e.exception))


if __name__ == "__main__":
    unittest.main()
