#!/usr/bin/env bash
# Builds and runs the fast tests under AddressSanitizer + UBSan (the sanitize preset: clang, the
# build the fuzz harnesses share), and the parallel kernels' tests (Delaunay, tet step, sweep,
# pyramids) under ThreadSanitizer:
#   tools/check-sanitizers.sh [asan|tsan|all]   (default all; CI runs asan)
# Any sanitizer report fails the run (exit 1). The asan part is clean; the tsan part is not yet:
# Debian's oneTBB is not instrumented, so TSan also reports the hand-offs inside its scheduler
# (tools/tsan-suppressions.txt drops those whose top frame is oneTBB's; the ones left, from a
# task's first read of data the spawning thread wrote, need a TSan-built oneTBB to go away).
set -euo pipefail
cd "$(dirname "$0")/.."
which=${1:-all}
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1

# The engine's unit suites: seconds each in a Release build, no OpenCASCADE. Longest under ASan first,
# so that the queue ends on short shards.
asan_tests=(test_predicates test_delaunay test_sweep test_tets_optimise test_tets_recovery test_mesh_io test_surface
            test_tets_refine test_tets_relaxation test_mesh_store test_quality test_pyramids test_mesh_check
            test_tets_ring_triangulation)
# The kernels that run in parallel: Delaunay passes, tet refinement and relaxation, recovery,
# the sweep (its determinism tests run it on several threads), the pyramid batches.
tsan_tests=(test_delaunay test_tets_refine test_tets_relaxation test_tets_recovery test_sweep test_pyramids)

run_one() {  # preset, suite, shard: one gtest shard of a suite, its output kept in a log
  local log=build/$1/sanitizer-$2-$3.txt
  if GTEST_TOTAL_SHARDS=$shards GTEST_SHARD_INDEX=$3 build/"$1"/tests/"$2" --gtest_brief=1 >"$log" 2>&1; then
    echo "$1 $2 shard $3: clean"
  else
    echo "$1 $2 shard $3: FAILED, see $log" >&2
    return 1
  fi
}
export -f run_one

run_suite() {  # preset, tests...: built (a no-op when tools/test.sh built them), then run on every core
  local preset=$1
  shift
  [[ -f build/$preset/build.ninja ]] || cmake --preset "$preset" >/dev/null
  cmake --build --preset "$preset" -j "$(nproc)" --target "$@" >/dev/null
  # Every suite in one shard per core, all shards in one queue: the longest suite (the predicates'
  # exact-arithmetic comparisons, minutes under ASan) no longer runs alone on one core at the end.
  export shards=$(nproc)
  local t k
  for t in "$@"; do for ((k = 0; k < shards; ++k)); do echo "$t $k"; done; done |
    xargs -P "$shards" -L 1 bash -c 'run_one "$0" "$1" "$2"' "$preset"
}

status=0
if [[ $which == asan || $which == all ]]; then
  # halt_on_error: the first report fails the suite; UBSan reports are errors too.
  ASAN_OPTIONS=detect_leaks=1:halt_on_error=1 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
    run_suite sanitize "${asan_tests[@]}" || status=1
fi
if [[ $which == tsan || $which == all ]]; then
  TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1 suppressions=$PWD/tools/tsan-suppressions.txt" \
    run_suite tsan "${tsan_tests[@]}" || status=1
fi
exit $status
