# SPDX-License-Identifier: Apache-2.0
"""Hand-eye registration from Python: a noise-free UR5 cell gives the offset and transform back,
one fixed orientation is reported unobservable."""
import numpy as np

import vrreg


def _cell(tilt):
    rng = np.random.default_rng(3)
    p_true = np.array([0.035, -0.025, 0.085])
    angle = 0.4
    c, s = np.cos(angle), np.sin(angle)
    rotation = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])
    translation = np.array([1.2, -0.5, 0.8])
    joints, sensor = [], []
    for j in range(30):
        q = np.array([0.2, -1.4, 1.6, -1.8, -1.57, 0.3]) + rng.uniform(-0.3, 0.3, 6) * tilt
        flange = vrreg.fk("ur5", q)
        marker = flange[:3, :3] @ p_true + flange[:3, 3]
        sensor.append(rotation.T @ (marker - translation))
        joints.append(q)
    return np.array(joints), np.array(sensor), p_true, rotation, translation


def test_noise_free_recovery():
    joints, sensor, p_true, rotation, translation = _cell(1.0)
    r = vrreg.estimate_marker_offset("ur5", joints, sensor)
    assert r["status"] == "ok"
    assert np.max(np.abs(r["p_flange_marker"] - p_true)) < 1e-9
    assert np.max(np.abs(r["rotation"] - rotation)) < 1e-9
    assert np.max(np.abs(r["translation"] - translation)) < 1e-9


def test_one_orientation_is_unobservable():
    joints, sensor, *_ = _cell(1.0)
    joints[:, 1:] = joints[0, 1:]  # only joint 1 moves: the flange turns about one axis
    r = vrreg.estimate_marker_offset("ur5", joints, sensor)
    assert r["status"] == "unobservable"
