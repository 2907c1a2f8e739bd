"""Decimals that round an exact number: ``0.333`` for 1/3, ``1.57`` for π/2, ``0.707`` for 1/√2.

Contents:
    exact_readings(text)   the text with its rounded decimals written as exact numbers they may
                           round, most likely first, each with the decimals it replaced

A formula's decimal is read as the exact number it denotes (0.333 is 333/1000), so ``0.333 m l² θ̇²``
is not (1/3) m l² θ̇². Where it would be with the decimal written exactly, the student has the
physics right and rounded a number: a person decides what that is worth, and the student is told to
write the exact value. A decimal is taken to round a number within one unit of its last digit
(rounded or cut off), and only with two significant digits or more: 0.3 is no reading of 1/3.
"""

from __future__ import annotations

import itertools
import math
import re
from fractions import Fraction

__all__ = ["exact_readings"]

# 0.333, 1.57, .707 as typed: not a piece of a name (m1.5), of 1.5e-3, or of a decimal comma's 2,01
_DECIMAL = re.compile(r"(?<![\w.,])(\d*\.\d+)(?![\d.]|[eE][+-]?\d)")

_DENOMINATORS = range(1, 13)
_ROOTS = (2, 3, 5, 6, 7)  # √n/q: 1.414, 0.707, 0.866
_MOST_DECIMALS = 3  # in one answer: past that, rounding is not what went wrong
_CANDIDATES = 2  # exact readings tried per decimal
_READINGS = 6  # texts returned in all


def exact_readings(text: str) -> list[tuple[str, tuple[str, ...]]]:
    """``text`` with each decimal that rounds a simple exact number written as that number, and the
    decimals so replaced; most likely first, none where no decimal rounds one.

    >>> exact_readings("0.333 m l^2")[0]
    ('(1/3) m l^2', ('0.333',))
    >>> exact_readings("0.5 m l^2"), exact_readings("0.3 m l^2")
    ([], [])
    """
    found = list(_DECIMAL.finditer(text))
    if not found or len(found) > _MOST_DECIMALS:
        return []
    choices = [[None, *_candidates(match[1])] for match in found]  # None: the decimal as typed
    readings = []
    # each decimal as typed or as one of its candidates: a student who rounds one number rounds the
    # others too, so every decimal written exactly first, each as its simplest candidate
    ranked = sorted(itertools.product(*(range(len(c)) for c in choices)), key=lambda p: (p.count(0), sum(p), p))
    for picks in ranked:
        if not any(picks):
            continue
        pieces, last, replaced = [], 0, []
        for match, options, pick in zip(found, choices, picks, strict=True):
            exact = options[pick]
            if exact is not None:
                pieces += [text[last : match.start(1)], exact]
                last = match.end(1)
                replaced.append(match[1])
        readings.append(("".join([*pieces, text[last:]]), tuple(replaced)))
        if len(readings) == _READINGS:
            break
    return readings


def _candidates(decimal: str) -> list[str]:
    """Up to two simple exact numbers (a fraction, a fraction of π or 1/π, √n/q) that ``decimal`` rounds or cuts
    off at its last digit, simplest first, as text; none where it is exact itself (0.5, 0.25) or has
    fewer than two significant digits."""
    digits = decimal.split(".")[1]
    significant = decimal.replace(".", "").lstrip("0")
    if len(significant) < 2:
        return []
    value = Fraction(decimal)
    if value.denominator in _DENOMINATORS or value == 0:
        return []  # 0.5, 0.25, 0.125: already the exact number
    within = Fraction(1, 10 ** len(digits))
    found = []
    for q in _DENOMINATORS:
        for rank, factor, size in ((q, "", 1.0), (q + 0.5, "pi", math.pi), (q + 0.6, "/pi", 1 / math.pi), *_roots(q)):
            p = round(float(value) * q / size)
            exact = Fraction(p, q) if not factor else None
            near = abs(exact - value) <= within if exact is not None else abs(p * size / q - float(value)) <= within
            if p and math.gcd(p, q) == 1 and (factor or q > 1) and near:
                found.append((rank, _written(p, q, factor)))
    return [exact for _, exact in sorted(found)[:_CANDIDATES]]


def _roots(q: int) -> list[tuple[float, str, float]]:
    return [(q + 0.75, f"sqrt({n})", math.sqrt(n)) for n in _ROOTS]


def _written(p: int, q: int, factor: str) -> str:
    """p·factor/q as our parser reads it, in brackets: (1/3), (pi/2), (2*pi), (1/(2*pi)), (sqrt(2)/2)."""
    if factor == "/pi":
        return f"({p}/({q}*pi))" if q > 1 else f"({p}/pi)"
    top = factor if p == 1 and factor else f"{p}*{factor}" if factor else str(p)
    return f"({top}/{q})" if q > 1 else f"({top})"
