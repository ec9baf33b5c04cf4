# SPDX-License-Identifier: Apache-2.0
"""UR and LWR 4+ kinematics: every IK solution reaches the pose (FK to 1e-12 m)."""
from pathlib import Path

import numpy as np
import pytest

import vrreg


@pytest.mark.parametrize("robot, q", [
    ("ur5", [0.3, -1.2, 1.4, -1.7, -1.5, 0.2]),
    ("ur10", [-0.7, -2.0, -1.1, 0.4, 1.3, -2.5]),
    ("lwr4", [0.2, 0.6, -0.3, -1.2, 0.4, 0.9, -0.1]),
])
def test_every_ik_solution_satisfies_fk(robot, q):
    pose = vrreg.fk(robot, np.array(q))
    assert pose.shape == (4, 4) and np.allclose(pose[3], [0, 0, 0, 1])
    psi = None
    if robot == "lwr4":
        psi = 0.0
    result = vrreg.ik(robot, pose, psi=psi)
    assert result["status"] == "ok"
    assert result["q"].shape == (len(result["configs"]), len(q)) and len(result["configs"]) >= 1
    assert len(set(result["configs"])) == len(result["configs"])
    for solution in result["q"]:
        reached = vrreg.fk(robot, solution)
        assert np.max(np.abs(reached[:3, 3] - pose[:3, 3])) < 1e-12
        assert np.max(np.abs(reached[:3, :3] - pose[:3, :3])) < 1e-9


def test_ur5_has_eight_solutions_in_general():
    pose = vrreg.fk("ur5", np.array([0.3, -1.2, 1.4, -1.7, -1.5, 0.2]))
    assert len(vrreg.ik("ur5", pose)["configs"]) == 8


def test_unreachable_is_a_status():
    pose = np.eye(4)
    pose[:3, 3] = [5.0, 0, 0]
    result = vrreg.ik("ur5", pose)
    assert result["status"] == "unreachable" and result["q"].shape == (0, 6)


def test_tool_offset():
    q = np.zeros(6)
    flange = vrreg.fk("ur5", q)
    tcp = vrreg.fk("ur5", q, tool=[0, 0, 0.1])
    assert np.allclose(tcp[:3, 3], flange[:3, 3] + 0.1 * flange[:3, 2], atol=1e-15)


URDF = Path(__file__).resolve().parents[2] / "tests" / "data" / "urdf"


def test_urdf_robots_fk_and_ik():
    # ROS-Industrial style UR5: root base_link is the DH base turned by pi about z.
    q = np.array([0.3, -1.2, 1.4, -1.7, -1.5, 0.2])
    turn = np.diag([-1.0, -1.0, 1.0, 1.0])
    assert np.allclose(vrreg.fk(str(URDF / "ur5.urdf"), q), turn @ vrreg.fk("ur5", q), atol=1e-12)
    # A 6-axis arm on a linear axis: numerical IK, every solution reaches the pose.
    rail = str(URDF / "ur5_on_rail.urdf")
    q7 = np.array([0.7, 0.3, -1.2, 1.4, -1.7, -1.5, 0.2])
    pose = vrreg.fk(rail, q7)
    result = vrreg.ik(rail, pose)
    assert result["status"] == "ok" and len(result["configs"]) >= 1
    for solution in result["q"]:
        assert np.max(np.abs(vrreg.fk(rail, solution)[:3, 3] - pose[:3, 3])) < 1e-12


def test_urdf_mimic_joints_and_tip_link():
    # A lifting column whose two stages mimic a side-branch drive, under a 6-axis arm: 7
    # commanded joints for 8 moving joints; the wrist's camera is as deep as tool0.
    lift = str(URDF / "lift_arm.urdf")
    with pytest.raises(ValueError, match="name the tip link"):
        vrreg.fk(lift, np.zeros(7))
    q = np.array([0.4, 0.3, -1.2, 1.5, -1.8, -1.57, 0.2])
    pose = vrreg.fk(lift, q, tip_link="tool0")
    result = vrreg.ik(lift, pose, tip_link="tool0")
    assert result["status"] == "ok" and result["q"].shape[1] == 7
    for solution in result["q"]:
        assert np.max(np.abs(vrreg.fk(lift, solution, tip_link="tool0") - pose)) < 1e-9
    with pytest.raises(ValueError, match="built-in ur5"):
        vrreg.fk("ur5", np.zeros(6), tip_link="tool0")
