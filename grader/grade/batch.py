"""Grading a class: each submission against an assignment, in parallel worker processes.

Contents:
    grade_submission(submission, assignment, bank, timeout)   one student's SubmissionGrade
    grade_class(submissions, assignment, bank, jobs=, timeout=, progress=)   everyone, in order

One student's failure is that student's result, never the batch's: an exception while
grading becomes a SubmissionGrade with status ``error``; a worker process that dies (a
memory limit, a crash) is replaced, and only the submission it was grading is lost.
Workers are forked with the bank already loaded and recycled after a number of tasks,
because sympy's cache does not give memory back.
"""

from __future__ import annotations

import concurrent.futures
import contextlib
import multiprocessing
import os
import resource
from collections.abc import Callable, Sequence
from dataclasses import replace

from grader.bank import Assignment, Part, Problem
from grader.grade.part import grade_answer
from grader.grade.results import PartGrade, SubmissionGrade
from grader.grade.submissions import Submission
from grader.judge import DEFAULT_TIMEOUT

__all__ = ["assignment_parts", "grade_class", "grade_submission", "limit_memory"]

GARBLED = "Part of this answer could not be read from the file it came in (shown as �): a person will check it."
TASKS_PER_WORKER = 200  # then the worker is replaced, and its memory returned
WORKER_MEMORY = 1_500_000_000  # bytes of address space; past it sympy raises MemoryError


def assignment_parts(assignment: Assignment, bank: dict[str, Problem]) -> list[tuple[Problem, Part, float]]:
    """(problem, part, points in this assignment) for every part the assignment sets, in order."""
    parts = []
    for item in assignment.items:
        problem = bank[item.problem]
        chosen = [p for p in problem.parts if not item.parts or p.id in item.parts]
        total = sum(p.points for p in chosen)
        scale = item.points / total if item.points else 1.0
        parts += [(problem, part, part.points * scale) for part in chosen]
    return parts


def grade_submission(
    submission: Submission,
    assignment: Assignment,
    bank: dict[str, Problem],
    *,
    timeout: float = DEFAULT_TIMEOUT,
    graded: dict | None = None,
) -> SubmissionGrade:
    """Every part of the assignment for one student.

    ``graded``, a dict kept for one grading run, holds every answer's grade as it is made: an
    answer another student already gave, character for character, takes that grade instead of
    being graded again. Verdicts are deterministic, so it is the grade it would get anyway.
    A part in ``submission.garbled`` lost bytes when its file was read: right or wrong, it is
    ``undecided``, its score proposed for a person to confirm.
    """
    grades = []
    for problem, part, points in assignment_parts(assignment, bank):
        answer = submission.answers.get(f"{problem.id}.{part.id}", "")
        # carried-forward credit depends on the answer derived from, too
        source = submission.answers.get(f"{problem.id}.{part.derive_from}", "") if part.derive_from else None
        key = (problem.id, part.id, points, answer, source)
        grade = graded.get(key) if graded is not None else None
        if grade is None:
            grade = _grade_part(problem, part, points, answer, submission.answers, timeout)
            if graded is not None:
                graded[key] = grade
        if f"{problem.id}.{part.id}" in submission.garbled:
            grade = _for_a_person(grade)
        grades.append(grade)
    return SubmissionGrade(submission.student, tuple(grades))


def _for_a_person(grade: PartGrade) -> PartGrade:
    """A grade for an answer that lost bytes on the way: what was read is graded, and a person confirms it."""
    status = "undecided" if grade.status in ("equivalent", "not_equivalent") else grade.status
    return replace(grade, status=status, feedback=(*grade.feedback, GARBLED))


def _grade_part(problem: Problem, part: Part, points: float, answer: str, answers: dict, timeout: float) -> PartGrade:
    base = {"problem": problem.id, "part": part.id, "max_score": points, "answer": answer, "kind": part.kind}
    if not answer.strip():
        return PartGrade(**base, status="blank", auto_score=0.0, feedback=("No answer.",), method="blank")
    verdict = grade_answer(problem, part, answer, timeout=timeout, answers=answers)
    score, feedback, method = verdict.score, verdict.feedback, verdict.method
    mathml = ""
    if verdict.answer is not None and verdict.answer.ok:
        mathml = verdict.answer.read_as_mathml
    return PartGrade(
        **base, status=verdict.status, auto_score=round(score * points, 6), feedback=feedback,
        diagnosis=verdict.diagnosis, method=method, read_as=verdict.read_as, read_as_mathml=mathml,
    )  # fmt: skip


# -- the class, in parallel ----------------------------------------------------------

_WORK: dict = {}  # set in the parent before forking, so workers inherit the bank


def limit_memory() -> None:
    """Cap this worker process's address space at WORKER_MEMORY (batch and self-check workers)."""
    # Where the limit cannot be set, recycling the workers still bounds their memory.
    with contextlib.suppress(ValueError, OSError):
        resource.setrlimit(resource.RLIMIT_AS, (WORKER_MEMORY, WORKER_MEMORY))


def _grade_one(index: int) -> tuple[int, SubmissionGrade]:
    submission = _WORK["submissions"][index]
    try:
        arguments = {"timeout": _WORK["timeout"], "graded": _WORK["graded"]}
        return index, grade_submission(submission, _WORK["assignment"], _WORK["bank"], **arguments)
    except Exception as error:  # one student's failure is that student's result
        return index, _failed(submission, f"could not be graded: {type(error).__name__}: {error}")


def _failed(submission: Submission, message: str) -> SubmissionGrade:
    return SubmissionGrade(submission.student, (), status="error", message=message)


def grade_class(
    submissions: Sequence[Submission],
    assignment: Assignment,
    bank: dict[str, Problem],
    *,
    jobs: int | None = None,
    timeout: float = DEFAULT_TIMEOUT,
    progress: Callable[[int], None] | None = None,
) -> list[SubmissionGrade]:
    """Everyone's grades, in the order of ``submissions``.

    ``jobs`` worker processes (default: the machine's cores; 1 grades in this process);
    ``progress(n)`` is called as each submission is done.
    """
    # each worker keeps the grades it makes (forked, it starts from this empty dict): an answer
    # many students gave word for word is graded once a worker, not once a student
    _WORK.update(submissions=list(submissions), assignment=assignment, bank=bank, timeout=timeout, graded={})
    jobs = jobs or os.cpu_count() or 1
    results: dict[int, SubmissionGrade] = {}
    pending = list(range(len(submissions)))
    if jobs == 1 or len(submissions) <= 1:
        for index in pending:
            results[index] = _grade_one(index)[1]
            if progress:
                progress(1)
    else:
        # A worker that dies breaks the pool and every task in flight: start a new pool for the
        # rest, then grade what is still lost one by one, so only the cause itself is lost.
        pending = _run_pool(pending, results, jobs, progress)
        pending = _run_pool(pending, results, jobs, progress) if pending else pending
        for index in pending:
            if not _run_pool([index], results, 1, progress):
                continue
            results[index] = _failed(submissions[index], "could not be graded: the grading process stopped")
            if progress:
                progress(1)
    return [results[index] for index in range(len(submissions))]


def _run_pool(pending: list[int], results: dict, jobs: int, progress) -> list[int]:
    """Grade ``pending`` in pools of forked workers; returns the indices lost with a dead worker.

    Each pool takes at most TASKS_PER_WORKER tasks a worker and is then replaced (fork cannot
    recycle workers by itself), so memory sympy keeps is returned between chunks.
    """
    context = multiprocessing.get_context("fork")
    chunk = TASKS_PER_WORKER * jobs
    for start in range(0, len(pending), chunk):
        with concurrent.futures.ProcessPoolExecutor(
            max_workers=jobs, mp_context=context, initializer=limit_memory
        ) as pool:
            futures = [pool.submit(_grade_one, index) for index in pending[start : start + chunk]]
            for future in concurrent.futures.as_completed(futures):
                try:
                    index, grade = future.result()
                except concurrent.futures.process.BrokenProcessPool:
                    continue
                results[index] = grade
                if progress:
                    progress(1)
    return [index for index in pending if index not in results]
