"""ToyWorld: a World written in pure Python (the pattern for plugging in your own robot).

It keeps an exact symbolic placement, runs each move as a fixed-duration
discrete event (so the reactive loop jumps from event to event instead of
ticking), and can take a person's relocations (the intervention capability:
true_placement() and apply()), so rtamp.Person drives it like any world.
A real robot's World would read perception in observe() and drive the arm in
start()/poll()/halt(); everything else stays the same.

    person = rtamp.Person(scenario, script=[rtamp.Intervention("relocate", "o2", "r1", time=5.0)])
    world = rtamp.PersonWorld(rtamp.toy.ToyWorld(scenario, move_time=2.0), person)
    metrics = rtamp.ReactiveLoop(world, scenario, planning="inline").run()

Invariants: at most one move runs; a thing is in exactly one place (a region,
a container, or "hand" while held); a move whose thing a person moved away
fails ("thing moved"); a halted move puts its thing back at once.
"""

import math

import rtamp


class ToyWorld(rtamp.World):
    """A discrete-event symbolic world in pure Python (see the module docstring)."""

    def __init__(self, scenario, move_time=2.0, fails=None):
        super().__init__(scenario)
        self.t = 0.0
        self.move_time = float(move_time)
        self.fails = fails                # callable(move) -> bool, or None
        self.place = rtamp.initial_placement(scenario).locations()
        self.move = None                  # the running move
        self.end = math.inf               # when it ends
        self.status = rtamp.MoveStatus.IDLE
        self.why = ""
        self.last_hand = ""
        self.events = []
        self.calls = 0                    # callbacks from C++ (for tests)

    # --- rtamp.World
    def time(self):
        """World time (s)."""
        return self.t

    def next_event_time(self):
        """When the running move ends (inf: nothing running)."""
        return self.end

    def advance(self, dt):
        """Moves time on by dt, finishing the running move on the way."""
        self.calls += 1
        target = self.t + dt
        if self.move is not None and self.end <= target + 1e-9:
            self.t = max(self.t, self.end)
            self._finish()
        self.t = max(self.t, target)

    def observe(self):
        """Where every thing is: {thing: location} ("hand" while held)."""
        self.calls += 1
        return self.place

    def start(self, move):
        """Starts a move: its thing goes into the hand until move_time has passed."""
        self.calls += 1
        if self.place.get(move.thing) is None:
            self.status, self.why = rtamp.MoveStatus.FAILED, "unknown thing"
            return
        self.move = move
        self.source = self.place[move.thing]
        self.place = dict(self.place)
        self.place[move.thing] = "hand"
        self.end = self.t + self.move_time
        self.status = rtamp.MoveStatus.RUNNING

    def poll(self):
        """The running move's (status, reason)."""
        self.calls += 1
        return self.status, self.why

    def halt(self):
        """Stops the running move and puts its thing back where it came from."""
        self.calls += 1
        if self.move is not None:
            self.place = dict(self.place)
            self.place[self.move.thing] = self.source
            self.move, self.end = None, math.inf
            self.status, self.why = rtamp.MoveStatus.FAILED, "halted"

    def busy(self):
        """Never busy outside a move (no settling, no person in the way)."""
        return False

    def hand(self):
        """Where the hand last put something ("" before the first move)."""
        return self.last_hand

    def take_events(self):
        """The interventions applied since the last call (and forgets them)."""
        out, self.events = self.events, []
        return out

    # --- the intervention capability (rtamp.Person drives it through rtamp.PersonWorld)
    def true_placement(self):
        """Where every thing truly is."""
        return self.place

    def apply(self, intervention):
        """Carries out a person's relocation now; other kinds are refused."""
        if intervention.kind != "relocate" or not intervention.location:
            ev = rtamp.WorldEvent(self.t, intervention, False, "the toy world only relocates to a named location")
            self.events.append(ev)
            return ev
        return self._relocate(intervention.subject, intervention.location)

    # --- the toy's own model
    def _finish(self):
        m = self.move
        self.move, self.end = None, math.inf
        self.place = dict(self.place)
        if self.fails is not None and self.fails(m):
            self.place[m.thing] = self.source
            self.status, self.why = rtamp.MoveStatus.FAILED, "grasp slipped"
            return
        self.place[m.thing] = m.to
        self.last_hand = m.to
        self.status, self.why = rtamp.MoveStatus.SUCCEEDED, ""

    def _relocate(self, thing, loc):
        iv = rtamp.Intervention("relocate", thing, loc, time=self.t)
        if thing not in self.place:
            ev = rtamp.WorldEvent(self.t, iv, False, "no such thing")
            self.events.append(ev)
            return ev
        self.place = dict(self.place)
        if self.move is not None and self.move.thing == thing:
            self.move, self.end = None, math.inf
            self.status, self.why = rtamp.MoveStatus.FAILED, "thing taken"
        self.place[thing] = loc
        ev = rtamp.WorldEvent(self.t, iv, True, loc)
        self.events.append(ev)
        return ev
