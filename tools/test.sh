#!/usr/bin/env bash
# Sets up, builds (Release, and the sanitize preset's clang ASan + UBSan build) and runs every
# test through ctest, the ASan + UBSan suites and a short fuzzing run included (label
# "sanitizers"). Tests labelled "heavy" are skipped here; run them with:
#   ctest --test-dir build/release -L heavy
set -euo pipefail
cd "$(dirname "$0")/.."
tools/setup.sh
tools/build.sh release
tools/build.sh sanitize
ctest --preset release
