#!/usr/bin/env python3
"""Compares two behaviour snapshots (scripts/behaviour_snapshot.sh): every file must be
byte-identical.

Differences listed in EXPLAINED (a file pattern, the pattern every changed line must match, and
why) are printed as explained and do not fail the comparison: a restructuring may change a detail
on purpose, and then says so here. Prints every other difference and exits 1 when there is one.
"""
import difflib
import os
import re
import sys

# (file pattern, pattern every differing line must match, explanation)
EXPLAINED = [
    (r"^serve_audit_bad_options/body$", r'"message":"must be',
     "the service's audit options are judged by the job library's one validator, in the command "
     "line's words (\"must be a positive number (got '-1')\" where the service alone said \"must be > 0\")."),
    (r"(^|/)truth\.json$", r'^\s*"description": "transverse Mercator',
     "covmap-make-map projects with io's LocalProjection (one transverse Mercator in covmap); "
     "its description prints the centre with four decimals (7.4000°E) where the generator's own "
     "copy printed six significant digits (7.4°E). The projection itself is the same."),
]


def files_of(root):
    out = set()
    for d, _, fs in os.walk(root):
        for f in fs:
            out.add(os.path.relpath(os.path.join(d, f), root))
    return out


def explained(path, text_a, text_b):
    """The explanation when every line that differs is covered by one EXPLAINED entry, else None."""
    la, lb = text_a.splitlines(), text_b.splitlines()
    if len(la) != len(lb):
        return None
    changed = [(x, y) for x, y in zip(la, lb) if x != y]
    for file_pattern, line_pattern, why in EXPLAINED:
        if re.search(file_pattern, path) and all(re.search(line_pattern, x) and re.search(line_pattern, y)
                                                 for x, y in changed):
            return why
    return None


def main():
    root_a, root_b = sys.argv[1], sys.argv[2]
    fa, fb = files_of(root_a), files_of(root_b)
    problems = [f"only in {root_a}: {f}" for f in sorted(fa - fb)]
    problems += [f"only in {root_b}: {f}" for f in sorted(fb - fa)]
    notes = {}
    for f in sorted(fa & fb):
        da = open(os.path.join(root_a, f), "rb").read()
        db = open(os.path.join(root_b, f), "rb").read()
        if da == db:
            continue
        ta, tb = da.decode("utf-8", "replace"), db.decode("utf-8", "replace")
        why = explained(f, ta, tb)
        if why:
            notes.setdefault(why, []).append(f)
            continue
        diff = list(difflib.unified_diff(ta.splitlines(), tb.splitlines(), lineterm="", n=0))[2:8]
        problems.append(f"{f}: differs\n    " + "\n    ".join(line[:200] for line in diff))
    for why, files in notes.items():
        print(f"explained ({len(files)} files, e.g. {files[0]}): {why}")
    for p in problems[:40]:
        print(p)
    n = len(fa | fb)
    if problems:
        print(f"behaviour: {len(problems)} differences in {n} files")
        return 1
    explained_files = sum(len(v) for v in notes.values())
    print(f"behaviour: {n} files the same ({explained_files} with explained differences)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
