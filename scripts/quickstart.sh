#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Quick start, command 1: install, build, run the main jobs.
# 1. register -> evaluate -> correct on the example cell that the repo ships
#    (examples/data/example-cell.csv, made by build/release/examples/example_01_make_example_cell);
# 2. vrreg reproduce: the paper's experiments on the simulated UR5 and KUKA test beds (one seed,
#    about a second), Tables 1-2 and the Figure 7-8 data beside the paper's, figure data and the
#    HTML report (report.html) in out/reproduce/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
# Only what the main job needs: the command and the Python module (not the tests and benchmarks);
# the module only where Python's development files are there (the configure step says so).
cmake --preset release >/dev/null
targets=(vrreg_cli)
# grep reads all of the list (no -q): an early exit would end cmake with SIGPIPE under pipefail.
if cmake --build build/release --target help | grep '^_vrreg:' >/dev/null; then targets+=(_vrreg); fi
scripts/build.sh release "${targets[@]}"
vrreg=build/release/bin/vrreg
data=examples/data/example-cell.csv
mkdir -p out
echo "== vrreg register --fiducials $data --sigma-rep-mm 0.05 -o out/model.json"
"$vrreg" register --fiducials "$data" --sigma-rep-mm 0.05 -o out/model.json
echo
echo "== vrreg evaluate --model out/model.json --targets $data"
"$vrreg" evaluate --model out/model.json --targets "$data" --per-target out/per-target.csv
echo
echo "== vrreg correct --model out/model.json --points $data -o out/corrected.csv"
"$vrreg" correct --model out/model.json --points "$data" -o out/corrected.csv
echo
echo "== vrreg reproduce --out out/reproduce"
"$vrreg" reproduce --out out/reproduce
