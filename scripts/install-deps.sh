#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Installs vrreg's build and test dependencies from Debian bookworm's packages, and the charting
# library that `vrreg report` inlines (web/: `npm ci` from the npm registry, pinned by
# web/package-lock.json). With --with-browser also Debian's Chromium, for the browser test; with
# --with-clang also clang and its sanitizer runtimes, for the `asan` preset (scripts/test.sh); with
# --with-fuzz the same, for libFuzzer (scripts/fuzz.sh); with --with-sklearn also
# scikit-learn, the Gaussian-process peer of scripts/bench-field-peers.py.
# Idempotent and quick when everything is already there.
set -euo pipefail
cd "$(dirname "$0")/.."
with_browser=0
with_fuzz=0
with_clang=0
with_sklearn=0
for arg in "$@"; do
  case "$arg" in
    --with-browser) with_browser=1 ;;
    --with-clang) with_clang=1 ;;
    --with-fuzz) with_fuzz=1 ;;
    --with-sklearn) with_sklearn=1 ;;
    *) echo "install-deps: unknown option $arg (use --with-browser, --with-clang, --with-fuzz, --with-sklearn)" >&2; exit 2 ;;
  esac
done
packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libcli11-dev nlohmann-json3-dev libtbb-dev libnanoflann-dev libqhull-dev
  libyaml-cpp-dev libfmt-dev liborocos-kdl-dev
  libgtest-dev libgmock-dev googletest libbenchmark-dev
  liburdfdom-dev  # URDF robot files (robot_io); tests: vrreg export's URDF read back
  libboost-dev libssl-dev  # vrreg serve: Boost.Asio and Beast (header-only), OpenSSL's SHA-256
  # benchmark-only peer (optional in CMake): OpenCV's calibrateRobotWorldHandEye beside the
  # marker-offset estimate (benchmarks/hand_eye_bench.cpp, docs/benchmarks.md)
  libopencv-calib3d-dev
  file dpkg-dev  # cpack -G DEB: dpkg-shlibdeps computes the .deb's Depends (scripts/package.sh)
  help2man  # the manual page vrreg(1), from --help
  lintian   # the packages' check (scripts/test-package.sh)
  # The Python module (python/, docs/python.md) for Debian's /usr/bin/python3, its tests and
  # python/benchmarks/bench.py (scipy peers).
  python3-dev python3-pybind11 python3-numpy python3-pytest python3-scipy
  # pip install . (pyproject.toml, setup.py) offline with Debian's build tools, into a venv; mypy's
  # stubtest and mypy --strict check the type stubs and the Python examples.
  python3-setuptools python3-wheel python3-pip python3-venv python3-mypy
)
# Node.js and npm: the machine's own when there (any Node >= 18), else Debian's.
if ! command -v node >/dev/null 2>&1; then packages+=(nodejs); fi
if ! command -v npm >/dev/null 2>&1; then packages+=(npm); fi
if ((with_browser)); then packages+=(chromium); fi
# clang++ (Debian's default clang, 14 on bookworm) and its sanitizer / libFuzzer runtimes.
if ((with_clang || with_fuzz)); then packages+=(clang libclang-rt-dev); fi
if ((with_sklearn)); then packages+=(python3-sklearn); fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "install-deps: installing ${missing[*]}" >&2
  SUDO=""
  if [[ $(id -u) -ne 0 ]]; then SUDO="sudo"; fi
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# web/node_modules, reinstalled only when web/package-lock.json changed since the last `npm ci`.
stamp=web/node_modules/.vrreg-package-lock.sha256
want=$(sha256sum web/package-lock.json | cut -d' ' -f1)
if [[ ! -f $stamp || $(cat "$stamp") != "$want" ||
      ! -f web/node_modules/plotly.js-dist-min/plotly.min.js ]]; then
  echo "install-deps: npm ci in web/ (Plotly for vrreg report, playwright-core for its test)" >&2
  (cd web && npm ci --no-audit --no-fund --loglevel=error >/dev/null)
  echo "$want" > "$stamp"
fi
