#!/usr/bin/env bash
# ONNX Runtime for the 2D detector, from package registries only (nothing is fetched at run time):
#  - the library: libonnxruntime.so.1.32.0 out of PyPI's `onnxruntime` 1.32.0 wheel (MIT). The wheel's shared
#    library is the plain C/C++ runtime; Python is not needed to use it. Debian 12 has no ONNX Runtime package.
#  - the headers: Debian trixie's `libonnxruntime-dev` 1.21.0 (MIT), the official C/C++ API headers. Fetched with
#    `apt-get download` through a throw-away source list and state, so the system's apt setup is untouched.
# Headers older than the library are safe: a library serves every older API version, and octocap asks for the
# headers' ORT_API_VERSION at run time (a clear error if the library were older).
# Result: .cache/onnxruntime/{include,lib} (not committed); CMake's OCTOCAP_ONNXRUNTIME_DIR points there.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
DEST="${OCTOCAP_ONNXRUNTIME_DIR:-$ROOT/.cache/onnxruntime}"
ORT_VERSION=1.32.0
HEADERS_DEB_VERSION=1.21.0+dfsg-1
MARKER="$DEST/.complete-$ORT_VERSION"
if [ -f "$MARKER" ]; then exit 0; fi
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
PIP="pip3"
command -v pip3 >/dev/null 2>&1 || PIP="python3 -m pip"

echo "== fetching onnxruntime==$ORT_VERSION (PyPI wheel, MIT) for its shared library" >&2
# --python-version/--platform: the library inside is the same for every CPython; pin the wheel, not the interpreter.
$PIP download --quiet --no-deps --only-binary=:all: --python-version 3.11 --implementation cp \
  --platform manylinux_2_28_x86_64 --dest "$TMP" "onnxruntime==$ORT_VERSION"

echo "== fetching libonnxruntime-dev $HEADERS_DEB_VERSION (Debian trixie, MIT) for the C/C++ headers" >&2
mkdir -p "$TMP/apt/lists/partial" "$TMP/apt/cache/archives/partial"
echo "deb http://deb.debian.org/debian trixie main" > "$TMP/apt/sources.list"
APT_OPTS=(-o "Dir::Etc::SourceList=$TMP/apt/sources.list" -o "Dir::Etc::SourceParts=/dev/null"
          -o "Dir::State::Lists=$TMP/apt/lists" -o "Dir::State::status=/dev/null" -o "Dir::Cache=$TMP/apt/cache"
          -o "Acquire::AllowInsecureRepositories=false" -o "APT::Sandbox::User=root")
apt-get -q "${APT_OPTS[@]}" update >/dev/null
(cd "$TMP" && apt-get -q "${APT_OPTS[@]}" download "libonnxruntime-dev=$HEADERS_DEB_VERSION" >/dev/null)
dpkg-deb -x "$TMP"/libonnxruntime-dev_*.deb "$TMP/deb"

rm -rf "$DEST"
mkdir -p "$DEST/include" "$DEST/lib"
cp "$TMP"/deb/usr/include/onnxruntime/*.h "$DEST/include/"
python3 "$ROOT/scripts/extract-from-wheel.py" "$TMP"/onnxruntime-"$ORT_VERSION"-*.whl "$DEST/lib" --flatten \
  "onnxruntime/capi/libonnxruntime.so.$ORT_VERSION"
ln -sf "libonnxruntime.so.$ORT_VERSION" "$DEST/lib/libonnxruntime.so.1"
ln -sf "libonnxruntime.so.1" "$DEST/lib/libonnxruntime.so"
cat > "$DEST/SOURCES.txt" <<TXT
lib/libonnxruntime.so.$ORT_VERSION  from PyPI onnxruntime==$ORT_VERSION (manylinux_2_28_x86_64 wheel), MIT licence
include/*.h                        from Debian trixie libonnxruntime-dev $HEADERS_DEB_VERSION, MIT licence
TXT
touch "$MARKER"
echo "== ONNX Runtime $ORT_VERSION ready in $DEST" >&2
