# SPDX-License-Identifier: Apache-2.0
"""Adaptive planning from Python: vrreg.plan_next gives the batch and the prediction that
`vrreg plan-next` writes, from a Measurements object or from arrays."""
import json
import math
import os
import subprocess

import numpy as np
import pytest

import vrreg

PARTS_MM = np.array([[420.0, -140.0, 250.0], [480.0, -140.0, 250.0], [480.0, -60.0, 260.0]])
NAMES = ["hole_A", "hole_B", "pin_C"]


def _cli(*args):
    run = subprocess.run([os.environ["VRREG_CLI"], *args], capture_output=True, text=True,
                         check=True)
    return run.stdout


def _plan_csv_rows(path):
    """point -> (x, y, z) mm of the data rows of a plan CSV."""
    rows = {}
    header = None
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("#"):
                continue
            cells = line.rstrip("\n").split(",")
            if header is None:
                header = cells
                continue
            rows[cells[0]] = tuple(float(cells[header.index(c)])
                                   for c in ("robot_x_mm", "robot_y_mm", "robot_z_mm"))
    return rows


@pytest.mark.skipif("VRREG_CLI" not in os.environ, reason="needs the vrreg binary")
def test_plan_next_matches_the_command_line(tmp_path):
    parts_csv = tmp_path / "parts.csv"
    parts_csv.write_text("point,robot_x_mm,robot_y_mm,robot_z_mm\n" + "".join(
        f"{n},{x:g},{y:g},{z:g}\n" for n, (x, y, z) in zip(NAMES, PARTS_MM)))
    common = ["--parts", str(parts_csv), "--robot", "ur5", "--goal-floor-multiple", "1",
              "--sigma-rep-mm", "0.05", "--batch", "6"]
    parts = PARTS_MM / 1000.0

    # First batch: nothing measured, the floor not known yet, a space-filling design of 12.
    first = vrreg.plan_next(parts, NAMES, goal_floor_multiple=1.0, sigma_rep=0.05e-3, batch=6)
    assert first.ok and first.decision == "continue" and first.space_filling
    assert first.goal_sd is None and first.noise_floor is None and first.predicted_sd_now is None
    assert len(first) == len(first.names) == 12 and first.joints.shape == (12, 6)
    b1 = tmp_path / "b1.csv"
    _cli("plan-next", *common, "-o", str(b1))
    cli_rows = _plan_csv_rows(b1)
    assert list(cli_rows) == first.names
    assert np.array_equal(np.array(list(cli_rows.values())), first.robot * 1000.0)

    # Measured on the simulated UR5: the same batch, prediction and floor as the command line.
    m1 = tmp_path / "m1.csv"
    _cli("simulate", "ur5", "--plan", str(b1), "--seed", "3", "-o", str(m1))
    measured = vrreg.read_measurements(str(m1))
    second = vrreg.plan_next(parts, NAMES, measured, goal_floor_multiple=1.0, sigma_rep=0.05e-3,
                             batch=6)
    cli = json.loads(_cli("plan-next", *common, "--measured", str(m1), "--json"))
    assert second.decision == cli["decision"] and second.reason == cli["reason"]
    assert second.n_measured == 12 and len(second) == cli["n_planned"] == 6
    assert second.predicted_sd_now * 1000.0 == pytest.approx(cli["predicted_sd_now_mm"], rel=1e-12)
    assert second.predicted_sd_after * 1000.0 == pytest.approx(cli["predicted_sd_after_mm"],
                                                               rel=1e-12)
    assert second.noise_floor * 1000.0 == pytest.approx(cli["noise_floor_mm"], rel=1e-12)
    assert second.goal_sd == pytest.approx(second.noise_floor, rel=1e-15)
    assert second.predicted_sd_after < second.predicted_sd_now
    assert second.part_sd_now.shape == (3,)
    rms = math.sqrt(float(np.mean(second.part_sd_now ** 2)))
    assert rms == pytest.approx(second.predicted_sd_now, rel=1e-12)
    assert second.names[0] == "n13"

    # Arrays in: the fiducials' averaged positions and the noise of one averaged reading (from
    # the floor, sqrt(3 (sigma_rep^2 + noise_sd^2))), the same batch.
    fid = [i for i, r in enumerate(measured.roles) if r == "fiducial"]
    noise_sd = math.sqrt(second.noise_floor ** 2 / 3.0 - 0.05e-3 ** 2)
    arrays = vrreg.plan_next(parts, NAMES, measured.sensor[fid], measured_robot=measured.robot[fid],
                             noise_sd=noise_sd, goal_floor_multiple=1.0, sigma_rep=0.05e-3,
                             batch=6)
    assert arrays.names == second.names
    assert np.allclose(arrays.robot, second.robot, atol=1e-12)
    assert arrays.predicted_sd_now == pytest.approx(second.predicted_sd_now, rel=1e-6)


@pytest.mark.skipif("VRREG_CLI" not in os.environ, reason="needs the vrreg binary")
def test_plan_next_judges_the_goal_on_the_joint_model(tmp_path):
    parts_csv = tmp_path / "parts.csv"
    parts_csv.write_text("point,robot_x_mm,robot_y_mm,robot_z_mm\n" + "".join(
        f"{n},{x:g},{y:g},{z:g}\n" for n, (x, y, z) in zip(NAMES, PARTS_MM)))
    parts = PARTS_MM / 1000.0
    # 27 fiducials around each part (81): enough for the joint-space model's parameters.
    plan = tmp_path / "plan.csv"
    _cli("plan", "--parts", str(parts_csv), "--robot", "ur5", "--halfwidth-mm", "20",
         "--spacing-mm", "20", "-o", str(plan))
    m = tmp_path / "m.csv"
    _cli("simulate", "ur5", "--plan", str(plan), "--only", "fiducial", "--seed", "3", "-o", str(m))
    measured = vrreg.read_measurements(str(m))
    joint = vrreg.plan_next(parts, NAMES, measured, goal_sd=1e-5, budget=200,
                            interpolation="joint")
    assert joint.decision == "continue" and len(joint) == 8
    assert joint.predicted_by == "joint" and joint.prediction_note == ""
    assert joint.predicted_sd_now > 0 and joint.predicted_sd_after is None
    cli = json.loads(_cli("plan-next", "--parts", str(parts_csv), "--robot", "ur5",
                          "--goal-sd-mm", "0.01", "--budget", "200", "--interpolation", "joint",
                          "--measured",
                          str(m), "--json"))
    assert cli["predicted_by"] == "joint"
    assert joint.predicted_sd_now * 1000.0 == pytest.approx(cli["predicted_sd_now_mm"], rel=1e-12)
    kriging = vrreg.plan_next(parts, NAMES, measured, goal_sd=1e-5, budget=200)
    assert kriging.predicted_by == "kriging"
    # The goal between the two predictions: reached for the lower one only (here kriging's:
    # three local cubes leave the joint-space model's parameters loosely determined).
    assert joint.predicted_sd_now != pytest.approx(kriging.predicted_sd_now, rel=0.05)
    goal = 0.5 * (joint.predicted_sd_now + kriging.predicted_sd_now)
    reasons = {method: vrreg.plan_next(parts, NAMES, measured, goal_sd=goal, budget=200,
                                       interpolation=method).reason
               for method in ("joint", "kriging")}
    lower = "joint" if joint.predicted_sd_now < kriging.predicted_sd_now else "kriging"
    for method, reason in reasons.items():
        assert (reason == "the goal is reached") == (method == lower), (method, reason)
    with pytest.raises(ValueError):
        vrreg.plan_next(parts, NAMES, measured.sensor, measured_robot=measured.robot,
                        goal_sd=1e-5, interpolation="joint")  # arrays carry no joints


def test_plan_next_refuses_bad_input():
    parts = PARTS_MM / 1000.0
    with pytest.raises(ValueError):
        vrreg.plan_next(parts, NAMES)  # no goal
    with pytest.raises(ValueError):
        vrreg.plan_next(parts, NAMES, goal_sd=1e-4, goal_floor_multiple=2.0)
    with pytest.raises(ValueError):
        vrreg.plan_next(parts, NAMES[:2], goal_sd=1e-4)
    with pytest.raises(ValueError):
        vrreg.plan_next(parts, NAMES, np.zeros((12, 3)), goal_sd=1e-4)  # no measured_robot
    with pytest.raises(ValueError):
        vrreg.plan_next(parts, NAMES, goal_sd=1e-4, robot="ur10")
    far = vrreg.plan_next(np.array([[2.0, 0.0, 0.2]]), ["far"], goal_sd=1e-4)
    assert not far.ok and "far" in far.message


def test_volume_part_points_fill_the_box_and_plan():
    # A 200 x 100 x 0 mm box at 50 mm: 5 x 3 x 1 nodes, centred, x fastest.
    parts, names = vrreg.volume_part_points([0.40, -0.15, 0.25], [0.60, -0.05, 0.25], 0.05)
    assert parts.shape == (15, 3)
    assert names[0] == "v1" and names[-1] == "v15"
    np.testing.assert_allclose(parts[0], [0.40, -0.15, 0.25], atol=1e-12)
    np.testing.assert_allclose(parts[1], [0.45, -0.15, 0.25], atol=1e-12)
    np.testing.assert_allclose(parts[-1], [0.60, -0.05, 0.25], atol=1e-12)
    # A 120 mm extent at 50 mm: 3 nodes with 10 mm left at each end.
    parts, _ = vrreg.volume_part_points([0.40, -0.15, 0.25], [0.52, -0.15, 0.25], 0.05)
    np.testing.assert_allclose(parts[:, 0], [0.41, 0.46, 0.51], atol=1e-12)
    first = vrreg.plan_next(*vrreg.volume_part_points([0.40, -0.15, 0.22], [0.50, -0.05, 0.29]),
                            goal_sd=1e-4, batch=6)
    assert len(first) == 12 and first.space_filling
    with pytest.raises(vrreg.InputError):
        vrreg.volume_part_points([0.5, 0, 0], [0.4, 0, 0], 0.05)
