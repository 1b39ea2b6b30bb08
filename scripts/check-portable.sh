#!/usr/bin/env bash
# The portable Linux release (scripts/package-linux.py) run where none of the build is: a clean Debian 13 (trixie)
# root made by debootstrap from Debian's packages (minbase: no OpenCV, no ONNX Runtime, no DDS, no Python), the
# release copied in, then, inside it: every file's libraries resolve, the sample recording solves into 3D against its
# ground truth, and real videos solve from pixels (FFmpeg's decoder, the inference runtime and the models the library
# finds in the release). Needs root (chroot, mount) and Debian's mirror the first time.
#
# Usage: check-portable.sh [BUILD_DIR]    (default: build). The bare root is cached outside the clone, in
# $OCTOCAP_CACHE_DIR (default /var/cache/octocap), keyed by the suite and debootstrap's version: one download a machine.
set -euo pipefail
source "$(dirname "$0")/common.sh"
BUILD="${1:-$BUILD_DIR}"
[ "$(id -u)" = 0 ] || { echo "check-portable: needs root (chroot and mount)" >&2; exit 1; }
command -v debootstrap >/dev/null && command -v patchelf >/dev/null || {
  echo "check-portable: needs debootstrap and patchelf (scripts/install-deps.sh installs them)" >&2; exit 1; }

DIST=/tmp/octocap-dist
python3 "$ROOT/scripts/package-linux.py" "$ROOT" "$BUILD" "$DIST"
RELEASE=$(ls -d "$DIST"/octocap-*-linux-x86_64)
VERSION=$(python3 "$ROOT/scripts/header_version.py")
[ "$RELEASE" = "$DIST/octocap-$VERSION-linux-x86_64" ] || { echo "check-portable: $RELEASE is not version $VERSION" >&2; exit 1; }
for f in LICENSE NOTICE CARRIED.txt; do
  [ -s "$RELEASE/share/doc/octocap/$f" ] || { echo "check-portable: the release has no share/doc/octocap/$f" >&2; exit 1; }
done
grep -q "^octocap $VERSION," "$RELEASE/README.txt" || { echo "check-portable: README.txt does not say $VERSION" >&2; exit 1; }

CACHE="${OCTOCAP_CACHE_DIR:-/var/cache/octocap}"
BASE="$CACHE/trixie-minbase-$(dpkg-query -W -f '${Version}' debootstrap).tar"
if [ ! -f "$BASE" ]; then
  mkdir -p "$CACHE"
  tmp=$(mktemp -d /tmp/octocap-debootstrap.XXXXXX)
  debootstrap --variant=minbase trixie "$tmp" http://deb.debian.org/debian >/dev/null
  tar -C "$tmp" -cf "$BASE.part" . && mv "$BASE.part" "$BASE"
  rm -rf "$tmp"
fi

CLEAN=/tmp/octocap-trixie
mounted=()
cleanup() {
  for m in "${mounted[@]}"; do umount "$m" 2>/dev/null || umount -l "$m" 2>/dev/null || true; done
  # Never remove through a bind mount that is still there (it would be the host's /dev): then leave the folder.
  if grep -q " $CLEAN/" /proc/mounts; then echo "check-portable: $CLEAN still has mounts, left as is" >&2; return; fi
  rm -rf --one-file-system "$CLEAN"
}
trap cleanup EXIT
grep -q " $CLEAN/" /proc/mounts && { echo "check-portable: $CLEAN has mounts" >&2; exit 1; }
rm -rf --one-file-system "$CLEAN" && mkdir -p "$CLEAN" && tar -C "$CLEAN" -xf "$BASE"
# /proc is where the loader reads the program's own path to expand $ORIGIN (/proc/self/exe): without it the tools
# cannot find lib/, as on any Linux without /proc. /sys and /dev tell the inference runtimes the CPU's cores and caches.
mount --bind /proc "$CLEAN/proc" || { echo "check-portable: cannot mount /proc in the root" >&2; exit 1; }
mounted=("$CLEAN/proc")
for fs in sys dev; do
  if mount --bind "/$fs" "$CLEAN/$fs"; then mounted=("$CLEAN/$fs" "${mounted[@]}");
  else echo "check-portable: /$fs could not be mounted in the root; going on without it" >&2; fi
done
cp -a "$RELEASE" "$CLEAN/opt/octocap"
# Real pictures for the from-pixels solve: data, not part of the release.
VIDEOS="$ROOT/.cache/pose2sim-0.10.49/Demo_SinglePerson/videos"
CALIB="$ROOT/.cache/pose2sim-0.4.15/Demo/calibration/Calib_qualisys.toml"
mkdir -p "$CLEAN/data/videos" && cp "$VIDEOS"/cam0[1-4].mp4 "$CLEAN/data/videos/" && cp "$CALIB" "$CLEAN/data/"

inside() { chroot "$CLEAN" env -i PATH=/usr/bin:/bin HOME=/root "$@"; }
trc_rows() { inside sh -c "tail -n +6 $1 | grep -c '^[0-9]'"; }  # the rows after TRC's five header lines
echo "== in a clean trixie root: $(inside cat /etc/debian_version), glibc $(inside ldd --version | head -1 | awk '{print $NF}')"
for pkg in libopencv-core406 libonnxruntime1 libddsc0debian python3; do
  if inside dpkg-query -W "$pkg" >/dev/null 2>&1; then echo "check-portable: the clean root has $pkg" >&2; exit 1; fi
done
missing=$(inside sh -c 'for f in /opt/octocap/bin/* /opt/octocap/lib/*.so*; do ldd "$f" 2>&1 | sed "s|^|$f: |"; done' |
          grep -E "not found|not a dynamic" || true)
[ -z "$missing" ] || { echo "check-portable: libraries the release lacks:"$'\n'"$missing" >&2; exit 1; }
echo "every file's libraries resolve inside the release or the system's C and C++ runtimes"

cd_opt="cd /opt/octocap &&"
inside sh -c "$cd_opt bin/octocap solve --calibration share/octocap/sample/calibration.toml \
  --keypoints share/octocap/sample/keypoints --output /tmp/sample.trc \
  --ground-truth share/octocap/sample/ground_truth.csv --rate 30 --quiet" | tee /tmp/octocap-portable.log
# The sample's ground truth says how far the 3D is from the true joints; the same bound as the tests' own.
mpjpe=$(sed -n 's/.*MPJPE[^0-9]*\([0-9.]*\) mm.*/\1/p' /tmp/octocap-portable.log | head -1)
[ -n "$mpjpe" ] && awk -v m="$mpjpe" 'BEGIN { exit !(m < 40) }' ||
  { echo "check-portable: the sample solved to an MPJPE of '${mpjpe}' mm (expected < 40)" >&2; exit 1; }
frames=$(trc_rows /tmp/sample.trc)
[ "$frames" -eq 90 ] || { echo "check-portable: sample.trc has $frames frames" >&2; exit 1; }

# Both inference back ends the release carries (automatic picks OpenVINO on a CPU).
for runtime in openvino onnxruntime; do
  inside sh -c "$cd_opt bin/octocap solve --images /data/videos --calibration /data/Calib_qualisys.toml \
    --output /tmp/videos.trc --rate 60 --frames 10 --runtime $runtime --quiet" | grep -E "keypoints solved|2D detection"
  frames=$(trc_rows /tmp/videos.trc)
  [ "$frames" -eq 10 ] || { echo "check-portable: $runtime: videos.trc has $frames frames (of 10)" >&2; exit 1; }
done
echo "check-portable: $(basename "$RELEASE") runs in a clean trixie root: sample MPJPE $mpjpe mm ($frames frames" \
     "from the videos' pixels with the release's models, in OpenVINO and in ONNX Runtime)"
