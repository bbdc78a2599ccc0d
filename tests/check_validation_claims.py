#!/usr/bin/env python3
"""Every agreement claim of the validation pages (docs/methods/validation.md and docs/methods/validation/),
checked against the table it describes.

Usage: /usr/bin/python3 tests/check_validation_claims.py [--doc PAGE.md ...]
           [--claims tests/validation_claims.toml]

The claims file lists each claim as it is written (its `quote`, found in its `section`) with the table it
rests on and the statements it makes, as expressions over that table (see the file's header). The script
fails when
- a quote is no longer in its section (the text changed: update the claim with it),
- a statement does not hold for the table (the claim is false as written), or
- a sentence of the page says "within CI", "within 1 %", "agrees", "consistent with" ... outside every
  registered claim (an unchecked claim). A claim that a test asserts is registered as `[[asserted]]` with
  the test that asserts it, a figure that a target prints but no table of the page holds as `[[reported]]`;
  table headers and the tables' "paper" columns (which quote the papers) are not scanned.
`make test` runs it (ctest: check_validation_claims).
"""
import argparse
import glob
import math
import re
import sys
import tomllib
from fractions import Fraction

import numpy as np

# The phrases that make a sentence an agreement claim.
CLAIM_PHRASES = re.compile(
    r"within (?:its |their |the )?CIs?\b|within \d[\d.]* ?(?:%|CI)|within \d[\d.]* of|\bagree(?:s|d|ment)?\b"
    r"|consistent with|all \d+ within|\d+ of \d+ points", re.IGNORECASE)
NUMBER = re.compile(r"^\s*([+-]?\d+(?:\.\d*)?(?:e[+-]?\d+)?)(?!\s*/)", re.IGNORECASE)
FRACTION = re.compile(r"^\s*(\d+)/(\d+)\s*$")


def normalize(text):
    return re.sub(r"\s+", " ", text).strip()


def cell_value(text):
    """A table cell as a number (leading number or a fraction such as 1/4), else its text."""
    m = FRACTION.match(text)
    if m:
        return float(Fraction(int(m.group(1)), int(m.group(2))))
    m = NUMBER.match(text)
    return float(m.group(1)) if m else text.strip()


def variable_name(header):
    return re.sub(r"[^0-9a-z]+", "_", header.strip().lower()).strip("_")


class Table:
    def __init__(self, lines):
        split = [[c.strip() for c in re.split(r"(?<!\\)\|", ln.strip().strip("|"))] for ln in lines]
        self.headers = split[0]
        self.rows = [r for r in split[2:]]
        for r in self.rows:
            if len(r) != len(self.headers):
                raise ValueError(f"table row has {len(r)} cells, header {len(self.headers)}: {r}")

    def column(self, name):
        hits = [i for i, h in enumerate(self.headers) if h == name]
        if len(hits) != 1:
            raise KeyError(f"column {name!r}: {len(hits)} matches in {self.headers}")
        return hits[0]


class Section:
    def __init__(self, title):
        self.title = title
        self.lines = []
        self.tables = []

    def finish(self):
        block = []
        for ln in self.lines + [""]:
            if ln.lstrip().startswith("|"):
                block.append(ln)
            elif block:
                self.tables.append(Table(block))
                block = []
        self.text = normalize(" ".join(self.lines))


def read_sections(path):
    sections, current = [], Section("")
    with open(path) as f:
        for ln in f.read().splitlines():
            if ln.startswith("#"):
                current.finish()
                sections.append(current)
                current = Section(ln.lstrip("#").strip())
            else:
                current.lines.append(ln)
    current.finish()
    sections.append(current)
    return sections


def find_section(sections, key):
    hits = [s for s in sections if key in s.title]
    if len(hits) != 1:
        raise KeyError(f"section {key!r}: {len(hits)} headings contain it")
    return hits[0]


def approx(x, stated):
    """x printed with the digits of `stated` (a string such as "1.43") reads `stated`."""
    decimals = len(stated.split(".")[1]) if "." in stated else 0
    return abs(float(x) - float(stated)) <= 0.5 * 10.0 ** -decimals + 1e-12


def claim_rows(table, claim):
    """Per selected row: value, CI, reference and the row's variables (one entry per value column)."""
    values = claim["value"] if isinstance(claim["value"], list) else [claim["value"]]
    group_values = claim.get("group_values", [None] * len(values))
    out = []
    for label, group in zip(values, group_values):
        iv = table.column(label)
        ic = iv + claim["ci"] if isinstance(claim.get("ci"), int) else table.column(claim.get("ci", "CI"))
        ref = claim["reference"]
        ir = iv + ref if isinstance(ref, int) else (table.column(ref) if isinstance(ref, str) else None)
        for env in selected(table, claim, group):
            r = env["__cells__"]
            v, ci = cell_value(r[iv]), cell_value(r[ic])
            rf = float(ref) if ir is None else cell_value(r[ir])
            if all(isinstance(x, float) for x in (v, ci, rf)):
                out.append((v, ci, rf, env))
    return out


def selected(table, claim, group=None):
    """The rows of a table that the claim's `where` selects, as {variable: cell value}."""
    rows = []
    for r in table.rows:
        env = {variable_name(h): cell_value(c) for h, c in zip(table.headers, r)}
        if group is not None:
            env[claim["group_var"]] = group
        if "where" in claim and not eval(claim["where"], {"math": math}, dict(env)):
            continue
        env["__cells__"] = r
        rows.append(env)
    return rows


def check_claim(sections, claim):
    section = find_section(sections, claim["section"])
    quote = normalize(claim["quote"])
    if quote not in section.text:
        return [f"quote not found in section {section.title!r}: {quote!r}"]
    if "expect" not in claim:
        return []
    if "inline" in claim:
        missing = [x for row in claim["inline"] for x in row if f"{x}" not in quote]
        if missing:
            return [f"{quote!r}: inline numbers {missing} are not in the quote"]
        rows = [(r[0], r[1] if len(r) == 3 else math.hypot(r[1], r[3]), r[2], {}) for r in claim["inline"]]
    elif "value" in claim:
        rows = claim_rows(section.tables[claim.get("table", 0)], claim)
    else:
        rows = [(math.nan, math.nan, math.nan, env) for env in selected(section.tables[claim.get("table", 0)], claim)]
    v = np.array([r[0] for r in rows])
    ci = np.array([r[1] for r in rows])
    ref = np.array([r[2] for r in rows])
    with np.errstate(divide="ignore", invalid="ignore"):
        env = {"v": v, "ci": ci, "ref": ref, "d": v - ref, "rel": v / ref - 1.0, "z": np.abs(v - ref) / ci,
               "n": len(rows), "np": np, "approx": approx,
               "col": lambda name: np.array([r[3][name] for r in rows], dtype=object)}
    failures = []
    for expr in claim["expect"]:
        try:
            ok = bool(eval(expr, {}, env))
        except Exception as e:  # a malformed statement is a failure too
            ok, expr = False, f"{expr} ({type(e).__name__}: {e})"
        if not ok:
            failures.append(f"{claim['section']!r}: {quote!r}\n    does not hold: {expr}\n    rows: n = {len(rows)}, "
                            f"z = {np.round(env['z'], 2).tolist()}, rel % = {np.round(100 * env['rel'], 2).tolist()}")
    return failures


def unchecked_phrases(sections, registered):
    """Claim phrases of the page outside every registered quote (tables' "paper" columns are not scanned)."""
    found = []
    for s in sections:
        spans = []
        for q in registered.get(s.title, []):
            start = s.text.find(q)
            while start >= 0:
                spans.append((start, start + len(q)))
                start = s.text.find(q, start + 1)
        masked = s.text
        for t in s.tables:
            header = normalize("| " + " | ".join(t.headers) + " |")
            masked = masked.replace(header, " " * len(header))
            quoted = [i for i, h in enumerate(t.headers) if h.lower().startswith("paper")]
            for r in t.rows:
                for i in quoted:
                    if r[i]:
                        masked = masked.replace(f"| {r[i]} |", "| " + " " * len(r[i]) + " |")
        for m in CLAIM_PHRASES.finditer(masked):
            if not any(a <= m.start() and m.end() <= b for a, b in spans):
                found.append(f"{s.title!r}: ...{s.text[max(0, m.start() - 60):m.end() + 40]}...")
    return found


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--doc", nargs="+", default=["docs/methods/validation.md"] +
                   sorted(glob.glob("docs/methods/validation/*.md")), help="the pages (default: the validation pages)")
    p.add_argument("--claims", default="tests/validation_claims.toml")
    args = p.parse_args()
    sections = [s for doc in args.doc for s in read_sections(doc)]
    with open(args.claims, "rb") as f:
        spec = tomllib.load(f)
    failures, registered = [], {}
    for kind in ("claim", "asserted", "reported"):
        for c in spec.get(kind, []):
            try:
                title = find_section(sections, c["section"]).title
            except KeyError as e:
                failures.append(str(e))
                continue
            registered.setdefault(title, []).append(normalize(c["quote"]))
            if kind == "asserted" and not re.search(r"\b" + re.escape(c["test"]) + r"\b",
                                                    open(c["test_file"]).read()):
                failures.append(f"{c['quote']!r}: {c['test']} not in {c['test_file']}")
            try:
                failures += check_claim(sections, c)
            except (KeyError, IndexError, ValueError) as e:
                failures.append(f"{c['section']!r}: {c['quote'][:60]!r}...: {type(e).__name__}: {e}")
    failures += [f"unchecked claim in {x}" for x in unchecked_phrases(sections, registered)]
    n = sum(len(spec.get(k, [])) for k in ("claim", "asserted", "reported"))
    if failures:
        print("\n".join(failures))
        print(f"check_validation_claims: {len(failures)} failure(s) over {n} registered claims")
        return 1
    print(f"check_validation_claims: {len(spec.get('claim', []))} claims hold for their tables, "
          f"{len(spec.get('asserted', []))} are asserted by tests, {len(spec.get('reported', []))} are figures "
          f"that a target reports; no other claim in the {len(args.doc)} pages")
    return 0


if __name__ == "__main__":
    sys.exit(main())
