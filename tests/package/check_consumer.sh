#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The installed package as a user sees it (ctest vrreg_package_consumer): installs BUILD_DIR into a
# fresh prefix, then builds and runs tests/package/consumer against it with find_package(vrreg
# CONFIG) and again with pkg-config, using the build's own compiler and generator.
# Usage: check_consumer.sh BUILD_DIR GENERATOR CXX BUILD_TYPE [SANITIZE_FLAGS]
# SANITIZE_FLAGS: a sanitized build's libraries need sanitized users, compiled as well as linked
# (Eigen's allocator, for one, differs under ASan).
set -euo pipefail
build=$1 generator=$2 cxx=$3 build_type=$4 sanitize_flags=${5:-}
consumer=$(cd "$(dirname "$0")/consumer" && pwd)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/vrreg-package.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
prefix=$tmp/prefix
fail() { echo "check_consumer: FAILED: $*" >&2; exit 1; }
step() { echo "== $*"; }

step "cmake --install $build --prefix $prefix"
cmake --install "$build" --prefix "$prefix" ${build_type:+--config "$build_type"} >"$tmp/install.log" ||
  { cat "$tmp/install.log"; fail "cmake --install"; }
# Only what a user needs: no test, benchmark or example binaries, no GoogleTest.
for entry in "$prefix"/* "$prefix"/bin/*; do
  case ${entry#"$prefix"/} in
    bin | include | lib | lib64 | share | bin/vrreg) ;;
    *) fail "unexpected installed file $entry" ;;
  esac
done
"$prefix/bin/vrreg" --help >/dev/null || fail "the installed vrreg --help"

step "find_package(vrreg CONFIG) with CMAKE_PREFIX_PATH=$prefix"
cmake -S "$consumer" -B "$tmp/cmake-build" -G "$generator" -DCMAKE_CXX_COMPILER="$cxx" \
  -DCMAKE_BUILD_TYPE="$build_type" -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_CXX_FLAGS="$sanitize_flags" -DCMAKE_EXE_LINKER_FLAGS="$sanitize_flags" \
  >"$tmp/configure.log" ||
  { cat "$tmp/configure.log"; fail "configuring the consumer"; }
found=$(grep '^vrreg_DIR:' "$tmp/cmake-build/CMakeCache.txt")
[[ $found == *"$prefix"/* ]] || fail "found another vrreg: $found"
cmake --build "$tmp/cmake-build" -j2 || fail "building the consumer with find_package"
"$tmp/cmake-build/consumer" | tee "$tmp/cmake.out" || fail "running the find_package consumer"

step "the same cell through the installed command line: register, correct"
"$tmp/cmake-build/write_cell" >"$tmp/cell.csv" || fail "writing the consumer's cell"
"$prefix/bin/vrreg" register --fiducials "$tmp/cell.csv" -o "$tmp/model.json" >/dev/null ||
  fail "vrreg register on the consumer's cell"
"$prefix/bin/vrreg" correct --model "$tmp/model.json" --points "$tmp/cell.csv" \
  -o "$tmp/corrected.csv" >/dev/null || fail "vrreg correct on the consumer's cell"
# Every target's corrected position, library against command line, to 1e-6 mm.
awk -F'[ ,]' 'NR == FNR { if (NF == 4) want[$1] = $2 " " $3 " " $4; next }
  /^#|^point/ { next }
  { split(want[$1], w, " "); n++
    for (a = 1; a <= 3; a++) if ((w[a] - $(a + 3)) ^ 2 > 1e-12) { print "differs: " $0; bad = 1 } }
  END { if (n != 8 || bad) exit 1 }' "$tmp/cmake.out" "$tmp/corrected.csv" ||
  fail "the library and the command line disagree on the consumer's cell"

pc=$(find "$prefix" -name vrreg.pc)
[[ -n $pc ]] || fail "no vrreg.pc installed"
export PKG_CONFIG_PATH=${pc%/*}
flags=$(pkg-config --cflags --libs vrreg) || fail "pkg-config --cflags --libs vrreg"
step "pkg-config --cflags --libs vrreg: $flags"
[[ $flags == *"$prefix"/* ]] || fail "pkg-config resolved another vrreg"
# shellcheck disable=SC2086  # the flags are words
"$cxx" -std=c++20 "$consumer/main.cpp" -o "$tmp/consumer-pc" $flags $sanitize_flags ||
  fail "building the consumer with pkg-config flags"
"$tmp/consumer-pc" >"$tmp/pc.out" || fail "running the pkg-config consumer"
cmp -s "$tmp/cmake.out" "$tmp/pc.out" || fail "the pkg-config consumer printed something else"
step "package consumer: ok"
