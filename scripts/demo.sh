#!/usr/bin/env bash
# One command: installs what is missing, builds, and solves the built-in sample recording
# (5 cameras, 90 frames of real CMU motion, noisy OpenPose detections with a bystander) into 3D, then
# real multi-camera videos from pixels to 3D with the ONNX Runtime detector, offline and as live cameras.
set -euo pipefail
source "$(dirname "$0")/common.sh"
ensure_deps
bash "$ROOT/scripts/fetch-models.sh"
bash "$ROOT/scripts/fetch-real-data.sh"
bash "$ROOT/scripts/fetch-real-videos.sh"
configure_and_build "$BUILD_DIR" >/dev/null
mkdir -p "$ROOT/out"
echo "== octocap solve on data/sample"
"$BUILD_DIR/tools/octocap/octocap" solve \
  --calibration "$ROOT/data/sample/calibration.toml" \
  --keypoints "$ROOT/data/sample/keypoints" \
  --output "$ROOT/out/sample.trc" --csv "$ROOT/out/sample.csv" \
  --ground-truth "$ROOT/data/sample/ground_truth.csv" --rate 30 "$@"
echo
echo "== octocap solve --images: Pose2Sim's real 4-camera videos (1088x1920, 60 fps), pixels to 3D"
rm -rf "$ROOT/out/debug"
"$BUILD_DIR/tools/octocap/octocap" solve \
  --images "$ROOT/.cache/pose2sim-0.10.49/Demo_SinglePerson/videos" \
  --calibration "$ROOT/.cache/pose2sim-0.4.15/Demo/calibration/Calib_qualisys.toml" \
  --output "$ROOT/out/videos.trc" --csv "$ROOT/out/videos.csv" --bvh "$ROOT/out/videos.bvh" --rate 60 \
  --detect-mode crop --frames 40 --debug-images "$ROOT/out/debug" --quiet
echo "  debug images (detections + reprojected 3D): out/debug/"
echo
echo "== octocap live: the same four videos as cameras (each played at its own 60 fps, as its camera delivered it),"
echo "   solved while they play: status line, per-stage table, one line per camera"
"$BUILD_DIR/tools/octocap/octocap" live \
  --calibration "$ROOT/.cache/pose2sim-0.4.15/Demo/calibration/Calib_qualisys.toml" \
  $(for c in 1 2 3 4; do echo --camera "$ROOT/.cache/pose2sim-0.10.49/Demo_SinglePerson/videos/cam0$c.mp4"; done) \
  --model movenet-lightning --output "$ROOT/out/live.trc"
echo
echo "== octocap-viewer: the default character on that motion, rendered headless (OSMesa)"
rm -rf "$ROOT/out/viewer"
"$BUILD_DIR/samples/viewer/octocap-viewer" --motion "$ROOT/out/videos.csv" --frames "$ROOT/out/viewer" \
  --skeleton --size 640x480
