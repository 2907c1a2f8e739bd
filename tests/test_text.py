"""The ``text`` kind's rubric: what it proposes, and what it must not be fooled into proposing.

A proposal is what a person starts from and, until one scores the answer, what the LMS gets:
a statement turned round (negated, or said of the rival term) must never earn the idea.
"""

from __future__ import annotations

import time

import pytest
from course import BANK

from grader import compare
from grader.grade import grade_answer
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
    ("it not only uses scalar energies but also generalized coordinates", "scalar", FOUND),  # affirms
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
    # "≠" denies the relation on both its sides, as "is not" would
    ("so H ≠ T + V", "t + v", NEGATED),
    ("so H != T + V", "t + v", NEGATED),
    ("so H \\ne T + V", "t + v", NEGATED),
    ("so E = T + V ≠ H", "t + v", NEGATED),
    # the negations of languages students mix in; "non" stays a prefix ("non-holonomic ones are …")
    ("la quantité n'est pas conserved", "conserved", NEGATED),
    ("der Impuls ist nicht conserved", "conserved", NEGATED),
]


@pytest.mark.parametrize(("text", "phrasing", "outcome"), NEGATION)
def test_a_negated_phrasing_earns_nothing(text, phrasing, outcome):
    reading = rubric_score(text, [(*CONSERVED[:2], (phrasing,))])
    assert (bool(reading.found), bool(reading.discounted)) == outcome


TAKEN_BACK = [
    # (text, what becomes of "conserved"): a statement taken back after it, or denied before its "that"
    ("Its momentum is conserved — not true in general.", NEGATED),
    ("Its momentum is conserved, which is false.", NEGATED),
    ("Its momentum is conserved, but that's not true.", NEGATED),
    ("Its momentum is conserved (false).", NEGATED),
    ("Its momentum is conserved - wrong.", NEGATED),
    ("Its momentum is conserved. That is wrong.", NEGATED),  # the next sentence
    ("Its momentum is conserved. Not true.", NEGATED),
    ("Is its momentum conserved? No.", NEGATED),  # a question, answered
    ("Is its momentum conserved? Not always.", NEGATED),
    ("It is not true that its momentum is conserved.", NEGATED),
    ("It is false that its momentum is conserved.", NEGATED),
    ("I don't think that the momentum is conserved.", NEGATED),
    ("It is a misconception that the momentum is conserved.", NEGATED),
    ("It is false that q is cyclic and that its momentum is conserved.", NEGATED),  # a denial shared
    ("Its momentum is conserved. Not really.", NEGATED),
    ("Its momentum is conserved, not really.", NEGATED),
    ("Its momentum is conserved. Nope.", NEGATED),
    ("Its momentum is conserved. Not!", NEGATED),
    ("Its momentum is conserved, no wait, its energy is.", NEGATED),
    ("Its momentum is conserved, or not.", NEGATED),
    ("Its momentum is conserved (both false)", NEGATED),
    ("Some say its momentum is conserved, but they are wrong.", NEGATED),
    ("Its momentum is conserved; they're wrong.", NEGATED),
    # a remark that takes back all said before it, not only its sentence
    ("Its momentum is conserved. Its energy is constant. None of this is true.", NEGATED),
    ("Its momentum is conserved. Both statements are false.", NEGATED),
    ("Its momentum is conserved. All of the above is wrong.", NEGATED),
    ("Its momentum is conserved. I am joking.", NEGATED),
    ("Its momentum is conserved. I'm just kidding.", NEGATED),
    ("Its momentum is conserved - just kidding", NEGATED),
    ("Its momentum is conserved. Ignore the above.", NEGATED),
    # doubted after it, or said by others
    ("Its momentum is conserved, I think.", NEGATED),
    ("Its momentum is conserved (I think).", NEGATED),
    ("Its momentum is conserved, probably.", NEGATED),
    ("Some people think its momentum is conserved.", NEGATED),
    ("Some say that its momentum is conserved.", NEGATED),
    ("People often think its momentum is conserved.", NEGATED),
    ("You might think its momentum is conserved.", NEGATED),
    ("A common misconception is to think that its momentum is conserved.", NEGATED),
    # what students write to take a statement back, as a probe of their phrasings found
    ("Its momentum is conserved. Not at all.", NEGATED),
    ("Its momentum is conserved. Of course not.", NEGATED),
    ("Its momentum is conserved. Totally wrong.", NEGATED),
    ("Its momentum is conserved. That's a lie.", NEGATED),
    ("Its momentum is conserved. JK.", NEGATED),
    ("Its momentum is conserved. Never mind.", NEGATED),
    ("Its momentum is conserved. I don't know.", NEGATED),
    ("Its momentum is conserved. Or is it?", NEGATED),
    ("Its momentum is conserved (or maybe not).", NEGATED),
    ("Its momentum is conserved. Neither is true.", NEGATED),
    ("Its momentum is conserved; actually it's the other way round.", NEGATED),
    ("Its momentum is conserved. My answer is wrong.", NEGATED),
    ("Its momentum is conserved. Its energy is constant. I'm not sure about any of this.", NEGATED),
    ("There is no doubt that its momentum is conserved.", FOUND),  # no denial before its "that"
    # what takes back something else, or nothing
    ("Is its momentum conserved? Yes.", FOUND),
    ("Its momentum is conserved, not its energy.", FOUND),
    ("Its momentum is conserved, which is true.", FOUND),
    ("Its momentum is conserved. Its energy has the wrong sign.", FOUND),
    ("Its momentum is conserved. That is why q is cyclic.", FOUND),
    ("It is not only true that the momentum is conserved.", FOUND),
    ("L does not depend on q, so that its momentum is conserved.", FOUND),
    ("Note that the momentum is conserved.", FOUND),
    ("H is conserved, but it is not true that H = E.", FOUND),  # the denial is of what follows it
    ("Its momentum is conserved, but that is not true for the energy.", FOUND),
    ("Its momentum is conserved. That is not true for E.", FOUND),
]


@pytest.mark.parametrize(("text", "outcome"), TAKEN_BACK)
def test_a_statement_taken_back_earns_nothing(text, outcome):
    reading = rubric_score(text, [CONSERVED])
    assert (bool(reading.found), bool(reading.discounted)) == outcome


TAKEN_BACK_OR_NOT = [
    # (a statement taken back, a neighbour of it that is not): each rule with where it stops
    ("Its momentum is conserved. No.", "Yes, its momentum is conserved. No, its energy is not."),
    ("Its momentum is conserved. Nope.", "Nope, its momentum is conserved."),
    ("Its momentum is conserved. None of this is true.", "None of this is true: its momentum is conserved."),
    ("Its momentum is conserved. None of this is true.", "Its momentum is conserved. None of the energy is lost."),
    ("Its momentum is conserved. None of this is true.",
     "Its momentum is conserved. None of these are true for the energy."),
    ("Its momentum is conserved, I think.", "Its momentum is conserved, and I think that is why q is cyclic."),
    ("Some say its momentum is conserved.", "Some say its energy is not conserved, but its momentum is conserved."),
    ("It is false that q is cyclic and that its momentum is conserved.",
     "Note that q is cyclic and that its momentum is conserved."),
    ("Its momentum is conserved. The opposite is true.", "Its momentum is conserved. The opposite is true of E."),
    ("Its momentum is conserved. I don't know.", "Its momentum is conserved. I don't know its energy."),
]  # fmt: skip


@pytest.mark.parametrize(("taken_back", "kept"), TAKEN_BACK_OR_NOT)
def test_a_rule_that_takes_a_statement_back_stops_at_its_neighbour(taken_back, kept):
    readings = rubric_score(taken_back, [CONSERVED]), rubric_score(kept, [CONSERVED])
    assert [(bool(reading.found), bool(reading.discounted)) for reading in readings] == [NEGATED, FOUND]


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
    # no term named, where the question has two subjects: which is which is not said (before, both)
    ("One kind is time independent, the other time dependent.", NEITHER),
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
    ("Holonomic and non-holonomic constraints are f(r, t) = 0 and inequalities, respectively.", (HOLONOMIC[0],
                                                                                              NON_HOLONOMIC[0])),
    ("Holonomic and non-holonomic constraints are inequalities and f(r, t) = 0, respectively.", ()),
]  # fmt: skip


@pytest.mark.parametrize(("text", "found"), TERMS_INSIDE_TERMS)
def test_a_term_inside_a_longer_or_negated_one_is_not_named(text, found):
    assert rubric_score(text, [HOLONOMIC, NON_HOLONOMIC]).found == found


# what does not appear in L is the coordinate, named as a word or as a bare letter, never its velocity
COORDINATE = ("the coordinate does not appear in L", 1.0, ("not appear", "independent of", "∂l/∂q = 0"),
              ("coordinate", "q", "q_k"), ("velocit", "q̇", "qdot", "q'"))  # fmt: skip

LETTER_TERMS = [
    # (text, what becomes of the idea): a one-letter term is a name of its own
    ("If q does not appear in L, its generalized momentum ∂L/∂q̇ is conserved.", FOUND),  # was q̇, named after
    ("L may depend on q̇, but if q does not appear in L, its momentum is conserved.", FOUND),
    ("When ∂L/∂q = 0, i.e. q does not appear in L, p = ∂L/∂q̇ is conserved.", FOUND),
    ("The velocity appears in L, the quantity q does not appear.", FOUND),
    ("The velocity is in L, but its square does not appear.", NEGATED),  # no q in "square"
    ("The velocity q̇ is in L; the frequency does not appear in it.", NEGATED),
    ("If q̇ does not appear in L, its momentum is conserved.", NEGATED),  # a velocity, not q
    ("If q' does not appear in L, q is cyclic.", NEGATED),
    ("Its velocity does not appear in L; q is cyclic.", NEGATED),
    ("The velocity is in L, but e.g. the angle does not appear.", NEGATED),  # "e.g." names no e
]


@pytest.mark.parametrize(("text", "outcome"), LETTER_TERMS)
def test_a_one_letter_term_is_a_name_of_its_own(text, outcome):
    reading = rubric_score(text, [COORDINATE])
    assert (bool(reading.found), bool(reading.discounted)) == outcome


# what is conserved is the momentum, neither the coordinate nor its velocity
MOMENTUM = ("its momentum is conserved", 1.0, ("conserved", "constant of the motion"), ("momentum", "p", "p_k"),
            ("energy", "coordinate", "q", "q_k", "velocit", "q̇"))  # fmt: skip

BELONGING = [
    # (text, what becomes of the momentum's idea): a term after "of" or "conjugate to" names what
    # the term before it belongs to, and a phrasing before a term describes it
    ("The momentum conjugate to a cyclic coordinate is conserved.", FOUND),
    ("The momentum of q is conserved.", FOUND),
    ("The momentum p_k associated with the cyclic coordinate q_k is a constant of the motion.", FOUND),
    ("A cyclic coordinate has a conserved generalized momentum.", FOUND),
    ("A cyclic coordinate has a conserved energy.", NEGATED),
    ("A cyclic coordinate is conserved.", NEGATED),
    ("The velocity of the coordinate is conserved.", NEGATED),
    ("The energy of the coordinate is conserved.", NEGATED),
]


@pytest.mark.parametrize(("text", "outcome"), BELONGING)
def test_a_phrasing_is_said_of_the_term_a_complement_belongs_to(text, outcome):
    reading = rubric_score(text, [COORDINATE, MOMENTUM])
    assert (MOMENTUM[0] in reading.found, MOMENTUM[0] in reading.discounted) == outcome


def test_the_velocity_of_the_coordinate_is_not_the_coordinate():
    assert rubric_score("The velocity of q does not appear in L.", [COORDINATE]).discounted == (COORDINATE[0],)


RESPECTIVELY = [
    # (text, the ideas found): "A and B are X and Y, respectively" says X of A and Y of B
    ("Scleronomic and rheonomic constraints are time independent and time dependent, respectively.", BOTH),
    ("Scleronomic and rheonomic constraints are time dependent and time independent, respectively.", NEITHER),
    ("Rheonomic and scleronomic constraints are time dependent and time independent, respectively.", BOTH),
    ("Scleronomic and rheonomic constraints are, respectively, time independent and time dependent.", BOTH),
    ("Scleronomic constraints and rheonomic ones are time independent and time dependent resp.", BOTH),
    ("Time-independent and time-dependent constraints are called scleronomic and rheonomic, respectively.", BOTH),
    ("Time-dependent and time-independent constraints are called scleronomic and rheonomic, respectively.", NEITHER),
    ("Scleronomic and rheonomic constraints are time independent, respectively.", NEITHER),  # no order to follow
]


LISTS = [
    # (text, the ideas found): what is said of a list that holds both terms is said of neither alone
    ("Scleronomic and rheonomic constraints are both time dependent.", NEITHER),
    ("Rheonomic and scleronomic constraints are time independent.", NEITHER),
    ("Rheonomic constraints and scleronomic ones are time independent.", NEITHER),
    ("Scleronomic ones are time independent, and rheonomic and other constraints are time dependent.", BOTH),
]


@pytest.mark.parametrize(("text", "found"), LISTS)
def test_a_phrasing_said_of_a_list_with_a_rival_is_said_of_neither(text, found):
    assert rubric_score(text, [SCLERONOMIC, RHEONOMIC]).found == found


def test_terms_joined_by_and_in_two_clauses_are_no_list():
    text = "If L depends on the velocity q̇ and q does not appear in L, q is cyclic."
    assert rubric_score(text, [COORDINATE]).found == (COORDINATE[0],)


@pytest.mark.parametrize(("text", "found"), RESPECTIVELY)
def test_respectively_pairs_the_terms_and_descriptions_in_order(text, found):
    assert rubric_score(text, [SCLERONOMIC, RHEONOMIC]).found == found


HEDGES = [
    # (text, the ideas found): a statement doubted, asked or offered with its rival is not claimed
    ("Scleronomic constraints are time dependent or time independent.", NEITHER),
    ("Scleronomic constraints are either time-independent or time-dependent.", NEITHER),
    ("Scleronomic constraints are maybe time independent; rheonomic ones are time dependent.", SECOND),
    ("Perhaps scleronomic constraints are time independent; rheonomic ones are time dependent.", SECOND),
    ("Scleronomic constraints are time independent, I'm not sure. Rheonomic ones are time dependent.", SECOND),
    ("Scleronomic constraints are time independent, I guess. Rheonomic ones are time dependent.", SECOND),
    ("Scleronomic constraints are time independent? Rheonomic ones are time dependent.", SECOND),
    ("Are scleronomic constraints time independent? Yes. Rheonomic ones are time dependent.", BOTH),
    ("Why are scleronomic constraints time independent? Their equations hold t fixed.", FIRST),
    # an "or" between terms, each with its own description, is no hedge
    ("Constraints are scleronomic (time independent) or rheonomic (time dependent).", BOTH),
    ("I think scleronomic constraints are time independent and rheonomic ones time dependent.", BOTH),
]


@pytest.mark.parametrize(("text", "found"), HEDGES)
def test_a_hedged_statement_earns_nothing(text, found):
    assert rubric_score(text, [SCLERONOMIC, RHEONOMIC]).found == found


ALTERNATIVES = [
    # (offered, stated), for the momentum's idea: a phrasing offered with "or" beside another claim of
    # its own shape, which turns it round or repeats one of its words, is offered, not stated; unless
    # what the "or" offers is credited too, or is no claim of that shape
    ("Its momentum is conserved or not.", "Its momentum is conserved or a constant of the motion."),
    ("Its momentum is either conserved or not.", "Its momentum is conserved (or a constant of the motion)."),
    ("Its momentum is conserved or it is not.", "Its momentum is conserved or constant."),
    ("Its momentum is conserved or not conserved.", "Its momentum, or p, is conserved."),
    (
        "Its momentum is conserved or the energy is conserved.",
        "Its momentum is conserved, whether or not the energy is.",
    ),
]


@pytest.mark.parametrize(("offered", "stated"), ALTERNATIVES)
def test_a_phrasing_offered_beside_another_of_its_shape_earns_nothing(offered, stated):
    readings = rubric_score(offered, [COORDINATE, MOMENTUM]), rubric_score(stated, [COORDINATE, MOMENTUM])
    assert [(MOMENTUM[0] in reading.found, MOMENTUM[0] in reading.discounted) for reading in readings] == [
        NEGATED,
        FOUND,
    ]


HARMONIC = [("sin θ ≈ θ", 1.0, ("sin θ ≈ θ", "small angle approximation")),
            ("proportional to θ", 1.0, ("proportional to θ", "proportional to the angle", "linear in θ"))]  # fmt: skip
SHAPES = [
    # (text, the ideas found): the "or" in "proportional to θ or to the angle" offers "proportional to the
    # angle", which the rubric credits too
    ("sin θ ≈ θ or sin θ ≈ 1, so the force is proportional to θ or to 1.", ()),
    ("sin θ ≈ 1 or sin θ ≈ θ, so the force is linear in θ or proportional to θ.", ("proportional to θ",)),
    ("sin θ ≈ θ or sin θ ≈ 1, so the force is proportional to θ or to the angle.", ("proportional to θ",)),
    ("The small angle approximation or linearisation: sin θ ≈ θ or θ̈ = −(g/l) θ, proportional to θ or to 1.",
     ("sin θ ≈ θ",)),
]  # fmt: skip


@pytest.mark.parametrize(("text", "found"), SHAPES)
def test_an_alternative_is_read_in_the_phrasings_place(text, found):
    assert rubric_score(text, HARMONIC).found == found


ELLIPSES = [
    # (an ellipsis that stands for the rival's claim turned round, and one that does not, with the
    # ideas it finds): "… if it does not" reads as the claim before it with "not", "… ones do" as
    # it without its "not"
    ("A constraint is rheonomic if it contains time explicitly, and scleronomic if it does not.",
     "A constraint is rheonomic if it does not contain time explicitly, and scleronomic if it does.", NEITHER),
    ("Scleronomic constraints do not contain t explicitly. Rheonomic ones do.",
     "Scleronomic constraints contain t explicitly. Rheonomic ones do not.", NEITHER),
    ("Rheonomic constraints contain t explicitly; scleronomic ones do not.",
     "Rheonomic constraints contain t explicitly; scleronomic ones do too.", SECOND),
]  # fmt: skip


@pytest.mark.parametrize(("elided", "not_elided", "found"), ELLIPSES)
def test_an_ellipsis_stands_for_the_claim_before_it_turned_round(elided, not_elided, found):
    readings = rubric_score(elided, [SCLERONOMIC, RHEONOMIC]), rubric_score(not_elided, [SCLERONOMIC, RHEONOMIC])
    assert [reading.found for reading in readings] == [BOTH, found]


# H is the energy when the constraints are scleronomic, and conserved when L has no explicit t
ENERGY = ("H = E when scleronomic", 1.0, ("scleronomic",), ("e", "energy"), ("conserved",))

ENERGY_LETTER = [
    ("H = E when the constraints are scleronomic.", FOUND),
    ("H is conserved, i.e. when the constraints are scleronomic.", NEGATED),  # no E in "i.e."
]


@pytest.mark.parametrize(("text", "outcome"), ENERGY_LETTER)
def test_a_letter_of_an_abbreviation_is_no_name(text, outcome):
    reading = rubric_score(text, [ENERGY])
    assert (bool(reading.found), bool(reading.discounted)) == outcome


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


@pytest.mark.parametrize("text", ["!=" * 2500, " -- " * 1250])
def test_a_long_run_of_punctuation_is_read_once(text):
    # a remark's opening is looked for a few characters after a boundary, not across the whole run
    start = time.process_time()
    rubric_score(text, [SCLERONOMIC, RHEONOMIC])
    assert time.process_time() - start < 0.25


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
     " answer negates, doubts or says of something else."),
    ("Scleronomic ones are time independent, rheonomic ones are not time dependent.", 0.5,
     "A person will read this answer; the rubric found 1 of its 2 ideas. It did not count 1 more that your"
     " answer negates, doubts or says of something else."),
    ("Scleronomic constraints are time independent, which is false.", 0.0,
     "A person will read this answer; the rubric found 0 of its 2 ideas. It did not count 1 more that your"
     " answer negates, doubts or says of something else."),
    ("Scleronomic and rheonomic constraints are time dependent and time independent, respectively.", 0.0,
     "A person will read this answer; the rubric found 0 of its 2 ideas. It did not count 2 more that your"
     " answer negates, doubts or says of something else."),
    ("Scleronomic constraints are maybe time independent.", 0.0,
     "A person will read this answer; the rubric found 0 of its 2 ideas. It did not count 1 more that your"
     " answer negates, doubts or says of something else."),
    ("Scleronomic ones are time independent, rheonomic ones time dependent. Both statements are false.", 0.0,
     "A person will read this answer; the rubric found 0 of its 2 ideas. It did not count 2 more that your"
     " answer negates, doubts or says of something else."),
    ("Scleronomic constraints are time independent or not. Rheonomic ones are time dependent.", 0.5,
     "A person will read this answer; the rubric found 1 of its 2 ideas. It did not count 1 more that your"
     " answer negates, doubts or says of something else."),
]  # fmt: skip


@pytest.mark.parametrize(("text", "score", "feedback"), FEEDBACK)
def test_the_feedback_never_claims_a_negated_idea(text, score, feedback):
    verdict = compare("", text, kind="text", rubric=(SCLERONOMIC, RHEONOMIC))
    assert (verdict.status, verdict.score, verdict.feedback) == ("undecided", score, (feedback,))


PROPOSALS = [
    # (problem.part, answer, points proposed): a tester's answers, and right ones said otherwise
    ("constraint-classification.scleronomic-definition",
     "Scleronomic constraints are time-dependent and rheonomic ones are time independent.", 0),  # was 2/2
    ("constraint-classification.scleronomic-definition",
     "Scleronomic: the constraint equations do not contain t explicitly. Rheonomic: they contain t explicitly.",
     2),  # was 0/2
    ("constraint-classification.scleronomic-definition",
     "A rheonomic constraint depends explicitly on time, while a scleronomic one doesn't depend on time.", 2),
    ("constraint-classification.holonomic-definition",
     "Holonomic constraints are inequalities, e.g. gas in a container; non-holonomic ones can be written as"
     " f(r,t)=0, e.g. a pendulum.", 0),  # was 4/4
    ("constraint-classification.holonomic-definition",
     "Holonomic constraints cannot be written as f(r, t) = 0 and non-holonomic ones are not inequalities.", 0),
    ("constraint-classification.holonomic-definition",
     "Non-holonomic: an inequality, or a non-integrable relation such as a disk rolling without slipping."
     " Holonomic: an equation of the form f(q, t) = 0, as for a rigid body.", 4),  # right, named after: kept
    ("lagrangian-vs-newtonian.cyclic-definition",
     "A cyclic coordinate is one whose velocity does not appear in the Lagrangian; then its momentum is not"
     " conserved.", 1),  # was 3/3; its one idea: it names the momentum
    ("lagrangian-vs-newtonian.cyclic-definition",
     "A coordinate q_k is cyclic if L does not depend on q_k (only on q̇_k); then its conjugate momentum"
     " p_k = ∂L/∂q̇_k is conserved.", 3),
    ("lagrangian-vs-newtonian.cyclic-definition",
     "If q does not appear in L, its generalized momentum ∂L/∂q̇ is conserved.", 3),  # was 2/3: a bare q
    ("lagrangian-vs-newtonian.cyclic-definition",
     "If q does not appear in L, its momentum is conserved, which is false.", 0),  # was 3/3
    ("constraint-classification.holonomic-definition",
     "Holonomic constraints can be written as f(r, t) = 0? No. Non-holonomic ones are inequalities.", 1),  # was 2/4
    ("constraint-classification.scleronomic-definition",
     "It is not true that scleronomic constraints are time independent.", 0),  # was 1/2
    ("constraint-classification.holonomic-definition",
     "Holonomic and non-holonomic constraints are, respectively, inequalities and equations f(q, t) = 0.", 0),  # was 1
    ("constraint-classification.scleronomic-definition",
     "Scleronomic and rheonomic constraints are time dependent and time independent, respectively.", 0),  # was 1
    ("constraint-classification.scleronomic-definition",
     "Scleronomic constraints are time dependent or time independent.", 0),  # was 1/2
    ("constraint-classification.holonomic-definition",
     "Holonomic constraints are either equations f(r, t) = 0 or inequalities, I'm not sure.", 0),  # was 1/4
    ("lagrangian-vs-newtonian.cyclic-definition", "A cyclic coordinate is conserved.", 0),  # was 1/3
    ("lagrangian-vs-newtonian.cyclic-definition",
     "If q does not appear in L, its velocity is constant.", 1),  # was 2/3
    ("lagrangian-vs-newtonian.cyclic-definition",
     "If q does not appear in L, the momentum conjugate to q is a constant of the motion.", 3),
    # rubrics whose phrasings named a topic, not the claim ("explicit time", "motor", "angular
    # momentum", "proportional to", "air resistance"), or bound no subject
    ("rotating-hoop.energy", "L depends explicitly on time, so H is not conserved.", 0),  # was 1/3
    ("rotating-hoop.energy", "E is conserved: the motor does no work.", 0),  # was 1/3
    ("rotating-hoop.energy", "E is conserved because the work done by the normal force is zero.", 0),  # was 1/3
    ("rotating-hoop.energy", "H is conserved because L does not depend explicitly on time.", 1),  # was 0/3
    ("spherical-pendulum.conservation", "The angular momentum is not conserved, because gravity exerts a torque.",
     0),  # was 1/3
    ("spherical-pendulum.conservation",
     "φ is cyclic, so p_φ = m l² sin²θ φ̇ is conserved (the vertical angular momentum).", 1),
    ("plane-pendulum.why-harmonic", "Because the restoring force is proportional to sin θ, which is not linear in θ.",
     0),  # was 1/2
    ("plane-pendulum.why-harmonic", "The force is proportional to the mass.", 0),  # was 1/2
    ("double-pendulum.kinetic-general", "For rheonomic constraints T is a homogeneous quadratic form.", 0),  # was 1.5
    ("double-pendulum-alpha-beta.assumptions", "We assume air resistance and friction at the pivots.", 0),  # was 1/2
    ("generalized-forces.hamiltonian", "H = sum of p_i qdot_i - L; H = E if scleronomic; conserved if ∂L/∂t = 0.",
     3),  # was 2/3: E named by its letter
    ("constraint-classification.holonomic-definition",
     "Holonomic and nonholonomic constraints are expressible as equations between coordinates and not"
     " expressible, respectively.", 2),  # was 1/4
    ("lagrangian-vs-newtonian.advantages",
     "Newton's and Lagrange's methods both use scalar energies, generalized coordinates, eliminate constraint"
     " forces, and have the same form.", 0),  # was 4/4
    ("lagrangian-vs-newtonian.advantages",
     "No. The Lagrangian formulation does not use scalar energies or generalized coordinates, the constraint"
     " forces are not eliminated, and its equations do not have the same form in every coordinate system.", 0),
    ("lagrangian-vs-newtonian.advantages",
     "No: Newton's method is the better one, since it uses scalar energies and generalized coordinates, the"
     " forces of constraint never appear in it, and its equations have the same form in any coordinates.", 0),
    ("lagrangian-vs-newtonian.advantages",
     "Yes. Unlike Newton's method, which needs vector forces, it uses the scalar energies T and V and any"
     " generalized coordinates, the constraint forces are eliminated, and its equations have the same form in"
     " every coordinate system.", 4),  # right, Newton named as a contrast: kept
    ("plane-pendulum.why-harmonic",
     "They are not harmonic: we cannot linearize, and the restoring force is not proportional to θ.", 0),
    ("damped-oscillator.rayleigh-meaning",
     "It is not quadratic in the velocities and does not describe friction proportional to the velocity; its"
     " gradient is not the friction force, and 2F is not the rate of energy dissipation.", 0),
    ("degrees-of-freedom.define-dof",
     "It is not the number of independent coordinates, since they need not specify the configuration"
     " completely; it is not 3N − k.", 0),
    ("generalized-forces.hamiltonian",
     "H = Σ p_j q̇_j − L. H is conserved when the constraints are scleronomic, and it equals T + V when L has"
     " no explicit time dependence.", 1),  # the conditions swapped: only the definition
    ("generalized-forces.hamiltonian",
     "H = Σ p_j q̇_j − L. H is not equal to T + V even when the constraints are scleronomic, and it is not"
     " conserved when L does not depend explicitly on time.", 1),
    ("generalized-forces.hamiltonian",
     "H = Σ p_j q̇_j − L. It is conserved if ∂L/∂t = 0; it is the total energy T + V if the constraints are"
     " time independent and V does not depend on the velocities.", 3),
    # a probe's false answers, proposed credit before (the credit then in the comment)
    ("plane-pendulum.why-harmonic",
     "Il n'est pas vrai que sin θ ≈ θ, et la force n'est pas proportional to θ.", 0),  # was 2/2
    ("spherical-pendulum.conservation", "p_φ is constant. ∂L/∂t ≠ 0. H ≠ T + V.", 1),  # was 2/3
    ("plane-pendulum.why-harmonic",
     "For small angles sin θ ≈ θ, so the restoring force is proportional to θ. Not really.", 0),  # was 2/2
    ("plane-pendulum.why-harmonic",
     "For small angles sin θ ≈ θ, so the restoring force is proportional to θ. None of this is true.", 0),  # was 2/2
    ("plane-pendulum.why-harmonic",
     "For small angles sin θ ≈ θ, so the restoring force is proportional to θ. Both statements are false.", 0),
    ("plane-pendulum.why-harmonic",
     "For small angles sin θ ≈ θ, so the restoring force is proportional to θ (both false)", 0),  # was 2/2
    ("plane-pendulum.why-harmonic",
     "For small angles sin θ ≈ θ, so the restoring force is proportional to θ. I am joking.", 0),  # was 2/2
    ("plane-pendulum.why-harmonic",
     "Some say sin θ ≈ θ and the force is proportional to θ, but they are wrong.", 0),  # was 2/2
    ("plane-pendulum.why-harmonic",
     "The force is proportional to θ, I think; sin θ ≈ θ for small angles.", 1),  # was 2/2
    ("plane-pendulum.why-harmonic",
     "It is false that for small angles sin θ ≈ θ and that the restoring force is proportional to θ.", 0),  # was 1
    ("plane-pendulum.why-harmonic",
     "sin θ ≈ θ or sin θ ≈ 1, so the force is proportional to θ or to 1.", 0),  # was 2/2
    ("spherical-pendulum.conservation", "The momentum is conserved or not. ∂L/∂t = 0. H = T + V.", 2),  # was 3/3
    # H conserved and why are two ideas: the reason earns its half beside a denied claim
    ("rotating-hoop.energy",
     "The Hamiltonian is not conserved, the energy is not conserved, H ≠ E. The Lagrangian has no explicit time"
     " dependence.", 2.5),  # was 3/3
    ("rotating-hoop.energy", "E is not conserved or it is conserved. L has no explicit time dependence. H ≠ E.",
     1.5),  # was 3/3
    ("rotating-hoop.energy", "H is conserved because L depends explicitly on time.", 0.5),  # the claim, not why
    ("rotating-hoop.energy",
     "H is a constant of the motion (a Jacobi integral) since ∂L/∂t = 0. It is not the total energy: T + V ≠ H."
     " E changes since the motor does work on the bead.", 3),  # was 2/3
    # the momentum of φ, the cyclic coordinate, not θ's, the coordinate's or the bob's
    ("spherical-pendulum.conservation",
     "θ is cyclic, so the momentum conjugate to θ is constant. No explicit time. H = T + V.", 2),  # was 3/3
    ("spherical-pendulum.conservation",
     "The coordinate conjugate to p_φ is conserved. L has no explicit time dependence. H = T + V.", 2),  # was 3/3
    ("spherical-pendulum.conservation", "The momentum of the bob is conserved. L has no explicit t, and H = T + V.",
     2),  # was 3/3
    ("spherical-pendulum.conservation", "E is a constant of the motion. ∂L/∂t = 0, H = T + V.", 2),  # was 3/3
    ("spherical-pendulum.conservation",
     "p_φ is constant. ∂L/∂t = 0. H ≠ T + V because the constraints are scleronomic.", 2),  # was 3/3
    # rubrics whose topic words credited wrong statements, now bound to what they describe
    ("constraint-classification.types-of-constraints",
     "Scleronomic constraints depend explicitly on time and rheonomic ones do not. Holonomic ones are equations"
     " f(r, t) = 0, like a pendulum.", 2),  # was 3/4
    ("constraint-classification.types-of-constraints",
     "Holonomic constraints are time independent, non-holonomic ones time dependent.", 0),  # was 1/4
    ("constraint-classification.types-of-constraints",
     "Holonomic and non-holonomic; scleronomic and rheonomic.", 0),  # was 1/4: names, no definition
    ("principles.dalembert-in-words", "The virtual work of the applied forces is zero.", 1),  # was 2/3: statics
    ("damped-oscillator.rayleigh-meaning", "F is quadratic in the coordinates; F is the rate of energy dissipation.",
     0),  # was 2/3: 2F is the rate
    ("damped-oscillator.rayleigh-meaning", "F is the power dissipated by friction, quadratic in the velocities.",
     1),  # was 2/3
    # an ellipsis for the claim before it, as 17 and 24 students of the example class write
    ("constraint-classification.scleronomic-definition",
     "A constraint is rheonomic if time appears explicitly in its equation (bead on a moving wire) and scleronomic"
     " if it does not (bead on a fixed wire).", 2),  # was 1/2
    ("constraint-classification.scleronomic-long",
     "A constraint is scleronomic when its equation does not contain time explicitly and rheonomic when it does."
     " Scleronomic: a bead on a fixed wire. Rheonomic: a bead on a rotating loop.", 4),  # was 3/4
    ("generalized-forces.hamiltonian",
     "H = Σ p q̇ − L. H = T + V when the constraints are scleronomic, and it is conserved when they are not.", 2),
    # and right answers the binding must still credit
    ("spherical-pendulum.conservation",
     "φ is cyclic, so ṗ_φ = 0. L has no explicit t, so H is conserved, and H = T + V since T is quadratic.", 3),
    ("rotating-hoop.energy",
     "H is conserved since L is time independent. H ≠ E. E is not conserved: the motor does work on the bead.", 3),
]  # fmt: skip


@pytest.mark.parametrize(("where", "answer", "points"), PROPOSALS, ids=[f"{row[0]}-{row[2]}" for row in PROPOSALS])
def test_the_bank_proposes_a_sensible_score(where, answer, points):
    problem_id, part_id = where.split(".")
    problem = BANK[problem_id]
    part = problem.part(part_id)
    verdict = grade_answer(problem, part, answer)
    assert (verdict.status, round(verdict.score * part.points, 9)) == ("undecided", points)
