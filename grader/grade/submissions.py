"""Reading a class's submissions: a wide CSV from an LMS, or a folder of per-student files.

Contents:
    Submission            one student's answers, keyed ``problem.part``, and where they came from
    InputIssue            something wrong in the input, by file and row; never fatal to the rest
    read_submissions(path, keys)   every submission that can be read, and every issue found

A wide CSV has a header ``id, name, email, problem.part, …`` (``id`` required; names match in
any case and with spaces around them), separated by commas, or by ``;`` or tabs as a
spreadsheet saves "CSV" where the comma is the decimal point. A folder holds one YAML or JSON
file per student: ``{id, name, email, answers: {problem.part: …}}``. Unknown columns, parts
with no column, unknown part ids, duplicate students and malformed rows (too few or too many
cells, a quote left open) are reported by file, row and line, and everything else is still
read. A file that cannot be used at all (empty, no ``id`` column, no column of the assignment,
no students) raises ``GraderError``.

Bytes that are not UTF-8 in a file that otherwise is are read as �, each reported where it is,
and the answers that hold one are listed in ``Submission.garbled`` for a person to check.
"""

from __future__ import annotations

import codecs
import csv
import io
import json
import re
from collections.abc import Iterable
from dataclasses import dataclass, field, replace
from pathlib import Path

import yaml

from grader.bank import repeated_keys
from grader.errors import GraderError
from grader.grade.results import Student

__all__ = ["InputIssue", "Submission", "read_submissions"]

MAX_INPUT_BYTES = 50_000_000
MAX_ANSWER_CHARS = 10_000  # longer cells are cut; the parser refuses anything over its own cap
_IDENTITY = ("id", "name", "email")
_SCALARS = (str, int, float)  # what a cell of a submission file may hold (bool is an int)
_DELIMITERS = (",", ";", "\t")  # a comma, else what spreadsheets save as "CSV" where 2,5 is a number
_NOT_UTF8 = re.compile("[\udc80-\udcff]")  # how errors="surrogateescape" holds a byte that is not UTF-8
_LONE_CR = re.compile(r"\r(?!\n)")
_PRIVATE_USE = re.compile("[\ue000-\uf8ff]")
_LOOKAHEAD = 10  # lines past a malformed row read to see whether another row starts inside it
_SHOWN = 40  # characters of a line quoted in a message
_LISTED = 10  # parts or lines named in one message before "and N more"
# A cell may be as long as the file; the csv module's default cap (131,072) would stop the
# whole class at one long answer. Raising it is process-wide, and only ever looser.
csv.field_size_limit(max(csv.field_size_limit(), MAX_INPUT_BYTES))


@dataclass(frozen=True)
class Submission:
    """One student's answers.

    Attributes:
        student: id, name and email.
        answers: the answer to each part, keyed ``problem.part``, as typed.
        source: where it was read: the file, and for a CSV the row and its lines.
        garbled: the parts whose answer held bytes that are not UTF-8, read as �: a person must look.
    """

    student: Student
    answers: dict[str, str] = field(default_factory=dict)
    source: str = ""
    garbled: frozenset[str] = frozenset()


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
        GraderError: when a CSV cannot be used at all: empty, with no ``id`` column or no column
            of the assignment, or with no student in it.
    """
    path, keys = Path(path), list(keys)
    if path.is_dir():
        submissions, issues = _read_folder(path, set(keys))
    else:
        submissions, issues = _read_csv(path, keys)
    return _without_duplicates(submissions, issues)


def _read_csv(path: Path, keys: list[str]) -> tuple[list[Submission], list[InputIssue]]:
    if path.stat().st_size > MAX_INPUT_BYTES:
        raise OSError(f"{path} is larger than {MAX_INPUT_BYTES} bytes")
    issues: list[InputIssue] = []
    text = _header(path, _Lines.of(_decoded(path, path.read_bytes(), issues)))
    header = [cell.strip() for cell in next(text.rows())]
    columns = _columns(path, header, keys, issues)
    id_column = next(index for index, column in columns.items() if column == "id")
    rows = text.rows()
    next(rows)
    submissions, students = [], 0
    for number, first, last, row in _numbered(rows, path, issues):
        if not any(cell.strip() for cell in row):
            continue
        students += 1
        where = f"{path}, row {number} ({_span(first, last)})"
        student_id = _NOT_UTF8.sub("\ufffd", text.restored(row[id_column])).strip() if id_column < len(row) else ""
        who = f"{where}, student {student_id!r}" if student_id else where
        malformed = _malformed(row, len(header), text, first, last)
        if malformed:
            issues.append(InputIssue(who, f"{malformed}; row skipped"))
            continue
        if not student_id:
            issues.append(InputIssue(where, "the row has no student id; row skipped"))
            continue
        values = {column: text.restored(row[index]) for index, column in columns.items()}
        garbled = _not_utf8(values, who, issues)
        student = Student(student_id, values.get("name", "").strip(), values.get("email", "").strip())
        answers = {key: value[:MAX_ANSWER_CHARS] for key, value in values.items() if key not in _IDENTITY}
        submissions.append(Submission(student, answers, where, garbled))
    if not students:
        raise GraderError(f"{path} has a header but no rows of answers: there is no student to grade")
    return submissions, issues


def _not_utf8(values: dict[str, str], who: str, issues: list[InputIssue]) -> frozenset[str]:
    """Put � for each byte that is not UTF-8 in ``values``, say where, and return the parts that held one."""
    garbled = set()
    for column, cell in values.items():
        bad = _NOT_UTF8.findall(cell)
        if bad and column in _IDENTITY:
            issues.append(InputIssue(who, f"the {column} holds {_bytes(bad)}, read as �"))
        elif bad:
            issues.append(InputIssue(f"{who}, part {column}", f"the answer holds {_bytes(bad)}, read as �; it goes "
                                     "to a person to check"))  # fmt: skip
            garbled.add(column)
        values[column] = _NOT_UTF8.sub("\ufffd", cell) if bad else cell
    return frozenset(garbled)


@dataclass(frozen=True)
class _Lines:
    """A CSV file's lines, each with its line break, and how rows are read from them."""

    lines: list[str]
    stand_in: str = ""  # what a lone carriage return is read as (see ``of``), or nothing
    delimiter: str = ","

    @classmethod
    def of(cls, text: str) -> _Lines:
        """The lines of ``text``.

        Where lines end in ``\\n``, a ``\\r`` alone is part of a cell (an answer pasted from an old
        Mac program, or put there to split a row), but the csv module would end the row at it. It
        is read as a character the file does not hold, and put back in each cell.
        """
        stand_in = ""
        if "\n" in text and _LONE_CR.search(text):
            held = set(_PRIVATE_USE.findall(text))  # one pass: a test per candidate could be 6,400 passes
            stand_in = next((chr(code) for code in range(0xE000, 0xF900) if chr(code) not in held), "")
            text = _LONE_CR.sub(stand_in, text) if stand_in else text
        return cls(io.StringIO(text, newline="").readlines(), stand_in)

    @property
    def newline(self) -> str:
        return "\n" if self.lines[0].endswith("\n") else "\r"  # \n or \r\n, or (old Macs) \r

    def rows(self, line: int = 1, *, strict: bool = False):
        """A csv reader from ``line`` on (the header is line 1); cells hold the stand-in, see ``restored``."""
        lines = self.lines if line == 1 else self.lines[line - 1 :]
        return csv.reader(lines, delimiter=self.delimiter, strict=strict)

    def restored(self, cell: str) -> str:
        return cell.replace(self.stand_in, "\r") if self.stand_in else cell

    def shown(self, line: int) -> str:
        """The start of ``line``, quoted for a message; escapes show what it holds (it may be anything)."""
        text = _NOT_UTF8.sub("\ufffd", self.restored(self.lines[line - 1])).rstrip("\r\n")
        return repr(text if len(text) <= _SHOWN else f"{text[:_SHOWN]}…")

    def begins_a_row(self, line: int, width: int, *, before: int) -> bool:
        """Whether a row of ``width`` cells, another student's say, starts at ``line`` and ends before ``before``.

        Reading stops there, so a file where every row looks malformed is read a few times over, not once a row.
        """
        try:
            return len(next(csv.reader(self.lines[line - 1 : before - 1], delimiter=self.delimiter))) == width
        except (StopIteration, csv.Error):
            return False

    def left_open(self, first: int, last: int) -> bool:
        """Whether the row on lines ``first`` to ``last`` opens a quote that never closes.

        Only the last row can: not strict, the csv module reads the rest of the file into its cell.
        """
        if last < len(self.lines):
            return False
        try:
            for _ in self.rows(first, strict=True):
                pass
        except csv.Error as error:  # strict, it says so in these words (and refuses "a"b, which is not this)
            return str(error) == "unexpected end of data"
        return False


def _header(path: Path, text: _Lines) -> _Lines:
    """The file's lines with the separator its header is written with: a comma, else ``;`` or a tab.

    Raises:
        GraderError: the file is empty, or its first line is not a header with an ``id`` column.
    """
    if not any(line.strip() for line in text.lines):
        raise GraderError(f"{path} is empty: no header and no students")
    for delimiter in _DELIMITERS:
        try:
            header = next(replace(text, delimiter=delimiter).rows())
        except csv.Error as error:
            raise GraderError(f"{path}, row 1: the header cannot be read: {error}") from error
        if "id" in (cell.strip().lower() for cell in header):
            return replace(text, delimiter=delimiter)
    raise GraderError(
        f"{path}, row 1: the header has no 'id' column: a CSV is expected, separated by commas, with the header "
        f"id, name, email, then a column per problem.part; its first line begins {text.shown(1)}"
    )


def _columns(path: Path, header: list[str], keys: list[str], issues: list[InputIssue]) -> dict[int, str]:
    """Which column holds what (``id``, ``name``, ``email`` or a part's key), by index.

    A part's column matches in any case. Unknown and repeated columns, and parts with no
    column, are reported.

    Raises:
        GraderError: no column is a part of the assignment: the file is for another one.
    """
    in_any_case = {key.lower(): key for key in reversed(keys)}  # were two keys one but for case, the first
    columns: dict[int, str] = {}
    for index, name in enumerate(header):
        lower = name.lower()
        column = lower if lower in _IDENTITY else name if name in keys else in_any_case.get(lower)
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
    missing = [key for key in keys if key not in columns.values()]
    if keys and len(missing) == len(keys):
        raise GraderError(
            f"{path}, row 1: no column of the header is a part of this assignment (a column per problem.part, such "
            f"as {keys[0]!r}): is it the file for another assignment?"
        )
    if missing:
        some = "1 part" if len(missing) == 1 else f"{len(missing)} parts"
        issues.append(
            InputIssue(f"{path}, row 1", f"no column for {some} of this assignment, so everyone's answer is blank: "
                       f"{_listed(missing)}")
        )  # fmt: skip
    return columns


def _numbered(rows, path: Path, issues: list[InputIssue]):
    """(row number, its first and last line, cells) from row 2 on; a row the csv module cannot read ends it."""
    number = 1
    while True:
        number += 1
        first = rows.line_num + 1
        try:
            row = next(rows)
        except StopIteration:
            return
        except csv.Error as error:
            where = f"{path}, row {number} (line {first})"
            issues.append(InputIssue(where, f"cannot be read ({error}); this row and the rest skipped"))
            return
        yield number, first, rows.line_num, row


def _malformed(row: list[str], width: int, text: _Lines, first: int, last: int) -> str:
    """Why the row on lines ``first`` to ``last`` cannot be read cell by cell under the header, or ``""``.

    A quote left open joins the lines after it into one cell, up to the next quote or the end
    of the file: the row has the wrong number of cells (or, at the end, maybe the right one), and
    the students on those lines vanish. Where that is what happened, the line swallowed is shown.
    """
    newline = text.newline
    left_open = text.left_open(first, last)
    if len(row) == width and not left_open:
        return ""
    counted = f"the row has {len(row)} cells but the header {width}"
    # with the quote left open, the cell it opens runs to the end of the file: the last one
    broken = len(row) - 1 if left_open else next((i for i, cell in enumerate(row) if newline in cell), None)
    if broken is None:
        return counted
    opened = first + sum(cell.count(newline) for cell in row[:broken])
    if left_open:
        said = f"the quote that opens cell {broken + 1} on line {opened} never closes"
        if opened == last:
            return said
        return f"{said}, so the rest of the file was read into it (line {opened + 1} starts {text.shown(opened + 1)})"
    if not text.begins_a_row(opened + 1, width, before=last + 1 + _LOOKAHEAD):  # a line break in an answer
        return counted
    return (
        f"{counted}: the quote that opens cell {broken + 1} on line {opened} closes only on line "
        f"{opened + row[broken].count(newline)}, and line {opened + 1}, read into that cell, begins a row of its own "
        f"({text.shown(opened + 1)}): most likely a quote was left open on line {opened}"
    )


def _span(first: int, last: int) -> str:
    return f"line {first}" if first == last else f"lines {first}–{last}"


def _listed(names: list[str]) -> str:
    shown = ", ".join(names[:_LISTED])
    return shown if len(names) <= _LISTED else f"{shown} and {len(names) - _LISTED} more"


def _bytes(bad: list[str]) -> str:
    """'a byte that is not UTF-8 (0xED)', from the stand-ins errors="surrogateescape" put for them."""
    values = ", ".join(f"0x{ord(char) - 0xDC00:02X}" for char in bad[:_LISTED])
    many = "a byte that is" if len(bad) == 1 else f"{len(bad)} bytes that are"
    return f"{many} not UTF-8 ({values})"


def _decoded(path: Path, data: bytes, issues: list[InputIssue]) -> str:
    """The file's text: UTF-8 (with Excel's BOM or without), else Windows-1252, which is what
    Excel on Windows saves as "CSV" and which decodes any byte, said so to the instructor.

    A file that is UTF-8 but for a few bytes (a line pasted from elsewhere, a character cut in
    two) is UTF-8: read as Windows-1252 every other accent and symbol would be garbled. Each bad
    byte is kept as the stand-in ``errors="surrogateescape"`` gives it, which no text decoded
    from UTF-8 holds, so the cell that holds it can be named; callers put � in its place.
    """
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
        first_bad = error.start
    text = data.decode("utf-8-sig", errors="surrogateescape")
    bad = [match.start() for match in _NOT_UTF8.finditer(text)]
    beyond_ascii = len(text) - len(text.encode("ascii", errors="ignore")) - len(bad)
    # Windows-1252 text has UTF-8's shape only by chance (Ã then ©), and rarely: fewer such
    # characters than bad bytes is a Windows-1252 file
    if beyond_ascii < len(bad):
        issues.append(
            InputIssue(
                str(path),
                f"not UTF-8 (byte {first_bad + 1}); read as Windows-1252 (Latin-1): check accented names and answers,"
                " or save the file as CSV UTF-8",
            )
        )
        return data.decode("cp1252", errors="replace")
    newline = "\n" if "\n" in text else "\r"
    lines = sorted({text.count(newline, 0, start) + 1 for start in bad[:_LISTED]})
    listed = ", ".join(map(str, lines)) + (", …" if len(bad) > _LISTED else "")
    where = f"line {listed}" if len(lines) == 1 else f"lines {listed}"
    many = "a byte" if len(bad) == 1 else f"{len(bad)} bytes"
    message = f"{many} not UTF-8 in a file that otherwise is ({where}): read as �, and an answer that holds one goes"
    issues.append(InputIssue(str(path), f"{message} to a person"))
    return text


def _read_folder(folder: Path, keys: set[str]) -> tuple[list[Submission], list[InputIssue]]:
    submissions, issues = [], []
    files = sorted(p for p in folder.iterdir() if p.suffix.lower() in (".yaml", ".yml", ".json"))
    for path in files:
        where = str(path)
        try:
            if path.stat().st_size > MAX_INPUT_BYTES:
                raise ValueError("the file is too large")
            text = _decoded(path, path.read_bytes(), issues)
            garbled_file = _NOT_UTF8.search(text) is not None
            text = _NOT_UTF8.sub("\ufffd", text)  # YAML refuses the stand-ins, and JSON would keep them
            data, repeated = _loaded(text, json_file=path.suffix.lower() == ".json")
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
        for key, line in repeated:
            at = f"{where}, line {line}" if line else where
            issues.append(InputIssue(at, f"{str(key)[:80]!r} is given twice; the last one is read"))
        answers, garbled = {}, set()
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
            if garbled_file and "\ufffd" in answers[key]:
                issues.append(InputIssue(f"{where}, part {key}", "the answer holds bytes that are not UTF-8, read "
                                         "as �; it goes to a person to check"))  # fmt: skip
                garbled.add(key)
        student = Student(student_id, str(identity["name"] or ""), str(identity["email"] or ""))
        submissions.append(Submission(student, answers, where, frozenset(garbled)))
    return submissions, issues


class _RepeatsNoted(yaml.SafeLoader):
    """Safe YAML that notes each key given twice in one mapping, of which YAML keeps the last silently."""

    def __init__(self, stream):
        super().__init__(stream)
        self.repeated: list[tuple[object, int | None]] = []

    def construct_mapping(self, node, deep=False):
        self.repeated += [(key, line) for key, line, _ in repeated_keys(node)]
        return super().construct_mapping(node, deep)


def _loaded(text: str, *, json_file: bool) -> tuple[object, list[tuple[object, int | None]]]:
    """A submission file's data, and each key it gives twice in one mapping (with its line, in YAML):
    a part answered twice, of which only the last would otherwise be seen."""
    repeated: list[tuple[object, int | None]] = []
    if json_file:

        def noted(pairs):
            keys = [key for key, _ in pairs]
            repeated.extend((key, None) for index, key in enumerate(keys) if key in keys[:index])
            return dict(pairs)

        return json.loads(text, object_pairs_hook=noted), repeated
    loader = _RepeatsNoted(text)
    try:
        return loader.get_single_data(), loader.repeated
    finally:
        loader.dispose()


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
