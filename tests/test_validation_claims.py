"""tests/check_validation_claims.py fails where it should: a table that no longer supports its claim, a
claim whose text changed, an agreement claim nobody registered. Run by ctest (test_validation_claims)."""
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
DOC = os.path.join(ROOT, "docs", "validation.md")


def check(text):
    with tempfile.NamedTemporaryFile("w", suffix=".md", delete=False) as f:
        f.write(text)
    try:
        return subprocess.run([sys.executable, os.path.join(HERE, "check_validation_claims.py"), "--doc", f.name,
                               "--claims", os.path.join(HERE, "validation_claims.toml")],
                              capture_output=True, text=True, cwd=ROOT)
    finally:
        os.unlink(f.name)


class CheckValidationClaims(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        with open(DOC) as f:
            cls.doc = f.read()

    def changed(self, old, new):
        self.assertEqual(self.doc.count(old), 1, old)
        return self.doc.replace(old, new)

    def test_the_page_passes(self):
        r = check(self.doc)
        self.assertEqual(r.returncode, 0, r.stdout)

    def test_a_table_that_no_longer_supports_its_claim_fails(self):
        # 000 Fig. 7, alpha = 0.7 at mu = 0.5: moved 2 CI off the theory, so "13 of 15 within CI" is false.
        r = check(self.changed("| 0.5 | 1.0951 | 0.0420 | 1.1039 | 1.2179 | 0.0411 | 1.2246 | 1.3282 |",
                               "| 0.5 | 1.0951 | 0.0420 | 1.1039 | 1.2179 | 0.0411 | 1.2246 | 1.2482 |"))
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("13 of 15 points are within their CI", r.stdout)

    def test_a_reworded_claim_fails(self):
        r = check(self.changed("13 of 15 points are within their CI", "14 of 15 points are within their CI"))
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("quote not found", r.stdout)

    def test_an_unregistered_claim_fails(self):
        r = check(self.changed("All consistent with 4.", "All consistent with 4. Every point agrees with theory."))
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("unchecked claim", r.stdout)


if __name__ == "__main__":
    unittest.main()
