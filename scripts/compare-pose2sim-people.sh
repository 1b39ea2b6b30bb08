#!/usr/bin/env bash
# octocap's several-people solve against Pose2Sim's own person association and triangulation (pose2sim 0.10.49 from
# PyPI, in a venv of its own under .cache), on the same 2D detections of Pose2Sim's real two-person take (MoveNet
# MultiPose per view, written as OpenPose JSON by octocap detect). A measurement, not a test: it installs Pose2Sim's
# Python dependencies (~300 MB), so CI does not run it. Usage: scripts/compare-pose2sim-people.sh (after a build).
set -euo pipefail
source "$(dirname "$0")/common.sh"
VENV="$ROOT/.cache/pose2sim-venv"
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT
bash "$ROOT/scripts/fetch-real-videos.sh"
if [ ! -x "$VENV/bin/python" ] || ! "$VENV/bin/python" -c "import Pose2Sim.personAssociation" 2>/dev/null; then
  python3 -m venv "$VENV"
  # Only what association and triangulation import (the package's full list pulls OpenSim, Qt and RTMLib).
  "$VENV/bin/pip" install --quiet --no-deps pose2sim==0.10.49
  "$VENV/bin/pip" install --quiet numpy rtoml tqdm opencv-python-headless anytree matplotlib pandas scipy c3d
fi
# Pose2Sim's project: its demo's Config.toml (from the wheel) for COCO_17 keypoints, every frame, no plots.
"$VENV/bin/python" - "$WORK" <<'PY'
import importlib.util, pathlib, re, sys
demo = pathlib.Path(importlib.util.find_spec("Pose2Sim").origin).parent / "Demo_MultiPerson" / "Config.toml"
s = demo.read_text()
s = s.replace("pose_model = 'Body_with_feet'", "pose_model = 'COCO_17'").replace("frame_range = 'auto'", "frame_range = 'all'")
s = re.sub(r"(make_c3d|display_figures|save_filt_plots) = true", r"\1 = false", s)
(pathlib.Path(sys.argv[1]) / "Config.toml").write_text(s)
PY
mkdir -p "$WORK/calibration"
cp "$ROOT/.cache/pose2sim-0.4.15/Demo/calibration/Calib_qualisys.toml" "$WORK/calibration/"
cli="$BUILD_DIR/tools/octocap/octocap"
"$cli" detect --images "$ROOT/.cache/pose2sim-0.10.49/Demo_MultiPerson/videos" --output "$WORK/pose" \
  --model movenet-multipose --detect-mode per-view --quiet
echo "== octocap solve --people auto"
"$cli" solve --keypoints "$WORK/pose" --calibration "$WORK/calibration/Calib_qualisys.toml" --output "$WORK/ours.trc" \
  --csv "$WORK/ours.csv" --people auto --filter none | grep -E "people:|person |solve time"
echo "== Pose2Sim personAssociation + triangulation"
"$VENV/bin/python" - "$WORK" <<'PY'
import logging, sys, time, rtoml
logging.basicConfig(level=logging.INFO, format="%(message)s", stream=sys.stdout)
from Pose2Sim.personAssociation import associate_all
from Pose2Sim.triangulation import triangulate_all
config = rtoml.load(open(sys.argv[1] + "/Config.toml"))
config["project"]["project_dir"] = sys.argv[1]
config["project"]["frame_rate"] = 60
t0 = time.time(); associate_all(config); t1 = time.time(); triangulate_all(config); t2 = time.time()
print(f"Pose2Sim: association {1000 * (t1 - t0) / 100:.1f} ms/frame, triangulation {1000 * (t2 - t1) / 100:.1f} ms/frame")
PY
echo "== the two side by side"
"$VENV/bin/python" "$ROOT/scripts/compare-pose2sim-people.py" "$WORK/ours.csv" "$WORK"/pose-3d/*_P*.trc
