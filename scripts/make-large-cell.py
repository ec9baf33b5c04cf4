#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Helpers of scripts/bench-large-cell.sh: the plan of a large lattice cell with joints.

  make-large-cell.py parts --nodes 47 --spacing-mm 10 --targets 1000 --seed 1 DIR
      writes DIR/centre_K.csv (the lattice's plan centres, 8 for an odd node count) and
      DIR/target_parts.csv (the targets, uniform inside the lattice, seeded)
  make-large-cell.py merge --nodes 47 DIR/plan_0.csv ... DIR/plan_t.csv -o PLAN.csv
      the union of the lattice plans cut to nodes^3 fiducials, plus the target rows of the last
      plan: one plan for `vrreg simulate ur5 --plan`
  make-large-cell.py split CELL.csv FIDUCIALS.csv TARGETS.csv
      the simulated cell's fiducial and target rows in two measurement CSVs

`vrreg plan` centres a part point in a grid cell, so a plan has an even number of nodes per
axis; eight plans one spacing apart (towards the base, within reach) cover an odd count (about
the UR5 test bed's volume centre, 450, 0, 250 mm, with 47 nodes at 10 mm: 103 823 fiducials). Standard library only; same
arguments -> same bytes.
"""
import argparse
import csv
import random
import sys

CENTRE_MM = (450.0, 0.0, 250.0)


def parts(args):
    even = args.nodes - (args.nodes % 2)  # nodes of each plan
    half = 0.5 * (even - 1) * args.spacing_mm
    shift = -args.spacing_mm if args.nodes % 2 else 0.0  # towards the base: in reach
    for k in range(8 if shift else 1):  # every corner of the odd lattice in one of the plans
        offset = [shift if k >> a & 1 else 0.0 for a in range(3)]
        with open(f"{args.dir}/centre_{k}.csv", "w", encoding="ascii", newline="\n") as out:
            out.write("point,robot_x_mm,robot_y_mm,robot_z_mm\n")
            out.write("C,%.6f,%.6f,%.6f\n" % tuple(c + o for c, o in zip(CENTRE_MM, offset)))
    rng = random.Random(args.seed)
    lo = [c - half + shift for c in CENTRE_MM]
    span = (args.nodes - 1) * args.spacing_mm
    margin = args.spacing_mm  # targets at least one spacing inside the lattice's faces
    with open(f"{args.dir}/target_parts.csv", "w", encoding="ascii", newline="\n") as out:
        out.write("point,robot_x_mm,robot_y_mm,robot_z_mm\n")
        for k in range(args.targets):
            xyz = [round(lo[a] + margin + (span - 2 * margin) * rng.random(), 3) for a in range(3)]
            out.write("T%d,%.3f,%.3f,%.3f\n" % (k, *xyz))
    # the planner's half-width: (even - 1) / 2 cells of A rounded up to a cell centre
    print("%.6f" % (0.5 * (even - 1) * args.spacing_mm))
    return 0


def rows_of(path):
    with open(path, encoding="ascii") as f:
        lines = [l for l in f if not l.startswith("#")]
    return lines[0], list(csv.reader(lines[1:]))


def merge(args):
    header, _ = rows_of(args.plans[0])
    lattice = []
    for path in args.plans[:-1]:
        lattice += rows_of(path)[1]
    _, t = rows_of(args.plans[-1])
    names = header.strip().split(",")
    ix, iy, iz = (names.index(c) for c in ("robot_x_mm", "robot_y_mm", "robot_z_mm"))
    seen = {}
    for row in lattice:
        if row[1] != "fiducial":
            continue
        key = tuple(round(float(row[i]) * 1000.0) for i in (ix, iy, iz))  # um
        seen.setdefault(key, row)
    lo = [min(k[a] for k in seen) for a in range(3)]
    with open(args.output, "w", encoding="ascii", newline="\n") as out:
        out.write(header)
        n = 0
        for key in sorted(seen):
            if all(key[a] - lo[a] < (args.nodes - 0.5) * args.spacing_mm * 1000.0 for a in range(3)):
                row = list(seen[key])
                row[0] = "F%d" % n
                out.write(",".join(row) + "\n")
                n += 1
        for row in t:
            if row[1] == "target":
                out.write(",".join(row) + "\n")
    if n != args.nodes ** 3:
        sys.exit(f"merge: {n} fiducials, expected {args.nodes ** 3}")
    return 0


def split(args):
    with open(args.cell, encoding="ascii") as f, \
            open(args.fiducials, "w", encoding="ascii", newline="\n") as fid, \
            open(args.targets, "w", encoding="ascii", newline="\n") as tgt:
        header = None
        for line in f:
            if line.startswith("#"):
                fid.write(line)
                tgt.write(line)
                continue
            if header is None:
                header = line
                fid.write(line)
                tgt.write(line)
                role = header.strip().split(",").index("role")
                continue
            (tgt if line.split(",")[role] == "target" else fid).write(line)
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("parts")
    p.add_argument("--nodes", type=int, default=47)
    p.add_argument("--spacing-mm", type=float, default=10.0)
    p.add_argument("--targets", type=int, default=1000)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("dir")
    m = sub.add_parser("merge")
    m.add_argument("--nodes", type=int, default=47)
    m.add_argument("--spacing-mm", type=float, default=10.0)
    m.add_argument("plans", nargs="+", help="the lattice plans, then the targets' plan")
    m.add_argument("-o", "--output", required=True)
    s = sub.add_parser("split")
    s.add_argument("cell")
    s.add_argument("fiducials")
    s.add_argument("targets")
    args = parser.parse_args()
    return {"parts": parts, "merge": merge, "split": split}[args.command](args)


if __name__ == "__main__":
    sys.exit(main())
