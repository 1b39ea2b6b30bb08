#!/usr/bin/env bash
# The API reference, checked: Doxygen (docs/Doxyfile) over the public C header into a temporary folder, failing with
# every warning printed when one public name is undocumented (enumerators and struct fields too), a function lacks a
# parameter's @param or its @retval / @return, a declaration its @since, or a reference does not resolve. Output of
# any kind fails it: the Doxyfile keeps Doxygen quiet otherwise.
# Usage: scripts/check-reference.sh [HEADER]
#   HEADER: check another octocap.h instead of sdk/include/octocap/octocap.h (how this check itself is tested).
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
header="${1:-}"
if [ -n "$header" ]; then header="$(cd "$(dirname "$header")" && pwd)/$(basename "$header")"; fi
if ! command -v doxygen >/dev/null 2>&1; then
  echo "reference: doxygen is not installed: run scripts/install-deps.sh" >&2
  exit 1
fi
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
cd "$ROOT"  # the Doxyfile's paths are the repository's
version="$(python3 scripts/header_version.py)"
status=0
# A setting given again wins: the output folder, the version, and maybe another header, after the Doxyfile's.
{
  cat docs/Doxyfile
  echo "OUTPUT_DIRECTORY = $out/reference"
  echo "PROJECT_NUMBER = $version"
  if [ -n "$header" ]; then echo "INPUT = $header"; fi
  echo "GENERATE_XML = YES"  # for the checks below
} | doxygen - >"$out/log" 2>&1 || status=$?
# What Doxygen 1.9.4 does not check itself: an enumerator without a comment passes its WARN_IF_UNDOCUMENTED, and
# nothing asks for @since. From its XML: every enumerator documented, every declaration of the file (function, macro,
# typedef, enum, struct) with the version that brought it.
python3 - "$out/reference/xml" >>"$out/log" <<'PY' || status=1
import glob, os, sys, xml.etree.ElementTree as ET
problems = []
def described(e):
    return any("".join(e.find(d).itertext()).strip() for d in ("briefdescription", "detaileddescription")
               if e.find(d) is not None)
def since(e):
    return any(s.get("kind") == "since" for s in e.iter("simplesect"))
def where(e):
    loc = e.find("location")
    return "%s:%s" % (loc.get("file"), loc.get("line")) if loc is not None else "?"
paths = sorted(glob.glob(os.path.join(sys.argv[1], "*.xml")))
if not paths:
    problems.append("%s: error: no XML from doxygen" % sys.argv[1])
for path in paths:
    for c in ET.parse(path).getroot().iter("compounddef"):
        if c.get("kind") == "struct" and not since(c):
            problems.append("%s: warning: struct %s has no @since" % (where(c), c.findtext("compoundname")))
        if c.get("kind") != "file":
            continue
        for m in c.iter("memberdef"):
            name = m.findtext("name")
            if m.get("kind") in ("function", "define", "typedef", "enum") and not since(m):
                problems.append("%s: warning: %s %s has no @since" % (where(m), m.get("kind"), name))
            for v in m.findall("enumvalue"):
                if not described(v):
                    problems.append("%s: warning: enumerator %s is not documented" % (where(m), v.findtext("name")))
print("\n".join(problems), end="\n" if problems else "")
sys.exit(1 if problems else 0)
PY
if [ "$status" != 0 ] || [ -s "$out/log" ]; then
  sed "s|$ROOT/||" "$out/log"
  echo "reference: $(grep -cE ': (warning|error): ' "$out/log" || true) warnings (doxygen $(doxygen --version)):" \
       "document every public name, parameter and result, with @since (docs/Doxyfile says what is checked)" >&2
  exit 1
fi
echo "reference: doxygen $(doxygen --version) documents every public name of ${header:-octocap.h} $version," \
     "no warnings"
