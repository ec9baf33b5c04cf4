# SPDX-License-Identifier: Apache-2.0
"""Shared fixtures: the example cell and the built command line (VRREG_CLI, set by ctest)."""
import json
import os
import pathlib
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("VRREG_SOURCE_DIR",
                                         pathlib.Path(__file__).resolve().parents[2]))
EXAMPLE_CELL = SOURCE_DIR / "examples" / "data" / "example-cell.csv"


@pytest.fixture(scope="session")
def cli():
    """Runs the built `vrreg` command and returns its stdout (parsed when --json is given)."""
    path = os.environ.get("VRREG_CLI", str(SOURCE_DIR / "build" / "release" / "bin" / "vrreg"))
    if not os.path.exists(path):
        pytest.skip(f"the vrreg command is not built ({path}); set VRREG_CLI")

    def run(*args):
        out = subprocess.run([path, *map(str, args)], check=True, capture_output=True, text=True)
        return json.loads(out.stdout) if "--json" in args else out.stdout

    return run


@pytest.fixture(scope="session")
def example_cell():
    return str(EXAMPLE_CELL)
