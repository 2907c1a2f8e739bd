"""grader: grades answers in analytical mechanics, and knows the physics.

The public API, flat; the modules behind it are free to move:

    parse_answer   read a student's answer safely (plain, Unicode or LaTeX)
    ParsedAnswer   an answer that was read, and how to show it back
    Refusal        an answer that could not be read, and why
"""

from grader.errors import AuthorError, GraderError, ReferenceAnswerError
from grader.parse import TIME, ParsedAnswer, Refusal, parse_answer

__all__ = [
    "TIME",
    "AuthorError",
    "GraderError",
    "ParsedAnswer",
    "ReferenceAnswerError",
    "Refusal",
    "parse_answer",
]
