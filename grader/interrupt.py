"""Ctrl-C held over a step that must not be cut in two.

Contents:
    ctrl_c_deferred()             a context manager: a Ctrl-C inside it is raised when it ends
    ctrl_c_kept_from_children()   the same, and a process started inside it never gets a Ctrl-C

Both do nothing outside the main thread: signal dispositions are the main thread's to set, and only
the main thread is interrupted, so a Ctrl-C cannot cut another thread's step.
"""

from __future__ import annotations

import contextlib
import signal
import threading
from collections.abc import Iterator


@contextlib.contextmanager
def ctrl_c_deferred() -> Iterator[None]:
    """Hold a Ctrl-C until the block is done, then raise it as KeyboardInterrupt.

    For steps that are quick but leave a mess when cut: renaming a set of outputs into place,
    handing a worker process its data down a pipe.
    """
    pressed = []
    with _sigint_handled_by(lambda *_: pressed.append(True)):
        yield
    if pressed:
        raise KeyboardInterrupt


@contextlib.contextmanager
def ctrl_c_kept_from_children() -> Iterator[None]:
    """Hold a Ctrl-C until the block is done, then raise it, as :func:`ctrl_c_deferred` does; a process
    started in the block never gets one, across its exec too: a helper that has no use for Ctrl-C, such
    as a fork server, which ends when its parent does.

    The child inherits SIGINT blocked. Ignoring it instead (SIG_IGN, which an exec keeps too) would
    ignore it here as well: a Ctrl-C in the block was lost, and `grader serve` went on serving.
    """
    with ctrl_c_deferred():
        blocked = threading.current_thread() is threading.main_thread() and hasattr(signal, "pthread_sigmask")
        if blocked:
            signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT})
        try:
            yield
        finally:
            if blocked:  # a Ctrl-C pending meanwhile reaches ctrl_c_deferred's handler now
                signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT})


@contextlib.contextmanager
def _sigint_handled_by(handler) -> Iterator[None]:
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = signal.signal(signal.SIGINT, handler)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)
