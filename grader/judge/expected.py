"""The expected answer, read once and prepared for many comparisons.

Contents:
    Expected        the reference answer with its setting, parsed and in plain symbols
    Outcome         what a kind's checker concludes, before it becomes a Verdict
    prepare(...)    read and cache an expected answer (author errors raise here)

Preparing costs far more than comparing: parsing, compiling evaluators, deriving
equations of motion. ``prepare`` is cached, so a class of 300 students pays once
per part; the kind checkers add what they derive to ``Expected.cache``.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from functools import lru_cache

import numpy as np
import sympy

from grader.errors import ReferenceAnswerError
from grader.judge.numeric import Compiled
from grader.judge.sampling import POINTS
from grader.judge.setting import Setting
from grader.parse import TIME, ParsedAnswer, parse_answer

__all__ = ["Expected", "Outcome", "prepare"]


@dataclass(frozen=True, eq=False)
class Expected:
    """A prepared reference answer.

    Attributes:
        text: as the author wrote it.
        kind: the answer kind.
        setting: the problem's coordinates, symbols and domains.
        parsed: the parsed answer (``None`` for kinds that are not parsed, such as choice).
        value: the parsed value in plain symbols (coordinates and derivatives as symbols).
        names: every name the problem defines: coordinates, known symbols, the symbols
            of the expected answer, and ``t``.
        options: the kind's options.
        cache: what checkers derive from this answer, kept for the next comparison.
    """

    text: str
    kind: str
    setting: Setting
    parsed: ParsedAnswer | None
    value: object
    names: frozenset[str]
    options: Mapping[str, object]
    cache: dict = field(default_factory=dict, repr=False)

    def option(self, name: str, default=None):
        return self.options.get(name, default)

    @property
    def variables(self) -> tuple[sympy.Symbol, ...]:
        """Every symbol an answer may contain here, in plain form, in a fixed order.

        Submitted answers are evaluated over the same variables at the same points as
        the expected one, so the expected values are computed once and remembered.
        """
        if "variables" not in self.cache:
            parameters = {sympy.Symbol(name) for name in self.names - set(self.setting.coords) - {TIME.name}}
            state = set(self.setting.state.values())
            self.cache["variables"] = (*sorted(parameters | state, key=str), TIME)
        return self.cache["variables"]

    @property
    def point_count(self) -> int:
        """How many sample points a comparison draws, in runs of GROUP that share the parameters.

        Where two or more parameters may be negative, twice as many: two draws of the
        parameters cannot give two such parameters all four pairs of signs, and √(a²b²) would
        pass for −ab; four draws can (see :meth:`Setting.points`).
        """
        if "point count" not in self.cache:
            self.cache["point count"] = 2 * POINTS if len(self.signed_parameters) >= 2 else POINTS
        return self.cache["point count"]

    @property
    def signed_parameters(self) -> tuple[str, ...]:
        """The names of the parameters that may be negative (declared real or nonzero)."""
        if "signed parameters" not in self.cache:
            self.cache["signed parameters"] = tuple(s.name for s in self.variables if self.setting.may_be_negative(s))
        return self.cache["signed parameters"]

    def compiled(self, key: str, expr) -> Compiled:
        """An expression derived from the expected answer, compiled once over :attr:`variables`."""
        cache_key = ("compiled", key)
        if cache_key not in self.cache:
            self.cache[cache_key] = Compiled(expr, self.variables, memo=True)
        return self.cache[cache_key]

    def compile(self, expr) -> Compiled:
        """A submitted expression (as parsed, or in plain symbols), compiled over :attr:`variables`.

        The last one is remembered: a wrong answer is compared with the expected one, its
        small-angle forms and its terms, and compiling walks the whole expression. Only the
        very same object is reused, so concurrent checks at worst compile twice.
        """
        last = self.cache.get("last compiled")
        if last is not None and last[0] is expr:
            return last[1]
        compiled = Compiled(expr, self.variables, aliases=self.setting.aliases)
        self.cache["last compiled"] = (expr, compiled)
        return compiled

    def points(self, count: int, *, salt: int = 0, group: int = 1) -> np.ndarray:
        """Seeded sample points over :attr:`variables`, the same for every submission: an array
        of ``count`` rows, one value per variable (``.tolist()`` for one point as Python numbers).

        Runs of ``group`` points share the parameters' values (see :meth:`Setting.points`).
        """
        cache_key = ("points", count, salt, group)
        if cache_key not in self.cache:
            points = np.array(self.setting.points(self.variables, count, salt=salt, group=group), complex)
            points.flags.writeable = False
            self.cache[cache_key] = points
        return self.cache[cache_key]


@dataclass(frozen=True)
class Outcome:
    """A checker's conclusion: status, credit, the feedback's key and details, and the method;
    ``more``, further sentences of the diagnosis; ``notes``, sentences on how the answer was read."""

    status: str
    score: float = 0.0
    key: str | None = None
    details: Mapping[str, object] = field(default_factory=dict)
    method: str = "numeric"
    more: tuple[tuple[str, Mapping[str, object]], ...] = ()
    notes: tuple[tuple[str, Mapping[str, object]], ...] = ()


def prepare(
    text: str,
    kind: str,
    coords: tuple[str, ...] = (),
    known: tuple[str, ...] = (),
    domains: tuple[tuple[str, str], ...] = (),
    options: tuple[tuple[str, object], ...] = (),
    *,
    parsed: bool = True,
    dimensions: tuple[tuple[str, str], ...] = (),
) -> Expected:
    """The expected answer, read and cached.

    Raises:
        ReferenceAnswerError: when the expected answer cannot be read; the message
            is addressed to the problem's author.
    """
    return _prepare(text, kind, coords, known, domains, options, parsed, dimensions)


@lru_cache(maxsize=1024)
def _prepare(text, kind, coords, known, domains, options, parsed, dimensions) -> Expected:
    setting = Setting.build(coords, known, dict(domains), dict(dimensions))
    if not parsed:
        return Expected(text, kind, setting, None, text, frozenset(), dict(options))
    answer = parse_answer(text, coords=setting.coords, known=setting.known)
    if not answer.ok:
        raise ReferenceAnswerError(
            f"The expected answer {text!r} cannot be read: {_said_of_it(answer.message)}\n{answer.pointer}",
            refusal=answer,
        )
    names = frozenset(setting.coords) | frozenset(setting.known) | {s.name for s in answer.symbols} | {TIME.name}
    return Expected(text, kind, setting, answer, setting.plain(answer.value), names, dict(options))


def _said_of_it(message: str) -> str:
    """A parser's message, which speaks to a student ("Your answer ends too early"), said of the
    expected answer the author is told about: "it ends too early"."""
    return re.sub(r"^Your answer\b", "it", message)
