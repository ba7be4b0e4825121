#!/usr/bin/env bash
# The main job on a bundled dataset: audit the coverage map of 58 towns around Bern (GeoNames
# places, best-server raster of 200 m bins, rounded, with reported sensors of which a few are
# grossly wrong) — reconstruct every sensor from the map, judge the reported ones, and write
# out/bern/report.html (open it in a browser), report.json, sensors.geojson and diagram.geojson.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
mkdir -p out
./build/cli/covmap audit datasets/maps/bern/map.geojson --sensors datasets/maps/bern/sensors.geojson \
  --alpha 3.5 -o out/bern
