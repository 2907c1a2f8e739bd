"""The self-check server's worker processes: a check that overruns is ended, and the pool goes on.

The pools here run stand-in checks (module-level functions, which a worker imports by name):
one that never finishes, one that raises, one that reports its process. The real check runs
through the server in test_serve.py.
"""

from __future__ import annotations

import multiprocessing.forkserver
import os
import signal
import threading
import time

import pytest
from course import BANK

import grader.serve.workers
from grader.grade.selfcheck import CheckResult
from grader.serve.workers import OVERRUN, CheckPool, PoolBusy

LAGRANGIAN = "plane-pendulum.lagrangian"


def _stuck(key, answer, *, bank, timeout, answers=None):
    if answer == "stuck":
        time.sleep(600)  # what one sympy call no signal interrupts looks like from outside
    return CheckResult(key, "equivalent", 1.0, (f"pid {os.getpid()}",))


def _raises(key, answer, *, bank, timeout, answers=None):
    raise ValueError(f"a bug reading {answer!r}")


def _pid(result: CheckResult) -> int:
    return int(result.hints[0].split()[1])


@pytest.fixture
def quick_grace(monkeypatch):
    monkeypatch.setattr(grader.serve.workers, "GRACE", 0.3)


def test_a_check_that_overruns_is_ended_and_its_worker_replaced(quick_grace):
    pool = CheckPool(BANK, timeout=0.2, workers=1, run=_stuck)
    try:
        first = _pid(pool.check(LAGRANGIAN, "x"))
        started = time.monotonic()
        assert pool.check(LAGRANGIAN, "stuck") is None
        assert time.monotonic() - started < 30  # ended at the limit and the grace, not after 600 s
        after = pool.check(LAGRANGIAN, "x")
        assert after.status == "equivalent" and _pid(after) != first  # a new worker took over
    finally:
        pool.close()


def test_an_exception_in_a_worker_reaches_the_caller_and_the_worker_goes_on():
    pool = CheckPool(BANK, timeout=1.0, workers=1, run=_raises)
    try:
        for _ in range(2):
            with pytest.raises(RuntimeError, match="ValueError: a bug reading 'x'"):
                pool.check(LAGRANGIAN, "x")
    finally:
        pool.close()


def test_a_worker_that_dies_is_replaced():
    pool = CheckPool(BANK, timeout=1.0, workers=1, run=_stuck)
    try:
        os.kill(_pid(pool.check(LAGRANGIAN, "x")), 9)  # as the kernel does with one out of memory
        assert pool.check(LAGRANGIAN, "x") is None
        assert pool.check(LAGRANGIAN, "x").status == "equivalent"
    finally:
        pool.close()


def test_ctrl_c_in_a_terminal_is_the_servers_to_handle_not_its_workers():
    pool = CheckPool(BANK, timeout=1.0, workers=1, run=_stuck)
    try:
        worker = _pid(pool.check(LAGRANGIAN, "x"))
        os.kill(worker, signal.SIGINT)  # a terminal sends Ctrl-C to every process of the server's group
        time.sleep(0.3)
        after = pool.check(LAGRANGIAN, "x")
    finally:
        pool.close()
    assert after is not None and _pid(after) == worker


@pytest.mark.parametrize("starts", [2, 3])
def test_a_ctrl_c_while_workers_start_stops_those_started(monkeypatch, starts):
    # before: they ran on, ended by multiprocessing at exit, and `grader serve` said a worker did not start
    started = []
    start = CheckPool._start

    def interrupted(pool):
        if len(started) == starts - 1:
            raise KeyboardInterrupt
        before = set(pool._all)
        start(pool)
        started.extend(worker.process for worker in pool._all - before)

    monkeypatch.setattr(CheckPool, "_start", interrupted)
    with pytest.raises(KeyboardInterrupt):
        CheckPool(BANK, timeout=1.0, workers=starts, run=_stuck)
    assert [process.is_alive() for process in started] == [False] * (starts - 1)


def test_a_ctrl_c_while_the_fork_server_starts_is_raised_once_it_has(monkeypatch):
    # before: ignored while the fork server started, so lost to the server too, which went on serving
    ensure_running = multiprocessing.forkserver.ensure_running

    def pressed():
        os.kill(os.getpid(), signal.SIGINT)  # as a terminal's Ctrl-C reaches the process, from outside
        ensure_running()

    monkeypatch.setattr(multiprocessing.forkserver, "ensure_running", pressed)
    with pytest.raises(KeyboardInterrupt):
        CheckPool(BANK, timeout=1.0, workers=1, run=_stuck)


def test_workers_are_recycled(monkeypatch):
    monkeypatch.setattr(grader.serve.workers, "CHECKS_PER_WORKER", 2)
    pool = CheckPool(BANK, timeout=1.0, workers=1, run=_stuck)
    try:
        pids = [_pid(pool.check(LAGRANGIAN, "x")) for _ in range(4)]
    finally:
        pool.close()
    assert pids[0] == pids[1] != pids[2] == pids[3]


def test_when_every_worker_stays_busy_a_request_is_told_so(monkeypatch, quick_grace):
    pool = CheckPool(BANK, timeout=5.0, workers=1, run=_stuck)
    try:
        assert pool.check(LAGRANGIAN, "x").status == "equivalent"  # the worker has started
        monkeypatch.setattr(grader.serve.workers, "WAIT", 0.2)
        holder = threading.Thread(target=pool.check, args=(LAGRANGIAN, "stuck"), daemon=True)
        holder.start()
        time.sleep(0.1)
        with pytest.raises(PoolBusy):
            pool.check(LAGRANGIAN, "x")
    finally:
        pool.close()


def test_the_real_check_runs_in_a_worker():
    pool = CheckPool(BANK, timeout=2.0, workers=1)
    try:
        right = pool.check(LAGRANGIAN, "1/2 m l^2 θ̇^2 + m g l cos θ")
        wrong = pool.check(LAGRANGIAN, "1/2 m l^2 θ̇^2 - m g l cos θ")
    finally:
        pool.close()
    assert (right.status, right.read_as_mathml.startswith("<math")) == ("equivalent", True)
    assert wrong.status == "not_equivalent" and wrong.hints
    assert OVERRUN not in wrong.hints
