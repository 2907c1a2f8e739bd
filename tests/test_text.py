"""The ``text`` kind's rubric: what it proposes, and what it must not be fooled into proposing.

A proposal is what a person starts from and, until one scores the answer, what the LMS gets:
a statement turned round (negated, or said of the rival term) must never earn the idea.
"""

from __future__ import annotations

import pytest

from grader import compare
from grader.judge.text import MAX_TEXT_LENGTH, rubric_score

CONSERVED = ("the momentum is conserved", 1.0, ("conserved",))

FOUND, NEGATED, ABSENT = (True, False), (False, True), (False, False)  # (found, discounted)
NEGATION = [
    # (text, phrasing, what becomes of the idea)
    ("its momentum is conserved", "conserved", FOUND),
    ("its momentum is not conserved", "conserved", NEGATED),
    ("its momentum is never conserved", "conserved", NEGATED),
    ("its momentum isn’t conserved", "conserved", NEGATED),  # a word processor's apostrophe
    ("there is no conserved momentum", "conserved", NEGATED),
    ("the momentum is non-conserved", "conserved", NEGATED),  # a negating prefix, hyphened or not
    ("the momentum is unconserved", "conserved", NEGATED),
    ("the constraint is time-independent", "dependent", NEGATED),
    ("it cannot in general be written as f(r, t) = 0", "f(r", NEGATED),  # six words before still reach
    ("they can't be written as f(r, t) = 0", "f(r", NEGATED),
    ("q does not appear in L, so its momentum is conserved", "conserved", FOUND),  # another clause
    ("q does not appear in L and its momentum is conserved", "conserved", FOUND),
    ("No. Its momentum is conserved.", "conserved", FOUND),  # another sentence
    ("a coordinate that does not appear in L has its momentum conserved", "conserved", FOUND),  # beyond reach
    ("it does not use scalar energies or generalized coordinates", "generalized coordinate", NEGATED),  # "or"
    ("it does not use vector forces but generalized coordinates", "generalized coordinate", FOUND),
    # the phrasing's own negation is its meaning; one before it, or in its gap, turns it round
    ("the constraint does not contain t explicitly", "not … explicitly", FOUND),
    ("the constraint doesn't explicitly contain t", "not ... explicitly", FOUND),
    ("the constraint contains t explicitly", "not … explicitly", ABSENT),
    ("it contains t explicitly", "contain … explicitly", FOUND),
    ("it does not contain t explicitly", "contain … explicitly", NEGATED),
    ("it contains no t explicitly", "contain … explicitly", NEGATED),
    ("it contains the coordinates, and t explicitly", "contain … explicitly", ABSENT),  # a gap stays in its clause
    ("the momentum does not change", "does not change", FOUND),
    ("the momentum doesn't change", "does not change", FOUND),
    # brackets hold formulas and asides, whose commas end nothing
    ("the momentum (p_k, not q̇_k) is conserved", "conserved", FOUND),
    ("it is not (in general, for any system) conserved", "conserved", NEGATED),
    ("e.g. not a pendulum, but conserved", "conserved", FOUND),
]


@pytest.mark.parametrize(("text", "phrasing", "outcome"), NEGATION)
def test_a_negated_phrasing_earns_nothing(text, phrasing, outcome):
    reading = rubric_score(text, [(*CONSERVED[:2], (phrasing,))])
    assert (bool(reading.found), bool(reading.discounted)) == outcome


# the two ideas of "define scleronomic and rheonomic", each tied to the term it describes
SCLERONOMIC = ("scleronomic: no explicit t", 1.0, ("time independent", "time-independent", "not … explicitly"),
               ("scleronom",), ("rheonom",))  # fmt: skip
RHEONOMIC = ("rheonomic: explicit t", 1.0, ("time dependent", "time-dependent", "contain … explicitly"),
             ("rheonom",), ("scleronom",))  # fmt: skip
BOTH, NEITHER = (SCLERONOMIC[0], RHEONOMIC[0]), ()
FIRST, SECOND = (SCLERONOMIC[0],), (RHEONOMIC[0],)

SUBJECTS = [
    # (text, the ideas found)
    ("Scleronomic constraints are time independent and rheonomic ones are time dependent.", BOTH),
    ("Scleronomic constraints are time-dependent and rheonomic ones are time independent.", NEITHER),  # swapped
    ("Scleronomic constraints are time-dependent; rheonomic ones are time-independent.", NEITHER),
    ("Time-independent constraints are scleronomic; time-dependent ones are rheonomic.", BOTH),  # named after
    ("Time-independent constraints are called rheonomic and time-dependent ones scleronomic.", NEITHER),
    ("Scleronomic: the equations do not contain t explicitly. Rheonomic: they contain t explicitly.", BOTH),
    ("Scleronomic constraints, e.g. x² + y² = l², are time independent.", FIRST),
    ("A scleronomic constraint is a fixed wire. It is time independent.", FIRST),  # the last term named
    ("A rheonomic constraint is a moving wire. It is time independent.", NEITHER),
    ("One kind is time independent, the other time dependent.", BOTH),  # no term: the question's own
    ("Unlike rheonomic constraints, scleronomic ones are time independent.", FIRST),
    ("Scleronomic constraints, unlike rheonomic ones, are time independent.", FIRST),  # set against: not named
    ("A constraint that is not scleronomic is time independent.", NEITHER),  # a denied term
    ("Rheonomic constraints are time dependent, while scleronomic ones are not.", SECOND),
]


@pytest.mark.parametrize(("text", "found"), SUBJECTS)
def test_a_phrasing_counts_only_said_of_its_own_term(text, found):
    assert rubric_score(text, [SCLERONOMIC, RHEONOMIC]).found == found


HOLONOMIC = ("holonomic: f(r, t) = 0", 1.0, ("f(r",), ("holonomic",), ("non-holonomic",))
NON_HOLONOMIC = ("non-holonomic: inequalities", 1.0, ("inequalit",), ("non-holonomic",), ("holonomic",))

TERMS_INSIDE_TERMS = [
    ("Holonomic constraints are f(r, t) = 0; non-holonomic ones are inequalities.", ("holonomic: f(r, t) = 0",
                                                                                  "non-holonomic: inequalities")),
    ("Holonomic constraints are inequalities; non-holonomic ones are f(r, t) = 0.", ()),
    # "holonomic" inside "nonholonomic", which the rubric does not list, is not holonomic
    ("Nonholonomic constraints can be written as f(r, t) = 0.", ()),
    ("Non holonomic constraints can be written as f(r, t) = 0.", ()),
]  # fmt: skip


@pytest.mark.parametrize(("text", "found"), TERMS_INSIDE_TERMS)
def test_a_term_inside_a_longer_or_negated_one_is_not_named(text, found):
    assert rubric_score(text, [HOLONOMIC, NON_HOLONOMIC]).found == found


def test_an_unbound_rubric_reads_as_before():
    # a rubric of (idea, points, phrasings), with no terms, is found anywhere it is not negated
    rubric = [("small angle", 1.0, ("sin θ ≈ θ",)), ("proportional", 1.0, ("proportional to",))]
    assert rubric_score("Rheonomic? For small angles sin θ ≈ θ, proportional to θ", rubric).points == 2.0


HOSTILE = [
    # (text): long or strange texts get a proposal, quickly, and never raise
    "not " * 2000,
    "(" * 6000,
    ")" * 6000,
    ", and " * 1000,
    "a. " * 2000,
    "..." * 2000,
    "…" * 6000,
    "scleronomic rheonomic not time independent " * 200,
    "n't" * 3000,
    "\u0000\u202e time independent",
]


@pytest.mark.parametrize("text", HOSTILE, ids=[f"hostile-{index}" for index in range(len(HOSTILE))])
def test_a_hostile_text_gets_a_proposal(text):
    reading = rubric_score(text, [SCLERONOMIC, RHEONOMIC])
    assert 0 <= reading.points <= 2 and len(reading.found) + len(reading.missing) == 2


def test_a_text_is_read_up_to_its_limit():
    padding = " " * MAX_TEXT_LENGTH
    assert rubric_score("conserved" + padding, [CONSERVED]).found
    assert not rubric_score(padding + "conserved", [CONSERVED]).found


FEEDBACK = [
    # (text, the proposal, what the student reads)
    ("Scleronomic constraints are time independent.", 0.5,
     "A person will read this answer; the rubric found 1 of its 2 ideas."),
    ("Scleronomic constraints are time-dependent and rheonomic ones are time independent.", 0.0,
     "A person will read this answer; the rubric found 0 of its 2 ideas. It did not count 2 more that your"
     " answer negates or says of something else."),
    ("Scleronomic ones are time independent, rheonomic ones are not time dependent.", 0.5,
     "A person will read this answer; the rubric found 1 of its 2 ideas. It did not count 1 more that your"
     " answer negates or says of something else."),
]  # fmt: skip


@pytest.mark.parametrize(("text", "score", "feedback"), FEEDBACK)
def test_the_feedback_never_claims_a_negated_idea(text, score, feedback):
    verdict = compare("", text, kind="text", rubric=(SCLERONOMIC, RHEONOMIC))
    assert (verdict.status, verdict.score, verdict.feedback) == ("undecided", score, (feedback,))
