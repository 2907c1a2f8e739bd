"""Time limits for symbolic work, which sympy does not bound by itself.

Contents:
    CheckTimeout        raised when a check runs out of time
    Deadline            a point in time that loops check cooperatively
    time_limit(s)       a context manager that also interrupts a long sympy call

``simplify`` and ``expand`` have no timeout of their own, and one of them on a
hostile answer can run for minutes. In the main thread ``time_limit`` arms a
real-time timer whose signal interrupts whatever sympy is doing; elsewhere
(threads of a web server) only the cooperative checks apply, so callers there
should run checks in worker processes, which can also be killed.
"""

from __future__ import annotations

import signal
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager

__all__ = ["CheckTimeout", "Deadline", "time_limit"]


class CheckTimeout(Exception):  # an event, not an error: no "Error" suffix
    """A check ran out of its time."""


class Deadline:
    """The moment a check must be done by."""

    def __init__(self, seconds: float):
        self.seconds = seconds
        self.end = time.monotonic() + seconds

    def remaining(self) -> float:
        return self.end - time.monotonic()

    def check(self) -> None:
        """Raise :class:`CheckTimeout` once the time is up."""
        if time.monotonic() > self.end:
            raise CheckTimeout(f"no verdict within {self.seconds:g} s")


def _can_interrupt() -> bool:
    return hasattr(signal, "setitimer") and threading.current_thread() is threading.main_thread()


@contextmanager
def time_limit(seconds: float) -> Iterator[Deadline]:
    """Bound the enclosed work to ``seconds``; yields the :class:`Deadline`.

    Nested limits keep the outer timer: the inner one only tightens the cooperative checks.
    """
    deadline = Deadline(seconds)
    if not _can_interrupt() or signal.getitimer(signal.ITIMER_REAL)[0] > 0:
        yield deadline
        return

    def interrupt(signum, frame):
        raise CheckTimeout(f"no verdict within {seconds:g} s")

    previous = signal.signal(signal.SIGALRM, interrupt)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield deadline
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
