#!/usr/bin/env bash
# The Khronos glTF-Validator (npm gltf-validator 2.0.0-dev.3.10, Apache-2.0) that the viewer's glTF export test runs
# on every file it writes (tests/support/validate_gltf.js): kept in .cache, never fetched at test time.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
DEST="$ROOT/.cache/gltf-validator"
VERSION=2.0.0-dev.3.10
if [ -f "$DEST/.complete-$VERSION" ]; then exit 0; fi
command -v npm >/dev/null 2>&1 || { echo "npm is missing: run scripts/install-deps.sh" >&2; exit 1; }
echo "== fetching gltf-validator@$VERSION (npm) for the glTF export test" >&2
rm -rf "$DEST"
mkdir -p "$DEST"
(cd "$DEST" && npm init -y >/dev/null && npm install --silent --no-audit --no-fund "gltf-validator@$VERSION" >/dev/null)
[ -f "$DEST/node_modules/gltf-validator/package.json" ] || { echo "gltf-validator did not install" >&2; exit 1; }
touch "$DEST/.complete-$VERSION"
