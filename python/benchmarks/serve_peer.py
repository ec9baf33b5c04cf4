#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The peer of `vrreg serve` in docs/benchmarks.md: a minimal Python service a cell engineer might
write instead, answering vrreg's line protocol with scipy's fitted RBFInterpolator.

It reads a vrreg model file (version 2, metres), fits RBFInterpolator(neighbors=50, thin-plate)
once on the fiducials' registered positions -> their corrections (robot frame), and answers
"<model> x y z" lines with "(x,y,z,0)" (no predicted sd). Threads per connection
(socketserver.ThreadingTCPServer), as such a service would be written. Used by
scripts/bench-serve.sh through benchmarks/serve_load.cpp.

    python3 python/benchmarks/serve_peer.py --model cell.json --name cell --port 30402
"""
import argparse
import json
import socketserver

import numpy as np
from scipy.interpolate import RBFInterpolator


def fit(path):
    m = json.load(open(path))
    rotation = np.array(m["rotation"], dtype=float)
    translation = np.array(m["translation_m"], dtype=float)
    scale = float(m.get("scale", 1.0))
    sensor = np.array([f["sensor_m"] for f in m["fiducials"]], dtype=float)
    robot = np.array([f["robot_m"] for f in m["fiducials"]], dtype=float)
    registered = scale * sensor @ rotation.T + translation
    rbf = RBFInterpolator(registered, robot - registered, neighbors=50,
                          kernel="thin_plate_spline")
    return rotation, translation, scale, rbf


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--model", required=True)
    parser.add_argument("--name", default="cell")
    parser.add_argument("--port", type=int, required=True)
    args = parser.parse_args()
    rotation, translation, scale, rbf = fit(args.model)

    class Handler(socketserver.StreamRequestHandler):
        def handle(self):
            for raw in self.rfile:
                fields = raw.decode("ascii", "replace").replace(",", " ").split()
                try:
                    if len(fields) != 4 or fields[0] != args.name:
                        raise ValueError
                    p = np.array([float(v) for v in fields[1:]]) / 1000.0
                    registered = scale * rotation @ p + translation
                    corrected = (registered + rbf(registered[None, :])[0]) * 1000.0
                    reply = "(%.12g,%.12g,%.12g,0)\n" % tuple(corrected)
                except ValueError:
                    reply = "(0,0,0,-1)\n"
                self.wfile.write(reply.encode())
                self.wfile.flush()

    socketserver.ThreadingTCPServer.allow_reuse_address = True
    socketserver.ThreadingTCPServer.daemon_threads = True
    with socketserver.ThreadingTCPServer(("127.0.0.1", args.port), Handler) as server:
        print("serve_peer: ready on 127.0.0.1:%d" % server.server_address[1], flush=True)
        server.serve_forever()


if __name__ == "__main__":
    main()
