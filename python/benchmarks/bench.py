#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Registration and RRBC correction of 10^6 points from Python: the vrreg call, the same call timed
inside C++ (vrreg._vrreg._cpp_seconds_*: input already converted, so the difference is the
binding's overhead), and the scipy peers a Python user would reach for. Prints a Markdown table
(docs/benchmarks.md, "From Python").

    PYTHONPATH=build/release/python /usr/bin/python3 python/benchmarks/bench.py
"""
import argparse
import time

import numpy as np
from scipy.interpolate import LinearNDInterpolator, RBFInterpolator
from scipy.spatial.transform import Rotation

import vrreg
from vrreg import _vrreg


def best(call, repeats):
    """Fastest of `repeats` runs [s]."""
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        call()
        times.append(time.perf_counter() - start)
    return min(times)


def rigid_cell(n, rng):
    """n random robot positions [m] and what a tracker 2 m away measures (noise 0.05 mm)."""
    robot = rng.uniform(-0.15, 0.15, size=(n, 3))
    rotation = Rotation.from_euler("xyz", [0.2, -0.4, 1.1]).as_matrix()
    sensor = (robot - [0.4, 0.1, 2.0]) @ rotation + rng.normal(scale=5e-5, size=(n, 3))
    return sensor, robot, rotation


def distorted_grid(nodes, step, rotation, rng):
    """A fiducial grid [m] with a smooth 1 mm robot error, as sensor and robot positions."""
    axis = (np.arange(nodes) - (nodes - 1) / 2) * step
    robot = np.array(np.meshgrid(axis, axis, axis, indexing="ij")).reshape(3, -1).T.copy()
    error = 1e-3 * np.sin(robot * 8.0)
    sensor = (robot + error - [0.4, 0.1, 2.0]) @ rotation + rng.normal(scale=5e-5, size=robot.shape)
    return sensor, robot


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=10**6)
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--grid-nodes", type=int, default=21, help="fiducial grid nodes per axis")
    parser.add_argument("--rbf-fiducials", type=int, default=1000)
    parser.add_argument("--rbf-queries", type=int, default=100_000)
    args = parser.parse_args()
    rng = np.random.default_rng(1)
    n, k = args.points, args.repeats
    rows = []

    sensor, robot, rotation = rigid_cell(n, rng)
    py_reg = best(lambda: vrreg.register(sensor, robot, rigid_body=False), k)
    cpp_reg = _vrreg._cpp_seconds_register(sensor, robot, k, False)

    def scipy_register():
        # Kabsch on centred points; translation from the centroids (no FRE, no corrections).
        cs, cr = sensor.mean(axis=0), robot.mean(axis=0)
        r, _ = Rotation.align_vectors(robot - cr, sensor - cs)
        return cr - r.apply(cs)

    rows.append((f"register {n:,} points (rigid_body=False)", py_reg, cpp_reg,
                 "Rotation.align_vectors (rotation + centroids only)", best(scipy_register, k)))

    step = 0.3 / (args.grid_nodes - 1)
    fid_sensor, fid_robot = distorted_grid(args.grid_nodes, step, rotation, rng)
    model = vrreg.register(fid_sensor, fid_robot, rigid_body=False).model
    queries_robot = rng.uniform(-0.149, 0.149, size=(n, 3))
    queries = (queries_robot - [0.4, 0.1, 2.0]) @ rotation
    py_cor = best(lambda: vrreg.correct(model, queries), k)
    cpp_cor = _vrreg._cpp_seconds_correct(model, queries, k)
    corrections = model.corrections
    r_model, t_model = model.rotation, model.translation

    def scipy_linear():
        # Delaunay of the fiducials, barycentric weights: vrreg's 'scattered' method.
        field = LinearNDInterpolator(fid_sensor, corrections)
        return (queries + field(queries)) @ r_model.T + t_model

    rows.append((f"correct {n:,} points ({model.n_fiducials} fiducials, {model.interpolation} "
                 "-> grid)", py_cor, cpp_cor, "LinearNDInterpolator (build + query)",
                 best(scipy_linear, k)))

    sub = rng.choice(len(fid_sensor), size=min(args.rbf_fiducials, len(fid_sensor)),
                     replace=False)
    few = queries[: args.rbf_queries]

    def scipy_rbf():
        field = RBFInterpolator(fid_sensor[sub], corrections[sub])
        return (few + field(few)) @ r_model.T + t_model

    rbf = best(scipy_rbf, 1) * n / len(few)
    rows.append((None, None, None,
                 f"RBFInterpolator, thin-plate on {len(sub)} of the fiducials, "
                 f"{len(few):,} queries timed, x{n // len(few)}", rbf))

    print("| call | vrreg from Python | same call in C++ | overhead | peer | peer time |")
    print("|---|---:|---:|---:|---|---:|")
    for what, py_s, cpp_s, peer, peer_s in rows:
        if what is None:
            print(f"| | | | | {peer} | {peer_s * 1e3:.0f} ms |")
            continue
        print(f"| {what} | {py_s * 1e3:.1f} ms | {cpp_s * 1e3:.1f} ms | "
              f"{100 * (py_s - cpp_s) / cpp_s:+.1f} % | {peer} | {peer_s * 1e3:.1f} ms |")


if __name__ == "__main__":
    main()
