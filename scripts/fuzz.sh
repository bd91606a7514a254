#!/usr/bin/env bash
# Runs the libFuzzer targets of a fuzz build for a bounded time each.
#
#   scripts/fuzz.sh BUILD_DIR SECONDS [TARGET...]
#
# BUILD_DIR was configured with -DBANDLIGHT_FUZZ=ON (scripts/sanitized-tests.sh
# makes one). New inputs go to BUILD_DIR/fuzz-work/TARGET; the corpus in
# tests/fuzz/corpus/TARGET is read, not written (copy interesting finds in by
# hand). Crashes are saved as BUILD_DIR/fuzz-work/TARGET/crash-* and make the
# script fail. Prints one line per target: executions and seconds.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:?usage: scripts/fuzz.sh BUILD_DIR SECONDS [TARGET...]}
seconds=${2:?usage: scripts/fuzz.sh BUILD_DIR SECONDS [TARGET...]}
shift 2
targets=("$@")
if ((${#targets[@]} == 0)); then
  targets=(fuzz_csv fuzz_cgats fuzz_scene fuzz_method fuzz_config fuzz_camera fuzz_spectral_channels)
fi

status=0
for t in "${targets[@]}"; do
  exe="$build/tests/fuzz/$t"
  [[ -x $exe ]] || { echo "fuzz.sh: $exe not built (configure with -DBANDLIGHT_FUZZ=ON)" >&2; exit 2; }
  work="$build/fuzz-work/$t"
  mkdir -p "$work"
  log="$build/fuzz-work/$t.log"  # beside the corpus, not in it
  if ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1} \
     "$exe" "$work" "tests/fuzz/corpus/$t" -max_total_time="$seconds" -timeout=10 \
            -rss_limit_mb=4096 -artifact_prefix="$work/" -print_final_stats=1 >"$log" 2>&1; then
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
    echo "$t: ${runs:-?} executions in ${seconds} s, clean"
  else
    echo "$t: FAILED, see $log and $work/crash-*" >&2
    tail -40 "$log" >&2
    status=1
  fi
done
exit $status
