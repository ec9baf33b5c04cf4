#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Fit once, correct many, from Python: a saved vrreg model (the simulated UR5 cell A1, seed 1,
registered with kriging and with rbf) correcting one point per call and 10^6 points in one call,
beside the fitted objects a Python user would reach for instead on the same fiducials and
corrections: scipy's RBFInterpolator (thin-plate spline, the 3 correction components) and
scikit-learn's GaussianProcessRegressor (Matern 5/2 with vrreg's fitted length scales, so that
only its prediction is timed; predict with return_std). Prints a Markdown table
(docs/benchmarks.md, "Fit once, correct many").

    scripts/install-deps.sh --with-sklearn
    PYTHONPATH=build/release/python /usr/bin/python3 python/benchmarks/corrector_peers.py
"""
import argparse
import os
import subprocess
import tempfile
import time

import numpy as np
from scipy.interpolate import RBFInterpolator

import vrreg


def per_call(call, seconds=1.0):
    """Mean time of one call [s], over at least `seconds` of calls (after one warm-up)."""
    call()
    n, start = 0, time.perf_counter()
    while time.perf_counter() - start < seconds:
        call()
        n += 1
    return (time.perf_counter() - start) / n


def best(call, repeats=3):
    """Fastest of `repeats` runs [s]."""
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        call()
        times.append(time.perf_counter() - start)
    return min(times)


def a1_cell(directory):
    cli = os.environ.get("VRREG_CLI", "build/release/bin/vrreg")
    path = os.path.join(directory, "a1.csv")
    subprocess.run([cli, "simulate", "ur5", "A1", "--seed", "1", "-o", path], check=True,
                   stdout=subprocess.DEVNULL)
    return vrreg.read_measurements(path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=10**6)
    parser.add_argument("--gp-points", type=int, default=20000,
                        help="points scikit-learn predicts (with std) to time its rate")
    args = parser.parse_args()
    rng = np.random.default_rng(5)
    with tempfile.TemporaryDirectory() as directory:
        cell = a1_cell(directory)
    fiducial = np.array([r == "fiducial" for r in cell.roles])
    target = ~fiducial
    sensor, robot = cell.sensor[fiducial], cell.robot[fiducial]
    one = cell.sensor[target][:1]
    rows = []
    for method in ("kriging", "rbf"):
        fitted = vrreg.register(sensor, robot, interpolation=method).model
        model = vrreg.model_from_json(fitted.to_json())  # as a cell loads it
        lo, hi = robot.min(axis=0), robot.max(axis=0)
        # Readings in the sensor frame of robot positions inside the fiducials' box.
        batch = (rng.uniform(lo, hi, size=(args.points, 3)) - model.translation) @ model.rotation
        batch /= model.scale
        t_one = per_call(lambda: vrreg.correct(model, one))
        t_batch = best(lambda: vrreg.correct(model, batch), 2)
        rows.append((f"vrreg {method} (saved, tabulated)", t_one, args.points / t_batch))
        t_exact = per_call(lambda: vrreg.correct(model, one, exact=True), 2.0)
        rows.append((f"vrreg {method}, exact model", t_exact, float("nan")))
    # The peers on the same fiducials: nominal positions -> corrections (what vrreg fits).
    model = vrreg.register(sensor, robot, interpolation="kriging").model
    y, eps = model.fiducials_robot, model.corrections
    queries = model.apply(one)
    rbf = RBFInterpolator(y, eps)
    big = rng.uniform(y.min(axis=0), y.max(axis=0), size=(args.points, 3))
    rows.append(("scipy RBFInterpolator (fitted)", per_call(lambda: rbf(queries)),
                 args.points / best(lambda: rbf(big), 1)))
    try:
        from sklearn.gaussian_process import GaussianProcessRegressor
        from sklearn.gaussian_process.kernels import ConstantKernel, Matern, WhiteKernel
        kernel = (ConstantKernel(1e-8, "fixed") * Matern([0.05, 0.12, 0.06], "fixed", nu=2.5) +
                  WhiteKernel(1e-9, "fixed"))
        gp = GaussianProcessRegressor(kernel, optimizer=None, normalize_y=True).fit(y, eps)
        small = big[:args.gp_points]
        rows.append(("scikit-learn GaussianProcessRegressor (fitted, with std)",
                     per_call(lambda: gp.predict(queries, return_std=True)),
                     args.gp_points / best(lambda: gp.predict(small, return_std=True), 1)))
    except ImportError:
        rows.append(("scikit-learn (not installed: install-deps.sh --with-sklearn)",
                     float("nan"), float("nan")))
    print(f"A1: {fiducial.sum()} fiducials; batch of {args.points} points "
          f"(scikit-learn: {args.gp_points})\n")
    print("| corrector | one point | points per second |")
    print("|---|---:|---:|")
    for name, t_one, rate in rows:
        one_text = f"{t_one * 1e6:.1f} us" if t_one == t_one else "-"
        rate_text = ("-" if rate != rate else f"{rate / 1e6:.2f} M/s" if rate >= 1e5
                     else f"{rate / 1e3:.2f} k/s")
        print(f"| {name} | {one_text} | {rate_text} |")


if __name__ == "__main__":
    main()
