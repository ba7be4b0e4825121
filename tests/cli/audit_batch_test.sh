#!/usr/bin/env bash
# covmap audit on several maps (a batch), against independent oracles:
#  - each map of a batch gets the report.json of its single-map audit (the same sensors with the
#    same verdicts, and every member the same but those that name the files and the run);
#  - summary.csv and summary.json hold, per map, the counts recounted from that map's report.json
#    sensor by sensor, its agreement and model fit, and the two summaries agree with each other;
#  - a folder with a broken map, a map with two sensors files and a good map exits 2, writes the
#    good map's reports, and lists the two failures with their errors; skipped files are named;
#  - two maps with the same file name get two folders; a single map writes into OUTDIR as before;
#  - outputs that may not be written stop the batch before any audit; a killed batch's OUTDIR, and
#    a single audit's, take a batch without --force.
# Usage: audit_batch_test.sh path/to/covmap path/to/datasets
set -u
covmap=$(realpath "$1")
data=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0
failed=0
ok() { passed=$((passed + 1)); }
fail() { failed=$((failed + 1)); echo "FAIL: $*"; }
run() {  # run NAME ARGS...: covmap with stdout in $work/NAME.out, stderr in $work/NAME.err; sets $code
  local name="$1"
  shift
  timeout 600 "$covmap" "$@" >"$work/$name.out" 2>"$work/$name.err"
  code=$?
}
want_code() {  # want_code CODE WHAT
  [ "$code" -eq "$1" ] && ok || fail "$2: exit $code (want $1); stderr: $(head -c 600 "$work/$run_name.err")"
}
# python3 CHECK ARGS...: the oracles below print one "FAIL: ..." line per failure.
check() {
  local out
  out=$(python3 - "$@")
  if [ -n "$out" ]; then
    echo "$out"
    failed=$((failed + $(echo "$out" | grep -c '^FAIL')))
  else
    ok
  fi
}

maps="$data/maps"
# --- Oracles: the single-map audits, exactly as before batches (report files directly in OUTDIR).
for name in bern switzerland; do
  run_name=single-$name
  run "$run_name" audit "$maps/$name/map.geojson" --sensors "$maps/$name/sensors.geojson" --alpha 3.5 -q \
    -o "$work/single/$name"
  want_code 0 "single audit of $name"
  for f in report.json report.html sensors.geojson shifts.geojson diagram.geojson .covmap-output; do
    [ -f "$work/single/$name/$f" ] && ok || fail "single audit of $name: no $f directly in OUTDIR"
  done
  [ -z "$(find "$work/single/$name" -mindepth 1 -type d)" ] && [ ! -e "$work/single/$name/summary.csv" ] && ok ||
    fail "single audit of $name: a folder or a summary in OUTDIR: $(ls -A "$work/single/$name")"
done

# --- A folder of two lon/lat maps, each with its NAME.sensors.geojson, and files that are no maps.
mkdir -p "$work/in/notes"
for name in bern switzerland; do
  cp "$maps/$name/map.geojson" "$work/in/$name.geojson"
  cp "$maps/$name/sensors.geojson" "$work/in/$name.sensors.geojson"
done
echo "not a map" >"$work/in/readme.txt"
cp "$maps/bern/truth.json" "$work/in/notes/truth.json"
run_name=batch
run batch audit "$work/in" --alpha 3.5 -o "$work/out/"
want_code 0 "batch of bern and switzerland"
grep -q "map 1 of 2: $work/in/bern.geojson" "$work/batch.err" && grep -q "map 2 of 2: $work/in/switzerland.geojson" "$work/batch.err" &&
  ok || fail "progress does not name each map as 'map K of 2: FILE': $(grep 'of 2' "$work/batch.err")"
for skipped in readme.txt notes bern.sensors.geojson switzerland.sensors.geojson; do
  grep -q "skipped $work/in/$skipped: " "$work/batch.err" && ok || fail "stderr does not name the skipped $skipped"
done

# Each map against its single audit: same verdict per sensor, and the same report.json apart from
# what names the files and the run. Then the summaries against the reports.
check "$work/out" "$work/single" "$work/in" <<'PY'
import csv, json, sys
from pathlib import Path
out, single, given = Path(sys.argv[1]), Path(sys.argv[2]), Path(sys.argv[3])
RUN_MEMBERS = ("command_line", "timings", "sensors_file")
VERDICTS = ["unreported", "consistent", "inconsistent", "undetermined", "not_in_map", "model_misfit"]

def stripped(report):
    r = {k: v for k, v in report.items() if k not in RUN_MEMBERS}
    r["map"] = {k: v for k, v in r["map"].items() if k != "file"}
    return r

def close(a, b):
    return (a is None and b is None) or (a is not None and b is not None and abs(a - b) <= 1e-9 * max(1.0, abs(b)))

rows = list(csv.DictReader(open(out / "summary.csv", newline="")))
summary = json.load(open(out / "summary.json"))
if [r["map"] for r in rows] != [str(given / "bern.geojson"), str(given / "switzerland.geojson")]:
    print(f"FAIL: summary.csv maps {[r['map'] for r in rows]}, want bern then switzerland from {given}")
for name in ["bern", "switzerland"]:
    batch = json.load(open(out / name / "report.json"))
    alone = json.load(open(single / name / "report.json"))
    verdicts = {s["id"]: s["verdict"] for s in batch["sensors"]}
    if verdicts != {s["id"]: s["verdict"] for s in alone["sensors"]}:
        print(f"FAIL: {name}: batch verdicts differ from the single audit's")
    if stripped(batch) != stripped(alone):
        print(f"FAIL: {name}: batch report.json differs from the single audit's beyond file names and run")
    if batch["sensors_file"] != str(given / f"{name}.sensors.geojson"):
        print(f"FAIL: {name}: audited with sensors {batch['sensors_file']}, not its {name}.sensors.geojson")
    row = next((r for r in rows if r["folder"] == name), None)
    if row is None:
        print(f"FAIL: summary.csv has no row for folder {name}")
        continue
    # The counts recounted sensor by sensor (report.json writes null for unreported).
    counted = {v: 0 for v in VERDICTS}
    for s in batch["sensors"]:
        counted[s["verdict"] or "unreported"] += 1
    want = dict(counted, sensors=len(batch["sensors"]),
                in_map=sum(1 for s in batch["sensors"] if s["in_map"]),
                reported=sum(1 for s in batch["sensors"] if s["reported"] is not None))
    got = {k: int(row[k]) for k in want}
    if got != want:
        print(f"FAIL: {name}: summary.csv counts {got}, report.json has {want}")
    if row["status"] != "audited" or row["error"] != "" or row["map"] != batch["map"]["file"]:
        print(f"FAIL: {name}: row {row} does not say audited without error for {batch['map']['file']}")
    if row["sensors_file"] != batch["sensors_file"]:
        print(f"FAIL: {name}: summary sensors_file {row['sensors_file']} != report's {batch['sensors_file']}")
    if not close(float(row["refined_agreement_percent"]), 100 * batch["agreement"]["refined"]["mean_iou"]):
        print(f"FAIL: {name}: refined agreement {row['refined_agreement_percent']} != 100 x report's mean_iou")
    reported = batch["agreement"]["reported"]
    if not close(float(row["reported_agreement_percent"]) if row["reported_agreement_percent"] else None,
                 100 * reported["mean_iou"] if reported else None):
        print(f"FAIL: {name}: reported agreement {row['reported_agreement_percent']} != report's")
    fit = batch["model_fit"]
    pairs = [("model_fit_ratio", fit["ratio"]), ("model_fit_reports_median_p", fit["reports_median_p"]),
             ("model_fit_misfit_sensors", fit["misfit_sensors"]),
             ("model_fit_misfit_area_percent", 100 * fit["misfit_area_share"])]
    for column, value in pairs:
        if not close(float(row[column]) if row[column] else None, value):
            print(f"FAIL: {name}: {column} {row[column]} != report.json's {value}")
    if row["map_follows_model"] != ("false" if fit["misfit"] else "true"):
        print(f"FAIL: {name}: map_follows_model {row['map_follows_model']}, report's misfit {fit['misfit']}")
# summary.json: the same rows, numbers as numbers.
for row, j in zip(rows, summary["maps"]):
    for k, v in row.items():
        text = "" if j[k] is None else ("true" if j[k] is True else "false" if j[k] is False else str(j[k]))
        if isinstance(j[k], float):
            if not close(float(v), j[k]):
                print(f"FAIL: summary.json {k} {j[k]} != summary.csv {v}")
        elif text != v:
            print(f"FAIL: summary.json {k} {j[k]!r} != summary.csv {v!r}")
if (summary["maps_audited"], summary["maps_failed"]) != (2, 0):
    print(f"FAIL: summary.json counts {summary['maps_audited']} audited, {summary['maps_failed']} failed")
skipped = {Path(s["file"]).name: s["reason"] for s in summary["skipped"]}
want = {"readme.txt": "not_a_map", "notes": "folder", "bern.sensors.geojson": "sensors_file",
        "switzerland.sensors.geojson": "sensors_file"}
if skipped != want:
    print(f"FAIL: summary.json skipped {skipped}, want {want}")
marker = (out / ".covmap-output").read_text().splitlines()[1:]
if sorted(marker) != ["summary.csv", "summary.json"]:
    print(f"FAIL: OUTDIR's marker lists {marker}")
PY

# --- Writing the batch again into its own OUTDIR needs no --force; a user's folder in the way of a
# map's folder, or an input folder as OUTDIR, stop it before any audit (nothing is written).
mkdir "$work/out/readme" && echo precious >"$work/out/readme/mine.txt"
cp "$work/in/readme.txt" "$work/in/readme.geojson"
run_name=user-folder
run user-folder audit "$work/in" --alpha 3.5 -o "$work/out"
want_code 2 "a user's folder where a map's reports would go"
grep -q "holds files covmap did not write (mine.txt)" "$work/user-folder.err" && ok ||
  fail "the refusal does not name the user's file: $(cat "$work/user-folder.err")"
[ "$(cat "$work/out/readme/mine.txt")" = precious ] && [ "$(ls -A "$work/out/readme")" = mine.txt ] && ok ||
  fail "the user's folder was touched: $(ls -A "$work/out/readme")"
! grep -q "map 1 of" "$work/user-folder.err" && ok || fail "an audit started before the refusal"
rm "$work/in/readme.geojson"
run_name=input-as-output
run input-as-output audit "$work/in" -o "$work/in"
want_code 2 "the input folder as OUTDIR"
[ "$(ls -A "$work/in" | sort | tr '\n' ' ')" = "bern.geojson bern.sensors.geojson notes readme.txt switzerland.geojson switzerland.sensors.geojson " ] &&
  ok || fail "the input folder changed: $(ls -A "$work/in")"

mkdir "$work/no-maps" && cp "$work/in/readme.txt" "$work/in/bern.sensors.geojson" "$work/no-maps/"
run_name=no-map
run no-map audit "$work/no-maps" -o "$work/none"
want_code 2 "a folder without maps"
grep -q "no-maps: the folder holds no map" "$work/no-map.err" && [ ! -e "$work/none" ] && ok ||
  fail "a folder without maps: want its name and no OUTDIR, got: $(cat "$work/no-map.err"); $(ls -A "$work/none" 2>&1)"

# --- A broken map, a map with two sensors files, and a good one (planar Ticino) in one folder.
mkdir "$work/mixed"
printf '{"type": "FeatureCollection", "features": [' >"$work/mixed/a_broken.geojson"
cp "$maps/ticino/map.geojson" "$work/mixed/b_twice.geojson"
cp "$maps/ticino/sensors.geojson" "$work/mixed/b_twice.sensors.geojson"
printf 'id,x,y\n' >"$work/mixed/b_twice.sensors.csv"
cp "$maps/ticino/map.geojson" "$work/mixed/c_ticino.geojson"
cp "$maps/ticino/sensors.geojson" "$work/mixed/c_ticino.sensors.geojson"
run_name=mixed
run mixed audit "$work/mixed" --planar --alpha 3.5 --fail-on-inconsistent -o "$work/mixed-out"
want_code 2 "a folder with failing maps (2 wins over --fail-on-inconsistent's 1)"
grep -q "map 1 of 3: $work/mixed/a_broken.geojson failed: .*a_broken.geojson" "$work/mixed.err" && ok ||
  fail "stderr does not say the broken map failed: $(cat "$work/mixed.err")"
grep -q "map 2 of 3: $work/mixed/b_twice.geojson failed: .*several sensors files" "$work/mixed.err" && ok ||
  fail "stderr does not say which map has two sensors files"
[ -f "$work/mixed-out/c_ticino/report.json" ] && [ ! -e "$work/mixed-out/a_broken" ] && [ ! -e "$work/mixed-out/b_twice" ] &&
  ok || fail "want only the good map's folder, got: $(ls -A "$work/mixed-out")"
check "$work/mixed-out" "$work/mixed" <<'PY'
import csv, json, sys
from pathlib import Path
out, given = Path(sys.argv[1]), Path(sys.argv[2])
rows = {Path(r["map"]).name: r for r in csv.DictReader(open(out / "summary.csv", newline=""))}
summary = json.load(open(out / "summary.json"))
for name, needle in [("a_broken.geojson", "a_broken.geojson"), ("b_twice.geojson", "several sensors files")]:
    row = rows.get(name)
    if row is None or row["status"] != "failed" or needle not in row["error"] or row["sensors"] != "":
        print(f"FAIL: {name}: want a failed row with an error naming '{needle}' and no counts, got {row}")
good = rows.get("c_ticino.geojson")
report = json.load(open(out / "c_ticino" / "report.json"))
if good is None or good["status"] != "audited" or int(good["inconsistent"]) != sum(
        1 for s in report["sensors"] if s["verdict"] == "inconsistent"):
    print(f"FAIL: c_ticino: row {good} does not match its report")
if (summary["maps_audited"], summary["maps_failed"]) != (1, 2):
    print(f"FAIL: summary.json says {summary['maps_audited']} audited, {summary['maps_failed']} failed")
errors = {Path(m["map"]).name: m["error"] for m in summary["maps"]}
if errors.get("a_broken.geojson") != rows["a_broken.geojson"]["error"]:
    print("FAIL: the error differs between summary.json and summary.csv")
PY

# --- Exit 1 with --fail-on-inconsistent when no map failed and one has an inconsistent sensor
# (by its report.json); two maps named map.geojson get two folders, named by their parent folders.
inconsistent=$(python3 -c "import json,sys; print(sum(s['verdict'] == 'inconsistent' for s in json.load(open(sys.argv[1]))['sensors']))" \
  "$work/mixed-out/c_ticino/report.json")
mkdir "$work/copy" && cp "$maps/ticino/map.geojson" "$work/copy/map.geojson"
run_name=stems
run stems audit "$maps/ticino/map.geojson" "$work/copy/map.geojson" --sensors "$maps/ticino/sensors.geojson" \
  --planar --alpha 3.5 --fail-on-inconsistent -q -o "$work/stems"
want_code "$([ "$inconsistent" -gt 0 ] && echo 1 || echo 0)" "--fail-on-inconsistent with $inconsistent inconsistent sensors per map"
check "$work/stems" "$maps/ticino/map.geojson" "$work/copy/map.geojson" <<'PY'
import csv, json, sys
from pathlib import Path
out, maps = Path(sys.argv[1]), sys.argv[2:]
rows = list(csv.DictReader(open(out / "summary.csv", newline="")))
folders = [r["folder"] for r in rows]
if [r["map"] for r in rows] != maps or len(set(folders)) != 2:
    print(f"FAIL: want two rows with distinct folders for {maps}, got {[(r['map'], r['folder']) for r in rows]}")
for r in rows:
    report = json.load(open(out / r["folder"] / "report.json"))
    if report["map"]["file"] != r["map"]:
        print(f"FAIL: folder {r['folder']} holds the report of {report['map']['file']}, not {r['map']}")
if folders != ["ticino_map", "copy_map"]:
    print(f"FAIL: folders {folders}, want ticino_map and copy_map (PARENT_STEM for a shared stem)")
PY
# -q: nothing on stderr but what went wrong (nothing here).
[ ! -s "$work/stems.err" ] && ok || fail "-q batch wrote to stderr: $(head -c 300 "$work/stems.err")"

# --- A batch killed mid-way leaves an OUTDIR covmap may write into again without --force (its marker
# was written before the first audit); a folder a single audit wrote becomes a batch's, and the
# reports the single audit listed in its marker are removed, as in any report folder rewritten.
# Killed as soon as the marker is there (not after a fixed time: on a loaded machine the batch may
# not have reached it in a second), while the batch's audits are still running.
"$covmap" audit "$work/in" --alpha 3.5 -q -o "$work/killed" >/dev/null 2>&1 &
batch_pid=$!
for _ in $(seq 600); do
  [ -f "$work/killed/.covmap-output" ] || ! kill -0 "$batch_pid" 2>/dev/null && break
  sleep 0.05
done
kill -KILL "$batch_pid" 2>/dev/null
wait "$batch_pid" 2>/dev/null
[ -f "$work/killed/.covmap-output" ] && ok || fail "a killed batch left no marker in OUTDIR: $(ls -A "$work/killed" 2>&1)"
[ ! -e "$work/killed/summary.csv" ] && ok || fail "the batch to be killed finished first: the test needs more maps in $work/in"
cp -r "$work/single/bern" "$work/was-single"
for outdir in killed was-single; do
  run_name=again-$outdir
  run "$run_name" audit "$work/mixed/c_ticino.geojson" "$work/copy/map.geojson" --planar --alpha 3.5 -q -o "$work/$outdir"
  want_code 0 "a batch into $outdir without --force"
  [ -f "$work/$outdir/summary.csv" ] && [ -f "$work/$outdir/c_ticino/report.json" ] && [ -f "$work/$outdir/map/report.json" ] &&
    ok || fail "$outdir: the batch's files are missing: $(ls -A "$work/$outdir")"
done
[ ! -e "$work/was-single/report.json" ] && [ ! -e "$work/was-single/diagram.geojson" ] && ok ||
  fail "the single audit's reports are still in the folder: $(ls -A "$work/was-single")"

echo "audit batch: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
