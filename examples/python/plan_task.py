#!/usr/bin/env python3
"""Plan a task from Python: the 3-block-tray scenario's minimum-motion plan, a replan after a
person moves a block back, and a task of your own written as LTL over new propositions.

Run: PYTHONPATH=<build>/python /usr/bin/python3 examples/python/plan_task.py
"""
import argparse

import rtamp

parser = argparse.ArgumentParser(description=__doc__)
parser.add_argument("--out", help="unused (the examples share one command line)")
parser.parse_args()

scenario = rtamp.load_scenario("3-block-tray")
planner = rtamp.Planner(scenario, algorithm="astar-exp", cost="euclid")
plan = planner.plan()
print(f"task {scenario.task}: cost {plan.cost:.3f} m, {len(plan.moves)} moves")
for a in plan.actions:
    print(f"  {a.action:16} {a.cost:.3f} m")
print(f"  searched {plan.stats.expanded} nodes in {plan.stats.seconds * 1e3:.2f} ms")

# The robot did the first two moves, then a person put o1 back in r1.
for step in plan.prefix[:2]:
    planner.execute(step)
planner.apply("move o1 r1")
replan = planner.plan()
print(f"after 'move o1 r1': cost {replan.cost:.3f} m: {' '.join(replan.moves)}"
      f" ({replan.stats.reused_nodes} nodes reused)")

# A task of your own: first o1 to r2, and only then every block to r1 (a sequence).
text = """
name: sequence
regions:
  - {name: r1, center: [0.40, 0.32, 0], size: [0.36, 0.36], capacity: 4}
  - {name: r2, center: [0.40, -0.32, 0], size: [0.36, 0.36], capacity: 4}
objects:
  - {name: o1, position: [0.32, 0.40, 0]}
  - {name: o2, position: [0.40, 0.40, 0]}
propositions:
  o1_in_r2: "o1 in r2"
  all_in_r1: "all block in r1"
task: "F (o1_in_r2 & F G all_in_r1)"
"""
own = rtamp.parse_scenario(text, "sequence.yaml")
p = rtamp.Planner(own)
result = p.plan()
assert result.found and result.moves == ["move(o1, r2)", "move(o1, r1)"], result.moves
print(f"task {own.task}: {' '.join(result.moves)}")
print(f"its Büchi automaton has {p.automaton.num_states} states")
