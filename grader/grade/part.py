"""One answer to one part of a bank problem: the reference, the options, the mistakes.

Contents:
    expected_answer(problem, part)                  the reference text (derived for derive_from)
    part_options(part, problem)                     the compare options a part implies
    symbol_meanings(problem)                        the problem's symbols with what each means
    grade_answer(problem, part, submitted, …)       the Verdict a student gets, with the part's
                                                    mistakes, and credit for equations that follow
                                                    from the student's own wrong Lagrangian
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping
from functools import lru_cache

from grader.bank import Part, Problem
from grader.errors import AuthorError
from grader.judge import DEFAULT_TIMEOUT, Verdict, compare
from grader.judge.compare import READINGS_FOR_A_PERSON, ROUNDED
from grader.judge.deadline import CheckTimeout, Deadline, time_limit
from grader.judge.lagrangian import equations_of_motion
from grader.judge.setting import Setting
from grader.parse import parse_answer

__all__ = ["expected_answer", "grade_answer", "part_options", "setting_of", "symbol_meanings"]

CARRIED = "Your equations follow correctly from your own Lagrangian, which is not right: method credit."


def setting_of(problem: Problem) -> dict:
    """The coordinates, known symbols, domains and dimensions compare needs for this problem."""
    domains = {s.name: s.domain for s in problem.coordinates if s.domain != "real"}
    domains |= {s.name: s.domain for s in problem.parameters if s.domain != "positive"}
    symbols = (*problem.coordinates, *problem.parameters)
    return {
        "coords": [s.name for s in problem.coordinates],
        "known": [s.name for s in problem.parameters],
        "domains": domains,
        "dimensions": {s.name: s.dimension for s in symbols if s.dimension},
    }


def expected_answer(problem: Problem, part: Part) -> str:
    """The reference answer as text: typed, or derived from the Lagrangian part it names."""
    if part.derive_from:
        source = problem.part(part.derive_from)
        return _derived(str(source.answer), **_frozen(setting_of(problem)))
    if isinstance(part.answer, list):
        return ", ".join(str(item) for item in part.answer)
    return "" if part.answer is None else str(part.answer)


@lru_cache(maxsize=256)
def _derived(lagrangian: str, coords: tuple, known: tuple, domains: tuple) -> str:
    return equations_of_motion(lagrangian, coords=coords, known=known, domains=dict(domains))


def _frozen(setting: dict) -> dict:
    return {
        "coords": tuple(setting["coords"]),
        "known": tuple(setting["known"]),
        "domains": tuple(sorted(setting["domains"].items())),
    }


def part_options(part: Part, problem: Problem | None = None) -> dict:
    """The compare options a part implies: its own, its given names, and its choices (with what the
    problem's symbols mean, where it is given) or rubric."""
    options = dict(part.options)
    if part.given:
        options["given"] = dict(part.given)
    if part.kind == "choice":
        options["options"] = tuple(part.choices.items())  # labels with their words, which a student may write
        if problem is not None:
            options["meanings"] = symbol_meanings(problem)  # "the azimuthal angle" for an option φ
    if part.kind == "text":
        options["rubric"] = tuple(
            (idea.idea, idea.points, idea.phrasings, idea.about, idea.not_about) for idea in part.rubric
        )
    return options


def symbol_meanings(problem: Problem) -> tuple[tuple[str, str], ...]:
    """The problem's symbols with what each means, as its symbol table says (``phi``, "azimuthal angle …")."""
    return tuple((s.name, s.meaning) for s in (*problem.coordinates, *problem.parameters) if s.meaning)


def grade_answer(
    problem: Problem,
    part: Part,
    submitted: str,
    *,
    timeout: float = DEFAULT_TIMEOUT,
    answers: Mapping[str, str] | None = None,
) -> Verdict:
    """The verdict on ``submitted``: compared with the reference; when wrong, matched against the
    part's anticipated mistakes, whose feedback and score replace the generic ones; and, given the
    student's other ``answers`` (``problem.part`` → answer), with the part's method credit where it
    is wrong but what the student's own Lagrangian implies: an error carried forward is not counted
    twice. Grading a class and a student's check of their answers give the same credit.

    ``timeout`` bounds all of it: each mistake and the method credit are tried in the time the
    verdict left, so a hostile answer costs one time limit, not one for every mistake listed.

    Raises:
        AuthorError: when the part's reference answer or options are wrong (``grader validate`` finds these).
    """
    deadline = Deadline(timeout)
    arguments = {"kind": part.kind, **setting_of(problem), **part_options(part, problem)}
    verdict = compare(expected_answer(problem, part), submitted, **arguments, timeout=timeout)
    if verdict.status != "not_equivalent":
        return verdict
    for mistake in part.mistakes:
        if deadline.remaining() <= 0:
            break  # wrong whichever mistake it is: only the generic feedback is said
        if _matches(compare(mistake.answer, submitted, **arguments, timeout=deadline.remaining())):
            # the mistake's hint replaces the diagnosis; how the answer was read is still said
            feedback = (mistake.feedback, *verdict.notes)
            verdict = dataclasses.replace(
                verdict, score=mistake.score, feedback=feedback, diagnosis="mistake", method="mistake"
            )
            break
    return _with_method_credit(problem, part, verdict, submitted, answers or {}, deadline)


def _matches(verdict: Verdict) -> bool:
    """Whether the answer is a mistake's, by value: what goes to a person only when the value is right,
    a label naming another quantity (``f = …`` where ω is asked), working that does not come to the
    value (``6 − 4 = 3``), words beside it (``…, which is a force``), is said in the verdict's notes
    already. The mistake's with its numbers rounded (6.28 for 2π) is the mistake too."""
    return (
        verdict.equivalent
        or (verdict.status == "undecided" and verdict.diagnosis in READINGS_FOR_A_PERSON)
        or verdict.diagnosis in ROUNDED
    )


def _with_method_credit(
    problem: Problem, part: Part, verdict: Verdict, submitted: str, answers: Mapping, deadline: Deadline
) -> Verdict:
    """``verdict``, with the part's method credit where the part is derived from the Lagrangian part and
    ``submitted`` is what the student's own Lagrangian, among ``answers``, implies."""
    lagrangian = answers.get(f"{problem.id}.{part.derive_from}", "") if part.derive_from else ""
    if verdict.status != "not_equivalent" or not str(lagrangian).strip() or deadline.remaining() <= 0:
        return verdict
    carried = _carried_forward(problem, part, submitted, str(lagrangian), deadline)
    if carried is None or carried <= verdict.score:
        return verdict
    return dataclasses.replace(verdict, score=carried, feedback=(CARRIED,), method="error carried forward")


def _carried_forward(problem: Problem, part: Part, answer: str, lagrangian: str, deadline: Deadline) -> float | None:
    """The method credit when ``answer`` is what the student's own Lagrangian implies.

    The Lagrangian is read as its own part reads it: ``L = …``, ``L = T − V = …``, ``T = …; V = …;
    L = T − V`` and ``½ m v² − …, where v = l θ̇`` are all a Lagrangian (before, only an expression
    alone was, and a labelled one lost its equations their credit)."""
    setting = setting_of(problem)
    source = problem.part(part.derive_from)
    reference = expected_answer(problem, source)
    # judged against the reference alone: a listed mistake's hint would hide what the verdict says of its units
    arguments = {"kind": source.kind, **setting, **part_options(source)}
    graded = compare(reference, lagrangian, **arguments, timeout=deadline.remaining())
    read = graded.answer
    if read is None or not read.ok or read.kind != "expression" or deadline.remaining() <= 0:
        return None
    if graded.diagnosis in _NOT_AN_ENERGY or not _as_full(read.value, reference, setting):
        return None  # ẋ², or ½ (m₁ + m₂) ẋ² with no potential: equations easier than those asked earn nothing
    try:
        with time_limit(deadline.remaining()):
            implied = equations_of_motion(read.read_as_text, **setting)
            verdict = compare(implied, answer, kind=part.kind, **setting, timeout=max(deadline.remaining(), 1e-3))
    except (AuthorError, CheckTimeout, ArithmeticError, ValueError, TypeError, RecursionError):
        return None  # the student's Lagrangian is not one we can derive from: no carried credit
    return part.method_credit if verdict.equivalent else None


# what the Lagrangian part says of a Lagrangian that is no energy: its equations are no physics. One
# with an acceleration has equations of a higher order, which equations_of_motion does not derive
_NOT_AN_ENERGY = frozenset({"units_differ", "units_mixed", "units_argument", "units_power", "lagrangian_accelerations"})


def _as_full(lagrangian, reference: str, setting: dict) -> bool:
    """Whether a student's Lagrangian depends on every coordinate and velocity the reference does.
    One that leaves a coordinate out (its potential forgotten) gives equations with no force in that
    coordinate, easier than those asked: an error carried forward earns credit where the work after it
    is as hard as it would have been, as markers of written work give it."""
    plain = Setting.build(setting["coords"], setting["known"], setting["domains"])
    state = set(plain.state.values())
    expected = parse_answer(reference, coords=setting["coords"], known=setting["known"])
    if not expected.ok:
        return True  # checked by grader validate; no reason here to withhold the credit
    return plain.plain(expected.value).free_symbols & state <= plain.plain(lagrangian).free_symbols
