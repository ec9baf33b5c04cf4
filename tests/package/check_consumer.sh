#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The installed package as a user sees it. Installs BUILD_DIR into a fresh prefix (or takes PREFIX,
# an installed tree), then builds and runs tests/package/consumer against it with
# find_package(vrreg CONFIG) and with pkg-config, twice: for the x86-64 baseline the libraries are
# built for, and with -march=native (-mavx2 where the machine has no AVX), where Eigen would align
# to 32 bytes unless vrreg's targets and vrreg.pc pass on the library's setting. Checks too that a
# build bypassing them stops at compile time (vrreg/config.hpp's static_assert), not in a crash.
# Usage: check_consumer.sh BUILD_DIR|PREFIX GENERATOR CXX BUILD_TYPE [SANITIZE_FLAGS]
# SANITIZE_FLAGS: a sanitized build's libraries need sanitized users, compiled as well as linked
# (Eigen's allocator, for one, differs under ASan).
set -euo pipefail
tree=$1 generator=$2 cxx=$3 build_type=$4 sanitize_flags=${5:-}
consumer=$(cd "$(dirname "$0")/consumer" && pwd)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/vrreg-package.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
fail() { echo "check_consumer: FAILED: $*" >&2; exit 1; }
step() { echo "== $*"; }

if [[ -f $tree/CMakeCache.txt ]]; then
  prefix=$tmp/prefix
  step "cmake --install $tree --prefix $prefix"
  cmake --install "$tree" --prefix "$prefix" ${build_type:+--config "$build_type"} \
    >"$tmp/install.log" || { cat "$tmp/install.log"; fail "cmake --install"; }
else
  prefix=$(cd "$tree" && pwd)
fi
# Only what a user needs: no test, benchmark or example binaries, no GoogleTest.
for entry in "$prefix"/* "$prefix"/bin/*; do
  case ${entry#"$prefix"/} in
    bin | include | lib | lib64 | share | bin/vrreg) ;;
    *) fail "unexpected installed file $entry" ;;
  esac
done
"$prefix/bin/vrreg" --help >/dev/null || fail "the installed vrreg --help"

pc=$(find "$prefix" -name vrreg.pc)
[[ -n $pc ]] || fail "no vrreg.pc installed"
export PKG_CONFIG_PATH=${pc%/*}
pc_flags=$(pkg-config --cflags --libs vrreg) || fail "pkg-config --cflags --libs vrreg"
[[ $pc_flags == *"$prefix"/* ]] || fail "pkg-config resolved another vrreg: $pc_flags"

# The instruction set beyond the baseline: the machine's own, or AVX2 to compile at least.
if grep -qw avx /proc/cpuinfo; then
  wide=-march=native
else
  wide=-mavx2
fi

# One consumer build and run with extra compile flags $1 (find_package, then pkg-config).
consume() {
  local flags=$1 name=$2
  local dir=$tmp/$name
  step "[$name] find_package(vrreg CONFIG) with CMAKE_PREFIX_PATH=$prefix, flags '$flags'"
  cmake -S "$consumer" -B "$dir/cmake-build" -G "$generator" -DCMAKE_CXX_COMPILER="$cxx" \
    -DCMAKE_BUILD_TYPE="$build_type" -DCMAKE_PREFIX_PATH="$prefix" \
    -DCMAKE_CXX_FLAGS="$sanitize_flags $flags" -DCMAKE_EXE_LINKER_FLAGS="$sanitize_flags" \
    >"$tmp/configure.log" || { cat "$tmp/configure.log"; fail "configuring the consumer"; }
  local found
  found=$(grep '^vrreg_DIR:' "$dir/cmake-build/CMakeCache.txt")
  [[ $found == *"$prefix"/* ]] || fail "found another vrreg: $found"
  cmake --build "$dir/cmake-build" -j2 >"$tmp/build.log" ||
    { cat "$tmp/build.log"; fail "building the consumer with find_package, flags '$flags'"; }
  if [[ $flags == -mavx2 ]] && ! grep -qw avx2 /proc/cpuinfo; then
    step "[$name] built; not run (this machine has no AVX2)"
    return
  fi
  "$dir/cmake-build/consumer" >"$dir/cmake.out" ||
    fail "running the find_package consumer built with '$flags'"

  step "[$name] pkg-config --cflags --libs vrreg: $pc_flags"
  # shellcheck disable=SC2086  # the flags are words
  "$cxx" -std=c++20 $flags "$consumer/main.cpp" -o "$dir/consumer-pc" $pc_flags $sanitize_flags ||
    fail "building the consumer with pkg-config flags and '$flags'"
  "$dir/consumer-pc" >"$dir/pc.out" || fail "running the pkg-config consumer built with '$flags'"
  cmp -s "$dir/cmake.out" "$dir/pc.out" || fail "the pkg-config consumer printed something else"
}

consume "" baseline
cat "$tmp/baseline/cmake.out"
consume "$wide" "${wide#-}"
if [[ -f $tmp/${wide#-}/cmake.out ]]; then
  # Same library code on both sides of every call: the same numbers, to the last digit.
  cmp -s "$tmp/baseline/cmake.out" "$tmp/${wide#-}/cmake.out" ||
    fail "the consumer built with $wide printed other numbers than the baseline one"
fi

step "the same cell through the installed command line: register, correct"
"$tmp/baseline/cmake-build/write_cell" >"$tmp/cell.csv" || fail "writing the consumer's cell"
"$prefix/bin/vrreg" register --fiducials "$tmp/cell.csv" -o "$tmp/model.json" >/dev/null ||
  fail "vrreg register on the consumer's cell"
"$prefix/bin/vrreg" correct --model "$tmp/model.json" --points "$tmp/cell.csv" \
  -o "$tmp/corrected.csv" >/dev/null || fail "vrreg correct on the consumer's cell"
# Every target's corrected position, library against command line, to 1e-6 mm.
awk -F'[ ,]' 'NR == FNR { if (NF == 4) want[$1] = $2 " " $3 " " $4; next }
  /^#|^point/ { next }
  { split(want[$1], w, " "); n++
    for (a = 1; a <= 3; a++) if ((w[a] - $(a + 3)) ^ 2 > 1e-12) { print "differs: " $0; bad = 1 } }
  END { if (n != 8 || bad) exit 1 }' "$tmp/baseline/cmake.out" "$tmp/corrected.csv" ||
  fail "the library and the command line disagree on the consumer's cell"

step "a build that bypasses the targets and vrreg.pc ($wide, no EIGEN_MAX_ALIGN_BYTES) must not compile"
include_dir=$(pkg-config --variable=includedir vrreg)
# shellcheck disable=SC2086  # the flags are words
if "$cxx" -std=c++20 $wide -fsyntax-only -I"$include_dir" $(pkg-config --cflags-only-I eigen3) \
  "$consumer/main.cpp" 2>"$tmp/bypass.log"; then
  fail "the consumer compiled with $wide without vrreg's Eigen setting"
fi
grep -q "EIGEN_MAX_ALIGN_BYTES" "$tmp/bypass.log" ||
  { cat "$tmp/bypass.log"; fail "the compile error does not name EIGEN_MAX_ALIGN_BYTES"; }
step "package consumer: ok"
