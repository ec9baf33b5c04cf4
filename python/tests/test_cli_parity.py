# SPDX-License-Identifier: Apache-2.0
"""Python on a measurement CSV gives the command line's numbers (1e-12 relative), and model files
pass between the two."""
import csv
import json

import numpy as np
import pytest

import vrreg

MM = 1e3
REL = 1e-12
SIGMA_REP = 0.05 * 1e-3  # --sigma-rep-mm 0.05, converted as the command line does (mm * 1e-3)


def close(a, b, rtol=REL):
    return np.allclose(np.asarray(a, float), np.asarray(b, float), rtol=rtol, atol=0.0)


@pytest.fixture(scope="module")
def cell(example_cell):
    return vrreg.read_measurements(example_cell)


def test_register_matches_cli(cli, cell, example_cell, tmp_path):
    j = cli("register", "--fiducials", example_cell, "--sigma-rep-mm", 0.05, "--json")
    r = vrreg.register(cell, sigma_rep=SIGMA_REP)
    assert j["n_fiducials"] == r.n_registered
    assert close(j["rotation"], r.rotation)
    assert close(j["translation_mm"], r.translation * MM)
    for key, value in [("fre_mm", r.fre), ("sigma_l_mm", r.sigma_l), ("mean_l_mm", r.mean_l),
                       ("sigma_opt_mm", r.sigma_opt), ("sigma_noise_mm", r.sigma_noise)]:
        assert close(j[key], value * MM), key
    assert close(j["rho"], r.rho)
    assert j["pairs"] == r.pairs
    assert close(j["spread_mm"], r.spread * MM)
    own = json.loads(r.to_json())
    assert {k: v for k, v in j.items() if k not in ("source", "config", "sigma_rep_mm", "model")} == own


def test_evaluate_and_correct_match_cli(cli, cell, example_cell, tmp_path):
    model_path = tmp_path / "model.json"
    cli("register", "--fiducials", example_cell, "--sigma-rep-mm", 0.05, "-o", model_path)
    model = vrreg.load_model(str(model_path))
    j = cli("evaluate", "--model", model_path, "--targets", example_cell, "--json")
    e = vrreg.evaluate(model, cell)
    assert j["n_targets"] == e.n_targets and j["n_bad"] == e.n_bad
    assert j["interpolation"] == e.method and j["layout"] == e.layout
    assert j["bad_targets"] == e.bad_targets
    assert close(j["unc_rms_t_mm"], e.unc_rms_t * MM)
    assert close(j["cor_rms_t_mm"], e.cor_rms_t * MM)
    assert close(j["gamma_percent"], e.gamma * 100)
    assert close(j["cor_max_tre_mm"], e.cor_tre.max() * MM)
    # The result's own JSON is the command's, less what only the command knows (its files).
    own = json.loads(e.to_json())
    assert {k: v for k, v in j.items() if k not in ("model", "targets")} == own

    out = tmp_path / "corrected.csv"
    cli("correct", "--model", model_path, "--points", example_cell, "-o", out)
    with open(out) as f:
        rows = [r for r in csv.DictReader(line for line in f if not line.startswith("#"))]
    c = vrreg.correct(model, vrreg.read_measurements(example_cell, require_robot=False))
    assert [r["point"] for r in rows] == c.names
    assert [r["status"] for r in rows] == c.status_names
    got = np.array([[float(r[f"robot_{a}_mm"]) for a in "xyz"] for r in rows])
    assert close(got, c.corrected * MM, rtol=1e-11)  # the CSV holds 12 significant digits


def test_model_round_trip_python_to_cli(cli, cell, example_cell, tmp_path):
    model_path = tmp_path / "py-model.json"
    r = vrreg.register(cell, sigma_rep=SIGMA_REP)
    r.model.save(str(model_path))
    j = cli("evaluate", "--model", model_path, "--targets", example_cell, "--json")
    e = vrreg.evaluate(r.model, cell)
    assert close(j["cor_rms_t_mm"], e.cor_rms_t * MM)
    cli_model = tmp_path / "cli-model.json"
    cli("register", "--fiducials", example_cell, "--sigma-rep-mm", 0.05, "-o", cli_model)
    # Both name the same fiducial file as their source: the files are the same.
    assert vrreg.load_model(str(cli_model)).to_json() == vrreg.load_model(str(model_path)).to_json()


def test_reproduce_matches_cli(cli):
    j = cli("reproduce", "--seed", 1, "--json", "--quiet", "--out", "")
    assert vrreg.reproduce(seed=1) == j


def test_field_model_matches_cli_with_predicted_sd(cli, cell, example_cell, tmp_path):
    """A field model (trilinear on the filled lattice) gives the command line's numbers, and its
    predicted sd and calibration, through Python."""
    model_path = tmp_path / "model.json"
    cli("register", "--fiducials", example_cell, "--sigma-rep-mm", 0.05, "-o", model_path)
    model = vrreg.load_model(str(model_path))
    j = cli("evaluate", "--model", model_path, "--targets", example_cell,
            "--interpolation", "trilinear", "--json")
    e = vrreg.evaluate(model, cell, interpolation="trilinear")
    assert j["interpolation"] == e.method == "trilinear"
    assert close(j["cor_rms_t_mm"], e.cor_rms_t * MM)
    assert e.predicted_sd is not None and e.predicted_sd.shape == (e.n_targets,)
    assert close(j["predicted_sd_median_mm"], np.median(e.predicted_sd) * MM)
    assert close(j["calibration"]["rms_tre_over_sd"], e.calibration["rms_tre_over_sd"])
    assert vrreg.evaluate(model, cell).predicted_sd is None  # the paper's stencils give none


def test_joint_model_with_arm_matches_cli(cli, tmp_path):
    """The joint-space model from Python (arm=, stored in the model) gives the command line's
    numbers (--robot), and without an arm it says what is missing."""
    data = tmp_path / "a1.csv"
    cli("simulate", "ur5", "A1", "--seed", 2, "-o", data)
    model_path = tmp_path / "m.json"
    cli("register", "--fiducials", data, "--sigma-rep-mm", 0.1, "--robot", "ur5", "-o",
        model_path)
    j = cli("evaluate", "--model", model_path, "--targets", data, "--interpolation", "joint",
            "--json")
    measurements = vrreg.read_measurements(str(data))
    model = vrreg.register(measurements, sigma_rep=1e-4, arm="ur5").model
    e = vrreg.evaluate(model, measurements, interpolation="joint")
    assert j["interpolation"] == e.method == "joint"
    # The command line's model went through its JSON file (17 significant digits), and the
    # joint model's least squares amplify that last-digit difference a little.
    assert close(j["cor_rms_t_mm"], e.cor_rms_t * MM, rtol=1e-9)
    assert close(j["predicted_sd_median_mm"], np.median(e.predicted_sd) * MM, rtol=1e-9)
    assert e.cor_rms_t < 0.12e-3  # the noise floor of A1 is ~0.094 mm
    bare = vrreg.register(measurements, sigma_rep=1e-4).model
    again = vrreg.evaluate(bare, measurements, interpolation="joint", arm="ur5")
    assert close(again.cor_rms_t, e.cor_rms_t)
    with pytest.raises(ValueError, match="robot"):
        vrreg.evaluate(bare, measurements, interpolation="joint")
