"""Students checking an answer before they submit it: ``check`` and what it returns.

Contents:
    CheckResult          right / not right / undecided / invalid, the hint, how the answer was read;
                         reads well as text and renders in Jupyter (HTML with MathML, Markdown)
    check(ref, answer)   ``check("atwood-machine.lagrangian", "1/2 (m1+m2) xdot^2 + (m1-m2) g x")``
    check_many(answers)  a mapping of ``problem.part`` → answer, e.g. from a student's YAML file

A result never shows a reference answer: it carries the verdict's feedback, which names
the kind of mistake, and the feedback authors wrote for anticipated mistakes, which the
bank's tests keep free of the answer.
"""

from __future__ import annotations

import html
from collections.abc import Mapping
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

from grader.bank import Problem, default_bank_path, load_bank
from grader.errors import GraderError
from grader.grade.part import grade_answer
from grader.judge import DEFAULT_TIMEOUT

__all__ = ["CheckResult", "check", "check_many", "find_part"]

SYMBOLS = {"equivalent": "✔", "not_equivalent": "✘", "undecided": "?", "invalid": "invalid"}
WORDS = {
    "equivalent": "right",
    "not_equivalent": "not right",
    "undecided": "a person will check this",
    "invalid": "could not be read",
}


@dataclass(frozen=True)
class CheckResult:
    """The outcome of checking one answer.

    Attributes:
        key: ``problem.part``.
        status: ``equivalent``, ``not_equivalent``, ``undecided`` or ``invalid``.
        score: the credit it would earn, 0 to 1 (provisional for text answers).
        hints: sentences for the student; never the answer.
        read_as: how the answer was read (for an unreadable answer, the line with a caret).
        read_as_mathml: the same as MathML, when the answer was read as mathematics.
    """

    key: str
    status: str
    score: float
    hints: tuple[str, ...]
    read_as: str = ""
    read_as_mathml: str = ""

    @property
    def right(self) -> bool:
        return self.status == "equivalent"

    @property
    def _unread(self) -> bool:
        # An invalid answer was either not read (read_as is the line with a caret) or read as
        # something that is not an answer here ("2.006 s" for a number), shown as read.
        return self.status == "invalid" and not self.read_as_mathml

    def __str__(self) -> str:
        lines = [f"{SYMBOLS[self.status]} {self.key}: {WORDS[self.status]}"]
        lines += [f"  {hint}" for hint in self.hints if hint != "Correct."]
        if self.read_as:
            label = "where" if self._unread else "read as"
            lines += [f"  {label}: {line}" if i == 0 else f"  {' ' * len(label)}  {line}"
                      for i, line in enumerate(self.read_as.splitlines())]  # fmt: skip
        return "\n".join(lines)

    def _repr_markdown_(self) -> str:
        hints = "".join(f"\n- {_markdown(hint)}" for hint in self.hints if hint != "Correct.")
        read = f"\n\nRead as: `{self.read_as}`" if self.read_as and not self._unread else ""
        where = f"\n\n```\n{self.read_as}\n```" if self._unread and self.read_as else ""
        return f"**{SYMBOLS[self.status]} {_markdown(self.key)}: {WORDS[self.status]}**{hints}{read}{where}"

    def _repr_html_(self) -> str:
        colour = {"equivalent": "#17663a", "not_equivalent": "#a61b1b"}.get(self.status, "#8a5a00")
        hints = "".join(f"<li>{html.escape(hint)}</li>" for hint in self.hints if hint != "Correct.")
        if self.read_as_mathml:  # built by our printer from the parsed expression, never from raw text
            read = f"<div>Read as: {self.read_as_mathml}</div>"
        elif self.read_as:
            read = f"<pre>{html.escape(self.read_as)}</pre>"
        else:
            read = ""
        return (
            f'<div class="grader-check"><strong style="color:{colour}">{SYMBOLS[self.status]} '
            f"{html.escape(self.key)}: {WORDS[self.status]}</strong>"
            f"{f'<ul>{hints}</ul>' if hints else ''}{read}</div>"
        )


def _markdown(text: str) -> str:
    return "".join(f"\\{c}" if c in "\\`*_{}[]<>#|" else c for c in text)


@lru_cache(maxsize=8)
def _bank(path: Path) -> dict[str, Problem]:
    return load_bank(path)


def find_part(key: str, bank: Mapping[str, Problem]):
    """(problem, part) for ``problem.part``; raises GraderError saying what exists instead."""
    problem_id, _, part_id = key.partition(".")
    problem = bank.get(problem_id)
    if problem is None:
        raise GraderError(f"no problem {problem_id!r}; the problems are: {', '.join(sorted(bank))}")
    try:
        return problem, problem.part(part_id)
    except KeyError:
        parts = ", ".join(f"{problem_id}.{p.id}" for p in problem.parts)
        raise GraderError(f"problem {problem_id!r} has no part {part_id!r}; its parts are: {parts}") from None


def check(
    key: str,
    answer: str,
    *,
    bank: Mapping[str, Problem] | None = None,
    timeout: float = DEFAULT_TIMEOUT,
    answers: Mapping[str, str] | None = None,
) -> CheckResult:
    """Check one answer to ``problem.part`` from the bank. With the student's other ``answers``
    (``problem.part`` → answer), equations that follow from their own wrong Lagrangian earn the
    method credit grading the class gives them.

    Raises:
        GraderError: no such problem or part (the message lists what exists).
    """
    bank = bank if bank is not None else _bank(default_bank_path())
    problem, part = find_part(key, bank)
    if not str(answer).strip():
        return CheckResult(key, "invalid", 0.0, ("Your answer is empty.",))
    verdict = grade_answer(problem, part, str(answer), timeout=timeout, answers=answers)
    mathml = verdict.answer.read_as_mathml if verdict.answer is not None and verdict.answer.ok else ""
    return CheckResult(key, verdict.status, verdict.score, verdict.feedback, verdict.read_as, mathml)


def check_many(
    answers: Mapping[str, str], *, bank: Mapping[str, Problem] | None = None, timeout: float = DEFAULT_TIMEOUT
) -> list[CheckResult]:
    """Check every ``problem.part → answer`` of a mapping, in its order, each with the others known."""
    return [check(key, answer, bank=bank, timeout=timeout, answers=answers) for key, answer in answers.items()]
