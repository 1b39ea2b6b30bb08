#!/usr/bin/env bash
# The smallest configuration (no DDS, no ONNX Runtime or OpenVINO, no viewer) builds, and its command line solves the built-in
# sample and refuses what this build cannot do with a clear message. Unoptimised, without tests: what it checks is
# that the optional parts stay optional (every #ifdef branch compiles and links); the full test suite runs elsewhere.
set -euo pipefail
source "$(dirname "$0")/common.sh"
DIR="${OCTOCAP_MINIMAL_BUILD_DIR:-$ROOT/build-minimal}"
bash "$ROOT/scripts/fetch-real-data.sh"    # the real take, for the images check below (cached)
bash "$ROOT/scripts/fetch-real-videos.sh"
if [ ! -f "$DIR/build.ninja" ]; then
  cmake -S "$ROOT" -B "$DIR" -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG=-O0 -DCMAKE_C_FLAGS_DEBUG=-O0 \
    -DOCTOCAP_WITH_DDS=OFF -DOCTOCAP_WITH_ONNX=OFF -DOCTOCAP_WITH_OPENVINO=OFF -DOCTOCAP_WITH_VIEWER=OFF -DOCTOCAP_TESTS=OFF -DOCTOCAP_UNITY=OFF \
    -DOCTOCAP_BENCH=OFF >/dev/null
fi
cmake --build "$DIR" -j "$JOBS" --target octocap_cli
cli="$DIR/tools/octocap/octocap"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
"$cli" solve --calibration "$ROOT/data/sample/calibration.toml" --keypoints "$ROOT/data/sample/keypoints" \
  --output "$out/sample.trc" --ground-truth "$ROOT/data/sample/ground_truth.csv" --quiet | tee "$out/solve.log"
grep -q "MPJPE" "$out/solve.log" && [ -s "$out/sample.trc" ]
# The real take's videos (fetched by scripts/test.sh): pictures this build cannot detect in.
if "$cli" solve --images "$ROOT/.cache/pose2sim-0.10.49/Demo_SinglePerson/videos" --frames 2 \
     --calibration "$ROOT/.cache/pose2sim-0.4.15/Demo/calibration/Calib_qualisys.toml" \
     --output "$out/x.trc" >"$out/images.log" 2>&1; then
  echo "the build without ONNX Runtime solved from images"; exit 1
fi
grep "built without ONNX Runtime" "$out/images.log"
if "$cli" live --calibration "$ROOT/data/sample/calibration.toml" --camera dds://a/b --camera dds://a/c \
     --camera dds://a/d --camera dds://a/e --camera dds://a/f >"$out/live.log" 2>&1; then
  echo "the build without DDS took remote cameras"; exit 1
fi
grep "remote cameras need DDS" "$out/live.log"
echo "== smallest configuration: builds, solves the sample, refuses images and remote cameras clearly"
