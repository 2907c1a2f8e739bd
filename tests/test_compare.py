"""compare: its contract, each kind's rules, and the feedback students read.

The physics tables (40+ pairs per kind) are in test_compare_pairs.py; here are
the API, the options, the exact feedback sentences, and hostile answers.
"""

from __future__ import annotations

import dataclasses
import importlib
import re
from types import SimpleNamespace

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from sympy.core.cache import clear_cache

from grader import KINDS, AuthorError, ReferenceAnswerError, Verdict, compare, parse_answer
from grader.judge import words
from grader.judge.euler_lagrange import euler_lagrange
from grader.judge.expected import prepare
from grader.judge.lagrangian import equations_of_motion

PENDULUM = {"coords": ["theta"], "known": ["m", "g", "l"]}
L_PENDULUM = "1/2 m l^2 thetadot^2 + m g l cos(theta)"
EOM_PENDULUM = "m l^2 thetaddot + m g l sin(theta) = 0"
DOUBLE = {"coords": ["theta1", "theta2"], "known": ["m1", "m2", "l1", "l2", "g"]}
EOM_DOUBLE_1 = (
    "(m1+m2) l1 theta1ddot + m2 l2 theta2ddot cos(theta1-theta2) + m2 l2 theta2dot^2 sin(theta1-theta2)"
    " + (m1+m2) g sin(theta1) = 0"
)
EOM_DOUBLE_2 = (
    "l2 theta2ddot + l1 theta1ddot cos(theta1-theta2) - l1 theta1dot^2 sin(theta1-theta2) + g sin(theta2) = 0"
)
EOM_DOUBLE = f"{EOM_DOUBLE_1}; {EOM_DOUBLE_2}"


_SHORT_DOUBLE = (
    "(m1 + m2) l1 th1dd + m2 l2 th2dd cos(th1 - th2) + m2 l2 th2d^2 sin(th1 - th2) + (m1 + m2) g sin(th1) = 0;"
    " l2 th2dd + l1 th1dd cos(th1 - th2) - l1 th1d^2 sin(th1 - th2) + g sin(th2) = 0"
)
SHORT_RATES = [
    # (submitted, status, feedback): th1dd, th2d for θ̈₁, θ̇₂, as th1ddot is read (before, undefined)
    (_SHORT_DOUBLE, "equivalent", ("Correct.",)),
    (_SHORT_DOUBLE.replace("- l1 th1d^2", "+ l1 th1d^2"), "not_equivalent",
     ("Your equation for θ₂ is not right; equation 1 is right.",
      "A term differs: the velocity-dependent term in sin(θ₁ − θ₂) has the wrong sign.")),
]  # fmt: skip


@pytest.mark.parametrize(("submitted", "status", "feedback"), SHORT_RATES)
def test_rates_glued_on_a_stand_in_as_d_or_dd_are_read(submitted, status, feedback):
    verdict = compare(EOM_DOUBLE, submitted, kind="equations", **DOUBLE)
    assert (verdict.status, verdict.feedback) == (status, feedback), verdict


STAND_IN_ON_THE_LEFT = [
    # (submitted, status, feedback): th for θ alone before `=`, as on the right side (before, a name of the
    # student's own that the problem does not define)
    ("thdd = -g/l sin(th)", "equivalent", ("Correct.",)),
    ("thddot = -(g/l) sin th", "equivalent", ("Correct.",)),
    ("th_dd = -g/l sin(th)", "equivalent", ("Correct.",)),
    ("thdd = g/l sin(th)", "not_equivalent", ("A term differs: the term in sin(θ) has the wrong sign.",)),
]


@pytest.mark.parametrize(("submitted", "status", "feedback"), STAND_IN_ON_THE_LEFT)
def test_a_stand_in_for_an_angles_rate_reads_the_same_on_the_left(submitted, status, feedback):
    verdict = compare("thetaddot = -g/l sin(theta)", submitted, kind="equation", **PENDULUM)
    assert (verdict.status, verdict.feedback) == (status, feedback), verdict


def test_verdict_is_a_frozen_dataclass_with_the_documented_fields():
    verdict = compare("2 m", "m + m", known=["m"])
    assert dataclasses.is_dataclass(verdict)
    with pytest.raises(dataclasses.FrozenInstanceError):
        verdict.score = 0  # type: ignore[misc]
    assert (verdict.status, verdict.equivalent, verdict.score) == ("equivalent", True, 1.0)
    assert verdict.feedback == ("Correct.",)
    assert verdict.read_as == "2*m"
    assert verdict.method == "numeric"


def test_every_kind_has_a_checker_and_options():
    assert set(KINDS) == {"expression", "equation", "equations", "lagrangian", "integer", "number", "choice", "text"}
    for kind in KINDS.values():
        assert callable(kind.check)


def test_a_malformed_submission_is_invalid_with_the_parsers_message():
    verdict = compare("sin(theta)", "sin(θ", **PENDULUM)
    assert verdict.status == "invalid"
    assert verdict.feedback == ("Unbalanced bracket: the `(` at position 4 is never closed.",)
    assert verdict.read_as == "sin(θ\n   ^"


def test_a_malformed_expected_answer_raises_for_the_author():
    with pytest.raises(ReferenceAnswerError, match="The expected answer 'sin\\(theta' cannot be read"):
        compare("sin(theta", "sin(theta)", **PENDULUM)


@pytest.mark.parametrize(
    ("expected", "message"),
    [
        ("x +", "The expected answer 'x +' cannot be read: it ends too early: something is missing after `+`."),
        ("", "The expected answer '' cannot be read: it is empty."),
        ("log(0)", "The expected answer 'log(0)' cannot be read: it contains a value that is undefined"),
    ],
)
def test_a_malformed_expected_answer_is_described_to_its_author_not_to_a_student(expected, message):
    with pytest.raises(ReferenceAnswerError) as raised:
        compare(expected, "x")
    assert str(raised.value).startswith(message)
    assert "your answer" not in str(raised.value).lower()


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (lambda: compare("x", "x", kind="vector"), "unknown answer kind 'vector'"),
        (lambda: compare("x", "x", rtol=0.1), "option rtol does not apply to kind 'expression'"),
        (lambda: compare("x", "x", domains={"x": "complex"}), "domain of 'x' is 'complex'"),
        (lambda: compare("x", "x", timeout=-1), "timeout must be a positive number of seconds, not -1"),
        (lambda: compare("2", "2", kind="number", known=["l"], values={"g": 9.81}), "option values names 'g'"),
        (lambda: compare("2", "2", kind="number", known=["l"], values={"l": "1 m"}), "gives 'l' the value '1 m'"),
        (lambda: compare("2", "2", kind="number", values=[1.0]), "option values maps the problem's names"),
        (lambda: compare("x", "x", timeout=float("nan")), "timeout must be a positive number of seconds"),
        (
            lambda: compare("x = 1", "x", kind="expression"),
            "of kind 'expression' must be an expression, not an equation",
        ),
        (
            lambda: compare("x'' = 1; y'' = 2", "x", kind="lagrangian", coords=["x", "y"]),
            "of kind 'lagrangian' must be an expression, not a system of equations",
        ),
    ],
)
def test_author_mistakes_in_the_call_raise_author_error(call, message):
    with pytest.raises(AuthorError, match=message):
        call()


@pytest.mark.parametrize(
    ("submitted", "name"),
    [
        ("1/2 m r^2 thetadot^2 + m g l cos(theta)", "r"),
        # glued to the problem's names before a bracket, the letter it lacks: before, `mgL` was told as
        # a function we do not know
        ("1/2 m l^2 θ̇^2 - mgL(1-cosθ)", "L"),
        ("1/2 m l^2 θ̇^2 + Lmg (cos θ)", "Lmg"),  # apart from its bracket: a name of its own, as always
        # a Greek letter glued after a letter is shown as typed: before, as `itheta`
        ("1/2 m l^2 θ̇^2 + m g l cos θ e^(iθ)", "iθ"),
        ("1/2 m l^2 θ̇^2 + m g l cos θ + xω₀", "xω₀"),
    ],
)
def test_symbols_the_problem_does_not_define_are_named(submitted, name):
    verdict = compare(L_PENDULUM, submitted, kind="lagrangian", **PENDULUM)
    assert verdict.status == "not_equivalent"
    assert verdict.feedback == (
        f"Your answer uses `{name}`, which this problem does not define (it uses g, l, m, θ)."
        f" Write your answer in those, or say what it stands for: …, where {name} = ….",
    )
    assert verdict.diagnosis == "undefined_symbol"


def test_by_default_parameters_are_positive_and_coordinates_real():
    assert compare("l", "sqrt(l^2)", known=["l"]).status == "equivalent"
    assert compare("theta", "sqrt(theta^2)", coords=["theta"]).status == "not_equivalent"
    assert compare("x", "sqrt(x^2)", known=["x"], domains={"x": "real"}).status == "not_equivalent"


# Answers right only for some signs of parameters an author declared real (a charge, a
# displacement). The problem's other names shift the seeded draws: every setting must catch them.
SIGN_BLIND = [
    ("expression", "a", "sqrt(a^2)", ["a"]),
    ("expression", "a*b", "sqrt(a^2 b^2)", ["a", "b"]),
    ("expression", "-a*b", "sqrt(a^2 b^2)", ["a", "b"]),
    ("expression", "a*b*c", "sqrt(a^2) b c", ["a", "b", "c"]),
    ("lagrangian", "1/2 m thetadot^2 - a*b*cos(theta)", "1/2 m thetadot^2 + sqrt(a^2 b^2) cos(theta)", ["a", "b"]),
    ("equation", "m thetaddot - a*b*sin(theta) = 0", "m thetaddot + sqrt(a^2 b^2) sin(theta) = 0", ["a", "b"]),
    ("equation", "m thetaddot = a*b*sin(theta)", "m thetaddot = sqrt(a^2 b^2) sin(theta)", ["a", "b"]),
]


@pytest.mark.parametrize("kind, expected, submitted, signed", SIGN_BLIND)
def test_real_parameters_take_both_signs_and_every_pair_of_signs(kind, expected, submitted, signed):
    for others in range(8):
        known = ["m", *signed, *(f"k{i}" for i in range(others))]
        verdict = compare(
            expected, submitted, kind=kind, coords=["theta"], known=known, domains=dict.fromkeys(signed, "real")
        )
        assert verdict.status == "not_equivalent", (others, verdict)


def test_an_answer_right_for_one_sign_of_a_parameter_is_told_so():
    verdict = compare("a x", "sqrt(a^2) x", coords=["x"], known=["a"], domains={"a": "real"})
    assert (verdict.status, verdict.diagnosis) == ("not_equivalent", "some_signs")
    assert verdict.feedback == (
        "Your answer is right only for some signs of a, which may be negative here: remember that √(x²) is |x|, not x.",
    )
    # wrong in every draw, it is no question of signs
    assert compare("a x", "a x + 1", coords=["x"], known=["a"], domains={"a": "real"}).diagnosis != "some_signs"


@pytest.mark.parametrize(
    "kind, expected, submitted",
    [
        ("expression", "-a*b", "-sqrt(a^2) b a/abs(a)"),
        ("expression", "abs(a b)", "sqrt(a^2 b^2)"),
        ("lagrangian", "1/2 m thetadot^2 - a*b*cos(theta)", "1/2 m thetadot^2 - b a cos(theta) + a b c"),
        ("equation", "m thetaddot - a*b*sin(theta) = 0", "thetaddot = a b sin(theta) / m"),
    ],
)
def test_real_parameters_keep_right_answers_right(kind, expected, submitted):
    for others in range(4):
        known = ["m", "a", "b", "c", *(f"k{i}" for i in range(others))]
        verdict = compare(
            expected, submitted, kind=kind, coords=["theta"], known=known, domains=dict.fromkeys("abc", "real")
        )
        assert verdict.status == "equivalent", (others, verdict)


FEEDBACK = [
    # (expected, submitted, kind, setting, diagnosis, feedback sentence)
    ("1/2 m l^2 thetadot^2", "m l^2 thetadot^2", "expression", PENDULUM, "factor",
     "Your answer is off by a constant factor: missing a factor 1/2?"),
    ("1/2 m l^2 thetadot^2", "-1/2 m l^2 θ̇^2", "expression", PENDULUM, "sign", "The overall sign is wrong."),
    ("sqrt(g/l)", "2 π √(g/l)", "expression", PENDULUM, "factor",
     "Your answer is off by a constant factor: missing a factor 1/(2π)?"),  # ω for a frequency, the other way
    ("sqrt(g/l)", "√(g/l)/π", "expression", PENDULUM, "factor",
     "Your answer is off by a constant factor: missing a factor π?"),
    (L_PENDULUM, "1/2 m l^2 θ̇^2 - m g l cos θ", "lagrangian", PENDULUM, "t_plus_v",
     "It looks like you wrote L = T + V; the Lagrangian is L = T − V."),
    (L_PENDULUM, "m l^2 θ̇^2 + 2 m g l cos θ", "lagrangian", PENDULUM, "normalization",
     "Your Lagrangian gives the right equations of motion, but it is 2 × (T − V); "
     "the convention L = T − V fixes the normalization."),
    (L_PENDULUM, "-1/2 m l^2 θ̇^2 - m g l cos θ", "lagrangian", PENDULUM, "v_minus_t",
     "Your Lagrangian has the opposite sign: it is V − T; the Lagrangian is L = T − V."),
    (L_PENDULUM, "1/2 m l^2 θ̇^2", "lagrangian", PENDULUM, "missing_term", "A term is missing: a term in cos(θ)."),
    (L_PENDULUM, "1/2 m l^2 θ̇^2 - 1/2 m g l θ^2", "lagrangian", PENDULUM, "small_angle",
     "You used the small-angle approximation, but the full answer is asked for here."),
    (EOM_PENDULUM, "θ̈ = -(g/l) θ", "equation", PENDULUM, "small_angle",
     "You used the small-angle approximation, but the full answer is asked for here."),
    (EOM_PENDULUM, "θ̈ = (g/l) sin θ", "equation", PENDULUM, "term_differs",
     "A term differs: the term in sin(θ) has the wrong sign."),
    # θ̈₁'s coefficient holds cos(θ₁ − θ₂): solved for θ̈₂ instead, each term stays as the student wrote it
    (EOM_DOUBLE_2, EOM_DOUBLE_2.replace("- l1", "+ l1"), "equation", DOUBLE, "term_differs",
     "A term differs: the velocity-dependent term in sin(θ₁ − θ₂) has the wrong sign."),
    # Newton's equations for the bob, with the string's tension T still in them
    (EOM_PENDULUM, "m l θ̈ = −m g sin θ; 0 = T − m g cos θ − m l θ̇²", "equation", PENDULUM, "eliminate_unknowns",
     "One equation is asked for here; your answer has 2, with `T`, which this problem does not define."
     " Eliminate it between your equations, to leave one in the problem's own names."),
    (EOM_PENDULUM, "m l^2 θ̈ + m g l sin θ", "equation", PENDULUM, "expected_equation",
     "An equation (with `=`) is asked for here, but your answer is an expression."),
    # a quantity where its equation of motion is asked: not "`L` is not defined"
    (EOM_PENDULUM, L_PENDULUM.join(["L = ", ""]), "equation", PENDULUM, "quantity_for_motion",
     "Your answer gives a Lagrangian, `L = …`, where an equation of motion is asked for: write the equation itself."),
    (EOM_PENDULUM, "H = p_theta^2/(2 m l^2) - m g l cos θ", "equation", PENDULUM, "quantity_for_motion",
     "Your answer gives a Hamiltonian, `H = …`, where an equation of motion is asked for: write the equation"
     " itself."),
    (EOM_DOUBLE, "T = 1/2 (m1 + m2) l1^2 θ̇₁² + 1/2 m2 l2^2 θ̇₂²", "equations", DOUBLE, "quantity_for_motion",
     "Your answer gives a kinetic energy, `T = …`, where the equations of motion are asked for: write the"
     " equations themselves."),
    # T without a velocity is no kinetic energy (a tension, a torque), nor V with one a potential energy
    (EOM_PENDULUM, "T = m g cos θ", "equation", PENDULUM, "undefined_symbol",
     "Your answer uses `T`, which this problem does not define (it uses g, l, m, θ). Write your answer in those,"
     " or say what it stands for: …, where T = …."),
    (EOM_PENDULUM, "V = 1/2 m l^2 θ̇²", "equation", PENDULUM, "undefined_symbol",
     "Your answer uses `V`, which this problem does not define (it uses g, l, m, θ). Write your answer in those,"
     " or say what it stands for: …, where V = …."),
    # with an acceleration, L is a label the student gave an equation's side, and undefined
    (EOM_PENDULUM, "L = m l^2 θ̈ + m g l sin θ", "equation", PENDULUM, "undefined_symbol",
     "Your answer uses `L`, which this problem does not define (it uses g, l, m, θ). Write your answer in those,"
     " or say what it stands for: …, where L = …."),
    (EOM_PENDULUM, "L = r^2 θ̇²", "equation", PENDULUM, "undefined_symbol",
     "Your answer uses `L` and `r`, which this problem does not define (it uses g, l, m, θ). Write your answer in"
     " those, or say what each stands for: …, where L = …."),
    ("sqrt(g/l)", "omega = sqrt(g/l) = 1", "expression", PENDULUM, None, None),
    (EOM_DOUBLE, EOM_DOUBLE_1, "equations", DOUBLE, "expected_system",
     "A system of 2 equations is asked for here (one per coordinate: θ₁, θ₂)."),
    (EOM_DOUBLE, f"{EOM_DOUBLE_1}; {EOM_DOUBLE_2.replace('+ g', '- g')}", "equations", DOUBLE, "wrong_equation",
     "Your equation for θ₂ is not right; equation 1 is right."),
    (EOM_DOUBLE, f"{EOM_DOUBLE_1}; {EOM_DOUBLE_1}", "equations", DOUBLE, "dependent_equations",
     "Your equations are not independent: they do not determine every acceleration."),
    (EOM_DOUBLE, f"{EOM_DOUBLE_1}; {EOM_DOUBLE_2}; theta1 = 0", "equations", DOUBLE, "extra_equation",
     "You gave 3 equations; this system needs exactly 2, one per coordinate."),
    # an equation that says nothing, as a third: that it is empty is the mistake, not the count
    (EOM_DOUBLE, f"{EOM_DOUBLE_1}; 0 = 0; {EOM_DOUBLE_2}", "equations", DOUBLE, "trivial_extra_equation",
     "Equation 2 holds for every motion, so it says nothing about this one: leave it out. This system needs"
     " exactly 2 equations, one per coordinate."),
]  # fmt: skip


@pytest.mark.parametrize(
    ("submitted", "status", "feedback"),
    [
        ("L = ½m(lθ̇)² + m g l cos θ = ½ml²θ̇² + m g l cos θ", "equivalent",
         ("Correct.", "Your answer has 2 sides after the name, each the same; the last was graded.")),
        ("L(θ, θ̇) = T − V = ½m(lθ̇)² + m g l cos θ = ½ml²θ̇² + m g l cos θ", "equivalent",
         ("Correct.", "Your answer has 3 sides after the name, each the same; the last was graded.")),
        ("L = ½m(lθ̇)² − m g l cos θ = ½ml²θ̇² + m g l cos θ", "undecided",
         ("Your last side is right, but side 1 does not say the same: a person will decide which is your answer.",)),
        ("L = ½m(lθ̇)² + m g l cos θ = ½ml²θ̇² − m g l cos θ", "not_equivalent",
         ("It looks like you wrote L = T + V; the Lagrangian is L = T − V.",
          "Your answer has 2 sides after the name; the last was graded as your answer.")),
        # no name first: an equation with two `=`, refused as before
        ("½m(lθ̇)² + m g l cos θ = ½ml²θ̇² + m g l cos θ = 3", "invalid",
         ("An equation has one `=`; this one has more.",)),
    ],
)  # fmt: skip
def test_a_chain_of_equal_sides_after_the_name_is_graded_by_its_last(submitted, status, feedback):
    verdict = compare(L_PENDULUM, submitted, kind="lagrangian", **PENDULUM)
    assert (verdict.status, verdict.feedback) == (status, feedback)


def test_a_formula_then_its_value_is_not_graded_by_the_value():
    verdict = compare("sqrt(g/l)", "ω = √(g/l) = 3.13", kind="expression", **PENDULUM)
    assert verdict.status == "invalid"


@pytest.mark.parametrize(
    ("expected", "submitted", "kind", "status", "score", "feedback"),
    [
        # working on paper, then the tidier form: each line the same equation
        (EOM_PENDULUM, "m l² θ̈ = −m g l sin θ\nθ̈ = −(g/l) sin θ", "equation", "equivalent", 1,
         ("Correct.", "Your answer has 2 lines, each the same; the last was graded.")),
        (EOM_PENDULUM, "m l² θ̈ = −m g l sin θ; θ̈ = −(g/l) sin θ", "equation", "equivalent", 1,
         ("Correct.", "Your answer has 2 lines, each the same; the last was graded.")),
        # a slip on the way, put right by the end: which is the answer, a person says
        (EOM_PENDULUM, "m l² θ̈ = m g l sin θ\nθ̈ = g/l sin θ\nθ̈ = −(g/l) sin θ", "equation", "undecided", 1,
         ("Your last line is right, but lines 1, 2 do not say the same: a person will decide which is your"
          " answer.",)),
        # right, then spoiled: the last line is the answer, and its mistake is named
        (EOM_PENDULUM, "m l² θ̈ = −m g l sin θ\nθ̈ = (g/l) sin θ", "equation", "not_equivalent", 0,
         ("A term differs: the term in sin(θ) has the wrong sign.",
          "Your answer has 2 lines; the last was graded as your answer.")),
        # the Lagrangian written twice; was read as the equation X = X
        (L_PENDULUM, f"L = {L_PENDULUM}\nL = {L_PENDULUM}", "lagrangian", "equivalent", 1,
         ("Correct.", "Your answer has 2 lines, each the same; the last was graded.")),
        (L_PENDULUM, f"L = 1/2 m l^2 θ̇^2 - m g l cos θ\nL = {L_PENDULUM}", "lagrangian", "undecided", 1,
         ("Your last line is right, but line 1 does not say the same: a person will decide which is your answer.",)),
        # a name of the student's own on the way, none in the last line: before, wrong, "eliminate ω"
        (EOM_PENDULUM, "θ̈ = −ω² sin θ\nθ̈ = −(g/l) sin θ", "equation", "undecided", 1,
         ("Your last line is right, but line 1 does not say the same: a person will decide which is your answer.",)),
        # and where the last line is wrong, the hint to eliminate ω stays
        (EOM_PENDULUM, "θ̈ = −ω² sin θ\nθ̈ = (g/l) sin θ", "equation", "not_equivalent", 0,
         ("One equation is asked for here; your answer has 2, with `ω`, which this problem does not define."
          " Eliminate it between your equations, to leave one in the problem's own names.",)),
    ],
)  # fmt: skip
def test_one_equation_written_on_several_lines_is_graded_by_its_last(
    expected, submitted, kind, status, score, feedback
):
    verdict = compare(expected, submitted, kind=kind, **PENDULUM)
    assert (verdict.status, verdict.score, verdict.feedback) == (status, score, feedback)


DRY_FRICTION = "m xddot + b xdot + k x + mu m g sign(xdot) = 0"
FRICTION = {"coords": ["x"], "known": ["m", "b", "k", "mu", "g"]}


@pytest.mark.parametrize(
    ("expected", "submitted", "kind", "status", "sentence"),
    [
        (DRY_FRICTION, "xddot = -(b/m) xdot - (k/m) x - mu g sgn(xdot)", "equation", "equivalent", "Correct."),
        (DRY_FRICTION, "m xddot + b xdot + k x - mu m g sgn(xdot) = 0", "equation", "not_equivalent",
         "A term differs: the velocity-dependent term has the wrong sign."),
        (DRY_FRICTION, "m xddot + b xdot + k x = 0", "equation", "not_equivalent",
         "A term is missing: a velocity-dependent term."),
        # a V-shaped well: its force −k sign(x) has no small-oscillation form to compare with
        ("1/2 m xdot^2 - k abs(x)", "1/2 m xdot^2 - k x sign(x)", "lagrangian", "equivalent",
         "Correct."),
        ("1/2 m xdot^2 - k abs(x)", "1/2 m xdot^2 + k abs(x)", "lagrangian", "not_equivalent",
         "It looks like you wrote L = T + V; the Lagrangian is L = T − V."),
        ("1/2 m xdot^2 - k abs(x)", "1/2 m xdot^2 - k x", "lagrangian", "not_equivalent",
         "A term differs: a term in x is not right."),
    ],
)  # fmt: skip
def test_sign_of_a_velocity_or_a_coordinate_is_judged_though_it_has_no_derivative_at_rest(
    expected, submitted, kind, status, sentence
):
    verdict = compare(expected, submitted, kind=kind, **FRICTION)
    assert (verdict.status, verdict.feedback[0]) == (status, sentence)


@pytest.mark.parametrize(("expected", "submitted", "kind", "setting", "diagnosis", "sentence"), FEEDBACK)
def test_feedback_names_the_mistake(expected, submitted, kind, setting, diagnosis, sentence):
    verdict = compare(expected, submitted, kind=kind, **setting)
    if diagnosis is None:  # a malformed answer: the parser speaks
        assert verdict.status == "invalid"
        return
    assert verdict.status == "not_equivalent"
    assert verdict.diagnosis == diagnosis
    assert verdict.feedback[0] == sentence


@pytest.mark.parametrize(
    ("submitted", "feedback"),
    [
        (f"{EOM_DOUBLE_1}; {EOM_DOUBLE_2.replace('- l1', '+ l1')}",
         ("Your equation for θ₂ is not right; equation 1 is right.",
          "A term differs: the velocity-dependent term in sin(θ₁ − θ₂) has the wrong sign.")),
        # the equations in the other order: the wrong one is named against the equation it is nearest
        (f"{EOM_DOUBLE_2}; {EOM_DOUBLE_1.replace(' + (m1+m2) g sin(theta1)', '')}",
         ("Your equation for θ₁ is not right; equation 1 is right.", "A term is missing: a term in sin(θ₁).")),
        # g and l's swapped everywhere in one equation: too many terms differ to name them
        (f"{EOM_DOUBLE_1}; l1 theta2ddot + l2 theta1ddot cos(theta1-theta2) - l2 theta1dot^2 sin(theta1-theta2)"
         " + g sin(theta1) = 0",
         ("Your equation for θ₂ is not right; equation 1 is right.",)),
    ],
)  # fmt: skip
def test_the_wrong_equation_of_a_system_has_its_terms_named(submitted, feedback):
    verdict = compare(EOM_DOUBLE, submitted, kind="equations", **DOUBLE)
    assert (verdict.status, verdict.diagnosis) == ("not_equivalent", "wrong_equation")
    assert verdict.feedback == feedback


# the double pendulum solved for each acceleration (θ̈₁ = …, θ̈₂ = …): derived from EOM_DOUBLE by Cramer's rule
SOLVED_1 = (
    "theta1ddot = (-g (2 m1 + m2) sin(theta1) - m2 g sin(theta1 - 2 theta2) - 2 sin(theta1 - theta2) m2"
    " (theta2dot^2 l2 + theta1dot^2 l1 cos(theta1 - theta2))) / (l1 (2 m1 + m2 - m2 cos(2 theta1 - 2 theta2)))"
)
SOLVED_2 = (
    "theta2ddot = (2 sin(theta1 - theta2) (theta1dot^2 l1 (m1 + m2) + g (m1 + m2) cos(theta1)"
    " + theta2dot^2 l2 m2 cos(theta1 - theta2))) / (l2 (2 m1 + m2 - m2 cos(2 theta1 - 2 theta2)))"
)


@pytest.mark.parametrize(
    ("submitted", "first"),
    [
        (f"{SOLVED_1}; {SOLVED_2}", None),
        (f"{SOLVED_2}; {SOLVED_1}", None),
        # the coordinate whose acceleration the right equation fixes is not the one said to be wrong
        (f"{SOLVED_1}; {SOLVED_2.replace('+ g (m1 + m2)', '- g (m1 + m2)')}",
         "Your equation for θ₂ is not right; equation 1 is right."),
        (f"{SOLVED_1.replace('- m2 g sin', '+ m2 g sin')}; {SOLVED_2}",
         "Your equation for θ₁ is not right; equation 2 is right."),
        (f"{SOLVED_2.replace('+ g (m1 + m2)', '- g (m1 + m2)')}; {SOLVED_1}",
         "Your equation for θ₂ is not right; equation 2 is right."),
        # an Euler–Lagrange equation holds both accelerations: the θ₁ one right says nothing of θ̈₁ alone
        (f"{EOM_DOUBLE_1}; {SOLVED_2.replace('+ g (m1 + m2)', '- g (m1 + m2)')}",
         "Your equation for θ₂ is not right; equation 1 is right."),
    ],
)  # fmt: skip
def test_a_system_solved_for_its_accelerations_names_the_wrong_ones_coordinate(submitted, first):
    verdict = compare(EOM_DOUBLE, submitted, kind="equations", **DOUBLE)
    if first is None:
        assert verdict.status == "equivalent", verdict
    else:
        assert (verdict.status, verdict.feedback[0]) == ("not_equivalent", first), verdict


def test_a_wrong_equation_is_named_against_equations_derived_from_a_lagrangian():
    # derived, the θ₁ equation has (m₁ + m₂) l₁² θ̈₁ multiplied out into two terms; the student's
    # (m₁ + m₂) l₁ θ̈₁ has one l₁ less: both are solved for θ̈₁ alike, and their terms agree
    lagrangian = (
        "1/2 (m1+m2) l1^2 theta1dot^2 + 1/2 m2 l2^2 theta2dot^2 + m2 l1 l2 theta1dot theta2dot cos(theta1-theta2)"
        " + (m1+m2) g l1 cos(theta1) + m2 g l2 cos(theta2)"
    )
    derived = equations_of_motion(lagrangian, coords=DOUBLE["coords"], known=DOUBLE["known"])
    submitted = f"{EOM_DOUBLE_1.replace(' + (m1+m2) g sin(theta1)', '')}; {EOM_DOUBLE_2}"
    verdict = compare(derived, submitted, kind="equations", **DOUBLE)
    assert verdict.feedback == (
        "Your equation for θ₁ is not right; equation 2 is right.",
        "A term is missing: a term in sin(θ₁).",
    )


def test_each_wrong_equation_of_a_system_has_its_terms_named_with_its_number():
    first = EOM_DOUBLE_1.replace(" + (m1+m2) g sin(theta1)", "")
    second = EOM_DOUBLE_2.replace("- l1", "+ l1")
    verdict = compare(EOM_DOUBLE, f"{second}; {first}", kind="equations", **DOUBLE)
    assert (verdict.status, verdict.diagnosis) == ("not_equivalent", "wrong_equations")
    assert verdict.feedback == (
        "Your equations do not determine the right accelerations for θ₁, θ₂.",
        "In your equation 1, a term differs: the velocity-dependent term in sin(θ₁ − θ₂) has the wrong sign.",
        "In your equation 2, a term is missing: a term in sin(θ₁).",
    )
    # a conserved quantity's terms are its derivative's, which the student did not write
    spherical = compare(SPHERICAL_EOM, "θ̈ = sin θ φ̇²; m l² sin θ φ̇ = const", kind="equations", **SPHERICAL)
    assert spherical.diagnosis == "wrong_equations"
    assert not any(sentence.startswith("In your equation 2") for sentence in spherical.feedback), spherical.feedback


@pytest.mark.parametrize(
    ("first", "sentence"),
    [
        # solved for θ̈₁, m₁ for m₁ + m₂ puts every other term off by (m₁ + m₂)/m₁: the one term is named
        (EOM_DOUBLE_1.replace("(m1+m2) l1", "m1 l1"),
         "A term differs: the term with an acceleration in θ̈₁ has the wrong factor."),
        (EOM_DOUBLE_1.replace("(m1+m2) l1", "-(m1+m2) l1"),
         "A term differs: the term with an acceleration in θ̈₁ has the wrong sign."),
        # the same, the equation multiplied through by l₁: in the ratio most terms share
        ("l1 (" + EOM_DOUBLE_1.replace("(m1+m2) l1", "m1 l1").replace(" = 0", ") = 0"),
         "A term differs: the term with an acceleration in θ̈₁ has the wrong factor."),
    ],
)  # fmt: skip
def test_an_acceleration_term_off_is_named_whatever_the_equation_is_multiplied_by(first, sentence):
    verdict = compare(EOM_DOUBLE, f"{first}; {EOM_DOUBLE_2}", kind="equations", **DOUBLE)
    assert verdict.status == "not_equivalent"
    assert verdict.feedback[-1] == sentence, verdict.feedback


@pytest.mark.parametrize(
    "first",
    [
        # m₂ for m₁ + m₂ on θ̈₁'s term and on the gravity term: two of four terms off, two right; solved
        # for θ̈₁, the right two looked off, and one of them was named
        EOM_DOUBLE_1.replace("(m1+m2)", "m2"),
        EOM_DOUBLE_1.replace("(m1+m2)", "m1"),
    ],
)
def test_two_of_four_terms_off_name_no_term(first):
    verdict = compare(EOM_DOUBLE, f"{first}; {EOM_DOUBLE_2}", kind="equations", **DOUBLE)
    assert verdict.feedback == ("Your equation for θ₁ is not right; equation 2 is right.",), verdict.feedback


def test_feedback_shows_velocities_as_typed_never_as_internal_names():
    verdict = compare(L_PENDULUM, "1/2 m l^2 θ̇^2 + m g l cos(θ̇)", kind="lagrangian", **PENDULUM)
    assert verdict.feedback == (
        "A term is missing: a term in cos(θ).",
        "There is a term too many: a velocity-dependent term in cos(θ̇).",
    )


@pytest.mark.parametrize(
    ("expected", "submitted", "kind", "options", "sentence"),
    [
        (L_PENDULUM, "m l (l θ̇^2/2)", "lagrangian", {}, "A term is missing: a term in cos(θ)."),
        (L_PENDULUM, "1/2 m l^2 θ̇^2 + 3 m g l cos θ", "lagrangian", {},
         "A term differs: the term in cos(θ) has the wrong factor."),
        ("m g l (1 - cos(theta)) + 1/2 k theta^2", "-m g l cos θ + 7", "expression", {"up_to_constant": True},
         "A term is missing: a term in θ."),
        ("-(g/l) sin(theta) - b thetadot", "-(g/l) sin θ + b θ̇", "expression", {},
         "A term differs: the velocity-dependent term in θ̇ has the wrong sign."),
        ("-(g/l) sin(theta) - 2 b cos(theta) thetadot / sin(theta)", "-(g/l) sin θ - b cot θ θ̇", "expression", {},
         "A term differs: the velocity-dependent term in cot(θ) has the wrong factor."),
    ],
)  # fmt: skip
def test_one_term_missing_or_off_is_named_without_expanding_the_answer(
    expected, submitted, kind, options, sentence, monkeypatch
):
    # the difference is a multiple of one expected term: the numbers say which, and sympy's
    # expansion of the submitted answer (a millisecond) is not needed
    def no_expanding(*args, **kwargs):
        raise AssertionError("the submitted answer was expanded")

    setting = {"kind": kind, "coords": ["theta"], "known": ["m", "g", "l", "k", "b"], **options}
    compare(expected, "0", **setting)  # a first answer: the expected one's terms are expanded, once
    monkeypatch.setattr("grader.judge.expression.terms", no_expanding)
    monkeypatch.setattr("grader.judge.lagrangian.terms", no_expanding)
    verdict = compare(expected, submitted, **setting)
    assert verdict.feedback == (sentence,), verdict


T_DOUBLE_TERMS = "1/2 (m1+m2) l1^2 θ̇₁^2 + 1/2 m2 l2^2 θ̇₂^2 + m2 l1 l2 θ̇₁ θ̇₂ cos(θ₁ − θ₂)"


@pytest.mark.parametrize(
    ("submitted", "sentences"),
    [
        # expanded, m₂ for m₁ + m₂ is a term ½ m₁ l₁² θ̇₁² missing; the student wrote the term in θ̇₁²
        (T_DOUBLE_TERMS.replace("(m1+m2)", "m2"),
         ("A term differs: the velocity-dependent term in θ̇₁² has the wrong factor.",)),
        # and m₁ + m₂ for m₂ is no term too many
        (T_DOUBLE_TERMS.replace("m2 l2^2", "(m1+m2) l2^2"),
         ("A term differs: the velocity-dependent term in θ̇₂² has the wrong factor.",)),
        (T_DOUBLE_TERMS.replace("m2 l1 l2", "(m1+m2) l1 l2"),
         ("A term differs: the velocity-dependent term in cos(θ₁ − θ₂) has the wrong factor.",)),
        (T_DOUBLE_TERMS.replace("m2 l1 l2", "m1 l1 l2"),
         ("A term differs: the velocity-dependent term in cos(θ₁ − θ₂) has the wrong factor.",)),
        (T_DOUBLE_TERMS.replace("m2 l1 l2", "-m2 l1 l2"),
         ("A term differs: the velocity-dependent term in cos(θ₁ − θ₂) has the wrong sign.",)),
        # two terms with wrong masses: both named
        (T_DOUBLE_TERMS.replace("(m1+m2)", "m1").replace("m2 l2^2", "m1 l2^2"),
         ("A term differs: the velocity-dependent term in θ̇₂² has the wrong factor.",
          "A term differs: the velocity-dependent term in θ̇₁² has the wrong factor.")),
        # a term the student did not write at all is still missing
        ("1/2 (m1+m2) l1^2 θ̇₁^2 + 1/2 m2 l2^2 θ̇₂^2",
         ("A term is missing: a velocity-dependent term in cos(θ₁ − θ₂).",)),
    ],
)  # fmt: skip
def test_a_term_with_wrong_masses_is_named_as_the_students_term(submitted, sentences):
    verdict = compare(T_DOUBLE_TERMS, submitted, **DOUBLE)
    assert verdict.status == "not_equivalent"
    assert verdict.feedback == sentences


def test_a_term_written_with_another_function_is_named_as_typed():
    # up to a constant, ω²cos²θ is −ω²sin²θ; but the student wrote cos, not a sin of the wrong sign
    hoop = "1/2 m R^2 (thetadot^2 + omega^2 sin(theta)^2) + m g R cos(theta)"
    verdict = compare(hoop, "1/2 m R^2 (θ̇² + ω² cos²θ) + m g R cos θ", kind="lagrangian", coords=["theta"])
    assert verdict.feedback == ("A term is missing: a term in sin(θ).", "There is a term too many: a term in cos(θ).")


@pytest.mark.parametrize(
    ("expected", "submitted", "sentences"),
    [
        # φ̈ = −2 cot θ θ̇ φ̇ against the derived −2 cos θ θ̇ φ̇ / sin θ: the term is there, as cot θ
        ("m l^2 sin(theta)^2 phiddot + 2 m l^2 sin(theta) cos(theta) thetadot phidot = 0", "φ̈ = −cot θ θ̇ φ̇",
         ("A term differs: the velocity-dependent term in cot(θ) has the wrong factor.",)),
        ("phiddot = -2 cot(theta) thetadot phidot", "sin θ φ̈ + cos θ θ̇ φ̇ = 0",
         ("A term differs: the velocity-dependent term in cos(θ) has the wrong factor.",)),
        ("phiddot = -2 tan(theta) thetadot phidot", "φ̈ = 2 sin θ θ̇ φ̇ / cos θ",
         ("A term differs: the velocity-dependent term in cos(θ) has the wrong sign.",)),  # the first by name
        # cot θ and cos θ / sin θ written side by side are one term: only the term in sin θ is missing
        ("phiddot = -2 cot(theta) thetadot phidot - g/l sin(theta)", "φ̈ = −cot θ θ̇ φ̇ − cos θ θ̇ φ̇ / sin θ",
         ("A term is missing: a term in sin(θ).",)),
        ("phiddot = -2 cot(theta) thetadot phidot - g/l sin(theta)",
         "φ̈ = −cot θ θ̇ φ̇ − cos θ θ̇ φ̇ / sin θ + (g/l) sin θ + g/l",
         ("A term differs: the term in sin(θ) has the wrong sign.", "There is a term too many: a gravity term.")),
        # two terms off: named by sympy's terms, matched however the trigonometry is written
        ("phiddot = -2 cot(theta) thetadot phidot - g/l sin(theta)",
         "φ̈ = −2 cos θ θ̇ φ̇ / sin θ + 3 (g/l) sin θ + g/l",
         ("A term differs: the term in sin(θ) has the wrong factor.",
          "There is a term too many: a gravity term.")),
        ("phiddot = -2 cot(theta) thetadot phidot - g/l sin(theta)", "φ̈ = −cot θ θ̇ φ̇",
         ("A term is missing: a term in sin(θ).",
          "A term differs: the velocity-dependent term in cot(θ) has the wrong factor.")),
    ],
)  # fmt: skip
def test_a_term_in_cot_or_tan_is_the_same_term_in_sin_and_cos(expected, submitted, sentences):
    verdict = compare(expected, submitted, kind="equation", **SPHERICAL)
    assert verdict.feedback == sentences, verdict


def test_a_term_the_answer_does_not_have_is_not_said_to_differ():
    # ẍ = g is (m₁ − m₂)g/(m₁ + m₂) with "the gravity term in m₂" of the other sign; but
    # the student wrote no m₂ (an Atwood machine's free-fall answer, from the example class)
    verdict = compare("(m1 + m2) xddot = (m1 - m2) g", "xddot = g", kind="equation", coords=["x"], known=["m1", "m2"])
    assert verdict.feedback == ("This equation does not say the same as the expected one.",), verdict


@pytest.mark.parametrize(
    ("submitted", "feedback"),
    [
        # (m₁ + m₂) ẍ, solved for ẍ, is ẍ: not m₁ ẍ/(m₁ + m₂) + m₂ ẍ/(m₁ + m₂), two terms the student's
        # ẍ = … has not, which left every mistake unnamed
        ("ẍ = (m₁ − m₂) g/(m₁ + m₂) + x", "There is a term too many: a term in x."),
        ("ẍ = (m₁ − m₂) g/(m₁ + m₂) − g", "There is a term too many: a gravity term."),
        ("2 ẍ = (m₁ − m₂) g/(m₁ + m₂)", "A term differs: the gravity term with m₂ has the wrong factor."),
    ],
)
def test_an_acceleration_whose_factor_is_a_sum_is_one_term_once_solved(submitted, feedback):
    verdict = compare("(m1 + m2) xddot = (m1 - m2) g", submitted, kind="equation", coords=["x"], known=["m1", "m2"])
    assert (verdict.status, verdict.feedback[0]) == ("not_equivalent", feedback), verdict


WEDGE = {"coords": ["X", "s"], "known": ["m", "M", "g", "alpha0"]}  # a block sliding s down a wedge at X


@pytest.mark.parametrize(
    ("expected", "submitted", "feedback"),
    [
        # the expected equation solved for Ẍ first: an answer without Ẍ was told it said nothing alike,
        # as if it were the other coordinate's equation, where a term of it is missing
        ("sddot + Xddot cos(alpha0) - g sin(alpha0) = 0", "s̈ = g sin α₀",
         ("A term is missing: a term with an acceleration.",)),
        ("(M + m) Xddot + m sddot cos(alpha0) = 0", "s̈ = 0", ("A term is missing: a term with an acceleration.",)),
    ],
)  # fmt: skip
def test_an_equation_without_the_first_acceleration_is_solved_for_one_it_has(expected, submitted, feedback):
    verdict = compare(expected, submitted, kind="equation", **WEDGE)
    assert (verdict.status, verdict.feedback) == ("not_equivalent", feedback), verdict


ATWOOD_A = "(m1 - m2) g / (m1 + m2)"
MASSES = {"coords": ["x"], "known": ["m1", "m2", "g"]}
MOMENTUM_PHI = "m l^2 sin(theta)^2 phidot"
SPHERICAL = {"coords": ["theta", "phi"], "known": ["m", "g", "l"]}


DOUBLE = {"coords": ["theta1", "theta2"], "known": ["m1", "m2", "l1", "l2", "g"]}
DOUBLE_V = "-(m1 + m2) g l1 cos(theta1) - m2 g l2 cos(theta2)"


def _instead(right, wrote, instead):
    return (
        f"Your answer depends on {right} as the right answer does, and on {wrote} where the right answer"
        f" depends on {instead}."
    )


def _depends(right, wrong, how="missing"):
    if how == "extra":
        return (
            f"Your answer depends on {right} as the right answer does, but the right answer does not depend on {wrong}."
        )
    said = "not on" if how == "missing" else "on"
    return (
        f"Your answer depends on {right} as the right answer does, but {said} {wrong}"
        f"{' in another way' if how == 'how' else ''}: check how your answer depends on {wrong}."
    )


@pytest.mark.parametrize(
    ("expected", "submitted", "setting", "sentence"),
    [
        # a product or quotient off by a factor in some of its symbols: those symbols are named
        # said as it is: not on g (missing), the right one not on m (extra), or on m₁ and m₂ in another way
        (ATWOOD_A, "(m1 + m2) g / (m1 - m2)", MASSES, _depends("g", "m₁ and m₂", "how")),  # a fraction upside down
        (ATWOOD_A, "(m1 - m2) / (m1 + m2)", MASSES, _depends("m₁ and m₂", "g")),
        (ATWOOD_A, "(m1 - m2) g / m1", MASSES, _depends("g", "m₁ and m₂", "how")),
        ("sqrt(g/l)", "sqrt(g m / l)", PENDULUM, _depends("g and l", "m", "extra")),  # a symbol that has no place
        ("-m g r sin(theta)", "−m g l₀ sin θ", {"coords": ["r", "theta"], "known": ["m", "g", "l0", "k"]},
         _instead("g, m and θ", "l₀", "r")),  # one symbol for another: both are named
        (MOMENTUM_PHI, "m l² θ̇ sin²θ", SPHERICAL, _instead("l, m and θ", "θ̇", "φ̇")),  # the wrong velocity
        (MOMENTUM_PHI, "m l² φ̇ sin θ", SPHERICAL, _depends("l, m and φ̇", "θ", "how")),
        # the factor depends on every symbol: each is named, and no term (√(g/l) has one)
        ("sqrt(g/l)", "sqrt(l/g)", PENDULUM, "Your answer depends on g and l, but not as the right answer does: check"
         " how it depends on each."),
        ("sqrt(g/l)", "3.13", PENDULUM,
         "A formula in the problem's symbols is asked for here; your answer is a number."),
        ("sqrt(g/l)", "sqrt(2 g/l)", PENDULUM, "Your answer is off by a constant factor: missing a factor 1/√2?"),
        ("sqrt(g/l)", "g", PENDULUM, "Your answer does not depend on l, and the right answer does."),
        # a sum: its terms are named
        (ATWOOD_A, "m1 g / (m1 + m2)", MASSES, "A term is missing: a gravity term."),
        # two sums: g, in every term of both, is no factor the student got right
        (DOUBLE_V, "−(m₁ + m₂) g l₁ sin θ₁ − m₂ g l₂ sin θ₂", DOUBLE, "Not equivalent to the expected answer."),
    ],
)  # fmt: skip
def test_a_product_off_by_a_factor_names_the_symbols_it_gets_wrong(expected, submitted, setting, sentence):
    verdict = compare(expected, submitted, **setting)
    assert (verdict.status, verdict.feedback) == ("not_equivalent", (sentence,))


@pytest.mark.parametrize(
    ("submitted", "sentence"),
    [
        # the m₂ part of −(m₁ + m₂) g l₁ cos θ₁ has the wrong sign; "the term in cos(θ₁)" alone would
        # send the student to flip the whole of it, and then again
        ("−(m₁ − m₂) g l₁ cos θ₁ − m₂ g l₂ cos θ₂", "A term differs: the term in cos(θ₁) with m₂ has the wrong sign."),
        ("(m₁ − m₂) g l₁ cos θ₁ − m₂ g l₂ cos θ₂", "A term differs: the term in cos(θ₁) with m₁ has the wrong sign."),
        # a term with no other of the student's described alike is named as before
        ("−(m₁ + m₂) g l₁ cos θ₁ + m₂ g l₂ cos θ₂", "A term differs: the term in cos(θ₂) has the wrong sign."),
    ],
)
def test_a_term_of_the_wrong_sign_is_told_apart_from_the_students_terms_named_alike(submitted, sentence):
    verdict = compare("-(m1 + m2) g l1 cos(theta1) - m2 g l2 cos(theta2)", submitted, **DOUBLE)
    assert verdict.feedback == (sentence,), verdict


def test_a_symbol_the_right_answer_has_no_place_for_is_said_so():
    # x in an acceleration: the answer depends on it, and the right one does not
    verdict = compare(ATWOOD_A, "(m1 - m2) g x / (m1 + m2)", **MASSES)
    assert verdict.feedback[-1] == _depends("g, m₁ and m₂", "x", "extra"), verdict


@pytest.mark.parametrize(
    "submitted",
    [
        "½ (m₁ + m₂) g l₁ θ₁² + ½ m₂ g l₂ θ₂²",  # the constant dropped, as another zero level may
        "−(m₁ + m₂) g l₁ (1 − θ₁²/2) − m₂ g l₂ (1 − θ₂²/2)",
    ],
)
def test_the_small_angle_form_of_a_potential_is_said_whatever_its_zero(submitted):
    verdict = compare(DOUBLE_V, submitted, up_to_constant=True, **DOUBLE)
    assert verdict.diagnosis == "small_angle", verdict


@pytest.mark.parametrize(
    ("expected", "submitted", "setting", "said"),
    [
        ("thetaddot = -g/l theta", "θ̈ = −(g/l) sin θ", {**PENDULUM, "dimensions": {"theta": "angle"}}, True),
        ("thetaddot = -g/l theta", "θ̈ = −(g/l) sin θ", PENDULUM, True),  # no dimension: may be an angle
        # a displacement is no angle: sin x is a slip of units, the harmonic form no approximation
        ("m xddot + b xdot + k x = 0", "m ẍ + b ẋ + k sin x = 0",
         {"coords": ["x"], "known": ["m", "b", "k"], "dimensions": {"x": "length"}}, False),
    ],
)  # fmt: skip
def test_the_full_form_where_the_linear_one_is_asked_is_said_only_of_an_angle(expected, submitted, setting, said):
    verdict = compare(expected, submitted, kind="equation", **setting)
    assert verdict.status == "not_equivalent"
    assert any("The small-angle (linearized) form is asked for" in s for s in verdict.feedback) is said, verdict


DOUBLE_EOM = (
    "(m1+m2) l1 theta1'' + m2 l2 theta2'' cos(theta1-theta2) + m2 l2 theta2'^2 sin(theta1-theta2)"
    " + (m1+m2) g sin(theta1) = 0;"
    " l2 theta2'' + l1 theta1'' cos(theta1-theta2) - l1 theta1'^2 sin(theta1-theta2) + g sin(theta2) = 0"
)


@pytest.mark.parametrize(
    "submitted",
    ["(l θ̈ + g sin θ)² = 0", "θ̈³ = −(g/l)³ sin³θ", "exp(θ̈) = 1 + g", "|θ̈| = −(g/l) sin θ", "√(θ̈²) = −(g/l) sin θ"],
)
def test_an_equation_not_linear_in_the_accelerations_is_told_so(submitted):
    verdict = compare(EOM_PENDULUM, submitted, kind="equation", **PENDULUM)
    assert (verdict.status, verdict.diagnosis) == ("not_equivalent", "not_linear"), verdict
    assert verdict.feedback[0].startswith("Your equation is not linear in the accelerations (θ̈)")


def test_a_system_with_one_equation_squared_blames_that_equation_alone():
    first, second = DOUBLE_EOM.split(";")
    verdict = compare(DOUBLE_EOM, f"{first}; ({second.removesuffix(' = 0')})^2 = 0", kind="equations", **DOUBLE)
    assert verdict.feedback[:2] == (
        "Your equation for θ₂ is not right; equation 1 is right.",
        "Your equation 2 is not linear in the accelerations, as every equation of motion from Lagrange's equations is.",
    ), verdict


def test_a_constant_too_many_is_not_a_constant_term_off_by_a_factor():
    # any constant difference is a multiple of cos 3: only the terms as typed can say which
    verdict = compare("cos(3) + g", "cos(3) - 3 + g")
    assert verdict.feedback == ("There is a term too many: a constant term.",), verdict


@pytest.mark.parametrize(
    "submitted",
    [
        "m g l (1 - cos(theta))",  # the zero of potential at the lowest point: a constant of the parameters
        "-m g l cos(theta) + 5",
        "-(m g l cos(theta) + 3)",
    ],
)
def test_a_potential_from_another_zero_is_told_so_where_no_constant_is_allowed(submitted):
    verdict = compare("-m g l cos(theta)", submitted, coords=["theta"], name="V")
    assert verdict.status == "not_equivalent", verdict
    assert verdict.feedback[0].startswith("Your answer is right but for an added constant"), verdict
    # named as no energy, or measured in no energy, its constant is a term
    for setting in ({"name": "p_phi"}, {}):
        verdict = compare("-m g l cos(theta)", submitted, coords=["theta"], **setting)
        assert "added constant" not in verdict.feedback[0], (setting, verdict)
    assert compare("-m g l cos(theta)", submitted, coords=["theta"], up_to_constant=True).equivalent


@pytest.mark.parametrize("name", ["T", "K", ["T", "K"]])
def test_a_kinetic_energy_with_a_constant_is_not_told_about_a_zero_of_potential(name):
    verdict = compare("1/2 m l^2 thetadot^2", "1/2 m l^2 thetadot^2 + m g l", coords=["theta"], known=["g"], name=name)
    assert verdict.feedback == (
        "Your answer is right but for an added constant: a kinetic energy has none, it is zero when nothing moves.",
    ), verdict  # before: "does the problem fix a zero, of potential energy say, …?"
    assert verdict.status == "not_equivalent"


@pytest.mark.parametrize(
    ("expected", "submitted", "coords"),
    [
        ("sqrt(g/l)", "sqrt(g/l) + 1", []),  # nothing varies: every wrong answer differs by "a constant"
        ("-m g l cos(theta)", "-m g l cos(theta) + theta", ["theta"]),
        ("m l^2 thetadot", "m l^2 thetadot + m g l cos(theta)", ["theta"]),
    ],
)
def test_only_a_difference_constant_along_the_motion_is_told_as_a_constant(expected, submitted, coords):
    verdict = compare(expected, submitted, coords=coords, name="V")
    assert verdict.status == "not_equivalent", verdict
    assert "added constant" not in " ".join(verdict.feedback), verdict


def test_feedback_never_contains_the_expected_answer():
    for expected, submitted, kind, setting, _, _ in FEEDBACK:
        verdict = compare(expected, submitted, kind=kind, **setting)
        for sentence in verdict.feedback:
            assert expected not in sentence


@pytest.mark.parametrize(
    ("submitted", "status"),
    [
        # a step of the potential where θ passes 0: the same equations wherever they are evaluated
        ("½ m l² θ̇² + m g l cos θ + m g l sgn θ", "undecided"),
        ("½ m l² θ̇² + m g l cos θ + m g l sign(sin θ)", "undecided"),
        ("½ m l² θ̇² + m g l cos θ + m g l sign(θ̇)", "undecided"),
        ("½ m l² θ̇² + m g l cos θ + sign(m) g", "equivalent"),  # a constant, however written
    ],
)
def test_a_lagrangian_with_a_step_in_the_motion_goes_to_a_person(submitted, status):
    assert compare(L_PENDULUM, submitted, kind="lagrangian", **PENDULUM).status == status


def test_partial_credit_for_a_rescaled_lagrangian_is_the_parts_option():
    verdict = compare(L_PENDULUM, "2 (" + L_PENDULUM + ")", kind="lagrangian", factor_credit=0.25, **PENDULUM)
    assert (verdict.status, verdict.score) == ("not_equivalent", 0.25)


@pytest.mark.parametrize(
    "submitted",
    [
        L_PENDULUM + " + 7",  # another zero of potential energy
        L_PENDULUM + " - m g l",
        L_PENDULUM + " + 2 θ θ̇",  # d/dt(θ²)
        L_PENDULUM + " + m l θ̇ cos θ",  # d/dt(m l sin θ)
        # large ones: each equation cancels terms far above its value, and draws' ratios agree to 10⁻¹²
        L_PENDULUM + " + 1000 θ̇ sin θ",
        L_PENDULUM + " + d/dt(θ^6)",
        L_PENDULUM + " + 10^6 θ̇ θ^2",
        "L = " + L_PENDULUM,
        # the constant in words, as TeX writes a word: \text{const} is \mathrm{const}
        r"\frac12 m l^2 \dot\theta^2 + m g l \cos\theta + \text{const}",
        r"\frac12 m l^2 \dot\theta^2 + m g l \cos\theta + \text{const.}",
        r"\frac12 m l^2 \dot\theta^2 + m g l \cos\theta + \mbox{ constant }",
    ],
)
def test_a_lagrangian_is_right_up_to_a_constant_or_a_total_derivative(submitted):
    verdict = compare(L_PENDULUM, submitted, kind="lagrangian", **PENDULUM)
    assert (verdict.status, verdict.score) == ("equivalent", 1.0)


@pytest.mark.parametrize(
    ("submitted", "status"),
    [
        # the prompts say "Write the Lagrangian L(θ, θ̇)": students write the name with its arguments
        ("L(θ, θ̇) = " + L_PENDULUM, "equivalent"),
        ("L(theta, thetadot, t) = " + L_PENDULUM, "equivalent"),
        ("L(q, q̇, t) = " + L_PENDULUM, "equivalent"),  # generic variables, in a list: before, the comma was refused
        (r"L(q_i, \dot q_i) = " + L_PENDULUM, "equivalent"),
        ("H(q, p) = " + L_PENDULUM, "undecided"),  # another quantity's name: a person decides
        (r"\mathcal{L}(\theta, \dot\theta) = \frac12 m l^2 \dot\theta^2 + m g l \cos\theta", "equivalent"),
        # and the definition on the way: the last side is the answer
        ("L = T - V = " + L_PENDULUM, "equivalent"),
        ("L(θ, θ̇) = T − V = ½ m v² + m g l cos θ = " + L_PENDULUM, "equivalent"),
        ("L(θ, θ̇) = T - V = 1/2 m l^2 θ̇^2 - m g l cos θ", "not_equivalent"),  # the last side is judged
        ("L = T - V", "not_equivalent"),  # a definition alone is no Lagrangian
        ("T - V = " + L_PENDULUM, "equivalent"),  # a left side only in names the problem leaves free
        ("m - V = " + L_PENDULUM, "not_equivalent"),  # m is the mass: this is an equation
        # a middle side in the problem's own names may be what was meant: a person decides (it was
        # refused for its second `=`; now the student is told which side differs)
        ("L = 1/2 m l^2 θ̇^2 = " + L_PENDULUM, "undecided"),
        ("l(θ, θ̇) = " + L_PENDULUM, "invalid"),  # l is the length here: no name, and no list
        ("L(θ, 2) = " + L_PENDULUM, "invalid"),
    ],
)
def test_an_answer_may_name_the_quantity_it_writes_out(submitted, status):
    assert compare(L_PENDULUM, submitted, kind="lagrangian", **PENDULUM).status == status


@pytest.mark.parametrize(
    "submitted",
    [
        "p_θ = ∂L/∂θ̇ = m l^2 θ̇",
        "∂L/∂θ̇ = m l^2 θ̇",
        r"p_\theta = \frac{\partial L}{\partial \dot\theta} = m l^2 \dot\theta",
    ],
)
def test_a_momentum_may_be_written_as_its_derivation(submitted):
    assert compare("m l^2 thetadot", submitted, **PENDULUM).status == "equivalent"


@pytest.mark.parametrize(
    ("submitted", "status"),
    [
        ("m l² θ̈ = −m g l sin θ ⇒ θ̈ = −(g/l) sin θ", "equivalent"),
        ("m l² θ̈ = −m g l sin θ\n⇒ θ̈ = −(g/l) cos θ", "not_equivalent"),  # the conclusion is judged
        # the conclusion is right, but the premise, which it does not follow from, says otherwise: a person reads
        # it (before, right, as it would be graded on paper)
        ("m l² θ̈ = m g l sin θ ⇒ θ̈ = −(g/l) sin θ", "undecided"),
        ("EOM: θ̈ = −(g/l) sin θ", "equivalent"),
        (r"\ddot\theta = -\frac gl \sin\theta \quad\Rightarrow", "equivalent"),
        ("m l² θ̈ = −m g l sin θ -> θ̈ = −(g/l) sin θ", "equivalent"),
        ("m l² θ̈ = −m g l sin θ, so θ̈ = −(g/l) sin θ", "equivalent"),
        # the Euler–Lagrange operator written out first: what it comes to is the equation
        ("d/dt(∂L/∂θ̇) − ∂L/∂θ = m l² θ̈ + m g l sin θ = 0", "equivalent"),
        ("d/dt ∂L/∂θ̇ − ∂L/∂θ = m l² θ̈ − m g l sin θ = 0", "not_equivalent"),
        (
            r"\frac{d}{dt}\left(\frac{\partial L}{\partial\dot\theta}\right) - \frac{\partial L}{\partial\theta}"
            r" = ml^2\ddot\theta + mgl\sin\theta = 0",
            "equivalent",
        ),
        ("d/dt(∂L/∂θ̇) − ∂L/∂θ = m l² θ̈ + m g l sin θ", "not_equivalent"),  # "= 0" left out: an expression
        ("θ̈ ≈ −(g/l) sin θ", "equivalent"),  # ≈ is the relation written
        # a force named, then the equation of motion it stands in: F = m ẍ = −k x says m ẍ = −k x
        ("F = m l θ̈ = −m g sin θ", "equivalent"),
        ("F_θ = −m g l sin θ = m l² θ̈", "equivalent"),
        ("F = m l θ̈ = m g sin θ", "not_equivalent"),
    ],
)
def test_an_equation_may_be_labelled_or_concluded_from_another(submitted, status):
    assert compare("thetaddot = -g/l sin(theta)", submitted, kind="equation", **PENDULUM).status == status


@pytest.mark.parametrize(
    ("expected", "submitted", "kind", "status"),
    [
        # the name asked for, times a number or raised to a power: its value is the other side's
        ("sqrt(g/l)", "ω² = g/l", "expression", "equivalent"),  # a frequency's positive root
        ("sqrt(g/l)", "2ω = 2√(g/l)", "expression", "equivalent"),
        ("sqrt(g/l)", "ω² = l/g", "expression", "not_equivalent"),
        ("sqrt(g/l)", "1/ω = √(l/g)", "expression", "equivalent"),  # before, the left side was dropped
        ("sqrt(g/l)", "1/ω² = l/g", "expression", "equivalent"),
        ("sqrt(g/l)", "√ω = (g/l)^(1/4)", "expression", "equivalent"),
        ("sqrt(g/l)", "1/ω = √(g/l)", "expression", "not_equivalent"),
        (L_PENDULUM, "2 L = m l² θ̇² + 2 m g l cos θ", "lagrangian", "equivalent"),
        (L_PENDULUM, "L/2 = ¼ m l² θ̇² + ½ m g l cos θ", "lagrangian", "equivalent"),
        (L_PENDULUM, "2L = m l² θ̇² + m g l cos θ", "lagrangian", "not_equivalent"),
        (L_PENDULUM, "V − T = −½ m l² θ̇² − m g l cos θ", "lagrangian", "equivalent"),  # −L, rightly
    ],
)
def test_a_multiple_or_a_power_of_the_name_asked_for_gives_its_value(expected, submitted, kind, status):
    verdict = compare(expected, submitted, kind=kind, **PENDULUM)
    assert (verdict.status, verdict.score) == (status, float(status == "equivalent")), verdict


_WRONG_KINETIC_FACTOR = "A term differs: the velocity-dependent term in θ̇² has the wrong factor."
_WRONG_IN_L = (
    "Your answer depends on m and θ̇ as the right answer does, but on l in another way: check how your answer"
    " depends on l."
)


@pytest.mark.parametrize(
    ("expected", "submitted", "kind", "status", "feedback"),
    [
        # the name over the problem's constants: L/m = … says L = m·(…). Before, L was a name the problem lacks
        (L_PENDULUM, "L/m = ½ l² θ̇² + g l cos θ", "lagrangian", "equivalent", "Correct."),
        (L_PENDULUM, "2L/(m l²) = θ̇² + (2g/l) cos θ", "lagrangian", "equivalent", "Correct."),
        # as wrong as L = m l² θ̇² + m g l cos θ, and told the same
        (L_PENDULUM, "L/m = l² θ̇² + g l cos θ", "lagrangian", "not_equivalent", _WRONG_KINETIC_FACTOR),
        (L_PENDULUM, "L/(m l) = l θ̇² + g cos θ", "lagrangian", "not_equivalent", _WRONG_KINETIC_FACTOR),
        ("m l^2 thetadot", "p_θ/m = l² θ̇", "expression", "equivalent", "Correct."),
        ("m l^2 thetadot", "p_θ/m = l θ̇", "expression", "not_equivalent", _WRONG_IN_L),
    ],
)
def test_the_name_asked_for_over_the_problems_constants_gives_its_value(expected, submitted, kind, status, feedback):
    verdict = compare(expected, submitted, kind=kind, **PENDULUM)
    assert (verdict.status, verdict.score, verdict.feedback) == (status, float(status == "equivalent"), (feedback,))


SIGN_OPEN = (
    "Your answer gives `{}`: {} leaves the sign open, and the quantity asked for may be negative. A person will"
    " check which root you meant."
)


@pytest.mark.parametrize(
    ("submitted", "options", "feedback", "read_as"),
    [
        # before, read as its positive root, m l² sin²θ |φ̇|, and told falsely that a term in sin θ was wrong
        ("p_φ² = m² l⁴ sin⁴θ φ̇²", {}, SIGN_OPEN.format("p_φ^2", "a square"), "p_φ^2 = l^4*m^2*sin(θ)^4*φ̇^2"),
        ("p_φ² = m² l⁴ sin⁴θ φ̇²", {"name": "p_phi"}, SIGN_OPEN.format("p_φ^2", "a square"),
         "p_φ^2 = l^4*m^2*sin(θ)^4*φ̇^2"),
        ("p_phi^2 = (m l^2 sin(theta)^2 phidot)^2", {}, SIGN_OPEN.format("p_φ^2", "a square"),
         "p_φ^2 = l^4*m^2*sin(θ)^4*φ̇^2"),
        ("p_φ⁴ = m⁴ l⁸ sin⁸θ φ̇⁴", {}, SIGN_OPEN.format("p_φ^4", "an even power"), "p_φ^4 = l^8*m^4*sin(θ)^8*φ̇^4"),
    ],
)  # fmt: skip
def test_a_square_of_a_signed_quantity_right_as_a_square_goes_to_a_person(submitted, options, feedback, read_as):
    verdict = compare(MOMENTUM_PHI, submitted, kind="expression", **SPHERICAL, **options)
    assert (verdict.status, verdict.score, verdict.feedback, verdict.read_as) == (
        "undecided",
        0.0,
        (feedback,),
        read_as,
    )


_L_AND_K = (
    "Your answer uses `L` and `k`, which this problem does not define (it uses g, l, m, θ). Write your answer in"
    " those, or say what each stands for: …, where L = …."
)


@pytest.mark.parametrize(
    ("expected", "submitted", "kind", "feedback"),
    [
        # the name times a factor of the student's own: L is the side over k, not the side. Before, Correct
        (L_PENDULUM, f"k L = {L_PENDULUM}", "lagrangian", _L_AND_K),
        (L_PENDULUM, f"L k = {L_PENDULUM}", "lagrangian", _L_AND_K),
        (L_PENDULUM, f"L/k = {L_PENDULUM}", "lagrangian", _L_AND_K),
        (L_PENDULUM, f"The Lagrangian is k L = {L_PENDULUM}", "lagrangian",
         "Your answer uses `L`, `Lagrangian`, `The`, `is` and `k`, which this problem does not define (it uses g, l,"
         " m, θ). Write your answer in those, or say what each stands for: …, where L = …."),
        (L_PENDULUM, f"m L = {L_PENDULUM}", "lagrangian",
         "Your answer uses `L`, which this problem does not define (it uses g, l, m, θ). Write your answer in those,"
         " or say what it stands for: …, where L = …."),
        ("m l^2 thetadot", "k p_θ = m l² θ̇", "expression",
         "Your answer uses `k` and `p_θ`, which this problem does not define (it uses g, l, m, θ). Write your answer"
         " in those, or say what each stands for: …, where k = …."),
    ],
)  # fmt: skip
def test_the_name_asked_for_times_a_name_of_the_students_own_is_no_label(expected, submitted, kind, feedback):
    verdict = compare(expected, submitted, kind=kind, **PENDULUM)
    assert (verdict.status, verdict.score, verdict.feedback) == ("not_equivalent", 0.0, (feedback,)), verdict


@pytest.mark.parametrize(
    "submitted",
    [f"The Lagrangian is L = {L_PENDULUM}", f"The Lagrangian is L = {L_PENDULUM}.", f"Our Lagrangian L = {L_PENDULUM}"],
)
def test_a_sentence_before_the_name_is_no_factor_of_it(submitted):
    # a guard, not a fix: read as the product The·Lagrangian·is·L, the sentence is words, not k in k L
    verdict = compare(L_PENDULUM, submitted, kind="lagrangian", **PENDULUM)
    assert (verdict.status, verdict.score) == ("equivalent", 1.0), verdict


@pytest.mark.parametrize(
    ("expected", "submitted", "status"),
    [
        # where a count is asked, 3N = 3 is the count 3N worked out, not N = 1
        ("1", "3N = 3", "not_equivalent"),
        ("15", "3N = 15", "equivalent"),
        ("2", "2n = 4", "not_equivalent"),
        # working in a list: the count is the name it ends in, not the first item's value
        ("1", "3N = 3, k = 2, n = 1", "equivalent"),
        ("1", "k = 2; 3N = 3; n = 1", "equivalent"),
        ("2", "3N = 6, k = 4, n = 2", "equivalent"),
        ("3", "3N = 6, k = 4, n = 2", "not_equivalent"),
        # a value the count was worked out with is never the count
        ("15", "3N = 15, N = 5", "equivalent"),
        ("15", "N = 5, 3N = 15", "equivalent"),
        # two values and no working: which is meant is for the student to say
        ("2", "n = 2; m = 3", "invalid"),
    ],
)
def test_a_multiple_of_a_name_in_a_count_is_working_not_the_counts_name(expected, submitted, status):
    assert compare(expected, submitted, kind="integer").status == status


@pytest.mark.parametrize(
    ("expected", "submitted", "status"),
    [
        # where the part names the count (n = 3N − k), a list of values gives n's, first or last
        ("2", "n = 2, k = 4", "equivalent"),
        ("4", "n = 2, k = 4", "not_equivalent"),
        ("2", "n = 2; k = 4", "equivalent"),
        ("2", "k = 4, n = 2", "equivalent"),
        ("2", "n = 3N − k = 2, N = 2, k = 4", "equivalent"),
        ("2", "n = 2, n = 4", "not_equivalent"),  # two values of n: the last word, as without the name
        # and the count's label is no other quantity: right as read, as without the name
        ("2", "DOF = 2", "equivalent"),
        ("2", "s = 2", "equivalent"),
    ],
)
def test_a_count_the_part_names_is_read_at_its_name(expected, submitted, status):
    verdict = compare(expected, submitted, kind="integer", name="n")
    assert (verdict.status, verdict.score) == (status, float(status == "equivalent")), verdict


NAMED_FINAL = "Graded your final value, `{}`; the working before it is not graded."
NAMED_REST = "Graded the number `{}`; what follows it (`{}`) is not graded."


@pytest.mark.parametrize(
    ("expected", "submitted", "status", "feedback"),
    [
        # before, the chain refused as a list gave the last value, k's: graded as 4, and not right
        ("2", "n = 6 − 4 = 2, k = 4", "equivalent", ("Correct.", NAMED_FINAL.format(2), NAMED_REST.format(2, "k = 4"))),
        ("4", "n = 6 − 4 = 2, k = 4", "not_equivalent",
         ("Not equivalent to the expected answer.", NAMED_FINAL.format(2), NAMED_REST.format(2, "k = 4"))),
        # and a wrong count is not graded at k's value, which here is right
        ("2", "n = 6 − 2 = 4, k = 2", "not_equivalent",
         ("Not equivalent to the expected answer.", NAMED_FINAL.format(4), NAMED_REST.format(4, "k = 2"))),
    ],
)  # fmt: skip
def test_a_chain_the_part_names_is_read_at_its_name(expected, submitted, status, feedback):
    verdict = compare(expected, submitted, kind="integer", name="n")
    assert (verdict.status, verdict.feedback) == (status, feedback)


DAMPED = {"coords": ["x"], "known": ["m", "b", "k"]}


@pytest.mark.parametrize(
    ("submitted", "status"),
    [
        # Lagrange's equation with Rayleigh's dissipation function, written out first
        ("d/dt(∂L/∂ẋ) − ∂L/∂x + ∂F/∂ẋ = m ẍ + k x + b ẋ = 0", "equivalent"),
        (
            r"\frac{d}{dt}\frac{\partial L}{\partial \dot x} - \frac{\partial L}{\partial x}"
            r" + \frac{\partial \mathcal{F}}{\partial \dot x} = m\ddot x + b\dot x + k x = 0",
            "equivalent",
        ),
        ("d/dt(∂L/∂ẋ) − ∂L/∂x + ∂F/∂ẋ = m ẍ + k x = 0", "not_equivalent"),  # what it comes to is judged
        ("d/dt(∂L/∂ẋ) − ∂L/∂x + ∂F/∂ẋ + = m ẍ + k x + b ẋ = 0", "invalid"),
    ],
)
def test_lagranges_equation_with_a_dissipation_function_may_be_written_out_first(submitted, status):
    assert compare("m xddot + b xdot + k x = 0", submitted, kind="equation", **DAMPED).status == status


GENERAL_FORM = (
    "This is Lagrange's equation in general form, which holds for every system: work it out for this one,"
    " with its {} put in, and give the equation of motion it comes to."
)


@pytest.mark.parametrize(
    ("submitted", "status", "feedback"),
    [
        # before, read as the expression 0, and told that an equation was asked for
        ("d/dt(∂L/∂ẋ) − ∂L/∂x + ∂F/∂ẋ = 0", "invalid", (GENERAL_FORM.format("`L` and `F`"),)),
        (r"\frac{d}{dt}\frac{\partial L}{\partial \dot x} - \frac{\partial L}{\partial x} = 0", "invalid",
         (GENERAL_FORM.format("`L`"),)),
        ("d/dt(∂L/∂ẋ) − ∂L/∂x = Q", "invalid", (GENERAL_FORM.format("`L`"),)),
        ("d/dt(∂L/∂x) − ∂L/∂ẋ = 0", "invalid",
         ("This is not Lagrange's equation, d/dt(∂L/∂q̇) − ∂L/∂q = 0, nor an equation of motion of this system:"
          " give the equation of motion, worked out for this system.",)),
        # Rayleigh's term on the right: before, refused for its `∂` ("read only in the name of …")
        ("d/dt(∂L/∂ẋ) − ∂L/∂x = −∂F/∂ẋ", "invalid", (GENERAL_FORM.format("`L` and `F`"),)),
        (r"\frac{d}{dt}\frac{\partial L}{\partial \dot x} - \frac{\partial L}{\partial x}"
         r" = -\frac{\partial \mathcal{F}}{\partial \dot x}", "invalid",
         (GENERAL_FORM.format("`L` and `\\mathcal{F}`"),)),
        ("d/dt(∂L/∂ẋ) − ∂L/∂x = ∂F/∂ẋ", "invalid",  # of the wrong sign
         ("This is not Lagrange's equation, d/dt(∂L/∂q̇) − ∂L/∂q = 0, nor an equation of motion of this system:"
          " give the equation of motion, worked out for this system.",)),
    ],
)  # fmt: skip
def test_lagranges_equation_in_general_form_alone_is_asked_to_be_worked_out(submitted, status, feedback):
    verdict = compare("m xddot + b xdot + k x = 0", submitted, kind="equation", **DAMPED)
    assert (verdict.status, verdict.feedback) == (status, feedback)


def _general_read_past(words: str) -> str:
    return f"Read without the words before it, `{words}`: the formula is what is graded."


_RAYLEIGH_RIGHT = "d/dt(∂L/∂ẋ) − ∂L/∂x = −∂F/∂ẋ"
# Lagrange's equation with Rayleigh's term on the right, then the equation it comes to, graded as the form
# with it on the left is: before, refused for its `∂`
GENERAL_FORM_THEN_EQUATION = (
    (f"{_RAYLEIGH_RIGHT}, m ẍ + b ẋ + k x = 0", "equivalent", ("Correct.", _general_read_past(f"{_RAYLEIGH_RIGHT},"))),
    (f"{_RAYLEIGH_RIGHT}, m ẍ − b ẋ + k x = 0", "not_equivalent",
     ("A term differs: the velocity-dependent term in ẋ has the wrong sign.",
      _general_read_past(f"{_RAYLEIGH_RIGHT},"))),
    (f"{_RAYLEIGH_RIGHT}\nm ẍ + b ẋ + k x = 0", "equivalent", ("Correct.", _general_read_past(_RAYLEIGH_RIGHT))),
    (f"Using {_RAYLEIGH_RIGHT} we get m ẍ + b ẋ + k x = 0", "equivalent",
     ("Correct.", _general_read_past(f"Using {_RAYLEIGH_RIGHT} we get"))),
    # Rayleigh's term of the wrong sign is no Lagrange's equation: a right equation after it goes to a person
    ("d/dt(∂L/∂ẋ) − ∂L/∂x = ∂F/∂ẋ, m ẍ + b ẋ + k x = 0", "undecided",
     ("Your answer says `d/dt(∂L/∂ẋ) − ∂L/∂x − ∂F/∂ẋ = 0` on the way to its equation, which is not Lagrange's"
      " equation. The equation was graded and is right; a person will check this answer.",
      _general_read_past("d/dt(∂L/∂ẋ) − ∂L/∂x = ∂F/∂ẋ,"))),
    # with d for ∂, as typed: before, `:` was refused, the side ending at dF, read as a word
    ("d/dt(dL/dxdot) - dL/dx = -dF/dxdot: m xddot + k x = -b xdot", "equivalent",
     ("Correct.", _general_read_past("d/dt(dL/dxdot) - dL/dx = -dF/dxdot:"))),
    ("d/dt(dL/dxdot) - dL/dx = -dF/dxdot: m xddot + k x = b xdot", "not_equivalent",
     ("A term differs: the velocity-dependent term in ẋ has the wrong sign.",
      _general_read_past("d/dt(dL/dxdot) - dL/dx = -dF/dxdot:"))),
    ("d/dt(dL/dxdot) - dL/dx = dF/dxdot: m xddot + k x = -b xdot", "undecided",
     ("Your answer says `d/dt(dL/dxdot) - dL/dx − dF/dxdot = 0` on the way to its equation, which is not Lagrange's"
      " equation. The equation was graded and is right; a person will check this answer.",
      _general_read_past("d/dt(dL/dxdot) - dL/dx = dF/dxdot:"))),
    # the generalized force written out, which must be the one the equation after it needs: before, `:` refused
    ("d/dt(∂L/∂ẋ) − ∂L/∂x = −b ẋ: m ẍ + k x + b ẋ = 0", "equivalent",
     ("Correct.", _general_read_past("d/dt(∂L/∂ẋ) − ∂L/∂x = −b ẋ:"))),
    ("d/dt(∂L/∂ẋ) − ∂L/∂x = −b ẋ: m ẍ + k x = −b ẋ", "equivalent",
     ("Correct.", _general_read_past("d/dt(∂L/∂ẋ) − ∂L/∂x = −b ẋ:"))),
    ("∂L/∂x − d/dt(∂L/∂ẋ) = b ẋ: m ẍ + k x + b ẋ = 0", "equivalent",
     ("Correct.", _general_read_past("∂L/∂x − d/dt(∂L/∂ẋ) = b ẋ:"))),
    ("d/dt(∂L/∂ẋ) − ∂L/∂x = −b ẋ: m ẍ + k x − b ẋ = 0", "not_equivalent",
     ("A term differs: the velocity-dependent term in ẋ has the wrong sign.",
      _general_read_past("d/dt(∂L/∂ẋ) − ∂L/∂x = −b ẋ:"))),
    # a force the equation after it does not need (of the wrong sign, twice as large): a person reads it
    ("d/dt(∂L/∂ẋ) − ∂L/∂x = +b ẋ: m ẍ + k x + b ẋ = 0", "undecided",
     ("Your answer says `d/dt(∂L/∂ẋ) − ∂L/∂x = +b ẋ` on the way to its equation, which is not Lagrange's"
      " equation. The equation was graded and is right; a person will check this answer.",
      _general_read_past("d/dt(∂L/∂ẋ) − ∂L/∂x = +b ẋ:"))),
    ("∂L/∂x − d/dt(∂L/∂ẋ) = −b ẋ: m ẍ + k x + b ẋ = 0", "undecided",
     ("Your answer says `∂L/∂x − d/dt(∂L/∂ẋ) = −b ẋ` on the way to its equation, which is not Lagrange's"
      " equation. The equation was graded and is right; a person will check this answer.",
      _general_read_past("∂L/∂x − d/dt(∂L/∂ẋ) = −b ẋ:"))),
    ("d/dt(∂L/∂ẋ) − ∂L/∂x = −2 b ẋ: m ẍ + k x + b ẋ = 0", "undecided",
     ("Your answer says `d/dt(∂L/∂ẋ) − ∂L/∂x = −2 b ẋ` on the way to its equation, which is not Lagrange's"
      " equation. The equation was graded and is right; a person will check this answer.",
      _general_read_past("d/dt(∂L/∂ẋ) − ∂L/∂x = −2 b ẋ:"))),
    ("d/dt(∂V/∂ẋ) − ∂V/∂x = −b ẋ: m ẍ + k x + b ẋ = 0", "undecided",
     ("Your answer says `d/dt(∂V/∂ẋ) − ∂V/∂x = −b ẋ` on the way to its equation, which is not Lagrange's"
      " equation. The equation was graded and is right; a person will check this answer.",
      _general_read_past("d/dt(∂V/∂ẋ) − ∂V/∂x = −b ẋ:"))),
    # the right equation divided by m, or negated, after the right force: the part's own equation fixes the
    # scale the force is read at (before, for a person); a force of the wrong sign still goes to one
    ("d/dt(∂L/∂ẋ) − ∂L/∂x = −b ẋ: ẍ + (b/m) ẋ + (k/m) x = 0", "equivalent",
     ("Correct.", _general_read_past("d/dt(∂L/∂ẋ) − ∂L/∂x = −b ẋ:"))),
    ("d/dt(∂L/∂ẋ) − ∂L/∂x = −b ẋ: −m ẍ − k x − b ẋ = 0", "equivalent",
     ("Correct.", _general_read_past("d/dt(∂L/∂ẋ) − ∂L/∂x = −b ẋ:"))),
    # the force, or Rayleigh's term, before a step ⇒ to the equation: before, the side ran on past the step, and
    # the operator was said to equal all of it (`… = −b ẋ ⇒ m ẍ + k x + b ẋ`), for a person
    ("d/dt(∂L/∂ẋ) − ∂L/∂x = −b ẋ ⇒ m ẍ + k x + b ẋ = 0", "equivalent", ("Correct.",)),
    ("d/dt(∂L/∂ẋ) − ∂L/∂x = −∂F/∂ẋ ⇒ m ẍ + k x + b ẋ = 0", "equivalent", ("Correct.",)),
    ("d/dt(∂L/∂ẋ) − ∂L/∂x = +b ẋ ⇒ m ẍ + k x + b ẋ = 0", "undecided",
     ("Your answer says `d/dt(∂L/∂ẋ) − ∂L/∂x = +b ẋ` on the way to its equation, which is not Lagrange's"
      " equation. The equation was graded and is right; a person will check this answer.",)),
    ("d/dt(∂L/∂ẋ) − ∂L/∂x = +b ẋ: ẍ + (b/m) ẋ + (k/m) x = 0", "undecided",
     ("Your answer says `d/dt(∂L/∂ẋ) − ∂L/∂x = +b ẋ` on the way to its equation, which is not Lagrange's"
      " equation. The equation was graded and is right; a person will check this answer.",
      _general_read_past("d/dt(∂L/∂ẋ) − ∂L/∂x = +b ẋ:"))),
    # the operator without Rayleigh's term or a force, = 0, cannot give friction: before, right with no flag
    ("d/dt(∂L/∂ẋ) − ∂L/∂x = 0: m ẍ + k x + b ẋ = 0", "undecided",
     ("Your answer says `d/dt(∂L/∂ẋ) − ∂L/∂x = 0` on the way to its equation, which is not Lagrange's"
      " equation. The equation was graded and is right; a person will check this answer.",
      _general_read_past("d/dt(∂L/∂ẋ) − ∂L/∂x = 0:"))),
    ("d/dt(∂L/∂ẋ) − ∂L/∂x = 0, so m ẍ + k x + b ẋ = 0", "undecided",
     ("Your answer says `d/dt(∂L/∂ẋ) − ∂L/∂x = 0` on the way to its equation, which is not Lagrange's"
      " equation. The equation was graded and is right; a person will check this answer.",)),
    ("d/dt(∂L/∂ẋ) − ∂L/∂x = 0 ⇒ m ẍ = −k x − b ẋ", "undecided",
     ("Your answer says `d/dt(∂L/∂ẋ) − ∂L/∂x = 0` on the way to its equation, which is not Lagrange's"
      " equation. The equation was graded and is right; a person will check this answer.",)),
    # with Rayleigh's term: as before
    ("d/dt(∂L/∂ẋ) − ∂L/∂x + ∂F/∂ẋ = 0, so m ẍ + k x + b ẋ = 0", "equivalent", ("Correct.",)),
)  # fmt: skip


@pytest.mark.parametrize(("submitted", "status", "feedback"), GENERAL_FORM_THEN_EQUATION)
def test_lagranges_equation_with_rayleighs_term_on_the_right_then_the_equation_grades_the_equation(
    submitted, status, feedback
):
    verdict = compare("m xddot + b xdot + k x = 0", submitted, kind="equation", **DAMPED)
    assert (verdict.status, verdict.feedback) == (status, feedback)


@pytest.mark.parametrize(
    "submitted",
    [
        # before, `dt` was refused as no derivative the grader could read
        "d(m l^2 thetadot)/dt + m g l sin(theta) = 0",
        "d(m l² θ̇)/dt = −m g l sin θ",
        "dθ̇/dt = −(g/l) sin θ",
    ],
)
def test_d_of_a_bracket_or_of_a_rate_over_dt_is_the_time_derivative(submitted):
    verdict = compare("thetaddot = -g/l sin(theta)", submitted, kind="equation", **PENDULUM)
    assert (verdict.status, verdict.feedback) == ("equivalent", ("Correct.",))


@pytest.mark.parametrize(
    ("submitted", "status"),
    [
        ("θ̈ + ω₀² sin θ = 0, ω₀² = g/l", "equivalent"),
        ("θ̈ + ω₀² sin θ = 0, where ω₀² = g/l", "equivalent"),
        ("ω = √(g/l) and θ̈ = −ω² sin θ", "equivalent"),  # defined first
        (r"\ddot\theta + \omega_0^2 \sin\theta = 0 \quad\text{where}\quad \omega_0^2 = \frac gl", "equivalent"),
        ("θ̈ = −k sin θ, k = a/l, a = g", "equivalent"),  # one definition in terms of another
        ("θ̈ + ω₀² sin θ = 0, ω₀² = l/g", "not_equivalent"),  # a wrong definition is a wrong answer
        ("θ̈ + ω₀² sin θ = 0", "not_equivalent"),  # undefined: said so
        ("θ̈ + ω₀² sin θ = 0, ω₀² = g/r", "not_equivalent"),  # a definition only in the problem's names
    ],
)
def test_a_name_the_answer_defines_is_put_in_place(submitted, status):
    assert compare("thetaddot = -g/l sin(theta)", submitted, kind="equation", **PENDULUM).status == status


def test_a_lagrangian_may_define_its_own_names():
    verdict = compare(L_PENDULUM, "L = ½ m v² + m g h, where v = l θ̇, h = l cos θ", kind="lagrangian", **PENDULUM)
    assert verdict.status == "equivalent"
    assert verdict.answer.read_as_text == "g*l*m*cos(θ) + l^2*m*θ̇^2/2"  # how it was read: with the definitions in place
    # as the notes build it: L from T and V, T from v; and the mistake is still named
    built = "L = T − V, T = ½ m v², V = {} m g l cos θ, v = l θ̇"
    assert compare(L_PENDULUM, built.format("−"), kind="lagrangian", **PENDULUM).status == "equivalent"
    wrong = compare(L_PENDULUM, built.format(""), kind="lagrangian", **PENDULUM)
    assert wrong.feedback == ("It looks like you wrote L = T + V; the Lagrangian is L = T − V.",)


L_EQUAL = (
    "m l^2 theta1dot^2 + 1/2 m l^2 theta2dot^2 + m l^2 theta1dot theta2dot cos(theta1 - theta2)"
    " + 2 m g l cos(theta1) + m g l cos(theta2)"
)
EQUAL = {"coords": ["theta1", "theta2"], "known": ["m", "l", "g"]}
L_EQUAL_DELTA = "m l² θ̇₁² + ½ m l² θ̇₂² + m l² θ̇₁ θ̇₂ cos Δθ + 2 m g l cos θ₁ + m g l cos θ₂"


@pytest.mark.parametrize(
    ("submitted", "status"),
    [
        # before: Δθ was Δ·θ, two names the problem does not define, even where the answer defines Δθ
        (f"L = {L_EQUAL_DELTA}, where Δθ = θ₁ − θ₂", "equivalent"),
        (f"Δθ = θ₁ − θ₂\nL = {L_EQUAL_DELTA.replace('cos Δθ', 'cos(Δθ)')}", "equivalent"),
        (f"L = {L_EQUAL_DELTA.replace('Δθ', 'δθ')}, where δθ = θ₁ − θ₂", "equivalent"),
        (f"L = {L_EQUAL_DELTA}, where Δθ = θ₁ + θ₂", "not_equivalent"),
    ],
)
def test_a_difference_the_answer_defines_is_one_name(submitted, status):
    verdict = compare(L_EQUAL, submitted, kind="lagrangian", **EQUAL)
    assert verdict.status == status, verdict
    assert "not define" not in " ".join(verdict.feedback), verdict
    # where nothing defines it, Δθ is still Δ·θ, which the problem does not define
    verdict = compare(L_EQUAL, L_EQUAL_DELTA, kind="lagrangian", **EQUAL)
    assert verdict.diagnosis == "undefined_symbol", verdict


L_EQUAL_TEX = (
    r"m l^2 \dot\theta_1^2 + \frac12 m l^2 \dot\theta_2^2 + m l^2 \dot\theta_1 \dot\theta_2 \cos\Delta\theta"
    r" + 2 m g l \cos\theta_1 + m g l \cos\theta_2"
)
EOM_EQUAL = (
    "2 l theta1ddot + l theta2ddot cos(theta1 - theta2) + l theta2dot^2 sin(theta1 - theta2) + 2 g sin(theta1) = 0;"
    " l theta2ddot + l theta1ddot cos(theta1 - theta2) - l theta1dot^2 sin(theta1 - theta2) + g sin(theta2) = 0"
)
EOM_EQUAL_TEX = (
    r"2 \ddot\theta_1 + \ddot\theta_2 \cos\Delta\theta + \dot\theta_2^2 \sin\Delta\theta + 2 \frac gl \sin\theta_1 = 0"
    r" \\ \ddot\theta_2 + \ddot\theta_1 \cos\Delta\theta - \dot\theta_1^2 \sin\Delta\theta + \frac gl \sin\theta_2 = 0"
)
DELTA_TEX = r"\Delta\theta = \theta_1 - \theta_2"


@pytest.mark.parametrize(
    ("expected", "kind", "submitted", "status"),
    [
        # before: \cos\Delta\theta was cos(Δ)·θ, and the definition Δ·θ defined nothing
        (L_EQUAL, "lagrangian", rf"{L_EQUAL_TEX}, \text{{ where }} {DELTA_TEX}", "equivalent"),
        (L_EQUAL, "lagrangian", rf"{L_EQUAL_TEX}, \Delta \theta = \theta_1 - \theta_2", "equivalent"),
        (L_EQUAL, "lagrangian", L_EQUAL_TEX.replace(r"\Delta\theta", r"(\Delta\theta)") + f", {DELTA_TEX}",
         "equivalent"),
        (L_EQUAL, "lagrangian", L_EQUAL_TEX.replace(r"\Delta", r"\delta") + r", \delta\theta = \theta_1 - \theta_2",
         "equivalent"),
        (L_EQUAL, "lagrangian", rf"{L_EQUAL_TEX}, \Delta\theta = \theta_1 + \theta_2", "not_equivalent"),
        # the sign of the difference: sin Δθ tells θ₁ − θ₂ from θ₂ − θ₁
        (EOM_EQUAL, "equations", rf"{EOM_EQUAL_TEX} \\ {DELTA_TEX}", "equivalent"),
        (EOM_EQUAL, "equations", rf"{EOM_EQUAL_TEX} \\ \Delta\theta = \theta_2 - \theta_1", "not_equivalent"),
    ],
)  # fmt: skip
def test_a_difference_the_answer_defines_in_tex_is_one_name(expected, kind, submitted, status):
    verdict = compare(expected, submitted, kind=kind, **EQUAL)
    assert verdict.status == status, verdict
    assert "not define" not in " ".join(verdict.feedback), verdict


def test_a_difference_nothing_defines_is_read_in_tex_as_in_unicode():
    # Δ·θ, names the problem does not define; and the argument of cos all of it, as in `cos Δθ`
    tex = compare(L_EQUAL, L_EQUAL_TEX, kind="lagrangian", **EQUAL)
    typed = compare(L_EQUAL, L_EQUAL_DELTA, kind="lagrangian", **EQUAL)
    assert (tex.diagnosis, tex.feedback, tex.read_as) == (typed.diagnosis, typed.feedback, typed.read_as)
    assert "cos(Δ*θ)" in tex.read_as


@pytest.mark.parametrize(
    ("expected", "submitted", "kind", "status"),
    [
        # an expression, unnamed, then the definitions of its names: as the feedback on an undefined name offers
        (L_PENDULUM, "½ m v² + m g l cos θ, where v = l θ̇", "lagrangian", "equivalent"),
        (L_PENDULUM, "½ m v² + m g l cos θ, v = l θ̇", "lagrangian", "equivalent"),
        (L_PENDULUM, "½ m v² + m g l cos θ\nv = l θ̇", "lagrangian", "equivalent"),
        (L_PENDULUM, "½ m v² + m g l cos θ, where v = 2 l θ̇", "lagrangian", "not_equivalent"),
        ("sqrt(g/l)", "ω₀, where ω₀ = √(g/l)", "expression", "equivalent"),
        # an equation is asked for: an expression, whatever it defines, is not one
        (EOM_PENDULUM, "l θ̈ + g s, where s = sin θ", "equation", "not_equivalent"),
        # a definition the expression does not use, or a system's equation without its `=`
        (L_PENDULUM, "½ m l² θ̇² + m g l cos θ, where u = l θ̇", "lagrangian", "invalid"),
        (EOM_PENDULUM, "θ̈ + (g/l) sin θ; θ = 0", "equations", "invalid"),
    ],
)
def test_an_expression_may_be_followed_by_the_definitions_of_its_names(expected, submitted, kind, status):
    verdict = compare(expected, submitted, kind=kind, **PENDULUM)
    assert verdict.status == status, verdict
    if status == "invalid":
        assert verdict.feedback[0].startswith("The first item of your answer has no `=`.")
        assert "answer" not in verdict.read_as  # the parser's name for the expression is not shown


def _words(words):
    return f"Read without the words after it, `{words}`: the formula is what is graded."


def _for_a_person(words):
    return (
        f"Your answer says `{words}` beside the formula. The formula was graded on its own;"
        " a person will read the words against it."
    )


@pytest.mark.parametrize(
    ("expected", "submitted", "kind", "status", "notes"),
    [
        (EOM_PENDULUM, "θ̈ = −(g/l) sin θ for all angles", "equation", "equivalent", (_words("for all angles"),)),
        (EOM_PENDULUM, "So θ̈ = −(g/l) sin θ for all angles", "equation", "equivalent", (_words("for all angles"),)),
        (EOM_PENDULUM, "m l θ̈ = −m g sin θ (Newton)", "equation", "equivalent", (_words("(Newton)"),)),
        (EOM_PENDULUM, "θ̈ + (g/l) sin θ = 0, a nonlinear equation", "equation", "equivalent",
         (_words(", a nonlinear equation"),)),  # from the mark before the words, past their article
        ("sqrt(g/l)", "ω = √(g/l) for small oscillations", "expression", "equivalent",
         (_words("for small oscillations"),)),
        # in TeX, the words in \text{…}: said as they were typed inside the braces, after TeX's space
        (EOM_PENDULUM, r"m l^2 \ddot\theta + m g l \sin\theta = 0 \text{(nonlinear)}", "equation", "equivalent",
         (_words("(nonlinear)"),)),
        ("sqrt(g/l)", r"\omega = \sqrt{g/l}\,\text{for small oscillations}", "expression", "equivalent",
         (_words("for small oscillations"),)),
        ("sqrt(g/l)", r"\omega = \sqrt{g/l} \quad \mbox{for oscillations of a small amplitude, about the bottom}",
         "expression", "equivalent", (_words("for oscillations of a small amplitude, about the bottom"),)),
        # the quantity asked, named (another goes to a person)
        (L_PENDULUM, "L = ½ m l² θ̇² + m g l cos θ, the Lagrangian", "lagrangian", "equivalent",
         (_words(", the Lagrangian"),)),
        # two words joined by a hyphen: before, a minus sign, the words read as typed and the answer wrong
        ("thetaddot = -(g/l) theta", "θ̈ + (g/l) θ = 0 (small-angle approximation)", "equation", "equivalent",
         (_words("(small-angle approximation)"),)),
        (EOM_PENDULUM, "θ̈ + (g/l) sin θ = 0, a non-linear equation", "equation", "equivalent",
         (_words(", a non-linear equation"),)),
        (L_PENDULUM, "L = ½ m l² θ̇² + m g l cos θ (y-axis vertical)", "lagrangian", "equivalent",
         (_words("(y-axis vertical)"),)),
    ],
)  # fmt: skip
def test_words_after_a_formula_are_read_past_and_said_so(expected, submitted, kind, status, notes):
    verdict = compare(expected, submitted, kind=kind, **PENDULUM)
    assert (verdict.status, verdict.notes) == (status, notes)


L_GIVEN = "L = ½ m l² θ̇² + m g l cos θ"
H_PIVOT = "1/2 m l^2 (thetadot^2 + sin(theta)^2 phidot^2) - m g l cos(theta)"  # the zero of potential at the pivot


@pytest.mark.parametrize(
    ("expected", "submitted", "kind", "status", "feedback"),
    [
        # a remark that states the zero of potential energy: before, "Something is missing before `=`"
        (L_PENDULUM, f"{L_GIVEN} (taking V = 0 at the pivot)", "lagrangian", "equivalent",
         ("Correct.", _words("(taking V = 0 at the pivot)"))),
        (L_PENDULUM, f"{L_GIVEN} (with V=0 at the top)", "lagrangian", "equivalent",
         ("Correct.", _words("(with V=0 at the top)"))),
        (L_PENDULUM, f"{L_GIVEN} [V = 0 at pivot].", "lagrangian", "equivalent",
         ("Correct.", _words("[V = 0 at pivot]"))),
        (L_PENDULUM, f"{L_GIVEN}, (taking the pivot as U = 0)", "lagrangian", "equivalent",
         ("Correct.", _words("(taking the pivot as U = 0)"))),
        (L_PENDULUM, r"L = \frac12 m l^2 \dot\theta^2 + m g l\cos\theta \text{ (taking V = 0 at the pivot)}",
         "lagrangian", "equivalent", ("Correct.", _words("(taking V = 0 at the pivot)"))),
        (EOM_PENDULUM, "m l² θ̈ + m g l sin θ = 0 (V = 0 at the pivot)", "equation", "equivalent",
         ("Correct.", _words("(V = 0 at the pivot)"))),
        # or after a comma, where a word begins it: before, V and `taking` undefined
        (L_PENDULUM, f"{L_GIVEN}, taking V = 0 at the pivot", "lagrangian", "equivalent",
         ("Correct.", _words("taking V = 0 at the pivot"))),
        (L_PENDULUM, "L = ½ m l² θ̇² − m g l cos θ, taking V = 0 at the pivot", "lagrangian", "not_equivalent",
         ("It looks like you wrote L = T + V; the Lagrangian is L = T − V.", _words("taking V = 0 at the pivot"))),
        (L_PENDULUM, "½ m l² θ̇² + m g l cos θ, with the pivot at U = 0.", "lagrangian", "equivalent",
         ("Correct.", _words("with the pivot at U = 0"))),
        # words that doubt it: for a person, as after any formula
        (L_PENDULUM, f"{L_GIVEN} (V = 0 at the pivot, I think)", "lagrangian", "undecided",
         (_for_a_person("(V = 0 at the pivot, I think)"),)),
    ],
)  # fmt: skip
def test_a_remark_that_states_the_zero_of_potential_is_read_past(expected, submitted, kind, status, feedback):
    setting = {"coords": ["theta", "phi"], "known": ["m", "g", "l"]} if expected == H_PIVOT else PENDULUM
    verdict = compare(expected, submitted, kind=kind, **setting)
    assert (verdict.status, verdict.feedback) == (status, feedback), verdict


@pytest.mark.parametrize(
    ("expected", "formula", "kind", "coords"),
    [
        (L_PENDULUM, "L = ½ m l² θ̇² + m g l cos θ", "lagrangian", ["theta"]),
        (L_PENDULUM, "L = ½ m l² θ̇² − m g l cos θ", "lagrangian", ["theta"]),  # wrong stays wrong
        (L_PENDULUM, "L = ½ m l θ̇² + m g l cos θ", "lagrangian", ["theta"]),
        # the formula's own zero, which the problem does not take, whatever the remark says
        (H_PIVOT, "½ m l²(θ̇² + sin²θ φ̇²) + m g l (1 − cos θ)", "expression", ["theta", "phi"]),
        (H_PIVOT, "½ m l²(θ̇² + sin²θ φ̇²) − m g l cos θ", "expression", ["theta", "phi"]),
        (EOM_PENDULUM, "m l² θ̈ − m g l sin θ = 0", "equation", ["theta"]),
    ],
)
def test_a_remark_on_the_zero_of_potential_changes_no_grade(expected, formula, kind, coords):
    setting = {"kind": kind, "coords": coords, "known": ["m", "g", "l"]}
    alone = compare(expected, formula, **setting)
    remarked = compare(expected, f"{formula} (taking V = 0 at the pivot)", **setting)
    note = _words("(taking V = 0 at the pivot)")
    assert (remarked.status, remarked.score, remarked.diagnosis) == (alone.status, alone.score, alone.diagnosis)
    assert (remarked.feedback, remarked.notes) == ((*alone.feedback, note), (*alone.notes, note))


@pytest.mark.parametrize(
    "submitted",
    [
        f"{L_GIVEN} (V = 0)",  # no words: a remark is words with the zero in them
        f"{L_GIVEN} (V = 0 or V = m g l)",  # a hedge, and another value
        f"{L_GIVEN} (V = 0 at θ = 0)",  # another `=`, and a number
        f"{L_GIVEN} (θ = 0 at the top)",  # a coordinate's zero may say the formula is other than it reads
        f"{L_GIVEN} (L = 0 at the pivot)",  # not the potential energy
        f"{L_GIVEN} (taking V = 0.5 at the pivot)",
        f"{L_GIVEN} (taking V = 0 at the pivot, times 2)",  # a word of arithmetic
        f"{L_GIVEN} (taking V = 0 at the pivot) (times 2)",  # the last bracket is no remark on the zero
        f"{L_GIVEN} (taking V = 0 at the pivot) + m g l",  # the bracket does not end the answer
        f"{L_GIVEN} (V = 0 at the pivot; V = 0 at the top)",
    ],
)
def test_a_remark_with_an_equals_sign_that_is_not_the_zero_of_potential_is_refused(submitted):
    verdict = compare(L_PENDULUM, submitted, kind="lagrangian", **PENDULUM)
    assert verdict.status == "invalid", verdict


def test_a_remark_on_the_zero_names_no_name_the_problem_has():
    # V is the problem's own here: V = 0 would say something of the formula
    verdict = compare("m g V", "m g V (taking V = 0 at the pivot)", known=["m", "g", "V"])
    assert verdict.status == "invalid", verdict


EOM_SMALL = "thetaddot = -(g/l) theta"
BOTH_FORMS = "θ̈ = −(g/l) sin θ, which for small θ gives θ̈ = −(g/l) θ"
WHICH = "which for small θ gives"


def _small_left_out(words):
    return f"Graded your formula before `{words}`; the small-angle form after it was not graded."


def _full_left_out(words):
    return f"Graded your formula after `{words}`; the full form before it was not graded."


def _forms_for_a_person(words):
    return (
        f"Your formula after `{words}` is not the small-angle form of the one before it, as your words say:"
        " a person will decide which is your answer."
    )


@pytest.mark.parametrize(
    ("expected", "kind", "submitted", "status", "score", "feedback"),
    [
        # the full form asked: the first is the answer, and its small-angle form after it costs nothing
        (EOM_PENDULUM, "equation", BOTH_FORMS, "equivalent", 1, ("Correct.", _small_left_out(WHICH))),
        (EOM_PENDULUM, "equation", "θ̈ = −(g/l) sin θ; for small θ, θ̈ = −(g/l) θ", "equivalent", 1,
         ("Correct.", _small_left_out("for small θ"))),
        (EOM_PENDULUM, "equation", "θ̈ = −(g/l) sin θ. For small angles this becomes θ̈ = −(g/l) θ", "equivalent", 1,
         ("Correct.", _small_left_out("For small angles this becomes"))),
        (L_PENDULUM, "lagrangian", "L = ½ m l² θ̇² + m g l cos θ, which for small θ gives L = ½ m l² θ̇² − ½ m g l θ²",
         "equivalent", 1, ("Correct.", _small_left_out(WHICH))),
        # the small-angle form asked: the last is the answer
        (EOM_SMALL, "equation", BOTH_FORMS, "equivalent", 1, ("Correct.", _full_left_out(WHICH))),
        (EOM_SMALL, "equation", "m l² θ̈ + m g l sin θ = 0, linearized: l θ̈ + g θ = 0", "equivalent", 1,
         ("Correct.", _full_left_out("linearized"))),
        # the one asked wrong, the other right: wrong, and said as of the one asked
        (EOM_PENDULUM, "equation", "θ̈ = (g/l) sin θ, which for small θ gives θ̈ = −(g/l) θ", "not_equivalent", 0,
         ("A term differs: the term in sin(θ) has the wrong sign.", _small_left_out(WHICH))),
        (EOM_SMALL, "equation", "θ̈ = −(g/l) sin θ, which for small θ gives θ̈ = (g/l) θ", "not_equivalent", 0,
         ("A term differs: the gravity term has the wrong sign.", _full_left_out(WHICH))),
        # one right, and the other not its other form as the words say: which is the answer? a person says
        (EOM_PENDULUM, "equation", "θ̈ = −(g/l) sin θ, which for small θ gives θ̈ = (g/l) θ", "undecided", 1,
         (_forms_for_a_person(WHICH),)),
        (EOM_SMALL, "equation", "θ̈ = (g/l) sin θ, which for small θ gives θ̈ = −(g/l) θ", "undecided", 1,
         (_forms_for_a_person(WHICH),)),
        (EOM_PENDULUM, "equation", "θ̈ = −(g/l) θ, which for small θ gives θ̈ = −(g/l) sin θ", "undecided", 1,
         (_forms_for_a_person(WHICH),)),  # the other way round
        # neither right, whichever was meant
        (EOM_PENDULUM, "equation", "θ̈ = (g/l) sin θ, which for small θ gives θ̈ = (g/l) θ", "not_equivalent", 0,
         (f"Neither your formula before `{WHICH}` nor the one after it is right.",)),
        # ≈ between the two, the second's left side the first's (before, refused); or ⇒ and words after it
        # (before, the small-angle form alone was read, and the full form asked for was wrong)
        (EOM_PENDULUM, "equation", "θ̈ = −(g/l) sin θ ≈ −(g/l) θ", "equivalent", 1, ("Correct.", _small_left_out("≈"))),
        (EOM_SMALL, "equation", "θ̈ = −(g/l) sin θ ≈ −(g/l) θ", "equivalent", 1, ("Correct.", _full_left_out("≈"))),
        (EOM_PENDULUM, "equation", r"\ddot\theta = -\frac{g}{l}\sin\theta \approx -\frac{g}{l}\theta", "equivalent",
         1, ("Correct.", _small_left_out("\\approx"))),
        (EOM_PENDULUM, "equation", "θ̈ + (g/l) sin θ = 0 ⇒ θ̈ + (g/l) θ = 0 for small θ", "equivalent", 1,
         ("Correct.", _small_left_out("⇒"))),
        (EOM_PENDULUM, "equation", "θ̈ = −(g/l) cos θ ≈ −(g/l) θ", "not_equivalent", 0,
         ("A term is missing: a term in sin(θ).", "There is a term too many: a term in cos(θ).",
          _small_left_out("≈"))),
    ],
)  # fmt: skip
def test_a_formula_then_its_small_angle_form_is_graded_by_the_one_asked(
    expected, kind, submitted, status, score, feedback
):
    verdict = compare(expected, submitted, kind=kind, **PENDULUM)
    assert (verdict.status, verdict.score, verdict.feedback) == (status, score, feedback), verdict


@pytest.mark.parametrize(
    ("submitted", "status"),
    [
        ("θ̈ = −(g/l) sin θ, or for small θ, θ̈ = −(g/l) θ", "invalid"),  # a hedge: as typed
        ("θ̈ = −(g/l) sin θ, which for large θ gives θ̈ = −(g/l) θ", "not_equivalent"),  # no small angle
        ("θ̈ = −(g/l) sin θ, which for small θ is maybe θ̈ = −(g/l) θ", "not_equivalent"),  # doubt
        ("θ̈ = −(g/l) sin θ, which for small θ times 2 gives θ̈ = −(g/l) θ", "not_equivalent"),  # arithmetic
        ("θ̈ = −(g/l) sin θ, which for small θ gives θ̈ = foo(θ)", "invalid"),  # the other cannot be read
        # ⇒ without words of small angles is a step, whose conclusion is the answer
        ("θ̈ + (g/l) sin θ = 0 ⇒ θ̈ + (g/l) θ = 0", "not_equivalent"),
    ],
)
def test_words_between_two_formulas_that_are_no_small_angle_remark_are_read_as_typed(submitted, status):
    verdict = compare(EOM_PENDULUM, submitted, kind="equation", **PENDULUM)
    assert verdict.status == status, verdict
    assert verdict.method != "forms" and not any("small-angle form" in note for note in verdict.notes), verdict


@pytest.mark.parametrize(
    ("expected", "submitted", "setting", "words"),
    [
        (ATWOOD_A, "(m₁ − m₂) g/(m₁ + m₂) upward", MASSES, "upward"),  # the other sign, in words
        (ATWOOD_A, "(m₁ − m₂) g/(m₁ + m₂), with m₁ going down", MASSES, ", with m₁ going down"),
        (ATWOOD_A, "The acceleration upward is (m₁ − m₂) g/(m₁ + m₂)", MASSES, "The acceleration upward is"),
        ("sqrt(g/l)", "√(g/l) inverted", PENDULUM, "inverted"),
        (L_PENDULUM, "½ m l² θ̇² + m g l cos θ except the cosine is a sine", PENDULUM, "except the cosine is a sine"),
    ],
)
def test_words_that_may_say_otherwise_send_a_right_formula_to_a_person(expected, submitted, setting, words):
    kind = "lagrangian" if expected == L_PENDULUM else "expression"
    verdict = compare(expected, submitted, kind=kind, **setting)
    assert (verdict.status, verdict.score) == ("undecided", 1.0), verdict
    assert verdict.feedback == (_for_a_person(words),)


RAYLEIGH = {"coords": ["x"], "known": ["m", "b", "k"], "name": "F"}


@pytest.mark.parametrize(
    ("submitted", "status", "feedback"),
    [
        # words of arithmetic beside a formula, no sign, number nor name of the problem's: before, read as its
        # factors, each told undefined, and the right formula wrong
        ("b ẋ²/2 (half the power dissipated)", "undecided", (_for_a_person("(half the power dissipated)"),)),
        ("½ b ẋ² times half", "undecided", (_for_a_person("times half"),)),
        ("½ b ẋ², the power over two", "undecided", (_for_a_person(", the power over two"),)),
        ("√(g/l) but negative", "undecided", (_for_a_person("but negative"),)),
        ("b ẋ² (half the power dissipated)", "not_equivalent",
         ("Your answer is off by a constant factor: missing a factor 1/2?",
          "Read without the words `(half the power dissipated)`: the formula is what is graded.")),
    ],
)  # fmt: skip
def test_words_of_arithmetic_beside_a_formula_go_to_a_person(submitted, status, feedback):
    expected, setting = ("sqrt(g/l)", PENDULUM) if "g/l" in submitted else ("1/2 b xdot^2", RAYLEIGH)
    verdict = compare(expected, submitted, **setting)
    assert (verdict.status, verdict.score, verdict.feedback) == (status, float(status == "undecided"), feedback)


@pytest.mark.parametrize(
    ("submitted", "status", "score"),
    [
        # the words after = 0 were 0 times words, so 0, and lost: before, each of these was Correct
        ("θ̈ + (g/l) sin θ = 0 (or minus)", "not_equivalent", 0.0),  # a hedge, as after any other side
        ("θ̈ + (g/l) sin θ = 0 or not", "not_equivalent", 0.0),
        ("θ̈ + (g/l) sin θ = 0 (inverted pendulum)", "undecided", 1.0),
        ("θ̈ + (g/l) sin θ = 0 (θ measured upward)", "undecided", 1.0),
        ("θ̈ + (g/l) sin θ = 0", "equivalent", 1.0),
        ("θ̈ + (g/l) sin θ = 0 (1)", "equivalent", 1.0),  # an equation's number is no word
    ],
)
def test_words_after_a_zero_side_are_not_lost(submitted, status, score):
    verdict = compare("thetaddot = -(g/l) sin(theta)", submitted, kind="equation", **PENDULUM)
    assert (verdict.status, verdict.score) == (status, score), verdict
    if status == "not_equivalent":
        assert "which this problem does not define" in verdict.feedback[0], verdict


def test_a_wrong_formula_with_words_that_may_say_otherwise_is_not_equivalent():
    verdict = compare(ATWOOD_A, "(m₁ + m₂) g/(m₁ − m₂) upward", **MASSES)
    assert (verdict.status, verdict.score) == ("not_equivalent", 0.0)
    assert verdict.notes == ("Read without the words `upward`: the formula is what is graded.",)


@pytest.mark.parametrize(
    ("submitted", "words"),
    [
        # the other sign, and a direction that may be what turns it: before, wrong, "The overall sign is wrong."
        ("-(m₁ − m₂) g/(m₁ + m₂) (upwards)", "(upwards)"),
        ("(m₂ − m₁) g/(m₁ + m₂), directed upward", ", directed upward"),
        ("a = (m₂ − m₁) g/(m₁ + m₂) upwards", "upwards"),
    ],
)
def test_the_opposite_sign_with_words_that_may_turn_it_goes_to_a_person(submitted, words):
    verdict = compare(ATWOOD_A, submitted, **MASSES)
    assert (verdict.status, verdict.score) == ("undecided", 0.0), verdict
    assert verdict.feedback == (
        f"Your formula has the opposite sign, and your answer says `{words}` beside it: a person will read"
        " whether the words turn the sign.",
    )
    # without the words, the sign is wrong
    assert compare(ATWOOD_A, submitted.replace(words, ""), **MASSES).diagnosis == "sign"


@pytest.mark.parametrize(
    ("submitted", "status", "feedback"),
    [
        # words that doubt the formula are read past, for a person, whatever else they say in words:
        # before, `sign` in them was told as a function without its argument
        ("m l² θ̈ + m g l sin θ = 0 (not sure about the sign)", "undecided",
         (_for_a_person("(not sure about the sign)"),)),
        ("θ̈ = −(g/l) sin θ (not sure about the sign, maybe minus)", "undecided",
         (_for_a_person("(not sure about the sign, maybe minus)"),)),
        ("θ̈ = −(g/l) sin θ, or the other sign, I think", "undecided",
         (_for_a_person(", or the other sign, I think"),)),
        ("θ̈ + (g/l) sin θ = 0 (maybe)", "undecided", (_for_a_person("(maybe)"),)),
        (r"\ddot\theta + \frac gl \sin\theta = 0 \quad \text{(not sure about the sign)}", "undecided",
         (_for_a_person("(not sure about the sign)"),)),
        ("Not sure, but the equation of motion is θ̈ = −(g/l) sin θ", "undecided",
         (_for_a_person("Not sure, but the equation of motion is"),)),
        # words that deny, with no "or" nor arithmetic: before, read as typed, `not` undefined and the answer wrong
        ("θ̈ = −(g/l) sin θ (not small angles)", "undecided", (_for_a_person("(not small angles)"),)),
        ("θ̈ = −(g/l) sin θ, not linearized", "undecided", (_for_a_person(", not linearized"),)),
        ("m l² θ̈ + m g l sin θ = 0 (friction is not included)", "undecided",
         (_for_a_person("(friction is not included)"),)),
        # a wrong formula is graded as written, and the words said to be read past
        ("m l² θ̈ − m g l sin θ = 0 (not sure about the sign)", "not_equivalent",
         ("A term differs: the term in sin(θ) has the wrong sign.",
          "Read without the words `(not sure about the sign)`: the formula is what is graded.")),
        # a remark in brackets that denies a formula: before, read as typed, T, V and `not` undefined
        ("θ̈ = −(g/l) sin θ (not −(g/l) θ)", "undecided", (_for_a_person("(not −(g/l) θ)"),)),
        ("m l² θ̈ + m g l sin θ = 0 (not m l² θ̈ − m g l sin θ = 0)", "undecided",
         (_for_a_person("(not m l² θ̈ − m g l sin θ = 0)"),)),
        ("θ̈ + (g/l) θ = 0 (not small angles)", "not_equivalent",
         ("You used the small-angle approximation, but the full answer is asked for here.",
          "Read without the words `(not small angles)`: the formula is what is graded.")),
    ],
)  # fmt: skip
def test_words_that_doubt_a_formula_send_it_to_a_person(submitted, status, feedback):
    verdict = compare(EOM_PENDULUM, submitted, kind="equation", **PENDULUM)
    assert (verdict.status, verdict.score, verdict.feedback) == (status, float(status == "undecided"), feedback)


@pytest.mark.parametrize(
    ("submitted", "status"),
    [
        ("½ m l² θ̇² + m g l cos θ up to a constant", "equivalent"),  # "up to" says nothing of the sign
        ("½ m l² θ̇² + m g l cos θ (Lagrange)", "equivalent"),
        ("½ m l² θ̇² + m g l floor(θ)", "invalid"),  # a function we do not know, not words
        ("½ m l² θ̇² + m g l cos θ + m g l Re(θ)", "invalid"),
    ],
)
def test_words_against_a_bracket_are_a_function_not_prose(submitted, status):
    verdict = compare(L_PENDULUM, submitted, kind="lagrangian", **PENDULUM)
    assert verdict.status == status, verdict


@pytest.mark.parametrize(
    "submitted",
    [
        "√(g/l) times l",  # a word of arithmetic: the words may be part of the formula
        "√(g/l) or √(l/g)",  # a hedge
        "√(g/l) for angles below 10 degrees",  # a number
    ],
)
def test_words_that_may_be_part_of_the_formula_are_not_read_past(submitted):
    verdict = compare("sqrt(g/l)", submitted, **PENDULUM)
    assert verdict.diagnosis == "undefined_symbol"
    assert not verdict.notes


def _before(words):
    return f"Read without the words before it, `{words}`: the formula is what is graded."


@pytest.mark.parametrize(
    ("expected", "submitted", "kind", "status", "notes"),
    [
        (EOM_PENDULUM, "The equation of motion is m l θ̈ = −m g sin θ", "equation", "equivalent",
         (_before("The equation of motion is"),)),  # a name of the problem's after the words: not a label
        (EOM_PENDULUM, "So the EOM is θ̈ = −(g/l) sin θ for all angles", "equation", "equivalent",
         (_before("So the EOM is"), _words("for all angles"))),
        (EOM_PENDULUM, "Equation of motion: θ̈ = −(g/l) sin θ", "equation", "equivalent", ()),  # the parser's label
        (EOM_PENDULUM, r"\text{The equation of motion is } ml\ddot\theta = -mg\sin\theta", "equation", "equivalent",
         (_before("The equation of motion is"),)),
        ("sqrt(g/l)", "The angular frequency is √(g/l)", "expression", "equivalent",
         (_before("The angular frequency is"),)),
        ("sqrt(g/l)", "Hence we get √(g/l)", "expression", "equivalent", (_before("Hence we get"),)),
        # the frequency labelled by its square, as ω² = g/l alone is read (its root): before, read as g/l, and
        # `squared`, a word of arithmetic, kept the words from being read past
        ("sqrt(g/l)", "The frequency is ω² = g/l", "expression", "equivalent", (_before("The frequency is"),)),
        ("sqrt(g/l)", "The frequency is ω² = l/g", "expression", "not_equivalent", (_before("The frequency is"),)),
        ("sqrt(g/l)", "The frequency squared is ω² = g/l", "expression", "equivalent",
         (_before("The frequency squared is"),)),
        ("sqrt(g/l)", "The frequency squared is ω² = l/g", "expression", "not_equivalent",
         (_before("The frequency squared is"),)),
        # a method's name before an equation names no quantity the part asks for
        (EOM_PENDULUM, "From energy conservation, θ̈ + (g/l) sin θ = 0", "equation", "equivalent",
         (_before("From energy conservation,"),)),
        (L_PENDULUM, "The Lagrangian is ½ m l² θ̇² − m g l cos θ", "lagrangian", "not_equivalent",
         (_before("The Lagrangian is"),)),  # the formula judged, the mistake named
        # words before and a remark after: before, the remark was left out and the words kept, undefined
        (L_PENDULUM, "The Lagrangian is ½ m l² θ̇² + m g l cos θ (taking V = 0 at the pivot)", "lagrangian",
         "equivalent", (_before("The Lagrangian is"), _words("(taking V = 0 at the pivot)"))),
        # a labelled formula after a sentence that names one of the problem's names: before, all read as one
        # product, the label with the words, and marked wrong
        ("m l^2 thetadot", "The momentum conjugate to θ is p_θ = m l² θ̇", "expression", "equivalent",
         (_before("The momentum conjugate to θ is"),)),
        ("m l^2 thetadot", "The momentum conjugate to θ is p_θ = m l θ̇", "expression", "not_equivalent",
         (_before("The momentum conjugate to θ is"),)),
        # another quantity named before the label, for a person to read: before, Correct, the words a factor of L
        (L_PENDULUM, "The Hamiltonian is L = ½ m l² θ̇² + m g l cos θ", "lagrangian", "undecided", ()),
        # words before a labelled formula and after it: before, refused for the comma, the label undefined
        (L_PENDULUM, "The Lagrangian is L = ½ m l² θ̇² + m g l cos θ, as asked", "lagrangian", "equivalent",
         (_before("The Lagrangian is"), _words(", as asked"))),
        ("m l^2 thetadot", "The momentum is p_θ = m l² θ̇, which is conserved.", "expression", "equivalent",
         (_before("The momentum is"), _words(", which is conserved."))),
        ("m l^2 thetadot", "The momentum is p_θ = m l θ̇, which is conserved.", "expression", "not_equivalent",
         (_before("The momentum is"), _words(", which is conserved."))),
        # a method in words, then a comma: before, the words were a list's first item, with no `=`
        (EOM_PENDULUM, "From the Euler–Lagrange equation, m l² θ̈ + m g l sin θ = 0", "equation", "equivalent",
         (_before("From the Euler–Lagrange equation,"),)),
        (EOM_PENDULUM, "Using the Euler-Lagrange equations, m l² θ̈ + m g l sin θ = 0", "equation", "equivalent",
         (_before("Using the Euler-Lagrange equations,"),)),  # the name's hyphen is no minus sign
        (EOM_PENDULUM, "By Lagrange's equation, θ̈ = −(g/l) sin θ", "equation", "equivalent",
         (_before("By Lagrange's equation,"),)),
        (EOM_PENDULUM, "From the Euler–Lagrange equation, m l² θ̈ − m g l sin θ = 0", "equation", "not_equivalent",
         (_before("From the Euler–Lagrange equation,"),)),
        # the Euler–Lagrange operator set to zero, then the equation it gives: before, `:` was refused
        (EOM_PENDULUM, "Applying d/dt(∂L/∂θ̇) − ∂L/∂θ = 0: m l² θ̈ + m g l sin θ = 0", "equation", "equivalent",
         (_before("Applying d/dt(∂L/∂θ̇) − ∂L/∂θ = 0:"),)),
        (EOM_PENDULUM, "Applying d/dt(∂L/∂θ̇) − ∂L/∂θ = 0, we get θ̈ = −(g/l) θ", "equation", "not_equivalent",
         (_before("Applying d/dt(∂L/∂θ̇) − ∂L/∂θ = 0, we get"),)),
        (EOM_PENDULUM, "d/dt(∂L/∂θ̇) − ∂L/∂θ = 0\nm l² θ̈ − m g l sin θ = 0", "equation", "not_equivalent",
         (_before("d/dt(∂L/∂θ̇) − ∂L/∂θ = 0"),)),
        # q for any coordinate; and a wrong equation is wrong, whatever the operator before it
        (EOM_PENDULUM, "Using d/dt(∂L/∂q̇) − ∂L/∂q = 0 we get m l² θ̈ + m g l sin θ = 0", "equation", "equivalent",
         (_before("Using d/dt(∂L/∂q̇) − ∂L/∂q = 0 we get"),)),
        (EOM_PENDULUM, "Using d/dt(∂V/∂θ̇) − ∂V/∂θ = 0 we get m l² θ̈ − m g l sin θ = 0", "equation",
         "not_equivalent", (_before("Using d/dt(∂V/∂θ̇) − ∂V/∂θ = 0 we get"),)),
    ],
)  # fmt: skip
def test_words_before_a_formula_are_read_past_and_said_so(expected, submitted, kind, status, notes):
    verdict = compare(expected, submitted, kind=kind, **PENDULUM)
    assert (verdict.status, verdict.notes) == (status, notes)
    assert not notes or verdict.feedback[-len(notes) :] == notes


@pytest.mark.parametrize(
    "submitted",
    [
        "The angular frequency is not √(g/l)",  # a hedge
        "The frequency is 2 times √(g/l)",  # a word of arithmetic after the words
        "The frequency is √(g/l) or √(l/g)",
        "The frequency over 2 is √(g/l)",  # a number among the words
        "m is the mass and √(g/l) it is",  # the problem's name first: not a sentence leading to a formula
    ],
)
def test_words_before_a_formula_that_may_be_part_of_it_are_not_read_past(submitted):
    verdict = compare("sqrt(g/l)", submitted, **PENDULUM)
    assert verdict.status != "equivalent"
    assert not verdict.notes


EOM_TYPED = "m l² θ̈ + m g l sin θ = 0"


def _operator(operator):
    return (
        f"Your answer says `{operator} = 0` on the way to its equation, which is not Lagrange's equation. The"
        " equation was graded and is right; a person will check this answer."
    )


@pytest.mark.parametrize(
    ("submitted", "status", "feedback"),
    [
        # another operator than Lagrange's, read past: before, Correct
        (f"Using d/dt(∂V/∂θ̇) − ∂V/∂θ = 0 we get {EOM_TYPED}", "undecided",
         (_operator("d/dt(∂V/∂θ̇) − ∂V/∂θ"), _before("Using d/dt(∂V/∂θ̇) − ∂V/∂θ = 0 we get"))),
        (f"Using d/dt(∂H/∂θ̇) − ∂H/∂θ = 0 we get {EOM_TYPED}", "undecided",
         (_operator("d/dt(∂H/∂θ̇) − ∂H/∂θ"), _before("Using d/dt(∂H/∂θ̇) − ∂H/∂θ = 0 we get"))),
        (f"Using d/dt(∂T/∂θ̇) − ∂T/∂θ = 0 we get {EOM_TYPED}", "undecided",
         (_operator("d/dt(∂T/∂θ̇) − ∂T/∂θ"), _before("Using d/dt(∂T/∂θ̇) − ∂T/∂θ = 0 we get"))),
        (f"Applying d/dt(∂L/∂θ) − ∂L/∂θ̇ = 0: {EOM_TYPED}", "undecided",  # θ and θ̇ swapped
         (_operator("d/dt(∂L/∂θ) − ∂L/∂θ̇"), _before("Applying d/dt(∂L/∂θ) − ∂L/∂θ̇ = 0:"))),
        # a plus between the terms: before, refused for its colon, or for ∂ outside a name
        (f"Applying d/dt(∂L/∂θ̇) + ∂L/∂θ = 0: {EOM_TYPED}", "undecided",
         (_operator("d/dt(∂L/∂θ̇) + ∂L/∂θ"), _before("Applying d/dt(∂L/∂θ̇) + ∂L/∂θ = 0:"))),
        (f"d/dt(∂L/∂θ̇) + ∂L/∂θ = {EOM_TYPED}", "undecided",
         (_operator("d/dt(∂L/∂θ̇) + ∂L/∂θ"), _before("d/dt(∂L/∂θ̇) + ∂L/∂θ ="))),
        # as the parser reads it before the equation it comes to: before, Correct
        (f"d/dt(∂L/∂θ) − ∂L/∂θ̇ = {EOM_TYPED}", "undecided", (_operator("d/dt(∂L/∂θ) − ∂L/∂θ̇"),)),
        # the true operator in other spellings and orders: before, refused for their colon or comma
        ("Applying d/dt(dL/dthetadot) - dL/dtheta = 0: m l^2 thetaddot + m g l sin(theta) = 0", "equivalent",
         ("Correct.", _before("Applying d/dt(dL/dthetadot) - dL/dtheta = 0:"))),
        (f"Applying ∂L/∂θ − d/dt(∂L/∂θ̇) = 0: {EOM_TYPED}", "equivalent",
         ("Correct.", _before("Applying ∂L/∂θ − d/dt(∂L/∂θ̇) = 0:"))),
        (f"d/dt(∂L/∂θ̇) − ∂L/∂θ = 0, {EOM_TYPED}", "equivalent",
         ("Correct.", _before("d/dt(∂L/∂θ̇) − ∂L/∂θ = 0,"))),
        # the operator on a line of its own, then the equation: before, refused ("the first item has no `=`")
        (f"d/dt(∂L/∂θ̇) − ∂L/∂θ = 0\n{EOM_TYPED}", "equivalent", ("Correct.", _before("d/dt(∂L/∂θ̇) − ∂L/∂θ = 0"))),
        (f"d/dt(∂V/∂θ̇) − ∂V/∂θ = 0\n{EOM_TYPED}", "undecided",
         (_operator("d/dt(∂V/∂θ̇) − ∂V/∂θ"), _before("d/dt(∂V/∂θ̇) − ∂V/∂θ = 0"))),
        # a method in words that hands over, or with a unit's name in it: before, refused
        ("From the Euler-Lagrange equation, it follows that m l^2 thetaddot + m g l sin(theta) = 0", "equivalent",
         ("Correct.", _before("From the Euler-Lagrange equation, it follows that"))),
        ("From Newton's second law, m l θ̈ = −m g sin θ", "equivalent",
         ("Correct.", _before("From Newton's second law,"))),
    ],
)  # fmt: skip
def test_lagranges_equation_before_an_equation_is_read_past_only_when_it_is_the_true_one(submitted, status, feedback):
    verdict = compare(EOM_PENDULUM, submitted, kind="equation", **PENDULUM)
    assert (verdict.status, verdict.score, verdict.feedback) == (status, 1.0, feedback), verdict


@pytest.mark.parametrize(
    ("operator", "coords", "judged"),
    [
        ("d/dt(∂L/∂θ̇) − ∂L/∂θ", ["theta"], True),
        ("-d/dt(∂L/∂θ̇) + ∂L/∂θ", ["theta"], True),  # either sign
        (r"\frac{d}{dt}\left(\frac{\partial L}{\partial\dot\theta}\right) - \frac{\partial L}{\partial\theta}",
         ["theta"], True),
        ("d/dt(dL/dθ̇) − dL/dθ", ["theta"], True),
        ("d/dt(∂L/∂ẋ) − ∂L/∂x + ∂F/∂ẋ", ["x"], True),  # Rayleigh's dissipation function
        ("d/dt(∂L/∂ẋ) − ∂L/∂x − ∂F/∂ẋ", ["x"], False),
        ("d/dt(∂L/∂φ̇) − ∂L/∂φ", ["theta"], False),  # not a coordinate of the problem
        ("d/dt(∂L/∂θ̇) − ∂L/∂θ̇", ["theta"], False),
        ("d/dt(∂L/∂θ̇) − ∂V/∂θ", ["theta"], False),
        # not of Lagrange's shape: a momentum, a conserved momentum's rate, a product
        ("∂L/∂θ̇", ["theta"], None),
        ("d/dt(∂L/∂φ̇)", ["phi"], None),
        ("d/dt(∂L/∂θ̇) ∂L/∂θ", ["theta"], None),
        ("m l² θ̈", ["theta"], None),
    ],
)  # fmt: skip
def test_the_euler_lagrange_operator_is_told_from_another_of_its_shape(operator, coords, judged):
    assert euler_lagrange(operator, coords) is judged


L_RIGHT = "L = ½ m l² θ̇² + m g l cos θ"
EOM_RIGHT = "m l^2 thetaddot + m g l sin(theta) = 0"
FROM_EULER_LAGRANGE = "From the Euler-Lagrange equation,"


@pytest.mark.parametrize(
    ("expected", "submitted", "feedback"),
    [
        # words that say the formula is false, or a slip: before, each of these was Correct
        (L_PENDULUM, f"{L_RIGHT}, which is false", (_for_a_person(", which is false"),)),
        (L_PENDULUM, f"{L_RIGHT} (false)", (_for_a_person("(false)"),)),
        (L_PENDULUM, f"{L_RIGHT}, which is incorrect", (_for_a_person(", which is incorrect"),)),
        (L_PENDULUM, f"{L_RIGHT}, which is invalid", (_for_a_person(", which is invalid"),)),
        (L_PENDULUM, f"{L_RIGHT} (sign error)", (_for_a_person("(sign error)"),)),
        (L_PENDULUM, f"{L_RIGHT}, but the sign is off", (_for_a_person(", but the sign is off"),)),
        (L_PENDULUM, f"{L_RIGHT} (I copied this)", (_for_a_person("(I copied this)"),)),
        # words that say it is another quantity than the one asked
        (L_PENDULUM, f"{L_RIGHT}, which is the Hamiltonian", (_for_a_person(", which is the Hamiltonian"),)),
        (L_PENDULUM, f"{L_RIGHT}, i.e. the Hamiltonian", (_for_a_person(", i.e. the Hamiltonian"),)),
        (L_PENDULUM, f"{L_RIGHT}, which is the total energy", (_for_a_person(", which is the total energy"),)),
        (L_PENDULUM, "The Hamiltonian is ½ m l² θ̇² + m g l cos θ", (_for_a_person("The Hamiltonian is"),)),
        (L_PENDULUM, "The energy is ½ m l² θ̇² + m g l cos θ", (_for_a_person("The energy is"),)),
        # after a sentence that leads to the formula, and after a zero side, as anywhere
        (EOM_PENDULUM, f"{EOM_RIGHT}, which is false", (_for_a_person(", which is false"),)),
        (EOM_PENDULUM, f"{FROM_EULER_LAGRANGE} {EOM_RIGHT}, which is false",
         (_for_a_person(", which is false"), _before(FROM_EULER_LAGRANGE))),
        (EOM_PENDULUM, f"{FROM_EULER_LAGRANGE} {EOM_RIGHT} is wrong",  # before, `0 · is · wrong` was 0
         (_for_a_person("is wrong"), _before(FROM_EULER_LAGRANGE))),
    ],
)  # fmt: skip
def test_words_that_disown_a_formula_or_name_another_quantity_send_it_to_a_person(expected, submitted, feedback):
    kind = "lagrangian" if expected == L_PENDULUM else "equation"
    verdict = compare(expected, submitted, kind=kind, **PENDULUM)
    assert (verdict.status, verdict.score, verdict.feedback) == ("undecided", 1.0, feedback), verdict


T_PENDULUM = "1/2 m l^2 thetadot^2"
V_PENDULUM = "-m g l cos(theta)"
KINETIC, POTENTIAL = {"name": ["T", "K"]}, {"name": ["V", "U"]}


@pytest.mark.parametrize(
    ("expected", "submitted", "options", "status", "feedback"),
    [
        # "kinetic energy" names T, "potential energy" V: before, each was read as the energy E, for a person
        (T_PENDULUM, "The kinetic energy is T = ½ m l² θ̇²", KINETIC, "equivalent",
         ("Correct.", _before("The kinetic energy is"))),
        (V_PENDULUM, "The potential energy is −m g l cos θ", POTENTIAL, "equivalent",
         ("Correct.", _before("The potential energy is"))),
        # the other energy, or the kind's own quantity, named for the formula: still for a person
        (T_PENDULUM, "The potential energy is ½ m l² θ̇²", KINETIC, "undecided",
         (_for_a_person("The potential energy is"),)),
        (V_PENDULUM, "The kinetic energy is −m g l cos θ", POTENTIAL, "undecided",
         (_for_a_person("The kinetic energy is"),)),
        (L_PENDULUM, "The kinetic energy is ½ m l² θ̇² + m g l cos θ", {"kind": "lagrangian"}, "undecided",
         (_for_a_person("The kinetic energy is"),)),
    ],
)  # fmt: skip
def test_a_sentence_naming_the_energy_asked_for_is_read_past(expected, submitted, options, status, feedback):
    verdict = compare(expected, submitted, **PENDULUM, **options)
    assert (verdict.status, verdict.score, verdict.feedback) == (status, 1.0, feedback), verdict


H_PENDULUM = "1/2 m l^2 thetadot^2 - m g l cos(theta)"
ATWOOD = {"coords": ["x"], "known": ["m1", "m2", "g"]}
L_ATWOOD = "1/2 (m1 + m2) xdot^2 + (m1 - m2) g x"


@pytest.mark.parametrize(
    ("expected", "submitted", "setting", "kind", "status"),
    [
        # l, the string's length: m₂g(l − x) holds the constant m₂gl
        (L_ATWOOD, "L = ½(m₁+m₂)ẋ² + m₁gx + m₂g(l−x)", ATWOOD, "lagrangian", "equivalent"),
        (L_ATWOOD, "½(m₁+m₂)ẋ² + m₁gx − m₂g(l−x)", ATWOOD, "lagrangian", "not_equivalent"),  # still judged
        (L_PENDULUM, "½ m l² θ̇² + m g (l cos θ − h)", PENDULUM, "lagrangian", "equivalent"),
        (H_PENDULUM, "½ m l² θ̇² − m g l (cos θ − h)", PENDULUM, "expression", "equivalent"),
    ],
)
def test_a_name_found_only_in_constant_terms_is_a_constant_where_one_is_allowed(
    expected, submitted, setting, kind, status
):
    options = {"up_to_constant": True} if kind == "expression" else {}
    verdict = compare(expected, submitted, kind=kind, **setting, **options)
    assert verdict.status == status, verdict
    assert "appears only in a term with no coordinate or velocity" in verdict.notes[0]
    assert "l" in verdict.read_as.replace("l*", "") or "h" in verdict.read_as  # shown with the constant, as typed


UNSURE = "Your answer was judged with {} as a constant; if `{}` changes with the motion"


@pytest.mark.parametrize(
    ("expected", "submitted", "setting", "kind", "score", "name"),
    [
        # y, the height of m₂, is l − x: two potential energies of one mass, not a constant
        (L_ATWOOD, "½ (m₁ + m₂) ẋ² + (m₁ − m₂) g x − m₂ g y", ATWOOD, "lagrangian", 1.0, "y"),
        (L_PENDULUM, "½ m l² θ̇² + m g l cos θ − m g z", PENDULUM, "lagrangian", 1.0, "z"),
        (L_PENDULUM, "½ m l² θ̇² + m g l cos θ + m g l φ", PENDULUM, "lagrangian", 1.0, "φ"),
        (H_PENDULUM, "½ m l² θ̇² − m g l cos θ + m g h", PENDULUM, "expression", 1.0, "h"),
        (L_PENDULUM, "m l² θ̇² + 2 m g l cos θ − m g z", PENDULUM, "lagrangian", 0.5, "z"),  # 2(T − V): its half
    ],
)
def test_a_name_only_in_terms_of_its_own_may_move_with_the_system_so_a_person_decides(
    expected, submitted, setting, kind, score, name
):
    options = {"up_to_constant": True} if kind == "expression" else {}
    verdict = compare(expected, submitted, kind=kind, **setting, **options)
    assert (verdict.status, verdict.score) == ("undecided", score), verdict
    assert UNSURE.format("it", name) in verdict.feedback[0]
    assert verdict.feedback[-1].endswith("A person will check this answer.") or score < 1
    assert len(verdict.feedback) == (1 if score == 1 else 2)  # the credit proposed, and why
    assert name in verdict.read_as  # shown as typed


@pytest.mark.parametrize(
    "submitted",
    [
        "½ (m₁ + m₂) ẋ² + (m₁ + m₂) g x − m₂ g y",
        # m₂'s height, not written in x: wrong with y a constant, and y is most likely no constant
        "½ (m₁ + m₂) ẋ² + m₁ g x − m₂ g y",
    ],
)
def test_an_answer_wrong_whatever_its_own_name_stands_for_names_it_as_undefined(submitted):
    verdict = compare(L_ATWOOD, submitted, kind="lagrangian", **ATWOOD)
    assert (verdict.status, verdict.score, verdict.diagnosis) == ("not_equivalent", 0.0, "undefined_symbol"), verdict
    assert verdict.feedback[0].startswith("Your answer uses `y`, which this problem does not define")
    assert len(verdict.feedback) == 1  # not also judged with y as a constant
    assert "y" in verdict.read_as


@pytest.mark.parametrize(
    ("expected", "submitted", "setting", "kind", "options"),
    [
        (L_ATWOOD, "½(m₁+m₂)ẋ² + (m₁−m₂)g x + m₂ g l ẋ", ATWOOD, "lagrangian", {}),  # l with a velocity
        (L_ATWOOD, "½(m₁+m₂)ẋ² + (m₁−m₂)g x + l", ATWOOD, "expression", {}),  # no constant allowed
        (L_PENDULUM, "L = T − V", PENDULUM, "lagrangian", {}),  # T and V alone: quantities, not constants
        (L_PENDULUM, "½ m v² + m g l cos θ", PENDULUM, "lagrangian", {}),  # v, a speed: squared, not a constant
        (L_PENDULUM, "½ m l² θ̇² + m g l cos θ + ½ m v²", PENDULUM, "lagrangian", {}),  # not left out either
        (H_PENDULUM, "½ m l² θ̇² − m g l cos θ + m g h", PENDULUM, "expression", {}),
        (H_PENDULUM, "½ m l² θ̇² − m g l cos(θ + h)", PENDULUM, "expression", {"up_to_constant": True}),
    ],
)
def test_a_name_that_is_not_only_in_constant_terms_is_undefined(expected, submitted, setting, kind, options):
    verdict = compare(expected, submitted, kind=kind, **setting, **options)
    assert verdict.diagnosis == "undefined_symbol", verdict
    assert not verdict.notes


MOTION_LEFT_OUT = (
    "The equation of motion after your Lagrangian was not graded: the Lagrangian is what is asked for here."
)


_OTHER_LEFT_OUT = "The line that defines `{}` was not graded: L is what is asked for here."


def _working(*names):
    if len(names) == 1:
        return f"The line that defines `{names[0]}` was read as your working, not as your answer."
    listed = " and ".join(f"`{name}`" for name in names)
    return f"The lines that define {listed} were read as your working, not as your answer."


@pytest.mark.parametrize(
    ("expected", "submitted", "kind", "status", "notes"),
    [
        (L_PENDULUM, "T = ½ m l² θ̇²; V = −m g l cos θ; L = ½ m l² θ̇² + m g l cos θ", "lagrangian", "equivalent",
         (_working("T", "V"),)),
        # L = T − V = …: the parser keeps the last side, so T and V are used by no other line
        (L_PENDULUM, "T = ½ m l² θ̇², V = −m g l cos θ, L = T − V = ½ m l² θ̇² + m g l cos θ", "lagrangian",
         "equivalent", (_working("T", "V"),)),
        (EOM_PENDULUM, "L = ½ m l² θ̇² + m g l cos θ; m l² θ̈ + m g l sin θ = 0", "equation", "equivalent",
         (_working("L"),)),
        (EOM_PENDULUM, "m l² θ̈ + m g l sin θ = 0\nL = ½ m l² θ̇² + m g l cos θ", "equations", "equivalent",
         (_working("L"),)),
        (H_PENDULUM, "L = ½ m l² θ̇² + m g l cos θ; H = ½ m l² θ̇² − m g l cos θ", "expression", "equivalent",
         (_working("L"),)),
        # a derivation's steps that define what its conclusion uses
        (L_PENDULUM, "T = ½ m l² θ̇², V = −m g l cos θ, so L = T − V", "lagrangian", "equivalent", ()),
        # the answer is graded, not the working: right working does not rescue a wrong answer
        (EOM_PENDULUM, "L = ½ m l² θ̇² + m g l cos θ; θ̈ = (g/l) sin θ", "equation", "not_equivalent",
         (_working("L"),)),
        (L_PENDULUM, "T = ½ m l² θ̇²; V = m g l cos θ; L = ½ m l² θ̇² − m g l cos θ", "lagrangian", "not_equivalent",
         (_working("T", "V"),)),
        # the equations derived after the Lagrangian asked for: L was told it is undefined
        (L_PENDULUM, "L = ½ m l² θ̇² + m g l cos θ; m l² θ̈ + m g l sin θ = 0", "lagrangian", "equivalent",
         (MOTION_LEFT_OUT,)),
        (L_PENDULUM, "T = ½ m l² θ̇²; V = −m g l cos θ; L = ½ m l² θ̇² + m g l cos θ\nm l² θ̈ + m g l sin θ = 0\n"
         "θ̈ = −(g/l) sin θ", "lagrangian", "equivalent",
         (_working("T", "V"), MOTION_LEFT_OUT.replace("equation", "equations").replace("was", "were"))),
        (L_PENDULUM, "L = ½ m l² θ̇² − m g l cos θ; m l² θ̈ − m g l sin θ = 0", "lagrangian", "not_equivalent",
         (MOTION_LEFT_OUT,)),
        # so after a step, ⇒ or `so`: before, the equation after it was graded as the Lagrangian, wrong
        (L_PENDULUM, "L = ½ m l² θ̇² + m g l cos θ, so m l² θ̈ = −m g l sin θ", "lagrangian", "equivalent",
         (MOTION_LEFT_OUT,)),
        (L_PENDULUM, "L = ½ m l² θ̇² − m g l cos θ, so m l² θ̈ = −m g l sin θ", "lagrangian", "not_equivalent",
         (MOTION_LEFT_OUT,)),
        (L_PENDULUM, "L = ½ m l² θ̇² + m g l cos θ ⇒ θ̈ = −(g/l) sin θ", "lagrangian", "equivalent",
         (MOTION_LEFT_OUT,)),
        (L_PENDULUM, "L = ½ m l² θ̇² + m g l ⇒ θ̈ = −(g/l) sin θ", "lagrangian", "not_equivalent",
         (MOTION_LEFT_OUT,)),
        (L_PENDULUM, r"L = \frac12 m l^2 \dot\theta^2 + m g l \cos\theta \implies m l^2 \ddot\theta = -m g l \sin\theta"
         r" \Rightarrow \ddot\theta = -\frac{g}{l} \sin\theta", "lagrangian", "equivalent",
         (MOTION_LEFT_OUT.replace("equation", "equations").replace("was", "were"),)),
        # a quantity of its own derived after a step: before, the momentum was graded as the Lagrangian, wrong
        (L_PENDULUM, "L = ½ m l² θ̇² + m g l cos θ ⇒ p = m l² θ̇", "lagrangian", "equivalent",
         (_OTHER_LEFT_OUT.format("p"),)),
        (L_PENDULUM, "L = ½ m l² θ̇² − m g l cos θ ⇒ p = m l² θ̇", "lagrangian", "not_equivalent",
         (_OTHER_LEFT_OUT.format("p"),)),
        (L_PENDULUM, "L = 1/2 m l^2 thetadot^2 + m g l cos(theta), hence p_theta = m l^2 thetadot", "lagrangian",
         "equivalent", (_OTHER_LEFT_OUT.format("p_θ"),)),
        # a quantity, then the equation of motion: before, L and p were told undefined
        (L_PENDULUM, "L = 1/2 m l^2 thetadot^2 + m g l cos(theta); p = m l^2 thetadot; m l^2 thetaddot = -m g l"
         " sin(theta)", "lagrangian", "equivalent", (_OTHER_LEFT_OUT.format("p"), MOTION_LEFT_OUT)),
        (L_PENDULUM, "L = ½ m l² θ̇² + m g l cos θ ⇒ p_θ = m l² θ̇ ⇒ θ̈ = −(g/l) sin θ", "lagrangian", "equivalent",
         (_OTHER_LEFT_OUT.format("p_θ"), MOTION_LEFT_OUT)),
        (L_PENDULUM, "L = ½ m l² θ̇² − m g l cos θ; p = m l² θ̇; m l² θ̈ = −m g l sin θ", "lagrangian",
         "not_equivalent", (_OTHER_LEFT_OUT.format("p"), MOTION_LEFT_OUT)),
    ],
)  # fmt: skip
def test_lines_that_name_quantities_no_other_line_uses_are_working(expected, submitted, kind, status, notes):
    verdict = compare(expected, submitted, kind=kind, **PENDULUM)
    assert (verdict.status, verdict.notes) == (status, notes), verdict
    assert "=" not in verdict.read_as.split(";")[0] or kind != "lagrangian"  # the answer shown, not the working


def _stated(line):
    return f"The line `{line}` states what the name means; the line that gives its value was graded."


@pytest.mark.parametrize(
    ("expected", "submitted", "options", "status", "notes"),
    [
        # before: L's value was put into L = T − V, and T and V were told undefined
        (L_PENDULUM, "L = T − V\nL = ½ m l² θ̇² + m g l cos θ", {"kind": "lagrangian"}, "equivalent",
         (_stated("L = T − V"),)),
        (L_PENDULUM, "L = T - U; L = ½ m l² θ̇² + m g l cos θ", {"kind": "lagrangian"}, "equivalent",
         (_stated("L = T - U"),)),
        (L_PENDULUM, "L = T − V\nL = ½ m l² θ̇² − m g l cos θ", {"kind": "lagrangian"}, "not_equivalent",
         (_stated("L = T − V"),)),
        # before: line 1 "does not say the same", for a person
        (H_PENDULUM, "H = T + V\nH = ½ m l² θ̇² − m g l cos θ", {"name": "H"}, "equivalent", (_stated("H = T + V"),)),
        # not the definition: left out too, but a person reads the value against what it says L is
        (L_PENDULUM, "L = T + V\nL = ½ m l² θ̇² + m g l cos θ", {"kind": "lagrangian"}, "undecided", ()),
        # T and V given values: L = T − V is the conclusion, not a statement
        (L_PENDULUM, "T = ½ m l² θ̇²; V = −m g l cos θ; L = T − V", {"kind": "lagrangian"}, "equivalent", ()),
    ],
)  # fmt: skip
def test_a_line_that_states_a_definition_is_not_the_answer(expected, submitted, options, status, notes):
    verdict = compare(expected, submitted, **PENDULUM, **options)
    assert (verdict.status, verdict.notes) == (status, notes), verdict


H_SPHERICAL = "1/2 m l^2 (thetadot^2 + sin(theta)^2 phidot^2) - m g l cos(theta)"
CHAIN = "Your 2 lines, each `H = …`, were read as one chain, H = … = …: its last side was graded."


@pytest.mark.parametrize(
    ("submitted", "status", "notes"),
    [
        # the definition in generic names, then the value: before, refused (q is no coordinate here)
        ("H = Σ p q̇ − L\nH = ½ m l²(θ̇² + sin²θ φ̇²) − m g l cos θ", "equivalent", (CHAIN,)),
        ("H = Σ p q̇ − L; H = ½ m l²(θ̇² + sin²θ φ̇²) + m g l cos θ", "not_equivalent", (CHAIN,)),
        # the sum written out: before, read as typed, H's value put into the first line, and L undefined
        ("H = p_θ θ̇ + p_φ φ̇ − L\nH = ½ m l²(θ̇² + sin²θ φ̇²) − m g l cos θ", "equivalent", (CHAIN,)),
        ("H = p_θ θ̇ + p_φ φ̇ − L; H = ½ m l²(θ̇² + sin²θ φ̇²) + m g l cos θ", "not_equivalent", (CHAIN,)),
        # a first line that is no definition we know: as typed, its unknown name told
        ("H = ½ m l²(θ̇² + sin²θ φ̇²) − q\nH = ½ m l²(θ̇² + sin²θ φ̇²) − m g l cos θ", "not_equivalent", ()),
        # as on one line
        ("H = Σ p q̇ − L = ½ m l²(θ̇² + sin²θ φ̇²) − m g l cos θ", "equivalent", ()),
        # lines of other names, or a last line that cannot be read: refused as before
        ("H = Σ p q̇ − L\nE = ½ m l²(θ̇² + sin²θ φ̇²) − m g l cos θ", "invalid", ()),
        ("H = Σ p q̇ − L\nH = ½ m l²(θ̇² + sin²θ φ̇²) − m g l cos θ\nH = foo(θ)", "invalid", ()),
    ],
)
def test_lines_that_give_one_name_values_are_one_chain(submitted, status, notes):
    verdict = compare(H_SPHERICAL, submitted, name="H", **SPHERICAL)
    assert (verdict.status, verdict.notes) == (status, notes), verdict


MOMENTUM_PHI = "m l^2 sin(theta)^2 phidot"
CHAIN_P = "Your 2 lines, each `p_φ = …`, were read as one chain, p_φ = … = …: its last side was graded."
P_DEFINED = r"p_\phi = \frac{\partial L}{\partial \dot\phi}"


@pytest.mark.parametrize(
    ("submitted", "status", "notes"),
    [
        ("p_φ = ∂L/∂φ̇\np_φ = m l² sin²θ φ̇", "equivalent", (CHAIN_P,)),
        ("p_φ = ∂L/∂φ̇,\np_φ = m l² sin²θ φ̇", "equivalent", (CHAIN_P,)),  # the sentence's comma
        # in TeX, as on one line (before: refused, `∂` out of its place)
        (rf"{P_DEFINED} \\ p_\phi = m l^2 \sin^2\theta \dot\phi", "equivalent", (CHAIN_P,)),
        (rf"{P_DEFINED}" "\n" r"p_\phi = m l^2 \sin^2\theta \dot\phi", "equivalent", (CHAIN_P,)),
        (rf"${P_DEFINED}$" "\n" r"$p_\phi = ml^2\sin^2\theta\,\dot\phi$", "equivalent", (CHAIN_P,)),
        (r"\[p_{\phi} = \frac{\partial L}{\partial\dot\phi}\]" "\n" r"\[p_\phi = m l^2 \sin^2\theta\,\dot\phi\]",
         "equivalent", (CHAIN_P,)),
        (rf"\begin{{aligned}} {P_DEFINED.replace(' =', ' &=')} \\ p_\phi &= m l^2 \sin^2\theta\,\dot\phi"
         r" \end{aligned}", "equivalent", (CHAIN_P,)),
        (rf"{P_DEFINED} \\ p_\phi = m l^2 \dot\phi", "not_equivalent", (CHAIN_P,)),
        # lines that name two quantities, or a line with no name, or no value: as typed
        ("p_φ = ∂L/∂φ̇\np_θ = m l² sin²θ φ̇", "invalid", ()),
        ("p_φ = ∂L/∂φ̇\nm l² sin²θ φ̇", "invalid", ()),
        ("p_φ = ∂L/∂φ̇\np_φ = ∂L/∂φ̇", "invalid", ()),
        (rf"{P_DEFINED} \\ p_\phi = m l^2 \sin^2\theta \dot\phi \\ p_\phi = foo(\theta)", "invalid", ()),
        (rf"{P_DEFINED} \\ 2p_\phi = m l^2 \sin^2\theta \dot\phi", "invalid", ()),
    ],
)  # fmt: skip
def test_a_momentum_defined_then_given_its_value_on_the_next_line_is_one_chain(submitted, status, notes):
    verdict = compare(MOMENTUM_PHI, submitted, name="p_phi", **SPHERICAL)
    assert (verdict.status, verdict.notes) == (status, notes), verdict


SPHERICAL_EOM = (
    "thetaddot = sin(theta) cos(theta) phidot^2 - (g/l) sin(theta);"
    " sin(theta)^2 phiddot + 2 sin(theta) cos(theta) thetadot phidot = 0"
)


def _one_chain(name):
    return f"Your 2 lines, each `{name} = …`, were read as one chain, {name} = … = …, as if written on one line."


@pytest.mark.parametrize(
    ("expected", "kind", "setting", "submitted", "status", "notes"),
    [
        # a system, or one equation through a momentum: the lines that name it, as on one line
        (SPHERICAL_EOM, "equations", SPHERICAL,
         "p_φ = ∂L/∂φ̇\np_φ = m l² sin²θ φ̇ = const\nθ̈ = sin θ cos θ φ̇² − (g/l) sin θ", "equivalent",
         (_one_chain("p_φ"),)),
        (SPHERICAL_EOM, "equations", SPHERICAL,
         rf"\ddot\theta = \sin\theta\cos\theta\,\dot\phi^2 - \frac gl \sin\theta \\ {P_DEFINED} \\"
         r" p_\phi = m l^2 \sin^2\theta\,\dot\phi = C", "equivalent", (_one_chain("p_φ"),)),
        (SPHERICAL_EOM, "equations", SPHERICAL,
         "θ̈ = sin θ cos θ φ̇² − (g/l) sin θ\np_φ = ∂L/∂φ̇\np_φ = m l² sin θ φ̇ = const", "not_equivalent",
         ("conserved_read", _one_chain("p_φ"))),
        (EOM_PENDULUM, "equation", PENDULUM, "p_θ = ∂L/∂θ̇\np_θ = m l² θ̇\nṗ_θ = −m g l sin θ", "equivalent",
         (_one_chain("p_θ"),)),
        (EOM_PENDULUM, "equation", PENDULUM, "p_θ = ∂L/∂θ̇\np_θ = m l θ̇\nṗ_θ = −m g l sin θ", "not_equivalent",
         (_one_chain("p_θ"),)),
        # not in a row: two names for one line each, as typed
        (SPHERICAL_EOM, "equations", SPHERICAL,
         "p_φ = ∂L/∂φ̇\nθ̈ = sin θ cos θ φ̇² − (g/l) sin θ\np_φ = m l² sin²θ φ̇ = const", "invalid", ()),
    ],
)  # fmt: skip
def test_lines_that_name_one_quantity_in_a_row_are_one_chain_in_a_system(
    expected, kind, setting, submitted, status, notes
):
    verdict = compare(expected, submitted, kind=kind, **setting)
    said = tuple("conserved_read" if "conserved quantity" in note else note for note in verdict.notes)
    assert (verdict.status, said) == (status, notes), verdict


SUM_REFUSED = (
    "`\\sum` is read only in a definition on the way to the answer, as in H = \\sum_j p_j \\dot q_j - L = …, whose"
    " last side is graded; anywhere else, write the sum out term by term."
)


@pytest.mark.parametrize(
    ("submitted", "status", "feedback"),
    [
        # TeX's sum in the definition on the way, as Σ is (before: \\sum was an unknown command)
        ("H = \\sum_i p_i \\dot q_i - L = ½ m l²(θ̇² + sin²θ φ̇²) − m g l cos θ", "equivalent", ("Correct.",)),
        ("H = \\sum_j p_j \\dot{q}_j - L = \\frac12 m l^2(\\dot\\theta^2 + \\sin^2\\theta\\,\\dot\\phi^2)"
         " - m g l\\cos\\theta", "equivalent", ("Correct.",)),
        ("H = \\sum p\\dot q - L = ½ m l²(θ̇² + sin²θ φ̇²) − m g l cos θ", "equivalent", ("Correct.",)),
        ("H = ∑_j p_j q̇_j − L = ½ m l²(θ̇² + sin²θ φ̇²) − m g l cos θ", "equivalent", ("Correct.",)),
        ("H = \\sum_i p_i \\dot q_i - L\nH = ½ m l²(θ̇² + sin²θ φ̇²) − m g l cos θ", "equivalent", ("Correct.", CHAIN)),
        # its value graded as Σ's is
        ("H = \\sum_i p_i \\dot q_i - L = ½ m l²(θ̇² + sin²θ φ̇²) + m g l cos θ", "not_equivalent",
         ("A term differs: the term in cos(θ) has the wrong sign.",)),
        # anywhere else a sum is refused, and said why
        ("H = \\sum_i p_i \\dot q_i - L", "invalid", (SUM_REFUSED,)),
        ("\\sum_i p_i \\dot q_i - L = ½ m l²(θ̇² + sin²θ φ̇²) − m g l cos θ", "invalid", (SUM_REFUSED,)),
        ("H = \\sum_i p_i \\dot q_i - L = \\sum_i p_i \\dot q_i - ½ m l²(θ̇² + sin²θ φ̇²) − m g l cos θ", "invalid",
         (SUM_REFUSED,)),
        ("½ m l² \\sum_i \\dot q_i^2 − m g l cos θ", "invalid", (SUM_REFUSED,)),
    ],
)  # fmt: skip
def test_a_sum_is_read_in_the_definition_passed_over_and_refused_elsewhere(submitted, status, feedback):
    verdict = compare(H_SPHERICAL, submitted, name="H", **SPHERICAL)
    assert (verdict.status, verdict.feedback) == (status, feedback), verdict


@pytest.mark.parametrize(
    ("expected", "submitted", "kind"),
    [
        (L_PENDULUM, "T = ½ m l² θ̇²; V = −m g l cos θ", "lagrangian"),  # no L: V is not the Lagrangian
        ("1/2 m l^2 thetadot^2", "T = ½ m l² θ̇²; V = −m g l cos θ", "expression"),  # V is not a kinetic energy
        (EOM_PENDULUM, "L = ½ m l² θ̇² + m g l cos θ; θ̈ = −(g/l) sin θ; θ̈ = −(g/l) θ", "equation"),  # two answers
        (EOM_PENDULUM, "L = ½ m l² θ̇² + m g l cos θ; p = m l² θ̇", "equation"),  # nothing but working
        (L_PENDULUM, "L = ½ m l² θ̇² + m g l cos θ; θ̇ = 0", "lagrangian"),  # no equation of motion after L
    ],
)
def test_working_is_not_read_where_the_answer_would_be_a_guess(expected, submitted, kind):
    verdict = compare(expected, submitted, kind=kind, **PENDULUM)
    assert verdict.status == "not_equivalent", verdict
    assert not verdict.notes


@pytest.mark.parametrize(
    ("submitted", "status"),
    [
        # Lagrange's equation through the momentum: ṗ = ∂L/∂θ, with p = ∂L/∂θ̇ defined beside it
        ("p_θ = m l² θ̇, ṗ_θ = −m g l sin θ", "equivalent"),
        ("ṗ = −m g l sin θ, where p = m l² θ̇", "equivalent"),
        ("d/dt(p) = −m g l sin θ; p = m l² θ̇", "equivalent"),
        ("dp/dt = −m g l sin θ\np = m l² θ̇", "equivalent"),
        ("d/dt(m l² ω) = −m g l sin θ, ω = θ̇", "equivalent"),
        ("p = m l² θ̇ ⇒ ṗ = −m g l sin θ", "equivalent"),  # a derivation keeps the step its conclusion uses
        # a definition through another's rate: p's rate holds ü, put in place whichever comes first
        ("ṗ = −m g l sin θ; p = m l² u̇; u = θ", "equivalent"),
        ("u = θ; p = m l² u̇; ṗ = −m g l sin θ", "equivalent"),
        # the momentum or the force wrong: wrong
        ("p_θ = m l θ̇, ṗ_θ = −m g l sin θ", "not_equivalent"),
        ("p_θ = m l² θ̇, ṗ_θ = m g l sin θ", "not_equivalent"),
        ("p = m l² θ, ṗ = −m g l sin θ", "not_equivalent"),  # a momentum of θ, not θ̇: no acceleration
        # a rate of a name nothing defines is no quantity: refused, as before
        ("ṗ_θ = −m g l sin θ", "invalid"),
        ("d/dt(p) = −m g l sin θ", "invalid"),
    ],
)
def test_an_equation_of_motion_may_be_written_through_a_momentum_it_defines(submitted, status):
    verdict = compare(EOM_PENDULUM, submitted, kind="equation", **PENDULUM)
    assert verdict.status == status, verdict


@pytest.mark.parametrize(
    ("expected", "submitted", "setting", "status"),
    [
        # a Lagrangian in Cartesian coordinates, with the transformation to the generalized ones
        (L_PENDULUM, "L = ½ m (ẋ² + ẏ²) − m g y, where x = l sin θ, y = −l cos θ", PENDULUM, "equivalent"),
        (L_PENDULUM, "L = ½ m (ẋ² + ẏ²) + m g y, where x = l sin θ, y = −l cos θ", PENDULUM, "not_equivalent"),
        (L_PENDULUM, "1/2 m (xdot^2 + ydot^2) - m g y where x = l sin(theta), y = -l cos(theta)", PENDULUM,
         "equivalent"),  # velocities spelled out, as thetadot
        (L_PENDULUM, "½ m sdot² + m g l cos θ, s = l θ", PENDULUM, "equivalent"),
        (L_PENDULUM, "x = l sin θ, y = −l cos θ ⇒ L = ½ m (ẋ² + ẏ²) − m g y", PENDULUM, "equivalent"),
        (L_PENDULUM, "L = ½ m (ẋ² + ẏ²) − m g y = ½ m l² θ̇² + m g l cos θ", PENDULUM, "equivalent"),  # the last side
        (L_PENDULUM, "L = ½ m (ẋ² + ẏ²) − m g y, where x = l sin θ, y = l cos θ", PENDULUM, "not_equivalent"),
        ("1/2 m l^2 (thetadot^2 + sin(theta)^2 phidot^2) + m g l cos(theta)",
         "½ m (ẋ² + ẏ² + ż²) − m g z; x = l sin θ cos φ; y = l sin θ sin φ; z = −l cos θ",
         {"coords": ["theta", "phi"], "known": ["m", "g", "l"]}, "equivalent"),
    ],
)  # fmt: skip
def test_a_lagrangian_may_be_written_in_cartesian_coordinates_it_defines(expected, submitted, setting, status):
    verdict = compare(expected, submitted, kind="lagrangian", **setting)
    assert verdict.status == status, verdict


T_DOUBLE = (
    "1/2 (m1 + m2) l1^2 theta1dot^2 + 1/2 m2 l2^2 theta2dot^2 + m2 l1 l2 theta1dot theta2dot cos(theta1 - theta2)"
)
CARTESIAN_DOUBLE = "x₁ = l₁ sin θ₁, y₁ = −l₁ cos θ₁, x₂ = x₁ + l₂ sin θ₂, y₂ = y₁ − l₂ cos θ₂, T = {}"


@pytest.mark.parametrize(
    ("kinetic", "status"),
    [
        ("½ m₁ (ẋ₁² + ẏ₁²) + ½ m₂ (ẋ₂² + ẏ₂²)", "equivalent"),  # definitions that build on each other
        ("½ m₁ (ẋ₁² + ẏ₁²) + ½ m₂ (ẋ₂² − ẏ₂²)", "not_equivalent"),
        ("½ (m₁ + m₂) (ẋ₁² + ẏ₁²) + ½ m₂ (ẋ₂² + ẏ₂²)", "not_equivalent"),
    ],
)
def test_a_kinetic_energy_may_be_built_from_cartesian_coordinates_defined_one_on_another(kinetic, status):
    verdict = compare(T_DOUBLE, CARTESIAN_DOUBLE.format(kinetic), **DOUBLE)
    assert verdict.status == status, verdict


def test_a_rate_whose_name_is_not_defined_in_the_problems_names_is_not_put_in_place():
    # p = m l² v: v is the student's too, so p is no definition; its rate stays, and is said so
    verdict = compare(EOM_PENDULUM, "ṗ = −m g l sin θ, p = m l² v", kind="equation", **PENDULUM)
    assert verdict.status == "not_equivalent"
    assert verdict.diagnosis == "eliminate_unknowns"


ENERGIES = "Your answer gives T and {0} but no Lagrangian: the answer asked for is L = T − {0}, written out."


@pytest.mark.parametrize(
    ("submitted", "feedback"),
    [
        ("T = ½ m l² θ̇²; V = −m g l cos θ", ENERGIES.format("V") + " T − V from yours would be right."),
        ("V = −m g l cos θ\nT = ½ m l² θ̇²", ENERGIES.format("V") + " T − V from yours would be right."),
        ("T = ½ m l² θ̇², U = −m g l cos θ", ENERGIES.format("U") + " T − U from yours would be right."),
        ("T = ½ m l² θ̇²; V = m g l cos θ",
         ENERGIES.format("V") + " Check your energies too: T − V from yours is not right."),
    ],
)  # fmt: skip
def test_the_energies_without_the_lagrangian_are_told_what_is_asked_for(submitted, feedback):
    verdict = compare(L_PENDULUM, submitted, kind="lagrangian", **PENDULUM)
    assert (verdict.status, verdict.score, verdict.feedback) == ("not_equivalent", 0.0, (feedback,))
    # not where an expression in them is asked for, nor with a name other than T and V
    for kind, expected, other in (("expression", L_PENDULUM, submitted), ("lagrangian", L_PENDULUM, "T = 1; W = 2")):
        assert compare(expected, other, kind=kind, **PENDULUM).diagnosis != verdict.diagnosis


SPRINGS = {"coords": ["x1", "x2"], "known": ["m", "k"]}
EOM_SPRINGS = "m x1ddot = -2 k x1 + k x2; m x2ddot = k x1 - 2 k x2"
DASHES = (
    "Each line of your answer starts with `- `. Read as minus signs, your answer is not right; read as a list's"
    " bullets, it is. Which is meant? Write a minus sign against its term (−2 l θ̈), or leave the bullets out."
)


@pytest.mark.parametrize(
    ("submitted", "status"),
    [
        # a Markdown list of right equations: its dashes may be bullets or minus signs, and only one reading is right
        ("- m ẍ₁ + 2 k x₁ − k x₂ = 0\n- m ẍ₂ − k x₁ + 2 k x₂ = 0", "invalid"),
        ("  – m ẍ₁ = −2 k x₁ + k x₂\n  – m ẍ₂ = k x₁ − 2 k x₂", "invalid"),
        # right as typed, minus signs and all: no question
        ("- m ẍ₁ - 2 k x₁ + k x₂ = 0\n- m ẍ₂ + k x₁ - 2 k x₂ = 0", "equivalent"),
        # wrong either way: as typed
        ("- m ẍ₁ = 0\n- m ẍ₂ = 0", "not_equivalent"),
        # not every line starts so, one line alone, or the minus sign −: as typed
        ("- m ẍ₁ + 2 k x₁ − k x₂ = 0\nm ẍ₂ − k x₁ + 2 k x₂ = 0", "not_equivalent"),
        ("−m ẍ₁ + 2 k x₁ − k x₂ = 0\n−m ẍ₂ − k x₁ + 2 k x₂ = 0", "not_equivalent"),
    ],
)
def test_dashes_that_start_every_line_are_asked_about_where_the_reading_decides(submitted, status):
    verdict = compare(EOM_SPRINGS, submitted, kind="equations", **SPRINGS)
    assert verdict.status == status, verdict
    assert (verdict.feedback == (DASHES,)) == (status == "invalid")


def test_a_name_left_in_the_formula_before_the_words_is_said_as_usual():
    verdict = compare(L_PENDULUM, "½ m v² + m g l cos θ, where v is the speed", kind="lagrangian", **PENDULUM)
    assert verdict.feedback[0].startswith("Your answer uses `v`, which this problem does not define")


def test_an_expression_before_definitions_is_shown_back_without_a_name():
    verdict = compare(L_PENDULUM, "½ m l² θ̇² + m g l cos θ, where u = l θ̇", kind="lagrangian", **PENDULUM)
    assert verdict.read_as == "g*l*m*cos(θ) + l^2*m*θ̇^2/2; u = l*θ̇"
    read = parse_answer("½ m v², where v = l θ̇", coords=["theta"], known=["m", "l"])
    assert read.read_as_latex == r"\begin{aligned}\frac{m v^{2}}{2} \\ v = l \dot{\theta}\end{aligned}"
    assert "answer" not in read.read_as_mathml


def test_a_system_may_define_its_own_names():
    double = {"coords": ["theta_1", "theta_2"], "known": ["m", "g", "l"]}
    expected = (
        "2 l theta1ddot + l theta2ddot cos(theta1 - theta2) + l theta2dot^2 sin(theta1 - theta2) + 2 g sin(theta1) = 0;"
        " l theta2ddot + l theta1ddot cos(theta1 - theta2) - l theta1dot^2 sin(theta1 - theta2) + g sin(theta2) = 0"
    )
    submitted = (
        "2 l θ̈₁ + l θ̈₂ cos Δ + l θ̇₂² sin Δ + 2 g sin θ₁ = 0\n"
        "l θ̈₂ + l θ̈₁ cos Δ − l θ̇₁² sin Δ + g sin θ₂ = 0\n"
        "where Δ = θ₁ − θ₂"
    )
    assert compare(expected, submitted, kind="equations", **double).status == "equivalent"
    assert compare(expected, submitted.replace("θ₁ − θ₂", "θ₂ − θ₁"), kind="equations", **double).status == (
        "not_equivalent"
    )


SPHERICAL = {"coords": ["theta", "phi"], "known": ["m", "g", "l"]}


@pytest.mark.parametrize(
    ("conserved", "status"),
    [
        ("m l² sin²θ φ̇ = const", "equivalent"),  # p_φ: φ is cyclic
        ("C = m l^2 sin(theta)^2 phidot", "equivalent"),
        ("p = m l² sin²θ φ̇, p = C₁", "equivalent"),  # named first, then conserved
        ("m l² sin θ φ̇ = const", "not_equivalent"),  # not the conserved quantity
        ("m l² sin²θ φ̈ = const", "not_equivalent"),  # an acceleration is no conserved quantity: C undefined
        ("m l² sin²θ φ̇ = r", "not_equivalent"),  # r is no word for a constant
        ("p_φ = m l² sin²θ φ̇ = const", "equivalent"),  # named on the way
        ("m l² sin²θ φ̇ = p_φ = const", "equivalent"),
        (r"\frac{\partial L}{\partial\dot\phi} = m l^2 \sin^2\theta\,\dot\phi = C", "equivalent"),
    ],
)
def test_a_conserved_quantity_is_read_as_an_equation_of_motion(conserved, status):
    submitted = f"θ̈ = sin θ cos θ φ̇² − (g/l) sin θ; {conserved}"
    assert compare(SPHERICAL_EOM, submitted, kind="equations", **SPHERICAL).status == status


SPHERICAL_THETA = "l θ̈ − l sin θ cos θ φ̇² + g sin θ"  # = 0, the θ equation


@pytest.mark.parametrize(
    ("submitted", "status"),
    [
        # at the pole the φ equation says nothing, but the θ equation still says θ̈ = 0
        (f"sin θ ({SPHERICAL_THETA}) = 0; sin²θ φ̈ + 2 sin θ cos θ θ̇ φ̇ = 0", "not_equivalent"),
        (f"θ ({SPHERICAL_THETA}) = 0; sin²θ φ̈ + 2 sin θ cos θ θ̇ φ̇ = 0", "not_equivalent"),
        (f"sin θ ({SPHERICAL_THETA}) + sin²θ φ̈ + 2 sin θ cos θ θ̇ φ̇ = 0; sin θ φ̈ + 2 cos θ θ̇ φ̇ = 0", "not_equivalent"),
        # the φ equation over sin θ, or solved, says as much as the θ equation where they are defined
        (f"{SPHERICAL_THETA} = 0; sin θ φ̈ + 2 cos θ θ̇ φ̇ = 0", "equivalent"),
        (f"{SPHERICAL_THETA} = 0; φ̈ = −2 cot θ θ̇ φ̇", "equivalent"),
        (f"{SPHERICAL_THETA} + sin²θ φ̈ + 2 sin θ cos θ θ̇ φ̇ = 0; sin θ φ̈ + 2 cos θ θ̇ φ̇ = 0", "equivalent"),
    ],
)
def test_an_equation_that_no_longer_fixes_its_acceleration_where_the_system_is_singular_is_wrong(submitted, status):
    verdict = compare(SPHERICAL_EOM, submitted, kind="equations", **SPHERICAL)
    assert verdict.status == status, verdict
    if status == "not_equivalent":
        assert verdict.diagnosis == "vanishing_factor_system"


@pytest.mark.parametrize(
    ("submitted", "status"),
    [
        # a factor that is zero somewhere between the states drawn, not at rest or at the origin
        ("cos θ (l θ̈ + g sin θ) = 0", "not_equivalent"),
        ("(θ − 1)(l θ̈ + g sin θ) = 0", "not_equivalent"),
        ("(1 − 2 cos θ)(l θ̈ + g sin θ) = 0", "not_equivalent"),
        # nonzero wherever the equation is defined: a pole, not a zero, where it changes sign
        ("(l θ̈ + g sin θ)/cos θ = 0", "equivalent"),
        ("(l θ̈ + g sin θ)/θ = 0", "equivalent"),
        ("(2 + cos θ)(l θ̈ + g sin θ) = 0", "equivalent"),
    ],
)
def test_an_equation_times_a_factor_that_vanishes_anywhere_is_not_equivalent(submitted, status):
    verdict = compare(EOM_PENDULUM, submitted, kind="equation", **PENDULUM)
    assert verdict.status == status, verdict
    if status == "not_equivalent":
        assert verdict.diagnosis == "vanishing_factor_between"


@pytest.mark.parametrize(
    ("submitted", "status"),
    [
        # zero without changing sign: at θ = π, at θ = π/2, where θ̇ = 1
        ("(1 + cos θ)(l θ̈ + g sin θ) = 0", "not_equivalent"),
        ("cos²θ (l θ̈ + g sin θ) = 0", "not_equivalent"),
        ("(θ̇ − 1)² (l θ̈ + g sin θ) = 0", "not_equivalent"),
        # as low, but never zero: a factor that comes close is still a factor
        ("(1.01 + cos θ)(l θ̈ + g sin θ) = 0", "equivalent"),
        ("(1.000001 + cos θ)(l θ̈ + g sin θ) = 0", "equivalent"),
        ("(1 + θ̇²)(l θ̈ + g sin θ) = 0", "equivalent"),
    ],
)
def test_an_equation_times_a_factor_that_touches_zero_is_not_equivalent(submitted, status):
    verdict = compare(EOM_PENDULUM, submitted, kind="equation", **PENDULUM)
    assert verdict.status == status, verdict
    if status == "not_equivalent":
        assert verdict.diagnosis == "vanishing_factor_between"


FEEDBACK_SENTENCES = {
    "vanishing_factor_between": "Your equation is right only where a factor of it is not zero: where that factor is"
    " zero, it no longer says what the acceleration is. Divide that factor out.",
    "vanishing_factor_system_between": "One of your equations is right only where a factor of it is not zero: where"
    " that factor is zero, your equations no longer determine every acceleration. Divide that factor out.",
}


@pytest.mark.parametrize(
    ("expected", "submitted", "kind", "setting", "diagnosis"),
    [
        # the factor multiplied into every term: each term is as small as the factor where it vanishes,
        # so the terms' own rounding could not call the equation zero there, and it was marked right
        (EOM_PENDULUM, "θ̈ cos θ = −(g/l) sin θ cos θ", "equation", PENDULUM, "vanishing_factor_between"),
        (EOM_PENDULUM, "θ̈ cos θ = −(g/(2 l)) sin 2θ", "equation", PENDULUM, "vanishing_factor_between"),
        (EOM_PENDULUM, "θ̈ cos²θ + (g/l) sin θ cos²θ = 0", "equation", PENDULUM, "vanishing_factor_between"),
        (SPHERICAL_EOM, "cos θ θ̈ − sin θ cos²θ φ̇² + (g/l) sin θ cos θ = 0; sin θ φ̈ + 2 cos θ θ̇ φ̇ = 0",
         "equations", SPHERICAL, "vanishing_factor_system_between"),
        (SPHERICAL_EOM, "θ̈ − sin θ cos θ φ̇² + (g/l) sin θ = 0; cos θ sin θ φ̈ + 2 cos²θ θ̇ φ̇ = 0",
         "equations", SPHERICAL, "vanishing_factor_system_between"),
    ],
)  # fmt: skip
def test_a_vanishing_factor_multiplied_out_is_found_as_one_kept_outside(expected, submitted, kind, setting, diagnosis):
    verdict = compare(expected, submitted, kind=kind, **setting)
    assert (verdict.status, verdict.diagnosis) == ("not_equivalent", diagnosis), verdict
    assert verdict.feedback == (FEEDBACK_SENTENCES[diagnosis],)


@pytest.mark.parametrize(
    ("submitted", "status"),
    [
        # sin θ is zero where the expected φ equation, sin²θ φ̈ + …, already fixes no φ̈: no mistake
        (f"{SPHERICAL_THETA} = 0; sin θ (sin²θ φ̈ + 2 sin θ cos θ θ̇ φ̇) = 0", "equivalent"),
        (f"{SPHERICAL_THETA} = 0; sin³θ φ̈ + 2 sin²θ cos θ θ̇ φ̇ = 0", "equivalent"),
        # cos θ is zero where it does
        (f"{SPHERICAL_THETA} = 0; cos θ (sin²θ φ̈ + 2 sin θ cos θ θ̇ φ̇) = 0", "not_equivalent"),
    ],
)
def test_a_factor_that_vanishes_only_where_the_expected_system_is_singular_is_no_mistake(submitted, status):
    expected = f"{SPHERICAL_THETA} = 0; sin²θ φ̈ + 2 sin θ cos θ θ̇ φ̇ = 0"
    assert compare(expected, submitted, kind="equations", **SPHERICAL).status == status


def test_a_system_whose_combination_touches_zero_is_not_equivalent():
    # the θ equation times 1 + cos θ: the determinant of the combination is zero at θ = π
    submitted = f"(1 + cos θ)({SPHERICAL_THETA}) = 0; sin θ φ̈ + 2 cos θ θ̇ φ̇ = 0"
    verdict = compare(SPHERICAL_EOM, submitted, kind="equations", **SPHERICAL)
    assert (verdict.status, verdict.diagnosis) == ("not_equivalent", "vanishing_factor_system_between")


E1, E2 = (equation.removesuffix(" = 0") for equation in (EOM_DOUBLE_1, EOM_DOUBLE_2))


@pytest.mark.parametrize(
    ("submitted", "status"),
    [
        # combined by a matrix of determinant 1 − cos²(θ₁ − θ₂ − 1): zero, without changing sign, at θ₁ − θ₂ = 1
        (f"{E1} + cos(theta1 - theta2 - 1) ({E2}) = 0; cos(theta1 - theta2 - 1) ({E1}) + {E2} = 0", "not_equivalent"),
        # of determinant 2 − cos²(θ₁ − θ₂), never below 1
        (f"{E1} + cos(theta1 - theta2) ({E2}) = 0; cos(theta1 - theta2) ({E1}) + 2 ({E2}) = 0", "equivalent"),
    ],
)
def test_a_system_combined_by_a_matrix_whose_determinant_touches_zero_is_not_equivalent(submitted, status):
    verdict = compare(EOM_DOUBLE, submitted, kind="equations", **DOUBLE)
    assert verdict.status == status, verdict
    if status == "not_equivalent":
        assert verdict.diagnosis == "vanishing_factor_system_between"


def test_a_factor_of_the_parameters_that_vanishes_for_some_of_them_is_not_equivalent():
    # zero where the masses are equal: then the equation says nothing of ẍ
    atwood = {"coords": ["x"], "known": ["m1", "m2", "g"]}
    verdict = compare(
        "(m1 + m2) xddot = (m1 - m2) g", "(m1 - m2)(m1 + m2) xddot = (m1 - m2)^2 g", kind="equation", **atwood
    )
    assert (verdict.status, verdict.diagnosis) == ("not_equivalent", "vanishing_factor_between")


@pytest.mark.parametrize(
    ("submitted", "status"),
    [
        (f"cos θ ({SPHERICAL_THETA}) = 0; sin²θ φ̈ + 2 sin θ cos θ θ̇ φ̇ = 0", "not_equivalent"),
        (f"{SPHERICAL_THETA} = 0; (2 cos θ − 1)(sin θ φ̈ + 2 cos θ θ̇ φ̇) = 0", "not_equivalent"),
        (f"{SPHERICAL_THETA} = 0; sin θ φ̈ + 2 cos θ θ̇ φ̇ = 0", "equivalent"),
    ],
)
def test_a_system_with_an_equation_times_a_vanishing_factor_is_not_equivalent(submitted, status):
    verdict = compare(SPHERICAL_EOM, submitted, kind="equations", **SPHERICAL)
    assert verdict.status == status, verdict
    if status == "not_equivalent":
        assert verdict.diagnosis == "vanishing_factor_system_between"


HOOP = {"coords": ["theta"], "known": ["R", "g", "omega"]}
EOM_HOOP = "theta'' = omega^2 sin(theta) cos(theta) - g/R sin(theta)"


@pytest.mark.parametrize(
    ("submitted", "sentence"),
    [
        # sin 2θ is 2 sin θ cos θ: the student's term is named as written, its factor wrong
        ("θ̈ = ω² sin 2θ − (g/R) sin θ", "A term differs: the term in sin(2θ) has the wrong factor."),
        ("θ̈ = −½ ω² sin 2θ − (g/R) sin θ", "A term differs: the term in sin(2θ) has the wrong sign."),
    ],
)
def test_a_double_angle_is_matched_with_the_product_it_stands_for(submitted, sentence):
    verdict = compare(EOM_HOOP, submitted, kind="equation", **HOOP)
    assert (verdict.status, verdict.feedback) == ("not_equivalent", (sentence,)), verdict
    assert compare(EOM_HOOP, "θ̈ = ½ ω² sin 2θ − (g/R) sin θ", kind="equation", **HOOP).equivalent


def test_one_term_in_its_small_angle_form_is_said_so_not_as_a_term_missing_and_one_too_many():
    submitted = "l θ̈ − l sin θ cos θ φ̇² + g θ = 0; sin²θ φ̈ + 2 sin θ cos θ θ̇ φ̇ = 0"
    verdict = compare(SPHERICAL_EOM, submitted, kind="equations", **SPHERICAL)
    assert verdict.feedback == (
        "Your equation for θ is not right; equation 2 is right.",
        "A term differs: the gravity term is in its small-angle form, and the full form is asked for.",
    )


SPHERICAL_FULL_L = "1/2 m l^2 (thetadot^2 + sin(theta)^2 phidot^2) + m g l cos(theta)"


@pytest.mark.parametrize(
    ("expected", "submitted", "kind"),
    [
        # m g l cos θ ≈ m g l − ½ m g l θ²: the terms that vary are compared, and −½ m g l θ² is its part
        (SPHERICAL_FULL_L, "½ m l² (θ̇² + sin²θ φ̇²) − ½ m g l θ²", "lagrangian"),
        (SPHERICAL_FULL_L, "½ m l² (θ̇² + sin²θ φ̇²) − ½ m g l θ²", "expression"),
    ],
)
def test_a_potential_in_its_small_angle_form_beside_full_kinetic_terms_is_said_so(expected, submitted, kind):
    verdict = compare(expected, submitted, kind=kind, **SPHERICAL)
    assert verdict.feedback == (
        "A term differs: the gravity term is in its small-angle form, and the full form is asked for.",
    ), verdict


SMALL_ANGLE_KEPT = [
    # sin u → u and cos u → 1 put in, as students write for small angles: a term of third order
    # (θ φ̇², (α − β) α̇²) stays, which the linearized equations have not
    ("thetaddot = sin(theta) cos(theta) phidot^2 - (g/l) sin(theta)", "θ̈ = θ φ̇² − (g/l) θ", "equation", SPHERICAL),
    ("thetaddot = sin(theta) cos(theta) phidot^2 - (g/l) sin(theta)", "θ̈ = θ (1 − θ²/2) φ̇² − (g/l) θ", "equation",
     SPHERICAL),
    ("sin(theta)^2 phiddot + 2 sin(theta) cos(theta) thetadot phidot = 0", "θ φ̈ + 2 θ̇ φ̇ = 0", "equation", SPHERICAL),
    (EOM_DOUBLE_2, "l2 θ̈₂ + l1 θ̈₁ − l1 θ̇₁² (θ₁ − θ₂) + g θ₂ = 0", "equation", DOUBLE),
    (SPHERICAL_EOM, "θ̈ = θ φ̇² − (g/l) θ; θ φ̈ + 2 θ̇ φ̇ = 0", "equations", SPHERICAL),
    (EOM_DOUBLE, "(m1+m2) l1 θ̈₁ + m2 l2 θ̈₂ + m2 l2 θ̇₂² (θ₁ − θ₂) + (m1+m2) g θ₁ = 0;"
     " l2 θ̈₂ + l1 θ̈₁ − l1 θ̇₁² (θ₁ − θ₂) + g θ₂ = 0", "equations", DOUBLE),
]  # fmt: skip


@pytest.mark.parametrize(("expected", "submitted", "kind", "setting"), SMALL_ANGLE_KEPT)
def test_equations_with_sines_put_as_their_angles_are_said_to_be_small_angle_forms(expected, submitted, kind, setting):
    verdict = compare(expected, submitted, kind=kind, **setting)
    assert (verdict.status, verdict.feedback) == (
        "not_equivalent",
        ("You used the small-angle approximation, but the full answer is asked for here.",),
    ), verdict


SMALL_ANGLE_ONE_OF_TWO = "You used the small-angle approximation, but the full answer is asked for here."


@pytest.mark.parametrize(
    ("expected", "submitted", "setting", "feedback"),
    [
        # one equation of the system in its small-angle form: which one, and that it is one
        (SPHERICAL_EOM, "θ̈ = θ φ̇² − (g/l) θ; sin²θ φ̈ + 2 sin θ cos θ θ̇ φ̇ = 0", SPHERICAL,
         ("Your equation for θ is not right; equation 2 is right.", SMALL_ANGLE_ONE_OF_TWO)),
        (EOM_DOUBLE, f"{EOM_DOUBLE_1}; l2 θ̈₂ + l1 θ̈₁ + g θ₂ = 0", DOUBLE,
         ("Your equation for θ₂ is not right; equation 1 is right.", SMALL_ANGLE_ONE_OF_TWO)),
        (SPHERICAL_EOM, "θ̈ = θ φ̇² − (g/l) θ; φ̈ = 0", SPHERICAL,
         ("Your equations do not determine the right accelerations for θ, φ.",
          "In your equation 1, you used the small-angle approximation, but the full answer is asked for here.",
          "In your equation 2, a term is missing: a velocity-dependent term in cos(θ).")),
    ],
)  # fmt: skip
def test_an_equation_of_a_system_in_its_small_angle_form_is_said_so(expected, submitted, setting, feedback):
    verdict = compare(expected, submitted, kind="equations", **setting)
    assert (verdict.status, verdict.feedback) == ("not_equivalent", feedback), verdict


DOUBLE_T = "1/2 (m1+m2) l1^2 theta1dot^2 + 1/2 m2 l2^2 theta2dot^2 + m2 l1 l2 theta1dot theta2dot cos(theta1-theta2)"


@pytest.mark.parametrize(
    ("submitted", "sentence"),
    [
        # too many terms differ to name them: which part is right is said, and how the other is off
        (f"{DOUBLE_T} + 2 (m1+m2) g l1 cos(theta1) + 2 m2 g l2 cos(theta2)",
         "The terms of your Lagrangian with velocities are right, but not the terms without: they are 2 times the"
         " right ones."),
        (f"{DOUBLE_T} + (m1+m2) g l1 sin(theta1) + m2 g l2 sin(theta2)",
         "The terms of your Lagrangian with velocities are right, but not the terms without."),
        (DOUBLE_T, "The terms of your Lagrangian with velocities are right, but there are none without: where is the"
         " potential energy?"),
        (f"{DOUBLE_T} - 1/2 (m1+m2) g l1 theta1^2 - 1/2 m2 g l2 theta2^2",
         "The terms of your Lagrangian with velocities are right, but the terms without are in their small-angle"
         " form, and the full form is asked for here."),
        ("1/2 m1 l1^2 theta1dot^2 + 1/2 m2 l2^2 theta2dot^2 + m2 l1 l2 theta1dot theta2dot"
         " + (m1+m2) g l1 cos(theta1) + m2 g l2 cos(theta2)",
         "The terms of your Lagrangian without velocities are right, but not the terms with them."),
    ],
)  # fmt: skip
def test_a_lagrangian_with_many_terms_wrong_says_which_part_is_right(submitted, sentence):
    expected = f"{DOUBLE_T} + (m1+m2) g l1 cos(theta1) + m2 g l2 cos(theta2)"
    verdict = compare(expected, submitted, kind="lagrangian", **DOUBLE)
    assert (verdict.status, verdict.feedback) == ("not_equivalent", (sentence,)), verdict


@pytest.mark.parametrize(
    ("submitted", "status"),
    [
        # r is the answer's own name: mr² is m r², read again with r known
        ("mr² φ̇, r = l sin θ", "equivalent"),
        ("mr² φ̇, r = l cos θ", "not_equivalent"),
    ],
)
def test_a_glued_product_with_a_name_the_answer_defines_is_read_with_it(submitted, status):
    verdict = compare("m l^2 sin(theta)^2 phidot", submitted, **SPHERICAL)
    assert verdict.status == status, verdict


@pytest.mark.parametrize(
    ("submitted", "status"),
    [
        # H = p_θ θ̇ − L, the prompt's own definition, written on the way: L is no name to define
        ("p_θ θ̇ − L = ½mR²θ̇² − ½mR²ω²sin²θ − mgR cosθ", "equivalent"),
        ("p_θ θ̇ − L = ½mR²θ̇² + ½mR²ω²sin²θ − mgR cosθ", "not_equivalent"),
    ],
)
def test_the_definition_of_the_hamiltonian_written_on_the_way_is_no_name_to_define(submitted, status):
    hoop = {"coords": ["theta"], "known": ["m", "R", "g", "omega"]}
    expected = "1/2 m R^2 thetadot^2 - 1/2 m R^2 omega^2 sin(theta)^2 - m g R cos(theta)"
    verdict = compare(expected, submitted, given={"p_theta": "m R^2 thetadot"}, **hoop)
    assert verdict.status == status, verdict
    assert verdict.diagnosis != "undefined_symbol"


def test_a_conserved_quantity_that_is_wrong_says_how_it_was_read():
    submitted = "θ̈ = sin θ cos θ φ̇² − (g/l) sin θ; m l² sin θ φ̇ = const"
    verdict = compare(SPHERICAL_EOM, submitted, kind="equations", **SPHERICAL)
    assert verdict.feedback[0] == "Your equation for φ is not right; equation 1 is right."
    assert "conserved quantity" in verdict.feedback[1]
    # the terms compared are its derivative's, which the student did not write: they are not named
    assert len(verdict.feedback) == 2, verdict.feedback
    phi = compare(SPHERICAL_EOM.split(";")[1], "m l² sin θ φ̇ = const", kind="equation", **SPHERICAL)
    assert phi.diagnosis == "wrong_equation_single"
    assert phi.feedback[0] == "This equation does not say the same as the expected one."
    # energy for one coordinate: its derivative is the equation of motion times θ̇, which vanishes at rest
    energy = compare("thetaddot = -g/l sin(theta)", "½ m l² θ̇² − m g l cos θ = C", kind="equation", **PENDULUM)
    assert (energy.diagnosis, len(energy.feedback)) == ("conserved_not_motion", 1)
    assert "Differentiate it and divide by that velocity" in energy.feedback[0]


def test_a_conserved_quantity_too_large_to_differentiate_is_left_as_typed():
    huge = " + ".join(f"m l^{k} sin(theta)^{k} phidot^{k}" for k in range(2, 40))
    verdict = compare(SPHERICAL_EOM, f"θ̈ = sin θ cos θ φ̇² − (g/l) sin θ; {huge} = C", kind="equations", **SPHERICAL)
    assert (verdict.status, verdict.diagnosis) == ("not_equivalent", "undefined_symbol")


def test_definitions_that_would_build_huge_numbers_are_not_put_in_place():
    # each equation is within the parser's caps; substituting one into the next is not
    verdict = compare(
        "thetaddot = -g/l sin(theta)", "θ̈ = d, a = 9^99 g, b = a^99, c = b^99, d = c^99", kind="equation", **PENDULUM
    )
    assert verdict.status == "not_equivalent"
    assert "does not define" in verdict.feedback[0]


def test_undefined_names_are_listed_in_order_and_counted_past_six():
    few = compare("m l^2 thetadot", "x10 + x2 + r", **PENDULUM)
    assert few.feedback[0].startswith("Your answer uses `r`, `x₂` and `x₁₀`, which")
    many = compare("m l^2 thetadot", " + ".join(f"x{i}" for i in range(60)), **PENDULUM)
    assert many.feedback[0].startswith("Your answer uses `x₀`, `x₁`, `x₂`, `x₃`, `x₄` and 55 more, which")
    # the way out the feedback offers is one the checker takes: the name defined in the answer
    assert many.feedback[0].endswith("or say what each stands for: …, where x₀ = ….")
    defined = compare("thetaddot = -g/l sin(theta)", "θ̈ = −ω₀² sin θ", kind="equation", **PENDULUM)
    assert defined.feedback[0].endswith("or say what it stands for: …, where ω₀ = ….")
    written = compare("thetaddot = -g/l sin(theta)", "θ̈ = −ω₀² sin θ, where ω₀ = √(g/l)", kind="equation", **PENDULUM)
    assert written.equivalent


def test_partial_derivatives_elsewhere_are_refused_with_a_message():
    verdict = compare("m l^2 thetadot", "∂L/∂θ̇", **PENDULUM)
    assert verdict.status == "invalid"
    assert verdict.feedback[0].startswith("`∂` is read only in the name of what an answer writes out, before `=`")


def test_a_defined_name_before_brackets_is_a_product_not_a_name():
    spring = {"coords": ["x"], "known": ["m", "k"]}
    assert compare("m xddot = -k x", "m(ẍ) = -k x", kind="equation", **spring).status == "equivalent"
    # F = m ẍ = −k x: the equation is in the last two sides, not the last one alone
    assert compare("m xddot = -k x", "F = m ẍ = -k x", kind="equation", **spring).status == "equivalent"
    assert compare("m xddot = -k x", "F = m ẍ = k x", kind="equation", **spring).status == "not_equivalent"
    assert compare("m xddot = -k x", "F = m ẍ = const", kind="equation", **spring).status == "not_equivalent"


@pytest.mark.parametrize(
    ("expected", "submitted", "options", "status"),
    [
        # "+ C" or "+ const" where a constant is allowed: the student's way of saying so
        (L_PENDULUM, L_PENDULUM + " + C", {"kind": "lagrangian"}, "equivalent"),
        (L_PENDULUM, L_PENDULUM + " - 3 const", {"kind": "lagrangian"}, "equivalent"),
        (L_PENDULUM, L_PENDULUM + " + C₁", {"kind": "lagrangian"}, "equivalent"),
        (L_PENDULUM, r"\frac12 m l^2 \dot\theta^2 + mgl\cos\theta + const", {"kind": "lagrangian"}, "equivalent"),
        ("-m g l cos(theta)", "-m g l cos θ + C", {"up_to_constant": True}, "equivalent"),
        # the quantity's own name at its zero, V₀, and the potential's in a Lagrangian: before, undefined names
        ("-m g l cos(theta)", "V = -m g l cos θ + V_0", {"up_to_constant": True, "name": ["V", "U"]}, "equivalent"),
        ("-m g l cos(theta)", "U = -m g l cos θ + U₀", {"up_to_constant": True, "name": ["V", "U"]}, "equivalent"),
        (L_PENDULUM, L_PENDULUM + " - V_0", {"kind": "lagrangian"}, "equivalent"),
        (L_PENDULUM, L_PENDULUM + " + L₀", {"kind": "lagrangian"}, "equivalent"),
        ("-m g l cos(theta)", "-m g l cos θ + V_0 θ", {"up_to_constant": True, "name": ["V", "U"]}, "not_equivalent"),
        # not a constant term of its own, or no constant allowed: C is a name the problem lacks
        (L_PENDULUM, "1/2 m l^2 θ̇^2 + C m g l cos θ", {"kind": "lagrangian"}, "not_equivalent"),
        (L_PENDULUM, L_PENDULUM + " + C^2", {"kind": "lagrangian"}, "not_equivalent"),
        ("-m g l cos(theta)", "-m g l cos θ + C", {}, "not_equivalent"),
        # the constant does not make a wrong answer right
        (L_PENDULUM, "1/2 m l^2 θ̇^2 - m g l cos θ + C", {"kind": "lagrangian"}, "not_equivalent"),
    ],
)
def test_an_arbitrary_constant_may_be_written_where_one_is_allowed(expected, submitted, options, status):
    assert compare(expected, submitted, **options, **PENDULUM).status == status


def test_up_to_constant_allows_another_zero_of_potential():
    expected = "-m g l cos(theta)"
    assert compare(expected, "m g l (1 - cos θ)", **PENDULUM).status == "not_equivalent"
    assert compare(expected, "m g l (1 - cos θ)", up_to_constant=True, **PENDULUM).status == "equivalent"


@pytest.mark.parametrize(
    "submitted",
    # beside 10¹⁴ the whole Lagrangian is below floats' resolution: "a constant" to a careless check
    ["1e14", "1e100", "2^47", "pi^30", "1e14 m", "1e14 + thetadot^2", "1e14 + m g l cos(theta)"],
)
def test_a_huge_constant_is_not_a_lagrangian_plus_a_constant(submitted):
    verdict = compare(L_PENDULUM, submitted, kind="lagrangian", **PENDULUM)
    assert (verdict.status, verdict.score) == ("not_equivalent", 0.0), verdict
    # nor a potential up to a constant: a person decides what floats cannot
    assert compare("-m g l cos(theta)", submitted, up_to_constant=True, **PENDULUM).status != "equivalent"


def test_a_constant_too_small_for_a_float_is_still_judged():
    # e⁻⁷¹⁰ underflows to 0, and 1/0 was no ratio to name: the check failed and said "undecided"
    verdict = compare("sqrt(g/l)", "exp(-710)", **PENDULUM)
    assert verdict.status == "not_equivalent", verdict


@pytest.mark.parametrize("constant", ["5", "1e6 m g l", "1e14", "1e100"])
def test_the_right_lagrangian_plus_any_constant_is_still_right(constant):
    verdict = compare(L_PENDULUM, f"{L_PENDULUM} + {constant}", kind="lagrangian", **PENDULUM)
    assert (verdict.status, verdict.score) == ("equivalent", 1.0), verdict


@pytest.mark.parametrize(
    ("expected", "submitted", "status"),
    [
        ("omega^2 = g/l", "omega = sqrt(g/l)", "equivalent"),  # same positive root
        ("omega = sqrt(g/l)", "omega = -sqrt(g/l)", "not_equivalent"),
        ("p_theta = m l^2 thetadot", "thetadot = p_theta / (m l^2)", "equivalent"),
        ("p_theta = m l^2 thetadot", "thetadot = p_theta / (m l)", "not_equivalent"),
    ],
)
def test_equations_without_accelerations_compare_as_relations(expected, submitted, status):
    known = [*PENDULUM["known"], "p_theta", "omega"]
    assert compare(expected, submitted, kind="equation", coords=["theta"], known=known).status == status


@pytest.mark.parametrize(
    ("expected", "submitted", "status"),
    [
        # a critically damped oscillator's characteristic equation has a double root
        ("s^2 + 2 gamma s + gamma^2 = 0", "s = -gamma", "not_equivalent"),
        ("s^2 + 2 gamma s + gamma^2 = 0", "(s + gamma)^2 (s^2 + 1) = 0", "equivalent"),  # the same roots, as often
        ("s = -gamma", "(s + gamma)^3 = 0", "not_equivalent"),
        ("s^3 = -gamma^3", "s = -gamma", "equivalent"),  # s³ + γ³ = (s + γ)(s² − γs + γ²): one simple real root
        ("s = gamma", "sqrt(s) = sqrt(gamma)", "equivalent"),  # √ is one-to-one; √s − √γ vanishes simply at γ
    ],
)
def test_relations_have_the_same_roots_each_as_often(expected, submitted, status):
    verdict = compare(expected, submitted, kind="equation", known=["s", "gamma"], domains={"s": "real"})
    assert verdict.status == status, verdict


@pytest.mark.parametrize(
    ("kind", "expected", "submitted"),
    [
        # equal for |θ| < π only: √ loses the sign cos(θ/2) takes beyond
        ("expression", "cos(theta/2)", "sqrt((1 + cos(theta))/2)"),
        ("expression", "abs(theta)", "acos(cos(theta))"),
        ("lagrangian", L_PENDULUM, "1/2 m l^2 thetadot^2 + 2 m g l cos(theta/2) sqrt((1 + cos(theta))/2)"),
    ],
)
def test_an_identity_that_fails_beyond_pi_is_not_equivalent(kind, expected, submitted):
    assert compare(expected, submitted, kind=kind, **PENDULUM).status == "not_equivalent"


@pytest.mark.parametrize(
    ("expected", "submitted", "known"),
    [
        # scaled by a factor that is not zero wherever the expected relation is defined
        ("T = m g / cos(alpha)", "T cos(alpha) = m g", ["T", "alpha", "m", "g"]),
        ("a = g sin(alpha)", "a/sin(alpha) = g", ["a", "g", "alpha"]),
        ("tan(alpha) = v^2/(r g)", "sin(alpha) = v^2 cos(alpha)/(r g)", ["alpha", "v", "r", "g"]),
        ("v^2 = 2 g l (1 - cos(theta0))", "v^2/(1 - cos(theta0)) = 2 g l", ["v", "g", "l", "theta0"]),
        ("x = 1 - cos(y)", "1/x = 1/(1 - cos(y))", ["x", "y"]),
    ],
)
def test_a_relation_scaled_by_a_trig_factor_of_a_parameter_is_equivalent(expected, submitted, known):
    # roots far out along α (out to 10³) are simple in both; a step relative to the root,
    # 0.5 at α = 500, measured them as of different order
    verdict = compare(expected, submitted, kind="equation", known=known)
    assert verdict.status == "equivalent", verdict


def test_a_float_that_underflows_far_out_is_no_root():
    # e^(st) never vanishes, but at t = −1000 it underflows to 0: a root only floats would see
    verdict = compare("s^2 = 0", "s^2 e^(s t) = 0", kind="equation", known=["s"], domains={"s": "real"})
    assert (verdict.status, verdict.method) == ("equivalent", "roots"), verdict


@pytest.mark.parametrize(
    ("expected", "submitted", "coords", "known"),
    [
        # an extra root along the one symbol that is not the first: ω = 2
        ("omega = sqrt(g/l)", "(omega - sqrt(g/l))(omega - 2) = 0", [], ["omega", "g", "l"]),
        # multiplied through by sin θ: every θ = nπ is a new solution, whatever φ̇ and p are
        (
            "p = m l^2 sin(theta)^2 phidot",
            "p sin(theta) = m l^2 sin(theta)^3 phidot",
            ["theta", "phi"],
            ["m", "l", "p"],
        ),
        ("x = 0", "x (x - 11) = 0", ["x"], []),  # an extra root beyond ±10
        # multiplied through by a symbol the expected relation does not have: at θ = 0 any p_θ will do
        ("p_theta = m l^2 thetadot", "theta (p_theta - m l^2 thetadot) = 0", ["theta"], ["m", "l", "p_theta"]),
        (
            "p_theta = m l^2 thetadot",
            "p_theta sin(theta) = m l^2 thetadot sin(theta)",
            ["theta"],
            ["m", "l", "p_theta"],
        ),
        # roots that floats put within 10⁻⁶ of each other, told apart at 40 digits
        ("omega^2 = k/m", "omega^2 = k/m (1 + 10^-7)", [], ["omega", "k", "m"]),
        ("omega = sqrt(g/l)", "omega = sqrt(g/l) + 10^-9 g", [], ["omega", "g", "l"]),
        ("cos(theta) = g/(omega^2 l)", "cos(theta) = g/(omega^2 l) + 10^-9", ["theta"], ["omega", "g", "l"]),
    ],
)
def test_a_relation_with_another_root_is_not_equivalent(expected, submitted, coords, known):
    assert compare(expected, submitted, kind="equation", coords=coords, known=known).status == "not_equivalent"


@pytest.mark.parametrize(
    ("expected", "submitted", "status"),
    [
        # at a < 0 both are real only where the exponents are simple numbers: b = 2, c = 1/2 gives a and |a|
        ("a^(b c)", "(a^b)^c", "not_equivalent"),
        ("x^(2 n)", "(x^2)^n", "not_equivalent"),
        # (−1/2)^(−1) = −2, but ((−1/2)^(−2))^(1/2) = 2
        ("(n + 1)^((n + 2)/(n + 1))", "((n + 1)^(1/(n + 1)))^(n + 2)", "not_equivalent"),
        # identities of the principal branch hold at those points too
        ("a^(b + c)", "a^b a^c", "equivalent"),
        ("x^(n/2)", "sqrt(x)^n", "equivalent"),
    ],
)
def test_a_power_of_a_base_that_may_be_negative_is_compared_at_whole_exponents(expected, submitted, status):
    names = ["a", "b", "c", "n", "x"]
    verdict = compare(expected, submitted, known=names, domains=dict.fromkeys(names, "real"))
    assert verdict.status == status, verdict


def test_a_power_of_a_positive_base_keeps_its_identities():
    assert compare("a^(b c)", "(a^b)^c", known=["a", "b", "c"], domains={"b": "real", "c": "real"}).equivalent


PENDULUM_P = {"coords": ["theta"], "known": ["m", "l", "p_theta"]}


@pytest.mark.parametrize("factor", ["exp(θ)", "exp(−θ)", "exp(−θ²)", "exp(θ̇)"])
def test_a_relation_times_a_factor_that_never_vanishes_is_equivalent_though_floats_underflow(factor):
    # far out on the grid e^θ is 0 in floats and tiny at 40 digits: no root, as the values beside it show
    # ~0.2 s, by the roots; a loaded machine once took the default 2 s: the verdict is tested, not the time
    verdict = compare(
        "p_theta = m l^2 thetadot", f"(p_θ − m l² θ̇) {factor} = 0", kind="equation", timeout=20, **PENDULUM_P
    )
    assert verdict.status == "equivalent", verdict


def test_a_relation_multiplied_by_a_parameter_that_may_be_zero_is_not_equivalent():
    # a is declared real, so a = 0 is admissible, and there a·x = a·y holds for every x and y
    assert compare("x = y", "a x = a y", kind="equation", known=["x", "y", "a"], domains={"a": "real"}).status == (
        "not_equivalent"
    )
    # a positive parameter is never zero: multiplying by it keeps the relation
    assert compare("x = y", "a x = a y", kind="equation", known=["x", "y", "a"]).status == "equivalent"


@pytest.mark.parametrize(
    ("submitted", "status"),
    [
        ("yddot = 10^12 g; xddot = m", "equivalent"),
        ("xddot = 2 m; yddot = 10^12 g", "not_equivalent"),  # the small equation is judged on its own scale
        ("xddot = m + 10^-3 m; yddot = 10^12 g", "not_equivalent"),
    ],
)
def test_each_equation_of_a_system_is_judged_on_its_own_scale(submitted, status):
    verdict = compare("xddot = m; yddot = 10^12 g", submitted, kind="equations", coords=["x", "y"], known=["m", "g"])
    assert verdict.status == status, verdict


@pytest.mark.parametrize(
    ("kind", "expected", "submitted", "status"),
    [
        # stiff springs in numbers: accelerations in the thousands beside unit coefficients
        ("equations", "xddot = -3000 x + y; yddot = 2000 (x - y)",
         "0.001 xddot + 3 x - 0.001 y = 0; yddot/2000 = x - y", "equivalent"),
        ("equations", "xddot = -3000 x + y; yddot = 2000 (x - y)",
         "0.001 xddot + 3 x - 0.0011 y = 0; yddot/2000 = x - y", "not_equivalent"),
        ("equation", "xddot = -2*10^6 x + 3*10^6 sin(x)", "10^-3 xddot + 2000 x - 3000 sin(x) = 0", "equivalent"),
        # multiplied through, the acceleration's coefficient is 10¹² times smaller than the rest
        ("equations", "xddot = m; yddot = 10^12 g", "m xddot = m m; l yddot - l 10^12 g = 0", "equivalent"),
        ("equations", "xddot = m; yddot = exp(-10 m x)", "m xddot = m m; l yddot - l exp(-10 m x) = 0", "equivalent"),
        ("equation", "yddot = 10^12 g", "l yddot - l 10^12 g = 0", "equivalent"),
        # off by 1 in 10¹²: floats cannot tell, 40 digits can
        ("equations", "xddot = m; yddot = 10^12 g", "m xddot = m m; l yddot - l 10^12 g = 1", "not_equivalent"),
        ("equation", "yddot = 10^12 g", "l yddot - l 10^12 g - 1 = 0", "not_equivalent"),
        # off by 1 in 10¹⁵: below what floats see at all; the numbers' span asks for fractions
        ("equation", "yddot = 10^12 g", "yddot = 10^12 g + 0.001", "not_equivalent"),
        ("equations", "xddot + yddot = 10^12 g; xddot - yddot = m",
         "2 xddot = 10^12 g + m; 2 yddot = 10^12 g - m + 0.001", "not_equivalent"),
        ("equations", "xddot + yddot = 10^12 g; xddot - yddot = m",
         "2 xddot = 10^12 g + m; 2 yddot = 10^12 g - m", "equivalent"),
    ],
)  # fmt: skip
def test_accelerations_far_larger_than_their_coefficients(kind, expected, submitted, status):
    verdict = compare(expected, submitted, kind=kind, coords=["x", "y"], known=["m", "g", "l"])
    assert verdict.status == status, verdict


HUGE_POTENTIAL = "1/2 m xdot^2 + exp(10 (m + 2)) cos(x)"


@pytest.mark.parametrize(
    ("kind", "expected", "submitted", "status"),
    [
        # beside e^(10(m + 2)) ≥ e²⁴, m is below floats' sight at every point: 40 digits see it
        ("expression", "exp(10 (m + 2))", "exp(10 (m + 2)) + m", "not_equivalent"),
        ("expression", "exp(10 (m + 2)) + m", "m + exp(10 (m + 2))", "equivalent"),
        ("equation", "yddot = exp(10 (m + 2))", "yddot = exp(10 (m + 2)) + m", "not_equivalent"),
        ("equations", "xddot = m; yddot = exp(10 (m + 2))", "xddot = m; yddot = exp(10 (m + 2)) + m", "not_equivalent"),
        # e^(10x²) is 10¹⁷ or more at some states, where floats lose the 1, and ordinary at others
        ("equations", "x^2 xddot = m; yddot = exp(10 x^2)", "x^2 xddot = m; yddot = exp(10 x^2) + 1", "not_equivalent"),
        ("equations", "x^2 xddot = m; yddot = exp(10 x^2)", "yddot = exp(10 x^2); x^2 xddot = m", "equivalent"),
        # a Lagrangian with a potential of e^(10(m + 2)): the kinetic term's change is lost beside it
        ("lagrangian", HUGE_POTENTIAL, f"{HUGE_POTENTIAL} + m xdot^2", "not_equivalent"),
        ("lagrangian", HUGE_POTENTIAL, f"{HUGE_POTENTIAL} + 1/100 xdot^2", "not_equivalent"),
        ("lagrangian", HUGE_POTENTIAL, f"{HUGE_POTENTIAL} + d/dt(m x^2)", "equivalent"),
        ("lagrangian", HUGE_POTENTIAL, f"{HUGE_POTENTIAL} + 7 m", "equivalent"),
        # lost inside a derivative's own sum: (e^(10(m + 2)) + m) ẋ²/2
        ("lagrangian", "1/2 exp(10 (m + 2)) xdot^2 + exp(10 (m + 2)) cos(x)",
         "1/2 (exp(10 (m + 2)) + m) xdot^2 + exp(10 (m + 2)) cos(x)", "not_equivalent"),
        # relations (no accelerations): compared by their ratio, which floats see as 1
        ("equation", "E = exp(10 (m + 2)) + m", "E = exp(10 (m + 2))", "not_equivalent"),
        ("equation", "E = exp(10 (m + 2)) + m", "2 E = 2 exp(10 (m + 2)) + 2 m", "equivalent"),
        # 18 digits typed: more than a float holds
        ("expression", "sin(x)/3", "0.333333333333333333 sin(x)", "not_equivalent"),
        # beyond 40 digits at every point: a person decides, nobody guesses
        ("expression", "exp(100 m) + 1", "exp(100 m) + 1 + 10^-50", "undecided"),
    ],
)  # fmt: skip
def test_a_term_too_small_for_floats_to_see_is_not_ignored(kind, expected, submitted, status):
    verdict = compare(expected, submitted, kind=kind, coords=["x", "y"], known=["m"])
    assert verdict.status == status, verdict


def test_a_relation_that_floats_call_the_same_is_checked_at_40_digits_where_a_term_was_lost():
    # at these points floats agree everywhere: only the lost m says to look again
    verdict = compare("E = exp(10 (m + 2)) + m", "E = exp(10 (m + 2))", kind="equation", coords=["theta"], known=["m"])
    assert verdict.status == "not_equivalent", verdict


def test_a_lagrangian_whose_dynamics_even_40_digits_cannot_judge_goes_to_a_person():
    # beside e^(30g) ≥ 10²⁶, m ẍ is lost even at 40 digits at one draw of g: too few states remain
    lagrangian = "1/2 m xdot^2 + exp(30 g) x"
    verdict = compare(lagrangian, f"{lagrangian} + d/dt(m x^2)", kind="lagrangian", coords=["x"], known=["m", "g"])
    assert verdict.status == "undecided", verdict


def test_a_constant_added_to_nearly_constant_dynamics_is_not_a_factor_one():
    # m ẍ − e^(10(m + 2)) g barely changes along the motion: minus m looks like a factor 1 + 10⁻²²
    lagrangian = "1/2 m xdot^2 + exp(10 (m + 2)) g x"
    verdict = compare(lagrangian, f"{lagrangian} + m x", kind="lagrangian", coords=["x"], known=["m", "g"])
    assert verdict.status == "not_equivalent", verdict


def test_answers_that_differ_by_a_tiny_term_are_not_off_by_a_factor_one():
    verdict = compare("exp(100 m) + 1", "exp(100 m)", known=["m"])
    assert verdict.diagnosis == "missing_term", verdict


def test_a_difference_at_the_edge_of_float_resolution_is_not_hidden_by_the_rows_scale():
    # 1 in 7·10¹² at these points: comparing the rows (c, b) as multiples moves b's difference
    # into c, whose rounding band must be no wider than c itself
    expected, submitted = "yddot = 10^12 g (coth(-m) (m + m))", "yddot = 10^12 g (coth(-m) (m + m)) + 1"
    verdict = compare(expected, submitted, kind="equation", coords=["x", "y"], known=["m", "g"])
    assert verdict.status == "not_equivalent", verdict


def test_an_equation_with_an_acceleration_is_never_called_trivial():
    # beside e^30 ≈ 10¹³ the coefficient 1 of ÿ is within rounding of zero; it is still there
    verdict = compare(
        "xddot = m; yddot = exp(30)", "yddot = exp(30); xddot = m", kind="equations", coords=["x", "y"], known=["m"]
    )
    assert verdict.status == "equivalent", verdict


def test_searching_a_students_roots_does_not_grow_the_prepared_reference():
    # A server keeps prepared answers for its lifetime: what one submission evaluates there
    # must not stay behind (the roots searched for differ with every answer).
    setting = {"kind": "equation", "known": ["s", "gamma"], "domains": {"s": "real"}}
    compare("(s + gamma)^2 = 0", "s = -gamma", **setting)
    reference = prepare("(s + gamma)^2 = 0", "equation", (), ("s", "gamma"), (("s", "real"),))
    compiled = reference.cache[("compiled", "relation")]
    remembered = len(compiled._memo)
    for k in range(2, 8):  # an extra root, and the same root found through another function
        compare("(s + gamma)^2 = 0", f"(s + gamma)^2 (s + {k} gamma) = 0", **setting)
        compare("(s + gamma)^2 = 0", f"(s + gamma)^2 (s^2 + {k}) = 0", **setting)
    assert len(compiled._memo) == remembered


def test_a_lost_double_root_is_named_without_giving_the_root():
    verdict = compare("(s + gamma)^2 = 0", "s = -gamma", kind="equation", known=["s", "gamma"], domains={"s": "real"})
    assert verdict.diagnosis == "root_multiplicity"
    assert "not each as often" in verdict.feedback[0] and "gamma" not in verdict.feedback[0]
    wrong_root = compare("(s + gamma)^2 = 0", "s = gamma", kind="equation", known=["s", "gamma"], domains={"s": "real"})
    assert wrong_root.diagnosis == "wrong_equation_single"


@pytest.mark.parametrize(
    ("kind", "expected", "submitted", "options", "status"),
    [
        ("integer", "3", "3", {}, "equivalent"),
        ("integer", "3", "6/2", {}, "equivalent"),
        ("integer", "3", "4", {}, "not_equivalent"),
        ("integer", "3", "3.5", {}, "not_equivalent"),
        # exactly: nsimplify's tolerance would round these to 15
        ("integer", "15", "15 + 10^-29", {}, "not_equivalent"),
        ("integer", "15", "15.0000000000000000000000001", {}, "not_equivalent"),
        ("integer", "15", "15 + exp(-100)", {}, "not_equivalent"),
        ("integer", "15", "log(2^15)/log(2)", {}, "equivalent"),
        ("number", "2 pi", "6.2832", {"rtol": 1e-4}, "equivalent"),
        ("number", "2 pi", "6.28", {"rtol": 1e-4}, "not_equivalent"),
        ("number", "9.81", "9.8", {"atol": 0.05, "rtol": 0}, "equivalent"),
        ("choice", "b", "B", {"options": ["a", "b", "c"]}, "equivalent"),
        ("choice", "a, c", "c; a", {"options": ["a", "b", "c"], "multiple": True}, "equivalent"),
        ("choice", "a, c", "a", {"options": ["a", "b", "c"], "multiple": True}, "not_equivalent"),
        ("choice", "b", "d", {"options": ["a", "b", "c"]}, "invalid"),
        ("choice", "b", "a, b", {"options": ["a", "b", "c"]}, "not_equivalent"),
    ],
)
def test_scalar_kinds(kind, expected, submitted, options, status):
    assert compare(expected, submitted, kind=kind, **options).status == status


CONSTRAINT = (("a", "holonomic"), ("b", "non-holonomic"), ("c", r"$\theta$ and $\phi$"), ("d", "holonomic"))


@pytest.mark.parametrize(
    ("expected", "submitted", "status", "read"),
    [
        ("b", "Non-holonomic", "equivalent", "b"),  # an option's own words, in any case, spacing or hyphen
        ("b", "nonholonomic", "equivalent", "b"),
        ("b", "non - holonomic", "equivalent", "b"),
        ("c", "θ and φ", "equivalent", "c"),  # its TeX as typed letters
        ("c", r"\theta and \phi", "equivalent", "c"),
        ("b", "holonomic", "invalid", None),  # the words of two options name neither
        ("b", "the second one", "invalid", None),
        ("b", "B", "equivalent", None),  # a label is read as a label first
        ("b", "anholonomic", "equivalent", "b"),  # another textbook's name for it
        # "not holonomic" is the option that says so in one word, never holonomic
        ("b", "not holonomic", "equivalent", "b"),
        ("b", "The constraint is not holonomic.", "equivalent", "b"),
        ("b", "it's non-holonomic", "equivalent", "b"),
        ("b", "It’s not holonomic", "equivalent", "b"),
        ("a", "not non-holonomic", "invalid", None),
        # the kind with the noun it qualifies
        ("b", "non-holonomic constraint", "equivalent", "b"),
        ("b", "Nonholonomic constraints", "equivalent", "b"),
        ("b", "It is a non-holonomic constraint", "equivalent", "b"),
        ("b", "anholonomic constraint", "equivalent", "b"),
        ("b", "a non-holonomic constraint", "equivalent", "b"),  # the article, not a label: a constraint
    ],
)
def test_a_choice_may_be_written_as_the_options_words(expected, submitted, status, read):
    verdict = compare(expected, submitted, kind="choice", options=CONSTRAINT)
    assert verdict.status == status
    assert (verdict.feedback[-1] == f"Read as the option you wrote out: {read}.") == (read is not None)


HOOP_CONSTRAINT = (
    ("a", "scleronomic, since the hoop's shape and size are fixed"),
    ("b", "rheonomic, since the constraint depends explicitly on time"),
    ("c", "it is not holonomic, so neither applies"),
    ("d", "rheonomic because the hoop turns"),
)


def test_words_that_name_no_option_are_shown_as_typed_and_a_missing_label_alone():
    words = compare("b", "the first one", kind="choice", options=HOOP_CONSTRAINT)
    assert words.feedback == ("`the first one` is not one of the options (a, b, c, d).",)
    label = compare("b", "a, e", kind="choice", options=HOOP_CONSTRAINT)
    assert label.feedback == ("e is not one of the options (a, b, c, d).",)


@pytest.mark.parametrize(
    ("submitted", "status", "read"),
    [
        ("scleronomic", "not_equivalent", "a"),  # the option's claim, without its reason
        ("It is not holonomic", "not_equivalent", "c"),
        ("rheonomic", "invalid", None),  # the claim of two options names neither
        ("since the constraint depends explicitly on time", "invalid", None),  # a reason is no claim
    ],
)
def test_a_choice_may_be_written_as_its_claim_without_the_reason(submitted, status, read):
    verdict = compare("b", submitted, kind="choice", options=HOOP_CONSTRAINT)
    assert verdict.status == status
    assert (verdict.feedback[-1] == f"Read as the option you wrote out: {read}.") == (read is not None)


TEX_CHOICES = [
    # (submitted, status, feedback): a choice set in TeX, as typed in a TeX box, reads as without it (before,
    # "`\text{b}` is not one of the options")
    (r"\text{b}", "equivalent", ("Correct.",)),
    (r"$b$", "equivalent", ("Correct.",)),
    (r"$\textbf{(b)}$", "equivalent", ("Correct.",)),
    (r"\(b\)", "equivalent", ("Correct.",)),
    (r"\text{a}", "not_equivalent", ("Not the right choice.",)),
    (r"\text{rheonomic}", "equivalent", ("Correct.", "Read as the option you wrote out: b.")),
    (r"$b$, since the hoop rotates", "equivalent",
     ("Correct.", "Graded your choice, b; what follows it (`since the hoop rotates`) is not graded.")),
    (r"\text{b or c}", "invalid",
     ("One option is asked for here, and your answer `\\text{b or c}` offers another, or doubts or denies the one it"
      " names: give the one you mean.",)),
    (r"\text{d}", "invalid", ("d is not one of the options (a, b, c).",)),
]  # fmt: skip


@pytest.mark.parametrize(("submitted", "status", "feedback"), TEX_CHOICES)
def test_a_choice_set_in_tex_reads_as_without_it(submitted, status, feedback):
    verdict = compare("b", submitted, kind="choice", options=HOOP_CONSTRAINT[:3])
    assert (verdict.status, verdict.feedback) == (status, feedback), verdict


def _hedged(typed):
    return (
        f"One option is asked for here, and your answer `{typed}` offers another, or doubts or denies the one it"
        " names: give the one you mean."
    )


def _past(labels, rest):
    return f"Graded your choice, {labels}; what follows it (`{rest}`) is not graded."


def _read_past(labels, rest):
    return f"Read as the option you wrote out: {labels}; what follows it (`{rest}`) is not graded."


def _option_read(feedback):
    """The options a verdict's feedback says the answer's words were read as, or None."""
    notes = (re.match(r"Read as the option you wrote out: (.*?)[.;]", line) for line in feedback)
    return next((note[1] for note in notes if note), None)


TIME_CHOICE = {"kind": "choice", "options": (("a", "scleronomic"), ("b", "rheonomic"))}
CYCLIC_CHOICE = {"kind": "choice", "options": (("a", r"$\theta$"), ("b", r"$\phi$"), ("c", "neither"), ("d", "both"))}


@pytest.mark.parametrize(
    ("submitted", "status", "read"),
    [
        # a sentence whose subject or predicate is an option's words
        ("phi is cyclic", "equivalent", "b"),
        ("φ is the cyclic coordinate", "equivalent", "b"),
        ("The cyclic coordinate is φ", "equivalent", "b"),
        ("φ is cyclic, since L does not depend on φ", "equivalent", "b"),
        ("θ is cyclic", "not_equivalent", "a"),
        ("both are cyclic", "not_equivalent", "d"),
        ("neither is cyclic", "not_equivalent", "c"),
        # a coordinate by its description, then its letter
        ("the azimuthal angle φ", "equivalent", "b"),
        ("The azimuthal angle $\\varphi$ is cyclic", "equivalent", "b"),
        ("the polar angle θ", "not_equivalent", "a"),
        # the one option, said to be the only one
        ("φ only", "equivalent", "b"),
        ("only phi", "equivalent", "b"),
        ("Only φ is cyclic", "equivalent", "b"),
        ("just θ", "not_equivalent", "a"),
        # denied, hedged, or naming two options: which is meant is for the student to say
        ("θ is not cyclic", "invalid", None),
        ("θ isn't cyclic", "invalid", None),
        ("φ is cyclic or θ", "invalid", None),
        ("θ is φ", "invalid", None),
        ("not the angle φ", "invalid", None),
        ("maybe the angle φ", "invalid", None),
        ("the angle φ or θ", "invalid", None),
    ],
)
def test_a_choice_may_be_said_in_a_sentence(submitted, status, read):
    verdict = compare("b", submitted, **CYCLIC_CHOICE)
    assert verdict.status == status, verdict
    assert _option_read(verdict.feedback) == read


FORCE_CHOICE = {
    "kind": "choice",
    "options": (
        ("a", r"$-\partial V / \partial q_j$"),
        ("b", r"$\partial V / \partial q_j$"),
        ("c", r"$-\partial V / \partial \dot q_j$"),
        ("d", r"$-\frac{d}{dt}\left(\partial V / \partial \dot q_j\right)$"),
    ),
}
WORK_CHOICE = {
    "kind": "choice",
    "options": (("a", "positive"), ("b", "zero"), ("c", "negative"), ("d", "depends on the path")),
}
INSTANT_CHOICE = {
    "kind": "choice",
    "options": (("a", "advances by $dt$, following the actual motion"), ("b", r"is held fixed, $\delta t = 0$")),
}
DOTS_CHOICE = {
    "kind": "choice",
    "options": (
        ("a", r"$\partial \mathbf r_i / \partial q_j$"),
        ("b", r"$0$, since $\mathbf r_i$ does not depend on $\dot q_j$"),
        ("c", r"$\partial \mathbf r_i / \partial t$"),
    ),
}


@pytest.mark.parametrize(
    ("options", "expected", "submitted", "status", "read"),
    [
        # an option that is a formula, typed as one: as the parser reads it, in any notation
        (FORCE_CHOICE, "a", "-∂V/∂q_j", "equivalent", "a"),
        (FORCE_CHOICE, "a", "−∂V/∂q_j", "equivalent", "a"),
        (FORCE_CHOICE, "a", r"-\partial V / \partial q_j", "equivalent", "a"),
        (FORCE_CHOICE, "a", r"$-\partial V / \partial q_j$", "equivalent", "a"),
        (FORCE_CHOICE, "a", "Q_j = -∂V/∂q_j", "equivalent", "a"),  # the value after the asked quantity's name
        (FORCE_CHOICE, "a", "−∂V/∂q_j, by the chain rule", "equivalent", "a"),
        # a fraction of one name over one name, ∂ before each perhaps, in TeX's \frac as inline
        (FORCE_CHOICE, "a", r"-\frac{\partial V}{\partial q_j}", "equivalent", "a"),
        (FORCE_CHOICE, "a", r"Q_j = -\frac{\partial V}{\partial q_j}", "equivalent", "a"),
        (FORCE_CHOICE, "a", r"\frac{\partial V}{\partial q_j}", "not_equivalent", "b"),
        (FORCE_CHOICE, "a", r"-\frac{\partial V}{\partial \dot q_j}", "not_equivalent", "c"),
        (FORCE_CHOICE, "a", "-d/dt(∂V/∂q̇_j)", "not_equivalent", "d"),
        (FORCE_CHOICE, "a", r"-\frac{\partial V}{\partial q_j \partial q_j}", "invalid", None),
        (FORCE_CHOICE, "a", r"-\frac{\partial V}{2 \partial q_j}", "invalid", None),
        (FORCE_CHOICE, "a", "∂V/∂q_j", "not_equivalent", "b"),
        (FORCE_CHOICE, "a", "Q_j = ∂V/∂q_j", "not_equivalent", "b"),
        (FORCE_CHOICE, "a", "-∂V/∂q̇_j", "not_equivalent", "c"),
        (FORCE_CHOICE, "a", r"-\partial V / \partial \dot q_j", "not_equivalent", "c"),
        # its sign, dots and letters count: no option is read where none is typed
        (FORCE_CHOICE, "a", r"\partial V / \partial \dot q_j", "invalid", None),
        (FORCE_CHOICE, "a", "∂V/∂q̇_j", "invalid", None),
        (FORCE_CHOICE, "a", "-∂v/∂q_j", "invalid", None),
        (FORCE_CHOICE, "a", "-∂V/∂q_j or ∂V/∂q_j", "invalid", None),
        (FORCE_CHOICE, "a", "-∂V/∂q_j, ∂V/∂q_j", "invalid", None),
        (FORCE_CHOICE, "a", "∂V/∂q_j = -∂V/∂q_j", "invalid", None),
        # a number, in digits or words; a formula of its own between an option's commas
        (WORK_CHOICE, "b", "0", "equivalent", "b"),
        (WORK_CHOICE, "b", "zero", "equivalent", "b"),
        (WORK_CHOICE, "b", "1", "invalid", None),
        (INSTANT_CHOICE, "b", "δt = 0", "equivalent", "b"),
        (INSTANT_CHOICE, "b", r"\delta t = 0", "equivalent", "b"),
        (INSTANT_CHOICE, "b", "dt", "invalid", None),  # a formula inside the option's words is no option
        (DOTS_CHOICE, "a", "∂r_i/∂q_j", "equivalent", "a"),
        (DOTS_CHOICE, "a", r"\partial \mathbf{r}_i / \partial q_j", "equivalent", "a"),
        (DOTS_CHOICE, "a", r"\frac{\partial \mathbf{r}_i}{\partial q_j}", "equivalent", "a"),
        (DOTS_CHOICE, "a", "0", "not_equivalent", "b"),
        (DOTS_CHOICE, "a", "∂ṙ_i/∂q_j", "invalid", None),
        # a letter, in any of its spellings
        (CYCLIC_CHOICE, "b", "varphi", "equivalent", "b"),
        (CYCLIC_CHOICE, "b", r"\varphi", "equivalent", "b"),
        (CYCLIC_CHOICE, "b", "vartheta", "not_equivalent", "a"),
    ],
)
def test_an_option_that_is_a_formula_may_be_typed_as_one(options, expected, submitted, status, read):
    verdict = compare(expected, submitted, **options)
    assert verdict.status == status, verdict
    assert _option_read(verdict.feedback) == read


@pytest.mark.parametrize(
    ("submitted", "status", "feedback"),
    [
        # a label, then its option's words, or after a mark a reason: the label, and what was read past said
        ("b (rheonomic)", "equivalent", ("Correct.",)),
        ("b) rheonomic", "equivalent", ("Correct.",)),
        ("(b) Rheonomic", "equivalent", ("Correct.",)),
        ("b. rheonomic", "equivalent", ("Correct.",)),
        ("b, since l = l(t)", "equivalent", ("Correct.", _past("b", "since l = l(t)"))),
        ("b - it depends on time", "equivalent", ("Correct.", _past("b", "it depends on time"))),
        ("a: scleronomic", "not_equivalent", ("Not the right choice.",)),
        ("b, not a", "equivalent", ("Correct.", _past("b", "not a"))),  # the other option set aside
        ("b (not scleronomic)", "equivalent", ("Correct.", _past("b", "(not scleronomic)"))),
        ("b, not rheonomic", "invalid", (_hedged("b, not rheonomic"),)),
        # or a reason in brackets, as after a comma
        ("b (the hoop rotates)", "equivalent", ("Correct.", _past("b", "(the hoop rotates)"))),
        ("b (the hoop's axis turns)", "equivalent", ("Correct.", _past("b", "(the hoop's axis turns)"))),
        ("a (the hoop's shape is fixed)", "not_equivalent",
         ("Not the right choice.", _past("a", "(the hoop's shape is fixed)"))),
        ("b (a)", "invalid", (_hedged("b (a)"),)),
        ("b (or a)", "invalid", (_hedged("b (or a)"),)),
        ("b (maybe scleronomic)", "invalid", (_hedged("b (maybe scleronomic)"),)),
        # the claim, then the reason
        ("rheonomic because l depends on t", "equivalent", ("Correct.", _read_past("b", "because l depends on t"))),
        # the option's words, then a remark in brackets that names no other option and does not hedge
        ("rheonomic (t appears explicitly)", "equivalent", ("Correct.", _read_past("b", "(t appears explicitly)"))),
        ("rheonomic (l = l(t), set from outside)", "equivalent",
         ("Correct.", _read_past("b", "(l = l(t), set from outside)"))),
        ("rheonomic (scleronomic, …)", "invalid", (_hedged("rheonomic (scleronomic, …)"),)),
        # Goldstein's names for them
        ("Rheonomous", "equivalent", ("Correct.", "Read as the option you wrote out: b.")),
        ("b (rheonomous)", "equivalent", ("Correct.",)),
        ("scleronomous", "not_equivalent", ("Not the right choice.", "Read as the option you wrote out: a.")),
        ("rheonomic (scleronomic)", "invalid", (_hedged("rheonomic (scleronomic)"),)),
        ("rheonomic (or scleronomic)", "invalid", (_hedged("rheonomic (or scleronomic)"),)),
        # a label and words that name another option: which one is meant?
        ("a (rheonomic)", "invalid",
         ("Your label a and your words `rheonomic` name different options: give one of them.",)),
        # a label, a space, and words that are no reason
        ("b foo", "invalid", ("`b foo` is not one of the options (a, b).",)),
        ("not scleronomic", "invalid", ("`not scleronomic` is not one of the options (a, b).",)),  # no non-scleronomic
        ("It is not scleronomic", "invalid", ("`It is not scleronomic` is not one of the options (a, b).",)),
        ("b or a", "invalid", (_hedged("b or a"),)),
        ("b, e", "invalid", ("e is not one of the options (a, b).",)),
        ("b - or maybe a", "invalid", (_hedged("b - or maybe a"),)),
    ],
)  # fmt: skip
def test_a_label_may_come_with_its_options_words_or_a_reason(submitted, status, feedback):
    verdict = compare("b", submitted, **TIME_CHOICE)
    assert (verdict.status, verdict.feedback) == (status, feedback)


@pytest.mark.parametrize(
    ("submitted", "options", "status"),
    [
        # two options' words, or one and a hedge: no claim and its reason, so which is meant is asked
        ("φ, θ", CYCLIC_CHOICE, "invalid"),
        ("phi; theta", CYCLIC_CHOICE, "invalid"),
        ("φ, or θ", CYCLIC_CHOICE, "invalid"),
        ("φ, both", CYCLIC_CHOICE, "invalid"),
        ("φ, neither", CYCLIC_CHOICE, "invalid"),
        ("rheonomic, scleronomic", TIME_CHOICE, "invalid"),
        ("rheonomic, maybe scleronomic", TIME_CHOICE, "invalid"),
        ("rheonomic, a", TIME_CHOICE, "invalid"),  # words, then another option's label
        ("b; not b", TIME_CHOICE, "invalid"),
        # a clarifying "not" before another option confirms the choice; before the same, takes it back
        ("rheonomic, not scleronomic", TIME_CHOICE, "equivalent"),
        ("rheonomic, not scleronomic, since l = l(t)", TIME_CHOICE, "equivalent"),
        ("scleronomic, not rheonomic", TIME_CHOICE, "not_equivalent"),
        ("φ, not θ", CYCLIC_CHOICE, "equivalent"),
        ("the azimuthal angle φ, not θ", CYCLIC_CHOICE, "equivalent"),
        ("rheonomic, not rheonomic", TIME_CHOICE, "invalid"),
        ("rheonomic (not b)", TIME_CHOICE, "invalid"),
        ("φ (not φ)", CYCLIC_CHOICE, "invalid"),
        ("φ, not θ or both", CYCLIC_CHOICE, "invalid"),
        ("rheonomic, not scleronomic, or maybe scleronomic", TIME_CHOICE, "invalid"),
        # a reason may name the other option: it says why, it does not choose
        ("φ, because θ appears in L", CYCLIC_CHOICE, "equivalent"),
        ("rheonomic, since a constraint depends on t", TIME_CHOICE, "equivalent"),
        ("rheonomic, b", TIME_CHOICE, "equivalent"),  # the same option twice
    ],
)
def test_an_option_then_another_or_a_hedge_is_no_choice(submitted, options, status):
    verdict = compare("b", submitted, **options)
    assert verdict.status == status, verdict


@pytest.mark.parametrize(
    ("submitted", "status"),
    [
        ("b\u200b", "equivalent"),  # a zero-width space, pasted
        ("ｂ", "equivalent"),  # a full-width letter
        ("\u200fb", "equivalent"),  # a mark of writing direction
        ("b.", "equivalent"),  # the full stop of a sentence
        ("(b).", "equivalent"),
        ("b?", "invalid"),  # asks: no answer
    ],
)
def test_a_label_is_read_as_it_looks(submitted, status):
    verdict = compare("b", submitted, **TIME_CHOICE)
    assert verdict.status == status, verdict


HOLONOMY_CHOICE = {"kind": "choice", "options": (("a", "holonomic"), ("b", "non-holonomic"))}
RADIAL_CHOICE = {"kind": "choice", "options": (("a", "$r$"), ("b", r"$\theta$"), ("c", r"both $r$ and $\theta$"))}


@pytest.mark.parametrize(
    ("options", "submitted"),
    [
        # another option offered beside the one named, in brackets or after it
        (HOLONOMY_CHOICE, "non-holonomic (maybe holonomic)"),
        (TIME_CHOICE, "rheonomic (but scleronomic too)"),
        (CYCLIC_CHOICE, "φ (maybe θ)"),
        (CYCLIC_CHOICE, "φ is cyclic (θ too)"),  # θ too is option d, both
        (HOLONOMY_CHOICE, "non-holonomic (both)"),
        (HOLONOMY_CHOICE, "non-holonomic (either)"),
        (HOLONOMY_CHOICE, "non-holonomic (actually holonomic)"),
        (HOLONOMY_CHOICE, "non-holonomic (could also be holonomic)"),
        (HOLONOMY_CHOICE, "non-holonomic, unless it is holonomic"),
        (HOLONOMY_CHOICE, "b (maybe a)"),
        (TIME_CHOICE, "rheonomic (or scleronomic)"),
        (TIME_CHOICE, "rheonomic (but scleronomic)"),  # another option named, with no hedge word
        (TIME_CHOICE, "b (I mean a)"),
        (TIME_CHOICE, "b (=a)"),
        (TIME_CHOICE, "b, no wait, a"),
        (TIME_CHOICE, "rheonomic, no wait, scleronomic"),
        (TIME_CHOICE, "rheonomic (no, scleronomic)"),
        (CYCLIC_CHOICE, "φ (θ)"),
        (CYCLIC_CHOICE, "φ (=θ)"),
        (FORCE_CHOICE, "−∂V/∂q_j (+∂V/∂q_j)"),
        # the option named denied, doubted or taken back
        (HOLONOMY_CHOICE, "b (false)"),
        (HOLONOMY_CHOICE, "b (incorrect)"),
        (HOLONOMY_CHOICE, "non-holonomic is wrong"),
        (HOLONOMY_CHOICE, "non-holonomic is inaccurate"),
        (HOLONOMY_CHOICE, "non-holonomic is a mistake"),
        (HOLONOMY_CHOICE, "non-holonomic is an error"),
        (HOLONOMY_CHOICE, "non-holonomic is invalid"),
        (HOLONOMY_CHOICE, "non-holonomic is erroneous"),
        (HOLONOMY_CHOICE, "non-holonomic is mistaken"),
        (HOLONOMY_CHOICE, "non-holonomic is bogus"),
        (HOLONOMY_CHOICE, "non-holonomic is nonsense"),
        (HOLONOMY_CHOICE, "non-holonomic is a myth"),
        (HOLONOMY_CHOICE, "non-holonomic is a lie"),
        (HOLONOMY_CHOICE, "non-holonomic is fake"),
        (HOLONOMY_CHOICE, "non-holonomic is a misconception"),
        (HOLONOMY_CHOICE, "non-holonomic: untrue"),
        (HOLONOMY_CHOICE, "b (untrue)"),
        (HOLONOMY_CHOICE, "b (inaccurate)"),
        (HOLONOMY_CHOICE, "b (a trap)"),
        # a truth taken back denies (before, right)
        (HOLONOMY_CHOICE, "b (not valid)"),
        (HOLONOMY_CHOICE, "non-holonomic, which is not accurate"),
        # another option called right (before, right)
        (HOLONOMY_CHOICE, "b (a is correct)"),
        (HOLONOMY_CHOICE, "b, a is valid"),
        (TIME_CHOICE, "rheonomic is inaccurate"),
        (CYCLIC_CHOICE, "φ is a misconception"),
        (TIME_CHOICE, "rheonomic is false"),
        (TIME_CHOICE, "rheonomic: false"),
        (TIME_CHOICE, "rheonomic (not sure)"),
        (TIME_CHOICE, "b (not really)"),
        (TIME_CHOICE, "b (no)"),
        (TIME_CHOICE, "rheonomic (nope)"),
        (TIME_CHOICE, "rheonomic, or not"),
        (TIME_CHOICE, "b (50/50)"),
        (TIME_CHOICE, "rheonomic (90% sure)"),
        (TIME_CHOICE, "rheonomic (I think)"),
        (TIME_CHOICE, "b (?)"),
        (TIME_CHOICE, "b (a‽)"),
        # a label or another option's name set equal to the option
        (CYCLIC_CHOICE, "a = φ"),
        (RADIAL_CHOICE, "r = θ"),
        (FORCE_CHOICE, "b = −∂V/∂q_j"),
        # as typed on other keyboards: full-width letters and brackets, a no-break space
        (TIME_CHOICE, "b (ｍａｙｂｅ ａ)"),
        (TIME_CHOICE, "b （maybe a）"),
        (TIME_CHOICE, "rheonomic\u00a0(maybe scleronomic)"),
    ],
)
def test_an_option_hedged_doubted_or_denied_is_refused_and_one_asked_for(options, submitted):
    expected = "a" if options is FORCE_CHOICE else "b"  # the option named first is the right one
    verdict = compare(expected, submitted, **options)
    assert (verdict.status, verdict.score, verdict.feedback) == ("invalid", 0.0, (_hedged(submitted),))


def test_a_long_hedged_choice_is_repeated_cut_short_as_every_note_cuts_one():
    # before, cut at 40 characters, mid-word and with no "…"
    verdict = compare(
        "b", "non-holonomic; but the surface constraint is maybe not valid once it leaves", **HOLONOMY_CHOICE
    )
    assert verdict.feedback == (_hedged("non-holonomic; but the surface constraint is maybe not vali…"),)


@pytest.mark.parametrize(
    ("options", "submitted"),
    [
        # the same hedges with the wrong option named first: never read as that option, so never right either way
        (HOLONOMY_CHOICE, "holonomic (maybe non-holonomic)"),
        (TIME_CHOICE, "scleronomic (but rheonomic too)"),
        (CYCLIC_CHOICE, "θ (maybe φ)"),
        (TIME_CHOICE, "a (maybe b)"),
        (TIME_CHOICE, "a, no wait, b"),
        (TIME_CHOICE, "scleronomic, unless it is rheonomic"),
    ],
)
def test_a_hedge_is_refused_whichever_option_it_names_first(options, submitted):
    verdict = compare("b", submitted, **options)
    assert (verdict.status, verdict.score, verdict.feedback) == ("invalid", 0.0, (_hedged(submitted),))


@pytest.mark.parametrize(
    ("options", "expected", "submitted", "status", "feedback"),
    [
        # a remark or a reason after the option is read past, and said so
        # a denial taken back affirms (before, refused as a denial: fix-s's words, and wrong, false)
        (HOLONOMY_CHOICE, "b", "b (no error)", "equivalent", ("Correct.", _past("b", "(no error)"))),
        (HOLONOMY_CHOICE, "b", "b (not a trap)", "equivalent", ("Correct.", _past("b", "(not a trap)"))),
        (HOLONOMY_CHOICE, "b", "b, which is no myth", "equivalent", ("Correct.", _past("b", "which is no myth"))),
        (HOLONOMY_CHOICE, "b", "b (that is not a lie)", "equivalent",
         ("Correct.", _past("b", "(that is not a lie)"))),
        (HOLONOMY_CHOICE, "b", "b, without error", "equivalent", ("Correct.", _past("b", "without error"))),
        (HOLONOMY_CHOICE, "b", "b (not wrong)", "equivalent", ("Correct.", _past("b", "(not wrong)"))),
        # a denial of another option is a reason (before, refused as a doubt of the chosen one)
        (HOLONOMY_CHOICE, "b", "b (a is untrue)", "equivalent", ("Correct.", _past("b", "(a is untrue)"))),
        (HOLONOMY_CHOICE, "b", "b, a is wrong", "equivalent", ("Correct.", _past("b", "a is wrong"))),
        (HOLONOMY_CHOICE, "b", "b, since holonomic is invalid here", "equivalent",
         ("Correct.", _past("b", "since holonomic is invalid here"))),
        (TIME_CHOICE, "b", "b (since the constraint depends on time)", "equivalent",
         ("Correct.", _past("b", "(since the constraint depends on time)"))),
        (TIME_CHOICE, "b", "b, because the hoop turns", "equivalent",
         ("Correct.", _past("b", "because the hoop turns"))),
        (CYCLIC_CHOICE, "b", "φ, since L does not depend on it", "equivalent",
         ("Correct.", _read_past("b", "since L does not depend on it"))),
        (CYCLIC_CHOICE, "b", "φ, because θ appears in L", "equivalent",  # a reason may name another option
         ("Correct.", _read_past("b", "because θ appears in L"))),
        (HOLONOMY_CHOICE, "b", "b (r ≥ a)", "equivalent", ("Correct.", _past("b", "(r ≥ a)"))),  # a is a radius
        (HOLONOMY_CHOICE, "b", "non-holonomic (r ≥ a, an inequality)", "equivalent",
         ("Correct.", _read_past("b", "(r ≥ a, an inequality)"))),
        # "lie" as a verb, and an en dash for the hyphen: no denial, and the option's words
        (HOLONOMY_CHOICE, "b", "non-holonomic, since it may lie anywhere outside", "equivalent",
         ("Correct.", _read_past("b", "since it may lie anywhere outside"))),
        (HOLONOMY_CHOICE, "b", "non–holonomic", "equivalent", ("Correct.", "Read as the option you wrote out: b.")),
        (TIME_CHOICE, "b", "scleronomic (no explicit t)", "not_equivalent",
         ("Not the right choice.", _read_past("a", "(no explicit t)"))),
        (TIME_CHOICE, "b", "b (correct)", "equivalent", ("Correct.", _past("b", "(correct)"))),
        (CYCLIC_CHOICE, "b", "φ is cyclic (since L lacks it)", "equivalent",
         ("Correct.", _read_past("b", "(since L lacks it)"))),
        (TIME_CHOICE, "b", "the answer is b or a", "invalid", (_hedged("the answer is b or a"),)),
        # a label said to be the answer, or an option's words in brackets or with a mark after them
        (TIME_CHOICE, "b", "The answer is b.", "equivalent", ("Correct.",)),
        (TIME_CHOICE, "b", "I choose b", "equivalent", ("Correct.",)),
        (TIME_CHOICE, "b", "option b", "equivalent", ("Correct.",)),
        (TIME_CHOICE, "b", "b is correct", "equivalent", ("Correct.",)),
        (TIME_CHOICE, "b", "Ans: b", "equivalent", ("Correct.",)),
        (TIME_CHOICE, "b", "ans. (b)", "equivalent", ("Correct.",)),
        (TIME_CHOICE, "b", "Ans b", "equivalent", ("Correct.",)),
        (TIME_CHOICE, "b", "b is the answer", "equivalent", ("Correct.",)),
        (TIME_CHOICE, "b", "I choose rheonomic", "equivalent", ("Correct.", "Read as the option you wrote out: b.")),
        (TIME_CHOICE, "b", "(rheonomic)", "equivalent", ("Correct.", "Read as the option you wrote out: b.")),
        (TIME_CHOICE, "b", "rheonomic!", "equivalent", ("Correct.", "Read as the option you wrote out: b.")),
        (FORCE_CHOICE, "a", "(−∂V/∂q_j)", "equivalent", ("Correct.", "Read as the option you wrote out: a.")),
        # two labels, then a reason: two options, where one is asked for
        (TIME_CHOICE, "a", "a, b (since the hoop turns)", "not_equivalent", ("Choose one option.",)),
        (TIME_CHOICE, "a", "a, b, since the hoop turns", "not_equivalent", ("Choose one option.",)),
    ],
)  # fmt: skip
def test_what_follows_an_option_is_read_past_and_said(options, expected, submitted, status, feedback):
    verdict = compare(expected, submitted, **options)
    assert (verdict.status, verdict.score, verdict.feedback) == (status, float(status == "equivalent"), feedback)


@pytest.mark.parametrize(
    ("options", "expected", "submitted", "status", "feedback"),
    [
        # a label closed by a bracket, as lists are written, then a remark
        (HOLONOMY_CHOICE, "b", "b) it is an inequality", "equivalent", ("Correct.", _past("b", "it is an inequality"))),
        (TIME_CHOICE, "b", "b) the hoop turns", "equivalent", ("Correct.", _past("b", "the hoop turns"))),
        (TIME_CHOICE, "b", "b: rheonomic, because l = l(t)", "equivalent",
         ("Correct.", _past("b", "because l = l(t)"))),  # the bracket of l(t) is the remark's own
        (TIME_CHOICE, "b", "b - rheonomic since l = l(t)", "equivalent", ("Correct.", _past("b", "since l = l(t)"))),
        (TIME_CHOICE, "b", "a) nothing moves", "not_equivalent",
         ("Not the right choice.", _past("a", "nothing moves"))),
        # a label said to be the answer, then a reason
        (TIME_CHOICE, "b", "b is correct, since the hoop turns", "equivalent",
         ("Correct.", _past("b", "since the hoop turns"))),
        (TIME_CHOICE, "b", "b is correct (the hoop turns)", "equivalent", ("Correct.", _past("b", "(the hoop turns)"))),
        (TIME_CHOICE, "b", "The answer is b, because l = l(t)", "equivalent",
         ("Correct.", _past("b", "because l = l(t)"))),
        (TIME_CHOICE, "b", "a is correct, since nothing moves", "not_equivalent",
         ("Not the right choice.", _past("a", "since nothing moves"))),
        (TIME_CHOICE, "b", "b is correct, or a", "invalid", (_hedged("b is correct, or a"),)),
        (TIME_CHOICE, "b", "b is correct, maybe", "invalid", (_hedged("b is correct, maybe"),)),
    ],
)  # fmt: skip
def test_a_label_with_a_remark_as_students_write_it(options, expected, submitted, status, feedback):
    verdict = compare(expected, submitted, **options)
    assert (verdict.status, verdict.score, verdict.feedback) == (status, float(status == "equivalent"), feedback)


def _scribbled(typed):
    return (
        f"Your answer `{typed}` names an option, then a formula that says nothing of it: is the formula your choice?"
        " Give the option's label alone, or words after it that say why."
    )


# a label, then a formula with no words: scribbles (another part's working?) that may be meant for the choice
SCRIBBLED_CHOICE = (
    "(b) = k θ̈",  # the label set equal to a formula
    "b) = m R² θ̈",
    "b, l sin ω",
    "(b) l sin ω",
    "b, mgR cos θ",  # letters glued, with no vowel: no word
    "b, thetadot^2",
    "b, \\dot\\theta^2",
    "b is correct, = k θ̈",
    "rheonomic, l sin ω",  # the option's words, then scribbles
)


@pytest.mark.parametrize("submitted", SCRIBBLED_CHOICE)
def test_a_label_then_a_formula_that_says_nothing_of_it_is_asked_again(submitted):
    verdict = compare("b", submitted, **TIME_CHOICE)
    assert (verdict.status, verdict.feedback) == ("invalid", (_scribbled(submitted),))


def _beside(labels, rest):
    return f"Read as the option you wrote out: {labels}; the words beside it (`{rest}`) are not graded."


@pytest.mark.parametrize(
    ("options", "submitted", "status", "feedback"),
    [
        # a constraint classified both ways, where one way is asked: the other is read past, and said
        (TIME_CHOICE, "rheonomic and holonomic", "equivalent", ("Correct.", _read_past("b", "and holonomic"))),
        (TIME_CHOICE, "holonomic and rheonomic", "equivalent", ("Correct.", _beside("b", "holonomic"))),
        (TIME_CHOICE, "Holonomic & rheonomic, since l = l(t)", "equivalent",
         ("Correct.", _beside("b", "Holonomic … since l = l(t)"))),
        (TIME_CHOICE, "holonomic and scleronomic", "not_equivalent",
         ("Not the right choice.", _beside("a", "holonomic"))),
        (HOLONOMY_CHOICE, "non-holonomic and scleronomic", "equivalent",
         ("Correct.", _read_past("b", "and scleronomic"))),
        (CYCLIC_CHOICE, "φ and not θ", "equivalent", ("Correct.", _read_past("b", "and not θ"))),  # not: confirms
    ],
)  # fmt: skip
def test_an_option_and_a_claim_that_names_no_other_is_the_option(options, submitted, status, feedback):
    verdict = compare("b", submitted, **options)
    assert (verdict.status, verdict.score, verdict.feedback) == (status, float(status == "equivalent"), feedback)


FALSE_CHOICE = {
    "kind": "choice",
    "options": (
        ("a", "It works with two scalar functions, the kinetic and the potential energy."),
        ("b", "Lagrange's equations have the same form in every set of generalized coordinates."),
        ("c", "It gives the forces of constraint directly, with no extra work."),
        ("d", "Ideal forces of constraint do not appear in Lagrange's equations."),
    ),
    "asks_false": True,  # "Which statement is false?"
}


def _not_an_option(typed):
    return f"`{typed}` is not one of the options (a, b, c, d)."


@pytest.mark.parametrize(
    ("submitted", "status", "feedback"),
    [
        # the option said to be false, which is what is asked
        ("c is false", "equivalent", ("Correct.",)),
        ("C is false.", "equivalent", ("Correct.",)),
        ("c is wrong", "equivalent", ("Correct.",)),
        ("c is incorrect", "equivalent", ("Correct.",)),
        ("c is not true", "equivalent", ("Correct.",)),
        ("c isn't true", "equivalent", ("Correct.",)),
        ("(c) is false", "equivalent", ("Correct.",)),
        ("c is the false statement", "equivalent", ("Correct.",)),
        ("Statement c is false", "equivalent", ("Correct.",)),
        ("statement c", "equivalent", ("Correct.",)),
        ("The false statement is c", "equivalent", ("Correct.",)),
        ("the false one is c", "equivalent", ("Correct.",)),
        ("c is the correct answer", "equivalent", ("Correct.",)),
        ("c) false", "equivalent", ("Correct.", _past("c", "false"))),
        ("c (false)", "equivalent", ("Correct.", _past("c", "(false)"))),
        ("c is false, because the constraint forces need multipliers", "equivalent",
         ("Correct.", _past("c", "because the constraint forces need multipliers"))),
        ("c is wrong (it needs multipliers)", "equivalent", ("Correct.", _past("c", "(it needs multipliers)"))),
        ("c (inaccurate)", "equivalent", ("Correct.", _past("c", "(inaccurate)"))),
        ("c (invalid)", "equivalent", ("Correct.", _past("c", "(invalid)"))),
        ("c, a misconception", "equivalent", ("Correct.", _past("c", "a misconception"))),
        ("c (a lie)", "equivalent", ("Correct.", _past("c", "(a lie)"))),
        # a truth taken back is a denial: it names the false option too
        ("c (not accurate)", "equivalent", ("Correct.", _past("c", "(not accurate)"))),
        ("c (not true)", "equivalent", ("Correct.", _past("c", "(not true)"))),
        # other options called true are the reason (before, refused as doubting c)
        ("c, as d holds", "equivalent", ("Correct.", _past("c", "as d holds"))),
        ("c is false; d is valid", "equivalent", ("Correct.", _past("c", "d is valid"))),
        ("c, because a, b and d are valid", "equivalent", ("Correct.", _past("c", "because a, b and d are valid"))),
        # another option called false too (before, right)
        ("c, a is false too", "invalid", (_hedged("c, a is false too"),)),
        ("a is false", "not_equivalent", ("Not the right choice.",)),
        ("d is wrong", "not_equivalent", ("Not the right choice.",)),
        # true, correct or right of the option: the opposite claim, or no answer
        ("c (true)", "invalid", (_hedged("c (true)"),)),
        ("c) correct", "invalid", (_hedged("c) correct"),)),
        ("c is correct", "invalid", (_not_an_option("c is correct"),)),
        ("c is true", "invalid", (_not_an_option("c is true"),)),
        ("c (valid)", "invalid", (_hedged("c (valid)"),)),
        ("c: valid", "invalid", (_hedged("c: valid"),)),
        ("c, which is valid", "invalid", (_hedged("c, which is valid"),)),
        ("c (accurate)", "invalid", (_hedged("c (accurate)"),)),
        ("c (holds)", "invalid", (_hedged("c (holds)"),)),
        # and a denial taken back says it is true
        ("c (not false)", "invalid", (_hedged("c (not false)"),)),
        ("c (no error)", "invalid", (_hedged("c (no error)"),)),
        ("It gives the forces of constraint directly is valid", "invalid",
         (_hedged("It gives the forces of constraint directly is valid"),)),
        ("the correct statement is c", "invalid", (_not_an_option("the correct statement is c"),)),
        # hedges stay hedges
        ("c is false, but maybe d", "invalid", (_hedged("c is false, but maybe d"),)),
        ("c (or d) is false", "invalid", (_not_an_option("c (or d) is false"),)),
        ("c is false (or d)", "invalid", (_hedged("c is false (or d)"),)),
        ("maybe c is false", "invalid", (_not_an_option("maybe c is false"),)),
    ],
)  # fmt: skip
def test_where_the_false_option_is_asked_for_saying_it_is_false_names_it(submitted, status, feedback):
    verdict = compare("c", submitted, **FALSE_CHOICE)
    assert (verdict.status, verdict.score, verdict.feedback) == (status, float(status == "equivalent"), feedback)


@pytest.mark.parametrize("submitted", ["c is false", "c) false", "The false statement is c"])
def test_where_the_right_option_is_asked_for_saying_it_is_false_denies_it(submitted):
    verdict = compare("c", submitted, **{**FALSE_CHOICE, "asks_false": False})
    assert (verdict.status, verdict.score) == ("invalid", 0.0)


SEVERAL_CHOICE = {
    "kind": "choice",
    "multiple": True,
    "options": (("a", "holonomic"), ("b", "scleronomic"), ("c", "rheonomic")),
}
_SEVERAL_HEDGED = (
    "Your answer `{}` offers another option, or doubts or denies one it names: give just the options you mean."
)


@pytest.mark.parametrize(
    ("submitted", "status", "feedback"),
    [
        ("a, b (since the hoop is fixed)", "equivalent", ("Correct.", _past("a, b", "(since the hoop is fixed)"))),
        ("a, b, since the hoop is fixed", "equivalent", ("Correct.", _past("a, b", "since the hoop is fixed"))),
        ("a, c (since the hoop is fixed)", "not_equivalent",
         ("Not the right choice.", _past("a, c", "(since the hoop is fixed)"))),
        ("a, b (not c)", "equivalent", ("Correct.", _past("a, b", "(not c)"))),
        ("a, b (c too)", "invalid", (_SEVERAL_HEDGED.format("a, b (c too)"),)),
        ("a, b (or c)", "invalid", (_SEVERAL_HEDGED.format("a, b (or c)"),)),
        ("a, b (rheonomic)", "invalid", (_SEVERAL_HEDGED.format("a, b (rheonomic)"),)),
        ("a, b?", "invalid", (_SEVERAL_HEDGED.format("a, b?"),)),
        ("a, maybe b", "invalid", (_SEVERAL_HEDGED.format("a, maybe b"),)),
        ("holonomic, scleronomic (maybe)", "invalid", (_SEVERAL_HEDGED.format("holonomic, scleronomic (maybe)"),)),
        ("holonomic, scleronomic, maybe rheonomic", "invalid",
         (_SEVERAL_HEDGED.format("holonomic, scleronomic, maybe rheonomic"),)),
    ],
)  # fmt: skip
def test_several_options_are_checked_for_the_same_words(submitted, status, feedback):
    verdict = compare("a, b", submitted, **SEVERAL_CHOICE)
    assert (verdict.status, verdict.score, verdict.feedback) == (status, float(status == "equivalent"), feedback)


PENDULUM_MEANINGS = (
    ("theta", "polar angle of the string from the downward vertical"),
    ("phi", "azimuthal angle about the vertical through the pivot"),
    ("m", "mass of the bob"),
)


@pytest.mark.parametrize(
    ("submitted", "meanings", "status", "feedback"),
    [
        # where an option is a symbol of the problem, the problem's own words for it name it
        ("the azimuthal angle", PENDULUM_MEANINGS, "equivalent", ("Correct.", "Read as the option you wrote out: b.")),
        ("Azimuthal angle", PENDULUM_MEANINGS, "equivalent", ("Correct.", "Read as the option you wrote out: b.")),
        ("the azimuthal angle about the vertical through the pivot", PENDULUM_MEANINGS, "equivalent",
         ("Correct.", "Read as the option you wrote out: b.")),
        ("the azimuthal angle is cyclic", PENDULUM_MEANINGS, "equivalent",
         ("Correct.", "Read as the option you wrote out: b.")),
        ("the polar angle", PENDULUM_MEANINGS, "not_equivalent",
         ("Not the right choice.", "Read as the option you wrote out: a.")),
        # the words and the letter must agree
        ("the azimuthal angle φ", PENDULUM_MEANINGS, "equivalent",
         ("Correct.", "Read as the option you wrote out: b.")),
        ("the polar angle φ", PENDULUM_MEANINGS, "invalid", (_hedged("the polar angle φ"),)),
        ("the azimuthal angle (maybe the polar angle)", PENDULUM_MEANINGS, "invalid",
         (_hedged("the azimuthal angle (maybe the polar angle)"),)),
        # no guess: a word of the description alone, a head two symbols share, a symbol no option
        ("azimuthal", PENDULUM_MEANINGS, "invalid", ("`azimuthal` is not one of the options (a, b, c, d).",)),
        ("the angle", PENDULUM_MEANINGS, "invalid", ("`the angle` is not one of the options (a, b, c, d).",)),
        ("the angle", (("theta", "angle of the string"), ("phi", "angle about the vertical")), "invalid",
         ("`the angle` is not one of the options (a, b, c, d).",)),
        ("the mass", PENDULUM_MEANINGS, "invalid", ("`the mass` is not one of the options (a, b, c, d).",)),
        ("the azimuthal angle", (), "invalid", ("`the azimuthal angle` is not one of the options (a, b, c, d).",)),
    ],
)  # fmt: skip
def test_an_option_that_is_a_symbol_may_be_named_by_its_meaning(submitted, meanings, status, feedback):
    verdict = compare("b", submitted, meanings=meanings, **CYCLIC_CHOICE)
    assert (verdict.status, verdict.score, verdict.feedback) == (status, float(status == "equivalent"), feedback)


def test_several_choices_may_be_written_out_each_between_commas():
    options = (("a", "holonomic"), ("b", "scleronomic"), ("c", "rheonomic"))
    verdict = compare("a, b", "Holonomic, scleronomic", kind="choice", options=options, multiple=True)
    assert verdict.status == "equivalent"
    assert verdict.feedback[-1] == "Read as the option you wrote out: a, b."


@pytest.mark.parametrize(
    ("kind", "expected", "submitted", "status"),
    [
        # a sign before the number is no words around it: ≠ 2 says what it is not, ± 2 two numbers
        ("integer", "2", "≠2", "invalid"),
        ("integer", "2", "±2", "invalid"),
        ("number", "2.006", "≠ 2.006", "invalid"),
        ("integer", "2", "‒2", "not_equivalent"),  # a figure dash is a minus: −2
        ("integer", "2", "It has 2", "equivalent"),
    ],
)
def test_a_sign_before_a_number_is_read_not_dropped(kind, expected, submitted, status):
    options = {"rtol": 0.005} if kind == "number" else {}
    assert compare(expected, submitted, kind=kind, **options).status == status


@pytest.mark.parametrize(
    ("kind", "expected", "submitted", "names"),
    [
        ("integer", "2", "2 θ", "`θ`"),
        ("number", "2.006", "2.006 s", "`s`"),  # a unit, where the part names none
        ("integer", "3", "x", "`x`"),
        ("integer", "6", "3N", "`N`"),  # a formula: 3N is not a count
        ("integer", "1", "3 Np - k", "`Np` and `k`"),  # arithmetic after the number is not a remark
    ],
)
def test_a_number_with_symbols_is_invalid_and_goes_to_a_person(kind, expected, submitted, names):
    verdict = compare(expected, submitted, kind=kind)
    assert (verdict.status, verdict.score, verdict.diagnosis) == ("invalid", 0.0, "not_a_number")
    assert verdict.feedback == (f"A number is asked for here; your answer contains {names}.",)


PERIOD = "2*pi*sqrt(1/9.81)"  # seconds, for l = 1 m and g = 9.81 m/s²
PERIOD_PART = {"kind": "number", "rtol": 0.005, "unit": "s", "known": ["l", "g"]}


_HEDGED = "One number is asked for here, and your answer offers a choice (`or`): give the one you mean."


def _remark(value, rest):
    return f"Graded the number `{value}`; what follows it (`{rest}`) is not graded."


def _number(value):
    return f"Graded the number `{value}`; the rest of your answer is not graded."


def _comma(typed):
    return f"Read `{typed}` as {typed.replace(',', '.')}: a decimal comma."


def _sentence(value):
    return f"Graded the number `{value}`; the words around it are not graded."


def _final(value):
    return f"Graded your final value, `{value}`; the working before it is not graded."


def _false(value, working):
    return f"Graded your final value, `{value}`; your working, `{working}`, does not hold."


@pytest.mark.parametrize(
    ("expected", "submitted", "options", "status", "read_as", "notes"),
    [
        # a count, then the coordinates it counts or what it is
        ("2", "2 (θ1 and θ2)", {}, "equivalent", "2", (_remark(2, "(θ1 and θ2)"),)),
        ("2", "2 (theta1, theta2)", {}, "equivalent", "2", (_remark(2, "(theta1, theta2)"),)),
        ("2", "2: θ1 and θ2", {}, "equivalent", "2", (_remark(2, "θ1 and θ2"),)),
        ("2", "2 degrees of freedom", {}, "equivalent", "2", (_remark(2, "degrees of freedom"),)),
        ("2", "four (x1, y1, x2, y2)", {}, "not_equivalent", "4", (_remark("four", "(x1, y1, x2, y2)"),)),
        ("2", "Two.", {}, "equivalent", "2", ("Read `Two` as 2.",)),
        # in a sentence, after words that are not mathematics
        ("2", "The system has 2 degrees of freedom", {}, "equivalent", "2", (_sentence(2),)),
        ("2", "It has 2 degrees of freedom: θ1 and θ2.", {}, "equivalent", "2", (_sentence(2),)),
        (PERIOD, "The period is about 2.01 s.", PERIOD_PART, "equivalent", "2.01", (_sentence("2.01 s"),)),
        ("2", "It has two degrees of freedom", {}, "equivalent", "2", (_sentence("two"),)),
        ("2", "2 d.o.f.", {}, "equivalent", "2", (_remark(2, "d.o.f."),)),  # an abbreviation
        ("2", "two (2)", {}, "equivalent", "2", (_remark("two", "(2)"),)),  # the number again, in digits
        ("2", "2 (one coordinate for each bob)", {}, "equivalent", "2", (_remark(2, "(one coordinate for each bob)"),)),
        ("2", "2 (the two angles)", {}, "equivalent", "2", (_remark(2, "(the two angles)"),)),
        # a count broken down, in brackets, into counts that add up to it
        ("6", "6 (3 translations + 3 rotations)", {}, "equivalent", "6",
         (_remark(6, "(3 translations + 3 rotations)"),)),
        ("6", "6 (3 translational and 3 rotational)", {}, "equivalent", "6",
         (_remark(6, "(3 translational and 3 rotational)"),)),
        ("6", "6 (3 translations, 3 rotations)", {}, "equivalent", "6", (_remark(6, "(3 translations, 3 rotations)"),)),
        ("2", "2 (4 coordinates − 2 constraints)", {}, "equivalent", "2",
         (_remark(2, "(4 coordinates − 2 constraints)"),)),
        ("15", "15 (5 particles times 3 coordinates)", {}, "equivalent", "15",
         (_remark(15, "(5 particles times 3 coordinates)"),)),
        ("5", "6 (3 translations + 3 rotations)", {}, "not_equivalent", "6",
         (_remark(6, "(3 translations + 3 rotations)"),)),
        # the counts in words: before, refused as names (three, translational, …)
        ("6", "6 (three translational and three rotational)", {}, "equivalent", "6",
         (_remark(6, "(three translational and three rotational)"),)),
        ("2", "2 (four coordinates minus two constraints)", {}, "equivalent", "2",
         (_remark(2, "(four coordinates minus two constraints)"),)),
        # working, then the final value
        ("2", "6 - 4 = 2", {}, "equivalent", "2", (_final(2),)),
        ("2", "6 - 3 = 3", {}, "not_equivalent", "3", (_final(3),)),
        (PERIOD, "T ≈ 2π√(l/g) ≈ 2.01 s", PERIOD_PART, "equivalent", "2.01", (_final("2.01 s"),)),
        (PERIOD, "2π√(1/9.81) = 3 s", PERIOD_PART, "not_equivalent", "3", (_false("3 s", "2π√(1/9.81) = 3 s"),)),
        (PERIOD, "2.01 s = T", PERIOD_PART, "equivalent", "2.01", (_number("2.01 s"),)),
        # the quantity's name before its value is no working
        # read as T ≈ 2.01 s is: before, also "the number", its name T called the rest of the answer
        (PERIOD, "T ≈ 2,01 s", PERIOD_PART, "equivalent", "2.01", (_comma("2,01"),)),
        (PERIOD, "T = 2.0 s (approx)", PERIOD_PART, "equivalent", "2", (_number("2.0 s"),)),
        # approximately: the tolerance says how near
        (PERIOD, "≈ 2.01 s", PERIOD_PART, "equivalent", "2.01", ()),
        (PERIOD, "about 2.0 s", PERIOD_PART, "equivalent", "2", ()),
        (PERIOD, "2.0 s (approx.)", PERIOD_PART, "equivalent", "2", ()),
        # as typed first, for a measured value: 2 (3) is 6, and a unit is checked, not taken for a remark (for a
        # count, see test_a_count_followed_by_brackets_is_the_count_where_they_are_its_working)
        (PERIOD, "2 (3)", PERIOD_PART, "not_equivalent", "6", ()),
        (PERIOD, "2.006 m (roughly)", PERIOD_PART, "not_equivalent", "1003*m/500", ()),
    ],
)  # fmt: skip
def test_the_number_is_found_in_what_a_student_wrote_around_it(expected, submitted, options, status, read_as, notes):
    verdict = compare(expected, submitted, **{"kind": "integer", **options})
    assert (verdict.status, verdict.read_as, verdict.notes) == (status, read_as, notes)


def _false_for_a_person(value, working):
    return (
        f"Your final value, `{value}`, was graded and is right, but your working, `{working}`, does not hold:"
        " a person will check this answer."
    )


@pytest.mark.parametrize(
    ("expected", "submitted", "options", "status", "score", "feedback"),
    [
        # sides joined by = that are not equal: a slip, or a value not worked out; right, it is for a person
        ("2", "4 - 1 = 2", {}, "undecided", 1.0, (_false_for_a_person(2, "4 - 1 = 2"),)),
        ("2", "3 − 2 = 1 × 2", {}, "undecided", 1.0, (_false_for_a_person("1 × 2", "3 − 2 = 1 × 2"),)),
        ("2", "n = 3N - k = 6 - 3 = 2", {}, "undecided", 1.0,
         (_false_for_a_person(2, "n = 3N - k = 6 - 3 = 2"),)),  # a side in names is not checked, nor wrong
        ("2", "6 - 2 = 5; 6 - 4 = 2", {}, "undecided", 1.0, (_false_for_a_person(2, "6 - 2 = 5"),)),
        ("2", "6 - 2 = 4\n6 - 3 = 2", {}, "undecided", 1.0, (_false_for_a_person(2, "6 - 3 = 2"),)),
        (PERIOD, "2π√(1/9.81) = 1.5 s = 2.006 s", PERIOD_PART, "undecided", 1.0,
         (_false_for_a_person("2.006 s", "2π√(1/9.81) = 1.5 s = 2.006 s"),)),
        # wrong, it is graded so, and told
        ("2", "6 - 4 = 3", {}, "not_equivalent", 0.0,
         ("Not equivalent to the expected answer.", _false(3, "6 - 4 = 3"))),
        # working that holds: graded at its final value, as before
        ("2", "6 - 4 = 2 = 2", {}, "equivalent", 1.0, ("Correct.", _final(2))),
        ("2", "6 - 2 = 4; 6 - 4 = 2", {}, "equivalent", 1.0, ("Correct.", _final(2))),
        (PERIOD, "2π√(1/9.81) = 2.0 s", PERIOD_PART, "equivalent", 1.0, ("Correct.", _final("2.0 s"))),  # rounded
        (PERIOD, "2.006 s = 2006 ms", PERIOD_PART, "equivalent", 1.0,
         ("Correct.", _final("2006 ms"), "Read as 2.006 s.")),  # in another unit
        (PERIOD, "2π√(1/9.81) = 2.006 s = 2006 ms", PERIOD_PART, "equivalent", 1.0,
         ("Correct.", _final("2006 ms"), "Read as 2.006 s.")),  # a side with no unit: in SI units, or in ms
        (PERIOD, "2π√(1/9.81) = 2006 ms", PERIOD_PART, "equivalent", 1.0,
         ("Correct.", _final("2006 ms"), "Read as 2.006 s.")),
        # two statements joined by a comma: the run back to the side that is no number
        (PERIOD, "ω = √(9.81) = 3.13, T = 2π/3.13 = 2.006 s", PERIOD_PART, "equivalent", 1.0,
         ("Correct.", _final("2.006 s"))),
        # units of different dimensions are never equal; nor are the sides of a run that a step follows
        (PERIOD, "2π√(1/9.81) = 2.006 kg = 2.006 s", PERIOD_PART, "undecided", 1.0,
         (_false_for_a_person("2.006 s", "2π√(1/9.81) = 2.006 kg = 2.006 s"),)),
        ("15", "3·5 = 16 → 15", {}, "undecided", 1.0, (_false_for_a_person(15, "3·5 = 16"),)),
        ("15", "3·5 = 16, so 15", {}, "undecided", 1.0, (_false_for_a_person(15, "3·5 = 16"),)),
        # a step says what follows from the run before it: 4, then 2, is two numbers (before, right)
        ("2", "6 - 2 = 4 → 2", {}, "undecided", 1.0, (_false_for_a_person(2, "6 - 2 = 4 → 2"),)),
        ("3", "4 - 1 = 2 d.o.f.", {}, "not_equivalent", 0.0,
         ("Not equivalent to the expected answer.", _false(2, "4 - 1 = 2 d.o.f."))),  # a remark after it too
    ],
)  # fmt: skip
def test_working_that_does_not_hold_goes_to_a_person_where_the_final_value_is_right(
    expected, submitted, options, status, score, feedback
):
    verdict = compare(expected, submitted.replace("\\n", "\n"), **{"kind": "integer", **options})
    assert (verdict.status, verdict.score, verdict.feedback) == (status, score, feedback)


@pytest.mark.parametrize(
    ("expected", "submitted", "status", "read_as", "notes"),
    [
        # working with steps, as on paper: the value after the last is the answer; but a step says that what
        # follows it follows from what came before, and two numbers are working that does not hold (before,
        # right: the last number was taken whatever came before it), for a person where the last is right
        ("2", "6 − 4 = 2 → 4", "not_equivalent", "4", (_false(4, "6 − 4 = 2 → 4"),)),  # before, 6 − 4 was graded
        ("2", "6 − 2 = 4 → 2", "undecided", "2", ()),
        ("2", "6 -> 4 -> 2", "undecided", "2", ()),
        ("2", "6 \\to 2", "undecided", "2", ()),
        ("2", "6 − 4 → 2", "equivalent", "2", (_final(2),)),  # → is a step of the count, not an equals sign
        ("2", "6 − 4 ⇒ 2", "equivalent", "2", ()),  # the parser reads ⇒ as the step it is
        ("1", "Two constraints, so 1", "equivalent", "1", (_final(1),)),
        ("1", "Two constraints, hence 1 degree of freedom", "equivalent", "1", (_remark(1, "degree of freedom"),)),
        ("2", "3N − k = 6 − 4, therefore 2", "equivalent", "2", (_final(2),)),
        ("2", "2 (so two angles)", "equivalent", "2", (_remark(2, "(so two angles)"),)),  # a step in brackets: a remark
        # a number it is not, after the count: a remark
        ("6", "9 − 3 = 6 ≠ 9", "equivalent", "6", (_final(6), _remark(6, "≠ 9"))),
        ("9", "9 − 3 = 6 ≠ 9", "not_equivalent", "6", (_final(6), _remark(6, "≠ 9"))),
        ("6", "n = 6 != nine", "equivalent", "6", (_remark(6, "!= nine"),)),
        ("6", "6 \\neq 9", "equivalent", "6", (_remark(6, "\\neq 9"),)),
        # …but not where it is the count itself, nor before more working: which is the answer is unclear
        ("6", "9 − 3 = 6 ≠ 6", "invalid", None, ()),
        ("9", "6 ≠ 9 = 3·3", "invalid", None, ()),  # before, read as 3·3: the number the answer is not
        ("6", "6 ≠ 9 → 6", "invalid", None, ()),
        # <=, >= and != are not the = of a chain: n >= 2 is no count of 2
        ("2", "n >= 2", "invalid", None, ()),
        ("2", "n <= 2", "invalid", None, ()),
        (PERIOD, "T >= 2.0 s", "invalid", None, ()),
        (PERIOD, "2.006 s != 2 s", "invalid", None, ()),
        # the first side is read where a value stands before its name, not before longer working or a step
        ("2", "6 − 4 = 2 = 4 θ", "invalid", None, ()),  # before, 6 − 4 was graded
        ("2", "2 = n", "equivalent", "2", (_number(2),)),
        ("2", "2 → n", "invalid", None, ()),
        (PERIOD, "2π√(1/9.81) → 2.01 s", "equivalent", "2.01", (_final("2.01 s"),)),
    ],
)  # fmt: skip
def test_working_with_steps_is_graded_at_its_last_value(expected, submitted, status, read_as, notes):
    options = PERIOD_PART if expected == PERIOD else {"kind": "integer"}
    verdict = compare(expected, submitted, **options)
    assert (verdict.status, verdict.notes) == (status, notes), verdict
    if read_as is not None:
        assert verdict.read_as == read_as


def _doubted(words):
    return f"Your answer says `{words}`, which may take back or doubt a number of it: a person will decide which" \
        " number is your answer."  # fmt: skip


_X = "A number is asked for here; your answer contains `x`."


@pytest.mark.parametrize(
    ("expected", "submitted", "status", "read_as", "feedback"),
    [
        # a value stands before the quantity's name: the value is graded
        ("2", "2 = DOF", "equivalent", "2", ("Correct.", _number(2))),
        ("2", "2 = d.o.f.", "equivalent", "2", ("Correct.", _number(2))),
        (PERIOD, "2.01 s = the period", "equivalent", "2.01", ("Correct.", _number("2.01 s"))),
        (PERIOD, "2.01 s = T.", "equivalent", "2.01", ("Correct.", _number("2.01 s"))),
        # before anything else, the first side is no answer: the last side is, read or refused (before, each right)
        ("1", "3 - 2 = 1 or 2", "invalid", "", (_HEDGED,)),  # as 2 or 3 alone is
        ("1", "3 - 2 = 1 x 2", "invalid", None, (_X,)),
        (PERIOD, "2π√(1/9.81) = 2.006 x 2", "invalid", None, (_X,)),
        ("2", "2 = or", "invalid", "", (_HEDGED,)),
        # words that take a number back, or doubt it: a person, whatever it would earn, nothing proposed; shown
        # is the last number (before, the first side was graded, and right)
        ("2", "6 - 4 = 2? no, 4", "undecided", "4", (_doubted("?, no"),)),
        ("4", "6 - 4 = 2? no, 4", "undecided", "4", (_doubted("?, no"),)),
        ("2", "6 - 4 = 2 is wrong, it is 4", "undecided", "4", (_doubted("wrong"),)),
        (PERIOD, "2π√(1/9.81) = 2.006 s? no, 3 s", "undecided", "3", (_doubted("?, no"),)),
        ("2", "2 = wrong", "undecided", "2", (_doubted("wrong"),)),
        ("2", "2 = n?", "undecided", "2", (_doubted("?"),)),
        # …in the working before the final value, or beside the number (before, graded, and right)
        ("4", "6 - 4 = 2? No wait = 4", "undecided", "4", (_doubted("?, No, wait"),)),
        ("2", "6 - 4 = 2 (wrong)", "undecided", "2", (_doubted("wrong"),)),
        ("2", "maybe 2", "undecided", "2", (_doubted("maybe"),)),
        ("2", "2, I  think", "undecided", "2", (_doubted("I think"),)),
        ("2", "It has perhaps 2 degrees of freedom", "undecided", "2", (_doubted("perhaps"),)),
        (PERIOD, "probably 2.01 s", "undecided", "2.01", (_doubted("probably"),)),
        # …or words beside a final value that the working before it does not come to: a second answer, maybe
        ("4", "6 - 4 = 2, so also 4", "undecided", "4", (_doubted("also"),)),  # before, right
        ("4", "6 - 4 = 2 = 4 as well", "undecided", "4", (_doubted("as well"),)),
        ("2", "6 − 2 = 4 → 2 degrees of freedom", "undecided", "2", (_doubted("degrees of freedom"),)),
        (PERIOD, "2π√(1/9.81) = 2.006 s → also 3 s", "undecided", "3", (_doubted("also"),)),
        # …where it does, or a measured value rounds it, the value is graded
        ("2", "6 − 4 = 2 → 2 degrees of freedom", "equivalent", "2", ("Correct.", _remark(2, "degrees of freedom"))),
        (PERIOD, "2π√(1/9.81) = 2.006 s (rounded)", "equivalent", "2.006",
         ("Correct.", _remark("2.006 s", "(rounded)"))),
    ],
)  # fmt: skip
def test_the_first_side_is_graded_only_before_a_name_and_a_doubted_number_goes_to_a_person(
    expected, submitted, status, read_as, feedback
):
    options = PERIOD_PART if expected == PERIOD else {"kind": "integer"}
    verdict = compare(expected, submitted, **options)
    assert (verdict.status, verdict.score, verdict.feedback) == (status, float(status == "equivalent"), feedback)
    if read_as is not None:
        assert verdict.read_as == read_as


@pytest.mark.parametrize(
    "submitted",
    [
        "6 - 4 = " * 60 + "2? no",  # many =, past the length read for words
        "6 - 4 = 2" + "? no" * 60 + ", 4",
        "2 = " + "n" * 300,
        "(" * 80 + "6 - 4" + ")" * 80 + " = 2? no, 4",
        "2 = " + "(" * 80 + "n",
        "9" * 40 + " = 2? no, " + "9" * 40,  # more digits than the parser reads
        "2 = n = " * 30 + "?",
        "6 − 4 = 2? no, 4 = 2",  # doubted working, whatever its final value
    ],
)
def test_hostile_chains_with_doubts_or_names_are_never_right(submitted):
    verdict = compare("2", submitted, kind="integer")
    assert verdict.status in ("invalid", "undecided", "not_equivalent") and verdict.score == 0, verdict


@pytest.mark.parametrize(
    ("expected", "submitted", "status", "read_as", "feedback"),
    [
        # working over several lines, or between ;: the last line's value, as on one line (before, the first's)
        ("2", "6 - 2 = 4; 6 - 4 = 2", "equivalent", "2", ("Correct.", _final(2))),
        ("4", "6 - 2 = 4; 6 - 4 = 2", "not_equivalent", "2", ("Not equivalent to the expected answer.", _final(2))),
        ("2", "6 - 4 = 2\n6 - 2 = 4", "not_equivalent", "4", ("Not equivalent to the expected answer.", _final(4))),
        ("2", "6 - 4 = 2\n2", "equivalent", "2", ("Correct.", _final(2))),  # before, refused: a list needs =
        ("2", "6 - 4 = 2; so 2", "equivalent", "2", ("Correct.", _final(2))),
        ("2", "6 - 4 = 2 \\\\ 2", "equivalent", "2", ("Correct.", _final(2))),  # TeX's row break
        ("2", "6 - 4 = 2\n\n2 = n", "equivalent", "2", ("Correct.", _final(2))),
        ("2", "6 − 4 → 2; 2 degrees of freedom", "equivalent", "2",
         ("Correct.", _final(2), _remark(2, "degrees of freedom"))),
        (PERIOD, "2π√(1/9.81) = 2.006 s\n2.006 s", "equivalent", "2.006", ("Correct.", _final("2.006 s"))),
        (PERIOD, "2π√(1/9.81) = 2.006 s; T = 3 s", "not_equivalent", "3",
         ("Not within the accepted tolerance.", _final("3 s"))),
        # where the lines disagree, words beside the last may say it is not the only answer: a person
        ("4", "6 - 4 = 2\nalso 4", "undecided", "4", (_doubted("also"),)),
        ("4", "6 - 4 = 2\n4 as well", "undecided", "4", (_doubted("as well"),)),
        ("4", "6 - 4 = 2\nalso 6 - 2 = 4", "undecided", "4", (_doubted("also"),)),
        ("2", "6 - 2 = 4\nThe answer is 2", "undecided", "2", (_doubted("The answer is"),)),
        (PERIOD, "2π√(1/9.81) = 2.006 s\nalso 3 s", "undecided", "3", (_doubted("also"),)),
        (PERIOD, "2π√(1/9.81) = 2.006 s\nThe period is 2.01 s", "equivalent", "2.01",
         ("Correct.", _final("2.01 s"), _sentence("2.01 s"))),  # rounded, not another value
        ("2", "6 - 4 = 2\nThe answer is 2", "equivalent", "2", ("Correct.", _final(2), _sentence(2))),  # they agree
        ("4", "6 - 4 = 2\nn = 4", "equivalent", "4", ("Correct.", _final(4))),  # a name of one letter, no words
        # one line and an empty one after it: the line (before, read as an equation where a number is asked)
        ("2", "6 - 4 = 2;", "equivalent", "2", ("Correct.", _final(2))),
        ("2", "6-4=2\n\n", "equivalent", "2", ("Correct.", _final(2))),
        ("2", "2 (not 4);", "equivalent", "2", ("Correct.", _remark(2, "(not 4)"))),
        # …and in a list, the last item that is working, not the first
        ("2", "6 - 2 = 4, 6 - 4 = 2", "equivalent", "2", ("Correct.",)),
        ("2", "3N = 6, 3N - k = 2", "equivalent", "2", ("Correct.",)),
        # words that take a line back or doubt it: a person, nothing proposed (before, the first line was graded)
        ("2", "6 - 4 = 2\nNo wait: 6 - 2 = 4", "undecided", "4", (_doubted("No wait"),)),
        ("2", "6 - 2 = 4\nwrong: 6 - 4 = 2", "undecided", "2", (_doubted("wrong"),)),
    ],
)  # fmt: skip
def test_working_over_several_lines_is_graded_at_the_last_lines_value(expected, submitted, status, read_as, feedback):
    options = PERIOD_PART if expected == PERIOD else {"kind": "integer"}
    verdict = compare(expected, submitted, **options)
    assert (verdict.status, verdict.score, verdict.read_as) == (status, float(status == "equivalent"), read_as)
    assert verdict.feedback == feedback


@pytest.mark.parametrize(
    "submitted",
    [
        "6 - 4 = 4\n" * 7 + "2",  # more lines than working has
        "4; 2",  # numbers alone offer a choice
        "6 - 4; 2",
        "6 - 4 = 4; " * 3 + "2 = " * 40 + "n",
        "1 = " * 14 + "1\n2",  # more sides than are read
        "(" * 60 + "6 - 4" + ")" * 60 + " = 4\n2",
        "9" * 40 + " = 4\n2",
        "6 - 4 = 4\n" + "9" * 40,
        "6 - 4 = 4\n2^2^2^2^2^2^2^2^2^2",
        "6 - 4 = 4;\n;\n;2 = 4",
        "6 - 4 = 4\n" + "2 " * 150,
    ],
)
def test_hostile_lines_of_working_are_never_right(submitted):
    verdict = compare("2", submitted, kind="integer")
    assert verdict.status in ("invalid", "undecided", "not_equivalent") and verdict.score == 0, verdict


@pytest.mark.parametrize(
    ("expected", "submitted", "status", "read_as", "feedback"),
    [
        # a number the count is not, in brackets or after a comma: a remark, as ≠ 4 is (before, refused as 8·not)
        ("2", "2 (not 4)", "equivalent", "2", ("Correct.", _remark(2, "(not 4)"))),
        ("4", "2 (not 4)", "not_equivalent", "2", ("Not equivalent to the expected answer.", _remark(2, "(not 4)"))),
        ("2", "2 (not four)", "equivalent", "2", ("Correct.", _remark(2, "(not four)"))),
        ("2", "2, not 4", "equivalent", "2", ("Correct.", _remark(2, "not 4"))),
        ("2", "n = 2, not 4.", "equivalent", "2", ("Correct.", _remark(2, "not 4"))),
        ("2", "6 - 4 = 2 (not 4)", "equivalent", "2", ("Correct.", _final(2), _remark(2, "(not 4)"))),
        # …not beside a doubt; where it rules out the count itself, refused (see the table of hostile ones)
        ("2", "maybe 2 (not 4)", "undecided", "2", (_doubted("maybe"),)),
    ],
)  # fmt: skip
def test_a_number_a_count_is_not_in_brackets_is_a_remark(expected, submitted, status, read_as, feedback):
    verdict = compare(expected, submitted, kind="integer")
    assert (verdict.status, verdict.score, verdict.feedback) == (status, float(status == "equivalent"), feedback)
    if read_as is not None:
        assert verdict.read_as == read_as


@pytest.mark.parametrize(
    "submitted",
    [
        "2 (not 2)",
        "4 (not 2)",
        "(not 2)",
        ", not 2",
        "2 (not 4",
        "2" + " (not 4)" * 40,
        "2 (" * 40 + "not 4" + ")" * 40,
        "9" * 40 + ", not 2",  # more digits than the parser reads
        "4" + ", not 2" * 30,
    ],
)
def test_hostile_numbers_ruled_out_are_never_right(submitted):
    verdict = compare("2", submitted, kind="integer")
    assert verdict.status in ("invalid", "undecided", "not_equivalent") and verdict.score == 0, verdict


def _qualified(value, words):
    return f"Your number `{value}` comes with `{words}`, which may make it another number, or no one number: a" \
        " person will decide what your answer is."  # fmt: skip


@pytest.mark.parametrize(
    ("expected", "submitted", "read_as", "feedback"),
    [
        # words that make the number another, or no one number: a person, nothing proposed (before, each the
        # bare number, and right)
        ("2", "less than 2", "2", _qualified(2, "less than")),
        ("2", "more than 2", "2", _qualified(2, "more than")),
        ("2", "at most 2", "2", _qualified(2, "at most")),
        ("2", "at least 2", "2", _qualified(2, "at least")),
        ("2", "2 at most", "2", _qualified(2, "at most")),
        ("2", "up to 2", "2", _qualified(2, "up to")),
        ("2", "It has at most 2 degrees of freedom", "2", _qualified(2, "at most")),
        ("2", "at most: 2", "2", _qualified(2, "at most")),  # the parser reads "at most:" as a label
        ("2", "2 (max)", "2", _qualified(2, "max")),
        # …or multiply it: 2 for each bob is 4, two hundred 200
        ("2", "two hundred", "2", _qualified("two", "hundred")),
        ("2", "2 dozen", "2", _qualified(2, "dozen")),
        ("2", "2 thousand", "2", _qualified(2, "thousand")),
        ("2", "2 (2 pairs)", "2", _qualified(2, "pairs")),
        ("2", "2 for each bob", "2", _qualified(2, "for each")),
        ("2", "2 each", "2", _qualified(2, "each")),
        ("2", "each bob has 2", "2", _qualified(2, "each")),
        ("2", "one each", "1", _qualified("one", "each")),  # 2, read as a product: before, wrong, read as 1
        ("1", "one each", "1", _qualified("one", "each")),  # before, right
        ("6", "3 for each particle", "3", _qualified(3, "for each")),
        # a count is exact: an approximation of one is no count
        ("2", "about 2", "2", _qualified(2, "about")),
        ("2", "approximately 2", "2", _qualified(2, "approximately")),
        ("2", "nearly 2", "2", _qualified(2, "nearly")),
        ("2", "≈ 2", "2", _qualified(2, "≈")),
        ("2", "n ≈ 2", "2", _qualified(2, "≈")),
        ("2", "2 (roughly)", "2", _qualified(2, "roughly")),
        ("2", "2 (approx.)", "2", _qualified(2, "approx")),
        # a measured value is near enough within its tolerance, but not less than it, nor one for each thing
        (PERIOD, "less than 2.01 s", "2.01", _qualified("2.01 s", "less than")),
        (PERIOD, "2.01 s for each swing", "2.01", _qualified("2.01 s", "for each")),
    ],
)
def test_words_that_make_a_number_another_send_it_to_a_person(expected, submitted, read_as, feedback):
    options = PERIOD_PART if expected == PERIOD else {"kind": "integer"}
    verdict = compare(expected, submitted, **options)
    assert (verdict.status, verdict.score, verdict.read_as, verdict.feedback) == (
        "undecided",
        0.0,
        read_as,
        (feedback,),
    )


@pytest.mark.parametrize(
    ("expected", "submitted"),
    [
        # words that say what was counted, not how many: read past, as remarks are
        ("15", "15 (no constraints)"),  # "no" before a word is no taking back
        ("2", "2 (minimum number of coordinates)"),  # what a count of degrees of freedom is, not "at least"
        ("2", "2 (a pair of angles)"),  # a pair is two, not pairs of something
    ],
)
def test_words_that_say_what_was_counted_are_a_remark_not_a_qualifier(expected, submitted):
    verdict = compare(expected, submitted, kind="integer")
    assert verdict.feedback == ("Correct.", _remark(expected, submitted[len(expected) :].strip()))


@pytest.mark.parametrize(("submitted", "value"), [("1, the angle θ", "1"), ("one, the angle θ", "one")])
def test_the_number_graded_is_shown_without_the_comma_after_it(submitted, value):
    # before: "Graded the number `1,`" and `one,`
    assert compare("1", submitted, kind="integer").feedback == ("Correct.", _remark(value, "the angle θ"))


@pytest.mark.parametrize(
    "submitted",
    [
        "less than " * 30 + "2",
        "2 " + "dozen " * 40,
        "about (" * 30 + "2" + ")" * 30,
        "maybe:" + " " * 300 + "2",  # longer than the words are read in, and read as typed: the label dropped
        "at most: " + " " * 300 + "2",
        "2 (one coordinate for each bob) " + "for each bob " * 20,
        "≈" * 100 + " 2",
        "2" + " = n" * 60 + " at most",
    ],
)
def test_hostile_qualified_numbers_are_never_right(submitted):
    verdict = compare("2", submitted, kind="integer")
    assert verdict.status in ("invalid", "undecided", "not_equivalent") and verdict.score == 0, verdict


@pytest.mark.parametrize(
    "submitted",
    [
        " → ".join(["1"] * 150),  # a long chain is read as typed, and refused
        "1 → " * 48 + "99999999999999999999999999999999999",  # more digits than the parser reads
        "((((((((((((((((((((((((((((((((((((((((((((6 − 4))))))))))))))))))))))))))))))))))))))))))) → 2 → 3",
        "6 − 4 = " + "9" * 60 + " ≠ 2",
        "2 → ⇒ → so hence thus ≠ 2",
        "→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→→",
        "2 " + "(" * 90 + " → 1",
    ],
)
def test_hostile_chains_of_steps_are_refused_and_never_right(submitted):
    verdict = compare("2", submitted, kind="integer")
    assert verdict.status in ("invalid", "not_equivalent"), verdict


PENDULUM_PERIOD = {**PERIOD_PART, "known": ["m", "g", "l"], "coords": ["theta"]}


@pytest.mark.parametrize(
    ("expected", "submitted", "options", "status", "notes"),
    [
        # the values it was worked out with, after a number: graded is the number
        (PERIOD, "2.006 s, since l = 1 m", PENDULUM_PERIOD, "equivalent", (_remark("2.006 s", "since l = 1 m"),)),
        (PERIOD, "2.006 s for l = 1.00 m", PENDULUM_PERIOD, "equivalent", (_remark("2.006 s", "for l = 1.00 m"),)),
        ("1", "1, since k = 2", {}, "equivalent", (_remark(1, "since k = 2"),)),
        ("1", "2, since k = 1", {}, "not_equivalent", (_remark(2, "since k = 1"),)),
        # after a named count, too: the values are no other count of the answer's, even where they are the last
        ("2", "n = 2 since k = 4 and 3N = 6", {}, "equivalent", (_remark("n = 2", "since k = 4 and 3N = 6"),)),
        ("4", "n = 2 since k = 4 and 3N = 6", {}, "not_equivalent", (_remark("n = 2", "since k = 4 and 3N = 6"),)),
        ("2", "n = 3N − k = 6 − 4 = 2, k = 4", {}, "equivalent", (_final(2), _remark(2, "k = 4"))),  # k: in the working
        ("4", "n = 3N − k = 6 − 4 = 2, k = 4", {}, "not_equivalent", (_final(2), _remark(2, "k = 4"))),
        ("2", "n = 2, n = 4", {}, "not_equivalent", (_final(4),)),  # the name of the answer, not of a value given
        # after a formula: the values are put in its names, the problem's or the student's own
        (PERIOD, "T = 2π√(l/g), where l = 1, g = 9.81", PENDULUM_PERIOD, "equivalent", ()),
        (PERIOD, "2π√(l/g), where l = 2, g = 9.81", PENDULUM_PERIOD, "not_equivalent", ()),
        ("1", "n = 3N − k, where N = 1, k = 2", {}, "equivalent", ()),
        # a value it was given is no final value: g has none here
        (PERIOD, "2π√(l/g), where l = 1", PENDULUM_PERIOD, "invalid", ()),
    ],
)  # fmt: skip
def test_a_number_may_be_followed_by_the_values_it_was_worked_out_with(expected, submitted, options, status, notes):
    verdict = compare(expected, submitted, **{"kind": "integer", **options})
    assert (verdict.status, verdict.notes) == (status, notes), verdict


@pytest.mark.parametrize(
    ("submitted", "names"),
    [
        ("2 pi sqrt(l/g)", "`g` and `l`"),  # a formula where a number is asked for: √(l/g) is no remark
        ("2 pi (l/g)^(1/2) s", "`g`, `l` and `s`"),
        ("T = 2 pi sqrt(l/g)", "`g` and `l`"),
    ],
)
def test_a_formula_for_the_number_is_not_taken_for_a_number_and_a_remark(submitted, names):
    verdict = compare(PERIOD, submitted, **PERIOD_PART)
    assert (verdict.status, verdict.feedback) == (
        "invalid",
        (f"A number is asked for here; your answer contains {names}.",),
    )


@pytest.mark.parametrize(
    "submitted",
    [
        "2 or 3",
        "2 (or 3)",
        "2 or three",
        "2 (three minus one)",
        "2 (maybe 3)",
        "2 (3 in total)",  # another count of what is counted, perhaps: no thing it was counted from
        "either 2 or 3",
        "not 3 but 2",
        "not 2",
        "2 (not sure)",  # a doubt beside a number, which a formula's words may voice, is no remark here
        "the one that swings",  # "one" after an article is a pronoun
    ],
)
def test_a_remark_with_another_number_is_a_hedge_not_a_remark(submitted):
    verdict = compare("2", submitted, kind="integer")
    hedged = " or " in f" {submitted} ".replace("(", " ")
    assert (verdict.status, verdict.diagnosis) == ("invalid", "number_hedged" if hedged else "not_a_number")
    if hedged:  # the choice is said, and not shown back as a product (2 or 3 as 6·or)
        assert verdict.feedback == (_HEDGED,) and verdict.read_as == ""
    assert compare("2", "2 (θ_1 and θ_2)", kind="integer").status == "equivalent"  # digits of names are not numbers


def test_a_breakdown_holds_no_name_of_the_problem():
    # 4 (2 ω + 2) is a formula in ω, where ω is the problem's: not counts of things named in words
    verdict = compare("4", "4 (2 omega + 2)", kind="integer", known=["omega"])
    assert (verdict.status, verdict.diagnosis) == ("invalid", "not_a_number")
    assert compare("4", "4 (2 omegas + 2)", kind="integer", known=["omega"]).status == "equivalent"


def _unclear(value, rest):
    return f"Your count `{value}` is followed by `{rest}`, which does not come to {value}: a person will decide which" \
        " number is your answer."  # fmt: skip


def _count_or_product(typed):
    return f"Your answer `{typed}` may be a count with its working in brackets, or the product of the two, and" \
        " these are different numbers: a person will check which you meant."  # fmt: skip


@pytest.mark.parametrize(
    ("expected", "submitted", "status", "read_as", "feedback"),
    [
        # a count, then brackets that come to it: the count with its working. As typed, they were its product
        ("2", "2 (6 − 4)", "equivalent", "2", ("Correct.", _remark(2, "(6 − 4)"))),  # before, 4
        ("6", "6 (3 + 3)", "equivalent", "6", ("Correct.", _remark(6, "(3 + 3)"))),  # before, 36
        ("2", "2 (3 − 1)", "equivalent", "2", ("Correct.", _remark(2, "(3 − 1)"))),
        ("2", "2 (4/2).", "equivalent", "2", ("Correct.", _remark(2, "(4/2)"))),
        ("2", "2 [6 − 4]", "equivalent", "2", ("Correct.", _remark(2, "[6 − 4]"))),
        ("2", "2 ((6) − (4))", "equivalent", "2", ("Correct.", _remark(2, "((6) − (4))"))),
        ("2", "n = 2 (6 − 4)", "equivalent", "2", ("Correct.", _remark(2, "(6 − 4)"))),  # before, n = 4
        ("2", "6 − 4 = 2 (6 − 4)", "equivalent", "2", ("Correct.", _remark(2, "(6 − 4)"))),
        ("2", "2 (6 − 4), since k = 4", "equivalent", "2",
         ("Correct.", _remark(2, "(6 − 4)"), _remark(2, "since k = 4"))),
        ("3", "3 (6 − 4)", "undecided", "3", (_unclear(3, "(6 − 4)"),)),
        ("4", "2 (6 − 4)", "undecided", "2", (_count_or_product("2 (6 − 4)"),)),  # 4 only as the product
        ("3", "2 (6 − 4)", "not_equivalent", "2", ("Not equivalent to the expected answer.", _remark(2, "(6 − 4)"))),
        ("1", "1 (3 − 2)", "equivalent", "1", ("Correct.", _remark(1, "(3 − 2)"))),  # its product is 1 too
        # written close, a product, as typed; but where only the count with its working earns, for a person
        ("4", "2(3 − 1)", "equivalent", "4", ("Correct.",)),
        ("2", "2(3 − 1)", "undecided", "4", (_count_or_product("2(3 − 1)"),)),
        ("5", "2(3 − 1)", "not_equivalent", "4", ("Not equivalent to the expected answer.",)),
        ("6", "3(2)", "equivalent", "6", ("Correct.",)),
        # brackets that come to another number: which is the answer is unclear, right or wrong (nothing proposed)
        ("2", "1 (2)", "undecided", "1", (_unclear(1, "(2)"),)),  # before, right: 1·2
        ("2", "2 (3)", "undecided", "2", (_unclear(2, "(3)"),)),  # before, 6
        ("5", "2 (3)", "undecided", "2", (_unclear(2, "(3)"),)),
        ("2", "1 [2]", "undecided", "1", (_unclear(1, "[2]"),)),
        ("2", "1 (2)(1)", "undecided", "1", (_unclear(1, "(2)(1)"),)),
        ("2", "n = 1 (2)", "undecided", "1", (_unclear(1, "(2)"),)),  # before, right: n = 2
        ("2", "two (3)", "undecided", "2", (_unclear("two", "(3)"),)),
        ("2", "2 (3), since k = 2", "undecided", "2", (_unclear(2, "(3)"),)),
        ("6", "6 (3 translations + 2 rotations)", "undecided", "6", (_unclear(6, "(3 translations + 2 rotations)"),)),
        ("2", "2 (3 coordinates - 2 constraints)", "undecided", "2", (_unclear(2, "(3 coordinates - 2 constraints)"),)),
        ("2", "2 (3 degrees of freedom)", "undecided", "2", (_unclear(2, "(3 degrees of freedom)"),)),
        ("2", "2 (3 generalized coordinates)", "undecided", "2", (_unclear(2, "(3 generalized coordinates)"),)),
        # a count in the words, the count again; or how many things it was counted from
        ("2", "2 (the 2 angles)", "equivalent", "2", ("Correct.", _remark(2, "(the 2 angles)"))),
        ("15", "15 (5 particles)", "equivalent", "15", ("Correct.", _remark(15, "(5 particles)"))),
        ("5", "15 (5 particles)", "not_equivalent", "15", ("Not equivalent to the expected answer.",
                                                            _remark(15, "(5 particles)"))),
        ("1", "1 (2 holonomic constraints)", "equivalent", "1", ("Correct.", _remark(1, "(2 holonomic constraints)"))),
        ("2", "2 (6 Cartesian coordinates)", "equivalent", "2", ("Correct.", _remark(2, "(6 Cartesian coordinates)"))),
        ("6", "6 (1 rigid body)", "equivalent", "6", ("Correct.", _remark(6, "(1 rigid body)"))),
    ],
)  # fmt: skip
def test_a_count_followed_by_brackets_is_the_count_where_they_are_its_working(
    expected, submitted, status, read_as, feedback
):
    verdict = compare(expected, submitted, kind="integer")
    assert (verdict.status, verdict.read_as, verdict.feedback) == (status, read_as, feedback), verdict
    assert verdict.score == (1.0 if status == "equivalent" else 0.0)


@pytest.mark.parametrize(
    "submitted",
    [
        "2 (" + "9" * 35 + ")",  # more digits than the parser reads
        "9" * 35 + " (3)",
        "2 (" * 60 + "2" + ")" * 60,  # nested deeper than the parser goes
        "2 " + "(" * 60 + "2" + ")" * 60,
        "2 (1/0)",
        "2 (2^2^2^2^2^2^2^2^2)",  # a power is no working: as typed, refused
        "1 (2) degrees of freedom",  # no product of the count and its bracket, before words: before, right
        "It has 1 (2)",  # before, right
        "1 (2",
        "1 (2))",
        "1 (2] ",
        "2 (" + "1 + " * 60 + "1)",
        "1 " + "(2)" * 80,
        "1 (2)" + " → 1 (2)" * 30,
    ],
)
def test_hostile_counts_with_brackets_are_never_right(submitted):
    verdict = compare("2", submitted, kind="integer")
    assert verdict.status in ("invalid", "undecided", "not_equivalent") and verdict.score == 0, verdict


def test_seconds_written_sec_are_not_a_remark_where_no_unit_is_asked_for():
    assert compare(PERIOD, "2.006 sec", kind="number", rtol=0.005).status == "invalid"
    assert compare(PERIOD, "2.006 sec", kind="number", rtol=0.005, unit="s").status == "equivalent"


@pytest.mark.parametrize(
    "submitted",
    [
        "2.006~\\text{s}", "2.006\\,\\text{ s}", "2.006 \\text{sec}", "2.006~s", "2.006 seconds", "2.006\\ \\textrm{s}",
        # \mathrm, and \mu for the prefix: before, 2006 \mathrm{ms} was read as 2006 m·s
        "2006 \\mathrm{ms}", "2006\\,\\mathrm{ms}", "2006000\\,\\mu\\mathrm{s}", "2006000~\\mathrm{\\mu s}",
        "2006000 \\mu s",
    ],
)  # fmt: skip
def test_a_unit_written_in_tex_or_in_words_is_the_parts_unit(submitted):
    # TeX's tie and \text{…} around a unit, as an equation editor writes them
    assert compare(PERIOD, submitted, kind="number", rtol=0.005, unit="s").status == "equivalent"
    wrong = submitted.replace("2.006", "2.106").replace("2006", "2106")
    assert compare(PERIOD, wrong, kind="number", rtol=0.005, unit="s").status == "not_equivalent"


def test_a_long_answer_is_read_only_as_typed():
    verdict = compare("2", "2 (" + "the angle and " * 20 + "θ)", kind="integer")
    assert (verdict.status, verdict.diagnosis) == ("invalid", "not_a_number")


@pytest.mark.parametrize(
    ("submitted", "status", "read_as"),
    [
        ("2,01", "equivalent", "2.01"),
        ("2,0061", "equivalent", "2.0061"),
        ("-2,01", "not_equivalent", "-2.01"),
        ("2,006", "invalid", None),  # 2006 in English: the student is asked for a point
        ("2,01, 3", "invalid", None),  # a list, not a number
    ],
)
def test_a_decimal_comma_is_read_as_a_point_in_a_number(submitted, status, read_as):
    verdict = compare("2*pi*sqrt(1/9.81)", submitted, kind="number", rtol=0.005)
    assert verdict.status == status
    if read_as is None:
        assert verdict.feedback[0].startswith("A comma is not understood here")
    else:
        assert verdict.read_as == read_as
        assert verdict.notes == (f"Read `{submitted}` as {read_as}: a decimal comma.",)
    # only numbers: in an expression the comma separates, and the parser says so
    assert compare("x", "1,5", known=["x"]).status == "invalid"


_COMMA_REFUSED = (
    "A comma is not understood here. Write decimals with a point (0.5); list equations as [eq1, eq2] or on separate"
    " lines."
)
_FREQUENCY = "sqrt(9.81)/(2*pi)"  # hertz, for l = 1 m and g = 9.81 m/s²
ZERO_DECIMAL_COMMA = (
    # a thousands separator never follows a lone 0: 0,498 can only be 0.498
    (_FREQUENCY, "Hz", "0,498", "equivalent", ("Correct.", "Read `0,498` as 0.498: a decimal comma.")),
    (_FREQUENCY, "Hz", "-0,498", "not_equivalent",
     ("Not within the accepted tolerance.", "Read `-0,498` as -0.498: a decimal comma.")),
    # T's value, named, is read as T = 2.01 s is: before, also said to be "the number", the rest (T) not graded
    (PERIOD, "s", "T = 2,01 s, f = 0,498 Hz", "equivalent",
     ("Correct.", "Read `2,01` as 2.01: a decimal comma.", "Graded `T = 2,01 s`, your value in s; the rest of your"
      " answer (`f = 0,498 Hz`) is not graded.")),
    (PERIOD, "s", "T = 2,01 s", "equivalent", ("Correct.", "Read `2,01` as 2.01: a decimal comma.")),
    (PERIOD, "s", "T = 2,21 s", "not_equivalent",
     ("Not within the accepted tolerance.", "Read `2,21` as 2.21: a decimal comma.")),
)  # fmt: skip

# a decimal comma inside the arithmetic that gives the number: before, refused ("A comma…"), or 1/0,498 said to divide
# by zero; each comma read as one alone is, and the answer as typed where any comma may be a list's or thousands'
ARITHMETIC_DECIMAL_COMMA = (
    (PERIOD, "2π/√9,81", "equivalent", ("Correct.", "Read `9,81` as 9.81: a decimal comma.")),
    (PERIOD, "2π/√9,18", "not_equivalent", ("Not within the accepted tolerance.", _comma("9,18"))),
    # two numbers, each in its own backticks: before, both in one pair and "a decimal comma"
    (PERIOD, "2π √(1,00/9,81) s", "equivalent",
     ("Correct.", "Read `1,00` and `9,81` as 1.00 and 9.81: decimal commas.")),
    (PERIOD, "2π √(1,00/9,81) ms", "not_equivalent",
     ("Not within the accepted tolerance.", "Read `1,00` and `9,81` as 1.00 and 9.81: decimal commas.",
      "Read as 0.00200607 s.")),
    (PERIOD, "2π √(1,00/9,81)/√1,00", "equivalent",
     ("Correct.", "Read `1,00`, `9,81` and `1,00` as 1.00, 9.81 and 1.00: decimal commas.")),
    (PERIOD, "2π √(1,00/9,18)/√1,00", "not_equivalent",
     ("Not within the accepted tolerance.", "Read `1,00`, `9,18` and `1,00` as 1.00, 9.18 and 1.00: decimal commas.")),
    (PERIOD, "1/0,498", "equivalent", ("Correct.", "Read `0,498` as 0.498: a decimal comma.")),
    (PERIOD, "1/0,489", "not_equivalent", ("Not within the accepted tolerance.", _comma("0,489"))),
    (PERIOD, "2π/√9,810", "invalid", (_COMMA_REFUSED,)),  # 9810 in English
    (PERIOD, "2π/√9,81, 3", "invalid", (_COMMA_REFUSED,)),  # a list
    # three digits after a comma, where the same answer writes 9,81: a decimal comma too (before, refused)
    (PERIOD, "T = 2π/√9,81 ≈ 2,006 s", "equivalent",
     ("Correct.", "Read `2,006` as 2.006: a decimal comma.",
      "Graded your final value, `2,006 s`; the working before it is not graded.")),
    (PERIOD, "T = 2π/√9,81 ≈ 3,006 s", "not_equivalent",
     ("Not within the accepted tolerance.", "Read `3,006` as 3.006: a decimal comma.",
      "Graded your final value, `3,006 s`; your working, `T = 2π/√9,81 = 3,006 s`, does not hold.")),
    (PERIOD, "2π √(1,000/9,81)", "equivalent",
     ("Correct.", "Read `1,000` and `9,81` as 1.000 and 9.81: decimal commas.")),
    (PERIOD, "2π √(1,000/9,810)", "invalid", (_COMMA_REFUSED,)),  # each may be thousands
    (PERIOD, "2,006 s", "invalid", (_COMMA_REFUSED,)),  # alone: 2006 in English
    # the values it was worked out with in a bracket at the end, as after a comma (before, refused, with a point too)
    (PERIOD, "2,006 s (with g = 9,81)", "equivalent",
     ("Correct.", _comma("2,006"), _remark("2,006 s", "with g = 9,81"))),
    (PERIOD, "2,106 s (with g = 9,81)", "not_equivalent",
     ("Not within the accepted tolerance.", _comma("2,106"), _remark("2,106 s", "with g = 9,81"))),
    (PERIOD, "2.006 s (using g = 9.81).", "equivalent", ("Correct.", _remark("2.006 s", "using g = 9.81"))),
    (PERIOD, "2,006 s (with g = 9.81)", "invalid", (_COMMA_REFUSED,)),  # 9.81 with a point: 2,006 may be 2006
)  # fmt: skip


@pytest.mark.parametrize(("expected", "submitted", "status", "feedback"), ARITHMETIC_DECIMAL_COMMA)
def test_a_decimal_comma_inside_the_arithmetic_of_a_number_is_read_as_a_point(expected, submitted, status, feedback):
    verdict = compare(expected, submitted, kind="number", rtol=0.005, unit="s")
    assert (verdict.status, verdict.feedback) == (status, feedback)


_WORKED = "Graded your final value, `{}`; the working before it is not graded."
GIVEN_AFTER_A_COMMA = (
    # the values worked out with after a comma, as in a bracket: their decimal comma makes 2,006 one too (before,
    # refused as 2006 in English, or a list)
    ("T = 2 pi sqrt(l/g) = 2,006 s, with g = 9,81", "equivalent",
     ("Correct.", _comma("2,006"), _WORKED.format("2,006 s"), _remark("2,006 s", "with g = 9,81"))),
    ("T = 2 pi sqrt(l/g) = 2,106 s, with g = 9,81", "not_equivalent",
     ("Not within the accepted tolerance.", _comma("2,106"), _WORKED.format("2,106 s"),
      _remark("2,106 s", "with g = 9,81"))),
    ("2,006 s, with g = 9,81", "equivalent", ("Correct.", _comma("2,006"), _remark("2,006 s", "with g = 9,81"))),
    ("2,106 s, with g = 9,81", "not_equivalent",
     ("Not within the accepted tolerance.", _comma("2,106"), _remark("2,106 s", "with g = 9,81"))),
    ("2,006, with g = 9,81", "equivalent", ("Correct.", _comma("2,006"), _remark("2,006", "with g = 9,81"))),
    ("2,006 s, using g = 9,81.", "equivalent", ("Correct.", _comma("2,006"), _remark("2,006 s", "using g = 9,81."))),
)  # fmt: skip


@pytest.mark.parametrize(("submitted", "status", "feedback"), GIVEN_AFTER_A_COMMA)
def test_values_given_after_a_comma_with_decimal_commas_make_the_number_s_comma_a_decimal(submitted, status, feedback):
    verdict = compare(PERIOD, submitted, **PERIOD_PART)
    assert (verdict.status, verdict.feedback) == (status, feedback)


@pytest.mark.parametrize(("expected", "unit", "submitted", "status", "feedback"), ZERO_DECIMAL_COMMA)
def test_three_digits_after_a_lone_zero_and_a_comma_are_decimals(expected, unit, submitted, status, feedback):
    verdict = compare(expected, submitted, kind="number", rtol=0.005, unit=unit)
    assert (verdict.status, verdict.feedback) == (status, feedback)


def test_three_digits_after_any_other_whole_number_and_a_comma_may_be_thousands():
    assert compare(_FREQUENCY, "0,498", kind="number", rtol=0.005, unit="Hz").status == "equivalent"
    for submitted in ("1,000", "10,498", "00,498", "2,006"):  # 1000 or 1.000? the student is asked for a point
        verdict = compare(PERIOD, submitted, kind="number", rtol=0.005, unit="s")
        assert verdict.feedback[0].startswith("A comma is not understood here"), submitted


def test_out_of_time_is_undecided_and_flagged_for_a_person():
    verdict = compare(L_PENDULUM, "1/2 m l^2 θ̇^2", kind="lagrangian", timeout=1e-9, **PENDULUM)
    assert verdict.status == "undecided"
    assert verdict.needs_person
    assert verdict.feedback == (
        "This answer could not be checked automatically; it has been set aside for a person to grade.",
    )


def test_reading_the_answer_counts_against_the_time_limit():
    # within every cap, yet sympy takes about a second to build each factor: (a + ib)¹⁰⁰ expanded
    slow = "*".join([f"(theta'''-(g^-{n})^(1/5))^(abs(m m)/(l+theta''))" for n in range(93, 101)])
    clear_cache()  # or sympy remembers the factors from an earlier test, and reading is quick
    verdict = compare("sqrt(g/l)", slow, timeout=0.2, **PENDULUM)
    assert (verdict.status, verdict.method) == ("undecided", "timeout")
    assert verdict.answer is None  # stopped while reading, not after


@pytest.mark.parametrize(
    "submitted",
    [
        "θ̈ = −(g/l) sin θ ≈ −(g/l) θ",  # read again as its two forms
        "θ̈ = −(g/l) sin θ, which for small θ gives θ̈ = −(g/l) θ",
    ],
)
def test_second_readings_of_an_answer_share_its_time_limit(monkeypatch, submitted):
    # each reading takes all the time it is given: once the first has, the others have none
    compare_module = importlib.import_module("grader.judge.compare")  # the module, not the function it exports
    now, given = [0.0], []
    judge = compare_module._judge

    def slow(spec, expected, text, timeout, *rest):
        given.append(timeout)
        verdict = judge(spec, expected, text, timeout, *rest)
        now[0] += max(timeout, 0.0)
        return verdict

    monkeypatch.setattr(compare_module, "time", SimpleNamespace(monotonic=lambda: now[0]))
    monkeypatch.setattr(compare_module, "_judge", slow)
    expected = "thetaddot = -(g/l) sin(theta)"
    verdict = compare(expected, submitted, kind="equation", timeout=2.0, **PENDULUM)
    assert given[0] == 2.0 and all(timeout <= 0 for timeout in given[1:]) and len(given) > 1
    assert now[0] <= 2.0 and verdict.status in ("undecided", "not_equivalent", "invalid")


def test_verdicts_are_deterministic():
    first = [compare(e, s, kind=k, **setting) for e, s, k, setting, _, _ in FEEDBACK]
    second = [compare(e, s, kind=k, **setting) for e, s, k, setting, _, _ in FEEDBACK]
    assert first == second


HOSTILE = [
    "9^9^9^9",
    "(a+b+c+d+e+f)^100",
    "x" * 3000,
    "__import__('os').system('true')",
    "sin(" * 50 + "x" + ")" * 50,
    "exp(exp(exp(exp(100))))",
    "1/(theta - theta)",
    "thetadot^100 * 10^100",
    "\\frac{1}{0}",
    "",
]


# with dimensions, a wrong answer's units are analysed too
PENDULUM_UNITS = {**PENDULUM, "dimensions": {"theta": "angle", "m": "mass", "g": "acceleration", "l": "length"}}


@pytest.mark.parametrize("setting", [PENDULUM, PENDULUM_UNITS], ids=["plain", "units"])
@pytest.mark.parametrize("kind", ["expression", "lagrangian", "equation"])
@pytest.mark.parametrize("submitted", HOSTILE)
def test_nothing_a_student_types_makes_compare_raise(kind, submitted, setting):
    expected = EOM_PENDULUM if kind == "equation" else L_PENDULUM
    verdict = compare(expected, submitted, kind=kind, **setting)
    assert isinstance(verdict, Verdict)
    assert verdict.status != "equivalent"


@pytest.mark.parametrize("submitted", [*HOSTILE, "x = 1; y = 2", "2.006 s = T", "T = 2006 ms", "1,5; 2", "2,01 = 2,01"])
def test_nothing_a_student_types_makes_a_number_with_a_unit_raise(submitted):
    verdict = compare("2*pi*sqrt(1/9.81)", submitted, kind="number", unit="s", rtol=0.005)
    assert isinstance(verdict, Verdict)
    # the number's value, named, reversed or repeated: T = 2006 ms, 2.006 s = T, 2,01 = 2,01
    assert verdict.status != "equivalent" or submitted in ("T = 2006 ms", "2.006 s = T", "2,01 = 2,01")


@pytest.mark.parametrize("second", ["theta1 = theta1", "0 = 0", "sin(theta1)^2 + cos(theta1)^2 = 1"])
def test_an_equation_that_holds_for_every_motion_is_named(second):
    verdict = compare(EOM_DOUBLE, f"{EOM_DOUBLE_1}; {second}", kind="equations", **DOUBLE)
    assert verdict.feedback == ("Equation 2 holds for every motion, so it says nothing about this one.",)


@pytest.mark.parametrize("second", ["theta1 = 0", "theta1dot = omega", "l1 cos(theta1) + l2 cos(theta2) = l1"])
def test_an_equation_without_accelerations_is_not_said_to_hold_for_every_motion(second):
    # θ₁ = 0 is a relation, not an identity: it holds for some motions, and says no acceleration
    setting = {**DOUBLE, "known": [*DOUBLE["known"], "omega"]}
    verdict = compare(EOM_DOUBLE, f"{EOM_DOUBLE_1}; {second}", kind="equations", **setting)
    assert verdict.status == "not_equivalent"
    assert verdict.feedback == ("Equation 2 has no acceleration (θ̈₁, θ̈₂) in it, so it is no equation of motion.",)


def test_an_expression_for_a_one_coordinate_system_is_told_an_equation_is_asked():
    verdict = compare(EOM_PENDULUM, "theta", kind="equations", **PENDULUM)
    assert verdict.diagnosis == "expected_equation"


_PIECES = ["theta", "thetadot", "θ̈", "m", "g", "l", "sin", "(", ")", "+", "-", "*", "/", "^", "2", "1/2", "=", ";",
           "\\frac{", "}{", "}", "\\dot\\theta", "x", "d/dt", "[", "]", ",", "9^9", " ",
           "\\over", "\\text{(not sure)}", "mgL"]  # fmt: skip


@settings(max_examples=150, deadline=None)
@given(text=st.lists(st.sampled_from(_PIECES), max_size=14).map("".join))
@pytest.mark.parametrize(
    ("expected", "kind"),
    [(L_PENDULUM, "lagrangian"), (EOM_PENDULUM, "equation"), (EOM_PENDULUM, "equations"), ("sqrt(g/l)", "expression")],
)
def test_no_answer_glued_from_answer_pieces_makes_compare_raise(expected, kind, text):
    # Found this way: a one-coordinate system answered with a bare expression raised KeyError.
    assert isinstance(compare(expected, text, kind=kind, **PENDULUM_UNITS), Verdict)


HOOP = {"coords": ["theta"], "known": ["m", "R", "g", "omega"]}
HOOP_H = "1/2 m R^2 thetadot^2 - 1/2 m R^2 omega^2 sin(theta)^2 - m g R cos(theta)"


@pytest.mark.parametrize(
    ("submitted", "status"),
    [
        ("p_θ²/(2 m R²) − ½ m R² ω² sin²θ − m g R cos θ", "equivalent"),  # the Hamiltonian in the momentum
        ("p_θ θ̇ − ½ m R² θ̇² − ½ m R² ω² sin²θ − m g R cos θ", "equivalent"),  # p θ̇ − L, as defined
        (r"H = \frac{p_\theta^2}{2mR^2} - \frac12 mR^2\omega^2\sin^2\theta - mgR\cos\theta", "equivalent"),
        ("p_θ²/(m R²) − ½ m R² ω² sin²θ − m g R cos θ", "not_equivalent"),
    ],
)
def test_a_given_name_is_put_in_place_and_the_feedback_says_so(submitted, status):
    verdict = compare(HOOP_H, submitted, given={"p_theta": "m R^2 thetadot"}, up_to_constant=True, **HOOP)
    assert verdict.status == status
    assert verdict.feedback[-1] == "Read with the problem's own meaning of `p_θ`."


_P_AS_P_THETA = (
    "Read `p` as `p_θ`, with the problem's own meaning: the problem has one coordinate, so p is its momentum.",
)  # one note: a second, "Read with the problem's own meaning of `p_θ`", would say it again
LONE_MOMENTUM = (
    ("p²/(2 m R²) − ½ m R² ω² sin²θ − m g R cos θ", "equivalent", ("Correct.", *_P_AS_P_THETA)),
    ("H = p²/(2 m R²) − ½ m R² ω² sin²θ − m g R cos θ", "equivalent", ("Correct.", *_P_AS_P_THETA)),
    ("p²/(m R²) − ½ m R² ω² sin²θ − m g R cos θ", "not_equivalent",
     ("A term differs: the term in p_θ² has the wrong factor.", *_P_AS_P_THETA)),
)  # fmt: skip


@pytest.mark.parametrize(("submitted", "status", "feedback"), LONE_MOMENTUM)
def test_a_bare_p_is_the_momentum_of_a_problem_with_one_coordinate(submitted, status, feedback):
    verdict = compare(HOOP_H, submitted, given={"p_theta": "m R^2 thetadot"}, up_to_constant=True, **HOOP)
    assert (verdict.status, verdict.feedback) == (status, feedback)


SPHERICAL_H = "1/2 m l^2 (thetadot^2 + sin(theta)^2 phidot^2) - m g l cos(theta)"
MOMENTA = {"p_theta": "m l^2 thetadot", "p_phi": "m l^2 sin(theta)^2 phidot"}


def test_a_bare_p_is_a_momentum_only_where_one_coordinate_has_one_and_the_student_gives_it_none():
    hoop = compare(HOOP_H, "p²/(2 m R²) − ½ m R² ω² sin²θ − m g R cos θ", given={"p_theta": "m R^2 thetadot"}, **HOOP)
    assert hoop.status == "equivalent"
    # the student's own p is theirs, read with their value and no note
    own = "p²/(2 m R²) − ½ m R² ω² sin²θ − m g R cos θ, where p = m R² θ̇"
    assert compare(HOOP_H, own, given={"p_theta": "m R^2 thetadot"}, **HOOP).feedback == ("Correct.",)
    # with two coordinates, p is neither momentum
    verdict = compare(SPHERICAL_H, "p²/(2 m l²) + p_φ²/(2 m l² sin²θ) − m g l cos θ", given=MOMENTA, **SPHERICAL)
    assert (verdict.status, verdict.diagnosis) == ("not_equivalent", "undefined_symbol")


@pytest.mark.parametrize(
    ("submitted", "sentences"),
    [
        # p_φ²/(2 m l²): in the velocities a term in sin⁴θ, which the student never wrote
        ("p_θ²/(2 m l²) + p_φ²/(2 m l²) − m g l cos θ",
         ("A term is missing: a term in p_φ and sin(θ).", "There is a term too many: a term in p_φ².")),
        ("p_θ²/(2 m l²) + p_φ²/(m l² sin²θ) − m g l cos θ",
         ("A term differs: the term in p_φ² and sin(θ) has the wrong factor.",)),
        ("p_θ²/(2 m) + p_φ²/(2 m l² sin²θ) − m g l cos θ", ("A term differs: the term in p_θ² has the wrong factor.",)),
        # a missing term is named in the momenta too, by the name alone
        ("p_φ²/(2 m l² sin²θ) − m g l cos θ", ("A term is missing: a term in p_θ.",)),
        # both kinetic terms doubled: one term of the expected answer as written, named by both momenta,
        # not "in p_θ p_φ", a product no one wrote
        ("p_θ²/(m l²) + p_φ²/(m l² sin²θ) − m g l cos θ",
         ("A term differs: the term in p_θ and p_φ has the wrong factor.",)),
        # written in the velocities, it is said in the velocities
        ("½ m l² θ̇² + ½ m l² φ̇² − m g l cos θ",
         ("A term is missing: a velocity-dependent term in sin(θ).",
          "There is a term too many: a velocity-dependent term in φ̇².")),
    ],
)  # fmt: skip
def test_an_answer_in_the_given_names_is_diagnosed_in_them(submitted, sentences):
    verdict = compare(SPHERICAL_H, submitted, given=MOMENTA, up_to_constant=True, **SPHERICAL)
    assert verdict.status == "not_equivalent"
    assert verdict.feedback[: len(sentences)] == sentences
    assert not any("velocity" in sentence for sentence in verdict.feedback) or "φ̇" in submitted


@pytest.mark.parametrize(
    ("submitted", "diagnosis"),
    [
        ("p_θ θ̇ + p_φ φ̇ − L", "undefined_symbol"),  # said before any comparison
        ("p_θ θ̇ + p_φ φ̇ − m g l cos θ + m g h", "undefined_symbol"),  # wrong with h taken as a constant
        ("p_θ θ̇ + p_φ φ̇", "wrong"),
    ],
)
def test_what_a_given_name_stands_for_is_never_shown_back(submitted, diagnosis):
    # another part asks for p_φ itself: reading it back as m l² sin²θ φ̇ would give that answer away
    verdict = compare(SPHERICAL_H, submitted, given=MOMENTA, up_to_constant=True, **SPHERICAL)
    assert (verdict.status, verdict.diagnosis) == ("not_equivalent", diagnosis), verdict
    assert "p_φ" in verdict.read_as and "sin" not in verdict.read_as
    assert verdict.feedback[-1] == "Read with the problem's own meaning of `p_φ` and `p_θ`."


def test_given_names_that_do_not_determine_the_velocities_leave_the_diagnosis_in_them():
    # one name for two velocities: the answer cannot be written in it, and is said in the velocities
    given = {"K": "m l^2 (thetadot^2 + phidot^2)"}
    verdict = compare(SPHERICAL_H, "K/2 − m g l cos θ", given=given, up_to_constant=True, **SPHERICAL)
    assert verdict.feedback[0] == "A term is missing: a velocity-dependent term in sin(θ)."


def test_what_a_given_name_stands_for_is_never_shown():
    # another part may ask for p_θ itself: neither feedback nor the answer read back may give it
    verdict = compare(HOOP_H, "p_θ", given={"p_theta": "m R^2 thetadot"}, up_to_constant=True, **HOOP)
    assert verdict.read_as == "p_θ"
    assert not any("R^2" in sentence or "R²" in sentence for sentence in verdict.feedback)


def test_without_given_a_momentum_is_an_undefined_name_and_with_it_unused_says_nothing():
    momentum = "p_θ²/(2 m R²) − ½ m R² ω² sin²θ − m g R cos θ"
    assert compare(HOOP_H, momentum, up_to_constant=True, **HOOP).diagnosis == "undefined_symbol"
    verdict = compare(HOOP_H, HOOP_H, given={"p_theta": "m R^2 thetadot"}, up_to_constant=True, **HOOP)
    assert verdict.feedback == ("Correct.",)


def test_given_names_apply_to_equations_too():
    given = {"omega_0": "sqrt(g/l)"}
    verdict = compare("thetaddot = -g/l sin(theta)", "θ̈ + ω₀² sin θ = 0", kind="equation", given=given, **PENDULUM)
    assert verdict.status == "equivalent"


@pytest.mark.parametrize(
    ("given", "message"),
    [
        ({"p_theta": "q R thetadot"}, "the value given for 'p_theta' uses q, which the problem does not define"),
        ({"m": "R"}, "given name 'm' is already a name of this problem or of its expected answer"),
        ({"p_theta": "a = b"}, "the value given for 'p_theta', 'a = b', cannot be read: it is not an expression"),
        (["p_theta"], "option given must map names to expressions, as {p_theta: m R^2 thetadot}"),
    ],
)
def test_a_wrong_given_is_the_authors_error(given, message):
    with pytest.raises(AuthorError) as error:
        compare(HOOP_H, "x", given=given, **HOOP)
    assert str(error.value) == message


def test_given_is_for_answers_read_as_mathematics():
    with pytest.raises(AuthorError, match="option given does not apply to kind 'choice'"):
        compare("a", "a", kind="choice", options=("a", "b"), given={"p": "1"})


def test_a_small_angle_equation_written_with_approx_is_read_and_told_apart():
    small = compare("thetaddot = -g/l theta", "θ̈ ≈ −(g/l) θ", kind="equation", **PENDULUM)
    full = compare("thetaddot = -g/l sin(theta)", "θ̈ ≈ −(g/l) θ", kind="equation", **PENDULUM)
    assert small.status == "equivalent"
    assert full.diagnosis == "small_angle"


@pytest.mark.parametrize(
    ("submitted", "status"),
    [
        ("ẍ + 2γẋ + ω₀²x = 0, 2γ = b/m, ω₀² = k/m", "equivalent"),  # a damping rate named with its 2
        ("ẍ + 2γẋ + ω₀²x = 0, where 2γ = b/m and ω₀² = 2k/m", "not_equivalent"),
        ("ẍ + γẋ + ω₀²x = 0, 2γ = b/m, ω₀² = k/m", "not_equivalent"),
    ],
)
def test_a_name_defined_with_a_number_before_it_is_put_in_place(submitted, status):
    damped = {"coords": ["x"], "known": ["m", "b", "k"]}
    assert compare("m xddot + b xdot + k x = 0", submitted, kind="equation", **damped).status == status


HOOP_EOM = "R thetaddot = R omega^2 sin(theta) cos(theta) - g sin(theta)"
HOOP = {"coords": ["theta"], "known": ["m", "g", "R", "omega"]}


@pytest.mark.parametrize(
    ("expected", "submitted", "setting", "sentences"),
    [
        # ω² sin θ for ω² sin θ cos θ: one term not right, named by the function both have, and
        # shown as read where the student's other term has that function too; not where the
        # other term is named otherwise, as (g/l) sin θ beside a velocity-dependent term
        (HOOP_EOM, "θ̈ = ω² sin θ − (g/R) sin θ", HOOP, ("A term differs: the term in ω² sin(θ) is not right.",)),
        (SPHERICAL_EOM, "θ̈ = sin θ φ̇² − (g/l) sin θ; φ̈ = −2 cot θ θ̇ φ̇", SPHERICAL,
         ("Your equation for θ is not right; equation 2 is right.",
          "A term differs: a velocity-dependent term in sin(θ) is not right.")),
        # nothing shared: a term lost, another gained
        (HOOP_EOM, "θ̈ = ω² sin θ cos θ − (g/R) cos θ", HOOP,
         ("A term is missing: a term in sin(θ).", "There is a term too many: a term in cos(θ).")),
    ],
)  # fmt: skip
def test_a_term_that_lost_a_function_is_one_term_not_right(expected, submitted, setting, sentences):
    kind = "equations" if ";" in submitted else "equation"
    assert compare(expected, submitted, kind=kind, **setting).feedback == sentences


@pytest.mark.parametrize(
    ("submitted", "sentence"),
    [
        ("m g cos θ + k (r − l0)", "A term differs: the term in r has the wrong sign."),
        ("m g cos θ − 2 k (r − l0)", "A term differs: the term in r has the wrong factor."),
        ("m g cos θ", "A term is missing: a term in r."),
    ],
)
def test_a_term_written_as_a_product_with_a_sum_is_named_as_one_term(submitted, sentence):
    # expanded, k(r − l₀) is two terms, k r and k l₀; the student wrote, and got wrong, one
    spring = {"coords": ["r", "theta"], "known": ["m", "g", "k", "l0"]}
    verdict = compare("m g cos(theta) - k (r - l0)", submitted, **spring)
    assert verdict.feedback == (sentence,)


@pytest.mark.parametrize(
    ("expected", "submitted", "kind", "sentences"),
    [
        # three velocity-dependent terms: the student's own is named by its velocities
        ("m l^2 alphadot^2 + 1/2 m l^2 betadot^2 + m l^2 alphadot betadot cos(alpha - beta)",
         "½ m l² α̇² + ½ m l² β̇² + m l² α̇ β̇ cos(α − β)", "lagrangian",
         ("A term differs: the velocity-dependent term in α̇² has the wrong factor.",)),
        ("m xddot + b xdot + k x = 0", "m ẍ + b ẋ² + k x = 0", "equation",
         ("A term differs: a velocity-dependent term in ẋ² is not right.",)),  # one term changed
        ("1/2 m xdot^2 - 1/2 k x^2", "½ m ẋ² − ½ k x² + b x ẋ", "expression",
         ("There is a term too many: a velocity-dependent term in ẋ.",)),  # (a total derivative in L)
        # a term the answer lacks is not described by its velocities: that would give it away
        ("1/2 m xdot^2 + b x xdot - 1/2 k x^2", "½ m ẋ² − ½ k x²", "expression",
         ("A term is missing: a velocity-dependent term.",)),
    ],
)  # fmt: skip
def test_the_students_own_velocity_dependent_term_is_named_by_its_velocities(expected, submitted, kind, sentences):
    setting = {"coords": ["x", "alpha", "beta"], "known": ["m", "l", "b", "k"]}
    assert compare(expected, submitted, kind=kind, **setting).feedback == sentences


L_HOOP = "1/2 m R^2 thetadot^2 + 1/2 m R^2 omega^2 sin(theta)^2 + m g R cos(theta)"
L_SPHERICAL = "1/2 m l^2 (thetadot^2 + sin(theta)^2 phidot^2) + m g l cos(theta)"


@pytest.mark.parametrize(
    ("expected", "submitted", "setting", "sentence"),
    [
        # m R² ω θ̇ of (θ̇ + ω)² is d/dt (m R² ω θ): only the missing ½ m R² ω² sin²θ is the mistake
        (L_HOOP, "1/2 m R^2 (thetadot + omega)^2 + m g R cos(theta)", {**HOOP, "known": ["m", *HOOP["known"]]},
         "A term is missing: a term in sin(θ)."),
        # φ̇ is d/dt φ; −φ̇ cos θ is no time derivative
        (L_SPHERICAL, f"{L_SPHERICAL} + phidot (1 - cos(theta))", SPHERICAL,
         "There is a term too many: a velocity-dependent term in cos(θ)."),
        (L_PENDULUM, "1/2 m l^2 thetadot^2 - m g l cos(theta) + m l^2 theta thetadot + t^2", PENDULUM,
         "It looks like you wrote L = T + V; the Lagrangian is L = T − V."),
        # t θ̇ is not one: d/dt (t θ) = θ + t θ̇
        (L_PENDULUM, f"{L_PENDULUM} + m l t thetadot", PENDULUM,
         "There is a term too many: a velocity-dependent term in θ̇."),
        # ½ m ẋ is d/dt (½ m x), but it is what the student wrote for ½ m ẋ²: told as written
        ("1/2 m xdot^2 - 1/2 k x^2", "1/2 m xdot - 1/2 k x^2", DAMPED,
         "A term differs: a velocity-dependent term in ẋ is not right."),
        # ½ (m₁ + m₂) g² t² goes; (m₁ + m₂) g t ẋ stays, and is all that is wrong
        (L_ATWOOD, "1/2 (m1 + m2) (xdot + g t)^2 + (m1 - m2) g x", ATWOOD,
         "There is a term too many: a velocity-dependent term in ẋ."),
        # sin θ → θ in T and cos θ → 1 − θ²/2 in V, which an expansion of all of L to second order is not
        (L_SPHERICAL, "1/2 m l^2 (thetadot^2 + theta^2 phidot^2) - 1/2 m g l theta^2", SPHERICAL,
         "You used the small-angle approximation, but the full answer is asked for here."),
    ],
)  # fmt: skip
def test_a_wrong_lagrangian_is_told_its_mistake_and_not_its_harmless_total_derivatives(
    expected, submitted, setting, sentence
):
    verdict = compare(expected, submitted, kind="lagrangian", **setting)
    assert (verdict.status, verdict.score) == ("not_equivalent", 0.0)
    assert verdict.feedback == (sentence,)


@pytest.mark.parametrize(
    ("expected", "kind", "submitted", "sentence"),
    [
        # the kinetic energy in brackets, twice too large: one term of the student's, named by its velocities
        (L_SPHERICAL, "lagrangian", "m l^2 (thetadot^2 + sin(theta)^2 phidot^2) + m g l cos(theta)",
         "A term differs: the velocity-dependent term in θ̇ and φ̇ has the wrong factor."),
        (SPHERICAL_H, "expression", "m l^2 (thetadot^2 + sin(theta)^2 phidot^2) - m g l cos(theta)",
         "A term differs: the velocity-dependent term in θ̇ and φ̇ has the wrong factor."),
        # written apart, only the one that is wrong is named, by its velocity
        (L_SPHERICAL, "lagrangian", "m l^2 thetadot^2 + 1/2 m l^2 sin(theta)^2 phidot^2 + m g l cos(theta)",
         "A term differs: the velocity-dependent term in θ̇² has the wrong factor."),
    ],
)  # fmt: skip
def test_a_term_of_the_students_that_sums_several_velocities_is_named_by_them(expected, kind, submitted, sentence):
    # named "the term in sin(θ)", a student would mend the φ̇² term and leave the θ̇² term twice too large
    verdict = compare(expected, submitted, kind=kind, **SPHERICAL)
    assert verdict.feedback == (sentence,)


P_PHI = "m l^2 sin(theta)^2 phidot"


@pytest.mark.parametrize(
    "submitted", ["p_phi = m l² sin²θ φ̇", "p_\\phi = m l^2 \\sin^2\\theta \\dot\\phi", "p = m l² sin²θ φ̇"]
)
def test_the_asked_quantitys_name_or_its_stem_is_a_label_like_any(submitted):
    for name in ("p_phi", "p_φ", ["H", "p_phi"]):  # a Greek letter in the name is its ASCII name
        assert compare(P_PHI, submitted, name=name, **SPHERICAL).status == "equivalent", name


@pytest.mark.parametrize(
    ("submitted", "label"),
    [
        ("p_theta = m l² sin²θ φ̇", "p_θ"),
        ("H = m l² sin²θ φ̇", "H"),
        ("2 p_theta = 2 m l² sin²θ φ̇", "p_θ"),
        ("p_theta/m = l² sin²θ φ̇", "p_θ"),  # over m, as p_φ/m = … is read
    ],
)
def test_a_right_value_under_another_quantitys_name_goes_to_a_person(submitted, label):
    verdict = compare(P_PHI, submitted, name="p_phi", **SPHERICAL)
    assert (verdict.status, verdict.score) == ("undecided", 1.0), verdict
    assert verdict.feedback[0].startswith(f"Your answer is labelled {label}, but the quantity asked for is p_φ."), (
        verdict
    )
    # without the option, any name is a label: the answer is right
    assert compare(P_PHI, submitted, **SPHERICAL).status == "equivalent"


@pytest.mark.parametrize(
    ("submitted", "status", "first"),
    [
        # ∂V/∂θ is −Q_θ: a right value under it is for a person, a wrong one is wrong; both name it as typed
        ("∂V/∂θ = −m g r sin θ", "undecided",
         "Your answer is labelled ∂V/∂θ, but the quantity asked for is Q_θ. Read as Q_θ, it is right; a person will"
         " check which you meant."),
        ("∂V/∂θ = m g r sin θ", "not_equivalent", "Your answer is labelled ∂V/∂θ, but the quantity asked for is Q_θ."),
        ("∂T/∂θ̇ = −m g r sin θ", "undecided",
         "Your answer is labelled ∂T/∂θ̇, but the quantity asked for is Q_θ. Read as Q_θ, it is right; a person will"
         " check which you meant."),
        # −∂V/∂θ is Q_θ, as the prompt defines it; −∂V/∂r is Q_r, another quantity: before, `∂` refused
        ("−∂V/∂θ = −m g r sin θ", "equivalent", "Correct."),
        ("−∂V/∂θ = m g r sin θ", "not_equivalent", "The overall sign is wrong."),
        ("-\\frac{\\partial V}{\\partial \\theta} = -m g r \\sin\\theta", "equivalent", "Correct."),
        ("−∂V/∂r = −m g r sin θ", "undecided",
         "Your answer is labelled −∂V/∂r, but the quantity asked for is Q_θ. Read as Q_θ, it is right; a person will"
         " check which you meant."),
        ("−∂V/∂r = m g r sin θ", "not_equivalent",
         "Your answer is labelled −∂V/∂r, but the quantity asked for is Q_θ."),
    ],
)  # fmt: skip
def test_a_label_that_is_a_partial_derivative_is_shown_as_typed(submitted, status, first):
    # before: "labelled dV_dtheta", the parser's own name for it
    (answer, setting) = Q_THETA
    verdict = compare(answer, submitted, **setting)
    assert verdict.status == status
    assert first in verdict.feedback


_OMEGA = {**PENDULUM, "name": ["omega", "omega_0", "w", "w_0"]}
_Q_R = {"coords": ["r", "theta"], "known": ["m", "g", "k", "l0"], "name": ["Q_r"]}


@pytest.mark.parametrize(
    ("expected", "submitted", "options", "status", "feedback"),
    [
        # a coordinate's rate, where the quantity asked for is not one, is another quantity: before, Correct
        ("sqrt(g/l)", "θ̇ = √(g/l)", _OMEGA, "undecided",
         ("Your answer is labelled θ̇, but the quantity asked for is ω. Read as ω, it is right; a person will check"
          " which you meant.",)),
        ("m g cos(theta) - k (r - l0)", "r̈ = m g cos θ − k (r − l0)", _Q_R, "undecided",
         ("Your answer is labelled r̈, but the quantity asked for is Q_r. Read as Q_r, it is right; a person will"
          " check which you meant.",)),
        ("sqrt(g/l)", "ω = √(g/l)", _OMEGA, "equivalent", ("Correct.",)),
    ],
)  # fmt: skip
def test_a_label_that_is_a_rate_where_none_is_asked_goes_to_a_person(expected, submitted, options, status, feedback):
    verdict = compare(expected, submitted, **options)
    assert (verdict.status, verdict.feedback) == (status, feedback)


@pytest.mark.parametrize(
    "submitted", ["∂V/∂θ = m g l sin θ", "−∂V/∂θ = −m g l sin θ", r"\frac{\partial V}{\partial \theta} = mgl\sin\theta"]
)
def test_a_partial_derivative_where_an_equation_is_asked_is_named_as_typed(submitted):
    # before: "Your answer uses `dV_dtheta`", and read as dV_dtheta = …
    verdict = compare("m l^2 thetaddot + m g l sin(theta) = 0", submitted, kind="equation", coords=["theta"])
    assert verdict.status == "not_equivalent"
    assert verdict.feedback[0].startswith("Your answer uses `∂V/∂θ`, which this problem does not define")
    assert "∂V/∂θ = " in verdict.read_as and "dV" not in verdict.read_as


@pytest.mark.parametrize(
    ("submitted", "status"),
    [
        ("m l² sin²θ φ̇ = p_φ", "equivalent"),  # before: p_φ was not defined
        ("m l² sin²θ φ̇ = p_θ", "undecided"),
        ("m l² θ̇ = p_φ", "not_equivalent"),
    ],
)
def test_a_value_may_come_before_its_name(submitted, status):
    verdict = compare(P_PHI, submitted, name="p_phi", **SPHERICAL)
    assert verdict.status == status, verdict
    assert "not define" not in " ".join(verdict.feedback), verdict


_ATWOOD_NAMED = {"coords": ["x"], "known": ["m1", "m2", "g"], "name": ["xddot", "a", "a_1"]}


@pytest.mark.parametrize(
    ("submitted", "status", "feedback"),
    [
        # the asked rate negated, or after its value: before, "An expression is asked for here"
        ("−ẍ = (m2 − m1) g/(m1 + m2)", "equivalent", ("Correct.",)),
        ("−ẍ = (m1 − m2) g/(m1 + m2)", "not_equivalent", ("The overall sign is wrong.",)),
        ("g (m1 − m2)/(m1 + m2) = ẍ", "equivalent", ("Correct.",)),
        ("g (m2 − m1)/(m1 + m2) = ẍ", "not_equivalent", ("The overall sign is wrong.",)),
        # the asked rate negated after its value: before, "An expression is asked for here"
        ("(m2 − m1) g/(m1 + m2) = −ẍ", "equivalent", ("Correct.",)),
        ("(m1 − m2) g/(m1 + m2) = −ẍ", "not_equivalent", ("The overall sign is wrong.",)),
        ("(m2-m1) g/(m1+m2) = -xddot", "equivalent", ("Correct.",)),
        ("(m2 − m1) g/(m1 + m2) = −a", "equivalent", ("Correct.",)),  # the asked quantity's other name, negated
        ("(m1 − m2) g/(m1 + m2) = −a", "not_equivalent", ("The overall sign is wrong.",)),
        # another rate so is another quantity's value: for a person
        ("−ẋ = (m2 − m1) g/(m1 + m2)", "undecided",
         ("Your answer is labelled ẋ, but the quantity asked for is ẍ. Read as ẍ, it is right; a person will check"
          " which you meant.",)),
        ("g (m1 − m2)/(m1 + m2) = ẋ", "undecided",
         ("Your answer is labelled ẋ, but the quantity asked for is ẍ. Read as ẍ, it is right; a person will check"
          " which you meant.",)),
    ],
)  # fmt: skip
def test_a_rate_named_negated_or_after_its_value_is_the_name_of_the_value(submitted, status, feedback):
    verdict = compare(ATWOOD_A, submitted, **_ATWOOD_NAMED)
    assert (verdict.status, verdict.feedback) == (status, feedback)


@pytest.mark.parametrize(
    ("submitted", "status", "score", "feedback"),
    [
        # a claim beside the value, true of p_φ (φ is cyclic) but not asked, and false of others: for a person
        ("p_φ = m l² sin²θ φ̇ = constant", "undecided", 1.0, ("Your answer ends `= constant`, which says the quantity"
         " is constant: that is not asked here. Its formula was graded and is right; a person will check this"
         " answer.",)),
        ("m l^2 sin(theta)^2 phidot = const", "undecided", 1.0, ("Your answer ends `= const`, which says the quantity"
         " is constant: that is not asked here. Its formula was graded and is right; a person will check this"
         " answer.",)),
        ("p_φ = m l² sin²θ φ̇ = C", "undecided", 1.0, ("Your answer ends `= C`, which says the quantity is constant:"
         " that is not asked here. Its formula was graded and is right; a person will check this answer.",)),
        # wrong either way: graded, and told how it was read
        ("m l^2 sin(theta) phidot = const", "not_equivalent", 0.0, ("Your answer depends on l, m and φ̇ as the right"
         " answer does, but on θ in another way: check how your answer depends on θ.", "Read without `= const`,"
         " which says the quantity is constant: its formula was graded.")),
    ],
)  # fmt: skip
def test_a_value_said_to_be_constant_is_no_value_labelled_constant(submitted, status, score, feedback):
    # before: "Your answer is labelled constant, but the quantity asked for is p_φ", which it is not
    verdict = compare(P_PHI, submitted, name="p_phi", **SPHERICAL)
    assert (verdict.status, verdict.score, verdict.feedback) == (status, score, feedback)


@pytest.mark.parametrize(
    ("submitted", "status", "score"),
    [
        # the name, its value, and "= const" after it: before, ẍ itself was graded as the value, wrong
        ("ẍ = (m1 - m2) g/(m1 + m2) = const", "undecided", 1.0),
        ("xddot = (m1 - m2) g / (m1 + m2) = constant", "undecided", 1.0),
        ("ẍ = (m1 + m2) g/(m1 - m2) = const", "not_equivalent", 0.0),
    ],
)
def test_a_chain_that_ends_in_a_constant_says_its_value_is_constant(submitted, status, score):
    verdict = compare(ATWOOD_A, submitted, coords=["x"], known=["m1", "m2", "g"])
    assert (verdict.status, verdict.score) == (status, score), verdict
    assert any("which says the quantity is constant" in line for line in verdict.feedback), verdict


def test_a_wrong_value_under_another_name_is_told_the_label_too():
    verdict = compare(P_PHI, "p_theta = m l² θ̇", name="p_phi", **SPHERICAL)
    assert verdict.status == "not_equivalent", verdict
    assert "Your answer is labelled p_θ, but the quantity asked for is p_φ." in verdict.feedback, verdict


def test_a_lagrangian_is_named_l_unless_the_part_says_otherwise():
    lagrangian = "1/2 m l^2 thetadot^2 + m g l cos(theta)"
    for label in ("L", "L(θ, θ̇)", "2 L"):
        right = lagrangian if label != "2 L" else f"2 ({lagrangian})"
        assert compare(lagrangian, f"{label} = {right}", kind="lagrangian", coords=["theta"]).equivalent, label
    verdict = compare(lagrangian, f"H = {lagrangian}", kind="lagrangian", coords=["theta"])
    assert verdict.status == "undecided" and "labelled H" in verdict.feedback[0], verdict
    assert compare(lagrangian, f"H = {lagrangian}", kind="lagrangian", coords=["theta"], name="H").equivalent


@pytest.mark.parametrize(
    ("label", "status", "score"),
    [
        ("T − V", "equivalent", 1.0),
        ("T − U", "equivalent", 1.0),
        ("T + V", "undecided", 1.0),  # the energy, where the Lagrangian is asked: before, Correct
        ("T + U", "undecided", 1.0),
        ("2(T − V)", "not_equivalent", 0.5),  # then L is half the right one: a normalization
        ("(T − V)/2", "not_equivalent", 0.5),
    ],
)
def test_a_left_side_in_the_energies_names_l_only_as_t_minus_v(label, status, score):
    lagrangian = "1/2 m l^2 thetadot^2 + m g l cos(theta)"
    verdict = compare(lagrangian, f"{label} = {lagrangian}", kind="lagrangian", coords=["theta"])
    assert (verdict.status, verdict.score) == (status, score), verdict
    if status == "undecided":
        assert verdict.feedback[0].startswith("Your answer is labelled T + "), verdict


def test_a_hamiltonian_is_t_plus_v_and_a_tension_t_no_energy():
    hamiltonian = "p^2/(2 m) + m g l (1 - cos(theta))"
    assert compare(hamiltonian, f"T + V = {hamiltonian}", coords=["theta"], name="H").equivalent
    verdict = compare(hamiltonian, f"T − V = {hamiltonian}", coords=["theta"], name="H")
    assert verdict.status == "undecided" and "labelled T - V" in verdict.feedback[0], verdict
    # where the problem names a tension T, T + V is no label of energies
    verdict = compare("T + m g", "T + V = T + m g", name="H")
    assert "labelled" not in " ".join(verdict.feedback), verdict


OMEGA = {"coords": ["theta"], "name": ["omega", "omega_0"]}
LAST_OF_TWO = "Your answer has 2 lines; the last was graded as your answer."


def _others(*names):
    if len(names) == 1:
        return f"The line that defines `{names[0]}` was not graded: ω is what is asked for here."
    listed = " and ".join(f"`{name}`" for name in names)
    return f"The lines that define {listed} were not graded: ω is what is asked for here."


@pytest.mark.parametrize(
    ("submitted", "status", "notes"),
    [
        # ω, T and f listed where ω is asked: the line labelled ω is graded, wherever it stands
        ("ω = √(g/l)\nT = 2π√(l/g)\nf = √(g/l)/(2π)", "equivalent", (_others("T", "f"),)),
        ("T = 2π√(l/g); f = 1/(2π) √(g/l); ω = √(g/l)", "equivalent", (_working("T", "f"),)),  # last, as before
        ("T = 2π√(l/g); ω = √(g/l); f = 1/(2π) √(g/l)", "equivalent", (_others("T", "f"),)),
        # before: the last line, f, was graded, and a right ω marked wrong; a wrong ω passed under a right f
        ("ω = √(l/g)\nT = 2π√(l/g)\nf = √(g/l)/(2π)", "not_equivalent", (_others("T", "f"),)),
        # two lines name the asked quantity: two answers, judged line by line (before: the last, Correct)
        ("ω = √(l/g)\nω₀ = √(g/l)", "undecided", ()),
        ("ω₀ = √(g/l)\nω = √(l/g)", "not_equivalent", (LAST_OF_TWO,)),
        # a line that uses ω keeps ω's line the answer: before, ω was put in place and T graded
        ("ω = √(g/l); T = 2π/ω", "equivalent", (_others("T"),)),
        ("ω² = g/l; T = 2π/ω", "equivalent", (_others("T"),)),
        # and ω defined from T is ω's value
        ("T = 2π√(l/g); ω = 2π/T; f = 1/T", "equivalent", (_others("f"),)),
    ],
)
def test_of_several_quantities_listed_the_one_asked_for_is_graded(submitted, status, notes):
    verdict = compare("sqrt(g/l)", submitted, **OMEGA)
    assert (verdict.status, verdict.notes) == (status, notes), verdict


def test_a_lagrangian_labelled_l_is_graded_before_other_quantities():
    # before: the last line is not L, so the answer was a guess, not equivalent
    verdict = compare(L_PENDULUM, "L = ½ m l² θ̇² + m g l cos θ; T = ½ m l² θ̇²", kind="lagrangian", **PENDULUM)
    assert (verdict.status, verdict.notes) == (
        "equivalent",
        ("The line that defines `T` was not graded: L is what is asked for here.",),
    ), verdict


@pytest.mark.parametrize("name", [5, [], [1], ["p", 3], ""])
def test_a_name_option_that_names_nothing_is_the_authors_error(name):
    with pytest.raises(AuthorError, match="option name"):
        compare(P_PHI, P_PHI, name=name, **SPHERICAL)


def test_a_forces_constant_term_left_out_is_a_term_not_a_zero_level():
    dimensions = {
        "m": "mass",
        "g": "acceleration",
        "k": "force per length",
        "r": "length",
        "l0": "length",
        "theta": "angle",
    }
    expected = "m g cos(theta) - k (r - l0)"
    verdict = compare(expected, "m g cos(theta) - k r", coords=["r", "theta"], dimensions=dimensions)
    assert verdict.status == "not_equivalent", verdict
    assert verdict.feedback[0].startswith("A term is missing"), verdict
    # the same difference in a potential energy is another zero of it
    energy = "-m g r cos(theta) + 1/2 k (r - l0)^2"
    verdict = compare(
        energy, "-m g r cos(theta) + 1/2 k (r - l0)^2 + m g l0", coords=["r", "theta"], dimensions=dimensions
    )
    assert verdict.feedback[0].startswith("Your answer is right but for an added constant"), verdict


def test_a_torques_constant_is_a_term_though_a_torque_is_measured_in_energy():
    dimensions = {"m": "mass", "g": "acceleration", "r": "length", "l0": "length", "theta": "angle"}
    torque = "-m g r sin(theta)"
    for name in ("Q_theta", None):
        setting = {"coords": ["r", "theta"], "known": ["l0"], "dimensions": dimensions}
        verdict = compare(torque, "-m g r sin θ + m g l0", name=name, **setting)
        said = " ".join(verdict.feedback)
        assert ("added constant" in said) == (name is None), (name, verdict)  # unnamed: measured as an energy


def test_a_one_term_answer_is_told_the_symbols_it_lacks_and_those_it_should_not_have():
    verdict = compare("sqrt(g/l)", "m θ̇", **PENDULUM)
    assert verdict.feedback == (
        "Your answer does not depend on g and l, and the right answer does.",
        "The right answer does not depend on m and θ̇.",
    ), verdict


HOOP_H_TYPED = "1/2 m R^2 θ̇^2 − 1/2 m R^2 ω^2 sin^2θ − m g R cos θ"


@pytest.mark.parametrize(
    ("expected", "submitted", "kind", "options", "status", "first"),
    [
        # right as a value, but it says L is T + V: a person decides
        (L_PENDULUM, "L = T + V = 1/2 m l^2 θ̇^2 + m g l cos θ", "lagrangian", {}, "undecided",
         "Your answer says `L = T + V` on the way to its value, which is not what L is. Its value was graded and"
         " is right; a person will check this answer."),
        (L_PENDULUM, "L = T + U = 1/2 m l^2 θ̇^2 + m g l cos θ", "lagrangian", {}, "undecided",
         "Your answer says `L = T + U` on the way to its value, which is not what L is. Its value was graded and"
         " is right; a person will check this answer."),
        (HOOP_H, f"H = T − V = {HOOP_H_TYPED}", "expression", {"name": "H"}, "undecided",
         "Your answer says `H = T − V` on the way to its value, which is not what H is. Its value was graded and"
         " is right; a person will check this answer."),
        # in lines of working: V's sign and L = T + V, two slips that make a right value
        (L_PENDULUM, "T = 1/2 m l^2 θ̇^2, V = m g l cos θ, L = T + V", "lagrangian", {}, "undecided",
         "Your answer says `L = T + V` on the way to its value, which is not what L is. Its value was graded and"
         " is right; a person will check this answer."),
        # on a line of its own, before the line that gives L's value
        (L_PENDULUM, "L = T + V\nL = 1/2 m l^2 θ̇^2 + m g l cos θ", "lagrangian", {}, "undecided",
         "Your answer says `L = T + V` on the way to its value, which is not what L is. Its value was graded and"
         " is right; a person will check this answer."),
        # wrong either way: said beside the diagnosis
        (L_PENDULUM, "L = T + U = 1/2 m l^2 θ̇^2 + 2 m g l cos θ", "lagrangian", {}, "not_equivalent",
         "A term differs: the term in cos(θ) has the wrong factor."),
        # what it says is right
        (L_PENDULUM, "L = T − V = 1/2 m l^2 θ̇^2 + m g l cos θ", "lagrangian", {}, "equivalent", "Correct."),
        (L_PENDULUM, "L = T − U = 1/2 m l^2 θ̇^2 + m g l cos θ", "lagrangian", {}, "equivalent", "Correct."),
        # H = T + V is what H is where T is quadratic in the velocities; whether it is here, the bank's
        # listed mistake (T + V's own value) says, not the statement
        (HOOP_H, f"H = T + V = {HOOP_H_TYPED}", "expression", {"name": "H"}, "equivalent", "Correct."),
    ],
)  # fmt: skip
def test_a_chain_that_says_its_quantity_is_the_wrong_sum_of_energies(expected, submitted, kind, options, status, first):
    verdict = compare(expected, submitted, kind=kind, coords=["theta"], known=["m", "g", "l", "R", "omega"], **options)
    assert verdict.status == status, verdict
    assert verdict.feedback[0] == first
    if status == "not_equivalent":
        statement = submitted.split(" = ")[1]
        said = f"Your answer says `L = {statement}` on the way to its value, which is not what L is."
        assert verdict.feedback[-1] == said


@pytest.mark.parametrize(
    "submitted",
    [
        "L = T + V = 1/2 m l^2 θ̇^2 - m g l cos θ",
        "T = 1/2 m l^2 θ̇^2; V = -m g l cos θ; L = T + V",
        "L = T + V\nL = 1/2 m l^2 θ̇^2 - m g l cos θ",  # not also "the line states what L means"
    ],
)
def test_a_chain_that_says_l_is_t_plus_v_of_its_value_too_is_told_once(submitted):
    verdict = compare(L_PENDULUM, submitted, kind="lagrangian", **PENDULUM)
    assert (verdict.status, verdict.diagnosis) == ("not_equivalent", "t_plus_v")
    assert verdict.feedback == ("It looks like you wrote L = T + V; the Lagrangian is L = T − V.",)


L_TYPED = "1/2 m l^2 θ̇^2 + m g l cos θ"
SPHERICAL_H_TYPED = "1/2 m l^2 (θ̇^2 + sin^2θ φ̇^2) - m g l cos θ"
SPHERICAL_P_PHI = "m l^2 sin(theta)^2 phidot"
# on a rotating hoop T = T₂ + T₀, so H = T₂ − T₀ + V, not the energy T + V; the part says so
HOOP_NOT_ENERGY = {"coords": ["theta"], "known": ["m", "R", "g", "omega"], "name": "H", "h_is_energy": False}
HOOP_H_TYPED = "1/2 m R^2 θ̇^2 − 1/2 m R^2 ω^2 sin^2θ − m g R cos θ"


ELASTIC = {"coords": ["r", "theta"], "known": ["m", "g", "k", "l0"]}  # the elastic pendulum's polar coordinates
_HOOP_WORKED = "m R² θ̇² − (½ m R² θ̇² + ½ m R² ω² sin²θ + m g R cos θ)"  # p_θ θ̇ − L, worked out
Q_THETA = ("-m g r sin(theta)", {"coords": ["r", "theta"], "known": ["m", "g", "k", "l0"], "name": "Q_theta"})


def _misstated(statement: str, label: str) -> str:
    return (
        f"Your answer says `{statement}` on the way to its value, which is not what {label} is. Its value was"
        " graded and is right; a person will check this answer."
    )


@pytest.mark.parametrize(
    ("expected", "submitted", "kind", "options", "first"),
    [
        # said in words or before ⇒, which the reading of the formula leaves out
        (L_PENDULUM, f"L = T + V ⇒ L = {L_TYPED}", "lagrangian", PENDULUM, _misstated("L = T + V", "L")),
        (L_PENDULUM, f"Using L = T + V we get L = {L_TYPED}", "lagrangian", PENDULUM, _misstated("L = T + V", "L")),
        (L_PENDULUM, f"The Lagrangian is L = T + V = {L_TYPED}", "lagrangian", PENDULUM,
         _misstated("L = T + V", "L")),
        # other letters for the same mistakes
        (L_PENDULUM, f"L = K + U = {L_TYPED}", "lagrangian", PENDULUM, _misstated("L = K + U", "L")),
        (L_PENDULUM, f"L = E = {L_TYPED}", "lagrangian", PENDULUM, _misstated("L = E", "L")),
        (L_PENDULUM, f"L = H = {L_TYPED}", "lagrangian", PENDULUM, _misstated("L = H", "L")),
        # another quantity in the sum, written as the energies it is: 2V − E is V − T
        (L_PENDULUM, f"L = 2V − E = {L_TYPED}", "lagrangian", PENDULUM, _misstated("L = 2V − E", "L")),
        (SPHERICAL_H, f"H = 2L − T = {SPHERICAL_H_TYPED}", "expression", SPHERICAL, _misstated("H = 2L − T", "H")),
        # H as the wrong combination of Σ p q̇ and L, in Unicode and in TeX
        (SPHERICAL_H, f"H = Σ p q̇ + L = {SPHERICAL_H_TYPED}", "expression", SPHERICAL,
         _misstated("H = Σ p q̇ + L", "H")),
        (SPHERICAL_H, f"H = L − Σ p q̇ = {SPHERICAL_H_TYPED}", "expression", SPHERICAL,
         _misstated("H = L − Σ p q̇", "H")),
        (SPHERICAL_H, rf"H = \sum_j p_j \dot q_j + L = {SPHERICAL_H_TYPED}", "expression", SPHERICAL,
         _misstated("H = \\sum_j p_j \\dot q_j + L", "H")),
        (SPHERICAL_H, f"H = L = {SPHERICAL_H_TYPED}", "expression", SPHERICAL, _misstated("H = L", "H")),
        # a momentum by the wrong derivative
        (SPHERICAL_P_PHI, "p_φ = ∂L/∂φ = m l² sin²θ φ̇", "expression", SPHERICAL, _misstated("p_φ = ∂L/∂φ", "p_φ")),
        (SPHERICAL_P_PHI, "p_φ = ∂L/∂θ̇ = m l² sin²θ φ̇", "expression", SPHERICAL,
         _misstated("p_φ = ∂L/∂θ̇", "p_φ")),
        # said in a sentence before the value: before, `Since`, T and V were told undefined, and wrong
        (L_PENDULUM, f"Since L = T + V, L = {L_TYPED}", "lagrangian", PENDULUM, _misstated("L = T + V", "L")),
        (L_PENDULUM, f"The Lagrangian L = K + U is {L_TYPED}", "lagrangian", PENDULUM, _misstated("L = K + U", "L")),
        (L_PENDULUM, f"With L = V − T: L = {L_TYPED}", "lagrangian", PENDULUM, _misstated("L = V − T", "L")),
        (L_PENDULUM, f"Using L = E, we have L = {L_TYPED}", "lagrangian", PENDULUM, _misstated("L = E", "L")),
        (SPHERICAL_H, f"As H = Σ p q̇ + L, H = {SPHERICAL_H_TYPED}", "expression", SPHERICAL,
         _misstated("H = Σ p q̇ + L", "H")),
        (SPHERICAL_P_PHI, "Since p_φ = ∂L/∂φ, p_φ = m l² sin²θ φ̇", "expression", SPHERICAL,
         _misstated("p_φ = ∂L/∂φ", "p_φ")),
        ("m l^2 thetadot", "Since p_θ = ∂L/∂θ, p_θ = m l² θ̇", "expression", {**PENDULUM, "name": "p_theta"},
         _misstated("p_θ = ∂L/∂θ", "p_θ")),
        # a generalized force as +∂V/∂r, or by another coordinate's derivative: before, Correct
        ("m g cos(theta) - k (r - l0)", "Q_r = ∂V/∂r = m g cos θ − k (r − l0)", "expression", ELASTIC,
         _misstated("Q_r = ∂V/∂r", "Q_r")),
        ("m g cos(theta) - k (r - l0)", "Q_r = −∂V/∂θ = m g cos θ − k (r − l0)", "expression", ELASTIC,
         _misstated("Q_r = −∂V/∂θ", "Q_r")),
        # Σ p q̇ − L written out, with a coordinate's term left out or + L: before, each was Correct
        (SPHERICAL_H, f"H = p_φ φ̇ − L = {SPHERICAL_H_TYPED}", "expression", SPHERICAL,
         _misstated("H = p_φ φ̇ − L", "H")),
        (SPHERICAL_H, f"H = p_θ θ̇ + p_φ φ̇ + L = {SPHERICAL_H_TYPED}", "expression", SPHERICAL,
         _misstated("H = p_θ θ̇ + p_φ φ̇ + L", "H")),
        (HOOP_H, f"Since H = p_θ θ̇ + L, H = {HOOP_H_TYPED}", "expression", HOOP_NOT_ENERGY,
         _misstated("H = p_θ θ̇ + L", "H")),
        # a chain of more sides, read side by side: before, the definition was passed over, and right
        (HOOP_H, f"H = p_θ θ̇ + L = {_HOOP_WORKED} = {HOOP_H_TYPED}", "expression", HOOP_NOT_ENERGY,
         _misstated("H = p_θ θ̇ + L", "H")),
        # Σ p q̇ − L written otherwise wrong, in momenta, as ∂L/∂θ̇ or worked out with the momenta given: before,
        # each was Correct (only a term left out, or + L, was known wrong)
        (HOOP_H, f"H = θ p_θ − L = {HOOP_H_TYPED}", "expression", HOOP_NOT_ENERGY, _misstated("H = θ p_θ − L", "H")),
        (HOOP_H, f"H = θ ∂L/∂θ̇ − L = {HOOP_H_TYPED}", "expression", HOOP_NOT_ENERGY,
         _misstated("H = θ ∂L/∂θ̇ − L", "H")),
        (HOOP_H, f"H = ∂L/∂θ̇ − L = {HOOP_H_TYPED}", "expression", HOOP_NOT_ENERGY, _misstated("H = ∂L/∂θ̇ − L", "H")),
        (HOOP_H, f"H = L − θ̇ ∂L/∂θ̇ = {HOOP_H_TYPED}", "expression", HOOP_NOT_ENERGY,
         _misstated("H = L − θ̇ ∂L/∂θ̇", "H")),
        (HOOP_H, f"H = 2 θ̇ ∂L/∂θ̇ − L = {HOOP_H_TYPED}", "expression", HOOP_NOT_ENERGY,
         _misstated("H = 2 θ̇ ∂L/∂θ̇ − L", "H")),
        (HOOP_H, f"H = θ̇ ∂L/∂θ̇ − T = {HOOP_H_TYPED}", "expression", HOOP_NOT_ENERGY,
         _misstated("H = θ̇ ∂L/∂θ̇ − T", "H")),
        (HOOP_H, f"H = θ̇ ∂L/∂θ̇ − L = m R² θ̇² + L = {HOOP_H_TYPED}", "expression",
         {**HOOP_NOT_ENERGY, "given": {"p_theta": "m R^2 thetadot"}}, _misstated("H = m R² θ̇² + L", "H")),
        (SPHERICAL_H, f"H = θ̇ ∂L/∂θ̇ + φ̇ ∂L/∂θ̇ − L = {SPHERICAL_H_TYPED}", "expression", SPHERICAL,
         _misstated("H = θ̇ ∂L/∂θ̇ + φ̇ ∂L/∂θ̇ − L", "H")),
        (SPHERICAL_H, f"H = p_φ θ̇ + p_θ φ̇ − L = {SPHERICAL_H_TYPED}", "expression", SPHERICAL,
         _misstated("H = p_φ θ̇ + p_θ φ̇ − L", "H")),
        (L_PENDULUM, f"L = θ̇ ∂L/∂θ̇ + H = {L_TYPED}", "lagrangian", PENDULUM, _misstated("L = θ̇ ∂L/∂θ̇ + H", "L")),
        # a sum that is one energy once L or H is put in: H = T − L is V, L = H − T is V (before, Correct)
        (SPHERICAL_H, f"H = T − L = {SPHERICAL_H_TYPED}", "expression", SPHERICAL, _misstated("H = T − L", "H")),
        (SPHERICAL_H, f"H = L + V = {SPHERICAL_H_TYPED}", "expression", SPHERICAL, _misstated("H = L + V", "H")),
        (L_PENDULUM, f"L = H − T = {L_TYPED}", "lagrangian", PENDULUM, _misstated("L = H − T", "L")),
        # judged by its values, not multiplied out: a power of a sum in it costs nothing
        (HOOP_H, f"H = (p_θ θ̇ + L + T + V + m + R + g)^40 − L = {HOOP_H_TYPED}", "expression",
         {**HOOP_NOT_ENERGY, "given": {"p_theta": "m R^2 thetadot"}},
         _misstated("H = (p_θ θ̇ + L + T + V + m + R + g)^40 − L", "H")),
        # a momentum as −∂L/∂φ̇, ∂V/∂φ̇ (zero) or 2 ∂L/∂φ̇: before, Correct
        (SPHERICAL_P_PHI, "p_φ = −∂L/∂φ̇ = m l² sin²θ φ̇", "expression", SPHERICAL, _misstated("p_φ = −∂L/∂φ̇", "p_φ")),
        (SPHERICAL_P_PHI, "p_φ = ∂V/∂φ̇ = m l² sin²θ φ̇", "expression", SPHERICAL, _misstated("p_φ = ∂V/∂φ̇", "p_φ")),
        (SPHERICAL_P_PHI, "p_φ = 2 ∂L/∂φ̇ = m l² sin²θ φ̇", "expression", SPHERICAL, _misstated("p_φ = 2 ∂L/∂φ̇", "p_φ")),
    ],
)  # fmt: skip
def test_a_wrong_definition_on_the_way_to_a_right_value_goes_to_a_person(expected, submitted, kind, options, first):
    verdict = compare(expected, submitted, kind=kind, **options)
    assert (verdict.status, verdict.score, verdict.diagnosis) == ("undecided", 1.0, "statement_for_a_person"), verdict
    assert verdict.feedback[0] == first


@pytest.mark.parametrize(
    ("expected", "submitted", "kind", "options"),
    [
        (L_PENDULUM, f"L = T − V ⇒ L = {L_TYPED}", "lagrangian", PENDULUM),
        (L_PENDULUM, f"Using L = T − V we get L = {L_TYPED}", "lagrangian", PENDULUM),
        (L_PENDULUM, f"L = K − U = {L_TYPED}", "lagrangian", PENDULUM),
        (SPHERICAL_H, f"H = Σ p q̇ − L = {SPHERICAL_H_TYPED}", "expression", SPHERICAL),
        (SPHERICAL_H, rf"H = \sum_j p_j \dot q_j - L = {SPHERICAL_H_TYPED}", "expression", SPHERICAL),
        (SPHERICAL_H, f"H = E = {SPHERICAL_H_TYPED}", "expression", SPHERICAL),
        (SPHERICAL_H, f"H = T + V = {SPHERICAL_H_TYPED}", "expression", SPHERICAL),  # the energy, where it is
        (SPHERICAL_H, f"H = 2T − L = {SPHERICAL_H_TYPED}", "expression", SPHERICAL),  # T + V, where H is that
        (SPHERICAL_H, f"E = 2T − L = {SPHERICAL_H_TYPED}", "expression", SPHERICAL),
        (L_PENDULUM, f"L = 2T − E = {L_TYPED}", "lagrangian", PENDULUM),
        (L_PENDULUM, f"L = H − 2V = {L_TYPED}", "lagrangian", PENDULUM),
        (SPHERICAL_H, f"H = L + 2V = {SPHERICAL_H_TYPED}", "expression", SPHERICAL),
        (HOOP_H, f"H = Σ p q̇ − L = {HOOP_H_TYPED}", "expression", HOOP_NOT_ENERGY),  # where it is not too
        (SPHERICAL_P_PHI, "p_φ = ∂L/∂φ̇ = m l² sin²θ φ̇", "expression", SPHERICAL),
        (SPHERICAL_P_PHI, "p_φ = ∂T/∂φ̇ = m l² sin²θ φ̇", "expression", SPHERICAL),  # V has no φ̇ in it
        # a generalized force by its potential, as the prompt defines it: before, refused for its minus sign
        ("m g cos(theta) - k (r - l0)", "Q_r = −∂V/∂r = m g cos θ − k (r − l0)", "expression", ELASTIC),
        (
            "-m g r sin(theta)",
            r"Q_\theta = -\frac{\partial V}{\partial \theta} = -mgr\sin\theta",
            "expression",
            ELASTIC,
        ),
    ],
)
def test_a_right_definition_on_the_way_is_right(expected, submitted, kind, options):
    assert compare(expected, submitted, kind=kind, **options).status == "equivalent"


_HOOP_GIVEN = {"p_theta": "m R^2 thetadot"}
_SPHERICAL_GIVEN = {"p_theta": "m l^2 thetadot", "p_phi": "m l^2 sin(theta)^2 phidot"}


def _redefined(definition: str, name: str) -> str:
    return (
        f"Your answer defines `{definition}`, which is not the problem's {name}. Read with your definition put in"
        " place, it is right; a person will check this answer."
    )


@pytest.mark.parametrize(
    ("expected", "submitted", "options", "given", "status", "first"),
    [
        # a wrong momentum of the student's own makes a wrong H in it right: before, Correct
        (HOOP_H, "H = p_θ²/(2 m) − ½ m R² ω² sin²θ − m g R cos θ, where p_θ = m R θ̇", HOOP, _HOOP_GIVEN, "undecided",
         _redefined("p_θ = m R θ̇", "p_θ")),
        (HOOP_H, "With p_θ = m R θ̇: H = p_θ²/(2 m) − ½ m R² ω² sin²θ − m g R cos θ", HOOP, _HOOP_GIVEN, "undecided",
         _redefined("p_θ = m R θ̇", "p_θ")),
        (HOOP_H, "H = p²/(8 m R²) − ½ m R² ω² sin²θ − m g R cos θ, where p = 2 m R² θ̇", HOOP, _HOOP_GIVEN, "undecided",
         _redefined("p = 2 m R² θ̇", "p_θ")),
        (SPHERICAL_H, "With p_φ = m l² sin θ φ̇: H = p_θ²/(2 m l²) + p_φ²/(2 m l²) − m g l cos θ", SPHERICAL,
         _SPHERICAL_GIVEN, "undecided", _redefined("p_φ = m l² sin θ φ̇", "p_φ")),
        # where it is wrong either way, said so
        (HOOP_H, "H = p_θ²/m − ½ m R² ω² sin²θ − m g R cos θ, where p_θ = m R θ̇", HOOP, _HOOP_GIVEN, "not_equivalent",
         "Your answer defines `p_θ = m R θ̇`, which is not the problem's p_θ."),
    ],
)  # fmt: skip
def test_a_given_name_defined_otherwise_goes_to_a_person(expected, submitted, options, given, status, first):
    verdict = compare(expected, submitted, given=given, **options)
    assert verdict.status == status, verdict
    assert first in verdict.feedback, verdict


def _steps_left_out(steps: str) -> str:
    return f"Read without the step `{steps}`: a derivative written out is not checked; the last side was graded."


_HOOP_DEFINED = r"H = \dot\theta \frac{\partial L}{\partial \dot\theta} - L = "
_Q_THETA_TEX = r"Q_\theta = \mathbf F \cdot \frac{\partial \mathbf r}{\partial \theta} = -mgr\sin\theta"
_P_PHI_STEP = "∂/∂φ̇(½ m l² sin²θ φ̇²)"
# a chain through a partial derivative written out: before, each was refused ("`∂` is read only in the name …")
_TWO_H_LINES = "Your 2 lines, each `H = …`, were read as one chain, H = … = …: its last side was graded."
PARTIALS_IN_CHAIN = (
    # q̇ ∂L/∂q̇ is p_q q̇, and the definition is judged as H = p_θ θ̇ − L = … is
    (HOOP_H, f"H = θ̇ ∂L/∂θ̇ − L = {HOOP_H_TYPED}", HOOP_NOT_ENERGY, "equivalent", ("Correct.",)),
    (HOOP_H, _HOOP_DEFINED + HOOP_H_TYPED, HOOP_NOT_ENERGY, "equivalent", ("Correct.",)),
    (HOOP_H, "H = θ̇ ∂L/∂θ̇ − L = m R² θ̇² − m g R cos θ", HOOP_NOT_ENERGY, "not_equivalent",
     ("A term differs: the velocity-dependent term in θ̇² has the wrong factor.",
      "A term is missing: a term in sin(θ).")),
    (SPHERICAL_H, f"H = θ̇ ∂L/∂θ̇ + φ̇ ∂L/∂φ̇ − L = {SPHERICAL_H_TYPED}", SPHERICAL, "equivalent", ("Correct.",)),
    (SPHERICAL_H, rf"H = \sum_j \dot q_j \frac{{\partial L}}{{\partial \dot q_j}} - L = {SPHERICAL_H_TYPED}", SPHERICAL,
     "equivalent", ("Correct.",)),
    # a wrong definition, + L or a coordinate's term left out, goes to a person
    (HOOP_H, f"H = θ̇ ∂L/∂θ̇ + L = {HOOP_H_TYPED}", HOOP_NOT_ENERGY, "undecided", (_misstated("H = θ̇ ∂L/∂θ̇ + L", "H"),)),
    (SPHERICAL_H, f"H = θ̇ ∂L/∂θ̇ − L = {SPHERICAL_H_TYPED}", SPHERICAL, "undecided",
     (_misstated("H = θ̇ ∂L/∂θ̇ − L", "H"),)),
    # any other ∂ in a step of H's chain: the step that defines H is not checked, so a person checks it
    (HOOP_H, f"H = θ̇ ∂L/∂θ − L = {HOOP_H_TYPED}", HOOP_NOT_ENERGY, "undecided",
     (_steps_left_out("θ̇ ∂L/∂θ − L"), "Its last side is right; a person will check the step that defines it.")),
    # a derivative worked out on the way: the step is left out, and the last side graded
    (SPHERICAL_P_PHI, f"p_φ = {_P_PHI_STEP} = m l² sin²θ φ̇", SPHERICAL, "equivalent",
     ("Correct.", _steps_left_out(_P_PHI_STEP))),
    (SPHERICAL_P_PHI, f"p_φ = {_P_PHI_STEP} = m l² φ̇", SPHERICAL, "not_equivalent",
     ("Your answer depends on l, m and φ̇ as the right answer does, but not on θ: check how your answer depends"
      " on θ.", _steps_left_out(_P_PHI_STEP))),
    # a definition before it is still judged: p_φ = ∂L/∂φ is not what p_φ is
    (SPHERICAL_P_PHI, f"p_φ = ∂L/∂φ = {_P_PHI_STEP} = m l² sin²θ φ̇", SPHERICAL, "undecided",
     (_misstated("p_φ = ∂L/∂φ", "p_φ"), _steps_left_out(_P_PHI_STEP))),
    (Q_THETA[0], "Q_θ = F·∂r/∂θ = −m g r sin θ", Q_THETA[1], "equivalent", ("Correct.", _steps_left_out("F·∂r/∂θ"))),
    (Q_THETA[0], "Q_θ = F·∂r/∂θ = m g r sin θ", Q_THETA[1], "not_equivalent",
     ("The overall sign is wrong.", _steps_left_out("F·∂r/∂θ"))),
    # a chain of more sides after the step, read side by side as any is
    (HOOP_H, f"H = θ̇ ∂L/∂θ̇ − L = {_HOOP_WORKED} = {HOOP_H_TYPED}", HOOP_NOT_ENERGY, "equivalent",
     ("Correct.", "Your answer has 3 sides after the name, each the same; the last was graded.")),
    (HOOP_H, f"H = θ̇ ∂L/∂θ̇ + L = {_HOOP_WORKED} = {HOOP_H_TYPED}", HOOP_NOT_ENERGY, "undecided",
     (_misstated("H = θ̇ ∂L/∂θ̇ + L", "H"),)),
    (SPHERICAL_P_PHI, f"p_φ = {_P_PHI_STEP} = ½ m l² · 2 φ̇ = m l² sin²θ φ̇", SPHERICAL, "undecided",
     ("Your last side is right, but side 1 does not say the same: a person will decide which is your answer.",
      _steps_left_out(_P_PHI_STEP))),
    (Q_THETA[0], _Q_THETA_TEX, Q_THETA[1], "equivalent",
     ("Correct.", _steps_left_out(r"\mathbf F \cdot \frac{\partial \mathbf r}{\partial \theta}"))),
    # the definition on a line of its own, then the value: read as the chain on one line is (before, refused
    # for its ∂; and cut at `;`, H = θ̇ p_θ − L and H = … apart, told that L is undefined)
    (HOOP_H, f"H = θ̇ ∂L/∂θ̇ − L\nH = {HOOP_H_TYPED}", HOOP_NOT_ENERGY, "equivalent", ("Correct.", _TWO_H_LINES)),
    (HOOP_H, f"H = θ̇ ∂L/∂θ̇ − L; H = {HOOP_H_TYPED}", HOOP_NOT_ENERGY, "equivalent", ("Correct.", _TWO_H_LINES)),
    (HOOP_H, f"H = θ̇ ∂L/∂θ̇ + L\nH = {HOOP_H_TYPED}", HOOP_NOT_ENERGY, "undecided",
     (_misstated("H = θ̇ ∂L/∂θ̇ + L", "H"), _TWO_H_LINES)),
)  # fmt: skip


@pytest.mark.parametrize(("expected", "submitted", "options", "status", "feedback"), PARTIALS_IN_CHAIN)
def test_a_chain_through_a_partial_derivative_written_out_grades_its_last_side(
    expected, submitted, options, status, feedback
):
    verdict = compare(expected, submitted, **options)
    assert (verdict.status, verdict.feedback) == (status, feedback)


_THREE_SIDES = "Your answer has 3 sides after the name, each the same; the last was graded."
_THREE_LINES = "Your 3 lines, each `H = …`, were read as one chain, H = … = …: its last side was graded."
# H's definition, its working and its value, a line each: before, read as typed, L undefined, and not right
LINES_OF_A_LONGER_CHAIN = (
    (f"H = p_θ θ̇ − L\nH = {_HOOP_WORKED}\nH = {HOOP_H_TYPED}", "equivalent", ("Correct.", _THREE_SIDES, _THREE_LINES)),
    (f"H = p_θ θ̇ + L\nH = {_HOOP_WORKED}\nH = {HOOP_H_TYPED}", "undecided",
     (_misstated("H = p_θ θ̇ + L", "H"), _THREE_LINES)),
    (f"H = p_θ θ̇ − L\nH = {_HOOP_WORKED}\nH = m R² θ̇²", "not_equivalent",
     ("Not equivalent to the expected answer.", "Your answer has 3 sides after the name; the last was graded as your"
      " answer.", _THREE_LINES)),
)  # fmt: skip


@pytest.mark.parametrize(("submitted", "status", "feedback"), LINES_OF_A_LONGER_CHAIN)
def test_lines_of_a_chain_with_working_between_its_definition_and_value_are_one_chain(submitted, status, feedback):
    verdict = compare(HOOP_H, submitted, given={"p_theta": "m R^2 thetadot"}, **HOOP_NOT_ENERGY)
    assert (verdict.status, verdict.feedback) == (status, feedback)


def _defined_before(words: str, definition: str) -> str:
    return f"Read without the words `{words}`, with your `{definition}` put in place in the formula after it."


_LABELLED_F = "Your answer is labelled f, but the quantity asked for is ω."
_LABELLED_F_RIGHT = f"{_LABELLED_F} Read as ω, it is right; a person will check which you meant."


def _others_left_out(label: str, name: str) -> str:
    return f"The line that defines `{label}` was not graded: {name} is what is asked for here."


def _multiple(label: str, name: str) -> str:
    return (
        f"{_others_left_out(label, name)} But your answer gives `{label}` as a number times {name}, which may be your"
        f" answer instead. Graded on your line for {name}, it is right; a person will check which you meant."
    )


def _momentum_spelt(definition: str) -> str:
    return (
        f"Your answer defines `{definition}`, which is not the problem's p_θ, then uses p_θ itself. Read with the"
        " problem's p_θ, it is right; a person will check which you meant."
    )


def _not_graded_p(label: str) -> str:
    return f"The line that defines `{label}` was not graded: H is what is asked for here."


def _unused(words: str, definition: str) -> str:
    return (
        f"Read without the words `{words}`: your `{definition}` is not used in the formula after it, which was"
        " graded as it stands."
    )


_HOOP_IN_P = "p_θ²/(2 m R²) − ½ m R² ω² sin²θ − m g R cos θ"
_HOOP_P = "p_θ = m R² θ̇"
# a sentence that defines a name, then the answer in it: before, refused for its colon, or its words undefined
DEFINITION_BEFORE = (
    (HOOP_H, f"With {_HOOP_P}: H = {_HOOP_IN_P}", HOOP_NOT_ENERGY, "equivalent",
     ("Correct.", _defined_before("With", _HOOP_P))),
    (HOOP_H, f"With {_HOOP_P}, H = {_HOOP_IN_P}", HOOP_NOT_ENERGY, "equivalent",
     ("Correct.", _defined_before("With", _HOOP_P))),
    (HOOP_H, f"Using {_HOOP_P}, we have H = {_HOOP_IN_P}", HOOP_NOT_ENERGY, "equivalent",
     ("Correct.", _defined_before("Using … we have", _HOOP_P))),
    (HOOP_H, f"With {_HOOP_P}: {_HOOP_IN_P}", HOOP_NOT_ENERGY, "equivalent",
     ("Correct.", _defined_before("With", _HOOP_P))),
    # the student's own definition, wrong, is put in place as theirs: wrong
    (HOOP_H, f"With p_θ = m R θ̇: H = {_HOOP_IN_P}", HOOP_NOT_ENERGY, "not_equivalent",
     ("A term differs: the velocity-dependent term in θ̇² has the wrong factor.",
      _defined_before("With", "p_θ = m R θ̇"))),
    (HOOP_H, f"With {_HOOP_P}: H = p_θ²/(m R²) − ½ m R² ω² sin²θ − m g R cos θ", HOOP_NOT_ENERGY, "not_equivalent",
     ("A term differs: the velocity-dependent term in θ̇² has the wrong factor.", _defined_before("With", _HOOP_P))),
    ("sqrt(g/l)", "With ω₀ = √(g/l): ω = ω₀", PENDULUM, "equivalent",
     ("Correct.", _defined_before("With", "ω₀ = √(g/l)"))),
    # a name the formula does not use is working, not put in place: the note says so, and not that it was
    (EOM_PENDULUM, "With L = ½ m l² θ̇² + m g l cos θ: m l² θ̈ = −m g l sin θ", {**PENDULUM, "kind": "equation"},
     "equivalent",
     ("Correct.", "The line that defines `L` was read as your working, not as your answer.")),
    # the name defined by its square, as a frequency is: before, `Using` and ω₀ undefined, and wrong
    ("sqrt(g/l)", "Using ω₀² = g/l, ω = ω₀", PENDULUM, "equivalent",
     ("Correct.", _defined_before("Using", "ω₀² = g/l"))),
    (EOM_PENDULUM, "With ω² = g/l: θ̈ + ω² sin θ = 0", {**PENDULUM, "kind": "equation"}, "equivalent",
     ("Correct.", _defined_before("With", "ω² = g/l"))),
    (EOM_PENDULUM, "With ω² = l/g: θ̈ + ω² sin θ = 0", {**PENDULUM, "kind": "equation"}, "not_equivalent",
     ("A term differs: the term in sin(θ) has the wrong factor.", _defined_before("With", "ω² = l/g"))),
    # `Let` defines as `With` does, and a full stop then `Then` hands over: before, `:` refused, or Let undefined
    ("sqrt(g/l)", "Let x = g: ω = √(x/l)", PENDULUM, "equivalent", ("Correct.", _defined_before("Let", "x = g"))),
    ("sqrt(g/l)", "Let x = g: ω = √(x/(2 l))", PENDULUM, "not_equivalent",
     ("Your answer is off by a constant factor: missing a factor √2?", _defined_before("Let", "x = g"))),
    ("sqrt(g/l)", "Let x = g. ω = √(x/l)", PENDULUM, "equivalent", ("Correct.", _defined_before("Let", "x = g"))),
    ("sqrt(g/l)", "Let x = 2g. ω = √(x/l)", PENDULUM, "not_equivalent",
     ("Your answer is off by a constant factor: missing a factor 1/√2?", _defined_before("Let", "x = 2g"))),
    ("sqrt(g/l)", "Let ω₀² = g/l, then ω = ω₀", PENDULUM, "equivalent",
     ("Correct.", _defined_before("Let … then", "ω₀² = g/l"))),
    ("sqrt(g/l)", "Let ω₀² = l/g, then ω = ω₀", PENDULUM, "not_equivalent",
     ("Your answer depends on g and l, but not as the right answer does: check how it depends on each.",
      _defined_before("Let … then", "ω₀² = l/g"))),
    # a sentence of its own that names the value, as one alone is read: before, `Let`, `The`… undefined
    ("sqrt(g/l)", "Let ω₀² = g/l. The frequency is ω = ω₀", PENDULUM, "equivalent",
     ("Correct.", _defined_before("Let … The frequency is", "ω₀² = g/l"))),
    ("sqrt(g/l)", "Let ω₀² = l/g. The frequency is ω = ω₀", PENDULUM, "not_equivalent",
     ("Your answer depends on g and l, but not as the right answer does: check how it depends on each.",
      _defined_before("Let … The frequency is", "ω₀² = l/g"))),
    # the value labelled by its square, as the words say: before, `squared` kept the sentence from being read
    ("sqrt(g/l)", "Let ω₀² = g/l. The frequency squared is ω² = ω₀²", _OMEGA, "equivalent",
     ("Correct.", _defined_before("Let … The frequency squared is", "ω₀² = g/l"))),
    ("sqrt(g/l)", "Let ω₀² = l/g. The frequency squared is ω² = ω₀²", _OMEGA, "not_equivalent",
     ("Your answer depends on g and l, but not as the right answer does: check how it depends on each.",
      _defined_before("Let … The frequency squared is", "ω₀² = l/g"))),
    ("sqrt(g/l)", "Let ω₀² = g/l; the frequency is ω = −ω₀", PENDULUM, "not_equivalent",
     ("The overall sign is wrong.", _defined_before("Let … the frequency is", "ω₀² = g/l"))),
    ("sqrt(g/l)", "Let ω₀² = g/l; the frequency is ω = ω₀", PENDULUM, "equivalent",
     ("Correct.", _defined_before("Let … the frequency is", "ω₀² = g/l"))),
    # the asked quantity defined, then another's value handed over to: that value is the answer, the definition
    # put in (before, the definition of ω₀ was graded, and f = 2 ω₀ left out, right)
    ("sqrt(g/l)", "Let ω₀² = g/l. The frequency is f = 2 ω₀", _OMEGA, "not_equivalent",
     ("Your answer is off by a constant factor: missing a factor 1/2?",
      _defined_before("Let … The frequency is", "ω₀² = g/l"), "Your answer is labelled f, but the quantity asked for"
      " is ω.")),
    ("sqrt(g/l)", "With ω₀² = g/l: f = 2 ω₀", _OMEGA, "not_equivalent",
     ("Your answer is off by a constant factor: missing a factor 1/2?", _defined_before("With", "ω₀² = g/l"),
      "Your answer is labelled f, but the quantity asked for is ω.")),
    ("sqrt(g/l)", "Let ω₀² = g/l. The frequency is ω = ω₀", _OMEGA, "equivalent",
     ("Correct.", _defined_before("Let … The frequency is", "ω₀² = g/l"))),
    ("sqrt(g/l)", "Let ω₀² = g/l. The frequency is f = ω₀", _OMEGA, "undecided",
     ("Your answer is labelled f, but the quantity asked for is ω. Read as ω, it is right; a person will check"
      " which you meant.", _defined_before("Let … The frequency is", "ω₀² = g/l"))),
    # so too after the value, in a `where` clause: the value before it is the answer (before, the clause was graded,
    # and f = 2 ω₀ left out, right; f = 2 ω₀ with ω₀² = g/(4 l), right as ω, wrong)
    ("sqrt(g/l)", "f = 2 ω₀, where ω₀² = g/l", _OMEGA, "not_equivalent",
     ("Your answer is off by a constant factor: missing a factor 1/2?", _LABELLED_F)),
    ("sqrt(g/l)", "f = 2 ω₀, where ω₀² = g/(4 l)", _OMEGA, "undecided", (_LABELLED_F_RIGHT,)),
    ("sqrt(g/l)", "f = 2 ω₀ with ω₀² = g/l", _OMEGA, "not_equivalent",
     ("Your answer is off by a constant factor: missing a factor 1/2?", _LABELLED_F)),
    ("sqrt(g/l)", "f = ω₀, where ω₀² = g/l", _OMEGA, "undecided", (_LABELLED_F_RIGHT,)),
    # with no word that says which, a line that gives another quantity as a number times the asked one may be
    # the answer, with the asked one's line its definition: for a person (before, right); T = 2π/ω₀ is no such
    ("sqrt(g/l)", "ω₀ = √(g/l); T = 5 ω₀", _OMEGA, "undecided", (_multiple("T", "ω₀"),)),
    ("sqrt(g/l)", "ω₀ = √(g/l); T = 2π/ω₀", _OMEGA, "equivalent", ("Correct.", _others_left_out("T", "ω₀"))),
    ("sqrt(g/l)", "f = 2 ω₀; ω₀² = g/l", _OMEGA, "undecided", (_multiple("f", "ω₀"),)),
    ("sqrt(g/l)", "ω = √(g/l); f = ω/(2π)", _OMEGA, "equivalent", ("Correct.", _others_left_out("f", "ω"))),
    ("sqrt(g/l)", "ω₀ = √(l/g); T = 5 ω₀", _OMEGA, "not_equivalent",
     ("Your answer depends on g and l, but not as the right answer does: check how it depends on each.",
      _others_left_out("T", "ω₀"))),
    (HOOP_H, f"Let {_HOOP_P}. Then H = {_HOOP_IN_P}", HOOP_NOT_ENERGY, "equivalent",
     ("Correct.", _defined_before("Let … Then", _HOOP_P))),
    (HOOP_H, f"Let p_θ = m R θ̇. Then H = {_HOOP_IN_P}", HOOP_NOT_ENERGY, "not_equivalent",
     ("A term differs: the velocity-dependent term in θ̇² has the wrong factor.",
      _defined_before("Let … Then", "p_θ = m R θ̇"))),
    # a name of the student's own the formula does not use: the formula alone, said so (before, M undefined)
    (ATWOOD_A, "With M = m₁ + m₂: ẍ = g (m₁ − m₂)/(m₁ + m₂)", ATWOOD, "equivalent",
     ("Correct.", _unused("With", "M = m₁ + m₂"))),
    (ATWOOD_A, "With M = m₁ + m₂: ẍ = g (m₁ + m₂)/(m₁ − m₂)", ATWOOD, "not_equivalent",
     ("Your answer depends on g as the right answer does, but on m₁ and m₂ in another way: check how your answer"
      " depends on m₁ and m₂.", _unused("With", "M = m₁ + m₂"))),
    (ATWOOD_A, "Let M = m₁ + m₂. Then ẍ = g (m₁ − m₂)/(m₁ + m₂)", ATWOOD, "equivalent",
     ("Correct.", _unused("Let … Then", "M = m₁ + m₂"))),
    (ATWOOD_A, "Let M = m₁ + m₂. Then ẍ = g (m₁ − m₂)/(m₁ − m₂)", ATWOOD, "not_equivalent",
     ("Your answer depends on g as the right answer does, but not on m₁ and m₂: check how your answer depends on"
      " m₁ and m₂.", _unused("Let … Then", "M = m₁ + m₂"))),
    # several names defined, after `,` or `and`, as after the formula: before, the second's colon refused
    ("m xddot + b xdot + k x = 0", "With γ = b/(2m), ω0² = k/m: ẍ + 2γẋ + ω0² x = 0", {**DAMPED, "kind": "equation"},
     "equivalent", ("Correct.", _defined_before("With", "γ = b/(2m) and ω0² = k/m"))),
    ("m xddot + b xdot + k x = 0", "With γ = b/(2m), ω0² = k/(2m): ẍ + 2γẋ + ω0² x = 0",
     {**DAMPED, "kind": "equation"}, "not_equivalent",
     ("A term differs: the term in x has the wrong factor.", _defined_before("With", "γ = b/(2m) and ω0² = k/(2m)"))),
    ("m xddot + b xdot + k x = 0", "With γ = b/(2m) and ω0² = k/m: ẍ + 2γẋ + ω0² x = 0",
     {**DAMPED, "kind": "equation"}, "equivalent",
     ("Correct.", _defined_before("With", "γ = b/(2m) and ω0² = k/m"))),
    ("m xddot + b xdot + k x = 0", "With γ = b/m and ω0² = k/m: ẍ + 2γẋ + ω0² x = 0", {**DAMPED, "kind": "equation"},
     "not_equivalent", ("A term differs: the velocity-dependent term in ẋ has the wrong factor.",
                        _defined_before("With", "γ = b/m and ω0² = k/m"))),
    ("m xddot + b xdot + k x = 0", "Let γ = b/(2m), and ω0² = k/m, then ẍ + 2γẋ + ω0² x = 0",
     {**DAMPED, "kind": "equation"}, "equivalent",
     ("Correct.", _defined_before("Let … then", "γ = b/(2m) and ω0² = k/m"))),
    ("m xddot + b xdot + k x = 0", "Let γ = b/(2m), and ω0² = −k/m, then ẍ + 2γẋ + ω0² x = 0",
     {**DAMPED, "kind": "equation"}, "not_equivalent",
     ("A term differs: the term in x has the wrong sign.", _defined_before("Let … then", "γ = b/(2m) and ω0² = −k/m"))),
    # a name the part asks for is no name of the student's own: a second value of the asked quantity (before,
    # right, the definition called unused)
    (ATWOOD_A, "Let a = g. Then ẍ = g (m₁ − m₂)/(m₁ + m₂)", {**ATWOOD, "name": ["xddot", "a", "a_1"]},
     "not_equivalent", ("Your answer uses `a`, which this problem does not define (it uses g, m₁, m₂, x). Write your"
      " answer in those, or say what it stands for: …, where a = ….",)),
    ("sqrt(g/l)", "With w = 2 √(g/l): ω = √(g/l)", {**PENDULUM, "name": ["omega", "omega_0", "w", "w_0"]},
     "not_equivalent", ("Your answer uses `ω` and `w`, which this problem does not define (it uses g, l, m, θ). Write"
      " your answer in those, or say what each stands for: …, where ω = ….",)),
    # the momentum the formula uses, spelt another way, is no name of the student's own: wrong, it goes to a
    # person (before, right, the definition called unused); right, the line is working
    (HOOP_H, f"Let P_θ = 2 m R² θ̇. Then H = {_HOOP_IN_P}", {**HOOP_NOT_ENERGY, "given": {"p_theta": "m R^2 thetadot"}},
     "undecided", (_momentum_spelt("P_θ = 2 m R² θ̇"), _not_graded_p("P_θ"), "Read with the problem's own meaning of"
     " `p_θ`.")),
    (HOOP_H, f"Let P = 2 m R² θ̇. Then H = {_HOOP_IN_P}", {**HOOP_NOT_ENERGY, "given": {"p_theta": "m R^2 thetadot"}},
     "undecided", (_momentum_spelt("P = 2 m R² θ̇"), _not_graded_p("P"), "Read with the problem's own meaning of"
     " `p_θ`.")),
    (HOOP_H, f"Let p_1 = m R² θ̇. Then H = {_HOOP_IN_P}", {**HOOP_NOT_ENERGY, "given": {"p_theta": "m R^2 thetadot"}},
     "equivalent", ("Correct.", _not_graded_p("p₁"), "Read with the problem's own meaning of `p_θ`.")),
    (SPHERICAL_P_PHI, "Let p_φ = 0. Then m l² sin²θ φ̇", {**SPHERICAL, "name": ["p_phi"]}, "invalid",
     ("The first item of your answer has no `=`. An expression may be followed only by definitions of the names it"
      " uses (…, where v = l θ̇); in a list of equations, every item needs an `=`.",)),
)  # fmt: skip


@pytest.mark.parametrize(("expected", "submitted", "options", "status", "feedback"), DEFINITION_BEFORE)
def test_a_sentence_that_defines_a_name_before_the_answer_puts_it_in_place(
    expected, submitted, options, status, feedback
):
    verdict = compare(expected, submitted, **options)
    assert (verdict.status, verdict.feedback) == (status, feedback)


def _chain(words: str, definition: str) -> str:
    return f"Read without the words `{words}`, as the chain `{definition} = …`: its last side was graded."


@pytest.mark.parametrize(
    ("submitted", "status", "feedback"),
    [
        # that H is not T + V here, said beside it: before, read as typed, T, V and `not` undefined, wrong
        (f"H = {HOOP_H_TYPED} (not T + V)", "undecided", (_for_a_person("(not T + V)"),)),
        ("H = 1/2 m R^2 θ̇^2 + 1/2 m R^2 ω^2 sin^2θ − m g R cos θ (not T + V)", "not_equivalent",
         ("A term differs: the term in sin(θ) has the wrong sign.",
          "Read without the words `(not T + V)`: the formula is what is graded.")),
    ],
)  # fmt: skip
def test_a_remark_in_brackets_that_h_is_not_t_plus_v_goes_to_a_person(submitted, status, feedback):
    verdict = compare(HOOP_H, submitted, **HOOP_NOT_ENERGY)
    assert (verdict.status, verdict.score, verdict.feedback) == (status, float(status == "undecided"), feedback)


DAMPED_EOM = ("m xddot + b xdot + k x = 0", {"kind": "equation", **DAMPED})


@pytest.mark.parametrize(
    ("expected", "submitted", "status", "feedback"),
    [
        # a remark that closes the answer, with commas, signs or numbers: before, refused (a comma, `<`, `>`
        # not understood, something missing before `=`) or read as typed
        (Q_THETA, "−m g r sin θ (a torque, N·m)", "undecided", (_for_a_person("(a torque, N·m)"),)),
        ((HOOP_H, HOOP_NOT_ENERGY), f"{HOOP_H_TYPED} (= E, conserved)", "undecided",
         (_for_a_person("(= E, conserved)"),)),
        (DAMPED_EOM, "m ẍ + b ẋ + k x = 0 (underdamped if b² < 4mk)", "undecided",
         (_for_a_person("(underdamped if b² < 4mk)"),)),
        ((ATWOOD_A, MASSES), "(m1 − m2) g/(m1 + m2), downward for m1 when m1 > m2", "undecided",
         (_for_a_person(", downward for m1 when m1 > m2"),)),
        (("sqrt(g/l)", PENDULUM), "√(g/l), the period over 2π", "undecided", (_for_a_person(", the period over 2π"),)),
        ((L_PENDULUM, {"kind": "lagrangian", **PENDULUM}), "½ m l² θ̇² + m g l cos θ, which is T − V", "undecided",
         (_for_a_person(", which is T − V"),)),
        # a wrong formula stays wrong, the remark said to be read past
        ((HOOP_H, HOOP_NOT_ENERGY), "1/2 m R^2 θ̇^2 + 1/2 m R^2 ω^2 sin^2θ − m g R cos θ (= E, conserved)",
         "not_equivalent", ("A term differs: the term in sin(θ) has the wrong sign.",
                            "Read without the words `(= E, conserved)`: the formula is what is graded.")),
        (DAMPED_EOM, "m ẍ + b ẋ − k x = 0 (underdamped if b² < 4mk)", "not_equivalent",
         ("A term differs: the term in x has the wrong sign.",
          "Read without the words `(underdamped if b² < 4mk)`: the formula is what is graded.")),
    ],
)  # fmt: skip
def test_a_remark_with_commas_or_signs_that_closes_the_answer_goes_to_a_person(expected, submitted, status, feedback):
    (answer, setting) = expected
    verdict = compare(answer, submitted, **setting)
    assert (verdict.status, verdict.score, verdict.feedback) == (status, float(status == "undecided"), feedback)


@pytest.mark.parametrize(
    ("submitted", "feedback"),
    [
        # before, each of these was Correct
        (f"H = T + V = {HOOP_H_TYPED}", (_misstated("H = T + V", "H"),)),
        (f"H = E = {HOOP_H_TYPED}", (_misstated("H = E", "H"),)),
        (f"Since H = T + V, H = {HOOP_H_TYPED}", (_misstated("H = T + V", "H"), _chain("Since", "H = T + V"))),
        (f"The Hamiltonian H = T + V is {HOOP_H_TYPED}",
         (_misstated("H = T + V", "H"), _chain("The Hamiltonian … is", "H = T + V"))),
        (f"H = T + V ⇒ H = {HOOP_H_TYPED}", (_misstated("H = T + V", "H"),)),
        # 2T − L is T + V, whatever T and V are: the same claim
        (f"H = 2T − L = {HOOP_H_TYPED}", (_misstated("H = 2T − L", "H"),)),
        (f"H = 2 T - L = {HOOP_H_TYPED}", (_misstated("H = 2 T - L", "H"),)),
        # the energies as the label: not H's here
        (f"T + V = {HOOP_H_TYPED}",
         ("Your answer is labelled T + V, but the quantity asked for is H. Read as H, it is right; a person will"
          " check which you meant.",)),
    ],
)  # fmt: skip
def test_where_the_part_says_h_is_not_the_energy_h_said_to_be_t_plus_v_goes_to_a_person(submitted, feedback):
    verdict = compare(HOOP_H, submitted, **HOOP_NOT_ENERGY)
    assert (verdict.status, verdict.score, verdict.feedback) == ("undecided", 1.0, feedback), verdict


P_THETA = {**PENDULUM, "name": "p_theta"}


@pytest.mark.parametrize(
    ("expected", "submitted", "kind", "options", "status", "feedback"),
    [
        # before, each was wrong: `Since`, `Using`, T and V undefined, or `:` refused
        (L_PENDULUM, f"Since L = T − V, L = {L_TYPED}", "lagrangian", PENDULUM, "equivalent",
         ("Correct.", _chain("Since", "L = T − V"))),
        (L_PENDULUM, f"The Lagrangian L = T − V is {L_TYPED}", "lagrangian", PENDULUM, "equivalent",
         ("Correct.", _chain("The Lagrangian … is", "L = T − V"))),
        (L_PENDULUM, f"With L = T − V: L = {L_TYPED}", "lagrangian", PENDULUM, "equivalent",
         ("Correct.", _chain("With", "L = T − V"))),
        (L_PENDULUM, f"Using L = T − V, L = {L_TYPED}", "lagrangian", PENDULUM, "equivalent",
         ("Correct.", _chain("Using", "L = T − V"))),
        (L_PENDULUM, f"Let L = T − V: L = {L_TYPED}", "lagrangian", PENDULUM, "equivalent",
         ("Correct.", _chain("Let", "L = T − V"))),
        (L_PENDULUM, f"Let L = T − V. Then L = {L_TYPED}", "lagrangian", PENDULUM, "equivalent",
         ("Correct.", _chain("Let … Then", "L = T − V"))),
        (L_PENDULUM, f"Let L = T + V. Then L = {L_TYPED}", "lagrangian", PENDULUM, "undecided",
         (_misstated("L = T + V", "L"), _chain("Let … Then", "L = T + V"))),
        (L_PENDULUM, f"Let L = T − V. L = {L_TYPED}", "lagrangian", PENDULUM, "equivalent",
         ("Correct.", _chain("Let", "L = T − V"))),
        (L_PENDULUM, "Let L = T − V. L = 1/2 m l^2 θ̇^2 − m g l cos θ", "lagrangian", PENDULUM, "not_equivalent",
         ("It looks like you wrote L = T + V; the Lagrangian is L = T − V.", _chain("Let", "L = T − V"))),
        (L_PENDULUM, f"Since L = T − V, we have L = {L_TYPED}", "lagrangian", PENDULUM, "equivalent",
         ("Correct.", _chain("Since … we have", "L = T − V"))),
        (L_PENDULUM, f"Given L = K − U we get {L_TYPED}", "lagrangian", PENDULUM, "equivalent",
         ("Correct.", _chain("Given … we get", "L = K − U"))),
        (L_PENDULUM, f"Since L = T − V, L(θ, θ̇) = {L_TYPED}", "lagrangian", PENDULUM, "equivalent",
         ("Correct.", _chain("Since", "L(θ, θ̇) = T − V"))),  # named as the prompt names it
        (L_PENDULUM, f"Since L = T − V, L = {L_TYPED} (taking V = 0 at the pivot)", "lagrangian", PENDULUM,
         "equivalent", ("Correct.", _chain("Since", "L = T − V"), _words("(taking V = 0 at the pivot)"))),
        (SPHERICAL_H, f"Since H = Σ p q̇ − L, H = {SPHERICAL_H_TYPED}", "expression", SPHERICAL, "equivalent",
         ("Correct.", _chain("Since", "H = Σ p q̇ − L"))),
        (SPHERICAL_H, rf"The Hamiltonian H = \sum_j p_j \dot q_j - L is {SPHERICAL_H_TYPED}", "expression",
         SPHERICAL, "equivalent", ("Correct.", _chain("The Hamiltonian … is", r"H = \sum_j p_j \dot q_j - L"))),
        (SPHERICAL_P_PHI, "Since p_φ = ∂L/∂φ̇, p_φ = m l² sin²θ φ̇", "expression", SPHERICAL, "equivalent",
         ("Correct.", _chain("Since", "p_φ = ∂L/∂φ̇"))),
        ("m l^2 thetadot", "Since p_θ = ∂L/∂θ̇, p_θ = m l² θ̇", "expression", P_THETA, "equivalent",
         ("Correct.", _chain("Since", "p_θ = ∂L/∂θ̇"))),
        # Σ p q̇ − L written out over the coordinates: before, wrong, `Since` and L undefined
        (HOOP_H, f"Since H = p_θ θ̇ − L, H = {HOOP_H_TYPED}", "expression", HOOP_NOT_ENERGY, "equivalent",
         ("Correct.", _chain("Since", "H = p_θ θ̇ − L"))),
        (HOOP_H, f"Using H = θ̇ p_θ − L, we have H = {HOOP_H_TYPED}", "expression", HOOP_NOT_ENERGY, "equivalent",
         ("Correct.", _chain("Using … we have", "H = θ̇ p_θ − L"))),
        (SPHERICAL_H, f"Since H = p_θ θ̇ + p_φ φ̇ − L, H = {SPHERICAL_H_TYPED}", "expression", SPHERICAL,
         "equivalent", ("Correct.", _chain("Since", "H = p_θ θ̇ + p_φ φ̇ − L"))),
        # ∂L/∂θ̇ is read as p_θ, and shown as typed: not as the name put in for it
        (HOOP_H, f"Since H = θ̇ ∂L/∂θ̇ − L, H = {HOOP_H_TYPED}", "expression", HOOP_NOT_ENERGY, "equivalent",
         ("Correct.", _chain("Since", "H = θ̇ ∂L/∂θ̇ − L"))),
        (HOOP_H, rf"Since {_HOOP_DEFINED[:-3]}, H = {HOOP_H_TYPED}", "expression", HOOP_NOT_ENERGY, "equivalent",
         ("Correct.", _chain("Since", _HOOP_DEFINED[:-3]))),
        # a wrong value after a right definition: the value's own feedback, never `Since` undefined
        (L_PENDULUM, "Since L = T − V, L = 1/2 m l^2 θ̇^2 − m g l cos θ", "lagrangian", PENDULUM, "not_equivalent",
         ("It looks like you wrote L = T + V; the Lagrangian is L = T − V.", _chain("Since", "L = T − V"))),
        (L_PENDULUM, "The Lagrangian L = T − V is 1/2 m l θ̇^2 + m g l cos θ", "lagrangian", PENDULUM,
         "not_equivalent", ("A term differs: the velocity-dependent term in θ̇² has the wrong factor.",
                            _chain("The Lagrangian … is", "L = T − V"))),
        (SPHERICAL_P_PHI, "Since p_φ = ∂L/∂φ̇, p_φ = m l² φ̇", "expression", SPHERICAL, "not_equivalent",
         ("Your answer depends on l, m and φ̇ as the right answer does, but not on θ: check how your answer depends"
          " on θ.",
          _chain("Since", "p_φ = ∂L/∂φ̇"))),
        (L_PENDULUM, "Since L = T − V, L = 1/2 m v^2 + m g l cos θ", "lagrangian", PENDULUM, "not_equivalent",
         ("Your answer uses `v`, which this problem does not define (it uses g, l, m, θ). Write your answer in"
          " those, or say what it stands for: …, where v = ….",)),  # the value's own name, not `Since`
    ],
)  # fmt: skip
def test_a_definition_said_in_a_sentence_before_the_value_is_read_as_the_chain(
    expected, submitted, kind, options, status, feedback
):
    verdict = compare(expected, submitted, kind=kind, **options)
    # a right value after a wrong definition keeps its credit until a person has read it
    right = status in ("equivalent", "undecided")
    assert (verdict.status, verdict.score, verdict.feedback) == (status, float(right), feedback)


_P_PHI_WORKED = "½ m l² sin²θ · 2φ̇"
_H_WORKED = "m l² θ̇² + m l² sin²θ φ̇² − ½ m l² (θ̇² + sin²θ φ̇²) − m g l cos θ"


@pytest.mark.parametrize(
    ("expected", "submitted", "status", "feedback"),
    [
        # a definition the parser reads only in a chain, then the working: before, each was refused
        (SPHERICAL_P_PHI, f"p_φ = ∂L/∂φ̇ = {_P_PHI_WORKED} = m l² sin²θ φ̇", "equivalent",
         ("Correct.", "Your answer has 3 sides after the name, each the same; the last was graded.")),
        (SPHERICAL_H, f"H = Σ p q̇ − L = {_H_WORKED} = {SPHERICAL_H_TYPED}", "equivalent",
         ("Correct.", "Your answer has 3 sides after the name, each the same; the last was graded.")),
        # the momentum named by its definition, then the working: before, refused
        (SPHERICAL_P_PHI, f"∂L/∂φ̇ = {_P_PHI_WORKED} = m l² sin²θ φ̇", "equivalent",
         ("Correct.", "Your answer has 2 sides after the name, each the same; the last was graded.")),
        (SPHERICAL_P_PHI, f"∂L/∂φ̇ = {_P_PHI_WORKED} = m l² φ̇", "not_equivalent",
         ("Your answer depends on l, m and φ̇ as the right answer does, but not on θ: check how your answer depends"
          " on θ.", "Your answer has 2 sides after the name; the last was graded as your answer.")),
        # the working's sides are numbered as written, the definition first
        (SPHERICAL_P_PHI, "p_φ = ∂L/∂φ̇ = ½ m l² sin²θ φ̇ = m l² sin²θ φ̇", "undecided",
         ("Your last side is right, but side 2 does not say the same: a person will decide which is your answer.",)),
        (SPHERICAL_P_PHI, f"p_φ = ∂L/∂φ̇ = {_P_PHI_WORKED} = m l² φ̇", "not_equivalent",
         ("Your answer depends on l, m and φ̇ as the right answer does, but not on θ: check how your answer depends"
          " on θ.", "Your answer has 3 sides after the name; the last was graded as your answer.")),
        (SPHERICAL_P_PHI, f"p_φ = ∂L/∂φ = {_P_PHI_WORKED} = m l² sin²θ φ̇", "undecided",
         (_misstated("p_φ = ∂L/∂φ", "p_φ"),
          "Your answer has 3 sides after the name; the last was graded as your answer.")),
    ],
)  # fmt: skip
def test_a_definition_then_working_then_the_value_is_graded_by_the_last_side(expected, submitted, status, feedback):
    verdict = compare(expected, submitted, kind="expression", **SPHERICAL)
    assert (verdict.status, verdict.feedback) == (status, feedback), verdict


@pytest.mark.parametrize(
    ("submitted", "status", "feedback"),
    [
        # before, the name at the end was graded as the value, undefined and wrong
        ("p_φ = m l² sin²θ φ̇ = L_z", "undecided",
         ("Your answer is labelled L_z, but the quantity asked for is p_φ. Read as p_φ, it is right; a person will"
          " check which you meant.", "Your answer has 2 sides after the name; the last was graded as your answer.")),
        ("p_φ = ∂L/∂φ̇ = m l² sin²θ φ̇ = L_z", "undecided",
         ("Your answer is labelled L_z, but the quantity asked for is p_φ. Read as p_φ, it is right; a person will"
          " check which you meant.", "Your answer has 3 sides after the name; the last was graded as your answer.")),
        ("p_φ = m l² φ̇ = L_z", "not_equivalent",
         ("Your answer depends on l, m and φ̇ as the right answer does, but not on θ: check how your answer depends"
          " on θ.", "Your answer is labelled L_z, but the quantity asked for is p_φ.",
          "Your answer has 2 sides after the name; the last was graded as your answer.")),
    ],
)  # fmt: skip
def test_a_chain_that_ends_in_a_name_of_its_own_names_the_value_again(submitted, status, feedback):
    verdict = compare(SPHERICAL_P_PHI, submitted, kind="expression", **SPHERICAL, name="p_phi")
    assert (verdict.status, verdict.feedback) == (status, feedback), verdict


L_TEX = r"\frac12 m l^2 \dot\theta^2 + m g l \cos\theta"


@pytest.mark.parametrize(
    ("submitted", "status", "score", "feedback"),
    [
        # TeX's inline mathematics in the sentence: before, `Since` was S·i·n·c·e, and T and V undefined
        (f"Since $L = T - V$, $L = {L_TEX}$", "equivalent", 1.0, ("Correct.", _chain("Since", "L = T - V"))),
        (f"Since $L = T - V$, L = {L_TYPED}", "equivalent", 1.0, ("Correct.", _chain("Since", "L = T - V"))),
        (f"Since L = T - V, $L = {L_TEX}$", "equivalent", 1.0, ("Correct.", _chain("Since", "L = T - V"))),
        (f"Since $L = T - V$, $L = {L_TEX.replace('+', '-')}$", "not_equivalent", 0.0,
         ("It looks like you wrote L = T + V; the Lagrangian is L = T − V.", _chain("Since", "L = T - V"))),
        # a wrong definition, in \(…\): before, `\(` was refused
        (rf"Since \(L = T + V\), \(L = {L_TEX}\)", "undecided", 1.0,
         (_misstated("L = T + V", "L"), _chain("Since", "L = T + V"))),
    ],
)  # fmt: skip
def test_a_sentence_with_its_mathematics_set_apart_in_tex_is_read_as_without_the_signs(
    submitted, status, score, feedback
):
    verdict = compare(L_PENDULUM, submitted, kind="lagrangian", **PENDULUM)
    assert (verdict.status, verdict.score, verdict.feedback) == (status, score, feedback), verdict


@pytest.mark.parametrize(
    ("expected", "submitted", "found", "status", "first"),
    [
        # words that change the meaning, or a condition: nothing found, read as typed
        (L_PENDULUM, f"L is not T + V, L = {L_TYPED}", False, "not_equivalent",
         "Your answer uses `T`, `V`, `is` and `not`, which this problem does not define (it uses g, l, m, θ)."),
        (L_PENDULUM, f"If L = T − V, L = {L_TYPED}", False, "not_equivalent",
         "Your answer uses `If`, `T` and `V`, which this problem does not define (it uses g, l, m, θ)."),
        (L_PENDULUM, f"Since L = T − V (not T + V), L = {L_TYPED}", False, "not_equivalent",
         "Your answer uses `Since`, `T`, `V` and `not`, which this problem does not define (it uses g, l, m, θ)."),
        (L_PENDULUM, f"Since L = T − V, not L = {L_TYPED}", False, "not_equivalent",
         "Your answer uses `L`, `Since`, `T`, `V` and `not`, which this problem does not define (it uses g, l, m,"
         " θ)."),
        (L_PENDULUM, f"Since L = T − V, the Hamiltonian is {L_TYPED}", False, "invalid",  # another quantity named
         "A comma is not understood here."),
        (L_PENDULUM, f"Since L = T − V, H = {L_TYPED}", False, "not_equivalent",  # another quantity's value
         "Your answer uses `H`, `L`, `Since`, `T` and `V`, which this problem does not define (it uses g, l, m, θ)."),
        ("thetaddot = -(g/l) theta", "If θ is small, θ̈ = −(g/l) θ", False, "invalid",  # a condition: as before
         "The first item of your answer has no `=`."),
        (EOM_PENDULUM, "Applying ∂L/∂θ = 0: m l² θ̈ + m g l sin θ = 0", False, "invalid",  # not Lagrange's equation
         "`:` is not something an answer can contain."),
        # found, but not read so: a definition we cannot judge, or two values for L (which is the answer?)
        (L_PENDULUM, f"Since L = 1/2 m l^2 θ̇^2 + m g l cos θ, L = {L_TYPED}", True, "not_equivalent",
         "Your answer uses `Since`, which this problem does not define (it uses g, l, m, θ)."),
        (L_PENDULUM, f"Since L = T − V, L = {L_TYPED}, L = 1/2 m l^2 θ̇^2 − m g l cos θ", True, "not_equivalent",
         "Your answer uses `Since`, `T` and `V`, which this problem does not define (it uses g, l, m, θ)."),
    ],
)  # fmt: skip
def test_a_sentence_that_may_change_the_definition_leaves_it_as_typed(expected, submitted, found, status, first):
    names, coords = ["g", "l", "m", "t", "theta"], ["theta"]
    assert bool(list(words.definition_then_formula(submitted, names, coords))) is found
    kind = "lagrangian" if expected == L_PENDULUM else "equation"
    verdict = compare(expected, submitted, kind=kind, **PENDULUM)
    assert verdict.status == status, verdict
    assert verdict.feedback[0].startswith(first), verdict


ROD = "1/6 m l^2 thetadot^2 + 1/2 m g l cos(theta)"  # a uniform rod pivoted at one end: I = m l²/3


@pytest.mark.parametrize(
    ("expected", "submitted", "kind", "feedback"),
    [
        (ROD, "0.1667 m l^2 thetadot^2 + 0.5 m g l cos(theta)", "lagrangian",
         "Your answer would be right with `0.1667` written exactly: it is a rounded decimal where an exact number"
         " belongs (a fraction, or one with π or a root)."),
        (ROD, "0.17 m l^2 thetadot^2 + 0.5 m g l cos(theta)", "lagrangian", "`0.17`"),  # rounded to two digits
        (ROD, "0.166 m l^2 thetadot^2 + 0.5 m g l cos(theta)", "lagrangian", "`0.166`"),  # or cut off
        ("pi/2 m g l", "1.57 m g l", "expression", "`1.57`"),
        ("sqrt(2)/2 m g l", "0.707 m g l", "expression", "`0.707`"),
        ("thetaddot = -(2/3) (g/l) sin(theta)", "thetaddot = -0.667 g sin(theta)/l", "equation", "`0.667`"),
        ("1/3 m l^2 thetadot^2 + 2/3 m g l", "0.33 m l^2 thetadot^2 + 0.67 m g l", "expression",
         "Your answer would be right with `0.33` and `0.67` written exactly: they are rounded decimals where exact"
         " numbers belong (fractions, or ones with π or roots)."),
    ],
)  # fmt: skip
def test_a_formula_right_but_for_a_rounded_decimal_is_told_so(expected, submitted, kind, feedback):
    # 0.1667 is not 1/6, as STACK holds too; but the physics is right, and that is what to say
    verdict = compare(expected, submitted, kind=kind, **PENDULUM)
    assert (verdict.status, verdict.score, verdict.diagnosis[:15]) == ("not_equivalent", 0.0, "rounded_decimal"), (
        verdict
    )
    assert feedback in verdict.feedback[0]


@pytest.mark.parametrize(
    ("expected", "submitted", "status"),
    [
        (ROD, "0.5 m l^2 thetadot^2 + 0.5 m g l cos(theta)", "not_equivalent"),  # 0.5 is exact: no rounding of 1/6
        (ROD, "0.2 m l^2 thetadot^2 + 0.5 m g l cos(theta)", "not_equivalent"),  # one digit says too little
        (ROD, "0.1667 m l thetadot^2 + 0.5 m g l cos(theta)", "not_equivalent"),  # wrong but for the rounding too
        (ROD, "0.1667 m l^2 thetadot^2 - 0.5 m g l cos(theta)", "not_equivalent"),
        (ROD, "0.19 m l^2 thetadot^2 + 0.5 m g l cos(theta)", "not_equivalent"),  # 3/16, no rounding of 1/6
        ("m g l", "1.5e-3 m g l", "not_equivalent"),  # a power of ten's decimal is no rounding
        (L_PENDULUM, "0.5 m l^2 thetadot^2 + 1.0 m g l cos(theta)", "equivalent"),  # exact decimals as before
    ],
)
def test_only_a_decimal_that_rounds_the_exact_number_is_told_it_is_rounded(expected, submitted, status):
    verdict = compare(expected, submitted, kind="lagrangian" if "thetadot" in expected else "expression", **PENDULUM)
    assert verdict.status == status, verdict
    assert "rounded" not in (verdict.diagnosis or "")


PERIOD_VALUES = {**PERIOD_PART, "name": ["T"], "values": {"l": 1.0, "g": 9.81}}  # as plane-pendulum.period


@pytest.mark.parametrize(
    ("submitted", "status", "feedback"),
    [
        # a number is judged within its tolerance: it was told an exact number belongs where it stands
        ("2.02", "not_equivalent", "Not within the accepted tolerance."),
        ("1.996", "not_equivalent", "Not within the accepted tolerance."),
        ("2.002", "equivalent", "Correct."),
        ("2.02 s", "not_equivalent", "Not within the accepted tolerance."),
        ("2.006 s", "equivalent", "Correct."),
        ("T = 2.02 s", "not_equivalent", "Not within the accepted tolerance."),
        ("T = 2.006 s", "equivalent", "Correct."),
    ],
)
def test_a_number_out_of_tolerance_is_told_so_not_that_it_is_rounded(submitted, status, feedback):
    verdict = compare(PERIOD, submitted, **PERIOD_VALUES)
    assert (verdict.status, verdict.feedback) == (status, (feedback,)), verdict


L_HOOP_TYPED = "1/2 m R^2 θ̇^2 + 1/2 m R^2 ω^2 sin^2θ + m g R cos θ"
HOOP_LAGRANGIAN_NOT_ENERGY = {"coords": ["theta"], "known": ["m", "R", "g", "omega"], "h_is_energy": False}


@pytest.mark.parametrize(
    ("submitted", "feedback"),
    [
        # before, each quoted the working as sympy prints it: `L = -H + 2*T`
        (f"L = 2T − H = {L_HOOP_TYPED}", (_misstated("L = 2T − H", "L"),)),
        (f"L=2T-H={L_HOOP_TYPED}", (_misstated("L=2T-H", "L"),)),
        # a later side of the chain, after its label: `L = -H + 2*T`
        (f"L = T − V = 2 T − H = {L_HOOP_TYPED}", (_misstated("L = 2 T − H", "L"),)),
        # as typed, in TeX too
        (rf"\mathcal{{L}} = 2T - H = {L_HOOP_TYPED}", (_misstated(r"\mathcal{L} = 2T - H", "L"),)),
    ],
)  # fmt: skip
def test_a_wrong_definition_is_quoted_as_the_student_typed_it(submitted, feedback):
    verdict = compare(L_HOOP, submitted, kind="lagrangian", **HOOP_LAGRANGIAN_NOT_ENERGY)
    assert (verdict.status, verdict.score, verdict.feedback) == ("undecided", 1.0, feedback), verdict


_HOOP_P_LINE = "p_θ = m R² θ̇"
_HOOP_H_LINE = "H = p_θ²/(2 m R²) − ½ m R² ω² sin²θ − m g R cos θ"


@pytest.mark.parametrize(
    ("submitted", "kind", "expected", "notes"),
    [
        # before, each named only H: p_θ's line was put into H's, and left out with it unsaid
        (f"L = {L_HOOP_TYPED}; {_HOOP_P_LINE}; {_HOOP_H_LINE}", "lagrangian", L_HOOP,
         ("The lines that define `H` and `p_θ` were not graded: L is what is asked for here.",)),
        (f"L = {L_HOOP_TYPED}\n{_HOOP_P_LINE}\n{_HOOP_H_LINE}", "lagrangian", L_HOOP,
         ("The lines that define `H` and `p_θ` were not graded: L is what is asked for here.",)),
        (f"L = {L_HOOP_TYPED}; {_HOOP_P_LINE}; H = p_θ θ̇ − L", "lagrangian", L_HOOP,
         ("The lines that define `H` and `p_θ` were not graded: L is what is asked for here.",)),
        (f"{_HOOP_P_LINE}; {_HOOP_H_LINE}; L = {L_HOOP_TYPED}", "lagrangian", L_HOOP,
         ("The lines that define `H` and `p_θ` were read as your working, not as your answer.",)),
        (f"{_HOOP_P_LINE}; {_HOOP_H_LINE}; R θ̈ = R ω² sin θ cos θ − g sin θ", "equation", HOOP_EOM,
         ("The lines that define `H` and `p_θ` were read as your working, not as your answer.",)),
        # a definition the graded line uses is put in place, not left out
        (f"v = R θ̇; L = ½ m v² + ½ m R² ω² sin²θ + m g R cos θ; {_HOOP_P_LINE}; {_HOOP_H_LINE}", "lagrangian",
         L_HOOP, ("The lines that define `H` and `p_θ` were not graded: L is what is asked for here.",)),
    ],
)  # fmt: skip
def test_a_definition_put_into_a_line_left_out_is_named_as_left_out(submitted, kind, expected, notes):
    verdict = compare(expected, submitted, kind=kind, **HOOP)
    assert (verdict.status, verdict.notes) == ("equivalent", notes), verdict


@pytest.mark.parametrize(
    ("expected", "submitted", "kind", "status", "feedback"),
    [
        # values for the problem's constants after a formula say where it will be used: left out (before, put
        # in, they made ω a number and its label undefined, and a right answer scored 0)
        ("sqrt(g/l)", "ω = √(g/l), where g = 9.81 m/s²", "expression", "equivalent",
         ("Correct.", "Read without the value you gave `g`: the formula is what is graded.")),
        ("sqrt(g/l)", "ω = √(g/l), with l = 1 m and g = 9.81 m/s^2", "expression", "equivalent",
         ("Correct.", "Read without the values you gave `g` and `l`: the formula is what is graded.")),
        ("sqrt(g/l)", "ω = √(l/g), where g = 9.81", "expression", "not_equivalent",
         ("Your answer depends on g and l, but not as the right answer does: check how it depends on each.",
          "Read without the value you gave `g`: the formula is what is graded.")),
        (L_PENDULUM, f"L = {L_PENDULUM}, where m = 1 kg", "lagrangian", "equivalent",
         ("Correct.", "Read without the value you gave `m`: the formula is what is graded.")),
        # a value for a coordinate is no constant's: as before
        ("sqrt(g/l)", "ω = √(g/l), where θ = 0.1", "expression", "not_equivalent",
         ("Your answer uses `ω`, which this problem does not define (it uses g, l, m, θ). Write your answer in those,"
          " or say what it stands for: …, where ω = ….",)),
    ],
)  # fmt: skip
def test_values_given_the_problems_constants_after_a_formula_are_left_out(expected, submitted, kind, status, feedback):
    verdict = compare(expected, submitted, kind=kind, **PENDULUM)
    assert (verdict.status, verdict.feedback) == (status, feedback), verdict
