#!/usr/bin/env python3
"""Memory bandwidth of this machine with 1 and 2 processes (docs/performance/scale.md, np = 2 speed-up).

A sparse matrix-vector product streams the matrix from memory: its speed is the memory
bandwidth, and so is the speed-up of a run made of them. This probe measures the bandwidth of
STREAM's 'add' a = b + c (numpy, arrays of --mib MiB each, far beyond the caches) in one process,
then in two processes at once, and prints the medians of --repeat timings and the ratio: the
ceiling of the np = 2 speed-up of a bandwidth-bound run on this machine. Writes
results/bench/bandwidth_probe.json.
    bandwidth_probe.py [--mib 256] [--repeat 7] [--json PATH]"""
import argparse
import multiprocessing as mp
import os
import statistics
import sys
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "lib"))
import chocrun  # noqa: E402


def triad(n, repeat, barrier, out):
    b = np.ones(n)
    c = np.full(n, 2.0)
    a = np.empty(n)
    rates = []
    for _ in range(repeat):
        if barrier is not None:
            barrier.wait()
        t0 = time.perf_counter()
        np.add(b, c, out=a)  # STREAM's 'add': 3 arrays of traffic (write-allocate not counted)
        dt = time.perf_counter() - t0
        rates.append(3 * 8 * n / dt / 1e9)
    out.put(statistics.median(rates))


def measure(procs, n, repeat):
    q = mp.Queue()
    barrier = mp.Barrier(procs) if procs > 1 else None
    ps = [mp.Process(target=triad, args=(n, repeat, barrier, q)) for _ in range(procs)]
    for p in ps:
        p.start()
    rates = [q.get() for _ in ps]
    for p in ps:
        p.join()
    return rates


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--mib", type=int, default=256)
    ap.add_argument("--repeat", type=int, default=7)
    ap.add_argument("--json", default=None, help="the figures' file (default results/bench/<bench>.json)")
    a = ap.parse_args()
    n = a.mib * 1024 * 1024 // 8
    load = chocrun.load_average()
    one = measure(1, n, a.repeat)
    two = measure(2, n, a.repeat)
    print(f"load average before: {load}")
    print(f"1 process : {one[0]:.1f} GB/s")
    print(f"2 processes: {two[0]:.1f} + {two[1]:.1f} = {sum(two):.1f} GB/s")
    print(f"ratio (ceiling of a bandwidth-bound np = 2 speed-up): {sum(two) / one[0]:.2f}")
    rows = [{"processes": 1, "gb_s_each": one, "gb_s_total": one[0], "ratio": 1.0, "load": load, "repeat": a.repeat},
            {"processes": 2, "gb_s_each": two, "gb_s_total": sum(two), "ratio": sum(two) / one[0], "load": load,
             "repeat": a.repeat}]
    tables = [{"title": f"STREAM 'add' on {a.mib} MiB arrays (medians of {a.repeat} timings)",
               "columns": [["processes", "processes", "d"], ["gb_s_each", "GB/s each", "list:.1f"],
                           ["gb_s_total", "GB/s in all", ".1f"], ["ratio", "ratio to one process", ".2f"],
                           ["load", "load before", ".2f"]],
               "note": "the ratio is the ceiling of the np = 2 speed-up of a bandwidth-bound run on this machine"}]
    chocrun.write_bench_json("bandwidth_probe", "Memory bandwidth with 1 and 2 processes", rows, tables, vars(a),
                             a.json)


if __name__ == "__main__":
    main()
