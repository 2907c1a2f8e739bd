"""Evaluating two answers side by side at sample points, and what the numbers say.

Contents:
    Pair                      one point: both values and their common scale
    evaluate_pairs(...)       both expressions at seeded points, near misses re-evaluated precisely
    side_by_side(f, g, points)  both expressions' values and scales at each point, in one numpy pass
    precise_side_by_side(...)   the same at 40 digits, point by point
    all_equal, constant_ratio, constant_difference   readings of a list of pairs
    nice_number(x)            1/2, 2, 2π… for feedback, or None

A point where either side is undefined (a division by zero, an overflow) is
skipped; when too few points remain, the caller falls back to symbolic work or
says "undecided".
"""

from __future__ import annotations

import cmath
import functools
import math
from collections.abc import Sequence
from dataclasses import dataclass
from fractions import Fraction

import mpmath
import numpy as np

from grader.judge.deadline import Deadline
from grader.judge.numeric import FLOAT_DIFFERENT, UNDEFINED, Closeness, Compiled, closeness

__all__ = [
    "POINTS",
    "Pair",
    "all_equal",
    "constant_difference",
    "constant_ratio",
    "evaluate_pairs",
    "nice_number",
    "precise_side_by_side",
    "short_fraction",
    "side_by_side",
]

POINTS = 10  # sample points per comparison
GROUP = 5  # points sharing their parameter values: two draws of them (four: Expected.point_count), five states each
MIN_DEFINED = 6  # fewer defined points than this cannot decide


@dataclass(frozen=True)
class Pair:
    """Both values at one point; ``group`` numbers the draw of parameter values it shares."""

    expected: complex
    submitted: complex
    scale: float
    precise: bool = False
    group: int = 0

    def closeness(self) -> Closeness:
        return closeness(self.expected, self.submitted, self.scale, precise=self.precise)


def evaluate_pairs(
    expected: Compiled,
    submitted: Compiled,
    points: np.ndarray,
    deadline: Deadline,
    *,
    precise: bool = False,
) -> list[Pair]:
    """Both expressions at each point where both are defined; unsure points, and points where
    either lost a term, are redone at 40 digits (all points, with ``precise``)."""
    deadline.check()
    pairs = []
    exact = expected.rational and submitted.rational

    @functools.cache
    def lost() -> np.ndarray:  # per point, whether either lost a term: asked only where floats agree
        return expected.lost(points) | submitted.lost(points)

    for number, (a, scale_a, b, scale_b) in enumerate(side_by_side(expected, submitted, points)):
        if not (cmath.isfinite(a) and cmath.isfinite(b)):
            continue
        if abs(a.imag) > 1e-12 * max(1.0, abs(a)):
            # The points are real, so a complex value of the reference means this point is
            # outside its real domain (√ or log of a negative): compare where it is defined.
            continue
        pair = Pair(a, b, max(scale_a, scale_b), group=number // GROUP)
        agreement = pair.closeness()
        if exact and a != b and agreement is Closeness.EQUAL:
            exact = False  # once per comparison: enough to catch a difference floats cannot see
            point = points[number].tolist()
            try:
                (a, scale_a), (b, scale_b) = expected.exact(point), submitted.exact(point)
            except UNDEFINED:
                continue
            pair = Pair(a, b, max(scale_a, scale_b), precise=True, group=number // GROUP)
        elif precise or agreement is Closeness.UNSURE or (agreement is Closeness.EQUAL and lost()[number]):
            deadline.check()
            point = points[number].tolist()
            try:
                a, scale_a = expected.precise(point)
                b, scale_b = submitted.precise(point)
            except UNDEFINED:
                continue
            if not (_finite(a) and _finite(b)):
                continue
            pair = Pair(a, b, max(scale_a, scale_b), precise=True, group=number // GROUP)
        pairs.append(pair)
    return pairs


def side_by_side(f: Compiled, g: Compiled, points: np.ndarray) -> list[tuple[complex, float, complex, float]]:
    """(f, its scale, g, its scale) at each point, as Python numbers; NaN where undefined."""
    (a, scale_a), (b, scale_b) = f.many(points), g.many(points)
    return list(zip(a.tolist(), scale_a.tolist(), b.tolist(), scale_b.tolist(), strict=True))


def precise_side_by_side(f: Compiled, g: Compiled, points: np.ndarray) -> list[tuple]:
    """As :func:`side_by_side`, at 40 digits; NaN scales where undefined (or a term is lost even so).
    Call it inside ``mpmath.workdps``: what is done with the values needs 40 digits too."""
    values = []
    for point in points.tolist():
        try:
            (a, scale_a), (b, scale_b) = f.precise(point), g.precise(point)
        except UNDEFINED:
            a = scale_a = b = scale_b = math.nan
        values.append((a, scale_a, b, scale_b))
    return values


def _finite(value) -> bool:
    if isinstance(value, complex):
        return cmath.isfinite(value)
    return bool(mpmath.isfinite(value))


def all_equal(pairs: Sequence[Pair]) -> bool | None:
    """True when every point agrees, False when one clearly does not, None when too few points."""
    if any(pair.closeness() is Closeness.DIFFERENT for pair in pairs):
        return False
    if len(pairs) < MIN_DEFINED:
        return None
    return True


def constant_ratio(pairs: Sequence[Pair]) -> complex | None:
    """The constant k with submitted = k·expected at every point, if there is one (k ≠ 0).

    Not k = 1 either: answers that differ yet agree that closely differ by a term too small
    beside the rest to show in a ratio (m beside e^(10(m + 2))), which is no factor.
    """
    usable = [pair for pair in pairs if abs(pair.expected) > 1e-9 * pair.scale]
    if len(usable) < MIN_DEFINED // 2:
        return None
    k = complex(usable[0].submitted / usable[0].expected)
    if k == 0 or abs(k - 1) <= 1e-9:
        return None
    for pair in pairs:
        precise = pair.precise and usable[0].precise  # k from floats is only good to floats' resolution
        scaled = Pair(k * pair.expected, pair.submitted, pair.scale * max(1.0, abs(k)), precise=precise)
        if scaled.closeness() is not Closeness.EQUAL:
            return None
    return k


def constant_difference(pairs: Sequence[Pair]) -> bool | None:
    """True when submitted − expected does not change along the motion; None when the
    numbers cannot tell.

    It may depend on the parameters (m g l is a constant of the motion), so it is
    compared within each group of points that share the parameters' values.

    They cannot tell where the submitted answer dwarfs the expected one: beside 10¹⁴, the
    whole of L changes submitted − expected by less than floats resolve, so "10¹⁴" would
    pass as L plus a constant. Within a group, the expected answer's own change must then
    be clear of the resolution (10⁻⁶ of the scale in floats, 10⁻²⁰ at 40 digits).
    """
    if len(pairs) < MIN_DEFINED:
        return False
    groups: dict[int, list[Pair]] = {}
    for pair in pairs:
        groups.setdefault(pair.group, []).append(pair)
    blind = False
    for group in groups.values():
        first = group[0]
        reference = first.submitted - first.expected
        for pair in group:
            precise = first.precise and pair.precise
            if closeness(pair.submitted - pair.expected, reference, pair.scale, precise=precise) is not Closeness.EQUAL:
                return False
        change = max(abs(pair.expected - first.expected) for pair in group)
        precise = all(pair.precise for pair in group)
        resolution = (_PRECISE_RESOLUTION if precise else FLOAT_DIFFERENT) * max(pair.scale for pair in group)
        blind = blind or 0 < change < resolution
    return None if blind else True


_PRECISE_RESOLUTION = 1e-20  # at 40 digits, a change this much smaller than the scale is not seen


def short_fraction(x: float) -> Fraction | None:
    """The nonzero fraction with a denominator of at most 12 within 10⁻⁹ of ``x`` (relatively),
    or None: what a ratio measured in floats is, when it is a number one would write."""
    if not math.isfinite(x):  # 1/ratio of a ratio that underflowed to 0
        return None
    fraction = Fraction(x).limit_denominator(12)
    return fraction if fraction != 0 and abs(float(fraction) - x) <= 1e-9 * abs(x) else None


def nice_number(k: complex) -> str | None:
    """A short exact form of ``k`` (1/2, 2, -3/4, 2π, π/2, 1/(2π)), or None when it has none.

    >>> nice_number(0.5), nice_number(2 * 3.141592653589793), nice_number(0.123456789)
    ('1/2', '2π', None)
    >>> nice_number(1 / (2 * 3.141592653589793))
    '1/(2π)'
    >>> nice_number(2**-0.5), nice_number(-(3**0.5)), nice_number((2 / 3) ** 0.5)
    ('1/√2', '-√3', '√(2/3)')
    """
    if abs(k.imag) > 1e-9 * abs(k):
        return None
    value = k.real
    fraction = short_fraction(value)
    if fraction is not None:
        return str(fraction)
    fraction = short_fraction(value / math.pi)
    if fraction is not None:  # 2π, π/2, -3π/4
        numerator = "" if fraction.numerator == 1 else "-" if fraction.numerator == -1 else str(fraction.numerator)
        return f"{numerator}π" if fraction.denominator == 1 else f"{numerator}π/{fraction.denominator}"
    fraction = short_fraction(value * math.pi)
    if fraction is not None:  # 1/(2π): a frequency for an angular one
        below = "π" if fraction.denominator == 1 else f"({fraction.denominator}π)"
        return f"{fraction.numerator}/{below}"
    fraction = short_fraction(value * value)
    if fraction is not None:  # √2: a frequency of √(2g/l), or ½ for a √ one
        sign = "-" if value < 0 else ""
        if fraction.denominator == 1:
            return f"{sign}√{fraction.numerator}"
        if fraction.numerator == 1:
            return f"{sign}1/√{fraction.denominator}"
        return f"{sign}√({fraction})"
    return None
