#!/usr/bin/env python3
"""Compares two behaviour snapshots (scripts/behaviour_snapshot.sh).

Every file must be byte-identical, except in the audits' folders (audit_*): the audit's
refinement is not yet reproducible from run to run (issue 12: the same binary run twice differs
in the last digits, and sometimes in the iterations a refinement phase takes). There:
  - every text file must be identical once each number in it is masked (same structure, same
    verdicts, same reasons, same messages),
  - and every number of report.json and sensors.geojson must agree within the stated tolerance:
    ABS_TOL absolute (metres, dB, χ²) or REL_TOL relative, whichever is larger, except the
    solver's own messages (their costs and iteration counts are the run-to-run noise itself).
Prints each difference and exits 1 when any is found.
"""
import json
import os
import re
import sys

ABS_TOL = 0.05   # metres / dB / χ² units: far below a bin (≥ 10 m) and the reported precision
REL_TOL = 1e-4
NUMBER = re.compile(r"-?\d+(\.\d+)?([eE][-+]?\d+)?")


def files_of(root):
    out = set()
    for d, _, fs in os.walk(root):
        for f in fs:
            out.add(os.path.relpath(os.path.join(d, f), root))
    return out


def close(x, y):
    return abs(x - y) <= max(ABS_TOL, REL_TOL * max(abs(x), abs(y)))


def compare_json(a, b, where, problems):
    if isinstance(a, dict) and isinstance(b, dict):
        if a.keys() != b.keys():
            problems.append(f"{where}: keys {sorted(a.keys() ^ b.keys())} differ")
            return
        for k in a:
            compare_json(a[k], b[k], f"{where}.{k}", problems)
    elif isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            problems.append(f"{where}: {len(a)} vs {len(b)} items")
            return
        for i, (x, y) in enumerate(zip(a, b)):
            compare_json(x, y, f"{where}[{i}]", problems)
    elif isinstance(a, (int, float)) and isinstance(b, (int, float)) and not isinstance(a, bool):
        if not close(float(a), float(b)):
            problems.append(f"{where}: {a} vs {b}")
    elif isinstance(a, str) and isinstance(b, str):
        if NUMBER.sub("#", a) != NUMBER.sub("#", b):
            problems.append(f"{where}: {a!r} vs {b!r}")
    elif a != b:
        problems.append(f"{where}: {a!r} vs {b!r}")


def main():
    root_a, root_b = sys.argv[1], sys.argv[2]
    fa, fb = files_of(root_a), files_of(root_b)
    problems = [f"only in {root_a}: {f}" for f in sorted(fa - fb)]
    problems += [f"only in {root_b}: {f}" for f in sorted(fb - fa)]
    tolerant = 0
    for f in sorted(fa & fb):
        pa, pb = os.path.join(root_a, f), os.path.join(root_b, f)
        da, db = open(pa, "rb").read(), open(pb, "rb").read()
        if da == db:
            continue
        if not f.startswith("audit_"):
            problems.append(f"{f}: differs")
            continue
        ta, tb = da.decode("utf-8"), db.decode("utf-8")
        if NUMBER.sub("#", ta) != NUMBER.sub("#", tb):
            problems.append(f"{f}: differs beyond its numbers")
            continue
        if f.endswith(("report.json", "sensors.geojson")):
            before = len(problems)
            compare_json(json.loads(ta), json.loads(tb), f, problems)
            if len(problems) > before:
                continue
        tolerant += 1
    for p in problems[:60]:
        print(p)
    n = len(fa | fb)
    if problems:
        print(f"behaviour: {len(problems)} differences in {n} files")
        return 1
    print(f"behaviour: {n} files the same ({tolerant} audit outputs within ±{ABS_TOL} or {REL_TOL:g} relative)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
