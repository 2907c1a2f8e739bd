"""Ctrl-C held over a step that must not be cut in two.

Contents:
    ctrl_c_deferred()   a context manager: a Ctrl-C inside it is raised when it ends
    ctrl_c_ignored()    a context manager: a Ctrl-C inside it is lost, and so for a process started in it

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
def ctrl_c_ignored() -> Iterator[None]:
    """Ignore a Ctrl-C for the block. A process started in it keeps ignoring it across its exec: a
    helper that has no use for Ctrl-C, such as a fork server, which ends when its parent does."""
    with _sigint_handled_by(signal.SIG_IGN):
        yield


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
