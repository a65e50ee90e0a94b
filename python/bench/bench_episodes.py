#!/usr/bin/env python3
"""A pure-Python World driving episodes of 3-block-tray (docs/benchmarks.md, "Python module"):
rtamp.toy.ToyWorld (a discrete-event symbolic world written in Python) under the C++ reactive
loop, planning inline (astar-exp, euclid), the scenario's scripted relocation of o2 at 20 s plus,
with --person, a relocation of a seeded random block at a seeded random time per episode.
Prints episodes per second (in-process wall time) and how many succeeded.

Usage: PYTHONPATH=<build>/python /usr/bin/python3 python/bench/bench_episodes.py N [--person]
"""
import random
import sys
import time

import rtamp
from rtamp.toy import ToyWorld

n = int(sys.argv[1]) if len(sys.argv) > 1 else 500
person = "--person" in sys.argv
scenario = rtamp.load_scenario("3-block-tray")
script = list(scenario.interventions)
rng = random.Random(1)
ok = 0
callbacks = 0
t0 = time.perf_counter()
for i in range(n):
    s = list(script)
    if person:
        s.append(rtamp.Intervention("relocate", rng.choice(["o1", "o2", "o3"]), "r1", time=rng.uniform(2, 20)))
    toy = ToyWorld(scenario, move_time=2.0)
    world = rtamp.PersonWorld(toy, rtamp.Person(scenario, script=s))
    m = rtamp.ReactiveLoop(world, scenario, planning="inline", seed=i).run()
    ok += m.success
    callbacks += toy.calls
dt = time.perf_counter() - t0
print(f"{n} episodes in {dt:.3f} s: {n / dt:.0f} episodes/s, {ok} succeeded, "
      f"{callbacks / n:.0f} world callbacks per episode")
