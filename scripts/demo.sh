#!/usr/bin/env bash
# One command: installs what is missing, builds, and solves the built-in sample recording
# (5 cameras, 90 frames of real CMU motion, noisy OpenPose detections with a bystander) into 3D.
set -euo pipefail
source "$(dirname "$0")/common.sh"
ensure_deps
configure_and_build "$BUILD_DIR" >/dev/null
mkdir -p "$ROOT/out"
echo "== octocap solve on data/sample"
"$BUILD_DIR/tools/octocap/octocap" solve \
  --calibration "$ROOT/data/sample/calibration.toml" \
  --keypoints "$ROOT/data/sample/keypoints" \
  --output "$ROOT/out/sample.trc" --csv "$ROOT/out/sample.csv" \
  --ground-truth "$ROOT/data/sample/ground_truth.csv" --rate 30 "$@"
