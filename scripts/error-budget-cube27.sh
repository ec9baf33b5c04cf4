#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Where the 27-fiducial cube's error comes from (docs/reproduction.md): the simulated
# UR5's A1 data with one group of its errors switched off at a time (`vrreg simulate --errors`),
# cut to the cube (the 3 x 3 x 3 even nodes around p04_06_04, 50 mm apart, and the 8 targets
# inside), corrected by octuplet RRBC and by kriging; medians over the seeds of RMS_T, mm.
# Usage: scripts/error-budget-cube27.sh [FIRST_SEED LAST_SEED] (default 1 10); needs the release
# build (scripts/build.sh release).
set -euo pipefail
cd "$(dirname "$0")/.."
vrreg=$PWD/build/release/bin/vrreg
first=${1:-1}
last=${2:-10}
[[ -x $vrreg ]] || { echo "error-budget-cube27: build first (scripts/build.sh release)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$vrreg" simulate ur5 A1 --seed 1 --write-errors "$work/defaults.json" -o "$work/unused.csv" >/dev/null
# variant name -> edit of the test bed's default errors (robot section)
variant() {
  python3 - "$work/defaults.json" "$1" "$2" <<'EOF'
import json, sys
errors = json.load(open(sys.argv[1]))
robot = errors["robot"]
amplitude = robot["transmission_amplitude_arcmin"]
which = sys.argv[2]
if which in ("no-joint1-wave", "no-waves"):
    amplitude[0] = 0.0
if which in ("no-wrist-elbow-waves", "no-waves", "joint1-wave-only"):
    amplitude[1:] = [0.0] * (len(amplitude) - 1)
if which == "joint1-wave-only":
    for key in ("joint_offset_sigma_deg", "link_length_sigma_mm", "link_offset_sigma_mm",
                "twist_sigma_deg"):
        robot[key] = 0.0
json.dump(errors, open(sys.argv[3], "w"), indent=1)
EOF
}

# Rows of the cube: even fiducial nodes within 2 of (4, 6, 4), targets within 1.
cube() {
  awk -F, '/^#/ || $1 == "point" {print; next}
    {split(substr($1, 2), n, "_"); dx = n[1] - 4; dy = n[2] - 6; dz = n[3] - 4
     m = (dx < 0 ? -dx : dx); if ((dy < 0 ? -dy : dy) > m) m = (dy < 0 ? -dy : dy)
     if ((dz < 0 ? -dz : dz) > m) m = (dz < 0 ? -dz : dz)
     if ($2 == "target" ? m <= 1 : (m <= 2 && n[1] % 2 == 0 && n[2] % 2 == 0 && n[3] % 2 == 0)) print}' "$1"
}

rms_t() { awk '/RMS_T/ {print $4; exit}'; }

median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2)}'; }

printf '%-22s %9s %9s\n' "errors" "octuplet" "kriging"
for name in all no-joint1-wave no-wrist-elbow-waves no-waves joint1-wave-only; do
  variant "$name" "$work/$name.json"
  : > "$work/octuplet.txt"
  : > "$work/kriging.txt"
  for seed in $(seq "$first" "$last"); do
    "$vrreg" simulate ur5 A1 --seed "$seed" --errors "$work/$name.json" -o "$work/a1.csv" >/dev/null
    cube "$work/a1.csv" > "$work/cube.csv"
    "$vrreg" register --fiducials "$work/cube.csv" --sigma-rep-mm 0.1 --robot ur5 \
      -o "$work/model.json" >/dev/null
    "$vrreg" evaluate --model "$work/model.json" --targets "$work/cube.csv" \
      --interpolation octuplet --cube-mm 50 | rms_t >> "$work/octuplet.txt"
    "$vrreg" evaluate --model "$work/model.json" --targets "$work/cube.csv" \
      --interpolation kriging | rms_t >> "$work/kriging.txt"
  done
  printf '%-22s %9s %9s\n' "$name" "$(median < "$work/octuplet.txt")" "$(median < "$work/kriging.txt")"
done
