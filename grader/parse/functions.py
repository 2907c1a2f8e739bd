"""The functions an answer may use, as the parser builds them and as numbers evaluate them.

Contents:
    SYMPY       canonical name (as :data:`~grader.parse.names.FUNCTION_NAMES` gives it) → sympy function
    COMPLEX     sympy's class name → the function in complex floats, on sympy's principal branch
    principal(f)  a cmath function made to agree with sympy on its branch cut
    with_reciprocals(t)  a table of sin, cos, tan… with cot, sec, csc… derived as 1/f

Keyed by sympy's class name because sympy may rewrite one function as another: the
arctangent of an imaginary number comes back as i·atanh. A function added to the
vocabulary goes in both tables here, and in the judge's numpy, 40-digit and
derivative tables (``grader.judge.numeric``).
"""

from __future__ import annotations

import cmath

import sympy

__all__ = ["COMPLEX", "SYMPY", "principal", "with_reciprocals"]

SYMPY = {
    "sin": sympy.sin, "cos": sympy.cos, "tan": sympy.tan, "cot": sympy.cot, "sec": sympy.sec,
    "csc": sympy.csc, "asin": sympy.asin, "acos": sympy.acos, "atan": sympy.atan,
    "sinh": sympy.sinh, "cosh": sympy.cosh, "tanh": sympy.tanh, "coth": sympy.coth, "sech": sympy.sech,
    "csch": sympy.csch, "asinh": sympy.asinh, "acosh": sympy.acosh, "atanh": sympy.atanh, "exp": sympy.exp,
    "log": sympy.log, "sqrt": sympy.sqrt, "abs": sympy.Abs, "sign": sympy.sign,
}  # fmt: skip


def principal(function):
    """``function`` on the principal branch, as sympy defines it.

    Complex arithmetic leaves signed zeros (1/(-2+0j) is -0.5-0j), and cmath puts
    a value with imaginary part -0.0 on the other side of a branch cut:
    sqrt(-0.5-0j) is -0.707j where sympy's sqrt(-1/2) is +0.707j.
    """

    def on_branch(z):
        return function(complex(z.real, 0.0) if z.imag == 0 else z)

    return on_branch


_RECIPROCALS = {"cot": "tan", "sec": "cos", "csc": "sin", "coth": "tanh", "sech": "cosh", "csch": "sinh"}


def with_reciprocals(table: dict) -> dict:
    """``table`` (sin, cos, tan, sinh, cosh, tanh… for one kind of number) with cot, sec, csc,
    coth, sech and csch added as 1/tan, 1/cos… of its own functions."""

    def reciprocal(function):
        return lambda z: 1 / function(z)

    return {**table, **{name: reciprocal(table[of]) for name, of in _RECIPROCALS.items()}}


COMPLEX = with_reciprocals({
    "sin": cmath.sin, "cos": cmath.cos, "tan": cmath.tan,
    "asin": principal(cmath.asin), "acos": principal(cmath.acos), "atan": cmath.atan,
    "sinh": cmath.sinh, "cosh": cmath.cosh, "tanh": cmath.tanh,
    "asinh": principal(cmath.asinh), "acosh": principal(cmath.acosh), "atanh": principal(cmath.atanh),
    "exp": cmath.exp, "log": principal(cmath.log), "Abs": abs, "sign": lambda z: 0j if z == 0 else z / abs(z),
})  # fmt: skip
