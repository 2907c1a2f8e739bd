"""The ``expression`` kind: equal for every admissible value of the symbols.

Contents:
    check_expression(expected, answer, deadline)   the kind's checker
    same_values(expected, e, s, deadline)           the numeric test other kinds reuse

Numbers first: both sides at ten seeded points inside the symbols' domains; a near
miss is redone at 40 digits; too few defined points fall back to ``simplify``
with the domains as assumptions. Then, when not equal, the diagnosis: sign,
constant factor, small-angle form, and which term differs. One term missing or
off by a factor is found in the numbers too (the difference is a multiple of that
term); only other mistakes need the submitted answer expanded by sympy.
"""

from __future__ import annotations

import cmath
from collections.abc import Callable

import numpy as np
import sympy
from sympy.core.function import AppliedUndef

from grader.judge.deadline import Deadline
from grader.judge.diagnose import (
    MAX_TERMS,
    TERM_KEYS,
    as_written,
    describe_term,
    has_angle_functions,
    in_sines_and_cosines,
    small_angle,
    state_part,
    symbolic_zero,
    term_changes,
    terms,
    told_apart,
)
from grader.judge.expected import Expected, Outcome
from grader.judge.numeric import FLOAT_EQUAL, UNDEFINED, Closeness
from grader.judge.sampling import (
    GROUP,
    MIN_DEFINED,
    POINTS,
    Pair,
    all_equal,
    constant_difference,
    constant_ratio,
    evaluate_pairs,
    nice_number,
)
from grader.judge.units import DIMENSIONS, Mixed, units_of
from grader.parse import ParsedAnswer
from grader.parse.messages import listed
from grader.parse.names import unicode_name

__all__ = [
    "check_expression",
    "diagnose_difference",
    "expected_terms",
    "same_values",
    "single_term_change",
    "term_outcome",
]


def same_values(expected: Expected, e, s, deadline: Deadline, *, key: str = "value") -> tuple[bool | None, list[Pair]]:
    """Whether ``s`` equals ``e`` everywhere (None: cannot tell), and the evaluated pairs.

    ``key`` names ``e`` among the expressions derived from the expected answer, for the cache.
    """
    points = expected.points(expected.point_count, group=GROUP)
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
    equal = all_equal(pairs)
    if equal:
        if ("signed powers", key) not in expected.cache:
            expected.cache["signed powers", key] = _signed_powers(expected, expected_c)
        exponents = expected.cache["signed powers", key]
        if exponents:  # where e is real only at whole exponents, points no random draw hits
            more = evaluate_pairs(expected_c, submitted_c, _whole_exponent_points(expected, exponents), deadline)
            if any(pair.closeness() is Closeness.DIFFERENT for pair in more):
                return False, pairs + more
    return equal, pairs


# Values for a variable in an exponent, at which a negative base gives a real power: (−2)^(bc)
# is real at b = 2, c = 1/2, and (a^b)^c is |a| there, not a.
_SIMPLE = (2, 1 / 2, 3, 1 / 3, 3 / 2, 2 / 3, 1, -1, -2, -1 / 2, -3, -1 / 3, -3 / 2, -2 / 3)
_PROBES = 40  # points with simple exponents, drawn where a power of a base that may be negative has a variable exponent


def _signed_powers(expected: Expected, compiled) -> frozenset[int]:
    """The positions (in ``expected.variables``) of the variables in the exponent of a power
    whose base may be negative, in a compiled expression: a^(bc), (−1)^n, (n + 1)^(1/(n + 1)).

    Only the expected answer's are asked for. Where it has none, it is real on a set that
    random draws hit, and a submitted answer that differs there is found at them."""
    variables, index = expected.variables, compiled.index
    positions = set()
    for power in compiled.expr.atoms(sympy.Pow):
        exponent = _variables_in(power.exp, index)
        if not exponent:
            continue
        base = power.base
        if base.is_number:
            signed = bool(base.is_negative)
        else:
            signed = any(expected.setting.domain(variables[i]) != "positive" for i in _variables_in(base, index))
        if signed:
            positions |= exponent
    return frozenset(positions)


def _variables_in(expr, index) -> set[int]:
    return {index[atom] for atom in (*expr.free_symbols, *expr.atoms(AppliedUndef, sympy.Derivative)) if atom in index}


def _whole_exponent_points(expected: Expected, positions: frozenset[int]) -> np.ndarray:
    """Seeded points where the variables at ``positions`` take simple values (2, 1/2, −3…), each
    within its domain, and the others their usual draws. A power of a negative base is real
    only where its exponent is a whole number, points of no width that random draws never hit;
    there (a^b)^c and a^(bc) differ."""
    key = ("whole exponents", positions)
    if key not in expected.cache:
        points = expected.points(_PROBES, salt=7).copy()
        rng = np.random.default_rng(expected.setting.seed + 7)
        for i in sorted(positions):
            domain = expected.setting.domain(expected.variables[i])
            allowed = [v for v in _SIMPLE if _within(v, domain)]
            points[:, i] = rng.choice(allowed, size=len(points))
        points.flags.writeable = False
        expected.cache[key] = points
    return expected.cache[key]


def _within(value: float, domain: str) -> bool:
    if domain == "positive":
        return value > 0
    if domain == "negative":
        return value < 0
    if domain == "integer":
        return value == int(value)
    return True


def check_expression(expected: Expected, answer: ParsedAnswer, deadline: Deadline) -> Outcome:
    equal, pairs = same_values(expected, expected.value, answer.value, deadline)
    if equal:
        return Outcome("equivalent", 1.0, "equivalent")
    if expected.option("up_to_constant"):
        constant = constant_difference(pairs)
        if constant:
            return Outcome("equivalent", 1.0, "equivalent_up_to_constant")
        if constant is None:  # a constant so large that it hides the rest: a person decides
            return Outcome("undecided", 0.0, "undecided", method="numeric: a constant hides the answer")
    elif equal is False and _an_energy(expected) and constant_difference(pairs):
        # right but for a constant of the motion: a potential measured from another zero than the prompt's;
        # a kinetic energy has no zero to choose
        return Outcome("not_equivalent", 0.0, "constant_offset_kinetic" if _kinetic(expected) else "constant_offset")
    if equal is None:
        deadline.check()
        if symbolic_zero(expected.setting.plain(answer.value) - expected.value, expected.setting):
            return Outcome("equivalent", 1.0, "equivalent", method="symbolic")
        return Outcome("undecided", 0.0, "undecided", method="numeric: too few defined points")
    outcome = diagnose_difference(expected, expected.value, answer.value, pairs, deadline)
    plain = expected.setting.plain(answer.value)
    # a product written wrong is better told by the symbols its factors get wrong than as "a term"
    # (√(l/g) for √(g/l) has no term wrong); of two sums, a symbol common to every term (g in a
    # potential) is no factor the student got right
    if expected.value.is_Add or plain.is_Add or outcome.key not in ("wrong", *TERM_KEYS):
        return outcome
    told_as_one = outcome.key in ("wrong", "term_differs") and not outcome.more
    if not (told_as_one or _monomial(expected)):
        return outcome  # m₁ g/(m₁ + m₂) for (m₁ − m₂) g/(m₁ + m₂): a term of the numerator is missing
    if expected.value.free_symbols and not plain.free_symbols:
        return Outcome("not_equivalent", 0.0, "number_for_formula")  # 3.13 for √(g/l)
    return _factor_dependence(expected, "value", expected.value, answer.value, plain) or outcome


def _monomial(expected: Expected) -> bool:
    """Whether the expected answer, multiplied out, is one term (√(g/l), m l² sin²θ φ̇): then no
    term of it can be missing, only a factor wrong."""
    if "monomial" not in expected.cache:
        expected.cache["monomial"] = not sympy.expand(expected.value).is_Add
    return expected.cache["monomial"]


def _an_energy(expected: Expected) -> bool:
    """Whether the expected answer changes along the motion and is an energy, whose zero is a
    choice: named as one (the option ``name``: V, U, T, H, E, L), or else measured in energy. A
    force's constant term (k l₀ in −k (r − l₀)) is no zero level, nor is a torque's (Q_θ is
    measured in energy): each is told as a term."""
    if not expected.value.free_symbols & expected.setting.varying:
        return False
    names = expected.option("name")  # canonical, first the quantity's own
    if names:
        return names[0].split("_")[0] in _ENERGY_NAMES
    try:
        return units_of(expected.value, expected.setting) == DIMENSIONS["energy"]
    except Mixed:
        return False


_ENERGY_NAMES = frozenset({"V", "U", "T", "K", "H", "E", "L"})
_KINETIC_NAMES = frozenset({"T", "K"})


def _kinetic(expected: Expected) -> bool:
    """Whether the part names its quantity a kinetic energy (T, K)."""
    names = expected.option("name")
    return bool(names) and names[0].split("_")[0] in _KINETIC_NAMES


_MOVED = (1.37, 0.29)  # a variable moved to 1.37 x + 0.29: away from its value, and from 0 where it was 0
_SAME_RATIO = 1e-9  # relative: a ratio that moves less than this does not depend on the variable


def _factor_dependence(expected: Expected, key: str, e, s, plain) -> Outcome | None:
    """``(m₁ + m₂) g/(m₁ − m₂)`` for ``(m₁ − m₂) g/(m₁ + m₂)``: where the ratio of ``s`` (``plain``
    in plain symbols) to ``e`` depends on some of the symbols the two are written in and not on
    the others, the outcome that names both: the answer depends on g as it should, and not on m₁
    and m₂. Found in the numbers: each symbol moved alone, at the first point of two draws of the
    parameters. None where the ratio depends on every symbol (a sum with a wrong term), or cannot
    be had. ``s`` as parsed is what :func:`same_values` compiled, and compiling it again is spared."""
    variables = expected.variables
    used = [i for i, symbol in enumerate(variables) if symbol in e.free_symbols | plain.free_symbols]
    e_c, s_c = expected.compiled(key, e), expected.compile(s)
    depends, rows = set(), 0
    for point in expected.points(expected.point_count, group=GROUP)[::GROUP][:2]:
        start = _ratio(e_c, s_c, point)
        if start is None:
            continue
        rows += 1
        for i in used:
            moved = point.copy()
            moved[i] = moved[i] * _MOVED[0] + _MOVED[1]
            ratio = _ratio(e_c, s_c, moved)
            if ratio is None or abs(ratio - start) > _SAME_RATIO * abs(start):
                depends.add(i)
    if not rows or not depends:
        return None
    names = [_shown(variables[i]) for i in used if i in depends]
    others = [_shown(variables[i]) for i in used if i not in depends]
    if not others:  # every symbol is wrong: say which the answer lacks, or has where the right one has not
        lacking = [_shown(variables[i]) for i in used if variables[i] not in plain.free_symbols]
        extra = [_shown(variables[i]) for i in used if variables[i] not in e.free_symbols]
        said = [("factor_lacks", {"names": listed(lacking)})] if lacking else []
        said += [("factor_extra", {"names": listed(extra)})] if extra else []
        if not said:
            said = [("factor_depends_all", {"names": listed(names)})]
        (key, details), *more = said
        return Outcome("not_equivalent", 0.0, key, details, method="numeric: ratio", more=tuple(more))
    details = {"names": listed(names), "others": listed(others)}
    # said as it is: the answer lacks them (g l for g l m), has them where the right one has not, has
    # one symbol for another (l₀ for r), or depends on them in another way
    theirs = [variables[i] in plain.free_symbols for i in used if i in depends]
    ours = [variables[i] in e.free_symbols for i in used if i in depends]
    key = "factor_depends" if not any(theirs) else "factor_depends_extra" if not any(ours) else "factor_depends_how"
    if key == "factor_depends_how" and not any(a and b for a, b in zip(theirs, ours, strict=True)):
        wrote = [name for name, mine in zip(names, theirs, strict=True) if mine]
        instead = [name for name, mine in zip(names, theirs, strict=True) if not mine]
        details = {**details, "names": listed(wrote), "instead": listed(instead)}
        key = "factor_depends_instead"
    return Outcome("not_equivalent", 0.0, key, details, method="numeric: ratio")


def _ratio(e_c, s_c, point: np.ndarray) -> complex | None:
    """``s / e`` at ``point``, or None where either is undefined or ``e`` is 0 there."""
    values = point.tolist()
    try:
        (a, scale), (b, _) = e_c.at(values), s_c.at(values)
    except UNDEFINED:
        return None
    if not (cmath.isfinite(a) and cmath.isfinite(b)) or abs(a) <= 1e-9 * scale or b == 0:
        return None
    return b / a


def _shown(symbol: sympy.Symbol) -> str:
    """A plain symbol as a student writes it: θ for theta, θ̇ for theta__1."""
    name, _, dots = symbol.name.partition("__")
    return unicode_name(name, int(dots) if dots else 0)


def diagnose_difference(
    expected: Expected,
    e,
    s,
    pairs: list[Pair],
    deadline: Deadline,
    *,
    key: str = "value",
    approximations: Callable[[sympy.Expr], list] | None = None,
    termwise: Callable[[], sympy.Expr | None] | None = None,
) -> Outcome:
    """A not-equivalent outcome for ``s`` (as parsed, or in plain symbols) against ``e``,
    naming the mistake where it can.

    ``key`` names ``e`` among the expressions derived from the expected answer;
    ``approximations`` gives the small-angle forms of an expression (by default
    sin u → u, cos u → 1 or 1 − u²/2); ``termwise``, when given, gives ``s`` expanded in
    the form whose terms are compared (None: it has no such form), for the last resort.
    """
    approximate = approximations or (lambda expr: small_angle(expr, expected.setting))
    signed = expected.signed_parameters
    if signed and _right_in_some_draws(pairs):
        return Outcome("not_equivalent", 0.0, "some_signs", {"names": expected.setting.describe(signed)})
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
        expected.cache[cache_key] = [
            (number, form)
            for number, form in enumerate(approximate(e))
            # not one that does not exist here (a Taylor expansion through a pole)
            if not form.has(sympy.nan, sympy.zoo, sympy.oo, -sympy.oo)
        ]
    for number, form in expected.cache[cache_key]:
        same, form_pairs = same_values(expected, form, s, deadline, key=f"{key}, small angle {number}")
        if same or (expected.option("up_to_constant") and constant_difference(form_pairs)):
            return Outcome("not_equivalent", 0.0, "small_angle")  # with another zero level too
    # where a constant is allowed, do not point at one
    varying = set(expected.setting.varying) if expected.option("up_to_constant") else None
    change = single_term_change(expected, key, e, s, varying)
    if change:
        return term_outcome([change])
    s = expected.setting.plain(s)
    # Only an expected answer without trigonometry can be a small-angle form the student did not use.
    if not has_angle_functions(e, expected.setting) and has_angle_functions(s, expected.setting):
        for form in approximate(s):
            if not form.has(sympy.nan, sympy.zoo) and same_values(expected, e, form, deadline, key=key)[0]:
                return Outcome("not_equivalent", 0.0, "not_small_angle")
    deadline.check()
    if termwise is None:
        submitted_terms = terms(s, varying=varying)
    else:
        solved = termwise()
        if solved is None:
            return Outcome("not_equivalent", 0.0, "wrong")
        submitted_terms = terms(solved, varying=varying, expanded=True)
    return term_outcome(term_changes(expected_terms(expected, key, e, varying), submitted_terms, expected.setting))


def _right_in_some_draws(pairs: list[Pair]) -> bool:
    """Whether the answer is right at every point of some draws of the parameters and wrong in
    another: with parameters that may be negative, one sign of them (√(a²) for a)."""
    draws: dict[int, list[Closeness]] = {}
    for pair in pairs:
        draws.setdefault(pair.group, []).append(pair.closeness())
    right = any(all(c is Closeness.EQUAL for c in draw) for draw in draws.values())
    return right and any(Closeness.DIFFERENT in draw for draw in draws.values())


def expected_terms(expected: Expected, key: str, e, varying: set | None = None) -> dict | None:
    """The terms of ``e`` (named ``key`` among the expected answer's expressions), as
    :func:`~grader.judge.diagnose.terms` gives them, expanded once for every submission."""
    cache_key = ("terms", key, varying is not None)
    if cache_key not in expected.cache:
        expected.cache[cache_key] = terms(e, varying=varying)
    return expected.cache[cache_key]


def single_term_change(expected: Expected, key: str, e, s, varying: set | None = None) -> tuple[str, str] | None:
    """(key, description) when ``s`` is ``e`` with one of its terms missing or off by a factor,
    as :func:`~grader.judge.diagnose.term_changes` would name it; None otherwise.

    Read from the numbers: s − e must be the same multiple λ of one term of ``e`` at every
    sample point (λ = −1: missing; −2: the wrong sign; otherwise the wrong factor, when
    the functions and symbols of that term occur in ``s``: a term can only differ if it
    is there). With
    ``varying`` (a constant is allowed), only the terms involving those symbols count, and
    differences are compared within each group of points sharing the parameters. Points
    the floats cannot decide make this give up; sympy's expansion then has the last word.
    """
    shapes = expected_terms(expected, key, e, varying)
    if shapes is None or not 1 <= len(shapes) <= MAX_TERMS:
        return None
    points = expected.points(expected.point_count, group=GROUP)
    (e_values, e_scales), (s_values, s_scales) = (
        expected.compiled(key, e).many(points),
        expected.compile(s).many(points),
    )
    difference, scale = s_values - e_values, np.maximum(e_scales, s_scales)

    def multiples(candidates: Callable[[], list], name: str) -> list:
        found = []
        for shape, term in _term_evaluators(expected, key, name, varying, candidates):
            t_values, t_scales = term.many(points)
            multiple = _multiple_of(difference, t_values, np.maximum(scale, t_scales), varying is not None)
            if multiple is not None:
                found.append((shape, multiple))
        return found

    found = multiples(lambda: list(shapes.items()), "term")
    if not found:
        # k(r − l₀) with the wrong sign is two expanded terms off, but one term as the answer is written
        found = multiples(lambda: _written_terms(e, shapes, varying), "written term")
    if len(found) != 1:
        return None
    (shape, multiple), setting = found[0], expected.setting
    if abs(multiple + 1) < 1e-9:
        if _written_in_state(shape, s, setting):
            return None  # ½ m₂ l₁² θ̇₁² for ½ (m₁ + m₂) l₁² θ̇₁²: a factor to look at, named from the terms
        return "missing_term", describe_term(shape, setting)
    if _function_names(shape) - _function_names(s):  # the term in cot θ where the student wrote cot θ
        shape = as_written(shape, expected.setting.plain(s))
    if _function_names(shape) - _function_names(s) or _symbol_names(shape) - _symbol_names(s):
        # cos²θ written for sin²θ is, up to a constant, sin²θ with the wrong sign; but the
        # student wrote no sin. Against (m₁ − m₂)g/(m₁ + m₂), ẍ = g has "the gravity term in
        # m₂ with the wrong sign"; but the student wrote no m₂. A term can only differ if it
        # is there: naming the terms as typed (sympy's comparison) says more.
        return None
    how = "has the wrong sign" if abs(multiple + 2) < 1e-9 else "has the wrong factor"
    # the expected answer's other terms are the student's too, and right: the term is told apart from them
    # (a term as written, k(r − l₀), from none: the expanded ones are its own pieces)
    named = describe_term(shape, setting, definite=True, own=True)
    if shape in shapes:
        named = told_apart(shape, named, list(shapes), setting, own=True)
    return "term_differs", f"{named} {how}"


def _term_evaluators(expected: Expected, key: str, name: str, varying: set | None, candidates) -> list:
    """(shape, the term compiled) for each of ``candidates()``, the (shape, coefficient) of terms of
    the expected answer: made once, not for every answer (each product is a new object to sympy)."""
    cache_key = ("term evaluators", key, name, varying is not None)
    if cache_key not in expected.cache:
        expected.cache[cache_key] = [
            (shape, expected.compiled(f"{key}, {name} {number}{' varying' if varying else ''}", coefficient * shape))
            for number, (shape, coefficient) in enumerate(candidates())
            # any constant difference is a multiple of a number: the numbers cannot say which
            if shape.free_symbols
        ]
    return expected.cache[cache_key]


def _written_in_state(shape, s, setting) -> bool:
    """Whether the answer ``s`` has a term with the part in the coordinates and velocities that
    ``shape`` has (one with coordinates or velocities at all)."""
    inside, plain = state_part(in_sines_and_cosines(shape), setting), setting.plain(s)
    if inside is sympy.S.One or not all(plain.has(factor) for factor in sympy.Mul.make_args(inside)):
        return False  # no term of the answer can have it: not worth expanding the answer to see
    written = terms(plain)
    return written is not None and any(state_part(in_sines_and_cosines(other), setting) == inside for other in written)


def _written_terms(e, shapes: dict, varying: set | None) -> list:
    """The terms of ``e`` as written that expanding splits (k(r − l₀)), as (shape, coefficient)."""
    written = []
    for term in sympy.Add.make_args(e):
        coefficient, shape = term.as_coeff_Mul()
        if shape not in shapes and shape.has(sympy.Add) and (varying is None or shape.free_symbols & varying):
            written.append((shape, coefficient))
    return written


def _function_names(expr) -> set[str]:
    return {type(f).__name__ for f in expr.atoms(sympy.Function)}


def _symbol_names(expr) -> set[str]:
    """The names of the symbols in ``expr``, plain or as parsed: θ, θ̇ and θ(t) are all ``theta``."""
    names = {symbol.name.split("__")[0] for symbol in expr.free_symbols}
    return names | {type(f).__name__ for f in expr.atoms(AppliedUndef)}


def _multiple_of(difference: np.ndarray, term: np.ndarray, scale: np.ndarray, up_to_constant: bool) -> float | None:
    """λ ≠ 0 with ``difference`` = λ·``term`` at every point where all are defined (up to a
    constant per group of points, with ``up_to_constant``), to floats' resolution; else None."""
    defined = np.isfinite(difference) & np.isfinite(term) & np.isfinite(scale)
    if up_to_constant:  # each point against its group's first defined point
        every = np.arange(len(defined))
        groups = every // GROUP
        firsts = np.full(groups[-1] + 1, len(defined))
        np.minimum.at(firsts, groups[defined], every[defined])
        base = np.where(firsts[groups] < len(defined), firsts[groups], every)
        difference, term, defined = difference - difference[base], term - term[base], defined & (base != every)
    if defined.sum() < (MIN_DEFINED - 2 if up_to_constant else MIN_DEFINED):
        return None
    difference, term, scale = difference[defined], term[defined], scale[defined]
    largest = int(np.argmax(np.abs(term) / np.where(scale > 0, scale, 1.0)))
    if abs(term[largest]) <= 1e-9 * scale[largest] or abs(difference[largest]) <= 1e-9 * scale[largest]:
        return None  # this term vanishes here, or it is not what differs
    multiple = difference[largest] / term[largest]
    if abs(multiple.imag) > 1e-9 * abs(multiple):
        return None
    bound = FLOAT_EQUAL * np.maximum(scale, np.abs(multiple) * scale)
    return float(multiple.real) if bool(np.all(np.abs(difference - multiple * term) <= bound)) else None


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
