#!/usr/bin/env bash
# The accuracy table of docs/ACCURACY.md: covmap audit on generated maps (bench/audit_bench),
# varying one thing at a time around a base case (100 sensors, mean spacing 2 km, 100 m bins,
# coordinates to 0.1 m, no jitter, 10 % gross errors, weight ratio 3, 3 seeds each).
# Usage: bench/accuracy.sh [build-dir]   (prints one JSON row per configuration)
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
