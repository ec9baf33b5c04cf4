# SPDX-License-Identifier: Apache-2.0
"""vrreg: vision-robot registration that knows its own accuracy (TRE, NIST's RRBC correction).

Positions are (N, 3) numpy arrays in METRES (sensor frame X, robot frame Y; Y ~ R X + tau, paper
Eq. 2). register -> evaluate -> correct, one call each, on arrays or on vrreg.read_measurements(path)
(then the numbers equal the command line's). Bad input raises ValueError (vrreg.InputError; file
problems vrreg.FileError with .path and .line). docs/python.md has the guide.
"""
import json as _json

from ._vrreg import (
    __version__,
    CheckResult,
    CorrectResult,
    EvaluateResult,
    FileError,
    InputError,
    Measurements,
    Model,
    Plan,
    PlanNext,
    RegisterResult,
    RHO_THRESHOLD,
    Simulation,
    StencilStatus,
    UpdateResult,
    check,
    correct,
    estimate_marker_offset,
    evaluate,
    fk,
    ik,
    improvement,
    load_model,
    model_from_json,
    plan,
    plan_next,
    read_measurements,
    register,
    rho,
    rigid_body_statistics,
    robots,
    sigma_noise,
    simulate,
    update,
    volume_part_points,
)
from . import _vrreg
from .client import Client, Correction, ServiceError


def reproduce(seed: int = 1, *, ur5: bool = True, lwr4: bool = True) -> dict:
    """The paper's experiments on the simulated test beds for one seed (Tables 1-2, Figures 7-15
    data, the findings checked): the dict of `vrreg reproduce --seed N --json` (lengths in mm, as
    in reproduce.json)."""
    return _json.loads(_vrreg._reproduce_json(seed, ur5, lwr4))


__all__ = [
    "__version__", "CheckResult", "Client", "Correction", "CorrectResult", "EvaluateResult", "FileError", "InputError", "Measurements", "Model",
    "Plan", "PlanNext", "RegisterResult", "RHO_THRESHOLD", "Simulation", "StencilStatus", "correct",
    "estimate_marker_offset", "evaluate", "fk", "ik", "improvement", "load_model", "model_from_json", "plan",
    "plan_next", "read_measurements", "register", "reproduce", "rho", "rigid_body_statistics", "robots",
    "ServiceError", "sigma_noise", "simulate", "UpdateResult", "check", "update",
    "volume_part_points",
]
