"""Reading a student's answer: ``parse_answer`` and what it returns.

Contents:
    parse_answer(text, coords=, known=)  text → ParsedAnswer or Refusal; never raises
    ParsedAnswer                         the answer as sympy objects, and how to show it back
    Refusal                              why an answer could not be read, and where
    TIME                                 the symbol t the coordinates depend on
    ANSWER                               the name an expression stands under beside its definitions
    too_many_digits(number)              whether a constant is beyond the parser's cap on digits
    within_diff_budget(value, order)     whether a value is small enough to differentiate in t
    own_rates(value, coords)             the rates of names the answer defines for itself (ṗ)
    visible(text)                        text as it reads: lookalike letters as ours, invisible ones as spaces

The modules behind it: ``tokens`` (the whitelist and threat model), ``grammar``
(tokens to sympy), ``names`` (one spelling per name), ``messages`` (every word a
student reads), ``readback`` (text, LaTeX, MathML).
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from functools import cached_property

import sympy

from grader.parse.grammar import (
    ANSWER,
    TIME,
    Context,
    holds_any,
    own_rates,
    parse_tokens,
    too_many_digits,
    within_diff_budget,
)
from grader.parse.messages import ParseFailure, Refusal, refusal
from grader.parse.readback import to_latex, to_mathml, to_text
from grader.parse.tokens import LIMITS, tokenize, visible

__all__ = [
    "ANSWER",
    "LIMITS",
    "TIME",
    "ParsedAnswer",
    "Refusal",
    "own_rates",
    "parse_answer",
    "too_many_digits",
    "visible",
    "within_diff_budget",
]


@dataclass(frozen=True)
class ParsedAnswer:
    """An answer that was read.

    Attributes:
        text: the answer as typed.
        value: a sympy expression, a ``sympy.Eq``, or a tuple of ``Eq`` (a system).
        kind: ``"expression"``, ``"equation"`` or ``"equations"``.
        stated: what a chain said its quantity is on the way to its value, as ``Eq(label, side)``:
            ``L = T − V`` of ``L = T − V = ½ m l² θ̇² + …`` (read as L = ½ m l² θ̇² + …).
        typed: each of ``stated`` and each equation of a system, with the text it was read from
            (see :meth:`as_typed`).
    """

    text: str
    value: object
    kind: str
    stated: tuple = ()
    typed: tuple = ()

    ok = True

    @cached_property
    def symbols(self) -> frozenset[sympy.Symbol]:
        """The symbols the answer uses, in every equation of a system."""
        items = self.value if isinstance(self.value, tuple) else (self.value,)
        return frozenset().union(*(item.free_symbols for item in items))

    def as_typed(self, item: sympy.Eq) -> str | None:
        """A stated side or an equation of the answer as the student typed it (``L = 2T - H``, where
        printed it is L = -H + 2*T); None for one the checker made."""
        return next((text for typed, text in self.typed if typed is item), None)

    @cached_property
    def read_as_text(self) -> str:
        """How the answer was read, as one line of Unicode text (as typed, if it cannot be printed)."""
        return _printed(to_text, self.value, self.text)

    @cached_property
    def read_as_latex(self) -> str:
        """How the answer was read, as LaTeX ("" if it cannot be printed)."""
        return _printed(to_latex, self.value, "")

    @cached_property
    def read_as_mathml(self) -> str:
        """How the answer was read, as a MathML ``<math>`` element ("" if it cannot be printed)."""
        return _printed(to_mathml, self.value, "")


def _printed(printer, value, otherwise: str) -> str:
    # The parser's limits keep every value printable; should one slip past them, showing the
    # answer back must not be what fails a student's whole submission.
    try:
        return printer(value)
    except _SYMPY_FAILURES:
        return otherwise


# sympy raises these from deep inside on values it cannot build; for a student they
# mean the same thing: this text is not mathematics we can work with.
_SYMPY_FAILURES = (ArithmeticError, ValueError, TypeError, RecursionError, MemoryError)


def parse_answer(text: str, *, coords: Iterable = (), known: Iterable = (), deadline=None) -> ParsedAnswer | Refusal:
    """Read an answer typed by a student, safely.

    Args:
        text: the answer, in plain notation (``1/2 m l^2 thetadot^2``), Unicode
            (``½``-free: ``m l² θ̇²``) or LaTeX (``\\frac{1}{2} m l^2 \\dot\\theta^2``).
        coords: the generalized coordinates, by name in any spelling or as
            functions of :data:`TIME`; ``theta'`` and ``θ̇`` are derivatives of these.
        known: the other symbols the problem defines, by name or as sympy Symbols
            (whose assumptions are kept). Juxtaposed known names split: ``mgl``.
        deadline: an object whose ``check()`` raises when time is up (a grader
            ``Deadline``); asked between the terms and factors of the answer.

    Returns:
        A :class:`ParsedAnswer`, or a :class:`Refusal` saying what is wrong and where.
        Nothing a student can type makes it raise; only a ``deadline`` that has passed does.

    >>> parse_answer("1/2 m l^2 thetadot^2", coords=["theta"], known=["m", "l"]).read_as_text
    'l^2*m*θ̇^2/2'
    >>> print(parse_answer("sin(θ"))
    Unbalanced bracket: the `(` at position 4 is never closed.
    sin(θ
       ^
    """
    if not isinstance(text, str):
        return refusal("unreadable", repr(type(text)))
    if len(text) > LIMITS.length:
        return refusal("too_long", text[:80], length=len(text), limit=LIMITS.length)
    if not text.strip():
        return refusal("empty", text)
    try:
        tokens = tokenize(text)
        stated, typed = [], []
        value = parse_tokens(tokens, Context.build(coords, known), text, deadline, stated, typed)
    except ParseFailure as failure:
        return failure.to_refusal(text)
    except _SYMPY_FAILURES:
        return refusal("unreadable", text)
    if _has_undefined(value):
        return refusal("undefined_value", text)
    kind = "equations" if isinstance(value, tuple) else "equation" if isinstance(value, sympy.Eq) else "expression"
    return ParsedAnswer(text, value, kind, tuple(stated), tuple(typed))


def _has_undefined(value) -> bool:
    items = value if isinstance(value, tuple) else (value,)
    return any(holds_any(item, _UNDEFINED) for item in items)


_UNDEFINED = frozenset({sympy.zoo, sympy.nan, sympy.oo, -sympy.oo})
