"""Reading a class's submissions: a wide CSV from an LMS, or a folder of per-student files.

Contents:
    Submission            one student's answers, keyed ``problem.part``, and where they came from
    InputIssue            something wrong in the input, by file and row; never fatal to the rest
    read_submissions(path, keys)   every submission that can be read, and every issue found

A wide CSV has a header ``id, name, email, problem.part, …`` (``id`` required). A folder
holds one YAML or JSON file per student: ``{id, name, email, answers: {problem.part: …}}``.
Unknown columns, unknown part ids, duplicate students and malformed rows are reported by
name and row, and everything else is still read.
"""

from __future__ import annotations

import csv
import io
import json
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path

import yaml

from grader.grade.results import Student

__all__ = ["InputIssue", "Submission", "read_submissions"]

MAX_INPUT_BYTES = 50_000_000
MAX_ANSWER_CHARS = 10_000  # longer cells are cut; the parser refuses anything over its own cap
_IDENTITY = ("id", "name", "email")


@dataclass(frozen=True)
class Submission:
    student: Student
    answers: dict[str, str] = field(default_factory=dict)
    source: str = ""


@dataclass(frozen=True)
class InputIssue:
    """A problem in the input, addressed to the instructor: where, and what."""

    where: str
    message: str

    def __str__(self) -> str:
        return f"{self.where}: {self.message}"


def read_submissions(path: str | Path, keys: Iterable[str]) -> tuple[list[Submission], list[InputIssue]]:
    """The submissions under ``path`` (a CSV file or a folder), for the parts ``keys``.

    Raises:
        OSError: when the path itself cannot be read (a usage error, not a bad row).
    """
    path, keys = Path(path), list(keys)
    if path.is_dir():
        submissions, issues = _read_folder(path, set(keys))
    else:
        submissions, issues = _read_csv(path, set(keys))
    return _without_duplicates(submissions, issues)


def _read_csv(path: Path, keys: set[str]) -> tuple[list[Submission], list[InputIssue]]:
    if path.stat().st_size > MAX_INPUT_BYTES:
        raise OSError(f"{path} is larger than {MAX_INPUT_BYTES} bytes")
    text = path.read_bytes().decode("utf-8-sig", errors="replace")  # Excel writes a BOM
    rows = csv.reader(io.StringIO(text, newline=""))
    issues: list[InputIssue] = []
    try:
        header = [cell.strip() for cell in next(rows)]
    except StopIteration:
        return [], [InputIssue(str(path), "the file is empty")]
    lower = [cell.lower() for cell in header]
    if "id" not in lower:
        return [], [InputIssue(f"{path}, row 1", "the header has no 'id' column")]
    columns = {}
    for index, name in enumerate(header):
        if lower[index] in _IDENTITY:
            columns[index] = lower[index]
        elif name in keys:
            columns[index] = name
        elif name:
            issues.append(
                InputIssue(
                    f"{path}, row 1, column {index + 1}", f"unknown column {name!r}: not a part of this assignment"
                )
            )
    submissions = []
    for number, row in enumerate(rows, start=2):
        where = f"{path}, row {number}"
        if not any(cell.strip() for cell in row):
            continue
        if len(row) > len(header):
            issues.append(InputIssue(where, f"the row has {len(row)} cells but the header {len(header)}; row skipped"))
            continue
        values = {columns[i]: cell for i, cell in enumerate(row) if i in columns}
        student_id = values.get("id", "").strip()
        if not student_id:
            issues.append(InputIssue(where, "the row has no student id; row skipped"))
            continue
        student = Student(student_id, values.get("name", "").strip(), values.get("email", "").strip())
        answers = {key: value[:MAX_ANSWER_CHARS] for key, value in values.items() if key not in _IDENTITY}
        submissions.append(Submission(student, answers, where))
    return submissions, issues


def _read_folder(folder: Path, keys: set[str]) -> tuple[list[Submission], list[InputIssue]]:
    submissions, issues = [], []
    files = sorted(p for p in folder.iterdir() if p.suffix.lower() in (".yaml", ".yml", ".json"))
    for path in files:
        where = str(path)
        try:
            if path.stat().st_size > MAX_INPUT_BYTES:
                raise ValueError("the file is too large")
            text = path.read_text(encoding="utf-8")
            data = json.loads(text) if path.suffix.lower() == ".json" else yaml.safe_load(text)
        except (OSError, ValueError, yaml.YAMLError) as error:
            issues.append(InputIssue(where, f"cannot be read: {error}"))
            continue
        if not isinstance(data, dict) or not isinstance(data.get("answers", {}), dict):
            issues.append(InputIssue(where, "expected a mapping with id, name, email and answers"))
            continue
        student_id = str(data.get("id") or path.stem).strip()
        answers = {}
        for key, value in data.get("answers", {}).items():
            if key not in keys:
                issues.append(InputIssue(where, f"unknown part {key!r}: not a part of this assignment"))
                continue
            answers[key] = "" if value is None else str(value)[:MAX_ANSWER_CHARS]
        student = Student(student_id, str(data.get("name") or ""), str(data.get("email") or ""))
        submissions.append(Submission(student, answers, where))
    return submissions, issues


def _without_duplicates(submissions: list[Submission], issues: list[InputIssue]):
    seen: dict[str, Submission] = {}
    kept = []
    for submission in submissions:
        first = seen.get(submission.student.id)
        if first is not None:
            issues.append(InputIssue(submission.source, f"student {submission.student.id!r} also appears at "
                                     f"{first.source}; the first one is graded"))  # fmt: skip
            continue
        seen[submission.student.id] = submission
        kept.append(submission)
    return kept, issues
