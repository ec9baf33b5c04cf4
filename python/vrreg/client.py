# SPDX-License-Identifier: Apache-2.0
"""A client of `vrreg serve`'s line protocol for cell software in Python (docs/serve.md).

    with vrreg.Client(port=30401) as service:
        c = service.correct("cell", [412.5, -90.0, 310.0])   # sensor frame, mm
        c.robot_mm, c.sd_mm                                  # what to command, robot frame, mm

A refused point raises ServiceError with its code (3: outside the model's support, 2: unknown
model, ...); a silent or closed service raises ServiceError too: there is no default answer.
"""
from __future__ import annotations

import socket
from dataclasses import dataclass
from typing import Optional

import numpy as np
import numpy.typing as npt

#: The service's reply codes (a refusal is sent as a negative sd).
CODES = {1: "malformed", 2: "unknown model", 3: "not correctable", 4: "missing input",
         5: "unauthorized", 6: "limit", 7: "internal error", 8: "too far to extrapolate"}


class ServiceError(RuntimeError):
    """The service refused the request (code > 0) or did not answer (code 0)."""

    def __init__(self, code: int, message: str) -> None:
        super().__init__(message)
        self.code = code


@dataclass(frozen=True)
class Correction:
    """One corrected point: the position to command (robot frame, mm) and its predicted sd (mm;
    0 when the model's method predicts none). With a measured orientation (`sensor_q`): the
    orientation to command, robot frame, as a unit quaternion (x, y, z, w; w >= 0), and the
    predicted sd of its angle error (mrad; 0 when the method predicts none); else None."""

    robot_mm: npt.NDArray[np.float64]
    sd_mm: float
    robot_q: Optional[npt.NDArray[np.float64]] = None
    angle_sd_mrad: Optional[float] = None


def _number(value: float, what: str) -> str:
    v = float(value)
    if not np.isfinite(v):
        raise ValueError(f"{what} is not finite: {value!r}")
    return repr(v)


class Client:
    """One connection to `vrreg serve --listen HOST:PORT`, reused for every request."""

    def __init__(self, host: str = "127.0.0.1", port: int = 30401, *,
                 token: Optional[str] = None, timeout_s: float = 2.0) -> None:
        try:
            self._socket = socket.create_connection((host, port), timeout=timeout_s)
        except OSError as e:  # refused, unreachable, timed out, unknown host
            raise ServiceError(0, f"cannot connect to {host}:{port}: {e}") from e
        self._socket.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        self._reader = self._socket.makefile("rb")
        if token is not None:
            reply = self._ask(f"auth {token}\n")
            if reply != "(1)":
                self.close()
                raise ServiceError(5, "the service refused the token")

    def correct(self, model: str, sensor_mm: npt.ArrayLike, *,
                joints_rad: Optional[npt.ArrayLike] = None, config: Optional[int] = None,
                extrapolate: bool = False,
                sensor_q: Optional[npt.ArrayLike] = None,
                from_rad: Optional[npt.ArrayLike] = None,
                approach: Optional[npt.ArrayLike] = None) -> Correction:
        """Corrects one point measured in the sensor frame [mm] with the served model `model`;
        `joints_rad` (the commanded joints) for the joint-space model, `config` (the arm
        configuration label) for models built with Procedure 2 strategies; `sensor_q` (the
        rigid-body marker's measured orientation, sensor frame, unit quaternion x, y, z, w) to
        have the orientation corrected too (models registered with orientations); `from_rad`
        (the joints the robot comes from, with `joints_rad`) or `approach` (one sign per joint,
        -1, 0 or 1): the approach direction, for a model with a lost-motion term."""
        p = np.asarray(sensor_mm, dtype=np.float64).reshape(-1)
        if p.shape != (3,):
            raise ValueError(f"sensor_mm: expected 3 coordinates, got shape {np.shape(sensor_mm)}")
        fields = [model] + [_number(v, "sensor_mm") for v in p]
        if config is not None:
            fields += ["config", str(int(config))]
        if joints_rad is not None:
            q = np.asarray(joints_rad, dtype=np.float64).reshape(-1)
            fields += ["joints"] + [_number(v, "joints_rad") for v in q]
        if from_rad is not None and approach is not None:
            raise ValueError("from_rad, approach: give one of them, not both")
        if from_rad is not None:
            if joints_rad is None:
                raise ValueError("from_rad: needs joints_rad (the approach is joints - from)")
            f = np.asarray(from_rad, dtype=np.float64).reshape(-1)
            fields += ["from"] + [_number(v, "from_rad") for v in f]
        if approach is not None:
            signs = np.asarray(approach, dtype=np.float64).reshape(-1)
            if not np.all(np.isin(signs, (-1.0, 0.0, 1.0))):
                raise ValueError(f"approach: each sign is -1, 0 or 1, got {signs.tolist()}")
            fields += ["approach"] + [str(int(v)) for v in signs]
        if extrapolate:
            fields.append("extrapolate")
        if sensor_q is not None:
            q = np.asarray(sensor_q, dtype=np.float64).reshape(-1)
            if q.shape != (4,):
                raise ValueError(f"sensor_q: expected (x, y, z, w), got shape {np.shape(sensor_q)}")
            fields += ["quat"] + [_number(v, "sensor_q") for v in q]
        reply = self._ask(" ".join(fields) + "\n")
        values = [float(v) for v in reply.strip("()").split(",")]
        expected = 4 if sensor_q is None else 9
        if len(values) != expected:
            raise ServiceError(0, f"unexpected reply {reply!r}")
        sd = values[3] if sensor_q is None else values[7]
        if sd < 0:
            code = int(-sd)
            raise ServiceError(code, f"point refused: {CODES.get(code, 'code %d' % code)}")
        if sensor_q is None:
            return Correction(np.array(values[:3]), sd)
        return Correction(np.array(values[:3]), sd, np.array(values[3:7]), values[8])

    def correct_many(self, model: str, sensor_mm: npt.ArrayLike, **options: object) -> list[Correction]:
        """correct() for each row of an (N, 3) array [mm]; raises at the first refusal."""
        points = np.asarray(sensor_mm, dtype=np.float64)
        if points.ndim != 2 or points.shape[1] != 3:
            raise ValueError(f"sensor_mm: expected an (N, 3) array, got shape {points.shape}")
        return [self.correct(model, row, **options) for row in points]  # type: ignore[arg-type]

    def close(self) -> None:
        """Closes the connection."""
        self._reader.close()
        self._socket.close()

    def __enter__(self) -> Client:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def _ask(self, line: str) -> str:
        try:
            self._socket.sendall(line.encode("ascii"))
            reply = self._reader.readline()
        except (OSError, socket.timeout) as e:
            raise ServiceError(0, f"no answer from the service: {e}") from e
        if not reply.endswith(b"\n"):
            raise ServiceError(0, "the service closed the connection")
        return reply.decode("ascii").strip()


__all__ = ["Client", "Correction", "ServiceError", "CODES"]
