#!/usr/bin/env bash
# Sets up, builds (Release) and runs the main job.
# Until the meshing pipeline lands, the main job checks a small hand-made hybrid mesh
# (hex + pyramid + tets) from the test suite's samples, and prints its report.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/setup.sh
tools/build.sh release >/dev/null
out=build/release/run
mkdir -p "$out"
build/release/tests/write_sample_mesh conforming "$out/conforming_patch.msh"
exec build/release/tools/tubemesh check "$out/conforming_patch.msh"
