#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Builds the release command and libraries and makes the Debian package (docs/install.md);
# prints the .deb's path on stdout.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --preset release >/dev/null
# The command links every module library, so this builds everything the package installs.
cmake --build --preset release --target vrreg_cli >&2
(cd build/release && cpack -G DEB) >&2
deb=$(ls -t build/release/vrreg_*.deb | head -n 1)
realpath "$deb"
