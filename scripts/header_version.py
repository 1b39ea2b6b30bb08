#!/usr/bin/env python3
"""The project's version, MAJOR.MINOR.PATCH, read where it lives: the OCTOCAP_VERSION_MAJOR/MINOR/PATCH lines of the
public header (sdk/include/octocap/octocap.h). The one reader for the scripts and tests; CMakeLists.txt reads the
same lines with the same pattern at configure time, before any script can run.

Usage: header_version.py [SOURCE_DIR]   prints it; SOURCE_DIR is the repository (default: the one holding this file)
From Python (scripts/ on sys.path):  from header_version import header_version; header_version(SOURCE_DIR)
"""
import os, re, sys

HEADER = os.path.join("sdk", "include", "octocap", "octocap.h")


def header_version(source_dir=None):
    """MAJOR.MINOR.PATCH of the header under source_dir; ValueError when a line is missing."""
    if source_dir is None:
        source_dir = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    path = os.path.join(source_dir, HEADER)
    with open(path) as f:
        text = f.read()
    parts = []
    for part in ("MAJOR", "MINOR", "PATCH"):
        # Whole lines, as CMakeLists.txt matches them: a mention of the macro in a comment is not the definition.
        m = re.search(r"^#define OCTOCAP_VERSION_%s ([0-9]+)$" % part, text, re.M)
        if not m:
            raise ValueError("%s: no '#define OCTOCAP_VERSION_%s N' line" % (path, part))
        parts.append(m.group(1))
    return ".".join(parts)


if __name__ == "__main__":
    if len(sys.argv) > 2:
        sys.exit("usage: header_version.py [SOURCE_DIR]")
    try:
        print(header_version(sys.argv[1] if len(sys.argv) == 2 else None))
    except (OSError, ValueError) as e:
        sys.exit("header_version.py: %s" % e)
