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
print(f"RMS_T {evaluated.unc_rms_t * 1e3:.3f} mm uncorrected, "
      f"{evaluated.cor_rms_t * 1e3:.3f} mm corrected, gamma {100 * evaluated.gamma:.1f} %")

corrected = vrreg.correct(registered.model, cell)
print(f"first target {corrected.names[0]}: command {corrected.corrected[0] * 1e3} mm")
