#!/usr/bin/env bash
# The sanitizer pass: the whole configuration built with clang under AddressSanitizer + UndefinedBehaviorSanitizer,
# with the libFuzzer targets (fuzz/) in the same build; the whole test suite runs instrumented, then every fuzz target
# for a bounded time (scripts/fuzz.sh). One instrumented build serves both: the two were separate builds before, and
# a build is the largest cost of CI on two cores. Usage: scripts/sanitize.sh [FUZZ_SECONDS_PER_TARGET] (default 15)
set -euo pipefail
source "$(dirname "$0")/common.sh"
FUZZ_SECONDS="${1:-15}"
export OCTOCAP_SANITIZE_BUILD_DIR="${OCTOCAP_SANITIZE_BUILD_DIR:-$ROOT/build-asan}"
CC="$(command -v clang-14 || command -v clang)"
CXX="$(command -v clang++-14 || command -v clang++)"
export CC CXX
# -O1 -g1: ASan's recommended optimisation and line tables for the reports.
# System OpenGL libraries leak a little on their own: .ci/lsan.supp names them (nothing of octocap's).
# Two tests judge the accuracy of the live pipeline fed in real time by real servers (four RTSP cameras at 60 fps, and
# capture nodes on them); instrumented, the detector runs at a third of its speed, decoding falls behind and sets
# lose views, so what they would measure here is the sanitizer's slowdown. They run in the normal pass; under the
# sanitizers the same code (feeds, remote feeds, nodes, the engine) runs in the other live and node tests.
OCTOCAP_CTEST_EXCLUDE="four RTSP cameras on loopback|capture nodes: two node processes" \
LSAN_OPTIONS="suppressions=$ROOT/.ci/lsan.supp:print_suppressions=0" OCTOCAP_SKIP_CSHARP=1 \
  OCTOCAP_BUILD_DIR="$OCTOCAP_SANITIZE_BUILD_DIR" bash "$ROOT/scripts/test.sh" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1" -DOCTOCAP_FUZZ=ON -DOCTOCAP_BENCH=OFF
bash "$ROOT/scripts/fuzz.sh" "$FUZZ_SECONDS"
