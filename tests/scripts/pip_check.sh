#!/usr/bin/env bash
# `pip install` of a copy of the source tree into a fresh virtual environment, offline: the
# backend (setuptools, wheel) and numpy come from Debian's packages through
# --system-site-packages; then the module imports and meshes from outside the trees.
# Usage: pip_check.sh SOURCE_DIR PYTHON
set -euo pipefail
src=$1 python=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "pip_check: $*" >&2; exit 1; }

mkdir "$dir/src"
tar -C "$src" --exclude=./build --exclude=./.git --exclude='*.egg-info' -cf - . | tar -C "$dir/src" -xf -
# The copy's objects are the checkout's: ccache serves them when the paths are made relative.
if command -v ccache >/dev/null; then
  export CMAKE_ARGS="-DCMAKE_CXX_COMPILER_LAUNCHER=ccache" CCACHE_BASEDIR="$dir/src" CCACHE_NOHASHDIR=1
fi
"$python" -m venv --system-site-packages "$dir/v"
"$dir/v/bin/pip" install --no-build-isolation --no-index -q "$dir/src" >"$dir/pip.log" 2>&1 ||
  { tail -40 "$dir/pip.log" >&2; fail "pip install failed"; }

mkdir "$dir/work"
cd "$dir/work"
unset PYTHONPATH
"$dir/v/bin/python" -c '
import sys, tubemesh
assert tubemesh.__file__.startswith(sys.argv[1]), tubemesh.__file__
r = tubemesh.mesh("paper-ex3")
assert len(r.hexes) > 0 and len(r.pyramids) > 0 and len(r.tets) > 0
' "$dir/v/" || fail "the pip-installed module did not import or mesh"
"$dir/v/bin/pip" show tubemesh | grep -qx "Version: $(sed -n 's/^project(tubemesh VERSION \([0-9.]*\).*/\1/p' "$src/CMakeLists.txt")" ||
  fail "pip records another version than CMakeLists.txt's"
