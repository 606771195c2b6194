#!/usr/bin/env bash
# Configures (once) and builds a preset: tools/build.sh [release|dev|asan|tsan]. Release by default.
set -euo pipefail
cd "$(dirname "$0")/.."
preset=${1:-release}
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
[[ -f build/$preset/build.ninja ]] || cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset" -j "$(nproc)"
