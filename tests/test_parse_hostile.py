"""Hostile answers: whatever a student might type to break, stall or escape the parser.

Contents:
    HOSTILE              (text, refusal code) rows, grouped by the threat they stand for
    test_hostile_input_is_refused_with_its_code
    FORMERLY_ACCEPTED    inputs these tests found accepted, or hanging, and that are now refused
    SHOWN                (text, exact message, exact pointer) for representative refusals
    test_refusal_is_shown_exactly
    test_non_text_input_is_refused / test_refusal_renders_as_text
    LARGE_BUT_ALLOWED    answers near the limits that must be accepted and shown back
    hang guard           turns "never returns" into a failure for inputs that once hung

Every row must come back as a Refusal and never raise. Speed is measured by
``benchmarks/parse.py``, never asserted here: test machines are too noisy for timings.
The only clock in this file is the hang guard, which waits thousands of times longer
than a parse takes and only exists to turn "never returns" into a failure.
"""

from __future__ import annotations

import signal
from contextlib import contextmanager

import pytest
from sympy.core.cache import clear_cache

from grader import Refusal, parse_answer
from grader.judge.deadline import CheckTimeout, Deadline

COORDS = ["theta", "x"]
KNOWN = ["m", "g", "l"]
CAP = 2000  # grader.parse.tokens.LIMITS.length, spelled out so a change to it is noticed here


def _nested(opener: str, closer: str, levels: int, core: str = "x") -> str:
    return opener * levels + core + closer * levels


HOSTILE = [
    # -- size: the cap on the whole answer, and on its parts --------------------
    ("x" * (CAP + 1), "too_long"),
    ("1+" * (CAP // 2) + "1", "too_long"),
    (" " * (CAP + 1), "too_long"),
    ("a" * 41, "name_too_long"),
    # -- nesting: brackets, and chains the grammar recurses on ------------------
    (_nested("(", ")", 41), "too_deep"),
    (_nested("[", "]", 41), "too_deep"),
    (_nested("{", "}", 41), "too_deep"),
    (_nested("(", ")", 999), "too_deep"),
    ("(" * 1999 + "x", "too_deep"),  # too deep is noticed before never closed
    ("-" * 41 + "x", "too_deep"),
    ("-" * (CAP - 1) + "x", "too_deep"),
    ("+-" * 30 + "x", "too_deep"),
    ("x" + "^x" * 41, "powers_too_deep"),
    ("x" + "^x" * ((CAP - 1) // 2), "powers_too_deep"),
    ("x" + "^x" * 9, "powers_too_deep"),  # LIMITS.powers is 8: x^x^…^x costs the square of its height
    ("e^(x^(y^(z^(x^(y^(z^(x^(y^2))))))))", "powers_too_deep"),
    (_nested("sin(", ")", 41), "too_deep"),
    (_nested("sin(", ")", 399), "too_deep"),
    ("sin " * 41 + "x", "too_deep"),
    (_nested("\\frac{", "}{2}", 41), "too_deep"),
    # -- numbers and powers too large to build ----------------------------------
    ("9^9^9^9", "exponent_too_large"),
    ("10^1000", "exponent_too_large"),
    ("1e999999999", "exponent_too_large"),
    ("x^(9^9)", "exponent_too_large"),
    ("(x^50)^50", "exponent_too_large"),
    ("x^101", "exponent_too_large"),
    ("2^-1000", "exponent_too_large"),
    ("x⁹⁹⁹", "exponent_too_large"),
    ("e^(e^(e^(e^9)))", "exponent_too_large"),
    ("sqrt(2)^(9^9)", "exponent_too_large"),
    ("1234567890" * 4, "number_too_large"),
    ("3.14159265358979323846264338327950288", "number_too_large"),
    # -- code: attribute access, strings, lambdas, comments, assignments ---------
    ("x.__class__", "attribute"),
    ("().__class__", "attribute"),
    ("os.system", "attribute"),
    ("os.system('rm -rf /')", "attribute"),
    ("'rm -rf /'", "string"),
    ('"rm -rf /"', "string"),
    ("`rm -rf /`", "string"),
    ("getattr(x, '__class__')", "string"),
    ("lambda x: x", "bad_character"),
    ("lambda: 1", "bad_character"),
    # a colon is read past only after a line's label of an equation: one to three undotted names
    ("m g:", "bad_character"),
    ("θ̈: -g sin θ = 0", "bad_character"),
    ("a b c d: x = 1", "bad_character"),
    ("m g: x", "bad_character"),  # before an expression, names are no label: only a word is
    ("sin: x", "bad_character"),
    ("a + b\nLagrangian: c", "bad_character"),  # and only where the answer starts
    ("x^2_1", "bad_character"),  # a subscript after a power is TeX's, not plain notation's
    ("x # comment", "comment"),
    ("#", "comment"),
    ("x := 1", "assignment"),
    ("x == 1", "assignment"),
    ("x += 1", "assignment"),
    ("x != 1", "assignment"),
    ("__import__('os')", "bad_character"),
    ("x[0] @ y", "bad_character"),
    # a call: a glued name before a bracket is the problem's names and one letter it lacks (mgL(…)), only so
    ("foo(x)", "unknown_function"),
    ("mgLL(x)", "unknown_function"),
    ("mgLgamma(x)", "unknown_function"),  # γ, spelled, is no name of the problem's
    # -- brackets ---------------------------------------------------------------
    ("sin(θ", "unclosed"),
    ("((m g l)", "unclosed"),
    ("x_{1", "unclosed"),
    ("m g l)", "unopened"),
    ("}", "unopened"),
    ("(x]", "mismatched"),
    ("[x}", "mismatched"),
    ("|x", "unclosed"),  # an absolute value's bars
    ("m |x - a", "unclosed"),
    ("||", "unclosed"),
    ("|a)", "mismatched"),
    ("(a|)", "mismatched"),
    # -- nothing to read --------------------------------------------------------
    ("", "empty"),
    ("   ", "empty"),
    ("\n\t \r", "empty"),
    ("\u00a0", "empty"),
    # -- LaTeX that is not mathematics ------------------------------------------
    ("\\input{/etc/passwd}", "unknown_command"),
    ("\\def\\x{1}", "unknown_command"),
    ("\\text{hello}", "latex_words"),
    ("x = 1 \\text{(a remark longer than forty characters, in words)}", "latex_words"),  # was: an unknown \\text
    ("\\sqrt{g/l}\\,\\mathrm{radians per second}", "latex_words"),  # words: said so, not "\\mathrm is unknown"
    ("\\sqrt{g/l}\\,\\mathrm{m/s}", "unit_is_a_name"),  # m is the problem's mass: which is it?
    ("\\mathrm{" + "a" * 41 + "/s}", "name_too_long"),  # a unit's words keep the cap on a name
    ("* a = b\n• c = d", "bad_character"),  # two bullets: not one list, and • is no mathematics
    ("\\text{{a}}", "unknown_command"),
    ("\\sqrt\\[3\\]{x}", "unknown_command"),
    ("m ∂θ", "partial"),  # ∂ only in a name before =, as in ∂L/∂θ̇ = …
    ("∂L/∂θ̇ + 1 = m", "partial"),  # \\[ opens the math only where a line starts
    ("d/dt(∂L/∂θ̇) = ∂L/∂θ", "partial"),  # the operator is read before an equation, not as one
    ("d/dt(∂L/∂θ̇) − ∂L/∂θ = m = g = l", "too_many_equals"),
    ("d/dt(∂L/∂θ̇ − ∂L/∂θ) = m", "partial"),  # the bracket around the momentum only
    ("d²/dt²(∂L/∂θ̇) − ∂L/∂θ = m = g", "partial"),
    ("\\immediate\\write18{rm -rf /}", "unknown_command"),
    ("\\begin{verbatim}x\\end{verbatim}", "unknown_command"),
    ("\\csname x\\endcsname", "unknown_command"),
    # a subscript on a brace that is an argument, or on a name that has one; dots that are no \\dot or \\ddot
    ("\\frac{a}{x}_1", "bad_character"),
    ("{\\theta_1}_2", "bad_character"),
    ("\\overset{a}{x}", "unknown_command"),
    ("\\overset{...}{x}", "unknown_command"),
    ("\\text{L} + a", "latex_words"),  # a name in \\text only before `=`, as the quantity written out
    ("a = b \\\\[6pt", "unclosed"),
    # TeX's \\over: one to a pair of braces (TeX itself refuses two), and something on each side of it
    ("{a \\over b \\over c}", "over_twice"),
    ("m \\over g \\over l = x", "over_twice"),
    ("a \\over " * 200 + "b", "over_twice"),
    ("{\\over 2}", "over_side"),
    ("{m g \\over} l", "over_side"),
    ("x = \\over l", "over_side"),
    ("\\over", "over_side"),
    ("{1 \\over 0}", "division_by_zero"),
    (_nested("{1 \\over ", "}", 41), "too_deep"),
    # a sum only in the definition a chain passes over (H = \\sum_j p_j \\dot q_j - L = …): anywhere else
    # its terms are not written, and it is refused, limits and all
    ("\\sum_i m_i", "sum"),
    ("H = \\sum_i p_i \\dot q_i - L", "sum"),  # the definition alone: no value after it
    ("\\sum_i p_i \\dot q_i - L = m", "sum"),  # no name before it: nothing passes it over
    ("H = \\sum_i p_i \\dot q_i - L = \\sum_i p_i \\dot q_i", "sum"),  # the value a sum too
    ("H = a = \\sum_i x_i", "sum"),
    ("H = \\sum p \\dot q - L = m \\sum_{j=1}^{2} l_j", "sum"),
    ("e^{\\sum_i x_i}", "sum"),
    ("m g l + ∑ m", "sum"),
    ("∑_i m_i = m", "sum"),
    ("\\sum_{i=1}^{10^{100}} x", "exponent_too_large"),  # a limit beyond what is read past is read
    ("\\sin\\sum x", "unexpected"),
    ("\\sum_{__import__} x", "bad_character"),
    # -- values that do not exist -----------------------------------------------
    ("1/0", "division_by_zero"),
    ("m/(l-l)", "division_by_zero"),
    ("\\frac{1}{0}", "division_by_zero"),
    ("0^-1", "division_by_zero"),
    ("log(0)", "undefined_value"),
    ("tan(pi/2)", "undefined_value"),
    # -- characters outside the whitelist ---------------------------------------
    ("x\x00", "bad_character"),
    ("\x00", "bad_character"),
    ("x\x1b[2J", "bad_character"),
    ("\u202ex", "bad_character"),  # right-to-left override
    ("x\u2066", "bad_character"),  # left-to-right isolate (zero-width spaces and full-width letters are read)
    ("a\u2064b", "bad_character"),  # Word's invisible plus, 2⁤½: not read as a space, which would multiply
    ("x\u00ad", "bad_character"),  # soft hyphen
    ("x\ud800", "bad_character"),  # lone surrogate, as json.loads can produce
    # a point with no digit after it, where no sentence ends
    ("2. 5", "lone_point"),  # before a digit: 2.5, or a slip
    ("(1) a = b (3) c = d", "too_many_equals"),  # numbers out of order are no equation numbers
    ("1) a = b 2) c", "unopened"),  # the second is no equation
    ("a . b", "lone_point"),
    # -- derivatives beyond the limit -------------------------------------------
    ("theta''''", "derivative_order"),
    ("diff(theta, t, 99999999999999999999)", "derivative_order"),
    ("Derivative(theta(t), (t, 99999999999999999999))", "derivative_order"),
    ("(d/dt)^99999999999999999999 x", "derivative_order"),
    ("Derivative(theta(t), (t, x))", "diff_usage"),
    # more than one '=': only a quantity named and said to be conserved (p = … = const) is read
    ("m = g = l", "too_many_equals"),
    ("m g = t = const", "too_many_equals"),  # t is time, not a name for the quantity
    ("m g = l = const", "too_many_equals"),  # l is the problem's own
    ("p = m g = q", "too_many_equals"),  # q is no word for a constant
    ("p = m g = const = C", "too_many_equals"),
    ("F = m θ̈ = −g = 0", "too_many_equals"),  # a chain past the named equation of motion
    ("F = m θ̇ = −m g", "too_many_equals"),  # no acceleration: no equation of motion named
    ("ω = √(g/l) = 3.13", "too_many_equals"),
    ("x = 1; m g", "not_an_equation"),  # an expression only first, before the definitions of its names
    ("9,81 θ + l = 0", "comma"),  # a decimal comma, not an expression and a definition
    ("1/0,498", "comma"),  # a decimal comma: no division by zero, as said before
    ("m g/0,5", "comma"),
    ("p = m g =", "unexpected_end"),  # a label, a side, and nothing after the last `=`
    ("m θ = m =", "unexpected_end"),
    ("Derivative(theta(t), (t, 2, 3))", "diff_usage"),
    ("diff(theta, x)", "diff_usage"),
    ("d/dt(d/dt(d/dt(d/dt(theta*m))))", "derivative_order"),  # nested around a product, past the cap
    # an arrow is a derivation's step only between two equations; elsewhere it is a limit or a map
    ("\\theta^{\\prime 2", "unclosed"),
    ("m^\\prime", "derivative_of_constant"),  # TeX's prime marks a derivative, only of a coordinate
    ("ṗ_θ = a", "derivative_of_constant"),  # the dot is p_θ's, not θ's: no p·θ̇; and nothing defines p_θ
    ("p_θ̇", "derivative_of_constant"),
    ("ṗ = a; q = m", "derivative_of_constant"),  # a name's rate, where the answer defines another name
    ("d/dt(m v) = a", "derivative_of_constant"),  # d/dt of a name nothing defines: no quantity in time
    ("p̈ = a; p = m", "derivative_of_constant"),  # a defined name's rate, but of the second order
    ("d^2/dt^2(p) = a; p = m", "derivative_of_constant"),
    ("ṁ = a; m = x", "derivative_of_constant"),  # m is the problem's own: a constant
    ("pdot = a; q = m", "derivative_of_constant"),  # spelled out as ṗ, and refused as ṗ is
    ("½ m pdot²", "derivative_of_constant"),
    ("θ → 0", "arrow"),
    ("θ̈ = -g/l θ (θ → 0)", "arrow"),
    ("θ̈ → -g/l θ", "arrow"),
    ("x -> 1", "arrow"),
    ("a = b ->", "arrow"),
    ("a = b -> c = d -> e", "arrow"),
    ("a = b; c -> d = e", "arrow"),  # `;` ends an equation as a line does
    ("\\theta \\to 0", "arrow"),
]


def _row_id(text) -> str:
    shown = ascii(text)
    return shown if len(shown) <= 40 else f"{shown[:36]}…[{len(text)}]"


def _refusal(text) -> Refusal:
    result = parse_answer(text, coords=COORDS, known=KNOWN)
    assert result.ok is False, f"accepted as {result.value!r}"
    return result


@pytest.mark.parametrize(("text", "code"), HOSTILE, ids=[_row_id(text) for text, _ in HOSTILE])
def test_hostile_input_is_refused_with_its_code(text, code):
    assert _refusal(text).code == code


def test_powers_beside_each_other_are_not_nested():
    assert parse_answer("e^(-(t/tau)^2) + (x^2)^3^2", known=["tau", "x"]).ok  # beside each other, not nested


# -- found by these tests, once bugs, now refused ------------------------------------

FORMERLY_ACCEPTED = [
    ("d/dt(p) = a", "derivative_of_constant"),  # d/dt of a name of the student's own was 0
    ("d/dt(" + "*".join(f"a{i}" for i in range(60)) + ") = 0", "derivative_of_constant"),  # took seconds
    ("eval(x)", "unknown_function"),  # calls of unknown functions were read as products
    ("exec(x)", "unknown_function"),
    ("open(f)", "unknown_function"),
    ("Integer(1)", "unknown_function"),
    ("getattr(x)", "unknown_function"),
    ("(((2^(1/2))^99)^99)^99", "value_too_large"),  # a 146,000-digit power of a non-rational base
    ("*".join(["9^99"] * 46), "value_too_large"),  # each factor within limits, the product 4,300 digits
    # a coefficient multiplied out beside a symbol: 10¹⁰⁰⁰⁰ in front of l⁻¹⁰⁰, which no printer could show
    ("(1e-100 l)^-100", "value_too_large"),
    ("x*" + "*".join(["1e99"] * 100), "value_too_large"),
    (r"\frac{10^{99} x}{10^{-99}} \cdot 10^{99} \cdot 10^{99} \cdot 10^{99}", "value_too_large"),
    ("√" * 41 + "x", "too_deep"),  # √ without brackets nests as brackets do
    ("√" * (CAP - 1) + "x", "too_deep"),
    ("x^exp(exp(exp(100)))", "value_too_large"),  # evalf of the exponent never returned
    ("abs(sin(exp(exp(100))))", "value_too_large"),  # nor sympy's evaluation of sin of it
    ("m + exp(exp(exp(100)))", "value_too_large"),  # nor the printer's ordering of the terms
    ("theta/dt", "leibniz"),  # a dt that is no derivative: refused, never read as a quotient
    ("dx/dt^2", "leibniz"),  # the orders of d and dt disagree
    # Lagrange's equation in general form alone was read as the expression 0: no equation of the system
    ("d/dt(∂L/∂θ̇) − ∂L/∂θ = 0", "euler_lagrange_general"),
    ("d/dt(∂L/∂ẋ) − ∂L/∂x = Q", "euler_lagrange_general"),  # a generalized force in general
    ("d/dt(∂L/∂θ) − ∂L/∂θ̇ = 0", "euler_lagrange_other"),  # q and q̇ swapped
    ("d/dt(∂V/∂θ̇) − ∂V/∂θ = 0", "euler_lagrange_other"),
    ("d/dt(∂L/∂ẋ) − ∂L/∂x − ∂F/∂ẋ = 0", "euler_lagrange_other"),  # Rayleigh's term of the wrong sign
    ("d/dt(∂L/∂ẋ) − ∂L/∂x + ∂F/∂θ̇ = 0", "euler_lagrange_other"),  # of another coordinate
    ("d/dt(∂L/∂ẋ) − ∂L/∂x = −∂F/∂ẋ", "euler_lagrange_general"),  # Rayleigh's term on the right
    ("d/dt(∂L/∂ẋ) − ∂L/∂x = ∂F/∂ẋ", "euler_lagrange_other"),  # on the right, of the wrong sign
    # a power on a bare angle was read as sin(θ²); who writes it in a Lagrangian mostly means sin²θ
    ("sin θ^2", "function_argument_power"),
    ("ω^2 sin θ² + 1", "function_argument_power"),
    ("\\sin\\theta^2", "function_argument_power"),
    ("cos 2θ^2", "function_argument_power"),
]


@pytest.mark.parametrize(("text", "code"), FORMERLY_ACCEPTED, ids=[_row_id(t) for t, _ in FORMERLY_ACCEPTED])
def test_formerly_accepted_input_is_refused_with_its_code(text, code):
    with _hang_guard(HANG_SECONDS):
        assert _refusal(text).code == code


# a name of the problem's (or a Greek letter's) that begins with d is no Leibniz numerator: delta/dt is δ over
# dt, refused as any name over dt is; before, read as d(elta)/dt and "elta is not a coordinate of this problem"
NAMES_BEGINNING_WITH_D = [
    # (text, coords, known)
    ("delta/dt", ["delta"], []),
    ("δ/dt", ["delta"], ["m"]),
    ("m delta/dt = 0", ["theta"], ["m"]),
    ("delta/dt", ["x"], ["delta"]),
    ("dm/dt", ["x"], ["dm"]),  # a known symbol's own name
]


@pytest.mark.parametrize(("text", "coords", "known"), NAMES_BEGINNING_WITH_D)
def test_a_name_that_begins_with_d_over_dt_is_no_derivative(text, coords, known):
    refusal = parse_answer(text, coords=coords, known=known)
    assert (refusal.ok, refusal.code) == (False, "leibniz"), refusal
    # the derivative itself, d then the coordinate's name, is read as before
    assert str(parse_answer("ddelta/dt + dδ/dt", coords=["delta"]).value) == "2*Derivative(delta(t), t)"


# -- what the student reads ----------------------------------------------------

SHOWN = [
    # (text, message, pointer)
    ("sin(θ", "Unbalanced bracket: the `(` at position 4 is never closed.", "sin(θ\n   ^"),
    (
        "m g l)",
        "Unbalanced bracket: the `)` at position 6 has no matching opening bracket.",
        "m g l)\n     ^",
    ),
    ("(x]", "The `(` at position 1 is closed by `]` at position 3.", "(x]\n  ^"),
    (
        "x.__class__",
        "`.__class__` looks like attribute access in code; it cannot be part of an answer.",
        "x.__class__\n ^^^^^^^^^^",
    ),
    (
        "x := 1",
        "`:=` is an assignment or a test in code; write an equation with a single `=`.",
        "x := 1\n  ^^",
    ),
    ("m g l # ok", "`#` starts a comment in code; it cannot be part of an answer.", "m g l # ok\n      ^"),
    ("getattr(x, 'a')", "Quotes are not allowed: an answer is mathematics, not text.", "getattr(x, 'a')\n           ^"),
    ("9^9^9^9", "This exponent is too large to handle (the limit is 100).", "9^9^9^9\n   ^"),
    (
        "1234567890" * 4,
        "This number is too large to handle (40 digits; the limit is 30).",
        "1234567890" * 4 + "\n" + "^" * 40,
    ),
    ("\\input{x}", "`\\input` is not a LaTeX command this grader knows.", "\\input{x}\n^^^^^^"),
    (
        "{a \\over b \\over c}",
        "Two `\\over` in one pair of braces can be read more than one way: give each fraction braces of its own,"
        " as in {a \\over b} + {c \\over d}, or write \\frac{a}{b}.",
        "{a \\over b \\over c}\n" + " " * 11 + "^" * 5,
    ),
    (
        "{m g l \\over}",
        "`\\over` divides what stands before it in its braces by what stands after it, as in {m g l \\over 2}:"
        " here one of them is missing.",
        "{m g l \\over}\n" + " " * 7 + "^" * 5,
    ),
    (
        "\\omega = \\sqrt{g/l}\\,\\text{for small angles}",
        "`\\text{for small angles}` is text, not mathematics: leave units and words out of the answer.",
        "\\omega = \\sqrt{g/l}\\,\\text{for small angles}\n" + " " * 21 + "^" * 23,
    ),
    ("m/(l-l)", "This divides by zero.", "m/(l-l)\n ^"),
    ("x" * (CAP + 1), f"Your answer is {CAP + 1} characters long; the limit is {CAP}.", ""),
    ("   ", "Your answer is empty.", ""),
    # A long line is shown as a window around the spot, so the caret stays on screen.
    (
        "m g l + " * 12 + "sin(θ",
        "Unbalanced bracket: the `(` at position 100 is never closed.",
        "… + m g l + m g l + m g l + sin(θ\n                               ^",
    ),
    # names as a student writes them, not as the parser spells them (theta_3)
    (
        "theta3dot",
        "`theta3dot` is written as a time derivative, but θ₃ is not a coordinate of this problem (θ, x).",
        "theta3dot\n^^^^^^^^^",
    ),
    ("$a$ + $", "`$` is not something an answer can contain.", "$a$ + $\n^"),  # unpaired: no TeX math
    # The caret is on the line with the mistake, not on the first line.
    ("x = 1\ny = sin(θ", "Unbalanced bracket: the `(` at position 14 is never closed.", "y = sin(θ\n       ^"),
    # Places as seen: θ̇'s combining dot takes no column, a full-width letter two.
    (
        "½ m l² θ̇² + m g l cos θ)",
        "Unbalanced bracket: the `)` at position 24 has no matching opening bracket.",
        "½ m l² θ̇² + m g l cos θ)\n" + " " * 23 + "^",
    ),
    ("θ̇ θ̇ (x]", "The `(` at position 5 is closed by `]` at position 7.", "θ̇ θ̇ (x]\n      ^"),
    (
        "ｍ ｇ ｌ)",
        "Unbalanced bracket: the `)` at position 6 has no matching opening bracket.",
        "ｍ ｇ ｌ)\n" + " " * 8 + "^",
    ),
    # A Cyrillic or Greek letter drawn as a Latin one is named: the student cannot see it.
    (
        "m g l c\u043es θ",
        "`\u043e` looks like the letter `o` but is the Cyrillic small letter o: type it again as a plain `o`.",
        "m g l c\u043es θ\n       ^",
    ),
    (
        "m g l c\u03bfs θ",  # Greek omicron, which was read as a name of its own: c·ο·s
        "`\u03bf` looks like the letter `o` but is the Greek small letter omicron: type it again as a plain `o`.",
        "m g l c\u03bfs θ\n       ^",
    ),
    (
        "\u0410 + x",
        "`\u0410` looks like the letter `A` but is the Cyrillic capital letter a: type it again as a plain `A`.",
        "\u0410 + x\n^",
    ),
    # a word all in another script is no slip of the keyboard: refused as before, where it begins
    (
        "2 \u0441\u0442\u0435\u043f\u0435\u043d\u0438",
        "`\u0441` is not something an answer can contain.",
        "2 \u0441\u0442\u0435\u043f\u0435\u043d\u0438\n  ^",
    ),
    (
        "m R^2 ω^2 sin θ^2",
        "A power after `sin θ` can be read two ways: write sin^2 θ for a power of sin θ, or sin(θ^2) to take the"
        " power inside.",
        "m R^2 ω^2 sin θ^2\n" + " " * 14 + "^^",
    ),
    (
        "θ̈ = -g/l θ (θ -> 0)",
        "`->` is read only between two equations, as a step of a derivation (`a = b -> c = d` is read as"
        " c = d); a limit such as θ → 0 cannot be part of an answer.",
        "θ̈ = -g/l θ (θ -> 0)\n" + " " * 14 + "^^",
    ),
    (
        "H = \\sum_i p_i \\dot q_i - L",
        "`\\sum` is read only in a definition on the way to the answer, as in H = \\sum_j p_j \\dot q_j - L = …,"
        " whose last side is graded; anywhere else, write the sum out term by term.",
        "H = \\sum_i p_i \\dot q_i - L\n    ^^^^",
    ),
    (
        "d/dt(∂L/∂ẋ) − ∂L/∂x + ∂F/∂ẋ = 0",
        "This is Lagrange's equation in general form, which holds for every system: work it out for this one,"
        " with its `L` and `F` put in, and give the equation of motion it comes to.",
        "d/dt(∂L/∂ẋ) − ∂L/∂x + ∂F/∂ẋ = 0\n" + "^" * 31,
    ),
    (
        "\\frac{d}{dt}\\frac{\\partial L}{\\partial \\dot x} - \\frac{\\partial L}{\\partial x} = 0",
        "This is Lagrange's equation in general form, which holds for every system: work it out for this one,"
        " with its `L` put in, and give the equation of motion it comes to.",
        "\\frac{d}{dt}\\frac{\\partial L}{\\partial \\dot x} - \\frac{\\part…\n" + "^" * 60,
    ),
    (
        "d/dt(∂V/∂θ̇) − ∂V/∂θ = 0",
        "This is not Lagrange's equation, d/dt(∂L/∂q̇) − ∂L/∂q = 0, nor an equation of motion of this system:"
        " give the equation of motion, worked out for this system.",
        "d/dt(∂V/∂θ̇) − ∂V/∂θ = 0\n" + "^" * 23,
    ),
    (
        "H = \\sum p \\dot q - L = \\sum p \\dot q",  # the sum left in, not the one passed over
        "`\\sum` is read only in a definition on the way to the answer, as in H = \\sum_j p_j \\dot q_j - L = …,"
        " whose last side is graded; anywhere else, write the sum out term by term.",
        "H = \\sum p \\dot q - L = \\sum p \\dot q\n" + " " * 24 + "^^^^",
    ),
]


@pytest.mark.parametrize(("text", "message", "pointer"), SHOWN, ids=[_row_id(text) for text, _, _ in SHOWN])
def test_refusal_is_shown_exactly(text, message, pointer):
    refusal = _refusal(text)
    assert refusal.message == message
    assert refusal.pointer == pointer
    assert str(refusal) == (f"{message}\n{pointer}" if pointer else message)


NOT_TEXT = [None, b"sin(x)", bytearray(b"x"), 1, 1.5, ["x"], object()]


@pytest.mark.parametrize("value", NOT_TEXT, ids=[type(value).__name__ for value in NOT_TEXT])
def test_non_text_input_is_refused(value):
    refusal = _refusal(value)
    assert refusal.code == "unreadable"
    assert refusal.message == "This answer could not be read as mathematics."


@pytest.mark.parametrize(("text", "code"), HOSTILE, ids=[_row_id(text) for text, _ in HOSTILE])
def test_refusal_renders_as_text(text, code):
    refusal = _refusal(text)
    rendered = str(refusal)
    assert refusal.message and rendered.startswith(refusal.message)
    if refusal.start is not None:
        assert 0 <= refusal.start <= len(text) and refusal.end >= refusal.start
        assert "^" in refusal.pointer.splitlines()[-1]


# -- large but allowed: accepted, and can still be shown back ---------------------

LARGE_BUT_ALLOWED = [
    "+".join(["x"] * (CAP // 2)),
    _nested("(", ")", 40),
    "x" + "^x" * 8,  # LIMITS.powers
    "-" * 40 + "x",
    _nested("sin(", ")", 20),  # a call is two levels: the function and its bracket
    "a" * 40,
    " ".join(["theta'"] * 285),
    "+".join(["\\frac{1}{2} m l^2 \\dot{\\theta}^2"] * 60),
    "\n".join(["x'' = -g/l sin θ"] * 110),
    "*".join(["9^99"] * 4),  # 380 digits: within the 400-digit cap, and printable
]


@pytest.mark.parametrize(
    "text", LARGE_BUT_ALLOWED, ids=[_row_id(getattr(row, "values", [row])[0]) for row in LARGE_BUT_ALLOWED]
)
def test_large_answer_is_accepted_and_read_back(text):
    assert len(text) <= CAP
    answer = parse_answer(text, coords=COORDS, known=KNOWN)
    assert answer.ok, str(answer)
    for shown in (answer.read_as_text, answer.read_as_latex, answer.read_as_mathml):
        assert isinstance(shown, str) and shown


# -- hang guard ----------------------------------------------------------------
# Inputs under 1000 characters once did not come back: sympy was asked to evaluate
# e^(e^(e^100)) to 15 digits, or to expand a third derivative of a product of many
# factors. The guard is not a speed test: it allows thousands of times what a parse
# takes and only turns "never returns" into a failure.

HANG_SECONDS = 3


class _Hung(Exception):
    pass


@contextmanager
def _hang_guard(seconds: float):
    if not hasattr(signal, "setitimer"):
        pytest.skip("needs POSIX interval timers")

    def interrupt(signum, frame):
        raise _Hung(f"did not return within {seconds} s")

    previous = signal.signal(signal.SIGALRM, interrupt)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)


_DIFF_OF_PRODUCT = "diff(" + "*".join(f"sin({i}theta)" for i in range(1, 60)) + ", t, 3)"


def test_high_derivative_of_a_long_product_is_refused_quickly():
    with _hang_guard(HANG_SECONDS):
        assert _refusal(_DIFF_OF_PRODUCT).code == "diff_too_large"


def test_a_deadline_stops_reading_between_factors():
    # No signal can interrupt sympy outside the main thread: the parser checks between factors.
    slow = "*".join([f"(theta'''-(m^-{n})^(1/7))^(abs(g g)/(l+theta''))" for n in range(93, 101)])
    clear_cache()  # or sympy remembers the factors from an earlier test, and reading is quick
    with pytest.raises(CheckTimeout):
        parse_answer(slow, coords=["theta"], known=["m", "g", "l"], deadline=Deadline(0.01))


def test_a_derivative_whose_result_grows_as_the_square_is_refused():
    product = "".join(f"(θ+{i})" for i in range(1, 40))  # d/dt gives 39 terms of 39 factors
    refusal = parse_answer(f"d/dt({product})", coords=["theta"])
    assert refusal.code == "diff_too_large"
    assert parse_answer("d/dt(1/2 m l^2 thetadot^2 - m g l cos(theta))", coords=["theta"], known=["m", "g", "l"]).ok
