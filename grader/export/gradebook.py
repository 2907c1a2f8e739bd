"""Gradebooks, per-student results and LMS imports, as text the caller writes atomically.

Contents:
    result_json(grade) / grade_from_json(text)   Gradescope's results.json shape, our details in extra_data
    gradebook_csv(grades, parts)                 one row per student, a points-possible row first
    scores_long_csv(grades)                      one row per student and part
    review_csv(grades)                           what needs a person, with a points column to fill in
    canvas_csv, moodle_csv                       LMS gradebook imports

CSVs are built as pandas frames and written by pandas, never by string formatting: a comma
or a quote in a name is quoted, not a broken row; and no cell is one a spreadsheet runs
(see :mod:`grader.export.spreadsheet`).

A student who could not be graded has no row in an LMS import: both Canvas and Moodle leave
the grade of a student the file does not list as it is, where a 0 would fail them and an empty
grade would make Moodle delete one already there.
"""

from __future__ import annotations

import dataclasses
import json
from collections.abc import Sequence

from grader.export import columns as c
from grader.export.spreadsheet import csv_text
from grader.grade.results import PartGrade, Student, SubmissionGrade

__all__ = [
    "canvas_csv",
    "grade_from_json",
    "gradebook_csv",
    "moodle_csv",
    "result_json",
    "review_csv",
    "scores_long_csv",
]


# -- results/<student>.json ------------------------------------------------------------


def result_json(grade: SubmissionGrade) -> str:
    """One student's results in Gradescope's results.json shape; everything else under extra_data."""
    tests = [
        {
            "name": part.key,
            "score": round(part.final_score, 4),
            "max_score": part.max_score,
            "status": "passed" if part.final_score >= part.max_score else "failed",
            "output": _output(part),
        }
        for part in grade.parts
    ]
    record = {
        "score": round(grade.score, 4),
        "max_score": grade.max_score,
        "tests": tests,
        "extra_data": {
            "student": dataclasses.asdict(grade.student),
            "status": grade.status,
            "message": grade.message,
            "parts": [dataclasses.asdict(part) for part in grade.parts],
        },
    }
    return json.dumps(record, ensure_ascii=False, indent=2)


def _output(part: PartGrade) -> str:
    """What Gradescope shows a student for a part: the feedback, and a person's score and comment
    first where one was given (then "a person will read this answer" is no longer said)."""
    if part.manual_score is None:
        return " ".join(part.feedback)
    person = f"Scored by a person: {part.manual_score:g} / {part.max_score:g}."
    if part.comment:
        person += f" {part.comment}"
    waited = part.status in ("undecided", "invalid")  # its feedback said it was waiting for a person
    return " ".join((person, *(() if waited else part.feedback)))


def grade_from_json(text: str) -> SubmissionGrade:
    """The SubmissionGrade a :func:`result_json` text holds (to rebuild a gradebook after --only)."""
    extra = json.loads(text)["extra_data"]
    parts = tuple(PartGrade(**{**part, "feedback": tuple(part["feedback"])}) for part in extra["parts"])
    return SubmissionGrade(Student(**extra["student"]), parts, extra["status"], extra["message"])


# -- gradebook.csv, scores_long.csv, review.csv --------------------------------------------


def gradebook_csv(grades: Sequence[SubmissionGrade], keys: Sequence[tuple[str, float]]) -> str:
    """``keys``: (problem.part, points possible) for every part, in order."""
    possible = {c.STUDENT_ID: c.POINTS_POSSIBLE, c.NAME: "", c.EMAIL: ""}
    possible |= {key: points for key, points in keys}
    possible |= {c.TOTAL: sum(points for _, points in keys), c.MAX: sum(points for _, points in keys)}
    possible |= {c.PERCENT: 100, c.STATUS: ""}
    rows = [possible]
    for grade in grades:
        scores = {part.key: round(part.final_score, 2) for part in grade.parts}
        rows.append(
            {c.STUDENT_ID: grade.student.id, c.NAME: grade.student.name, c.EMAIL: grade.student.email}
            | {key: scores.get(key, "") for key, _ in keys}
            | {c.TOTAL: round(grade.score, 2), c.MAX: possible[c.MAX], c.STATUS: grade.status}
            | {c.PERCENT: round(100 * grade.score / possible[c.MAX], 2) if possible[c.MAX] else 0}
        )
    order = [c.STUDENT_ID, c.NAME, c.EMAIL, *(key for key, _ in keys), c.TOTAL, c.MAX, c.PERCENT, c.STATUS]
    return csv_text(rows, order)


def scores_long_csv(grades: Sequence[SubmissionGrade]) -> str:
    rows = [
        (
            grade.student.id,
            part.key,
            part.auto_score,
            part.manual_score,
            part.final_score,
            part.max_score,
            part.status,
            part.diagnosis or "",
            part.read_as,
            part.comment,
        )
        for grade in grades
        for part in grade.parts
    ]
    return csv_text(rows, c.LONG)


def review_csv(grades: Sequence[SubmissionGrade]) -> str:
    rows = [
        (
            grade.student.id,
            grade.student.name,
            part.key,
            part.status,
            part.auto_score,
            part.max_score,
            "",  # points and comment: for a person to fill in, and feed back with --overrides
            "",
            part.answer,
            part.read_as,
            " ".join(part.feedback),
        )
        for grade in grades
        for part in grade.parts
        if part.needs_review
    ]
    rows += [
        (grade.student.id, grade.student.name, "", grade.status, "", "", "", "", "", "", grade.message)
        for grade in grades
        if grade.status == "error"
    ]
    return csv_text(rows, c.REVIEW)


# -- LMS imports ------------------------------------------------------------------------------


def canvas_csv(grades: Sequence[SubmissionGrade], *, assignment: str, assignment_id: str, max_score: float) -> str:
    """Canvas's gradebook import: identity columns, one assignment column, a points-possible row.

    A student who could not be graded has no row (see the module's docstring).
    """
    column = f"{assignment} ({assignment_id})"
    rows = [
        dict.fromkeys(c.CANVAS_IDENTITY, "")
        | {c.CANVAS_IDENTITY[0]: c.CANVAS_POINTS_POSSIBLE, column: f"{max_score:.2f}"}
    ]
    for grade in _graded(grades):
        rows.append(
            {
                "Student": grade.student.name,
                "ID": "",
                "SIS User ID": grade.student.id,
                "SIS Login ID": grade.student.email,
                "Section": "",
                column: f"{grade.score:.2f}",
            }
        )
    return csv_text(rows, [*c.CANVAS_IDENTITY, column])


def moodle_csv(grades: Sequence[SubmissionGrade], *, assignment: str) -> str:
    """Moodle's grade import: an identity column, the assignment's grade and its feedback.

    A student who could not be graded has no row (see the module's docstring).
    """
    grade_column, feedback_column = f"Assignment: {assignment}", f"Feedback: {assignment}"
    rows = [
        {
            c.MOODLE_IDENTITY: grade.student.email,
            grade_column: round(grade.score, 2),
            feedback_column: f"{grade.score:.2f} / {grade.max_score:.2f}",
        }
        for grade in _graded(grades)
    ]
    return csv_text(rows, [c.MOODLE_IDENTITY, grade_column, feedback_column])


def _graded(grades: Sequence[SubmissionGrade]) -> list[SubmissionGrade]:
    return [grade for grade in grades if grade.status != "error"]
