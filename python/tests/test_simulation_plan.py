# SPDX-License-Identifier: Apache-2.0
"""The simulated test beds and Procedure 1 from Python."""
import numpy as np
import pytest

import vrreg


def test_simulated_a1_registers_near_the_truth():
    sim = vrreg.simulate("ur5", "A1", seed=3)
    assert sim.dataset == "A1" and sim.seed == 3
    m = sim.measurements
    assert len(m) == sim.visit_tcp.shape[0]
    assert sim.readings_sensor.shape[1] == 3 and len(sim.reading_visit) == len(sim.readings_sensor)
    r = vrreg.register(m, sigma_rep=sim.sigma_rep_spec)
    assert np.allclose(r.rotation, sim.true_rotation, atol=2e-2)  # robot errors ~ 1 mm
    e = vrreg.evaluate(r.model, m, interpolation="octuplet", cube_edge=0.05)
    assert e.n_targets > 0 and 0 < e.cor_rms_t < e.unc_rms_t < 5e-3
    again = vrreg.simulate("ur5", "A1", seed=3)
    assert np.array_equal(again.readings_sensor, sim.readings_sensor)


def test_wrong_dataset_for_testbed():
    with pytest.raises(ValueError):
        vrreg.simulate("ur5", "grid")
    with pytest.raises(ValueError):
        vrreg.simulate("ur5")


def test_plan_predicted_on_the_testbed():
    parts = np.array([[0.45, -0.1, 0.25], [0.45, 0.1, 0.25]])
    p = vrreg.plan(parts, ["P1", "P2"], robot="ur5", halfwidth=0.01, spacing=0.02,
                   force=True)
    assert p.ok and len(p) == len(p.names) == p.joints.shape[0]
    assert p.roles.count("target") == 2
    sim = vrreg.simulate("ur5", plan=p, seed=1)
    r = vrreg.register(sim.measurements, sigma_rep=sim.sigma_rep_spec)
    e = vrreg.evaluate(r.model, sim.measurements, interpolation="octuplet", cube_edge=0.02)
    assert e.n_targets == 2 and np.all(np.isfinite(e.cor_tre))


def test_metrics_helpers():
    x = np.random.default_rng(0).normal(size=(10, 3))
    s = vrreg.rigid_body_statistics(x, x)
    assert s["pairs"] == 45 and s["sigma_l"] == 0.0
    assert vrreg.sigma_noise(3.0, 4.0) == 5.0 and vrreg.rho(5.0, 2.0) == 2.5
    d = vrreg.improvement([1.0, 2.0], [0.5, 3.0])
    assert d["n_bad"] == 1 and d["bad_targets"] == [1]
