"""The repository's references to its files and to sections of its pages all resolve
(tests/check_doc_references.py), and the checker reports what it should, shown on a small tree of its own: a
missing file, a missing section, a section reference wrapped over two comment lines, and history (a date, a
commit, an issue number, a work session) in a reference page but not in the notebook or a code block. Run by ctest
(test_doc_references)."""
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
CHECKER = os.path.join(HERE, "check_doc_references.py")

PAGE = """# A page

## Units

Text.

**A bold lead** and its paragraph.

Acceptance on the mean: a paragraph that names itself.
"""


def check(files):
    """Runs the checker on a git tree holding `files` (name -> text); returns (status, output)."""
    with tempfile.TemporaryDirectory() as d:
        for name, text in files.items():
            os.makedirs(os.path.join(d, os.path.dirname(name)), exist_ok=True)
            with open(os.path.join(d, name), "w") as f:
                f.write(text)
        subprocess.run(["git", "init", "-q", d], check=True)
        subprocess.run(["git", "-C", d, "add", "-A"], check=True)
        r = subprocess.run([sys.executable, CHECKER, "--root", d], capture_output=True, text=True)
        return r.returncode, r.stdout


class CheckDocReferences(unittest.TestCase):
    def test_the_repository_has_no_broken_reference(self):
        r = subprocess.run([sys.executable, CHECKER], capture_output=True, text=True, cwd=ROOT)
        self.assertEqual(r.returncode, 0, r.stdout)

    def test_references_that_resolve_pass(self):
        status, out = check({"docs/page.md": PAGE, "kernel/a.hpp": "", "kernel/b.cpp":
                             '// docs/page.md, "Units"; docs/page.md, "A bold lead"; kernel/a.hpp; kernel/a;\n'
                             '// docs/page.md, "Acceptance on the mean"; drivers/scenes/fig<k>/x.toml\n'})
        self.assertEqual(status, 0, out)

    def test_a_missing_file_is_reported(self):
        status, out = check({"docs/page.md": PAGE, "kernel/b.cpp": "// see kernel/gone.hpp\n"})
        self.assertEqual(status, 1)
        self.assertIn("kernel/b.cpp: no such file: kernel/gone.hpp", out)

    def test_a_missing_section_is_reported_even_when_wrapped(self):
        status, out = check({"docs/page.md": PAGE, "kernel/b.cpp": '// as docs/page.md,\n// "Numerics" says\n'})
        self.assertEqual(status, 1)
        self.assertIn('kernel/b.cpp: no such section: docs/page.md, "Numerics"', out)

    def test_history_in_a_reference_page_is_reported(self):
        for text, found in [("Rerun on 2026-12-02.\n", "2026-12-02"), ("Since commit a884ac3 it draws.\n", "a884ac3"),
                            ("As issue 28 asks.\n", "issue 28"), ("Measured in session 12.\n", "session")]:
            status, out = check({"docs/page.md": PAGE + text})
            self.assertEqual(status, 1, text)
            self.assertIn(f"docs/page.md: history in a reference page: {found}", out)

    def test_dates_of_notebook_pages_and_data_in_code_blocks_pass(self):
        status, out = check({"docs/notebook/2026-01-01-x.md": "", "docs/page.md": PAGE +
                             "See docs/notebook/2026-01-01-x.md.\n\n```json\n{\"build\": \"0.1.0+0123456789ab\"}\n```\n"
                             "The class `mpi::Session` and 10^7 particles (10000000).\n"})
        self.assertEqual(status, 0, out)

    def test_the_notebook_is_not_checked(self):
        status, out = check({"docs/page.md": PAGE, "docs/notebook/2026-01-01-x.md": "kernel/gone.hpp\n"})
        self.assertEqual(status, 0, out)


if __name__ == "__main__":
    unittest.main()
