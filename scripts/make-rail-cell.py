#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Write the rail cell: a measurement CSV of a UR5-geometry arm on a 2 m linear axis, as a cell
would record it. The robot is commanded by its nominal URDF (tests/data/urdf/ur5_on_rail.urdf);
it really moves as the as-built URDF (ur5_on_rail_as_built.urdf: the rail offset and skewed,
link lengths and the shoulder off by tenths of a millimetre) with a rail scale error of 0.8 mm/m,
a rail ripple of 0.15 mm and small joint offsets; a tracker 2-3 m away reads the marker with
0.02 mm of noise per axis.

Fiducials: a 5 x 3 x 3 lattice (75 mm, 100 mm, 100 mm) visited at three carriage positions (config
1, 2, 3 = 0.70, 1.00, 1.30 m). Targets: 30 points inside the lattice, each at a carriage position
drawn between 0.75 and 1.25 m (config 0). Tool pointing down, the same arm branch throughout.

Usage: PYTHONPATH=build/release/python python3 scripts/make-rail-cell.py OUT.csv [--seed N]
"""
import argparse
import pathlib

import numpy as np

import vrreg

DATA = pathlib.Path(__file__).resolve().parent.parent / "tests" / "data" / "urdf"
NOMINAL = str(DATA / "ur5_on_rail.urdf")
AS_BUILT = str(DATA / "ur5_on_rail_as_built.urdf")
RAIL_M = (0.70, 0.85, 1.00, 1.15, 1.30)
# Tool z straight down, tool x along the world x axis.
R_DOWN = np.array([[1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, -1.0]])


def rotation_error(R_target, R_now):
    """Rotation vector of R_target R_now^T (small angles)."""
    E = R_target @ R_now.T
    return 0.5 * np.array([E[2, 1] - E[1, 2], E[0, 2] - E[2, 0], E[1, 0] - E[0, 1]])


def arm_ik(rail_m, p_world_m, seed_q):
    """Arm joints putting tool0 at p (tool down) with the carriage at rail_m: damped Newton steps
    on the nominal chain, the carriage held fixed."""
    q = np.concatenate(([rail_m], seed_q))
    for _ in range(300):
        T = vrreg.fk(NOMINAL, q)
        e = np.concatenate((p_world_m - T[:3, 3], rotation_error(R_DOWN, T[:3, :3])))
        if np.linalg.norm(e) < 1e-13:
            return q
        J = np.zeros((6, 6))
        for k in range(6):
            dq = q.copy()
            dq[k + 1] += 1e-7
            Tk = vrreg.fk(NOMINAL, dq)
            J[:3, k] = (Tk[:3, 3] - T[:3, 3]) / 1e-7
            J[3:, k] = rotation_error(Tk[:3, :3], T[:3, :3]) / 1e-7
        step = np.linalg.solve(J.T @ J + 1e-6 * np.eye(6), J.T @ e)
        q[1:] += step * min(1.0, 0.2 / np.linalg.norm(step))  # damped, bounded: from far seeds
    raise SystemExit(f"make-rail-cell: no IK for {p_world_m} at rail {rail_m} m")


def actual_q(q):
    """The joints the arm really takes when commanded q: rail scale error and ripple, offsets."""
    qa = q.copy()
    qa[0] += 8e-4 * q[0] + 1.0e-4 * np.sin(2 * np.pi * q[0] / 1.6)
    qa[1:] += np.array([1.2e-4, -0.8e-4, 1.0e-4, 0.5e-4, -0.6e-4, 0.0])
    return qa


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("output")
    parser.add_argument("--seed", type=int, default=7)
    args = parser.parse_args()
    rng = np.random.default_rng(args.seed)
    # The tracker: 2.4 m in front of the cell, turned, its own frame.
    yaw, pitch = np.deg2rad(152.0), np.deg2rad(-8.0)
    Rz = np.array([[np.cos(yaw), -np.sin(yaw), 0], [np.sin(yaw), np.cos(yaw), 0], [0, 0, 1]])
    Ry = np.array([[np.cos(pitch), 0, np.sin(pitch)], [0, 1, 0], [-np.sin(pitch), 0, np.cos(pitch)]])
    R_sensor_robot = Ry @ Rz
    t_sensor_robot = np.array([2.1, -0.65, 0.4])
    centre = np.array([0.0, 0.0, 0.20])
    seed_q = np.array([-1.2, -1.9, -1.6, -1.2, 1.57, 0.4])

    rows = []

    def measure(name, role, config, rail_m, p):
        q = arm_ik(rail_m, p, seed_q)
        seed_q[:] = q[1:]  # the next location starts here: one arm branch throughout
        nominal = vrreg.fk(NOMINAL, q)[:3, 3]
        truth = vrreg.fk(AS_BUILT, actual_q(q))[:3, 3]
        sensor = R_sensor_robot @ truth + t_sensor_robot + rng.normal(0.0, 2e-5, 3)
        rows.append((name, role, config, nominal, sensor, q))

    offsets = [(x, y, z) for x in (-0.15, -0.075, 0.0, 0.075, 0.15) for y in (-0.1, 0.0, 0.1)
               for z in (-0.1, 0.0, 0.1)]
    for c, rail in enumerate(RAIL_M, start=1):
        for k, o in enumerate(offsets):
            measure(f"f{k:02d}_c{c}", "fiducial", str(c), rail, centre + np.array(o))
    for k in range(30):
        p = centre + rng.uniform([-0.14, -0.09, -0.09], [0.14, 0.09, 0.09])
        measure(f"t{k:02d}", "target", "0", rng.uniform(0.75, 1.25), p)

    with open(args.output, "w", encoding="ascii") as out:
        out.write(f"# rail cell: scripts/make-rail-cell.py --seed {args.seed}; robot "
                  "tests/data/urdf/ur5_on_rail.urdf (q1 is the carriage, metres)\n")
        out.write("point,role,config,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_mm,sensor_y_mm,"
                  "sensor_z_mm," + ",".join(f"q{i}_rad" for i in range(1, 8)) + "\n")
        for name, role, config, nominal, sensor, q in rows:
            values = [f"{v * 1e3:.4f}" for v in nominal] + [f"{v * 1e3:.4f}" for v in sensor]
            values += [f"{v:.9f}" for v in q]
            out.write(",".join([name, role, config] + values) + "\n")


if __name__ == "__main__":
    main()
