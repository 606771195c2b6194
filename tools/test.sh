#!/usr/bin/env bash
# Sets up, builds (Release) and runs every test through ctest. Tests labelled "heavy" are
# skipped here; run them with: ctest --test-dir build/release -L heavy
set -euo pipefail
cd "$(dirname "$0")/.."
tools/setup.sh
tools/build.sh release
ctest --preset release
