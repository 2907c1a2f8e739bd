"""The self-check server: the page, a preview of how an answer is read, and checking it.

Contents:
    make_server(bank=, assignment=, host=, port=, log_path=, workers=)   a server; the caller runs serve_forever
    SelfCheckServer                                            the server and what every request shares
    AttemptsLog                                                one JSON line per check, from any thread
    LIMITS                                                     sizes past which a request is refused

Routes: ``GET /`` the page; ``POST /api/preview`` and ``POST /api/check`` take JSON
``{"part": "problem.part", "answer": "…"}`` and answer JSON. Every error is JSON with a 4xx
or 5xx status, and no request stops the server. Checks run in worker processes
(:mod:`grader.serve.workers`), which can be stopped; a preview only reads the answer, in the
handler's thread, bounded by the parser's own checks of the time limit.

Nothing a response holds comes from a Part's ``answer`` or the answers of its ``mistakes`` and
``tests``: the page is built from the views in ``page`` (an allow-list), a preview only from the
student's own text, and a check from ``CheckResult``, whose hints the bank's tests keep free of
the answer.
"""

from __future__ import annotations

import datetime
import json
import re
import sys
import threading
import traceback
from collections.abc import Mapping
from dataclasses import dataclass
from http import HTTPStatus
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path
from typing import ClassVar

from grader.bank import Assignment, Problem
from grader.errors import GraderError
from grader.grade.part import setting_of, symbol_meanings
from grader.grade.selfcheck import SYMBOLS, WORDS, CheckResult, find_part
from grader.judge import DEFAULT_TIMEOUT
from grader.judge.choice import chosen
from grader.judge.deadline import CheckTimeout, Deadline
from grader.parse import parse_answer
from grader.serve.page import MATH_KINDS, problem_views, render_page
from grader.serve.workers import OVERRUN, CheckPool, PoolBusy

_SLOW_PREVIEW = "This answer takes too long to read back here; check it to see how it was read."

__all__ = ["LIMITS", "AttemptsLog", "SelfCheckServer", "make_server"]

SECURITY_HEADERS = {
    "Content-Security-Policy": "default-src 'self'; script-src 'self' 'unsafe-inline'; style-src 'unsafe-inline'",
    "X-Content-Type-Options": "nosniff",
    "X-Frame-Options": "DENY",
    "Referrer-Policy": "no-referrer",
}


@dataclass(frozen=True)
class Limits:
    body: int = 64 * 1024  # bytes of a request body
    answer: int = 5000  # characters of an answer (the parser itself stops at 2000)
    student: int = 200  # characters of a student id
    discard: int = 16 * 1024 * 1024  # bytes of a refused body read away so the client gets its 413


LIMITS = Limits()


class _Refused(Exception):  # the handler's own flow, never raised out of it: not in grader.errors
    """A request we refuse: its HTTP status and the sentence that says why."""

    def __init__(self, status: HTTPStatus, message: str):
        super().__init__(message)
        self.status = status
        self.message = message


class AttemptsLog:
    """Appends one JSON line per attempt; a lock keeps lines from interleaving across threads."""

    def __init__(self, path: str | Path):
        self.path = Path(path)
        # Opened now, so a path that cannot be written is found when the server starts.
        self._file = self.path.open("a", encoding="utf-8")
        self._lock = threading.Lock()

    def append(self, record: Mapping) -> None:
        line = json.dumps(record, ensure_ascii=False) + "\n"
        with self._lock:
            self._file.write(line)
            self._file.flush()

    def close(self) -> None:
        with self._lock:
            self._file.close()


class SelfCheckServer(ThreadingHTTPServer):
    """A threading HTTP server holding the bank, the rendered page, the attempts log and the
    worker processes that check answers."""

    daemon_threads = True  # a stuck check never keeps the process from exiting

    def __init__(
        self,
        address: tuple[str, int],
        *,
        bank: Mapping[str, Problem],
        assignment: Assignment | None,
        log: AttemptsLog | None,
        check_timeout: float,
        workers: int | None = None,
    ):
        self.bank = bank
        self.assignment = assignment
        self.attempts = log
        self.check_timeout = check_timeout  # not ``timeout``: socketserver uses that name for handle_request
        views = problem_views(bank, assignment)
        self.keys = frozenset(part.key for view in views for part in view.parts)
        title = assignment.title if assignment is not None else "The problem bank"
        self.page = render_page(views, title=title).encode("utf-8")
        self.checks: CheckPool | None = None  # started once the address is bound
        super().__init__(address, SelfCheckHandler)
        try:
            self.checks = CheckPool(bank, keys=tuple(sorted(self.keys)), timeout=check_timeout, workers=workers)
        except BaseException:
            super().server_close()
            raise

    @property
    def url(self) -> str:
        host, port = self.server_address[:2]
        return f"http://{host}:{port}/"

    def server_close(self) -> None:
        super().server_close()
        if self.checks is not None:
            self.checks.close()
        if self.attempts is not None:
            self.attempts.close()


def make_server(
    *,
    bank: Mapping[str, Problem],
    assignment: Assignment | None = None,
    host: str = "127.0.0.1",
    port: int = 0,
    log_path: str | Path | None = None,
    timeout: float = DEFAULT_TIMEOUT,
    workers: int | None = None,
) -> SelfCheckServer:
    """A self-check server bound to ``host:port``, not yet serving.

    Args:
        bank: the problems by id (``load_bank``).
        assignment: show only its parts, and check only those; every problem of the bank when None.
        host: the address to listen on; the default is reachable from this machine only.
        port: 0 picks a free port (read it back from ``server.server_address`` or ``server.url``).
        log_path: a JSON-lines file each check is appended to; None keeps no log.
        timeout: seconds per check before it is "undecided".
        workers: processes that check answers (default: the machine's cores); a check that
            overruns its limit is ended by killing its worker.

    Returns:
        The server; run ``serve_forever()`` (in a thread, for tests) and ``server_close()`` after.
        Its check workers come from multiprocessing's fork server, which imports the main
        module in each: a script that calls this must do so under ``if __name__ == "__main__":``,
        as with any start method but fork (``grader serve``, pytest and notebooks need nothing).

    Raises:
        OSError: the address is taken or the log cannot be opened.
    """
    log = AttemptsLog(log_path) if log_path is not None else None
    try:
        return SelfCheckServer(
            (host, port), bank=bank, assignment=assignment, log=log, check_timeout=timeout, workers=workers
        )
    except BaseException:
        if log is not None:
            log.close()
        raise


def _chosen(
    choices: Mapping[str, str], answer: str, *, multiple: bool = False, meanings=(), asks_false: bool = False
) -> str:
    """The options an answer names, as ``label) text``, read as the checker reads them (``b
    (rheonomic)`` is b); otherwise word by word, where a label that is no option stays as typed.

    >>> _chosen({"a": "holonomic", "b": "non-holonomic"}, " B, c ")
    'b) non-holonomic; c'
    >>> _chosen({"a": "scleronomic", "b": "rheonomic"}, "b (rheonomic)")
    'b) rheonomic'
    >>> _chosen({"a": "L = T - V", "b": "L = T + V"}, "b is false", asks_false=True)
    'b) L = T + V'
    """
    labels = {label.casefold(): label for label in choices}
    read = chosen(answer, tuple(choices.items()), multiple=multiple, meanings=meanings, asks_false=asks_false)
    named = read if read and all(label in labels for label in read) else [w for w in re.split(r"[\s,;]+", answer) if w]
    return "; ".join(
        f"{labels[word.casefold()]}) {' '.join(str(choices[labels[word.casefold()]]).split())}"
        if word.casefold() in labels
        else word
        for word in named
    )


class SelfCheckHandler(BaseHTTPRequestHandler):
    server: SelfCheckServer
    server_version = "grader-serve"
    sys_version = ""
    timeout = 30  # seconds a client may take to send its request; a silent one does not hold a thread for ever

    # -- routing ---------------------------------------------------------------------------

    ROUTES: ClassVar = {
        ("GET", "/"): "_page",
        ("GET", "/favicon.ico"): "_no_icon",  # browsers ask for it; "none" keeps their consoles quiet
        ("POST", "/api/preview"): "_preview",
        ("POST", "/api/check"): "_check",
    }

    def do_GET(self) -> None:
        self._dispatch("GET")

    def do_HEAD(self) -> None:
        self._dispatch("HEAD")

    def do_POST(self) -> None:
        self._dispatch("POST")

    def do_PUT(self) -> None:
        self._dispatch("PUT")

    def do_DELETE(self) -> None:
        self._dispatch("DELETE")

    def do_PATCH(self) -> None:
        self._dispatch("PATCH")

    def do_OPTIONS(self) -> None:
        self._dispatch("OPTIONS")

    def _dispatch(self, method: str) -> None:
        path = self.path.split("?", 1)[0]
        try:
            route = self.ROUTES.get(("GET" if method == "HEAD" else method, path))
            if route is None:
                allowed = sorted(m for m, p in self.ROUTES if p == path)
                if not allowed:
                    raise _Refused(HTTPStatus.NOT_FOUND, f"there is no {path}; the page is at /")
                self._allow = ", ".join(allowed)
                raise _Refused(HTTPStatus.METHOD_NOT_ALLOWED, f"{path} takes {' or '.join(allowed)}, not {method}")
            getattr(self, route)()
        except _Refused as error:
            self._send_json({"error": error.message}, error.status)
        except (BrokenPipeError, ConnectionResetError):
            pass  # the browser went away; nothing to answer
        except Exception:
            traceback.print_exc(file=sys.stderr)
            self._send_json({"error": "the server failed on this request; it has been logged"}, 500)

    # -- routes ----------------------------------------------------------------------------

    def _page(self) -> None:
        self._send(self.server.page, "text/html; charset=utf-8", HTTPStatus.OK)

    def _no_icon(self) -> None:
        self._send(b"", "image/x-icon", HTTPStatus.NO_CONTENT)

    def _preview(self) -> None:
        request = self._request()
        problem, part = self._part(request)
        answer = request["answer"]
        if part.kind == "choice":  # the options chosen, by label and text
            multiple, asks_false = bool(part.options.get("multiple")), bool(part.options.get("asks_false"))
            meanings = symbol_meanings(problem)
            text = _chosen(part.choices, answer, multiple=multiple, meanings=meanings, asks_false=asks_false)
            self._send_json({"ok": True, "mathml": "", "text": text})
            return
        if part.kind not in MATH_KINDS:  # words and numbers are shown as typed
            self._send_json({"ok": True, "mathml": "", "text": answer.strip()})
            return
        setting = setting_of(problem)
        try:  # sent as the student types: bounded like a check, so one answer cannot hold a thread
            deadline = Deadline(self.server.check_timeout)
            read = parse_answer(answer, coords=setting["coords"], known=setting["known"], deadline=deadline)
        except CheckTimeout:
            self._send_json({"ok": False, "message": _SLOW_PREVIEW, "pointer": ""})
            return
        if read.ok:
            self._send_json({"ok": True, "mathml": read.read_as_mathml, "text": read.read_as_text})
        else:
            self._send_json({"ok": False, "message": read.message, "pointer": read.pointer})

    def _check(self) -> None:
        request = self._request()
        problem, part = self._part(request)
        key, answer = request["part"], request["answer"]
        # the student's own Lagrangian, for the method credit of equations that follow from it
        answers = {f"{problem.id}.{part.derive_from}": request["lagrangian"]} if part.derive_from else {}
        try:  # in a worker process, ended if it overruns (see grader.serve.workers)
            result = self.server.checks.check(key, answer, answers)
        except PoolBusy:
            raise _Refused(HTTPStatus.SERVICE_UNAVAILABLE, "the server is busy; check again in a moment") from None
        if result is None:
            result = CheckResult(key, "undecided", 0.0, (OVERRUN,))
        if self.server.attempts is not None:
            self.server.attempts.append(
                {
                    "time": datetime.datetime.now(datetime.UTC).isoformat(timespec="milliseconds"),
                    "student": request["student"],
                    "part": key,
                    "answer": answer,
                    "status": result.status,
                }
            )
        self._send_json(
            {
                "part": key,
                "status": result.status,
                "symbol": SYMBOLS[result.status],
                "words": WORDS[result.status],
                "score": result.score,
                "hints": [hint for hint in result.hints if hint != "Correct."],
                "read_as": result.read_as,
                "mathml": result.read_as_mathml,
            }
        )

    # -- reading requests ------------------------------------------------------------------

    def _request(self) -> dict:
        """The JSON body as ``{"part", "answer", "student", "lagrangian"}``, or a _Refused saying what is
        wrong. ``lagrangian`` is the student's answer to the part a derived part follows from ("" if none)."""
        if self.headers.get("Transfer-Encoding"):
            self.close_connection = True
            raise _Refused(HTTPStatus.LENGTH_REQUIRED, "send the body with a Content-Length")
        try:
            length = int(self.headers.get("Content-Length", "0"))
        except ValueError:
            length = -1
        if length < 0:
            self.close_connection = True
            raise _Refused(HTTPStatus.BAD_REQUEST, "the Content-Length is not a number of bytes")
        if length > LIMITS.body:
            self.close_connection = True
            self._discard(length)
            raise _Refused(HTTPStatus.REQUEST_ENTITY_TOO_LARGE, f"the request is larger than {LIMITS.body} bytes")
        # A JSON content type makes a cross-site form post need CORS approval, which this
        # server never gives: another site open in the browser cannot post attempts here.
        content_type = self.headers.get("Content-Type", "").split(";", 1)[0].strip().lower()
        body = self.rfile.read(length)
        if content_type != "application/json":
            raise _Refused(HTTPStatus.UNSUPPORTED_MEDIA_TYPE, "send JSON, with Content-Type: application/json")
        try:
            data = json.loads(body.decode("utf-8"))
        except (UnicodeDecodeError, ValueError):
            raise _Refused(HTTPStatus.BAD_REQUEST, "the request body is not valid JSON") from None
        if not isinstance(data, dict):
            raise _Refused(HTTPStatus.BAD_REQUEST, 'send a JSON object: {"part": "problem.part", "answer": "…"}')
        for field in ("part", "answer"):
            if not isinstance(data.get(field), str):
                raise _Refused(HTTPStatus.BAD_REQUEST, f'"{field}" must be a string')
        if len(data["answer"]) > LIMITS.answer:
            raise _Refused(
                HTTPStatus.REQUEST_ENTITY_TOO_LARGE,
                f"the answer is {len(data['answer'])} characters long; at most {LIMITS.answer} are read",
            )
        student = data.get("student")
        if student is not None and not isinstance(student, str):
            raise _Refused(HTTPStatus.BAD_REQUEST, '"student" must be a string')
        student = (student or "").strip()[: LIMITS.student] or None
        lagrangian = data.get("lagrangian", "")
        if not isinstance(lagrangian, str):
            raise _Refused(HTTPStatus.BAD_REQUEST, '"lagrangian" must be a string')
        if len(lagrangian) > LIMITS.answer:
            raise _Refused(
                HTTPStatus.REQUEST_ENTITY_TOO_LARGE,
                f"the Lagrangian is {len(lagrangian)} characters long; at most {LIMITS.answer} are read",
            )
        return {"part": data["part"].strip(), "answer": data["answer"], "student": student, "lagrangian": lagrangian}

    def _discard(self, length: int) -> None:
        # Closing a socket with unread bytes in it resets the connection, and the client then
        # sees a broken pipe instead of our 413: read a refused body away, up to a bound.
        remaining = min(length, LIMITS.discard)
        while remaining > 0:
            chunk = self.rfile.read(min(remaining, 65536))
            if not chunk:
                break
            remaining -= len(chunk)

    def _part(self, request: dict):
        """(problem, part) of the request, when it is on the page."""
        try:
            problem, part = find_part(request["part"], self.server.bank)
        except GraderError as error:
            raise _Refused(HTTPStatus.BAD_REQUEST, str(error)) from None
        if request["part"] not in self.server.keys:
            where = self.server.assignment.id if self.server.assignment else "this page"
            raise _Refused(HTTPStatus.BAD_REQUEST, f"{request['part']} is not a part of {where}")
        return problem, part

    # -- answering -------------------------------------------------------------------------

    _allow = ""

    def _send_json(self, record: Mapping, status: int = HTTPStatus.OK) -> None:
        body = json.dumps(record, ensure_ascii=False).encode("utf-8")
        self._send(body, "application/json; charset=utf-8", status)

    def _send(self, body: bytes, content_type: str, status: int) -> None:
        self.send_response(status)
        self.send_header("Content-Type", content_type)
        if status != HTTPStatus.NO_CONTENT:
            self.send_header("Content-Length", str(len(body)))
        self.send_header("Cache-Control", "no-store")
        if status == HTTPStatus.METHOD_NOT_ALLOWED and self._allow:
            self.send_header("Allow", self._allow)
        for name, value in SECURITY_HEADERS.items():
            self.send_header(name, value)
        self.end_headers()
        if self.command != "HEAD":
            self.wfile.write(body)
