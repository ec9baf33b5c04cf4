# SPDX-License-Identifier: Apache-2.0
"""Orientations from Python: the simulated UR5 A1 cell with a rigid-body marker, registered,
evaluated and corrected; the corrected orientations are rotations, closer to the commanded ones
than the uncorrected, and the figures are those of the command line's JSON."""
import json

import numpy as np
import pytest

import vrreg


def test_rigid_body_orientations_are_corrected():
    sim = vrreg.simulate("ur5", "A1", seed=1, rigid_body_mm=50.0)
    reg = vrreg.register(sim.measurements, interpolation="scattered")
    ev = vrreg.evaluate(reg.model, sim.measurements)
    angles = ev.angle_errors
    assert angles is not None
    assert angles["cor_rms"] < 0.2 * angles["unc_rms"]
    assert abs(np.sqrt(np.mean(angles["cor"] ** 2)) / angles["cor_rms"] - 1.0) < 1e-12
    orientation = ev.orientation
    rotations = orientation["R_robot_marker_corrected"]
    assert rotations.shape == (ev.n_targets, 3, 3)
    eye = np.einsum("nij,nkj->nik", rotations, rotations)
    assert np.abs(eye - np.eye(3)).max() < 1e-12
    assert orientation["q_robot_marker_corrected"].shape == (ev.n_targets, 4)
    assert orientation["rotation_robot"].shape == (ev.n_targets, 3)
    figures = json.loads(ev.to_json())["orientation"]
    assert abs(figures["cor_rms_angle_mrad"] - 1e3 * angles["cor_rms"]) < 1e-9
    corrected = vrreg.correct(reg.model, sim.measurements)
    assert corrected.orientation is not None
    # The same targets, the same corrector: the same bits as evaluate's.
    assert np.array_equal(corrected.orientation["R_robot_marker_corrected"], rotations)


def test_spheres_have_no_orientation_and_positions_do_not_change():
    with_body = vrreg.simulate("ur5", "A1", seed=2, rigid_body_mm=40.0)
    sphere = vrreg.simulate("ur5", "A1", seed=2)
    a = vrreg.evaluate(vrreg.register(with_body.measurements).model, with_body.measurements)
    b = vrreg.evaluate(vrreg.register(sphere.measurements).model, sphere.measurements)
    assert np.array_equal(a.cor_tre, b.cor_tre)
    assert b.orientation is None and b.angle_errors is None
    assert a.orientation is not None


def test_arrays_with_quaternions_give_the_measurements_numbers():
    sim = vrreg.simulate("ur5", "A1", seed=3, rigid_body_mm=50.0)
    m = sim.measurements
    assert m.sensor_q is not None and m.robot_q is not None
    assert m.sensor_q.shape == (len(m), 4)
    reg = vrreg.register(m, interpolation="trilinear")
    targets = np.array([r == "target" for r in m.roles])
    on_set = vrreg.correct(reg.model, m)
    on_arrays = vrreg.correct(reg.model, m.sensor[targets], sensor_q=m.sensor_q[targets])
    assert np.array_equal(on_arrays.corrected, on_set.corrected)
    assert np.array_equal(on_arrays.orientation["R_robot_marker_corrected"],
                          on_set.orientation["R_robot_marker_corrected"])
    # Register and evaluate on arrays carry orientations too.
    fid = ~targets
    reg_arrays = vrreg.register(m.sensor[fid], m.robot[fid], sensor_q=m.sensor_q[fid],
                                robot_q=m.robot_q[fid], interpolation="trilinear")
    ev = vrreg.evaluate(reg_arrays.model, m.sensor[targets], m.robot[targets],
                        sensor_q=m.sensor_q[targets], robot_q=m.robot_q[targets])
    assert ev.angle_errors is not None
    assert ev.angle_errors["cor_rms"] < 0.2 * ev.angle_errors["unc_rms"]


def test_bad_quaternion_arrays_are_value_errors():
    sim = vrreg.simulate("ur5", "A1", seed=3, rigid_body_mm=50.0)
    m = sim.measurements
    reg = vrreg.register(m, interpolation="scattered")
    targets = np.array([r == "target" for r in m.roles])
    q = m.sensor_q[targets].copy()
    with pytest.raises(ValueError, match="sensor_q"):
        vrreg.correct(reg.model, m.sensor[targets], sensor_q=q[:, :3])
    q[2] *= 1.1
    with pytest.raises(ValueError, match="sensor_q row 2"):
        vrreg.correct(reg.model, m.sensor[targets], sensor_q=q)
    with pytest.raises(ValueError, match="sensor_q"):
        vrreg.correct(reg.model, m.sensor[targets], sensor_q=m.sensor_q[targets][:-1])
    spheres = vrreg.register(vrreg.simulate("ur5", "A1", seed=3).measurements,
                             interpolation="scattered")
    with pytest.raises(ValueError, match="orientations"):
        vrreg.correct(spheres.model, m.sensor[targets], sensor_q=m.sensor_q[targets])
