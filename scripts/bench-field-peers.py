#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""vrreg's field models beside the peers a user would pick, on the same data.

Runs the vrreg benchmark binary (BM_FieldKriging, BM_FieldRbf) with VRREG_FIELD_DATA_DIR set,
so it writes the A1 (1 167 fiducials) and A2 (7 965) fields it fits as CSV; then fits
scikit-learn's GaussianProcessRegressor (anisotropic Matern 5/2 + white noise, ML
hyperparameters) and scipy's RBFInterpolator (cubic, degree 1, smoothing by 5-fold CV on a
grid) to the same fiducials and prints RMS against the true field at the 120 / 960 targets and
the wall time of fit + predict. Needs Debian's python3-numpy, python3-scipy, python3-sklearn
(scripts/install-deps.sh --with-sklearn). Usage:
  /usr/bin/python3 scripts/bench-field-peers.py build/release/benchmarks/vrreg_benchmarks [--skip-a2-gp]
"""
import json
import os
import subprocess
import sys
import tempfile
import time

import numpy as np
from scipy.interpolate import RBFInterpolator
from sklearn.gaussian_process import GaussianProcessRegressor
from sklearn.gaussian_process.kernels import ConstantKernel, Matern, WhiteKernel


def load(path):
    data = np.loadtxt(path, delimiter=",", skiprows=1)
    return data[:, :3], data[:, 3:]


def rms_3d_mm(predicted_m, truth_m):
    return 1e3 * float(np.sqrt(np.mean(np.sum((predicted_m - truth_m) ** 2, axis=1))))


def sklearn_gp(fid, val, tgt, fit_subset=None):
    """Per axis, ML hyperparameters (sklearn's L-BFGS-B, no restart); above fit_subset the
    hyperparameters come from a seeded subset and the final fit uses all fiducials."""
    out = np.zeros((tgt.shape[0], 3))
    for axis in range(3):
        kernel = ConstantKernel(1.0, (1e-3, 1e2)) * Matern(
            length_scale=[0.1, 0.1, 0.1], length_scale_bounds=(1e-3, 10.0), nu=2.5
        ) + WhiteKernel(0.01, (1e-8, 1.0))
        x, y = fid, val[:, axis]
        if fit_subset is not None and len(x) > fit_subset:
            pick = np.random.default_rng(1).choice(len(x), fit_subset, replace=False)
            gp = GaussianProcessRegressor(kernel, normalize_y=True, n_restarts_optimizer=0,
                                          random_state=0).fit(x[pick], y[pick])
            gp = GaussianProcessRegressor(gp.kernel_, normalize_y=True, optimizer=None).fit(x, y)
        else:
            gp = GaussianProcessRegressor(kernel, normalize_y=True, n_restarts_optimizer=0,
                                          random_state=0).fit(x, y)
        out[:, axis] = gp.predict(tgt)
    return out


def scipy_rbf(fid, val, tgt, neighbors=None):
    """Cubic RBF, degree 1; smoothing by 5-fold CV (seeded folds) over 7 values."""
    folds = np.random.default_rng(1).integers(0, 5, len(fid))
    best = (np.inf, 0.0)
    for smoothing in 10.0 ** np.arange(-10, -3):
        sse = 0.0
        for k in range(5):
            train, test = folds != k, folds == k
            model = RBFInterpolator(fid[train], val[train], kernel="cubic", degree=1,
                                    smoothing=smoothing, neighbors=neighbors)
            sse += float(np.sum((model(fid[test]) - val[test]) ** 2))
        best = min(best, (sse, smoothing))
    model = RBFInterpolator(fid, val, kernel="cubic", degree=1, smoothing=best[1],
                            neighbors=neighbors)
    return model(tgt)


class Rows(list):
    """Prints each table row as soon as it is measured (the GP peers take minutes)."""

    def append(self, row):
        dataset, method, rms_mm, sec = row
        print(f"| {dataset} | {method} | {rms_mm:.4f} | {sec:.2f} |", flush=True)
        super().append(row)


def timed(fn, *args, **kwargs):
    start = time.perf_counter()
    result = fn(*args, **kwargs)
    return result, time.perf_counter() - start


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    binary = sys.argv[1]
    skip_a2_gp = "--skip-a2-gp" in sys.argv
    with tempfile.TemporaryDirectory() as tmp:
        env = dict(os.environ, VRREG_FIELD_DATA_DIR=tmp)
        run = subprocess.run(
            [binary, "--benchmark_filter=BM_Field(Kriging/[01]/500/2000/2|Rbf)",
             "--benchmark_format=json"], env=env, check=True, capture_output=True, text=True)
        vrreg = {}
        for b in json.loads(run.stdout)["benchmarks"]:
            method = "kriging" if "Kriging" in b["name"] else "rbf"
            dataset = "A1" if b["fiducials"] < 2000 else "A2"
            vrreg[(dataset, method)] = (b["rms_um"] / 1e3, b["real_time"] / 1e3)
            print(f"vrreg {method} {dataset}: process CPU {b['cpu_time'] / 1e3:.2f} s",
                  file=sys.stderr)
        print("| data | method | RMS vs true field [mm] | fit + predict [s] |")
        print("|---|---|---|---|", flush=True)
        rows = Rows()
        for dataset in ("A1", "A2"):
            fid, val = load(f"{tmp}/{dataset.lower()}_fiducials.csv")
            tgt, truth = load(f"{tmp}/{dataset.lower()}_targets.csv")
            big = len(fid) > 2000
            rows.append((dataset, "vrreg kriging", *vrreg[(dataset, "kriging")]))
            if big and skip_a2_gp:
                pass
            else:
                pred, sec = timed(sklearn_gp, fid, val, tgt, 1000 if big else None)
                rows.append((dataset, "sklearn GaussianProcessRegressor", rms_3d_mm(pred, truth), sec))
            rows.append((dataset, "vrreg rbf", *vrreg[(dataset, "rbf")]))
            pred, sec = timed(scipy_rbf, fid, val, tgt, 150 if big else None)
            rows.append((dataset, "scipy RBFInterpolator (5-fold CV)", rms_3d_mm(pred, truth), sec))


if __name__ == "__main__":
    main()
