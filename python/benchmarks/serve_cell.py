#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""An A1-size lattice cell for the service benchmark (scripts/bench-serve.sh): 11 x 11 x 10
fiducials at 25 mm (1 210, as the paper's A1 has 1 167) with a smooth robot error, 3 readings of
0.01 mm noise each, and 120 targets inside; writes CELL.csv and POINTS.txt (the targets' sensor
positions, mm, one "x y z" per line). Seeded: the same files every run.

    python3 python/benchmarks/serve_cell.py CELL.csv POINTS.txt
"""
import sys

import numpy as np


def field(p):
    x, y, z = p
    return np.array([0.15 * np.sin(x / 60), 0.12 * np.cos(y / 45), 0.10 * np.sin(z / 50)])


def main(cell_path, points_path):
    rng = np.random.default_rng(3)
    rotation = np.array([[0.36, -0.48, 0.8], [0.8, 0.6, 0.0], [-0.48, 0.64, 0.6]])
    shift = np.array([-1000.0, 300.0, 0.0])
    rows, points = [], []

    def sensor_of(robot):
        return rotation.T @ (robot + field(robot) + rng.normal(0, 0.01, 3) - shift)

    for i in range(11):
        for j in range(11):
            for k in range(10):
                robot = np.array([300 + 25 * i, -150 + 25 * j, 150 + 25 * k], float)
                for _ in range(3):
                    s = sensor_of(robot)
                    rows.append(f"f{i}_{j}_{k},fiducial,{robot[0]},{robot[1]},{robot[2]},"
                                f"{s[0]!r},{s[1]!r},{s[2]!r}")
    for t in range(120):
        robot = np.array([310, -140, 160]) + rng.uniform(0, 1, 3) * np.array([230, 230, 210])
        s = sensor_of(robot)
        rows.append(f"t{t},target,{robot[0]!r},{robot[1]!r},{robot[2]!r},{s[0]!r},{s[1]!r},{s[2]!r}")
        points.append(f"{s[0]!r} {s[1]!r} {s[2]!r}")
    with open(cell_path, "w") as f:
        f.write("point,role,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_mm,sensor_y_mm,sensor_z_mm\n")
        f.write("\n".join(rows) + "\n")
    with open(points_path, "w") as f:
        f.write("\n".join(points) + "\n")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: serve_cell.py CELL.csv POINTS.txt")
    main(sys.argv[1], sys.argv[2])
