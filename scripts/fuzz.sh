#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Fuzzes the file readers with libFuzzer under ASan + UBSan (tests/fuzz/, docs/file-formats.md):
#   scripts/fuzz.sh [SECONDS_PER_HARNESS] [HARNESS...]     (default: 60 s each, every harness)
# Builds the `fuzz` preset (clang; `scripts/install-deps.sh --with-fuzz` installs it), then runs
# each harness for the budget from its checked-in seed corpus (tests/fuzz/corpus/NAME) plus the
# regression inputs (tests/fuzz/regressions/NAME). New corpus entries go to build/fuzz/corpus/NAME
# (not checked in). A crash, leak, timeout (> 10 s per input) or a Finding (an exception other
# than FileError, a multi-line message, a broken write-back) stops that harness: its input is in
# build/fuzz/artifacts/NAME/; fix the bug, copy the input to tests/fuzz/regressions/NAME/ (the
# test suite replays it) and run again. Exit status: 0 when every harness ran clean.
set -uo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
shift || true
if ! [[ $seconds =~ ^[0-9]+$ ]] || ((seconds < 1)); then
  echo "fuzz.sh: SECONDS_PER_HARNESS must be a whole number >= 1, got '$seconds'" >&2
  exit 2
fi
all=(measurement_csv model_json robot_file error_model plan_csv parts_csv urdf serve_line serve_http
  serve_line_handler serve_http_handler)
harnesses=("$@")
((${#harnesses[@]})) || harnesses=("${all[@]}")
if ! command -v clang++ >/dev/null 2>&1; then
  echo "fuzz.sh: clang++ not found: run scripts/install-deps.sh --with-fuzz" >&2
  exit 2
fi
launcher=()
command -v ccache >/dev/null 2>&1 && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake --preset fuzz "${launcher[@]}" >/dev/null || exit 2
targets=()
for h in "${harnesses[@]}"; do targets+=("vrreg_fuzz_$h"); done
cmake --build --preset fuzz --target "${targets[@]}" || exit 2

export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:symbolize=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$PWD/tests/lsan.supp"  # third-party leaks only (urdfdom)
failed=()
for h in "${harnesses[@]}"; do
  corpus=build/fuzz/corpus/$h
  artifacts=build/fuzz/artifacts/$h
  mkdir -p "$corpus" "$artifacts"
  seeds=(tests/fuzz/corpus/"$h")
  [[ -d tests/fuzz/regressions/$h ]] && seeds+=(tests/fuzz/regressions/"$h")
  log=build/fuzz/$h.log
  echo "fuzz.sh: $h for ${seconds} s (log: $log)"
  # -max_len 65536: room for whole model files; -rss_limit_mb: a reader must not balloon.
  build/fuzz/fuzz/vrreg_fuzz_"$h" "$corpus" "${seeds[@]}" -max_total_time="$seconds" \
    -max_len=65536 -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="$artifacts/" >"$log" 2>&1
  status=$?
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || true)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 || true)
  if ((status == 0)); then
    echo "fuzz.sh: $h clean: ${runs:-?} executions, ${cov:-cov ?}"
  else
    echo "fuzz.sh: $h FAILED (exit $status): see $log and $artifacts/" >&2
    grep -m5 -E 'ERROR|finding|SUMMARY|Test unit written' "$log" >&2 || true
    failed+=("$h")
  fi
done
if ((${#failed[@]})); then
  echo "fuzz.sh: failed: ${failed[*]}" >&2
  exit 1
fi
echo "fuzz.sh: every harness ran clean"
