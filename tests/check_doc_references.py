#!/usr/bin/env python3
"""Every reference to a file of the repository, and to a section of a page, points at something that exists.

Usage: /usr/bin/python3 tests/check_doc_references.py [--root DIR]

It reads the tracked text files (pages, sources, scripts, scenes, build files; not the dated pages of
docs/notebook/, which record what was true when they were written, nor this checker and its test, whose
examples are broken on purpose) and reports
- a path under one of the top-level folders (docs/, drivers/, kernel/, io/, perf/, tests/, python/, scripts/,
  cmake/) that is neither a file nor a folder nor, without its extension, the stem of a file
  (`io/hdf5_output` for io/hdf5_output.cpp and .hpp); paths with a placeholder (<k>, {species}, *, $) are
  skipped;
- a section named after a page, `docs/PAGE.md, "Section"`, that is not the start of, or contained in, a
  heading, a bold paragraph lead (**Section** ...) or the first words of a paragraph of that page;
- history where current facts belong: a date (other than in the name of a notebook page) or an issue number
  anywhere, and in a Markdown page also a commit hash or a work session outside its code blocks. Dated,
  append-only history belongs in docs/notebook/.
A comment that wraps a reference over two lines is read as one line. Exit status 1 if anything is reported.
"""
import argparse
import glob
import os
import re
import subprocess
import sys

FOLDERS = ("docs", "drivers", "kernel", "io", "perf", "tests", "python", "scripts", "cmake")
PATH = re.compile(r"(?<![\w/.-])((?:%s)/[A-Za-z0-9_./<>{}*$-]*[A-Za-z0-9_/>}])" % "|".join(FOLDERS))
SECTION = re.compile(r"(docs/[A-Za-z0-9_./-]+\.md),?\s+\"([^\"]+)\"")
SUFFIXES = (".md", ".cpp", ".hpp", ".py", ".toml", ".txt", ".sh", ".cmake", "Makefile")
PLACEHOLDER = set("<>{}*$")
EXAMPLES = {"tests/check_doc_references.py", "tests/test_doc_references.py"}  # hold broken references on purpose
DATE = re.compile(r"(?<!notebook/)\b20\d\d-[01]\d-[0-3]\d\b")
ISSUE = re.compile(r"\b[Ii]ssues? #?\d+")
COMMIT = re.compile(r"\b(?=[0-9a-f]*[a-f])(?=[0-9a-f]*\d)[0-9a-f]{7,40}\b")
SESSION = re.compile(r"(?<!::)\b[Ss]essions?\b(?! *[(&:])")  # not the C++ class mpi::Session
FENCE = re.compile(r"^```.*?^```", re.M | re.S)
WRAP = re.compile(r"\s*\n\s*(?://+|#+|\*(?!\*))?\s*")  # a line break and the next line's comment marker


def checked_files(root):
    """The tracked text files whose references are checked."""
    out = subprocess.run(["git", "ls-files"], cwd=root, capture_output=True, text=True, check=True).stdout.split()
    return [f for f in out if f.endswith(SUFFIXES) and not f.startswith(("docs/notebook/", "perf/baselines/"))
            and f not in EXAMPLES and os.path.isfile(os.path.join(root, f))]  # a deletion not yet committed


def anchors(text):
    """What a section reference may name in a page: headings, bold paragraph leads, paragraphs' first words."""
    found = []
    paragraph_start = True
    for line in text.splitlines():
        stripped = line.strip()
        if stripped.startswith("#"):
            found.append(stripped.lstrip("#").strip())
        else:
            bold = re.match(r"(?:[-*]\s+)?\*\*(.+?)\*\*", stripped)
            if bold:
                found.append(bold.group(1))
            elif paragraph_start and stripped:
                found.append(stripped)
        paragraph_start = not stripped
    return found


def exists(root, path):
    full = os.path.join(root, path)
    return os.path.exists(full) or bool(glob.glob(glob.escape(full) + ".*"))


def broken_references(root, files):
    """(file, what, reference) for every reference in `files` (relative to root) that points at nothing."""
    broken, pages = [], {}
    for name in files:
        with open(os.path.join(root, name), errors="replace") as f:
            text = f.read()
        for m in PATH.finditer(text):
            path = m.group(1)
            if not PLACEHOLDER & set(path) and not exists(root, path):
                broken.append((name, "no such file", path))
        for m in SECTION.finditer(WRAP.sub(" ", text)):
            page, section = m.group(1), m.group(2)
            if not os.path.isfile(os.path.join(root, page)):
                continue  # reported above as a missing file
            if page not in pages:
                with open(os.path.join(root, page)) as f:
                    pages[page] = anchors(f.read())
            if not any(a.startswith(section) or section in a for a in pages[page]):
                broken.append((name, "no such section", f'{page}, "{section}"'))
        history = [DATE, ISSUE] + ([COMMIT, SESSION] if name.endswith(".md") else [])
        prose = FENCE.sub("", text) if name.endswith(".md") else text
        for pattern in history:
            for m in pattern.finditer(prose):
                broken.append((name, "history in a reference page", m.group(0)))
    return broken


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--root", default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    args = p.parse_args()
    files = checked_files(args.root)
    broken = broken_references(args.root, files)
    for name, what, ref in broken:
        print(f"{name}: {what}: {ref}")
    print(f"check_doc_references: {len(files)} files, {len(broken)} broken references")
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main())
