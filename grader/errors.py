"""The grader's exceptions: one small tree.

A student's mistake is never an exception: a malformed answer is a value
(:class:`grader.Refusal`) and a wrong one is a verdict. Exceptions are for the
people who must act on them, the problem author and the instructor::

    GraderError (Exception)
    └── AuthorError (GraderError, ValueError)   a problem or its reference answer is wrong
        └── ReferenceAnswerError                the reference answer cannot be read

``AuthorError`` is a ``ValueError`` because callers that hand the library a
bad value expect one, as :class:`statistics.StatisticsError` is.
"""

from __future__ import annotations

__all__ = ["AuthorError", "GraderError", "ReferenceAnswerError"]


class GraderError(Exception):
    """Root of every exception the grader raises on purpose."""


class AuthorError(GraderError, ValueError):
    """A problem, a reference answer or an option given by its author is wrong.

    The message is addressed to the author: it says where and what is allowed.
    """


class ReferenceAnswerError(AuthorError):
    """A reference (expected) answer could not be read.

    Attributes:
        refusal: the parser's account of what is wrong and where.
    """

    def __init__(self, message: str, *, refusal=None):
        super().__init__(message)
        self.refusal = refusal
