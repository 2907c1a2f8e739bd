"""The numbers behind a class summary: pure functions of the grades, nothing rendered.

Contents:
    ClassCounts, class_counts(grades)           students graded, errors, mean and median percent
    score_histogram(grades, bins)               how many students in each band of percent
    ItemStats, item_analysis(grades)            per part: mean, share of full credit, discrimination
    WrongAnswer, common_wrong_answers(grades)   the wrong answers given most often, per part
    review_queue(grades)                        every part waiting for a person, with its student

Only submissions with status ``graded`` count; one with status ``error`` has no parts.
A part's score is its ``final_score``: a person's score when there is one.
"""

from __future__ import annotations

import math
import statistics
from collections import Counter
from collections.abc import Sequence
from dataclasses import dataclass

from grader.grade.results import PartGrade, Student, SubmissionGrade

__all__ = [
    "ClassCounts",
    "ItemStats",
    "WrongAnswer",
    "class_counts",
    "common_wrong_answers",
    "item_analysis",
    "review_queue",
    "score_histogram",
]

FULL_CREDIT_TOLERANCE = 1e-6  # scaled points are rounded to 6 places when graded


def _graded(grades: Sequence[SubmissionGrade]) -> list[SubmissionGrade]:
    return [grade for grade in grades if grade.status == "graded"]


def _part_order(grades: Sequence[SubmissionGrade]) -> dict[str, int]:
    """Each part key's position in the assignment, as the grades list the parts."""
    order: dict[str, int] = {}
    for grade in grades:
        for part in grade.parts:
            order.setdefault(part.key, len(order))
    return order


@dataclass(frozen=True)
class ClassCounts:
    """How a class did, over the graded submissions.

    Attributes:
        graded: submissions graded.
        errors: submissions that could not be graded (status ``error``).
        mean_percent, median_percent: of the graded ones; None when there are none.
    """

    graded: int
    errors: int
    mean_percent: float | None
    median_percent: float | None


def class_counts(grades: Sequence[SubmissionGrade]) -> ClassCounts:
    """Counts and the centre of the percent scores.

    >>> from grader.grade.results import PartGrade, Student, SubmissionGrade
    >>> def one(score):
    ...     part = PartGrade("p", "a", 4.0, "x", "equivalent", score)
    ...     return SubmissionGrade(Student("s"), (part,))
    >>> class_counts([one(4.0), one(2.0), one(1.0), SubmissionGrade(Student("e"), (), status="error")])
    ClassCounts(graded=3, errors=1, mean_percent=58.333333333333336, median_percent=50.0)
    """
    percents = [grade.percent for grade in _graded(grades)]
    return ClassCounts(
        graded=len(percents),
        errors=sum(grade.status == "error" for grade in grades),
        mean_percent=statistics.fmean(percents) if percents else None,
        median_percent=statistics.median(percents) if percents else None,
    )


def score_histogram(grades: Sequence[SubmissionGrade], bins: int = 10) -> list[int]:
    """How many graded students fall in each of ``bins`` equal bands of percent; 100 % is in the top band.

    >>> from grader.grade.results import PartGrade, Student, SubmissionGrade
    >>> def one(score):
    ...     return SubmissionGrade(Student("s"), (PartGrade("p", "a", 3.0, "x", "equivalent", score),))
    >>> score_histogram([one(0.0), one(0.3), one(2.7), one(3.0)])
    [1, 1, 0, 0, 0, 0, 0, 0, 0, 2]
    """
    counts = [0] * bins
    for grade in _graded(grades):
        # 2.7 / 3 is 89.99999999999999 % in floating point: round first, or it lands a band low.
        percent = min(max(round(grade.percent, 6), 0.0), 100.0)
        counts[min(int(percent * bins // 100), bins - 1)] += 1
    return counts


@dataclass(frozen=True)
class ItemStats:
    """How one part of the assignment did across the class.

    Attributes:
        problem, part: which part; ``key`` is ``problem.part``.
        max_score: the points it is worth.
        count: graded students who had it.
        mean: mean points.
        full_credit: share of students (0–1) with full points.
        discrimination: the point-biserial correlation between this part's score and the rest
            of the test's (the total without it); None when either does not vary.
    """

    problem: str
    part: str
    max_score: float
    count: int
    mean: float
    full_credit: float
    discrimination: float | None

    @property
    def key(self) -> str:
        return f"{self.problem}.{self.part}"

    @property
    def mean_share(self) -> float:
        """The mean as a share of the points (0–1)."""
        return self.mean / self.max_score if self.max_score else 0.0


def item_analysis(grades: Sequence[SubmissionGrade]) -> list[ItemStats]:
    """Every part's statistics, in the order parts first appear in ``grades``.

    >>> from grader.grade.results import PartGrade, Student, SubmissionGrade
    >>> def one(a, b):
    ...     parts = (PartGrade("p", "a", 1.0, "", "blank", a), PartGrade("p", "b", 2.0, "", "blank", b))
    ...     return SubmissionGrade(Student("s"), parts)
    >>> first, second = item_analysis([one(1, 2), one(1, 1), one(0, 1), one(0, 0)])
    >>> first.mean_share, first.full_credit, round(first.discrimination, 4)   # rest of test 2, 1, 1, 0: r = 1/√2
    (0.5, 0.5, 0.7071)
    >>> item_analysis([one(1, 2), one(1, 0)])[0].discrimination is None   # everyone had part a right
    True
    """
    graded = _graded(grades)
    scores: dict[str, list[float]] = {}
    rests: dict[str, list[float]] = {}
    first: dict[str, PartGrade] = {}
    full: Counter[str] = Counter()
    for grade in graded:
        total = grade.score
        for part in grade.parts:
            scores.setdefault(part.key, []).append(part.final_score)
            rests.setdefault(part.key, []).append(total - part.final_score)
            first.setdefault(part.key, part)
            full[part.key] += part.final_score >= part.max_score - FULL_CREDIT_TOLERANCE
    return [
        ItemStats(
            problem=first[key].problem,
            part=first[key].part,
            max_score=first[key].max_score,
            count=len(values),
            mean=statistics.fmean(values),
            full_credit=full[key] / len(values),
            discrimination=_correlation(values, rests[key]),
        )
        for key, values in scores.items()
    ]


def _correlation(xs: Sequence[float], ys: Sequence[float]) -> float | None:
    """Pearson's r, or None when either side is constant (r is undefined, not 0).

    >>> round(_correlation([1, 1, 0, 0], [3, 1, 2, 0]), 6) == round(1 / math.sqrt(5), 6)
    True
    >>> _correlation([1, 1, 1], [0, 1, 2]) is None
    True
    """
    # Tested on the values themselves: a mean of equal floats need not equal them exactly,
    # so a "zero" variance computed from deviations can come out as 1e-33.
    if len(xs) < 2 or min(xs) == max(xs) or min(ys) == max(ys):
        return None
    mean_x, mean_y = statistics.fmean(xs), statistics.fmean(ys)
    sxy = sum((x - mean_x) * (y - mean_y) for x, y in zip(xs, ys, strict=True))
    sxx = sum((x - mean_x) ** 2 for x in xs)
    syy = sum((y - mean_y) ** 2 for y in ys)
    return max(-1.0, min(1.0, sxy / math.sqrt(sxx * syy)))


@dataclass(frozen=True)
class WrongAnswer:
    """A wrong answer to one part, as read, and how often it was given.

    Attributes:
        answer: the answer normalized: how it was read, else as typed with spaces collapsed.
        example: one of the answers as typed (the first seen), since a reading can look unlike
            what students typed (2 m g l cos θ is read as 2*g*l*m*cos(θ)).
        count: students who gave it.
        diagnosis: the kind of mistake it triggered (the most frequent, should it vary), or None.
        feedback: the first feedback sentence it got, or "".
    """

    answer: str
    example: str
    count: int
    diagnosis: str | None
    feedback: str


def _normalized(part: PartGrade) -> str:
    return part.read_as or " ".join(part.answer.split())


def common_wrong_answers(grades: Sequence[SubmissionGrade], limit: int = 5) -> dict[str, list[WrongAnswer]]:
    """The ``limit`` most frequent wrong (``not_equivalent``) answers of each part that has any,
    by part key in the assignment's order.

    Answers that read the same count as one: ``-m g l cos θ`` and ``-mgl cos(theta)`` are both
    read as ``-g*l*m*cos(θ)``. Ties keep the order in which the answers first appear.

    >>> from grader.grade.results import PartGrade, Student, SubmissionGrade
    >>> def one(answer, read_as):
    ...     feedback = ("Check the sign.",)
    ...     part = PartGrade("p", "a", 1.0, answer, "not_equivalent", 0.0, feedback, "sign", read_as=read_as)
    ...     return SubmissionGrade(Student("s"), (part,))
    >>> for key, answers in common_wrong_answers([one("-x", "-x"), one(" b ", ""), one(" - x", "-x")]).items():
    ...     print(key, [(wrong.answer, wrong.example, wrong.count) for wrong in answers])
    p.a [('-x', '-x', 2), ('b', ' b ', 1)]
    """
    found: dict[str, dict[str, tuple[str, Counter]]] = {}
    graded = _graded(grades)
    for grade in graded:
        for part in grade.parts:
            if part.status == "not_equivalent":
                answers = found.setdefault(part.key, {})
                _, reasons = answers.setdefault(_normalized(part), (part.answer, Counter()))
                reasons[(part.diagnosis, part.feedback[0] if part.feedback else "")] += 1
    order = _part_order(graded)
    result = {}
    for key in sorted(found, key=order.__getitem__):
        ranked = sorted(found[key].items(), key=lambda item: -item[1][1].total())  # stable: ties keep order
        result[key] = [
            WrongAnswer(answer, example, reasons.total(), *reasons.most_common(1)[0][0])
            for answer, (example, reasons) in ranked[:limit]
        ]
    return result


def review_queue(grades: Sequence[SubmissionGrade]) -> list[tuple[Student, PartGrade]]:
    """Every part waiting for a person (``needs_review``), with its student: part by part in the
    assignment's order, so one person can read every answer to a question in turn; students in
    the order of ``grades``.

    >>> from grader.grade.results import PartGrade, Student, SubmissionGrade
    >>> def one(student, status_a, status_b):
    ...     parts = (PartGrade("p", "a", 1.0, "x", status_a, 0.0), PartGrade("p", "b", 1.0, "y", status_b, 0.0))
    ...     return SubmissionGrade(Student(student), parts)
    >>> queue = review_queue([one("s1", "equivalent", "invalid"), one("s2", "undecided", "undecided")])
    >>> [(student.id, part.key) for student, part in queue]
    [('s2', 'p.a'), ('s1', 'p.b'), ('s2', 'p.b')]
    """
    order = _part_order(grades)
    waiting = [(grade.student, part) for grade in grades for part in grade.parts if part.needs_review]
    return sorted(waiting, key=lambda item: order[item[1].key])
