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

import codecs
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
_SCALARS = (str, int, float)  # what a cell of a submission file may hold (bool is an int)
# A cell may be as long as the file; the csv module's default cap (131,072) would stop the
# whole class at one long answer. Raising it is process-wide, and only ever looser.
csv.field_size_limit(max(csv.field_size_limit(), MAX_INPUT_BYTES))


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
    issues: list[InputIssue] = []
    text = _decoded(path, path.read_bytes(), issues)
    rows = csv.reader(io.StringIO(text, newline=""))
    try:
        header = [cell.strip() for cell in next(rows)]
    except StopIteration:
        return [], [InputIssue(str(path), "the file is empty")]
    except csv.Error as error:
        return [], [InputIssue(f"{path}, row 1", f"the header cannot be read: {error}")]
    lower = [cell.lower() for cell in header]
    if "id" not in lower:
        return [], [InputIssue(f"{path}, row 1", "the header has no 'id' column")]
    columns: dict[int, str] = {}
    for index, name in enumerate(header):
        column = lower[index] if lower[index] in _IDENTITY else name if name in keys else None
        if column is not None and column in columns.values():
            first = next(i for i, c in columns.items() if c == column) + 1
            issues.append(
                InputIssue(f"{path}, row 1, column {index + 1}", f"{column!r} is also column {first}; that one is read")
            )
        elif column is not None:
            columns[index] = column
        elif name:
            issues.append(
                InputIssue(
                    f"{path}, row 1, column {index + 1}", f"unknown column {name!r}: not a part of this assignment"
                )
            )
    submissions = []
    for number, row in _numbered(rows, path, issues):
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


def _decoded(path: Path, data: bytes, issues: list[InputIssue]) -> str:
    """The file's text: UTF-8 (with Excel's BOM or without), else Windows-1252, which is what
    Excel on Windows saves as "CSV" and which decodes any byte, said so to the instructor."""
    if data.startswith((codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE)):  # "Unicode" as some spreadsheets save it
        try:
            return data.decode("utf-16").replace("\x00", "")
        except UnicodeDecodeError:
            pass
    if b"\x00" in data:  # never text; echoed into reports and CSVs it breaks other tools
        issues.append(InputIssue(str(path), "the file holds NUL characters; they are left out"))
        data = data.replace(b"\x00", b"")
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as error:
        issues.append(
            InputIssue(
                str(path),
                f"not UTF-8 (byte {error.start + 1}); read as Windows-1252 (Latin-1): check accented names and answers,"
                " or save the file as CSV UTF-8",
            )
        )
        return data.decode("cp1252", errors="replace")


def _numbered(rows, path: Path, issues: list[InputIssue]):
    """(row number, cells) from row 2 on; a row the csv module cannot read ends the file, said so."""
    number = 1
    while True:
        number += 1
        try:
            row = next(rows)
        except StopIteration:
            return
        except csv.Error as error:
            issues.append(
                InputIssue(f"{path}, row {number}", f"cannot be read ({error}); this row and the rest skipped")
            )
            return
        yield number, row


def _read_folder(folder: Path, keys: set[str]) -> tuple[list[Submission], list[InputIssue]]:
    submissions, issues = [], []
    files = sorted(p for p in folder.iterdir() if p.suffix.lower() in (".yaml", ".yml", ".json"))
    for path in files:
        where = str(path)
        try:
            if path.stat().st_size > MAX_INPUT_BYTES:
                raise ValueError("the file is too large")
            text = _decoded(path, path.read_bytes(), issues)
            data = json.loads(text) if path.suffix.lower() == ".json" else yaml.safe_load(text)
        except (OSError, ValueError, yaml.YAMLError) as error:
            issues.append(InputIssue(where, f"cannot be read: {error}"))
            continue
        except RecursionError:  # [[[[…: nested deeper than the reader's stack
            issues.append(InputIssue(where, "cannot be read: nested too deeply"))
            continue
        if not isinstance(data, dict) or not isinstance(data.get("answers", {}), dict):
            issues.append(InputIssue(where, "expected a mapping with id, name, email and answers"))
            continue
        identity = {name: data.get(name) for name in _IDENTITY}
        if not all(value is None or isinstance(value, _SCALARS) for value in identity.values()):
            issues.append(InputIssue(where, "id, name and email must each be text"))
            continue
        student_id = str(identity["id"] or path.stem).strip()
        answers = {}
        for key, value in data.get("answers", {}).items():
            if key not in keys:
                issues.append(InputIssue(where, f"unknown part {str(key)[:80]!r}: not a part of this assignment"))
                continue
            if value is not None and not isinstance(value, _SCALARS):
                # str() of a list would build all of it first: nine YAML aliases nine deep are 387 M items
                issues.append(
                    InputIssue(where, f"the answer to {key} is a {type(value).__name__}, not text; left blank")
                )
                value = None
            answers[key] = "" if value is None else str(value)[:MAX_ANSWER_CHARS]
        student = Student(student_id, str(identity["name"] or ""), str(identity["email"] or ""))
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
