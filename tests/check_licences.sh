#!/usr/bin/env bash
# Usage: check_licences.sh LIBOCTOCAP.so SOURCE_DIR
# The licence travels with everything octocap ships: LICENSE is Apache-2.0; NOTICE names every shared library the
# built liboctocap loads directly (the C library's own aside); the Unity and Godot packages carry the SPDX licence and
# the header's version (a package saying 0.1.0 for a 1.8 library sent users to the wrong documentation).
set -euo pipefail
lib="$1"; src="$2"
status=0
fail() { echo "FAIL: $*"; status=1; }
grep -q "Apache License" "$src/LICENSE" && grep -q "Version 2.0, January 2004" "$src/LICENSE" || fail "LICENSE is not Apache-2.0"
for soname in $(readelf -d "$lib" | awk '/NEEDED/ {gsub(/[\[\]]/, "", $5); print $5}'); do
  base="${soname%%.so*}"
  case "$base" in libc|libm|libdl|libpthread|librt|ld-linux-x86-64) continue ;; esac
  grep -qF "$base" "$src/NOTICE" || fail "NOTICE does not name $soname, which $(basename "$lib") loads"
done
header="$src/sdk/include/octocap/octocap.h"
version="$(python3 "$src/scripts/header_version.py" "$src")" || fail "no version in $header"
unity="$src/bindings/csharp/Unity/package.json"
python3 - "$unity" "$version" <<'PY' || status=1
import json, sys
manifest = json.load(open(sys.argv[1]))
ok = True
if manifest.get("license") != "Apache-2.0":
    print("FAIL: %s: license is %r, not the SPDX id Apache-2.0" % (sys.argv[1], manifest.get("license"))); ok = False
if manifest.get("version") != sys.argv[2]:
    print("FAIL: %s: version %r, the header says %s" % (sys.argv[1], manifest.get("version"), sys.argv[2])); ok = False
sys.exit(0 if ok else 1)
PY
godot="$src/bindings/csharp/Godot/addons/octocap/plugin.cfg"
grep -qx "version=\"$version\"" "$godot" || fail "$godot: version is not the header's $version"
[ -f "$src/bindings/csharp/Godot/addons/octocap/LICENSE" ] && cmp -s "$src/LICENSE" "$src/bindings/csharp/Godot/addons/octocap/LICENSE" ||
  fail "the Godot addon does not carry LICENSE (Godot's asset library wants it in the addon folder)"
[ -f "$src/bindings/csharp/Unity/LICENSE.md" ] && cmp -s "$src/LICENSE" "$src/bindings/csharp/Unity/LICENSE.md" ||
  fail "the Unity package does not carry LICENSE.md (UPM's place for it)"
[ $status = 0 ] && echo "licence and versions: LICENSE Apache-2.0, NOTICE names every library liboctocap loads, packages at $version"
exit $status
