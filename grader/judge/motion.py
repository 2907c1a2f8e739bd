"""The ``equation`` and ``equations`` kinds: the same relation, the same motion.

Contents:
    check_equation(expected, answer, deadline)    one equation
    check_equations(expected, answer, deadline)   a system of equations of motion
    accelerations_in(expr, expected)              the coordinates whose acceleration it holds

An equation of motion is linear in the accelerations: Σₖ cₖ(q, q̇, t) q̈ₖ + b(q, q̇, t) = 0.
At each sample state the coefficients are read off numerically, with no symbolic
solving: b is the equation at q̈ = 0 and cₖ what a step in q̈ₖ adds, divided by the
step; a probe at other accelerations confirms the equation really is linear in them.
The step is 256 times the reference's accelerations at that state (a power of two):
with a unit step, ÿ = 10⁴ g would leave cₖ only the digits that survive 10⁴ − (10⁴ − 1).
Then

* one equation is right when its coefficient vector (c, b) is a nonzero multiple
  of the expected one at every state: multiplied through by anything, rearranged;
* a system is right when it has one equation per coordinate, each is satisfied by
  the accelerations the expected system implies, and together they determine the
  accelerations: reordered, scaled, recombined, or solved for q̈ explicitly.

"Every state" includes two that random draws never give: at rest (every velocity 0) and
at the origin (every coordinate 0). A factor that vanishes there (θ̇, as in dE/dt = 0;
θ or sin θ, cleared from a denominator) leaves an equation that no longer says what q̈
is in those states, where the expected one does. Where the expected system is itself singular
there (the spherical pendulum at its pole, where the φ equation says nothing), each acceleration
it still fixes must be fixed by the submitted one too. A factor that vanishes elsewhere (cos θ,
θ̇ − 1, m₁ − m₂) changes sign between two drawn states, and the segment between them is searched
for its zero; a factor that changes sign at a pole (1/cos θ) is no mistake. A factor of the
state that falls to zero without changing sign (1 + cos θ, (θ̇ − 1)²) dips between two states:
each dip that looks like a zero is narrowed to see whether it is one. A factor of the parameters
alone is not searched so: (m₁ − m₂)² is written by nobody, and 1/l by most right answers. Nor are
equations whose own coefficients are of the parameters alone (solved, θ̈ = …): their factor is
zero only where the expected equations are undefined.

An equation without accelerations (a constraint, a conserved quantity) is right
when submitted/expected is, at fixed parameters, the same nonzero number
whatever the state.
"""

from __future__ import annotations

import enum
import functools
import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass, replace
from fractions import Fraction
from functools import cached_property

import mpmath
import numpy as np
import sympy

from grader.judge.deadline import Deadline
from grader.judge.diagnose import (
    MAX_TERMS,
    TERM_KEYS,
    coefficients_differ,
    expand_terms,
    has_angle_functions,
    small_angle,
    taylor,
    terms,
)
from grader.judge.expected import Expected, Outcome
from grader.judge.expression import diagnose_difference, same_values, term_outcome
from grader.judge.numeric import FLOAT_EQUAL, PRECISE_DIGITS, UNDEFINED, Closeness, Compiled, closeness
from grader.judge.sampling import GROUP, MIN_DEFINED, precise_side_by_side, side_by_side
from grader.parse import ParsedAnswer
from grader.parse.names import unicode_name

__all__ = ["accelerations_in", "check_equation", "check_equations"]

# accelerations at which linearity is confirmed; the first below 0, where every step is above: |θ̈| is
# linear for θ̈ > 0
_PROBE = (-1.3, 0.7, 0.45, 1.9)
_GROUPS, _STATES = 4, 3  # parameter draws × state draws for the ratio test
_WIDE = 10**8  # numbers further apart than this may hide a term from floats: check exactly
_DYADIC = 1024  # the exact check's state is rounded to multiples of 1/1024
_STEP_MARGIN = 256  # the step is this many times the largest acceleration
_STEP_ROUNDS = 4  # rounds of reading the reference's rows for the steps
_MAX_STEP_EXPONENT = 200  # steps up to 2²⁰⁰: beyond, a value's square would overflow a float
_SPECIAL = 2  # states after the drawn ones (expected.point_count): at rest, and at the origin
# a segment between two states is searched for where a factor changes sign in rounds of _ALONG states:
# 32¹¹ ≈ 4·10¹⁶ narrows it below a float's resolution, where a zero's row is zero to rounding
_ALONG, _ROUNDS = 33, 11
# a factor this many times its size at both ends is near a pole (E/sin θ), not a zero: no need to go on
_POLE = 1e4
# factors at the sample states within this of each other (relative) are one constant factor
_CONSTANT = 1e-9
# a dip of |factor| whose parabola falls below this part of its neighbours may touch zero (of a
# double zero's, the parabola misses zero by about h²/12 of them, h the samples' spacing: < 0.01)
_DIP = 0.05
_MOST_DIPS = 32  # dips narrowed at most, in one numpy pass a round
# a factor narrowed to this part of its size along the segment has fallen to rounding there: a zero,
# though every term of the submitted equations holds it (θ̈ cos θ + (g/l) sin θ cos θ), so that their
# own rounding, of terms as small as the factor, cannot call their rows zero
_VANISHED = 1e-12
# a factor of the parameters alone is sought from 1/_SPREAD of each one's drawn value to _SPREAD times it
_SPREAD = 64.0
_SMOOTH = 2.0  # a pole of the expected equations grows at least 3 times over a dip's samples


def _as_zero(value) -> sympy.Expr:
    return value.lhs - value.rhs if isinstance(value, sympy.Eq) else value


def _equations(value) -> tuple:
    return tuple(_as_zero(item) for item in (value if isinstance(value, tuple) else (value,)))


def _expected_equations(expected: Expected) -> tuple[tuple, tuple[tuple[str, ...], ...]]:
    """The expected answer's equations (each as an expression = 0), and the coordinates whose
    accelerations each holds: built once, not for every answer (lhs − rhs is a new sum to sympy)."""
    if "equations as zero" not in expected.cache:
        equations = _equations(expected.value)
        expected.cache["equations as zero"] = equations, tuple(tuple(accelerations_in(f, expected)) for f in equations)
    return expected.cache["equations as zero"]


class _Rows:
    """Coefficient rows (c₁…cₙ, b) of equations at one state, and whether they are linear in q̈.

    Built from each equation's values at the acceleration settings of :func:`_settings`
    (q̈ = 0, a ``step`` in each q̈ₖ, the probe) and its scale at each (the largest term
    summed there). Every entry has its own rounding scale: b's is the equation's scale at
    q̈ = 0, and cₖ's the larger of that and the scale at its step, divided by the step. So
    each equation is judged on its own scale (in ẍ = m, ÿ = 10¹³ g the first must not look
    like zero), and a large step leaves neither b nor cₖ looking rounder than it is.
    """

    def __init__(self, samples: Sequence[tuple[Sequence, Sequence[float]]], precise: bool, step: float = 1.0):
        self.step = step
        self.rows, self.entry_scales, self.linear, self.linear_each = [], [], Closeness.EQUAL, []
        for values, scales in samples:
            (b, *stepped, probed), (b_scale, *stepped_scales, probe_scale) = values, scales
            c = [(value - b) / step for value in stepped]
            c_scales = [max(scale, b_scale) / step for scale in stepped_scales]
            probe = _probe_as(type(step), len(c))  # fractions for exact rows
            predicted = b + sum(ck * pk for ck, pk in zip(c, probe, strict=True))
            noise = max(probe_scale, b_scale + sum(s * abs(p) for s, p in zip(c_scales, probe, strict=True)))
            self.linear_each.append(closeness(probed, predicted, noise, precise=precise))
            self.linear = _worst(self.linear, self.linear_each[-1])
            self.rows.append([*c, b])
            self.entry_scales.append([*c_scales, b_scale])

    def scale_at(self, i: int, accelerations) -> float:
        """The rounding scale of equation ``i`` evaluated at ``accelerations``: its constant's,
        and each coefficient's times its acceleration."""
        *c_scales, b_scale = self.entry_scales[i]
        return b_scale + sum(s * abs(a) for s, a in zip(c_scales, accelerations, strict=True))

    @cached_property
    def accelerations(self) -> list | None:
        """The accelerations these equations determine, if they do (None when singular)."""
        n = len(self.rows[0]) - 1 if self.rows else 0
        return _solve([row[:n] for row in self.rows], [-row[n] for row in self.rows])

    @cached_property
    def uncertainty(self) -> list[float]:
        """How large each acceleration's rounding can be: |A⁻¹| times the equations' scales there.

        Where the equations are coupled, an acceleration inherits the scale of every
        equation it is solved from; where they are not, only its own.
        """
        n = len(self.rows[0]) - 1
        matrix = [row[:n] for row in self.rows]
        columns = [_solve(matrix, [float(i == j) for i in range(n)]) for j in range(n)]
        accelerations = self.accelerations or [0.0] * n
        scales = [self.scale_at(i, accelerations) for i in range(len(self.rows))]
        if any(column is None for column in columns):
            return [max(scales, default=0.0)] * n
        return [sum(abs(columns[i][k]) * scales[i] for i in range(n)) for k in range(n)]


def _probe(n: int) -> list[float]:
    return [_PROBE[k % len(_PROBE)] * (1 + k // len(_PROBE)) for k in range(n)]


@functools.cache
def _probe_as(number: type, n: int) -> tuple:
    """:func:`_probe` in the number type of the rows, made once: every row of every state reads it."""
    return tuple(number(p) for p in _probe(n))


def _settings(n: int, step: float = 1.0) -> list[list[float]]:
    """The accelerations each equation is evaluated at: zero, ``step`` along each, the probe."""
    return [[0.0] * n, *([step * (k == j) for k in range(n)] for j in range(n)), _probe(n)]


def _step(rows: _Rows | None, step: float) -> float:
    """The step for reading coefficients at a state: the power of two at or above 256 times the
    largest acceleration the reference's equations imply there, |b| / max |cₖ| (at least 1),
    from ``rows`` read with ``step``. Coefficients that rounded away entirely (ÿ beside e⁴⁰)
    ask for a step 2⁵² times larger.

    At the step, cₖ·step then outweighs b 256 to 1, so cₖ's rounding scale is cₖ's own
    (within 0.4 %), not up to twice it: else a difference of 1.4·10⁻¹³ in b, moved into
    cₖ when the rows are compared as multiples, hides under cₖ's wider band."""
    size = 1.0
    for row in rows.rows if rows is not None else ():
        largest = max(abs(c) for c in row[:-1])
        if largest > 0 and math.isfinite(abs(row[-1]) / largest):
            size = max(size, abs(row[-1]) / largest)
        elif largest == 0 and row[-1] != 0:
            size = max(size, step * 2.0**52)
    return 2.0 ** min(math.ceil(math.log2(size * _STEP_MARGIN)), _MAX_STEP_EXPONENT)


def _steps(expected: Expected, reference: Sequence[Compiled]) -> tuple[float, ...]:
    """The step at each sample state: the reference's rows are read with a unit step, and
    again with the steps those imply until they settle (a few rounds; kept per problem)."""
    key = ("steps", tuple(id(f) for f in reference))
    if key not in expected.cache:
        steps = (1.0,) * len(_states_of(expected))
        for _ in range(_STEP_ROUNDS):
            rows = _float_rows(expected, reference, steps, reference=True)
            settled = tuple(_step(state, step) for state, step in zip(rows, steps, strict=True))
            if settled == steps:
                break
            steps = settled
        expected.cache[key] = steps
    return expected.cache[key]


def _worst(a: Closeness, b: Closeness) -> Closeness:
    return max(a, b, key=_BADNESS.__getitem__)


_BADNESS = {Closeness.EQUAL: 0, Closeness.UNSURE: 1, Closeness.DIFFERENT: 2}


def _positions(expected: Expected) -> list[int]:
    index = {symbol: i for i, symbol in enumerate(expected.variables)}
    return [index[expected.setting.acceleration(q)] for q in expected.setting.coords]


def accelerations_in(expr, expected: Expected) -> list[str]:
    """The coordinates whose acceleration occurs in ``expr`` (as parsed, or in plain symbols)."""
    setting = expected.setting
    present = expr.atoms(sympy.Symbol, sympy.Derivative)  # one walk: q̈ as a plain symbol, or as parsed
    return [q for q in setting.coords if setting.acceleration(q) in present or setting.node(q, 2) in present]


def _states_of(expected: Expected) -> np.ndarray:
    """The sample states: the drawn ones, then the first at rest (every velocity 0) and
    the second at the origin (every coordinate 0), where a factor like θ̇ or sin θ vanishes."""
    if "motion states" not in expected.cache:
        drawn = expected.points(expected.point_count, group=GROUP)
        index = {symbol: i for i, symbol in enumerate(expected.variables)}
        velocities = [index[expected.setting.velocity(q)] for q in expected.setting.coords]
        coordinates = [index[expected.setting.state[(q, 0)]] for q in expected.setting.coords]
        special = drawn[:_SPECIAL].copy()
        special[0, velocities] = 0
        special[1, coordinates] = 0
        states = np.vstack([drawn, special])
        states.flags.writeable = False
        expected.cache["motion states"] = states
    return expected.cache["motion states"]


def _accelerated_states(expected: Expected, steps: tuple[float, ...]) -> np.ndarray:
    """Every sample state at each acceleration setting, one row per (state, setting), state-major."""
    key = ("accelerated states", steps)
    if key not in expected.cache:
        batch = _accelerated(expected, _states_of(expected), steps)
        batch.flags.writeable = False
        expected.cache[key] = batch
    return expected.cache[key]


def _accelerated(expected: Expected, states: np.ndarray, steps: Sequence[float]) -> np.ndarray:
    """``states`` (one per row) each at every acceleration setting of its step, state-major."""
    positions = _positions(expected)
    unique, which = np.unique(np.asarray(steps, float), return_inverse=True)  # many states, few steps
    settings = np.array([_settings(len(positions), step) for step in unique.tolist()], complex)[which.ravel()]
    batch = np.repeat(np.asarray(states, complex), settings.shape[1], axis=0)
    batch[:, positions] = settings.reshape(-1, len(positions))
    return batch


def _float_rows(
    expected: Expected, system: Sequence[Compiled], steps: tuple[float, ...], *, reference: bool = False
) -> list[_Rows | None]:
    """The rows of a system at each sample state, read with that state's step, in floats;
    None where it is undefined.

    A ``reference`` system is compiled from the expected answer and kept in its cache (so
    its identity is stable): its rows are the same for every submission and kept too. A
    submitted system's last rows are kept with the system itself (only the very same objects
    reuse them): the vanishing-factor search and the linearity test read them again.
    """
    key = ("rows", tuple(id(f) for f in system), steps)
    if reference and key in expected.cache:
        return expected.cache[key]
    last = None if reference else expected.cache.get("last rows")
    if last is not None and last[:2] == (tuple(system), steps):  # a Compiled equals only itself
        return last[2]
    batch = _accelerated_states(expected, steps)
    width = len(_positions(expected)) + 2
    evaluated = []
    for f in system:
        values, scales = f.many(batch)
        evaluated.append((values.reshape(-1, width).tolist(), scales.reshape(-1, width).tolist()))
    rows = []
    for number, step in enumerate(steps):
        samples = [(values[number], scales[number]) for values, scales in evaluated]
        defined = all(math.isfinite(sum(scales)) for _, scales in samples)
        rows.append(_Rows(samples, precise=False, step=step) if defined else None)
    if reference:
        expected.cache[key] = rows
    else:
        expected.cache["last rows"] = (tuple(system), steps, rows)
    return rows


def _rows_at(
    expected: Expected, system: Sequence[Compiled], point: list, step: float, *, exact: bool, floats: bool = False
) -> _Rows:
    """The rows of a system at one state, at 40 digits, in floats (``floats``, not remembered) or
    (``exact``, for rational functions) in fractions; raises where it is undefined."""
    positions = _positions(expected)
    samples = []
    for f in system:
        values, scales = [], []
        for accelerations in _settings(len(positions), step):
            moved = list(point)
            for position, acceleration in zip(positions, accelerations, strict=True):
                moved[position] = complex(acceleration)
            value, size = f.exact(moved) if exact else f.at(moved) if floats else f.precise(moved)
            if floats and not math.isfinite(size):
                raise ZeroDivisionError("undefined here")
            values.append(value)
            scales.append(size)
        samples.append((values, scales))
    return _Rows(samples, precise=not floats, step=Fraction(step) if exact else step)


def _at_each_state(
    expected: Expected, systems: Sequence[Sequence[Compiled]], deadline: Deadline, judge, unsure, agrees
):
    """``(state number, judge(rows of each system, precise))`` at each sample state where every
    system is defined; the states are :func:`_states_of`, numbered from 0.

    The first system is the reference, compiled from the expected answer.

    Where ``unsure(result)``, or where it ``agrees`` but a sum lost a term in floats, the
    state is judged again on rows evaluated at 40 digits; results that are None (the
    state says nothing) are dropped. When every result
    ``agrees``, the systems are rational functions and their numbers span more than
    :data:`_WIDE`, one state is judged once more in exact fractions: it sees the 0.001
    beside 10¹² g that floats round away. (Numbers of like size cannot hide a term
    below the floats' 10⁻¹³, so the fractions, a millisecond each, are spared there.)
    """
    steps = _steps(expected, systems[0])
    floats = [_float_rows(expected, system, steps, reference=number == 0) for number, system in enumerate(systems)]
    results, lost = [], None
    for number, point in enumerate(_states_of(expected)):
        deadline.check()
        rows = [per_state[number] for per_state in floats]
        if None in rows:
            continue
        try:
            result = judge(rows, False)
            redo = unsure(result)
            if not redo and result is not None and agrees(result):  # unless floats lost a term here
                lost = lost if lost is not None else _lost_states(expected, systems, steps)
                redo = bool(lost[number])
            if redo:
                # Rows, solving and residuals are sums of 40-digit values: all of it at 40 digits,
                # or each sum rounds to a float's 16 and nothing looks linear any more.
                with mpmath.workdps(PRECISE_DIGITS):
                    precise = [
                        _rows_at(expected, system, point.tolist(), steps[number], exact=False) for system in systems
                    ]
                    result = judge(precise, True)
        except UNDEFINED:
            continue
        if result is not None:
            results.append((number, result))
    functions = [f for fs in systems for f in fs]
    if results and all(agrees(r) for _, r in results) and all(f.rational for f in functions) and _wide(functions):
        exact = _exactly(expected, systems, steps, judge)
        if exact is not None:
            results.append(exact)
    return results


def _wide(functions: Sequence[Compiled]) -> bool:
    """Whether the numbers written in these functions span more than :data:`_WIDE`."""
    numbers = [abs(n) for f in functions for n in f.expr.atoms(sympy.Rational) if n != 0]
    return bool(numbers) and max(numbers) > _WIDE * min(numbers)


def _lost_states(expected: Expected, systems: Sequence[Sequence[Compiled]], steps: tuple[float, ...]) -> np.ndarray:
    """Per sample state: whether any equation of the systems lost a term there, at any setting."""
    batch = _accelerated_states(expected, steps)
    lost = np.zeros(len(steps), bool)
    for f in (f for system in systems for f in system):
        lost |= f.lost(batch).reshape(len(steps), -1).any(axis=1)
    return lost


def _exactly(expected: Expected, systems: Sequence[Sequence[Compiled]], steps: tuple[float, ...], judge):
    """``(state number, judge)`` at the first sample state where every system is defined, in fractions.

    The state is rounded to multiples of 1/1024 first: any state will do, and fractions
    of a float's 53 bits grow to hundreds of digits within a few products.
    """
    for number, point in enumerate(_states_of(expected)):
        rounded = [complex(round(value.real * _DYADIC) / _DYADIC) for value in point.tolist()]
        try:
            result = judge([_rows_at(expected, system, rounded, steps[number], exact=True) for system in systems], True)
        except UNDEFINED:
            continue
        if result is not None:
            return number, result
    return None


def _decided(results: list[Closeness]) -> bool | None:
    if Closeness.DIFFERENT in results:
        return False
    if len(results) < MIN_DEFINED or Closeness.UNSURE in results:
        return None
    return True


# -- one equation -----------------------------------------------------------------


def check_equation(expected: Expected, answer: ParsedAnswer, deadline: Deadline) -> Outcome:
    (f,), (accelerations,) = _expected_equations(expected)
    (g,) = _equations(answer.value)
    if not accelerations:
        return _check_relation(expected, f, expected.setting.plain(g), deadline)
    if not accelerations_in(g, expected):
        names = ", ".join(unicode_name(q, 2) for q in accelerations)
        return Outcome("not_equivalent", 0.0, "not_equation_of_motion", {"accelerations": names}, "accelerations")
    expected_f = expected.compiled("equation", f)
    submitted_g = expected.compile(g)

    def proportional(rows, precise):
        mine, theirs = rows
        if mine.linear is not Closeness.EQUAL:
            return None  # the reference itself is not linear here: no information
        if theirs.linear is not Closeness.EQUAL:
            return theirs.linear
        return _multiple(mine.rows[0], theirs.rows[0], mine.entry_scales[0], theirs.entry_scales[0], precise)

    numbered = _at_each_state(
        expected,
        ([expected_f], [submitted_g]),
        deadline,
        proportional,
        _is_unsure,
        lambda result: result is Closeness.EQUAL,
    )
    results = [result for _, result in numbered]
    same = _decided(results)
    if same and _vanishes_between(expected, [expected_f], [submitted_g]):
        return Outcome("not_equivalent", 0.0, "vanishing_factor_between", method="accelerations")
    if same:
        return Outcome("equivalent", 1.0, "equivalent", method="accelerations")
    if same is None:
        return Outcome("undecided", 0.0, "undecided", method="accelerations: too few defined states")
    if _decided([result for number, result in numbered if number < expected.point_count]):
        # right wherever states are drawn, wrong at rest or at the origin: a vanishing factor
        return Outcome("not_equivalent", 0.0, "vanishing_factor", method="accelerations")
    if _nonlinear(expected, [expected_f], [submitted_g]) == [True]:
        names = ", ".join(unicode_name(q, 2) for q in accelerations)
        return Outcome("not_equivalent", 0.0, "not_linear", {"accelerations": names}, "accelerations")
    return _diagnose_motion(expected, f, expected.setting.plain(g), deadline)


def _vanishes_between(expected: Expected, reference: Sequence[Compiled], submitted: Sequence[Compiled]) -> bool:
    """Whether the submitted equations, right at every sample state, are the expected ones times
    a factor that vanishes between two of the drawn states: (θ̇ − 1)·E, cos θ·E, (m₁ − m₂)·E.
    There they say nothing of an acceleration. (Of a system, the factor is the determinant of
    the combination: det of the submitted coefficients over the expected ones'.)

    Where the factor has one sign at one state and the other at the next, and the expected
    equations' own coefficients keep theirs (else the change is theirs: the spherical pendulum's
    sin θ φ̈ at its pole), the segment between the states (inside the domain: the parameters stay
    positive) is searched for where the factor changes sign; there it is a zero of the submitted
    equations (not a pole of the factor, as in E/θ) or not. A factor of one sign everywhere, as
    every right answer's is, costs one pass over rows already evaluated."""
    if any(expected.setting.domain(symbol) in ("nonzero", "integer") for symbol in expected.variables):
        return False  # a segment between two states could leave the domain
    steps = _steps(expected, reference)
    count = expected.point_count
    mine = _float_rows(expected, reference, steps, reference=True)[:count]
    theirs = _float_rows(expected, submitted, steps)[:count]
    defined = [
        number for number, (a, b) in enumerate(zip(mine, theirs, strict=True)) if a is not None and b is not None
    ]
    if len(defined) < 2:
        return False
    stacked = [np.array([rows[number].rows for number in defined], complex) for rows in (mine, theirs)]
    factors, owns = _scalings(*stacked)
    signs = [
        (number, factor > 0, own > 0)
        for number, factor, own in zip(defined, factors.tolist(), owns.tolist(), strict=True)
        if math.isfinite(factor) and factor and own
    ]
    states = _states_of(expected)
    systems = (reference, submitted)
    if any(
        sign != other
        and own == own_other
        and _silent_between(expected, systems, states[first], states[second], steps[first])
        for (first, sign, own), (second, other, own_other) in itertools.pairwise(signs)
    ):
        return True
    sizes = {number: abs(factor) for number, factor in zip(defined, factors.tolist(), strict=True)}
    if _one_value(list(sizes.values())):
        return False  # the same factor at every state, as a right answer's often is: it vanishes nowhere
    # A factor of the parameters alone (1/l, m l²) is one value within each run of states that share
    # them. It is most right answers' and is not searched between states: such a factor that touches zero
    # without changing sign ((m₁ − m₂)²) is written by nobody, and the search would cost every one of them.
    # But two draws may leave one that changes sign of one sign in both ((l₁ − l₂), R ω² − g): it is
    # sought along each parameter in turn.
    if _of_parameters(sizes):
        return _vanishes_along_parameters(expected, systems, states[defined[0]], steps[defined[0]])
    # Nor where the submitted equations' own coefficient (determinant) is of the parameters alone, as
    # in θ̈₁ = …, θ̈₂ = … solved, or m l² θ̈ + …: the factor is that over the expected equations' own, and
    # is zero only where theirs is infinite, where they are undefined.
    _, their_owns = _scalings(stacked[1], stacked[0])
    if _of_parameters({number: abs(own) for number, own in zip(defined, their_owns.tolist(), strict=True)}):
        return False
    pairs = [
        (first, second)
        for (first, sign, own), (second, other, own_other) in itertools.pairwise(signs)
        if sign == other and own == own_other
    ]
    if not pairs:
        return False
    step = max(max(steps[first], steps[second]) for first, second in pairs)  # a larger step reads as well
    return _touches_between(expected, systems, [(states[first], states[second]) for first, second in pairs], step)


def _vanishes_along_parameters(
    expected: Expected, systems: tuple[Sequence[Compiled], Sequence[Compiled]], state: np.ndarray, step: float
) -> bool:
    """Whether the factor between the submitted equations and the expected ones, a function of the
    parameters alone, changes sign where the submitted say less as one parameter goes from
    1/:data:`_SPREAD` of its value at ``state`` to :data:`_SPREAD` times it, the others held: (l₁ − l₂)·E
    at l₁ = l₂. One numpy pass over the ends of every parameter's segment; a segment is searched
    (:func:`_silent_between`) only where the factor's sign differs at its ends and the expected
    equations' own does not."""
    parameters = [i for i, symbol in enumerate(expected.variables) if not expected.setting.is_state(symbol)]
    if not parameters:
        return False
    ends = np.repeat(state[None, :], 2 * len(parameters), axis=0)
    for k, i in enumerate(parameters):
        ends[2 * k, i] /= _SPREAD
        ends[2 * k + 1, i] *= _SPREAD
    with np.errstate(all="ignore"):  # 64 m in e^(−10 m x) overflows: undefined there, and let go
        factors, owns = _scalings(*(_stacked_rows(expected, system, ends, step) for system in systems))
    for k in range(len(parameters)):
        low, high = factors[2 * k], factors[2 * k + 1]
        if not (math.isfinite(low) and math.isfinite(high) and low and high and (low > 0) != (high > 0)):
            continue
        if (owns[2 * k] > 0) == (owns[2 * k + 1] > 0) and _silent_between(
            expected, systems, ends[2 * k], ends[2 * k + 1], step
        ):
            return True
    return False


def _scalings(mine: np.ndarray, theirs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """At each of a stack of states (rows: states × equations × (accelerations + 1)): the real
    number whose sign says how ``theirs`` scale ``mine`` (for one equation the factor, by least
    squares; for a system the ratio of their coefficients' determinants), and the expected
    equations' own (the leading coefficient; the determinant). NaN where ``mine`` says nothing."""
    n = mine.shape[2] - 1
    if mine.shape[1] == 1:
        f, g = mine[:, 0, :], theirs[:, 0, :]
        size = np.sum(np.abs(f) ** 2, axis=1)
        with np.errstate(divide="ignore", invalid="ignore"):
            factor = (np.sum(g * f.conj(), axis=1) / size).real
        lead = np.argmax(np.abs(f[:, :n]), axis=1)
        return factor, f[np.arange(len(f)), lead].real
    own = np.linalg.det(mine[:, :, :n])
    with np.errstate(divide="ignore", invalid="ignore"):
        factor = (np.linalg.det(theirs[:, :, :n]) / own).real
    return factor, own.real


def _says_less(a: _Rows, b: _Rows, *, vanished: bool = False) -> bool:
    """Whether rows ``b`` leave undetermined what rows ``a`` say at their state: one equation all
    of whose entries are within rounding of zero, or a system that no longer fixes an acceleration;
    with ``vanished`` (the factor from ``a`` to ``b`` has fallen to rounding), whether ``a`` says
    anything there (of a system, fixes every acceleration: at its own singular point, as the
    spherical pendulum's pole, the factor may vanish where ``a`` fixes no more than ``b``).

    What ``a`` says must be plain: an entry of it that rounding cannot tell from zero (closeness
    unsure) says nothing. At the expected equations' own singular point their coefficient may be
    10⁻¹³ of its scale there, or 10⁻¹¹, as near as the search came: sin θ times the spherical
    pendulum's sin²θ φ̈ + 2 sin θ cos θ θ̇ φ̇ fixes no φ̈ at θ = 0, and neither do they."""
    if len(a.rows) == 1:
        said = any(
            closeness(x, 0, scale) is Closeness.DIFFERENT for x, scale in zip(a.rows[0], a.entry_scales[0], strict=True)
        )
        silent = vanished or all(
            closeness(x, 0, scale) is Closeness.EQUAL for x, scale in zip(b.rows[0], b.entry_scales[0], strict=True)
        )
        return said and silent
    if vanished and all(_determined(a, plain=True)):
        return True
    return any(mine and not yours for mine, yours in zip(_determined(a, plain=True), _determined(b), strict=True))


def _silent_between(
    expected: Expected,
    systems: tuple[Sequence[Compiled], Sequence[Compiled]],
    start: np.ndarray,
    end: np.ndarray,
    step: float,
) -> bool:
    """Whether the factor between the submitted equations and the expected ones (the second of
    ``systems`` and the first), of one sign at ``start`` and the other at ``end``, changes sign
    between them where the submitted say less (:func:`_says_less`); in floats. Not where either
    is undefined, or the factor grows without bound (a pole, as of E/sin θ).

    The segment is searched in rounds of :data:`_ALONG` states at once, in one numpy pass per
    equation, each round narrowing it to the two states the sign changes between."""
    low, high, size = start, end, None
    for _ in range(_ROUNDS):
        states = low + np.linspace(0.0, 1.0, _ALONG)[:, None] * (high - low)
        factors, _ = _scalings(*(_stacked_rows(expected, system, states, step) for system in systems))
        if not np.isfinite(factors).all():
            return False  # undefined here, or the expected equations say nothing here either
        size = size if size is not None else max(abs(factors[0]), abs(factors[-1]))
        if np.abs(factors).max() > _POLE * size:
            return False
        changed = np.nonzero((factors > 0) != (factors[0] > 0))[0]
        if not len(changed):
            return False  # the change fell between rounds' states: at a pole's edge, as rounding goes
        change = int(changed[0])
        low, high = states[change - 1], states[change]
    nearest = low if abs(factors[change - 1]) <= abs(factors[change]) else high
    try:
        rows = [_rows_at(expected, system, nearest.tolist(), step, exact=False, floats=True) for system in systems]
    except UNDEFINED:
        return False
    vanished = min(abs(factors[change - 1]), abs(factors[change])) <= _VANISHED * size
    return _says_less(*rows, vanished=vanished)


def _touches_between(
    expected: Expected,
    systems: tuple[Sequence[Compiled], Sequence[Compiled]],
    segments: Sequence[tuple[np.ndarray, np.ndarray]],
    step: float,
) -> bool:
    """Whether the factor between the submitted equations and the expected ones falls to zero
    without changing sign on one of ``segments`` (pairs of states where it has the same sign):
    (1 + cos θ)·E at θ = π, (θ̇ − 1)²·E. There the submitted say less (:func:`_says_less`).

    Each segment is sampled at :data:`_ALONG` states. Each dip of |factor| there that looks like
    a zero (:func:`_dips`) is narrowed, all at once, in rounds of as many states around its lowest,
    to a float's resolution. A dip that is a zero is zero to rounding there; one that is not
    (1.01 + cos θ) is far from it. A dip is let go where the expected equations' own size grows
    :data:`_POLE` times (their pole), or their own coefficient (determinant) falls with the
    factor (their singular point: sin θ φ̈ + 2 cos θ θ̇ φ̇ at θ = 0, where it fixes no φ̈ either)."""
    along = np.linspace(0.0, 1.0, _ALONG)
    lows = np.array([low for low, _ in segments])
    spans = np.array([high for _, high in segments]) - lows
    first = _factor_sizes_at(expected, systems, lows, spans, np.broadcast_to(along, (len(segments), len(along))), step)
    found = [
        (depth, number, i)
        for number, rows in enumerate(zip(*first, strict=True))
        if np.isfinite(rows[0]).all()
        for i, depth in _dips(*rows)
    ]
    if not found:
        return False
    # the most zero-like first: a factor as cos²(50 θ) has hundreds of dips, and one zero is enough
    owners, dips = np.array([(number, i) for _, number, i in sorted(found)[:_MOST_DIPS]]).T
    lows, spans = lows[owners], spans[owners]
    low, high = (dips - 1) / (_ALONG - 1), (dips + 1) / (_ALONG - 1)
    norm0, own0 = first[1][owners, dips], first[2][owners, dips]
    size0 = np.nanmax(first[0][owners], axis=1)  # the factor's size along each dip's segment
    for _ in range(_ROUNDS):
        where = low[:, None] + along[None, :] * (high - low)[:, None]  # brackets × _ALONG fractions
        sizes, norms, owns = _factor_sizes_at(expected, systems, lows, spans, where, step)
        at = np.argmin(np.where(np.isfinite(sizes), sizes, np.inf), axis=1)
        every = np.arange(len(where))
        lowest, width = where[every, at], (high - low) / (_ALONG - 1)
        alive = (norms[every, at] <= _POLE * norm0) & (owns[every, at] >= _DIP * own0)
        if not alive.any():
            return False
        low, high = np.maximum(lowest - width, 0.0)[alive], np.minimum(lowest + width, 1.0)[alive]
        lows, spans, norm0, own0 = lows[alive], spans[alive], norm0[alive], own0[alive]
        least, size0 = sizes[every, at][alive], size0[alive]
    for start, span, fraction, vanished in zip(lows, spans, (low + high) / 2, least <= _VANISHED * size0, strict=True):
        try:
            point = (start + fraction * span).tolist()
            rows = [_rows_at(expected, system, point, step, exact=False, floats=True) for system in systems]
        except UNDEFINED:
            continue
        if _says_less(*rows, vanished=bool(vanished)):
            return True
    return False


def _of_parameters(sizes: dict[int, float]) -> bool:
    """Whether ``sizes`` at the numbered sample states are one value within each run of states that
    share the parameters' values (:data:`GROUP`): a function of the parameters alone."""
    runs = itertools.groupby(sorted(sizes), key=lambda number: number // GROUP)
    return all(_one_value([sizes[number] for number in run]) for _, run in runs)


def _one_value(sizes: Sequence[float]) -> bool:
    return max(sizes) - min(sizes) <= _CONSTANT * max(sizes)


def _dips(row: np.ndarray, norm: np.ndarray, own: np.ndarray) -> list[tuple[int, float]]:
    """Where samples ``row`` of |factor| dip as if to zero, and how deep (the parabola's lowest
    over the lower neighbour): below both neighbours, with the parabola through the three falling
    below :data:`_DIP` of the lower neighbour. A smooth minimum that is not a zero (of 2 + cos θ,
    or of 1/sin²θ between its poles) is shallower.

    Not where the expected equations' own size (``norm``) changes :data:`_SMOOTH` times over the
    three, as at a pole of theirs (sin²θ times φ̈ + 2 cot θ θ̇ φ̇ at θ = 0), nor where their own
    coefficient or determinant (``own``) falls by half at the dip: their singular point, where they
    fix no acceleration either (sin θ φ̈ + 2 cos θ θ̇ φ̇ at θ = 0). A system may still fix another
    there (the spherical pendulum's θ̈ at θ = π), so the θ equation times 1 + cos θ is missed: to
    narrow every such dip to see would cost its right answers 15 ms each."""
    found = []
    for i in range(1, len(row) - 1):
        a, b, c = row[i - 1], row[i], row[i + 1]
        curvature = a - 2 * b + c
        if not (b < a and b <= c and curvature > 0):
            continue
        depth = (b - (c - a) ** 2 / (8 * curvature)) / min(a, c)
        around = norm[i - 1 : i + 2]
        singular = 2 * own[i] <= min(own[i - 1], own[i + 1])
        if depth < _DIP and around.max() <= _SMOOTH * around.min() and not singular:
            found.append((i, depth))
    return found


def _factor_sizes_at(expected, systems, starts, spans, where, step) -> tuple[np.ndarray, ...]:
    """At states ``starts + where · spans``, one row of ``where`` per start: |factor| (NaN where
    either system is undefined or says nothing), and of the first system, the size of its rows
    and |its own coefficient| (:func:`_scalings`)."""
    states = (starts[:, None, :] + where[:, :, None] * spans[:, None, :]).reshape(-1, starts.shape[1])
    mine, theirs = (_stacked_rows(expected, system, states, step) for system in systems)
    factors, owns = _scalings(mine, theirs)
    norms = np.sqrt(np.sum(np.abs(mine) ** 2, axis=(1, 2)))
    return tuple(np.abs(values).reshape(where.shape) for values in (factors, norms, owns))


def _stacked_rows(expected: Expected, system: Sequence[Compiled], states: np.ndarray, step: float) -> np.ndarray:
    """The rows of a system at each of ``states``, stacked: states × equations × (accelerations + 1),
    (c₁…cₙ, b) as :class:`_Rows` reads them; NaN where undefined. Not remembered."""
    n = len(_positions(expected))
    width = n + 2  # the settings: q̈ = 0, a step in each q̈ₖ, the probe
    batch = _accelerated(expected, states, [step] * len(states))
    stacked = []
    for f in system:
        values, scales = f.many_once(batch)
        values = np.where(np.isfinite(scales), values, np.nan).reshape(len(states), width)
        b = values[:, 0]
        c = (values[:, 1 : n + 1] - b[:, None]) / step
        stacked.append(np.concatenate([c, b[:, None]], axis=1))
    return np.stack(stacked, axis=1)


def _nonlinear(expected: Expected, reference: Sequence[Compiled], submitted: Sequence[Compiled]) -> list[bool]:
    """Per submitted equation: whether it is plainly not linear in the accelerations at some sample
    state, as no equation of motion from Lagrange's equations is: ``(l θ̈ + g sin θ)² = 0``."""
    found = [False] * len(submitted)
    for rows in _float_rows(expected, submitted, _steps(expected, reference)):
        for i, linear in enumerate(rows.linear_each if rows is not None else ()):
            found[i] = found[i] or linear is Closeness.DIFFERENT
    return found


def _is_unsure(result) -> bool:
    return result is Closeness.UNSURE


def _multiple(expected_row, submitted_row, expected_scales, submitted_scales, precise: bool) -> Closeness:
    """Whether ``submitted_row`` is a nonzero multiple of ``expected_row`` (each entry judged on
    the larger of the two rows' scales for it); None where the expected equation does not
    involve the acceleration (sin θ φ̈ + … at θ = 0): such a state says nothing."""
    k = max(range(len(expected_row) - 1), key=lambda j: abs(expected_row[j]) / (expected_scales[j] or 1.0))
    if closeness(expected_row[k], 0, expected_scales[k], precise=precise) is Closeness.EQUAL:
        return None  # a degenerate state of the reference
    factor = submitted_row[k] / expected_row[k]
    if closeness(submitted_row[k], 0, submitted_scales[k], precise=precise) is Closeness.EQUAL:
        return Closeness.DIFFERENT
    worst = Closeness.EQUAL
    for a, b, scale_a, scale_b in zip(expected_row, submitted_row, expected_scales, submitted_scales, strict=True):
        worst = _worst(worst, closeness(factor * a, b, max(abs(factor) * scale_a, scale_b), precise=precise))
    return worst


def _diagnose_motion(expected: Expected, f, g, deadline: Deadline, key: str = "equation, normalized") -> Outcome:
    """Compare the two equations solved for the same acceleration, term by term.

    For the numbers, g divided by its coefficient of the acceleration need not be
    expanded (sympy's expansion is most of the cost); only naming the terms when the
    numbers cannot needs g solved and expanded (:func:`_solved`). ``key`` names ``f``
    among the expressions derived from the expected answer, for the cache.
    """
    if key not in expected.cache:
        acceleration = _leading_acceleration(f, expected)
        expected.cache[key] = acceleration, _solved(f, acceleration)
    acceleration, normal_f = expected.cache[key]
    coefficient = _coefficient(g, acceleration)
    if coefficient == 0:
        # solved for another acceleration of the expected equation, one the answer has: s̈ = g sin α₀ for
        # s̈ + Ẍ cos α₀ = g sin α₀ (solved for Ẍ first) lacks a term, and is no other coordinate's equation
        others = [expected.setting.acceleration(q) for q in accelerations_in(f, expected)]
        other = next((a for a in others if a != acceleration and _coefficient(g, a) != 0), None)
        if other is None:  # none of the expected equation's accelerations: another coordinate's equation
            return Outcome("not_equivalent", 0.0, "wrong_equation_single", method="accelerations")
        key = f"{key}, for {other}"
        if key not in expected.cache:
            expected.cache[key] = other, _solved(f, other)
        acceleration, normal_f = expected.cache[key]
        coefficient = _coefficient(g, acceleration)
    # the same terms, off in their parameters: named in the ratio most share, or not at all, since
    # solved for an acceleration whose own factor is off, the right terms would be named instead
    scaled = _off_in_scale(expected, f, g, key)
    if scaled:
        return replace(term_outcome(scaled), method="accelerations")
    if scaled is None:
        return Outcome("not_equivalent", 0.0, "wrong_equation_single", method="accelerations")
    normal_g = g / coefficient
    if normal_f is None:  # a reference of too many terms to name them
        return Outcome("not_equivalent", 0.0, "wrong_equation_single", method="accelerations")
    deadline.check()
    _, pairs = same_values(expected, normal_f, normal_g, deadline, key=key)
    outcome = diagnose_difference(
        expected, normal_f, normal_g, pairs, deadline, key=key,
        # linearized, or sin u → u and cos u → 1 put in: θ̈ = θ φ̇² − (g/l) θ keeps a term of third order
        approximations=lambda expr: [taylor(expr, expected.setting, 1), *small_angle(expr, expected.setting)],
        termwise=lambda: _solved(g, acceleration),
    )  # fmt: skip
    if outcome.key in ("sign", "factor", "wrong"):
        return Outcome("not_equivalent", 0.0, "wrong_equation_single", method="accelerations")
    return Outcome(outcome.status, 0.0, outcome.key, outcome.details, "accelerations", outcome.more)


def _off_in_scale(expected: Expected, f, g, key: str) -> list | None:
    """The terms of ``g`` off from ``f``'s when both are compared in the ratio most of their terms
    share (:func:`~grader.judge.diagnose.coefficients_differ`): m₁ l₁ θ̈₁ for (m₁ + m₂) l₁ θ̈₁.
    [] where they are not the same terms; None where they are, but nothing tells which are off."""
    cache_key = ("terms", key, "as written")
    if cache_key not in expected.cache:
        expected.cache[cache_key] = terms(f)
    ours, theirs = expected.cache[cache_key], terms(g)
    if ours is None or theirs is None or len(ours) > MAX_TERMS or len(theirs) > MAX_TERMS:
        return []
    kept = expected.cache.setdefault(("coefficients", key), {})
    return coefficients_differ(ours, theirs, expected.setting, any_factor=True, kept=kept)


def _leading_acceleration(f, expected: Expected):
    """The acceleration an equation is solved for to compare it term by term: the first whose
    coefficient holds no coordinate or velocity, where there is one.

    Dividing by l₁ cos(θ₁ − θ₂) would turn l₁ θ̇₁² sin(θ₁ − θ₂) into a term in tan(θ₁ − θ₂), one the
    student never wrote; dividing the same equation by l₂, the coefficient of θ̈₂, keeps every
    term as written, and a description names the term the student can find."""
    accelerations = [expected.setting.acceleration(q) for q in accelerations_in(f, expected)]
    for acceleration in accelerations:
        if not any(expected.setting.is_state(symbol) for symbol in _coefficient(f, acceleration).free_symbols):
            return acceleration
    return accelerations[0]


def _coefficient(g, acceleration):
    """The coefficient of ``acceleration`` in ``g``, in which it is linear."""
    return g.xreplace({acceleration: sympy.Integer(1)}) - g.xreplace({acceleration: sympy.Integer(0)})


def _solved(g, acceleration):
    """``g`` divided by its coefficient of ``acceleration``, expanded; None when it has none,
    or more terms than naming them is worth.

    Usually the coefficient is one term, such as m l²: then each term of g expanded is
    divided by it, which costs a third of expanding the quotient (sympy's ``diff`` and
    ``expand`` were most of the time spent on a wrong equation).
    """
    expansion = expand_terms(g)
    if expansion is None or len(expansion) > MAX_TERMS:
        return None  # too many terms to name (and dividing each by a power of a sum would cost seconds)
    terms = [coefficient * shape for shape, coefficient in expansion.items()]
    coefficients = []
    for term in terms:
        coefficient, factor = term.as_independent(acceleration, as_Add=False)
        if factor == acceleration:
            coefficients.append(coefficient)
        elif factor != 1:  # not linear in the acceleration
            coefficients = None
            break
    if coefficients is not None and len(coefficients) <= 1:
        return sympy.Add(*(term / coefficients[0] for term in terms)) if coefficients else None
    if coefficients is not None:
        # (m₁ + m₂) l₁² θ̈₁ + …, expanded into two terms: their sum, factored, so that l₁ cancels from
        # each term as it does from the student's (m₁ + m₂) l₁ θ̈₁ + …, and the shapes of the two agree
        # (multiplied out again, as the expected terms are: 1/(l₁m₁ + l₁m₂) for 1/(l₁(m₁ + m₂)))
        lead = sympy.factor(sympy.Add(*coefficients))
        # the acceleration's own terms come to the acceleration alone: divided one by one, (m₁ + m₂) ẍ
        # would stay m₁ ẍ/(m₁ + m₂) + m₂ ẍ/(m₁ + m₂), two terms no solved answer has
        rest = [term for term in terms if not term.has(acceleration)]
        quotient = expand_terms(sympy.Add(*(term / lead for term in rest)))
        return None if quotient is None else acceleration + sympy.Add(*(c * shape for shape, c in quotient.items()))
    lead = sympy.diff(g, acceleration)
    return None if lead == 0 else sympy.expand(g / lead)


def _check_relation(expected: Expected, f, g, deadline: Deadline) -> Outcome:
    """An equation without accelerations: the same roots, each as often.

    First g = λ f with λ ≠ 0, where λ may depend on the parameters when the relation
    involves the state (p_θ = m l² θ̇ ≡ θ̇ = p_θ/(m l²)), and must be a number when it
    does not. Failing that, the roots are compared directly: ω² = g/l and ω = √(g/l)
    have the same simple root ω > 0, while (s + γ)² = 0 has a double root that s = −γ
    lacks (a critically damped oscillator's characteristic equation).
    """
    involves_state = any(expected.setting.is_state(symbol) for symbol in f.free_symbols)
    group = _STATES if involves_state else _GROUPS * _STATES
    expected_f = expected.compiled("relation", f)
    submitted_g = expected.compile(g)
    deadline.check()
    points = expected.points(_GROUPS * _STATES, salt=1, group=_STATES)
    results = _ratio_test(side_by_side(expected_f, submitted_g, points), group, precise=False)
    redo = Closeness.UNSURE in results
    if not redo and all(result is Closeness.EQUAL for result in results):
        redo = bool((expected_f.lost(points) | submitted_g.lost(points)).any())  # m beside e^(10(m + 2))
    if redo:  # floats could not tell somewhere: all of it again at 40 digits
        with mpmath.workdps(PRECISE_DIGITS):
            results = _ratio_test(precise_side_by_side(expected_f, submitted_g, points), group, precise=True)
    if all(result is Closeness.EQUAL for result in results) and len(results) >= MIN_DEFINED:
        return Outcome("equivalent", 1.0, "equivalent", method="ratio")
    same = _same_roots(expected, expected_f, submitted_g, f.free_symbols | g.free_symbols, deadline)
    if same is _Roots.SAME:
        return Outcome("equivalent", 1.0, "equivalent", method="roots")
    if same is _Roots.MULTIPLICITY:
        return Outcome("not_equivalent", 0.0, "root_multiplicity", method="roots")
    if same is None and Closeness.DIFFERENT not in results:
        return Outcome("undecided", 0.0, "undecided", method="ratio: too few defined points")
    return Outcome("not_equivalent", 0.0, "wrong_equation_single", method="ratio")


def _ratio_test(values, group: int, *, precise: bool) -> list[Closeness]:
    """Per point where both are defined: is g = λ f there, λ fixed within each ``group`` of
    points (``values``: f, its scale, g, its scale at each point)."""
    results = []
    ratios: dict = {}
    for number, (a, scale_a, b, scale_b) in enumerate(values):
        if not math.isfinite(scale_a + scale_b):
            continue  # undefined here
        scale = max(scale_a, scale_b)
        if closeness(a, 0, scale, precise=precise) is Closeness.EQUAL:
            results.append(closeness(b, 0, scale, precise=precise))  # on the expected relation's zero set
            continue
        ratio = ratios.setdefault(number // group, b / a)
        if closeness(ratio, 0, 1.0, precise=precise) is Closeness.EQUAL:
            results.append(Closeness.DIFFERENT)
        else:
            results.append(closeness(ratio * a, b, scale * max(1.0, abs(ratio)), precise=precise))
    return results


_NEAR_ROOT = 1e-3  # relative: how far either side of a root its neighbours are taken, to see it is one

# Where roots are looked for: steps of 1/8 within ±10, and 20 per decade out to 10³ and in to 10⁻³.
_LINEAR = [i / 8 for i in range(1, 81)]
_LOGARITHMIC = [10 ** (k / 20) for k in range(-60, 61)]
_SCAN = sorted(set(_LINEAR + _LOGARITHMIC))


class _Roots(enum.Enum):
    SAME = "the same roots, each as often"
    DIFFERENT = "a root of one is no root of the other"
    MULTIPLICITY = "the same roots, not each as often"


def _grid(domain: str) -> list[float]:
    if domain == "positive":
        return _SCAN
    negative = [-x for x in reversed(_SCAN)]
    return negative if domain == "negative" else [*negative, 0.0, *_SCAN]


def _same_roots(expected: Expected, f: Compiled, g: Compiled, symbols, deadline: Deadline) -> _Roots | None:
    """Whether f = 0 and g = 0 have the same real roots, each of the same multiplicity (order
    of vanishing): along each symbol of either in turn, through sample points.

    Every symbol, because (ω − √(g/l))(ω − 2) = 0 has its extra root along ω alone, and
    p sin θ = … its extra roots along θ alone; and a symbol only one of them has, because
    θ (p_θ − m l² θ̇) = 0 has a root at θ = 0 that p_θ = m l² θ̇ lacks. A root found in floats is checked in the other
    function in floats; where that cannot tell (ω² = 1.000001 k/m), again at 40 digits.
    None when no root was found to compare, or a root could not be judged.
    """
    found, multiplicity = 0, False
    points = expected.points(4, salt=2).tolist()
    for symbol in sorted(symbols, key=lambda s: (not expected.setting.is_state(s), s.name)):
        position = expected.variables.index(symbol)
        grid = _grid(expected.setting.domain(symbol))
        for point in points:
            for one, other in ((f, g), (g, f)):
                for root, bracket in _real_roots(one, point, position, grid, deadline):
                    try:
                        value, scale = other.at(_moved(point, position, root))
                        verdict = closeness(value, 0, max(scale, 1.0))
                        if verdict is Closeness.UNSURE and bracket is not None:
                            verdict = _vanishes_at_root(one, other, point, position, bracket)
                    except UNDEFINED:
                        return None
                    if verdict is Closeness.DIFFERENT:
                        return _Roots.DIFFERENT
                    orders = [_order(function, point, position, root) for function in (one, other)]
                    if None not in orders and abs(orders[0] - orders[1]) > 0.25:
                        multiplicity = True
                    found += 1
    if not found:
        return None
    return _Roots.MULTIPLICITY if multiplicity else _Roots.SAME


def _vanishes_at_root(one: Compiled, other: Compiled, point, position: int, bracket) -> Closeness:
    """Whether ``other`` vanishes at the root of ``one`` inside ``bracket`` (where ``one``
    changes sign), the root found by bisection at 40 digits.

    Raises:
        UNDEFINED: where either is undefined at 40 digits.
    """
    with mpmath.workdps(PRECISE_DIGITS):
        low, high = (mpmath.mpf(end) for end in bracket)
        values = [mpmath.mpmathify(value) for value in point]

        def at(function: Compiled, x):
            values[position] = x
            return function.precise(values)

        low_sign = mpmath.sign(mpmath.re(at(one, low)[0]))
        for _ in range(4 * PRECISE_DIGITS):
            middle = (low + high) / 2
            if middle in (low, high):
                break
            if mpmath.sign(mpmath.re(at(one, middle)[0])) == low_sign:
                low = middle
            else:
                high = middle
        value, scale = at(other, (low + high) / 2)
        return closeness(value, 0, max(scale, 1.0), precise=True)


def _order(function: Compiled, point, position: int, root: float) -> float | None:
    """The order to which ``function`` vanishes at ``root``: 1 for x − 2, 2 for (x − 2)², ½ for √x.

    |f(r + h)| ∝ hᵏ near the root, so halving h divides it by 2ᵏ; measured on each side
    where f is defined and real there, and averaged. None where neither side is.
    """
    h = 1e-3  # not relative to the root: at α = 500 a step of 0.5 spans a twelfth of cos α's period
    orders = []
    for step in (h, -h):
        try:
            far, _ = function.at(_moved(point, position, root + step))
            near, _ = function.at(_moved(point, position, root + step / 2))
        except UNDEFINED:
            continue
        if far == 0 or near == 0 or abs(far.imag) > 1e-9 * abs(far) or abs(near.imag) > 1e-9 * abs(near):
            continue
        orders.append(math.log2(abs(far) / abs(near)))
    return sum(orders) / len(orders) if orders else None


def _moved(point, position: int, x: float) -> list:
    """``point`` with one variable set to ``x``."""
    values = list(point)
    values[position] = complex(x)
    return values


def _real_roots(function: Compiled, point, position: int, grid, deadline: Deadline) -> list[tuple[float, tuple | None]]:
    """Real roots of a function of one variable on ``grid``, each with the bracket where the
    function changes sign around it (None for a touching root, or one on the grid).

    Sign changes are refined by bisection and kept only where the function really
    vanishes (a pole changes sign too); a touching root such as that of (x − 2)² is
    found as a local minimum of |f| that reaches zero.
    """

    def at(x: float):
        try:
            value, scale = function.at(_moved(point, position, x))
        except UNDEFINED:
            return None
        if abs(value.imag) > 1e-9 * max(1.0, abs(value)):
            return None
        return value.real, scale

    def vanishes(x: float) -> bool:
        sample = at(x)
        return sample is not None and closeness(sample[0], 0, max(sample[1], 1.0)) is Closeness.EQUAL

    def really_vanishes(x: float) -> bool:
        # Far out on the grid a float underflows: s² e^(st) at t = −1000 is 0, though no root.
        # At 40 digits (mpmath's exponents do not underflow) a root is still a root. And a value
        # small beside its terms' scale only because a factor is (E e^θ at θ = −891) is no root
        # either: a root is small beside the values on both sides of it too.
        try:
            with mpmath.workdps(PRECISE_DIGITS):
                value, scale = function.precise(_moved(point, position, x))
                if value == 0:
                    return True
                step = _NEAR_ROOT * max(1.0, abs(x))
                around = [abs(function.precise(_moved(point, position, x + h))[0]) for h in (-step, step)]
        except UNDEFINED:
            return False
        # in mpmath's numbers: as floats, e^(−1000 s) would underflow all over again
        return abs(value) <= FLOAT_EQUAL * mpmath.mpmathify(scale) and abs(value) <= FLOAT_EQUAL * min(around)

    batch = np.array([point] * len(grid), complex)
    batch[:, position] = grid
    values, scales = function.many(batch)
    samples = [
        (x, (value.real, scale) if math.isfinite(scale) and abs(value.imag) <= 1e-9 * max(1.0, abs(value)) else None)
        for x, value, scale in zip(grid, values.tolist(), scales.tolist(), strict=True)
    ]
    roots: list[tuple[int, float, tuple | None]] = []  # where on the grid, the root, its bracket
    changes, dips = [], []  # (where on the grid, x0, x1, f(x0) > 0); (where, x0, x2)
    for number, ((x0, s0), (x1, s1), (x2, s2)) in enumerate(zip(samples, samples[1:], samples[2:], strict=False)):
        if s0 is None or s1 is None:
            continue
        if s1[0] == 0:
            if really_vanishes(x1):
                roots.append((number, x1, None))
        elif s0[0] * s1[0] < 0:
            changes.append((number, x0, x1, s0[0] > 0))
        elif s2 is not None and abs(s1[0]) < min(abs(s0[0]), abs(s2[0])) and s0[0] * s2[0] > 0:
            dips.append((number, x0, x2))
    # every bracket narrowed at once, in one numpy pass a step: bisection where f changes sign,
    # golden-section search for the least |f| where it dips
    if changes:
        low, high = (np.array([change[k] for change in changes], float) for k in (1, 2))
        positive = np.array([change[3] for change in changes])
        on = np.ones(len(changes), bool)
        for _ in range(60):
            deadline.check()
            middle = (low + high) / 2
            value, defined = _along(function, point, position, middle)
            on &= defined  # where undefined, the bracket stays as it was
            keep_low = on & ((value > 0) == positive)
            low, high = np.where(keep_low, middle, low), np.where(on & ~keep_low, middle, high)
        for (number, *_), a, b in zip(changes, low.tolist(), high.tolist(), strict=True):
            if vanishes((a + b) / 2):
                roots.append((number, (a + b) / 2, (a, b)))
    if dips:
        low, high = (np.array([dip[k] for dip in dips], float) for k in (1, 2))
        on = np.ones(len(dips), bool)
        for _ in range(80):
            deadline.check()
            a, b = high - 0.618 * (high - low), low + 0.618 * (high - low)
            value, defined = _along(function, point, position, np.concatenate([a, b]))
            on &= defined[: len(a)] & defined[len(a) :]
            nearer = np.abs(value[: len(a)]) < np.abs(value[len(a) :])
            low, high = np.where(on & ~nearer, a, low), np.where(on & nearer, b, high)
        for (number, *_), a, b in zip(dips, low.tolist(), high.tolist(), strict=True):
            if vanishes((a + b) / 2) and really_vanishes((a + b) / 2):
                roots.append((number, (a + b) / 2, None))
    return [(root, bracket) for _, root, bracket in sorted(roots, key=lambda item: item[0])]


def _along(function: Compiled, point, position: int, xs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The real part of ``function`` at ``point`` with one variable at each of ``xs``, and where
    it is defined and real there (its imaginary part within rounding); not remembered."""
    batch = np.repeat(np.asarray([point], complex), len(xs), axis=0)
    batch[:, position] = xs
    values, scales = function.many_once(batch)
    defined = np.isfinite(scales) & (np.abs(values.imag) <= 1e-9 * np.maximum(1.0, np.abs(values)))
    return values.real, defined


# -- systems ----------------------------------------------------------------------


@dataclass
class _State:
    """What one sample state says of a submitted system."""

    verdicts: list[Closeness]  # per submitted equation: satisfied by the expected accelerations?
    trivial: list[bool]  # per submitted equation: no acceleration in it at this state
    empty: list[bool]  # per submitted equation: nothing in it at all at this state (0 = 0)
    independent: bool  # the submitted equations determine the accelerations
    good: list[list]  # the rows of the submitted equations that are satisfied
    reference: list[list]  # the rows of the expected equations

    @property
    def unsure(self) -> bool:
        return Closeness.UNSURE in self.verdicts

    @cached_property
    def spanned(self) -> list[bool]:
        """Per coordinate: whether its expected equation follows from the right submitted ones.
        Only feedback on a wrong system asks, so it is worked out only then."""
        return [_in_span(self.good, row) for row in self.reference]

    @cached_property
    def fixed(self) -> list[bool]:
        """Per coordinate: whether the right submitted equations alone fix its acceleration, as
        θ̈₁ = … solved for it does, where its Euler–Lagrange equation, which holds θ̈₂ too, is not spanned."""
        n = len(self.reference[0]) - 1 if self.reference else 0
        rows = [row[:n] for row in self.good]
        return [_in_span(rows, [int(i == k) for i in range(n)]) for k in range(n)]


def check_equations(expected: Expected, answer: ParsedAnswer, deadline: Deadline) -> Outcome:
    theirs, (references, _) = _equations(answer.value), _expected_equations(expected)
    expected_fs = [expected.compiled(f"equations {i}", f) for i, f in enumerate(references)]
    submitted_gs = [expected.compile(g) for g in theirs]
    numbered = _states(expected, expected_fs, submitted_gs, deadline)
    states = [state for _, state in numbered]
    if len(states) < MIN_DEFINED:
        return Outcome("undecided", 0.0, "undecided", method="accelerations: too few defined states")
    outcome = _system_outcome(expected, states, theirs)
    drawn = [state for number, state in numbered if number < expected.point_count]
    if outcome.key == "dependent_equations" and all(state.independent for state in drawn):
        # independent wherever states are drawn, not at rest or at the origin: a vanishing factor
        return Outcome("not_equivalent", 0.0, "vanishing_factor_system", method=outcome.method)
    if outcome.key == "equivalent" and _loses_an_acceleration(expected, expected_fs, submitted_gs):
        return Outcome("not_equivalent", 0.0, "vanishing_factor_system", method=outcome.method)
    if outcome.key == "equivalent" and _vanishes_between(expected, expected_fs, submitted_gs):
        return Outcome("not_equivalent", 0.0, "vanishing_factor_system_between", method=outcome.method)
    wrong = outcome.key in ("wrong_equation", "wrong_equations")
    # an answer that keeps sin θ or cos θ is no small-angle form: the forms are not tried, at milliseconds each
    if (
        wrong
        and not any(has_angle_functions(expected.setting.plain(g), expected.setting) for g in theirs)
        and _is_small_angle_system(expected, submitted_gs, theirs, deadline)
    ):
        return Outcome("not_equivalent", 0.0, "small_angle", method="accelerations")
    if not wrong:
        return outcome
    wrong_ones = [j for j in range(len(theirs)) if not all(s.verdicts[j] is Closeness.EQUAL for s in states)]
    nonlinear = _nonlinear(expected, expected_fs, submitted_gs)
    if any(nonlinear[j] for j in wrong_ones):
        more = tuple(("not_linear_in", {"index": j + 1}) for j in wrong_ones if nonlinear[j])
        return replace(outcome, more=more)
    if outcome.key == "wrong_equation" and len(wrong_ones) == 1:
        (j,) = wrong_ones
        return replace(outcome, more=_terms_named(expected, references, theirs[j], j, deadline))
    if outcome.key == "wrong_equations" and len(theirs) > 1:
        # several wrong: each named with its number, as far as it is near an expected equation
        more = tuple(
            (f"{key}_in", {**details, "index": j + 1})
            for j in wrong_ones
            for key, details in _terms_named(expected, references, theirs[j], j, deadline)
        )
        return replace(outcome, more=more)
    return outcome


def _loses_an_acceleration(expected: Expected, expected_fs, submitted_gs) -> bool:
    """Whether, at rest or at the origin, where the expected system determines only some of the
    accelerations, the submitted one leaves one of those undetermined.

    The spherical pendulum's φ equation, sin²θ φ̈ + 2 sin θ cos θ θ̇ φ̇ = 0, says nothing at θ = 0,
    so the system there is singular and the state says nothing of a submitted system as a whole.
    Its θ equation still says what θ̈ is; multiplied by sin θ, it no longer does."""
    steps = _steps(expected, expected_fs)
    reference = _float_rows(expected, expected_fs, steps, reference=True)
    special = [
        number
        for number in range(len(steps) - _SPECIAL, len(steps))
        if reference[number] is not None
        and reference[number].linear is Closeness.EQUAL
        and reference[number].accelerations is None
    ]
    if not special:
        return False
    submitted = _float_rows(expected, submitted_gs, steps)
    for number in special:
        theirs = submitted[number]
        if theirs is None or theirs.linear is not Closeness.EQUAL:
            continue
        mine, yours = _determined(reference[number]), _determined(theirs)
        if any(a and not b for a, b in zip(mine, yours, strict=True)):
            return True
    return False


def _determined(rows: _Rows, *, plain: bool = False) -> list[bool]:
    """Per coordinate: whether these equations fix its acceleration at their state (whatever the
    others'). A coefficient within rounding of zero, on its own scale, counts as zero; ``plain``,
    so does one that rounding cannot tell from zero."""
    n = len(rows.rows[0]) - 1
    zero = (Closeness.EQUAL, Closeness.UNSURE) if plain else (Closeness.EQUAL,)
    coefficients = [
        [0.0 if closeness(c, 0, scale) in zero else c for c, scale in zip(row[:n], scales[:n], strict=True)]
        for row, scales in zip(rows.rows, rows.entry_scales, strict=True)
    ]
    coefficients = [row for row in coefficients if any(row)]
    return [_in_span(coefficients, [float(j == k) for j in range(n)]) for k in range(n)]


def _terms_named(expected: Expected, references: Sequence, g, position: int, deadline: Deadline) -> tuple:
    """What differs in a wrong equation ``g`` (as parsed) of a system (the ``position``-th), as the
    sentences of a single equation's diagnosis: against the expected equation (of ``references``,
    the expected answer's, each as an expression = 0) it differs
    from by the fewest terms, one or two, and the one in the same place on a tie; only
    equations with the same accelerations are compared. Nothing when no expected equation is
    so near: the student combined or solved the equations, and the terms they wrote are not
    the expected ones."""
    named, accelerations, plain = [], set(accelerations_in(g, expected)), None
    _, of_references = _expected_equations(expected)
    # the one in the same place first: of two equally near, min keeps the first
    for i, f in sorted(enumerate(references), key=lambda item: item[0] != position):
        if not accelerations or set(of_references[i]) != accelerations:
            continue  # θ̈₁ = … solved is no term or two away from an equation in θ̈₁ and θ̈₂
        plain = plain if plain is not None else expected.setting.plain(g)  # built only when compared
        outcome = _diagnose_motion(expected, f, plain, deadline, key=f"equations {i}, normalized")
        if outcome.key == "small_angle":  # θ̈ = θ φ̇² − (g/l) θ beside a right φ equation
            return (("small_angle", {}),)
        if outcome.key in TERM_KEYS:
            sentences = ((outcome.key, outcome.details), *outcome.more)
            if len(sentences) == 1:
                return sentences  # none can be nearer
            named.append(sentences)
    return min(named, key=len) if named else ()


def _states(expected: Expected, expected_fs, submitted_gs, deadline: Deadline) -> list[tuple[int, _State]]:
    """What each sample state says of the submitted system, by state number; unsure states
    are redone at 40 digits."""
    return _at_each_state(expected, (expected_fs, submitted_gs), deadline, _system_state, _state_unsure, _state_agrees)


def _state_unsure(state: _State | None) -> bool:
    return state is not None and state.unsure


def _state_agrees(state: _State) -> bool:
    return all(verdict is Closeness.EQUAL for verdict in state.verdicts)


def _is_small_angle_system(expected: Expected, submitted_gs, theirs, deadline: Deadline) -> bool:
    """Whether the submitted system is the expected one linearized about q = q̇ = 0, or with
    sin u → u and cos u → 1 in it."""
    if "equations, small angle" not in expected.cache:
        expected.cache["equations, small angle"] = [
            [expected.compiled(f"equations, small angle {number} {i}", f) for i, f in enumerate(system)]
            for number, system in enumerate(_small_angle_systems(expected))
        ]
    for forms in expected.cache["equations, small angle"]:
        deadline.check()
        states = [state for _, state in _states(expected, forms, submitted_gs, deadline)]
        if len(states) >= MIN_DEFINED and _system_outcome(expected, states, theirs).key == "equivalent":
            return True
    return False


def _small_angle_systems(expected: Expected) -> list[list]:
    """The expected equations linearized, and with sin u → u, cos u → 1 put in each.

    Linearized, the spherical pendulum's θ̈ − sin θ cos θ φ̇² + (g/l) sin θ loses its φ̇² term, a
    third-order one; the form a student writes for small θ keeps it, as θ̈ − θ φ̇² + (g/l) θ. (Not
    cos u → 1 − u²/2 too, as for one equation: each form tried costs a wrong system milliseconds.)
    """
    equations = _expected_equations(expected)[0]
    linear = [taylor(f, expected.setting, 1) for f in equations]
    substituted = [(small_angle(f, expected.setting) or [f])[0] for f in equations]  # no angle's function: as it is
    finite = [system for system in (linear, substituted) if not any(f.has(sympy.nan, sympy.zoo) for f in system)]
    return [system for number, system in enumerate(finite) if system not in finite[:number]]


def _system_state(rows: Sequence[_Rows], precise: bool) -> _State | None:
    reference, submitted = rows
    n = len(reference.rows[0]) - 1
    accelerations = reference.accelerations
    if reference.linear is not Closeness.EQUAL or accelerations is None:
        return None  # a degenerate state of the reference: it says nothing
    verdicts, trivial, empty = [], [], []
    for i, row in enumerate(submitted.rows):
        # the residual's rounding: the row's entries at these accelerations, its own terms,
        # and what the accelerations carry in
        scale = submitted.scale_at(i, accelerations)
        size = sum(abs(c * a) for c, a in zip(row, accelerations, strict=False)) + abs(row[n])
        inherited = sum(abs(c) * u for c, u in zip(row, reference.uncertainty, strict=False))
        residual = sum(c * a for c, a in zip(row, accelerations, strict=False)) + row[n]
        verdict = closeness(residual, 0, max(scale, float(size), float(inherited)), precise=precise)
        verdicts.append(_worst(verdict, submitted.linear_each[i]))  # a squared equation is wrong alone
        coefficients = zip(row[:n], submitted.entry_scales[i][:n], strict=True)
        trivial.append(all(closeness(c, 0, s, precise=precise) is Closeness.EQUAL for c, s in coefficients))
        empty.append(
            trivial[-1] and closeness(row[n], 0, submitted.entry_scales[i][n], precise=precise) is Closeness.EQUAL
        )
    good = [row for row, verdict in zip(submitted.rows, verdicts, strict=True) if verdict is Closeness.EQUAL]
    independent = _solve([row[:n] for row in submitted.rows], [-row[n] for row in submitted.rows]) is not None
    return _State(verdicts, trivial, empty, independent, good, reference.rows)


def _system_outcome(expected: Expected, states: list[_State], theirs: Sequence) -> Outcome:
    """The verdict on the submitted system ``theirs`` (its equations as expressions = 0)."""
    coords, describe = expected.setting.coords, expected.setting.describe
    n, given = len(coords), len(theirs)
    right = [all(state.verdicts[j] is Closeness.EQUAL for state in states) for j in range(given)]
    # An equation with an acceleration in it is not trivial, even where its coefficient looks
    # like rounding beside a huge constant (ÿ = e³⁰); only those that look trivial are read.
    trivial = [
        all(state.trivial[j] for state in states) and not accelerations_in(theirs[j], expected) for j in range(given)
    ]
    # 0 = 0 holds for every motion; θ₁ = 0 has no acceleration in it either, but is no identity
    empty = [trivial[j] and all(state.empty[j] for state in states) for j in range(given)]
    method = "accelerations"
    if given > n:
        if any(empty):  # 0 = 0 written as a third equation: that it is empty is what to say
            details = {"index": empty.index(True) + 1, "count": n}
            return Outcome("not_equivalent", 0.0, "trivial_extra_equation", details, method)
        return Outcome("not_equivalent", 0.0, "extra_equation", {"given": given, "count": n}, method)
    wrong_or_short = given < n or not all(right)  # only then is it asked which coordinate's equation is off
    unspanned = (
        [q for i, q in enumerate(coords) if not all(state.spanned[i] for state in states)] if wrong_or_short else []
    )
    if given < n:
        return Outcome("not_equivalent", 0.0, "missing_equation", {"coords": _or(unspanned, describe)}, method)
    if any(empty):
        return Outcome("not_equivalent", 0.0, "trivial_equation", {"index": empty.index(True) + 1}, method)
    if any(trivial):
        names = ", ".join(unicode_name(q, 2) for q in coords)
        details = {"index": trivial.index(True) + 1, "accelerations": names}
        return Outcome("not_equivalent", 0.0, "equation_without_acceleration", details, method)
    if all(right):
        if all(state.independent for state in states):
            return Outcome("equivalent", 1.0, "equivalent", method=method)
        return Outcome("not_equivalent", 0.0, "dependent_equations", method=method)
    if any(right) and unspanned:
        right_ones = [str(j + 1) for j, ok in enumerate(right) if ok]
        rest = f"equation {right_ones[0]} is right" if len(right_ones) == 1 else "the others are right"
        # θ̈₁ = … right and θ̈₂ = … wrong: θ₁'s acceleration is right, so the wrong one is θ₂'s
        fixed = {q for i, q in enumerate(coords) if all(state.fixed[i] for state in states)}
        off = [q for q in unspanned if q not in fixed] or unspanned
        return Outcome("not_equivalent", 0.0, "wrong_equation", {"coords": _or(off, describe), "right": rest}, method)
    return Outcome("not_equivalent", 0.0, "wrong_equations", {"coords": describe(coords)}, method)


def _or(names: list[str], describe) -> str:
    if len(names) <= 1:
        return describe(names)
    return "one of " + describe(names)


def _solve(matrix, rhs):
    """Gaussian elimination with partial pivoting; None when (numerically) singular."""
    n = len(matrix)
    if n == 0 or any(len(row) != n for row in matrix):
        return None
    a = [[*row, value] for row, value in zip(matrix, rhs, strict=True)]
    norm = max(abs(x) for row in matrix for x in row) or 1
    for col in range(n):
        pivot = max(range(col, n), key=lambda r: abs(a[r][col]))
        if abs(a[pivot][col]) <= 1e-12 * norm:
            return None
        a[col], a[pivot] = a[pivot], a[col]
        for r in range(col + 1, n):
            factor = a[r][col] / a[col][col]
            for c in range(col, n + 1):
                a[r][c] -= factor * a[col][c]
    solution = [0] * n
    for r in reversed(range(n)):
        solution[r] = (a[r][n] - sum(a[r][c] * solution[c] for c in range(r + 1, n))) / a[r][r]
    return solution


def _rank(rows) -> int:
    # each row on its own scale first: ẍ − m = 0 beside ÿ − 10¹³ g = 0 is no zero row
    rows = [[x / (max(abs(y) for y in row) or 1) for x in row] for row in rows]
    if not rows:
        return 0
    norm = max((abs(x) for row in rows for x in row), default=0) or 1
    rank, width = 0, len(rows[0])
    for col in range(width):
        pivot = max(range(rank, len(rows)), key=lambda r: abs(rows[r][col]), default=None)
        if pivot is None or abs(rows[pivot][col]) <= 1e-9 * norm:
            continue
        rows[rank], rows[pivot] = rows[pivot], rows[rank]
        for r in range(len(rows)):
            if r != rank:
                factor = rows[r][col] / rows[rank][col]
                rows[r] = [x - factor * y for x, y in zip(rows[r], rows[rank], strict=True)]
        rank += 1
        if rank == len(rows):
            break
    return rank


def _in_span(rows, row) -> bool:
    """Whether ``row`` is a combination of ``rows`` (at this state)."""
    return _rank([*rows, row]) == _rank(rows) if rows else False
