"""What grading produces: a grade per part, per student, and its totals.

Contents:
    Student             id, name, email (as the LMS export gives them)
    PartGrade           one answer's verdict, in points, with a person's score when there is one
    SubmissionGrade     one student's grades; totals and percent are derived, never stored
    PART_STATUSES       the statuses a part can have

A part's ``status`` is the verdict's (equivalent, not_equivalent, undecided, invalid), or
``blank`` when nothing was answered. A submission's ``status`` is ``graded``, or
``error`` when it could not be graded at all (its message says why).
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["PART_STATUSES", "PartGrade", "Student", "SubmissionGrade"]

PART_STATUSES = ("equivalent", "not_equivalent", "undecided", "invalid", "blank")


@dataclass(frozen=True)
class Student:
    id: str
    name: str = ""
    email: str = ""


@dataclass(frozen=True)
class PartGrade:
    """One part of one submission.

    Attributes:
        problem, part: where it belongs; ``key`` is ``problem.part``.
        max_score: the points the part is worth in this assignment.
        answer: the answer as submitted.
        status: see :data:`PART_STATUSES`.
        auto_score: points the grader gave.
        feedback: sentences for the student.
        diagnosis: the kind of mistake, a stable key (or None).
        method: how the verdict was reached.
        read_as: how the answer was read (text), and ``read_as_mathml`` for reports.
        manual_score, comment: a person's score and note, when one was given.
        kind: the part's kind.
    """

    problem: str
    part: str
    max_score: float
    answer: str
    status: str
    auto_score: float
    feedback: tuple[str, ...] = ()
    diagnosis: str | None = None
    method: str = ""
    read_as: str = ""
    read_as_mathml: str = ""
    manual_score: float | None = None
    comment: str = ""
    kind: str = ""

    @property
    def key(self) -> str:
        return f"{self.problem}.{self.part}"

    @property
    def final_score(self) -> float:
        """A person's score when there is one, else the grader's."""
        return self.auto_score if self.manual_score is None else self.manual_score

    @property
    def needs_review(self) -> bool:
        """Waiting for a person: text answers, undecided checks and unreadable answers, until scored by hand."""
        return self.manual_score is None and self.status in ("undecided", "invalid")


@dataclass(frozen=True)
class SubmissionGrade:
    """One student's grades. ``status`` is ``graded`` or ``error``."""

    student: Student
    parts: tuple[PartGrade, ...]
    status: str = "graded"
    message: str = ""

    @property
    def score(self) -> float:
        return sum(part.final_score for part in self.parts)

    @property
    def auto_score(self) -> float:
        return sum(part.auto_score for part in self.parts)

    @property
    def max_score(self) -> float:
        return sum(part.max_score for part in self.parts)

    @property
    def percent(self) -> float:
        return 100 * self.score / self.max_score if self.max_score else 0.0
