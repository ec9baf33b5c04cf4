# SPDX-License-Identifier: Apache-2.0
"""check and update from Python: a cell with three monitor points read in eight visits, unchanged,
bumped, then updated from the monitors; the JSON is the command line's."""
import json

import numpy as np
import pytest

import vrreg

HEADER = "point,role,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_mm,sensor_y_mm,sensor_z_mm,visit\n"
MONITORS = np.array([[400.0, -120.0, 100.0], [600.0, 120.0, 300.0], [500.0, 100.0, 50.0]])


def _sensor(robot_mm, turn=0.0, shift=(0.0, 0.0, 0.0)):
    c, s = np.cos(0.3 + turn), np.sin(0.3 + turn)
    rotation = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    field = 0.3 * np.sin(robot_mm / 90.0)  # the robot misses by ~0.3 mm, smoothly
    return (robot_mm + field) @ rotation.T + np.array([100.0, -200.0, 2000.0]) + np.array(shift)


def _monitor_rows(rng, turn=0.0, shift=(0.0, 0.0, 0.0)):
    rows = []
    for visit in range(8):
        for m, robot in enumerate(MONITORS):
            sensor = _sensor(robot, turn, shift) + rng.normal(0.0, 0.02, 3)
            rows.append(f"monitor-{m + 1},monitor,{','.join(map(repr, robot))},"
                        f"{','.join(map(repr, sensor))},{visit}\n")
    return rows


def _write(path, rows):
    path.write_text(HEADER + "".join(rows))
    return vrreg.read_measurements(str(path))


def test_check_then_update_after_a_bump(tmp_path):
    rng = np.random.default_rng(5)
    rows = []
    for i in range(6):
        for j in range(6):
            for k in range(6):
                robot = np.array([400.0 + 40 * i, -100.0 + 40 * j, 50.0 + 40 * k])
                sensor = _sensor(robot) + rng.normal(0.0, 0.02, 3)
                rows.append(f"f{i}{j}{k},fiducial,{','.join(map(repr, robot))},"
                            f"{','.join(map(repr, sensor))},0\n")
    model = vrreg.register(_write(tmp_path / "cell.csv", rows + _monitor_rows(rng))).model

    same = vrreg.check(model, _write(tmp_path / "same.csv", _monitor_rows(rng)))
    assert same.verdict == "valid", same.message
    assert same.sensor_rotation is None
    assert same.visit_sd == pytest.approx(0.02e-3, rel=0.25)

    bumped = _write(tmp_path / "bumped.csv", _monitor_rows(rng, turn=1e-4, shift=(0.05, 0, 0)))
    moved = vrreg.check(model, bumped)
    assert moved.verdict == "rigid change", moved.message
    assert moved.sensor_rotation.shape == (3,)
    assert json.loads(moved.to_json())["verdict"] == "rigid change"

    updated = vrreg.update(model, bumped, change="bump", parent="cell.json",
                           time="2026-11-26T09:00:00Z")
    assert updated.fit_rms < 0.05e-3
    assert json.loads(updated.to_json())["lineage"][0]["parent"] == "cell.json"
    again = vrreg.check(updated.model, _write(tmp_path / "again.csv",
                                              _monitor_rows(rng, turn=1e-4, shift=(0.05, 0, 0))))
    assert again.verdict == "valid", again.message


def test_bad_calls_say_what(tmp_path):
    rng = np.random.default_rng(6)
    monitors = _write(tmp_path / "m.csv", _monitor_rows(rng))
    rows = [f"f{k},fiducial,{400 + 10 * k},{(k % 3) * 20},{(k // 3) * 15},"
            f"{','.join(map(repr, _sensor(np.array([400.0 + 10 * k, (k % 3) * 20.0, (k // 3) * 15.0]))))},0\n"
            for k in range(9)]
    plain = vrreg.register(_write(tmp_path / "plain.csv", rows)).model
    with pytest.raises(vrreg.InputError, match="no monitor points"):
        vrreg.check(plain, monitors)
    with pytest.raises(vrreg.InputError, match="Measurements"):
        vrreg.check(plain, np.zeros((3, 3)))
    with pytest.raises(vrreg.InputError, match="change"):
        vrreg.update(plain, monitors, change="tilt")
