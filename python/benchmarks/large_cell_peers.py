#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The scipy peers of vrreg on a large cell (docs/benchmarks.md, "Large cells"): the fiducials and
targets scripts/bench-large-cell.sh simulates (47^3 = 103 823 fiducials at 10 mm, 1 000 targets),
registered by SVD, their corrections (paper Eq. 6) fitted and predicted at the targets by
scipy's RBFInterpolator (cubic, degree 1, neighbors=50) and by LinearNDInterpolator (scipy's
Delaunay, barycentric weights: vrreg's scattered), and scipy's Delaunay alone. Prints a Markdown
table: fit + predict wall time, peak memory growth, corrected RMS_T.

    scripts/bench-large-cell.sh -k -m linear          # makes /tmp/vrreg-large-cell/cell-47-*.csv
    /usr/bin/python3 python/benchmarks/large_cell_peers.py /tmp/vrreg-large-cell/cell-47
"""
import argparse
import csv
import resource
import time

import numpy as np
from scipy.interpolate import LinearNDInterpolator, RBFInterpolator
from scipy.spatial import Delaunay


def read_cell(path):
    """Per location (repeats averaged): nominal robot and sensor positions [m]."""
    sums = {}
    with open(path, encoding="ascii") as f:
        rows = csv.reader(line for line in f if not line.startswith("#"))
        header = next(rows)
        point = header.index("point")
        cols = [header.index(c) for c in ("robot_x_mm", "robot_y_mm", "robot_z_mm",
                                          "sensor_x_mm", "sensor_y_mm", "sensor_z_mm")]
        for row in rows:
            values = np.array([float(row[c]) for c in cols])
            entry = sums.setdefault(row[point], [np.zeros(6), 0])
            entry[0] += values
            entry[1] += 1
    mean = np.array([s / n for s, n in sums.values()]) * 1e-3
    return mean[:, :3], mean[:, 3:]


def register(sensor, robot):
    """Y ~ R X + t by SVD (no scale)."""
    xs, ys = sensor.mean(axis=0), robot.mean(axis=0)
    u, _, vt = np.linalg.svd((sensor - xs).T @ (robot - ys))
    d = np.sign(np.linalg.det(vt.T @ u.T))
    rotation = vt.T @ np.diag([1.0, 1.0, d]) @ u.T
    return rotation, ys - rotation @ xs


def timed(call):
    start = time.perf_counter()
    out = call()
    return out, time.perf_counter() - start


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("cell", help="path prefix: CELL-fiducials.csv and CELL-targets.csv")
    args = parser.parse_args()
    fid_robot, fid_sensor = read_cell(args.cell + "-fiducials.csv")
    tgt_robot, tgt_sensor = read_cell(args.cell + "-targets.csv")
    rotation, t = register(fid_sensor, fid_robot)
    # Eq. 6: the sensor-frame correction that maps each fiducial onto its commanded position.
    corrections = (fid_robot - t) @ rotation - fid_sensor
    registered = tgt_sensor @ rotation.T + t

    def rms_t(correction):
        corrected = (tgt_sensor + correction) @ rotation.T + t
        return 1e3 * np.sqrt(np.mean(np.sum((corrected - tgt_robot) ** 2, axis=1)))

    print(f"{len(fid_robot)} fiducials, {len(tgt_robot)} targets; uncorrected RMS_T "
          f"{rms_t(np.zeros_like(tgt_sensor)):.4f} mm\n")
    print("| peer | fit + predict, wall | peak RSS growth | corrected RMS_T |")
    print("|---|---:|---:|---:|")
    before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    for name, make in (
            ("scipy `RBFInterpolator(neighbors=50)` (cubic, degree 1)",
             lambda: RBFInterpolator(fid_robot, corrections, neighbors=50, kernel="cubic",
                                     degree=1)(registered)),
            ("scipy `LinearNDInterpolator` (Delaunay + barycentric)",
             lambda: LinearNDInterpolator(fid_robot, corrections)(registered))):
        correction, seconds = timed(make)
        grown = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - before
        print(f"| {name} | {seconds:.2f} s | {grown / 1024:.0f} MiB | {rms_t(correction):.4f} mm |")
    _, seconds = timed(lambda: Delaunay(fid_robot))
    grown = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - before
    print(f"| scipy `Delaunay` alone | {seconds:.2f} s | {grown / 1024:.0f} MiB | |")


if __name__ == "__main__":
    main()
