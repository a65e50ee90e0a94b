#!/usr/bin/env python3
"""Planning 3-block-tray through Python (docs/benchmarks.md, "Python module"): N times, load the
scenario and make the first plan with a fresh rtamp.Planner (astar-exp, euclid) — the same calls
python/bench/plan_peer.cpp makes in C++. Prints the in-process time per plan as well.

Usage: PYTHONPATH=<build>/python /usr/bin/python3 python/bench/bench_plan.py N
"""
import sys
import time

import rtamp

n = int(sys.argv[1]) if len(sys.argv) > 1 else 1000
t0 = time.perf_counter()
for _ in range(n):
    cost = rtamp.Planner(rtamp.load_scenario("3-block-tray")).plan().cost
dt = time.perf_counter() - t0
print(f"{n} plans, cost {cost:.6f}, {dt / n * 1e6:.1f} us per plan (in process)")
