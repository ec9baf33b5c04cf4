# SPDX-License-Identifier: Apache-2.0
"""vrreg.Client against a running `vrreg serve`: the numbers of `vrreg correct`, refusals raised."""
import csv
import os
import re
import socket
import subprocess
import time

import numpy as np
import pytest

import vrreg
from conftest import SOURCE_DIR


def _vrreg_command():
    path = os.environ.get("VRREG_CLI", str(SOURCE_DIR / "build" / "release" / "bin" / "vrreg"))
    if not os.path.exists(path):
        pytest.skip(f"the vrreg command is not built ({path}); set VRREG_CLI")
    return path


def _serve(path, model):
    """`vrreg serve` of `model` as 'cell' on a free port: the process and its line port."""
    proc = subprocess.Popen([path, "serve", "--model", f"cell={model}", "--listen", "127.0.0.1:0"],
                            stderr=subprocess.PIPE, text=True)
    port = None
    deadline = time.time() + 60
    while port is None and time.time() < deadline:
        m = re.search(r"line protocol on 127\.0\.0\.1:(\d+)", proc.stderr.readline())
        if m:
            port = int(m.group(1))
    assert port, "vrreg serve did not start"
    return proc, port


@pytest.fixture(scope="module")
def service(tmp_path_factory, example_cell):
    path = _vrreg_command()
    d = tmp_path_factory.mktemp("serve")
    model = d / "cell.json"
    subprocess.run([path, "register", "--fiducials", example_cell, "--interpolation", "kriging",
                    "-o", str(model)], check=True, capture_output=True)
    proc, port = _serve(path, model)
    yield path, model, port, d
    proc.terminate()
    proc.wait(timeout=30)


def test_client_answers_as_correct(service, example_cell):
    path, model, port, d = service
    rows = [r for r in csv.reader(line for line in open(example_cell) if not line.startswith("#"))]
    header = rows[0]
    ix = [header.index(c) for c in ("sensor_x_mm", "sensor_y_mm", "sensor_z_mm")]
    points = {}
    for r in rows[1:]:
        if r[header.index("role")] == "target" and r[0] not in points:
            points[r[0]] = [r[i] for i in ix]
    pts = d / "points.csv"
    pts.write_text("point,role,sensor_x_mm,sensor_y_mm,sensor_z_mm\n" +
                   "".join(f"{k},target,{','.join(v)}\n" for k, v in points.items()))
    out = d / "out.csv"
    subprocess.run([path, "correct", "--model", str(model), "--points", str(pts), "-o", str(out)],
                   check=True, capture_output=True)
    expected = [r for r in csv.reader(line for line in open(out) if not line.startswith("#"))][1:]
    with vrreg.Client(port=port) as client:
        compared = 0
        for (name, xyz), row in zip(points.items(), expected):
            assert row[0] == name
            if row[2] != "ok":
                with pytest.raises(vrreg.ServiceError) as e:
                    client.correct("cell", [float(v) for v in xyz])
                assert e.value.code == 3
                continue
            c = client.correct("cell", [float(v) for v in xyz])
            np.testing.assert_array_equal(c.robot_mm, [float(v) for v in row[3:6]])
            assert c.sd_mm == float(row[12])
            compared += 1
        assert compared > 5


def test_client_refusals_raise(service):
    _, _, port, _ = service
    with vrreg.Client(port=port) as client:
        with pytest.raises(vrreg.ServiceError) as e:
            client.correct("no-such-model", [1.0, 2.0, 3.0])
        assert e.value.code == 2
        with pytest.raises(vrreg.ServiceError) as e:
            client.correct("cell", [1e7, 0.0, 0.0])
        assert e.value.code == 3
        # Extrapolation is capped (vrreg serve --max-extrapolation): 10 km is beyond it.
        with pytest.raises(vrreg.ServiceError) as e:
            client.correct("cell", [1e7, 0.0, 0.0], extrapolate=True)
        assert e.value.code == 8
        with pytest.raises(ValueError):
            client.correct("cell", [float("nan"), 0.0, 0.0])
        with pytest.raises(ValueError):
            client.correct("cell", [1.0, 2.0])


def test_client_sends_the_approach_direction(service, example_cell):
    # The example cell's model has no lost-motion term: a direction changes nothing; malformed
    # directions are refused by the client (ValueError) or by the service (code 1).
    _, _, port, _ = service
    cell = vrreg.read_measurements(example_cell)
    p_mm = 1e3 * cell.sensor[[i for i, r in enumerate(cell.roles) if r == "target"][0]]
    q = [0.1, -1.2, 1.5, -1.9, -1.57, 0.25]
    with vrreg.Client(port=port) as client:
        plain = client.correct("cell", p_mm, joints_rad=q, extrapolate=True)
        came_from = client.correct("cell", p_mm, joints_rad=q, from_rad=np.add(q, 0.1),
                                   extrapolate=True)
        signs = client.correct("cell", p_mm, joints_rad=q, approach=[1, -1, 0, 1, -1, 0],
                               extrapolate=True)
        for other in (came_from, signs):
            np.testing.assert_array_equal(other.robot_mm, plain.robot_mm)
            assert other.sd_mm == plain.sd_mm
        with pytest.raises(ValueError, match="needs joints_rad"):
            client.correct("cell", p_mm, from_rad=q)
        with pytest.raises(ValueError, match="-1, 0 or 1"):
            client.correct("cell", p_mm, joints_rad=q, approach=[2, 0, 0, 0, 0, 0])
        with pytest.raises(vrreg.ServiceError) as e:
            client.correct("cell", p_mm, joints_rad=q, from_rad=q[:5])
        assert e.value.code == 1


@pytest.fixture(scope="module")
def pose_service(tmp_path_factory):
    path = _vrreg_command()
    d = tmp_path_factory.mktemp("serve_pose")
    cell, model = d / "a1.csv", d / "cell.json"
    subprocess.run([path, "simulate", "ur5", "A1", "--seed", "4", "--rigid-body-mm", "50", "-o",
                    str(cell)], check=True, capture_output=True)
    subprocess.run([path, "register", "--fiducials", str(cell), "--interpolation", "trilinear",
                    "-o", str(model)], check=True, capture_output=True)
    proc, port = _serve(path, model)
    yield path, cell, model, port
    proc.terminate()
    proc.wait(timeout=30)


def test_client_corrects_orientations_as_the_library(pose_service):
    _, cell, model_path, port = pose_service
    measurements = vrreg.read_measurements(cell)
    model = vrreg.load_model(str(model_path))
    targets = np.array([r == "target" for r in measurements.roles])
    sensor_mm = 1e3 * measurements.sensor[targets]
    sensor_q = measurements.sensor_q[targets]
    # As the service reads them: mm, divided by 1000.
    expected = vrreg.correct(model, sensor_mm / 1e3, sensor_q=sensor_q)
    ok = expected.status == 0
    with vrreg.Client(port=port) as client:
        compared = 0
        for i in range(0, len(sensor_mm), 7):
            if not ok[i]:
                continue
            c = client.correct("cell", sensor_mm[i], sensor_q=sensor_q[i])
            np.testing.assert_allclose(c.robot_mm, 1e3 * expected.corrected[i], rtol=0, atol=1e-8)
            q = expected.orientation["q_robot_marker_corrected"][i]
            q = q if q[3] >= 0 else -q
            np.testing.assert_allclose(c.robot_q, q, rtol=0, atol=1e-11)
            assert abs(c.angle_sd_mrad - 1e3 * expected.orientation["predicted_angle_sd"][i]) < 1e-9
            compared += 1
        assert compared > 10
        plain = client.correct("cell", sensor_mm[0])
        assert plain.robot_q is None and plain.angle_sd_mrad is None
        with pytest.raises(ValueError):
            client.correct("cell", sensor_mm[0], sensor_q=[0.0, 0.0, 1.0])
        with pytest.raises(vrreg.ServiceError) as e:
            client.correct("cell", sensor_mm[0], sensor_q=[0.0, 0.0, 2.0, 1.0])
        assert e.value.code == 1


def test_nothing_listening_is_a_service_error():
    # A port just freed: nothing listens there.
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    with pytest.raises(vrreg.ServiceError, match=f"cannot connect to 127.0.0.1:{port}") as e:
        vrreg.Client(port=port, timeout_s=2.0)
    assert e.value.code == 0
