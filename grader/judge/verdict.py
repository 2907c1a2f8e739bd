"""What a check concludes: the ``Verdict``.

Contents:
    Verdict     status, score, feedback, and how the answer was read
    STATUSES    the four outcomes
"""

from __future__ import annotations

from dataclasses import dataclass, field

__all__ = ["STATUSES", "Verdict"]

STATUSES = ("equivalent", "not_equivalent", "undecided", "invalid")


@dataclass(frozen=True)
class Verdict:
    """The outcome of comparing a submitted answer with the expected one.

    Attributes:
        status: ``"equivalent"``, ``"not_equivalent"``, ``"undecided"`` (the check ran
            out of time or could not sample: a person must look) or ``"invalid"``
            (the answer could not be read).
        score: the credit earned, from 0 to 1.
        feedback: sentences for the student; they never reveal the expected answer.
        method: how the verdict was reached (``"numeric"``, ``"accelerations"``, ``"symbolic"``…).
        diagnosis: a stable key for the kind of mistake (``"sign"``, ``"factor"``,
            ``"missing_term"``…), or ``None``; reports count answers by it.
        answer: the submitted answer as parsed (a ``ParsedAnswer``), the parser's
            ``Refusal``, or ``None`` for kinds that are not parsed.
        notes: the last sentences of ``feedback`` when they say how the answer was read
            (a given p_θ put in place, an option's words, a conserved quantity); they stay
            when a part's anticipated mistake replaces the rest of the feedback.

    ``read_as`` (how the answer was read) is derived from ``answer`` when asked for:
    printing costs more than judging, and a batch may not need it.
    """

    status: str
    score: float = 0.0
    feedback: tuple[str, ...] = ()
    method: str = ""
    diagnosis: str | None = None
    answer: object = field(default=None, repr=False, compare=False)
    notes: tuple[str, ...] = ()

    def __post_init__(self):
        if self.status not in STATUSES:
            raise ValueError(f"status must be one of {STATUSES}, not {self.status!r}")
        if not 0 <= self.score <= 1:
            raise ValueError(f"score must be between 0 and 1, not {self.score}")

    @property
    def equivalent(self) -> bool:
        """True when the answer is right in full."""
        return self.status == "equivalent"

    @property
    def read_as(self) -> str:
        """The submitted answer as it was read, in one line of text; for an answer that
        could not be read, the line with a caret under the problem; "" when not parsed."""
        if self.answer is None:
            return ""
        if self.answer.ok:
            return self.answer.read_as_text
        return self.answer.pointer

    @property
    def needs_person(self) -> bool:
        """True when no automatic verdict was reached."""
        return self.status == "undecided"
