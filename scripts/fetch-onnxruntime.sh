#!/usr/bin/env bash
# ONNX Runtime for the 2D detector, from package registries only (nothing is fetched at run time):
#  - the library: libonnxruntime.so.1.31.1 out of PyPI's `onnxruntime` 1.31.1 wheel (MIT). The wheel's shared
#    library is the plain C/C++ runtime; Python is not needed to use it. Debian 12 has no ONNX Runtime package.
#  - the headers: Debian trixie's `libonnxruntime-dev` 1.21.0 (MIT), the official C/C++ API headers. Fetched with
#    `apt-get download` through a throw-away source list and state, so the system's apt setup is untouched.
# Headers older than the library are safe: a library serves every older API version, and octocap asks for the
# headers' ORT_API_VERSION at run time (a clear error if the library were older).
# Result: .cache/onnxruntime/{include,lib} (not committed); CMake's OCTOCAP_ONNXRUNTIME_DIR points there.
#
# --gpu (opt-in, about 2 GB of downloads a CPU user never pays for): the library from PyPI's `onnxruntime-gpu` wheel
# instead (its CPU kernels are the same; it adds the CUDA execution provider), with the CUDA 13 and cuDNN 9 libraries
# it needs from NVIDIA's PyPI wheels (its `cuda` and `cudnn` extras), all in .cache/onnxruntime/lib. Same soname:
# nothing is rebuilt; a detector with device AUTO or CUDA then runs on the GPU (octocap preloads those libraries from
# there), and falls back to the CPU (AUTO) where no GPU answers. Needs an NVIDIA driver; nothing else.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
DEST="${OCTOCAP_ONNXRUNTIME_DIR:-$ROOT/.cache/onnxruntime}"
# The CPU and GPU wheels at one version: the library exports versioned symbols (VERS_1.31.1), so a program linked
# against one runs on the other and --gpu swaps the runtime without a rebuild. 1.31.1 is the newest onnxruntime-gpu
# on PyPI (the CPU wheel has a 1.32.0, which the GPU build would not serve).
ORT_VERSION=1.31.1
ORT_GPU_VERSION=$ORT_VERSION
HEADERS_DEB_VERSION=1.21.0+dfsg-1
GPU=0
if [ "${1:-}" = "--gpu" ]; then GPU=1; fi
MARKER="$DEST/.complete-$ORT_VERSION"
GPU_MARKER="$DEST/.complete-gpu-$ORT_GPU_VERSION"
if [ -f "$GPU_MARKER" ]; then exit 0; fi        # the GPU runtime serves the CPU too
if [ "$GPU" = 0 ] && [ -f "$MARKER" ]; then exit 0; fi
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
if [ "$GPU" = 1 ]; then
  echo "== fetching onnxruntime-gpu[cuda,cudnn]==$ORT_GPU_VERSION (PyPI: ONNX Runtime MIT, NVIDIA's CUDA and cuDNN wheels under NVIDIA's licences)" >&2
  $PIP download --quiet --only-binary=:all: --python-version 3.11 --implementation cp \
    --platform manylinux_2_28_x86_64 --platform manylinux_2_27_x86_64 --platform manylinux2014_x86_64 \
    --dest "$TMP/gpu" "onnxruntime-gpu[cuda,cudnn]==$ORT_GPU_VERSION"
  # Over the CPU library of the same version and name: a build made against that one links and runs on this one.
  python3 "$ROOT/scripts/extract-from-wheel.py" "$TMP"/gpu/onnxruntime_gpu-*.whl "$DEST/lib" --flatten \
    "onnxruntime/capi/libonnxruntime.so.$ORT_GPU_VERSION" "onnxruntime/capi/libonnxruntime_providers_shared.so" \
    "onnxruntime/capi/libonnxruntime_providers_cuda.so"
  ln -sf "libonnxruntime.so.$ORT_GPU_VERSION" "$DEST/lib/libonnxruntime.so.1"
  ln -sf "libonnxruntime.so.1" "$DEST/lib/libonnxruntime.so"
  # Every shared library of NVIDIA's wheels (nvidia/<part>/lib/lib*.so.N), flat beside it.
  for wheel in "$TMP"/gpu/nvidia_*.whl; do
    python3 - "$wheel" "$DEST/lib" <<'PY'
import os, sys, zipfile
with zipfile.ZipFile(sys.argv[1]) as z:
    for name in z.namelist():
        base = os.path.basename(name)
        if name.startswith("nvidia/") and "/lib/" in name and base.startswith("lib") and ".so" in base:
            with z.open(name) as src, open(os.path.join(sys.argv[2], base), "wb") as dst:
                dst.write(src.read())
PY
  done
  ls "$TMP"/gpu/*.whl | xargs -n1 basename > "$DEST/GPU-WHEELS.txt"
  touch "$GPU_MARKER"
  echo "== ONNX Runtime $ORT_GPU_VERSION with CUDA ready in $DEST (wheels listed in GPU-WHEELS.txt)" >&2
  exit 0
fi
cat > "$DEST/SOURCES.txt" <<TXT
lib/libonnxruntime.so.$ORT_VERSION  from PyPI onnxruntime==$ORT_VERSION (manylinux_2_28_x86_64 wheel), MIT licence
include/*.h                        from Debian trixie libonnxruntime-dev $HEADERS_DEB_VERSION, MIT licence
TXT
touch "$MARKER"
echo "== ONNX Runtime $ORT_VERSION ready in $DEST" >&2
