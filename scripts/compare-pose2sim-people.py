#!/usr/bin/env python3
"""Compares octocap's several-people solve with Pose2Sim's own person association and triangulation on the same 2D
detections (scripts/compare-pose2sim-people.sh runs both and then this). Prints, per person: frames, the median
distance between the two systems' keypoints, and each system's thigh lengths (an identity switch mixes builds).

Usage: compare-pose2sim-people.py OURS.csv POSE2SIM_P0.trc POSE2SIM_P1.trc ...
"""
import csv
import itertools
import math
import sys

import numpy as np


def read_ours(path):
    rows = list(csv.reader(open(path)))
    # frame,time,person,NAME_x,... (1.6; before it frame,person,NAME_x,...)
    person = rows[0].index('person')
    first = person + 1
    names = [c[:-2] for c in rows[0][first::3]]
    people = {}
    for r in rows[1:]:
        r = r + [''] * (first + 3 * len(names) - len(r))
        frame, pid = int(r[0]), int(r[person])
        pts = np.array([[float(r[first + 3 * k + i]) if r[first + 3 * k] else np.nan for i in range(3)]
                        for k in range(len(names))])
        people.setdefault(pid, {})[frame] = pts
    return names, people


def read_trc(path):
    lines = open(path).read().splitlines()
    names = [n for n in lines[3].split('\t')[2:] if n]
    frames = {}
    for line in lines[5:]:
        cells = line.split('\t')
        if len(cells) < 2 + 3 * len(names):
            continue
        values = [float(c) if c else np.nan for c in cells[2:2 + 3 * len(names)]]
        frames[int(cells[0])] = np.array(values).reshape(-1, 3)
    return names, frames


def main():
    ours_names, ours = read_ours(sys.argv[1])
    theirs = [read_trc(p) for p in sys.argv[2:]]
    names = theirs[0][0]
    idx = [ours_names.index(n) for n in names]
    # Pose2Sim writes Y up; octocap keeps the calibration's world (Z up here): the axis map that makes frame 0 agree.
    best = None
    first_ours = [p[min(p)][idx] for p in ours.values()]
    first_theirs = [t[1][min(t[1])] for t in theirs]
    for perm in itertools.permutations(range(3)):
        for signs in itertools.product([1, -1], repeat=3):
            m = np.zeros((3, 3))
            for i in range(3):
                m[i, perm[i]] = signs[i]
            cost = sum(min(np.nanmedian(np.linalg.norm(a @ m.T - b, axis=1)) for b in first_theirs) for a in first_ours)
            if best is None or cost < best[0]:
                best = (cost, m)
    m = best[1]
    lhip, lknee, rhip, rknee = (names.index(n) for n in ('LHip', 'LKnee', 'RHip', 'RKnee'))
    thigh = lambda p: [np.linalg.norm(p[a] - p[b]) for a, b in ((lhip, lknee), (rhip, rknee))
                       if np.all(np.isfinite(p[a])) and np.all(np.isfinite(p[b]))]
    print("| person (octocap / Pose2Sim) | frames (octocap / Pose2Sim) | median distance between them | thigh octocap | thigh Pose2Sim |")
    print("|---|---|---|---|---|")
    for pid, frames in sorted(ours.items()):
        mapped = {f: p[idx] @ m.T for f, p in frames.items()}
        # The Pose2Sim participant nearest this person over the take.
        def distance(t):
            d = [np.nanmedian(np.linalg.norm(mapped[f] - t[f], axis=1)) for f in mapped if f in t]
            return np.nanmedian(d) if d else math.inf
        j = min(range(len(theirs)), key=lambda j: distance(theirs[j][1]))
        t = theirs[j][1]
        all_d = np.concatenate([np.linalg.norm(mapped[f] - t[f], axis=1) for f in mapped if f in t])
        all_d = all_d[np.isfinite(all_d)]
        t_ours = np.median([x for p in frames.values() for x in thigh(p[idx])])
        t_theirs = np.median([x for p in t.values() for x in thigh(p)])
        print(f"| {pid} / P{j} | {len(frames)} / {sum(1 for p in t.values() if np.isfinite(p).any())} | "
              f"{1000 * np.median(all_d):.0f} mm (90th percentile {1000 * np.percentile(all_d, 90):.0f} mm) | "
              f"{t_ours:.2f} m | {t_theirs:.2f} m |")


if __name__ == '__main__':
    main()
