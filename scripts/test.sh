#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Quick start, command 2: install, build and run every test, optimised (GCC) and under ASan + UBSan
# (clang: a second compiler, and its sanitized build compiles faster than GCC's).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --with-browser --with-clang
scripts/build.sh release
ctest --preset release
scripts/build.sh asan
ctest --preset asan
