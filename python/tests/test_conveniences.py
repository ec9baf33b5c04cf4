# SPDX-License-Identifier: Apache-2.0
"""What users of scipy and Open3D expect of a transform-like object: pickle and copies, a version,
apply / as_matrix, single points, one exception type with Python names, readable reprs."""
import copy
import pickle
import re

import numpy as np
import pytest

import vrreg


def grid(n=4, step=0.025):
    axis = np.arange(n) * step
    return np.array(np.meshgrid(axis, axis, axis, indexing="ij")).reshape(3, -1).T.copy()


ANGLE = 0.3
ROTATION = np.array([[np.cos(ANGLE), -np.sin(ANGLE), 0], [np.sin(ANGLE), np.cos(ANGLE), 0],
                     [0, 0, 1]])
TRANSLATION = np.array([0.4, -0.1, 0.2])


@pytest.fixture(scope="module")
def registered():
    sensor = grid()
    robot = sensor @ ROTATION.T + TRANSLATION
    robot += 1e-4 * np.sin(40 * sensor)  # a smooth robot error for RRBC to correct
    return vrreg.register(sensor, robot)


def test_version():
    assert re.fullmatch(r"\d+\.\d+\.\d+", vrreg.__version__)


def test_pickle_and_copies_keep_the_model(registered):
    model = registered.model
    points = grid(3, 0.03) + 0.005
    want = vrreg.correct(model, points).corrected
    pickled = [pickle.loads(pickle.dumps(model, protocol=p))
               for p in range(pickle.HIGHEST_PROTOCOL + 1)]
    for clone in (*pickled, copy.copy(model), copy.deepcopy(model)):
        assert clone is not model
        assert clone.to_json() == model.to_json()
        np.testing.assert_array_equal(vrreg.correct(clone, points).corrected, want)


def test_as_matrix_and_apply(registered):
    model = registered.model
    T = model.as_matrix()
    assert T.shape == (4, 4)
    np.testing.assert_array_equal(T[3], [0, 0, 0, 1])
    np.testing.assert_allclose(T[:3, :3], model.rotation)
    np.testing.assert_allclose(T[:3, 3], model.translation)
    points = grid(2, 0.05)
    mapped = model.apply(points)
    assert mapped.shape == points.shape
    np.testing.assert_allclose(mapped, points @ T[:3, :3].T + T[:3, 3], rtol=0, atol=1e-15)
    one = model.apply(points[1])  # a single (3,) position gives a (3,) result
    assert one.shape == (3,)
    np.testing.assert_allclose(one, mapped[1], rtol=0, atol=1e-15)
    np.testing.assert_allclose(T[:3, :3], ROTATION, atol=1e-3)


def test_single_point_is_accepted(registered):
    one = vrreg.correct(registered.model, grid()[5])
    many = vrreg.correct(registered.model, grid()[5:6])
    np.testing.assert_array_equal(one.corrected, many.corrected)


@pytest.mark.parametrize("kwargs, message", [
    (dict(sensor=np.zeros((5, 2))), r"^sensor: expected an \(N, 3\) array"),
    (dict(sensor=grid(), robot=grid()[:10]), r"^robot: expected 64 entries"),
    (dict(sensor=grid(), robot=grid(), weights=np.ones(3)), r"^weights: expected 64 entries"),
    (dict(sensor=grid(), robot=grid(), configs=np.full(64, 2**40)), r"^configs\[0\] = 1099511627776"),
    (dict(sensor=grid(), robot=grid(), configs=np.ones(64)), r"^configs: expected integers"),
    (dict(sensor=grid(), robot=grid(), names="abc"), r"^names: expected a sequence of str"),
    (dict(sensor=grid(), robot=grid(), joints=np.ones((3, 6))), r"^joints: expected 64 entries"),
    (dict(sensor=grid() > 0.01, robot=grid()), r"^sensor: booleans \(bool\), expected real"),
    (dict(sensor=grid(), robot=grid(), weights=np.ones(64, dtype=bool)), r"^weights: booleans"),
])
def test_bad_input_is_one_exception_with_python_names(kwargs, message):
    with pytest.raises(vrreg.InputError, match=message) as raised:
        vrreg.register(**kwargs)
    assert "_m" not in str(raised.value)  # no C++ member names (sensor_m, robot_m)


def test_reprs(registered):
    text = repr(registered)
    assert re.search(r"FRE \d+\.\d{4} mm", text), text
    model_text = repr(registered.model)
    assert "fiducials" in model_text
    e = vrreg.evaluate(registered.model, grid(3, 0.03) + 0.005,
                       (grid(3, 0.03) + 0.005) @ ROTATION.T + TRANSLATION)
    text = repr(e)
    assert re.search(r"gamma -?\d+\.\d%", text), text
    assert "n_flagged" in text
    assert "n_flagged" in repr(vrreg.correct(registered.model, grid()))


def test_register_result_has_cross_validation(registered):
    assert registered.cross_validation is None


def test_stencil_status_value():
    assert vrreg.StencilStatus.OK.value == 0
    assert vrreg.StencilStatus(1).name == "OUTSIDE_GRID"
