"""Automata bindings: translate; states, edges, acceptance; HOA, DOT, never claims; lasso acceptance."""

import itertools

import pytest

import rtamp


def subsets(atoms):
    return [set(c) for k in range(len(atoms) + 1) for c in itertools.combinations(atoms, k)]


def lassos(atoms, n_prefix, n_cycle):
    for p in itertools.product(subsets(atoms), repeat=n_prefix):
        for c in itertools.product(subsets(atoms), repeat=n_cycle):
            yield list(p), list(c)


@pytest.mark.parametrize("text", ["G F a", "F G a", "a U b", "G (a -> F b)", "G F a & G F b", "(a U b) | G !a"])
@pytest.mark.parametrize("state_based", [True, False])
def test_translate_language_agrees_with_ltl_semantics(text, state_based):
    a = rtamp.translate(text, state_based=state_based)
    assert a.state_based == state_based
    assert a.atoms == sorted(rtamp.parse(text).atoms())
    for prefix, cycle in lassos(a.atoms, 1, 2):
        assert a.accepts(prefix, cycle) == rtamp.holds(text, prefix, cycle), (prefix, cycle)


def test_states_edges_acceptance():
    a = rtamp.translate("G F a")
    assert a.num_states == len(list(a.states)) >= 1
    assert a.num_sets == 1 and a.state_based
    assert any(a.is_accepting(q) for q in a.states)
    assert a.state_accepting == [a.is_accepting(q) for q in a.states]
    n = 0
    for q in a.states:
        for e in a.edges(q):
            assert 0 <= e.dst < a.num_states
            assert not (e.guard.pos & e.guard.neg)
            n += 1
    assert n == a.num_edges == len(a.transitions())
    src, dst, guard, marks = a.transitions()[0]
    assert isinstance(guard, str) and isinstance(marks, int)
    assert a.guard_text(rtamp.Cube()) == "true"
    assert a.letter_atoms(1) == ["a"]
    assert rtamp.Cube(pos=1).matches(1) and not rtamp.Cube(neg=1).matches(1)
    with pytest.raises(IndexError):
        a.edges(a.num_states)


def test_hoa_round_trip_keeps_the_language():
    for text in ["G F a & F b", "a U b"]:
        for sb in (True, False):
            a = rtamp.translate(text, state_based=sb)
            b = rtamp.read_hoa_one(a.to_hoa())
            assert b.atoms == a.atoms and b.num_states == a.num_states and b.state_based == a.state_based
            for prefix, cycle in lassos(a.atoms, 1, 2):
                assert a.accepts(prefix, cycle) == b.accepts(prefix, cycle)
    both = rtamp.read_hoa(rtamp.translate("F a").to_hoa() + rtamp.translate("G a").to_hoa())
    assert len(both) == 2


def test_hoa_file(tmp_path):
    p = tmp_path / "a.hoa"
    p.write_text(rtamp.translate("F a").to_hoa())
    assert rtamp.read_hoa_file(str(p))[0].atoms == ["a"]


def test_hoa_error_location():
    with pytest.raises(rtamp.Error) as e:
        rtamp.read_hoa("HOA: v1\nStates: 1\nAcceptance: 1 Fin(0)\n--BODY--\n--END--\n", "x.hoa")
    assert e.value.file == "x.hoa" and e.value.line == 3


def test_hoa_names_must_be_utf8(tmp_path):
    """A name that is not UTF-8 is refused where it is, not a UnicodeDecodeError in every accessor later."""
    p = tmp_path / "latin1.hoa"
    p.write_bytes(b'HOA: v1\nStates: 1\nStart: 0\nAP: 1 "caf\xe9"\nAcceptance: 0 t\n--BODY--\nState: 0\n[0] 0\n--END--\n')
    with pytest.raises(rtamp.Error, match="not UTF-8") as e:
        rtamp.read_hoa_file(str(p))
    assert (e.value.line, e.value.column) == (4, 7)
    with pytest.raises(rtamp.Error, match="it is a directory"):
        rtamp.read_hoa_file(str(tmp_path))


def test_dot_and_never_claim():
    a = rtamp.translate("G F a")
    dot = a.to_dot()
    assert dot.startswith("digraph") and "doublecircle" in dot
    never = a.to_never_claim()
    assert never.startswith("never")
    b = rtamp.read_never_claim(never)
    for prefix, cycle in lassos(a.atoms, 1, 2):
        assert a.accepts(prefix, cycle) == b.accepts(prefix, cycle)


def test_build_by_hand():
    a = rtamp.Automaton()
    q0 = a.add_state(accepting=False)
    q1 = a.add_state(accepting=True)
    a.add_edge(q0, q0)
    a.add_edge(q0, q1, pos={"a"})
    a.add_edge(q1, q1, pos={"a"}, marks=1)  # state-based: edges carry their source's marks
    a.state_based = True
    assert a.atoms == ["a"] and a.num_edges == 3
    assert a.accepts([set()], [{"a"}]) and not a.accepts([], [set()])
    with pytest.raises(rtamp.Error):
        a.add_edge(q0, q1, pos={"a"}, neg={"a"})


def test_translate_options():
    for c in ("smallest", "gastin-oddoux", "merged"):
        a = rtamp.translate("G (a -> F b)", construction=c, simplify=False, reduce=False, shortcuts=False)
        for prefix, cycle in lassos(a.atoms, 1, 1):
            assert a.accepts(prefix, cycle) == rtamp.holds("G (a -> F b)", prefix, cycle)
    with pytest.raises(rtamp.Error):
        rtamp.translate("F a", construction="magic")
