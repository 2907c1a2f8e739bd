"""Fast numeric evaluation of sympy expressions, without ``lambdify``.

Contents:
    Compiled            an expression turned into nested closures, evaluated in
                        complex floats (at one point, or at many at once with
                        numpy), for near misses in 40-digit mpmath, exactly
                        in fractions when it is a rational function, and with
                        its first and mixed second derivatives (hyper-dual numbers)
    NotCompilable       an expression holds something we cannot evaluate
    sample_points(...)  seeded random points inside the symbols' domains
    Closeness           EQUAL / DIFFERENT / UNSURE for two numbers and their scale

Why not ``lambdify``: it writes Symbol names into Python source and ``exec``s it
(sympy #24990), and compiling costs ~2 ms per expression, more than the whole
budget of a verdict. Closures over a variable index cost ~0.1 ms to build and
~0.3 µs per node and point to evaluate; over numpy arrays, ~1 µs per node for
all of a comparison's points at once. A batch in which any point divides by zero
or overflows is redone point by point, so an undefined point is treated the same
whichever way it was evaluated.

Every evaluation also reports its *scale*: the largest magnitude seen among the
terms of any sum. Two values that agree to 1e-13 of that scale are equal; one
cancelling ``1e3 - 1e3`` must not make 1e-13 of rounding look like a difference.
And it notes where a sum *lost* a term: one nonzero but below what the sum can
resolve (1e-13 of its largest term in floats, 1e-25 at 40 digits), as m is lost
beside e^(10(m + 2)). A value that lost a term cannot say the term was there: floats
that lost one defer to 40 digits, and 40 digits that lose one call the point
undefined (:class:`LostTerm`), so that another point or ``simplify`` decides.
"""

from __future__ import annotations

import enum
import functools
import math
import random
from collections.abc import Callable, Mapping, Sequence
from fractions import Fraction
from functools import cached_property

import mpmath
import numpy as np
import sympy
from sympy.core.function import AppliedUndef

from grader.parse.functions import COMPLEX, with_reciprocals

__all__ = ["UNDEFINED", "Closeness", "Compiled", "LostTerm", "NotCompilable", "closeness", "sample_points"]

PRECISE_DIGITS = 40

# Equal pairs differed by at most ~1e-14 of their scale in float; a term of 1e-9 of the
# scale (or a constant off by one in a sum of billions) must not pass. Between the two
# bounds the float result cannot decide: re-evaluate at 40 digits.
FLOAT_EQUAL = 1e-13
FLOAT_DIFFERENT = 1e-6
PRECISE_EQUAL = 1e-25


UNDEFINED = (ArithmeticError, ValueError, TypeError)  # what evaluating at a point outside the domain raises


class LostTerm(ArithmeticError):
    """At 40 digits a sum lost a term: this point cannot tell whether the term is there."""


class NotCompilable(Exception):  # a condition reported to the caller, not an error
    """The expression contains an object the evaluator does not know."""


class _Backend:
    """The number type and functions one kind of evaluation uses; ``vector`` evaluates numpy arrays.
    ``resolution``: a sum's term smaller than this times its largest is lost (0: exact, never);
    ``digits``: a number p/q with p or q beyond this is lost too (it holds more than the type).
    Losses are noted only when asked: ``scale[1]`` is False (and becomes True), not None."""

    def __init__(
        self, number, functions: Mapping[str, Callable], pi, e, *, vector=False, resolution=FLOAT_EQUAL, digits=2**53
    ):
        self.number, self.functions, self.pi, self.e, self.vector = number, functions, pi, e, vector
        self.resolution, self.digits = resolution, digits


def _power(base, exponent):
    if isinstance(base, complex) and base.imag == 0:
        base = complex(base.real, 0.0)
    return base**exponent


_FLOAT = _Backend(
    number=lambda p, q: complex(p / q),
    functions={
        **COMPLEX,
        "re": lambda z: complex(z.real), "im": lambda z: complex(z.imag),
    },
    pi=lambda: complex(math.pi), e=lambda: complex(math.e),
)  # fmt: skip


def _on_branch(z):
    """The array's real values with imaginary part +0.0: see :func:`grader.parse.functions.principal`."""
    return np.where(z.imag == 0, z.real + 0j, z)


def _vector_principal(function):
    return lambda z: function(_on_branch(z))


def _vector_sign(z):
    size = np.abs(z)
    return np.where(size == 0, 0j, z / np.where(size == 0, 1.0, size))


_VECTOR = _Backend(
    number=lambda p, q: complex(p / q),
    functions=with_reciprocals({
        "sin": np.sin, "cos": np.cos, "tan": np.tan,
        "asin": _vector_principal(np.arcsin), "acos": _vector_principal(np.arccos), "atan": np.arctan,
        "sinh": np.sinh, "cosh": np.cosh, "tanh": np.tanh,
        "asinh": _vector_principal(np.arcsinh), "acosh": _vector_principal(np.arccosh),
        "atanh": _vector_principal(np.arctanh),
        "exp": np.exp, "log": _vector_principal(np.log), "Abs": lambda z: np.abs(z) + 0j,
        "sign": _vector_sign, "re": lambda z: z.real + 0j, "im": lambda z: z.imag + 0j,
    }),
    pi=lambda: complex(math.pi), e=lambda: complex(math.e), vector=True,
)  # fmt: skip


def _mp(name):
    return getattr(mpmath, name)


_PRECISE = _Backend(
    number=lambda p, q: mpmath.mpf(p) / q,
    functions={
        **{name: _mp(name) for name in ("sin", "cos", "tan", "cot", "sec", "csc", "asin", "acos", "atan")},
        **{name: _mp(name) for name in ("sinh", "cosh", "tanh", "coth", "sech", "csch", "asinh", "acosh", "atanh")},
        **{name: _mp(name) for name in ("exp", "log")},
        "Abs": abs, "sign": lambda z: 0 if z == 0 else z / abs(z),
        "re": lambda z: mpmath.re(z), "im": lambda z: mpmath.im(z),
    },
    pi=lambda: +mpmath.pi, e=lambda: +mpmath.e,  # + fixes the value at the working precision
    resolution=PRECISE_EQUAL, digits=10**38,
)  # fmt: skip


_ALIASABLE = (sympy.Derivative, AppliedUndef)
_EXACT = _Backend(number=Fraction, functions={}, pi=None, e=None, resolution=0, digits=math.inf)


def _is_rational_function(expr) -> bool:
    """Only +, ×, integer powers, rationals and variables: exactly computable with fractions."""
    if expr.is_Symbol or expr.is_Rational or isinstance(expr, _ALIASABLE):
        return True
    if expr.is_Add or expr.is_Mul:
        return all(_is_rational_function(arg) for arg in expr.args)
    if expr.is_Pow:
        return expr.exp.is_Integer and _is_rational_function(expr.base)
    return False


class Compiled:
    """An expression ready to evaluate at many points.

    Args:
        expr: a sympy expression in plain symbols (no functions of time).
        variables: the symbols, in the order values will be given.

    Raises:
        NotCompilable: for an object outside the whitelist of the parser's functions.
    """

    def __init__(
        self,
        expr: sympy.Expr,
        variables: Sequence[sympy.Symbol],
        *,
        memo: bool = False,
        aliases: Mapping[sympy.Expr, sympy.Symbol] | None = None,
    ):
        self.expr = expr
        self.index = {symbol: i for i, symbol in enumerate(variables)}
        # Aliases let an answer keep θ(t) and its derivatives: each is read as the variable it
        # stands for, which spares rebuilding the whole expression in plain symbols first.
        self.index |= {node: self.index[symbol] for node, symbol in (aliases or {}).items() if symbol in self.index}
        self._float = None  # each evaluator is compiled when first needed
        self._vector = None
        self._jet = None
        self._precise = None
        self._exact = None  # compiled when first needed: most comparisons never need it
        self._last: dict = {}  # kind of evaluation → (key, result) of the last batch, when not memoized
        # A reference answer is evaluated at the same points for every submission: remember them.
        self._memo: dict | None = {} if memo else None

    def __call__(self, values: Sequence[complex]) -> tuple[complex, float]:
        """The value and its scale at ``values``; raises ArithmeticError/ValueError where undefined.

        A reference answer's values are remembered: call this at the seeded sample points,
        which are the same for every submission, and :meth:`at` anywhere else.
        """
        if self._memo is not None:
            key = tuple(values)
            if key not in self._memo:
                try:
                    self._memo[key] = self.at(values)
                except UNDEFINED as undefined:
                    self._memo[key] = undefined
            result = self._memo[key]
            if isinstance(result, Exception):
                raise result
            return result
        return self.at(values)

    def at(self, values: Sequence[complex]) -> tuple[complex, float]:
        """The same, never remembered: for points that depend on a submission (a root being
        searched for), which would otherwise grow a reference's memory with every answer."""
        if self._float is None:
            self._float = _compile(self.expr, self.index, _FLOAT)
        scale = [0.0, None]
        value = self._float(values, scale)
        return value, max(scale[0], abs(value))

    def _remembered(self, key: tuple, compute):
        """``compute()``, kept under ``key`` when this is a reference answer's (``memo``);
        a submitted answer's keeps only its last result of each kind (``key[0]``): the same
        points are asked for again by the next diagnosis, and :meth:`lost` comes in between."""
        if self._memo is None:
            last = self._last.get(key[0])
            if last is None or last[0] != key:
                last = self._last[key[0]] = (key, compute())
            return last[1]
        if key not in self._memo:
            self._memo[key] = compute()
        return self._memo[key]

    def many(self, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Values and scales at every row of ``points`` (count × variables); NaN where undefined."""
        return self._remembered(("many", points.shape, points.tobytes()), lambda: self._many(points))

    def many_once(self, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The same as :meth:`many`, never remembered: for points that depend on a submission."""
        return self._many(points)

    def _many(self, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        if self._vector is None:
            self._vector = _compile(self.expr, self.index, _VECTOR)

        def evaluate(rows):
            scale = [0.0, None]
            value = np.broadcast_to(np.asarray(self._vector(rows.T, scale), complex), len(rows))
            return value, np.maximum(scale[0], np.abs(value))

        return _row_by_row_if_undefined(evaluate, np.ascontiguousarray(points))

    def lost(self, points: np.ndarray) -> np.ndarray:
        """At every row of ``points``: whether a sum lost a term there (see the module's notes);
        False where undefined.

        A lost term can only make different values look equal, so this is asked only where
        :meth:`many`'s values agree, in a pass of its own: noting losses costs a third of
        an evaluation, which different answers would pay for nothing.
        """
        return self._remembered(("lost", points.shape, points.tobytes()), lambda: self._lost(points))

    def _lost(self, points: np.ndarray) -> np.ndarray:
        if self._vector is None:
            self._vector = _compile(self.expr, self.index, _VECTOR)

        def evaluate(rows):
            scale = [0.0, False]  # False, not None: note losses
            self._vector(rows.T, scale)
            lost = np.broadcast_to(np.asarray(scale[1], complex), len(rows))
            return lost, np.zeros(len(rows))

        lost, _ = _row_by_row_if_undefined(evaluate, np.ascontiguousarray(points))
        return lost.real == 1  # NaN (undefined) and 0 are not lost

    def derivatives(self, points: np.ndarray, first: np.ndarray, second: np.ndarray) -> tuple[np.ndarray, ...]:
        """At every row of ``points``: the derivative along the same row of ``first``, the mixed second
        derivative along ``first`` and ``second``, and the scale of both (the largest term summed
        into either); NaN where undefined.

        Forward-mode differentiation: one pass over hyper-dual numbers a + b ε₁ + c ε₂ + d ε₁ε₂
        (ε₁² = ε₂² = 0), exact but for rounding.
        """
        return self._jets(points, first, second)[:3]

    def derivatives_lost(self, points: np.ndarray, first: np.ndarray, second: np.ndarray) -> np.ndarray:
        """At every row: whether a sum in the value or those derivatives lost a term there (see the
        module's notes). Noted in the same pass as :meth:`derivatives`: a third more than a pass
        without, where a pass of its own would cost a whole one."""
        return self._jets(points, first, second)[3]

    def _jets(self, points: np.ndarray, first: np.ndarray, second: np.ndarray) -> tuple[np.ndarray, ...]:
        key = ("derivatives", points.shape, points.tobytes(), first.tobytes(), second.tobytes())
        return self._remembered(key, lambda: self._derivatives(points, first, second))

    def _derivatives(self, points: np.ndarray, first: np.ndarray, second: np.ndarray) -> tuple[np.ndarray, ...]:
        if self._jet is None:
            self._jet = _compile_jet(self.expr, self.index)

        def evaluate(rows, one, two):
            scale = [0.0, False]
            _, slope, _, mixed = self._jet(rows.T, one.T, two.T, scale)
            parts = (slope, mixed, scale[1])
            slope, mixed, lost = (np.broadcast_to(np.asarray(part, complex), len(rows)) for part in parts)
            size = np.maximum(scale[0], np.maximum(np.abs(slope), np.abs(mixed)))
            return np.stack([slope, mixed, lost]), size

        arrays = (np.ascontiguousarray(array) for array in (points, first, second))
        (slope, mixed, lost), scale = _row_by_row_if_undefined(evaluate, *arrays, parts=3)
        return slope, mixed, scale, lost.real == 1

    @cached_property
    def constant(self) -> bool:
        """Whether the expression depends on no variable (a reference's is asked on every comparison)."""
        return not self.expr.free_symbols and not self.expr.atoms(*_ALIASABLE)

    @cached_property
    def rational(self) -> bool:
        """Whether :meth:`exact` can evaluate this expression."""
        return _is_rational_function(self.expr)

    def exact(self, values: Sequence[complex]) -> tuple[Fraction, float]:
        """The exact value at real ``values``, for a rational function of the variables.

        Floats cannot tell a degree-13 polynomial from one whose constant is off by one.
        """
        scale = [0.0, None]
        if self._exact is None:
            self._exact = _compile(self.expr, self.index, _EXACT)
        value = self._exact([Fraction(v.real) for v in values], scale)
        return value, max(scale[0], float(abs(value)))

    def precise(self, values: Sequence[complex]) -> tuple[object, float]:
        """The same at 40 digits, for values the float evaluation could not tell apart.

        Raises:
            LostTerm: a sum lost a term even at 40 digits.
        """
        with mpmath.workdps(PRECISE_DIGITS):
            if self._precise is None:  # constants are fixed when compiled: at 40 digits too
                self._precise = _compile(self.expr, self.index, _PRECISE)
            scale = [0.0, False]
            value = self._precise([mpmath.mpmathify(v) for v in values], scale)
            if scale[1]:
                raise LostTerm("a term is below 40 digits' resolution here")
            return value, max(scale[0], float(abs(value)))


def _compile(expr, index: Mapping[sympy.Symbol, int], backend: _Backend):
    """Nested closures ``f(values, scale) -> value``; ``scale[0]`` collects the largest term."""
    if expr.is_Symbol or isinstance(expr, _ALIASABLE):
        if expr not in index:
            raise NotCompilable(f"unknown symbol {expr}")
        position = index[expr]
        return lambda values, scale: values[position]
    if expr.is_Rational or expr.is_Float:
        exact = expr if expr.is_Rational else sympy.Rational(expr)
        p, q = int(exact.p), int(exact.q)
        try:
            constant = backend.number(p, q)
        except OverflowError as overflow:
            raise NotCompilable("a number too large for floating point") from overflow
        if max(abs(p), q) > backend.digits:
            # 1 + 10⁻³⁰ folded into one number: a sum whose small term rounds away

            def rounded(values, scale):
                if scale[1] is not None:
                    scale[1] = True
                return constant

            return rounded
        return lambda values, scale: constant
    if expr is sympy.pi:
        pi = backend.pi
        return lambda values, scale: pi()
    if expr is sympy.E:
        e = backend.e
        return lambda values, scale: e()
    if expr is sympy.I:
        return lambda values, scale: 1j
    args = [_compile(arg, index, backend) for arg in expr.args]
    if backend.vector and (expr.is_Add or (expr.is_Pow and not expr.exp.is_Integer)):
        return _vector_node(expr, args)
    if expr.is_Add:
        resolution = backend.resolution

        def add(values, scale):
            total, largest, smallest = 0, 0.0, math.inf
            for f in args:
                term = f(values, scale)
                total += term
                size = abs(term)
                if size > largest:
                    largest = size
                if 0 < size < smallest:
                    smallest = size
            if largest > scale[0]:
                scale[0] = float(largest)
            if scale[1] is not None and smallest < resolution * largest:
                scale[1] = True
            return total

        return add
    if expr.is_Mul:

        def mul(values, scale):
            product = 1
            for f in args:
                product *= f(values, scale)
            return product

        return mul
    if expr.is_Pow:
        base, exponent = args
        if expr.exp.is_Integer:
            n = int(expr.exp)
            return lambda values, scale: base(values, scale) ** n
        return lambda values, scale: _power(base(values, scale), exponent(values, scale))
    name = type(expr).__name__
    if name in backend.functions and len(args) == 1:
        function, (argument,) = backend.functions[name], args
        return lambda values, scale: function(argument(values, scale))
    raise NotCompilable(f"cannot evaluate {name}")


def _vector_node(expr, args):
    """The closures that differ over numpy arrays: a sum tracks each point's largest term,
    and, when asked, where it lost one."""
    if expr.is_Add:

        def add(values, scale):
            total, largest, terms = 0, 0.0, []
            for f in args:
                term = f(values, scale)
                total = total + term
                largest = np.maximum(largest, np.abs(term))
                terms.append(term)
            scale[0] = np.maximum(scale[0], largest)
            if scale[1] is not None:
                _note_lost(terms, scale)
            return total

        return add
    base, exponent = args
    return lambda values, scale: np.power(_on_branch(base(values, scale)), exponent(values, scale))


def _row_by_row_if_undefined(evaluate, *arrays: np.ndarray, parts: int = 0) -> tuple[np.ndarray, np.ndarray]:
    """``evaluate(*arrays) -> (values, scales)`` on all rows at once.

    ``values`` is one value per row, or with ``parts``, that many stacked. When a value
    somewhere divides by zero, overflows or is not finite, each row is evaluated alone
    and the rows where that happens are NaN.
    """
    try:
        with np.errstate(all="raise", under="ignore"):
            values, scales = evaluate(*arrays)
        if np.isfinite(values).all() and np.isfinite(scales).all():
            return values, scales
    except (FloatingPointError, *UNDEFINED):
        pass
    count = len(arrays[0])
    values = np.full((parts, count) if parts else count, complex("nan+nanj"))
    scales = np.full(count, math.nan)
    for row in range(count):
        try:
            with np.errstate(all="raise", under="ignore"):
                value, scale = evaluate(*(array[row : row + 1] for array in arrays))
        except (FloatingPointError, *UNDEFINED):
            continue
        if np.isfinite(value).all() and np.isfinite(scale).all():
            values[..., row], scales[row] = value[..., 0], scale[0]
    return values, scales


# The first and second derivatives of the functions the parser accepts, for forward-mode
# differentiation: name → z ↦ (f′(z), f″(z)).
_SLOPES = {
    "sin": lambda z: (np.cos(z), -np.sin(z)),
    "cos": lambda z: (-np.sin(z), -np.cos(z)),
    "tan": lambda z: (1 / np.cos(z) ** 2, 2 * np.tan(z) / np.cos(z) ** 2),
    "cot": lambda z: (-1 / np.sin(z) ** 2, 2 * np.cos(z) / np.sin(z) ** 3),
    "sec": lambda z: (np.sin(z) / np.cos(z) ** 2, (1 + np.sin(z) ** 2) / np.cos(z) ** 3),
    "csc": lambda z: (-np.cos(z) / np.sin(z) ** 2, (1 + np.cos(z) ** 2) / np.sin(z) ** 3),
    "asin": lambda z: (_root(1 - z * z) ** -1, z * _root(1 - z * z) ** -3),
    "acos": lambda z: (-(_root(1 - z * z) ** -1), -z * _root(1 - z * z) ** -3),
    "atan": lambda z: (1 / (1 + z * z), -2 * z / (1 + z * z) ** 2),
    "sinh": lambda z: (np.cosh(z), np.sinh(z)),
    "cosh": lambda z: (np.sinh(z), np.cosh(z)),
    "tanh": lambda z: (1 / np.cosh(z) ** 2, -2 * np.tanh(z) / np.cosh(z) ** 2),
    "coth": lambda z: (-1 / np.sinh(z) ** 2, 2 * np.cosh(z) / np.sinh(z) ** 3),
    "sech": lambda z: (-np.sinh(z) / np.cosh(z) ** 2, (np.sinh(z) ** 2 - 1) / np.cosh(z) ** 3),
    "csch": lambda z: (-np.cosh(z) / np.sinh(z) ** 2, (np.cosh(z) ** 2 + 1) / np.sinh(z) ** 3),
    "asinh": lambda z: (_root(1 + z * z) ** -1, -z * _root(1 + z * z) ** -3),
    "acosh": lambda z: ((_root(z - 1) * _root(z + 1)) ** -1, -z * (_root(z - 1) * _root(z + 1)) ** -3),
    "atanh": lambda z: (1 / (1 - z * z), 2 * z / (1 - z * z) ** 2),
    "exp": lambda z: (np.exp(z), np.exp(z)),
    "log": lambda z: (1 / z, -1 / (z * z)),
    "sign": lambda z: (0 * z, 0 * z),
}


def _root(z):
    return np.sqrt(_on_branch(z))


def _chain(function, slopes, jet):
    """f(a + b ε₁ + c ε₂ + d ε₁ε₂) = f(a) + f′(a) b ε₁ + f′(a) c ε₂ + (f′(a) d + f″(a) b c) ε₁ε₂."""
    a, b, c, d = jet
    first, second = slopes(a)
    return function(a), first * b, first * c, first * d + second * b * c


def _compile_jet(expr, index: Mapping[sympy.Symbol, int]):
    """Closures ``f(values, first, second, scale) -> (a, b, c, d)`` over numpy arrays (one row per
    variable): the value, its derivatives along ``first`` and ``second``, and the mixed one.
    ``scale[0]`` collects the largest term summed into a first or mixed derivative."""
    if expr.is_Symbol or isinstance(expr, _ALIASABLE):
        if expr not in index:
            raise NotCompilable(f"unknown symbol {expr}")
        position = index[expr]
        return lambda values, first, second, scale: (values[position], first[position], second[position], 0j)
    if not expr.args or expr.is_Rational:
        value = _compile(expr, index, _VECTOR)
        return lambda values, first, second, scale: (value(values, scale), 0j, 0j, 0j)
    args = [_compile_jet(arg, index) for arg in expr.args]
    if expr.is_Add:

        def add(values, first, second, scale):
            total = [0, 0, 0, 0]
            parts = [jet for f in args for jet in [f(values, first, second, scale)]]
            for jet in parts:
                total = [t + part for t, part in zip(total, jet, strict=True)]
                scale[0] = np.maximum(scale[0], np.maximum(np.abs(jet[1]), np.abs(jet[3])))
            if scale[1] is not None:
                for k in (0, 1, 3):  # value and derivatives: lost where a term is below the rest's resolution
                    _note_lost([jet[k] for jet in parts], scale)
            return tuple(total)

        return add
    if expr.is_Mul:

        def mul(values, first, second, scale):
            jet = args[0](values, first, second, scale)
            for f in args[1:]:
                jet = _mul_jets(jet, f(values, first, second, scale), scale)
            return jet

        return mul
    if expr.is_Pow:
        base, exponent = args
        if not (expr.exp.free_symbols or expr.exp.atoms(*_ALIASABLE)):  # a constant power: the chain rule
            e = int(expr.exp) if expr.exp.is_Integer else complex(expr.exp)
            on_branch = _on_branch if isinstance(e, complex) else (lambda z: z)

            def power_of(z):
                return z**e

            def slopes(z):
                return e * z ** (e - 1), e * (e - 1) * z ** (e - 2)

            def constant_power(values, first, second, scale):
                a, b, c, d = base(values, first, second, scale)
                return _chain(power_of, slopes, (on_branch(a), b, c, d))

            return constant_power
        exp, log = _VECTOR.functions["exp"], _VECTOR.functions["log"]

        def power(values, first, second, scale):  # b^e = exp(e log b)
            logarithm = _chain(log, _SLOPES["log"], base(values, first, second, scale))
            return _chain(exp, _SLOPES["exp"], _mul_jets(exponent(values, first, second, scale), logarithm))

        return power
    name = type(expr).__name__
    if name in ("re", "im"):
        (argument,) = args
        part = (lambda z: z.real + 0j) if name == "re" else (lambda z: z.imag + 0j)
        return lambda values, first, second, scale: tuple(map(part, argument(values, first, second, scale)))
    if name == "Abs":
        (argument,) = args

        def absolute(values, first, second, scale):  # |z| = z·sign(z) on the real line, away from 0
            jet = argument(values, first, second, scale)
            sign = np.sign(jet[0].real) + 0j
            if np.any(sign == 0) or np.any(jet[0].imag != 0):
                raise FloatingPointError("|z| is not differentiable here")
            return tuple(sign * part for part in jet)

        return absolute
    if name in _SLOPES and len(args) == 1:
        function, slopes, (argument,) = _VECTOR.functions[name], _SLOPES[name], args
        return lambda values, first, second, scale: _chain(function, slopes, argument(values, first, second, scale))
    raise NotCompilable(f"cannot differentiate {name}")


def _note_lost(terms, scale: list) -> None:
    """Mark ``scale[1]`` where a nonzero one of ``terms`` (summed, in floats: numpy arrays or
    numbers) is below floats' resolution beside the largest: the rule for the vector sums
    and the jets alike."""
    # a constant's derivative is the number 0: it is no term, and costs numpy nothing to skip
    sizes = [np.abs(term) for term in terms if not (isinstance(term, complex | float | int) and term == 0)]
    if len(sizes) < 2:
        return
    largest = functools.reduce(np.maximum, sizes)
    smallest = functools.reduce(np.minimum, [np.where(size > 0, size, math.inf) for size in sizes])
    scale[1] = scale[1] | (smallest < FLOAT_EQUAL * largest)


def _mul_jets(x, y, scale: list | None = None):
    """The product of two hyper-dual numbers (a, b, c, d), by the product rule; ``scale[0]``,
    when given, collects the largest term of its first and mixed parts."""
    a1, b1, c1, d1 = x
    a2, b2, c2, d2 = y
    first, mixed = (a1 * b2, b1 * a2), (a1 * d2, b1 * c2, c1 * b2, d1 * a2)
    if scale is not None:
        for term in (*first, mixed[0], mixed[3]):
            scale[0] = np.maximum(scale[0], np.abs(term))
    return a1 * a2, first[0] + first[1], a1 * c2 + c1 * a2, sum(mixed)


def sample_points(
    variables: Sequence[sympy.Symbol], domains: Mapping[sympy.Symbol, str], count: int, seed: int
) -> list[list[complex]]:
    """``count`` points, each a value per variable, drawn inside its domain.

    Domains: ``real`` (uniform in ±[0.2, 5]: past π, where √((1 + cos θ)/2) stops being
    cos(θ/2)), ``positive`` (0.4 to 3),
    ``negative``, ``nonzero`` (as real), ``integer`` (1 to 6). The same seed
    gives the same points on every run and machine, so verdicts are deterministic.
    """
    rng = random.Random(seed)
    points = []
    for _ in range(count):
        point = []
        for symbol in variables:
            domain = domains.get(symbol, "positive")
            if domain == "positive":
                value = rng.uniform(0.4, 3.0)
            elif domain == "negative":
                value = -rng.uniform(0.4, 3.0)
            elif domain == "integer":
                value = float(rng.randint(1, 6))
            else:  # real, nonzero
                value = rng.choice((-1, 1)) * rng.uniform(0.2, 5.0)
            point.append(complex(value))
        points.append(point)
    return points


class Closeness(enum.Enum):
    EQUAL = "equal"
    DIFFERENT = "different"
    UNSURE = "unsure"


def closeness(a, b, scale: float, *, precise: bool = False) -> Closeness:
    """Whether two evaluated values are the same number, relative to the scale of their terms."""
    difference = abs(a - b)
    scale = max(scale, float(abs(a)), float(abs(b)))
    if difference == 0:
        return Closeness.EQUAL
    if precise:
        return Closeness.EQUAL if difference <= PRECISE_EQUAL * scale else Closeness.DIFFERENT
    if difference <= FLOAT_EQUAL * scale:
        return Closeness.EQUAL
    if difference > FLOAT_DIFFERENT * scale:
        return Closeness.DIFFERENT
    return Closeness.UNSURE
