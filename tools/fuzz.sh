#!/usr/bin/env bash
# Builds the libFuzzer harnesses (clang, ASan + UBSan; the sanitize preset) and runs them side by
# side, one core each:
#   tools/fuzz.sh [SECONDS] [HARNESS...]        explore for SECONDS each (default 60)
#   tools/fuzz.sh --runs N [HARNESS...]         N inputs each from seed 1: the same inputs every
#                                               time, so a CI failure is a real, replayable finding
# Harnesses: msh_reader, block_spec, batch_manifest. The committed seed corpus (fuzz/corpus/NAME) is read, never
# written: new inputs go to build/sanitize/corpus-NAME, findings to build/sanitize/findings-NAME.
# Exit 1 on any finding.
set -euo pipefail
cd "$(dirname "$0")/.."
budget=(-max_total_time=60)
if [[ ${1:-} == --runs ]]; then
  [[ ${2:-} =~ ^[0-9]+$ ]] || { echo "fuzz.sh: --runs needs a count" >&2; exit 2; }
  budget=(-runs="$2" -seed=1); shift 2
elif [[ ${1:-} =~ ^[0-9]+$ ]]; then
  budget=(-max_total_time="$1"); shift
fi
harnesses=("$@")
[[ ${#harnesses[@]} -gt 0 ]] || harnesses=(msh_reader block_spec batch_manifest)
command -v clang++ >/dev/null || { echo "fuzz.sh: clang++ is missing (tools/setup.sh installs it)" >&2; exit 2; }
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
[[ -f build/sanitize/build.ninja ]] || cmake --preset sanitize >/dev/null
cmake --build --preset sanitize -j "$(nproc)" --target "${harnesses[@]/#/fuzz_}" >/dev/null
fuzz_one() {  # harness: one run, its statistics printed; exit 1 on a finding
  local h=$1 seeds=fuzz/corpus/$1 work=build/sanitize/corpus-$1 findings=build/sanitize/findings-$1
  # A deterministic run starts from the committed seeds alone, not from what earlier runs kept.
  if [[ ${budget[0]} == -runs=* ]]; then work=build/sanitize/replay-$h; rm -rf "$work"; fi
  mkdir -p "$work" "$findings"
  # -timeout: an input that takes more than 10 s is a finding too (a reader must not hang).
  if ! build/sanitize/fuzz/fuzz_"$h" "$work" "$seeds" "${budget[@]}" -timeout=10 \
       -rss_limit_mb=2048 -artifact_prefix="$findings/" -print_final_stats=1 2>build/sanitize/log-"$h".txt; then
    echo "fuzz $h: ${budget[*]}: FINDING (log build/sanitize/log-$h.txt, input in $findings/)" >&2
    tail -n 30 build/sanitize/log-"$h".txt >&2
    return 1
  fi
  echo "fuzz $h: ${budget[*]}"
  grep -E "stat::number_of_executed_units|stat::peak_rss_mb" build/sanitize/log-"$h".txt | sed "s/^/  /" || true
}
for h in "${harnesses[@]}"; do
  [[ -d fuzz/corpus/$h ]] || { echo "fuzz.sh: no seed corpus fuzz/corpus/$h" >&2; exit 2; }
done
# The harnesses run side by side (libFuzzer uses one core each), each one's report printed whole.
status=0
pids=()
for h in "${harnesses[@]}"; do
  fuzz_one "$h" >build/sanitize/report-"$h".txt 2>&1 &
  pids+=($!)
done
for k in "${!harnesses[@]}"; do
  if wait "${pids[$k]}"; then
    cat build/sanitize/report-"${harnesses[$k]}".txt
  else
    status=1
    cat build/sanitize/report-"${harnesses[$k]}".txt >&2
  fi
done
exit $status
