#!/usr/bin/env bash
# `cmake --install` into a temporary prefix, then the installed programs and module run from a
# folder outside the source and build trees, found through PATH and PYTHONPATH under the prefix
# only. Usage: install_check.sh CMAKE BUILD_DIR PYTHON PYTHON_DIR [MPI_PROGRAM]
# (PYTHON_DIR: the module's folder relative to the prefix, empty when the module is not built).
set -euo pipefail
cmake=$1 build=$2 python=$3 pydir=$4 mpi=${5:-}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
prefix=$dir/prefix
fail() { echo "install_check: $*" >&2; exit 1; }

"$cmake" --install "$build" --prefix "$prefix" >"$dir/install.log" || { cat "$dir/install.log" >&2; fail "cmake --install failed"; }
programs=(tubemesh)
[[ -n $mpi ]] && programs+=(tubemesh-mpi)
for p in "${programs[@]}"; do
  [[ -x $prefix/bin/$p ]] || fail "$p is not installed in bin/"
  # Every shared library found, none in the build tree.
  ! LC_ALL=C ldd "$prefix/bin/$p" | grep -q "not found" || fail "$p: a library is not found"
  ! readelf -d "$prefix/bin/$p" | grep -E "RPATH|RUNPATH" | grep -qF "$build" || fail "$p: RPATH into the build tree"
done

mkdir "$dir/work"
cd "$dir/work"
export PATH="$prefix/bin:$PATH"
unset PYTHONPATH
[[ $(command -v tubemesh) == "$prefix/bin/tubemesh" ]] || fail "PATH does not find the installed tubemesh"
tubemesh make-block --preset straight-pipe -o pipe.step >/dev/null
tubemesh mesh pipe.step -o pipe.msh --html pipe.html --quiet
tubemesh check pipe.msh | grep -q "valid and conforming" || fail "the installed tubemesh wrote no valid mesh"
# The report's page carries three.js and Chart.js inside the program, not from the build machine.
grep -q "THREE" pipe.html && grep -q "Chart" pipe.html || fail "the HTML report lacks three.js or Chart.js"
[[ -z $mpi ]] || tubemesh-mpi --help >/dev/null || fail "the installed tubemesh-mpi does not start"

if [[ -n $pydir ]]; then
  PYTHONPATH=$prefix/$pydir "$python" -c '
import sys, tubemesh
assert tubemesh.__file__.startswith(sys.argv[1]), tubemesh.__file__
r = tubemesh.mesh("pipe.step")
assert len(r.hexes) > 0 and len(r.pyramids) > 0 and len(r.tets) > 0
' "$prefix/" || fail "the installed Python module did not import or mesh"
fi
