"""Lagrange's equation as a student writes it on the way to an equation of motion.

Contents:
    euler_lagrange(text, coords, names)   whether ``text`` is d/dt(∂L/∂q̇) − ∂L/∂q: True, False, or None
    moved_left(operator, side)            ``… = −∂F/∂ẋ`` as the operator ``… + ∂F/∂ẋ``, its side moved left
    dissipative(operator)                 whether an operator holds Rayleigh's ``∂F/∂q̇``
    from_a_lagrangian(side, q)            whether a side the operator is said to equal can be what it gives
    force_agrees(operator, force, …)      whether ``operator = −b ẋ`` agrees with the equation said to follow

``Applying d/dt(∂L/∂θ̇) − ∂L/∂θ = 0: m l² θ̈ + m g l sin θ = 0``: the operator says how the equation was
found, and is read past before it (:func:`grader.judge.words.euler_lagrange_then_formula`). Only the true
one may be: d/dt(∂L/∂q̇) − ∂L/∂q for a coordinate q of the problem (or q, q_j in general), with either
sign, its two terms in either order, written with ∂ or d, in plain notation or TeX's, and Rayleigh's
``+ ∂F/∂q̇`` where there is friction. ∂V, ∂H or ∂T for ∂L, q and q̇ swapped, or a plus between the two
terms is another operator: it states what is not Lagrange's equation, which a person reads.
"""

from __future__ import annotations

import re
from collections.abc import Collection
from typing import NamedTuple

import sympy

from grader.parse.messages import ParseFailure
from grader.parse.names import canonical_name
from grader.parse.tokens import Token, tokenize

__all__ = ["dissipative", "euler_lagrange", "force_agrees", "from_a_lagrangian", "moved_left"]

_LENGTH = 200  # characters: an operator is short; anything longer is not read as one
_DISSIPATION = frozenset({"F", "R", "D"})  # Rayleigh's function, as texts name it (TeX's \mathcal{F} is F)
_GENERIC = re.compile(r"q(?:_?[a-z0-9]+)?")  # q, q_j, q_k: a coordinate in general
_BRACKETS = {"(": ")", "[": "]", "{": "}"}


class _Term(NamedTuple):
    sign: int
    rate: bool  # d/dt of the quotient
    top: str  # L of ∂L/∂θ̇
    bottom: str  # thetadot of ∂L/∂θ̇, as the parser names a velocity


def euler_lagrange(text: str, coords: Collection[str], names: Collection[str] = ()) -> bool | None:
    """Whether ``text`` is the Euler–Lagrange operator of a coordinate of the problem (``coords``): True
    for the true one, False for another of its shape (a rate d/dt(∂·/∂·) and a derivative ∂·/∂·, and
    nothing else), None for a text of any other shape (``∂L/∂θ̇``, a momentum's name; ``d/dt(∂L/∂φ̇)``,
    a conserved momentum's rate; or no derivative at all). A generic q may be named where the problem
    has no q of its own (``names``).

    >>> euler_lagrange("d/dt(∂L/∂θ̇) − ∂L/∂θ", ["theta"]), euler_lagrange("∂L/∂θ − d/dt(dL/dthetadot)", ["theta"])
    (True, True)
    >>> euler_lagrange("d/dt(∂V/∂θ̇) − ∂V/∂θ", ["theta"]), euler_lagrange("d/dt(∂L/∂θ) − ∂L/∂θ̇", ["theta"])
    (False, False)
    >>> euler_lagrange("∂L/∂θ̇", ["theta"]) is None
    True
    """
    if len(text) > _LENGTH or "dt" not in text:
        return None  # as nearly every text: no d/dt
    try:
        tokens = tokenize(text)
    except ParseFailure:
        return None
    terms = _terms(tokens)
    if terms is None or all(term.rate for term in terms) or not any(term.rate for term in terms):
        return None
    return _true(terms, coords, names)


def moved_left(operator: str, side: str) -> str | None:
    """``d/dt(∂L/∂ẋ) − ∂L/∂x = −∂F/∂ẋ``, Rayleigh's term on the right: the operator with ``side``, one
    derivative ∂·/∂· alone, moved to its left, its sign changed (as :func:`euler_lagrange` then judges
    it); None where ``side`` is anything else (``0``, a generalized force ``Q_x``, an equation's side).

    >>> moved_left("d/dt(∂L/∂ẋ) − ∂L/∂x", "−∂F/∂ẋ")
    'd/dt(∂L/∂ẋ) − ∂L/∂x + ∂F/∂ẋ'
    >>> moved_left("d/dt(∂L/∂ẋ) − ∂L/∂x", "m ẍ") is None
    True
    """
    if len(side) > _LENGTH:
        return None
    try:
        tokens = tokenize(side)
    except ParseFailure:
        return None
    terms = _terms(tokens)
    if terms is None or len(terms) != 1 or terms[0].rate:
        return None
    term = side.strip().lstrip("+-−").strip()
    return f"{operator.strip()} {'+' if terms[0].sign < 0 else '−'} {term}"


def dissipative(operator: str) -> bool:
    """Whether an operator of Lagrange's shape holds a term of Rayleigh's function (``+ ∂F/∂ẋ``).

    >>> dissipative("d/dt(∂L/∂ẋ) − ∂L/∂x + ∂F/∂ẋ"), dissipative("d/dt(∂L/∂ẋ) − ∂L/∂x")
    (True, False)
    """
    try:
        terms = _terms(tokenize(operator)) if len(operator) <= _LENGTH else None
    except ParseFailure:
        return False
    return any(not term.rate and term.top in _DISSIPATION for term in terms or ())


def force_agrees(operator: str, force: sympy.Expr, motion: sympy.Expr, coordinate: str) -> bool:
    """Whether ``operator = force`` (``d/dt(∂L/∂ẋ) − ∂L/∂x = −b ẋ``, the generalized force written out) and
    the equation ``motion = 0`` it is said to give (left side minus right, as typed) agree: the operator
    then comes to ``motion`` plus the force (its sign as the operator's), which must be what some L gives
    (:func:`from_a_lagrangian`), with a positive factor of q̈, as a kinetic energy gives. The scale is the
    equation's as typed: ``m ẍ + k x + b ẋ = 0`` with ``= −b ẋ`` agree, ``= +b ẋ`` and ``= −2 b ẋ`` do not.

    >>> t, m, k, b = sympy.symbols("t m k b")
    >>> x = sympy.Function("x")(t)
    >>> motion = m * x.diff(t, 2) + b * x.diff(t) + k * x
    >>> force_agrees("d/dt(∂L/∂ẋ) − ∂L/∂x", -b * x.diff(t), motion, "x")
    True
    >>> force_agrees("d/dt(∂L/∂ẋ) − ∂L/∂x", b * x.diff(t), motion, "x")
    False
    """
    try:
        terms = _terms(tokenize(operator)) if len(operator) <= _LENGTH else None
    except ParseFailure:
        return False
    rates = [term for term in terms or () if term.rate]
    if len(rates) != 1 or dissipative(operator):
        return False  # Rayleigh's term and a force besides: for a person
    comes_to = motion + rates[0].sign * force
    if from_a_lagrangian(comes_to, coordinate) is not True:
        return False
    (function,) = comes_to.atoms(sympy.core.function.AppliedUndef)
    factor = comes_to.diff(function.diff(function.args[0], 2))
    names = sorted(factor.free_symbols, key=str)
    rates_and_coordinate = sorted(factor.atoms(sympy.Derivative, sympy.core.function.AppliedUndef), key=str)
    for trial in _TRIALS:
        values = {name: sympy.Float(trial[number % len(trial)] + number / 10) for number, name in enumerate(names)}
        values |= {item: sympy.Float(trial[number % len(trial)]) for number, item in enumerate(rates_and_coordinate)}
        try:
            value = complex(factor.xreplace(values).evalf(15))
        except (TypeError, ValueError, ArithmeticError):
            return False
        if not (value.real > 0 and abs(value.imag) < _NEAR_ZERO):
            return False
    return True


# values the names take where a condition is tested: two sets, of no special value (not 0 or 1)
_TRIALS = ((0.7, 1.3, 0.45), (1.9, 0.35, 2.6))
_NEAR_ZERO = 1e-9


def from_a_lagrangian(side: sympy.Expr, coordinate: str) -> bool | None:
    """Whether ``side``, in one coordinate q(t) (its name), its rates and the time, can be what d/dt(∂L/∂q̇) − ∂L/∂q
    gives for some L(q, q̇, t): linear in q̈, as A q̈ + B, with ∂B/∂q̇ = dA/dt (Helmholtz's condition for one
    coordinate). ``m ẍ + b ẋ + k x`` cannot be, where b is not 0: friction comes from no L of this kind, and
    needs Rayleigh's term. None where ``side`` is no such expression (a rate above q̈, another function).

    >>> t, m, k, b = sympy.symbols("t m k b")
    >>> x = sympy.Function("x")(t)
    >>> spring, damped = m * x.diff(t, 2) + k * x, m * x.diff(t, 2) + b * x.diff(t) + k * x
    >>> from_a_lagrangian(spring, "x"), from_a_lagrangian(damped, "x")
    (True, False)
    """
    functions = side.atoms(sympy.core.function.AppliedUndef)
    if len(functions) != 1 or next(iter(functions)).func.__name__ != coordinate:
        return None
    (coordinate,) = functions
    (time,) = coordinate.args
    q, velocity, acceleration = sympy.symbols("q_ v_ a_", cls=sympy.Dummy)
    plain = side.xreplace({coordinate.diff(time, 2): acceleration, coordinate.diff(time): velocity})
    plain = plain.xreplace({coordinate: q})
    if plain.atoms(sympy.Derivative, sympy.core.function.AppliedUndef):
        return None
    factor = plain.diff(acceleration)
    if factor.has(acceleration):
        return None
    rest = plain - factor * acceleration
    rate = factor.diff(time) + factor.diff(q) * velocity + factor.diff(velocity) * acceleration
    condition = sympy.expand(rest.diff(velocity) - rate)
    if condition == 0:
        return True
    names = sorted(condition.free_symbols, key=str)
    for trial in _TRIALS:
        values = {name: trial[number % len(trial)] + number / 10 for number, name in enumerate(names)}
        try:
            value = complex(condition.evalf(15, subs=values))
        except (TypeError, ValueError, ArithmeticError):
            return None
        if abs(value) < _NEAR_ZERO:
            return True  # cos² + sin² − 1, unexpanded: zero somewhere it is no condition
    return False


def _true(terms: list[_Term], coords: Collection[str], names: Collection[str]) -> bool:
    """Whether ``terms`` are d/dt(∂L/∂q̇) − ∂L/∂q (either sign), and perhaps + ∂F/∂q̇, of one coordinate."""
    rates = [term for term in terms if term.rate]
    forces = [term for term in terms if not term.rate and not term.bottom.endswith("dot")]
    if len(rates) != 1 or len(forces) != 1:
        return False
    rate, force = rates[0], forces[0]
    coordinate = force.bottom
    known = coordinate in coords or (_GENERIC.fullmatch(coordinate) is not None and coordinate not in names)
    if not known or (rate.top, force.top, rate.bottom) != ("L", "L", f"{coordinate}dot") or rate.sign == force.sign:
        return False
    dissipation = [term for term in terms if term not in (rate, force)]
    return all(
        term.top in _DISSIPATION and term.bottom == rate.bottom and term.sign == rate.sign for term in dissipation
    )


def _terms(tokens: list[Token]) -> list[_Term] | None:
    """The signed terms of ``tokens``, each d/dt of a partial derivative or one alone; None where
    they are anything else."""
    terms, i = [], 0
    while True:
        sign = 1
        if tokens[i].is_op("+", "-"):
            sign = -1 if tokens[i].is_op("-") else 1
            i += 1
        elif terms:
            return None  # two terms side by side: a product
        found = _rate(tokens, i) or _quotient(tokens, i)
        if found is None:
            return None
        i, rate, top, bottom = found
        terms.append(_Term(sign, rate, top, bottom))
        if tokens[i].kind == "end":
            return terms


def _rate(tokens: list[Token], i: int) -> tuple[int, bool, str, str] | None:
    """``d/dt(∂L/∂θ̇)``, ``d/dt ∂L/∂θ̇`` or TeX's ``\\frac{d}{dt}\\left(…\\right)`` at ``i``: (the position
    after it, True, the quotient's top and bottom); None where there is none."""
    if _is_name(tokens[i], "d") and tokens[i + 1].is_op("/") and _is_name(tokens[i + 2], "dt"):
        i += 3
    elif (
        tokens[i].kind == "frac"
        and [token.value for token in tokens[i + 1 : i + 7] if token.kind == "op"] == ["{", "}", "{", "}"]
        and _is_name(tokens[i + 2], "d")
        and _is_name(tokens[i + 5], "dt")
    ):
        i += 7
    else:
        return None
    closer = _BRACKETS.get(tokens[i].value) if tokens[i].kind == "op" else None
    found = _quotient(tokens, i + 1 if closer else i)
    if found is None:
        return None
    j, _, top, bottom = found
    if closer:
        if not tokens[j].is_op(closer):
            return None
        j += 1
    return j, True, top, bottom


def _quotient(tokens: list[Token], i: int) -> tuple[int, bool, str, str] | None:
    """``∂L/∂θ``, ``dL/dθ``, ``d L/d θ`` or TeX's ``\\frac{\\partial L}{\\partial \\theta}`` at ``i``: (the
    position after it, False, its top and bottom, as ``L`` and ``theta``); None where there is none."""
    if tokens[i].kind == "frac" and tokens[i + 1].is_op("{"):
        top = _differential(tokens, i + 2)
        if top is None or not tokens[top[0]].is_op("}") or not tokens[top[0] + 1].is_op("{"):
            return None
        bottom = _differential(tokens, top[0] + 2)
        if bottom is None or not tokens[bottom[0]].is_op("}"):
            return None
        return bottom[0] + 1, False, top[1], bottom[1]
    top = _differential(tokens, i)
    if top is None or not tokens[top[0]].is_op("/"):
        return None
    bottom = _differential(tokens, top[0] + 1)
    return None if bottom is None else (bottom[0], False, top[1], bottom[1])


def _differential(tokens: list[Token], i: int) -> tuple[int, str] | None:
    """``∂L``, ``dL``, ``d L`` or ``∂θ̇`` at ``i``: (the position after it, the name differentiated, as
    the parser names it: ``thetadot``); None where there is none."""
    token = tokens[i]
    if (token.kind == "partial" or _is_name(token, "d")) and tokens[i + 1].kind == "name":
        return i + 2, _named(tokens[i + 1].value.raw, tokens[i + 1])
    if token.kind == "name" and token.value.raw.startswith("d") and len(token.value.raw) > 1:
        return i + 1, _named(token.value.raw[1:], token)  # dL, dthetadot: one name as typed
    return None


def _named(raw: str, token: Token) -> str:
    return canonical_name(raw) + "dot" * (token.value.dots + token.value.primes)


def _is_name(token: Token, raw: str) -> bool:
    return token.kind == "name" and token.value.raw == raw and not token.value.dots and not token.value.primes
