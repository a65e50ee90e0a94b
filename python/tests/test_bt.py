"""Behavior-tree bindings: build from specs, tick, halt, change, export; leaves as Python callables."""

import pytest

import rtamp
from rtamp import Status, bt


class Counter:
    """An action that runs for `n` ticks, then succeeds; records starts and halts."""

    def __init__(self, n):
        self.n, self.ticks, self.starts, self.halts = n, 0, 0, 0

    def start(self):
        self.starts += 1
        self.ticks = 1
        return Status.RUNNING if self.n > 1 else Status.SUCCESS

    def running(self):
        self.ticks += 1
        return "SUCCESS" if self.ticks >= self.n else "RUNNING"

    def halted(self):
        self.halts += 1


def test_sequence_of_python_leaves():
    c = Counter(3)
    ok = {"v": True}
    tree = rtamp.Tree(bt.Sequence("main", bt.Condition("ok", lambda: ok["v"]),
                                  bt.Action("work", c.start, c.running, c.halted)))
    assert tree.tick() == Status.RUNNING
    assert tree.tick() == Status.RUNNING
    assert tree.tick() == Status.SUCCESS
    assert c.starts == 1 and c.ticks == 3 and tree.tick_count == 3
    ok["v"] = False
    assert tree.tick() == Status.FAILURE


def test_reactive_sequence_halts_the_running_action():
    c = Counter(10)
    ok = {"v": True}
    tree = rtamp.Tree(bt.ReactiveSequence("r", bt.Condition("ok", lambda: ok["v"]),
                                          bt.Action("work", c.start, c.running, c.halted)))
    assert tree.tick() == Status.RUNNING
    ok["v"] = False
    assert tree.tick() == Status.FAILURE
    assert c.halts == 1
    tree.halt()
    assert tree.status == Status.INVALID


def test_other_nodes():
    assert rtamp.Tree(bt.Fallback("f", bt.Condition("no", lambda: False), bt.Condition("yes", lambda: True))).tick() == Status.SUCCESS
    assert rtamp.Tree(bt.ReactiveFallback("f", bt.Condition("no", lambda: False))).tick() == Status.FAILURE
    assert rtamp.Tree(bt.Inverter("i", bt.Condition("no", lambda: False))).tick() == Status.SUCCESS
    runs = []

    def flaky():
        runs.append(1)
        return Status.SUCCESS if len(runs) >= 3 else Status.FAILURE
    retry = rtamp.Tree(bt.Retry("r", bt.Action("a", flaky), num_attempts=3))
    while retry.tick() == Status.RUNNING:
        pass
    assert retry.status == Status.SUCCESS and len(runs) == 3
    runs.clear()
    once = rtamp.Tree(bt.Retry("r", bt.Action("a", flaky), num_attempts=2))
    while once.tick() == Status.RUNNING:
        pass
    assert once.status == Status.FAILURE and len(runs) == 2
    par = rtamp.Tree(bt.Parallel("p", bt.Condition("y", lambda: True), bt.Action("r", lambda: Status.RUNNING),
                                 success_count=1))
    assert par.tick() == Status.SUCCESS
    ch = rtamp.Tree(bt.Chooser("c", bt.Condition("no", lambda: False), bt.Action("a", lambda: Status.SUCCESS)))
    assert ch.tick() == Status.SUCCESS


def test_timeout_with_a_manual_clock():
    tree = rtamp.Tree(bt.Timeout("t", bt.Action("forever", lambda: Status.RUNNING), seconds=2.0), clock="manual")
    assert tree.tick() == Status.RUNNING
    tree.advance_clock(1.0)
    assert tree.tick() == Status.RUNNING
    tree.advance_clock(1.5)
    assert tree.tick() == Status.FAILURE
    with pytest.raises(rtamp.Error):
        rtamp.Tree(bt.Condition("x", lambda: True)).advance_clock(1)


def test_changes_between_ticks_keep_the_running_action():
    a, b = Counter(5), Counter(1)
    tree = rtamp.Tree(bt.Sequence("main", bt.Action("a", a.start, a.running, a.halted)))
    root = tree.root
    assert tree.tick() == Status.RUNNING
    changes = []
    tree.on_change(lambda kind, node, prev, parent, pos: changes.append((kind, parent, pos)))
    bid = tree.insert(root, 1, bt.Action("b", b.start))
    assert tree.node(bid)["name"] == "b" and tree.node(root)["children"][1] == bid
    assert tree.tick() == Status.RUNNING and a.starts == 1  # the running action was not restarted
    new = tree.replace(bid, bt.Condition("c", lambda: True))
    tree.remove(new)
    cid = tree.append(root, bt.Condition("d", lambda: True))
    assert [k for k, _, _ in changes] == ["insert", "replace", "remove", "insert"]
    assert len(tree) == 3 and tree.find("d") == cid and tree.find("zzz") is None
    assert tree.change_count == 5  # set_root counts too
    while tree.tick() == Status.RUNNING:
        pass
    assert tree.status == Status.SUCCESS and a.starts == 1


def test_non_interruptible_nodes_refuse_a_cut():
    tree = rtamp.Tree(bt.Sequence("main", bt.Action("arm", lambda: Status.RUNNING, interruptible=False)))
    tree.tick()
    arm = tree.find("arm")
    assert not tree.can_cut(arm)
    with pytest.raises(rtamp.Error):
        tree.remove(arm)
    tree.remove(arm, force=True)
    assert len(tree) == 1


def test_status_observer_and_nodes():
    seen = []
    tree = rtamp.Tree(bt.Sequence("s", bt.Condition("c", lambda: True)))
    tree.on_status(lambda i, name, prev, cur: seen.append((name, prev, cur)))
    tree.tick()
    assert ("c", Status.INVALID, Status.SUCCESS) in seen
    nodes = tree.nodes()
    assert [n["name"] for n in nodes] == ["s", "c"] and nodes[0]["kind"] == "Control"
    assert nodes[1]["parent"] == nodes[0]["id"]


def test_export():
    tree = rtamp.Tree(bt.Sequence("s", bt.Condition("holds", lambda: True, type_id="InRegion", ports={"object": "o1"})))
    tree.set_port(tree.find("holds"), "region", "r2")
    xml = tree.to_xml()
    assert "<root" in xml and 'BTCPP_format="4"' in xml and "InRegion" in xml and 'region="r2"' in xml
    assert tree.to_dot().startswith("digraph")
    tree.tick()
    text = tree.to_text()
    assert "[o]" in text and "holds" in text


def test_python_errors_in_leaves_propagate():
    def boom():
        raise KeyError("no such sensor")
    tree = rtamp.Tree(bt.Sequence("s", bt.Action("a", boom)))
    with pytest.raises(KeyError):
        tree.tick()
    with pytest.raises(rtamp.Error):
        rtamp.Tree(bt.Action("a", lambda: 42)).tick()
    with pytest.raises(rtamp.Error):
        rtamp.Tree(bt.Inverter("i"))
    with pytest.raises(rtamp.Error):
        rtamp.Tree(bt.Condition("c", lambda: True)).set_root(bt.Spec("x"))


def _leaves():
    """Fresh, deterministic leaves for one tree: what they do depends only on their own ticks."""
    state = {"ticks": 0, "moves": []}

    def ready():
        state["ticks"] += 1
        return state["ticks"] % 5 != 0

    def done():
        return bool(state["moves"]) and all(c.ticks >= c.n for c in state["moves"])

    def make_move(name, ports):
        c = Counter(int(ports.get("steps", "2")))
        state["moves"].append(c)
        return bt.Action(name, c.start, c.running, c.halted, type_id="Move")

    return state, ready, done, make_move


def _tree_spec(ready, done, make_move):
    return bt.ReactiveSequence(
        "main",
        bt.Condition("ready", ready, type_id="Ready"),
        bt.Fallback(
            "until done",
            bt.Condition("done", done, type_id="Done"),
            bt.Retry("retry", bt.Sequence("moves", make_move("m1", {"steps": "2"}), make_move("m2", {"steps": "3"})),
                     num_attempts=3),
        ),
        bt.Parallel("both", bt.Condition("again", done, type_id="Done"), bt.Inverter("not", bt.Condition(
            "busy", lambda: False, type_id="Busy")), success_count=2),
        bt.Timeout("limit", bt.Action("finish", lambda: Status.SUCCESS, type_id="Finish"), seconds=5.0),
    )


def test_xml_round_trip_ticks_the_same():
    state_a, ready_a, done_a, move_a = _leaves()
    a = rtamp.Tree(_tree_spec(ready_a, done_a, move_a), clock="manual")
    a.set_port(a.find("m1"), "steps", "2")
    a.set_port(a.find("m2"), "steps", "3")
    xml = a.to_xml()

    state_b, ready_b, done_b, move_b = _leaves()
    b = rtamp.Tree.from_xml(xml, nodes={"Move": move_b}, conditions={"Ready": ready_b, "Done": done_b,
                                                                    "Busy": lambda: False},
                            actions={"Finish": lambda: "SUCCESS"}, clock="manual")
    assert len(b) == len(a)
    assert [(n["name"], n["kind"], n["type_id"]) for n in b.nodes()] == \
        [(n["name"], n["kind"], n["type_id"]) for n in a.nodes()]
    assert b.to_xml() == xml
    for _ in range(12):
        assert a.tick() == b.tick()
        assert a.to_text(ids=False) == b.to_text(ids=False)
    assert state_a["ticks"] == state_b["ticks"] == 12
    assert [(c.starts, c.ticks) for c in state_a["moves"]] == [(c.starts, c.ticks) for c in state_b["moves"]]
    assert sum(c.starts for c in state_b["moves"]) > 0


def test_xml_import_errors_are_located(tmp_path):
    bad = '<root BTCPP_format="4">\n  <BehaviorTree ID="T">\n    <Sequence>\n      <Wave name="w"/>\n' \
          '    </Sequence>\n  </BehaviorTree>\n</root>\n'
    with pytest.raises(rtamp.Error) as e:
        rtamp.Tree.from_xml(bad, file="wave.xml")
    assert e.value.file == "wave.xml" and e.value.line == 4 and e.value.column is not None
    assert "Wave" in e.value.message
    # Known once registered.
    t = rtamp.Tree.from_xml(bad, actions={"Wave": lambda: Status.SUCCESS})
    assert t.tick() == Status.SUCCESS
    # Malformed XML, from a file: the error names the file.
    path = tmp_path / "broken.xml"
    path.write_text('<root BTCPP_format="4">\n  <BehaviorTree ID="T">\n    <Sequence>\n  </BehaviorTree>\n')
    with pytest.raises(rtamp.Error) as e:
        rtamp.Tree.load_xml(str(path))
    assert e.value.file == str(path) and e.value.line is not None
    # A factory must not bring children of its own: they come from the file.
    with pytest.raises(rtamp.Error):
        rtamp.Tree.from_xml(bad, nodes={"Wave": lambda name, ports: bt.Sequence(name, bt.Condition("c", bool))})
    # A Python exception in a factory propagates as itself.
    def boom(name, ports):
        raise KeyError(name)
    with pytest.raises(KeyError):
        rtamp.Tree.from_xml(bad, nodes={"Wave": boom})
    # The empty tree.
    assert rtamp.Tree.from_xml(rtamp.Tree().to_xml()).root is None


def test_the_docs_replace_then_remove_example_works_as_written():
    # docs/python.md "Behavior trees": replace returns the new id, which remove then takes.
    tree = rtamp.Tree(bt.Sequence("main", bt.Condition("ready", lambda: True),
                                  bt.Action("work", lambda: "RUNNING")))
    leaf = tree.find("work")
    skip = tree.replace(leaf, bt.Condition("skip", lambda: True))
    assert tree.find("work") is None and tree.find("skip") == skip
    tree.remove(skip, force=False)
    assert tree.find("skip") is None
    assert tree.tick() == rtamp.Status.SUCCESS


def test_a_tree_built_in_python_reads_back_from_its_own_xml():
    # Leaves without a type_id are exported as UserAction / UserCondition and found again by name.
    ticks = []
    tree = rtamp.Tree(bt.Sequence("main", bt.Condition("ready", lambda: True),
                                  bt.Action("work", lambda: ticks.append("old") or "SUCCESS")))
    xml = tree.to_xml()
    again = rtamp.Tree.from_xml(xml, conditions={"ready": lambda: True},
                                actions={"work": lambda: ticks.append("new") or "SUCCESS"})
    assert again.to_xml() == xml  # the same tree, node for node
    assert again.tick() == Status.SUCCESS and ticks == ["new"]
    with pytest.raises(rtamp.Error, match=r"no callable for UserAction 'work': pass actions=\{'work': \.\.\.\}") as e:
        rtamp.Tree.from_xml(xml, conditions={"ready": lambda: True})
    assert e.value.line is not None
