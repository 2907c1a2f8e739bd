"""Inputs the parser must accept, each with the sympy object it must give.

The expected objects are built here directly with sympy, never through the parser.
Rows are grouped by the line of the answer language they exercise.
"""

from __future__ import annotations

import pytest
import sympy
from sympy import Eq, Rational, cos, exp, sin, sqrt

from grader import TIME, parse_answer

t = TIME
COORDS = ["theta", "phi", "theta_1", "theta_2", "x", "alpha", "beta", "r"]
KNOWN = ["m", "g", "l", "m_1", "m_2", "l_1", "l_2", "k", "a", "b", "c", "d", "omega", "p_theta", "R"]

m, g, l, m1, m2, l1, l2, k, a, b, c, d, omega, R = sympy.symbols("m g l m_1 m_2 l_1 l_2 k a b c d omega R")
p_theta = sympy.Symbol("p_theta")
theta, phi, theta1, theta2, x, alpha, beta, r = (
    sympy.Function(name, real=True)(t) for name in ("theta", "phi", "theta_1", "theta_2", "x", "alpha", "beta", "r")
)


U, W, L, H, Delta = sympy.symbols("U W L H Delta")


def D(q, n=1):
    return sympy.Derivative(q, (t, n))


ARITHMETIC = [
    ("a + b - c", a + b - c),
    ("a*b/c", a * b / c),
    ("a^2", a**2),
    ("a**2", a**2),
    ("2m", 2 * m),
    ("m g l", m * g * l),
    ("2(a+1)", 2 * (a + 1)),
    ("(a+b)(c-d)", (a + b) * (c - d)),
    ("[a+b]c", (a + b) * c),
    ("1/2 m l^2", m * l**2 / 2),
    ("1/2m", m / 2),
    # a number glued to a name after a symbol's /: the denominator, as physicists write b/2m (before: b·m/2)
    ("b/2m", b / (2 * m)),
    ("m g/2l", m * g / (2 * l)),
    ("a/2b/c", a / (2 * b * c)),
    ("3g/2 l", 3 * g * l / 2),  # not across a space
    ("g/l sin θ", g / l * sin(theta)),
    ("0.5 m", Rational(1, 2) * m),
    (".25", Rational(1, 4)),
    ("9.81", Rational(981, 100)),
    ("2.5e3 k", 2500 * k),
    ("-a^2", -(a**2)),
    ("a^-1", 1 / a),
    ("a^b^c", a ** (b**c)),
    ("a − b", a - b),
    ("a · b × c ⋅ d", a * b * c * d),
    ("a ∗ b ﹢ c", a * b + c),
    ("‒a ‐ b ‑ c ﹣ d", -a - b - c - d),  # the dashes a minus is typed or pasted as
    ("a ÷ b", a / b),
    ("a^2 b", a**2 * b),
    ("--a", a),
    ("½ m", m / 2),
    ("2½ m", Rational(5, 2) * m),  # a mixed number, as a person reads it: not 2·½
    ("3¼", Rational(13, 4)),
]

FUNCTIONS = [
    ("sin(θ) + cos(φ) + tan(a)", sin(theta) + cos(phi) + sympy.tan(a)),
    ("cot(a) + sec(b) + csc(c)", sympy.cot(a) + sympy.sec(b) + sympy.csc(c)),
    ("asin(a) + arcsin(b)", sympy.asin(a) + sympy.asin(b)),
    ("acos(a) + arccos(b) + atan(c) + arctan(d)", sympy.acos(a) + sympy.acos(b) + sympy.atan(c) + sympy.atan(d)),
    ("sinh(a) cosh(b) tanh(c)", sympy.sinh(a) * sympy.cosh(b) * sympy.tanh(c)),
    ("coth(a) + sech(b) + \\csch c", sympy.coth(a) + sympy.sech(b) + sympy.csch(c)),
    ("asinh(a) + arsinh(b) + arccosh(c)", sympy.asinh(a) + sympy.asinh(b) + sympy.acosh(c)),
    ("atanh(a) + artanh(b) + arctanh(c)", sympy.atanh(a) + sympy.atanh(b) + sympy.atanh(c)),
    # sympy writes the tangent of an imaginary number with tanh, its arctangent with atanh: both readable
    ("atan(log(-1))", sympy.I * sympy.atanh(sympy.pi)),
    ("exp(a) + log(b) + ln(c)", exp(a) + sympy.log(b) + sympy.log(c)),
    ("sqrt(g/l)", sqrt(g / l)),
    ("abs(a - b)", sympy.Abs(a - b)),
    # |x| is abs(x): a bar after a value closes the innermost open bar, any other opens one
    ("|a - b|", sympy.Abs(a - b)),
    ("k|a|", k * sympy.Abs(a)),
    ("|a||b|", sympy.Abs(a) * sympy.Abs(b)),
    ("||a| - b|", sympy.Abs(sympy.Abs(a) - b)),
    ("|a|b|c|", sympy.Abs(a) * b * sympy.Abs(c)),
    ("sin |a| + |b|^2", sin(sympy.Abs(a)) + sympy.Abs(b) ** 2),
    ("\\left| a \\right| + \\lvert b \\rvert + \\vert c \\vert", sympy.Abs(a) + sympy.Abs(b) + sympy.Abs(c)),
    ("(|a| + 1)", sympy.Abs(a) + 1),
    # sine as Spanish and Portuguese write it, and babel's \sen
    ("sen a + senh b + arcsen c + \\sen d", sin(a) + sympy.sinh(b) + sympy.asin(c) + sin(d)),
    # dry friction's direction: −μ m g sign(ẋ)
    ("sign(a) + sgn(b) + signum(c)", sympy.sign(a) + sympy.sign(b) + sympy.sign(c)),
    ("\\operatorname{sgn}(a - b)", sympy.sign(a - b)),
    ("sin θ", sin(theta)),
    ("cos theta1", cos(theta1)),
    ("sin θ cos φ", sin(theta) * cos(phi)),
    ("m g l cos θ", m * g * l * cos(theta)),
    ("sin 2θ", sin(2 * theta)),
    ("sin^2(θ)", sin(theta) ** 2),
    ("sin^2 θ", sin(theta) ** 2),
    ("sin²θ + cos²θ", sin(theta) ** 2 + cos(theta) ** 2),
    ("\\sin^2\\theta", sin(theta) ** 2),
    ("cos(θ₁ − θ₂)", cos(theta1 - theta2)),
    ("√(g/l)", sqrt(g / l)),
    ("√2 a", sqrt(2) * a),
    ("mglsinθ", m * g * l * sin(theta)),
    # a bare argument takes a glued product (cos ωt), but never a velocity: that is no angle
    ("cos ωt", cos(omega * t)),
    ("sin kx", sin(k * x)),
    ("sin²θφ̇²", sin(theta) ** 2 * D(phi) ** 2),
    ("ml²sin²θφ̇", m * l**2 * sin(theta) ** 2 * D(phi)),
    ("sin 2θφ̇", sin(2 * theta) * D(phi)),
    ("cos θ₁θ̇₂²", cos(theta1) * D(theta2) ** 2),
    ("sqrt lθ̇", sqrt(l * D(theta))),  # not an angle: the glued product stays whole
    # a phase of the problem's constants, then t apart: cos(ωt), as TeX's \\cos\\omega t must mean
    ("cos ω t", cos(omega * t)),
    ("\\cos\\omega t", cos(omega * t)),
    ("R\\sin\\theta\\cos\\omega t", R * sin(theta) * cos(omega * t)),
    ("sin 2ω t cos θ", sin(2 * omega * t) * cos(theta)),
    ("cos ω t θ̇", cos(omega * t) * D(theta)),
    ("sin ω t", sin(omega * t)),  # t the last token
    ("cos(ω) t", t * cos(omega)),  # bracketed: the argument is closed
    ("sin θ t", t * sin(theta)),  # an angle of the motion's: t is a factor of its own
    ("cos ω t^2", t**2 * cos(omega)),  # t raised: not a phase
    ("cos ω t²", t**2 * cos(omega)),
    ("√ω t", sqrt(omega) * t),  # no angle
    # a function's name with a phone's first capital, caps lock or Mathematica's; Mathematica's brackets
    (
        "Sin θ + SIN φ + Cos a + Cot b + COSH c + Ln d",
        sin(theta) + sin(phi) + cos(a) + sympy.cot(b) + sympy.cosh(c) + sympy.log(d),
    ),
    ("Sin[θ[t]] + Cos[x] + Sqrt[a] + Exp[b] + ArcTan[c]", sin(theta) + cos(x) + sqrt(a) + exp(b) + sympy.atan(c)),
    ("ctg a + cotg b + \\ctg c + \\cotg d", sympy.cot(a) + sympy.cot(b) + sympy.cot(c) + sympy.cot(d)),  # Europe's cot
    # tg is t·g, never the tangent; no other casing is a function's, nor two capitals (L·N)
    ("tg + sIn + LN", t * g + sympy.Symbol("sIn") + sympy.Symbol("LN")),
]

NAMES = [
    ("theta", theta),
    ("θ", theta),
    ("ϑ", theta),
    ("theta1 + theta_1 + θ₁", 3 * theta1),
    ("m_1 + m1 + m₁", 3 * m1),
    ("l2", l2),
    ("omega + ω", 2 * omega),
    ("alpha + α + beta + β", 2 * alpha + 2 * beta),
    ("θ²", theta**2),
    ("a³", a**3),
    ("pi + π", 2 * sympy.pi),
    ("e", sympy.E),
    ("e^a", exp(a)),
    ("p_theta + p_θ", 2 * p_theta),
    ("psi", sympy.Symbol("psi")),
    ("lambda + λ", 2 * sympy.Symbol("lambda")),
    ("mu + μ", 2 * sympy.Symbol("mu")),
    ("gamma", sympy.Symbol("gamma")),
    ("E + I + N + S + Q", sum(sympy.Symbol(n) for n in "EINSQ")),
    ("theta(t)", theta),
    ("θ[t] + θ'[t]^2 + θ''[t]", theta + D(theta) ** 2 + D(theta, 2)),  # Mathematica's
    ("R", R),
    ("Qᵣ + Q_r + vₓ + v_x", 2 * sympy.Symbol("Q_r") + 2 * sympy.Symbol("v_x")),  # subscript letters
    # letters typed for Greek ones the problem defines: w for ω, th for θ, ph for φ
    ("w^2 + th + ph + th1 + w t", omega**2 + theta + phi + theta1 + omega * t),
]

DERIVATIVES = [
    ("thetadot", D(theta)),
    ("theta_dot", D(theta)),
    ("theta'", D(theta)),
    ("θ̇", D(theta)),
    ("\\dot{\\theta}", D(theta)),
    ("\\dot\\theta", D(theta)),
    ("diff(theta, t)", D(theta)),
    # the variant letters are the same letter to a student, however typed
    ("varphidot + varphi' + \\dot\\varphi + ϕ̇ + \\dot\\phi", 5 * D(phi)),
    ("varphi_ddot + vartheta + ϑ", D(phi, 2) + 2 * theta),
    ("thetaddot", D(theta, 2)),
    ("theta_ddot", D(theta, 2)),
    ("theta_dd + theta_d + theta1_dd", D(theta, 2) + D(theta) + D(theta1, 2)),  # as code spells them
    ("theta_dotdot + thetadoubledot", 2 * D(theta, 2)),  # two dots spelled out
    ("m.*l.^2./g", m * l**2 / g),  # MATLAB's element-wise operations, on numbers the operations themselves
    ("theta''", D(theta, 2)),
    ("θ’’ + θ’", D(theta, 2) + D(theta)),  # a phone's apostrophe for a prime
    ("θ̈", D(theta, 2)),
    ("\\ddot{\\theta}", D(theta, 2)),
    ("diff(theta, t, 2)", D(theta, 2)),
    ("Derivative(theta(t), t) + Derivative(theta(t), (t, 2))", D(theta) + D(theta, 2)),  # as sympy prints them
    ("theta1dot", D(theta1)),
    ("theta1'", D(theta1)),
    ("θ̇₁", D(theta1)),
    ("θ̇_{1}", D(theta1)),  # a Unicode dot, then TeX's braced subscript: was refused at the `_`
    ("θ̈_{1} + θ̇_{1}^2", D(theta1, 2) + D(theta1) ** 2),
    ("\\dot{\\theta}_1", D(theta1)),
    ("\\dot\\theta_1", D(theta1)),
    ("\\dot{\\theta_1}", D(theta1)),
    ("xdot^2 + ẋ", D(x) ** 2 + D(x)),
    ("ẍ", D(x, 2)),
    ("θ̇²", D(theta) ** 2),
    ("theta2ddot", D(theta2, 2)),
    ("m l thetadot", m * l * D(theta)),
    ("mlθ̇", m * l * D(theta)),
    ("diff(x^2, t)", 2 * x * D(x)),
    ("θ˙ + θ¨₁", D(theta) + D(theta1, 2)),
    # a glued name dotted once is undotted the next time: (lθ̇)(lθ) once passed for (lθ̇)²
    ("(lθ̇)(lθ)", l**2 * theta * D(theta)),
    ("lθ̈ + lθ̇ + lθ", l * D(theta, 2) + l * D(theta) + l * theta),
    ("(ltheta')(ltheta)", l**2 * theta * D(theta)),
    # a prime before the subscript, on a glued name too
    ("θ'₁ + l₁θ'₂", D(theta1) + l1 * D(theta2)),
    # letters and signs as a PDF or another keyboard gives them; invisible characters
    ("ℓ + ℒ + a ⁄ b + c ∕ d", l + sympy.Symbol("L") + a / b + c / d),
    ("２ａ＋ｂ", 2 * a + b),
    ("a\u200b + b\ufeff", a + b),  # the spacing dots a Mac keyboard types (Option-h, Option-u)
    # an equation editor's styled letters and digits, the script ɡ, and marks of writing direction
    ("𝑚 𝑔 𝑙 sin 𝜃 + 𝐚 + 𝟏", m * g * l * sin(theta) + a + 1),
    ("ɡ l\u200f + a\u200e", g * l + a),
    # Word's function application after a function's name, invisible times, thin and other spaces
    ("m\u2062g\u2062l cos\u2061\u2009θ + a\u202fb\u205fc\u2002d\u2063k", m * g * l * cos(theta) + a * b * c * d * k),
    ("sin\u2061〖2θ〗 + 〖θ̇〗^2", sin(2 * theta) + D(theta) ** 2),  # and its linear format's grouping
]

LEIBNIZ = [
    ("d/dt(theta)", D(theta)),
    # the operator in brackets, with a power
    ("(d/dt)^2 θ + (d/dt)² x + (d/dt)(m x)", D(theta, 2) + D(x, 2) + m * D(x)),
    ("\\left(\\frac{d}{dt}\\right)^2 x", D(x, 2)),
    # as code spells rates: a d or dd before a coordinate
    ("dtheta^2 + ddx", D(theta) ** 2 + D(x, 2)),
    ("dtheta1 dθ₂ + ddtheta_1", D(theta1) * D(theta2) + D(theta1, 2)),
    ("dθ/dt", D(theta)),
    ("d^2x/dt^2", D(x, 2)),
    ("d²x/dt²", D(x, 2)),
    ("m dx/dt", m * D(x)),
    ("d theta / d t", D(theta)),
    ("d/dt (m l^2 thetadot) = 0", Eq(m * l**2 * D(theta, 2), 0)),
    ("\\frac{d\\theta}{dt}", D(theta)),
    ("\\frac{d^2 x}{dt^2}", D(x, 2)),
    # a power after the fraction is the derivative's, as in (dx/dt)², not x²'s
    ("\\frac{1}{2} m \\frac{dx}{dt}^2", m * D(x) ** 2 / 2),
    ("\\frac{d\\theta}{dt}^{2}", D(theta) ** 2),
    ("d/dt x^2", 2 * x * D(x)),  # the operator form still takes the factor after it, power and all
    ("\\frac{d}{dt}\\left(m l^2 \\dot\\theta\\right) + m g l \\sin\\theta = 0",
     Eq(m * l**2 * D(theta, 2) + m * g * l * sin(theta), 0)),
    # sympy's own LaTeX (sp.latex, Jupyter): a coordinate as a function of time, its brace around (t)
    ("g l m \\cos{\\left(\\theta{\\left(t \\right)} \\right)}"
     " + \\frac{l^{2} m \\left(\\frac{d}{d t} \\theta{\\left(t \\right)}\\right)^{2}}{2}",
     g * l * m * cos(theta) + l**2 * m * D(theta) ** 2 / 2),
    ("\\frac{d^{2}}{d t^{2}} \\theta_{1}{\\left(t \\right)} + x{(t)}", D(theta1, 2) + x),
    # d of a bracket over dt, the bracket of any length, as d/dt(…) and d(θ̇)/dt are read
    ("d(m l^2 thetadot)/dt + m g l sin(theta) = 0", Eq(m * l**2 * D(theta, 2) + m * g * l * sin(theta), 0)),
    ("d(m l² θ̇)/dt = −m g l sin θ", Eq(m * l**2 * D(theta, 2), -m * g * l * sin(theta))),
    ("d[m_1 l_1 x]/dt", m1 * l1 * D(x)),
    ("d²(m x + a θ)/dt²", m * D(x, 2) + a * D(theta, 2)),
    ("d(m l² θ̇)/dt·2", 2 * m * l**2 * D(theta, 2)),  # the bracket is the target, not what follows it
    ("d(m l^2 dθ/dt)/dt", m * l**2 * D(theta, 2)),  # and holds Leibniz's notation of its own
    ("d(d(x)/dt)/dt", D(x, 2)),
    # d glued to a coordinate's rate, as dθ/dt is to the coordinate
    ("dθ̇/dt = −(g/l) sin θ", Eq(D(theta, 2), -g / l * sin(theta))),
    ("dθ̇₁/dt + dẋ/dt", D(theta1, 2) + D(x, 2)),
    ("\\frac{dθ̇}{dt}", D(theta, 2)),
]  # fmt: skip

SPLITTING = [
    ("mgl", m * g * l),
    ("mgl cos θ", m * g * l * cos(theta)),
    ("m1gl1", m1 * g * l1),
    ("m_1l_1", m1 * l1),
    ("kx^2", k * x**2),
    ("2mgl", 2 * m * g * l),
    ("xyz", sympy.Symbol("xyz")),  # not all pieces known: one unknown name
    # before a bracket, the problem's names and one letter it lacks: that letter, for the checker to name
    ("mgL(a + b) + Lmg(a) + mgLsin(θ)", m * g * L * (a + b) + L * m * g * a + m * g * L * sin(theta)),
]

EQUATIONS = [
    ("m l^2 θ̈ + m g l sin θ = 0", Eq(m * l**2 * D(theta, 2) + m * g * l * sin(theta), 0)),
    ("thetaddot = -(g/l) sin(theta)", Eq(D(theta, 2), -(g / l) * sin(theta))),
    ("m x'' = -k x", Eq(m * D(x, 2), -k * x)),
    ("I(θ̈) = -m g l sin θ", Eq(sympy.Symbol("I") * D(theta, 2), -m * g * l * sin(theta))),  # no L(θ, θ̇) label
]

SYSTEMS = [
    ("a = b; c = d", (Eq(a, b), Eq(c, d))),
    # a conserved quantity named on the way: p = … = const, beside another equation
    ("p = a b = const, c = d", (Eq(a * b, sympy.Symbol("const")), Eq(c, d))),
    ("a = b and p = m l^2 thetadot = C_1", (Eq(a, b), Eq(m * l**2 * D(theta), sympy.Symbol("C_1")))),
    ("a = b\nc = d", (Eq(a, b), Eq(c, d))),
    ("[a = b, c = d]", (Eq(a, b), Eq(c, d))),
    ("{a = b, c = d}", (Eq(a, b), Eq(c, d))),
    ("a = b;", Eq(a, b)),
    # as people write a system: commas or "and" between equations, numbers that label them
    ("a = b, c = d", (Eq(a, b), Eq(c, d))),
    ("a = b and c = d", (Eq(a, b), Eq(c, d))),
    # a full stop, a space and a letter: the next sentence, as a new line is the next equation
    ("a = 0. c = d.", (Eq(a, 0), Eq(c, d))),
    ("For θ: a = b. For φ: c = d", (Eq(a, b), Eq(c, d))),
    ("a = b. θ̈ = c", (Eq(a, b), Eq(D(theta, 2), c))),
    ("a = b, where c = d", (Eq(a, b), Eq(c, d))),
    ("a = b with c = d", (Eq(a, b), Eq(c, d))),
    ("a = b \\quad\\text{where}\\quad c = d", (Eq(a, b), Eq(c, d))),
    ("(1) a = b\n(2) c = d", (Eq(a, b), Eq(c, d))),
    # a bracket that is an argument, or touches what it multiplies, is no equation's number
    ("m = sin(1); m = sin(2)", (Eq(m, sin(1)), Eq(m, sin(2)))),
    ("a = b(1)\nc = d(2)", (Eq(a, b), Eq(c, 2 * d))),
    # numbered in one line, in order, each number before an equation
    ("(1) a = b (2) c = d", (Eq(a, b), Eq(c, d))),
    ("1) a = b 2) c = d", (Eq(a, b), Eq(c, d))),
    ("1) a = b, 2) c = d.", (Eq(a, b), Eq(c, d))),
    ("a = b (2) c", Eq(a, 2 * b * c)),  # no (1) first: a factor
    ("(1) a + b (2)", a + 2 * b),
    ("a = b (1)\nc = d (2)", (Eq(a, b), Eq(c, d))),
    ("(1) a = b; (2) c = 2 (d)", (Eq(a, b), Eq(c, 2 * d))),
    ("(a) a = b\n(b) c = d", (Eq(a, b), Eq(c, d))),  # letters too, even where a and b are symbols
    ("$$\\ddot x = a$$ $$\\ddot\\theta = b$$", (Eq(D(x, 2), a), Eq(D(theta, 2), b))),  # two displays, one line
    ("$\\dot x$ + $\\dot\\theta$", D(x) + D(theta)),  # inline math around an operator: one expression
    ("(i) a = b\n(ii) c = d", (Eq(a, b), Eq(c, d))),
    ("(b) a = b\n(a) c = d", (Eq(b * a, b), Eq(a * c, d))),
    # numbers out of order, or on one equation only, are factors as written where they touch what follows
    ("(2)a = b\n(1)c = d", (Eq(2 * a, b), Eq(c, d))),
    ("a = b; (2) c = d", (Eq(a, b), Eq(2 * c, d))),
    ("1. a = b\n2. c = d", (Eq(a, b), Eq(c, d))),  # a numbered list, every line in order
    ("  1) a = b\n\n  2) c = d\n", (Eq(a, b), Eq(c, d))),
    ("1.5 a = b\n2.5 c = d", (Eq(3 * a / 2, b), Eq(5 * c / 2, d))),  # decimals, not a list
    ("1. ẍ = -k x.\n2. a = b.", (Eq(D(x, 2), -k * x), Eq(a, b))),
    # a bulleted list: the same bullet on every line, or a • alone, which is never mathematics
    ("• a = b\n• c = d", (Eq(a, b), Eq(c, d))),
    ("  * a = b\n  * c = d\n", (Eq(a, b), Eq(c, d))),
    ("• a = b", Eq(a, b)),
    # Markdown's "- " stays a minus sign: on every line it may as well be one
    ("- a = b\n- c = d", (Eq(-a, b), Eq(-c, d))),
    ("θ̈₁ = a; θ̈₂ = b", (Eq(D(theta1, 2), a), Eq(D(theta2, 2), b))),
    ("a = b +\nc", Eq(a, b + c)),
    ("a = b\n+ c", Eq(a, b + c)),
    # a label before a colon names the equation that follows it
    ("EOM: ẍ = -k x", Eq(D(x, 2), -k * x)),
    # a step's word or arrow that starts the answer, before an equation: the step's conclusion
    ("so ẍ = -k x", Eq(D(x, 2), -k * x)),
    ("Therefore ẍ = a", Eq(D(x, 2), a)),
    ("→ ẍ = a", Eq(D(x, 2), a)),
    ("-> a = b", Eq(a, b)),  # as ⇒ a = b
    ("a = b\nSo c = d", Eq(c, d)),
    ("Lagrangian: a + b", a + b),  # before an expression, a word that starts the answer
    ("Answer: 2 m", 2 * m),
    ("θ₁: a = b\nθ₂: c = d", (Eq(a, b), Eq(c, d))),
    ("eq 1: a = b; eq 2: c = d", (Eq(a, b), Eq(c, d))),
    ("EOM:\nẍ = -k x", Eq(D(x, 2), -k * x)),
    # a derivation with ⇒ concludes with what follows the last ⇒ (and a line that goes on from it)
    ("m ẍ = -k x ⇒ ẍ = -k x / m", Eq(D(x, 2), -k * x / m)),
    ("m ẍ = -k x => ẍ = -k x / m", Eq(D(x, 2), -k * x / m)),
    ("m ẍ = -k x\n⇒ ẍ = -k x / m", Eq(D(x, 2), -k * x / m)),
    ("m ẍ = -k x ⟹\nẍ = -k x / m", Eq(D(x, 2), -k * x / m)),
    ("⇒ ẍ = a", Eq(D(x, 2), a)),
    ("ẍ = a ⇒", Eq(D(x, 2), a)),
    ("c ẍ = c a ⇒ ẍ = a\nd θ̈ = d b ⇒ θ̈ = b", (Eq(D(x, 2), a), Eq(D(theta, 2), b))),
    # ⇒ ends at `;` as at a line's end: the equation before it stays
    ("ẍ = a; c θ̈ = c b ⇒ θ̈ = b", (Eq(D(x, 2), a), Eq(D(theta, 2), b))),
    ("c ẍ = c a ⇒ ẍ = a; θ̈ = b", (Eq(D(x, 2), a), Eq(D(theta, 2), b))),
    ("[ẍ = a; θ̈ = b]", (Eq(D(x, 2), a), Eq(D(theta, 2), b))),
    # a step that defines a name the conclusion uses stays before it, as a definition
    ("U = a, W = b, so L = U - W", (Eq(U, a), Eq(W, b), Eq(L, U - W))),
    ("U = a\nW = b\n⇒ L = U - W", (Eq(U, a), Eq(W, b), Eq(L, U - W))),
    ("U = a ⇒ W = b ⇒ L = U", (Eq(U, a), Eq(L, U))),  # W is used by no conclusion
    ("F = m a ⇒ m ẍ = -k x", Eq(m * D(x, 2), -k * x)),  # F, nor a, is used by the conclusion
    ("L = a ⇒ L = b", Eq(L, b)),  # a conclusion's own label is not a use of the name
    # every spelling of a step: ⇔ ∴ and typed arrows; → and words only between two equations
    *(
        (f"m ẍ = -k x {step} ẍ = -k x / m", Eq(D(x, 2), -k * x / m))
        for step in ("⇔", "⟺", "∴", "<=>", "==>", "→", "⟶", "->", "-->", "so", "hence", "thus", "therefore")
    ),
    ("m ẍ = -k x, so ẍ = -k x / m", Eq(D(x, 2), -k * x / m)),
    # the comma after the word, as a sentence has it (before: refused)
    ("So, ẍ = a", Eq(D(x, 2), a)),
    ("m ẍ = -k x, therefore, ẍ = -k x / m", Eq(D(x, 2), -k * x / m)),
    ("m ẍ = -k x ->\nẍ = -k x / m", Eq(D(x, 2), -k * x / m)),
    ("m ẍ = -k x\nso ẍ = -k x / m", Eq(D(x, 2), -k * x / m)),
    ("c ẍ = c a -> ẍ = a; θ̈ = b", (Eq(D(x, 2), a), Eq(D(theta, 2), b))),
    ("a - -b = c", Eq(a + b, c)),  # two minus signs are no arrow
    # a dot on a name glued to a coordinate is the coordinate's: ζθ̇ is ζ·θ̇, ζ the answer's own name
    ("2ζẋ + ζθ̇ + ξx'", 2 * sympy.Symbol("zeta") * D(x) + sympy.Symbol("zeta") * D(theta) + sympy.Symbol("xi") * D(x)),
    # ≈ is the relation a small-angle equation or a rounded number is written with
    ("θ̈ ≈ -g/l θ", Eq(D(theta, 2), -g / l * theta)),
    ("ẍ ≃ a", Eq(D(x, 2), a)),
    ("a + b\n- c", a + b - c),
    ("(a +\n b) = c", Eq(a + b, c)),
    # an equation's number set apart at its line's end: after TeX's wide space, or two spaces or a tab
    ("\\ddot{\\theta}=-\\frac{g}{l}\\sin\\theta \\qquad (3)", Eq(D(theta, 2), -g / l * sin(theta))),
    ("a = b \\quad (1) \\\\ c = d\\qquad(2)", (Eq(a, b), Eq(c, d))),
    ("a = b   (2)", Eq(a, b)),
    ("a = b\t(1)\nc = d  (2)", (Eq(a, b), Eq(c, d))),
    ("a + b \\quad (2)", a + b),
    ("a + b  (2)", a + 2 * b),  # no equation, no wide space: 2(a + b) may be meant, as typed
    ("a = b (2)", Eq(a, 2 * b)),  # one space: a factor
    # and at its start, a space and a name after it, on an equation's line; or a coordinate the line is for
    ("(2) L = ½ m", Eq(L, m / 2)),
    ("(2) a = b\n(1) c = d", (Eq(a, b), Eq(c, d))),
    ("(θ) m θ̈ = a\n(x) m ẍ = b", (Eq(m * D(theta, 2), a), Eq(m * D(x, 2), b))),
    ("\\left(\\theta_1\\right) \\ddot\\theta_1 = a", Eq(D(theta1, 2), a)),
    # a bracket that may be a factor stays one: a number, a bracket or no space after it, no `=`, no coordinate
    ("(2) (m)(g) = a", Eq(2 * m * g, a)),
    ("(1/2) m = a", Eq(m / 2, a)),
    ("(2) 3 a = b", Eq(6 * a, b)),
    ("(2) a + b", 2 * a + b),
    ("(m) a = b", Eq(m * a, b)),
]

LATEX = [
    ("\\frac{1}{2} m l^2 \\dot{\\theta}^2", m * l**2 * D(theta) ** 2 / 2),
    ("\\frac12 m", m / 2),
    ("\\dfrac{g}{l}", g / l),
    ("a \\cdot b", a * b),
    ("a \\times b", a * b),
    ("\\left( a + b \\right)^2", (a + b) ** 2),
    ("\\left[ a + b \\right] c", (a + b) * c),
    ("{a + b}^{2}", (a + b) ** 2),
    ("m^{2}", m**2),
    ("a \\cdot x^23", 3 * a * x**2),  # as in TeX: a superscript is one token
    ("theta1 + \\theta_1", 2 * theta1),  # names in plain notation inside LaTeX
    ("\\frac{1}{2} m l^2 thetadot^2", m * l**2 * D(theta) ** 2 / 2),
    ("uv \\cdot 2", 2 * sympy.Symbol("u") * sympy.Symbol("v")),  # unknown letters: TeX reads each alone
    ("m_{1}", m1),
    ("m_1", m1),
    ("\\sin\\theta + \\cos{\\phi}", sin(theta) + cos(phi)),
    ("\\sqrt{\\frac{g}{l}}", sqrt(g / l)),
    ("\\sqrt[3]{a}", a ** Rational(1, 3)),
    ("\\pi", sympy.pi),
    ("\\omega^2", omega**2),
    ("mgl", m * g * l),
    ("m_2l_2", m2 * l2),
    ("\\frac{1}{2} m_2 l_2^2 \\dot\\theta_2^2", m2 * l2**2 * D(theta2) ** 2 / 2),
    ("p_\\theta + p_{\\theta}", 2 * p_theta),
    ("\\ddot{x} = -\\frac{k}{m} x", Eq(D(x, 2), -k / m * x)),
    ("\\ddot\\theta_1 = a \\\\ \\ddot\\theta_2 = b", (Eq(D(theta1, 2), a), Eq(D(theta2, 2), b))),
    ("\\begin{aligned} a &= b \\\\ c &= d \\end{aligned}", (Eq(a, b), Eq(c, d))),
    ("\\begin{cases} a = b \\\\ c = d \\end{cases}", (Eq(a, b), Eq(c, d))),
    ("\\left\\{ \\begin{aligned} a &= b \\\\ c &= d \\end{aligned} \\right.", (Eq(a, b), Eq(c, d))),
    # what equation editors write: an array with its columns, \newline, eqnarray; and wide spaces or
    # one environment after another between two equations (elsewhere a \quad is a space)
    ("\\left\\{\\begin{array}{l} a = b \\\\ c = d \\end{array}\\right.", (Eq(a, b), Eq(c, d))),
    ("\\begin{array}{rcl} a &=& b \\\\ c &=& d \\end{array}", (Eq(a, b), Eq(c, d))),
    ("\\begin{eqnarray} a &=& b \\\\ c &=& d \\end{eqnarray}", (Eq(a, b), Eq(c, d))),
    ("a = b \\newline c = d", (Eq(a, b), Eq(c, d))),
    ("a = b \\qquad c = d \\quad\\text{and}\\quad \\ddot x = d", (Eq(a, b), Eq(c, d), Eq(D(x, 2), d))),
    ("\\begin{equation} a = b \\end{equation} \\begin{equation} c = d \\end{equation}", (Eq(a, b), Eq(c, d))),
    ("a = \\quad b \\qquad c", Eq(a, b * c)),
    ("\\left\\{ a + b \\right\\} c", (a + b) * c),  # a brace closed by a brace is a bracket
    ("$\\frac{a}{b}$", a / b),
    ("$a b$", a * b),  # TeX's math without a backslash in it: the dollars are still read past
    ("\\exp(a) + \\ln b", exp(a) + sympy.log(b)),
    ("\\dot{\\theta}'", D(theta, 2)),
    ("\\ell", l),
    # an argument without braces is one character, as TeX reads it
    ("\\frac gl", g / l),
    ("-\\frac gl \\sin\\theta", -g / l * sin(theta)),
    ("\\frac m2 l^2", m * l**2 / 2),
    ("\\frac m23", 3 * m / 2),
    ("\\frac\\pi2", sympy.pi / 2),
    ("\\sqrt gl", sqrt(g) * l),
    ("\\frac{mgl}{2}", m * g * l / 2),
    ("√gl \\cdot x", sqrt(g * l) * x),  # √ is not \\sqrt: its argument is the name that follows
    ("\\, mv = p", Eq(m * sympy.Symbol("v"), sympy.Symbol("p"))),  # in TeX, mv is m·v: no name
    # the math's own delimiters, and the full stop or comma of the sentence around it
    ("\\[ \\frac{a}{b} \\]", a / b),
    ("\\( a + b \\)", a + b),
    ("a + b.", a + b),
    ("\\[\\ddot x = -k x.\\]", Eq(D(x, 2), -k * x)),
    ("\\begin{cases} a = b. \\\\ c = d. \\end{cases}", (Eq(a, b), Eq(c, d))),
    ("\\ddot x = -\\frac km x,", Eq(D(x, 2), -k / m * x)),
    ("\\bigl(a + b\\bigr)^2 + \\Bigl[c\\Bigr]", (a + b) ** 2 + c),
    ("\\mathcal L + \\mathrm d", sympy.Symbol("L") + d),  # a font's letter without braces, as TeX reads it
    ("a~b\\,.", a * b),
    # what a document adds around the math: labels, tags, a full stop in \text; \operatorname{cos} is \cos
    ("m g l \\operatorname{cos}\\theta \\label{eq:L} \\tag{1}\\text{.}", m * g * l * cos(theta)),
    ("\\mathscr{L} + \\mathscr L", 2 * sympy.Symbol("L")),
    ("\\text{cos}\\,\\theta", cos(theta)),
    # TeX puts a subscript that follows a power on the base: x^2_1 is x₁²
    ("\\dot{\\theta}^2_1 + x^{2}_{1}", D(theta1) ** 2 + sympy.Symbol("x_1") ** 2),
    ("m \\ddot x = -k x \\Rightarrow \\ddot x = -\\frac km x", Eq(D(x, 2), -k / m * x)),
    ("\\ddot x = a \\implies", Eq(D(x, 2), a)),
    ("\\ddot x \\approx a; \\ddot\\theta \\simeq b", (Eq(D(x, 2), a), Eq(D(theta, 2), b))),
    # TeX's prime is a superscript: θ' typeset is \theta^\prime, and its square \theta^{\prime 2}
    ("\\theta^\\prime + \\theta^{\\prime\\prime} + x^{ \\prime }", D(theta) + D(theta, 2) + D(x)),
    ("\\theta^{\\prime 2} + \\theta_1^{\\prime\\prime 3}", D(theta) ** 2 + D(theta1, 2) ** 3),
    ("{\\theta^{\\prime}}^2", D(theta) ** 2),
    # a compound unit in roman type: its words whole names (rad, not r·a·d), for the checker to read as units
    ("a\\,\\text{kg\\cdot s^{-2}}", a * sympy.Symbol("kg") * sympy.Symbol("s") ** -2),
    ("\\sqrt{g}\\,\\mathrm{rad/s}", sympy.sqrt(g) * sympy.Symbol("rad") / sympy.Symbol("s")),  # a, d known
    *(
        (f"m \\ddot x = -k x {step} \\ddot x = -\\frac km x", Eq(D(x, 2), -k / m * x))
        for step in ("\\iff", "\\Leftrightarrow", "\\therefore", "\\to", "\\rightarrow", "\\text{ so }")
    ),
    # a row break's spacing below its row, \\\\[6pt]: a length, no factor of the next row
    ("a = b \\\\[6pt] c = d \\\\ [1em] \\ddot x = a \\\\[-2.5mm] m = k",
     (Eq(a, b), Eq(c, d), Eq(D(x, 2), a), Eq(m, k))),
    ("a = b \\\\ [c + d] = a", (Eq(a, b), Eq(c + d, a))),  # no length: a bracket
    # MathType's spaces before a subscript or a prime, and its braces around the name they mark
    ("\\theta _1 + {\\dot \\theta _1}^2 + {\\theta}_2 + {\\dot\\theta}_2",
     theta1 + D(theta1) ** 2 + theta2 + D(theta2)),
    ("\\theta ' + \\phi '' + x^{\\prime} + \\theta ^{\\prime\\prime} + \\phi ^\\prime + {\\theta}'",
     2 * D(theta) + D(phi, 2) + D(x) + D(theta, 2) + D(phi)),
    ("m{l^2}{\\dot \\theta _1}^2 + \\frac{1}{2}m{l^2}{\\dot \\theta _2}^2"
     " + m{l^2}{\\dot \\theta _1}{\\dot \\theta _2}\\cos ({\\theta _1} - {\\theta _2})"
     " + 2mgl\\cos {\\theta _1} + mgl\\cos {\\theta _2}",
     m * l**2 * D(theta1) ** 2 + m * l**2 * D(theta2) ** 2 / 2 + m * l**2 * D(theta1) * D(theta2) * cos(theta1 - theta2)
     + 2 * m * g * l * cos(theta1) + m * g * l * cos(theta2)),
    # a power after the marks, a brace's power, a name's brace alone
    ("{\\theta}_1^{\\prime 2} + {\\theta}^2 + {\\theta_1}", D(theta1) ** 2 + theta**2 + theta1),
    # a name in \\text before `=`, as in \\mathrm; bold type, which says nothing of a scalar; more of a document
    ("\\text{L}=a", Eq(L, a)),
    ("\\text{Lagrangian} = a", Eq(sympy.Symbol("Lagrangian"), a)),  # a word in text is one name, never L·a·g·…
    ("\\mathbf{x} + \\boldsymbol{\\theta} + \\bm\\phi + \\mathbf{m}_1 + \\boldsymbol{\\dot\\theta}",
     x + theta + phi + m1 + D(theta)),
    ("a = b \\nonumber \\\\ c = d \\tag*{2} \\notag", (Eq(a, b), Eq(c, d))),
    ("\\overset{..}{\\theta} + \\overset{\\cdot\\cdot}{x} + \\overset{.}{\\phi} + \\overset{\\cdot}{\\theta}_1",
     D(theta, 2) + D(x, 2) + D(phi) + D(theta1)),
    # plain TeX's \\over: what stands before it in its braces over what stands after; at top level, the side
    ("{m g l \\over 2} + {1 \\over 2} m l^2 \\dot\\theta^2", m * g * l / 2 + m * l**2 * D(theta) ** 2 / 2),
    ("\\ddot x = -{k \\over m} x", Eq(D(x, 2), -k / m * x)),
    ("m g l \\over 2", m * g * l / 2),
    ("a = b + c \\over 2 m", Eq(a, (b + c) / (2 * m))),
    ("{{a \\over b} \\over c} + \\sqrt{g \\over l} + \\left( a \\over c \\right)^2",
     a / (b * c) + sqrt(g / l) + (a / c) ** 2),
    # a sum in the definition a chain passes over, as Σ is: H = Σ p q̇ − L = … (before: \\sum unknown)
    ("H = \\sum_i p_i \\dot q_i - L = a", Eq(H, a)),
    ("H = \\sum_j p_j \\dot{q}_j - L = a", Eq(H, a)),
    ("H = \\sum p\\dot q - L = a", Eq(H, a)),
    ("H = \\sum_{j=1}^{n} p_j \\dot q_j - L = a", Eq(H, a)),
    ("H = \\sum\\limits_{k} p_k \\dot q_k - L = a", Eq(H, a)),
    ("H = ∑ p q̇ − L = a", Eq(H, a)),
    ("H = ∑_i p_i q̇_i − L = a", Eq(H, a)),
    # \\Delta or \\delta, then a name: one name, as Δθ typed is; so all of it is a function's argument
    # (before: \\cos\\Delta\\theta was cos(Δ)·θ), and where no name of the answer's is that, Δ·θ
    ("\\cos\\Delta\\theta", cos(Delta * theta)),
    ("\\sin \\Delta \\theta_1 + \\cos\\delta x", sin(Delta * theta1) + cos(sympy.Symbol("delta") * x)),
    ("\\Delta\\theta^2 + \\Delta x", Delta * theta**2 + Delta * x),
    ("\\cos\\Delta_1\\theta_1 + \\cos\\Delta\\dot x", cos(sympy.Symbol("Delta_1")) * theta1 + cos(Delta) * D(x)),
]  # fmt: skip

ACCEPTED = ARITHMETIC + FUNCTIONS + NAMES + DERIVATIVES + SPLITTING + EQUATIONS + SYSTEMS + LATEX


@pytest.mark.parametrize(("text", "expected"), ACCEPTED, ids=[text for text, _ in ACCEPTED])
def test_accepted_input_gives_its_sympy_object(text, expected):
    result = parse_answer(text, coords=COORDS, known=KNOWN)
    assert result.ok, str(result)
    assert result.value == expected


@pytest.mark.parametrize(
    ("text", "kind"),
    [("a + b", "expression"), ("a = b", "equation"), ("a = b; c = d", "equations"), ("[a = b, c = d]", "equations")],
)
def test_kind_says_what_was_typed(text, kind):
    assert parse_answer(text, known=KNOWN).kind == kind


@pytest.mark.parametrize(("text", "expected"), LEIBNIZ, ids=[text for text, _ in LEIBNIZ])
def test_leibniz_notation_is_a_time_derivative(text, expected):
    # Only where the problem does not itself define a symbol d, as KNOWN does.
    result = parse_answer(text, coords=COORDS, known=[name for name in KNOWN if name != "d"])
    assert result.ok, str(result)
    assert result.value == expected


@pytest.mark.parametrize(
    ("text", "rates"),
    [
        ("ṗ = -m g l sin θ; p = m l² θ̇", ["p"]),
        ("p' = a\np = m θ̇", ["p"]),
        ("d/dt(p) = a, where p = m θ̇", ["p"]),
        ("dp/dt = a; p = m θ̇", ["p"]),
        ("p_θ = m θ̇, ṗ_θ = a", ["p_theta"]),  # p_θ is no name of this problem's
        # spelled out, as thetadot is θ̇: on either side, with a subscript of letters or digits
        ("pdot = -m g l sin θ; p = m l² θ̇", ["p"]),
        ("p_thetadot = a, p_theta = m θ̇", ["p_theta"]),
        ("p_theta_dot = a, p_theta = m θ̇", ["p_theta"]),
        ("½ m (x_1dot² + ydot²), x_1 = l sin θ, y = l cos θ", ["x_1", "y"]),
        ("d/dt(m u v) = a; u = θ; v = θ̇", ["u", "v"]),  # each of the answer's names has its rate
        # a derivation keeps the step that defines a name whose rate its conclusion uses
        ("p = m θ̇ ⇒ ṗ = a", ["p"]),
        ("x = l sin θ ⇒ L = ½ m ẋ²", ["x"]),
        # a chain's middle side is left out, and its rate with it: nothing to define
        ("T = ½ m ẋ² = ½ m l² θ̇²", []),
    ],
)
def test_the_rate_of_a_name_the_answer_defines_is_its_derivative_in_time(text, rates):
    # ṗ where p = m l² θ̇: the derivative of p as a function of time, for compare to put in place
    result = parse_answer(text, coords=["theta"], known=["m", "g", "l", "a"])
    assert result.ok, str(result)
    items = result.value if isinstance(result.value, tuple) else (result.value,)
    found = {d.expr.func.__name__ for item in items for d in item.atoms(sympy.Derivative) if d.expr.args == (t,)}
    assert found - {"theta"} == set(rates)


def test_d_and_dt_are_symbols_when_the_problem_defines_them():
    assert parse_answer("d/dt x", known=["d"], coords=["x"]).value == x / t  # d·x/(d·t): the problem said d
    d = sympy.Symbol("d")
    assert parse_answer("dx + ddx", known=["d"], coords=["x"]).value == d * x + d**2 * x  # not ẋ + ẍ


def test_letters_stand_in_for_a_greek_name_only_where_the_problem_has_it_and_not_them():
    w, th = sympy.Symbol("w"), sympy.Symbol("th")
    assert parse_answer("w + th", coords=["x"], known=["m"]).value == w + th  # no ω or θ here
    assert parse_answer("w", known=["w", "omega"]).value == w  # the problem's own w
    assert parse_answer("th1'", coords=["theta_1"]).value == D(theta1)
    h, p = sympy.Symbol("h"), sympy.Symbol("p")
    assert parse_answer("ph + th", coords=["theta", "phi"], known=["p", "h"]).value == p * h + t * h  # splits first


STAND_IN_RATES = [
    # (text, coords, known, value): th and ph with a rate glued on as d or dd, for θ̇ and θ̈ (before, undefined)
    ("th1dd", ["theta_1", "theta_2"], [], D(theta1, 2)),
    ("th2d", ["theta_1", "theta_2"], [], D(theta2)),
    ("th_1dd", ["theta_1", "theta_2"], [], D(theta1, 2)),
    ("thdd", ["theta"], [], D(theta, 2)),
    ("phd", ["theta", "phi"], [], D(phi)),
    # what read before reads as it did: the other stand-ins, the problem's names and splits first, w alone
    ("th1dot", ["theta_1", "theta_2"], [], D(theta1)),
    ("th_2ddot", ["theta_1", "theta_2"], [], D(theta2, 2)),
    ("th1", ["theta_1", "theta_2"], [], theta1),
    ("thd", ["theta"], ["h", "d"], t * sympy.Symbol("h") * d),
    ("thd", ["theta"], ["thd"], sympy.Symbol("thd")),
    ("th1dd", ["x"], ["m"], sympy.Symbol("th1dd")),  # no θ₁ here
    ("wd", ["x"], ["omega"], sympy.Symbol("wd")),  # no ω̇ of a constant
    ("w_0", ["x"], ["omega_0"], sympy.Symbol("omega_0")),
]


@pytest.mark.parametrize(("text", "coords", "known", "value"), STAND_IN_RATES)
def test_th_and_ph_with_d_or_dd_glued_on_are_the_angle_s_rates(text, coords, known, value):
    result = parse_answer(text, coords=coords, known=known)
    assert result.ok and result.value == value, result


STAND_IN_LABELS = [
    # (text, coords, value): a stand-in for an angle's rate alone before `=` is that rate, as after it, and no
    # label of the answer's own (before, thdd = … was the name thdd)
    ("thdd = -g sin(th)", ["theta"], Eq(D(theta, 2), -g * sin(theta))),
    ("thddot = g", ["theta"], Eq(D(theta, 2), g)),
    ("th_dd = g", ["theta"], Eq(D(theta, 2), g)),
    ("th1dd = g", ["theta_1", "theta_2"], Eq(D(theta1, 2), g)),
    ("phd = g", ["theta", "phi"], Eq(D(phi), g)),
]


@pytest.mark.parametrize(("text", "coords", "value"), STAND_IN_LABELS)
def test_a_stand_in_for_an_angles_rate_is_no_label(text, coords, value):
    result = parse_answer(text, coords=coords, known=["g"])
    assert result.ok and result.value == value, result


def test_a_d_before_a_name_that_is_no_coordinate_is_part_of_the_name():
    assert parse_answer("dy + da", coords=["x"]).value == sympy.Symbol("dy") + sympy.Symbol("da")


def test_a_word_for_a_step_is_a_name_unless_it_stands_between_two_equations():
    s, o = sympy.symbols("s o")
    assert parse_answer("x = so", known=["s", "o", "x"]).value == Eq(sympy.Symbol("x"), s * o)
    assert parse_answer("a = b so", known=["s", "o", "a", "b"]).value == Eq(a, b * s * o)
    assert parse_answer("a = b so c = d", known=["a", "b", "c", "d"]).value == Eq(c, d)


def test_e_is_a_symbol_when_the_problem_defines_one():
    assert parse_answer("e^2", known=["e"]).value == sympy.Symbol("e") ** 2


def test_known_symbols_keep_their_assumptions():
    mass = sympy.Symbol("m", positive=True)
    assert parse_answer("m", known=[mass]).value is mass


def test_coordinates_given_as_functions_are_used_as_given():
    q = sympy.Function("q")(t)
    assert parse_answer("qdot", coords=[q]).value == sympy.Derivative(q, t)


def test_juxtaposed_names_do_not_split_unless_every_piece_is_known():
    assert parse_answer("mgl", known=["m", "g"]).value == sympy.Symbol("mgl")


def test_a_greek_letter_glued_to_names_is_one_piece_never_its_spelling_split():
    # γ is "gamma" once read: with g, a and m defined it was g·a²·m², and the dot went on all of it
    gamma, x = sympy.Symbol("gamma"), sympy.Symbol("x")
    assert parse_answer("γx", known=["m", "g", "a", "x"]).value == gamma * x
    assert parse_answer("mgalpha", known=["m", "g", "a", "l", "p", "h"]).value == sympy.Symbol("alpha") * sympy.Symbol(
        "g"
    ) * sympy.Symbol("m")
    assert parse_answer("sinu", known=["u"]).value == sympy.sin(sympy.Symbol("u"))  # mu, nu, pi, xi: too short to tell


def test_a_greek_letter_with_a_numbered_subscript_splits_off_a_known_name_glued_after():
    # ω₀t was one name ω_0t, undefined, where m₁x was already m₁·x
    omega0 = sympy.Symbol("omega_0")
    for typed in ("ω₀t", "omega_0t", "\\omega_0t"):
        assert parse_answer(f"cos({typed})", known=["omega_0"]).value == sympy.cos(omega0 * t), typed  # t is time
    assert parse_answer("ω₀x", known=["omega_0"]).value == sympy.Symbol("omega_0x")  # x not known: one name
    assert parse_answer("θ₁g", coords=["theta_1"], known=["g"]).value == g * theta1


def test_the_whole_name_wins_over_a_split():
    assert parse_answer("mgl", known=["m", "g", "l", "mgl"]).value == sympy.Symbol("mgl")


def test_equations_keep_both_sides_unevaluated():
    result = parse_answer("a = a", known=["a"])
    assert result.value == Eq(a, a, evaluate=False)
    assert isinstance(result.value, sympy.Eq)
