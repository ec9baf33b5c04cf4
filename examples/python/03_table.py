#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""A plain-text table, no plotting: RMS_T uncorrected and corrected on the simulated UR5 datasets
A1 and A2 (paper Table 1) for a few seeds.

    PYTHONPATH=build/release/python /usr/bin/python3 examples/python/03_table.py
"""
import vrreg

CUBE_EDGE = {"A1": 0.050, "A2": 0.025}  # octuplet cube edges of Table 1 [m]

print(f"{'dataset':8} {'seed':>4} {'rho':>6} {'unc RMS_T mm':>13} {'cor RMS_T mm':>13} "
      f"{'gamma %':>8} {'N_bad':>5}")
for dataset, edge in CUBE_EDGE.items():
    for seed in (1, 2, 3):
        sim = vrreg.simulate("ur5", dataset, seed=seed)
        r = vrreg.register(sim.measurements, sigma_rep=sim.sigma_rep_spec)
        e = vrreg.evaluate(r.model, sim.measurements, interpolation="octuplet", cube_edge=edge)
        unc, cor, gamma = e.unc_rms_t, e.cor_rms_t, e.gamma  # None if no target was corrected
        if unc is None or cor is None or gamma is None:
            print(f"{dataset:8} {seed:>4} no target corrected")
            continue
        print(f"{dataset:8} {seed:>4} {r.rho:>6.2f} {unc * 1e3:>13.3f} "
              f"{cor * 1e3:>13.3f} {100 * gamma:>8.1f} {e.n_bad:>5}")
