"""The symbols of a problem, as the checker sees them.

Contents:
    Setting             coordinates, known symbols and their domains
    Setting.plain(v)    an answer with q(t), q̇, q̈ replaced by plain real symbols (as_typed: back)
    Setting.points(...) seeded sample points for a set of symbols

The parser keeps coordinates as functions of time so that ``diff`` works; the
checker evaluates numbers, so each coordinate and each of its derivatives becomes
a plain symbol (``theta``, ``theta__1``, ``theta__2``: names no student can type,
because the parser refuses ``__``).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from functools import cached_property, lru_cache

import sympy

from grader.errors import AuthorError
from grader.judge.numeric import sample_points
from grader.judge.units import DIMENSIONS
from grader.parse.grammar import TIME, coordinate, time_derivative
from grader.parse.names import canonical_name, unicode_name

__all__ = ["DOMAINS", "Setting"]

DOMAINS = ("real", "positive", "negative", "nonzero", "integer")
MAX_ORDER = 3


@dataclass(frozen=True)
class Setting:
    """What a problem defines.

    Attributes:
        coords: canonical names of the generalized coordinates, in order.
        known: canonical names of the other symbols (parameters).
        domains: canonical name → domain, overriding the defaults (coordinates,
            their derivatives and t are real; every other symbol is positive).
        dimensions: canonical name → its dimension (one of :data:`grader.judge.units.DIMENSIONS`),
            where the problem says; a coordinate's derivatives are divided by time.
        given: the names among ``known`` that stand for a quantity of the problem (p_θ for
            m l² θ̇), where answers are diagnosed in them (see :mod:`grader.judge.given`).
        seed: seeds the sample points, so a verdict is the same on every run.
    """

    coords: tuple[str, ...]
    known: tuple[str, ...] = ()
    domains: Mapping[str, str] = field(default_factory=dict)
    dimensions: Mapping[str, str] = field(default_factory=dict)
    given: tuple[str, ...] = ()
    seed: int = 20261121

    @classmethod
    def build(
        cls,
        coords: Iterable[str] = (),
        known: Iterable[str] = (),
        domains: Mapping[str, str] | None = None,
        dimensions: Mapping[str, str] | None = None,
    ):
        """A setting from names in any spelling; raises :class:`AuthorError` for an unknown domain
        or dimension."""
        domains = {canonical_name(name): domain for name, domain in (domains or {}).items()}
        for name, domain in domains.items():
            if domain not in DOMAINS:
                raise AuthorError(f"domain of {name!r} is {domain!r}; allowed: {', '.join(DOMAINS)}")
        dimensions = {canonical_name(name): dimension for name, dimension in (dimensions or {}).items()}
        for name, dimension in dimensions.items():
            if dimension not in DIMENSIONS:
                raise AuthorError(f"dimension of {name!r} is {dimension!r}; allowed: {', '.join(DIMENSIONS)}")
        coords, known = tuple(canonical_name(q) for q in coords), tuple(canonical_name(k) for k in known)
        return cls(coords, known, domains, dimensions)

    @cached_property
    def functions(self) -> dict[str, sympy.Expr]:
        """Coordinate name → the coordinate as a function of time, as the parser builds it."""
        return {name: coordinate(name) for name in self.coords}

    @cached_property
    def state(self) -> dict[tuple[str, int], sympy.Symbol]:
        """(coordinate, order of derivative) → its plain symbol."""
        return {
            (name, order): sympy.Symbol(name if order == 0 else f"{name}__{order}")
            for name in self.coords
            for order in range(MAX_ORDER + 1)
        }

    @property
    def aliases(self) -> dict:
        """q(t), q̇(t), q̈(t)… → their plain symbols, for evaluating an answer as parsed."""
        return self._replacements

    @cached_property
    def _replacements(self) -> dict:
        return {self.node(name, order): symbol for (name, order), symbol in self.state.items()}

    def plain(self, value):
        """An answer's value with coordinates and their derivatives as plain symbols."""
        # xreplace matches whole subtrees top-down, so θ̈ is replaced before the θ inside it.
        if isinstance(value, tuple):
            return tuple(self.plain(item) for item in value)
        if isinstance(value, sympy.Eq):  # rebuilding an Eq would make sympy try to decide it
            return sympy.Eq(self.plain(value.lhs), self.plain(value.rhs), evaluate=False)
        return value.xreplace(self._plain_rule)

    @cached_property
    def _plain_rule(self) -> dict:
        return self._replacements | _angle_functions(self.coords)

    def as_typed(self, value):
        """The reverse of :meth:`plain`: plain symbols back to q(t), q̇, q̈…, which print as θ, θ̇, θ̈."""
        return value.xreplace(self._typed)

    @cached_property
    def _typed(self) -> dict:
        return {symbol: node for node, symbol in self._replacements.items()}

    def node(self, name: str, order: int) -> sympy.Expr:
        """The coordinate, or its derivative of ``order`` (up to ``MAX_ORDER``), as the parser builds it."""
        return self._nodes[(name, order)]

    @cached_property
    def _nodes(self) -> dict:
        # built once: a sympy Derivative takes 16 µs to build, 150 µs with sympy's cache emptied
        return {
            (name, order): time_derivative(q, order) if order else q
            for name, q in self.functions.items()
            for order in range(MAX_ORDER + 1)
        }

    def velocity(self, name: str) -> sympy.Symbol:
        return self.state[(name, 1)]

    def acceleration(self, name: str) -> sympy.Symbol:
        return self.state[(name, 2)]

    def is_state(self, symbol: sympy.Symbol) -> bool:
        """Coordinates, their derivatives, given names (a momentum), and time: what varies along a motion."""
        return symbol == TIME or symbol in self.varying

    @cached_property
    def angles(self) -> frozenset:
        """The plain symbols of the coordinates, and the difference of each two (θ₁ − θ₂ and θ₂ − θ₁)."""
        coordinates = [self.state[(name, 0)] for name in self.coords]
        return frozenset(coordinates) | {a - b for a in coordinates for b in coordinates if a != b}

    @cached_property
    def said(self) -> dict:
        """The problem's own functions of :attr:`angles` as feedback words them, kept for the next
        answer (see :mod:`grader.judge.diagnose`)."""
        return {}

    @cached_property
    def varying(self) -> frozenset:
        """The plain symbols of the coordinates and their derivatives, and the given names."""
        return frozenset(self.state.values()) | {sympy.Symbol(name) for name in self.given}

    def domain(self, symbol: sympy.Symbol) -> str:
        if self.is_state(symbol):
            return self.domains.get(symbol.name, "real")
        return self.domains.get(symbol.name, "positive")

    def may_be_negative(self, symbol: sympy.Symbol) -> bool:
        """Whether ``symbol`` is a parameter declared real or nonzero: its sign is drawn per draw."""
        return not self.is_state(symbol) and self.domain(symbol) in ("real", "nonzero")

    def points(self, variables, count: int, *, salt: int = 0, group: int = 1) -> list[list[complex]]:
        """``count`` sample points for ``variables`` (a sequence of symbols).

        Consecutive runs of ``group`` points share their parameter values and differ
        only in the state, so a test can ask whether something is constant along
        the motion (an additive constant like m g l may depend on the parameters).
        """
        domains = {symbol: self.domain(symbol) for symbol in variables}
        points = sample_points(variables, domains, count, self.seed + salt)
        parameters = [i for i, symbol in enumerate(variables) if not self.is_state(symbol)]
        signed = [i for i in parameters if self.may_be_negative(variables[i])]
        for start in range(0, count, group):
            signs = _signs(start // group, len(signed), count // group)
            for i, sign in zip(signed, signs, strict=True):
                points[start][i] = sign * abs(points[start][i].real)
            for point in points[start + 1 : start + group]:
                for i in parameters:
                    point[i] = points[start][i]
        return points

    def describe(self, names: Iterable[str]) -> str:
        """Names as a student reads them: ``m, l, g, θ``."""
        return ", ".join(unicode_name(name) for name in names)


@lru_cache(maxsize=256)
def _angle_functions(coords: tuple[str, ...]) -> dict:
    """sin and cos of each coordinate, and of the difference of each two (θ₁ − θ₂), as parsed → in plain
    symbols, as :meth:`Setting.plain` would rebuild them: a function of a new argument is evaluated
    afresh, and with sympy's cache emptied cos(θ₁ − θ₂) costs a millisecond. Most answers have some."""
    plain = {coordinate(name): sympy.Symbol(name) for name in coords}
    angles = [*plain, *(a - b for a in plain for b in plain if a != b)]
    typed = [function(angle) for function in (sympy.sin, sympy.cos) for angle in angles]
    # sin(θ₂ − θ₁) is −sin(θ₁ − θ₂), a product: only the functions themselves are whole subtrees to match
    return {f: f.xreplace(plain) for f in typed if isinstance(f, sympy.sin | sympy.cos)}


def _signs(draw: int, count: int, draws: int) -> list[int]:
    """The signs of ``count`` parameters that may be negative, in parameter draw ``draw`` of ``draws``.

    Random signs would leave a parameter positive in every draw a quarter of the time with two
    draws, and √(a²) would pass for a. Instead, parameter k takes the sign (−1)^|draw ∧ mask_k|
    (the parity of the bits they share), with masks 1, 2, 3, … below the number of draws. Each
    parameter is negative in half the draws, and two whose masks differ meet all four pairs of
    signs (two draws of signs are too few for that: there, parameters alternate, so that
    neighbours differ and √(a²b²) cannot pass for ab).

    >>> [_signs(draw, 3, 4) for draw in range(4)]
    [[1, 1, 1], [-1, 1, -1], [1, -1, -1], [-1, -1, 1]]
    >>> [_signs(draw, 3, 2) for draw in range(2)]
    [[1, -1, 1], [-1, 1, -1]]
    """
    if draws < 2:
        return [1] * count
    if draws < 4:
        return [(-1) ** (draw + k) for k in range(count)]
    masks = range(1, 2 ** (draws.bit_length() - 1))  # bits a draw number below ``draws`` can hold
    return [(-1) ** (draw & masks[k % len(masks)]).bit_count() for k in range(count)]
