"""Showing an answer back as it was read: plain text, LaTeX and MathML, with dots.

Contents:
    to_text(value)     one line of Unicode that could be typed back in: ``g*l*m*sin(θ)``
    to_latex(value)    LaTeX with ``\\dot{\\theta}_{1}`` for time derivatives
    to_mathml(value)   a complete ``<math>`` element, presentation markup, no scripts

``value`` is what the parser returns: an expression, an ``Eq`` or a tuple of them.
Coordinates are printed as their names (``θ``, not ``θ(t)``) and their time
derivatives with dots over them, as a student writes them.
"""

from __future__ import annotations

import sympy
from sympy.core.function import AppliedUndef
from sympy.printing.latex import LatexPrinter
from sympy.printing.mathml import MathMLPresentationPrinter
from sympy.printing.str import StrPrinter

from grader.parse.grammar import ANSWER
from grader.parse.names import unicode_name

__all__ = ["to_latex", "to_mathml", "to_text"]

_MATHML_NS = "http://www.w3.org/1998/Math/MathML"
_DOT_SUFFIX = {1: "dot", 2: "ddot", 3: "dddot"}
# Name endings sympy's LaTeX printer turns into accents (see sympy.printing.latex.modifier_dict).
_MODIFIERS = ("dot", "hat", "bar", "vec", "tilde", "prime", "check", "breve", "acute", "grave", "mathring")


def _as_coordinate(expr) -> tuple[str, int] | None:
    """(name, number of dots) for a coordinate q(t) or its time derivative, else ``None``."""
    if isinstance(expr, AppliedUndef) and len(expr.args) == 1 and expr.args[0].is_Symbol:
        return expr.func.__name__, 0
    if isinstance(expr, sympy.Derivative) and isinstance(expr.expr, AppliedUndef):
        (variable, order), *rest = expr.variable_count
        if not rest and variable in expr.expr.args:
            return expr.expr.func.__name__, int(order)
    return None


def _dotted_symbol(name: str, dots: int) -> sympy.Symbol:
    """A Symbol whose name sympy's printers show with dots: theta_1 → thetadot_1."""
    base, underscore, sub = name.partition("_")
    return sympy.Symbol(base + _DOT_SUFFIX.get(dots, "") + underscore + sub)


class _TextPrinter(StrPrinter):
    def _print_Symbol(self, expr):
        return unicode_name(expr.name)

    def _print_Derivative(self, expr):
        coordinate = _as_coordinate(expr)
        return unicode_name(*coordinate) if coordinate else super()._print_Derivative(expr)

    def _print_Function(self, expr):
        coordinate = _as_coordinate(expr)
        return unicode_name(*coordinate) if coordinate else super()._print_Function(expr)

    def _print_Pi(self, expr):
        return "π"

    def _print_Rational(self, expr):
        return _decimal(expr) or super()._print_Rational(expr)

    # Read back only what the parser reads: sqrt(-1), not I (a symbol here); abs, not Abs.
    def _print_ImaginaryUnit(self, expr):
        return "sqrt(-1)"

    def _print_Abs(self, expr):
        return f"abs({self._print(expr.args[0])})"

    def _print_Exp1(self, expr):
        return "e"

    def _print_Pow(self, expr, rational=False):
        return super()._print_Pow(expr, rational).replace("**", "^")

    def _print_Relational(self, expr):
        return f"{self._print(expr.lhs)} = {self._print(expr.rhs)}"


class _LatexPrinter(LatexPrinter):
    def _print_Derivative(self, expr):
        coordinate = _as_coordinate(expr)
        if coordinate:
            return super()._print_Symbol(_dotted_symbol(*coordinate))
        return super()._print_Derivative(expr)

    def _print_Function(self, expr, exp=None):
        coordinate = _as_coordinate(expr)
        if coordinate:
            text = super()._print_Symbol(_dotted_symbol(*coordinate))
            return f"{text}^{{{exp}}}" if exp else text
        return super()._print_Function(expr, exp)

    def _print_Symbol(self, expr, style="plain"):
        # sympy would typeset a symbol named "thetadot" as θ̇; here only real derivatives get dots.
        base = expr.name.partition("_")[0]
        if base.endswith(_MODIFIERS):
            escaped = expr.name.replace("_", "\\_")
            return rf"\mathrm{{{escaped}}}"
        return super()._print_Symbol(expr, style)


class _MathMLPrinter(MathMLPresentationPrinter):
    def _print_Derivative(self, expr):
        coordinate = _as_coordinate(expr)
        return self._dotted(*coordinate) if coordinate else super()._print_Derivative(expr)

    def _print_Function(self, expr):
        coordinate = _as_coordinate(expr)
        return self._dotted(*coordinate) if coordinate else super()._print_Function(expr)

    def parenthesize(self, item, level, strict=False):
        if _as_coordinate(item):  # θ̇ is an atom, not (θ̇)
            return self._print(item)
        return super().parenthesize(item, level, strict)

    def _print_Rational(self, e):
        decimal = _decimal(e)
        if decimal is None:
            return super()._print_Rational(e)
        element = self.dom.createElement("mn")
        element.appendChild(self.dom.createTextNode(decimal))
        return element

    def _dotted(self, name: str, dots: int):
        base, _, sub = name.partition("_")
        element = self._print(sympy.Symbol(base))
        if dots:
            # An accent over the letter, as MathML means it: a combining dot inside the <mi>
            # is dropped by math fonts (DejaVu Math TeX Gyre draws θ̇ as a bare θ).
            over = self.dom.createElement("mover")
            over.setAttribute("accent", "true")
            mark = self.dom.createElement("mo")
            mark.appendChild(self.dom.createTextNode({1: "\u02d9", 2: "\u00a8"}.get(dots, "\u20db")))
            over.appendChild(element)
            over.appendChild(mark)
            element = over
        if sub:
            subscripted = self.dom.createElement("msub")
            subscripted.appendChild(element)
            subscripted.appendChild(self._print(sympy.Symbol(sub)))
            element = subscripted
        return element


def _decimal(number) -> str | None:
    """A rational typed as a decimal, shown as one again: 2.006, not 1003/500.

    >>> _decimal(sympy.Rational(1003, 500)), _decimal(sympy.Rational(-1, 8)), _decimal(sympy.Rational(1, 3))
    ('2.006', '-0.125', None)
    """
    p, q = abs(int(number.p)), int(number.q)
    places = next((k for k in range(1, 31) if 10**k % q == 0), None)  # q = 2^a 5^b: a terminating decimal
    if q == 1 or places is None:
        return None
    scaled = p * (10**places // q)
    return ("-" if number.p < 0 else "") + f"{scaled // 10**places}.{scaled % 10**places:0{places}d}"


def _items(value) -> list:
    """The items shown, in order; the parser's name for an expression before its definitions
    (``answer = ½ m v²; v = l θ̇``) is not the student's, and is not shown."""
    items = list(value) if isinstance(value, tuple) else [value]
    return [item.rhs if isinstance(item, sympy.Eq) and item.lhs == ANSWER else item for item in items]


def to_text(value) -> str:
    """One line of Unicode text; the equations of a system are joined by ``; ``.

    >>> import sympy
    >>> theta = sympy.Function("theta")(sympy.Symbol("t"))
    >>> to_text(sympy.Symbol("m_1") * theta.diff("t") ** 2)
    'm₁*θ̇^2'
    """
    printer = _TextPrinter()
    return "; ".join(printer.doprint(item) for item in _items(value))


def to_latex(value) -> str:
    r"""LaTeX; a system is a ``\begin{aligned}`` block.

    >>> import sympy
    >>> theta = sympy.Function("theta_1")(sympy.Symbol("t"))
    >>> to_latex(sympy.Eq(theta.diff("t", 2), -sympy.sin(theta), evaluate=False))
    '\\ddot{\\theta}_{1} = - \\sin{\\left(\\theta_{1} \\right)}'
    """
    printer = _LatexPrinter()
    items = [printer.doprint(item) for item in _items(value)]
    if len(items) == 1:
        return items[0]
    return r"\begin{aligned}" + r" \\ ".join(items) + r"\end{aligned}"


def to_mathml(value) -> str:
    """A complete ``<math>`` element; a system is a table, one equation per row."""
    printer = _MathMLPrinter()
    items = [printer.doprint(item) for item in _items(value)]
    if len(items) == 1:
        body = items[0]
    else:
        body = "<mtable>" + "".join(f"<mtr><mtd>{item}</mtd></mtr>" for item in items) + "</mtable>"
    return f'<math xmlns="{_MATHML_NS}" display="inline">{body}</math>'
