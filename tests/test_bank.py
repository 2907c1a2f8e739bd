"""The problem bank: every file loads and grades itself; broken files say what is wrong, and where.

Fixtures in tests/broken_problems/ have one defect each, named by the defect; the message each
must give is pinned here word for word, so a change of wording is a decision.
"""

from __future__ import annotations

import re
from pathlib import Path
from types import SimpleNamespace

import pytest

from grader import KINDS
from grader.bank import DIMENSIONS, PART_KINDS, load_assignment, load_bank, load_problem
from grader.grade import grade_answer, validate_bank
from grader.grade import part as grading
from grader.judge import Verdict, deadline
from grader.judge.units import DIMENSIONS as UNITS

ROOT = Path(__file__).resolve().parent.parent
BANK = ROOT / "problems"
BROKEN = Path(__file__).resolve().parent / "broken_problems"
PROBLEM_FILES = sorted(path for path in BANK.glob("*.yaml"))

BROKEN_MESSAGES = [
    # (file, problem, part, message)
    ("missing_schema_version", "", "", "line 1: missing field 'schema_version' (this grader reads schema_version 1)"),
    ("wrong_schema_version", "", "", "line 1: schema_version is 2; this grader reads 1"),
    ("not_yaml", "", "", "line 4: this is not valid YAML: expected ',' or ']', but got '<stream end>'"),
    ("bad_seed_id", "bad_seed_id", "", "line 4: seed item 'X9' is not an id such as S1, L16, A3 or E5"),
    ("id_does_not_match_file", "another-name", "",
     "line 2: the problem id is 'another-name' but the file is named 'id_does_not_match_file.yaml'; make them match"),
    ("unknown_kind", "unknown_kind", "lagrangian",
     "line 14: field 'kind' is 'lagrangean'; allowed: integer, number, choice, expression, equation, equations,"
     " lagrangian, text"),
    ("misspelled_field", "misspelled_field", "lagrangian",
     "line 16: unknown field 'anwser' in a part; allowed: answer, choices, derive_from, given, id, kind,"
     " method_credit, mistakes, options, points, prompt, rubric, tests"),
    ("negative_points", "negative_points", "lagrangian", "line 15: field 'points' is -2; points must be more than 0"),
    ("duplicate_part_id", "duplicate_part_id", "lagrangian",
     "line 18: part id 'lagrangian' is used twice in this problem"),
    ("derive_from_not_lagrangian", "derive_from_not_lagrangian", "motion",
     "line 25: derive_from is 'energy'; it must name a lagrangian part of this problem (lagrangian)"),
    ("option_not_for_kind", "option_not_for_kind", "energy",
     "line 22: option 'rtol' does not apply to kind 'expression' (its options: asks_more, h_is_energy, name,"
     " up_to_constant)"),
    ("option_not_yes_or_no", "option_not_yes_or_no", "energy", "line 22: h_is_energy is true or false, not 'no'"),
    ("asks_false_not_yes_or_no", "asks_false_not_yes_or_no", "false-statement",
     "line 10: asks_false is true or false, not 'yes'"),
    ("name_not_a_name", "name_not_a_name", "energy",
     "line 22: name is the quantity's name, or a list of names, as p_phi or [V, U]"),
    ("choice_answer_not_in_choices", "choice_answer_not_in_choices", "cyclic",
     "line 22: answer 'c' is not one of the choices (a, b)"),
    ("text_without_rubric", "text_without_rubric", "explain",
     "line 18: a text part needs a 'rubric': the ideas an answer must contain, with points and phrasings"),
    ("rubric_not_about_without_about", "rubric_not_about_without_about", "define",
     "line 13: not_about needs 'about': the words naming what this idea's phrasings describe"),
    ("rubric_term_about_and_not_about", "rubric_term_about_and_not_about", "define",
     "line 14: 'constraint' is in both about and not_about: a term is the idea's own subject or a rival, not both"),
    ("rubric_phrasing_gap_at_end", "rubric_phrasing_gap_at_end", "define",
     "line 13: phrasing 'not explicitly …' has a … with no words on one side; … stands for words between two"
     " others"),
    ("unreadable_reference", "unreadable_reference", "lagrangian",
     "The expected answer '1/2 m l^2 thetadot^2 + m g l cos(theta' cannot be read: Unbalanced bracket: the `(` at"
     " position 33 is never closed.\n…2 m l^2 thetadot^2 + m g l cos(theta\n                               ^"),
    ("mistake_equals_reference", "mistake_equals_reference", "lagrangian",
     "mistake 'L = 1/2 m l^2 θ̇^2 + m g l cos θ + 3' is equivalent to the reference answer"),
    ("given_on_choice", "given_on_choice", "cyclic",
     "line 14: given applies to kinds expression, equation, equations, lagrangian, not 'choice'"),
    ("given_undefined_name", "given_undefined_name", "hamiltonian",
     "the value given for 'p_theta' uses L, which the problem does not define"),
    ("unknown_dimension", "unknown_dimension", "",
     "line 10: field 'dimension' is 'metres'; allowed: dimensionless, angle, mass, length, time, area, velocity,"
     " acceleration, angular velocity, frequency, angular acceleration, momentum, angular momentum, moment of"
     " inertia, force, torque, energy, power, force per length, mass per time, pressure"),
    ("reference_units_mixed", "reference_units_mixed", "lagrangian",
     "in the reference answer, the terms have units kg·m/s² and kg·m²/s²: check it, or the dimensions of its"
     " symbols"),
    ("lagrangian_not_an_energy", "lagrangian_not_an_energy", "lagrangian",
     "a Lagrangian is an energy (kg·m²/s²), but the reference answer is measured in m²/s²"),
    ("lagrangian_without_motion", "lagrangian_without_motion", "motion",
     "no equations of motion follow from the Lagrangian 'm g l cos(theta)': they do not determine every"
     " acceleration (its second derivatives in the velocities are singular; is a kinetic term missing?)"),
    # YAML itself would keep the last answer, or expand aliases without end, or overflow the stack
    ("answer_given_twice", "", "",
     "line 17: field 'answer' is given a second time (first on line 16); YAML would silently keep only the last"),
    ("aliases_expand_too_far", "", "", "the file holds more than 100000 values once its aliases are expanded"),
    ("nested_too_deeply", "", "", "the file is nested too deeply to read"),
    ("field_name_a_list", "", "", "line 3: a field's name must be a word, not a list or a mapping"),  # was a TypeError
    ("test_gets_another_score", "test_gets_another_score", "lagrangian",
     "test '1/2 m l^2 thetadot^2' gets 0, not 1 (not_equivalent: A term is missing: a term in cos(θ).)"),
]  # fmt: skip


@pytest.mark.parametrize(
    ("name", "problem", "part", "message"), BROKEN_MESSAGES, ids=[row[0] for row in BROKEN_MESSAGES]
)
def test_a_broken_file_gets_a_message_for_its_author(name, problem, part, message):
    path = BROKEN / f"{name}.yaml"
    _, failures = validate_bank([path])
    assert [(f.path, f.problem, f.part, f.message) for f in failures] == [(str(path), problem, part, message)]


def test_every_broken_fixture_is_in_the_table():
    assert sorted(path.stem for path in BROKEN.glob("*.yaml")) == sorted(row[0] for row in BROKEN_MESSAGES)


def test_one_broken_file_does_not_stop_the_others_being_checked():
    problems, failures = validate_bank([BROKEN / "not_yaml.yaml", BANK / "plane-pendulum.yaml"])
    assert list(problems) == ["plane-pendulum"] and len(failures) == 1


@pytest.mark.parametrize("path", PROBLEM_FILES, ids=[path.stem for path in PROBLEM_FILES])
def test_each_bank_file_loads_and_grades_itself(path):
    problems, failures = validate_bank([path])
    assert [str(failure) for failure in failures] == []
    assert list(problems) == [path.stem]


def test_the_bank_validates_as_a_whole_with_its_assignments():
    problems, failures = validate_bank([BANK])
    assert [str(failure) for failure in failures] == []
    assert len(problems) == len(PROBLEM_FILES)


def test_the_bank_kinds_are_the_checkers_kinds():
    assert set(PART_KINDS) == set(KINDS)
    for kind, options in PART_KINDS.items():
        # options the bank lets authors set are options the checker accepts (choices and rubrics come from fields)
        assert options <= set(KINDS[kind].options) - {"options", "rubric"}, kind


def test_the_bank_dimensions_are_the_checkers_dimensions():
    assert tuple(UNITS) == DIMENSIONS


def test_every_symbol_of_a_mathematical_problem_has_a_dimension():
    # a wrong answer's units are checked only where every symbol in it has one
    for problem in load_bank(BANK).values():
        if any(part.kind in ("expression", "equation", "equations", "lagrangian") for part in problem.parts):
            symbols = (*problem.coordinates, *problem.parameters)
            assert all(symbol.dimension for symbol in symbols), problem.id


def test_every_kind_appears_in_the_bank():
    used = {part.kind for problem in load_bank(BANK).values() for part in problem.parts}
    assert used == set(KINDS)


SEED_IDS = (
    [f"S{i}" for i in range(1, 12)] + [f"L{i}" for i in range(1, 18)]
    + [f"A{i}" for i in range(1, 6)] + [f"E{i}" for i in range(1, 6)]
)  # fmt: skip


def test_every_seed_item_is_covered():
    covered = {item for problem in load_bank(BANK).values() for item in problem.seed}
    assert len(SEED_IDS) == 38
    assert sorted(set(SEED_IDS) - covered, key=lambda s: (s[0], int(s[1:]))) == []


def test_the_review_assignment_covers_the_review_questions():
    bank = load_bank(BANK)
    assignment = load_assignment(BANK / "assignments" / "review.yaml", bank)
    covered = {item for entry in assignment.items for item in bank[entry.problem].seed}
    review = {item for item in SEED_IDS if re.fullmatch(r"[SL]\d+", item)}
    assert review <= covered


def test_a_listed_mistake_gives_its_feedback_and_score():
    problem = load_bank(BANK)["plane-pendulum"]
    part = problem.part("lagrangian")
    verdict = grade_answer(problem, part, "1/2 m l^2 θ̇^2 - mgl cos θ")
    assert verdict.score == part.mistakes[0].score
    assert verdict.feedback == (part.mistakes[0].feedback,)
    assert verdict.diagnosis == "mistake"


def test_a_listed_mistake_is_matched_by_a_final_value_whose_working_does_not_hold():
    problem = load_bank(BANK)["degrees-of-freedom"]
    part = problem.part("double-pendulum")
    mistake = next(mistake for mistake in part.mistakes if str(mistake.answer) == "3")
    verdict = grade_answer(problem, part, "6 - 4 = 3")
    assert (verdict.status, verdict.diagnosis, verdict.score) == ("not_equivalent", "mistake", mistake.score)
    note = "Graded your final value, `3`; your working, `6 - 4 = 3`, does not hold."
    assert verdict.feedback == (mistake.feedback, note)


@pytest.mark.parametrize(
    ("problem", "part", "answers", "spent"),
    [
        ("rotating-hoop", "hamiltonian", None, 1.0),  # five mistakes listed
        ("plane-pendulum", "motion", {"plane-pendulum.lagrangian": "m g l cos θ"}, 1.0),  # and method credit
        ("rotating-hoop", "hamiltonian", None, 0.6),
    ],
)
def test_the_time_limit_bounds_the_verdict_its_mistakes_and_method_credit_together(
    monkeypatch, problem, part, answers, spent
):
    # a hostile answer that makes every check run out of time costs one time limit, not one per mistake
    now, given = [0.0], []

    def slow(expected, submitted, *, timeout, **options):  # each check takes a share of the time it is given
        given.append(timeout)
        now[0] += spent * timeout
        return Verdict("not_equivalent", 0.0, ("Not equivalent to the expected answer.",))

    monkeypatch.setattr(deadline, "time", SimpleNamespace(monotonic=lambda: now[0]))
    monkeypatch.setattr(grading, "compare", slow)
    problem = load_bank(BANK)[problem]
    verdict = grade_answer(problem, problem.part(part), "(m + R)^99 (g + R)^99", timeout=2.0, answers=answers)
    assert verdict.status == "not_equivalent" and now[0] <= 2.0
    if spent == 1.0:  # all of it: once the verdict has taken it, nothing more is tried
        assert given == [2.0]
    else:  # every mistake is tried, in the time the checks before it left
        left = [2.0 * (1 - spent) ** n for n in range(1 + len(problem.part(part).mistakes))]
        assert given == pytest.approx(left)


KINETIC_BEFORE_L = [
    # (problem, T, status): each Lagrangian part's T, then its reference L. A T whose velocities L's are not goes to
    # a person (before, right); the right T stays right, the hoop's ½ m R² ω² sin²θ, with no velocity, in it or
    # not (the T of the hoop's own frame)
    ("plane-pendulum", "1/2 m l^2 thetadot^2", "equivalent"),
    ("plane-pendulum", "m l^2 thetadot^2", "undecided"),
    ("atwood-machine", "1/2 m1 xdot^2 + 1/2 m2 xdot^2", "equivalent"),
    ("atwood-machine", "1/2 m1 xdot^2", "undecided"),
    ("damped-oscillator", "1/2 m xdot^2", "equivalent"),
    ("damped-oscillator", "m xdot^2", "undecided"),
    ("rotating-hoop", "1/2 m R^2 (thetadot^2 + omega^2 sin(theta)^2)", "equivalent"),
    ("rotating-hoop", "1/2 m R^2 thetadot^2", "equivalent"),
    ("rotating-hoop", "m R^2 thetadot^2 + 1/2 m R^2 omega^2 sin(theta)^2", "undecided"),
    ("spherical-pendulum", "1/2 m l^2 (thetadot^2 + sin(theta)^2 phidot^2)", "equivalent"),
    ("spherical-pendulum", "1/2 m l^2 (thetadot^2 + phidot^2)", "undecided"),
    ("double-pendulum", "1/2 (m1 + m2) l1^2 theta1dot^2 + 1/2 m2 l2^2 theta2dot^2"
     " + m2 l1 l2 theta1dot theta2dot cos(theta1 - theta2)", "equivalent"),
    ("double-pendulum", "1/2 (m1 + m2) l1^2 theta1dot^2 + 1/2 m2 l2^2 theta2dot^2", "undecided"),
    ("double-pendulum-equal", "m l^2 theta1dot^2 + 1/2 m l^2 theta2dot^2"
     " + m l^2 theta1dot theta2dot cos(theta1 - theta2)", "equivalent"),
    ("double-pendulum-equal", "m l^2 theta1dot^2 + 1/2 m l^2 theta2dot^2"
     " + m l^2 theta1dot theta2dot cos(theta1 + theta2)", "undecided"),
    ("double-pendulum-alpha-beta", "m l^2 alphadot^2 + 1/2 m l^2 betadot^2"
     " + m l^2 alphadot betadot cos(alpha - beta)", "equivalent"),
    ("double-pendulum-alpha-beta", "1/2 m l^2 alphadot^2 + 1/2 m l^2 betadot^2"
     " + m l^2 alphadot betadot cos(alpha - beta)", "undecided"),
]  # fmt: skip
KINETIC_MOVES = (
    "Your working gives T, but T − L with the value your answer gives L depends on the velocities, which a potential"
    " energy V does not: so L = T − V cannot hold. Its value was graded and is right; a person will check this"
    " answer."
)


@pytest.mark.parametrize(("problem", "kinetic", "status"), KINETIC_BEFORE_L)
def test_a_kinetic_energy_before_the_reference_lagrangian_is_held_against_it(problem, kinetic, status):
    problem = load_problem(BANK / f"{problem}.yaml")
    part = problem.part("lagrangian")
    verdict = grade_answer(problem, part, f"T = {kinetic} ⇒ L = {part.answer}")
    first = "Correct." if status == "equivalent" else KINETIC_MOVES
    assert (verdict.status, verdict.score, verdict.feedback[0]) == (status, 1.0, first), verdict


def test_a_listed_mistake_is_matched_by_a_value_with_words_beside_it():
    # the words are for a person where the value is right; where it is a mistake's, its hint is said
    problem = load_bank(BANK)["generalized-forces"]
    part = problem.part("q-theta")
    verdict = grade_answer(problem, part, "−m g sin θ, which is a force")
    assert (verdict.status, verdict.diagnosis) == ("not_equivalent", "mistake")
    note = "Read without the words `, which is a force`: the formula is what is graded."
    assert verdict.feedback == (part.mistakes[0].feedback, note)


def test_a_listed_mistake_keeps_how_the_answer_was_read():
    # the option's words matched option a, a listed mistake: its hint, and what "Holonomic" was read as
    problem = load_bank(BANK)["constraint-classification"]
    part = problem.part("rolling-disk-holonomic")
    verdict = grade_answer(problem, part, "Holonomic")
    assert verdict.feedback == (part.mistakes[0].feedback, "Read as the option you wrote out: a.")
    assert verdict.diagnosis == "mistake"


@pytest.mark.parametrize(
    ("submitted", "mistake"),
    [
        ("f = √(g/l)/(2π)", 1),  # the frequency under its own name: still its mistake
        ("ω = 2π√(l/g)\nf = √(g/l)/(2π)", 0),  # ω, the period's value: the period's mistake, not f's
        ("ω = √(l/g)\nT = 2π√(l/g)\nf = √(g/l)/(2π)", None),  # ω is wrong and no listed mistake: before, f's
    ],
)
def test_a_listed_mistake_is_matched_by_the_line_that_was_graded(submitted, mistake):
    problem = load_bank(BANK)["plane-pendulum"]
    part = problem.part("frequency")
    verdict = grade_answer(problem, part, submitted)
    assert verdict.status == "not_equivalent", verdict
    if mistake is None:
        assert verdict.diagnosis != "mistake", verdict
    else:
        assert verdict.feedback[0] == part.mistakes[mistake].feedback, verdict


def test_equations_of_motion_are_derived_from_the_lagrangian_part():
    problem = load_bank(BANK)["plane-pendulum"]
    assert grade_answer(problem, problem.part("motion"), "θ̈ = -(g/l) sin θ").equivalent
    assert not grade_answer(problem, problem.part("motion"), "θ̈ = -(g/l) θ").equivalent


def test_a_text_answer_always_waits_for_a_person_with_a_proposed_score():
    problem = load_bank(BANK)["plane-pendulum"]
    verdict = grade_answer(problem, problem.part("why-harmonic"), "Because of the small angle approximation.")
    assert verdict.status == "undecided" and verdict.score == 0.5
