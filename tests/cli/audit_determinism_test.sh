#!/usr/bin/env bash
# covmap audit writes the same report bytes whatever the refinement's thread count, run after run
# (a solve whose sums depend on thread scheduling can change the numbers by far more than
# rounding). The
# bundled Bern map is audited with --threads 1, 2 (twice) and 4, each into its own folder, and the
# four files are compared byte for byte with the first run's. Only what describes the run itself
# may differ, and it sits apart: report.json's "command_line" (it names --threads and the folder)
# and "timings" (wall-clock seconds); report.html's paragraphs with ids "run-command" and
# "run-timings". Usage: audit_determinism_test.sh path/to/covmap path/to/datasets
set -u
covmap="$1"
data="$2"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failed=0
fail() { failed=$((failed + 1)); echo "FAIL: $*"; }

audit() {  # THREADS FOLDER
  "$covmap" audit "$data/maps/bern/map.geojson" --sensors "$data/maps/bern/sensors.geojson" --alpha 3.5 \
    --threads "$1" -o "$work/$2" >/dev/null 2>"$work/$2.err" || fail "audit --threads $1: $(cat "$work/$2.err")"
}

# The run-describing parts out, everything else kept as written (re-serialising would hide
# differences in number formatting).
strip_run() {  # FOLDER
  python3 - "$work/$1/report.json" "$work/$1/report.stripped.json" <<'PY' || fail "$1/report.json: no command_line or timings member"
import json, sys
j = json.load(open(sys.argv[1]))
del j["command_line"], j["timings"]
open(sys.argv[2], "w").write(json.dumps(j, indent=1))
PY
  grep -v -e 'id="run-command"' -e 'id="run-timings"' "$work/$1/report.html" > "$work/$1/report.stripped.html"
}

audit 1 t1
audit 2 t2
audit 2 t2-again
audit 4 t4
for run in t1 t2 t2-again t4; do strip_run "$run"; done
for run in t2 t2-again t4; do
  for f in sensors.geojson shifts.geojson diagram.geojson report.stripped.json report.stripped.html; do
    cmp -s "$work/t1/$f" "$work/$run/$f" || fail "$f differs between --threads 1 and $run: $(cmp "$work/t1/$f" "$work/$run/$f")"
  done
done
# The stripped parts are what they claim to be: the run's command and timings, nothing else.
grep -q '"timings"' "$work/t1/report.json" || fail "report.json has no timings member"
[ "$(grep -c -e 'id="run-command"' -e 'id="run-timings"' "$work/t1/report.html")" -eq 2 ] ||
  fail "report.html: expected one run-command and one run-timings paragraph"

if [ "$failed" -gt 0 ]; then
  echo "$failed failure(s)"
  exit 1
fi
echo "audit reports identical for --threads 1, 2, 2, 4"
