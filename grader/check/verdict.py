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
        read_as: the submitted answer as it was read, in one line of text ("" if invalid).
        method: how the verdict was reached (``"numeric"``, ``"accelerations"``, ``"symbolic"``…).
        diagnosis: a stable key for the kind of mistake (``"sign"``, ``"factor"``,
            ``"missing_term"``…), or ``None``; reports count answers by it.
        read_as_latex: the same as ``read_as``, as LaTeX.
    """

    status: str
    score: float = 0.0
    feedback: tuple[str, ...] = ()
    read_as: str = ""
    method: str = ""
    diagnosis: str | None = None
    read_as_latex: str = field(default="", repr=False)

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
    def needs_person(self) -> bool:
        """True when no automatic verdict was reached."""
        return self.status == "undecided"
