#!/usr/bin/env bash
# Real data for the integration tests: Pose2Sim's demo (BSD-3-Clause), 4 real cameras with a Qualisys
# calibration, 100 frames of real OpenPose BODY_25B detections (with a bystander), and Pose2Sim's own 3D.
# Taken from the pose2sim 0.4.15 wheel on PyPI, unpacked once into .cache/ (not committed); its checkerboard
# images of the same 4 cameras test the intrinsics calibration against the Qualisys one.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
DEST="$ROOT/.cache/pose2sim-0.4.15"
if [ -f "$DEST/.complete-2" ]; then exit 0; fi
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
PIP="pip3"
command -v pip3 >/dev/null 2>&1 || PIP="python3 -m pip"
echo "== fetching pose2sim==0.4.15 (Pose2Sim demo data, BSD-3-Clause)" >&2
$PIP download --quiet --no-deps --only-binary=:all: --dest "$TMP" pose2sim==0.4.15
rm -rf "$DEST"
mkdir -p "$DEST"
python3 "$ROOT/scripts/extract-from-wheel.py" "$TMP"/pose2sim-0.4.15-*.whl "$DEST" --strip Pose2Sim/ \
  Pose2Sim/Demo/calibration/Calib_qualisys.toml Pose2Sim/Demo/pose/ Pose2Sim/Demo/calibration/intrinsics/ \
  Pose2Sim/Demo/opensim/Balancing_for_IK.trc Pose2Sim/Demo/User/Config.toml
cat > "$DEST/LICENSE-NOTE.txt" <<'TXT'
From the pose2sim 0.4.15 wheel (PyPI), Pose2Sim/Demo: BSD-3-Clause, (c) David Pagnon.
TXT
touch "$DEST/.complete-2"
