"""Ctrl-C held over a step that must not be cut in two.

Contents:
    ctrl_c_deferred()   a context manager: a Ctrl-C inside it is raised when it ends
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
    handing a worker process its data down a pipe. Outside the main thread it does nothing:
    only the main thread is interrupted, so a Ctrl-C cannot cut another thread's step.
    """
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    pressed = []
    previous = signal.signal(signal.SIGINT, lambda *_: pressed.append(True))
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)
    if pressed:
        raise KeyboardInterrupt
