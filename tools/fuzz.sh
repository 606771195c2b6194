#!/usr/bin/env bash
# Builds the libFuzzer harnesses (clang, ASan + UBSan; the fuzz preset) and runs each for
# SECONDS (default 60): tools/fuzz.sh [SECONDS] [HARNESS...]. Harnesses: msh_reader, block_spec.
# The committed seed corpus (fuzz/corpus/NAME) is read, never written: new inputs go to
# build/fuzz/corpus-NAME, findings to build/fuzz/findings-NAME. Exit 1 on any finding.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
harnesses=("$@")
[[ ${#harnesses[@]} -gt 0 ]] || harnesses=(msh_reader block_spec)
command -v clang++ >/dev/null || { echo "fuzz.sh: clang++ is missing (tools/setup.sh installs it)" >&2; exit 2; }
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
[[ -f build/fuzz/build.ninja ]] || cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j "$(nproc)" >/dev/null
status=0
for h in "${harnesses[@]}"; do
  work=build/fuzz/corpus-$h findings=build/fuzz/findings-$h
  mkdir -p "$work" "$findings"
  echo "fuzz $h: ${seconds} s"
  # -timeout: an input that takes more than 10 s is a finding too (a reader must not hang).
  if ! build/fuzz/fuzz/fuzz_"$h" "$work" "fuzz/corpus/$h" -max_total_time="$seconds" -timeout=10 \
       -rss_limit_mb=2048 -artifact_prefix="$findings/" -print_final_stats=1 2>build/fuzz/log-"$h".txt; then
    status=1
    echo "fuzz $h: FINDING (log build/fuzz/log-$h.txt, input in $findings/)" >&2
  fi
  grep -E "stat::number_of_executed_units|stat::peak_rss_mb" build/fuzz/log-"$h".txt | sed "s/^/  /" || true
done
exit $status
