#!/usr/bin/env bash
# The whole test suite under AddressSanitizer + UndefinedBehaviorSanitizer,
# built with clang together with the libFuzzer targets (whose corpora replay
# as tests), then every fuzz target for a bounded time.
#
#   scripts/sanitized-tests.sh [FUZZ_SECONDS]      (default 30 per target)
#
# BUILD_DIR (default build-sanitize) is the build tree. Any sanitizer report,
# failing test or fuzz crash makes the script fail.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-30}
build=${BUILD_DIR:-build-sanitize}

cmake -S . -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DBANDLIGHT_FUZZ=ON -DBANDLIGHT_BUILD_BENCH=OFF
cmake --build "$build"

supp="$PWD/tests/sanitizers"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:check_initialization_order=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$supp/lsan.supp:print_suppressions=0"
ctest --test-dir "$build" -j"$(nproc)" --output-on-failure
scripts/fuzz.sh "$build" "$seconds"
