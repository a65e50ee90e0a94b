"""LTL bindings: parse, print, simplify, NNF, implication, lasso semantics (src/rtamp/ltl)."""

import itertools

import pytest

import rtamp
from rtamp import Formula


def test_parse_print_round_trip():
    for text in ["F G a", "G (a -> F b)", "a U (b R c)", "!(a & b) | X c", "a W b", "a M b", "a xor b",
                 '"o1 in r2" & F x']:
        f = rtamp.parse(text)
        assert rtamp.parse(str(f)) == f
        assert rtamp.to_string(f) == str(f)
        assert rtamp.to_string(text) == str(f)


def test_spin_syntax_and_mixed_input():
    assert rtamp.parse("[] <> a && b") == rtamp.parse("G F a & b")
    spin = rtamp.to_spin("a W b")
    assert "V" in spin and rtamp.parse(spin) == rtamp.parse("b R (a | b)")


def test_constructors_operators_and_identity():
    a, b = Formula.atom("a"), Formula.atom("b")
    assert (a & b) == Formula.And([b, a])
    assert (a | b) == Formula.Or([a, b])
    assert ~~a == a
    assert (a >> b) == Formula.Implies(a, b)
    assert Formula.G(Formula.F(a)) == rtamp.parse("G F a")
    assert Formula.U(a, b) == rtamp.parse("a U b") and Formula.R(a, b) == rtamp.parse("a R b")
    assert Formula.W(a, b) == rtamp.parse("a W b") and Formula.M(a, b) == rtamp.parse("a M b")
    assert Formula.X(a) == rtamp.parse("X a") and Formula.Not(a) == rtamp.parse("!a")
    assert Formula.Equiv(a, b) == rtamp.parse("a <-> b") and Formula.Xor(a, b) == rtamp.parse("a xor b")
    assert Formula.true_() == rtamp.parse("true") and Formula.false_() == rtamp.parse("false")
    assert Formula("F a") == rtamp.parse("F a")
    assert len({rtamp.parse("F a"), rtamp.parse("F a"), rtamp.parse("F b")}) == 2
    f = rtamp.parse("G (a -> F b)")
    assert f.op == "G" and f.children[0].op == "->" and f.atoms() == ["a", "b"]
    assert a.name == "a" and a.op == "atom" and a.size == 1 and a.depth == 1
    assert f.size == 5 and f.depth == 4
    assert rtamp.parse("a & b").is_boolean and rtamp.parse("F a").is_eventual and rtamp.parse("G a").is_universal
    assert repr(a) == "rtamp.Formula('a')"


def test_pickle():
    import pickle
    f = rtamp.parse("G (a -> F b)")
    assert pickle.loads(pickle.dumps(f)) == f


def letters(atoms, n):
    subsets = [set(c) for k in range(len(atoms) + 1) for c in itertools.combinations(atoms, k)]
    return list(itertools.product(subsets, repeat=n))


@pytest.mark.parametrize("text", ["G (a -> F b)", "a U b", "!(a R b)", "F G a | G F b", "(a <-> b) W X a"])
def test_simplify_and_nnf_are_equivalent_on_lassos(text):
    f = rtamp.parse(text)
    s, n = rtamp.simplify(f), rtamp.nnf(f)
    assert rtamp.is_nnf(s) and rtamp.is_nnf(n)
    for prefix in letters(["a", "b"], 1):
        for cycle in letters(["a", "b"], 2):
            expected = rtamp.holds(f, list(prefix), list(cycle))
            assert rtamp.holds(s, list(prefix), list(cycle)) == expected
            assert rtamp.holds(n, list(prefix), list(cycle)) == expected


def test_simplify_shrinks():
    assert rtamp.simplify("F F a | F a") == rtamp.parse("F a")
    assert rtamp.simplify("a U (F b)") == rtamp.parse("F b")


def test_evaluate_and_holds():
    # positions: prefix {} then the cycle {a}, {}: G F a holds everywhere, a only at 1.
    assert rtamp.evaluate("a", [set()], [{"a"}, set()]) == [False, True, False]
    assert rtamp.evaluate("G F a", [set()], [{"a"}, set()]) == [True, True, True]
    assert rtamp.holds("F G a", [set()], [{"a"}])
    assert not rtamp.holds("F G a", [], [{"a"}, set()])
    with pytest.raises(rtamp.Error):
        rtamp.holds("a", [], [])


def test_implies():
    assert rtamp.implies("G a", "F a")
    assert not rtamp.implies("F a", "G a")
