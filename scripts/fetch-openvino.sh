#!/usr/bin/env bash
# OpenVINO, octocap's second inference back end on the CPU, from a package registry only (nothing is fetched at run
# time): PyPI's `openvino` 2026.4.0 wheel (Apache-2.0) holds the runtime as plain shared libraries, its C API and
# headers; Python is not needed to use them. Kept: the runtime, its C API, the CPU plugin and the ONNX reader, about
# 90 MB of the wheel's 250. Not its oneTBB: Debian's libtbb12 (2021.8, which OpenCV already loads) has every symbol
# they use, and two libtbb.so.12 in one process would be one too many. Debian 12 has no OpenVINO package.
# Why a second runtime: on the same CPU core MoveNet Thunder costs 34.8 ms in ONNX Runtime, 26.5 ms in OpenVINO at
# f32 and 12.3 ms at the reduced precision its CPU plugin picks on CPUs with bf16 (docs/detecting.md "Inference back ends").
# Result: .cache/openvino/{include,lib} (not committed); CMake's OCTOCAP_OPENVINO_DIR points there.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
DEST="${OCTOCAP_OPENVINO_DIR:-$ROOT/.cache/openvino}"
OV_VERSION=2026.4.0
SOVERSION=2640
MARKER="$DEST/.complete-$OV_VERSION-systbb"
if [ -f "$MARKER" ]; then exit 0; fi
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
PIP="pip3"
command -v pip3 >/dev/null 2>&1 || PIP="python3 -m pip"

echo "== fetching openvino==$OV_VERSION (PyPI wheel, Apache-2.0) for its runtime and C API" >&2
$PIP download --quiet --no-deps --only-binary=:all: --python-version 3.11 --implementation cp \
  --platform manylinux_2_28_x86_64 --dest "$TMP" "openvino==$OV_VERSION"
WHEEL="$(ls "$TMP"/openvino-"$OV_VERSION"-*.whl)"
rm -rf "$DEST"
mkdir -p "$DEST/include" "$DEST/lib" "$DEST/licences"
python3 "$ROOT/scripts/extract-from-wheel.py" "$WHEEL" "$DEST/include" --strip openvino/include/ \
  openvino/include/openvino/c/
python3 "$ROOT/scripts/extract-from-wheel.py" "$WHEEL" "$DEST/lib" --flatten \
  "openvino/libs/libopenvino.so.$SOVERSION" "openvino/libs/libopenvino_c.so.$SOVERSION" \
  "openvino/libs/libopenvino_onnx_frontend.so.$SOVERSION" "openvino/libs/libopenvino_intel_cpu_plugin.so"
python3 "$ROOT/scripts/extract-from-wheel.py" "$WHEEL" "$DEST/licences" --flatten \
  "openvino-$OV_VERSION.dist-info/licenses/"
ln -sf "libopenvino_c.so.$SOVERSION" "$DEST/lib/libopenvino_c.so"
cat > "$DEST/SOURCES.txt" <<TXT
lib/*, include/openvino/c/*.h  from PyPI openvino==$OV_VERSION (manylinux_2_28_x86_64 wheel), Apache-2.0 licence
licences/*                     the wheel's licence and third-party notices (oneDNN, oneTBB)
TXT
touch "$MARKER"
echo "== OpenVINO $OV_VERSION ready in $DEST" >&2
