#!/usr/bin/python3
# An IP camera on loopback: GStreamer's RTSP server (gst-rtsp-server, through PyGObject) serving H.264 elementary
# streams (Annex B, as `ffmpeg -f h264` writes them) at their own frame rate, looped for ever, one mount per file.
# The tests and the live benchmark start one per camera so that a camera can be killed and brought back.
#
#   rtsp_server.py --port 8554 /cam1=cam01.h264 [/cam2=cam02.h264 ...]
#
# Runs with Debian's python3 (python3-gi, gir1.2-gst-rtsp-server-1.0). The file must carry access unit delimiters
# (x264's aud=1): it is cut into frames there and pushed through an appsrc with timestamps that keep running across
# loops (a raw H.264 stream has none of its own), and the server's sinks play them against the clock: frames go
# out at the camera's rate, as a camera would send them, every server in step with the others (the wall clock).
import argparse
import re
import signal
import sys
import time

import gi

gi.require_version("Gst", "1.0")
gi.require_version("GstRtspServer", "1.0")
from gi.repository import GLib, Gst, GstRtspServer  # noqa: E402


def access_units(path):
    data = open(path, "rb").read()
    # Every frame starts with an access unit delimiter (NAL type 9) behind a 3- or 4-byte start code.
    starts = [m.start() for m in re.finditer(b"\x00\x00\x01\x09", data)]
    starts = [s - 1 if s > 0 and data[s - 1] == 0 else s for s in starts]
    if not starts:
        sys.exit(f"rtsp_server: {path} has no access unit delimiters (encode with -x264-params aud=1)")
    return [data[a:b] for a, b in zip(starts, starts[1:] + [len(data)])]


def is_key_frame(unit):
    # An IDR slice (NAL type 5) in the access unit.
    return any((unit[m.end()] & 0x1F) == 5 for m in re.finditer(b"\x00\x00\x01", unit) if m.end() < len(unit))


class LoopingCamera:
    """Feeds a mount's appsrc: the file's frames in a loop, in step with the wall clock (frame n of the endless loop
    is shown at time n / rate since 1970), so that several servers play one take as cameras filming one scene do,
    whenever each was started or connected to. A new media starts at the next key frame, its own clock at 0."""

    def __init__(self, frames, rate):
        self.frames, self.rate, self.period = frames, rate, Gst.SECOND // rate
        self.keys = [i for i, f in enumerate(frames) if is_key_frame(f)]
        if not self.keys:
            sys.exit("rtsp_server: the stream has no key frame")

    def configure(self, _factory, media):
        now = int(time.time() * self.rate)
        start = now
        while start % len(self.frames) not in self.keys:
            start += 1
        state = {"origin": now, "next": start}
        src = media.get_element().get_child_by_name("src")
        src.connect("need-data", lambda appsrc, _length: self.push(appsrc, state))

    def push(self, src, state):
        n = state["next"]
        buf = Gst.Buffer.new_wrapped(self.frames[n % len(self.frames)])
        buf.pts = buf.dts = (n - state["origin"]) * self.period
        buf.duration = self.period
        state["next"] = n + 1
        src.emit("push-buffer", buf)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--port", type=int, required=True)
    parser.add_argument("--rate", type=int, default=60, help="frames per second (default 60)")
    parser.add_argument("mounts", nargs="+", help="/PATH=FILE.h264")
    args = parser.parse_args()
    Gst.init(None)
    server = GstRtspServer.RTSPServer()
    server.set_address("127.0.0.1")
    server.set_service(str(args.port))
    mounts = server.get_mount_points()
    cameras = []
    for spec in args.mounts:
        path, _, location = spec.partition("=")
        if not path.startswith("/") or not location:
            sys.exit(f"rtsp_server: '{spec}' is not /PATH=FILE")
        camera = LoopingCamera(access_units(location), args.rate)
        factory = GstRtspServer.RTSPMediaFactory()
        factory.set_launch(
            f"( appsrc name=src format=time caps=video/x-h264,stream-format=byte-stream,alignment=au,"
            f"framerate={args.rate}/1 ! h264parse ! rtph264pay name=pay0 pt=96 config-interval=-1 )")
        factory.set_shared(True)  # every client sees the same camera, as with a real one
        factory.connect("media-configure", camera.configure)
        cameras.append(camera)
        mounts.add_factory(path, factory)
    if server.attach(None) == 0:
        sys.exit(f"rtsp_server: cannot listen on port {args.port}")
    loop = GLib.MainLoop()
    GLib.unix_signal_add(GLib.PRIORITY_DEFAULT, signal.SIGTERM, loop.quit)
    GLib.unix_signal_add(GLib.PRIORITY_DEFAULT, signal.SIGINT, loop.quit)
    print(f"rtsp_server: serving {len(args.mounts)} stream(s) on rtsp://127.0.0.1:{args.port}", flush=True)
    loop.run()


if __name__ == "__main__":
    main()
