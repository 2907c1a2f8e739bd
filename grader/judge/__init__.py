"""Deciding whether an answer is right: ``compare`` and the ``Verdict`` it returns.

Contents:
    compare(expected, submitted, kind=, coords=, **options) → Verdict
    Verdict     equivalent / not_equivalent / undecided / invalid, with score and feedback
    KINDS       the closed registry of answer kinds and their options

Modules: ``compare`` (dispatch, the shared steps), ``chains`` (an answer's text cut into lines
and a chain's sides), ``expression``, ``motion``
(equation, equations), ``lagrangian``, ``scalar`` (integer, number), ``choice``, the
kinds' checkers; ``numeric`` and ``sampling`` (fast evaluation at seeded points),
``diagnose`` (naming mistakes), ``feedback`` (every sentence), ``deadline`` (time
limits), ``setting`` and ``expected`` (the problem's symbols, the prepared reference).
"""

from grader.judge.compare import DEFAULT_TIMEOUT, KINDS, Kind, compare
from grader.judge.verdict import STATUSES, Verdict

__all__ = ["DEFAULT_TIMEOUT", "KINDS", "STATUSES", "Kind", "Verdict", "compare"]
