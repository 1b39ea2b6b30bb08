#!/usr/bin/env bash
# Runs the secured streaming example of docs/security.md exactly as written (its first ```bash block) in a scratch
# copy of the paths it uses, checks that the keystore's viewer received every frame, then that nobody outside the
# keystore gets in, each a publisher and a subscriber in two processes on loopback: an identity of another keystore
# posing as the hub, an unsecured subscriber, an unsecured publisher, and an identity whose role may not read.
# Usage: check-security.sh [BUILD_DIR]
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
BUILD="$(cd "${1:-$ROOT/build}" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
python3 - "$ROOT/docs/security.md" > "$work/example.sh" <<'PY'
import sys
text = open(sys.argv[1]).read()
start = text.index("```bash\n") + len("```bash\n")
print(text[start:text.index("```", start)])
PY
mkdir -p "$work/root"
ln -s "$BUILD" "$work/root/build"
ln -s "$ROOT/data" "$work/root/data"
cd "$work/root"
timeout 120 bash -euo pipefail "$work/example.sh" > "$work/stdout.txt" 2>&1 || { cat "$work/stdout.txt"; exit 1; }
last="$(tail -1 "$work/stdout.txt")"
echo "docs/security.md example: $last"
[[ "$last" == "received 90 frames, lost 0, publisher restarts 0, rejected 0" ]] || { cat "$work/stdout.txt"; exit 1; }

# The intruders, on a domain of their own (the example used 0), with the example's loopback configuration.
export CYCLONEDDS_URI="$(grep -o "CYCLONEDDS_URI='[^']*'" "$work/example.sh" | sed "s/^CYCLONEDDS_URI='//; s/'$//")"
domain=$(( $$ % 200 + 1 ))
octocap="build/tools/octocap/octocap"
"$octocap" security init out/foreign > /dev/null
"$octocap" security add out/foreign hub --role hub > /dev/null
"$octocap" security add out/studio booth --role node > /dev/null
# $1: the subscriber's identity ("" none), $2: the publisher's; prints the subscriber's last line.
frames_through() {
  build/samples/stream/octocap-stream-echo --qos record --domain "$domain" --quiet --timeout-s 6 \
    ${1:+--dds-security "$1"} > "$work/echo.txt" 2> "$work/echo.err" &
  local echo_pid=$!
  sleep 1
  "$octocap" solve --calibration data/sample/calibration.toml --keypoints data/sample/keypoints --output /dev/null \
    --publish --publish-qos record --domain "$domain" --quiet --linger-s 2 ${2:+--dds-security "$2"} \
    > /dev/null 2> "$work/solve.err" || { cat "$work/solve.err"; return 1; }
  wait "$echo_pid" || true
  tail -1 "$work/echo.txt"
}
expect_nothing() {
  local got
  got="$(frames_through "$2" "$3")"
  echo "$1: ${got:-nothing}"
  [[ "$got" == "received 0 frames, lost 0, publisher restarts 0, rejected 0" ]] || { cat "$work/echo.err"; exit 1; }
}
expect_nothing "another keystore's hub into the keystore's viewer" out/studio/unity out/foreign/hub
expect_nothing "the keystore's hub to an unsecured subscriber" "" out/studio/hub
expect_nothing "an unsecured publisher into the keystore's viewer" out/studio/unity ""
# A node's identity may not read skeletons: the subscriber stops at once and says which topic.
if build/samples/stream/octocap-stream-echo --domain "$domain" --timeout-s 1 --dds-security out/studio/booth \
     > /dev/null 2> "$work/echo.err"; then
  echo "a node's identity subscribed to skeletons"; exit 1
fi
grep -q "role node) may neither publish nor read 'octocap_definition'" "$work/echo.err" || { cat "$work/echo.err"; exit 1; }
echo "a node's identity reading skeletons: refused, naming octocap_definition"
