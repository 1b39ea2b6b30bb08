#!/usr/bin/env bash
# Runs the documented streaming example exactly as written (the first ```bash block after "# Streaming" in
# docs/streaming.md, which the README links), in a scratch copy of the paths it uses, and checks what it promises:
# the echo received all 90 frames, none lost, and recorded them. Usage: check-readme-streaming.sh [BUILD_DIR]
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
BUILD="${1:-$ROOT/build}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
python3 - "$ROOT/docs/streaming.md" > "$work/example.sh" <<'PY'
import sys
text = open(sys.argv[1]).read()
section = text[text.index("# Streaming"):]
start = section.index("```bash\n") + len("```bash\n")
print(section[start:section.index("```", start)])
PY
# The example's paths are relative to the repository root: give it one, with the build and data it names.
mkdir -p "$work/root"
ln -s "$BUILD" "$work/root/build"
ln -s "$ROOT/data" "$work/root/data"
cd "$work/root"
timeout 120 bash -euo pipefail "$work/example.sh" > "$work/stdout.txt" 2>&1 || { cat "$work/stdout.txt"; exit 1; }
last="$(tail -1 "$work/stdout.txt")"
echo "docs/streaming.md example: $last"
[[ "$last" == "received 90 frames, lost 0, publisher restarts 0, rejected 0" ]] || { cat "$work/stdout.txt"; exit 1; }
lines="$(wc -l < out/received.trc)"
[ "$lines" -ge 95 ] || { echo "out/received.trc has $lines lines, expected a header and 90 frames"; exit 1; }
