#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""register -> evaluate -> correct on the example cell, as scripts/quickstart.sh does with the
command line (the same numbers).

    PYTHONPATH=build/release/python /usr/bin/python3 examples/python/01_register_evaluate_correct.py
"""
import pathlib

import vrreg

cell_csv = pathlib.Path(__file__).resolve().parents[1] / "data" / "example-cell.csv"
cell = vrreg.read_measurements(str(cell_csv))
registered = vrreg.register(cell, sigma_rep=0.05e-3)  # UR5-class repeatability [m]
print(registered)
print(f"rho = {registered.rho:.2f} (RRBC should help when > {vrreg.RHO_THRESHOLD})")

evaluated = vrreg.evaluate(registered.model, cell)
# RMS_T and gamma are over the targets that were corrected; None when none could be.
unc, cor, gamma = evaluated.unc_rms_t, evaluated.cor_rms_t, evaluated.gamma
if unc is None or cor is None or gamma is None:
    raise SystemExit(f"no target could be corrected ({evaluated.n_flagged} flagged)")
print(f"RMS_T {unc * 1e3:.3f} mm uncorrected, {cor * 1e3:.3f} mm corrected, "
      f"gamma {100 * gamma:.1f} % over {evaluated.n_corrected} of {evaluated.n_targets} targets")

corrected = vrreg.correct(registered.model, cell)
print(f"first target {corrected.names[0]}: command {corrected.corrected[0] * 1e3} mm")
