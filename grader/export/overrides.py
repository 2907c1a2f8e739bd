"""A person's scores over the grader's: read and checked, applied, and saved.

Contents:
    read_overrides(path, max_points=)    {(student, problem.part): (points, comment)}, every row checked
    apply_overrides(grades, overrides)   the grades with a person's scores, and the overrides that match nothing
    overrides_csv(overrides)             overrides.csv as the grader saves it, for read_overrides to read again

An overrides file is a CSV with the columns student, part, points and, if wanted, comment; other
columns are ignored, so the review.csv the grader writes is one once its points column is filled
in. A row whose points are empty is not scored yet and is skipped. Excel's way of saving is read
too: a byte-order mark, Windows-1252 text, ";" between cells and a decimal comma.
"""

from __future__ import annotations

import csv
import dataclasses
import io
import math
import re
from collections.abc import Mapping, Sequence
from pathlib import Path

from grader.errors import GraderError
from grader.export import columns as c
from grader.export.spreadsheet import csv_text, typed
from grader.grade.results import SubmissionGrade

__all__ = ["apply_overrides", "overrides_csv", "read_overrides"]

Overrides = dict[tuple[str, str], tuple[float, str]]

_DECIMAL_COMMA = re.compile(r"[+-]?\d+,\d+")
_SLACK = 1e-9  # a part worth 10/3 points is 3.3333333333333335: typing its full worth back is not more


def read_overrides(path: str | Path, *, max_points: Mapping[str, float]) -> Overrides:
    """A person's scores: {(student, problem.part): (points, comment)}.

    ``max_points``: what each part of the assignment is worth (problem.part → points). A part not
    in it is read unchecked: it matches no graded part, which :func:`apply_overrides` reports.

    Raises:
        GraderError: the file cannot be read; its header lacks student, part or points; or rows
            cannot be used (points that are not a number from 0 to the part's worth, or that differ
            from another row's for the same student and part). Every such row is listed by file,
            row, student and part.
    """
    path = Path(path)
    text = _text(path)
    try:
        table = list(csv.reader(io.StringIO(text, newline=""), delimiter=_delimiter(text)))
    except csv.Error as error:
        raise GraderError(f"cannot read the overrides {path} as CSV: {error}") from error
    header = [typed(name.strip()).lower() for name in (table[0] if table else [])]
    missing = [name for name in c.OVERRIDE[:3] if name not in header]
    if missing:
        raise GraderError(
            f"{path}, row 1: the header needs the columns student, part and points (and may have comment);"
            f" {', '.join(missing)} {'is' if len(missing) == 1 else 'are'} missing"
        )
    overrides: dict[tuple[str, str], tuple[float, str, int]] = {}
    problems = []
    for number, cells in enumerate(table[1:], start=2):
        row = dict(zip(header, (typed(cell.strip()) for cell in cells), strict=False))
        raw = row.get("points", "")
        if not raw:
            continue  # not scored yet: a review.csv row left for later
        student, part = row.get("student", ""), row.get("part", "")
        if not student or not part:
            problems.append(f"{path}, row {number}: points {raw!r} for no {'student' if not student else 'part'}")
            continue
        where = f"{path}, row {number} (student {student!r}, part {part!r})"
        points = _points(raw)
        maximum = max_points.get(part, math.inf)
        if points is None or not 0 <= points <= maximum + _SLACK:
            worth = f"from 0 to {maximum:g}, what the part is worth" if maximum < math.inf else "of at least 0"
            problems.append(f"{where}: points must be a number {worth}, not {raw!r}")
            continue
        earlier = overrides.setdefault((student, part), (points, row.get("comment", ""), number))
        if earlier[0] != points:
            problems.append(f"{where}: points {raw!r}, but row {earlier[2]} gives this part {earlier[0]:g}")
    if problems:
        raise GraderError("the overrides cannot be used:\n" + "\n".join(f"  {problem}" for problem in problems))
    return {key: (points, comment) for key, (points, comment, _) in overrides.items()}


def _text(path: Path) -> str:
    try:
        data = path.read_bytes()
    except OSError as error:
        raise GraderError(f"cannot read the overrides {path}: {error.strerror or error}") from error
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError:
        pass
    try:
        return data.decode("cp1252")  # what Excel on Windows saves as "CSV"
    except UnicodeDecodeError as error:
        raise GraderError(f"cannot read the overrides {path}: not UTF-8 text; save it as CSV UTF-8") from error


def _delimiter(text: str) -> str:
    """The delimiter the header uses: ",", or ";" (or a tab) as Excel saves CSV where a comma is the decimal mark."""
    header = text.partition("\n")[0]
    return max((",", ";", "\t"), key=header.count)


def _points(raw: str) -> float | None:
    """The number a person typed (``1.5`` or ``1,5``), or None; never nan or an infinity."""
    try:
        points = float(raw.replace(",", ".") if _DECIMAL_COMMA.fullmatch(raw) else raw)
    except ValueError:
        return None
    return points if math.isfinite(points) else None


def apply_overrides(grades: Sequence[SubmissionGrade], overrides: Overrides) -> tuple[list[SubmissionGrade], list[str]]:
    """Grades with each override applied (the grader's score kept beside it), and overrides that match nothing.

    The points are used as given: :func:`read_overrides` has checked them against each part's worth.
    """
    used, result = set(), []
    for grade in grades:
        parts = []
        for part in grade.parts:
            override = overrides.get((grade.student.id, part.key))
            if override is not None:
                used.add((grade.student.id, part.key))
                points, comment = override
                part = dataclasses.replace(part, manual_score=points, comment=comment)
            parts.append(part)
        result.append(dataclasses.replace(grade, parts=tuple(parts)))
    unmatched = [
        f"override for {student}, {key} matches no graded part"
        for student, key in overrides
        if (student, key) not in used
    ]
    return result, unmatched


def overrides_csv(overrides: Overrides) -> str:
    """overrides.csv: every override, as :func:`read_overrides` reads it back."""
    rows = [(student, key, points, comment) for (student, key), (points, comment) in overrides.items()]
    return csv_text(rows, c.OVERRIDE)
