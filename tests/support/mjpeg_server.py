#!/usr/bin/env python3
"""An MJPEG-over-HTTP camera on loopback, honest or hostile, for the live tests.

Serves multipart/x-mixed-replace parts, one JPEG each, from the .jpg files of a folder (looped) at --rate parts per
second. --mode decides how it misbehaves:

  good         every part a JPEG
  corrupt      every --every-th part keeps its JPEG headers but its entropy-coded data is garbage
  not-jpeg     every part is text, not a picture
  huge-part    the first part announces Content-Length 99999999999 and its body never ends
  not-found    every request answered 404
  silent       connections accepted, never answered
  stall        --parts good parts, then the connection stays open and silent

Standard library only; one thread per connection, so a camera that reconnects is served again.
"""
import argparse
import glob
import os
import random
import socket
import threading
import time

BOUNDARY = b"octocapframe"


def corrupt(jpeg: bytes, rng: random.Random) -> bytes:
    # The entropy-coded data follows the start-of-scan segment (FF DA) and its header; it ends at EOI (FF D9).
    sos = jpeg.find(b"\xff\xda")
    if sos < 0:
        return jpeg
    start = sos + 2 + int.from_bytes(jpeg[sos + 2:sos + 4], "big")
    end = len(jpeg) - 2
    body = bytearray(rng.getrandbits(8) for _ in range(end - start))
    return jpeg[:start] + bytes(body) + jpeg[end:]


def part(body: bytes, length=None) -> bytes:
    n = len(body) if length is None else length
    head = b"--" + BOUNDARY + b"\r\nContent-Type: image/jpeg\r\nContent-Length: " + str(n).encode() + b"\r\n\r\n"
    return head + body + b"\r\n"


def serve(conn: socket.socket, args, pictures):
    rng = random.Random(7)
    try:
        conn.settimeout(10)
        request = b""
        while b"\r\n\r\n" not in request:
            chunk = conn.recv(4096)
            if not chunk:
                return
            request += chunk
        if args.mode == "silent":
            time.sleep(3600)
            return
        if args.mode == "not-found":
            conn.sendall(b"HTTP/1.1 404 Not Found\r\nContent-Length: 9\r\nConnection: close\r\n\r\nnot found")
            return
        conn.sendall(b"HTTP/1.1 200 OK\r\nContent-Type: multipart/x-mixed-replace;boundary=" + BOUNDARY +
                     b"\r\nCache-Control: no-cache\r\nConnection: close\r\n\r\n")
        if args.mode == "huge-part":
            conn.sendall(part(b"", 99999999999)[:-2])
            filler = b"\x00" * 65536
            while True:
                conn.sendall(filler)
        period = 1.0 / args.rate
        due = time.monotonic()
        i = 0
        while True:
            jpeg = pictures[i % len(pictures)]
            if args.mode == "not-jpeg":
                body = b"this is not a picture " * 50
            elif args.mode == "corrupt" and i % args.every == args.every - 1:
                body = corrupt(jpeg, rng)
            else:
                body = jpeg
            if args.mode == "stall" and i >= args.parts:
                time.sleep(3600)
            conn.sendall(part(body))
            i += 1
            due += period
            time.sleep(max(0.0, due - time.monotonic()))
    except (OSError, socket.timeout):
        pass
    finally:
        conn.close()


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--port", type=int, default=0, help="0: any free port, written to --port-file")
    p.add_argument("--port-file", help="where the port listened on is written once the server accepts")
    p.add_argument("--pictures", required=True, help="folder of .jpg files")
    p.add_argument("--mode", default="good",
                   choices=["good", "corrupt", "not-jpeg", "huge-part", "not-found", "silent", "stall"])
    p.add_argument("--every", type=int, default=3)
    p.add_argument("--parts", type=int, default=10)
    p.add_argument("--rate", type=float, default=30)
    args = p.parse_args()
    files = sorted(glob.glob(os.path.join(args.pictures, "*.jpg")))
    pictures = [open(f, "rb").read() for f in files]
    if not pictures:
        raise SystemExit("no .jpg in " + args.pictures)
    listener = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    listener.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    listener.bind(("127.0.0.1", args.port))
    listener.listen(8)
    if args.port_file:
        with open(args.port_file + ".tmp", "w") as f:
            f.write(str(listener.getsockname()[1]))
        os.replace(args.port_file + ".tmp", args.port_file)  # whole or absent: the test never reads half a number
    while True:
        conn, _ = listener.accept()
        threading.Thread(target=serve, args=(conn, args, pictures), daemon=True).start()


if __name__ == "__main__":
    main()
