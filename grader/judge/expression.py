"""The ``expression`` kind: equal for every admissible value of the symbols.

Contents:
    check_expression(expected, answer, deadline)   the kind's checker
    same_values(expected, e, s, deadline)           the numeric test other kinds reuse

Numbers first: both sides at ten seeded points inside the symbols' domains; a near
miss is redone at 40 digits; too few defined points fall back to ``simplify``
with the domains as assumptions. Then, when not equal, the diagnosis: sign,
constant factor, small-angle form, and which term differs.
"""

from __future__ import annotations

from collections.abc import Callable

import sympy

from grader.judge.deadline import Deadline
from grader.judge.diagnose import has_angle_functions, small_angle, symbolic_zero, term_changes, terms
from grader.judge.expected import Expected, Outcome
from grader.judge.numeric import Closeness
from grader.judge.sampling import (
    GROUP,
    POINTS,
    Pair,
    all_equal,
    constant_difference,
    constant_ratio,
    evaluate_pairs,
    nice_number,
)
from grader.parse import ParsedAnswer

__all__ = ["check_expression", "diagnose_difference", "expected_terms", "same_values", "term_outcome"]


def same_values(expected: Expected, e, s, deadline: Deadline, *, key: str = "value") -> tuple[bool | None, list[Pair]]:
    """Whether ``s`` equals ``e`` everywhere (None: cannot tell), and the evaluated pairs.

    ``key`` names ``e`` among the expressions derived from the expected answer, for the cache.
    """
    points = expected.points(POINTS, group=GROUP)
    expected_c, submitted_c = expected.compiled(key, e), expected.compile(s)
    if expected_c.constant and submitted_c.constant:
        # A constant: floats cannot tell 99999998/99999999 from 0.99999999; 40 digits can.
        pairs = evaluate_pairs(expected_c, submitted_c, points[:1], deadline, precise=True)
        return (pairs[0].closeness() is Closeness.EQUAL if pairs else None), pairs
    pairs = evaluate_pairs(expected_c, submitted_c, points, deadline)
    for salt, count in ((3, 4 * POINTS), (4, 20 * POINTS)):
        if all_equal(pairs) is not None:
            break
        # Many points lie outside the reference's domain (√(g/R − ω²) needs ω² < g/R): draw more.
        more = expected.points(count, salt=salt, group=GROUP)
        pairs += evaluate_pairs(expected_c, submitted_c, more, deadline)
    return all_equal(pairs), pairs


def check_expression(expected: Expected, answer: ParsedAnswer, deadline: Deadline) -> Outcome:
    equal, pairs = same_values(expected, expected.value, answer.value, deadline)
    if equal:
        return Outcome("equivalent", 1.0, "equivalent")
    if expected.option("up_to_constant") and constant_difference(pairs):
        return Outcome("equivalent", 1.0, "equivalent_up_to_constant")
    submitted = expected.setting.plain(answer.value)
    if equal is None:
        deadline.check()
        if symbolic_zero(submitted - expected.value, expected.setting):
            return Outcome("equivalent", 1.0, "equivalent", method="symbolic")
        return Outcome("undecided", 0.0, "undecided", method="numeric: too few defined points")
    return diagnose_difference(expected, expected.value, submitted, pairs, deadline)


def diagnose_difference(
    expected: Expected,
    e,
    s,
    pairs: list[Pair],
    deadline: Deadline,
    *,
    key: str = "value",
    approximations: Callable[[sympy.Expr], list] | None = None,
    expanded: bool = False,
) -> Outcome:
    """A not-equivalent outcome for ``s`` against ``e``, naming the mistake where it can.

    ``key`` names ``e`` among the expressions derived from the expected answer;
    ``approximations`` gives the small-angle forms of an expression (by default
    sin u → u, cos u → 1 or 1 − u²/2); ``expanded`` says ``s`` is already expanded.
    """
    approximate = approximations or (lambda expr: small_angle(expr, expected.setting))
    ratio = constant_ratio(pairs)
    if ratio is not None:
        if abs(ratio + 1) < 1e-9:
            return Outcome("not_equivalent", 0.0, "sign")
        factor = nice_number(1 / ratio)
        if factor:
            return Outcome("not_equivalent", 0.0, "factor", {"factor": factor})
    deadline.check()
    cache_key = ("approximations", key)
    if cache_key not in expected.cache:
        expected.cache[cache_key] = approximate(e)
    for number, form in enumerate(expected.cache[cache_key]):
        if form.has(sympy.nan, sympy.zoo, sympy.oo, -sympy.oo):
            continue  # the approximation does not exist here (a Taylor expansion through a pole)
        if same_values(expected, form, s, deadline, key=f"{key}, small angle {number}")[0]:
            return Outcome("not_equivalent", 0.0, "small_angle")
    # Only an expected answer without trigonometry can be a small-angle form the student did not use.
    if not has_angle_functions(e, expected.setting) and has_angle_functions(s, expected.setting):
        for form in approximate(s):
            if not form.has(sympy.nan, sympy.zoo) and same_values(expected, e, form, deadline, key=key)[0]:
                return Outcome("not_equivalent", 0.0, "not_small_angle")
    deadline.check()
    # where a constant is allowed, do not point at one
    varying = set(expected.setting.state.values()) if expected.option("up_to_constant") else None
    submitted_terms = terms(s, varying=varying, expanded=expanded)
    return term_outcome(term_changes(expected_terms(expected, key, e, varying), submitted_terms, expected.setting))


def expected_terms(expected: Expected, key: str, e, varying: set | None = None) -> dict:
    """The terms of ``e`` (named ``key`` among the expected answer's expressions), as
    :func:`~grader.judge.diagnose.terms` gives them, expanded once for every submission."""
    cache_key = ("terms", key, varying is not None)
    if cache_key not in expected.cache:
        expected.cache[cache_key] = terms(e, varying=varying)
    return expected.cache[cache_key]


def term_outcome(changes: list[tuple[str, str]]) -> Outcome:
    """Not equivalent, naming the differing terms when there are one or two (more says nothing)."""
    if len(changes) == 2 and {key for key, _ in changes} == {"missing_term", "extra_term"}:
        (_, first), (_, second) = changes
        if first == second:  # sin²θ written sin θ: one term changed, not one lost and one gained
            return Outcome("not_equivalent", 0.0, "term_differs", {"description": f"{first} is not right"})
    if not 1 <= len(changes) <= 2:
        return Outcome("not_equivalent", 0.0, "wrong")
    (key, description), *rest = changes
    more = tuple((other, {"description": text}) for other, text in rest)
    return Outcome("not_equivalent", 0.0, key, {"description": description}, more=more)
