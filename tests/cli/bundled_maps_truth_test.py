#!/usr/bin/env python3
"""covmap audit on the bundled maps (datasets/maps/*), judged against their truth.json.

Usage: bundled_maps_truth_test.py path/to/covmap path/to/datasets [verdicts|accounting]

With "verdicts" only the targets on verdicts are checked, with "accounting" only the accounting
(ctest registers the two apart, so that one can be followed while the other still fails); the
table is printed either way.

Each map is audited as a user would (its sensors.geojson, --alpha from the generator, --planar for a
planar map) and the verdicts in report.json are compared with what the generator really did
(truth.json, datasets/maps/README.md). The targets are those of docs/ACCURACY.md; none
is adjusted to what the audit achieves:

  precision  >= 0.95  of the sensors judged "inconsistent", the share that truly has a gross error
  recall     >= 0.97  of the gross errors the map can reveal (below), the share judged "inconsistent"
  verdict    every sensor that has a cell in the map (truth: bins > 0) gets a verdict: it is in the
             map and its verdict is neither null nor "not_in_map"
  undetermined <= 2 % of the sensors whose cell the map resolves (below)
  accounting the summary's counts by verdict add up to its sensors, match the sensors listed, and
             the stdout summary line says the same; every truth sensor is listed once; χ² is a
             number exactly for the sensors the χ² test judged (null for undetermined, not_in_map
             and unreported ones)

"Can reveal", defined from the truth alone (independent of the audit):
  - the cell is resolved: it has at least MIN_CELL_BINS = 100 bins, i.e. it is about 10 bins
    across, which is docs/ACCURACY.md's condition for its targets (bins <= 1/10 of the local sensor
    spacing) applied to this sensor's own cell; and
  - the error is large against what the raster and the ordinary report noise blur: a position
    offset of at least GROSS_MULTIPLE = 5 bin sizes, or a power offset of at least GROSS_MULTIPLE
    times 1 dB (the reported powers' own noise is 1 dB; the targets ask reconstructions to within
    0.5 bin and 0.5 dB RMS, so 5 is ten of those).
A sensor with a gross error the map cannot reveal is not required to be flagged; if it is flagged,
it still counts as a true positive for precision (it does have a gross error).

Prints a table of what the audit achieves on each map; exits 1 listing every target missed.
"""
import json
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

MAPS = ["bern", "ticino", "switzerland"]
MIN_CELL_BINS = 100
GROSS_MULTIPLE = 5.0
PRECISION_TARGET = 0.95
RECALL_TARGET = 0.97
UNDETERMINED_TARGET = 0.02


def can_reveal(sensor, bin_size_m):
    error = sensor["gross_error"]
    if error is None or sensor["bins"] < MIN_CELL_BINS:
        return False
    position = error.get("position_offset_distance_m") or 0.0
    power = abs(error.get("power_offset_db") or 0.0)
    return position >= GROSS_MULTIPLE * bin_size_m or power >= GROSS_MULTIPLE * 1.0


def audit(covmap, folder, out):
    truth = json.loads((folder / "truth.json").read_text())
    generator = truth["generator"]
    command = [covmap, "audit", str(folder / "map.geojson"), "--sensors", str(folder / "sensors.geojson"),
               "--alpha", repr(generator["alpha"]), "-o", str(out), "-q"]
    if generator["frame"] == "planar":
        command.append("--planar")
    start = time.monotonic()
    run = subprocess.run(command, capture_output=True, text=True)
    seconds = time.monotonic() - start
    if run.returncode != 0:
        raise RuntimeError(f"{' '.join(command)}: exit {run.returncode}: {run.stderr}")
    return truth, json.loads((out / "report.json").read_text()), run.stdout, seconds


def ratio(numerator, denominator):
    return numerator / denominator if denominator else float("nan")


def accounting_failures(name, truth, report, stdout):
    """The counts add up, in report.json and on stdout, and every truth sensor is listed once."""
    failures = []
    summary = report["summary"]
    by_verdict = {k: v for k, v in summary.items() if k not in ("sensors", "in_map", "reported")}
    listed = report["sensors"]
    if sum(by_verdict.values()) != summary["sensors"]:
        failures.append(f"{name}: summary verdict counts {by_verdict} add up to {sum(by_verdict.values())}, "
                        f"not to its {summary['sensors']} sensors")
    tally = {}
    for s in listed:
        key = s["verdict"] if s["verdict"] is not None else "unreported"
        tally[key] = tally.get(key, 0) + 1
    if {k: v for k, v in by_verdict.items() if v} != tally or summary["sensors"] != len(listed):
        failures.append(f"{name}: summary {by_verdict} does not match the {len(listed)} sensors listed {tally}")
    ids = [s["id"] for s in listed]
    truth_ids = sorted(s["id"] for s in truth["sensors"])
    if sorted(ids) != truth_ids:
        failures.append(f"{name}: sensors listed {len(ids)} (distinct {len(set(ids))}) are not the "
                        f"{len(truth_ids)} true sensors")
    # A χ² exists only where the χ² test of the boundary fit judged the sensor (verdict_basis
    # "boundary_fit"); elsewhere it was never computed: null. Every judged sensor names its basis.
    for s in listed:
        judged = s["verdict_basis"] == "boundary_fit"
        if judged != (s["chi2"] is not None):
            failures.append(f"{name}: sensor {s['id']} ({s['verdict']}, basis {s['verdict_basis']}) has chi2 {s['chi2']}")
        if s["verdict"] in ("consistent", "inconsistent") and s["verdict_basis"] is None:
            failures.append(f"{name}: sensor {s['id']} is {s['verdict']} on no basis")
    # stdout: "MAP: N sensors (...): n1 words, n2 words, ...; refined diagram ..."
    first = stdout.splitlines()[0] if stdout else ""
    match = re.match(r".*?: (\d+) sensors \((\d+) with a cell in the map, (\d+) reported without one; "
                     r"(\d+) reported\): (.*?); refined", first)
    if not match:
        failures.append(f"{name}: stdout summary line not understood: {first!r}")
        return failures
    total, in_map, only_reported, reported = (int(match.group(i)) for i in range(1, 5))
    counts = [int(part.split(" ", 1)[0]) for part in match.group(5).split(", ")]
    if (total, in_map, reported) != (summary["sensors"], summary["in_map"], summary["reported"]) or \
            in_map + only_reported != total:
        failures.append(f"{name}: stdout totals {total} = {in_map} + {only_reported}, {reported} reported, "
                        f"differ from report.json {summary}")
    if sum(counts) != total or counts != list(by_verdict.values()):
        failures.append(f"{name}: stdout verdict counts {counts} (sum {sum(counts)}) differ from "
                        f"report.json {list(by_verdict.values())} or do not add up to {total}")
    return failures


def judge(name, truth, report):
    """The table row and the targets missed for one map."""
    bin_size = truth["generator"]["bin_size_m"]
    verdict = {s["id"]: s for s in report["sensors"]}
    true_sensors = truth["sensors"]
    gross = {s["id"] for s in true_sensors if s["gross_error"] is not None}
    revealable = {s["id"] for s in true_sensors if can_reveal(s, bin_size)}
    flagged = {s["id"] for s in report["sensors"] if s["verdict"] == "inconsistent"}
    with_cell = [s for s in true_sensors if s["bins"] > 0]
    resolved = [s for s in with_cell if s["bins"] >= MIN_CELL_BINS]
    no_verdict = [s["id"] for s in with_cell
                  if s["id"] not in verdict or not verdict[s["id"]]["in_map"]
                  or verdict[s["id"]]["verdict"] in (None, "not_in_map")]
    undetermined = [s["id"] for s in resolved if verdict.get(s["id"], {}).get("verdict") == "undetermined"]
    undetermined_all = [s["id"] for s in with_cell if verdict.get(s["id"], {}).get("verdict") == "undetermined"]
    precision = ratio(len(flagged & gross), len(flagged))
    recall = ratio(len(flagged & revealable), len(revealable))
    row = dict(map=name, sensors=len(true_sensors), with_cell=len(with_cell), resolved=len(resolved),
               gross=len(gross), revealable=len(revealable), flagged=len(flagged), hits=len(flagged & gross),
               precision=precision, recall=recall, undetermined=len(undetermined),
               undetermined_all=len(undetermined_all))
    failures = []
    if flagged and precision < PRECISION_TARGET:
        failures.append(f"{name}: precision {precision:.3f} < {PRECISION_TARGET}: flagged without a gross error "
                        f"{sorted(flagged - gross)}")
    if revealable and recall < RECALL_TARGET:
        missed = sorted(revealable - flagged)
        failures.append(f"{name}: recall {recall:.3f} < {RECALL_TARGET}: revealable gross errors not flagged "
                        + ", ".join(f"{i} ({verdict[i]['verdict'] if i in verdict else 'absent'})" for i in missed))
    if no_verdict:
        failures.append(f"{name}: sensors with a cell but no verdict: {no_verdict}")
    share = ratio(len(undetermined), len(resolved))
    if resolved and share > UNDETERMINED_TARGET:
        failures.append(f"{name}: undetermined {len(undetermined)} of {len(resolved)} resolved cells "
                        f"({100 * share:.1f} % > {100 * UNDETERMINED_TARGET:.0f} %): {undetermined}")
    # The bundled maps were drawn by the multiplicative model: it must be found to fit, no sensor
    # set aside as a misfit, and a map drawn with a reach must have it back within a bin.
    fit = report["model_fit"]
    if fit is None or fit["misfit"]:
        failures.append(f"{name}: model fit {fit}: the map was drawn by the model")
    misfits = sorted(s["id"] for s in report["sensors"] if s["verdict"] == "model_misfit")
    if misfits:
        failures.append(f"{name}: model_misfit verdicts on a map drawn by the model: {misfits}")
    reach = truth["generator"].get("max_range_m")
    got = report["reception"]["range_m"] if report["reception"] else None
    if (reach is None) != (got is None) or (reach is not None and abs(got - reach) > bin_size):
        failures.append(f"{name}: reach {got} m, drawn with {reach} m (bin {bin_size} m)")
    return row, failures


def main():
    covmap, datasets = sys.argv[1], Path(sys.argv[2])
    part = sys.argv[3] if len(sys.argv) > 3 else "all"
    if part not in ("all", "verdicts", "accounting"):
        sys.exit(f"unknown part {part!r}: verdicts, accounting or nothing for both")
    rows, failures = [], []
    with tempfile.TemporaryDirectory() as work:
        for name in MAPS:
            truth, report, stdout, seconds = audit(covmap, datasets / "maps" / name, Path(work) / name)
            row, missed = judge(name, truth, report)
            row["seconds"] = seconds
            rows.append(row)
            if part != "accounting":
                failures += missed
            if part != "verdicts":
                failures += accounting_failures(name, truth, report, stdout)
    print(f"can reveal: cell >= {MIN_CELL_BINS} bins and gross error >= {GROSS_MULTIPLE:g} bins or "
          f">= {GROSS_MULTIPLE:g} dB")
    print("map          sensors cell resolved gross reveal flagged hits precision recall undetermined   time")
    print("                                                                           resolved/all")
    for r in rows:
        undetermined = f"{r['undetermined']}/{r['undetermined_all']}"
        print(f"{r['map']:<12} {r['sensors']:>7} {r['with_cell']:>4} {r['resolved']:>8} {r['gross']:>5} "
              f"{r['revealable']:>6} {r['flagged']:>7} {r['hits']:>4} {r['precision']:>9.3f} {r['recall']:>6.3f} "
              f"{undetermined:>12} {r['seconds']:>5.1f} s")
    for f in failures:
        print("FAIL:", f)
    print(f"{len(failures)} target(s) missed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
