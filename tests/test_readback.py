"""How an answer is shown back: plain text, LaTeX and MathML, with dots over derivatives."""

from __future__ import annotations

import xml.dom.minidom

import pytest
import sympy

from grader import TIME, parse_answer
from grader.parse import ParsedAnswer

COORDS = ["theta", "theta_1", "theta_2", "x"]
KNOWN = ["m", "g", "l", "m_1", "l_1", "p_theta"]

READ_BACK = [
    # (typed, as text, as LaTeX)
    ("1/2 m l^2 thetadot^2", "l^2*m*θ̇^2/2", r"\frac{l^{2} m \dot{\theta}^{2}}{2}"),
    ("theta1''", "θ̈₁", r"\ddot{\theta}_{1}"),
    ("\\dot\\theta_2 + x'", "θ̇₂ + ẋ", r"\dot{\theta}_{2} + \dot{x}"),
    ("mgl cos θ", "g*l*m*cos(θ)", r"g l m \cos{\left(\theta \right)}"),
    ("p_θ + π", "p_θ + π", r"p_{\theta} + \pi"),
    ("θ̈ = -(g/l) sin θ", "θ̈ = -g*sin(θ)/l", r"\ddot{\theta} = - \frac{g \sin{\left(\theta \right)}}{l}"),
    ("x = 1; θ = 2", "x = 1; θ = 2", r"\begin{aligned}x = 1 \\ \theta = 2\end{aligned}"),
    ("m₁ e^x", "m₁*exp(x)", r"m_{1} e^{x}"),
]


@pytest.mark.parametrize(("typed", "text", "latex"), READ_BACK)
def test_read_back_as_text_and_latex(typed, text, latex):
    result = parse_answer(typed, coords=COORDS, known=KNOWN)
    assert result.read_as_text == text
    assert result.read_as_latex == latex


def test_mathml_puts_dots_over_derivatives_and_is_well_formed():
    mathml = parse_answer("θ̇₁ + ẍ", coords=COORDS).read_as_mathml
    document = xml.dom.minidom.parseString(mathml)
    assert document.documentElement.tagName == "math"
    overs = document.getElementsByTagName("mover")
    assert sorted(over.lastChild.firstChild.data for over in overs) == ["\u00a8", "\u02d9"]
    assert all(over.getAttribute("accent") == "true" for over in overs)
    assert "<script" not in mathml


def test_a_time_derivative_is_an_atom_in_mathml_never_in_parentheses():
    mathml = parse_answer("m l^2 thetadot^2 + theta1dot theta2dot", coords=COORDS, known=KNOWN).read_as_mathml
    assert "<mo>(</mo>" not in mathml and "<mfenced" not in mathml


def test_a_decimal_number_reads_back_as_a_decimal():
    answer = parse_answer("2.006")  # exactly 1003/500
    assert (answer.read_as_text, answer.read_as_mathml.count("<mn>2.006</mn>")) == ("2.006", 1)


def test_a_system_is_a_mathml_table_with_one_row_per_equation():
    mathml = parse_answer("x = 1; θ = 2", coords=COORDS).read_as_mathml
    document = xml.dom.minidom.parseString(mathml)
    assert len(document.getElementsByTagName("mtr")) == 2


def test_names_in_mathml_are_escaped_text_not_markup():
    mathml = parse_answer("lt + gt + amp", known=[]).read_as_mathml
    xml.dom.minidom.parseString(mathml)  # raises if a name broke the markup


def test_a_value_no_printer_can_show_is_shown_as_typed():
    # The parser refuses such values; should one get past it, showing it back must not raise.
    answer = ParsedAnswer("10^10000 x", sympy.Integer(10) ** 10000 * sympy.Symbol("x"), "expression")
    assert (answer.read_as_text, answer.read_as_latex, answer.read_as_mathml) == ("10^10000 x", "", "")


def test_sympys_own_latex_of_coordinates_in_time_reads_back_as_the_same_value():
    # Jupyter shows sympy's LaTeX: θ{\left(t \right)}, \frac{d}{d t} θ{\left(t \right)}. Pasted back into
    # an answer, the brace around (t) once made the coordinate t·θ.
    theta, theta_1 = (sympy.Function(name, real=True)(TIME) for name in ("theta", "theta_1"))
    m, g, l = sympy.symbols("m g l")
    value = m * l**2 * sympy.Derivative(theta, TIME) ** 2 / 2 + m * g * l * sympy.cos(theta)
    value += sympy.Derivative(theta_1, (TIME, 2)) * sympy.sin(theta - theta_1)
    pasted = sympy.latex(value)
    assert "{\\left(t \\right)}" in pasted
    assert parse_answer(pasted, coords=COORDS, known=KNOWN).value == value
