"""Dimensional analysis of answers: what they are measured in, and what a student is told when
a wrong answer's units are wrong."""

from __future__ import annotations

from fractions import Fraction

import pytest
import sympy

from grader import AuthorError, compare
from grader.bank import default_bank_path, load_bank
from grader.grade import grade_answer
from grader.judge.setting import Setting
from grader.judge.units import Mixed, si, units_of
from grader.parse import TIME

PENDULUM = {
    "coords": ["theta"],
    "known": ["m", "g", "l"],
    "dimensions": {"theta": "angle", "m": "mass", "l": "length", "g": "acceleration"},
}
FALLING = {"coords": ["x", "y"], "known": ["g"], "dimensions": {"x": "length", "y": "length", "g": "acceleration"}}
SETTING = Setting.build(PENDULUM["coords"], PENDULUM["known"], dimensions=PENDULUM["dimensions"])
L_PENDULUM = "1/2 m l^2 thetadot^2 + m g l cos(theta)"
theta, velocity, acceleration, m, l, g = sympy.symbols("theta theta__1 theta__2 m l g")
t = TIME


def units(mass, length, time):
    return (Fraction(mass), Fraction(length), Fraction(time))


@pytest.mark.parametrize(
    ("expr", "expected"),
    [
        (m * l**2 * velocity**2 / 2 + m * g * l * sympy.cos(theta), units(1, 2, -2)),  # an energy
        (sympy.sqrt(g / l), units(0, 0, -1)),
        (2 * sympy.pi * sympy.sqrt(l / g), units(0, 0, 1)),
        (acceleration + g / l * sympy.sin(theta), units(0, 0, -2)),  # a dot divides by time
        (l * velocity * t, units(0, 1, 0)),  # t is a time
        (sympy.sqrt(l), units(0, Fraction(1, 2), 0)),
        (sympy.exp(-g * t**2 / l) * m, units(1, 0, 0)),
        (sympy.Integer(3), units(0, 0, 0)),
        (-m * g * sympy.sign(velocity), units(1, 1, -2)),  # friction: sign takes any quantity
        (sympy.Abs(l * velocity), units(0, 1, -1)),
    ],
)
def test_units_of_an_expression(expr, expected):
    assert units_of(expr, SETTING) == expected


@pytest.mark.parametrize(
    ("expr", "found", "function"),
    [
        (acceleration + g * theta, [units(0, 0, -2), units(0, 1, -2)], ""),
        (m * g * sympy.cos(theta) + m * l**2 * velocity**2, [units(1, 1, -2), units(1, 2, -2)], ""),
        (sympy.cos(l * theta), [units(0, 1, 0)], "cos"),
        (g**l, [units(0, 1, 0)], "power"),
        (1 + velocity, None, ""),  # a pure number beside 1/s
    ],
)
def test_terms_or_arguments_in_different_units_are_mixed(expr, found, function):
    with pytest.raises(Mixed) as mixed:
        units_of(expr, SETTING)
    assert mixed.value.function == function
    if found is not None:
        assert sorted(mixed.value.found) == sorted(found)


def test_a_symbol_without_a_dimension_makes_the_units_unknown():
    assert units_of(m * sympy.Symbol("k") + g * theta, SETTING) is None
    assert units_of(g * l, Setting.build(["theta"], ["g", "l"])) is None


@pytest.mark.parametrize(
    ("powers", "text"),
    [
        ((1, 2, -2), "kg·m²/s²"),
        ((0, 0, -1), "1/s"),
        ((0, 1, -2), "m/s²"),
        ((1, 0, 0), "kg"),
        ((-1, 0, -1), "1/(kg·s)"),
        ((0, Fraction(1, 2), 0), "m^(1/2)"),
        ((0, 0, 0), "no units (a pure number)"),
    ],
)
def test_units_are_shown_in_si(powers, text):
    assert si(units(*powers)) == text


@pytest.mark.parametrize(
    ("expected", "submitted", "kind", "diagnosis", "sentence"),
    [
        ("sqrt(g/l)", "sqrt(l/g)", "expression", "units_differ",
         "Your answer is measured in s, but the quantity asked for is measured in 1/s: check the dimensions of each"
         " factor."),
        ("sqrt(g/l)", "g/l", "expression", "units_differ",
         "Your answer is measured in 1/s², but the quantity asked for is measured in 1/s: check the dimensions of"
         " each factor."),
        ("thetaddot = -(g/l) theta", "θ̈ = -g θ", "equation", "units_mixed",
         "The terms of your equation are not all measured in the same units (1/s² and m/s²): terms that add up must"
         " have the same dimensions."),
        (L_PENDULUM, "1/2 m l θ̇^2 + m g l cos θ", "lagrangian", "units_mixed",
         "The terms of your answer are not all measured in the same units (kg·m/s² and kg·m²/s²): terms that add up"
         " must have the same dimensions."),
        (L_PENDULUM, "1/2 m l^2 θ̇^2 + m g l cos(l θ)", "lagrangian", "units_argument",
         "In your answer, `cos` is applied to a quantity measured in m: the argument of cos must be a pure number."),
        ("xddot = -g; yddot = -g", "ẍ = -g; ÿ = -x", "equations", "units_mixed",
         "The terms of your equation 2 are not all measured in the same units (m and m/s²): terms that add up"
         " must have the same dimensions."),
    ],
)  # fmt: skip
def test_a_wrong_answer_in_the_wrong_units_is_told_so_first(expected, submitted, kind, diagnosis, sentence):
    setting = FALLING if kind == "equations" else PENDULUM
    verdict = compare(expected, submitted, kind=kind, **setting)
    assert (verdict.status, verdict.diagnosis) == ("not_equivalent", diagnosis)
    assert verdict.feedback[0] == sentence
    assert len(verdict.feedback) >= 2  # the diagnosis it replaced follows
    without = compare(expected, submitted, kind=kind, **{**setting, "dimensions": {}})
    assert verdict.feedback[1:] == without.feedback


@pytest.mark.parametrize(
    ("expected", "submitted", "kind"),
    [
        (L_PENDULUM, "1/2 m l^2 θ̇^2 - m g l cos θ", "lagrangian"),  # T + V: the units are right
        ("sqrt(g/l)", "0", "expression"),  # zero has any units
        ("thetaddot = -(g/l) theta", "θ̈ = -(g/l) sin θ", "equation"),
        ("sqrt(g/l)", "sqrt(g/l)", "expression"),
    ],
)
def test_answers_in_the_right_units_are_not_told_about_units(expected, submitted, kind):
    verdict = compare(expected, submitted, kind=kind, **PENDULUM)
    assert not verdict.diagnosis or not verdict.diagnosis.startswith("units"), verdict
    assert verdict == compare(expected, submitted, kind=kind, **{**PENDULUM, "dimensions": {}})


def test_an_unknown_dimension_is_the_authors_error():
    with pytest.raises(AuthorError, match="dimension of 'l' is 'metres'"):
        compare("sqrt(g/l)", "1", **{**PENDULUM, "dimensions": {"l": "metres"}})


def test_the_bank_passes_its_dimensions_to_the_checker():
    problem = load_bank(default_bank_path())["plane-pendulum"]
    verdict = grade_answer(problem, problem.part("frequency"), "sqrt(l/g)")
    assert verdict.diagnosis == "units_differ"
    assert verdict.feedback[0].startswith("Your answer is measured in s, but")


PERIOD = "2*pi*sqrt(1/9.81)"  # seconds, for l = 1 m


@pytest.mark.parametrize(
    ("submitted", "status", "feedback", "read_as"),
    [
        ("2.006", "equivalent", ("Correct.",), "2.006"),  # a number alone is in the unit asked
        ("2.006 s", "equivalent", ("Correct.",), "2.006"),
        (r"2.006\,\mathrm{s}", "equivalent", ("Correct.",), "2.006"),
        ("2.006 seconds", "equivalent", ("Correct.",), "2.006"),
        ("2006 ms", "equivalent", ("Correct.", "Read as 2.006 s."), "2.006"),
        ("2.006 sec", "equivalent", ("Correct.",), "2.006"),  # seconds, not the secant
        ("2.006secs.", "equivalent", ("Correct.",), "2.006"),
        ("2006 msec", "equivalent", ("Correct.", "Read as 2.006 s."), "2.006"),
        ("0.03343 min", "equivalent", ("Correct.", "Read as 2.0058 s."), "2.0058"),
        ("3 min", "not_equivalent", ("Not within the accepted tolerance.", "Read as 180 s."), "180"),
        ("2.006 m", "not_equivalent", ("Your answer is in m, but the quantity asked for is measured in s.",),
         "1003*m/500"),
        ("2.006 s^2", "not_equivalent", ("Your answer is in s², but the quantity asked for is measured in s.",),
         "1003*s^2/500"),
        ("2.006 x", "invalid", ("A number is asked for here; your answer contains `x`.",), "1003*x/500"),
        # SI prefixes: before, 2.006 ns was read as 2.006 and words after it
        ("0.002006 ks", "equivalent", ("Correct.", "Read as 2.006 s."), "2.006"),
        ("2.006e6 μs", "equivalent", ("Correct.", "Read as 2.006 s."), "2.006"),
        ("2006000 us", "equivalent", ("Correct.", "Read as 2.006 s."), "2.006"),
        ("2.006 ns", "not_equivalent", ("Not within the accepted tolerance.", "Read as 2.006e-09 s."),
         "0.000000002006"),
        ("2.006 nm", "not_equivalent", ("Your answer is in m, but the quantity asked for is measured in s.",),
         "1003*nm/500"),
        # a measured value with its uncertainty: the value is graded
        ("2.006 ± 0.001 s", "equivalent", ("Correct.", "Read without its uncertainty, `± 0.001`: the value is what is"
         " graded."), "2.006"),
        ("T = (2006 +/- 1) ms", "equivalent", ("Correct.", "Read without its uncertainty, `± 1`: the value is what is"
         " graded.", "Read as 2.006 s."), "2.006"),
        ("2.1 \\pm 0.2", "not_equivalent", ("Not within the accepted tolerance.", "Read without its uncertainty,"
         " `± 0.2`: the value is what is graded."), "2.1"),
        ("2.006(5) s", "equivalent", ("Correct.", "Read without its uncertainty, `(5)`: the value is what is graded."),
         "2.006"),  # the concise form: not 2.006 × 5
        ("2.006 s ± 0.001 s", "equivalent", ("Correct.", "Read without its uncertainty, `± 0.001`: the value is what"
         " is graded."), "2.006"),
        ("2.006 ps", "not_equivalent", ("Not within the accepted tolerance.", "Read as 2.006e-12 s."),
         "0.000000000002006"),  # every prefix is a unit: none is a word left out
        ("200.6 cs", "equivalent", ("Correct.", "Read as 2.006 s."), "2.006"),
        # with a unit typed, the number is not asked about another unit ("in ks?" for 2.006 ms)
        ("2.006 ms", "not_equivalent", ("Not within the accepted tolerance.", "Read as 0.002006 s."), "0.002006"),
        ("2006", "not_equivalent", ("Not within the accepted tolerance. Is your number in ms? The answer is asked"
         " in s.",), "2006"),
        ("2.006 s = 2006 ms", "equivalent", ("Correct.", "Graded your final value, `2006 ms`; the working before it"
         " is not graded.", "Read as 2.006 s."), "2.006"),  # not 2.006 times a name s
        # in a sentence, or in per cent: before, refused
        ("The period is 2.006 ± 0.001 s.", "equivalent", ("Correct.", "Graded the number `2.006 s`; the words around"
         " it are not graded.", "Read without its uncertainty, `± 0.001`: the value is what is graded."), "2.006"),
        ("2.006 s ± 0.05%", "equivalent", ("Correct.", "Read without its uncertainty, `± 0.05%`: the value is what is"
         " graded."), "2.006"),
        ("2.106 s ± 0.05%", "not_equivalent", ("Not within the accepted tolerance.", "Read without its uncertainty,"
         " `± 0.05%`: the value is what is graded."), "2.106"),
        ("2.006 ± 0.001 ± 0.002", "invalid", ("`±` is not something an answer can contain.",),
         "2.006 ± 0.001 ± 0.002\n      ^"),
        # the letter x for ×, before a power of ten: before, 2006·x·10⁻³, refused, and 2.006x10^0 right only as
        # 2.006·x₁₀⁰, so that 2.006x10^3 was refused
        ("2006 x 10^-3 s", "equivalent", ("Correct.",), "2.006"),
        ("2006X10^-3 s", "equivalent", ("Correct.",), "2.006"),
        ("2006x10^-3", "equivalent", ("Correct.",), "2.006"),
        ("2006 x 10^-2 s", "not_equivalent", ("Not within the accepted tolerance.",), "20.06"),
        ("2.006x10^3 s", "not_equivalent", ("Not within the accepted tolerance.",), "2006"),
        # how the number was rounded, after it: before, refused for the digit in the remark
        ("2.006 s, to 4 figures", "equivalent",
         ("Correct.", "Graded the number `2.006 s`; what follows it (`to 4 figures`) is not graded."), "2.006"),
        ("2.5 s, to 4 figures", "not_equivalent", ("Not within the accepted tolerance.",
         "Graded the number `2.5 s`; what follows it (`to 4 figures`) is not graded."), "2.5"),
        ("2.01 s to 3 s.f.", "equivalent",
         ("Correct.", "Graded the number `2.01 s`; what follows it (`to 3 s.f.`) is not graded."), "2.01"),
        # and without "to" (review-o: before, refused, `.p` read as attribute access)
        ("2.006 s (3 d.p.)", "equivalent",
         ("Correct.", "Graded the number `2.006 s`; what follows it (`(3 d.p.)`) is not graded."), "2.006"),
        ("2.006 s, 4 s.f.", "equivalent",
         ("Correct.", "Graded the number `2.006 s`; what follows it (`4 s.f.`) is not graded."), "2.006"),
        ("2.006 s (3dp)", "equivalent",
         ("Correct.", "Graded the number `2.006 s`; what follows it (`(3dp)`) is not graded."), "2.006"),
        ("2.006 s, accurate to 3 decimal places", "equivalent",
         ("Correct.", "Graded the number `2.006 s`; what follows it (`accurate to 3 decimal places`) is not graded."),
         "2.006"),
        ("2.5 s (3 d.p.)", "not_equivalent", ("Not within the accepted tolerance.",
         "Graded the number `2.5 s`; what follows it (`(3 d.p.)`) is not graded."), "2.5"),
    ],
)  # fmt: skip
def test_a_number_may_carry_the_unit_it_is_asked_in(submitted, status, feedback, read_as):
    verdict = compare(PERIOD, submitted, kind="number", rtol=0.005, unit="s")
    assert (verdict.status, verdict.feedback, verdict.read_as) == (status, feedback, read_as)


LEFT_OUT = "Graded `{}`, your value in s; the rest of your answer (`{}`) is not graded."


@pytest.mark.parametrize(
    ("submitted", "status", "feedback", "read_as"),
    [
        # before, graded at the last statement, f, and told it was in 1/s; or refused
        ("T = 2.006 s, f = 0.498 Hz", "equivalent", ("Correct.", LEFT_OUT.format("T = 2.006 s", "f = 0.498 Hz")),
         "2.006"),
        ("T = 2.006 s; f = 0.498 Hz", "equivalent", ("Correct.", LEFT_OUT.format("T = 2.006 s", "f = 0.498 Hz")),
         "2.006"),
        ("T = 2.006 s (f = 0.498 Hz)", "equivalent", ("Correct.", LEFT_OUT.format("T = 2.006 s", "f = 0.498 Hz")),
         "2.006"),
        ("f = 0.498 Hz, T = 2.006 s", "equivalent", ("Correct.", LEFT_OUT.format("T = 2.006 s", "f = 0.498 Hz")),
         "2.006"),
        ("ω = √(9.81) = 3.13 rad/s\nT = 2π/ω = 2.006 s", "equivalent",
         ("Correct.", LEFT_OUT.format("T = 2π/ω = 2.006 s", "ω = √(9.81) = 3.13 rad/s")), "2.006"),
        ("T = 2π√(l/g) = 2.006 s, l = 1 m, g = 9.81 m/s^2", "equivalent",
         ("Correct.", LEFT_OUT.format("T = 2π√(l/g) = 2.006 s", "l = 1 m, g = 9.81 m/s^2")), "2.006"),
        # a wrong value in the unit asked stays wrong
        ("T = 2.1 s, f = 0.498 Hz", "not_equivalent",
         ("Not within the accepted tolerance.", LEFT_OUT.format("T = 2.1 s", "f = 0.498 Hz")), "2.1"),
        ("f = 0.498 Hz; T = 2.1 s", "not_equivalent",
         ("Not within the accepted tolerance.", LEFT_OUT.format("T = 2.1 s", "f = 0.498 Hz")), "2.1"),
        # two values that may be in the unit asked: which is the answer is not for the checker to say
        ("T = 2.006 s, T = 3 s", "not_equivalent", ("Not within the accepted tolerance.", "Graded your final value,"
         " `3 s`; the working before it is not graded."), "3"),
    ],
)  # fmt: skip
def test_of_values_stated_side_by_side_the_one_in_the_parts_unit_is_graded(submitted, status, feedback, read_as):
    verdict = compare(PERIOD, submitted, kind="number", rtol=0.005, unit="s")
    assert (verdict.status, verdict.feedback, verdict.read_as) == (status, feedback, read_as)


def test_a_count_has_no_uncertainty():
    assert compare("3", "3 ± 1", kind="integer").status == "invalid"


def test_sec_is_the_secant_where_no_unit_is_asked_for():
    assert compare("2", "2 sec", kind="number").status == "invalid"  # sec needs an argument
    assert compare("1 + 1/cos(1)", "1 + sec 1", kind="number", unit="s").status == "equivalent"


def test_without_a_unit_a_number_with_one_is_for_a_person():
    verdict = compare(PERIOD, "2.006 s", kind="number", rtol=0.005)
    assert (verdict.status, verdict.diagnosis) == ("invalid", "not_a_number")


def test_a_compound_unit_converts_each_factor():
    assert compare("9.81", "981 cm/s^2", kind="number", unit="m/s^2").status == "equivalent"
    assert compare("9.81", "0.00981 km/s^2", kind="number", unit="m/s^2").status == "equivalent"
    assert compare("3.13", "3.13 rad/s", kind="number", unit="1/s").status == "equivalent"


OMEGA, FREQUENCY = "sqrt(9.81)", "sqrt(9.81)/(2*pi)"  # a pendulum of 1 m: ω = 3.13 rad/s, f = 0.498 Hz
CYCLES = "Read as {}: a cycle is 2π rad, so 1 Hz is 2π rad/s (ω = 2πf)."


@pytest.mark.parametrize(
    ("expected", "unit", "submitted", "status", "feedback"),
    [
        # ω's number with f's unit, and f's with ω's: both SI 1/s, and both wrong
        (OMEGA, "rad/s", "3.13 Hz", "not_equivalent",
         ("Not within the accepted tolerance.", CYCLES.format("19.6664 rad/s"))),
        (FREQUENCY, "Hz", "0.498 rad/s", "not_equivalent",
         ("Not within the accepted tolerance.", CYCLES.format("0.0792592 Hz"))),
        # the same rate in the other unit
        (OMEGA, "rad/s", "0.498 Hz", "equivalent", ("Correct.", CYCLES.format("3.12903 rad/s"))),
        (FREQUENCY, "Hz", "3.13 rad/s", "equivalent", ("Correct.", CYCLES.format("0.498155 Hz"))),
        (FREQUENCY, "hertz", "3.13 rad/s", "equivalent", ("Correct.", CYCLES.format("0.498155 hertz"))),
        # 1/s says neither: read as the part's unit, as it stands
        (OMEGA, "rad/s", "3.13 s^-1", "equivalent", ("Correct.",)),
        (FREQUENCY, "Hz", "0.498 s^-1", "equivalent", ("Correct.",)),
        (OMEGA, "1/s", "3.13 Hz", "equivalent", ("Correct.",)),
        (OMEGA, "1/s", "3.13 rad/s", "equivalent", ("Correct.",)),
        # a number alone is in the part's unit; right in the other, it is asked about
        (OMEGA, "rad/s", "0.498", "not_equivalent",
         ("Not within the accepted tolerance. Is your number in Hz? The answer is asked in rad/s.",)),
        (FREQUENCY, "Hz", "3.13", "not_equivalent",
         ("Not within the accepted tolerance. Is your number in rad/s? The answer is asked in Hz.",)),
        (OMEGA, "1/s", "0.498", "not_equivalent", ("Not within the accepted tolerance.",)),
    ],
)  # fmt: skip
def test_hz_and_rad_per_s_are_a_cycle_apart(expected, unit, submitted, status, feedback):
    verdict = compare(expected, submitted, kind="number", rtol=0.005, unit=unit)
    assert (verdict.status, verdict.feedback) == (status, feedback)


def test_a_unit_we_cannot_read_is_the_authors_error():
    with pytest.raises(AuthorError, match="unit 'furlong' is not a product of powers of the units we know"):
        compare("2", "2", kind="number", unit="furlong")
    with pytest.raises(AuthorError, match="unit '2 s'"):
        compare("2", "2", kind="number", unit="2 s")


@pytest.mark.parametrize(
    ("submitted", "sentence"),
    [
        ("2006", "Not within the accepted tolerance. Is your number in ms? The answer is asked in s."),
        ("0.03343", "Not within the accepted tolerance. Is your number in min? The answer is asked in s."),
        ("3", "Not within the accepted tolerance."),  # no unit makes 3 s right
    ],
)
def test_a_number_right_in_another_unit_is_asked_about_its_unit(submitted, sentence):
    verdict = compare(PERIOD, submitted, kind="number", rtol=0.005, unit="s")
    assert (verdict.status, verdict.feedback) == ("not_equivalent", (sentence,))
    # without a unit nothing is known of other units
    assert compare(PERIOD, submitted, kind="number", rtol=0.005).feedback == ("Not within the accepted tolerance.",)


OMEGA = "sqrt(g/l)"
LEFT_OUT = "Read without its unit, `{}`: the formula is what is graded."


@pytest.mark.parametrize(
    ("submitted", "setting", "status", "feedback"),
    [
        # a formula, then its unit: the formula is graded, and the note says the unit was left out
        ("√(g/l) rad/s", PENDULUM, "equivalent", ("Correct.", LEFT_OUT.format("rad/s"))),
        ("ω = √(g/l) s^-1", PENDULUM, "equivalent", ("Correct.", LEFT_OUT.format("1/s"))),
        (r"\omega=\sqrt{\frac{g}{l}}\,\mathrm{rad/s}", PENDULUM, "equivalent", ("Correct.", LEFT_OUT.format("rad/s"))),
        (r"\sqrt{g/l}\;\text{s^{-1}}", PENDULUM, "equivalent", ("Correct.", LEFT_OUT.format("1/s"))),
        ("√(g/l) [rad/s]", {"coords": ["theta"], "known": ["m", "g", "l"]}, "equivalent",
         ("Correct.", LEFT_OUT.format("rad/s"))),
        ("2 √(g/l) Hz", PENDULUM, "not_equivalent",
         ("Your answer is off by a constant factor: missing a factor 1/2?", LEFT_OUT.format("Hz"))),
        # a unit that does not measure the quantity asked for, where the problem gives dimensions
        ("√(l/g) seconds", PENDULUM, "not_equivalent",
         ("Your answer is in s, which is not how the quantity asked for is measured: check its dimensions.",)),
        ("√(g/l) kg", PENDULUM, "not_equivalent",
         ("Your answer is in kg, which is not how the quantity asked for is measured: check its dimensions.",)),
        # a number with units, where a formula is asked for
        ("3.13 rad/s", PENDULUM, "not_equivalent",
         ("Your answer uses `rad` and `s`, which this problem does not define: units, it seems. A formula in the"
          " problem's own symbols is asked for here, and its units follow from theirs.",)),
    ],
)  # fmt: skip
def test_a_formula_may_be_followed_by_its_unit(submitted, setting, status, feedback):
    verdict = compare(OMEGA, submitted, **setting)
    assert (verdict.status, verdict.feedback) == (status, feedback)


FOR_A_PERSON = (
    "Your formula is labelled `{}`. Graded without its unit, it is right; but a frequency in Hz counts cycles and"
    " an angular frequency in rad/s radians, 2π apart (ω = 2πf). A person will check which you meant."
)


@pytest.mark.parametrize(
    ("expected", "submitted", "status", "feedback"),
    [
        # ω has no π in it: in Hz, √(g/l) is 2π too large, if the label is meant
        (OMEGA, "√(g/l) Hz", "undecided", (FOR_A_PERSON.format("Hz"),)),
        (OMEGA, "ω = √(g/l) hertz", "undecided", (FOR_A_PERSON.format("hertz"),)),
        # f = ω/2π has: in rad/s it is 2π too small
        ("sqrt(g/l)/(2 pi)", "√(g/l)/(2π) rad/s", "undecided", (FOR_A_PERSON.format("rad/s"),)),
        ("sqrt(g/l)/(2 pi)", "√(g/l)/(2π) Hz", "equivalent", ("Correct.", LEFT_OUT.format("Hz"))),
        ("sqrt(g/l)/(2 pi)", "√(g/l)/(2π) 1/s", "equivalent", ("Correct.", LEFT_OUT.format("1/s"))),
    ],
)
def test_a_formula_labelled_in_cycles_or_radians_the_other_one_counts_goes_to_a_person(
    expected, submitted, status, feedback
):
    verdict = compare(expected, submitted, **PENDULUM)
    assert (verdict.status, verdict.feedback) == (status, feedback)
    assert verdict.score == 1.0


@pytest.mark.parametrize("submitted", ["√(g/l) h", "√(g/l) + 3 s", "√(g/l) s"])
def test_a_single_letter_is_a_name_to_define_not_a_unit_to_leave_out(submitted):
    # m g h: h is the student's height sooner than hours, and a unit inside a sum is no unit of the answer
    verdict = compare(OMEGA, submitted, known=["m", "g", "l"], coords=["theta"])
    assert verdict.diagnosis == "undefined_symbol"


TORQUE = "-m g l sin(theta)"  # a generalized force conjugate to an angle: an energy, N·m


@pytest.mark.parametrize(
    ("submitted", "status", "unit"),
    [
        # a unit with a name of the problem's in it (m, the mass, for metres), which as read was one
        # product with the formula: the formula is graded, and the note says the unit was left out
        ("−m g l sin θ N·m", "equivalent", "N·m"),
        ("−m g l sin θ kg m^2/s^2", "equivalent", "kg·m²/s²"),
        ("−m g l sin θ (N m)", "equivalent", "N·m"),
        ("−m g l sin θ, N·m", "equivalent", "N·m"),  # the comma sets it apart, and is no list
        ("Q_θ = −m g l sin θ [J]", "equivalent", "J"),  # one letter, set apart by its bracket
        ("−m g sin θ N·m", "not_equivalent", "N·m"),
    ],
)
def test_a_unit_after_a_formula_may_hold_a_name_of_the_problems(submitted, status, unit):
    verdict = compare(TORQUE, submitted, **{**PENDULUM, "known": [*PENDULUM["known"], "Q_theta"]})
    assert verdict.status == status, verdict
    assert LEFT_OUT.format(unit) in verdict.feedback
    assert verdict.read_as == ("-g*l*m*sin(θ)" if status == "equivalent" else "-g*m*sin(θ)")


@pytest.mark.parametrize(
    ("submitted", "status", "feedback"),
    [
        # "in" and the unit: before, read past as words (Correct whatever the unit), or read as names
        ("√(g/l) in rad/s", "equivalent", ("Correct.", LEFT_OUT.format("rad/s"))),
        ("ω = √(g/l) in s^-1", "equivalent", ("Correct.", LEFT_OUT.format("1/s"))),
        ("√(g/l) (in 1/s)", "equivalent", ("Correct.", LEFT_OUT.format("1/s"))),
        ("√(g/l), in rad/s", "equivalent", ("Correct.", LEFT_OUT.format("rad/s"))),  # was refused: a comma
        (
            "√(g/l) in s",
            "not_equivalent",
            ("Your answer is in s, which is not how the quantity asked for is measured: check its dimensions.",),
        ),
        (
            "√(g/l) (in s)",
            "not_equivalent",
            ("Your answer is in s, which is not how the quantity asked for is measured: check its dimensions.",),
        ),
    ],
)
def test_a_unit_may_be_said_with_in(submitted, status, feedback):
    verdict = compare(OMEGA, submitted, **PENDULUM)
    assert (verdict.status, verdict.feedback) == (status, feedback), verdict


@pytest.mark.parametrize(
    "submitted",
    [
        "−m g l sin θ, m/s",
        "−m g l sin θ (N)",
        # said with "in"
        "−m g l sin θ, in N",
        "−m g l sin θ in m/s",
        # a unit that is the problem's name too (m, g): after "in", a unit; before, read past as words
        "−m g l sin θ, in m",
        "−m g l sin θ, in g",
        # prefixed, or spelled out, or a pressure
        "−m g l sin θ (in cm)",
        "−m g l sin θ, in kilograms",
        "−m g l sin θ, in Pa",
    ],
)
def test_a_unit_after_a_formula_that_measures_something_else_is_said_so(submitted):
    verdict = compare(TORQUE, submitted, **PENDULUM)
    assert (verdict.status, verdict.diagnosis) == ("not_equivalent", "formula_unit_differs"), verdict


@pytest.mark.parametrize(
    "submitted",
    [
        "−m g l sin θ (dimensionless)",
        "−m g l sin θ; dimensions: force",
        "−m g l sin θ, it has dimensions of energy",
        "−m g l sin θ, units of force",  # before, read past as words: Correct
        "−m g l sin θ, units of N",
        # the kind of quantity, said in a word: its dimensions in other words (before, Correct)
        "−m g l sin θ, it is a force",
        "−m g l sin θ (force)",
        "−m g l sin θ, an angle",
        "−m g l sin θ (torque)",
        "−m g l sin θ, which is a force",  # before, read past as Correct
        # in signs and symbols too: before, refused for a comma or a colon
        "−m g l sin θ; its dimensions are those of energy (torque), N·m",
        "Q_θ = −m g l sin θ. Dimensions: [M L² T⁻²]",
        "−m g l sin θ, units: N m",
    ],
)
def test_words_that_state_dimensions_are_for_a_person_to_read(submitted):
    # a prompt may ask for the dimensions too (generalized-forces.q-theta): before, read past as Correct
    verdict = compare(TORQUE, submitted, **PENDULUM)
    assert (verdict.status, verdict.diagnosis) == ("undecided", "words_for_a_person"), verdict


def _unit_letter(name: str) -> str:
    return (
        f"Your answer ends in `{name}`, which this problem does not define. If it is a unit, leave it out, or write it"
        f" in square brackets after the formula: … [{name}]. If it is a name of your own, say what it stands for: …,"
        f" where {name} = …."
    )


Q_R = ("m g cos(theta) - k (r - l0)", {"coords": ["r", "theta"], "known": ["m", "g", "k", "l0"], "name": "Q_r"})


@pytest.mark.parametrize(
    ("expected", "submitted", "name"),
    [
        # N may be a normal force and J a moment of inertia: not set apart, they are names still, not read past,
        # where no dimensions check them as units (or not N or J); but at the end, a unit's letter is said to be
        # one, and how to write it (before, only a name to define)
        ((TORQUE, {"coords": ["theta"], "known": ["m", "g", "l"]}), "−m g l sin θ J", "J"),
        (Q_R, "m g cos θ − k (r − l0) N", "N"),
        (Q_R, "(m g cos θ − k (r − l0)) N.", "N"),
        (Q_R, "m g cos θ − k (r − l0) W", "W"),
    ],
)
def test_a_lone_unit_letter_after_a_formula_is_said_to_be_a_name_or_a_unit(expected, submitted, name):
    answer, setting = expected
    verdict = compare(answer, submitted, **setting)
    assert (verdict.status, verdict.diagnosis) == ("not_equivalent", "undefined_unit_letter")
    assert verdict.feedback == (_unit_letter(name),)


_Q_R_DIMENSIONS = {"r": "length", "theta": "angle", "m": "mass", "g": "acceleration", "k": "force per length"}
Q_R_MEASURED = {**Q_R[1], "dimensions": {**_Q_R_DIMENSIONS, "l0": "length"}}
_NOT_MEASURED_SO = "Your answer is in {}, which is not how the quantity asked for is measured: check its dimensions."


@pytest.mark.parametrize(
    ("expected", "submitted", "status", "feedback"),
    [
        # newtons or joules alone after a formula, where the dimensions check them, as N m is read: before,
        # "Your answer ends in `N`, which this problem does not define"
        ((TORQUE, PENDULUM), "−m g l sin θ J", "equivalent", ("Correct.", LEFT_OUT.format("J"))),
        ((TORQUE, PENDULUM), "−m g sin θ J", "not_equivalent",
         ("Your answer is measured in kg·m/s², but the quantity asked for is measured in kg·m²/s²: check the"
          " dimensions of each factor.", "Your answer depends on g, m and θ as the right answer does, but not on l:"
          " check how your answer depends on l.", LEFT_OUT.format("J"))),
        ((TORQUE, PENDULUM), "−m g l sin θ N", "not_equivalent", (_NOT_MEASURED_SO.format("kg·m/s²"),)),
        ((Q_R[0], Q_R_MEASURED), "m g cos θ − k (r − l0) N", "equivalent", ("Correct.", LEFT_OUT.format("N"))),
        ((Q_R[0], Q_R_MEASURED), "m g cos θ + k (r − l0) N", "not_equivalent",
         ("A term differs: the term in r has the wrong sign.", LEFT_OUT.format("N"))),
        ((Q_R[0], Q_R_MEASURED), "m g cos θ − k (r − l0) J", "not_equivalent",
         (_NOT_MEASURED_SO.format("kg·m²/s²"),)),
    ],
)  # fmt: skip
def test_newtons_or_joules_alone_after_a_formula_are_its_unit_where_dimensions_check_it(
    expected, submitted, status, feedback
):
    answer, setting = expected
    verdict = compare(answer, submitted, **setting)
    assert (verdict.status, verdict.feedback) == (status, feedback)


@pytest.mark.parametrize(
    ("submitted", "unit"),
    [("½ m l² θ̇² + m g l cos θ (J)", "J"), ("½ m l² θ̇² + m g l cos θ, [kg m^2/s^2]", "kg·m²/s²"),
     ("½ m l² θ̇² + m g l cos θ joules", "joules")],
)  # fmt: skip
def test_a_lagrangian_may_be_followed_by_its_unit(submitted, unit):
    # a unit after a sum is its last term's as read: the end of the text is read as the unit
    verdict = compare(L_PENDULUM, submitted, kind="lagrangian", **PENDULUM)
    assert (verdict.status, verdict.feedback) == ("equivalent", ("Correct.", LEFT_OUT.format(unit))), verdict


NORMALIZATION = (
    "Your Lagrangian gives the right equations of motion, but it is a constant multiple of T − V; the"
    " convention L = T − V fixes the normalization."
)


@pytest.mark.parametrize(
    ("submitted", "feedback"),
    [
        # (T − V)/l: the dynamics, and a constant multiple's credit; but no energy, and it is said
        ("½ m l θ̇² + m g cos θ",
         ("Your answer is measured in kg·m/s², but the quantity asked for is measured in kg·m²/s²: check the"
          " dimensions of each factor.", NORMALIZATION)),
        # (T − V)/m and (T − V)/(m l²), per unit of mass or of inertia: so written on purpose, but still
        # no energy (before, only the normalization was said)
        ("1/2 l^2 θ̇^2 + g l cos θ",
         ("Your answer is measured in m²/s², but the quantity asked for is measured in kg·m²/s²: check the"
          " dimensions of each factor.", NORMALIZATION)),
        ("½ θ̇² + (g/l) cos θ",
         ("Your answer is measured in 1/s², but the quantity asked for is measured in kg·m²/s²: check the"
          " dimensions of each factor.", NORMALIZATION)),
        # a number's multiple is an energy: the normalization alone
        ("m l^2 θ̇^2 + 2 m g l cos θ",
         ("Your Lagrangian gives the right equations of motion, but it is 2 × (T − V); the convention"
          " L = T − V fixes the normalization.",)),
    ],
)  # fmt: skip
def test_a_lagrangians_multiple_that_is_no_energy_says_so_and_keeps_its_credit(submitted, feedback):
    verdict = compare("1/2 m l^2 thetadot^2 + m g l cos(theta)", submitted, kind="lagrangian", **PENDULUM)
    assert (verdict.status, verdict.score, verdict.feedback) == ("not_equivalent", 0.5, feedback), verdict


DIMENSIONS_LEFT_OUT = "Read without its dimensions, `{}`: the formula is what is graded."


# a part whose prompt asks for more than the formula: "Compute Q_θ. What are its dimensions?"
ASKS_MORE = {**PENDULUM, "name": "Q_theta", "asks_more": True}
Q_TYPED = "Q_θ = −m g l sin θ"


def _words_for_a_person(words):
    return (
        f"Your answer says `{words}` beside the formula. The formula was graded on its own; a person will read"
        " the words against it.",
    )


@pytest.mark.parametrize(
    ("submitted", "status", "score", "feedback"),
    [
        # any words beside the formula, whatever they say: before, each of these was Correct
        (f"{Q_TYPED}, measured in newtons", "undecided", 1.0, _words_for_a_person(", measured in newtons")),
        (f"{Q_TYPED}, expressed in N", "undecided", 1.0, _words_for_a_person(", expressed in N")),
        (f"{Q_TYPED}, given in newtons", "undecided", 1.0, _words_for_a_person(", given in newtons")),
        (f"{Q_TYPED}, Newtons", "undecided", 1.0, _words_for_a_person(", Newtons")),
        (f"{Q_TYPED}, SI unit: N", "undecided", 1.0, _words_for_a_person(", SI unit: N")),
        (f"{Q_TYPED}, in the same units as work", "undecided", 1.0,
         _words_for_a_person(", in the same units as work")),
        # words before it, which the parser read past as the line's label
        (f"Dimension of force: {Q_TYPED}", "undecided", 1.0, _words_for_a_person("Dimension of force")),
        # a unit typed is checked, as after the formula: in the label's brackets too (before, read past)
        ("Q_θ [N] = −m g l sin θ", "not_equivalent", 0.0,
         ("Your answer is in kg·m/s², which is not how the quantity asked for is measured: check its dimensions.",)),
        ("Q_θ [N m] = −m g l sin θ", "equivalent", 1.0, ("Correct.", LEFT_OUT.format("N·m"))),
        # the dimensions asked for, in M, L and T, are checked as a unit is: before, names not defined
        ("−m g l sin θ [ML²T⁻²]", "equivalent", 1.0, ("Correct.", DIMENSIONS_LEFT_OUT.format("ML²T⁻²"))),
        ("−m g l sin θ [MLT⁻²]", "not_equivalent", 0.0,
         ("Your answer is in kg·m/s², which is not how the quantity asked for is measured: check its dimensions.",)),
        ("−m g l sin θ [M L^2 T^-2]", "equivalent", 1.0, ("Correct.", DIMENSIONS_LEFT_OUT.format("M L^2 T^-2"))),
        ("−m g l sin θ [M L T^-2]", "not_equivalent", 0.0,
         ("Your answer is in kg·m/s², which is not how the quantity asked for is measured: check its dimensions.",)),
        ("−m g l sin θ (ML²T⁻²)", "equivalent", 1.0, ("Correct.", DIMENSIONS_LEFT_OUT.format("ML²T⁻²"))),
        ("Q_θ = −m g l sin θ ML²T⁻²", "equivalent", 1.0, ("Correct.", DIMENSIONS_LEFT_OUT.format("ML²T⁻²"))),
        # N·m run together (before, words for a person), and a unit in square brackets whose name is the
        # problem's too (before, read as the mass m, a factor of the formula)
        ("−m g l sin θ Nm", "equivalent", 1.0, ("Correct.", LEFT_OUT.format("Nm"))),
        ("−m g l sin θ [m]", "not_equivalent", 0.0,
         ("Your answer is in m, which is not how the quantity asked for is measured: check its dimensions.",)),
        ("−m g l sin θ [J]", "equivalent", 1.0, ("Correct.", LEFT_OUT.format("J"))),
    ],
)  # fmt: skip
def test_where_a_part_asks_for_more_than_the_formula_words_beside_it_go_to_a_person(submitted, status, score, feedback):
    verdict = compare(TORQUE, submitted, **ASKS_MORE)
    assert (verdict.status, verdict.score, verdict.feedback) == (status, score, feedback), verdict


@pytest.mark.parametrize(
    ("submitted", "words"),
    [
        ("−m g l sin θ, the generalized force", ", the generalized force"),
        ("−m g l sin θ (the torque of gravity)", "(the torque of gravity)"),
    ],
)
def test_words_that_name_a_quantity_after_a_formula_are_for_a_person_to_read(submitted, words):
    # what the formula is, in words: right here, but the checker cannot tell them from "the Hamiltonian"
    # beside a Lagrangian, nor "a force" beside a torque where the prompt asks for its dimensions (before,
    # read past as Correct)
    verdict = compare(TORQUE, submitted, **PENDULUM)
    feedback = (
        f"Your answer says `{words}` beside the formula. The formula was graded on its own; a person will read"
        " the words against it.",
    )
    assert (verdict.status, verdict.score, verdict.feedback) == ("undecided", 1.0, feedback), verdict
