#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Writes a large measurement CSV (design.md 6) for scale checks, without committing big data.

  scripts/make-large-input.py --fiducials 100000 --targets 0 -o /tmp/f.csv
  scripts/make-large-input.py --fiducials 0 --targets 1000000 -o /tmp/t.csv
  scripts/make-large-input.py --fiducials 1000000 --targets 1000 --targets-inside -o /tmp/c.csv

Locations lie on a cubic grid at --pitch-mm (fiducials first, then targets, each at its own grid
node, so no two share a position), or with --scattered uniformly at random in a 250 x 300 x 200 mm
box with their robot coordinates written with --decimals decimals (a cell measured at free
positions); the sensor frame is the robot frame turned 30 degrees about z
and shifted; the robot positions carry a smooth 0.2 mm error and the sensor readings Gaussian
noise of 0.05 mm per axis. One reading per location. Same arguments -> same bytes (seeded).
Standard library only (Debian's /usr/bin/python3).
"""
import argparse
import math
import random
import sys


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--fiducials", type=int, default=100000)
    parser.add_argument("--targets", type=int, default=0)
    parser.add_argument("--pitch-mm", type=float, default=2.0)
    parser.add_argument("--scattered", action="store_true",
                        help="uniform random positions instead of the grid")
    parser.add_argument("--decimals", type=int, default=3,
                        help="decimals of the robot coordinates with --scattered")
    parser.add_argument("--targets-inside", action="store_true",
                        help="targets uniform at random inside the fiducials' grid (one spacing "
                             "in from its faces) instead of at grid nodes after them")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("-o", "--output", required=True)
    args = parser.parse_args()
    if args.fiducials < 0 or args.targets < 0 or args.fiducials + args.targets == 0:
        parser.error("need a positive number of locations")
    rng = random.Random(args.seed)
    total = args.fiducials + args.targets
    side = max(2, math.ceil((args.fiducials if args.targets_inside else total) ** (1.0 / 3.0)))
    layers = max(1, (args.fiducials - 1) // (side * side))  # the fiducials' grid: side^2 x layers
    c, s = math.cos(math.radians(30.0)), math.sin(math.radians(30.0))
    shift = (250.0, 600.0, 2000.0)
    with open(args.output, "w", encoding="ascii", newline="\n") as out:
        layout = (f"--scattered --decimals {args.decimals}" if args.scattered
                  else f"--pitch-mm {args.pitch_mm}")
        if args.targets_inside:
            layout += " --targets-inside"
        out.write(f"# scripts/make-large-input.py --fiducials {args.fiducials} "
                  f"--targets {args.targets} {layout} --seed {args.seed}\n")
        out.write("point,role,robot_x_mm,robot_y_mm,robot_z_mm,"
                  "sensor_x_mm,sensor_y_mm,sensor_z_mm\n")
        lines = []
        for k in range(total):
            i, j, m = k % side, (k // side) % side, k // (side * side)
            x, y, z = 300.0 + i * args.pitch_mm, -200.0 + j * args.pitch_mm, 100.0 + m * args.pitch_mm
            if args.targets_inside and k >= args.fiducials:
                x, y, z = (round(300.0 + args.pitch_mm * rng.uniform(1.0, side - 2.0), 4),
                           round(-200.0 + args.pitch_mm * rng.uniform(1.0, side - 2.0), 4),
                           round(100.0 + args.pitch_mm * rng.uniform(1.0, layers - 1.0), 4))
            elif args.scattered:
                x, y, z = (round(300.0 + 250.0 * rng.random(), args.decimals),
                           round(-150.0 + 300.0 * rng.random(), args.decimals),
                           round(50.0 + 200.0 * rng.random(), args.decimals))
            # true TCP = nominal + smooth error; the sensor sees the true TCP plus noise
            tx = x + 0.2 * math.sin(0.01 * y)
            ty = y + 0.2 * math.cos(0.01 * z)
            tz = z + 0.2 * math.sin(0.01 * x)
            sx = c * tx + s * ty - shift[0] + rng.gauss(0.0, 0.05)
            sy = -s * tx + c * ty - shift[1] + rng.gauss(0.0, 0.05)
            sz = tz + shift[2] + rng.gauss(0.0, 0.05)
            role, name = ("fiducial", f"F{k}") if k < args.fiducials else ("target", f"T{k}")
            d = args.decimals if args.scattered else 4
            lines.append(f"{name},{role},{x:.{d}f},{y:.{d}f},{z:.{d}f},{sx:.5f},{sy:.5f},{sz:.5f}\n")
            if len(lines) >= 65536:
                out.writelines(lines)
                lines.clear()
        out.writelines(lines)
    return 0


if __name__ == "__main__":
    sys.exit(main())
