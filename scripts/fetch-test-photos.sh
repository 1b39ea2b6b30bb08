#!/usr/bin/env bash
# Real photos of people for the detector tests, from PyPI wheels (taken with --no-deps, only the images kept):
# ultralytics 8.4.190 (AGPL-3.0 code; the photos bus.jpg, zidane.jpg are its sample assets) and scikit-image 0.26.0
# (BSD-3-Clause; astronaut.png is public domain NASA, camera.png is scikit-image's own).
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
DEST="$ROOT/.cache/photos"
if [ -f "$DEST/.complete-1" ]; then exit 0; fi
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
PIP="pip3"
command -v pip3 >/dev/null 2>&1 || PIP="python3 -m pip"
echo "== fetching photos of people (ultralytics, scikit-image wheels)" >&2
$PIP download --quiet --no-deps --only-binary=:all: --dest "$TMP" "ultralytics==8.4.190"
$PIP download --quiet --no-deps --only-binary=:all: --python-version 3.11 --implementation cp \
  --platform manylinux_2_28_x86_64 --dest "$TMP" "scikit-image==0.26.0"
mkdir -p "$DEST"
for wheel in "$TMP"/*.whl; do
  python3 "$ROOT/scripts/extract-from-wheel.py" "$wheel" "$DEST" --flatten ultralytics/assets/bus.jpg \
    ultralytics/assets/zidane.jpg skimage/data/astronaut.png skimage/data/camera.png
done
for f in bus.jpg zidane.jpg astronaut.png camera.png; do [ -f "$DEST/$f" ] || { echo "missing $f" >&2; exit 1; }; done
touch "$DEST/.complete-1"
