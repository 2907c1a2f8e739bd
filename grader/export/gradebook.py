"""Gradebooks, per-student results and LMS imports, as text the caller writes atomically.

Contents:
    result_json(grade) / grade_from_json(text)   Gradescope's results.json shape, our details in extra_data
    gradebook_csv(grades, parts)                 one row per student, a points-possible row first
    scores_long_csv(grades)                      one row per student and part
    review_csv(grades)                           what needs a person
    read_overrides(path) / apply_overrides(...)  a person's scores over the grader's
    canvas_csv, moodle_csv                       LMS gradebook imports

CSVs are built as pandas frames and written by pandas, never by string formatting: a comma
or a quote in a name is quoted, not a broken row. A text cell that a spreadsheet would run
as a formula (=, +, -, @, a tab or a carriage return first: =HYPERLINK(…) or +cmd|… typed as
an answer or a name) is written after an apostrophe, which spreadsheets read as "text".
"""

from __future__ import annotations

import csv
import dataclasses
import io
import json
from collections.abc import Sequence
from pathlib import Path

import pandas

from grader.export import columns as c
from grader.grade.results import PartGrade, Student, SubmissionGrade

__all__ = [
    "apply_overrides",
    "canvas_csv",
    "grade_from_json",
    "gradebook_csv",
    "moodle_csv",
    "read_overrides",
    "result_json",
    "review_csv",
    "scores_long_csv",
]


_FORMULA_START = ("=", "+", "-", "@", "\t", "\r")


def _csv(frame: pandas.DataFrame) -> str:
    return frame.map(_inert).to_csv(index=False, lineterminator="\n")


def _inert(value):
    """A cell no spreadsheet runs: text that would start a formula gets an apostrophe first.

    >>> _inert("=HYPERLINK('http://x')"), _inert("-m g l cos θ"), _inert(-1.5), _inert("s1")
    ("'=HYPERLINK('http://x')", "'-m g l cos θ", -1.5, 's1')
    """
    return "'" + value if isinstance(value, str) and value.startswith(_FORMULA_START) else value


def _typed(cell: str) -> str:
    """A cell as a person typed it, from one this module wrote (its apostrophe removed)."""
    return cell[1:] if cell.startswith("'") and cell[1:].startswith(_FORMULA_START) else cell


# -- results/<student>.json ------------------------------------------------------------


def result_json(grade: SubmissionGrade) -> str:
    """One student's results in Gradescope's results.json shape; everything else under extra_data."""
    tests = [
        {
            "name": part.key,
            "score": round(part.final_score, 4),
            "max_score": part.max_score,
            "status": "passed" if part.final_score >= part.max_score else "failed",
            "output": " ".join(part.feedback),
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
    return _csv(pandas.DataFrame(rows, columns=order))


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
        )
        for grade in grades
        for part in grade.parts
    ]
    return _csv(pandas.DataFrame(rows, columns=list(c.LONG)))


def review_csv(grades: Sequence[SubmissionGrade]) -> str:
    rows = [
        (
            grade.student.id,
            grade.student.name,
            part.key,
            part.status,
            part.auto_score,
            part.max_score,
            part.answer,
            part.read_as,
            " ".join(part.feedback),
        )
        for grade in grades
        for part in grade.parts
        if part.needs_review
    ]
    rows += [
        (grade.student.id, grade.student.name, "", grade.status, "", "", "", "", grade.message)
        for grade in grades
        if grade.status == "error"
    ]
    return _csv(pandas.DataFrame(rows, columns=list(c.REVIEW)))


# -- overrides ------------------------------------------------------------------------------


def read_overrides(path: str | Path) -> tuple[dict[tuple[str, str], tuple[float, str]], list[str]]:
    """A person's scores: {(student, problem.part): (points, comment)}, and the rows that could not be read."""
    overrides, issues = {}, []
    text = Path(path).read_text(encoding="utf-8-sig")
    reader = csv.DictReader(io.StringIO(text, newline=""))
    missing = set(c.OVERRIDE[:3]) - set(reader.fieldnames or ())
    if missing:
        return {}, [f"{path}, row 1: the header needs the columns {', '.join(c.OVERRIDE)}"]
    for number, row in enumerate(reader, start=2):
        try:
            points = float(row["points"])
        except (TypeError, ValueError):
            issues.append(f"{path}, row {number}: points {row.get('points')!r} is not a number; row ignored")
            continue
        student, part = _typed(row["student"].strip()), _typed(row["part"].strip())  # copied from review.csv
        overrides[(student, part)] = (points, (row.get("comment") or "").strip())
    return overrides, issues


def apply_overrides(
    grades: Sequence[SubmissionGrade], overrides: dict[tuple[str, str], tuple[float, str]]
) -> tuple[list[SubmissionGrade], list[str]]:
    """Grades with each override applied (the grader's score kept beside it), and overrides that match nothing."""
    used, result = set(), []
    for grade in grades:
        parts = []
        for part in grade.parts:
            override = overrides.get((grade.student.id, part.key))
            if override is not None:
                used.add((grade.student.id, part.key))
                points, comment = override
                part = dataclasses.replace(part, manual_score=min(max(points, 0.0), part.max_score), comment=comment)
            parts.append(part)
        result.append(dataclasses.replace(grade, parts=tuple(parts)))
    unmatched = [
        f"override for {student}, {key} matches no graded part"
        for student, key in overrides
        if (student, key) not in used
    ]
    return result, unmatched


# -- LMS imports ------------------------------------------------------------------------------


def canvas_csv(grades: Sequence[SubmissionGrade], *, assignment: str, assignment_id: str, max_score: float) -> str:
    """Canvas's gradebook import: identity columns, one assignment column, a points-possible row."""
    column = f"{assignment} ({assignment_id})"
    rows = [
        dict.fromkeys(c.CANVAS_IDENTITY, "")
        | {c.CANVAS_IDENTITY[0]: c.CANVAS_POINTS_POSSIBLE, column: f"{max_score:.2f}"}
    ]
    for grade in grades:
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
    return _csv(pandas.DataFrame(rows, columns=[*c.CANVAS_IDENTITY, column]))


def moodle_csv(grades: Sequence[SubmissionGrade], *, assignment: str) -> str:
    """Moodle's grade import: an identity column, the assignment's grade and its feedback."""
    grade_column, feedback_column = f"Assignment: {assignment}", f"Feedback: {assignment}"
    rows = [
        {
            c.MOODLE_IDENTITY: grade.student.email,
            grade_column: round(grade.score, 2),
            feedback_column: f"{grade.score:.2f} / {grade.max_score:.2f}"
            + (f" ({grade.message})" if grade.message else ""),
        }
        for grade in grades
    ]
    return _csv(pandas.DataFrame(rows, columns=[c.MOODLE_IDENTITY, grade_column, feedback_column]))
