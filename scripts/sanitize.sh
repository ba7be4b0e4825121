#!/usr/bin/env bash
# The whole test suite under AddressSanitizer + UndefinedBehaviorSanitizer (docs/RELIABILITY.md):
# configures build-asan/ with COVMAP_SANITIZE=ON, builds (incremental), runs ctest there.
#   bash scripts/sanitize.sh [-R REGEX | other ctest arguments...]
# Environment: JOBS (default nproc) for the build and ctest, CMAKE_ARGS for extra configure options
# (e.g. CMAKE_ARGS=-DCOVMAP_BUILD_BENCH=ON to compile the benchmarks sanitized too; they are not
# run by the suite, so they are off by default).
#
# ASan and LeakSanitizer reports are written to build-asan/sanitizer-logs/ rather than stderr: the
# end-to-end shell tests check exit codes and messages, and an error inside a command that is
# expected to fail would otherwise pass unnoticed. UBSan reports go to stderr all the same (GCC 12's
# combined runtime ignores log_path for them); every one aborts its process (exit 1), and the script
# also looks for them in ctest's log of every test's output. The script fails if ctest fails or if
# any report was found.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=${JOBS:-$(nproc)}
build=build-asan
logs=$PWD/$build/sanitizer-logs

# RelWithDebInfo at -O1: line numbers in every stack, fast enough for the whole suite. NDEBUG as in
# the release build, so CGAL and Eigen run as they do there.
# shellcheck disable=SC2086
cmake -S . -B "$build" -DCOVMAP_SANITIZE=ON -DCOVMAP_BUILD_BENCH=OFF \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g -DNDEBUG" \
  ${CMAKE_ARGS:-} >/dev/null
cmake --build "$build" -j"$jobs"

rm -rf "$logs"
mkdir -p "$logs"
export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:check_initialization_order=1:strict_init_order=1:detect_stack_use_after_return=1:log_path=$logs/asan"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:log_path=$logs/ubsan"

status=0
ctest --test-dir "$build" --output-on-failure -j"$jobs" "$@" || status=$?

reports=$(find "$logs" -type f | sort)
if [ -n "$reports" ]; then
  echo "sanitizer reports in $logs:"
  for f in $reports; do
    echo "==== $f"
    head -60 "$f"
  done
  status=1
fi
if grep -n "runtime error:" "$build/Testing/Temporary/LastTest.log"; then
  echo "UBSan reports above: $build/Testing/Temporary/LastTest.log"
  status=1
fi
[ "$status" -eq 0 ] && echo "sanitize: the whole suite ran clean under ASan + UBSan"
exit "$status"
