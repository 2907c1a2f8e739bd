"""Wrong answers that were once marked right, or earned credit they do not deserve, by kind.

Each row is an answer a student could write, the verdict it must get, and what it is told.
"""

from __future__ import annotations

import pytest

from grader import compare

PENDULUM = {"coords": ["theta"], "known": ["m", "g", "l"]}
L_PENDULUM = "1/2 m l^2 thetadot^2 + m g l cos(theta)"
ATWOOD = {"coords": ["x"], "known": ["m1", "m2", "g"]}
L_ATWOOD = "1/2 (m1 + m2) xdot^2 + (m1 - m2) g x"
DOUBLE = {"coords": ["theta1", "theta2"], "known": ["m1", "m2", "l1", "l2", "g"]}
L_DOUBLE = (
    "1/2 (m1 + m2) l1^2 theta1dot^2 + 1/2 m2 l2^2 theta2dot^2 + m2 l1 l2 theta1dot theta2dot cos(theta1 - theta2)"
    " + (m1 + m2) g l1 cos(theta1) + m2 g l2 cos(theta2)"
)

UNDECIDED = "This answer could not be checked automatically; it has been set aside for a person to grade."
ACCELERATIONS = "but a Lagrangian is a function of the coordinates, the velocities and the time alone."

LAGRANGIANS = [
    # (expected, submitted, setting, status, score, first feedback sentence)
    # d/dt(m l² θ θ̇) − m l² θ̇²... written with θ̈: it has no kinetic energy, yet read θ̈ as fixed it passed
    (L_PENDULUM, "m l^2 θ̇^2 + m l^2 θ θ̈ + m g l cos θ", PENDULUM, "not_equivalent", 0.0,
     f"Your Lagrangian has θ̈ in it, {ACCELERATIONS}"),
    # d/dt of a function of the velocity: it raises the order of Lagrange's equations
    (L_PENDULUM, f"{L_PENDULUM} + m l^2 θ̇ θ̈", PENDULUM, "not_equivalent", 0.0,
     f"Your Lagrangian has θ̈ in it, {ACCELERATIONS}"),
    (L_PENDULUM, f"{L_PENDULUM} + m l^2 d^2θ/dt^2", PENDULUM, "not_equivalent", 0.0,
     f"Your Lagrangian has θ̈ in it, {ACCELERATIONS}"),
    (L_PENDULUM, f"{L_PENDULUM} + m l^2 theta'''", PENDULUM, "not_equivalent", 0.0,
     f"Your Lagrangian has θ⃛ in it, {ACCELERATIONS}"),
    (L_ATWOOD, "(m1 + m2) ẋ^2 + (m1 + m2) x ẍ + (m1 - m2) g x", ATWOOD, "not_equivalent", 0.0,
     f"Your Lagrangian has ẍ in it, {ACCELERATIONS}"),
    (L_DOUBLE, f"{L_DOUBLE} + m2 l1^2 θ₁ θ̈₁ + m2 l2^2 θ̈₂", DOUBLE, "not_equivalent", 0.0,
     f"Your Lagrangian has θ̈₁, θ̈₂ in it, {ACCELERATIONS}"),
    # the momentum m l² (θ̇ + sgn θ̇) steps where θ̇ passes 0, which no sample state sees: for a person
    (L_PENDULUM, f"{L_PENDULUM} + m l^2 |θ̇|", PENDULUM, "undecided", 0.0, UNDECIDED),
    (L_PENDULUM, f"{L_PENDULUM} + m l sqrt(l^2 θ̇^2)", PENDULUM, "undecided", 0.0, UNDECIDED),
    # |θ̇| in other words: acos(cos θ̇) where the states are drawn (before, Correct), asin(sin θ̇) to π/2
    (L_PENDULUM, f"{L_PENDULUM} + m l^2 acos(cos θ̇)", PENDULUM, "undecided", 0.0, UNDECIDED),
    (L_PENDULUM, f"{L_PENDULUM} + m l^2 asin(sin θ̇)", PENDULUM, "undecided", 0.0, UNDECIDED),
    # |θ̇|² is θ̇², with no kink: 2 (T − V) so written earns its half, and goes to no person
    (L_PENDULUM, "m l^2 |θ̇|^2 + 2 m g l cos θ", PENDULUM, "not_equivalent", 0.5,
     "Your Lagrangian gives the right equations of motion, but it is 2 × (T − V); the convention L = T − V fixes"
     " the normalization."),
]  # fmt: skip


@pytest.mark.parametrize(("expected", "submitted", "setting", "status", "score", "sentence"), LAGRANGIANS)
def test_a_lagrangian_is_right_only_up_to_d_dt_of_a_function_of_q_and_t(
    expected, submitted, setting, status, score, sentence
):
    verdict = compare(expected, submitted, kind="lagrangian", **setting)
    assert (verdict.status, verdict.score) == (status, score), verdict
    assert sentence in verdict.feedback, verdict


PERIOD = "2*pi*sqrt(1/9.81)"  # 2.006 s

NUMBERS = [
    # (submitted, status, feedback): the period of a pendulum of 1 m, asked in seconds
    # units of time spelled so the number was read alone, and the word taken for a remark after it
    ("2.006 mins", "not_equivalent", ("Not within the accepted tolerance.", "Read as 120.36 s.")),
    ("2.006 hrs", "not_equivalent", ("Not within the accepted tolerance.", "Read as 7221.6 s.")),
    ("2.006 days", "not_equivalent", ("Not within the accepted tolerance.", "Read as 173318 s.")),
    ("2.006 milliseconds", "not_equivalent", ("Not within the accepted tolerance.", "Read as 0.002006 s.")),
    ("2.006 Hertz", "not_equivalent", ("Your answer is in 1/s, but the quantity asked for is measured in s.",)),
    ("2006 milliseconds", "equivalent", ("Correct.", "Read as 2.006 s.")),
    ("2.006 Seconds", "equivalent", ("Correct.",)),
    # a remark that names another unit, or per cent, says what the number is in
    ("2.006 (in minutes)", "invalid", ("A number is asked for here; your answer contains `in` and `minutes`.",)),
    ("2.006 percent", "invalid", ("A number is asked for here; your answer contains `percent`.",)),
    # a value, then its reason: read as 2.5·because·2π√(1/9.81) = 2.006 s, the reason's last side was graded
    ("2.5 s because 2π√(1/9.81) = 2.006 s", "not_equivalent", ("Not within the accepted tolerance.",
     "Graded your final value, `2.5 s`; your working, `2.5 s because 2π√(1/9.81) = 2.006 s`, does not hold.")),
    # in any case, and years as yr: before, each word a remark and the number right
    ("2.006 (MINUTES)", "invalid", ("A number is asked for here; your answer contains `MINUTES`.",)),
    ("2.006 Min", "invalid", ("A number is asked for here; your answer contains `Min`.",)),
    ("2.006 hz", "invalid", ("A number is asked for here; your answer contains `hz`.",)),
    ("2.006 Hr", "invalid", ("A number is asked for here; your answer contains `Hr`.",)),
    ("2.006 yrs", "not_equivalent", ("Not within the accepted tolerance.", "Read as 6.33045e+07 s.")),
    ("2.006 s (Second try)", "equivalent",
     ("Correct.", "Graded the number `2.006 s`; what follows it (`(Second try)`) is not graded.")),
    # prefixed seconds spelled out or cut short: each was a remark, and 2.006 ns right
    ("2.006 nsec", "not_equivalent", ("Not within the accepted tolerance.", "Read as 2.006e-09 s.")),
    ("2006000000 nsec", "equivalent", ("Correct.", "Read as 2.006 s.")),
    ("T = 2.006 nsec", "not_equivalent", ("Not within the accepted tolerance.", "Read as 2.006e-09 s.")),
    ("T = 2006000000 nsec", "equivalent", ("Correct.", "Read as 2.006 s.")),
    ("2.006 nanosec", "not_equivalent", ("Not within the accepted tolerance.", "Read as 2.006e-09 s.")),
    ("2.006 millisec", "not_equivalent", ("Not within the accepted tolerance.", "Read as 0.002006 s.")),
    ("2006 millisec", "equivalent", ("Correct.", "Read as 2.006 s.")),
    ("2.006 milli seconds", "not_equivalent", ("Not within the accepted tolerance.", "Read as 0.002006 s.")),
    ("2006 Milli seconds", "equivalent", ("Correct.", "Read as 2.006 s.")),
    ("2.006 millis", "not_equivalent", ("Not within the accepted tolerance.", "Read as 0.002006 s.")),
    ("2006 millis", "equivalent", ("Correct.", "Read as 2.006 s.")),
    ("2.006 usec", "not_equivalent", ("Not within the accepted tolerance.", "Read as 2.006e-06 s.")),
    ("2.006 microsec", "not_equivalent", ("Not within the accepted tolerance.", "Read as 2.006e-06 s.")),
    ("2006000 usec", "equivalent", ("Correct.", "Read as 2.006 s.")),
    ("2.006 ksec", "not_equivalent", ("Not within the accepted tolerance.", "Read as 2006 s.")),
    ("0.002006 ksec", "equivalent", ("Correct.", "Read as 2.006 s.")),
    ("2.006 picoseconds", "not_equivalent", ("Not within the accepted tolerance.", "Read as 2.006e-12 s.")),
    ("2.006 gigaseconds", "not_equivalent", ("Not within the accepted tolerance.", "Read as 2.006e+09 s.")),
    ("2.006 megaseconds", "not_equivalent", ("Not within the accepted tolerance.", "Read as 2.006e+06 s.")),
    ("2.006 centiseconds", "not_equivalent", ("Not within the accepted tolerance.", "Read as 0.02006 s.")),
    ("200.6 centiseconds", "equivalent", ("Correct.", "Read as 2.006 s.")),
    ("2.006 wk", "not_equivalent", ("Not within the accepted tolerance.", "Read as 1.21323e+06 s.")),
    # a word we cannot read as a unit, yet like one: a person, not the bare number, decides
    ("2.006 flubsec", "undecided", ("Your number `2.006` comes with `flubsec`, which may be a unit the checker does"
     " not know, and make it another number: a person will check your answer.",)),
    ("2.006 millisex", "undecided", ("Your number `2.006` comes with `millisex`, which may be a unit the checker"
     " does not know, and make it another number: a person will check your answer.",)),
    ("2.006 s exactly", "equivalent",
     ("Correct.", "Graded the number `2.006 s`; what follows it (`exactly`) is not graded.")),
]  # fmt: skip


@pytest.mark.parametrize(("submitted", "status", "feedback"), NUMBERS)
def test_a_number_is_read_with_the_unit_it_is_written_in(submitted, status, feedback):
    verdict = compare(PERIOD, submitted, kind="number", rtol=0.005, unit="s")
    assert (verdict.status, verdict.feedback) == (status, feedback), verdict


HOOP = {"coords": ["theta"], "known": ["m", "R", "omega", "g"]}
EOM_HOOP = "R thetaddot - R omega^2 sin(theta) cos(theta) + g sin(theta) = 0"
EOM_DOUBLE_1 = "(m1 + m2) l1 θ̈₁ + m2 l2 θ̈₂ cos(θ₁ − θ₂) + m2 l2 θ̇₂² sin(θ₁ − θ₂) + (m1 + m2) g sin θ₁ = 0"
EOM_DOUBLE_2 = "l2 θ̈₂ + l1 θ̈₁ cos(θ₁ − θ₂) − l1 θ̇₁² sin(θ₁ − θ₂) + g sin θ₂"
VANISHING = (
    "Your equation is right only where a factor of it is not zero: where that factor is zero, it no longer says"
    " what the acceleration is. Divide that factor out."
)
VANISHING_SYSTEM = (
    "One of your equations is right only where a factor of it is not zero: where that factor is zero, your"
    " equations no longer determine every acceleration. Divide that factor out."
)

PARAMETER_FACTORS = [
    # (expected, submitted, kind, setting, feedback): a factor of the parameters alone that vanishes where
    # both draws of the parameters leave it of one sign; m₁ − m₂ changed sign between them, and was caught
    (EOM_HOOP, f"(R omega^2 - g) ({EOM_HOOP.removesuffix(' = 0')}) = 0", "equation", HOOP, VANISHING),
    (f"{EOM_DOUBLE_1}; {EOM_DOUBLE_2} = 0", f"{EOM_DOUBLE_1}; (l1 − l2) ({EOM_DOUBLE_2}) = 0", "equations", DOUBLE,
     VANISHING_SYSTEM),
]  # fmt: skip


@pytest.mark.parametrize(("expected", "submitted", "kind", "setting", "sentence"), PARAMETER_FACTORS)
def test_a_factor_of_the_parameters_that_vanishes_is_found_whatever_the_draws(
    expected, submitted, kind, setting, sentence
):
    verdict = compare(expected, submitted, kind=kind, **setting)
    assert (verdict.status, verdict.feedback) == ("not_equivalent", (sentence,)), verdict


ATWOOD_A = "(m1 - m2) g / (m1 + m2)"
ACCELERATION = {**ATWOOD, "name": ["xddot", "a", "a_1"]}

LABELS = [
    # (submitted, status, feedback): the acceleration ẍ asked, named as the coordinate's rate; a label that
    # names another rate, or the coordinate, gave a velocity or a position, and was graded as ẍ
    (f"ẋ = {ATWOOD_A}", "undecided",
     "Your answer is labelled ẋ, but the quantity asked for is ẍ. Read as ẍ, it is right; a person will check"
     " which you meant."),
    (f"x''' = {ATWOOD_A}", "undecided",
     "Your answer is labelled x⃛, but the quantity asked for is ẍ. Read as ẍ, it is right; a person will check"
     " which you meant."),
    ("ẋ = (m2 - m1) g / (m1 + m2)", "not_equivalent", "Your answer is labelled ẋ, but the quantity asked for is ẍ."),
    (f"x = {ATWOOD_A}", "undecided",  # was so before, but said "xddot" for ẍ
     "Your answer is labelled x, but the quantity asked for is ẍ. Read as ẍ, it is right; a person will check"
     " which you meant."),
]  # fmt: skip


@pytest.mark.parametrize(("submitted", "status", "sentence"), LABELS)
def test_a_label_that_names_another_rate_is_not_the_asked_one(submitted, status, sentence):
    verdict = compare(ATWOOD_A, submitted, kind="expression", **ACCELERATION)
    assert verdict.status == status, verdict
    assert sentence in verdict.feedback, verdict


NUMBER_LABELS = [
    # (submitted, status, feedback): the period asked, by the names T, T₀, τ or P; a number labelled with
    # another quantity's name was graded as the period, its label not read
    ("f = 2.006", "undecided",
     "Your answer is labelled f, but the quantity asked for is T. Read as T, it is right; a person will check"
     " which you meant."),
    ("ω = 2.006 s", "undecided",
     "Your answer is labelled ω, but the quantity asked for is T. Read as T, it is right; a person will check"
     " which you meant."),
    ("f = 0.319", "not_equivalent", "Your answer is labelled f, but the quantity asked for is T."),
    # the word for a quantity measured in the unit asked names it (before, for a person); another does not
    ("period = 2.006 s", "equivalent", "Correct."),
    ("Period = 2006 ms", "equivalent", "Correct."),
    ("period = 2.1 s", "not_equivalent", "Not within the accepted tolerance."),
    ("length = 2.006", "undecided",
     "Your answer is labelled length, but the quantity asked for is T. Read as T, it is right; a person will check"
     " which you meant."),
    ("frequency = 2.006", "undecided",
     "Your answer is labelled frequency, but the quantity asked for is T. Read as T, it is right; a person will"
     " check which you meant."),
]  # fmt: skip


@pytest.mark.parametrize(("submitted", "status", "sentence"), NUMBER_LABELS)
def test_a_number_labelled_with_another_quantity_is_not_the_asked_one(submitted, status, sentence):
    verdict = compare(PERIOD, submitted, kind="number", rtol=0.005, unit="s", name=["T", "T_0", "tau", "P"])
    assert verdict.status == status, verdict
    assert sentence in verdict.feedback, verdict


PARTLY_RIGHT = [
    # (submitted, status, score, feedback): a Lagrangian right only in part, read in a way a person would confirm
    # were it right: it was told "Its value was graded and is right", or "Read as L, it is right"
    ("H = m l^2 θ̇^2 + 2 m g l cos θ", "undecided", 0.5, (
        "Your Lagrangian gives the right equations of motion, but it is 2 × (T − V); the convention L = T − V fixes"
        " the normalization.",
        "Your answer is labelled H, but the quantity asked for is L.")),
    ("L = T + V = m l^2 θ̇^2 + 2 m g l cos θ", "undecided", 0.5, (
        "Your Lagrangian gives the right equations of motion, but it is 2 × (T − V); the convention L = T − V fixes"
        " the normalization.",
        "Your answer says `L = T + V` on the way to its value, which is not what L is.")),
    # L = V − T, as its value is: said once
    ("T = 1/2 m l^2 θ̇^2; V = -m g l cos θ; L = V - T", "not_equivalent", 0.5,
     ("Your Lagrangian has the opposite sign: it is V − T; the Lagrangian is L = T − V.",)),
]  # fmt: skip


@pytest.mark.parametrize(("submitted", "status", "score", "feedback"), PARTLY_RIGHT)
def test_an_answer_right_in_part_is_not_told_it_is_right(submitted, status, score, feedback):
    verdict = compare(L_PENDULUM, submitted, kind="lagrangian", **PENDULUM)
    assert (verdict.status, verdict.score, verdict.feedback) == (status, score, feedback), verdict


def test_a_count_of_one_pair_is_not_one():
    # 1 pair is 2: as 2 pairs was, the number goes to a person, who decides which it is; before, 1 was graded
    verdict = compare("1", "1 pair", kind="integer", name="n")
    assert (verdict.status, verdict.score, verdict.feedback) == ("undecided", 0.0, (
        "Your number `1` comes with `pair`, which may make it another number, or no one number: a person will"
        " decide what your answer is.",
    ))  # fmt: skip


def test_words_that_set_another_angle_go_to_a_person():
    # θ from the horizontal makes cos θ the other convention's sin θ: the words were read past, as harmless
    verdict = compare(
        L_PENDULUM, f"{L_PENDULUM} with theta measured from the horizontal", kind="lagrangian", **PENDULUM
    )
    assert (verdict.status, verdict.feedback) == ("undecided", (
        "Your answer says `with theta measured from the horizontal` beside the formula. The formula was graded on"
        " its own; a person will read the words against it.",
    )), verdict  # fmt: skip


COUNTS_WORKED = [
    # (submitted, status, feedback): a count worked out with values given after it, which do not come to it
    ("n = 3N - k = 1, where N = 1, k = 1", "undecided",
     "Your final value, `1`, was graded and is right, but your working, `3N - k, where N = 1, k = 1`, does not"
     " hold: a person will check this answer."),
    # the arithmetic that gives its reason: 3 − 1 is 2
    ("1, since 3 − 1 = 1", "undecided",
     "Your final value, `1`, was graded and is right, but your working, `1, since 3 − 1 = 1`, does not hold: a"
     " person will check this answer."),
    ("n = 3N - k = 3, where N = 1, k = 1", "not_equivalent",
     "Graded your final value, `3`; your working, `3N - k, where N = 1, k = 1`, does not hold."),
    # the count before because, then its reason: read as 3·because − 1 = 1, the reason's last side was graded
    ("1 because 3 − 1 = 1", "undecided",
     "Your final value, `1`, was graded and is right, but your working, `1 because 3 − 1 = 1`, does not hold: a"
     " person will check this answer."),
    ("2 because 3 − 1 = 1", "not_equivalent",
     "Graded your final value, `2`; your working, `2 because 3 − 1 = 1`, does not hold."),
    ("n = 2 because 3 − 1 = 1", "not_equivalent",
     "Graded your final value, `2`; your working, `n = 2 because 3 − 1 = 1`, does not hold."),
    ("2 because 3 coordinates minus 2 constraints = 1", "not_equivalent",
     "Graded your final value, `2`; your working, `2 because 3 coordinates minus 2 constraints = 1`, does not"
     " hold."),
    # the reason was checked, but not against the count before it
    ("2, since 3 − 2 = 1", "not_equivalent",
     "Graded your final value, `2`; your working, `2, since 3 − 2 = 1`, does not hold."),
    ("n = 1 because 3 − 1 = 2", "undecided",
     "Your final value, `1`, was graded and is right, but your working, `n = 1 because 3 − 1 = 2`, does not hold:"
     " a person will check this answer."),
    # a reason that holds, and one that gives the values of names, as before
    ("1 because 3 − 2 = 1", "equivalent",
     "Graded the number `1`; what follows it (`because 3 − 2 = 1`) is not graded."),
    ("1, since 3 − 2 = 1", "equivalent", "Graded the number `1`; what follows it (`since 3 − 2 = 1`) is not graded."),
    ("n = 3N − k = 1 because N = 1 and k = 2", "equivalent", "Correct."),
    # as and given that give a reason too; and n, the count's name, may label the reason's working
    ("2, as 3 − 2 = 1", "not_equivalent",
     "Graded your final value, `2`; your working, `2, as 3 − 2 = 1`, does not hold."),
    ("2 given that 3 − 2 = 1", "not_equivalent",
     "Graded your final value, `2`; your working, `2 given that 3 − 2 = 1`, does not hold."),
    ("2 because n = 3 − 2 = 1", "not_equivalent",
     "Graded your final value, `2`; your working, `2 because n = 3 − 2 = 1`, does not hold."),
    ("1 because n = 3 − 2 = 1", "equivalent",
     "Graded the number `1`; what follows it (`because n = 3 − 2 = 1`) is not graded."),
    # a step says what follows from what came before it: a number, then another after the step, is working
    # that does not hold (before, right: the last number was taken)
    ("2 hence 3 − 2 = 1", "undecided",
     "Your final value, `1`, was graded and is right, but your working, `2 hence 3 − 2 = 1`, does not hold: a"
     " person will check this answer."),
    ("n = 2, so n = 1", "undecided",
     "Your final value, `1`, was graded and is right, but your working, `n = 2, so n = 1`, does not hold: a"
     " person will check this answer."),
    ("3 − 1 = 2 ⇒ 1", "undecided",
     "Your final value, `1`, was graded and is right, but your working, `3 − 1 = 2 ⇒ 1`, does not hold: a"
     " person will check this answer."),
    ("6 − 4 → 3", "not_equivalent", "Graded your final value, `3`; your working, `6 − 4 → 3`, does not hold."),
    ("1 hence 2", "not_equivalent", "Graded your final value, `2`; your working, `1 hence 2`, does not hold."),
    # steps between the same number, or from words: as before
    ("3 − 2 → 1", "equivalent", "Graded your final value, `1`; the working before it is not graded."),
    ("1 hence 3 − 2 = 1", "equivalent", "Correct."),
    ("3 − 2 = 1, so n = 1", "equivalent", "Correct."),
    ("Two constraints, so 1", "equivalent", "Graded your final value, `1`; the working before it is not graded."),
    # a count too long to read is refused, not passed over for the reason's last side
    (f"{'9' * 40} because 1 = 1", "invalid", "This number is too large to handle (40 digits; the limit is 30)."),
]  # fmt: skip


@pytest.mark.parametrize(("submitted", "status", "sentence"), COUNTS_WORKED)
def test_a_count_worked_out_with_values_that_do_not_come_to_it_is_for_a_person(submitted, status, sentence):
    verdict = compare("1", submitted, kind="integer", name="n")
    assert verdict.status == status, verdict
    assert sentence in verdict.feedback, verdict


QUALIFIED = "which may make it another number, or no one number: a person will decide what your answer is."

COUNTS_SAID_OTHERWISE = [
    # (expected, submitted, status, feedback): a count whose own words say another number, or another thing
    ("1", "It has 2 degrees of freedom, so 1 generalized coordinate.", "undecided",
     "Your answer gives two counts of the same thing, 2 and then 1: a person will decide which number is your"
     " answer."),
    ("2", "It has 2 degrees of freedom, so 1 generalized coordinate.", "undecided",
     "Your answer gives two counts of the same thing, 2 and then 1: a person will decide which number is your"
     " answer."),
    ("2", "2 (three angles)", "undecided",
     "Your count `2` is followed by `(three angles)`, which does not come to 2: a person will decide which number"
     " is your answer."),
    ("1", "1 constraint", "undecided", f"Your number `1` comes with `constraint`, {QUALIFIED}"),
    ("1", "one angle and one length", "undecided", f"Your number `one` comes with `angle and one length`, {QUALIFIED}"),
    ("1", "1 (θ and φ)", "undecided", f"Your number `1` comes with `(θ and φ)`, {QUALIFIED}"),
    ("1", "1 (x, y)", "undecided", f"Your number `1` comes with `(x, y)`, {QUALIFIED}"),
    # the coordinates listed after what is counted, or one where two are counted, or spelt out (before, right)
    ("1", "1 dof: θ and r", "undecided", f"Your number `1` comes with `dof: θ and r`, {QUALIFIED}"),
    ("1", "1 degree of freedom (θ, r)", "undecided",
     f"Your number `1` comes with `degree of freedom (θ, r)`, {QUALIFIED}"),
    ("1", "1, namely θ and r", "undecided", f"Your number `1` comes with `namely θ and r`, {QUALIFIED}"),
    ("1", "1 (theta and r)", "undecided", f"Your number `1` comes with `(theta and r)`, {QUALIFIED}"),
    ("2", "2 (θ)", "undecided", f"Your number `2` comes with `(θ)`, {QUALIFIED}"),
    ("2", "2 dof: θ₁", "undecided", f"Your number `2` comes with `dof: θ₁`, {QUALIFIED}"),
    # words after a count that name or add more coordinates than it counts, or fewer, outside a plain list
    ("1", "one angle, and one length", "undecided",
     f"Your number `one` comes with `angle, and one length`, {QUALIFIED}"),
    ("1", "1 (θ) and one for φ", "undecided", f"Your number `1` comes with `(θ) and one for φ`, {QUALIFIED}"),
    ("1", "1, and another for φ", "undecided", f"Your number `1` comes with `and another for φ`, {QUALIFIED}"),
    ("1", "1, and a second one (φ)", "undecided", f"Your number `1` comes with `and a second one (φ)`, {QUALIFIED}"),
    ("1", "one (θ), and another one (φ)", "undecided",
     f"Your number `one` comes with `(θ), and another one (φ)`, {QUALIFIED}"),
    ("1", "1 (the angles θ and φ)", "undecided", f"Your number `1` comes with `(the angles θ and φ)`, {QUALIFIED}"),
    ("1", "1 (both angles)", "undecided", f"Your number `1` comes with `(both angles)`, {QUALIFIED}"),
    ("1", "1 (angles θ, φ)", "undecided", f"Your number `1` comes with `(angles θ, φ)`, {QUALIFIED}"),
    ("2", "2 (θ₁ only)", "undecided", f"Your number `2` comes with `(θ₁ only)`, {QUALIFIED}"),
    ("2", "2 (just θ₁)", "undecided", f"Your number `2` comes with `(just θ₁)`, {QUALIFIED}"),
    ("2", "2 (the angle θ₁)", "undecided", f"Your number `2` comes with `(the angle θ₁)`, {QUALIFIED}"),
    ("2", "2 (one coordinate)", "undecided",
     "Your count `2` is followed by `(one coordinate)`, which does not come to 2: a person will decide which number"
     " is your answer."),
    # and their twins, whose words name as many coordinates as counted
    ("1", "1 (the angle θ from the vertical)", "equivalent", "Correct."),
    ("2", "2 (the angles θ₁ and θ₂)", "equivalent", "Correct."),
    ("2", "2 (both angles)", "equivalent", "Correct."),
    ("2", "2 (θ₁, and another for θ₂)", "equivalent", "Correct."),
    ("2", "2 (6 coordinates)", "equivalent", "Correct."),  # what it was counted from
    ("2", "2 (one coordinate for each bob)", "equivalent", "Correct."),
    ("2", "2 (θ₁ and θ₂, both from the vertical)", "equivalent", "Correct."),
    # another or a second implies the first (before, right), a triple is no one coordinate, and a coordinate
    # said to be fixed, or needed only if something varied, is none counted
    ("2", "2 (another angle for the second bob)", "equivalent", "Correct."),
    ("2", "2 (a second angle for the second bob)", "equivalent", "Correct."),
    ("2", "2 (θ₁ for the first bob and another for the second)", "equivalent", "Correct."),
    ("6", "6 (a second triple for rotation)", "equivalent", "Correct."),
    ("1", "1 (θ — φ is fixed by the plane)", "equivalent", "Correct."),
    ("1", "1 (θ and φ fixed)", "equivalent", "Correct."),
    ("1", "1: θ (φ fixed)", "equivalent", "Correct."),
    ("1", "1 (another would be needed if l varied)", "equivalent", "Correct."),
    ("1", "1 (θ, with φ and r fixed)", "equivalent", "Correct."),
    # but not one said to be free, or needed with no condition: as before
    ("1", "1 (θ and φ no longer fixed)", "undecided",
     f"Your number `1` comes with `(θ and φ no longer fixed)`, {QUALIFIED}"),
    ("1", "1 (θ and another would be needed)", "undecided",
     f"Your number `1` comes with `(θ and another would be needed)`, {QUALIFIED}"),
    # a count worked from others, what it counts, and how many things it was counted from: as before
    ("2", "2 (θ₁, θ₂)", "equivalent", "Correct."),
    ("1", "1 (θ)", "equivalent", "Correct."),
    ("1", "3 degrees of freedom, minus 2 constraints, so 1", "equivalent", "Correct."),
    ("1", "It has 1 degree of freedom, so 1 generalized coordinate.", "equivalent", "Correct."),
    ("2", "2 (two angles)", "equivalent", "Correct."),
    ("1", "1 angle", "equivalent", "Correct."),
    ("15", "15 (5 particles)", "equivalent", "Correct."),
    ("1", "1 dof: θ", "equivalent", "Correct."),
    ("2", "2 degrees of freedom: θ₁, θ₂", "equivalent", "Correct."),
    ("2", "2 (theta1, theta2)", "equivalent", "Correct."),
    ("1", "1, namely θ", "equivalent", "Correct."),
]  # fmt: skip


@pytest.mark.parametrize(("expected", "submitted", "status", "sentence"), COUNTS_SAID_OTHERWISE)
def test_a_count_whose_words_say_another_goes_to_a_person(expected, submitted, status, sentence):
    verdict = compare(expected, submitted, kind="integer", name="n")
    assert verdict.status == status, verdict
    assert sentence in verdict.feedback, verdict


def _count_labelled(label):
    return (
        f"Your answer is labelled `{label}`, but the quantity asked for is n. Read as n, it is right; a person will"
        " check which you meant."
    )


COUNT_LABELS = [
    # (expected, submitted, status, feedback): a count labelled with another quantity's name, where n = 3N − k
    # is asked, goes to a person; the asked name, a word for degrees of freedom, f or s, and working, stay right
    ("15", "k = 15", "undecided", (_count_labelled("k"),)),
    ("2", "3N = 2", "undecided", (_count_labelled("3N"),)),
    ("6", "N = 6", "undecided", (_count_labelled("N"),)),
    ("2", "constraints = 2", "undecided", (_count_labelled("constraints"),)),
    ("2", "T = 2", "undecided", (_count_labelled("T"),)),
    ("2", "x = 2", "undecided", (_count_labelled("x"),)),
    ("2", "m = 2", "undecided", (_count_labelled("m"),)),
    ("2", "2 = k", "undecided", (_count_labelled("k"),)),
    ("2", "k = 4", "not_equivalent",
     ("Not equivalent to the expected answer.", "Your answer is labelled `k`, but the quantity asked for is n.")),
    ("15", "n = 15", "equivalent", ("Correct.",)),
    ("15", "dof = 15", "equivalent", ("Correct.",)),
    ("15", "DOF = 15", "equivalent", ("Correct.",)),
    ("15", "n_dof = 15", "equivalent", ("Correct.",)),
    ("15", "f = 15", "equivalent", ("Correct.",)),
    ("15", "s = 15", "equivalent", ("Correct.",)),
    ("2", "degrees of freedom = 2", "equivalent", ("Correct.",)),
    ("2", "3N - k = 2", "equivalent", ("Correct.",)),
    ("2", "2 = n", "equivalent", ("Correct.", "Graded the number `2`; the rest of your answer is not graded.")),
    ("2", "2 = d.o.f.", "equivalent", ("Correct.", "Graded the number `2`; the rest of your answer is not graded.")),
    ("2", "k = 4, n = 2", "equivalent", ("Correct.",)),
    # a label in words: another thing's count, or the count's, or the answer's
    ("2", "No. of constraints = 2", "undecided", (_count_labelled("No. of constraints"),)),
    ("2", "Number of constraints = 2", "undecided", (_count_labelled("Number of constraints"),)),
    ("2", "No. of DOF = 2", "equivalent",
     ("Correct.", "Graded your final value, `2`; the working before it is not graded.")),
    ("2", "number of generalized coordinates = 2", "equivalent", ("Correct.",)),
    ("2", "The answer = 2", "equivalent", ("Correct.",)),
]  # fmt: skip

COUNTS_SPELT = [
    # (expected, submitted, status, feedback): a count glued or hyphened to what it counts, in words, or with the
    # values it was worked out with in a bracket
    ("2", "2-DOF", "equivalent", ("Correct.", "Graded the number `2`; what follows it (`DOF`) is not graded.")),
    ("2", "2DOF", "equivalent", ("Correct.", "Graded the number `2`; what follows it (`DOF`) is not graded.")),
    ("2", "2 degrees-of-freedom", "equivalent",
     ("Correct.", "Graded the number `2`; what follows it (`degrees of freedom`) is not graded.")),
    ("1", "a single degree of freedom", "equivalent",
     ("Correct.", "Graded the number `one`; what follows it (`degree of freedom`) is not graded.")),
    ("2", "a single degree of freedom", "not_equivalent", ("Not equivalent to the expected answer.",
     "Graded the number `one`; what follows it (`degree of freedom`) is not graded.")),
    ("2", "2 (k = 4)", "equivalent", ("Correct.", "Graded the number `2`; what follows it (`k = 4`) is not graded.")),
    ("2", "n = 2 (k = 4, N = 2)", "equivalent",
     ("Correct.", "Graded the number `n = 2`; what follows it (`k = 4, N = 2`) is not graded.")),
    ("2", "n = 3N - k = 2 (k = 3, N = 2)", "undecided",
     ("Your final value, `2`, was graded and is right, but your working, `3N - k, where k = 3, N = 2`, does not"
      " hold: a person will check this answer.",)),
    ("2", "3-DOF", "not_equivalent", ("Not equivalent to the expected answer.",
     "Graded the number `3`; what follows it (`DOF`) is not graded.")),
]  # fmt: skip


@pytest.mark.parametrize(("expected", "submitted", "status", "feedback"), COUNTS_SPELT)
def test_a_count_spelt_as_students_write_it_is_read(expected, submitted, status, feedback):
    verdict = compare(expected, submitted, kind="integer", name="n")
    assert (verdict.status, verdict.feedback) == (status, feedback), verdict


@pytest.mark.parametrize(("expected", "submitted", "status", "feedback"), COUNT_LABELS)
def test_a_count_labelled_as_another_quantity_goes_to_a_person(expected, submitted, status, feedback):
    verdict = compare(expected, submitted, kind="integer", name="n")
    assert (verdict.status, verdict.feedback) == (status, feedback), verdict


ENERGIES = "Your working gives T and V, but T − V with them is not the value your answer gives L."
WORKING_READ = "The lines that define `T` and `V` were read as your working, not as your answer."
KINETIC_MOVES = (
    "Your working gives T, but T − L with the value your answer gives L depends on the velocities, which a potential"
    " energy V does not: so L = T − V cannot hold."
)
MOVES = "Your working gives {}, which depends on the velocities: a potential energy does not."
CHECKED = " Its value was graded and is right; a person will check this answer."
T_READ = "The line that defines `T` was read as your working, not as your answer."
TV_READ = "The lines that define `T` and `v` were read as your working, not as your answer."

ENERGIES_WORKED = [
    # (submitted, status, feedback): the energies, then a Lagrangian their difference is not; the lines of
    # working were read past, and the stated value graded alone
    ("T = m l² θ̇²; V = −m g l cos θ; L = T − V = ½ m l² θ̇² + m g l cos θ", "undecided",
     (f"{ENERGIES} Its value was graded and is right; a person will check this answer.", WORKING_READ)),
    ("T = ½ m l² θ̇²; V = m g l cos θ; L = ½ m l² θ̇² + m g l cos θ", "undecided",
     (f"{ENERGIES} Its value was graded and is right; a person will check this answer.", WORKING_READ)),
    ("L = T − V = ½ m l² θ̇² + m g l cos θ, where T = m l² θ̇² and V = −m g l cos θ", "undecided",
     (f"{ENERGIES} Its value was graded and is right; a person will check this answer.",
      "The lines that define `T` and `V` were not graded: L is what is asked for here.")),
    ("T = m l² θ̇²; V = −m g l cos θ; L = T − V = ½ m l² θ̇² − m g l cos θ", "not_equivalent",
     ("It looks like you wrote L = T + V; the Lagrangian is L = T − V.", ENERGIES, WORKING_READ)),
    # the same before a step (⇒, so, therefore), whose working the reading dropped unseen (before, right)
    ("T = ½ m l² θ̇², V = m g l cos θ ⇒ L = ½ m l² θ̇² + m g l cos θ", "undecided",
     (f"{ENERGIES} Its value was graded and is right; a person will check this answer.", WORKING_READ)),
    ("V = −m g l cos θ, T = m l² θ̇² therefore L = ½ m l² θ̇² + m g l cos θ", "undecided",
     (f"{ENERGIES} Its value was graded and is right; a person will check this answer.", WORKING_READ)),
    # working that comes to the value, or to it but for a constant: as before
    ("T = ½ m l² θ̇²; V = −m g l cos θ; L = T − V = ½ m l² θ̇² + m g l cos θ", "equivalent", ("Correct.", WORKING_READ)),
    ("T = ½ m l² θ̇², V = −m g l cos θ, so L = ½ m l² θ̇² + m g l cos θ", "equivalent", ("Correct.", WORKING_READ)),
    ("T = ½ m l² θ̇²; V = m g l (1 − cos θ); L = ½ m l² θ̇² + m g l cos θ", "equivalent", ("Correct.", WORKING_READ)),
    # T alone, whose velocities L's are not: T − L, the V that L = T − V leaves, moves with θ̇ (before, right)
    ("T = m l^2 thetadot^2 => L = 1/2 m l^2 thetadot^2 + m g l cos(theta)", "undecided",
     (f"{KINETIC_MOVES}{CHECKED}", T_READ)),
    ("T = m l^2 thetadot^2; L = 1/2 m l^2 thetadot^2 + m g l cos(theta)", "undecided",
     (f"{KINETIC_MOVES}{CHECKED}", T_READ)),
    ("T = m l² θ̇²; L = T − V = ½ m l² θ̇² + m g l cos θ", "undecided", (f"{KINETIC_MOVES}{CHECKED}", T_READ)),
    ("T = 0; L = ½ m l² θ̇² + m g l cos θ", "undecided", (f"{KINETIC_MOVES}{CHECKED}", T_READ)),
    ("T = ½ m v²; v = 2 l θ̇; L = ½ m l² θ̇² + m g l cos θ", "undecided", (f"{KINETIC_MOVES}{CHECKED}", TV_READ)),
    ("T = ½ m l² θ̇² ⇒ L = m l² θ̇² + m g l cos θ", "not_equivalent",
     ("A term differs: the velocity-dependent term in θ̇² has the wrong factor.", KINETIC_MOVES, T_READ)),
    # a V (U) with velocities in it, alone or with a T that makes up for it (before, right)
    ("V = 1/2 m l^2 thetadot^2 => L = 1/2 m l^2 thetadot^2 + m g l cos(theta)", "undecided",
     (f"{MOVES.format('V')}{CHECKED}", "The line that defines `V` was read as your working, not as your answer.")),
    ("U = ½ m l² θ̇² ⇒ L = ½ m l² θ̇² + m g l cos θ", "undecided",
     (f"{MOVES.format('U')}{CHECKED}", "The line that defines `U` was read as your working, not as your answer.")),
    ("T = m l² θ̇²; V = ½ m l² θ̇² − m g l cos θ; L = ½ m l² θ̇² + m g l cos θ", "undecided",
     (f"{MOVES.format('V')}{CHECKED}", WORKING_READ)),
    # their right twins, and a T consistent with a wrong L: as before
    ("T = 1/2 m l^2 thetadot^2 => L = 1/2 m l^2 thetadot^2 + m g l cos(theta)", "equivalent", ("Correct.", T_READ)),
    ("T = 1/2 m l^2 thetadot^2; L = 1/2 m l^2 thetadot^2 + m g l cos(theta)", "equivalent", ("Correct.", T_READ)),
    ("T = ½ m l² θ̇²; L = T − V = ½ m l² θ̇² + m g l cos θ", "equivalent", ("Correct.", T_READ)),
    ("T = ½ m v²; v = l θ̇; L = ½ m l² θ̇² + m g l cos θ", "equivalent", ("Correct.", TV_READ)),
    ("T = m l² θ̇² ⇒ L = m l² θ̇² + m g l cos θ", "not_equivalent",
     ("A term differs: the velocity-dependent term in θ̇² has the wrong factor.", T_READ)),
    ("V = -m g l cos(theta) => L = 1/2 m l^2 thetadot^2 + m g l cos(theta)", "equivalent",
     ("Correct.", "The line that defines `V` was read as your working, not as your answer.")),
    ("U = m g l (1 − cos θ) ⇒ L = ½ m l² θ̇² + m g l cos θ", "equivalent",
     ("Correct.", "The line that defines `U` was read as your working, not as your answer.")),
    # K for T, as some texts write it: held against L as T is, and named as typed (before, right)
    ("K = m l² θ̇²; L = ½ m l² θ̇² + m g l cos θ", "undecided",
     ("Your working gives K, but K − L with the value your answer gives L depends on the velocities, which a"
      f" potential energy V does not: so L = K − V cannot hold.{CHECKED}", T_READ.replace("`T`", "`K`"))),
    ("K = ½ m l² θ̇²; L = ½ m l² θ̇² + m g l cos θ", "equivalent", ("Correct.", T_READ.replace("`T`", "`K`"))),
    # an L that differs from T − V by d/dt of a function of θ gives T's equations: honest working (before this
    # was checked, right; then for a person)
    ("T = ½ m l² θ̇²; L = ½ m l² θ̇² + m g l cos θ + m g l cos θ θ̇", "equivalent",
     ("Correct: your Lagrangian gives the same equations of motion.", T_READ)),
    # a multiple of T on the left is the line of working it names (before, an AttributeError)
    ("2T = m l² θ̇²; L = ½ m l² θ̇² + m g l cos θ", "equivalent",
     ("Correct.", "The line that defines `T` was not graded: L is what is asked for here.")),
]  # fmt: skip


@pytest.mark.parametrize(("submitted", "status", "feedback"), ENERGIES_WORKED)
def test_energies_in_the_working_that_do_not_make_the_lagrangian_go_to_a_person(submitted, status, feedback):
    verdict = compare(L_PENDULUM, submitted, kind="lagrangian", **PENDULUM)
    assert (verdict.status, verdict.feedback) == (status, feedback), verdict


DAMPED = {"coords": ["x"], "known": ["m", "k", "b"]}
EOM_DAMPED = "m xddot + b xdot + k x = 0"
NOT_LAGRANGE = (
    "on the way to its equation, which is not Lagrange's equation. The equation was graded and is right; a person"
    " will check this answer."
)

OPERATORS_WITHOUT_FRICTION = [
    # (submitted, status, feedback): Lagrange's operator without Rayleigh's term, said to equal a side with the
    # friction in it, which no L gives (∂(b ẋ)/∂ẋ is not d/dt of m): the step was read past
    ("d/dt(∂L/∂ẋ) − ∂L/∂x = m ẍ + k x + b ẋ = 0", "undecided",
     (f"Your answer says `d/dt(∂L/∂ẋ) − ∂L/∂x = m ẍ + k x + b ẋ` {NOT_LAGRANGE}",)),
    ("∂L/∂x − d/dt(∂L/∂ẋ) = −m ẍ − k x − b ẋ = 0", "undecided",
     (f"Your answer says `∂L/∂x − d/dt(∂L/∂ẋ) = −m ẍ − k x − b ẋ` {NOT_LAGRANGE}",
      "Read without the words before it, `∂L/∂x − d/dt(∂L/∂ẋ) =`: the formula is what is graded.")),
    # with Rayleigh's term in the operator, or the friction on the far side: as before
    ("d/dt(∂L/∂ẋ) − ∂L/∂x + ∂F/∂ẋ = m ẍ + k x + b ẋ = 0", "equivalent", ("Correct.",)),
    ("d/dt(∂L/∂ẋ) − ∂L/∂x = m ẍ + k x = −b ẋ", "equivalent", ("Correct.",)),
]  # fmt: skip


@pytest.mark.parametrize(("submitted", "status", "feedback"), OPERATORS_WITHOUT_FRICTION)
def test_an_operator_said_to_give_what_no_lagrangian_gives_goes_to_a_person(submitted, status, feedback):
    verdict = compare(EOM_DAMPED, submitted, kind="equation", **DAMPED)
    assert (verdict.status, verdict.feedback) == (status, feedback), verdict


def test_an_operator_that_gives_the_pendulum_equation_stays_right():
    # m l² θ̈ + m g l sin θ is what d/dt(∂L/∂θ̇) − ∂L/∂θ gives for the pendulum's L: no friction to leave out
    submitted = "d/dt(∂L/∂θ̇) − ∂L/∂θ = m l² θ̈ + m g l sin θ = 0"
    verdict = compare("m l^2 thetaddot + m g l sin(theta) = 0", submitted, kind="equation", **PENDULUM)
    assert (verdict.status, verdict.feedback) == ("equivalent", ("Correct.",)), verdict


SPHERICAL = {"coords": ["theta", "phi"], "known": ["m", "g", "l"], "name": "H"}
H_SPHERICAL = "1/2 m l^2 (thetadot^2 + sin(theta)^2 phidot^2) - m g l cos(theta)"


@pytest.mark.parametrize(
    "submitted",
    [
        # H = T + V, as T − V was for L: the T before it, twice the kinetic energy, was read past
        "T = m l² (θ̇² + sin²θ φ̇²); V = −m g l cos θ; H = T + V = ½ m l² (θ̇² + sin²θ φ̇²) − m g l cos θ",
        # and before a step, V with the wrong sign, was dropped unseen
        "T = ½ m l² (θ̇² + sin²θ φ̇²), V = m g l cos θ ⇒ H = ½ m l² (θ̇² + sin²θ φ̇²) − m g l cos θ",
    ],
)
def test_energies_in_the_working_that_do_not_make_the_hamiltonian_go_to_a_person(submitted):
    verdict = compare(H_SPHERICAL, submitted, kind="expression", **SPHERICAL)
    assert (verdict.status, verdict.feedback) == ("undecided", (
        "Your working gives T and V, but T + V with them is not the value your answer gives H. Its value was graded"
        " and is right; a person will check this answer.",
        WORKING_READ,
    )), verdict  # fmt: skip


def test_energies_before_a_step_that_make_the_hamiltonian_stay_right():
    submitted = "T = ½ m l² (θ̇² + sin²θ φ̇²), V = −m g l cos θ ⇒ H = ½ m l² (θ̇² + sin²θ φ̇²) − m g l cos θ"
    verdict = compare(H_SPHERICAL, submitted, kind="expression", **SPHERICAL)
    assert (verdict.status, verdict.feedback) == ("equivalent", ("Correct.", WORKING_READ)), verdict


HOOP_HAMILTONIAN = {"coords": ["theta"], "known": ["m", "R", "omega", "g"], "name": "H", "h_is_energy": False}
SPHERICAL_COORDS = {"coords": ["theta", "phi"], "known": ["m", "g", "l"]}
L_SPHERICAL = "1/2 m l^2 (thetadot^2 + sin(theta)^2 phidot^2) + m g l cos(theta)"
MAGNETIC = {"coords": ["x", "y"], "known": ["m", "q", "B"]}
L_MAGNETIC = "1/2 m (xdot^2 + ydot^2) + 1/2 q B (x ydot - y xdot)"

KINETIC_ALONE = [
    # (expected, submitted, kind, setting, status, feedback): T alone before H, where H = T + V, whose velocities
    # H's are not (before, right)
    (H_SPHERICAL, "T = m l² (θ̇² + sin²θ φ̇²) ⇒ H = ½ m l² (θ̇² + sin²θ φ̇²) − m g l cos θ", "expression", SPHERICAL,
     "undecided",
     ("Your working gives T, but H − T with the value your answer gives H depends on the velocities, which a"
      f" potential energy V does not: so H = T + V cannot hold.{CHECKED}", T_READ)),
    # a charge in a magnetic field, whose L has q A·v, linear in the velocities: only the rest is told
    (L_MAGNETIC, "T = m (ẋ² + ẏ²); L = ½ m (ẋ² + ẏ²) + ½ q B (x ẏ − y ẋ)", "lagrangian", MAGNETIC, "undecided",
     ("Your working gives T, but T − L with the value your answer gives L depends on the velocities other than"
      f" linearly, which a potential energy V does not: so L = T − V cannot hold.{CHECKED}", T_READ)),
    (L_MAGNETIC, "U = ½ m ẋ²; L = ½ m (ẋ² + ẏ²) + ½ q B (x ẏ − y ẋ)", "lagrangian", MAGNETIC, "undecided",
     (f"Your working gives U, which depends on the velocities other than linearly: a potential energy does"
      f" not.{CHECKED}", "The line that defines `U` was read as your working, not as your answer.")),
    # their right twins: as before; and on the hoop, where H is not T + V, H − T may move with θ̇
    (H_SPHERICAL, "T = ½ m l² (θ̇² + sin²θ φ̇²) ⇒ H = ½ m l² (θ̇² + sin²θ φ̇²) − m g l cos θ", "expression",
     SPHERICAL, "equivalent", ("Correct.", T_READ)),
    (L_MAGNETIC, "T = ½ m (ẋ² + ẏ²); L = ½ m (ẋ² + ẏ²) + ½ q B (x ẏ − y ẋ)", "lagrangian", MAGNETIC, "equivalent",
     ("Correct.", T_READ)),
    (L_MAGNETIC, "U = −½ q B (x ẏ − y ẋ); L = ½ m (ẋ² + ẏ²) + ½ q B (x ẏ − y ẋ)", "lagrangian", MAGNETIC,
     "equivalent", ("Correct.", "The line that defines `U` was read as your working, not as your answer.")),
    # on the spherical pendulum: + m l² φ̇ is d/dt(m l² φ), and gives L's equations; + m l² θ φ̇ in T is no
    # derivative, as ∂(m l² θ)/∂θ is not ∂0/∂φ, so T − L is no V and no such derivative
    (L_SPHERICAL, "T = ½ m l² (θ̇² + sin²θ φ̇²); L = ½ m l² (θ̇² + sin²θ φ̇²) + m g l cos θ + m l² φ̇", "lagrangian",
     SPHERICAL_COORDS, "equivalent", ("Correct: your Lagrangian gives the same equations of motion.", T_READ)),
    (L_SPHERICAL, "T = ½ m l² (θ̇² + sin²θ φ̇²) + m l² θ φ̇; L = ½ m l² (θ̇² + sin²θ φ̇²) + m g l cos θ", "lagrangian",
     SPHERICAL_COORDS, "undecided", (f"{KINETIC_MOVES}{CHECKED}", T_READ)),
    ("1/2 m R^2 (thetadot^2 - omega^2 sin(theta)^2) - m g R cos(theta)",
     "T = ½ m R² (θ̇² + ω² sin²θ) ⇒ H = ½ m R² (θ̇² − ω² sin²θ) − m g R cos θ", "expression", HOOP_HAMILTONIAN,
     "equivalent", ("Correct.", T_READ)),
]  # fmt: skip


@pytest.mark.parametrize(("expected", "submitted", "kind", "setting", "status", "feedback"), KINETIC_ALONE)
def test_a_kinetic_energy_alone_whose_velocities_the_value_does_not_have_goes_to_a_person(
    expected, submitted, kind, setting, status, feedback
):
    verdict = compare(expected, submitted, kind=kind, **setting)
    assert (verdict.status, verdict.feedback) == (status, feedback), verdict


EOM_PENDULUM = "m l^2 thetaddot + m g l sin(theta) = 0"
SMALL_PENDULUM = "thetaddot = -(g/l) theta"
EOM_DOUBLE = (
    "(m1 + m2) l1 theta1ddot + m2 l2 theta2ddot cos(theta1 - theta2) + m2 l2 theta2dot^2 sin(theta1 - theta2)"
    " + (m1 + m2) g sin(theta1) = 0;"
    " l2 theta2ddot + l1 theta1ddot cos(theta1 - theta2) - l1 theta1dot^2 sin(theta1 - theta2) + g sin(theta2) = 0"
)
L_DOUBLE_WRONG = L_DOUBLE.replace("1/2 (m1 + m2) l1^2", "1/2 m1 l1^2")
DISAGREES = "but Lagrange's equation with {} does not give the equation of motion your answer gives. Your equation"
FOR_A_PERSON = " was graded and is right; a person will check this answer."
DISAGREE = "but Lagrange's equations with it do not give the equations of motion your answer gives."
FOR_A_PERSON_ALL = " Your equations were graded and are right; a person will check this answer."
SPHERE = {"coords": ["theta", "phi"], "known": ["m", "g", "l"]}
EOM_SPHERICAL = "l θ̈ − l sin θ cos θ φ̇² + g sin θ = 0; sin²θ φ̈ + 2 sin θ cos θ θ̇ φ̇ = 0"
L_DOUBLE_NO_CROSS = (
    "1/2 m1 l1^2 theta1dot^2 + 1/2 m2 l1^2 theta1dot^2 + 1/2 m2 l2^2 theta2dot^2 + m1 g l1 cos(theta1)"
    " + m2 g l1 cos(theta1) + m2 g l2 cos(theta2)"
)
L_UNFOLLOWED = "sqrt(1 + θ̇₁² + θ̇₂² + θ̇₁ θ̇₂ cos(θ₁ − θ₂))^(3/2) log(2 + cos θ₁)"
L_READ = "The line that defines `L` was read as your working, not as your answer."
L_AND_F_READ = "The lines that define `F` and `L` were read as your working, not as your answer."

LAGRANGIAN_IN_THE_WORKING = [
    # (expected, submitted, setting, kind, status, feedback): working that states a Lagrangian (or T and V, or
    # L and Rayleigh's F), then a right equation of motion that Lagrange's equation with it does not give
    (EOM_PENDULUM, f"L = m l^2 thetadot^2 - m g l cos(theta); {EOM_PENDULUM}", PENDULUM, "equation", "undecided",
     (f"Your working gives L, {DISAGREES.format('it')}{FOR_A_PERSON}", L_READ)),
    # a sentence that defines L before the equation: its L was read as working, and no value of it judged
    (EOM_PENDULUM, "With L = ½ m l² θ̇² − m g l cos θ: m l² θ̈ = −m g l sin θ", PENDULUM, "equation", "undecided",
     (f"Your working gives L, {DISAGREES.format('it')}{FOR_A_PERSON}", L_READ)),
    (EOM_PENDULUM, f"T = 1/2 m l^2 thetadot^2; V = m g l cos(theta); {EOM_PENDULUM}", PENDULUM, "equation",
     "undecided", (f"Your working gives T − V, {DISAGREES.format('it')}{FOR_A_PERSON}", WORKING_READ)),
    (EOM_DOUBLE, f"L = {L_DOUBLE_WRONG}; {EOM_DOUBLE}", DOUBLE, "equations", "undecided",
     (f"Your working gives L, {DISAGREE}{FOR_A_PERSON_ALL}", L_READ)),
    (EOM_SPHERICAL, f"L = ½ m l² (θ̇² + φ̇²) + m g l cos θ; {EOM_SPHERICAL}", SPHERE, "equations", "undecided",
     (f"Your working gives L, {DISAGREE}{FOR_A_PERSON_ALL}", L_READ)),
    (EOM_SPHERICAL, f"L = m g l cos θ; {EOM_SPHERICAL}", SPHERE, "equations", "undecided",
     (f"Your working gives L, {DISAGREE}{FOR_A_PERSON_ALL}", L_READ)),
    (EOM_HOOP, "L = ½ m R² θ̇² + m g R cos θ; R θ̈ = R ω² sin θ cos θ − g sin θ", HOOP, "equation", "undecided",
     (f"Your working gives L, {DISAGREES.format('it')}{FOR_A_PERSON}", L_READ)),
    # the same after `so`, `therefore` or ⇒, where the parser keeps only a derivation's conclusion (probe-k);
    # an L and two equations run past the 400 characters a Lagrangian part reads again after a step
    (EOM_SPHERICAL, f"L = ½ m l² (θ̇² + φ̇²) + m g l cos θ, so {EOM_SPHERICAL}", SPHERE, "equations", "undecided",
     (f"Your working gives L, {DISAGREE}{FOR_A_PERSON_ALL}", L_READ)),
    (EOM_DOUBLE, f"L = {L_DOUBLE_NO_CROSS}, therefore {EOM_DOUBLE}", DOUBLE, "equations", "undecided",
     (f"Your working gives L, {DISAGREE}{FOR_A_PERSON_ALL}", L_READ)),
    (EOM_DOUBLE, f"L = {L_UNFOLLOWED}; {EOM_DOUBLE}", DOUBLE, "equations", "undecided",
     (f"Your working gives L, {DISAGREE}{FOR_A_PERSON_ALL}", L_READ)),
    # an L whose equation cannot be compared with the answer's (|θ| has no derivative at 0): not taken on
    # trust either (before, the answer was right)
    (EOM_PENDULUM, f"L = {L_PENDULUM} + m g l |theta|; {EOM_PENDULUM}", PENDULUM, "equation", "undecided",
     ("Your working gives L, but your equation could not be checked against Lagrange's equation with it. Your"
      f" equation{FOR_A_PERSON}", L_READ)),
    (EOM_DAMPED, f"L = m xdot^2 + 1/2 k x^2; {EOM_DAMPED}", DAMPED, "equation", "undecided",
     (f"Your working gives L, {DISAGREES.format('it')}{FOR_A_PERSON}", L_READ)),
    (EOM_DAMPED, f"L = 1/2 m xdot^2 - 1/2 k x^2; F = b xdot^2; {EOM_DAMPED}", DAMPED, "equation", "undecided",
     (f"Your working gives L and F, {DISAGREES.format('them')}{FOR_A_PERSON}", L_AND_F_READ)),
    # a wrong equation after a wrong L: wrong, and told the L is no help either
    (EOM_PENDULUM, "L = m l^2 thetadot^2 - m g l cos(theta); m l^2 thetaddot - m g l sin(theta) = 0", PENDULUM,
     "equation", "not_equivalent",
     ("A term differs: the term in sin(θ) has the wrong sign.",
      "Your working gives L, but Lagrange's equation with it does not give a right equation of motion either.",
      L_READ)),
    # a right L, or one off by a constant, a factor or d/dt of a function of θ and t, and the friction's F or
    # none: as before
    (EOM_PENDULUM, f"L = {L_PENDULUM}; {EOM_PENDULUM}", PENDULUM, "equation", "equivalent", ("Correct.", L_READ)),
    (EOM_PENDULUM, f"L = m l^2 thetadot^2 + 2 m g l cos(theta) + 7; {EOM_PENDULUM}", PENDULUM, "equation",
     "equivalent", ("Correct.", L_READ)),
    (EOM_PENDULUM, f"L = {L_PENDULUM} + m l^2 sin(theta) thetadot; thetaddot + g/l sin(theta) = 0", PENDULUM,
     "equation", "equivalent", ("Correct.", L_READ)),
    (EOM_PENDULUM, f"T = 1/2 m l^2 thetadot^2; V = -m g l cos(theta); {EOM_PENDULUM}", PENDULUM, "equation",
     "equivalent", ("Correct.", WORKING_READ)),
    (EOM_DOUBLE, f"L = {L_DOUBLE}; {EOM_DOUBLE}", DOUBLE, "equations", "equivalent", ("Correct.", L_READ)),
    (EOM_DOUBLE, f"L = {L_DOUBLE}, so {EOM_DOUBLE}", DOUBLE, "equations", "equivalent", ("Correct.", L_READ)),
    (EOM_SPHERICAL, f"L = m l² (θ̇² + sin²θ φ̇²) + 2 m g l cos θ, so {EOM_SPHERICAL}", SPHERE, "equations",
     "equivalent", ("Correct.", L_READ)),
    (EOM_HOOP, "L = ½ m R² (θ̇² + ω² sin²θ) + m g R cos θ ⇒ m R² θ̈ = m R² ω² sin θ cos θ − m g R sin θ ⇒ R θ̈ ="
     " R ω² sin θ cos θ − g sin θ", HOOP, "equation", "equivalent", ("Correct.", L_READ)),
    (EOM_DAMPED, f"L = 1/2 m xdot^2 - 1/2 k x^2; {EOM_DAMPED}", DAMPED, "equation", "equivalent", ("Correct.", L_READ)),
    (EOM_DAMPED, f"L = m xdot^2 - k x^2; {EOM_DAMPED}", DAMPED, "equation", "equivalent", ("Correct.", L_READ)),
    (EOM_DAMPED, f"L = 1/2 m xdot^2 - 1/2 k x^2; F = 1/2 b xdot^2; {EOM_DAMPED}", DAMPED, "equation", "equivalent",
     ("Correct.", L_AND_F_READ)),
    # the pendulum's own L, then the small-angle equation asked for: its equation linearized, a derivation
    # (before, for a person); an L that does not give the full one still goes to a person
    (SMALL_PENDULUM, f"L = {L_PENDULUM}; {SMALL_PENDULUM}", PENDULUM, "equation", "equivalent", ("Correct.", L_READ)),
    (SMALL_PENDULUM, f"L = {L_PENDULUM.replace('+ m g l', '+ 2 m g l')}; {SMALL_PENDULUM}", PENDULUM, "equation",
     "undecided", (f"Your working gives L, {DISAGREES.format('it')}{FOR_A_PERSON}", L_READ)),
    # an L before the step that has no value, which the reading dropped unseen (before, right)
    (EOM_SPHERICAL, f"L = 1/0 ⇒ {EOM_SPHERICAL}", SPHERE, "equations", "undecided",
     ("Your answer says `L = 1/0` before the equations it gives, as what it follows from, but that has no value: it"
      " divides by zero, or is otherwise undefined. The equations were graded and are right; a person will check"
      " this answer.",)),
]  # fmt: skip


@pytest.mark.parametrize(("expected", "submitted", "setting", "kind", "status", "feedback"), LAGRANGIAN_IN_THE_WORKING)
def test_a_lagrangian_in_the_working_that_does_not_give_the_equation_goes_to_a_person(
    expected, submitted, setting, kind, status, feedback
):
    verdict = compare(expected, submitted, kind=kind, **setting)
    assert (verdict.status, verdict.feedback) == (status, feedback), verdict


GIVEN_VALUES = {"coords": ["theta"], "known": ["m", "g", "l"], "values": {"l": 1.00, "g": 9.81}}

WORKED_IN_SYMBOLS = [
    # (submitted, status, feedback): the period for l = 1.00 m and g = 9.81 m/s², worked in the problem's names
    # first: read at those values, working that does not come to the number goes to a person, as in numbers
    ("T = 2 pi sqrt(g/l) = 2.006 s", "undecided",
     ("Your final value, `2.006 s`, was graded and is right, but your working, `T = 2 pi sqrt(g/l) = 2.006 s`,"
      " does not hold: a person will check this answer.",)),
    ("T = 2π√(g/l); T = 2.006 s", "undecided",
     ("Your final value, `2.006 s`, was graded and is right, but your working, `T = 2π√(g/l) = 2.006 s`, does not"
      " hold: a person will check this answer.",
      "Your 2 lines, each `T = …`, were read as one chain, T = … = …: its last side was graded.")),
    ("T = 2 pi sqrt(l/g) = 2.5 s", "not_equivalent",
     ("Not within the accepted tolerance.",
      "Graded your final value, `2.5 s`; your working, `T = 2 pi sqrt(l/g) = 2.5 s`, does not hold.")),
    # working that comes to it: as before; and the formula alone is still no number
    ("T = 2 pi sqrt(l/g) = 2.006 s", "equivalent",
     ("Correct.", "Graded your final value, `2.006 s`; the working before it is not graded.")),
    ("T = 2π√(l/g) = 2π√(1/9.81) ≈ 2.01 s", "equivalent",
     ("Correct.", "Graded your final value, `2.01 s`; the working before it is not graded.")),
    ("T = 2 pi sqrt(l/g)", "invalid", ("A number is asked for here; your answer contains `g` and `l`.",)),
    # a name the problem gives no value: not read, as before
    ("T = 2 pi sqrt(m/g) = 2.006 s", "equivalent",
     ("Correct.", "Graded your final value, `2.006 s`; the working before it is not graded.")),
    # values the answer gives the names itself are the ones its working uses: read past, the working held at
    # the problem's, and the answer was right though at its own values it comes to 2.837 s, or 1.405 s
    ("T = 2π√(l/g) = 2.006 s, where l = 2 m", "undecided",
     ("Your final value, `2.006 s`, was graded and is right, but your working, `T = 2π√(l/g) = 2.006 s, where l ="
      " 2 m`, does not hold: a person will check this answer.",)),
    ("T = 2π√(l/g) = 2.006 s, where l = 1 m", "equivalent",
     ("Correct.", "Graded your final value, `2.006 s`; the working before it is not graded.",
      "Graded the number `2.006 s`; what follows it (`where l = 1 m`) is not graded.")),
    ("T = 2π√(l/g) = 2.006 s, where g = 20", "undecided",
     ("Your final value, `2.006 s`, was graded and is right, but your working, `T = 2π√(l/g) = 2.006 s, where g ="
      " 20`, does not hold: a person will check this answer.",)),
    ("T = 2π√(l/g) = 2.006 s, where g = 9.81 m/s^2", "equivalent",
     ("Correct.", "Graded your final value, `2.006 s`; the working before it is not graded.",
      "Graded the number `2.006 s`; what follows it (`where g = 9.81 m/s^2`) is not graded.")),
    ("T = 2π√(l/g) = 2.006 s, l = 2 m, g = 9.81 m/s^2", "undecided",
     ("Your final value, `2.006 s`, was graded and is right, but your working, `T = 2π√(l/g) = 2.006 s, l = 2 m,"
      " g = 9.81 m/s^2`, does not hold: a person will check this answer.",)),
    ("T = 2π√(l/g) = 2.006 s, l = 100 cm, g = 9.81 m/s^2", "equivalent",
     ("Correct.", "Graded your final value, `2.006 s`; the working before it is not graded.",
      "Graded `T = 2π√(l/g) = 2.006 s`, your value in s; the rest of your answer (`l = 100 cm, g = 9.81 m/s^2`) is"
      " not graded.")),
    ("l = 2 m; T = 2π√(l/g) = 2.006 s", "undecided",
     ("Your final value, `2.006 s`, was graded and is right, but your working, `l = 2 m; T = 2π√(l/g) = 2.006 s`,"
      " does not hold: a person will check this answer.",)),
    ("l = 1 m; T = 2π√(l/g) = 2.006 s", "equivalent",
     ("Correct.", "Graded your final value, `2.006 s`; the working before it is not graded.",
      "Graded `T = 2π√(l/g) = 2.006 s`, your value in s; the rest of your answer (`l = 1 m`) is not graded.")),
    # a wrong number its working comes to at the student's own values: told so, not that the working does not
    # hold, nor that the values were not graded (before, both); only the values that differ are named
    ("T = 2π√(l/g) = 2.837 s, where l = 2 m", "not_equivalent",
     ("Not within the accepted tolerance.",
      "Your working holds with the value you gave `l`, not with the one the problem gives.")),
    ("T = 2π√(l/g) = 1.8 s, where l = 0.9 m and g = 10.9", "not_equivalent",
     ("Not within the accepted tolerance.",
      "Your working holds with the values you gave `g` and `l`, not with the ones the problem gives.")),
    ("T = 2π√(l/g) = 2.837 s, where l = 2 m and g = 9.81", "not_equivalent",
     ("Not within the accepted tolerance.",
      "Your working holds with the value you gave `l`, not with the one the problem gives.")),
    # nor at them: one note on the working, not two (before, the chain's and the where clause's)
    ("T = 2π√(l/g) = 3.5 s, where l = 2 m", "not_equivalent",
     ("Not within the accepted tolerance.",
      "Graded your final value, `3.5 s`; your working, `T = 2π√(l/g) = 3.5 s, where l = 2 m`, does not hold.")),
]  # fmt: skip


@pytest.mark.parametrize(("submitted", "status", "feedback"), WORKED_IN_SYMBOLS)
def test_working_in_names_the_problem_gives_values_is_read_at_them(submitted, status, feedback):
    verdict = compare(PERIOD, submitted, kind="number", rtol=0.005, unit="s", **GIVEN_VALUES)
    assert (verdict.status, verdict.feedback) == (status, feedback), verdict


@pytest.mark.parametrize(
    ("submitted", "status", "feedback"),
    [
        # the asked quantity given another value beside the one graded (before, right)
        ("2.006 s, where T = 3.13 s", "undecided",
         ("Your final value, `2.006 s`, was graded and is right, but your working, `2.006 s, where T = 3.13 s`,"
          " does not hold: a person will check this answer.",)),
        ("2.006 s, where T = 2.006 s", "equivalent",
         ("Correct.", "Graded the number `2.006 s`; what follows it (`where T = 2.006 s`) is not graded.")),
    ],
)  # fmt: skip
def test_the_asked_quantity_given_another_value_beside_the_number_goes_to_a_person(submitted, status, feedback):
    verdict = compare(PERIOD, submitted, kind="number", rtol=0.005, unit="s", name=["T"], **GIVEN_VALUES)
    assert (verdict.status, verdict.feedback) == (status, feedback), verdict


L_HOOP = "1/2 m R^2 thetadot^2 + 1/2 m R^2 omega^2 sin(theta)^2 + m g R cos(theta)"
HOOP_LAGRANGIAN = {**HOOP, "h_is_energy": False}
ON_THE_WAY = (
    "on the way to its value, which is not what L is. Its value was graded and is right; a person will check"
    " this answer."
)

LAGRANGIAN_FROM_H = [
    # (submitted, setting, status, feedback): where H is not the energy (a hoop turned at a fixed rate, where
    # H = T₂ − T₀ + V), L = 2T − H is a false identity on the way to a right value (before, right)
    (f"L = 2T - H = {L_HOOP}", HOOP_LAGRANGIAN, "undecided", (f"Your answer says `L = 2T - H` {ON_THE_WAY}",)),
    (f"L = H - 2V = {L_HOOP}", HOOP_LAGRANGIAN, "undecided", (f"Your answer says `L = H - 2V` {ON_THE_WAY}",)),
    # true on the hoop too: E is T + V, and L = p θ̇ − H is the Legendre transform; and where H is the energy
    (f"L = 2T - E = {L_HOOP}", HOOP_LAGRANGIAN, "equivalent", ("Correct.",)),
    (f"L = p_theta thetadot - H = {L_HOOP}", HOOP_LAGRANGIAN, "equivalent", ("Correct.",)),
    (f"L = T - V = {L_HOOP}", HOOP_LAGRANGIAN, "equivalent", ("Correct.",)),
    (f"L = 2T - H = {L_PENDULUM}", PENDULUM, "equivalent", ("Correct.",)),
]  # fmt: skip


@pytest.mark.parametrize(("submitted", "setting", "status", "feedback"), LAGRANGIAN_FROM_H)
def test_l_as_2t_minus_h_where_h_is_not_the_energy_goes_to_a_person(submitted, setting, status, feedback):
    expected = L_PENDULUM if setting is PENDULUM else L_HOOP
    verdict = compare(expected, submitted, kind="lagrangian", **setting)
    assert (verdict.status, verdict.feedback) == (status, feedback), verdict


L_SPHERICAL = "1/2 m l^2 (thetadot^2 + sin(theta)^2 phidot^2) + m g l cos(theta)"
L_SPHERICAL_WRONG = "m l^2 (thetadot^2 + sin(theta)^2 phidot^2) + m g l cos(theta)"
P_PHI = "m l^2 sin(theta)^2 phidot"
MOMENTUM_SPHERICAL = {**SPHERICAL, "name": "p_phi"}
DERIVED = (
    "with it is not the value your answer gives. Its value was graded and is right; a person will check this answer."
)
SPHERICAL_L_READ = "The line that defines `L` was read as your working, not as your answer."

Q_R = "m g cos(theta) - k (r - l0)"
FORCES = {"coords": ["r", "theta"], "known": ["m", "g", "k", "l0"], "name": "Q_r"}
V_READ = "The line that defines `V` was read as your working, not as your answer."
H_HOOP = "1/2 m R^2 (thetadot^2 - omega^2 sin(theta)^2) - m g R cos(theta)"
HOOP_H = {**HOOP, "name": "H"}

COMMA_REFUSED = (
    "A comma is not understood here. Write decimals with a point (0.5); list equations as [eq1, eq2] or on separate"
    " lines."
)
DERIVED_FROM_L = [
    # (expected, submitted, setting, status, feedback): working that states L, then the momentum or the
    # Hamiltonian asked for, which that L does not give; or V, then a generalized force (before, right)
    (P_PHI, f"L = {L_SPHERICAL_WRONG}; p_phi = {P_PHI}", MOMENTUM_SPHERICAL, "undecided",
     (f"Your working gives L, but ∂L/∂φ̇ {DERIVED}", SPHERICAL_L_READ)),
    # its ∂L/∂φ̇ said and worked out in a chain (probe-k)
    (P_PHI, "L = ½ m l² φ̇², p_φ = ∂L/∂φ̇ = m l² sin²θ φ̇", MOMENTUM_SPHERICAL, "undecided",
     (f"Your working gives L, but ∂L/∂φ̇ {DERIVED}", SPHERICAL_L_READ)),
    (H_SPHERICAL, f"L = {L_SPHERICAL_WRONG}; H = {H_SPHERICAL}", SPHERICAL, "undecided",
     (f"Your working gives L, but Σ p q̇ − L {DERIVED}", SPHERICAL_L_READ)),
    # the same after `so`, ⇒ or `therefore`, where the parser keeps only a derivation's conclusion
    (P_PHI, "L = ½ m l² φ̇², so p_φ = m l² sin²θ φ̇", MOMENTUM_SPHERICAL, "undecided",
     (f"Your working gives L, but ∂L/∂φ̇ {DERIVED}", SPHERICAL_L_READ)),
    (H_SPHERICAL, f"L = {L_SPHERICAL_WRONG} ⇒ H = {H_SPHERICAL}", SPHERICAL, "undecided",
     (f"Your working gives L, but Σ p q̇ − L {DERIVED}", SPHERICAL_L_READ)),
    (H_HOOP, "L = ½ m R² θ̇² + m g R cos θ, therefore H = ½ m R² (θ̇² − ω² sin²θ) − m g R cos θ", HOOP_H,
     "undecided", (f"Your working gives L, but Σ p q̇ − L {DERIVED}", SPHERICAL_L_READ)),
    (Q_R, f"V = m g r cos(theta) + 1/2 k (r - l0)^2, so Q_r = {Q_R}", FORCES, "undecided",
     (f"Your working gives V, but −∂V/∂r {DERIVED}", V_READ)),
    # the value alone after the step, named as the part asks
    (P_PHI, "L = ½ m l² φ̇² ⇒ m l² sin²θ φ̇", MOMENTUM_SPHERICAL, "undecided",
     (f"Your working gives L, but ∂L/∂φ̇ {DERIVED}", SPHERICAL_L_READ)),
    (Q_R, f"V = m g r cos(theta) + 1/2 k (r - l0)^2 ⇒ {Q_R}", FORCES, "undecided",
     (f"Your working gives V, but −∂V/∂r {DERIVED}", V_READ)),
    (Q_R, f"V = m g r cos(theta) + 1/2 k (r - l0)^2; Q_r = {Q_R}", FORCES, "undecided",
     (f"Your working gives V, but −∂V/∂r {DERIVED}", V_READ)),
    (Q_R, f"V = -m g r cos(theta) + 1/2 k r^2; Q_r = {Q_R}", FORCES, "undecided",
     (f"Your working gives V, but −∂V/∂r {DERIVED}", V_READ)),
    # the L (V) that gives them, or that plus a constant: as before
    (Q_R, f"V = -m g r cos(theta) + 1/2 k (r - l0)^2 + 7; Q_r = {Q_R}", FORCES, "equivalent", ("Correct.", V_READ)),
    (P_PHI, f"L = {L_SPHERICAL}; p_phi = {P_PHI}", MOMENTUM_SPHERICAL, "equivalent", ("Correct.", SPHERICAL_L_READ)),
    (H_SPHERICAL, f"L = {L_SPHERICAL} + 5 m g l; H = {H_SPHERICAL}", SPHERICAL, "equivalent",
     ("Correct.", SPHERICAL_L_READ)),
    (P_PHI, f"L = {L_SPHERICAL}, so p_φ = {P_PHI}", MOMENTUM_SPHERICAL, "equivalent", ("Correct.", SPHERICAL_L_READ)),
    (H_SPHERICAL, f"L = {L_SPHERICAL} ⇒ H = {H_SPHERICAL}", SPHERICAL, "equivalent", ("Correct.", SPHERICAL_L_READ)),
    (H_HOOP, f"L = {L_HOOP}, therefore H = {H_HOOP}", HOOP_H, "equivalent", ("Correct.", SPHERICAL_L_READ)),
    (Q_R, f"V = -m g r cos(theta) + 1/2 k (r - l0)^2, so Q_r = {Q_R}", FORCES, "equivalent", ("Correct.", V_READ)),
    (P_PHI, f"L = {L_SPHERICAL} ⇒ {P_PHI}", MOMENTUM_SPHERICAL, "equivalent", ("Correct.", SPHERICAL_L_READ)),
    (H_SPHERICAL, f"L = {L_SPHERICAL} ⇒ {H_SPHERICAL}", SPHERICAL, "equivalent", ("Correct.", SPHERICAL_L_READ)),
    # the value alone after `so` or `therefore`, as after ⇒ (before, refused: the comma was not understood)
    (P_PHI, f"L = {L_SPHERICAL}, so {P_PHI}", MOMENTUM_SPHERICAL, "equivalent", ("Correct.", SPHERICAL_L_READ)),
    (H_SPHERICAL, f"L = {L_SPHERICAL}, therefore {H_SPHERICAL}", SPHERICAL, "equivalent",
     ("Correct.", SPHERICAL_L_READ)),
    (P_PHI, f"L = {L_SPHERICAL}, so m l^2 sin(theta) phidot", MOMENTUM_SPHERICAL, "not_equivalent",
     ("Your answer depends on l, m and φ̇ as the right answer does, but on θ in another way: check how your answer"
      " depends on θ.", SPHERICAL_L_READ)),
    (P_PHI, "L = ½ m l² φ̇², so m l² sin²θ φ̇", MOMENTUM_SPHERICAL, "undecided",
     (f"Your working gives L, but ∂L/∂φ̇ {DERIVED}", SPHERICAL_L_READ)),
    # words between the step and the value are no factors of it: refused as typed, as before (then, `that` was
    # read as a name, and the right value scored 0)
    (P_PHI, f"L = {L_SPHERICAL}, so that {P_PHI}", MOMENTUM_SPHERICAL, "invalid", (COMMA_REFUSED,)),
    (P_PHI, f"L = {L_SPHERICAL}, so we get {P_PHI}", MOMENTUM_SPHERICAL, "invalid", (COMMA_REFUSED,)),
]  # fmt: skip


@pytest.mark.parametrize(("expected", "submitted", "setting", "status", "feedback"), DERIVED_FROM_L)
def test_a_lagrangian_in_the_working_that_does_not_give_the_momentum_goes_to_a_person(
    expected, submitted, setting, status, feedback
):
    verdict = compare(expected, submitted, kind="expression", **setting)
    assert (verdict.status, verdict.feedback) == (status, feedback), verdict


def test_the_asked_name_alone_after_a_lagrangian_is_shown_as_typed():
    # before, read as p_φ = p_φ: the name alone was named as the answer
    verdict = compare(P_PHI, f"L = {L_SPHERICAL} ⇒ p_phi", kind="expression", **MOMENTUM_SPHERICAL)
    assert (verdict.status, verdict.read_as) == ("not_equivalent", "p_φ"), verdict


PREMISE = (
    "before the equation it gives, as what that equation follows from, but the two do not agree. The equation was"
    " graded and is right; a person will check this answer."
)
L_WRONG = "L = m l^2 thetadot^2 - m g l cos(theta)"
UNDEFINED = (
    "before the equation it gives, as what it follows from, but that has no value: it divides by zero, or is"
    " otherwise undefined. The equation was graded and is right; a person will check this answer."
)
UNDEFINED_VALUE = (
    "before the value it gives, as what it follows from, but that has no value: it divides by zero, or is otherwise"
    " undefined. Its value was graded and is right; a person will check this answer."
)

PREMISES = [
    # (expected, submitted, status, feedback): an equation of motion, or an L, before a step (⇒, so) to the right
    # equation, which the reading leaves behind the step: where it does not give it, for a person (before, right)
    (EOM_PENDULUM, "m l^2 thetaddot = m g l sin(theta) ⇒ thetaddot = -(g/l) sin(theta)", "undecided",
     (f"Your answer says `m l^2 thetaddot = m g l sin(theta)` {PREMISE}",)),
    (EOM_PENDULUM, "m l^2 thetaddot - m g l sin(theta) = 0, so thetaddot + (g/l) sin(theta) = 0", "undecided",
     (f"Your answer says `m l^2 thetaddot - m g l sin(theta) = 0` {PREMISE}",)),
    # an L: working, which must give the equation, as after a semicolon
    (EOM_PENDULUM, f"{L_WRONG} ⇒ {EOM_PENDULUM}", "undecided",
     (f"Your working gives L, {DISAGREES.format('it')}{FOR_A_PERSON}", L_READ)),
    (EOM_PENDULUM, f"{L_WRONG}, so {EOM_PENDULUM}", "undecided",
     (f"Your working gives L, {DISAGREES.format('it')}{FOR_A_PERSON}", L_READ)),
    (EOM_PENDULUM, f"{L_WRONG} ⇒ m l^2 thetaddot = -m g l sin(theta) ⇒ thetaddot = -(g/l) sin(theta)", "undecided",
     (f"Your working gives L, {DISAGREES.format('it')}{FOR_A_PERSON}", L_READ)),
    # a premise that gives it, or the full form before the small-angle one asked for: as before
    (EOM_PENDULUM, "m l thetaddot = -m g sin(theta) ⇒ thetaddot = -(g/l) sin(theta)", "equivalent", ("Correct.",)),
    (EOM_PENDULUM, f"L = {L_PENDULUM} ⇒ {EOM_PENDULUM}", "equivalent", ("Correct.", L_READ)),
    ("thetaddot = -(g/l) theta", "thetaddot = -(g/l) sin(theta) ⇒ thetaddot = -(g/l) theta", "equivalent",
     ("Correct.",)),
    (SMALL_PENDULUM, f"L = {L_PENDULUM} ⇒ {SMALL_PENDULUM}", "equivalent", ("Correct.", L_READ)),  # before, a person
    (SMALL_PENDULUM, f"{L_WRONG} ⇒ {SMALL_PENDULUM}", "undecided",
     (f"Your working gives L, {DISAGREES.format('it')}{FOR_A_PERSON}", L_READ)),
    # a premise with no value, which the reading dropped unseen (before, right)
    (EOM_PENDULUM, f"L = 1/0 ⇒ {EOM_PENDULUM}", "undecided", (f"Your answer says `L = 1/0` {UNDEFINED}",)),
    (EOM_PENDULUM, f"m l^2 thetaddot = -m g l sin(theta)/(l - l) ⇒ {EOM_PENDULUM}", "undecided",
     (f"Your answer says `m l^2 thetaddot = -m g l sin(theta)/(l - l)` {UNDEFINED}",)),
]  # fmt: skip


@pytest.mark.parametrize(("expected", "submitted", "status", "feedback"), PREMISES)
def test_an_equation_after_a_step_from_one_it_does_not_follow_from_goes_to_a_person(
    expected, submitted, status, feedback
):
    verdict = compare(expected, submitted, kind="equation", **PENDULUM)
    assert (verdict.status, verdict.feedback) == (status, feedback), verdict


ATWOOD_ACCELERATION = {**ATWOOD, "name": ["xddot", "a", "a_1"]}
A_ATWOOD = "(m1 - m2) g/(m1 + m2)"
PREMISE_VALUE = (
    "before the value it gives, as what that value follows from, but the two do not agree. Its value was graded"
    " and is right; a person will check this answer."
)

PREMISES_OF_A_VALUE = [
    # (submitted, status, feedback): the acceleration asked for, after a step from an equation it does not
    # solve (before, right)
    (f"2 (m1 + m2) xddot = (m1 - m2) g, so xddot = {A_ATWOOD}", "undecided",
     (f"Your answer says `2 (m1 + m2) xddot = (m1 - m2) g` {PREMISE_VALUE}",)),
    (f"(m1 + m2) xddot = (m1 + m2) g ⇒ a = {A_ATWOOD}", "undecided",
     (f"Your answer says `(m1 + m2) xddot = (m1 + m2) g` {PREMISE_VALUE}",)),
    # an equation it solves: as before
    (f"(m1 + m2) xddot = (m1 - m2) g, so xddot = {A_ATWOOD}", "equivalent", ("Correct.",)),
    (f"(m1 + m2) xddot = (m1 - m2) g ⇒ a = {A_ATWOOD}", "equivalent", ("Correct.",)),
]  # fmt: skip


@pytest.mark.parametrize(("submitted", "status", "feedback"), PREMISES_OF_A_VALUE)
def test_a_value_after_a_step_from_an_equation_it_does_not_solve_goes_to_a_person(submitted, status, feedback):
    verdict = compare(A_ATWOOD, submitted, kind="expression", **ATWOOD_ACCELERATION)
    assert (verdict.status, verdict.feedback) == (status, feedback), verdict


L_WRONG_SIGN = "L = 1/2 m l^2 thetadot^2 - m g l cos(theta)"
PREMISES_OF_A_LAGRANGIAN = [
    # (submitted, status, feedback): the right L after a step from another (before, right)
    (f"{L_WRONG_SIGN} ⇒ L = {L_PENDULUM}", "undecided", (f"Your answer says `{L_WRONG_SIGN}` {PREMISE_VALUE}",)),
    (f"{L_WRONG_SIGN}, so L = {L_PENDULUM}", "undecided", (f"Your answer says `{L_WRONG_SIGN}` {PREMISE_VALUE}",)),
    # energies before the step: read as lines, judged as after `;`
    (f"T = 1/2 m l thetadot^2, V = -m g l cos(theta) => L = {L_PENDULUM}", "undecided",
     (f"{ENERGIES} Its value was graded and is right; a person will check this answer.", WORKING_READ)),
    # after one of the same motion, the energies whose difference it is, or names of the student's own: as before
    (f"L = {L_PENDULUM} + theta thetadot ⇒ L = {L_PENDULUM}", "equivalent", ("Correct.",)),
    (f"T = 1/2 m l^2 thetadot^2, V = m g l (1 - cos(theta)) => L = {L_PENDULUM}", "equivalent",
     ("Correct.", WORKING_READ)),
    (f"x = l sin(theta), y = -l cos(theta) => L = {L_PENDULUM}", "equivalent", ("Correct.",)),
    (f"L = T - V ⇒ L = {L_PENDULUM}", "equivalent", ("Correct.",)),
    # a formula with no name is a Lagrangian before another with none, and may be T before L = …
    ("1/2 m l^2 thetadot^2 ⇒ 1/2 m l^2 thetadot^2 + m g l cos(theta)", "undecided",
     (f"Your answer says `1/2 m l^2 thetadot^2` {PREMISE_VALUE}",)),
    (f"1/2 m l^2 thetadot^2 ⇒ L = {L_PENDULUM}", "equivalent", ("Correct.",)),
    # a premise with no value (it divides by zero, or takes log 0), which the reading dropped unseen (before, right)
    (f"L = 1/0 => L = {L_PENDULUM}", "undecided", (f"Your answer says `L = 1/0` {UNDEFINED_VALUE}",)),
    (f"T = 1/0 ⇒ L = {L_PENDULUM}", "undecided", (f"Your answer says `T = 1/0` {UNDEFINED_VALUE}",)),
    (f"T = 1/2 m l^2 thetadot^2, V = log(0) ⇒ L = {L_PENDULUM}", "undecided",
     (f"Your answer says `T = 1/2 m l^2 thetadot^2, V = log(0)` {UNDEFINED_VALUE}",)),
    # one the parser refuses for how it is written, as honest working may be (ẋ of a name of its own, a bracket
    # left open): read past, as before
    (f"L = 1/2 m l^2 thetadot^2 + m g l cos(theta ⇒ L = {L_PENDULUM}", "equivalent", ("Correct.",)),
    (f"T = ½ m (ẋ² + ẏ²), x = l sin θ, y = −l cos θ ⇒ L = {L_PENDULUM}", "equivalent", ("Correct.",)),
]  # fmt: skip


@pytest.mark.parametrize(("submitted", "status", "feedback"), PREMISES_OF_A_LAGRANGIAN)
def test_a_lagrangian_after_a_step_from_another_goes_to_a_person(submitted, status, feedback):
    verdict = compare(L_PENDULUM, submitted, kind="lagrangian", **PENDULUM)
    assert (verdict.status, verdict.feedback) == (status, feedback), verdict


QUALIFIED = "which may make it another number, or no one number: a person will decide what your answer is."


@pytest.mark.parametrize(
    ("expected", "submitted", "words"),
    [
        # a count per thing beside the count: for a person, who reads whether it is the total (before, refused
        # as words in a formula, and a right count scored 0 in a batch)
        ("15", "15 (3 per particle)", "per"),
        ("15", "15, 3 for each particle", "for each"),
        ("2", "2, one angle per bob", "per"),
        ("2", "2 (one angle each)", "each"),
    ],
)
def test_a_count_with_a_count_per_thing_beside_it_goes_to_a_person(expected, submitted, words):
    verdict = compare(expected, submitted, kind="integer", name="n")
    assert (verdict.status, verdict.feedback[0]) == (
        "undecided",
        f"Your number `{expected}` comes with `{words}`, {QUALIFIED}",
    ), verdict
