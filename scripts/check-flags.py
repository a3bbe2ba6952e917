#!/usr/bin/env python3
"""Checks that every option flag is spelled in one string literal of src/: its option row.

Errors, help texts and JSON take a flag from its row (`table.flagOf`, `row.flag`, or a help
placeholder `{module.key}`), so a flag written in two literals is a copy that can drift.
Prints each such flag with the places it is written and exits 1; exits 0 when there is none.
"""
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent / "src"
LITERAL = re.compile(r'"((?:[^"\\\n]|\\.)*)"')
FLAG = re.compile(r"(?<![\w-])--[a-z][a-z0-9]*(?:-[a-z0-9]+)*")


def literals(text):
    """String literals of C++ source, outside comments."""
    text = re.sub(r"//[^\n]*", "", re.sub(r"/\*.*?\*/", "", text, flags=re.S))
    for line_no, line in enumerate(text.splitlines(), 1):
        for m in LITERAL.finditer(line):
            yield line_no, m.group(1)


def main():
    places = {}
    for path in sorted(ROOT.rglob("*")):
        if path.suffix not in (".cpp", ".h", ".hpp", ".cc"):
            continue
        rel = path.relative_to(ROOT.parent)
        for line_no, lit in literals(path.read_text(encoding="utf-8")):
            for flag in set(FLAG.findall(lit)):
                places.setdefault(flag, []).append(f"{rel}:{line_no}")
    repeated = {f: p for f, p in places.items() if len(p) > 1}
    for flag in sorted(repeated):
        print(f"{flag}: {len(repeated[flag])} literals: {' '.join(repeated[flag])}")
    if repeated:
        print(f"check-flags: {len(repeated)} flags are written in more than one string literal of src/")
        return 1
    print(f"check-flags: {len(places)} flags, each written once")
    return 0


if __name__ == "__main__":
    sys.exit(main())
