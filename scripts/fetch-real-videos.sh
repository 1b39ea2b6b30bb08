#!/usr/bin/env bash
# Real multi-camera videos for the image-to-3D tests: Pose2Sim's Demo_SinglePerson (BSD-3-Clause), 4 cameras,
# 1088x1920, 100 frames, from the pose2sim 0.10.49 wheel on PyPI. Its Calib.qca.txt is the same Qualisys
# calibration as the TOML in pose2sim 0.4.15 (scripts/fetch-real-data.sh), which the tests use.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
DEST="$ROOT/.cache/pose2sim-0.10.49"
if [ -f "$DEST/.complete-1" ]; then exit 0; fi
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
PIP="pip3"
command -v pip3 >/dev/null 2>&1 || PIP="python3 -m pip"
echo "== fetching pose2sim==0.10.49 (Pose2Sim demo videos, BSD-3-Clause)" >&2
$PIP download --quiet --no-deps --only-binary=:all: --dest "$TMP" pose2sim==0.10.49
rm -rf "$DEST"
mkdir -p "$DEST"
python3 "$ROOT/scripts/extract-from-wheel.py" "$TMP"/pose2sim-0.10.49-*.whl "$DEST" --strip Pose2Sim/ \
  Pose2Sim/Demo_SinglePerson/videos/ Pose2Sim/Demo_SinglePerson/calibration/Calib.qca.txt
echo "From the pose2sim 0.10.49 wheel (PyPI), Pose2Sim/Demo_SinglePerson: BSD-3-Clause, (c) David Pagnon." > "$DEST/LICENSE-NOTE.txt"
touch "$DEST/.complete-1"
