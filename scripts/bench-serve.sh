#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The correction service under load (docs/serve.md, docs/benchmarks.md), over loopback on this
# machine: p50 / p99 latency and corrections per second with 1, 16 and 64 clients, on the line
# protocol and on HTTP, for an A1-size kriging model, the simulated A1 cell's kriging
# model (tabulated every 5 mm) and its RRBC grid model, beside a minimal Python service
# wrapping scipy's RBFInterpolator (python/benchmarks/serve_peer.py). Every line-protocol reply of
# vrreg is checked against `vrreg correct`'s CSV (wrong = 0), but for the poses (checked against
# vrreg::correct in tests/serve/serve_orientation_test.cpp) and the lost-motion model's answers
# with an approach direction (against vrreg::correct in tests/serve/serve_approach_test.cpp).
# Last, one robot client's latency while two clients send 10 000-point HTTP batches. The service writes its audit log (one line per
# correction) throughout, as a plant runs it.
#   scripts/bench-serve.sh [SECONDS_PER_RUN]        (default 5; needs the release build)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-5}"
build=build/release
vrreg=$build/bin/vrreg
load=$build/benchmarks/vrreg_serve_load
for f in "$vrreg" "$load"; do
  [[ -x $f ]] || { echo "bench-serve: $f missing: cmake --build $build" >&2; exit 2; }
done
work=$(mktemp -d)
pids=()
cleanup() { for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done; rm -rf "$work"; }
trap cleanup EXIT

/usr/bin/python3 python/benchmarks/serve_cell.py "$work/lattice.csv" "$work/lattice.txt"
"$vrreg" register --fiducials "$work/lattice.csv" --interpolation kriging -o "$work/lattice.json" >/dev/null
# With a rigid-body marker: the positions are those without it, bit for bit, and the kriging
# model also answers poses.
"$vrreg" simulate ur5 A1 --seed 1 --rigid-body-mm 50 -o "$work/a1.csv" >/dev/null
"$vrreg" register --fiducials "$work/a1.csv" --interpolation kriging -o "$work/a1-kriging.json" >/dev/null
"$vrreg" register --fiducials "$work/a1.csv" -o "$work/a1-grid.json" >/dev/null
# The A1 targets' first readings, as points to correct.
awk -F, '!/^#/ && $2 == "target" && !seen[$1]++ { print $6, $7, $8 }' "$work/a1.csv" > "$work/a1.txt"
# ... and as poses, the marker's measured orientation as a quaternion.
awk -F, '/^point,/ { for (i = 1; i <= NF; ++i) col[$i] = i }
  !/^#/ && $2 == "target" && !seen[$1]++ {
    print $6, $7, $8, "quat", $col["sensor_qx"], $col["sensor_qy"], $col["sensor_qz"], $col["sensor_qw"] }' \
  "$work/a1.csv" > "$work/a1-pose.txt"

# With lost motion (0.6 arc-min on joints 1, 4, 5, 6, 0.15 on 2 and 3; docs/joint-space-model.md):
# the kriging model with its lost-motion term, asked with the joints and where they came from
# (`joints ... from ...`, the previous target's joints), as a robot program asks it.
"$vrreg" simulate ur5 A1 --write-errors "$work/ur5-errors.json" >/dev/null
/usr/bin/python3 - "$work/ur5-errors.json" <<'PY'
import json, sys
errors = json.load(open(sys.argv[1]))
errors["robot"]["lost_motion_arcmin"] = [0.6, 0.15, 0.15, 0.6, 0.6, 0.6]
json.dump(errors, open(sys.argv[1], "w"))
PY
"$vrreg" simulate ur5 A1 --seed 1 --errors "$work/ur5-errors.json" -o "$work/a1-lm.csv" >/dev/null
"$vrreg" register --fiducials "$work/a1-lm.csv" --robot ur5 --interpolation kriging \
  --lost-motion on -o "$work/a1-lm.json" >/dev/null
awk -F, '/^point,/ { for (i = 1; i <= NF; ++i) col[$i] = i }
  !/^#/ && !/^point,/ && $2 == "target" && !seen[$1]++ {
    q = ""; for (j = 1; j <= 6; ++j) q = q " " $col["q" j "_rad"]
    if (prev != "") print $6, $7, $8, "joints" q, "from" prev
    prev = q }' "$work/a1-lm.csv" > "$work/a1-lm.txt"

# What `vrreg correct` writes, as the line protocol would reply it.
expect() {  # MODEL_JSON POINTS_TXT OUT
  awk 'BEGIN { print "point,role,sensor_x_mm,sensor_y_mm,sensor_z_mm" } { print "p" NR ",target," $1 "," $2 "," $3 }' "$2" > "$work/points.csv"
  "$vrreg" correct --model "$1" --points "$work/points.csv" -o "$work/corrected.csv" >/dev/null
  awk -F, '!/^#/ && NR > 2 { if ($3 == "ok" || $3 == "extrapolated") print "(" $4 "," $5 "," $6 "," ($13 == "" ? 0 : $13) ")"; else print "(0,0,0,-3)" }' "$work/corrected.csv" > "$3"
}
expect "$work/lattice.json" "$work/lattice.txt" "$work/lattice.expect"
expect "$work/a1-kriging.json" "$work/a1.txt" "$work/a1-kriging.expect"
expect "$work/a1-grid.json" "$work/a1.txt" "$work/a1-grid.expect"

port_of() {  # LOG PATTERN
  for _ in $(seq 600); do
    port=$(grep -o "$2 on 127.0.0.1:[0-9]*" "$1" | grep -o '[0-9]*$' || true)
    [[ -n $port ]] && { echo "$port"; return; }
    sleep 0.1
  done
  echo "bench-serve: no $2 port in $1" >&2; exit 1
}
"$vrreg" serve --model "lattice=$work/lattice.json" --model "a1k=$work/a1-kriging.json" \
  --model "a1g=$work/a1-grid.json" --model "a1lm=$work/a1-lm.json" --listen 127.0.0.1:0 --http 127.0.0.1:0 \
  --audit-log "$work/audit.jsonl" 2> "$work/serve.log" &
pids+=($!)
line=$(port_of "$work/serve.log" "line protocol")
http=$(port_of "$work/serve.log" "HTTP")
/usr/bin/python3 python/benchmarks/serve_peer.py --model "$work/lattice.json" --name lattice \
  --port 0 > "$work/peer.log" 2>&1 &
pids+=($!)
peer=$(port_of "$work/peer.log" "ready")

echo "| service | model | protocol | clients | corrections/s | p50 | p99 | wrong |"
echo "|---|---|---|---|---|---|---|---|"
run() {  # SERVICE MODEL[ LABEL] PROTOCOL ADDRESS CLIENTS POINTS [EXPECT]
  local args=("--$3" "$4" --model "${2%% *}" --points "$6" --clients "$5" --seconds "$seconds")
  local checked=False
  [[ -n ${7:-} ]] && { args+=(--expect "$7"); checked=True; }
  "$load" "${args[@]}" | /usr/bin/python3 -c "
import json, sys
r = json.load(sys.stdin)
print(f\"| $1 | $2 | {r['protocol']} | {r['clients']} | {r['per_second']:.0f} | {r['p50_us']:.0f} us | {r['p99_us']:.0f} us | {r['wrong'] if $checked else '-'} |\")"
}
for c in 1 16 64; do run vrreg lattice line 127.0.0.1:$line $c "$work/lattice.txt" "$work/lattice.expect"; done
for c in 1 16 64; do run vrreg lattice http 127.0.0.1:$http $c "$work/lattice.txt"; done
for c in 1 16 64; do run vrreg a1g line 127.0.0.1:$line $c "$work/a1.txt" "$work/a1-grid.expect"; done
for c in 1 16 64; do run vrreg a1k line 127.0.0.1:$line $c "$work/a1.txt" "$work/a1-kriging.expect"; done
for c in 1 16 64; do run vrreg "a1k pose" line 127.0.0.1:$line $c "$work/a1-pose.txt"; done
for c in 1 16 64; do run vrreg "a1lm from" line 127.0.0.1:$line $c "$work/a1-lm.txt"; done
for c in 1 16 64; do run "scipy peer" lattice line 127.0.0.1:$peer $c "$work/lattice.txt"; done

# A robot's request while cell software sends batches: one line-protocol client (checked) beside
# two clients posting 10 000-point HTTP batches back to back. Batches are answered on workers of
# their own, so the line request's p99 should stay near the table's 1-client row (<= 1 ms).
/usr/bin/python3 - "$http" "$work/a1.txt" "$seconds" > "$work/batches.log" <<'PY' &
import http.client, json, sys, threading, time
port, points_file, seconds = int(sys.argv[1]), sys.argv[2], float(sys.argv[3]) + 1.0
points = [[float(v) for v in line.split()] for line in open(points_file) if line.strip()]
body = json.dumps({"model": "a1k", "points": [{"sensor_mm": points[i % len(points)]}
                                              for i in range(10000)]})
times = []
def post():
    c = http.client.HTTPConnection("127.0.0.1", port, timeout=60)
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        start = time.monotonic()
        c.request("POST", "/v1/correct", body, {"Content-Type": "application/json"})
        r = c.getresponse()
        r.read()
        assert r.status == 200, r.status
        times.append(time.monotonic() - start)
threads = [threading.Thread(target=post) for _ in range(2)]
for t in threads: t.start()
for t in threads: t.join()
print(f"{len(times)} batches of 10 000 points, {min(times):.2f}-{max(times):.2f} s each")
PY
batcher=$!
pids+=($batcher)
sleep 0.5  # the batches running before the robot's requests are timed
run vrreg "a1k beside 2 batch clients" line 127.0.0.1:$line 1 "$work/a1.txt" "$work/a1-kriging.expect"
wait "$batcher"
echo
echo "beside the robot: $(cat "$work/batches.log")"
