#!/usr/bin/env bash
# The accuracy table of docs/ACCURACY.md: covmap audit on generated maps (bench/audit_bench),
# varying one thing at a time around a base case (100 sensors, mean spacing 2 km, 100 m bins,
# coordinates to 0.1 m, no jitter, 10 % gross errors, weight ratio 3, 3 seeds each).
# Usage: bench/accuracy.sh [build-dir]   (from the repository root; prints one JSON row per configuration)
set -euo pipefail
b="${1:-build}/bench/audit_bench"
run() { "$b" --json "$@" 2>/dev/null || echo "{\"failed\": \"$*\"}"; }
run --n 100 --bin 100 --digits 1 --seeds 3                  # base
for bin in 50 200 400; do run --n 100 --bin "$bin" --digits 1 --seeds 3; done
for digits in 0; do run --n 100 --bin 100 --digits "$digits" --seeds 3; done
for jitter in 5 10; do run --n 100 --bin 100 --digits 1 --jitter "$jitter" --seeds 3; done
for n in 30 300 1000; do run --n "$n" --bin 100 --digits 1 --seeds 3; done
run --n 100 --bin 100 --digits 1 --seeds 3 --lonlat
run --n 100 --bin 100 --digits 1 --seeds 3 --ratio 10
run --n 100 --bin 100 --digits 1 --seeds 3 --ratio 1

# Clustered real town layouts (datasets/towns, a window of --n towns per seed, default bins: mean
# spacing / 20; share_spaced_10_bins says how many sensors meet the targets' bins ≤ local spacing / 10).
for towns in ile_de_france netherlands nordrhein_westfalen scotland iowa; do
  run --towns datasets/towns/$towns.csv --n 100 --bin 0 --digits 1 --seeds 3
done
run --towns datasets/towns/netherlands.csv --n 100 --bin 0 --digits 1 --seeds 3 --town-weights power-classes
# Reception limits (the strongest sensor reaches --max-range metres), uniform and clustered.
run --n 100 --bin 100 --digits 1 --seeds 3 --max-range 2000
run --towns datasets/towns/nordrhein_westfalen.csv --n 100 --bin 0 --digits 1 --seeds 3 --max-range 10000
# Lon/lat rasters of real towns.
run --towns datasets/towns/scotland.csv --n 100 --bin 0 --digits 1 --seeds 3 --lonlat
run --towns datasets/towns/netherlands.csv --n 100 --bin 0 --digits 1 --seeds 3 --lonlat --max-range 8000
# Maps the multiplicative model does not explain, every sensor reported correctly (no gross
# errors): the audit should blame nobody (correct_flagged 0) and report the misfit.
for model in exponents excess-loss shadowing; do
  run --n 100 --bin 100 --digits 1 --seeds 3 --gross 0 --model "$model"
  run --towns datasets/towns/nordrhein_westfalen.csv --n 100 --bin 0 --digits 1 --seeds 3 --gross 0 --model "$model"
done
