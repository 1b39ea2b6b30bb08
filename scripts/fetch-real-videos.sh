#!/usr/bin/env bash
# Real multi-camera videos for the image-to-3D tests: Pose2Sim's Demo_SinglePerson and Demo_MultiPerson
# (BSD-3-Clause), 4 cameras, 1088x1920, from the pose2sim 0.10.49 wheel on PyPI. Its Calib.qca.txt is the same Qualisys
# calibration as the TOML in pose2sim 0.4.15 (scripts/fetch-real-data.sh), which the tests use.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
DEST="$ROOT/.cache/pose2sim-0.10.49"
if [ ! -f "$DEST/.complete-2" ]; then
  TMP="$(mktemp -d)"
  trap 'rm -rf "$TMP"' EXIT
  PIP="pip3"
  command -v pip3 >/dev/null 2>&1 || PIP="python3 -m pip"
  echo "== fetching pose2sim==0.10.49 (Pose2Sim demo videos, BSD-3-Clause)" >&2
  $PIP download --quiet --no-deps --only-binary=:all: --dest "$TMP" pose2sim==0.10.49
  rm -rf "$DEST"
  mkdir -p "$DEST"
  python3 "$ROOT/scripts/extract-from-wheel.py" "$TMP"/pose2sim-0.10.49-*.whl "$DEST" --strip Pose2Sim/ \
    Pose2Sim/Demo_SinglePerson/videos/ Pose2Sim/Demo_SinglePerson/calibration/Calib.qca.txt \
    Pose2Sim/Demo_MultiPerson/videos/ Pose2Sim/Demo_MultiPerson/calibration/Calib.qca.txt
  echo "From the pose2sim 0.10.49 wheel (PyPI), Pose2Sim/Demo_SinglePerson and Demo_MultiPerson: BSD-3-Clause, (c) David Pagnon." > "$DEST/LICENSE-NOTE.txt"
  touch "$DEST/.complete-2"
fi

# The same four views as H.264 elementary streams (Annex B, one access unit delimiter per frame, no B-frames,
# a key frame every half second) for the RTSP server that plays them as IP cameras (tests/support/rtsp_server.py):
# what an IP camera's encoder sends, at full size and as a 544x960 sub-stream (what IP cameras offer beside the main
# stream; four full-size 60 fps streams alone take most of two cores to decode). Encoded once, never at test time.
STREAMS="$ROOT/.cache/rtsp-streams"
if [ ! -f "$STREAMS/.complete-3" ]; then
  echo "== encoding the demo videos as H.264 camera streams (once)" >&2
  # One slice per frame: zerolatency's sliced threads cut each frame into one slice per thread (two on a 2-core
  # machine), and such frames, served by GStreamer's RTSP server, decode corrupt in FFmpeg (the ffmpeg CLI too):
  # one slice lost, the rest of the picture smeared until the next key frame. The live RTSP test then lost the
  # person in whole views for seconds, on an idle host too (it failed 4 runs in 6).
  rm -rf "$STREAMS"
  mkdir -p "$STREAMS"
  for c in 1 2 3 4; do
    ffmpeg -loglevel error -y -i "$DEST/Demo_SinglePerson/videos/cam0$c.mp4" -an -c:v libx264 -preset veryfast \
      -tune zerolatency -bf 0 -g 30 -crf 23 -x264-params aud=1:sliced-threads=0 -f h264 "$STREAMS/cam0$c.h264"
    ffmpeg -loglevel error -y -i "$DEST/Demo_SinglePerson/videos/cam0$c.mp4" -an -vf scale=544:960 -c:v libx264 \
      -preset veryfast -tune zerolatency -bf 0 -g 30 -crf 23 -x264-params aud=1:sliced-threads=0 -f h264 "$STREAMS/cam0${c}_960.h264"
  done
  touch "$STREAMS/.complete-3"
fi
