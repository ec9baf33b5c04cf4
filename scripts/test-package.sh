#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# From a fresh tree, as a user who clones the repository: scripts/package.sh (configure, build,
# the three .deb files), lintian on each (no error, no warning), the docs/install.md recipe
# (cmake --install into a prefix) with the outside consumer built against it twice (baseline and
# -march=native: tests/package/check_consumer.sh), the same consumer against the build tree
# (find_package and pkg-config), each source file outside tests/ compiled on its own
# (scripts/check-sources.sh), and `pip install .` of the Python package into a fresh venv that
# sees Debian's packages, then `import vrreg` there. scripts/test.sh runs it.
# The fresh tree is a clone of the committed HEAD: uncommitted changes are not in it.
# Usage: scripts/test-package.sh [KEEP_DIR]   (default: a temporary directory, removed after)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
if (($#)); then
  tmp=$1
  rm -rf "$tmp" && mkdir -p "$tmp"
else
  tmp=$(mktemp -d "${TMPDIR:-/tmp}/vrreg-fresh.XXXXXX")
  trap 'rm -rf "$tmp"' EXIT
fi
fail() { echo "test-package: FAILED: $*" >&2; exit 1; }
step() { echo "== test-package: $*"; }
started=$SECONDS

step "git clone $root (HEAD $(git -C "$root" rev-parse --short HEAD))"
git clone --quiet --no-hardlinks "$root" "$tmp/src"
src=$tmp/src
# The charting library comes from the npm registry (install-deps.sh); a copy of the checkout's
# saves the download when it is there.
if [[ -d $root/web/node_modules ]]; then cp -a "$root/web/node_modules" "$src/web/"; fi

step "scripts/package.sh"
(cd "$src" && scripts/package.sh) >"$tmp/debs.txt" 2>"$tmp/package.log" ||
  { tail -40 "$tmp/package.log"; fail "scripts/package.sh"; }
mapfile -t debs <"$tmp/debs.txt"
names=$(for d in "${debs[@]}"; do dpkg-deb -f "$d" Package; done | sort | tr '\n' ' ')
[[ $names == "libvrreg-dev python3-vrreg vrreg " ]] || fail "packages built: $names"

for deb in "${debs[@]}"; do
  step "lintian ${deb##*/}"
  # --fail-on: errors and warnings fail; info and pedantic tags are printed only.
  lintian --fail-on error,warning --tag-display-limit 0 "$deb" || fail "lintian ${deb##*/}"
  package=$(dpkg-deb -f "$deb" Package)
  dpkg-deb -c "$deb" >"$tmp/$package.list"
  grep -q "./usr/share/doc/$package/copyright$" "$tmp/$package.list" || fail "$package: no copyright"
done
grep -q "usr/lib/x86_64-linux-gnu/libvrreg_core.a\|usr/lib/$(dpkg-architecture -qDEB_HOST_MULTIARCH)/libvrreg_core.a" \
  "$tmp/libvrreg-dev.list" || fail "libvrreg-dev: the libraries are not in the multiarch directory"

step "docs/install.md: cmake --install build/package --prefix $tmp/prefix"
cmake --install "$src/build/package" --prefix "$tmp/prefix" >"$tmp/install.log" ||
  { cat "$tmp/install.log"; fail "cmake --install"; }
cxx=$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$src/build/package/CMakeCache.txt")
bash "$src/tests/package/check_consumer.sh" "$tmp/prefix" Ninja "$cxx" Release ||
  fail "the outside consumer against the installed prefix"

# The build tree used as a package (vrreg_DIR=<build>, PKG_CONFIG_PATH=<build>), as a project
# built beside vrreg's sources does: -march=native, where only the Eigen setting the build tree's
# vrreg.pc and targets pass on keeps the consumer's memory layout the library's.
step "the build tree as a package: find_package and pkg-config against $src/build/package"
if grep -qw avx /proc/cpuinfo; then wide=-march=native; else wide=-mavx2; fi
tree_pc=$(PKG_CONFIG_PATH="$src/build/package" pkg-config --cflags --libs vrreg) ||
  fail "pkg-config against the build tree"
[[ $tree_pc == *"-I$src/include "* && $tree_pc == *"-DEIGEN_MAX_ALIGN_BYTES="* ]] ||
  fail "the build tree's vrreg.pc: $tree_pc"
{
  cmake -S "$src/tests/package/consumer" -B "$tmp/tree-consumer" -G Ninja \
    -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=Release -Dvrreg_DIR="$src/build/package" \
    -DCMAKE_CXX_FLAGS="$wide" && cmake --build "$tmp/tree-consumer" -j2
} >"$tmp/tree-consumer.log" 2>&1 ||
  { tail -30 "$tmp/tree-consumer.log"; fail "the consumer with find_package against the build tree"; }
# shellcheck disable=SC2086  # the flags are words
"$cxx" -std=c++20 $wide "$src/tests/package/consumer/main.cpp" -o "$tmp/tree-consumer-pc" $tree_pc ||
  fail "the consumer with pkg-config against the build tree"
if [[ $wide == -march=native ]] || grep -qw avx2 /proc/cpuinfo; then
  "$tmp/tree-consumer/consumer" >"$tmp/tree-cmake.out" || fail "running the build-tree consumer"
  "$tmp/tree-consumer-pc" >"$tmp/tree-pc.out" || fail "running the build-tree pkg-config consumer"
  cmp -s "$tmp/tree-cmake.out" "$tmp/tree-pc.out" ||
    fail "the build tree's pkg-config and find_package consumers printed different numbers"
fi

# The package preset builds in unity batches, which hide a missing include; a packager's plain
# build compiles each file alone. Each library, command, Python, benchmark and example file is
# compiled alone here, syntax only (tests/ too would overrun the test command's hour:
# docs/install.md, "The tests").
step "scripts/check-sources.sh: every source file outside tests/ compiles on its own"
(cd "$src" && scripts/check-sources.sh "$src" "$tmp/check-sources") >"$tmp/check-sources.log" 2>&1 ||
  { tail -40 "$tmp/check-sources.log"; fail "scripts/check-sources.sh"; }
tail -1 "$tmp/check-sources.log"

step "pip install . into a fresh venv (--system-site-packages: Debian's numpy, setuptools)"
/usr/bin/python3 -m venv --system-site-packages "$tmp/venv"
# The package preset's build is configured for Debian's python3, the venv's interpreter: setup.py
# builds (nothing left to build) and copies the module from there.
(cd "$src" && VRREG_CMAKE_BUILD_DIR="$src/build/package" \
  "$tmp/venv/bin/pip" wheel --no-build-isolation --no-index --no-deps -w "$tmp/wheel" . \
  >"$tmp/pip-wheel.log" 2>&1) || { tail -30 "$tmp/pip-wheel.log"; fail "pip wheel ."; }
wheel=$(ls "$tmp"/wheel/vrreg-*.whl)
/usr/bin/python3 -m zipfile -l "$wheel" >"$tmp/wheel.list"
for f in vrreg/__init__.py vrreg/__init__.pyi vrreg/py.typed "vrreg/_vrreg.cpython-"; do
  grep -q "$f" "$tmp/wheel.list" || fail "the wheel lacks $f"
done
(cd "$src" && VRREG_CMAKE_BUILD_DIR="$src/build/package" \
  "$tmp/venv/bin/pip" install --no-build-isolation --no-index . >"$tmp/pip.log" 2>&1) ||
  { tail -30 "$tmp/pip.log"; fail "pip install ."; }
(cd "$tmp" && "$tmp/venv/bin/python" - <<'PY') || fail "import vrreg in the venv"
import pickle
import numpy as np
import vrreg
assert vrreg.__file__.startswith(__import__("sys").prefix), vrreg.__file__
rng = np.random.default_rng(1)
sensor = rng.uniform(-0.1, 0.1, (27, 3))
model = vrreg.register(sensor, sensor + [0.3, 0.0, 0.2]).model
assert np.allclose(pickle.loads(pickle.dumps(model)).apply(sensor[0]), sensor[0] + [0.3, 0.0, 0.2])
print("venv: vrreg", vrreg.__version__, "from", vrreg.__file__)
PY
step "ok in $((SECONDS - started)) s"
