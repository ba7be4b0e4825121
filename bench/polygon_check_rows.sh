#!/usr/bin/env bash
# One polygon_check_bench row per process under /usr/bin/time -v, so every row's peak RSS and wall
# time are its own (docs/PERFORMANCE.md, "Polygon checks"). Prints one JSON object per row: the
# bench's own row plus "process_wall_s", "process_cpu_s" (user + system) and
# "process_peak_rss_kib" from time -v, and the load average when the row started.
#
#   bench/polygon_check_rows.sh BENCH "10000 100000" "spiral circle comb" "defect crossing"
set -euo pipefail
bench=$1 sizes=$2 shapes=$3 checks=$4
log=$(mktemp)
trap 'rm -f "$log"' EXIT
for n in $sizes; do
  for shape in $shapes; do
    for check in $checks; do
      load=$(cut -d' ' -f1 /proc/loadavg)
      row=$(/usr/bin/time -v -o "$log" "$bench" --n "$n" --shape "$shape" --check "$check" --json)
      wall=$(sed -n 's/.*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$log" |
             awk -F: '{ s = 0; for (i = 1; i <= NF; ++i) s = s * 60 + $i; print s }')
      rss=$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$log")
      cpu=$(awk -F': ' '/User time \(seconds\)|System time \(seconds\)/ { s += $2 } END { print s }' "$log")
      echo "${row%\}},\"process_wall_s\":$wall,\"process_cpu_s\":$cpu,\"process_peak_rss_kib\":$rss,\"load_at_start\":$load}"
    done
  done
done
