#!/usr/bin/env bash
# Usage: check_deprecated.sh CC INCLUDE_DIR SOURCE.c
# The deprecated group warns where it is called (OCTOCAP_DEPRECATED), and OCTOCAP_NO_DEPRECATION_WARNINGS silences it
# for a program that calls it on purpose.
set -euo pipefail
cc="$1"; inc="$2"; src="$3"
if out="$("$cc" -std=c99 -fsyntax-only -Werror=deprecated-declarations -I"$inc" "$src" 2>&1)"; then
  echo "FAIL: a call of octocap_session_get_frame_info() compiled without a deprecation warning"; exit 1
fi
grep -q "deprecated" <<<"$out" || { echo "FAIL: the compiler refused the call, but not as deprecated:"; echo "$out"; exit 1; }
grep -q "octocap_frame_" <<<"$out" || { echo "FAIL: the warning does not name the replacement:"; echo "$out"; exit 1; }
"$cc" -std=c99 -fsyntax-only -Werror -Wall -Wextra -DOCTOCAP_NO_DEPRECATION_WARNINGS -I"$inc" "$src" ||
  { echo "FAIL: OCTOCAP_NO_DEPRECATION_WARNINGS did not silence the warning"; exit 1; }
echo "deprecated group: warns where called, naming octocap_frame_*; OCTOCAP_NO_DEPRECATION_WARNINGS silences it"
