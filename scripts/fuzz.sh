#!/usr/bin/env bash
# Fuzzes the parsers of io/, which read untrusted input, with libFuzzer (the targets are
# tests/fuzz/*.cpp).
#
#   bash scripts/fuzz.sh [SECONDS] [TARGET...]       fuzz each TARGET (default: all) for SECONDS
#                                                    (default 60), one after the other
#   bash scripts/fuzz.sh --ci [SECONDS] [TARGET...]  what CI runs: every input kept in
#                                                    tests/fuzz/regressions/<target>/ once, then a
#                                                    bounded run of SECONDS (default 15) per target;
#                                                    fails while any regression input still breaks
#                                                    its target. All ten targets: 3.5 minutes on 2
#                                                    busy cores, plus the build (about 4 minutes
#                                                    there) and, on a fresh machine, the packages
#   bash scripts/fuzz.sh --list                      the targets
#
# Set-up: installs clang, libclang-rt-14-dev, llvm-14 (the symbolizer) and the parsers' build
# dependencies from Debian when they are missing (apt-get update first; needs root or sudo), then
# configures build-fuzz/ with CC=clang CXX=clang++ -DCOVMAP_FUZZ=ON, which builds covmap_core,
# covmap_io and the fuzz_<target> executables only, instrumented for libFuzzer with
# AddressSanitizer and UndefinedBehaviorSanitizer (see the top-level CMakeLists.txt).
#
# A run starts from a copy of the seeds tests/fuzz/corpus/<target>/ in build-fuzz/work/<target>/
# (inputs the fuzzer adds stay there; the seeds in git are not touched), with the dictionary
# assembled from tests/fuzz/dict/ for the target's format, and stops at the first finding. A
# finding is anything but a parse result that keeps the reader's documented promises or an
# io::InputError: a crash, a sanitizer report, another exception, a broken promise
# (tests/fuzz/checks.h), an input taking over 10 s (a hang) or over 2 GB. Each target prints one
# line: executions, executions per second, coverage (libFuzzer's "cov:", instrumented edges
# reached), corpus size, and the path of each input that broke it
# (build-fuzz/crashes/<target>/<date-time>/).
# The full libFuzzer output is in build-fuzz/logs/<target>.log.
#
# Exit status: 0 if no target found anything (and, with --ci, every regression input passes), 1 if
# one did, 2 on bad usage.
#
# When a target finds something: shrink the input with
#   build-fuzz/tests/fuzz/fuzz_<target> -minimize_crash=1 -runs=20000 -exact_artifact_path=small FILE
# (the shrunk input may break the target another way: check its report), keep it as
# tests/fuzz/regressions/<target>/<what-broke> and fix the reader; --ci replays it from
# then on. Reproduce one input: build-fuzz/tests/fuzz/fuzz_<target> FILE.
#
# Environment: FUZZ_JOBS, targets fuzzed at the same time (default 1; one core each);
# FUZZ_KEEP_GOING=1, fuzz for the whole time and collect every finding instead of stopping at the
# first (libFuzzer's -fork=1 -ignore_crashes=1 ...; for measuring, or a target with a known open
# finding); FUZZ_BUILD_DIR (default build-fuzz).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)

# The targets, each with the dictionary parts (tests/fuzz/dict/*.dict) of its format.
declare -A DICTS=(
  [sites_json]="json numbers sites"
  [sites_csv]="csv numbers sites"
  [arcgraph]="json numbers sites arcgraph"
  [clip_spec]="clip numbers"
  [polygon_json]="json numbers polygon geojson"
  [coverage_map_lonlat]="json numbers geojson coverage_map"
  [coverage_map_planar]="json numbers geojson coverage_map"
  [sensors_json]="json numbers sensors"
  [sensors_csv]="csv numbers sensors"
  [sensors_geojson]="json numbers geojson sensors"
)
ALL_TARGETS=(sites_json sites_csv arcgraph clip_spec polygon_json coverage_map_lonlat coverage_map_planar
             sensors_json sensors_csv sensors_geojson)

usage() {
  sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2
  exit 2
}

ci=false
case "${1:-}" in
  --ci) ci=true; shift ;;
  --list) printf '%s\n' "${ALL_TARGETS[@]}"; exit 0 ;;
  -h|--help) usage ;;
esac
seconds=$($ci && echo 15 || echo 60)
if [[ "${1:-}" =~ ^[0-9]+$ ]]; then
  seconds=$1
  shift
fi
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=("${ALL_TARGETS[@]}")
for t in "${targets[@]}"; do
  [ -n "${DICTS[$t]+set}" ] || { echo "fuzz: unknown target '$t' (bash scripts/fuzz.sh --list)" >&2; exit 2; }
done
jobs=${FUZZ_JOBS:-1}
keep_going=$([ "${FUZZ_KEEP_GOING:-0}" = 1 ] && echo true || echo false)
build=${FUZZ_BUILD_DIR:-build-fuzz}
case "$build" in /*) ;; *) build="$root/$build" ;; esac

# ---- set-up and build ----
packages=(clang libclang-rt-14-dev llvm-14 cmake make nlohmann-json3-dev libgeographiclib-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO=sudo
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
CC=clang CXX=clang++ cmake -S . -B "$build" -DCOVMAP_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" -j"$(nproc)" >/dev/null

bin="$build/tests/fuzz"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1}"
[ -x /usr/lib/llvm-14/bin/llvm-symbolizer ] && export ASAN_SYMBOLIZER_PATH=/usr/lib/llvm-14/bin/llvm-symbolizer
mkdir -p "$build/logs" "$build/dict" "$build/crashes" "$build/work"
failed=0

# ---- --ci: replay the regression inputs ----
if $ci; then
  for t in "${targets[@]}"; do
    dir="tests/fuzz/regressions/$t"
    [ -d "$dir" ] || continue
    count=0 broken=0
    for f in "$dir"/*; do
      [ -f "$f" ] || continue
      count=$((count + 1))
      if ! "$bin/fuzz_$t" "$f" >"$build/logs/$t.regressions.log" 2>&1; then
        broken=$((broken + 1))
        echo "fuzz: $t: regression input fails: $f" >&2
        grep -E "^SUMMARY|broken promise|runtime error|terminate called|what\(\)" "$build/logs/$t.regressions.log" | head -3 | sed 's/^/  /' >&2
      fi
    done
    [ "$broken" -eq 0 ] || failed=1
    echo "fuzz: $t: $count regression inputs replayed, $broken fail"
  done
fi

# ---- fuzzing ----
# One target: fuzz it, then print its line. Runs in the background when FUZZ_JOBS > 1.
fuzz_target() {
  local t=$1
  local work="$build/work/$t" log="$build/logs/$t.log" dict="$build/dict/$t.dict"
  local crashes="$build/crashes/$t/$stamp"  # this run's findings; earlier runs' stay beside it
  rm -rf "$work"
  mkdir -p "$work/corpus" "$work/cwd" "$crashes"
  cp tests/fuzz/corpus/"$t"/* "$work/corpus/"
  : >"$dict"
  for part in ${DICTS[$t]}; do cat "tests/fuzz/dict/$part.dict" >>"$dict"; done
  local status=0
  local mode=(-print_final_stats=1)
  $keep_going && mode=(-fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1)
  # An empty working directory: clip_spec hands the fuzzer's bytes to parse_clip as a path.
  (cd "$work/cwd" && exec "$bin/fuzz_$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -dict="$dict" -artifact_prefix="$crashes/" "${mode[@]}" "$work/corpus") >"$log" 2>&1 || status=$?
  local new execs="" rate="" cov corpus
  new=$(find "$crashes" -type f | sort)
  rmdir "$crashes" 2>/dev/null || true
  if $keep_going; then
    # The parent's last progress line: "#N: cov: C ft: F corp: K exec/s R oom/timeout/crash: a/b/c
    # time: Ts job: J ...", where R is the rate of the last job only.
    local last elapsed
    last=$(grep -E '^#[0-9]+: cov:' "$log" | tail -1 || true)
    execs=$(sed -n 's/^#\([0-9]*\):.*/\1/p' <<<"$last")
    elapsed=$(sed -n 's/.* time: \([0-9]*\)s.*/\1/p' <<<"$last")
    [ -z "$execs" ] || [ "${elapsed:-0}" -eq 0 ] || rate=$((execs / elapsed))
  else
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
    rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  fi
  if $keep_going; then
    # The parent of -fork counts coverage its own way (about twice the figure of a plain run); one
    # plain pass over the final corpus gives the usual "cov:", comparable across modes.
    (cd "$work/cwd" && exec "$bin/fuzz_$t" -runs=0 -timeout=10 -rss_limit_mb=2048 "$work/corpus") >"$build/logs/$t.corpus.log" 2>&1 || true
    cov=$(grep -o 'cov: [0-9]*' "$build/logs/$t.corpus.log" | tail -1 | cut -d' ' -f2 || true)
  else
    cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | cut -d' ' -f2 || true)
  fi
  corpus=$(grep -o 'corp: [0-9]*' "$log" | tail -1 | cut -d' ' -f2 || true)
  local line
  line=$(printf '%-20s %10s execs %7s exec/s  cov %5s  corpus %5s' "$t" "${execs:-?}" "${rate:-?}" "${cov:-?}" "${corpus:-?}")
  if [ "$status" -ne 0 ] || [ -n "$new" ]; then
    echo "$line  FOUND $(wc -w <<<"$new") input(s); log $log"
    # What each input does, from one more run of it alone (the first five).
    local f what
    for f in $(head -5 <<<"$new"); do
      what=$(cd "$work/cwd" && "$bin/fuzz_$t" -timeout=10 -rss_limit_mb=2048 "$f" 2>&1 |
             grep -m1 -E "broken promise|runtime error|ERROR: AddressSanitizer|ERROR: libFuzzer|ALARM|terminate called|^SUMMARY" || true)
      echo "    $f"
      echo "      ${what:-(does not fail when run alone)}"
    done
    echo found >"$build/logs/$t.status"
  else
    echo "$line  ok"
    echo ok >"$build/logs/$t.status"
  fi
}

stamp=$(date +%Y%m%d-%H%M%S)
echo "fuzz: ${#targets[@]} target(s), $seconds s each, $jobs at a time"
for t in "${targets[@]}"; do
  rm -f "$build/logs/$t.status"
  if [ "$jobs" -le 1 ]; then
    fuzz_target "$t"
  else
    while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n || true; done
    fuzz_target "$t" &
  fi
done
wait
for t in "${targets[@]}"; do
  [ "$(cat "$build/logs/$t.status" 2>/dev/null)" = ok ] || failed=1
done
exit "$failed"
