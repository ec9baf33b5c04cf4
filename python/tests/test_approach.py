# SPDX-License-Identifier: Apache-2.0
"""Approach directions in correct() and evaluate(): approach_from_q or approach_sign, checked and
named as the caller named them; a model without a lost-motion term answers as without them."""
import json

import numpy as np
import pytest

import vrreg


def grid_cell():
    axis = np.arange(5) * 0.025
    robot = np.array(np.meshgrid(axis, axis, axis, indexing="ij")).reshape(3, -1).T.copy()
    sensor = (robot + [0.1, 0.2, 0.3] + 5e-4 * np.sin(20 * robot)
              + np.random.default_rng(2).normal(scale=5e-5, size=robot.shape))
    return sensor, robot


@pytest.fixture(scope="module")
def model_and_points():
    sensor, robot = grid_cell()
    model = vrreg.register(sensor, robot, interpolation="kriging").model
    rng = np.random.default_rng(5)
    points = sensor[30:40] + rng.normal(scale=2e-3, size=(10, 3))
    joints = rng.uniform(-1.0, 1.0, size=(10, 6))
    return model, points, robot[30:40], joints


def test_a_model_without_lost_motion_answers_as_without_a_direction(model_and_points):
    model, points, robot, joints = model_and_points
    plain = vrreg.correct(model, points, joints=joints)
    came_from = joints + np.where(np.arange(6) % 2 == 0, 0.1, -0.1)
    from_q = vrreg.correct(model, points, joints=joints, approach_from_q=came_from)
    signs = vrreg.correct(model, points, joints=joints,
                          approach_sign=np.tile([1, -1, 0, 1, -1, 0], (10, 1)))
    for other in (from_q, signs):
        assert np.array_equal(other.corrected, plain.corrected)
        assert np.array_equal(other.predicted_sd, plain.predicted_sd)
    ev = vrreg.evaluate(model, points, robot, joints=joints, approach_from_q=came_from)
    assert ev.n_targets == 10
    assert ev.cor_rms_t == vrreg.evaluate(model, points, robot, joints=joints).cor_rms_t


@pytest.mark.parametrize("kwargs, message", [
    ({"approach_from_q": np.zeros((10, 6))}, "needs joints"),
    ({"joints": np.zeros((10, 6)), "approach_from_q": np.zeros((10, 5))},
     "approach_from_q: 5 joints per row, joints has 6"),
    ({"joints": np.zeros((10, 6)), "approach_from_q": np.zeros((9, 6))}, "approach_from_q"),
    ({"joints": np.zeros((10, 6)), "approach_from_q": np.full((10, 6), np.nan)}, "not all finite"),
    ({"joints": np.zeros((10, 6)), "approach_sign": np.full((10, 6), 0.5)},
     "a sign is -1, 0 or 1"),
    ({"joints": np.zeros((10, 6)), "approach_sign": np.full((10, 6), 2)}, "-1, 0 or 1"),
    ({"joints": np.zeros((10, 6)), "approach_sign": np.ones((10, 6)),
      "approach_from_q": np.ones((10, 6))}, "not both"),
])
def test_malformed_directions_raise_value_error_naming_the_argument(model_and_points, kwargs,
                                                                     message):
    model, points, _, _ = model_and_points
    with pytest.raises(ValueError, match=message):
        vrreg.correct(model, points, **kwargs)


def test_measurements_carry_their_own_directions(model_and_points, example_cell):
    model, _, _, _ = model_and_points
    targets = vrreg.read_measurements(example_cell)
    with pytest.raises(ValueError, match="approach_sign go with arrays"):
        vrreg.correct(model, targets, approach_sign=np.ones((3, 6)))


def test_evaluate_reports_multidirectional_accuracy_as_the_command_does(model_and_points):
    model, points, robot, joints = model_and_points
    # Each of the ten targets visited twice, from opposite directions of every joint.
    twice = np.vstack([points, points + 1e-5])
    signs = np.vstack([np.ones((10, 6)), -np.ones((10, 6))])
    names = [f"t{i}" for i in range(10)] * 2
    ev = vrreg.evaluate(model, twice, np.vstack([robot, robot]), names=names,
                        joints=np.vstack([joints, joints]), approach_sign=signs)
    m = ev.multidirectional
    assert m is not None and m["n_points"] == 10
    assert [d["approach"] for d in m["directions"]] == ["++++++", "------"]
    assert [d["n_targets"] for d in m["directions"]] == [10, 10]
    # The second visit reads 1e-5 m further on every axis: every point's directions are that far
    # apart uncorrected.
    assert m["unc_spread_max"] == pytest.approx(np.sqrt(3) * 1e-5, rel=1e-6)
    assert m["unc_spread_mean"] == pytest.approx(np.sqrt(3) * 1e-5, rel=1e-6)
    cli = json.loads(ev.to_json())["multidirectional"]
    assert cli["n_points"] == 10
    assert cli["unc_spread_max_mm"] == pytest.approx(1e3 * m["unc_spread_max"], rel=1e-12)
    assert vrreg.evaluate(model, points, robot, joints=joints).multidirectional is None
