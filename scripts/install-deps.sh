#!/usr/bin/env bash
# Installs every system dependency octocap's build and tests need on a fresh Debian 12 (bookworm).
# The one place that installs anything; CI and the demo call it. Safe to run twice.
set -euo pipefail
# Usage: scripts/install-deps.sh [--gpu]
if [ "${1:-}" = "--gpu" ]; then OCTOCAP_GPU=1; elif [ -n "${1:-}" ]; then echo "usage: $0 [--gpu]" >&2; exit 2; fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive

# Catch2 v3 (3.7) lives in bookworm-backports; bookworm itself has only the slow-to-compile 2.13 header.
BACKPORTS=/etc/apt/sources.list.d/octocap-bookworm-backports.list
if ! grep -rqs "bookworm-backports" /etc/apt/sources.list /etc/apt/sources.list.d/; then
  echo "deb http://deb.debian.org/debian bookworm-backports main" | $SUDO tee "$BACKPORTS" >/dev/null
fi

$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends \
  build-essential cmake ninja-build pkg-config \
  libeigen3-dev \
  libtomlplusplus-dev nlohmann-json3-dev libcli11-dev \
  libopencv-core-dev libopencv-calib3d-dev libopencv-imgproc-dev libopencv-imgcodecs-dev libopencv-contrib-dev \
  libopencv-videoio-dev libopencv-video-dev \
  libcurl4-openssl-dev libturbojpeg0-dev libssl-dev openssl \
  libceres-dev libtbb12 \
  assimp-testmodels python3 python3-pip python3-venv \
  mono-devel nunit-console libnunit-cil-dev \
  cyclonedds-dev cyclonedds-tools liblo-dev \
  libassimp-dev libosmesa6-dev libglfw3-dev xvfb xauth \
  clang-14 libclang-rt-14-dev \
  ffmpeg \
  doxygen debootstrap patchelf \
  gstreamer1.0-rtsp gir1.2-gst-rtsp-server-1.0 python3-gi gstreamer1.0-plugins-good gstreamer1.0-plugins-bad
$SUDO apt-get install -y -q --no-install-recommends -t bookworm-backports libcatch2-dev
# Node.js + npm convert the shipped pose models (scripts/fetch-models.sh); keep a Node.js already installed.
if ! command -v npm >/dev/null 2>&1; then
  $SUDO apt-get install -y -q --no-install-recommends nodejs npm
fi
# ONNX Runtime is not packaged for Debian 12: library from PyPI, headers from Debian trixie (see the script).
# --gpu: its GPU build with the CUDA and cuDNN libraries it needs (about 2 GB; NVIDIA driver required).
bash "$(dirname "$0")/fetch-onnxruntime.sh" ${OCTOCAP_GPU:+--gpu}
# OpenVINO, the faster CPU back end (scripts/fetch-openvino.sh: PyPI wheel, Apache-2.0).
bash "$(dirname "$0")/fetch-openvino.sh"
