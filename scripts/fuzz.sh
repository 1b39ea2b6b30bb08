#!/usr/bin/env bash
# Runs every libFuzzer target (fuzz/) for a bounded time from its committed corpus (fuzz/corpus/<target>, never
# modified here), in the sanitizer build (clang, ASan + UBSan; scripts/sanitize.sh makes it, with the test suite).
# A crash, leak, UB report or timeout fails the script and leaves the input in <build>/crashes/.
# Usage: scripts/fuzz.sh [SECONDS_PER_TARGET] (default 20)
set -euo pipefail
source "$(dirname "$0")/common.sh"
SECONDS_PER_TARGET="${1:-20}"
DIR="$SANITIZE_BUILD_DIR"
if ! grep -q "OCTOCAP_FUZZ:BOOL=ON" "$DIR/CMakeCache.txt" 2>/dev/null; then
  use_clang
  cmake -S "$ROOT" -B "$DIR" -G Ninja "${SANITIZE_CMAKE_ARGS[@]}" >/dev/null
fi
targets=(calibration openpose_json motion model_card board_spec solve)
cmake --build "$DIR" -j "$JOBS" --target "${targets[@]/#/fuzz_}"
mkdir -p "$DIR/crashes"
for target in "${targets[@]}"; do
  work="$(mktemp -d)"
  echo "== fuzz_$target for ${SECONDS_PER_TARGET} s"
  "$DIR/fuzz/fuzz_$target" -max_total_time="$SECONDS_PER_TARGET" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
    -print_final_stats=1 -artifact_prefix="$DIR/crashes/fuzz_${target}-" "$work" "$ROOT/fuzz/corpus/$target" 2>&1 |
    grep -E "^(#[0-9]+ +DONE|stat::number_of_executed_units|==[0-9]+==ERROR|SUMMARY|artifact_prefix|Test unit written)" || true
  status=${PIPESTATUS[0]}
  rm -rf "$work"
  [ "$status" = 0 ] || { echo "fuzz_$target found a crash (see $DIR/crashes/)"; exit 1; }
done
echo "== fuzzing done: no crash in ${SECONDS_PER_TARGET} s per target"
