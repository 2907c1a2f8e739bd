"""grader: grades answers in analytical mechanics, and knows the physics.

The public API, flat; the modules behind it are free to move:

    parse_answer   read a student's answer safely (plain, Unicode or LaTeX)
    ParsedAnswer   an answer that was read, and how to show it back
    Refusal        an answer that could not be read, and why
    compare        judge a submitted answer against the expected one, knowing the physics
    Verdict        what compare concludes: status, score, feedback, how the answer was read
    KINDS          the answer kinds compare knows
    check          a student checks an answer to a bank part: verdict, hint, how it was read
    CheckResult    what check returns; renders in Jupyter

Each name is imported when first used (PEP 562), so that ``import grader`` costs nothing until
then: the ``grader`` command can begin inside a ``try`` that ends a Ctrl-C while sympy and pandas
load with a word instead of a traceback (see ``grader/__main__.py``).
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING

from grader.errors import AuthorError, GraderError, ReferenceAnswerError

_HOMES = {
    "CheckResult": "grader.grade.selfcheck",
    "check": "grader.grade.selfcheck",
    "KINDS": "grader.judge",
    "Verdict": "grader.judge",
    "compare": "grader.judge",
    "TIME": "grader.parse",
    "ParsedAnswer": "grader.parse",
    "Refusal": "grader.parse",
    "parse_answer": "grader.parse",
}

if TYPE_CHECKING:
    from grader.grade.selfcheck import CheckResult, check
    from grader.judge import KINDS, Verdict, compare
    from grader.parse import TIME, ParsedAnswer, Refusal, parse_answer

__all__ = [
    "KINDS",
    "TIME",
    "AuthorError",
    "CheckResult",
    "GraderError",
    "ParsedAnswer",
    "ReferenceAnswerError",
    "Refusal",
    "Verdict",
    "check",
    "compare",
    "parse_answer",
]


def __getattr__(name: str):
    if name not in _HOMES:
        raise AttributeError(f"module 'grader' has no attribute {name!r}")
    value = getattr(importlib.import_module(_HOMES[name]), name)
    globals()[name] = value  # found once; later lookups do not come here
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))
