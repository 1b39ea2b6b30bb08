#!/usr/bin/env bash
# Builds the C# bindings with Mono's mcs (C# 7.2, what Unity and Godot accept), runs the NUnit 2 suite against
# the real native library, and prints one closing line "C#: N passed, N failed".
set -euo pipefail
HERE="$(cd "$(dirname "$0")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
BUILD_DIR="${OCTOCAP_BUILD_DIR:-$ROOT/build}"
OUT="$BUILD_DIR/csharp"
mkdir -p "$OUT"
NUNIT_DLL="$(ls /usr/lib/cli/nunit.framework-2.6*/nunit.framework.dll | head -1)"
mcs -langversion:7.2 -unsafe -warnaserror -target:library -out:"$OUT/Octocap.dll" -recurse:"$HERE/Octocap/*.cs"
mcs -langversion:7.2 -unsafe -target:library -out:"$OUT/Octocap.Tests.dll" -r:"$OUT/Octocap.dll" -r:"$NUNIT_DLL" \
  "$HERE"/tests/*.cs
export LD_LIBRARY_PATH="$BUILD_DIR/sdk${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export OCTOCAP_SAMPLE_DIR="$ROOT/data/sample"
export OCTOCAP_SOURCE_DIR="$ROOT"
export OCTOCAP_ABI_DUMP="$BUILD_DIR/bindings/csharp/native/octocap-abi-dump"
# Streaming tests stay on loopback, with no multicast.
export CYCLONEDDS_URI='<CycloneDDS><Domain Id="any"><General><Interfaces><NetworkInterface name="lo"/></Interfaces><AllowMulticast>false</AllowMulticast></General><Discovery><Peers><Peer address="127.0.0.1"/></Peers><ParticipantIndex>auto</ParticipantIndex><MaxAutoParticipantIndex>50</MaxAutoParticipantIndex></Discovery></Domain></CycloneDDS>'
cd "$OUT"
status=0
nunit-console -nologo -labels -xml="$OUT/TestResult.xml" "$OUT/Octocap.Tests.dll" || status=$?
python3 - "$OUT/TestResult.xml" <<'PY'
import sys, xml.etree.ElementTree as ET
r = ET.parse(sys.argv[1]).getroot()
total, failed, errors = int(r.get("total")), int(r.get("failures")), int(r.get("errors"))
skipped = int(r.get("not-run", 0))
print(f"C#: {total - failed - errors} passed, {failed + errors} failed" + (f", {skipped} skipped" if skipped else ""))
PY
exit $status
