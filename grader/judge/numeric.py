"""Fast numeric evaluation of sympy expressions, without ``lambdify``.

Contents:
    Compiled            an expression turned into nested closures, evaluated in
                        complex floats (at one point, or at many at once with
                        numpy), for near misses in 40-digit mpmath, and exactly
                        in fractions when it is a rational function
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
"""

from __future__ import annotations

import cmath
import enum
import math
import random
from collections.abc import Callable, Mapping, Sequence
from fractions import Fraction
from functools import cached_property

import mpmath
import numpy as np
import sympy
from sympy.core.function import AppliedUndef

__all__ = ["UNDEFINED", "Closeness", "Compiled", "NotCompilable", "closeness", "sample_points"]

PRECISE_DIGITS = 40


UNDEFINED = (ArithmeticError, ValueError, TypeError)  # what evaluating at a point outside the domain raises


class NotCompilable(Exception):  # a condition reported to the caller, not an error
    """The expression contains an object the evaluator does not know."""


class _Backend:
    """The number type and functions one kind of evaluation uses; ``vector`` evaluates numpy arrays."""

    def __init__(self, number, functions: Mapping[str, Callable], pi, e, *, vector: bool = False):
        self.number, self.functions, self.pi, self.e, self.vector = number, functions, pi, e, vector


def _cot(z):
    return 1 / cmath.tan(z)


def _principal(function):
    """``function`` on the principal branch, as sympy defines it.

    Complex arithmetic leaves signed zeros (1/(-2+0j) is -0.5-0j), and cmath puts
    a value with imaginary part -0.0 on the other side of a branch cut:
    sqrt(-0.5-0j) is -0.707j where sympy's sqrt(-1/2) is +0.707j.
    """

    def on_branch(z):
        return function(complex(z.real, 0.0) if z.imag == 0 else z)

    return on_branch


def _power(base, exponent):
    if isinstance(base, complex) and base.imag == 0:
        base = complex(base.real, 0.0)
    return base**exponent


_FLOAT = _Backend(
    number=lambda p, q: complex(p / q),
    functions={
        "sin": cmath.sin, "cos": cmath.cos, "tan": cmath.tan, "cot": _cot,
        "sec": lambda z: 1 / cmath.cos(z), "csc": lambda z: 1 / cmath.sin(z),
        "asin": _principal(cmath.asin), "acos": _principal(cmath.acos), "atan": cmath.atan,
        "sinh": cmath.sinh, "cosh": cmath.cosh, "tanh": cmath.tanh,
        "exp": cmath.exp, "log": _principal(cmath.log), "Abs": abs,
        "sign": lambda z: 0 if z == 0 else z / abs(z), "re": lambda z: complex(z.real), "im": lambda z: complex(z.imag),
    },
    pi=lambda: complex(math.pi), e=lambda: complex(math.e),
)  # fmt: skip


def _on_branch(z):
    """The array's real values with imaginary part +0.0: see :func:`_principal`."""
    return np.where(z.imag == 0, z.real + 0j, z)


def _vector_principal(function):
    return lambda z: function(_on_branch(z))


def _vector_sign(z):
    size = np.abs(z)
    return np.where(size == 0, 0j, z / np.where(size == 0, 1.0, size))


_VECTOR = _Backend(
    number=lambda p, q: complex(p / q),
    functions={
        "sin": np.sin, "cos": np.cos, "tan": np.tan, "cot": lambda z: 1 / np.tan(z),
        "sec": lambda z: 1 / np.cos(z), "csc": lambda z: 1 / np.sin(z),
        "asin": _vector_principal(np.arcsin), "acos": _vector_principal(np.arccos), "atan": np.arctan,
        "sinh": np.sinh, "cosh": np.cosh, "tanh": np.tanh,
        "exp": np.exp, "log": _vector_principal(np.log), "Abs": lambda z: np.abs(z) + 0j,
        "sign": _vector_sign, "re": lambda z: z.real + 0j, "im": lambda z: z.imag + 0j,
    },
    pi=lambda: complex(math.pi), e=lambda: complex(math.e), vector=True,
)  # fmt: skip


def _mp(name):
    return getattr(mpmath, name)


_PRECISE = _Backend(
    number=lambda p, q: mpmath.mpf(p) / q,
    functions={
        **{name: _mp(name) for name in ("sin", "cos", "tan", "cot", "sec", "csc", "asin", "acos", "atan")},
        **{name: _mp(name) for name in ("sinh", "cosh", "tanh", "exp", "log")},
        "Abs": abs, "sign": lambda z: 0 if z == 0 else z / abs(z),
        "re": lambda z: mpmath.re(z), "im": lambda z: mpmath.im(z),
    },
    pi=lambda: +mpmath.pi, e=lambda: +mpmath.e,  # + fixes the value at the working precision
)  # fmt: skip


_ALIASABLE = (sympy.Derivative, AppliedUndef)
_EXACT = _Backend(number=Fraction, functions={}, pi=None, e=None)


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
        self._dual = None
        self._precise = None
        self._rational = _is_rational_function(expr)
        self._exact = None  # compiled when first needed: most comparisons never need it
        # A reference answer is evaluated at the same points for every submission: remember them.
        self._memo: dict | None = {} if memo else None

    def __call__(self, values: Sequence[complex]) -> tuple[complex, float]:
        """The value and its scale at ``values``; raises ArithmeticError/ValueError where undefined."""
        if self._memo is not None:
            key = tuple(values)
            if key not in self._memo:
                try:
                    self._memo[key] = self._evaluate(values)
                except UNDEFINED as undefined:
                    self._memo[key] = undefined
            result = self._memo[key]
            if isinstance(result, Exception):
                raise result
            return result
        return self._evaluate(values)

    def _evaluate(self, values: Sequence[complex]) -> tuple[complex, float]:
        if self._float is None:
            self._float = _compile(self.expr, self.index, _FLOAT)
        scale = [0.0]
        value = self._float(values, scale)
        return value, max(scale[0], abs(value))

    def many(self, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Values and scales at every row of ``points`` (count × variables); NaN where undefined."""
        if self._memo is None:
            return self._many(points)
        key = ("many", points.shape, points.tobytes())
        if key not in self._memo:
            self._memo[key] = self._many(points)
        return self._memo[key]

    def _many(self, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        if self._vector is None:
            self._vector = _compile(self.expr, self.index, _VECTOR)

        def evaluate(rows):
            scale = [0.0]
            value = np.broadcast_to(np.asarray(self._vector(rows.T, scale), complex), len(rows))
            return value, np.maximum(scale[0], np.abs(value))

        return _row_by_row_if_undefined(evaluate, np.ascontiguousarray(points))

    def derivative(self, points: np.ndarray, directions: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The derivative at every row of ``points`` along the same row of ``directions``, and its
        scale (the largest term summed into it); NaN where undefined.

        Forward-mode differentiation: one pass over dual numbers, exact but for rounding.
        """
        if self._memo is None:
            return self._derivative(points, directions)
        key = ("derivative", points.shape, points.tobytes(), directions.tobytes())
        if key not in self._memo:
            self._memo[key] = self._derivative(points, directions)
        return self._memo[key]

    def _derivative(self, points: np.ndarray, directions: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        if self._dual is None:
            self._dual = _compile_dual(self.expr, self.index)

        def evaluate(rows, along):
            scale = [0.0]
            _, slope = self._dual(rows.T, along.T, scale)
            slope = np.broadcast_to(np.asarray(slope, complex), len(rows))
            return slope, np.maximum(scale[0], np.abs(slope))

        return _row_by_row_if_undefined(evaluate, np.ascontiguousarray(points), np.ascontiguousarray(directions))

    @cached_property
    def constant(self) -> bool:
        """Whether the expression depends on no variable (a reference's is asked on every comparison)."""
        return not self.expr.free_symbols and not self.expr.atoms(*_ALIASABLE)

    @property
    def rational(self) -> bool:
        """Whether :meth:`exact` can evaluate this expression."""
        return self._rational

    def exact(self, values: Sequence[complex]) -> tuple[Fraction, float]:
        """The exact value at real ``values``, for a rational function of the variables.

        Floats cannot tell a degree-13 polynomial from one whose constant is off by one.
        """
        scale = [0.0]
        if self._exact is None:
            self._exact = _compile(self.expr, self.index, _EXACT)
        value = self._exact([Fraction(v.real) for v in values], scale)
        return value, max(scale[0], float(abs(value)))

    def precise(self, values: Sequence[complex]) -> tuple[object, float]:
        """The same at 40 digits, for values the float evaluation could not tell apart."""
        with mpmath.workdps(PRECISE_DIGITS):
            if self._precise is None:  # constants are fixed when compiled: at 40 digits too
                self._precise = _compile(self.expr, self.index, _PRECISE)
            scale = [0.0]
            value = self._precise([mpmath.mpmathify(v) for v in values], scale)
            return value, max(scale[0], float(abs(value)))


def _compile(expr, index: Mapping[sympy.Symbol, int], backend: _Backend):
    """Nested closures ``f(values, scale) -> value``; ``scale[0]`` collects the largest term."""
    if expr.is_Symbol or isinstance(expr, _ALIASABLE):
        if expr not in index:
            raise NotCompilable(f"unknown symbol {expr}")
        position = index[expr]
        return lambda values, scale: values[position]
    if expr.is_Rational or expr.is_Float:
        p, q = expr.as_numer_denom() if expr.is_Rational else sympy.Rational(expr).as_numer_denom()
        try:
            constant = backend.number(int(p), int(q))
        except OverflowError as overflow:
            raise NotCompilable("a number too large for floating point") from overflow
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

        def add(values, scale):
            total, largest = 0, 0.0
            for f in args:
                term = f(values, scale)
                total += term
                size = abs(term)
                if size > largest:
                    largest = size
            if largest > scale[0]:
                scale[0] = float(largest)
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
    """The closures that differ over numpy arrays: a sum tracks each point's largest term."""
    if expr.is_Add:

        def add(values, scale):
            total, largest = 0, 0.0
            for f in args:
                term = f(values, scale)
                total = total + term
                largest = np.maximum(largest, np.abs(term))
            scale[0] = np.maximum(scale[0], largest)
            return total

        return add
    base, exponent = args
    return lambda values, scale: np.power(_on_branch(base(values, scale)), exponent(values, scale))


def _row_by_row_if_undefined(evaluate, *arrays: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``evaluate(*arrays) -> (values, scales)`` on all rows at once.

    When a value somewhere divides by zero, overflows or is not finite, each row is
    evaluated alone and the rows where that happens are NaN.
    """
    try:
        with np.errstate(all="raise", under="ignore"):
            values, scales = evaluate(*arrays)
        if np.isfinite(values).all() and np.isfinite(scales).all():
            return values, scales
    except (FloatingPointError, *UNDEFINED):
        pass
    count = len(arrays[0])
    values, scales = np.full(count, complex("nan+nanj")), np.full(count, math.nan)
    for row in range(count):
        try:
            with np.errstate(all="raise", under="ignore"):
                value, scale = evaluate(*(array[row : row + 1] for array in arrays))
        except (FloatingPointError, *UNDEFINED):
            continue
        if np.isfinite(value).all() and np.isfinite(scale).all():
            values[row], scales[row] = value[0], scale[0]
    return values, scales


# Derivatives of the functions the parser accepts, for forward-mode differentiation.
_SLOPES = {
    "sin": np.cos, "cos": lambda z: -np.sin(z), "tan": lambda z: 1 / np.cos(z) ** 2,
    "cot": lambda z: -1 / np.sin(z) ** 2, "sec": lambda z: np.sin(z) / np.cos(z) ** 2,
    "csc": lambda z: -np.cos(z) / np.sin(z) ** 2,
    "asin": lambda z: 1 / np.sqrt(_on_branch(1 - z * z)), "acos": lambda z: -1 / np.sqrt(_on_branch(1 - z * z)),
    "atan": lambda z: 1 / (1 + z * z), "sinh": np.cosh, "cosh": np.sinh, "tanh": lambda z: 1 / np.cosh(z) ** 2,
    "exp": np.exp, "log": lambda z: 1 / z, "sign": lambda z: 0 * z,
}  # fmt: skip


def _compile_dual(expr, index: Mapping[sympy.Symbol, int]):
    """Closures ``f(values, directions, scale) -> (value, derivative)`` over numpy arrays
    (one row per variable); ``scale[0]`` collects the largest term summed into a derivative."""
    if expr.is_Symbol or isinstance(expr, _ALIASABLE):
        if expr not in index:
            raise NotCompilable(f"unknown symbol {expr}")
        position = index[expr]
        return lambda values, directions, scale: (values[position], directions[position])
    if not expr.args or expr.is_Rational:
        value = _compile(expr, index, _VECTOR)
        return lambda values, directions, scale: (value(values, scale), 0j)
    args = [_compile_dual(arg, index) for arg in expr.args]
    if expr.is_Add:

        def add(values, directions, scale):
            total, slope = 0, 0
            for f in args:
                value, derivative = f(values, directions, scale)
                total, slope = total + value, slope + derivative
                scale[0] = np.maximum(scale[0], np.abs(derivative))
            return total, slope

        return add
    if expr.is_Mul:

        def mul(values, directions, scale):
            product, slope = 1, 0
            for f in args:
                value, derivative = f(values, directions, scale)
                earlier, this = slope * value, product * derivative  # the product rule's two terms
                scale[0] = np.maximum(scale[0], np.maximum(np.abs(earlier), np.abs(this)))
                product, slope = product * value, earlier + this
            return product, slope

        return mul
    if expr.is_Pow:
        (base, exponent), constant_exponent = args, not (expr.exp.free_symbols or expr.exp.atoms(*_ALIASABLE))

        if expr.exp.is_Integer:
            n = int(expr.exp)

            def integer_power(values, directions, scale):
                b, db = base(values, directions, scale)
                return b**n, n * b ** (n - 1) * db

            return integer_power

        def power(values, directions, scale):
            (b, db), (e, de) = base(values, directions, scale), exponent(values, directions, scale)
            b = _on_branch(b)
            value = np.power(b, e)
            if constant_exponent:
                return value, e * np.power(b, e - 1) * db
            return value, value * (de * np.log(b) + e * db / b)

        return power
    name = type(expr).__name__
    if name == "Abs":
        (argument,) = args

        def absolute(values, directions, scale):
            z, dz = argument(values, directions, scale)
            size = np.abs(z)
            return size + 0j, (z.real * dz.real + z.imag * dz.imag) / size + 0j

        return absolute
    if name in ("re", "im"):
        (argument,) = args
        part = (lambda z: z.real + 0j) if name == "re" else (lambda z: z.imag + 0j)
        return lambda values, directions, scale: tuple(map(part, argument(values, directions, scale)))
    if name in _SLOPES and len(args) == 1:
        function, slope, (argument,) = _VECTOR.functions[name], _SLOPES[name], args

        def apply(values, directions, scale):
            z, dz = argument(values, directions, scale)
            return function(z), slope(z) * dz

        return apply
    raise NotCompilable(f"cannot differentiate {name}")


def sample_points(
    variables: Sequence[sympy.Symbol], domains: Mapping[sympy.Symbol, str], count: int, seed: int
) -> list[list[complex]]:
    """``count`` points, each a value per variable, drawn inside its domain.

    Domains: ``real`` (uniform in ±[0.2, 2.5]), ``positive`` (0.4 to 3),
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
                value = rng.choice((-1, 1)) * rng.uniform(0.2, 2.5)
            point.append(complex(value))
        points.append(point)
    return points


class Closeness(enum.Enum):
    EQUAL = "equal"
    DIFFERENT = "different"
    UNSURE = "unsure"


# Equal pairs differed by at most ~1e-14 of their scale in float; a term of 1e-9 of the
# scale (or a constant off by one in a sum of billions) must not pass. Between the two
# bounds the float result cannot decide: re-evaluate at 40 digits.
FLOAT_EQUAL = 1e-13
FLOAT_DIFFERENT = 1e-6
PRECISE_EQUAL = 1e-25


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
