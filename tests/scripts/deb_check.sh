#!/usr/bin/env bash
# `cpack -G DEB` on a Release build tree: the package's Depends name the runtime libraries and
# resolve against the Debian archive as seen by a machine with nothing installed, and the programs
# and module extracted from it run from a temporary root.
# Usage: deb_check.sh CPACK BUILD_DIR PYTHON
set -euo pipefail
cpack=$1 build=$2 python=$3
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "deb_check: $*" >&2; exit 1; }

"$cpack" -G DEB --config "$build/CPackConfig.cmake" -B "$dir/pkg" >"$dir/cpack.log" || { cat "$dir/cpack.log" >&2; fail "cpack failed"; }
debs=("$dir"/pkg/tubemesh_*.deb)
[[ ${#debs[@]} -eq 1 && -f ${debs[0]} ]] || fail "no single tubemesh_*.deb written"
deb=${debs[0]}

depends=$(dpkg-deb -f "$deb" Depends)
names=$(tr ',' '\n' <<<"$depends" | awk '{print $1}')
for p in libocct-data-exchange-7.6 libocct-foundation-7.6 libtbb12 libfmt9 libstdc++6 python3 python3-numpy; do
  grep -qxF "$p" <<<"$names" || fail "Depends lacks $p: $depends"
done
dpkg-deb --contents "$deb" >"$dir/contents.txt"
grep -q " ./usr/bin/tubemesh$" "$dir/contents.txt" || fail "no /usr/bin/tubemesh in the package"
grep -qE " ./usr/lib/python3[.0-9]*/dist-packages/tubemesh\..*\.so$" "$dir/contents.txt" || fail "no Python module in the package"
! grep -qF "$build" "$dir/contents.txt" || fail "the package holds a path of the build tree"

# apt's own resolver on an empty dpkg status (a fresh machine): every dependency has an installable
# version in the configured archive.
: >"$dir/status"
apt-get -s -o Dir::State::status="$dir/status" install "$deb" >"$dir/apt.log" 2>&1 ||
  { cat "$dir/apt.log" >&2; fail "apt-get cannot resolve the package's dependencies on a fresh machine"; }

dpkg-deb -x "$deb" "$dir/root"
mkdir "$dir/work"
cd "$dir/work"
"$dir/root/usr/bin/tubemesh" make-block --preset straight-pipe -o pipe.step >/dev/null
"$dir/root/usr/bin/tubemesh" mesh pipe.step -o pipe.msh --quiet
"$dir/root/usr/bin/tubemesh" check pipe.msh | grep -q "valid and conforming" || fail "the packaged tubemesh wrote no valid mesh"
PYTHONPATH=$(echo "$dir"/root/usr/lib/python3*/dist-packages) "$python" -c '
import sys, tubemesh
assert tubemesh.__file__.startswith(sys.argv[1]), tubemesh.__file__
' "$dir/root/" || fail "the packaged Python module does not import"
