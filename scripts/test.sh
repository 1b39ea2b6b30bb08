#!/usr/bin/env bash
# One command: installs what is missing, fetches the real test data (cached), builds, runs every test.
set -euo pipefail
source "$(dirname "$0")/common.sh"
ensure_deps
bash "$ROOT/scripts/fetch-real-data.sh"
configure_and_build "$BUILD_DIR" "$@"
cd "$BUILD_DIR"
ctest --output-on-failure -j "$JOBS"
