# SPDX-License-Identifier: Apache-2.0
"""numpy in and out: any strides, float32 converted, and a 10^6-point array copied at most once."""
import tracemalloc

import numpy as np
import pytest

import vrreg


def cell(n, seed=0):
    rng = np.random.default_rng(seed)
    robot = rng.uniform(-0.2, 0.2, size=(n, 3))
    angle = 0.3
    rotation = np.array([[np.cos(angle), -np.sin(angle), 0], [np.sin(angle), np.cos(angle), 0],
                         [0, 0, 1]])
    sensor = (robot - [0.5, 0.1, 2.0]) @ rotation + rng.normal(scale=5e-5, size=(n, 3))
    return sensor, robot


def test_recovers_a_rigid_motion():
    sensor, robot = cell(50)
    r = vrreg.register(sensor, robot)
    assert np.allclose(r.rotation @ sensor.T + r.translation[:, None], robot.T, atol=5e-4)
    assert r.fre < 2e-4 and r.model.n_fiducials == 50
    assert r.residuals.shape == (50,) and not r.residuals.flags.writeable


def test_non_contiguous_and_float32_inputs():
    sensor, robot = cell(40)
    base = vrreg.register(sensor, robot)
    wide = np.zeros((40, 6))
    wide[:, ::2] = sensor  # column stride 16 bytes
    fortran = np.asfortranarray(robot)
    strided = vrreg.register(wide[:, ::2], fortran)
    assert np.array_equal(strided.rotation, base.rotation)
    assert np.array_equal(strided.translation, base.translation)
    reversed_rows = vrreg.register(sensor[::-1], robot[::-1])
    assert np.allclose(reversed_rows.rotation, base.rotation, rtol=0, atol=1e-12)
    single = vrreg.register(sensor.astype(np.float32), robot.astype(np.float32))
    assert np.allclose(single.rotation, base.rotation, atol=1e-5)
    as_lists = vrreg.register(sensor.tolist(), robot.tolist())
    assert np.array_equal(as_lists.rotation, base.rotation)


def test_correct_returns_n_by_3_views():
    axis = np.arange(5) * 0.025
    robot = np.array(np.meshgrid(axis, axis, axis, indexing="ij")).reshape(3, -1).T.copy()
    # A systematic error well above the noise: the guard applies the correction.
    sensor = (robot + [0.1, 0.2, 0.3] + 5e-4 * np.sin(20 * robot)
              + np.random.default_rng(2).normal(scale=5e-5, size=robot.shape))
    model = vrreg.register(sensor, robot).model
    c = vrreg.correct(model, sensor[25:45])  # the second layer: interior and face nodes
    assert c.method == "grid"
    assert c.corrected.shape == (20, 3) and c.corrected.dtype == np.float64
    assert not c.corrected.flags.writeable
    assert c.status.shape == (20,) and c.n_flagged == int(np.count_nonzero(c.status))
    assert c.names == []  # no names given: none invented (10^6 labels would outweigh the points)
    # Corrected fiducials land near their nominal positions (the grid cell comes from the
    # registered position, which the 0.1 mm noise moves off the node); boundary ones fall outside.
    ok = c.status == int(vrreg.StencilStatus.OK)
    assert 0 < np.count_nonzero(ok) < 20
    assert np.allclose(c.corrected[ok], robot[25:45][ok], rtol=0, atol=1e-5)
    assert c.status_names[int(np.argmax(~ok))] == "outside grid"


def test_a_correction_not_better_than_none_is_not_applied():
    axis = np.arange(5) * 0.025
    robot = np.array(np.meshgrid(axis, axis, axis, indexing="ij")).reshape(3, -1).T.copy()
    # Noise alone: interpolating it is worse than leaving it.
    sensor = robot + [0.1, 0.2, 0.3] + np.random.default_rng(2).normal(scale=1e-4, size=robot.shape)
    model = vrreg.register(sensor, robot).model
    c = vrreg.correct(model, sensor[:20])
    assert c.guard is not None and c.guard["judged"] and not c.guard["applied"]
    assert c.guard["cv_rms"] >= c.guard["uncorrected_rms"] > 0
    # Every point uncorrected: those the grid holds say why, the others are outside it.
    not_better = c.status == int(vrreg.StencilStatus.NOT_BETTER_THAN_NONE)
    outside = c.status == int(vrreg.StencilStatus.OUTSIDE_GRID)
    assert np.count_nonzero(not_better) > 0 and np.all(not_better | outside)
    assert np.array_equal(c.corrected, c.uncorrected)


N = 10**6


def traced_peak(call):
    """Peak bytes numpy / Python allocate during call (C++ working memory is not traced)."""
    tracemalloc.start()
    tracemalloc.reset_peak()
    try:
        result = call()
        return tracemalloc.get_traced_memory()[1], result
    finally:
        tracemalloc.stop()


@pytest.fixture(scope="module")
def million():
    return cell(N, seed=1)


@pytest.mark.parametrize("layout", ["contiguous", "strided", "float32"])
def test_million_points_copied_at_most_once(million, layout):
    sensor, robot = million
    if layout == "strided":
        wide = np.empty((N, 6))
        wide[:, 1::2] = sensor
        sensor = wide[:, 1::2]
    elif layout == "float32":
        sensor = sensor.astype(np.float32)
    one_copy = N * 3 * 8
    peak, r = traced_peak(lambda: vrreg.register(sensor, robot, rigid_body=False))
    assert r.n_registered == N
    assert peak < 2 * one_copy, f"register allocated {peak / one_copy:.2f} copies"
    model = vrreg.register(sensor[:1000], robot[:1000], interpolation="scattered").model
    peak, c = traced_peak(lambda: vrreg.correct(model, sensor))
    assert c.corrected.shape == (N, 3)
    assert peak < 2 * one_copy, f"correct allocated {peak / one_copy:.2f} copies"


# Process-level peak memory (C++ included): correct() on 10^6 points in a fresh interpreter. The
# result holds 4 (N, 3) arrays and one stencil per point (8 fiducial indices and 8 weights,
# 136 bytes); besides that, the input may be copied once (into the library's array), no more.
PEAK_SCRIPT = r"""
import resource, sys
import numpy as np
import vrreg
n = 10**6
rng = np.random.default_rng(3)
robot = rng.uniform(-0.1, 0.1, size=(n, 3))
sensor = robot + [0.2, -0.1, 2.0]
model = vrreg.register(sensor[:2000], robot[:2000], interpolation="scattered").model
vrreg.correct(model, sensor[:1000])  # the code paths warm
before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
c = vrreg.correct(model, sensor)
after = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
print((after - before) * 1024, c.corrected.shape[0])
"""


def test_million_point_correct_peak_memory_is_one_copy_beyond_the_result(tmp_path):
    import subprocess
    import sys

    out = subprocess.run([sys.executable, "-c", PEAK_SCRIPT], capture_output=True, text=True,
                         check=True).stdout.split()
    growth, n = int(out[0]), int(out[1])
    one_copy = n * 3 * 8
    result = 4 * one_copy + n * 136
    assert growth < result + 1.5 * one_copy, (
        f"correct grew the process by {growth / one_copy:.2f} copies of the input; the result "
        f"holds {result / one_copy:.2f}")


def test_far_points_are_outside_support_unless_extrapolate_is_asked():
    axis = np.arange(5) * 0.025
    robot = np.array(np.meshgrid(axis, axis, axis, indexing="ij")).reshape(3, -1).T.copy()
    rng = np.random.default_rng(3)
    sensor = robot + [0.1, 0.2, 0.3] + 2e-4 * np.sin(20 * robot) + rng.normal(scale=2e-5,
                                                                              size=robot.shape)
    model = vrreg.register(sensor, robot, interpolation="rbf").model
    points = np.array([sensor[62], sensor[62] + [1.0, 0.0, 0.0]])
    plain = vrreg.correct(model, points)
    assert list(plain.status) == [int(vrreg.StencilStatus.OK),
                                  int(vrreg.StencilStatus.OUTSIDE_SUPPORT)]
    assert np.isnan(plain.predicted_sd[1]) and plain.n_flagged == 1
    far = vrreg.correct(model, points, extrapolate=True)
    assert far.status[1] == int(vrreg.StencilStatus.EXTRAPOLATED) and far.n_flagged == 0
    assert far.predicted_sd[1] > far.predicted_sd[0] > 0
    assert np.array_equal(far.corrected[0], plain.corrected[0])


def test_three_fiducials_correct_nothing_and_say_why():
    robot = np.array([[0.4, 0.0, 0.2], [0.5, 0.0, 0.2], [0.4, 0.1, 0.25]])
    sensor = robot + [0.1, 0.2, 0.3] + [[1e-4, 0, 0], [0, -1e-4, 0], [0, 0, 2e-4]]
    model = vrreg.register(sensor, robot).model
    points = sensor[:2] + 0.01
    result = vrreg.correct(model, points)
    assert list(result.status) == [int(vrreg.StencilStatus.TOO_FEW_FIDUCIALS)] * 2
    assert list(result.status_names) == ["too few fiducials"] * 2
    assert result.n_flagged == 2
    np.testing.assert_array_equal(result.corrected, result.uncorrected)
    assert "fewer than any correction method needs" in result.layout
