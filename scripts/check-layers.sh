#!/usr/bin/env bash
# The dependency direction of DESIGN.md, enforced: a stage of sdk/src/ includes only stages above it in
#   core, io, calib, capture, detect, solve, rig, stream, pipeline, capi
# and nothing outside sdk/ includes sdk/src/ headers except tests and benchmarks (which may test internals).
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
order=(core io calib capture detect solve rig stream pipeline capi)
rank() { local i; for i in "${!order[@]}"; do [ "${order[$i]}" = "$1" ] && { echo "$i"; return; }; done; echo -1; }
status=0
for dir in "$ROOT"/sdk/src/*/; do
  stage="$(basename "$dir")"
  r="$(rank "$stage")"
  [ "$r" = -1 ] && { echo "sdk/src/$stage: not a stage of DESIGN.md"; status=1; continue; }
  while IFS= read -r line; do
    file="${line%%:*}"
    inc="$(sed -E 's/.*#include "([^"]+)".*/\1/' <<<"$line")"
    dep="${inc%%/*}"
    [ "$dep" = "$inc" ] && continue           # same-folder or generated header
    [ "$dep" = "octocap" ] && continue        # the public header
    d="$(rank "$dep")"
    [ "$d" = -1 ] && continue
    if [ "$d" -gt "$r" ]; then
      echo "${file#$ROOT/}: $stage includes $inc (a later stage)"; status=1
    fi
  done < <(grep -H '#include "' "$dir"*.h "$dir"*.cpp 2>/dev/null || true)
done
# Tools and samples are users: the public headers only. (tools/synth, the generator of the built-in sample, is
# built on the test harness's synthesizer and links octocap_internals on purpose.)
while IFS= read -r line; do
  echo "${line#$ROOT/}: a tool or sample includes an internal header"; status=1
done < <(grep -rHE '#include "(core|io|calib|capture|detect|solve|rig|stream|pipeline|capi)/' "$ROOT/tools" "$ROOT/samples" --exclude-dir=synth || true)
# The C ABI's own tests (tests/capi/) call the library as a user does: the public headers and the test helpers only.
while IFS= read -r line; do
  echo "${line#$ROOT/}: a C ABI test includes an internal header"; status=1
done < <(grep -rHE '#include "(core|io|calib|capture|detect|solve|rig|stream|pipeline|capi)/' "$ROOT/tests/capi" || true)
[ $status = 0 ] && echo "layers: every include goes to an earlier stage; tools, samples and the C ABI tests use the public headers"
exit $status
