"""Checks in worker processes, so that no answer can hold the server past its time limit.

Contents:
    CheckPool(bank, timeout=, workers=)   ``check(key, answer, answers)`` from any handler thread
    OVERRUN                               what a check that had to be ended says to the student

Why processes: a handler thread's time limit is cooperative, because the signal that
interrupts sympy reaches only a process's main thread. One long sympy call then holds the
thread past the limit, and holding the GIL it slows every other student's check. A worker
checks in its main thread, where the limit interrupts sympy; one that still has not answered
when the limit and a grace period are over is killed and replaced.

Workers are forked from a fork server, a process started before any handler thread exists
(forking a threaded process copies locks other threads hold). Each takes the bank once, when
it starts, checks the reference answer of every part it will be asked about (half a second
for the whole bank: a student's first check then finds the reference prepared, as it would in
one long-lived process), and only then takes checks. It is replaced after CHECKS_PER_WORKER
checks, which returns the memory sympy's caches keep.
"""

from __future__ import annotations

import contextlib
import multiprocessing
import multiprocessing.forkserver
import multiprocessing.resource_tracker
import os
import queue
import signal
import sys
import threading
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from multiprocessing.connection import Connection

from grader.bank import Problem
from grader.grade.batch import limit_memory
from grader.grade.part import expected_answer
from grader.grade.selfcheck import CheckResult, check, find_part
from grader.interrupt import ctrl_c_deferred, ctrl_c_kept_from_children

__all__ = ["CHECKS_PER_WORKER", "GRACE", "OVERRUN", "CheckPool", "PoolBusy"]

GRACE = 2.0  # seconds past the time limit before a worker that has not answered is killed
WAIT = 30.0  # seconds a request waits for a free worker before the server says it is busy
STARTUP = 120.0  # seconds a new worker may take to be ready
_READY = "ready"
_PREPARED = ("expression", "equation", "equations", "lagrangian", "number", "integer")
CHECKS_PER_WORKER = 500
OVERRUN = (
    "This answer took too long to check, so it was stopped. Write it more simply (multiply out "
    "less, nest fewer powers) and check it again; if it is right as it stands, a person will see that "
    "when it is graded."
)


class PoolBusy(Exception):  # a condition reported to the handler, not an error of the grader
    """Every worker stayed busy for as long as a request may wait."""


def _serve(
    connection: Connection, bank: Mapping[str, Problem], timeout: float, run: Callable, keys: tuple[str, ...]
) -> None:
    """A worker: prepares the parts ``keys`` names, says it is ready, then checks each
    (key, answer, the student's other answers) it receives until its pipe closes."""
    # A terminal's Ctrl-C reaches every process of its group: a worker's KeyboardInterrupt would
    # print a traceback and lose the check it held, while the server, which owns the shutdown, kills it.
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    limit_memory()
    for key in keys:
        problem, part = find_part(key, bank)
        if part.kind in _PREPARED:
            with contextlib.suppress(Exception):  # a reference that fails fails its checks, with the message
                run(key, expected_answer(problem, part), bank=bank, timeout=timeout)
    connection.send(_READY)
    while True:
        try:
            key, answer, answers = connection.recv()
        except (EOFError, OSError):
            return
        try:
            outcome = run(key, answer, bank=bank, timeout=timeout, answers=answers)
        except Exception as error:  # the handler answers 500 and logs it; this worker goes on
            outcome = RuntimeError(f"in a check worker: {type(error).__name__}: {error}")
        connection.send(outcome)


@dataclass(eq=False)  # each worker is itself: kept in a set
class _Worker:
    process: multiprocessing.process.BaseProcess
    connection: Connection
    checks: int = 0

    def stop(self) -> None:
        with contextlib.suppress(OSError):
            self.connection.close()
        self.process.kill()
        self.process.join(timeout=5)


class CheckPool:
    """Worker processes that check answers; any number of threads may call :meth:`check`.

    Args:
        bank: the problems by id, sent to each worker when it starts.
        keys: the parts (``problem.part``) to prepare in each worker before it takes checks.
        timeout: the time limit of one check, as ``grader.check`` takes it.
        workers: how many processes (default: the machine's cores).
        run: what a worker calls, ``run(key, answer, bank=, timeout=)``; a module-level
            function (it is sent to the worker by name). Tests pass their own.
    """

    def __init__(
        self,
        bank: Mapping[str, Problem],
        *,
        keys: tuple[str, ...] = (),
        timeout: float,
        workers: int | None = None,
        run: Callable[..., CheckResult] = check,
    ):
        self.bank, self.keys, self.timeout, self.run = bank, tuple(keys), timeout, run
        self._context = multiprocessing.get_context("forkserver")
        self._context.set_forkserver_preload(["grader.grade.selfcheck"])
        # a Ctrl-C while the fork server loads sympy, a second or two, would print the traceback of an
        # import it did not need to finish: it never gets one, and ends when this process does. The
        # resource tracker, which the fork server's start would start first, unblocks SIGINT after its own.
        multiprocessing.resource_tracker.ensure_running()
        with ctrl_c_kept_from_children():
            multiprocessing.forkserver.ensure_running()
        self._idle: queue.Queue[_Worker] = queue.Queue()
        self._all: set[_Worker] = set()
        self._lock = threading.Lock()
        self._closed = False
        try:
            for _ in range(max(1, workers or os.cpu_count() or 1)):
                self._start()
        except BaseException:
            # a Ctrl-C between two starts: the workers started are stopped here, not ended at exit by
            # multiprocessing, which each one's thread would report as a worker that did not start
            self.close()
            raise

    def _start(self) -> None:
        """Start a worker; it joins the idle ones when it says it is ready (a thread waits for that,
        so that no request waits for a worker to start, nor has that counted against its limit)."""
        mine, theirs = self._context.Pipe()
        arguments = (theirs, self.bank, self.timeout, self.run, self.keys)
        process = self._context.Process(target=_serve, args=arguments, name="grader-check", daemon=True)
        with ctrl_c_deferred():
            process.start()
        theirs.close()
        worker = _Worker(process, mine)
        with self._lock:
            self._all.add(worker)
        threading.Thread(target=self._when_ready, args=(worker,), name="grader-check-start", daemon=True).start()

    def _when_ready(self, worker: _Worker) -> None:
        try:
            ready = worker.connection.poll(STARTUP) and worker.connection.recv() == _READY
        except (EOFError, OSError):
            ready = False
        if ready and not self._closed:
            self._idle.put(worker)
            return
        self._retire(worker)
        if not self._closed:  # not replaced: what stopped this one would stop the next
            print(f"grader serve: a check worker did not start (exit code {worker.process.exitcode})", file=sys.stderr)

    def _retire(self, worker: _Worker) -> None:
        with self._lock:
            self._all.discard(worker)
        worker.stop()

    def check(self, key: str, answer: str, answers: dict | None = None) -> CheckResult | None:
        """The result of checking ``answer`` to ``key`` (with the student's ``answers`` to other parts,
        ``problem.part`` → answer, for method credit); None when the check overran and was ended.

        Raises:
            PoolBusy: no worker came free within WAIT seconds.
            Exception: whatever the check raised in its worker (a bug: the handler logs it).
        """
        try:
            worker = self._idle.get(timeout=WAIT)
        except queue.Empty:
            raise PoolBusy from None
        outcome, alive = None, False
        try:
            worker.connection.send((key, answer, answers or {}))
            if worker.connection.poll(self.timeout + GRACE):
                outcome, alive = worker.connection.recv(), True
        except (EOFError, OSError):  # the worker died: out of memory, or killed from outside
            pass
        finally:
            worker.checks += 1
            if alive and worker.checks < CHECKS_PER_WORKER:
                self._idle.put(worker)
            else:
                self._retire(worker)
                if not self._closed:
                    self._start()
        if isinstance(outcome, Exception):
            raise outcome
        return outcome

    def close(self) -> None:
        """Stop every worker; a check in progress ends with the pipe's error (the server is closing)."""
        self._closed = True
        with self._lock:
            workers = list(self._all)
            self._all.clear()
        for worker in workers:
            worker.stop()
