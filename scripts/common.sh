# Shared by the scripts: where things are, and installing dependencies only when something is missing.
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${OCTOCAP_BUILD_DIR:-$ROOT/build}"
JOBS="${OCTOCAP_JOBS:-$(nproc)}"

ensure_deps() {
  local missing=0
  for pkg in cmake ninja-build libeigen3-dev libtomlplusplus-dev nlohmann-json3-dev libcli11-dev \
             libcatch2-dev libopencv-calib3d-dev libopencv-imgcodecs-dev libopencv-contrib-dev libopencv-videoio-dev libopencv-video-dev libcurl4-openssl-dev libturbojpeg0-dev libceres-dev libtbb12 assimp-testmodels python3-pip python3-venv mono-devel \
             nunit-console libnunit-cil-dev cyclonedds-dev cyclonedds-tools liblo-dev \
             libassimp-dev libosmesa6-dev libglfw3-dev xvfb ffmpeg clang-14 gir1.2-gst-rtsp-server-1.0 python3-gi \
             gstreamer1.0-plugins-good gstreamer1.0-plugins-bad doxygen libssl-dev; do
    dpkg -s "$pkg" >/dev/null 2>&1 || { missing=1; break; }
  done
  command -v npm >/dev/null 2>&1 || missing=1
  ls "$ROOT"/.cache/onnxruntime/.complete-*1.31.1 >/dev/null 2>&1 || missing=1  # the CPU or the GPU (--gpu) runtime
  [ -f "$ROOT/.cache/openvino/.complete-2026.4.0-systbb" ] || missing=1
  if [ "$missing" = 1 ]; then
    echo "== installing dependencies (scripts/install-deps.sh)" >&2
    bash "$ROOT/scripts/install-deps.sh"
  fi
}

# The sanitizer build (scripts/sanitize.sh, scripts/fuzz.sh): clang, ASan + UBSan with the libFuzzer targets, -O1 -g1
# (ASan's recommended optimisation, line tables for the reports), no benchmarks, no viewer sample, no OpenVINO: its
# oneTBB dlopens libtbbbind with RTLD_DEEPBIND, which ASan refuses (google/sanitizers#611), so every detector there
# would fail; the instrumented detector tests run ONNX Runtime, the normal pass both back ends.
SANITIZE_BUILD_DIR="${OCTOCAP_SANITIZE_BUILD_DIR:-$ROOT/build-asan}"
SANITIZE_CMAKE_ARGS=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1"
                     -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1" -DOCTOCAP_FUZZ=ON -DOCTOCAP_BENCH=OFF -DOCTOCAP_WITH_VIEWER=OFF
                     -DOCTOCAP_WITH_OPENVINO=OFF)
use_clang() {
  CC="$(command -v clang-14 || command -v clang)"
  CXX="$(command -v clang++-14 || command -v clang++)"
  export CC CXX
}

configure_and_build() {
  local dir="$1"; shift
  if [ ! -f "$dir/build.ninja" ]; then
    cmake -S "$ROOT" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
  fi
  cmake --build "$dir" -j "$JOBS"
}
