#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Builds the Debian packages vrreg, libvrreg-dev and python3-vrreg (docs/install.md) in
# build/package (preset `package`: release, no tests, prefix /usr so that the libraries go to the
# multiarch directory) and prints their paths on stdout.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --preset package >/dev/null
# Everything the preset builds is installed: the command, the libraries, the Python module, the
# manual page and the changelog.
cmake --build --preset package >&2
rm -f build/package/*.deb
(cd build/package && cpack -G DEB) >&2
realpath build/package/*.deb
