"""The ``text`` kind: a rubric proposes a score, and a person always confirms it.

Contents:
    check_text(expected, submitted, deadline)   the kind's checker
    rubric_score(text, rubric)                  points proposed, ideas found and missed

Free text is never graded automatically: the verdict is always ``undecided`` (set
aside for a person), carrying the rubric's proposal so the grader starts from it.
"""

from __future__ import annotations

import re
import unicodedata

from grader.judge.deadline import Deadline
from grader.judge.expected import Expected, Outcome

__all__ = ["MAX_TEXT_LENGTH", "check_text", "rubric_score"]

MAX_TEXT_LENGTH = 5000


def _normal(text: str) -> str:
    """Lower case, accents and extra spaces removed: how phrasings are matched."""
    text = unicodedata.normalize("NFKC", text).casefold()
    return re.sub(r"\s+", " ", text).strip()


def rubric_score(text: str, rubric) -> tuple[float, list[str], list[str]]:
    """(points proposed, ideas found, ideas missing) for ``text`` against ``rubric``.

    ``rubric`` is a sequence of (idea, points, phrasings); an idea counts when any of
    its phrasings occurs in the text.

    >>> rubric = [("small angle", 1.0, ("sin θ ≈ θ",)), ("proportional", 1.0, ("proportional",))]
    >>> rubric_score("For small angles sin θ ≈ θ", rubric)
    (1.0, ['small angle'], ['proportional'])
    """
    normal = _normal(text[:MAX_TEXT_LENGTH])
    found, missing, points = [], [], 0.0
    for idea, worth, phrasings in rubric:
        if any(_normal(phrase) in normal for phrase in phrasings):
            found.append(idea)
            points += worth
        else:
            missing.append(idea)
    return points, found, missing


def check_text(expected: Expected, submitted: str, deadline: Deadline) -> Outcome:
    rubric = expected.option("rubric") or ()
    total = sum(worth for _, worth, _ in rubric) or 1.0
    points, found, _ = rubric_score(submitted if isinstance(submitted, str) else "", rubric)
    return Outcome(
        "undecided", points / total, "text_review",
        {"found": len(found), "total": len(rubric)}, method="rubric",
    )  # fmt: skip
