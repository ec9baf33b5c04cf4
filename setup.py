# SPDX-License-Identifier: Apache-2.0
"""Builds the compiled part of the vrreg package (_vrreg) with the project's CMake for the Python
that runs this (pip install . / pip wheel .; pyproject.toml holds the metadata).

The CMake build lives in build/pip (kept, so a second install only relinks what changed), or in
$VRREG_CMAKE_BUILD_DIR: a build directory already configured for this interpreter (the tests reuse
the one they built). Nothing is downloaded: CMake finds pybind11, Eigen and the other libraries
installed on the system (scripts/install-deps.sh).
"""
import os
import re
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent


def project_version() -> str:
    """The version in CMakeLists.txt's project() call: the one source of it."""
    text = (ROOT / "CMakeLists.txt").read_text()
    match = re.search(r"project\(vrreg VERSION ([0-9.]+)", text)
    if not match:
        raise RuntimeError("CMakeLists.txt: no `project(vrreg VERSION x.y.z` found")
    return match.group(1)


class CMakeBuild(build_ext):
    """Configures (once) and builds the CMake target _vrreg, then copies the module into place."""

    def build_extension(self, ext: Extension) -> None:
        build_dir = Path(os.environ.get("VRREG_CMAKE_BUILD_DIR", ROOT / "build" / "pip"))
        if not (build_dir / "CMakeCache.txt").exists():
            generator = ["-G", "Ninja"] if shutil.which("ninja") else []
            subprocess.run(
                ["cmake", "-S", str(ROOT), "-B", str(build_dir), *generator,
                 "-DCMAKE_BUILD_TYPE=Release", f"-DPython_EXECUTABLE={sys.executable}",
                 "-DVRREG_BUILD_TESTS=OFF", "-DVRREG_BUILD_BENCHMARKS=OFF",
                 "-DVRREG_BUILD_EXAMPLES=OFF",
                 # 16 sources per translation unit: half the CPU time of a file-by-file build.
                 "-DCMAKE_UNITY_BUILD=ON", "-DCMAKE_UNITY_BUILD_BATCH_SIZE=16"],
                check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "_vrreg", "-j", jobs],
                       check=True)
        # The module must be for this interpreter: a reused build directory may be another's.
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        built = build_dir / "python" / "vrreg" / f"_vrreg{suffix}"
        if not built.exists():
            found = sorted(p.name for p in (build_dir / "python" / "vrreg").glob("_vrreg*"))
            raise RuntimeError(f"{built} was not built (found {found}): {build_dir} is configured "
                               f"for another Python than {sys.executable}")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)
        # The compiled module without its symbol table and debug sections, as Debian ships it.
        if shutil.which("strip"):
            subprocess.run(["strip", "--strip-unneeded", str(target)], check=True)


# setuptools' own scratch files under build/ too, beside the CMake builds (not in the sources).
SCRATCH = ROOT / "build" / "setuptools"
SCRATCH.mkdir(parents=True, exist_ok=True)
setup(
    version=project_version(),
    ext_modules=[Extension("vrreg._vrreg", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": str(SCRATCH)}, "egg_info": {"egg_base": str(SCRATCH)}},
)
