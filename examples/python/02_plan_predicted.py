#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Procedure 1 (paper section 6): plan fiducial cubes around two part points, measure the plan on
the simulated UR5 test bed and predict the RMS_T it will give, before using the robot.

    PYTHONPATH=build/release/python /usr/bin/python3 examples/python/02_plan_predicted.py
"""
import numpy as np

import vrreg

parts = np.array([[0.45, -0.10, 0.25], [0.45, 0.10, 0.25]])  # robot base frame [m]
spacing = 0.02
plan = vrreg.plan(parts, ["P1", "P2"], robot="ur5", halfwidth=0.02, spacing=spacing, force=True)
print(plan, f"d_min = {plan.d_min * 1e3:.1f} mm")

measured = vrreg.simulate("ur5", plan=plan, seed=1)
registered = vrreg.register(measured.measurements, sigma_rep=measured.sigma_rep_spec)
predicted = vrreg.evaluate(registered.model, measured.measurements, interpolation="octuplet",
                           cube_edge=spacing)
for name, unc, cor in zip(predicted.names, predicted.unc_tre, predicted.cor_tre):
    print(f"{name}: TRE {unc * 1e3:.3f} mm -> {cor * 1e3:.3f} mm with RRBC")
