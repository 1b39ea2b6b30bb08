"""Copies chosen files out of a wheel (a zip) without installing it: the fetch scripts' one extractor.

Usage: extract-from-wheel.py WHEEL DEST [--strip PREFIX | --flatten] KEEP [KEEP ...]
A member is kept when its name starts with one of the KEEP prefixes. It is written under DEST with PREFIX removed
from its name (--strip), or by its base name alone (--flatten). Exit status 1 when nothing matched.
"""
import os
import sys
import zipfile


def main(argv):
    wheel, dest, mode = argv[0], argv[1], argv[2]
    if mode == "--strip":
        strip, keep = argv[3], tuple(argv[4:])
    elif mode == "--flatten":
        strip, keep = None, tuple(argv[3:])
    else:
        raise SystemExit("give --strip PREFIX or --flatten")
    written = 0
    with zipfile.ZipFile(wheel) as z:
        for name in z.namelist():
            if not name.startswith(keep) or name.endswith("/"):
                continue
            rel = os.path.basename(name) if strip is None else name[len(strip):] if name.startswith(strip) else name
            out = os.path.join(dest, rel)
            os.makedirs(os.path.dirname(out) or ".", exist_ok=True)
            with z.open(name) as src, open(out, "wb") as dst:
                dst.write(src.read())
            written += 1
    return 0 if written else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
