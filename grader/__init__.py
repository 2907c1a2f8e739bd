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
"""

from grader.errors import AuthorError, GraderError, ReferenceAnswerError

# Last, and on purpose: the function ``check`` takes the name that importing the subpackage
# grader.judge gave this module's attribute; the subpackage stays importable by its full name.
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
