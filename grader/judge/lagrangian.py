"""The ``lagrangian`` kind: the same equations of motion, and the same normalization.

Contents:
    euler_lagrange(L, setting)                      d/dt ∂L/∂q̇ − ∂L/∂q, symbolically by the chain rule
    check_lagrangian(expected, answer, deadline)    the kind's checker

A Lagrangian is right up to an additive constant (another zero of the potential)
or a total time derivative of a function of q and t: both leave the equations of
motion unchanged. One with an acceleration in it is wrong, d/dt of f(q̇) too. The
fast path catches the first without any calculus. Otherwise both sets of
Euler–Lagrange expressions are evaluated at sample states: equal is full credit;
a constant multiple k ≠ 1 has the right dynamics but not L = T − V, which earns
the part's ``factor_credit``. They are evaluated by forward-mode differentiation
(no sympy ``diff``, which costs milliseconds on an answer it has not seen), with
the symbolic equations as the judge where rounding leaves a state unsure.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
import sympy

from grader.errors import ReferenceAnswerError
from grader.judge.deadline import Deadline
from grader.judge.diagnose import expand_terms, small_angle, taylor, term_changes, terms
from grader.judge.expected import Expected, Outcome, prepare
from grader.judge.expression import expected_terms, same_values, single_term_change, term_outcome
from grader.judge.numeric import FLOAT_EQUAL, PRECISE_DIGITS, UNDEFINED, Closeness, Compiled, NotCompilable, closeness
from grader.judge.sampling import (
    GROUP,
    MIN_DEFINED,
    constant_difference,
    constant_ratio,
    nice_number,
    precise_side_by_side,
    short_fraction,
    side_by_side,
)
from grader.judge.setting import MAX_ORDER, Setting
from grader.parse import TIME, ParsedAnswer
from grader.parse.names import unicode_name
from grader.parse.readback import to_text

__all__ = ["check_lagrangian", "equations_of_motion", "euler_lagrange"]


def euler_lagrange(lagrangian, setting: Setting) -> list:
    """The Euler–Lagrange expressions, one per coordinate, in plain symbols.

    The total time derivative is taken by the chain rule on plain symbols, which is
    several times faster than differentiating functions of time.
    """
    expressions = []
    for q in setting.coords:
        momentum = sympy.diff(lagrangian, setting.velocity(q))
        total = sympy.diff(momentum, TIME)
        for r in setting.coords:
            total += sympy.diff(momentum, setting.state[(r, 0)]) * setting.velocity(r)
            total += sympy.diff(momentum, setting.velocity(r)) * setting.acceleration(r)
        expressions.append(total - sympy.diff(lagrangian, setting.state[(q, 0)]))
    return expressions


def equations_of_motion(lagrangian: str, *, coords, known=(), domains=None, dimensions=None) -> str:
    """The equations of motion of a Lagrangian, as answer-language text (``eq1 = 0; eq2 = 0``);
    ``coords``, ``known``, ``domains`` and ``dimensions`` as :func:`~grader.judge.compare` takes them.

    Raises:
        ReferenceAnswerError: when the Lagrangian cannot be read, or its equations do not
            determine the accelerations (``m g l cos θ`` has no kinetic term: ``sin θ = 0``
            is no equation of motion).
    """
    expected = prepare(
        lagrangian, "lagrangian", tuple(coords), tuple(known), tuple(sorted((domains or {}).items())),
        dimensions=tuple(sorted((dimensions or {}).items())),
    )  # fmt: skip
    if not _determines_accelerations(expected):
        raise ReferenceAnswerError(
            f"no equations of motion follow from the Lagrangian {lagrangian!r}: they do not determine every"
            " acceleration (its second derivatives in the velocities are singular; is a kinetic term missing?)"
        )
    back = {symbol: node for node, symbol in expected.setting.aliases.items()}
    equations = euler_lagrange(expected.value, expected.setting)
    return "; ".join(f"{to_text(sympy.expand(e).xreplace(back))} = 0" for e in equations)


def _determines_accelerations(expected: Expected) -> bool:
    """Whether Lagrange's equations can be solved for the accelerations: ∂²L/∂q̇ᵢ∂q̇ⱼ is regular.

    Its determinant is evaluated at the sample states at 40 digits (``simplify`` takes seconds on
    a double pendulum's): it is singular only where it is 0 at every state the numbers can tell.
    """
    setting = expected.setting
    determinant = sympy.hessian(expected.value, [setting.velocity(q) for q in setting.coords]).det(method="berkowitz")
    if determinant == 0:
        return False
    compiled, told = Compiled(determinant, expected.variables), False
    for point in expected.points(expected.point_count, group=GROUP).tolist():
        try:
            value, scale = compiled.precise(point)
        except UNDEFINED:
            continue
        except NotCompilable:  # |θ̇|'s second derivative is a delta: the numbers cannot say
            return True
        seen = closeness(value, 0, scale, precise=True)
        if seen is Closeness.DIFFERENT:
            return True
        told = told or seen is Closeness.EQUAL
    return not told  # unsure at every state (or defined at none): not called singular


def check_lagrangian(expected: Expected, answer: ParsedAnswer, deadline: Deadline) -> Outcome:
    lagrangian = expected.value
    # As parsed: the evaluators read θ(t) and its derivatives as they are, and the one compiled
    # here serves every comparison below. Plain symbols are built only for sympy's own work.
    submitted = answer.value
    equal, pairs = same_values(expected, lagrangian, submitted, deadline)
    if equal:
        return Outcome("equivalent", 1.0, "equivalent")
    if constant_difference(pairs):
        return Outcome("equivalent", 1.0, "equivalent_up_to_constant")
    beyond = _beyond_velocities(submitted, expected.setting)
    if beyond and not _beyond_velocities(expected.parsed.value, expected.setting):
        # the evaluators differentiate along q, q̇ and t only, and read θ̈ as fixed: m l² θ θ̈ would
        # pass for −m l² θ̇² (it is d/dt(m l² θ θ̇) − m l² θ̇²), and d/dt of any f(q̇) for nothing
        return Outcome("not_equivalent", 0.0, "lagrangian_accelerations", {"names": ", ".join(beyond)})
    deadline.check()
    if "jumps" not in expected.cache:  # the expected answer's, the same for every submission
        expected.cache["jumps"] = _jumps(expected.parsed.value)
    if _jumps(submitted) and not expected.cache["jumps"]:
        # m g l sgn θ: Lagrange's equations are the same wherever they are evaluated, yet the step
        # gives a kick where θ passes 0 that no sample state sees
        return Outcome("undecided", 0.0, "undecided", method="euler-lagrange: a step in the Lagrangian")
    ratio, named = _dynamics_ratio(expected, submitted, deadline)
    if ratio is Closeness.UNSURE:  # too few states where even 40 digits see every term
        return Outcome("undecided", 0.0, "undecided", method="euler-lagrange: the numbers cannot tell")
    if ratio is not None and _kinked_in_velocity(submitted) and not _kinked_in_velocity(expected.parsed.value):
        # m l² |θ̇|: its momentum steps where θ̇ passes 0, a kick no sample state sees, as a step's
        return Outcome("undecided", 0.0, "undecided", method="euler-lagrange: a kink in a velocity")
    if ratio is not None:
        credit = float(expected.option("factor_credit", 0.5))
        if named and abs(ratio - 1) < 1e-9:
            return Outcome("equivalent", 1.0, "lagrangian_gauge", method="euler-lagrange")
        if named and abs(ratio + 1) < 1e-9:
            return Outcome("not_equivalent", credit, "v_minus_t", method="euler-lagrange")
        factor = nice_number(ratio) if named else None
        if factor is None:
            return Outcome("not_equivalent", credit, "normalization_scaled", method="euler-lagrange")
        return Outcome("not_equivalent", credit, "normalization", {"factor": factor}, "euler-lagrange")
    return _diagnose(expected, lagrangian, submitted, deadline)


def _beyond_velocities(value, setting: Setting) -> list[str]:
    """The derivatives of the coordinates past the velocities in ``value`` (as parsed), as typed: θ̈, θ⃛."""
    present = value.atoms(sympy.Derivative)
    orders = range(2, MAX_ORDER + 1)
    return [unicode_name(q, order) for q in setting.coords for order in orders if setting.node(q, order) in present]


_INVERSE_TRIGONOMETRIC = (sympy.asin, sympy.acos, sympy.atan, sympy.acot, sympy.asec, sympy.acsc)


def _kinked_in_velocity(value) -> bool:
    """Whether ``value`` (as parsed) has |…| of a velocity, √(θ̇²) (which the parser keeps as
    typed), or an inverse trigonometric function of one (acos(cos θ̇)): ∂L/∂q̇ then steps along the motion."""
    even = {power: power.base.args[0] ** power.exp for power in value.atoms(sympy.Pow)
            if isinstance(power.base, sympy.Abs) and power.exp.is_even}  # fmt: skip
    if any(kink.args[0].has(sympy.Derivative) for kink in value.xreplace(even).atoms(sympy.Abs)):
        return True  # |θ̇|, not |θ̇|², which is θ̇²
    if any(inverse.args[0].has(sympy.Derivative) for inverse in value.atoms(*_INVERSE_TRIGONOMETRIC)):
        return True  # acos(cos θ̇) is |θ̇| where the states are drawn, and asin(sin θ̇) kinks at π/2
    return any(
        power.exp.is_Rational and not power.exp.is_integer and any(
            factor.is_Pow and factor.exp.is_even and factor.base.has(sympy.Derivative)
            for factor in sympy.Mul.make_args(power.base)
        )
        for power in value.atoms(sympy.Pow)
    )  # fmt: skip


def _jumps(value) -> bool:
    """Whether ``value`` (as parsed) steps along the motion: a sign of something that moves."""
    return any(step.args[0].has(TIME) for step in value.atoms(sympy.sign, sympy.Heaviside))


def _dynamics_ratio(expected: Expected, submitted, deadline: Deadline) -> tuple[complex | Closeness | None, bool]:
    """(k, named) when the submitted equations of motion are k times the expected ones.

    k may depend on the parameters (L/m is as good as 2L), so it is found afresh for
    each draw of the parameters; ``named`` says whether it was the same number in all.
    Returns (None, False) when the equations are not proportional, and
    (Closeness.UNSURE, False) when the numbers cannot tell.

    The equations are evaluated by forward-mode differentiation (:func:`_dynamics`);
    where rounding leaves a state unsure, or they look proportional but a sum lost a term
    (m θ̈ beside e^(10(m + 2)) sin θ), they are derived symbolically and evaluated at 40 digits.
    """
    deadline.check()
    columns, lost = _dynamics(expected, submitted)
    proportional = _proportional(columns)
    if proportional is not None and proportional is not Closeness.UNSURE and not lost:
        lost = _jets_lost(expected, submitted)
    if proportional is Closeness.UNSURE or (lost and proportional is not None):
        deadline.check()
        with mpmath.workdps(PRECISE_DIGITS):
            columns = _symbolic_dynamics(expected, submitted, precise=True)
            return _ratio_of(columns, _proportional(columns, precise=True), precise=True)
    return _ratio_of(columns, proportional, precise=False)


def _ratio_of(columns, proportional, *, precise: bool) -> tuple[complex | Closeness | None, bool]:
    """:func:`_dynamics_ratio`'s answer from the ratios :func:`_proportional` found in ``columns``.

    A ratio that is the same short number in every draw (1, −1, 2, 1/2) is that number only
    if the equations are exactly that multiple at every point: where the equations barely
    change along the motion (m ẍ beside e^(10(m + 2)) g), adding a constant looks like a
    factor 1 + 10⁻²².
    """
    if proportional is None or proportional is Closeness.UNSURE:
        return proportional, False
    first, *others = proportional.values()
    named = all(closeness(first, other, abs(first)) is Closeness.EQUAL for other in others)
    # A ratio is taken on values that may be small beside the terms that made them (L + 1000 θ̇ sin θ
    # cancels 10³ in each equation), so draws agree only to 10⁻¹²: a short number near the first
    # is tried even when they differ, and the check at every point, on the terms' scale, decides.
    k = short_fraction(float(first.real)) if abs(first.imag) <= 1e-9 * abs(first) else None
    if k is None:
        return first, named
    for column in columns:
        for a, scale_a, b, scale_b in column:
            if not math.isfinite(scale_a + scale_b):
                continue
            scale = max(scale_a, scale_b) * max(1.0, abs(float(k)))
            if closeness(a * k.numerator / k.denominator, b, scale, precise=precise) is not Closeness.EQUAL:
                return (None, False) if named else (first, False)
    return complex(float(k)), True


def _proportional(columns: list[list[tuple]], *, precise: bool = False):
    """The ratio in each group of points (a dict), None when the equations are not proportional,
    or Closeness.UNSURE when the numbers cannot tell (unsure somewhere, or too few defined points).

    ``columns`` holds, per coordinate and per point, (expected, its scale, submitted, its scale),
    in floats or (``precise``) at 40 digits.
    """
    ratios: dict[int, complex] = {}
    checked, unsure = 0, False
    for number, values in enumerate(zip(*columns, strict=True)):
        if not all(math.isfinite(scale_a + scale_b) for _, scale_a, _, scale_b in values):
            continue  # undefined here
        scale = max(max(scale_a, scale_b) for _, scale_a, _, scale_b in values)
        group = number // GROUP
        if group not in ratios:
            a, _, b, _ = max(values, key=lambda value: abs(value[0]))
            if closeness(a, 0, scale, precise=precise) is Closeness.EQUAL:
                continue
            if closeness(b, 0, scale, precise=precise) is Closeness.EQUAL:
                return None
            ratios[group] = b / a
        ratio = ratios[group]
        for a, _, b, _ in values:
            same = closeness(ratio * a, b, scale * max(1.0, abs(ratio)), precise=precise)
            if same is Closeness.DIFFERENT:
                return None
            unsure |= same is Closeness.UNSURE
        checked += 1
    if unsure:
        return Closeness.UNSURE
    return ratios if checked >= MIN_DEFINED else Closeness.UNSURE


def _dynamics(expected: Expected, submitted) -> tuple[list[list[tuple]], bool]:
    """Both sets of Euler–Lagrange expressions at the sample states, as :func:`_proportional` reads
    them, and whether d/dt ∂L/∂q̇ − ∂L/∂q lost a term at any state (see :mod:`grader.judge.numeric`;
    the sums inside either part are :func:`_jets_lost`'s).

    No calculus on symbols: d/dt ∂L/∂q̇ is the mixed second derivative of L along q̇ and
    along the motion (q̇, q̈ and 1 for q, q̇ and t), and ∂L/∂q its derivative along q,
    all by forward-mode differentiation at every state at once.
    """
    points, first, second = _directions(expected)
    n = len(expected.setting.coords)
    count = len(points) // (2 * n)  # rows: per coordinate the states along (q̇, motion), then along q

    lost = False

    def euler_lagrange_at(lagrangian: Compiled) -> list[tuple[list, list]]:
        nonlocal lost
        slope, mixed, scale = lagrangian.derivatives(points, first, second)
        expressions = []
        for i in range(n):
            along, across = slice(i * count, (i + 1) * count), slice((n + i) * count, (n + i + 1) * count)
            values = mixed[along] - slope[across]
            # d/dt ∂L/∂q̇ − ∂L/∂q is a sum too: m θ̈ is lost beside e^(10(m + 2)) sin θ
            sizes = np.abs(mixed[along]), np.abs(slope[across])
            smaller, larger = np.minimum(*sizes), np.maximum(*sizes)
            lost |= bool(np.any((smaller > 0) & (smaller < FLOAT_EQUAL * larger)))
            expressions.append((values.tolist(), np.maximum(scale[along], scale[across]).tolist()))
        return expressions

    mine = euler_lagrange_at(expected.compiled("value", expected.value))
    theirs = euler_lagrange_at(expected.compile(submitted))
    columns = [
        list(zip(a, scale_a, b, scale_b, strict=True)) for (a, scale_a), (b, scale_b) in zip(mine, theirs, strict=True)
    ]
    return columns, lost


def _jets_lost(expected: Expected, submitted) -> bool:
    """Whether a sum inside either Lagrangian or its derivatives lost a term at a sample state."""
    points, first, second = _directions(expected)
    lagrangians = (expected.compiled("value", expected.value), expected.compile(submitted))
    return any(bool(lagrangian.derivatives_lost(points, first, second).any()) for lagrangian in lagrangians)


def _directions(expected: Expected) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The sample states, repeated once per coordinate with the directions that give d/dt ∂L/∂q̇
    (first q̇, second the motion: q̇ for q, q̈ for q̇, 1 for t), then once more with those that
    give ∂L/∂q (first q, second none)."""
    if "directions" not in expected.cache:
        points = expected.points(expected.point_count, group=GROUP)
        setting, index = expected.setting, {symbol: i for i, symbol in enumerate(expected.variables)}
        motion = np.zeros_like(points)
        motion[:, index[TIME]] = 1
        for q in setting.coords:
            position, velocity = index[setting.state[(q, 0)]], index[setting.velocity(q)]
            motion[:, position] = points[:, velocity]
            motion[:, velocity] = points[:, index[setting.acceleration(q)]]
        firsts, seconds = [], []
        for symbols, along in (([setting.velocity(q) for q in setting.coords], motion),
                               ([setting.state[(q, 0)] for q in setting.coords], np.zeros_like(points))):  # fmt: skip
            for symbol in symbols:
                unit = np.zeros_like(points)
                unit[:, index[symbol]] = 1
                firsts.append(unit)
                seconds.append(along)
        n = len(setting.coords)
        batch = np.concatenate([points] * 2 * n)
        expected.cache["directions"] = (batch, np.concatenate(firsts), np.concatenate(seconds))
    return expected.cache["directions"]


def _symbolic_dynamics(expected: Expected, submitted, *, precise: bool = False) -> list[list[tuple]]:
    """Both sets of Euler–Lagrange expressions derived symbolically, at the sample states (at 40
    digits with ``precise``, where a point that loses a term even so counts as undefined)."""
    if "euler-lagrange" not in expected.cache:
        expected.cache["euler-lagrange"] = [
            expected.compiled(f"euler-lagrange {i}", e)
            for i, e in enumerate(euler_lagrange(expected.value, expected.setting))
        ]
    theirs = [expected.compile(e) for e in euler_lagrange(expected.setting.plain(submitted), expected.setting)]
    points = expected.points(expected.point_count, group=GROUP)
    evaluate = precise_side_by_side if precise else side_by_side
    return [evaluate(f, g, points) for f, g in zip(expected.cache["euler-lagrange"], theirs, strict=True)]


def _diagnose(expected: Expected, lagrangian, submitted, deadline: Deadline) -> Outcome:
    setting = expected.setting
    if "without total derivatives" not in expected.cache:
        expected.cache["without total derivatives"] = _without_total_derivatives(lagrangian, setting)
    lagrangian = expected.cache["without total derivatives"]
    value = "value" if lagrangian is expected.value else "value, without total derivatives"
    cleaned = _without_total_derivatives(submitted, setting)
    if "mistaken forms" not in expected.cache:
        at_rest = lagrangian.xreplace({setting.velocity(q): 0 for q in setting.coords})
        expanded = taylor(lagrangian, setting, 2)
        # sin θ → θ and cos θ → 1 − θ²/2 alone: the spherical pendulum's ½ m l² θ² φ̇², of fourth
        # order, is what students keep, and the expansion to second order leaves out
        substituted = [form for form in small_angle(lagrangian, setting, second_order=True) if form != expanded]
        forms = (
            ("t_plus_v", lagrangian - 2 * at_rest, "T+V"),  # T − V − 2(−V) = T + V, where T vanishes at rest
            ("small_angle", expanded, "small angle"),
            *(("small_angle", form, f"small angles {number}") for number, form in enumerate(substituted)),
        )
        # not a small-angle form where the Lagrangian has no expansion at rest
        expected.cache["mistaken forms"] = tuple(item for item in forms if not item[1].has(sympy.nan))
    for key, form, name in expected.cache["mistaken forms"]:
        deadline.check()
        _, pairs = same_values(expected, form, cleaned, deadline, key=name)
        if constant_difference(pairs):
            return Outcome("not_equivalent", 0.0, key)
    outcome = _by_terms(expected, value, lagrangian, cleaned, deadline)
    if cleaned is not submitted:
        # ½ m ẋ written for ½ m ẋ² is harmless, but is the student's kinetic energy: told as
        # written ("a term in ẋ is not right") unless that names more terms than it would without
        written = _by_terms(expected, value, lagrangian, submitted, deadline)
        if 0 < _named(written) <= _named(outcome) or not _named(outcome):
            return written
    return outcome


def _by_terms(expected: Expected, value: str, lagrangian, submitted, deadline: Deadline) -> Outcome:
    """The terms of ``submitted`` that differ from those of ``lagrangian`` (named ``value`` among
    the expected answer's expressions); where too many do, whether T or V is right."""
    setting = expected.setting
    # the terms that vary along the motion: another zero of the potential is no mistake
    state = set(setting.state.values()) | {TIME}
    change = single_term_change(expected, value, lagrangian, submitted, state)
    if change:
        return term_outcome([change])
    plain = setting.plain(submitted)
    submitted_terms = terms(plain, varying=state)
    outcome = term_outcome(term_changes(expected_terms(expected, value, lagrangian, state), submitted_terms, setting))
    if outcome.key != "wrong":
        return outcome
    deadline.check()
    return _by_energies(expected, lagrangian, plain, deadline) or outcome


def _named(outcome: Outcome) -> int:
    """How many mistakes ``outcome`` names: none for a bare "not right"."""
    return 0 if outcome.key == "wrong" else 1 + len(outcome.more)


def _without_total_derivatives(value, setting: Setting):
    """``value`` (as parsed) without its terms that are total time derivatives on their own, and
    so change no equation of motion: f(q) q̇ for one coordinate q (d/dt of ∫f dq), and f(t).

    Named as a term too many, m R² ω θ̇ in ½ m R² (θ̇ + ω)² would send the student after a term
    that does no harm, beside the one that does. ``value`` itself where it has no such term, or
    too many terms to look.
    """
    plain = setting.plain(value)
    expansion = expand_terms(plain)
    if expansion is None:
        return value
    harmless = [coefficient * shape for shape, coefficient in expansion.items() if _total_derivative(shape, setting)]
    if not harmless:
        return value
    return setting.as_typed(plain - sympy.Add(*harmless))


def _total_derivative(shape, setting: Setting) -> bool:
    """Whether the term ``shape`` (in plain symbols) is f(q) q̇ for one coordinate q, or f(t)."""
    moving = set(setting.state.values())
    symbols = shape.free_symbols
    if not symbols & moving:
        return TIME in symbols
    rates = [setting.velocity(q) for q in setting.coords if setting.velocity(q) in symbols]
    if len(rates) != 1:
        return False
    coefficient, factor = shape.as_independent(rates[0], as_Add=False)
    coordinate = {setting.state[(q, 0)] for q in setting.coords if setting.velocity(q) == rates[0]}
    return factor == rates[0] and not coefficient.free_symbols & (moving - coordinate | {TIME})


def _by_energies(expected: Expected, lagrangian, plain, deadline: Deadline) -> Outcome | None:
    """Where too many terms differ to name them: which part is right, the terms with velocities
    (T) or those without (−V, up to a constant: another zero), and how the other is off: missing,
    a multiple of the right one, or in its small-angle form. None where neither is right."""
    setting = expected.setting
    rest = {setting.velocity(q): sympy.S.Zero for q in setting.coords}  # not 0: θ̇ alone becomes the int 0
    if "energies" not in expected.cache:
        at_rest = lagrangian.xreplace(rest)
        expected.cache["energies"] = (lagrangian - at_rest, at_rest, taylor(at_rest, setting, 2))
    kinetic, potential, small = expected.cache["energies"]
    theirs_at_rest = plain.xreplace(rest)
    equal, pairs = same_values(expected, kinetic, plain - theirs_at_rest, deadline, key="kinetic part")
    deadline.check()
    if equal:  # T is right: how is V off?
        if not theirs_at_rest.free_symbols & set(setting.state.values()):
            return Outcome("not_equivalent", 0.0, "potential_missing", method="euler-lagrange: energies")
        _, pairs = same_values(expected, potential, theirs_at_rest, deadline, key="potential part")
        if not small.has(sympy.nan) and small != potential:
            _, near = same_values(expected, small, theirs_at_rest, deadline, key="small-angle potential part")
            if constant_difference(near):
                return Outcome("not_equivalent", 0.0, "potential_small_angle", method="euler-lagrange: energies")
        return Outcome("not_equivalent", 0.0, "potential_wrong", _factor_note(pairs), method="euler-lagrange: energies")
    _, pairs = same_values(expected, potential, theirs_at_rest, deadline, key="potential part")
    if constant_difference(pairs):
        return Outcome("not_equivalent", 0.0, "kinetic_wrong", method="euler-lagrange: energies")
    return None


def _factor_note(pairs) -> dict:
    """``{"factor": ": they are 2 times the right ones"}`` where the terms are a multiple of the right ones."""
    ratio = constant_ratio(pairs)
    factor = nice_number(ratio) if ratio is not None else None
    return {"factor": f": they are {factor} times the right ones" if factor else ""}
