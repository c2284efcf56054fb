#!/usr/bin/env python3
"""How long Ctrl-C takes to stop a computation of the Python module: SIGINT sent at a range of delays into the
smoothest cross field of one mesh (by default nefertiti_sub4, 400k faces, whose factorization is the longest
step without a solve), the time from the signal to the KeyboardInterrupt, and the phase the signal fell in
(the last progress fraction seen: 0.2 is the factorization).
  usage: PYTHONPATH=build/python interrupt_latency.py [MESH] [--repeat N]"""
import argparse
import os
import signal
import statistics
import threading
import time

import surface_mesh_direction_fields as smdf


def one_run(V, F, delay):
    seen = []
    sent = []

    def interrupt():
        sent.append(time.perf_counter())
        os.kill(os.getpid(), signal.SIGINT)
    timer = threading.Timer(delay, interrupt)
    timer.start()
    try:
        smdf.compute_globally_optimal_directions(V, F, degree=4, progress=seen.append)
        return None, None  # ended before the signal
    except KeyboardInterrupt:
        return time.perf_counter() - sent[0], seen[-1] if seen else None
    finally:
        timer.cancel()


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("mesh", nargs="?", default="../shared/data/meshes/nefertiti_sub4.off")
    parser.add_argument("--repeat", type=int, default=2)
    args = parser.parse_args()
    V, F = smdf.read_mesh(args.mesh)
    start = time.perf_counter()
    smdf.compute_globally_optimal_directions(V, F, degree=4)
    whole = time.perf_counter() - start
    print(f"{args.mesh}: {len(F)} faces, whole computation {whole:.3f} s")
    latencies = {}
    for _ in range(args.repeat):
        for step in range(1, 20):
            latency, phase = one_run(V, F, whole * step / 20)
            if latency is not None:
                latencies.setdefault(phase, []).append(latency)
    print("phase (last progress fraction)  signals  median latency  largest latency")
    for phase in sorted(latencies, key=lambda p: -1 if p is None else p):
        values = latencies[phase]
        print(f"{phase!s:>30}  {len(values):7d}  {statistics.median(values) * 1e3:11.1f} ms  "
              f"{max(values) * 1e3:12.1f} ms")


if __name__ == "__main__":
    main()
