"""grader: grades answers in analytical mechanics, and knows the physics.

The public API, flat; the modules behind it are free to move:

    parse_answer   read a student's answer safely (plain, Unicode or LaTeX)
    ParsedAnswer   an answer that was read, and how to show it back
    Refusal        an answer that could not be read, and why
    compare        judge a submitted answer against the expected one, knowing the physics
    Verdict        what compare concludes: status, score, feedback, how the answer was read
    KINDS          the answer kinds compare knows
"""

from grader.check import KINDS, Verdict, compare
from grader.errors import AuthorError, GraderError, ReferenceAnswerError
from grader.parse import TIME, ParsedAnswer, Refusal, parse_answer

__all__ = [
    "KINDS",
    "TIME",
    "AuthorError",
    "GraderError",
    "ParsedAnswer",
    "ReferenceAnswerError",
    "Refusal",
    "Verdict",
    "compare",
    "parse_answer",
]
