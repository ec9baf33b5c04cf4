#!/usr/bin/env bash
# Quick start, command 2: install, build and run every test, optimised and under ASan + UBSan.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --with-browser
scripts/build.sh release
ctest --preset release
scripts/build.sh asan
ctest --preset asan
