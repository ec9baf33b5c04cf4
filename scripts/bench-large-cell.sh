#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# A large simulated cell and the time and peak memory of every correction method on it
# (docs/benchmarks.md, "Large cells"):
#
#   scripts/bench-large-cell.sh [-n NODES] [-m "METHODS"] [-k] [-c CELL] [VRREG] [DIR]
#
# NODES^3 fiducials on a 10 mm lattice about the UR5 test bed's volume centre, with joints (vrreg
# plan) and 1 000 targets inside, measured on the simulated UR5 (seed 1); then for each method
# `vrreg register --interpolation M -o model.json` and `vrreg evaluate --model model.json
# --targets targets.csv --json`, each under /usr/bin/time -v. Prints one Markdown row per method
# and command: wall time, user time, peak resident memory, exit status. -k keeps the cell in DIR
# (default /tmp/vrreg-large-cell) between runs. Default: 47 nodes (103 823 fiducials), all methods.
# -c CELL measures CELL-fiducials.csv and CELL-targets.csv instead (e.g. 10^6 fiducials without
# joints: scripts/make-large-input.py --fiducials 1000000 --targets 1000 --targets-inside
# --pitch-mm 2.5 -o c.csv; scripts/make-large-cell.py split c.csv c-fiducials.csv c-targets.csv).
set -eu
nodes=47
methods="linear grid octuplet trilinear scattered kriging rbf joint auto"
keep=0
cell=
while getopts n:m:kc: opt; do
  case $opt in
    n) nodes=$OPTARG ;;
    m) methods=$OPTARG ;;
    k) keep=1 ;;
    c) cell=$OPTARG ;;
    *) exit 2 ;;
  esac
done
shift $((OPTIND - 1))
here=$(cd "$(dirname "$0")" && pwd)
vrreg=${1:-$here/../build/release/bin/vrreg}
dir=${2:-/tmp/vrreg-large-cell}
mkdir -p "$dir"
rm -f "$dir"/centre_*.csv
if [ -n "$cell" ]; then
  nodes="$(($(grep -c ',fiducial,' "$cell-fiducials.csv")))"
elif cell=$dir/cell-$nodes && { [ "$keep" = 0 ] || [ ! -f "$cell-fiducials.csv" ]; }; then
  half=$(/usr/bin/python3 "$here/make-large-cell.py" parts --nodes "$nodes" "$dir")
  plans=
  for centre in "$dir"/centre_*.csv; do
    plan=${centre%.csv}-plan.csv
    "$vrreg" plan --parts "$centre" --halfwidth-mm "$half" --spacing-mm 10 --robot ur5 --force \
      -o "$plan" >/dev/null
    plans="$plans $plan"
  done
  "$vrreg" plan --parts "$dir/target_parts.csv" --halfwidth-mm 5 --spacing-mm 10 --robot ur5 \
    --force -o "$dir/plan_t.csv" >/dev/null
  # shellcheck disable=SC2086
  /usr/bin/python3 "$here/make-large-cell.py" merge --nodes "$nodes" $plans "$dir/plan_t.csv" \
    -o "$dir/plan.csv"
  "$vrreg" simulate ur5 --plan "$dir/plan.csv" --seed 1 -o "$cell.csv" >/dev/null
  /usr/bin/python3 "$here/make-large-cell.py" split "$cell.csv" "$cell-fiducials.csv" \
    "$cell-targets.csv"
fi
measure() {  # label, then the command: one table row
  label=$1
  shift
  set +e
  /usr/bin/time -v "$@" >"$dir/out.txt" 2>"$dir/time.txt"
  status=$?
  set -e
  wall=$(sed -n 's/.*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$dir/time.txt")
  user=$(sed -n 's/.*User time (seconds): //p' "$dir/time.txt")
  rss=$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$dir/time.txt")
  why=$(grep -m1 '^vrreg: ' "$dir/time.txt" || true)
  echo "| $label | $wall | $user s | $((rss / 1024)) MiB | $status $why |"
}
case $nodes in
  *[!0-9]*) ;;
  *) [ "$nodes" -gt 1000 ] || nodes="$nodes^3" ;;
esac
echo "| command ($nodes fiducials) | wall | user | peak RSS | exit |"
echo "|---|---:|---:|---:|---|"
for m in $methods; do
  measure "register --interpolation $m" "$vrreg" register --fiducials "$cell-fiducials.csv" \
    --robot ur5 --interpolation "$m" $([ "$m" = octuplet ] && echo --cube-mm 10) \
    -o "$dir/model-$m.json"
  cp "$dir/out.txt" "$dir/register-$m.txt"
  if [ -f "$dir/model-$m.json" ]; then
    measure "evaluate ($m)" "$vrreg" evaluate --model "$dir/model-$m.json" \
      --targets "$cell-targets.csv" --json
    cp "$dir/out.txt" "$dir/evaluate-$m.json"
    rm -f "$dir/model-$m.json"
  fi
done
