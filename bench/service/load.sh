#!/usr/bin/env bash
# Load figures of `covmap serve` (docs/PERFORMANCE.md, "The service under load"): requests per
# second and latency percentiles, loopback only, with wrk (Debian's wrk package).
#   bench/service/load.sh path/to/covmap [seconds=10] [connections=4]
# 1. POST /v1/diagram with 10^3 random sites (seed 1, CSV) — the synchronous path.
# 2. POST /v1/audits with a small map (12 sensors, planar, made by covmap-make-map beside covmap)
#    — job submission: the upload is stored and read once before the job is queued; the jobs
#    themselves run on one worker meanwhile and are not part of the figure.
set -euo pipefail
covmap=$(realpath "$1")
seconds=${2:-10}
connections=${3:-4}
here=$(dirname "$(realpath "$0")")
work=$(mktemp -d)
trap 'kill $server 2>/dev/null || true; wait 2>/dev/null || true; rm -rf "$work"' EXIT
python3 - "$work/sites.csv" <<'PY'
import random, sys
random.seed(1)
with open(sys.argv[1], "w") as f:
    f.write("id,x,y,weight\n")
    for i in range(1000):
        f.write(f"s{i},{random.uniform(0, 10000):.3f},{random.uniform(0, 10000):.3f},{random.uniform(0.5, 2):.4f}\n")
PY
make_map="$(dirname "$covmap")/../tools/mapgen/covmap-make-map"
"$make_map" --random 12 --area 5,5 --seed 3 -o "$work/map" -q
boundary=covmapbench
{
  printf -- "--%s\r\nContent-Disposition: form-data; name=\"map\"; filename=\"map.geojson\"\r\n\r\n" $boundary
  cat "$work/map/map.geojson"
  printf "\r\n--%s\r\nContent-Disposition: form-data; name=\"options\"\r\n\r\n{\"planar\": true}\r\n--%s--\r\n" $boundary $boundary
} >"$work/upload.bin"
"$covmap" serve --port 0 --data "$work/data" --workers 1 --queue 100000 >"$work/serve.out" 2>&1 &
server=$!
for _ in $(seq 50); do grep -q listening "$work/serve.out" && break; sleep 0.1; done
base=$(grep -o 'http://[^/]*' "$work/serve.out")
echo "== POST /v1/diagram, 10^3 sites, ${connections} connections, ${seconds} s"
BODY_FILE="$work/sites.csv" wrk -t2 -c"$connections" -d"${seconds}s" --latency -s "$here/post_file.lua" "$base/v1/diagram"
echo "== POST /v1/audits (submission), ${connections} connections, ${seconds} s"
BODY_FILE="$work/upload.bin" CONTENT_TYPE="multipart/form-data; boundary=$boundary" \
  wrk -t2 -c"$connections" -d"${seconds}s" --latency -s "$here/post_file.lua" "$base/v1/audits"
