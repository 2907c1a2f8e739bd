"""Naming a wrong answer's terms: ``expand_terms`` against ``sympy.expand``, whose work it does."""

from __future__ import annotations

import pytest
import sympy
from hypothesis import HealthCheck, assume, example, given, settings
from hypothesis import strategies as st

from grader.judge.diagnose import EXPANSION_LIMIT, expand_terms, in_sines_and_cosines, term_changes, terms
from grader.judge.numeric import UNDEFINED, Compiled, NotCompilable
from grader.judge.setting import Setting

a, b, m, l, g = sympy.symbols("a b m l g", positive=True)
theta, omega = sympy.symbols("theta theta__1", real=True)

_ATOMS = st.sampled_from([a, b, m, l, g, theta, omega, sympy.Integer(2), sympy.Integer(-3), sympy.Rational(1, 2)])


def _mechanics(children, exponentials=False):
    """Sums, products, integer powers, sines and cosines: what Lagrangians and equations of motion hold."""
    return st.one_of(
        st.lists(children, min_size=2, max_size=3).map(lambda args: sympy.Add(*args)),
        st.lists(children, min_size=2, max_size=3).map(lambda args: sympy.Mul(*args)),
        st.tuples(children, st.sampled_from([2, 3, -1, -2])).map(lambda p: sympy.Pow(*p)),
        children.map(sympy.sin),
        children.map(sympy.cos),
        *([children.map(sympy.exp)] if exponentials else []),
    )


EXPRESSIONS = st.recursive(_ATOMS, _mechanics, max_leaves=12)
# sympy's fraction moves e^(−a) below a sum (e^(−a)/(a + b) is 1/(a e^a + b e^a)); we leave it
WITH_EXPONENTIALS = st.recursive(_ATOMS, lambda children: _mechanics(children, exponentials=True), max_leaves=12)


def _sympy_terms(expr) -> dict:
    """The terms as ``sympy.expand`` names them: what ``expand_terms`` replaced."""
    collected: dict = {}
    for term in sympy.Add.make_args(sympy.expand(expr)):
        coefficient, shape = term.as_coeff_Mul()
        collected[shape] = collected.get(shape, 0) + coefficient
    return {shape: c for shape, c in collected.items() if c != 0}


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(EXPRESSIONS)
def test_expand_terms_names_the_terms_sympy_expand_names(expr):
    if expr.has(sympy.zoo, sympy.nan):
        return
    found = expand_terms(expr)
    if found is None:  # too many terms: then sympy's expansion has more than the limit too
        assert len(sympy.Add.make_args(sympy.expand(expr))) > EXPANSION_LIMIT // 4
        return
    assert found == _sympy_terms(expr)


@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(WITH_EXPONENTIALS, st.sampled_from([sympy.log, sympy.sqrt]))
@example(sympy.cos(sympy.exp(sympy.exp(a + 2 * m))), sympy.log)  # found by a fresh clone: see the cos guard
def test_expand_terms_sums_to_the_expression_where_its_names_differ_from_sympys(expr, function):
    # logarithms and roots of sums are left whole, where sympy splits some: the terms still add up
    expr = function(expr) * (a + b) + expr
    found = expand_terms(expr)
    if found is None or expr.has(sympy.zoo, sympy.nan):
        return
    assert all(c.is_Rational for c in found.values())
    # at 40 digits by our evaluator (sin(e^(e^(a + 2))) is too sensitive for floats), not sympy's
    # evalf, which on e^(e^(e^m)) asks for ever more precision
    variables, point = (a, b, m, l, g, theta, omega), [0.7, 1.3, 2.1, 0.9, 9.8, 0.4, -1.1]
    try:
        compiled, total = Compiled(expr, variables), Compiled(sum(c * s for s, c in found.items()), variables)
        _, size = compiled.at(point)  # in floats first: 40 digits of e^(e^(e^m)) would take for ever
        assume(size < 1e100)
        # cos(e^(e^(a + 2m))) is cos(10⁵⁸) here: 40 digits do not reach the units of its argument
        arguments = [Compiled(f.args[0], variables).at(point)[0] for f in expr.atoms(sympy.sin, sympy.cos)]
        assume(all(abs(argument) < 1e20 for argument in arguments))
        value, scale = compiled.precise(point)
        summed, _ = total.precise(point)
    except (*UNDEFINED, NotCompilable):
        assume(False)
    assert abs(complex(summed) - complex(value)) <= 1e-15 * max(1.0, scale)


@pytest.mark.parametrize(
    ("expr", "expected"),
    [
        ((a + b) ** 2, {a**2: 1, a * b: 2, b**2: 1}),
        (sympy.sin(2 * (theta + a)), {sympy.sin(2 * theta + 2 * a): 1}),  # inside functions too
        (m / (l * (a + b)), {m / (a * l + b * l): 1}),  # one denominator, multiplied out, as sympy's fraction does
        (1 / (a + b) ** 2, {1 / (a**2 + 2 * a * b + b**2): 1}),
        (sympy.exp(a + 2 * b), {sympy.exp(a) * sympy.exp(2 * b): 1}),  # e^(a + b) is e^a·e^b
        (sympy.sqrt(2) * sympy.sqrt(2) * a, {a: 2}),  # a product of shapes may be a number
        ((a + b) * (a - b), {a**2: 1, b**2: -1}),  # terms that cancel are gone
        (m * l**2 * omega**2 / 2, {m * l**2 * omega**2: sympy.Rational(1, 2)}),  # nothing to do: the very term
    ],
)
def test_expand_terms_examples(expr, expected):
    assert expand_terms(expr) == expected


def test_too_many_terms_are_not_named():
    many = sum(sympy.symbols("x:5")) ** 8  # 495 terms
    assert expand_terms(many) is None
    assert terms(many) is None
    setting = Setting.build(["theta"], ["m", "l", "g"])
    assert term_changes({m: 1}, terms(many), setting) == []  # nothing said, rather than 495 "extra terms"
    assert term_changes(terms(many), {m: 1}, setting) == []


_X, _Y = sympy.symbols("x y", real=True)


@pytest.mark.parametrize(
    ("expr", "form"),
    [
        (sympy.sin(2 * _X), 2 * sympy.sin(_X) * sympy.cos(_X)),
        (sympy.sin(2 * _X - 2 * _Y), 2 * sympy.sin(_X - _Y) * sympy.cos(_X - _Y)),
        (sympy.cot(_X), sympy.cos(_X) / sympy.sin(_X)),
        # no double angle: left as written
        (sympy.sin(_X / 2), sympy.sin(_X / 2)),
        (sympy.sin(2 * _X / 3), sympy.sin(2 * _X / 3)),
        (sympy.sin(3 * _X), sympy.sin(3 * _X)),
        (sympy.cos(2 * _X), sympy.cos(2 * _X)),  # a sum in any other form: not one term
    ],
)
def test_a_term_is_put_in_one_form_of_its_trigonometry(expr, form):
    assert in_sines_and_cosines(expr) == form
