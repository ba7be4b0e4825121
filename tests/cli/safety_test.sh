#!/usr/bin/env bash
# The CLI's promises on hostile use: outputs never destroy what the user did not ask to
# replace, multi-file outputs are all or nothing, the exit-code contract holds, hostile inputs end
# quickly with exit 2 and a message naming the problem, interrupted runs leave nothing behind.
# Usage: safety_test.sh path/to/covmap path/to/covmap-make-map
# Every covmap call runs under `timeout`: a hang is a failure, not a stuck test suite.
set -u
covmap=$(realpath "$1")
make_map=$(realpath "$2")
work=$(mktemp -d)
trap 'chmod -R u+w "$work" 2>/dev/null; rm -rf "$work"' EXIT
passed=0
failed=0
ok() { passed=$((passed + 1)); }
fail() { failed=$((failed + 1)); echo "FAIL: $*"; }
# run LIMIT_SECONDS ARGS...: covmap with stdout+stderr in $work/out.txt; sets $code (124 = timed out).
run() {
  local limit="$1"
  shift
  timeout "$limit" "$covmap" "$@" >"$work/out.txt" 2>&1
  code=$?
}
expect() {  # expect CODE PATTERN WHAT
  [ "$code" -eq "$1" ] && grep -qE -- "$2" "$work/out.txt" && ok ||
    fail "$3: exit $code (want $1), output: $(head -c 400 "$work/out.txt")"
}
no_temporaries() {  # no_temporaries DIR WHAT
  if find "$1" -name '.covmap-tmp-*' | grep -q .; then fail "$2: temporaries left: $(find "$1" -name '.covmap-tmp-*')"; else ok; fi
}

# A small planar map (6 sensors, 5 km) and a lon/lat one, made by the generator.
"$make_map" --random 6 --area 5,5 --seed 3 -o "$work/planar" -q || fail "make planar map"
"$make_map" --random 6 --area 5,5 --seed 3 --lonlat 7.4,46.9 -o "$work/geo" -q || fail "make lon/lat map"
map="$work/planar/map.geojson"
printf 'id,x,y,weight\na,0,0,1\nb,10,0,2\nc,0,10,1.5\nd,10,10,1\n' >"$work/s.csv"

# --- Data loss -----------------------------------------------------------------------------
# 1. A folder holding a user's file is refused; the file survives; nothing is added to it.
mkdir "$work/d" && echo precious >"$work/d/mydata.txt"
run 120 audit --planar "$map" -o "$work/d" -q
expect 2 "did not write.*mydata.txt.*--force" "foreign folder refused"
[ "$(cat "$work/d/mydata.txt")" = precious ] && [ "$(ls -A "$work/d")" = mydata.txt ] && ok || fail "foreign folder touched: $(ls -A "$work/d")"
# 2. With --force covmap writes its files beside the user's and leaves the user's alone.
run 120 audit --planar "$map" -o "$work/d" -q --force
expect 0 "with a cell in the map" "--force into a foreign folder"
[ "$(cat "$work/d/mydata.txt")" = precious ] && [ -s "$work/d/report.json" ] && ok || fail "--force lost the user's file"
# 3. A file where the report folder should go is refused and survives.
echo mine >"$work/f.txt"
run 120 audit --planar "$map" -o "$work/f.txt" -q
expect 2 "is a file" "file as report folder"
[ "$(cat "$work/f.txt")" = mine ] && ok || fail "file replaced by a folder"
# 4. The input map as output: refused, input unchanged.
cp "$map" "$work/map_copy.geojson"
run 120 audit --planar "$work/map_copy.geojson" -o "$work/map_copy.geojson" -q
expect 2 "map_copy.geojson" "input as output (audit)"
cmp -s "$map" "$work/map_copy.geojson" && ok || fail "audit changed its input"
# 5. diagram with -o equal to its input (even spelled differently): refused before any work.
cp "$work/s.csv" "$work/s2.csv"
run 60 diagram "$work/s2.csv" -o "$work/./s2.csv"
expect 2 "never writes over its inputs" "input as output (diagram)"
cmp -s "$work/s.csv" "$work/s2.csv" && ok || fail "diagram changed its input"
run 60 diagram "$work/s.csv" -o "$work/x.json" --svg "$work/x.json"
expect 2 "two outputs are the same" "two outputs the same file"
# 6. Trailing slash, ".", relative paths; a second run into covmap's own folder replaces it.
mkdir "$work/rel"
(cd "$work/rel" && timeout 120 "$covmap" audit --planar ../planar/map.geojson -o out/ -q >/dev/null 2>&1) &&
  [ -s "$work/rel/out/report.html" ] && ok || fail "-o out/ (relative, trailing slash)"
(cd "$work/rel/out" && timeout 120 "$covmap" audit --planar ../../planar/map.geojson -o . -q >/dev/null 2>&1) &&
  [ -s "$work/rel/out/report.html" ] && ok || fail "-o . inside covmap's own folder"
mkdir "$work/empty" && (cd "$work/empty" && timeout 120 "$covmap" audit --planar ../planar/map.geojson -o . -q >/dev/null 2>&1) &&
  [ -s "$work/empty/report.json" ] && ok || fail "-o . in an empty folder"
no_temporaries "$work" "after the successful runs"
# 7. All or nothing across files: the SVG cannot go where a folder is, so the JSON is not written
#    either, and an existing JSON keeps its content.
mkdir "$work/pic.svg"
echo old >"$work/keep.json"
run 60 diagram "$work/s.csv" -o "$work/keep.json" --svg "$work/pic.svg"
expect 2 "pic.svg" "svg into a folder"
[ "$(cat "$work/keep.json")" = old ] && ok || fail "JSON replaced although the SVG failed"
# 8. A full disk (a file-size limit makes every write fail with EFBIG): exit 2, the reason, nothing left.
echo old >"$work/full.json"
(ulimit -f 1 && timeout 60 "$covmap" diagram "$work/s.csv" -o "$work/full.json" >"$work/out.txt" 2>&1)
code=$?
expect 2 "full.json.*File too large" "full disk"
[ "$(cat "$work/full.json")" = old ] && ok || fail "full disk: old output lost"
no_temporaries "$work" "after the full disk"
# 9. An output in a folder that does not exist yet is created; an output under a file is a user error.
run 60 diagram "$work/s.csv" -o "$work/new/deeper/d.json" -q
[ "$code" -eq 0 ] && [ -s "$work/new/deeper/d.json" ] && ok || fail "missing output folder: exit $code"
run 60 diagram "$work/s.csv" -o "$work/f.txt/d.json" -q
expect 2 "cannot" "output below a file"
# 9b. A read-only location (sysfs refuses new files even to root, so this holds in CI too).
run 60 diagram "$work/s.csv" -o /sys/covmap-test.json -q
expect 2 "cannot write '/sys/covmap-test.json'.*(Permission denied|Read-only|not permitted)" "read-only location"

# --- Leftovers of killed runs ----------------------------------------------------------------
# 10. A SIGKILLed run's temporaries (a process id that cannot exist) and the NAME.tmp-N/NAME.old-N
#     folders of older versions are removed by the next run that writes there; others' files are not.
mkdir -p "$work/k/.covmap-tmp-2147483646-0-out" "$work/k/out.tmp-77" "$work/k/out.old-78" "$work/k/other.tmp-5"
echo x >"$work/k/out.tmp-77/report.json"
echo x >"$work/k/other.tmp-5/notes.txt"
run 120 audit --planar "$map" -o "$work/k/out" -q
[ "$code" -eq 0 ] && [ ! -e "$work/k/.covmap-tmp-2147483646-0-out" ] && [ ! -e "$work/k/out.tmp-77" ] &&
  [ ! -e "$work/k/out.old-78" ] && [ -e "$work/k/other.tmp-5/notes.txt" ] && ok ||
  fail "stale leftovers: exit $code, left: $(ls -A "$work/k")"
# 11. SIGTERM at any moment: the process dies of the signal and leaves no temporary behind.
for delay in 0.3 1 2; do
  mkdir -p "$work/t$delay"
  timeout 120 "$covmap" audit --planar "$map" -o "$work/t$delay/out" -q >/dev/null 2>&1 &
  pid=$!
  sleep "$delay"
  kill -TERM "$pid" 2>/dev/null
  wait "$pid"
  code=$?
  { [ "$code" -eq 143 ] || [ "$code" -eq 0 ]; } && ok || fail "SIGTERM after $delay s: exit $code"
  no_temporaries "$work/t$delay" "SIGTERM after $delay s"
done

# --- The exit-code contract ---------------------------------------------------------------------
run 10
expect 2 "no subcommand given; use one of: .*audit" "no subcommand"
run 10 frobnicate
expect 2 "unknown subcommand 'frobnicate'; use one of:.*diagram" "unknown subcommand"
run 10 --version
expect 0 "^covmap [0-9]+\.[0-9]+" "--version"
run 10 audit "$work/missing.geojson" -o "$work/m"
expect 2 "cannot read '.*missing.geojson': no such file" "missing input"
run 10 audit --planar "$map" -o "$work/a0" --alpha 0
expect 2 "alpha: must be a positive number \(got '0'\)" "--alpha 0"
[ "$(wc -c <"$work/out.txt")" -lt 300 ] && ok || fail "--alpha 0 message too long: $(cat "$work/out.txt")"
run 10 compare "$work/new/deeper/d.json" "$work/new/deeper/d.json" --tolerance nan
expect 2 "tolerance: must be a number between 0 and 1" "--tolerance nan"
run 10 check "$work/new/deeper/d.json" --tolerance -1
expect 2 "tolerance: must be a number between 0 and 1" "--tolerance -1"
run 10 check "$work/new/deeper/d.json" --probes 2000000000
expect 2 "probes: must be a whole number in 0.10000000" "--probes 2e9"
run 10 audit --planar "$map" -o "$work/a1" --alpha nan
expect 2 "alpha: must be a positive number" "--alpha nan"
run 10 audit --planar "$map" -o "$work/a2" --threads 0
expect 2 "threads: must be a whole number in 1.64" "--threads 0"

# Findings: audit exits 0 whatever the verdicts, 1 with --fail-on-inconsistent when a reported
# sensor is inconsistent (the generator moved half of the sensors by 800-1200 m); messages in fixed
# notation.
"$make_map" --random 8 --area 5,5 --seed 4 --gross-fraction 0.5 --gross-position 800,1200 -o "$work/gross" -q
run 120 audit --planar "$work/gross/map.geojson" --sensors "$work/gross/sensors.geojson" --alpha 3.5 -o "$work/g0" -q
expect 0 "inconsistent: position off by [0-9]+ m \([0-9.]+ σ\)" "audit with inconsistent sensors"
grep -qE "e[+-][0-9]" "$work/out.txt" && fail "exponent in an audit message: $(cat "$work/out.txt")" || ok
run 120 audit --planar "$work/gross/map.geojson" --sensors "$work/gross/sensors.geojson" --alpha 3.5 -o "$work/g1" -q \
  --fail-on-inconsistent
expect 1 "inconsistent" "--fail-on-inconsistent"
[ -s "$work/g1/report.json" ] && ok || fail "--fail-on-inconsistent: reports not written"

# --- Hostile inputs: exit 2 with the reason, in bounded time -------------------------------
# 12. ~200 KB of nested brackets in a map's coordinates, in a crs member, in a sensors file.
python3 - "$work" <<'PY'
import sys
w = sys.argv[1]
deep = "[" * 200000 + "]" * 200000
open(w + "/deep_map.geojson", "w").write('{"type":"FeatureCollection","features":[{"type":"Feature","properties":{"sensor":"a"},"geometry":{"type":"Polygon","coordinates":' + deep + '}}]}')
open(w + "/deep_crs.geojson", "w").write('{"type":"FeatureCollection","crs":' + deep + ',"features":[]}')
open(w + "/deep_sensors.json", "w").write('{"format":"covmap.sites/1","sites":' + deep + '}')
PY
run 20 audit "$work/deep_map.geojson" -o "$work/o1" -q
expect 2 "nested more than 32 levels" "deep map"
run 20 audit "$work/deep_crs.geojson" -o "$work/o2" -q
expect 2 "nested more than 32 levels" "deep crs"
run 20 audit --planar "$map" --sensors "$work/deep_sensors.json" -o "$work/o3" -q
expect 2 "nested more than 32 levels" "deep sensors"
run 20 diagram "$work/deep_sensors.json" -o "$work/o4.json"
expect 2 "nested more than 32 levels" "deep sites"
# 13. One mistyped coordinate (y = 2147483648) and a map scaled by 1e150: refused at once.
python3 - "$map" "$work" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
ring = m["features"][1]["geometry"]["coordinates"][0]
ring[1][1] = 2147483648
json.dump(m, open(sys.argv[2] + "/typo.geojson", "w"))
def scaled(c):
    return [scaled(v) for v in c] if isinstance(c[0], list) else [c[0] * 1e150, c[1] * 1e150]
m = json.load(open(sys.argv[1]))
for f in m["features"]:
    f["geometry"]["coordinates"] = scaled(f["geometry"]["coordinates"])
json.dump(m, open(sys.argv[2] + "/huge.geojson", "w"))
PY
run 30 audit --planar "$work/typo.geojson" -o "$work/o5" -q
expect 2 "features\[1\].*2147483648.*mistyped" "mistyped coordinate"
run 30 audit --planar "$work/huge.geojson" -o "$work/o6" -q
expect 2 "mistyped or in the wrong unit" "map scaled by 1e150"
grep -q "more like it" "$work/out.txt" && ok || fail "1e150 map: one line per repeated mistake expected"
# 14. Sites at 1e308: refused naming the site, not the JSON writer.
printf 'id,x,y,weight\na,0,0,1\nb,1e308,0,2\nc,0,1e308,1.5\n' >"$work/big.csv"
run 20 diagram "$work/big.csv" -o "$work/big.json"
expect 2 "site" "sites at 1e308"
grep -q "write_diagram_json" "$work/out.txt" && fail "1e308: internal writer named" || ok
[ ! -e "$work/big.json" ] && ok || fail "1e308: output written"

# --- Plausibility -------------------------------------------------------------------------------
# 15. A lon/lat map with --planar: refused; with --force a warning and an audit.
run 120 audit --planar "$work/geo/map.geojson" -o "$work/p1" -q
expect 2 "longitude/latitude.*--planar" "lon/lat map with --planar"
[ ! -e "$work/p1" ] && ok || fail "lon/lat with --planar: output written"
# 16. Reported sensors thousands of km away: refused with how many and how far; --force audits.
python3 - "$work/planar/sensors.geojson" "$work/far.geojson" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
for f in s["features"][:2]:
    f["geometry"]["coordinates"][0] += 3.0e6
json.dump(s, open(sys.argv[2], "w"))
PY
run 120 audit --planar "$map" --sensors "$work/far.geojson" --alpha 3.5 -o "$work/p2" -q
expect 2 "2 reported sensors lie farther outside the map" "far sensors"
run 120 audit --planar "$map" --sensors "$work/far.geojson" --alpha 3.5 -o "$work/p3" -q --force
expect 0 "warning: .*farther outside" "far sensors with --force"

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
