#!/usr/bin/env bash
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
grep -qx "consumer: ok" "$tmp/cmake.out" || fail "the find_package consumer printed a wrong result"

pc=$(find "$prefix" -name vrreg.pc)
[[ -n $pc ]] || fail "no vrreg.pc installed"
export PKG_CONFIG_PATH=${pc%/*}
flags=$(pkg-config --cflags --libs vrreg) || fail "pkg-config --cflags --libs vrreg"
step "pkg-config --cflags --libs vrreg: $flags"
[[ $flags == *"$prefix"/* ]] || fail "pkg-config resolved another vrreg"
# shellcheck disable=SC2086  # the flags are words
"$cxx" -std=c++20 "$consumer/main.cpp" -o "$tmp/consumer-pc" $flags $sanitize_flags ||
  fail "building the consumer with pkg-config flags"
"$tmp/consumer-pc" | tee "$tmp/pc.out" || fail "running the pkg-config consumer"
grep -qx "consumer: ok" "$tmp/pc.out" || fail "the pkg-config consumer printed a wrong result"
step "package consumer: ok"
