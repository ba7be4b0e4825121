#!/usr/bin/env bash
# The audit's scaling table of docs/PERFORMANCE.md: `covmap audit` end to end on generated planar
# maps of N sensors at a constant density (mean spacing 2 km, 100 m bins, weight ratio 3, 10 %
# gross errors, seed 1), with its stage times from report.json, wall
# and user time and peak memory from /usr/bin/time, and a same-run reference: the engine's MWVD of
# 10⁵ uniform sites (mwvd_bench) timed just before each audit, so rows taken under different loads
# can be compared.
# Usage: bench/audit_scaling.sh [build-dir] [N ...]   (from the repository root; default N: 1000 3000 10000 30000)
# Prints one markdown row per N; the maps and reports go to a temporary folder, removed at the end.
set -euo pipefail
build="${1:-build}"
shift || true
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(1000 3000 10000 30000)
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

echo "| cells | vertices | read | cleaning | refinement (joint / restarts / local re-solves) | diagrams | reports | audit wall | user | peak RSS | reference (engine, 10⁵ sites) |"
echo "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for n in "${sizes[@]}"; do
  side=$(python3 -c "import math; print(round(2 * math.sqrt($n), 3))")
  "$build/tools/mapgen/covmap-make-map" --random "$n" --area "$side,$side" --weight-ratio 3 --bin 100 \
    --gross-fraction 0.1 --seed 1 -q -o "$work/map$n"
  reference=$("$build/bench/mwvd_bench" --n 100000 --dist uniform12 --seed 1 --repeat 1 --json |
              python3 -c "import json, sys; print('%.2f s' % json.loads(sys.stdin.readline())['engine_seconds'])")
  /usr/bin/time -v -o "$work/time$n" "$build/cli/covmap" audit "$work/map$n/map.geojson" \
    --sensors "$work/map$n/sensors.geojson" --alpha 3.5 --planar -q -o "$work/audit$n" >/dev/null
  python3 - "$n" "$work/audit$n/report.json" "$work/time$n" "$reference" <<'PY'
import json, re, sys
n, report, timing, reference = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4]
r = json.load(open(report))
stages = {s["stage"]: s["seconds"] for s in r["timings"]["stages"]}
t = open(timing).read()
def field(name):
    return re.search(re.escape(name) + r": (.*)", t).group(1).strip()
wall_text = field("Elapsed (wall clock) time (h:mm:ss or m:ss)")
wall = 0.0
for part in wall_text.split(":"):
    wall = wall * 60 + float(part)
user = float(field("User time (seconds)"))
peak_mib = int(field("Maximum resident set size (kbytes)")) / 1024
reports = wall - r["timings"]["seconds"]  # the rest of the process: writing the reports, start-up
def s(name):
    return "%.1f s" % stages[name] if name in stages else "–"
def refinement():
    parts = [stages.get(name, 0.0) for name in ("refinement", "refinement (several starts)")]
    joint = sum(parts)
    restarts = stages.get("refinement: restarts of escaped sensors", 0.0)
    local = stages.get("refinement: local re-solves", 0.0)
    return "%.1f s (%.1f / %.1f / %.1f)" % (joint + restarts + local, joint, restarts, local)
print("| %s | %s | %s | %s | %s | %s | %.1f s | **%.1f s** | %.1f s | %.0f MiB | %s |" % (
    f"{int(r['map']['cells']):,}".replace(",", " "), f"{int(r['map']['vertices']):,}".replace(",", " "),
    s("reading map and sensors"), s("cleaning and starting values"), refinement(),
    s("recomputed diagrams and comparison"), reports, wall, user, peak_mib, reference))
PY
done
