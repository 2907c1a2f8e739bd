"""``grader validate``: the bank tests itself, as STACK's question tests do.

Contents:
    Failure                     what is wrong, and where
    validate_problem(problem)   every part: reference, derived equations, mistakes, tests
    validate_bank(paths)        load every problem and assignment under the paths, then validate
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

import sympy

from grader.bank import BankError, Part, Problem, load_assignment, load_problem
from grader.errors import AuthorError
from grader.grade.part import expected_answer, grade_answer, part_options, setting_of
from grader.judge import compare
from grader.judge.expected import prepare
from grader.judge.units import DIMENSIONS, Mixed, si, units_of

__all__ = ["Failure", "validate_bank", "validate_problem"]

SCORE_TOLERANCE = 1e-9


@dataclass(frozen=True)
class Failure:
    """One thing wrong in the bank, addressed to the problem's author."""

    path: str
    problem: str
    part: str
    message: str

    def __str__(self) -> str:
        where = ", ".join(bit for bit in (self.path, f"problem {self.problem}" if self.problem else "",
                                          f"part {self.part}" if self.part else "") if bit)  # fmt: skip
        return f"{where}: {self.message}"


def validate_problem(problem: Problem) -> list[Failure]:
    """Every check ``grader validate`` makes of one loaded problem."""
    failures = []
    for part in problem.parts:
        try:
            failures += [Failure(problem.path, problem.id, part.id, message) for message in _check_part(problem, part)]
        except AuthorError as error:
            failures.append(Failure(problem.path, problem.id, part.id, str(error)))
    return failures


def _check_part(problem: Problem, part: Part) -> Iterable[str]:
    expected = expected_answer(problem, part)
    if part.kind == "text":
        yield from _check_rubric(problem, part)
    else:
        yield from _check_units(problem, part, expected)
        verdict = grade_answer(problem, part, expected)
        if not (verdict.equivalent and verdict.score == 1):
            yield f"the reference answer does not grade as full credit against itself ({_said(verdict)})"
    if part.derive_from and part.answer is not None:
        verdict = compare(expected, str(part.answer), kind=part.kind, **setting_of(problem))
        if not verdict.equivalent:
            yield (
                f"the typed answer disagrees with the equations of motion derived from part"
                f" {part.derive_from!r} ({_said(verdict)})"
            )
    for mistake in part.mistakes:
        arguments = {"kind": part.kind, **setting_of(problem), **part_options(part, problem)}
        if compare(expected, mistake.answer, **arguments).equivalent:
            yield f"mistake {mistake.answer!r} is equivalent to the reference answer"
            continue
        verdict = grade_answer(problem, part, mistake.answer)
        if abs(verdict.score - mistake.score) > SCORE_TOLERANCE:
            listed = f"not its listed {mistake.score:g}"
            yield f"mistake {mistake.answer!r} gets {verdict.score:g}, {listed} ({_said(verdict)})"
    for test in part.tests:
        verdict = grade_answer(problem, part, test.answer)
        if abs(verdict.score - test.score) > SCORE_TOLERANCE:
            yield f"test {test.answer!r} gets {verdict.score:g}, not {test.score:g} ({_said(verdict)})"
        elif test.feedback_contains and test.feedback_contains not in " ".join(verdict.feedback):
            yield f"test {test.answer!r}: the feedback lacks {test.feedback_contains!r} ({_said(verdict)})"


_ENERGY = DIMENSIONS["energy"]


def _check_units(problem: Problem, part: Part, expected: str) -> Iterable[str]:
    """The reference answer's units, where every symbol in it has a dimension: its terms agree,
    and a Lagrangian is an energy. A slip here is the author's, or a symbol's dimension is."""
    setting = setting_of(problem)
    if part.kind not in _UNITS_CHECKED or not setting["dimensions"]:
        return
    prepared = prepare(
        expected, part.kind, tuple(setting["coords"]), tuple(setting["known"]),
        tuple(sorted(setting["domains"].items())), dimensions=tuple(sorted(setting["dimensions"].items())),
    )  # fmt: skip
    items = prepared.value if isinstance(prepared.value, tuple) else (prepared.value,)
    for number, item in enumerate(items, 1):
        where = f"equation {number} of the reference answer" if len(items) > 1 else "the reference answer"
        try:
            units = units_of(item.lhs - item.rhs if isinstance(item, sympy.Eq) else item, prepared.setting)
        except Mixed as mixed:
            shown = " and ".join(dict.fromkeys(si(found) for found in mixed.found))
            inside = {"": "the terms have", "power": "a power has"}.get(mixed.function, f"{mixed.function} has")
            yield f"in {where}, {inside} units {shown}: check it, or the dimensions of its symbols"
            continue
        if part.kind == "lagrangian" and units is not None and units != _ENERGY:
            yield f"a Lagrangian is an energy ({si(_ENERGY)}), but {where} is measured in {si(units)}"


_UNITS_CHECKED = ("expression", "equation", "equations", "lagrangian")


def _said(verdict) -> str:
    return f"{verdict.status}: {' '.join(verdict.feedback)}"


def _check_rubric(problem: Problem, part: Part) -> Iterable[str]:
    if part.answer is None:
        return
    verdict = grade_answer(problem, part, str(part.answer))
    if verdict.score < 1 - SCORE_TOLERANCE:
        yield f"the model answer finds only part of the rubric (proposed {verdict.score:g}); add its phrasings"


def validate_bank(paths: Iterable[str | Path]) -> tuple[dict[str, Problem], list[Failure]]:
    """Load every problem (and then every assignment) under ``paths`` and validate them.

    Returns the problems that loaded and every failure, loading errors included; one bad
    file does not stop the others from being checked.
    """
    files = sorted({file for path in map(Path, paths) for file in ([path] if path.is_file() else path.rglob("*.yaml"))})
    problems: dict[str, Problem] = {}
    failures: list[Failure] = []
    assignments = [file for file in files if "assignments" in file.parts]
    for file in files:
        if file in assignments:
            continue
        try:
            problem = load_problem(file)
        except BankError as error:
            failures.append(Failure(str(file), error.problem, error.part, _message(error)))
            continue
        if problem.id in problems:
            failures.append(Failure(str(file), problem.id, "", f"the id is also used by {problems[problem.id].path}"))
            continue
        problems[problem.id] = problem
        failures += validate_problem(problem)
    for file in assignments:
        try:
            load_assignment(file, problems)
        except BankError as error:
            failures.append(Failure(str(file), error.problem, error.part, _message(error)))
    return problems, failures


def _message(error: BankError) -> str:
    return f"line {error.line}: {error.reason}" if error.line else error.reason
