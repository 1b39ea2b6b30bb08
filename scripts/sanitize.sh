#!/usr/bin/env bash
# The sanitizer pass: the whole configuration built with clang under AddressSanitizer + UndefinedBehaviorSanitizer,
# with the libFuzzer targets (fuzz/) in the same build; the whole test suite runs instrumented, then every fuzz target
# for a bounded time (scripts/fuzz.sh). One instrumented build serves both: the two were separate builds before, and
# a build is the largest cost of CI on two cores. Usage: scripts/sanitize.sh [FUZZ_SECONDS_PER_TARGET] (default 15)
set -euo pipefail
source "$(dirname "$0")/common.sh"
FUZZ_SECONDS="${1:-15}"
export OCTOCAP_SANITIZE_BUILD_DIR="$SANITIZE_BUILD_DIR"
use_clang
# The configuration is common.sh's SANITIZE_CMAKE_ARGS: the SDK, its command-line tools and the DDS sample; not the
# viewer sample (assimp, OpenGL): a fifth of the instrumented build, and what CI can spend.
# System libraries leak a little on their own: .ci/lsan.supp names them (nothing of octocap's).
# Two tests judge the accuracy of the live pipeline fed in real time by real servers (four RTSP cameras at 60 fps, and
# capture nodes on them); instrumented, the detector runs at a third of its speed, decoding falls behind and sets
# lose views, so what they would measure here is the sanitizer's slowdown. They run in the normal pass; under the
# sanitizers the same code (feeds, remote feeds, nodes, the engine) runs in the other live and node tests.
# Three more are left to the normal pass, compute-bound runs of code that other tests run instrumented: extrinsics
# from a person on synthetic rigs of 4 and 6 cameras (3.5 minutes instrumented: Ceres' automatic derivatives at -O1;
# calibrate_extrinsics runs instrumented on the real take's keypoints and for the scale), the same through
# octocap-calibrate on the sample, and the lab's cameras calibrated from their own videos end to end (its calibration
# and detection run instrumented in the tests of each).
# Two more for time (CI is kept well under 30 minutes; instrumented test times from build-asan's LastTest.log): the
# command line solving the real two-person videos twice over (116 s; the same association, tracks and detector paths
# run instrumented in `octocap live --people auto` on those videos and in the crowd tests), and the programs built
# against the older headers but the first and the last (each solves the sample at a thirteenth of its speed, 15 s;
# the 0.3 header, whose session config nests the detector's, and the last released one stay).
OCTOCAP_CTEST_EXCLUDE="four RTSP cameras on loopback|capture nodes: two node processes|extrinsics from a person: cameras recovered|octocap-calibrate extrinsics recovers the sample|markerless end to end: the lab's cameras|solve --people auto on Pose2Sim's real two-person videos|against the (0\.1|0\.2|0\.2-vmc|0\.3-last|1\.1|1\.2|1\.3|1\.4|1\.5) header" \
LSAN_OPTIONS="suppressions=$ROOT/.ci/lsan.supp:print_suppressions=0" OCTOCAP_SKIP_CSHARP=1 \
  OCTOCAP_BUILD_DIR="$SANITIZE_BUILD_DIR" bash "$ROOT/scripts/test.sh" "${SANITIZE_CMAKE_ARGS[@]}"
bash "$ROOT/scripts/fuzz.sh" "$FUZZ_SECONDS"
