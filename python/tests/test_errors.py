# SPDX-License-Identifier: Apache-2.0
"""Every class of bad input raises a Python exception (a ValueError) and never kills the
interpreter."""
import numpy as np
import pytest

import vrreg


def grid(n=4, step=0.025):
    axis = np.arange(n) * step
    return np.array(np.meshgrid(axis, axis, axis, indexing="ij")).reshape(3, -1).T.copy()


@pytest.fixture(scope="module")
def model():
    robot = grid()
    return vrreg.register(robot + [0.1, 0.2, 0.3], robot).model


@pytest.mark.parametrize("sensor, robot, message", [
    (np.zeros((5, 2)), np.zeros((5, 2)), "(N, 3)"),
    (np.zeros(15), np.zeros(15), "(N, 3)"),
    (np.zeros((2, 3)), np.eye(3)[:2], "3"),
    (np.array([[0, 0, 0], [1, 0, 0], [2, 0, 0], [3, 0, 0]], float),
     np.array([[0, 0, 0], [1, 0, 0], [2, 0, 0], [3, 0, 0]], float), "collinear"),
    (grid()[:10], grid()[:9], "robot"),
    ([["a", "b", "c"]] * 4, grid()[:4], "sensor"),
])
def test_bad_arrays(sensor, robot, message):
    with pytest.raises(ValueError, match=message.replace("(", r"\(").replace(")", r"\)")):
        vrreg.register(sensor, robot)


def test_nan_is_named():
    sensor = grid()
    sensor[3, 1] = np.nan
    with pytest.raises(vrreg.InputError, match="not all finite"):
        vrreg.register(sensor, grid())


def test_mismatched_extras():
    with pytest.raises(ValueError, match="names"):
        vrreg.register(grid(), grid(), names=["a", "b"])
    with pytest.raises(ValueError, match="weights"):
        vrreg.register(grid(), grid(), weights=np.ones(3))


def test_bad_options(model):
    with pytest.raises(ValueError, match="interpolation"):
        vrreg.register(grid(), grid(), interpolation="cubic")
    with pytest.raises(ValueError, match="cube"):
        vrreg.evaluate(model, grid(), grid(), interpolation="octuplet")
    with pytest.raises(ValueError):
        vrreg.register(grid(), grid(), strategy=7)
    with pytest.raises(ValueError):
        vrreg.register(grid(), grid(), joint_norm="l3")
    with pytest.raises(TypeError):
        vrreg.register(grid(), grid(), interpolation=3)


def test_measurements_take_no_arrays(example_cell):
    cell = vrreg.read_measurements(example_cell)
    with pytest.raises(ValueError, match="arrays"):
        vrreg.register(cell, grid())


def test_missing_file(tmp_path):
    missing = str(tmp_path / "nope.csv")
    with pytest.raises(vrreg.FileError) as e:
        vrreg.read_measurements(missing)
    assert e.value.path == missing and isinstance(e.value, ValueError)
    with pytest.raises(vrreg.FileError):
        vrreg.load_model(str(tmp_path / "nope.json"))


def test_malformed_csv(tmp_path):
    bad = tmp_path / "bad.csv"
    bad.write_text("point,role,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_mm,sensor_y_mm,sensor_z_mm\n"
                   "F1,fiducial,1,2,3,4,5\n")
    with pytest.raises(vrreg.FileError) as e:
        vrreg.read_measurements(str(bad))
    assert e.value.line == 2 and str(bad) in str(e.value)
    bad.write_text("{}")
    with pytest.raises(vrreg.FileError):
        vrreg.load_model(str(bad))


def test_unwritable_model_path(model, tmp_path):
    with pytest.raises(ValueError):
        model.save(str(tmp_path / "no" / "such" / "dir" / "model.json"))


def test_kinematics_errors():
    with pytest.raises(ValueError, match="unknown robot"):
        vrreg.fk("ur99", np.zeros(6))
    with pytest.raises(ValueError, match="6 entries"):
        vrreg.fk("ur5", np.zeros(5))
    with pytest.raises(ValueError, match="4, 4"):
        vrreg.ik("ur5", np.eye(3))
