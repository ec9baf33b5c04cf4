#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Quick start, command 2: install, build and run every test, optimised (GCC) and under ASan + UBSan
# (clang: a second compiler, and its sanitized build compiles faster than GCC's), and the packages
# and installs from a fresh clone (scripts/test-package.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --with-browser --with-clang
scripts/build.sh release
ctest --preset release
# From a fresh clone: the .deb files and lintian, install, the outside consumer (baseline and
# -march=native, installed and from the build tree), every library, command and Python source
# compiled on its own (scripts/check-sources.sh: unity batches hide a missing include), pip
# install . into a venv (a few minutes: one release build without tests, one syntax pass).
scripts/test-package.sh
scripts/build.sh asan
ctest --preset asan
