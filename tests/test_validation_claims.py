"""The validation pages (docs/methods/validation.md and docs/methods/validation/) hold every claim they make
(tests/check_validation_claims.py), and the checker fails where it should, shown on a small page of its own: a
table that no longer supports its claim, a claim whose text changed, an agreement claim nobody registered. Run
by ctest (test_validation_claims)."""
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

PAGE = """# Validation

## A figure (`make fig-x`, 1 min)

| alpha | granmc | CI | theory |
|---|---|---|---|
| 0.9 | 1.010 | 0.020 | 1.000 |
| 0.8 | 1.050 | 0.020 | 1.000 |

Reading: 1 of 2 points is within its CI, the other 2.5 CI above the theory.
"""

CLAIMS = """[[claim]]
section = "A figure"
quote = "1 of 2 points is within its CI, the other 2.5 CI above the theory."
value = "granmc"
reference = "theory"
expect = ["n == 2", "sum(z <= 1) == 1", "approx(max(z), '2.5')", "all(rel >= 0)"]
"""


def check(page, claims=CLAIMS):
    with tempfile.TemporaryDirectory() as d:
        doc, spec = os.path.join(d, "page.md"), os.path.join(d, "claims.toml")
        with open(doc, "w") as f:
            f.write(page)
        with open(spec, "w") as f:
            f.write(claims)
        return subprocess.run([sys.executable, os.path.join(HERE, "check_validation_claims.py"), "--doc", doc,
                               "--claims", spec], capture_output=True, text=True, cwd=ROOT)


class CheckValidationClaims(unittest.TestCase):
    def test_the_validation_pages_hold_their_claims(self):
        r = subprocess.run([sys.executable, os.path.join(HERE, "check_validation_claims.py")], capture_output=True,
                           text=True, cwd=ROOT)
        self.assertEqual(r.returncode, 0, r.stdout)

    def test_a_true_claim_passes(self):
        r = check(PAGE)
        self.assertEqual(r.returncode, 0, r.stdout)

    def test_a_table_that_no_longer_supports_its_claim_fails(self):
        r = check(PAGE.replace("| 0.9 | 1.010 |", "| 0.9 | 1.030 |"))  # now 1.5 CI off: no point within CI
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("does not hold: sum(z <= 1) == 1", r.stdout)

    def test_a_reworded_claim_fails(self):
        r = check(PAGE.replace("the other 2.5 CI above", "the other 2.4 CI above"))
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("quote not found", r.stdout)

    def test_an_unregistered_claim_fails(self):
        r = check(PAGE + "\nBoth points agree with theory.\n")
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("unchecked claim", r.stdout)

    def test_a_claim_asserted_by_a_missing_test_fails(self):
        page = PAGE + "\nAll 12 within CI (a test).\n"
        claims = CLAIMS + ('\n[[asserted]]\nsection = "A figure"\nquote = "All 12 within CI (a test)."\n'
                           'test = "test_that_does_not_exist"\ntest_file = "tests/CMakeLists.txt"\n')
        r = check(page, claims)
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("test_that_does_not_exist not in tests/CMakeLists.txt", r.stdout)


if __name__ == "__main__":
    unittest.main()
