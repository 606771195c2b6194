#!/usr/bin/env bash
# Meshes built blocks one after another and records how each run ended, one TSV line per block:
# kind, seed, exit status, `tubemesh check`'s exit status (- when nothing was written), seconds,
# warning lines, the first error line, the pipes' wall area and the part of it under hex rings
# (from the JSON report; - when nothing was written). Run two at a time on two cores (one thread each):
#   bench/hostile_sweep.sh TUBEMESH OUTDIR random|close FIRST LAST
set -u
cli=$1 out=$2 kind=$3 first=$4 last=$5
mkdir -p "$out"
flag=()
[[ $kind == close ]] && flag=(--close)
for seed in $(seq "$first" "$last"); do
  dir=$(mktemp -d)
  "$cli" make-block --seed "$seed" "${flag[@]}" -o "$dir/b.step" >/dev/null 2>&1
  start=$(date +%s.%N)
  "$cli" mesh "$dir/b.step" -o "$dir/b.msh" --report "$dir/r.json" --threads 1 >/dev/null 2>"$dir/err"
  status=$?
  seconds=$(echo "$(date +%s.%N) - $start" | bc)
  check=-
  if [[ $status == 0 ]]; then "$cli" check "$dir/b.msh" >/dev/null 2>&1; check=$?; fi
  message=$(grep -v -e "^tubemesh: warning" -e "^progress:" "$dir/err" | head -n 1 | cut -c1-300)
  warnings=$(grep -c "^tubemesh: warning" "$dir/err")
  wall=- ring=-
  if [[ -f $dir/r.json ]]; then
    wall=$(jq '[.pipes[].wall_area] | add // 0' "$dir/r.json")
    ring=$(jq '[.pipes[] | .wall_area * .ring_share] | add // 0' "$dir/r.json")
  fi
  printf '%s\t%s\t%s\t%s\t%.1f\t%s\t%s\t%s\t%s\n' "$kind" "$seed" "$status" "$check" "$seconds" "$warnings" \
    "$message" "$wall" "$ring" >>"$out/$kind.tsv"
  rm -rf "$dir"
done
