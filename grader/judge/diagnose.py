"""Naming the mistake: which term differs, and how it can be described without revealing it.

Contents:
    terms(expr, varying=, expanded=)              an expression's terms, keyed by shape
    expand_terms(expr)                            multiplied out as sympy.expand does, without building the sum
    term_changes(expected, submitted, setting)    missing / extra / differing terms, from two such
    coefficients_differ(...)                      terms that differ only in their parameters
    describe_term(term, setting)                  "a velocity-dependent term", "a term in cos(θ₁ − θ₂)"
    state_part(shape, setting)                    a term's factors in the coordinates and velocities
    in_sines_and_cosines(expr), as_written(shape, answer)   cot θ as cos θ / sin θ, sin 2θ as 2 sin θ cos θ;
                                                  and back as typed
    small_angle(expr, setting)                    sin u → u, cos u → 1 (and 1 − u²/2)
    taylor(expr, setting, order)                  expansion about the equilibrium q = q̇ = q̈ = 0
    symbolic_zero(expr, setting)                  sympy's last word, with the problem's assumptions

Descriptions name the *kind* of term a student can look for in their own answer;
they never print the expected term itself.
"""

from __future__ import annotations

import itertools
import math
import re
import zlib

import sympy

from grader.judge.setting import Setting
from grader.parse.names import superscript, unicode_name
from grader.parse.readback import to_text

__all__ = [
    "TERM_KEYS",
    "coefficients_differ",
    "describe_term",
    "expand_terms",
    "has_angle_functions",
    "in_sentence",
    "small_angle",
    "state_part",
    "symbolic_zero",
    "taylor",
    "term_changes",
    "terms",
    "told_apart",
]

MAX_TERMS = 60  # beyond this, listing terms says nothing useful
_TRIG = (sympy.sin, sympy.cos, sympy.tan, sympy.cot, sympy.sec, sympy.csc)


def terms(expr, *, varying: set | None = None, expanded: bool = False) -> dict | None:
    """The terms of ``expr`` expanded, keyed by their shape (the term without its numeric
    coefficient); None when there are too many to name (see :func:`expand_terms`).

    With ``varying`` (a set of symbols), only the terms that involve one of them: what a
    constant the answer may add does not hide. ``expanded`` says ``expr`` already is.
    """
    if expanded:
        collected: dict = {}
        for term in sympy.Add.make_args(expr):
            coefficient, shape = term.as_coeff_Mul()
            collected[shape] = collected.get(shape, 0) + coefficient
    else:
        collected = expand_terms(expr)
        if collected is None:
            return None
    return {s: c for s, c in collected.items() if c != 0 and (varying is None or s.free_symbols & varying)}


def expand_terms(expr) -> dict | None:
    """``expr`` multiplied out, as ``sympy.expand`` would, as {shape: rational coefficient};
    None when that is more than :data:`EXPANSION_LIMIT` terms.

    Products and positive integer powers of sums are multiplied out, inside functions too;
    a product's denominators become one, multiplied out (1/(l(a + b)) is 1/(al + bl), as
    sympy's ``fraction`` makes it); e^(a + b) is e^a·e^b. Unlike ``sympy.expand`` it builds
    no sum of the result, walks the expression once rather than once per hint, and leaves
    alone what needs nothing: on the benchmark's answers it names the same terms, 5 to 9
    times faster. Logarithms, fractional powers of sums and e^(−a) beside a denominator are
    left as they are (sympy splits log(ab) and (a + b)^(3/2), and moves e^(−a) below):
    shapes only have to agree with each other.

    The last expression's terms are remembered, and given again for the very same object: a
    diagnosis asks for an answer's in several steps. They are only to be read.

    >>> x, y = sympy.symbols("x y")
    >>> expand_terms((x + y) ** 2 / 2 + sympy.sin(2 * (x + 1)))
    {x**2: 1/2, x*y: 1, y**2: 1/2, sin(2*x + 2): 1}
    """
    last = _last_expansion.get("last")
    if last is not None and last[0] is expr:
        return last[1]
    try:
        expansion, _ = _expanded(expr)
        collected = {shape: coefficient for shape, coefficient in expansion.items() if coefficient != 0}
    except _TooMany:
        collected = None
    _last_expansion["last"] = (expr, collected)
    return collected


_last_expansion: dict = {}


EXPANSION_LIMIT = 4 * MAX_TERMS  # past this many terms (or products of terms) the names say nothing


class _TooMany(Exception):
    pass


def _expanded(expr) -> tuple[dict, bool]:
    """{shape: coefficient} for ``expr`` multiplied out, and whether that changed anything."""
    if expr.is_Rational:
        return ({sympy.S.One: expr} if expr != 0 else {}), False
    if expr.is_Add:
        collected, changed = {}, False
        for arg in expr.args:
            parts, moved = _expanded(arg)
            changed |= moved
            for shape, coefficient in parts.items():
                changed |= shape in collected
                collected[shape] = collected.get(shape, 0) + coefficient
        return collected, changed
    if expr.is_Mul:
        return _expanded_product(expr)
    if expr.is_Pow:
        base, exponent = expr.args
        if exponent.is_Integer and exponent < -1 and base.is_Add:  # 1/(a + b)²: its denominator multiplied out
            return _single(sympy.Pow(_rebuilt(sympy.Pow(base, -exponent)), -1)), True
        if exponent.is_Integer and exponent > 0 and base.is_Add:
            parts, result = _expanded(base)[0], {sympy.S.One: sympy.S.One}
            for _ in range(int(exponent)):
                result = _product(result, parts)
            return result, True
        new_base, new_exponent = _rebuilt(base), _rebuilt(exponent)
        if new_base is base and new_exponent is exponent:
            return _single(expr), False
        return _single(sympy.Pow(new_base, new_exponent)), True
    if isinstance(expr, sympy.exp):
        exponent, changed = _expanded(expr.args[0])
        if len(exponent) > 1:  # e^(a + b) is e^a·e^b
            result = {sympy.S.One: sympy.S.One}
            for shape, coefficient in exponent.items():
                result = _product(result, _single(sympy.exp(coefficient * shape)))
            return result, True
        return (_single(sympy.exp(_sum(exponent))), True) if changed else (_single(expr), False)
    if isinstance(expr, sympy.Function) and expr.args:
        args = [_rebuilt(arg) for arg in expr.args]
        if all(new is old for new, old in zip(args, expr.args, strict=True)):
            return _single(expr), False
        return _single(expr.func(*args)), True
    return {expr: sympy.S.One}, False


def _expanded_product(expr) -> tuple[dict, bool]:
    below = [f for f in expr.args if f.is_Pow and f.exp.is_Rational and f.exp.is_negative]
    number = expr.args[0] if expr.args[0].is_Rational else sympy.S.One
    if below and (len(below) > 1 or number.q != 1):
        # 1/(2l(a + b)), which sympy holds as ½·l⁻¹·(a + b)⁻¹: one denominator, multiplied out
        # (sympy's fraction), where that makes it a sum
        denominator = _rebuilt(sympy.Mul(number.q, *(f.base**-f.exp for f in below)))
        if denominator.is_Add:
            result = {sympy.Pow(denominator, -1): sympy.Integer(number.p)}
            for factor in expr.args:
                if factor is not number and factor not in below:
                    result = _product(result, _expanded(factor)[0])
            return result, True
    parts = [_expanded(factor) for factor in expr.args]
    if not any(moved or len(terms) > 1 for terms, moved in parts):
        return _single(expr), False
    result = {sympy.S.One: sympy.S.One}
    for terms, _ in parts:
        result = _product(result, terms)
    return result, True


def _product(a: dict, b: dict) -> dict:
    if len(a) * len(b) > EXPANSION_LIMIT**2 // 4:
        raise _TooMany
    result: dict = {}
    for shape_a, coefficient_a in a.items():
        for shape_b, coefficient_b in b.items():
            if shape_a is sympy.S.One or shape_b is sympy.S.One:
                coefficient, shape = sympy.S.One, (shape_b if shape_a is sympy.S.One else shape_a)
            else:
                coefficient, shape = (shape_a * shape_b).as_coeff_Mul()  # x·x is x², √2·√2 is 2
            result[shape] = result.get(shape, 0) + coefficient_a * coefficient_b * coefficient
    if len(result) > EXPANSION_LIMIT:
        raise _TooMany
    return result


def _single(value) -> dict:
    coefficient, shape = value.as_coeff_Mul()
    return {shape: coefficient} if coefficient != 0 else {}


def _sum(parts: dict):
    return sympy.Add(*(coefficient * shape for shape, coefficient in parts.items()))


def _rebuilt(expr):
    """``expr`` multiplied out, as an expression (the very same object where nothing changes)."""
    parts, changed = _expanded(expr)
    return _sum(parts) if changed else expr


# The feedback keys of a diagnosis that names terms, as term_changes gives them.
TERM_KEYS = ("missing_term", "extra_term", "term_differs")


def term_changes(expected_terms: dict | None, submitted_terms: dict | None, setting: Setting) -> list[tuple[str, str]]:
    """How the submitted terms differ from the expected ones (each as :func:`terms` gives them):
    [(key, description)].

    Keys are ``missing_term``, ``extra_term`` and ``term_differs``. An empty list
    means the comparison is not informative (too many terms, or none differ by shape).
    """
    if expected_terms is None or submitted_terms is None:
        return []
    if len(expected_terms) > MAX_TERMS or len(submitted_terms) > MAX_TERMS:
        return []
    # cot θ is cos θ / sin θ: a term is matched whichever the student wrote, and named as written
    theirs, ours = _by_form(submitted_terms), _by_form(expected_terms)
    written_shapes = [shape for shape, _ in theirs.values()]
    changes, lost, gained = [], [], []
    for key, (shape, coefficient) in ours.items():
        written = theirs.get(key)
        if written is None:
            lost.append(shape)
            changes.append(("missing_term", describe_term(shape, setting)))
        elif written[1] != coefficient:
            how = "has the wrong sign" if written[1] == -coefficient else "has the wrong factor"
            named = describe_term(written[0], setting, definite=True, own=True)
            changes.append(
                ("term_differs", f"{told_apart(written[0], named, written_shapes, setting, own=True)} {how}")
            )
    for key, (shape, _) in theirs.items():
        if key not in ours:
            gained.append(shape)
            changes.append(("extra_term", describe_term(shape, setting, own=True)))
    if lost or gained:
        regrouped = _differing_factors(ours, theirs, setting, any_factor=False)
        if regrouped:
            return regrouped
    if len(changes) == 2 and len(lost) == 1 and len(gained) == 1:
        coefficients = (expected_terms.get(lost[0]), submitted_terms.get(gained[0]))
        if (coefficients[0] == coefficients[1] and gained[0] in small_angle(lost[0], setting)) or _small_but_constant(
            lost[0], gained[0], coefficients, setting
        ):
            # g θ for g sin θ in one equation of a system: not "a term in sin θ missing, a gravity term too many"
            named = describe_term(gained[0], setting, definite=True, own=True)
            return [("term_differs", f"{named} is in its small-angle form, and the full form is asked for")]
        return _one_term_changed(changes, lost[0], gained[0], setting, [shape for shape, _ in theirs.values()])
    return changes


def coefficients_differ(
    expected_terms: dict,
    submitted_terms: dict,
    setting: Setting,
    *,
    any_factor: bool = False,
    kept: dict | None = None,
) -> list[tuple[str, str]] | None:
    """Terms that differ only in their parameters, each named once as the term the student
    wrote; [] where the answer has not the same terms in the coordinates and velocities.

    Expanded, ½ m₂ l₁² θ̇₁² written for ½ (m₁ + m₂) l₁² θ̇₁² is a term ½ m₁ l₁² θ̇₁² missing;
    but the student wrote a term in θ̇₁² and should look at its factor, not for another term.
    Terms are grouped by their part in the coordinates and velocities (and given names), their
    parameters summed; where both answers have the same groups, one or two whose parameters
    differ are named. The constant group is left to the terms as they are.

    With ``any_factor`` (an equation, right whatever it is multiplied by), the groups are
    compared in the ratio most of them share: m₁ l₁ θ̈₁ for (m₁ + m₂) l₁ θ̈₁ is one term off,
    not every other term off by (m₁ + m₂)/m₁ once the equation is solved for θ̈₁. There, None
    says the terms are the same but no ratio tells which are off (two of four terms off): then
    no term may be named, as any normalization would name a right one.

    The parameters are compared by their values at two generic points, not by sympy's algebra
    (which cost milliseconds a wrong answer): this only names a term, the verdict is made.
    ``kept``, a dict kept with the expected answer, keeps its terms' grouping for the next answer.
    """
    kept = {} if kept is None else kept
    if "by form" not in kept:
        kept["by form"] = _by_form(expected_terms)
    return _differing_factors(kept["by form"], _by_form(submitted_terms), setting, any_factor, kept)


def _differing_factors(
    ours_by_form: dict, theirs_by_form: dict, setting: Setting, any_factor: bool, kept: dict | None = None
) -> list | None:
    """:func:`coefficients_differ`, from the terms as :func:`_by_form` groups them (the expected
    side's split kept in ``kept``, where given)."""
    if kept is not None and "split" not in kept:
        kept["split"] = _split_by_state(ours_by_form, setting)
    split_ours = kept["split"] if kept is not None else _split_by_state(ours_by_form, setting)
    split_theirs = _split_by_state(theirs_by_form, setting)
    if {split[0] for split in split_ours.values()} != {split[0] for split in split_theirs.values()}:
        return []  # a term in the coordinates and velocities is missing or too many: said as such
    ours, theirs = _by_state(split_ours), _by_state(split_theirs)
    if ours is None or theirs is None:
        return []
    if any(not all(abs(v) > _TINY for v in values) for _, values in ours.values()):
        return []
    ratio = (1.0,) * len(_GENERIC)
    if any_factor:
        ratios = [tuple(t / o for t, o in zip(theirs[key][1], ours[key][1], strict=True)) for key in ours]
        shared = [r for r in ratios if all(abs(v) > _TINY for v in r)]
        counts = [sum(_close(r, other) for other in shared) for r in shared]
        best = max(counts, default=0)
        rivals = {index for index, count in enumerate(counts) if count == best}
        if best < 2 or any(not _close(shared[i], shared[j]) for i in rivals for j in rivals):
            # no ratio more terms share than any other: which are off is a guess. With two terms the
            # caller may still name one by a convention (the acceleration's is right); with more, nothing
            return [] if len(ours) <= 2 else None
        ratio = shared[min(rivals)]
    scaled = {key: tuple(r * v for r, v in zip(ratio, ours[key][1], strict=True)) for key in ours}
    differing = [key for key in ours if not _close(scaled[key], theirs[key][1])]
    if not 1 <= len(differing) <= 2 or any(key is sympy.S.One for key in differing):
        return []
    if any_factor and len(ours) - len(differing) < len(differing) + 1:
        return None  # as many terms off as right: which are "off" is a guess
    written = [shape for shape, _ in theirs.values()]
    changes = []
    for key in differing:
        shape, values = theirs[key]
        wrong_sign = _close(values, tuple(-v for v in scaled[key]))
        how = "has the wrong sign" if wrong_sign else "has the wrong factor"
        named = describe_term(shape, setting, definite=True, own=True)
        changes.append(("term_differs", f"{told_apart(shape, named, written, setting, own=True)} {how}"))
    return changes


# The points where coefficients are compared: each symbol's value there comes from its name (crc32,
# the same on every run and machine), between 0.6 and 1.6, so that two different polynomials of the
# problem's size do not meet at both.
_GENERIC = (0, 1)
_TINY = 1e-12


def _close(a: tuple, b: tuple) -> bool:
    return all(abs(x - y) <= 1e-9 * max(abs(x), abs(y), 1e-300) for x, y in zip(a, b, strict=True))


def _split_by_state(by_form: dict, setting: Setting) -> dict:
    """{form: (its part in the coordinates, velocities and given names; the rest of its factors;
    its number times its coefficient; that part as written)} for :func:`_by_form`'s grouping."""
    varying, split, moves = setting.varying, {}, {}

    def varies(factor) -> bool:  # the terms share their factors, and free_symbols walks each anew
        if factor not in moves:
            moves[factor] = bool(factor.free_symbols & varying)
        return moves[factor]

    for form, (written, coefficient) in by_form.items():
        times, bare = form.as_coeff_Mul()
        factors = sympy.Mul.make_args(bare)
        inside = sympy.Mul(*(f for f in factors if varies(f)))
        outside = [f for f in factors if not varies(f)]
        shown = inside if written is form else sympy.Mul(*(f for f in sympy.Mul.make_args(written) if varies(f)))
        split[form] = (inside, outside, coefficient * times, shown)
    return split


def _by_state(split: dict) -> dict | None:
    """{a term's part in the coordinates, velocities and given names (as :func:`_split_by_state`
    splits them): (that part as the student wrote it, the rest of the terms that share it, summed,
    at each generic point)}; None where a parameter's part is not a product of powers and sums."""
    grouped: dict = {}
    for inside, outside, number, written in split.values():
        values = []
        for point in _GENERIC:
            value = _parameters_at(outside, point)
            if value is None:
                return None
            values.append(float(number) * value)
        shown, before = grouped.get(inside, (written, (0.0,) * len(_GENERIC)))
        grouped[inside] = (shown, tuple(b + v for b, v in zip(before, values, strict=True)))
    return grouped


def _parameters_at(factors: list, point: int) -> float | None:
    """The product of ``factors`` (powers of the problem's parameters, and sums of them) at a
    generic ``point``, each symbol given a value by its name; None for anything else."""
    total = 1.0
    for factor in factors:
        value = _parameter_value(factor, point)
        if value is None:
            return None
        total *= value
    return total


def _parameter_value(expr, point: int) -> float | None:
    if expr.is_Number:
        return float(expr)
    if expr.is_Symbol:
        return 0.6 + zlib.crc32(f"{expr.name} {point}".encode()) / 2**32
    if expr.is_Pow and expr.exp.is_Rational:
        base = _parameter_value(expr.base, point)
        return None if base is None or base <= 0 else base ** float(expr.exp)
    if expr.is_Add or expr.is_Mul:
        values = [_parameter_value(arg, point) for arg in expr.args]
        if any(value is None for value in values):
            return None
        return sum(values) if expr.is_Add else math.prod(values)
    return None


def state_part(shape, setting: Setting):
    """The factors of a term (as :func:`terms` keys it) in the coordinates, their rates and the
    given names: θ̇₁² of ½ m₁ l₁² θ̇₁²; 1 for a term of parameters alone."""
    return sympy.Mul(*(f for f in sympy.Mul.make_args(shape) if f.free_symbols & setting.varying))


def told_apart(shape, description: str, shapes: list, setting: Setting, **how) -> str:
    """``description`` of a term the student wrote (``shape``), with the parameters that tell it
    apart from their other terms (``shapes``) described alike: −(m₁ − m₂) g l₁ cos θ₁ for
    −(m₁ + m₂) g l₁ cos θ₁ has one term in cos θ₁ of the wrong sign, and "the term in cos(θ₁)"
    would send the student to flip both (and then again). Said as "the term in cos(θ₁) with m₂".
    ``how`` are :func:`describe_term`'s options ``description`` was made with, for the others."""
    kind = description.split(" ", 1)[1]
    how.pop("definite", None)
    rivals = [
        other for other in shapes if other != shape and describe_term(other, setting, **how).split(" ", 1)[1] == kind
    ]
    if not rivals:
        return description
    state = set(setting.state.values())
    # the factors of its own no rival shares (m₁ of m₁ g/(m₁ + m₂) beside m₂ g/(m₁ + m₂)), by their names
    factors = set(sympy.Mul.make_args(shape)) - set.intersection(*(set(sympy.Mul.make_args(r)) for r in rivals))
    apart = sorted({s for factor in factors for s in factor.free_symbols - state}, key=lambda s: s.name)
    if not apart:
        return description  # nothing to tell it by that would not show the term itself
    return f"{description} with {' and '.join(unicode_name(symbol.name) for symbol in apart)}"


def _by_form(collected: dict) -> dict:
    """{form in sines and cosines: (a shape as written, the coefficients of that form summed)}:
    cot θ θ̇ and cos θ θ̇ / sin θ, written side by side, are one term; ω² sin 2θ is the form
    ω² sin θ cos θ, twice."""
    by_form: dict = {}
    for shape, coefficient in collected.items():
        times, form = in_sines_and_cosines(shape).as_coeff_Mul()
        written, before = by_form.get(form, (shape, 0))
        by_form[form] = (written, before + coefficient * times)
    return by_form


def _small_but_constant(lost, gained, coefficients: tuple, setting: Setting) -> bool:
    """Whether ``gained`` (times its coefficient) is what varies of ``lost``'s small-angle form: −½ m g l θ²
    for m g l cos θ, whose small-angle form m g l (1 − θ²/2) has a constant the terms compared leave out."""
    if None in coefficients or has_angle_functions(gained, setting) or not has_angle_functions(lost, setting):
        return False  # (checked first: sympy's expansion below costs a wrong answer milliseconds)
    moving = set(setting.state.values())
    for form in small_angle(coefficients[0] * lost, setting, second_order=True):
        varying = [term for term in sympy.Add.make_args(sympy.expand(form)) if term.free_symbols & moving]
        if varying and sympy.expand(sympy.Add(*varying) - coefficients[1] * gained) == 0:
            return True
    return False


def _one_term_changed(changes: list, lost, gained, setting: Setting, written: list) -> list:
    """One term lost and one gained (as ``changes`` names them) of the same kind: one term that
    is not right, named as the student wrote it (b ẋ² for b ẋ: the velocity-dependent term in
    ẋ²). Where they share a function of the coordinates, as ω² sin θ written for ω² sin θ cos θ,
    they are named by it: said as a term in cos θ missing and one in sin θ too many, it would
    send the student to look for a cos θ they never wrote. Where another of the student's terms
    (``written``) would be named so too, as (g/R) sin θ beside it, the term is shown as read."""
    (_, lost_kind), (_, gained_as_written) = changes
    if describe_term(gained, setting) == lost_kind:
        return [("term_differs", f"{gained_as_written} is not right")]
    shared = _angle_functions(lost, setting) & _angle_functions(gained, setting)
    if not shared:
        return changes
    first, second = (describe_term(shape, setting, functions=shared) for shape in (lost, gained))
    if first != second:
        return changes
    others = [shape for shape in written if shape != gained and shared <= _angle_functions(shape, setting)]
    if any(describe_term(shape, setting, functions=shared) == first for shape in others):
        return [("term_differs", f"the term in {_shown(gained, setting)} is not right")]
    return [("term_differs", f"{first} is not right")]


def _angle_functions(shape, setting: Setting) -> set:
    state = set(setting.state.values())
    return {f for f in in_sines_and_cosines(shape).atoms(*_TRIG) if f.args[0].free_symbols & state}


_AS_SINES_AND_COSINES = {
    sympy.tan: lambda u: sympy.sin(u) / sympy.cos(u),
    sympy.cot: lambda u: sympy.cos(u) / sympy.sin(u),
    sympy.sec: lambda u: 1 / sympy.cos(u),
    sympy.csc: lambda u: 1 / sympy.sin(u),
}


def in_sines_and_cosines(expr):
    """``expr`` with tan, cot, sec and csc written as quotients of sin and cos, and sin 2u as
    2 sin u cos u (a product still: cos 2u would be a sum): one form for a term however its
    trigonometry was written (the very same object where there is none)."""
    found = expr.atoms(*_AS_SINES_AND_COSINES)
    doubled = {f: half for f in expr.atoms(sympy.sin) if (half := _half(f.args[0])) is not None}
    if not found and not doubled:
        return expr
    return expr.xreplace(
        {f: _AS_SINES_AND_COSINES[type(f)](f.args[0]) for f in found}
        | {f: 2 * sympy.sin(half) * sympy.cos(half) for f, half in doubled.items()}
    )


def _half(angle):
    """u where ``angle`` is 2u, each term of u a whole multiple (2θ, 2θ₁ − 2θ₂, 4θ); else None
    (θ/2 is no double angle, nor is 2θ/3)."""
    if not angle.free_symbols:
        return None
    half = angle.extract_multiplicatively(2)
    if half is None or not all(term.as_coeff_Mul()[0].is_Integer for term in sympy.Add.make_args(half)):
        return None
    return half


def as_written(shape, answer):
    """``shape`` with its trigonometry in the functions ``answer`` uses where they differ only
    in form: cos θ / sin θ as cot θ where the answer has cot θ, and the reverse."""
    theirs = answer.atoms(*_TRIG)
    unwritten = [f for f in shape.atoms(*_AS_SINES_AND_COSINES) if f not in theirs]
    shape = shape.xreplace({f: _AS_SINES_AND_COSINES[type(f)](f.args[0]) for f in unwritten})
    for f in theirs:
        if type(f) in _AS_SINES_AND_COSINES and f not in shape.atoms(type(f)):
            shape = shape.subs(_AS_SINES_AND_COSINES[type(f)](f.args[0]), f)
    return shape


def describe_term(
    term, setting: Setting, *, definite: bool = False, functions: set | None = None, own: bool = False
) -> str:
    """What kind of term this is, in words a student can act on.

    >>> s = Setting.build(["theta_1", "theta_2"], ["m", "g", "l"])
    >>> describe_term(sympy.Symbol("theta_1__1") ** 2 * sympy.Symbol("m"), s)
    'a velocity-dependent term'
    >>> describe_term(sympy.cos(sympy.Symbol("theta_1") - sympy.Symbol("theta_2")), s)
    'a term in cos(θ₁ − θ₂)'
    """
    article = "the" if definite else "a"
    symbols = term.free_symbols
    velocities = {setting.velocity(q) for q in setting.coords}
    accelerations = {setting.acceleration(q) for q in setting.coords}
    trig = [f for f in term.atoms(*_TRIG) if f.args[0].free_symbols & set(setting.state.values())]
    if functions is not None:  # named by these alone (a function the term has, though maybe as cot)
        trig = sorted(functions, key=str)
    if trig:  # the first by its printed form, when there are several
        first = trig[0] if len(trig) == 1 else min(trig, key=str)
        within = f" in {_shown(first, setting)}"  # θ̇, not theta__1
    else:
        within = ""
    given = {sympy.Symbol(name) for name in setting.given} & symbols
    if given:  # p_φ²/(2 m l²) in a Hamiltonian written in the momenta: named by them
        named = _powers(term, given, setting) if own else ""
        if not named and len(given) > 1:  # (p_θ² + p_φ²/sin²θ)/2ml², a sum: not "in p_θ p_φ", a product
            return f"{article} term in {' and '.join(sorted(unicode_name(s.name) for s in given))}"
        named = named or unicode_name(next(iter(given)).name)
        return f"{article} term in {named}{within.replace(' in ', ' and ', 1)}"
    if symbols & accelerations:
        if own and not within:  # the student's own term: which acceleration, as θ̈₁ beside θ̈₂ cos(θ₁ − θ₂)
            within = _velocities(term, accelerations, setting)
        return f"{article} term with an acceleration{within}"
    if symbols & velocities:
        if own and _summed(term, velocities):  # m l² (θ̇² + sin²θ φ̇²): by its velocities, not by one sin(θ) of it
            within = " in " + " and ".join(sorted(to_text(setting.as_typed(v)) for v in symbols & velocities))
        elif own and not within:  # the student's own term: which velocities, as ½ m l² α̇² beside ½ m l² β̇²
            within = _velocities(term, velocities, setting)
        return f"{article} velocity-dependent term{within}"
    if trig:
        return f"{article} term{within}"
    if sympy.Symbol("g") in symbols:
        return f"{article} gravity term"
    if not symbols:
        return f"{article} constant term"
    if not symbols & set(setting.state.values()):
        return f"{article} term without coordinates or velocities"
    coordinates = sorted(symbols & set(setting.state.values()), key=str)
    shown = [unicode_name(s.name) if "__" not in s.name else to_text(setting.as_typed(s)) for s in coordinates]
    return f"{article} term in {', '.join(shown)}"


def _shown(expr, setting: Setting) -> str:
    """``expr`` (in plain symbols) as a sentence shows it: ω² sin(θ), sin(2θ)."""
    if isinstance(expr, _TRIG) and expr.args[0] in setting.angles:
        # sin θ, cos(θ₁ − θ₂): the problem's own, named in answer after answer, and printing one
        # costs sympy a millisecond of rebuilding and sorting: each is said once per problem
        if expr not in setting.said:
            setting.said[expr] = in_sentence(to_text(setting.as_typed(expr)))
        return setting.said[expr]
    return in_sentence(to_text(setting.as_typed(expr)))


def in_sentence(text: str, times: str = " ") -> str:
    """An expression read back (:func:`~grader.parse.readback.to_text`) as a sentence writes it:
    ω² sin(θ) and sin(2θ), not ω^2*sin(θ) and sin(2*θ), as code would; a product by ``times``
    (N·m for a unit), and none after a digit."""
    text = _POWER.sub(lambda found: superscript(int(found[1])), text)
    return _PRODUCT.sub(lambda found: "" if found[1] in "0123456789" else times, text).replace(" - ", " − ")


_POWER = re.compile(r"\^(-?[0-9]+)(?![0-9.])")  # not x^2.5
_PRODUCT = re.compile(r"(?<=(.))\*(?!\*)")


def _summed(term, velocities: set) -> bool:
    """Whether a term is a product with a sum of terms in different velocities: a student's kinetic
    energy kept in brackets, ``m l² (θ̇² + sin²θ φ̇²)``."""
    sums = [factor for factor in sympy.Mul.make_args(term) if factor.is_Add]
    return any(
        len({frozenset(part.free_symbols & velocities) for part in added.args} - {frozenset()}) > 1 for added in sums
    )


def _velocities(term, velocities: set, setting: Setting) -> str:
    """The velocities a term is a product of, as typed (" in α̇²", " in θ̇₁ θ̇₂"); "" if it is not one."""
    shown = _powers(term, velocities, setting)
    return f" in {shown}" if shown else ""


def _powers(term, symbols: set, setting: Setting) -> str:
    """The powers of ``symbols`` a term is a product of, as typed ("α̇²", "p_φ²"); "" if it is not one."""
    powers = [(v, p) for v, p in term.as_powers_dict().items() if v in symbols]
    if not powers or not all(p.is_Integer and p > 0 for _, p in powers):
        return ""
    shown = [to_text(setting.as_typed(v)) + ("" if p == 1 else superscript(int(p))) for v, p in powers]
    return " ".join(sorted(shown))


def has_angle_functions(expr, setting: Setting) -> bool:
    """Whether a trigonometric function of a coordinate that is an angle occurs in ``expr``: one
    whose dimension is angle or not given. sin x of a length is a slip of units, not of angles."""
    angles = [q for q in setting.coords if setting.dimensions.get(q, "angle") == "angle"]
    coordinates = {setting.state[(q, 0)] for q in angles}
    return any(f.args[0].free_symbols & coordinates for f in expr.atoms(*_TRIG))


def small_angle(expr, setting: Setting, *, second_order: bool = False) -> list:
    """The small-angle forms of ``expr``: sin u → u, tan u → u, and cos u → 1 or 1 − u²/2
    (``second_order``: 1 − u²/2 alone, as a potential is approximated; m g l cos θ → m g l
    would leave no potential)."""
    coordinates = {setting.state[(q, 0)] for q in setting.coords}

    def involves(u) -> bool:
        return bool(u.free_symbols & coordinates)

    def replace(rules):
        return expr.replace(
            lambda e: isinstance(e, tuple(rules)) and involves(e.args[0]),
            lambda e: rules[type(e)](e.args[0]),
        )

    linear = {sympy.sin: lambda u: u, sympy.tan: lambda u: u}
    cosines = (lambda u: 1 - u**2 / 2,) if second_order else (lambda u: sympy.Integer(1), lambda u: 1 - u**2 / 2)
    forms = [replace({**linear, sympy.cos: cosine}) for cosine in cosines]
    return [form for form in forms if form != expr]


def taylor(expr, setting: Setting, order: int):
    """The expansion of ``expr`` to ``order`` about q = q̇ = q̈ = 0 (the equilibrium at the origin);
    nan where there is none, as for dry friction's sign(q̇), which has no derivative at rest."""
    variables = sorted(expr.free_symbols & set(setting.state.values()), key=str)
    at_zero = dict.fromkeys(variables, 0)
    result = expr.subs(at_zero)
    for degree in range(1, order + 1):
        for combination in itertools.combinations_with_replacement(variables, degree):
            derivative = sympy.diff(expr, *combination).subs(at_zero)
            if derivative.has(sympy.Derivative, sympy.DiracDelta):
                return sympy.nan
            if derivative != 0:
                multiplicity = sympy.Mul(*(sympy.factorial(combination.count(v)) for v in set(combination)))
                result += derivative * sympy.Mul(*combination) / multiplicity
    return result


def symbolic_zero(expr, setting: Setting) -> bool:
    """Whether sympy can show ``expr`` is zero, with the problem's domains as assumptions."""
    assumed = {}
    for symbol in expr.free_symbols:
        domain = setting.domain(symbol)
        flags = {"real": {"real": True}, "positive": {"positive": True}, "negative": {"negative": True}}.get(
            domain, {"real": True}
        )
        assumed[symbol] = sympy.Symbol(symbol.name, **flags)
    return sympy.simplify(expr.xreplace(assumed)) == 0
