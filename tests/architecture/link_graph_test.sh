#!/usr/bin/env bash
# The layers of docs/ARCHITECTURE.md, checked against CMake's own dependency graph: every covmap
# library links (directly or through others) only the covmap libraries its layer allows, and the
# third-party libraries named here stay where they belong (Ceres in fitting, CGAL out of io).
#   link_graph_test.sh CMAKE SOURCE_DIR WORK_DIR
set -euo pipefail
cmake_bin=$1 src=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
"$cmake_bin" -S "$src" -B "$work/build" -DCOVMAP_BUILD_TESTS=OFF -DCOVMAP_BUILD_BENCH=OFF \
  --graphviz="$work/deps.dot" >"$work/configure.log" 2>&1 || { cat "$work/configure.log"; exit 1; }

# Every covmap library, bottom up, with the covmap libraries it may link (transitively).
declare -A allowed=(
  [covmap_core]=""
  [covmap_voronoi]="covmap_core"
  [covmap_check]="covmap_core"
  [covmap_mobius]="covmap_core"
  [covmap_recognition]="covmap_core covmap_mobius covmap_voronoi"
  [covmap_cleaning]="covmap_core"
  [covmap_fitting]="covmap_core"
  [covmap_audit]="covmap_core covmap_cleaning covmap_fitting covmap_mobius covmap_voronoi"
  [covmap_io]="covmap_core"
  [covmap_gis]="covmap_core covmap_io"
  [covmap_job]="covmap_core covmap_voronoi covmap_mobius covmap_recognition covmap_cleaning covmap_fitting covmap_audit covmap_io covmap_gis covmap_report"
  [covmap_service]="covmap_core covmap_voronoi covmap_check covmap_mobius covmap_recognition covmap_cleaning covmap_fitting covmap_audit covmap_io covmap_gis covmap_report covmap_job"
  [covmap_report]="covmap_core covmap_voronoi covmap_mobius covmap_recognition covmap_cleaning covmap_fitting covmap_audit covmap_io covmap_gis"
)
# Third-party libraries a covmap library must not link, even indirectly.
declare -A forbidden=(
  [covmap_core]="ceres CGAL nlohmann"
  [covmap_check]="ceres CGAL nlohmann"
  [covmap_recognition]="ceres"
  [covmap_cleaning]="ceres CGAL"
  [covmap_io]="ceres CGAL gdal proj"
  [covmap_gis]="ceres CGAL"
)

failures=0
# The label of every node of the graph: the file for target T holds T and everything it links.
links_of() {
  local file="$work/deps.dot.$1"
  [ -f "$file" ] || { echo "missing graph for $1" >&2; return 1; }
  grep -oE 'label\s*=\s*"[^"]+"' "$file" | sed -E 's/label\s*=\s*"([^"]+)"/\1/' | grep -vx "$1" | sort -u
}
for lib in "${!allowed[@]}"; do
  deps=$(links_of "$lib")
  for d in $(echo "$deps" | grep -E '^covmap_' || true); do
    if ! [[ " ${allowed[$lib]} " == *" $d "* ]]; then
      echo "FAIL: $lib links $d, which its layer does not allow (docs/ARCHITECTURE.md)"
      failures=$((failures + 1))
    fi
  done
  for bad in ${forbidden[$lib]:-}; do
    if echo "$deps" | grep -qi "$bad"; then
      echo "FAIL: $lib links $(echo "$deps" | grep -i "$bad" | head -1)"
      failures=$((failures + 1))
    fi
  done
done
# The graph really was read: the engine links CGAL, fitting links Ceres.
links_of covmap_voronoi | grep -q CGAL || { echo "FAIL: no CGAL under covmap_voronoi: graph not read"; failures=$((failures + 1)); }
links_of covmap_fitting | grep -qi ceres || { echo "FAIL: no Ceres under covmap_fitting: graph not read"; failures=$((failures + 1)); }
if [ "$failures" -ne 0 ]; then
  echo "$failures layer violations"
  exit 1
fi
echo "link graph: ${#allowed[@]} libraries within their layers"
