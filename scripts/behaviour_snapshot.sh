#!/usr/bin/env bash
# Runs every covmap subcommand (and covmap-make-map) on the bundled data and on generated maps and
# graphs, and keeps everything they say and write in one folder: exit codes, stdout, stderr and
# output files. Two snapshots of two builds are then compared file by file: a change that must not
# change behaviour (a restructuring, a speed-up) shows no difference, or only explained ones.
#
#   scripts/behaviour_snapshot.sh COVMAP MAKE_MAP OUT_DIR
#   scripts/behaviour_snapshot.sh --compare OUT_A OUT_B
#
# What is normalised, and why: the folder each snapshot runs in and the source tree's (paths appear
# in messages), the programs' own paths (the audit records its command line), and wall-clock
# figures (the audit's "seconds", progress timings), which differ from run to run. Everything else must be
# reproducible; the audit runs with one refinement thread (--threads 1) so that this holds
# whatever the machine. The comparison is scripts/behaviour_compare.py.
set -uo pipefail

normalise() {  # FILE...: wall-clock figures and the run folder out of text outputs
  for f in "$@"; do
    [ -f "$f" ] || continue
    sed -i -E \
      -e "s#${RUN_DIR}#RUN#g" -e "s#${covmap}#COVMAP#g" -e "s#${make_map}#MAKE_MAP#g" -e "s#${root}#SRC#g" \
      -e 's/("seconds"|"time_s"|"wall_s"): ?[-0-9.e+]+/\1: 0/g' \
      -e 's/\(([0-9.]+(e[-+]?[0-9]+)?) ?(s|ms)\)/(T)/g' \
      -e 's/[0-9]+\.[0-9]+ s\b/T s/g' \
      -e 's/in [0-9.]+(e[-+]?[0-9]+)? s/in T s/g' \
      "$f"
  done
}

if [[ ${1:-} == --compare ]]; then
  exec python3 "$(dirname "$0")/behaviour_compare.py" "${2:?OUT_A}" "${3:?OUT_B}"
fi

covmap=$(realpath "${1:?usage: behaviour_snapshot.sh COVMAP MAKE_MAP OUT_DIR}")
make_map=$(realpath "${2:?MAKE_MAP}")
out=${3:?OUT_DIR}
root=$(cd "$(dirname "$0")/.." && pwd)
data=$root/datasets
rm -rf "$out"
mkdir -p "$out"
out=$(realpath "$out")
RUN_DIR=$(mktemp -d)
trap 'rm -rf "$RUN_DIR"' EXIT

# run NAME CMD...: runs in RUN_DIR, keeps exit code, stdout, stderr and every file it wrote.
run() {
  local name=$1; shift
  local dir=$out/$name
  mkdir -p "$dir"
  local before
  before=$(cd "$RUN_DIR" && find . -type f | sort)
  (cd "$RUN_DIR" && "$@" >"$dir/stdout" 2>"$dir/stderr")
  echo $? >"$dir/exit"
  local after
  after=$(cd "$RUN_DIR" && find . -type f | sort)
  comm -13 <(echo "$before") <(echo "$after") | while read -r f; do
    [ -n "$f" ] || continue
    mkdir -p "$dir/files/$(dirname "$f")"
    cp "$RUN_DIR/$f" "$dir/files/$f"
  done
  normalise "$dir/stdout" "$dir/stderr"
  find "$dir/files" -type f 2>/dev/null | while read -r f; do normalise "$f"; done
}

# Inputs the snapshot makes itself.
cat >"$RUN_DIR/bad_sites.csv" <<'CSV'
id,x,y,weight
a,0,0,1
b,1,0,-2
c,0,0,1
CSV
cat >"$RUN_DIR/square.json" <<'JSON'
{"format":"covmap.sites/1","sites":[{"id":"a","x":0,"y":0,"weight":1},{"id":"b","x":4,"y":0,"weight":2},
{"id":"c","x":0,"y":4,"weight":1.5},{"id":"d","x":4,"y":4,"weight":1},{"id":"e","x":2,"y":2,"weight":3}]}
JSON
printf 'id,x,y,weight\n' >"$RUN_DIR/grid.csv"
for i in 0 1 2 3 4; do for j in 0 1 2 3 4; do
  printf 'g%d%d,%d,%d,%d\n' "$i" "$j" "$i" "$j" $(( (i * 5 + j) % 3 + 1 )) >>"$RUN_DIR/grid.csv"
done; done
echo "not json" >"$RUN_DIR/garbage.json"

# covmap diagram / check / recognize / compare on sites files.
run diagram_towns "$covmap" diagram "$data/swiss_towns.csv" -o towns.json --svg towns.svg -q
run diagram_towns_clip "$covmap" diagram "$data/swiss_towns.csv" -o towns_clip.json --clip 0,0,150,150 -q
run diagram_square "$covmap" diagram square.json -o square_d.json --svg square.svg
run diagram_grid "$covmap" diagram grid.csv -o grid_d.json
run diagram_bad "$covmap" diagram bad_sites.csv -o bad.json
run diagram_garbage "$covmap" diagram garbage.json -o g.json
run check_towns "$covmap" check towns.json
run check_towns_sites "$covmap" check towns_clip.json --sites "$data/swiss_towns.csv"
run check_grid "$covmap" check grid_d.json
run recognize_towns "$covmap" recognize towns.json -o towns_r.json --svg towns_r.svg
run recognize_clip "$covmap" recognize towns_clip.json -o clip_r.json
run recognize_square "$covmap" recognize square_d.json -o square_r.json
run recognize_grid "$covmap" recognize grid_d.json -o grid_r.json
run recognize_garbage "$covmap" recognize garbage.json
run compare_same "$covmap" compare towns.json towns.json
run compare_clip "$covmap" compare towns.json towns_clip.json --show 5

# covmap-make-map: generated maps of several families, then audits of them and of the bundled maps.
run make_random "$make_map" --random 60 --area 30,30 --weight-ratio 4 --gross-fraction 0.1 --seed 3 -q -o gen_random
run make_lonlat "$make_map" --random 40 --area 20,20 --lonlat 7.4,46.9 --max-range 6000 --jitter 2 \
  --gross-fraction 0.15 --seed 5 -q -o gen_lonlat
run make_towns "$make_map" --sites "$data/maps/ticino_towns.csv" --unit km --margin 3 --seed 7 -q -o gen_towns
run audit_random "$covmap" audit gen_random/map.geojson --sensors gen_random/sensors.geojson --planar -q --threads 1 -o audit_random
run audit_lonlat "$covmap" audit gen_lonlat/map.geojson --sensors gen_lonlat/sensors.geojson --alpha 3.5 -q --threads 1 -o audit_lonlat
run audit_towns "$covmap" audit gen_towns/map.geojson --sensors gen_towns/sensors.geojson --planar -q --threads 1 -o audit_towns
run audit_bern "$covmap" audit "$data/maps/bern/map.geojson" --sensors "$data/maps/bern/sensors.geojson" --alpha 3.5 --threads 1 -o audit_bern
run audit_ticino "$covmap" audit "$data/maps/ticino/map.geojson" --sensors "$data/maps/ticino/sensors.geojson" --planar -q --threads 1 -o audit_ticino
run audit_no_sensors "$covmap" audit "$data/maps/ticino/map.geojson" --planar -q --threads 1 -o audit_nosensors
run audit_garbage "$covmap" audit garbage.json -q -o audit_garbage
run audit_batch "$covmap" audit gen_random/map.geojson gen_towns/map.geojson --planar -q --threads 1 -o audit_batch
run audit_gpkg "$covmap" audit gen_random/map.geojson --sensors gen_random/sensors.geojson --planar -q --threads 1 \
  --format gpkg -o audit_gpkg
rm -f "$out/audit_gpkg/files/audit_gpkg/audit.gpkg"  # SQLite pages carry write times: the GeoPackage's rows are dumped instead
if command -v ogrinfo >/dev/null && [ -f "$RUN_DIR/audit_gpkg/audit.gpkg" ]; then
  ogrinfo -ro -al -q "$RUN_DIR/audit_gpkg/audit.gpkg" >"$out/audit_gpkg/gpkg_rows" 2>&1
fi

# covmap serve: the synchronous endpoints answer exactly what the CLI's library functions compute,
# and an audit job's outcome (done, or failed with its error) is what the job API reports.
serve_log=$RUN_DIR/serve.log
"$covmap" serve --port 0 --data "$RUN_DIR/serve-data" --workers 1 >"$serve_log" 2>&1 &
serve_pid=$!
port=""
for _ in $(seq 100); do
  port=$(sed -n 's#.*listening on http://127.0.0.1:\([0-9]*\)/.*#\1#p' "$serve_log")
  [ -n "$port" ] && break
  sleep 0.1
done
post() {  # NAME PATH CURL-ARGS...: status code and body of one request
  local name=$1 path=$2; shift 2
  mkdir -p "$out/$name"
  # No "Expect: 100-continue" (curl's default above 1 KiB), and bodies sent with their own
  # Content-Type (curl's default, a URL-encoded form, is one the HTTP library caps at 8 KiB).
  curl -s -H 'Expect:' -o "$out/$name/body" -w '%{http_code}\n' "$@" "http://127.0.0.1:$port$path" >"$out/$name/status"
  normalise "$out/$name/body"
  sed -i -E 's/"(created|started|finished)_ms": ?[0-9]+/"\1_ms": 0/g' "$out/$name/body"
}
if [ -n "$port" ]; then
  post serve_diagram /v1/diagram -H "Content-Type: application/json" --data-binary @"$RUN_DIR/square.json"
  post serve_diagram_csv /v1/diagram -H 'Content-Type: text/csv' --data-binary @"$RUN_DIR/grid.csv"
  post serve_diagram_bad /v1/diagram -H "Content-Type: text/csv" --data-binary @"$RUN_DIR/bad_sites.csv"
  post serve_check /v1/check -H "Content-Type: application/json" --data-binary @"$RUN_DIR/grid_d.json"
  post serve_recognize /v1/recognize -H "Content-Type: application/json" --data-binary @"$RUN_DIR/square_d.json"
  post serve_recognize_garbage /v1/recognize -H "Content-Type: application/json" --data-binary @"$RUN_DIR/garbage.json"
  python3 -c 'import json,sys; print(json.dumps({"a": json.load(open(sys.argv[1])), "b": json.load(open(sys.argv[2]))}))' \
    "$RUN_DIR/towns.json" "$RUN_DIR/towns_clip.json" >"$RUN_DIR/pair.json"
  post serve_compare /v1/compare -H "Content-Type: application/json" --data-binary @"$RUN_DIR/pair.json"
  post serve_audit_bad_options /v1/audits -F map=@"$RUN_DIR/gen_random/map.geojson" -F 'options={"alpha": -1}'
  post serve_audit_garbage /v1/audits -F map=@"$RUN_DIR/garbage.json" -F 'options={"planar": true}'
  post serve_audit_submit /v1/audits -F map=@"$RUN_DIR/gen_random/map.geojson" \
    -F sensors=@"$RUN_DIR/gen_random/sensors.geojson" -F 'options={"planar": true}'
  id=$(sed -n 's/.*"id": *"\([0-9a-f]*\)".*/\1/p' "$out/serve_audit_submit/body")
  for _ in $(seq 600); do
    curl -s "http://127.0.0.1:$port/v1/audits/$id" >"$RUN_DIR/job.json"
    grep -q '"status": *"\(done\|failed\)"' "$RUN_DIR/job.json" && break
    sleep 0.2
  done
  python3 -c 'import json,sys; j=json.load(open(sys.argv[1])); print(j["status"], json.dumps(j.get("error")), json.dumps(j.get("summary"), sort_keys=True))' \
    "$RUN_DIR/job.json" >"$out/serve_audit_submit/outcome" 2>&1
  sed -i -E 's/[0-9a-f]{32}/ID/g' "$out/serve_audit_submit/body"
fi
kill "$serve_pid" 2>/dev/null
wait "$serve_pid" 2>/dev/null
echo "snapshot: $(find "$out" -type f | wc -l) files in $out"
