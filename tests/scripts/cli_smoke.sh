#!/usr/bin/env bash
# The fast tier's end-to-end run: build a block, mesh it, and let `tubemesh check` verify the
# written mesh (every cell positive, every face matched). Usage: cli_smoke.sh TUBEMESH
set -euo pipefail
cli=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$cli" make-block --preset straight-pipe -o "$dir/pipe.step" >/dev/null
"$cli" mesh "$dir/pipe.step" -o "$dir/pipe.msh" --quiet
"$cli" check "$dir/pipe.msh" >"$dir/check.txt"
grep -q "valid and conforming" "$dir/check.txt" && grep -q " hexahedra, " "$dir/check.txt" && grep -q " pyramids, " "$dir/check.txt" ||
  { echo "cli_smoke: the check found no valid hybrid mesh:" >&2; cat "$dir/check.txt" >&2; exit 1; }
