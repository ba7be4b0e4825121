#!/usr/bin/env bash
# End-to-end tests of the covmap program: exit codes, messages naming the offending input, and
# nothing written on failure. Usage: cli_test.sh path/to/covmap path/to/datasets
set -u
covmap="$1"
data="$2"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0
failed=0
ok() { passed=$((passed + 1)); }
fail() { failed=$((failed + 1)); echo "FAIL: $*"; }

# 1. The bundled dataset: diagram, then the independent check passes.
if "$covmap" diagram "$data/swiss_towns.csv" -o "$work/d.json" --svg "$work/d.svg" -q &&
   "$covmap" check "$work/d.json" >/dev/null; then ok; else fail "diagram + check on swiss_towns"; fi
grep -q '"format":"covmap.arcgraph/1"' "$work/d.json" && ok || fail "arcgraph format tag"
grep -q '<svg' "$work/d.svg" && ok || fail "svg written"

# 2. Bad sites: duplicate position and a negative weight, both named with their lines; exit 2;
#    no output file.
cat > "$work/bad.csv" <<'CSV'
id,x,y,weight
a,0,0,1
b,1,0,-2
c,0,0,1
CSV
"$covmap" diagram "$work/bad.csv" -o "$work/bad.json" 2>"$work/err.txt"
code=$?
[ "$code" -eq 2 ] && ok || fail "bad sites exit code $code"
grep -q "bad.csv:3" "$work/err.txt" && grep -q "'b'" "$work/err.txt" && ok || fail "negative weight not named: $(cat "$work/err.txt")"
grep -q "'c'" "$work/err.txt" && ok || fail "duplicate not named: $(cat "$work/err.txt")"
[ ! -e "$work/bad.json" ] && ok || fail "output written despite error"

# 3. A corrupted diagram: move one node far away; check must fail with exit 1 and name a place.
python3 - "$work/d.json" "$work/broken.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
d["nodes"][0]["x"] += 1.0
json.dump(d, open(sys.argv[2], "w"))
PY
"$covmap" check "$work/broken.json" >"$work/out.txt"
code=$?
[ "$code" -eq 1 ] && ok || fail "corrupted diagram exit code $code"
grep -q "NodeNotEquidistant\|ArcEndNotOnCurve" "$work/out.txt" && ok || fail "violation not listed"

# 4. Clipping to a rectangle: frame arcs present and the check passes.
"$covmap" diagram "$data/swiss_towns.csv" -o "$work/c.json" --clip=-50,-40,60,50 -q &&
  "$covmap" check "$work/c.json" >/dev/null && grep -q '"frame":true' "$work/c.json" && ok ||
  fail "clipped diagram"

# 5. Unknown file: exit code 2 from the command line parser or reader.
"$covmap" diagram "$work/missing.csv" -o "$work/m.json" 2>/dev/null
code=$?
[ "$code" -ne 0 ] && [ ! -e "$work/m.json" ] && ok || fail "missing input accepted"

# 6. Recognition round trip: the engine's diagram is recognized as the MWVD of its own sites.
"$covmap" recognize "$work/d.json" -o "$work/r.json" >"$work/rec.txt"
code=$?
[ "$code" -eq 0 ] && grep -q "MWVD: yes" "$work/rec.txt" && ok || fail "recognize: exit $code, $(cat "$work/rec.txt")"
grep -q '"format":"covmap.reconstruction/1"' "$work/r.json" && ok || fail "reconstruction format tag"
# 7. A circle arc with a changed radius is not a bisector graph: exit 3.
python3 - "$work/d.json" "$work/bent.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
for a in d["arcs"]:
    if "circle" in a and a["from"] is not None:
        a["circle"]["r"] *= 1.01
        break
json.dump(d, open(sys.argv[2], "w"))
PY
"$covmap" recognize "$work/bent.json" >"$work/rec2.txt"
code=$?
[ "$code" -eq 3 ] && ok || fail "bent graph: exit $code, $(cat "$work/rec2.txt")"
# 7b. The graph's own sites (d.json carries them) are compared with the reconstruction: they agree;
#     two sites swapped, one moved or one reweighted disagree: exit 1 and input_sites.agree false.
grep -q '"input_sites":{"agree":true' "$work/r.json" && grep -q "sites agree" "$work/rec.txt" && ok ||
  fail "input sites of d.json: $(cat "$work/rec.txt")"
for change in swap move reweight; do
  python3 - "$work/d.json" "$work/$change.json" "$change" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
s = d["sites"]
if sys.argv[3] == "swap":
    for k in ("x", "y", "weight"):
        s[0][k], s[1][k] = s[1][k], s[0][k]
elif sys.argv[3] == "move":
    s[2]["x"] += 1e-3
else:
    s[3]["weight"] *= 1.01
json.dump(d, open(sys.argv[2], "w"))
PY
  "$covmap" recognize "$work/$change.json" -o "$work/$change-r.json" >"$work/$change.txt"
  code=$?
  [ "$code" -eq 1 ] && grep -q "sites disagree" "$work/$change.txt" && ok ||
    fail "$change: exit $code, $(cat "$work/$change.txt")"
  python3 - "$work/$change-r.json" "$change" <<'PY' && ok || fail "$change: input_sites in the reconstruction"
import json, sys
r = json.load(open(sys.argv[1]))
kinds = {"swap": "swapped_label", "move": "position", "reweight": "weight"}
i = r["input_sites"]
sys.exit(0 if i["agree"] is False and kinds[sys.argv[2]] in [x["kind"] for x in i["differences"]] else 1)
PY
done
# 8. compare: a graph equals itself; the clipped one differs.
"$covmap" compare "$work/d.json" "$work/d.json" >/dev/null && ok || fail "compare equal"
"$covmap" compare "$work/d.json" "$work/c.json" >/dev/null
[ $? -eq 1 ] && ok || fail "compare different"

# 9. recognize: a graph of nested circles without sites or labels (paper 5 §3): a region answer.
cat > "$work/nested.json" <<'JSON'
{"format":"covmap.arcgraph/1","nodes":[],"arcs":[
 {"from":null,"to":null,"circle":{"cx":0,"cy":0,"r":1,"ccw":true}},
 {"from":null,"to":null,"circle":{"cx":0,"cy":0,"r":0.5,"ccw":true}},
 {"from":null,"to":null,"circle":{"cx":2.5,"cy":0,"r":1,"ccw":true}}]}
JSON
"$covmap" recognize "$work/nested.json" -o "$work/nested_rec.json" >"$work/nested.txt"
code=$?
[ "$code" -eq 0 ] && grep -q '"region":{' "$work/nested_rec.json" && ok || fail "nested circles: exit $code, $(cat "$work/nested.txt")"

# 10. audit: a bundled map with its reported sensors writes the five reports; a broken map is
#     named with its feature and leaves no output directory.
map="$data/maps/bern"
if "$covmap" audit "$map/map.geojson" --sensors "$map/sensors.geojson" --alpha 3.5 -o "$work/audit" -q >"$work/audit.txt"; then
  for f in report.json report.html sensors.geojson shifts.geojson diagram.geojson; do
    [ -s "$work/audit/$f" ] && ok || fail "audit did not write $f"
  done
  grep -q '"format": *"covmap.audit/1"' "$work/audit/report.json" && ok || fail "audit report format tag"
else
  fail "audit on the bundled Bern map: $(cat "$work/audit.txt")"
fi
python3 - "$map/map.geojson" "$work/broken_map.geojson" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
ring = m["features"][2]["geometry"]["coordinates"]
ring = ring[0] if m["features"][2]["geometry"]["type"] == "Polygon" else ring[0][0]
ring.pop()  # no longer closed
json.dump(m, open(sys.argv[2], "w"))
PY
"$covmap" audit "$work/broken_map.geojson" -o "$work/audit_broken" -q 2>"$work/audit_err.txt"
code=$?
[ "$code" -eq 2 ] && ok || fail "broken map: exit $code"
grep -q "features\[2\]" "$work/audit_err.txt" && ok || fail "broken map: feature not named: $(cat "$work/audit_err.txt")"
[ ! -e "$work/audit_broken" ] && ok || fail "broken map: output directory left behind"

# covmap reads what it writes: a map and sensors that declare covmap's own plane
# ("covmap:local-plane-metres", as covmap-make-map writes them) are planar without --planar, and
# their audit is the --planar audit's, report for report (only the recorded command line differs).
ticino="$data/maps/ticino"
if "$covmap" audit "$ticino/map.geojson" --sensors "$ticino/sensors.geojson" -q --threads 1 -o "$work/ticino_declared" 2>"$work/ticino_err.txt" &&
   "$covmap" audit "$ticino/map.geojson" --sensors "$ticino/sensors.geojson" --planar -q --threads 1 -o "$work/ticino_planar"; then
  python3 - "$work/ticino_declared/report.json" "$work/ticino_planar/report.json" <<'PY' && ok || fail "declared plane: reports differ"
import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:3])
for r in (a, b):
    r.pop("command_line", None); r.pop("seconds", None); r.pop("timings", None)
sys.exit(0 if a == b else 1)
PY
else
  fail "declared plane: the bundled Ticino map without --planar: $(cat "$work/ticino_err.txt")"
fi

# A mistyped --alpha (35 for 3.5) is named in the first line of the summary, with the interval the
# map and the reported powers imply; the right one is not.
bern="$data/maps/bern"
"$covmap" audit "$bern/map.geojson" --sensors "$bern/sensors.geojson" --alpha 35 -q -o "$work/bern35" >"$work/bern35.txt" 2>&1
head -1 "$work/bern35.txt" | grep -q "Check --alpha: the map and the reported powers imply a path-loss exponent" &&
  ok || fail "alpha typo not named first: $(head -2 "$work/bern35.txt")"
"$covmap" audit "$bern/map.geojson" --sensors "$bern/sensors.geojson" --alpha 3.5 -q -o "$work/bern3" >"$work/bern3.txt" 2>&1
! grep -q "Check --alpha" "$work/bern3.txt" && ok || fail "the right alpha was questioned: $(head -1 "$work/bern3.txt")"

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
