"""The kinds that are single numbers: ``integer`` and ``number`` (``choice`` is in :mod:`grader.judge.choice`).

Contents:
    check_integer    a whole number, exactly (``6/2`` is 3)
    check_number     a number within a tolerance: |submitted − expected| ≤ atol + rtol·|expected|
"""

from __future__ import annotations

import sympy

from grader.judge.deadline import Deadline
from grader.judge.expected import Expected, Outcome
from grader.judge.units import other_units
from grader.parse import ParsedAnswer

__all__ = ["check_integer", "check_number"]

DIGITS = 30


def check_integer(expected: Expected, answer: ParsedAnswer, deadline: Deadline) -> Outcome:
    value = _whole(answer.value) if answer.value.is_number else answer.value
    if not (value.is_number and value.is_Integer):
        return Outcome("not_equivalent", 0.0, "not_an_integer", method="exact")
    equal = value == expected.parsed.value
    return Outcome(
        "equivalent" if equal else "not_equivalent", float(equal), "equivalent" if equal else "wrong", method="exact"
    )


def _whole(value):
    """``value`` as a sympy Integer when it is one exactly, else as it is.

    A rational is one only if its denominator is 1 (15 + 10⁻²⁹ is not 15). Anything else
    (log(8)/log(2)) is guessed by ``nsimplify``, whose guess has a tolerance, so the guess
    must agree with the value to 50 digits.
    """
    if value.is_Rational:
        return value
    guess = sympy.nsimplify(value)
    if guess.is_Integer and abs((value - guess).evalf(DIGITS + 30)) < sympy.Float(10) ** -50:
        return guess
    return value


def check_number(expected: Expected, answer: ParsedAnswer, deadline: Deadline) -> Outcome:
    rtol, atol = float(expected.option("rtol")), float(expected.option("atol"))
    target = complex(expected.parsed.value.evalf(DIGITS))
    deadline.check()
    value = complex(answer.value.evalf(DIGITS))
    method = f"tolerance rtol={rtol:g} atol={atol:g}"
    if abs(value - target) <= atol + rtol * abs(target):
        return Outcome("equivalent", 1.0, "equivalent", method=method)
    unit = expected.option("unit")
    for name, size in other_units(str(unit)) if unit else ():
        # 2006 for a period asked in s: the right number in ms, written without its unit
        in_other = target / complex(size)
        if abs(value - in_other) <= atol / abs(complex(size)) + rtol * abs(in_other):
            return Outcome("not_equivalent", 0.0, "other_unit", {"unit": name, "wanted": str(unit)}, method)
    return Outcome("not_equivalent", 0.0, "out_of_tolerance", method=method)
