#!/usr/bin/env python3
"""Foot sliding from pixels: how far a solved ankle moves while the true foot stands.

Usage: measure-foot-lock.py TRUTH.csv SOLVED.csv [SOLVED.csv ...]
TRUTH.csv is octocap-viewer --ground-truth's (frame, NAME_x/y/z in the world, Y up); each SOLVED.csv is octocap
solve's CSV of the same frames. A foot stands where its true ankle moves less than 0.1 m/s horizontally within 5 cm
of its lowest height in the take; over those frames the table gives the horizontal ankle speed (mm/s: mean, median,
90th percentile) of the truth and of each solve. The truth's is what there really is (a rolling foot's ankle moves).
"""
import csv
import math
import sys

RATE_HINT = 30.0  # frames per second when a CSV has no time column


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    frames = [int(r["frame"]) for r in rows]
    times = [float(r["time"]) if r.get("time") not in (None, "") else None for r in rows]
    return rows, frames, times


def ankle(row, side):
    try:
        return tuple(float(row[f"{side}Ankle_{a}"]) for a in "xyz")
    except (KeyError, ValueError):
        return None


def speeds(points, dt):
    """Horizontal speed (m/s, X-Z plane) at each frame by central differences; None where a neighbour is missing."""
    out = [None] * len(points)
    for i in range(1, len(points) - 1):
        a, b = points[i - 1], points[i + 1]
        if a is None or b is None:
            continue
        out[i] = math.hypot(b[0] - a[0], b[2] - a[2]) / (2 * dt)
    return out


def summary(values):
    v = sorted(x * 1000 for x in values if x is not None)
    if not v:
        return "-"
    return f"{sum(v) / len(v):6.1f} {v[len(v) // 2]:6.1f} {v[int(0.9 * (len(v) - 1))]:6.1f}"


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    truth_rows, _, _ = read(sys.argv[1])
    dt = 1.0 / RATE_HINT
    solved = []
    for path in sys.argv[2:]:
        rows, _, times = read(path)
        if len(rows) != len(truth_rows):
            sys.exit(f"{path}: {len(rows)} frames, the truth has {len(truth_rows)}")
        if times[0] is not None and times[-1] is not None and len(rows) > 1:
            dt = (times[-1] - times[0]) / (len(rows) - 1)
        solved.append((path, rows))
    print(f"frame period {dt * 1000:.1f} ms; horizontal ankle speed while the true foot stands, mm/s: mean median p90")
    for side in ("L", "R"):
        truth = [ankle(r, side) for r in truth_rows]
        floor = min(p[1] for p in truth if p is not None)
        truth_speed = speeds(truth, dt)
        standing = [s is not None and s < 0.1 and truth[i][1] < floor + 0.05 for i, s in enumerate(truth_speed)]
        count = sum(standing)
        print(f"{side} ankle: standing in {count} of {len(truth)} frames")
        print(f"  {'truth':24s} {summary([s for s, k in zip(truth_speed, standing) if k])}")
        for path, rows in solved:
            sp = speeds([ankle(r, side) for r in rows], dt)
            print(f"  {path[-24:]:24s} {summary([s for s, k in zip(sp, standing) if k])}")


if __name__ == "__main__":
    main()
