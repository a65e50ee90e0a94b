#!/usr/bin/env python3
"""Plug in your own robot: a World written in pure Python runs a sequencing task.

The reactive loop only ever asks the world what time it is, lets time pass, observes
where every thing is, and starts / polls / halts one move at a time (rtamp.World).
This world is a toy stand-in for a real robot: each move takes two seconds, and a
person moves o1 back to r1 while the robot works; the loop notices it by observing
and replans. The task is a sequence: o1 to r2 first, then every block to r1 for good.

Run: PYTHONPATH=<build>/python /usr/bin/python3 examples/python/python_world_sequencing.py
"""
import argparse
import math

import rtamp


class MyRobot(rtamp.World):
    """A discrete-event robot: where things are, one move at a time, a person's script."""

    def __init__(self, scenario, person):
        super().__init__(scenario)  # observe() may then give plain locations for the scenario's things
        self.now = 0.0
        self.where = rtamp.initial_placement(scenario).locations()
        self.move, self.done_at = None, math.inf
        self.status, self.why, self.last_place = rtamp.MoveStatus.IDLE, "", ""
        self.person = sorted(person)  # [(time, thing, location)]
        self.events = []

    def time(self):
        return self.now

    def next_event_time(self):  # lets the loop jump from event to event
        return min([self.done_at] + [t for t, _, _ in self.person[:1]])

    def advance(self, dt):
        end = self.now + dt
        while self.next_event_time() <= end:
            self.now = self.next_event_time()
            if self.move is not None and self.done_at <= self.now:
                self.where[self.move.thing] = self.move.to
                self.status, self.last_place = rtamp.MoveStatus.SUCCEEDED, self.move.to
                self.move, self.done_at = None, math.inf
            else:
                t, thing, loc = self.person.pop(0)
                if self.move is not None and self.move.thing == thing:
                    self.move, self.done_at, self.status, self.why = None, math.inf, rtamp.MoveStatus.FAILED, "taken"
                self.where[thing] = loc
                self.events.append(rtamp.WorldEvent(t, rtamp.Intervention("relocate", thing, loc, time=t)))
        self.now = end

    def observe(self):  # a real robot: perception
        return dict(self.where)

    def start(self, move):  # a real robot: send the pick and place to the arm
        self.move, self.done_at, self.status = move, self.now + 2.0, rtamp.MoveStatus.RUNNING
        self.where[move.thing] = "hand"

    def poll(self):
        return self.status, self.why

    def halt(self):
        if self.move is not None:
            self.where[self.move.thing] = self.move.from_
            self.move, self.done_at, self.status, self.why = None, math.inf, rtamp.MoveStatus.FAILED, "halted"

    def hand(self):
        return self.last_place

    def take_events(self):
        out, self.events = self.events, []
        return out


class Printer(rtamp.Observer):
    def on_action(self, t, what, action, why):
        print(f"{t:6.1f} s  {what:9} {action} {why}")

    def on_intervention(self, e):
        print(f"{e.time:6.1f} s  person: {e.what.subject} -> {e.what.location}")

    def on_plan(self, t, plan):
        print(f"{t:6.1f} s  plan: {' '.join(plan['moves'])}")


parser = argparse.ArgumentParser(description=__doc__)
parser.add_argument("--out", help="unused (the examples share one command line)")
parser.parse_args()

scenario = rtamp.generate_scenario(regions=2, objects=3, task="F (o1_in_r2 & F G all_in_r1)",
                                   propositions=[("o1_in_r2", "o1 in r2"), ("all_in_r1", "all block in r1")])
robot = MyRobot(scenario, person=[(1.0, "o2", "r2")])
loop = rtamp.ReactiveLoop(robot, scenario, planning="inline")
loop.add_observer(Printer())
metrics = loop.run()
print(f"{metrics.end} after {metrics.world_time:.1f} s: {metrics.actions_succeeded} moves, {metrics.replans} replans")
states = [p.locations() for p in loop.observed_run]
assert metrics.success and any(s["o1"] == "r2" for s in states) and all(v == "r1" for v in states[-1].values())
