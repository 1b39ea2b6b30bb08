#!/usr/bin/env bash
# The packages a user installs, from the build: dist/octocap-VERSION-linux-x86_64/ (and its .tar.gz), the portable
# Linux release (scripts/package-linux.py), and dist/unity/com.octocap.avatar-VERSION.tgz, the Unity package
# (scripts/package-unity.py). Builds first if the build is missing.
# Usage: scripts/package.sh [BUILD_DIR]
set -euo pipefail
source "$(dirname "$0")/common.sh"
BUILD="${1:-$BUILD_DIR}"
[ -f "$BUILD/sdk/liboctocap.so" ] || configure_and_build "$BUILD" >/dev/null
python3 "$ROOT/scripts/package-linux.py" "$ROOT" "$BUILD" "$ROOT/dist" --tar
python3 "$ROOT/scripts/package-unity.py" "$ROOT" "$BUILD" "$ROOT/dist/unity"
