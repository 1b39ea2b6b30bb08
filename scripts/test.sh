#!/usr/bin/env bash
# One command: installs what is missing, fetches the real test data (cached), builds, runs every test:
# the Catch2 suite (ctest) and the C# bindings' NUnit suite.
set -euo pipefail
source "$(dirname "$0")/common.sh"
ensure_deps
bash "$ROOT/scripts/fetch-real-data.sh"
bash "$ROOT/scripts/fetch-real-videos.sh"
bash "$ROOT/scripts/fetch-models.sh"
configure_and_build "$BUILD_DIR" "$@"
status=0
# OCTOCAP_CTEST_EXCLUDE: a regex of test names this pass leaves out (the sanitizer pass of .ci/run says why).
(cd "$BUILD_DIR" && ctest --output-on-failure -j "$JOBS" ${OCTOCAP_CTEST_EXCLUDE:+-E "$OCTOCAP_CTEST_EXCLUDE"}) || status=$?
# The sanitizer pass (.ci/run) sets OCTOCAP_SKIP_CSHARP: an ASan-instrumented library cannot be loaded
# into Mono, and the C# suite has already run against the normal build.
if [ -z "${OCTOCAP_SKIP_CSHARP:-}" ]; then
  echo "== C# bindings (NUnit)"
  OCTOCAP_BUILD_DIR="$BUILD_DIR" bash "$ROOT/bindings/csharp/run-tests.sh" || status=$?
fi
exit $status
