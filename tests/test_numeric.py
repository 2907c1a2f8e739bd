"""The numeric evaluator: many points at once, derivatives, and undefined points.

Each test compares two independent routes to the same number: the numpy batch
with the scalar closures, forward-mode derivatives with sympy's ``diff``, and the
Lagrangian's numeric equations of motion with the symbolic Euler–Lagrange ones.
"""

from __future__ import annotations

import cmath
import dataclasses

import mpmath
import numpy as np
import pytest
import sympy

from grader.judge.expected import prepare
from grader.judge.lagrangian import _dynamics, _symbolic_dynamics
from grader.judge.numeric import UNDEFINED, Compiled, LostTerm, sample_points
from grader.judge.sampling import Pair, constant_difference, constant_ratio

x, y, z = sympy.symbols("x y z", real=True)
VARIABLES = (x, y, z)

EXPRESSIONS = [
    x**2 * y - 3 * z + sympy.Rational(1, 7),
    sympy.sin(x) * sympy.cos(y) + sympy.tan(z) - sympy.cot(x * y),
    sympy.sec(x) + sympy.csc(y + 1),
    sympy.asin(x / 4) + sympy.acos(y / 5) + sympy.atan(z),
    sympy.sinh(x) * sympy.cosh(y) / (1 + sympy.tanh(z) ** 2),
    sympy.coth(x) + sympy.sech(y) * sympy.csch(z),
    sympy.asinh(x) * sympy.atanh(y / 4) + sympy.acosh(z**2 + 2),
    sympy.exp(-x * y) * sympy.log(z**2 + 1),
    sympy.sqrt(x**2 + y**2 + z**2) ** 3 - x ** sympy.Rational(2, 3),
    sympy.Abs(x - y) * z + y**z,
    sympy.pi * x + sympy.E ** (y / 3) + sympy.sqrt(2) * z,
    1 / (x**2 + 1) ** 4 - (y - z) ** -2,
    x * sympy.sin(x * sympy.cos(y * sympy.exp(z))),
]


def _points(count: int = 12, seed: int = 7) -> np.ndarray:
    domains = dict.fromkeys(VARIABLES, "real")
    return np.array(sample_points(VARIABLES, domains, count, seed), complex)


@pytest.mark.parametrize("expr", EXPRESSIONS, ids=str)
def test_a_batch_agrees_with_point_by_point_evaluation(expr):
    compiled, points = Compiled(expr, VARIABLES), _points()
    values, scales = compiled.many(points)
    for point, value, scale in zip(points.tolist(), values.tolist(), scales.tolist(), strict=True):
        try:
            expected, expected_scale = compiled(point)
        except UNDEFINED:
            assert cmath.isnan(value)
            continue
        assert abs(value - expected) <= 1e-13 * expected_scale
        assert scale == pytest.approx(expected_scale, rel=1e-12)


def test_only_the_undefined_point_of_a_batch_is_undefined():
    points = _points(6)
    singular = points.copy()
    singular[2, 0] = singular[2, 1]  # x = y there: 1/(x − y) divides by zero
    values, scales = Compiled(1 / (x - y) + z, VARIABLES).many(singular)
    assert [cmath.isnan(value) for value in values.tolist()] == [False, False, True, False, False, False]
    assert np.isnan(scales[2]) and np.isfinite(np.delete(scales, 2)).all()


def test_an_overflow_is_undefined_not_infinite():
    huge = np.array([[800 + 0j, 1 + 0j, 1 + 0j], [1 + 0j, 1 + 0j, 1 + 0j]])
    values, _ = Compiled(sympy.exp(x) * y - sympy.exp(x) * z + sympy.exp(x**2), VARIABLES).many(huge)
    assert cmath.isnan(values[0]) and cmath.isfinite(values[1])


def test_a_term_too_small_for_its_sum_is_noted_as_lost():
    points = np.array([[1 + 0j, 2 + 0j, 0.5 + 0j], [40 + 0j, 2 + 0j, 0.5 + 0j]])
    # beside e^40 ≈ 2·10¹⁷, y = 2 is below a float's 10⁻¹³ of the sum; beside e^1 it is not
    assert Compiled(sympy.exp(x) + y, VARIABLES).lost(points).tolist() == [False, True]
    # a sum of like terms loses nothing, nor does one with a zero term (not a small one)
    assert not Compiled(x**2 * y - 3 * z + 1, VARIABLES).lost(points).any()
    assert not Compiled(x * (y - 2) + z, VARIABLES).lost(points).any()


def test_a_number_with_more_digits_than_a_float_is_noted_as_lost():
    points = _points(3)
    third = sympy.Rational(333333333333333333, 10**18)  # 0.333333333333333333: 18 digits
    assert Compiled(third * sympy.sin(x), VARIABLES).lost(points).all()
    assert not Compiled(sympy.sin(x) / 3, VARIABLES).lost(points).any()
    point = points[0].tolist()  # 40 digits hold it
    value, _ = Compiled(third * sympy.sin(x), VARIABLES).precise(point)
    exact = third * sympy.sin(sympy.Rational(point[0].real))
    assert abs(value - exact.evalf(40)) < 1e-35


def test_at_40_digits_a_lost_term_leaves_the_point_undefined():
    point = [200 + 0j, 2 + 0j, 0.5 + 0j]  # e^200 ≈ 10⁸⁷: y is beyond 40 digits too
    with pytest.raises(LostTerm):
        Compiled(sympy.exp(x) + y, VARIABLES).precise(point)
    value, _ = Compiled(sympy.exp(x) + y, VARIABLES).precise([40 + 0j, 2 + 0j, 0.5 + 0j])
    with mpmath.workdps(40):
        assert abs(value - (mpmath.exp(40) + 2)) < 1e-20  # y is there


def test_readings_of_40_digit_pairs_use_40_digits_tolerance():
    with mpmath.workdps(40):
        big = mpmath.mpf(10) ** 15
        # submitted = 2·expected but for a term of 1 in 10¹⁵: equal to floats, not to 40 digits
        pairs = [Pair(big + k, 2 * (big + k) + (k % 2), 2 * big, precise=True, group=k // 5) for k in range(10)]
        assert constant_ratio(pairs) is None
        assert constant_ratio([dataclasses.replace(pair, precise=False) for pair in pairs]) is not None
        # submitted − expected varies by 1 in 10¹⁵ along the motion: no constant
        pairs = [Pair(big + k, big + 2 * k, big, precise=True, group=k // 5) for k in range(10)]
        assert not constant_difference(pairs)
        # in floats the expected answer's change (1 in 10¹⁵) is below resolution: they cannot tell
        assert constant_difference([dataclasses.replace(pair, precise=False) for pair in pairs]) is None


def test_noting_losses_does_not_change_values():
    points = _points()
    for expr in EXPRESSIONS:
        compiled = Compiled(expr, VARIABLES)
        before = compiled.many(points)
        compiled.lost(points)
        after = Compiled(expr, VARIABLES).many(points)
        assert np.array_equal(before[0], after[0], equal_nan=True), expr


@pytest.mark.parametrize("expr", EXPRESSIONS, ids=str)
def test_forward_mode_derivatives_agree_with_sympy(expr):
    points = _points()
    domains = dict.fromkeys(VARIABLES, "real")
    u, w = (np.array(sample_points(VARIABLES, domains, len(points), seed), complex) for seed in (98, 99))
    slopes, mixed, scales = Compiled(expr, VARIABLES).derivatives(points, u, w)

    def at_points(e):  # |x|'' is a Dirac delta, zero away from the kink where the points lie
        return Compiled(e.replace(sympy.DiracDelta, lambda *_: 0), VARIABLES).many(points)[0]

    n = len(VARIABLES)
    slope = sum(u[:, i] * at_points(sympy.diff(expr, VARIABLES[i])) for i in range(n))
    second = sum(
        u[:, i] * w[:, j] * at_points(sympy.diff(expr, VARIABLES[i], VARIABLES[j])) for i in range(n) for j in range(n)
    )
    for ours, theirs in ((slopes, slope), (mixed, second)):
        defined = np.isfinite(theirs) & np.isfinite(ours)
        assert defined.sum() >= len(points) // 2
        assert np.all(np.abs(ours - theirs)[defined] <= 1e-11 * np.maximum(scales[defined], 1.0))


LAGRANGIANS = [
    ("double pendulum", "1/2 (m1+m2) l1^2 theta1'^2 + 1/2 m2 l2^2 theta2'^2"
     " + m2 l1 l2 theta1' theta2' cos(theta1-theta2) + (m1+m2) g l1 cos(theta1) + m2 g l2 cos(theta2)",
     ("theta1", "theta2"), ("m1", "m2", "l1", "l2", "g")),
    ("spherical pendulum", "1/2 m l^2 (theta'^2 + sin(theta)^2 phi'^2) + m g l cos(theta)", ("theta", "phi"),
     ("m", "l", "g")),
    ("driven hoop", "1/2 m R^2 (theta'^2 + w^2 sin(theta)^2) + m g R cos(theta) + t x^2", ("theta",),
     ("m", "R", "g", "w", "x")),
    ("damped, time-dependent", "exp(k t) (1/2 m x'^2 - 1/2 c x^2) + sqrt(x'^2 + 1)"
     " + x^4 log(t^2 + 2) / (x'^2 + 3)", ("x",),
     ("m", "c", "k")),
]  # fmt: skip


@pytest.mark.parametrize(("name", "lagrangian", "coords", "known"), LAGRANGIANS, ids=[row[0] for row in LAGRANGIANS])
def test_numeric_equations_of_motion_agree_with_euler_lagrange(name, lagrangian, coords, known):
    expected = prepare(lagrangian, "lagrangian", coords, known, (), (("factor_credit", 0.5),))
    numeric, lost = _dynamics(expected, expected.value)
    assert not lost, name  # ordinary Lagrangians never need the 40-digit path
    symbolic = _symbolic_dynamics(expected, expected.value)
    for by_numbers, by_symbols in zip(numeric, symbolic, strict=True):
        for (a, scale, _, _), (b, _, _, _) in zip(by_numbers, by_symbols, strict=True):
            assert abs(a - b) <= 1e-12 * scale, name
