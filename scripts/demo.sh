#!/usr/bin/env bash
# The main job on a bundled dataset: the MWVD of 151 Swiss towns (GeoNames), drawn and verified.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
mkdir -p out
./build/cli/covmap diagram datasets/swiss_towns.csv -o out/swiss_towns.json --svg out/swiss_towns.svg
./build/cli/covmap check out/swiss_towns.json
