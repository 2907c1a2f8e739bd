"""Grading an assignment end to end: read, grade, apply a person's scores, write every output.

Contents:
    RunSummary           what happened: who was graded, who could not be, what was wrong in the input
    grade_assignment()   the library call behind ``grader grade``
    export_grades()      the library call behind ``grader export``
    file_name(student)   a student id made safe as a file name

Outputs in the folder ``out`` (every file written atomically):
    results/<student>.json   Gradescope's results.json shape, our details under extra_data
    gradebook.csv, scores_long.csv, review.csv, summary.html, reports/<student>.html and .md
    overrides.csv            the person's scores applied, kept so they survive a regrade
    input-issues.txt         what was wrong in the submissions, by file and row
"""

from __future__ import annotations

import hashlib
import re
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import pandas

from grader.bank import Assignment, Problem
from grader.errors import GraderError
from grader.export import (
    apply_overrides,
    canvas_csv,
    grade_from_json,
    gradebook_csv,
    moodle_csv,
    read_overrides,
    result_json,
    review_csv,
    scores_long_csv,
    write_atomic,
)
from grader.export import columns as c
from grader.grade.batch import assignment_parts, grade_class
from grader.grade.results import SubmissionGrade
from grader.grade.submissions import read_submissions
from grader.judge import DEFAULT_TIMEOUT
from grader.report import render_student_report, render_summary

__all__ = ["EXPORTS", "RunSummary", "export_grades", "file_name", "grade_assignment"]

EXPORTS = ("canvas", "moodle", "gradescope")


@dataclass(frozen=True)
class RunSummary:
    """The outcome of a run, for the command line to report."""

    out: Path
    grades: tuple[SubmissionGrade, ...]
    issues: tuple[str, ...] = ()
    failed: tuple[str, ...] = field(default=())  # students who could not be graded, with the reason

    @property
    def review_count(self) -> int:
        return sum(part.needs_review for grade in self.grades for part in grade.parts)


def file_name(student_id: str) -> str:
    """A student id as a safe file name: no path separators, no leading dot, unique for unsafe ids.

    >>> file_name("s1001"), file_name("../../etc/passwd")[:12]
    ('s1001', 'etc_passwd-3')
    """
    safe = re.sub(r"[^A-Za-z0-9_-]+", "_", student_id).strip("_") or "student"
    if safe == student_id and len(safe) <= 60:
        return safe
    return f"{safe[:60]}-{hashlib.sha256(student_id.encode()).hexdigest()[:8]}"


def grade_assignment(
    submissions: Path,
    assignment: Assignment,
    bank: dict[str, Problem],
    out: Path,
    *,
    jobs: int | None = None,
    timeout: float = DEFAULT_TIMEOUT,
    only: str | None = None,
    overrides: Path | None = None,
    reveal: bool = False,
    progress: Callable[[int], None] | None = None,
    on_start: Callable[[int], None] | None = None,
) -> RunSummary:
    """Grade ``submissions`` for ``assignment`` and write every output into ``out``.

    Raises:
        GraderError: the submissions cannot be read at all, or ``only`` names no student.
        OSError: the output folder cannot be written.
    """
    parts = assignment_parts(assignment, bank)
    keys = [(f"{problem.id}.{part.id}", points) for problem, part, points in parts]
    try:
        found, input_issues = read_submissions(submissions, [key for key, _ in keys])
    except OSError as error:
        raise GraderError(f"cannot read the submissions {submissions}: {error}") from error
    issues = [str(issue) for issue in input_issues]
    if only is not None:
        found = [s for s in found if s.student.id == only]
        if not found:
            raise GraderError(f"no submission from student {only!r} in {submissions}")
    if on_start:
        on_start(len(found))
    grades = grade_class(found, assignment, bank, jobs=jobs, timeout=timeout, progress=progress)
    if only is not None:
        grades = _merged_with_previous(out, grades)
    grades, override_issues = _with_overrides(out, grades, overrides)
    issues += override_issues
    _write_outputs(out, grades, keys, assignment, bank, issues, reveal)
    failed = tuple(f"{g.student.id}: {g.message}" for g in grades if g.status == "error")
    return RunSummary(out, tuple(grades), tuple(issues), failed)


def _merged_with_previous(out: Path, regraded: list[SubmissionGrade]) -> list[SubmissionGrade]:
    """Everyone graded before, with the regraded students replaced, in the previous order."""
    fresh = {grade.student.id: grade for grade in regraded}
    previous = []
    for path in sorted((out / "results").glob("*.json")):
        grade = grade_from_json(path.read_text(encoding="utf-8"))
        previous.append(fresh.pop(grade.student.id, grade))
    return previous + list(fresh.values())


def _with_overrides(out: Path, grades: list[SubmissionGrade], new: Path | None):
    """Apply the overrides saved in ``out`` and those in ``new`` (which win), and save them all."""
    saved = out / "overrides.csv"
    overrides, issues = read_overrides(saved) if saved.exists() else ({}, [])
    if new is not None:
        more, more_issues = read_overrides(new)
        overrides |= more
        issues += more_issues
    if not overrides:
        return grades, issues
    grades, unmatched = apply_overrides(grades, overrides)
    rows = [(student, key, points, comment) for (student, key), (points, comment) in overrides.items()]
    write_atomic(saved, pandas.DataFrame(rows, columns=list(c.OVERRIDE)).to_csv(index=False, lineterminator="\n"))
    return grades, issues + unmatched


def _write_outputs(out: Path, grades, keys, assignment, bank, issues, reveal) -> None:
    for grade in grades:
        name = file_name(grade.student.id)
        write_atomic(out / "results" / f"{name}.json", result_json(grade))
        html, markdown = render_student_report(grade, assignment=assignment, bank=bank, reveal=reveal)
        write_atomic(out / "reports" / f"{name}.html", html)
        write_atomic(out / "reports" / f"{name}.md", markdown)
    write_atomic(out / "gradebook.csv", gradebook_csv(grades, keys))
    write_atomic(out / "scores_long.csv", scores_long_csv(grades))
    write_atomic(out / "review.csv", review_csv(grades))
    write_atomic(out / "summary.html", render_summary(list(grades), assignment=assignment, bank=bank))
    write_atomic(out / "input-issues.txt", "".join(f"{issue}\n" for issue in issues))


def export_grades(out: Path, to: str, *, assignment: Assignment, max_score: float) -> list[Path]:
    """Write an LMS import of the grades in ``out``; returns the files written.

    Raises:
        GraderError: ``out`` holds no graded results.
    """
    paths = sorted((out / "results").glob("*.json"))
    if not paths:
        raise GraderError(f"{out} holds no results: grade first (grader grade … --out {out})")
    grades = [grade_from_json(path.read_text(encoding="utf-8")) for path in paths]
    exports = out / "exports"
    if to == "canvas":
        text = canvas_csv(grades, assignment=assignment.title, assignment_id=assignment.id, max_score=max_score)
        return [write_atomic(exports / "canvas.csv", text)]
    if to == "moodle":
        return [write_atomic(exports / "moodle.csv", moodle_csv(grades, assignment=assignment.title))]
    return [
        write_atomic(exports / "gradescope" / file_name(grade.student.id) / "results.json", result_json(grade))
        for grade in grades
    ]
