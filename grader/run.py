"""Grading an assignment end to end: read, grade, apply a person's scores, write every output.

Contents:
    RunSummary           what happened: who was graded, who could not be, what was wrong in the input
    grade_assignment()   the library call behind ``grader grade``
    ExportSummary        what an export wrote, and who it left out
    export_grades()      the library call behind ``grader export``
    file_name(student)   a student id made safe as a file name

Outputs in the folder ``out``, written all or none (a run that fails changes none of them):
    results/<student>.json   Gradescope's results.json shape, our details under extra_data
    gradebook.csv, scores_long.csv, review.csv, summary.html, reports/<student>.html and .md
    overrides.csv            the person's scores applied, kept so they survive a regrade
    exports/                 LMS imports (``grader export``): a regrade writes those there again
    input-issues.txt         what was wrong in the submissions, by file and row

results/ and reports/ hold this run's students only (what export reads): a regrade removes
those of students it did not grade, and ``only`` keeps everyone graded before. The CSVs start
with a byte-order mark, without which Excel reads UTF-8 as Windows-1252 (θ shows as Î¸).
"""

from __future__ import annotations

import contextlib
import hashlib
import math
import re
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from pathlib import Path

from grader.bank import Assignment, Problem
from grader.errors import GraderError
from grader.export import (
    apply_overrides,
    canvas_csv,
    csv_file,
    grade_from_json,
    gradebook_csv,
    moodle_csv,
    overrides_csv,
    read_overrides,
    result_json,
    review_csv,
    scores_long_csv,
    write_all_atomic,
)
from grader.grade.batch import assignment_parts, grade_class
from grader.grade.results import Student, SubmissionGrade
from grader.grade.submissions import read_submissions
from grader.judge import DEFAULT_TIMEOUT
from grader.report import render_student_report, render_summary

__all__ = ["EXPORTS", "ExportSummary", "RunSummary", "export_grades", "file_name", "grade_assignment"]

EXPORTS = ("canvas", "moodle", "gradescope")


@dataclass(frozen=True)
class RunSummary:
    """The outcome of a run, for the command line to report."""

    out: Path
    grades: tuple[SubmissionGrade, ...]
    issues: tuple[str, ...] = ()
    failed: tuple[str, ...] = field(default=())  # students who could not be graded, with the reason
    exports: tuple[str, ...] = ()  # the LMS imports in out/exports/, written again from these grades

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
    """Grade ``submissions`` for ``assignment`` and write every output into ``out``, all or none.

    Whatever is wrong with the input is found before grading: the time limit, the submissions,
    the overrides (those saved in ``out`` and those in ``overrides``), the output folder.

    Raises:
        GraderError: the time limit is not a positive number of seconds; the submissions cannot be
            read at all, or ``only`` names no student; the overrides cannot be read or used; ``out``
            is not a folder that can be written. Nothing was graded or written.
        OSError: the outputs cannot be written; none was changed.
    """
    if not (timeout > 0 and math.isfinite(timeout)):  # nan too: a timer that cannot be set fails every check
        raise GraderError(f"the time limit must be a positive number of seconds, not {timeout}")
    parts = assignment_parts(assignment, bank)
    keys = [(f"{problem.id}.{part.id}", points) for problem, part, points in parts]
    try:
        found, input_issues = read_submissions(submissions, [key for key, _ in keys])
    except OSError as error:
        raise GraderError(f"cannot read the submissions {submissions}: {error}") from error
    issues = [str(issue) for issue in input_issues]
    if not found:  # an empty gradebook written over the last one would lose it for nothing
        listed = "".join(f"\n  {issue}" for issue in issues)
        raise GraderError(f"no student in {submissions} can be graded, so nothing was written{listed and ':'}{listed}")
    if only is not None:
        found = [s for s in found if s.student.id == only]
        if not found:
            raise GraderError(f"no submission from student {only!r} in {submissions}")
    if out.exists() and not out.is_dir():
        raise GraderError(f"the output folder {out} is a file")
    scores = _overrides(out, overrides, dict(keys))
    previous = _previous_grades(out) if only is not None else []
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        raise GraderError(f"cannot make the output folder {out}: {error.strerror or error}") from error
    if on_start:
        on_start(len(found))
    grades = grade_class(found, assignment, bank, jobs=jobs, timeout=timeout, progress=progress)
    if only is not None:
        grades = _merged(previous, grades)
    grades, unmatched = apply_overrides(grades, scores)
    issues += unmatched
    refreshed = _earlier_exports(out)
    _write_outputs(out, grades, keys, assignment, bank, issues, reveal, scores, refreshed)
    failed = tuple(f"{g.student.id}: {g.message}" for g in grades if g.status == "error")
    return RunSummary(out, tuple(grades), tuple(issues), failed, refreshed)


def _overrides(out: Path, new: Path | None, max_points: dict[str, float]) -> dict:
    """The overrides saved in ``out`` and those in ``new`` (which win), every row checked."""
    saved = out / "overrides.csv"
    overrides = read_overrides(saved, max_points=max_points) if saved.is_file() else {}
    if new is not None:
        overrides |= read_overrides(new, max_points=max_points)
    return overrides


def _previous_grades(out: Path) -> list[SubmissionGrade]:
    """Everyone graded into ``out`` before, in file order."""
    grades = []
    for path in sorted((out / "results").glob("*.json")):
        try:
            grades.append(grade_from_json(path.read_text(encoding="utf-8")))
        except (OSError, UnicodeDecodeError, ValueError, KeyError, TypeError) as error:
            raise GraderError(f"cannot read the earlier result {path}: {error}; grade everyone again") from error
    return grades


def _merged(previous: list[SubmissionGrade], regraded: list[SubmissionGrade]) -> list[SubmissionGrade]:
    """Everyone graded before, with the regraded students replaced, in the previous order."""
    fresh = {grade.student.id: grade for grade in regraded}
    return [fresh.pop(grade.student.id, grade) for grade in previous] + list(fresh.values())


def _write_outputs(out: Path, grades, keys, assignment, bank, issues, reveal, overrides, refreshed) -> None:
    """Every output, all or none; results and reports of students not in ``grades`` are removed, and
    the LMS imports in ``refreshed`` are written again from ``grades``."""
    names = [file_name(grade.student.id) for grade in grades]
    ours = {out / folder / f"{name}{suffix}" for name in names for folder, suffix in _PER_STUDENT}
    stale = [path for folder, suffix in _PER_STUDENT for path in (out / folder).glob(f"*{suffix}") if path not in ours]

    # An LMS import made from the earlier grades would post them: each is made again from these.
    exported, max_score = {}, sum(points for _, points in keys)
    in_order = sorted(grades, key=lambda grade: file_name(grade.student.id))  # as export reads results/
    for to in refreshed:
        files, gone = _export_files(out, to, in_order, assignment, max_score)
        exported |= files
        stale += gone

    def outputs() -> Iterator[tuple[Path, str | bytes]]:  # made one by one: a class's reports need not fit in memory
        for name, grade in zip(names, grades, strict=True):
            html, markdown = render_student_report(grade, assignment=assignment, bank=bank, reveal=reveal)
            yield out / "results" / f"{name}.json", result_json(grade)
            yield out / "reports" / f"{name}.html", html
            yield out / "reports" / f"{name}.md", markdown
        yield out / "gradebook.csv", csv_file(gradebook_csv(grades, keys))
        yield out / "scores_long.csv", csv_file(scores_long_csv(grades))
        yield out / "review.csv", csv_file(review_csv(grades))
        yield out / "summary.html", render_summary(list(grades), assignment=assignment, bank=bank, input_issues=issues)
        yield out / "input-issues.txt", "".join(f"{issue}\n" for issue in issues)
        if overrides:
            yield out / "overrides.csv", csv_file(overrides_csv(overrides))
        yield from exported.items()

    write_all_atomic(outputs(), remove=stale)
    _remove_empty_folders(stale)


_PER_STUDENT = (("results", ".json"), ("reports", ".html"), ("reports", ".md"))


@dataclass(frozen=True)
class ExportSummary:
    """What an export wrote, and the students it left out because they could not be graded."""

    written: tuple[Path, ...]
    not_graded: tuple[Student, ...] = ()
    waiting: int = 0  # answers waiting for a person, whose proposed points the grades include


def export_grades(out: Path, to: str, *, assignment: Assignment, max_score: float) -> ExportSummary:
    """Write an LMS import of the grades in ``out``, all or none.

    A student who could not be graded is left out (no row, no results.json): the LMS keeps their
    grade as it is, and ``not_graded`` names them for the instructor. ``waiting`` counts the answers
    still waiting for a person: the grades hold their proposed points, not yet a person's.

    Raises:
        GraderError: ``out`` holds no graded results.
    """
    paths = sorted((out / "results").glob("*.json"))
    if not paths:
        raise GraderError(f"{out} holds no results: grade first (grader grade … --out {out})")
    grades = [grade_from_json(path.read_text(encoding="utf-8")) for path in paths]
    not_graded = tuple(grade.student for grade in grades if grade.status == "error")
    files, stale = _export_files(out, to, grades, assignment, max_score)
    written = write_all_atomic(files, remove=stale)
    _remove_empty_folders(stale)
    waiting = sum(part.needs_review for grade in grades for part in grade.parts)
    return ExportSummary(tuple(written), not_graded, waiting)


def _export_files(
    out: Path, to: str, grades: list[SubmissionGrade], assignment: Assignment, max_score: float
) -> tuple[dict[Path, str | bytes], list[Path]]:
    """The files of an LMS import of ``grades`` (in results/'s order), and those of an earlier one to remove."""
    exports, stale = out / "exports", []
    if to == "canvas":
        text = canvas_csv(grades, assignment=assignment.title, assignment_id=assignment.id, max_score=max_score)
        files = {exports / "canvas.csv": csv_file(text)}
    elif to == "moodle":
        files = {exports / "moodle.csv": csv_file(moodle_csv(grades, assignment=assignment.title))}
    else:
        folder = exports / "gradescope"
        files = {
            folder / file_name(grade.student.id) / "results.json": result_json(grade)
            for grade in grades
            if grade.status != "error"
        }
        stale = [path for path in folder.glob("*/results.json") if path not in files]
    return files, stale


def _earlier_exports(out: Path) -> tuple[str, ...]:
    """The LMS imports an earlier ``grader export`` wrote into ``out``: a regrade writes them again."""
    exports = out / "exports"
    made = {"canvas": exports / "canvas.csv", "moodle": exports / "moodle.csv", "gradescope": exports / "gradescope"}
    return tuple(to for to, path in made.items() if path.exists())


def _remove_empty_folders(removed: list[Path]) -> None:
    """The folders of files removed, where nothing else is left in them (a student no longer exported)."""
    for path in removed:
        with contextlib.suppress(OSError):
            path.parent.rmdir()
