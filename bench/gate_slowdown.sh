#!/usr/bin/env bash
# The gate's own acceptance test: a second build whose Delaunay insertion does about
# 25 % more work (CMake option TUBEMESH_BENCH_SLOWDOWN) must make bench/bench-compare fail
# with exit status 1. A pass, or a gate that cannot run (status 2), fails this test.
# Usage: gate_slowdown.sh SOURCE_DIR BUILD_DIR CXX_COMPILER
set -euo pipefail
src=$1 build=$2 cxx=$3
launcher=()
if command -v ccache >/dev/null; then
    export CCACHE_BASEDIR="$src" CCACHE_NOHASHDIR=1
    launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
cmake -S "$src" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER="$cxx" \
    -DTUBEMESH_BUILD_TESTS=OFF -DTUBEMESH_BENCH_SLOWDOWN=25 "${launcher[@]}" >/dev/null
# Two jobs: the machines running this have two cores, shared.
cmake --build "$build" -j2 --target bench_gate
status=0
"$src/bench/bench-compare" --build-dir "$build" || status=$?
if [ "$status" -eq 1 ]; then
    echo "bench_gate_slowdown: the gate caught the 25 % slowdown, as it must"
    exit 0
fi
echo "bench_gate_slowdown: expected the gate to fail with status 1 on the slowed-down build, got $status" >&2
exit 1
