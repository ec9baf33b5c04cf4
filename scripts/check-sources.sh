#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Every source file compiles on its own. The presets build in unity batches, where a file that
# misses an include is rescued by the files before it in its batch; a plain build (a packager's
# `cmake -S . -B b && cmake --build b`, an outside project's add_subdirectory) compiles each file
# alone and fails. This configures SOURCE_DIR without unity builds and runs each compile command
# of compile_commands.json with -fsyntax-only: the parse a missing include fails, without the code
# generation of a second build. Warnings are not errors here (the real builds check them).
# clang++ when there is one: its parse took 0.80 of GCC's (16 files, 61 s against 76 s).
# Measured on the shared 2-core machine: all 430 files with GCC 17.0 min (32 CPU-min); the 273
# outside tests/ with clang 9.4 min (13.4 CPU-min). So by default the libraries, the command, the
# Python module, the benchmarks and the examples (what a packager and an add_subdirectory user
# compile); the test files too with --with-tests (docs/install.md, "The tests").
# Usage: scripts/check-sources.sh [--with-tests] [SOURCE_DIR [BUILD_DIR]]
#   (default: this tree, build/check-sources)
set -euo pipefail
with_tests=0
if [[ ${1:-} == --with-tests ]]; then
  with_tests=1
  shift
fi
src=$(cd "${1:-$(dirname "$0")/..}" && pwd)
build=${2:-$src/build/check-sources}
jobs=${VRREG_CHECK_JOBS:-2}
compiler=()
if command -v clang++ >/dev/null; then compiler=(-DCMAKE_CXX_COMPILER=clang++); fi
mkdir -p "$build"
cmake -S "$src" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD=OFF \
  -DCMAKE_EXPORT_COMPILE_COMMANDS=ON "${compiler[@]}" >"$build/configure.log" 2>&1 ||
  { cat "$build/configure.log"; echo "check-sources: FAILED: configuring $build" >&2; exit 1; }
python3 - "$build/compile_commands.json" "$jobs" "$src/tests/" "$with_tests" <<'PY'
import concurrent.futures
import json
import shlex
import subprocess
import sys

entries = json.load(open(sys.argv[1]))
jobs = int(sys.argv[2])
if sys.argv[4] != "1":
    entries = [e for e in entries if not e["file"].startswith(sys.argv[3])]


def syntax_only(entry):
    words = entry["arguments"] if "arguments" in entry else shlex.split(entry["command"])
    args, skip = [], 0
    for w in words:
        if skip:
            skip -= 1
        elif w in ("-o", "-MT", "-MF"):
            skip = 1  # the object and dependency files: nothing is written
        elif w not in ("-MD", "-MMD", "-c"):
            args.append(w)
    run = subprocess.run(args + ["-fsyntax-only", "-Wno-error"], cwd=entry["directory"],
                         capture_output=True, text=True)
    return entry["file"], run.returncode, run.stderr


failed = []
with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
    for name, code, err in pool.map(syntax_only, entries):
        if code != 0:
            failed.append(name)
            sys.stderr.write(err)
if failed:
    sys.stderr.write("check-sources: FAILED: %d of %d files do not compile on their own:\n  %s\n"
                     % (len(failed), len(entries), "\n  ".join(failed)))
    sys.exit(1)
print("check-sources: %d files compile on their own" % len(entries))
PY
