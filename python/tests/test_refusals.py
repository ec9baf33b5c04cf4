# SPDX-License-Identifier: Apache-2.0
"""Inputs at the edges: a part point too far to reach is a status naming it (never NaN joints),
complex arrays are refused (numpy would drop their imaginary parts with a warning only), and a
path is a str or any os.PathLike wherever one is taken."""
import pathlib
import warnings

import numpy as np
import pytest

import vrreg


class Where:
    """An os.PathLike that is no pathlib.Path."""

    def __init__(self, path):
        self.path = str(path)

    def __fspath__(self):
        return self.path


@pytest.fixture(scope="module")
def robot_file(example_cell):
    return pathlib.Path(example_cell).parents[2] / "tests" / "fuzz" / "corpus" / "robot_file" / \
        "ur5.json"


@pytest.mark.parametrize("far", [[1e305, 0, 0], [1e200, 1e200, 0], [-1.7e305, 1.7e305, 1e305],
                                 [10.0, 0, 0]])
@pytest.mark.parametrize("robot", ["ur5", "lwr4"])
def test_far_part_point_is_unreachable_and_named(far, robot):
    p = vrreg.plan(np.array([[0.48, 0.22, 0.30], far]), ["near", "A"], robot=robot,
                   halfwidth=0.01, spacing=0.02)
    assert not p.ok and len(p) == 0
    assert "A (unreachable: the wrist centre is " in p.message
    assert "nan" not in p.message and "inf " not in p.message


def complex_inputs(example_cell):
    m = vrreg.read_measurements(example_cell)
    sensor, robot = m.sensor[:20], m.robot[:20]
    model = vrreg.register(sensor, robot).model
    c = sensor.astype(complex)
    return [
        ("sensor", lambda: vrreg.register(c, robot)),
        ("robot", lambda: vrreg.register(sensor, [list(map(complex, r)) for r in robot])),
        ("weights", lambda: vrreg.register(sensor, robot, weights=np.ones(20, dtype=complex))),
        ("configs", lambda: vrreg.register(sensor, robot, configs=np.ones(20, dtype=complex))),
        ("sensor", lambda: vrreg.evaluate(model, c, robot)),
        ("sensor", lambda: vrreg.correct(model, c)),
        ("points", lambda: model.apply(c)),
        ("sensor", lambda: vrreg.rigid_body_statistics(c, robot)),
        ("unc_tre", lambda: vrreg.improvement(np.ones(3, dtype=np.complex64), np.ones(3))),
        ("q", lambda: vrreg.fk("ur5", np.zeros(6, dtype=complex))),
        ("pose", lambda: vrreg.ik("ur5", np.eye(4, dtype=complex))),
        ("tool", lambda: vrreg.fk("ur5", np.zeros(6), tool=[0, 0, 0.1j])),
        ("parts", lambda: vrreg.plan(np.array([[0.45 + 0j, -0.1, 0.25]]), ["P"],
                                     halfwidth=0.01, spacing=0.02)),
    ]


def test_complex_arrays_are_refused(example_cell):
    for name, call in complex_inputs(example_cell):
        with warnings.catch_warnings():
            warnings.simplefilter("error")  # no ComplexWarning first: refused before converting
            with pytest.raises(vrreg.InputError, match=f"^{name}: complex numbers"):
                call()


def test_real_arrays_of_any_dtype_still_work(example_cell):
    m = vrreg.read_measurements(example_cell)
    r = vrreg.register(m.sensor[:20].astype(np.float32), m.robot[:20].astype(np.float32))
    assert np.isfinite(r.fre)
    assert vrreg.fk("ur5", np.zeros(6, dtype=np.int64)).shape == (4, 4)


@pytest.mark.parametrize("wrap", [pathlib.Path, Where, str])
def test_paths_are_str_or_any_pathlike(wrap, example_cell, robot_file, tmp_path):
    m = vrreg.read_measurements(wrap(example_cell))
    assert m.source == example_cell
    model = vrreg.register(m).model
    model.save(wrap(tmp_path / "model.json"))
    again = vrreg.load_model(wrap(tmp_path / "model.json"))
    assert again.to_json() == model.to_json()
    tool = [0, 0, 0.0455]  # the robot file's
    assert np.allclose(vrreg.fk(wrap(robot_file), np.zeros(6)),
                       vrreg.fk("ur5", np.zeros(6), tool=tool), atol=1e-12)
    assert vrreg.ik(wrap(robot_file), vrreg.fk("ur5", np.full(6, 0.3), tool=tool))["status"] == "ok"
    with pytest.raises(vrreg.FileError) as missing:
        vrreg.load_model(wrap(tmp_path / "missing.json"))
    assert missing.value.path == str(tmp_path / "missing.json")


def test_arm_takes_a_pathlike(robot_file):
    sim = vrreg.simulate("ur5", "A1", seed=1)
    r = vrreg.register(sim.measurements, interpolation="joint", arm=pathlib.Path(robot_file))
    assert r.model.interpolation == "joint"
    e = vrreg.evaluate(r.model, sim.measurements, arm=Where(robot_file))
    assert e.n_targets > 0 and e.cor_rms_t < e.unc_rms_t


def test_other_types_are_no_path():
    for bad in (3, None, ["m.json"]):
        with pytest.raises(TypeError):
            vrreg.load_model(bad)


def test_messages_name_python_keywords_not_command_line_flags(example_cell):
    """The library names its options; Python says them as its keywords, never as flags."""
    cell = vrreg.read_measurements(example_cell)
    model = vrreg.register(cell).model
    with pytest.raises(vrreg.InputError) as raised:
        vrreg.evaluate(model, cell, interpolation="octuplet")
    message = str(raised.value)
    assert "cube_edge=" in message and "--" not in message and "`" not in message, message
    arm_cell = vrreg.simulate("ur5", "A2", seed=1).measurements  # joints, no robot kept
    with pytest.raises(vrreg.InputError) as raised:
        vrreg.evaluate(vrreg.register(arm_cell).model, arm_cell, interpolation="joint")
    message = str(raised.value)
    assert "arm=" in message and "--robot" not in message, message
