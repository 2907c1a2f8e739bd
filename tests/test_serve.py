"""The self-check server (grader serve), over real HTTP against the real bank and review assignment.

A server runs on a free port in a daemon thread for the whole module. Every response body
is kept, and the last test asserts that none of them, nor the page, holds a reference answer.
"""

from __future__ import annotations

import dataclasses
import html
import json
import os
import re
import signal
import subprocess
import sys
import threading
import time
import urllib.error
import urllib.request

import pytest
from course import BANK, REVIEW, ROOT
from sympy.core.cache import clear_cache

from grader.cli import main
from grader.errors import GraderError
from grader.grade.part import expected_answer
from grader.grade.selfcheck import find_part
from grader.serve import LIMITS, make_server, problem_views, render_page
from grader.serve.workers import OVERRUN, PoolBusy

LAGRANGIAN = "plane-pendulum.lagrangian"
CSP = "default-src 'self'; script-src 'self' 'unsafe-inline'; style-src 'unsafe-inline'"
SEEN: list[str] = []  # every response body, for the last test


@pytest.fixture(scope="module")
def server(tmp_path_factory):
    log = tmp_path_factory.mktemp("serve") / "attempts.jsonl"
    server = make_server(bank=BANK, assignment=REVIEW, log_path=log)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    yield server
    server.shutdown()
    server.server_close()


def _call(server, method: str, path: str, body: bytes | None = None, content_type: str = "application/json"):
    """(status, headers, text) of one request; HTTP errors are answers too."""
    request = urllib.request.Request(server.url.rstrip("/") + path, data=body, method=method)
    if body is not None:
        request.add_header("Content-Type", content_type)
    try:
        with urllib.request.urlopen(request, timeout=30) as response:
            status, headers, raw = response.status, response.headers, response.read()
    except urllib.error.HTTPError as error:
        status, headers, raw = error.code, error.headers, error.read()
    text = raw.decode("utf-8")
    SEEN.append(text)
    return status, headers, text


def _post(server, path: str, record) -> tuple[int, dict]:
    status, headers, text = _call(server, "POST", path, json.dumps(record).encode("utf-8"))
    assert headers["Content-Type"] == "application/json; charset=utf-8"
    return status, json.loads(text)


# -- the page ---------------------------------------------------------------------------------


def test_the_page_lists_every_part_of_the_assignment(server):
    status, headers, page = _call(server, "GET", "/")
    assert status == 200
    assert headers["Content-Type"] == "text/html; charset=utf-8"
    keys = re.findall(r'<article class="part" data-part="([^"]+)"', page)
    expected = [f"{item.problem}.{part.id}" for item in REVIEW.items for part in BANK[item.problem].parts]
    assert keys == expected
    assert page.count("<textarea") == len(expected)
    assert page.count('<button type="button" class="check">Check</button>') == len(expected)
    assert "<h2>The plane pendulum</h2>" in page
    assert "<title>Self-check — Review questions — the Lagrangian formulation</title>" in page


def test_the_page_shows_prompts_and_choices_as_text(server):
    page = _call(server, "GET", "/")[2]
    # LaTeX is Unicode text (no MathJax), its source kept in a tooltip
    assert 'Write the Lagrangian <span class="tex" title="L(\\theta, \\dot\\theta)">L(θ, θ̇)</span>.' in page
    assert '<span class="tex" title="|\\theta| \\ll 1">|θ| ≪ 1</span>' in page
    assert '<span class="tex" title="\\theta_1">θ<sub>1</sub></span>' in page
    assert '<li><span class="label">a)</span> holonomic</li>' in page
    assert '<li><span class="label">b)</span> non-holonomic</li>' in page
    assert (
        '<span class="sym">θ₁</span> <code>theta1</code> angle of the upper rod from the downward vertical'
        ' <span class="unit">(rad)</span>;' in page
    )
    # each symbol's unit, as the feedback on units writes it
    assert 'gravitational acceleration <span class="unit">(m/s²)</span>' in page


HOSTILE = "<script>alert(1)</script> {{ 7*7 }} $</span><img src=x onerror=alert(1)>$ **<b>x</b>**"


def test_bank_text_is_escaped_everywhere():
    problem = BANK["plane-pendulum"]
    part = dataclasses.replace(problem.parts[0], prompt=HOSTILE, kind="choice", choices={"a": HOSTILE})
    hostile = dataclasses.replace(problem, title=HOSTILE, prompt=HOSTILE, parts=(part,))
    page = render_page(problem_views({"plane-pendulum": hostile}), title=HOSTILE)
    body = page.split("<body>", 1)[1].split("<script>", 1)[0]
    assert "<script>alert" not in body and "<img" not in body and "<b>x" not in body
    assert "&lt;script&gt;alert(1)&lt;/script&gt; {{ 7*7 }}" in body
    assert "49" not in body


def test_the_page_is_self_contained(server):
    page = _call(server, "GET", "/")[2]
    assert (
        "<script src" not in page
        and "<link" not in page
        and "http://" not in page.replace('xmlns="http://www.w3.org', "")
    )
    assert "https://" not in page
    assert "fetch(url" in page and 'post("/api/preview"' in page and 'post("/api/check"' in page


def test_security_headers_on_every_response(server):
    for method, path, body in [("GET", "/", None), ("POST", "/api/check", b"{"), ("GET", "/nowhere", None)]:
        _, headers, _ = _call(server, method, path, body)
        assert headers["Content-Security-Policy"] == CSP
        assert headers["X-Content-Type-Options"] == "nosniff"


def test_head_of_the_page(server):
    status, headers, text = _call(server, "HEAD", "/")
    assert (status, text) == (200, "")
    assert int(headers["Content-Length"]) > 10_000


def test_the_server_binds_to_this_machine_only_by_default(server):
    assert server.server_address[0] == "127.0.0.1"
    assert server.url == f"http://127.0.0.1:{server.server_address[1]}/"


# -- preview ------------------------------------------------------------------------------------


def test_preview_shows_how_the_answer_is_read(server):
    status, record = _post(server, "/api/preview", {"part": LAGRANGIAN, "answer": "1/2 m l^2 thetadot^2"})
    assert status == 200
    assert record["ok"] is True
    assert record["text"] == "l^2*m*θ̇^2/2"
    assert record["mathml"].startswith('<math xmlns="http://www.w3.org/1998/Math/MathML"')


def test_preview_refusal_says_what_and_where(server):
    status, record = _post(server, "/api/preview", {"part": LAGRANGIAN, "answer": "sin(θ"})
    assert status == 200
    assert record == {
        "ok": False,
        "message": "Unbalanced bracket: the `(` at position 4 is never closed.",
        "pointer": "sin(θ\n   ^",
    }


# Within every cap, yet sympy takes about a second to build each factor: (a + ib)¹⁰⁰ expanded.
SLOW = "*".join([f"(theta'''-(l^-{n})^(1/3))^(abs(m m)/(g+theta''))" for n in range(93, 101)])


def test_preview_of_an_answer_too_slow_to_read_is_bounded_by_the_check_timeout(tmp_path):
    clear_cache()  # or sympy remembers the factors from an earlier test, and reading is quick
    slow_server = make_server(bank=BANK, assignment=REVIEW, log_path=tmp_path / "log.jsonl", timeout=0.2)
    thread = threading.Thread(target=slow_server.serve_forever, daemon=True)
    thread.start()
    try:
        status, record = _post(slow_server, "/api/preview", {"part": LAGRANGIAN, "answer": SLOW})
    finally:
        slow_server.shutdown()
        slow_server.server_close()
    assert status == 200
    assert record == {
        "ok": False,
        "message": "This answer takes too long to read back here; check it to see how it was read.",
        "pointer": "",
    }


CHOICE = "constraint-classification.rigid-body-holonomic"


@pytest.mark.parametrize(
    ("answer", "text"),
    [
        (" b ", "b) non-holonomic"),
        ("A, b", "a) holonomic; b) non-holonomic"),
        ("z", "z"),
        ("b (non-holonomic)", "b) non-holonomic"),  # read as the checker reads it, not word by word
        ("non-holonomic", "b) non-holonomic"),
        ("non-holonomic (maybe holonomic)", "non-holonomic; (maybe; holonomic)"),  # a hedge names no option: as typed
    ],
)
def test_preview_of_a_choice_names_the_options_chosen(server, answer, text):
    status, record = _post(server, "/api/preview", {"part": CHOICE, "answer": answer})
    assert (status, record) == (200, {"ok": True, "mathml": "", "text": text})


def test_preview_of_a_choice_reads_a_symbol_by_what_the_problem_says_it_means(server):
    request = {"part": "spherical-pendulum.cyclic", "answer": "the azimuthal angle"}
    status, record = _post(server, "/api/preview", request)
    assert (status, record) == (200, {"ok": True, "mathml": "", "text": "b) $\\phi$"})


def test_preview_of_a_number_is_the_text_as_typed(server):
    status, record = _post(server, "/api/preview", {"part": "plane-pendulum.period", "answer": " 2.006 "})
    assert (status, record) == (200, {"ok": True, "mathml": "", "text": "2.006"})


def test_the_browser_asks_for_an_icon_and_gets_none(server):
    status, _, text = _call(server, "GET", "/favicon.ico")
    assert (status, text) == (204, "")


MATHML_TAGS = {
    "math", "mrow", "mi", "mo", "mn", "msup", "msub", "msubsup", "mfrac", "msqrt", "mroot", "mover", "munder",
    "mtext", "mspace", "mtable", "mtr", "mtd", "mstyle", "mfenced", "mpadded", "mphantom",
}  # fmt: skip
PREVIEWS = [
    "\\frac{1}{2} m l^2 \\dot\\theta^2 + mgl\\cos\\theta",
    "θ̈ = -(g/l) cos θ",
    "m l^2 theta'' + m g l cos(theta) = 0; x = 2",
    "sqrt(l/g) + abs(theta) + exp(-t) + theta_1dot",
    "<script>alert(1)</script>",
    "a<b & c>d",
]


@pytest.mark.parametrize("answer", PREVIEWS)
def test_preview_mathml_is_only_mathml(server, answer):
    # The page inserts this markup as HTML: it must be our printer's MathML and nothing else.
    status, record = _post(server, "/api/preview", {"part": LAGRANGIAN, "answer": answer})
    assert status == 200
    if record["ok"]:
        assert set(re.findall(r"<\s*/?\s*([a-zA-Z][\w:-]*)", record["mathml"])) <= MATHML_TAGS
        assert "script" not in record["mathml"].lower() and " on" not in record["mathml"].lower()


# -- check --------------------------------------------------------------------------------------


def test_check_right(server):
    status, record = _post(server, "/api/check", {"part": LAGRANGIAN, "answer": "1/2 m l^2 θ̇^2 + m g l cos θ"})
    assert status == 200
    assert {k: record[k] for k in ("status", "symbol", "words", "hints", "read_as")} == {
        "status": "equivalent",
        "symbol": "✔",
        "words": "right",
        "hints": [],
        "read_as": "g*l*m*cos(θ) + l^2*m*θ̇^2/2",
    }
    assert record["mathml"].startswith("<math")


def test_check_wrong_gives_the_hint(server):
    answer = "1/2 m l^2 thetadot^2 - m g l cos(theta)"
    status, record = _post(server, "/api/check", {"part": LAGRANGIAN, "answer": answer, "student": "ada"})
    assert status == 200
    assert (record["status"], record["symbol"], record["words"]) == ("not_equivalent", "✘", "not right")
    assert record["hints"] == [
        "Check the sign of the potential energy; with θ from the downward vertical the bob is lowest at θ = 0."
    ]


def test_check_invalid_points_at_the_spot(server):
    status, record = _post(server, "/api/check", {"part": LAGRANGIAN, "answer": "sin(theta"})
    assert status == 200
    assert (record["status"], record["symbol"], record["words"]) == ("invalid", "invalid", "could not be read")
    assert record["hints"] == ["Unbalanced bracket: the `(` at position 4 is never closed."]
    assert record["read_as"] == "sin(theta\n   ^"
    assert record["mathml"] == ""


def test_check_of_a_text_part_is_for_a_person(server):
    answer = "sin θ ≈ θ for small angles, so the restoring acceleration is proportional to θ"
    status, record = _post(server, "/api/check", {"part": "plane-pendulum.why-harmonic", "answer": answer})
    assert (status, record["status"], record["symbol"]) == (200, "undecided", "?")


def test_the_attempts_log_gets_one_line_per_check(server):
    before = server.attempts.path.read_text(encoding="utf-8").splitlines()
    _post(server, "/api/check", {"part": LAGRANGIAN, "answer": "m g l", "student": "  grace  "})
    _post(server, "/api/check", {"part": "plane-pendulum.period", "answer": "2.006"})
    _post(server, "/api/preview", {"part": LAGRANGIAN, "answer": "m g l"})  # previews are not attempts
    lines = server.attempts.path.read_text(encoding="utf-8").splitlines()
    assert len(lines) == len(before) + 2
    first, second = (json.loads(line) for line in lines[-2:])
    assert list(first) == ["time", "student", "part", "answer", "status"]
    assert (first["student"], first["part"], first["answer"], first["status"]) == (
        "grace", LAGRANGIAN, "m g l", "not_equivalent"
    )  # fmt: skip
    assert (second["student"], second["status"]) == (None, "equivalent")
    assert re.fullmatch(r"\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d\.\d{3}\+00:00", first["time"])


def test_concurrent_checks_write_whole_lines(server):
    before = len(server.attempts.path.read_text(encoding="utf-8").splitlines())
    statuses = []

    def one(n: int) -> None:
        statuses.append(
            _post(server, "/api/check", {"part": LAGRANGIAN, "answer": f"{n} m g l", "student": f"s{n}"})[0]
        )

    threads = [threading.Thread(target=one, args=(n,)) for n in range(12)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert statuses == [200] * 12
    lines = server.attempts.path.read_text(encoding="utf-8").splitlines()[before:]
    assert sorted(json.loads(line)["student"] for line in lines) == sorted(f"s{n}" for n in range(12))


# -- bad requests ---------------------------------------------------------------------------------


def test_unknown_part_is_400_with_what_exists(server):
    status, record = _post(server, "/api/check", {"part": "plane-pendulum.nope", "answer": "x"})
    assert status == 400
    with pytest.raises(GraderError) as error:
        find_part("plane-pendulum.nope", BANK)
    assert record == {"error": str(error.value)}
    status, record = _post(server, "/api/preview", {"part": "no-such-problem.x", "answer": "x"})
    assert status == 400 and record["error"].startswith("no problem 'no-such-problem'; the problems are: ")


def test_a_part_outside_the_assignment_is_400(server):
    part = BANK["double-pendulum-equal"].parts[0].id
    status, record = _post(server, "/api/check", {"part": f"double-pendulum-equal.{part}", "answer": "x"})
    assert (status, record) == (400, {"error": f"double-pendulum-equal.{part} is not a part of review"})


BAD_BODIES = [
    (b"{not json", 400, "the request body is not valid JSON"),
    (b"\xff\xfe", 400, "the request body is not valid JSON"),
    (b'["plane-pendulum.lagrangian", "x"]', 400, 'send a JSON object: {"part": "problem.part", "answer": "…"}'),
    (b'{"answer": "x"}', 400, '"part" must be a string'),
    (b'{"part": "plane-pendulum.lagrangian", "answer": 3}', 400, '"answer" must be a string'),
    (b'{"part": "plane-pendulum.lagrangian", "answer": "x", "student": 7}', 400, '"student" must be a string'),
    (b"", 400, "the request body is not valid JSON"),
]


@pytest.mark.parametrize(("body", "status", "message"), BAD_BODIES)
@pytest.mark.parametrize("path", ["/api/preview", "/api/check"])
def test_bad_json_is_400(server, path, body, status, message):
    got_status, _, text = _call(server, "POST", path, body)
    assert (got_status, json.loads(text)) == (status, {"error": message})


def test_a_form_post_is_refused(server):
    # A JSON content type is what keeps other sites' pages from posting here without CORS.
    body = json.dumps({"part": LAGRANGIAN, "answer": "x"}).encode()
    status, _, text = _call(server, "POST", "/api/check", body, content_type="text/plain")
    assert (status, json.loads(text)) == (415, {"error": "send JSON, with Content-Type: application/json"})


def test_an_answer_too_long_is_413(server):
    status, record = _post(server, "/api/check", {"part": LAGRANGIAN, "answer": "x" * (LIMITS.answer + 1)})
    assert (status, record) == (413, {"error": "the answer is 5001 characters long; at most 5000 are read"})


def test_a_body_too_large_is_413(server):
    body = json.dumps({"part": LAGRANGIAN, "answer": "x", "pad": "y" * LIMITS.body}).encode()
    status, _, text = _call(server, "POST", "/api/check", body)
    assert (status, json.loads(text)) == (413, {"error": "the request is larger than 65536 bytes"})


@pytest.mark.parametrize(("method", "path"), [("GET", "/nowhere"), ("POST", "/api/nothing"), ("GET", "/api")])
def test_unknown_path_is_404(server, method, path):
    status, _, text = _call(server, method, path, b"{}" if method == "POST" else None)
    assert (status, json.loads(text)) == (404, {"error": f"there is no {path}; the page is at /"})


METHODS = [
    ("GET", "/api/check", "POST", "/api/check takes POST, not GET"),
    ("PUT", "/api/preview", "POST", "/api/preview takes POST, not PUT"),
    ("DELETE", "/api/check", "POST", "/api/check takes POST, not DELETE"),
    ("POST", "/", "GET", "/ takes GET, not POST"),
]


@pytest.mark.parametrize(("method", "path", "allow", "message"), METHODS)
def test_wrong_method_is_405(server, method, path, allow, message):
    status, headers, text = _call(server, method, path, b"{}" if method in ("POST", "PUT") else None)
    assert (status, json.loads(text)) == (405, {"error": message})
    assert headers["Allow"] == allow


def test_an_exception_is_500_and_the_server_keeps_running(server, monkeypatch, capfd):
    def broken(*args, **kwargs):
        raise RuntimeError("a bug")

    monkeypatch.setattr(server.checks, "check", broken)
    status, record = _post(server, "/api/check", {"part": LAGRANGIAN, "answer": "x"})
    assert (status, record) == (500, {"error": "the server failed on this request; it has been logged"})
    assert "RuntimeError: a bug" in capfd.readouterr().err
    monkeypatch.undo()
    status, record = _post(server, "/api/check", {"part": LAGRANGIAN, "answer": "1/2 m l^2 θ̇^2 + m g l cos θ"})
    assert (status, record["status"]) == (200, "equivalent")


def test_a_check_ended_for_overrunning_is_undecided_and_says_why(server, monkeypatch):
    monkeypatch.setattr(
        server.checks, "check", lambda key, answer, answers: None
    )  # what CheckPool says of one it ended
    status, record = _post(server, "/api/check", {"part": LAGRANGIAN, "answer": "m l^2 θ̇^2"})
    assert (status, record["status"], record["symbol"]) == (200, "undecided", "?")
    assert record["hints"] == [OVERRUN]


WRONG_L = "1/2 m l^2 θ̇^2 + m g l sin θ"  # sin for cos (not T + V: read back, its equation holds the reference's)
FROM_WRONG_L = "m l^2 θ̈ - m g l cos θ = 0"  # what it implies


def test_equations_from_the_students_own_lagrangian_earn_the_method_credit(server):
    # the page sends the Lagrangian part's answer along with a derived part's: as grading the class does
    sent = {"part": "plane-pendulum.motion", "answer": FROM_WRONG_L, "lagrangian": WRONG_L}
    status, record = _post(server, "/api/check", sent)
    assert (status, record["status"], record["score"]) == (200, "not_equivalent", 0.5), record
    assert record["hints"] == [
        "Your equations follow correctly from your own Lagrangian, which is not right: method credit."
    ]
    # without it, or with the right Lagrangian, the equations are judged alone
    for lagrangian in ("", "1/2 m l^2 θ̇^2 + m g l cos θ"):
        status, record = _post(server, "/api/check", {**sent, "lagrangian": lagrangian})
        assert (status, record["score"]) == (200, 0.0), record


def test_the_page_sends_a_derived_parts_lagrangian():
    page = render_page(problem_views(BANK, REVIEW), title="t")
    assert (
        '<article class="part" data-part="plane-pendulum.motion" data-kind="equation"'
        ' data-derived-from="plane-pendulum.lagrangian"'
    ) in page
    assert 'data-part="plane-pendulum.lagrangian" data-kind="lagrangian" data-derived-from=""' in page
    assert "payload.lagrangian = source.value" in page


@pytest.mark.parametrize(
    ("lagrangian", "status", "error"),
    [
        (3, 400, '"lagrangian" must be a string'),
        ("x" * 5001, 413, "the Lagrangian is 5001 characters long; at most 5000 are read"),
    ],
)
def test_a_lagrangian_sent_along_is_checked_like_an_answer(server, lagrangian, status, error):
    sent = {"part": "plane-pendulum.motion", "answer": FROM_WRONG_L, "lagrangian": lagrangian}
    assert _post(server, "/api/check", sent) == (status, {"error": error})


def test_every_worker_busy_is_503(server, monkeypatch):
    def busy(key, answer, answers):
        raise PoolBusy

    monkeypatch.setattr(server.checks, "check", busy)
    status, record = _post(server, "/api/check", {"part": LAGRANGIAN, "answer": "m l^2 θ̇^2"})
    assert (status, record) == (503, {"error": "the server is busy; check again in a moment"})


def test_a_slow_check_is_bounded_by_the_time_limit(tmp_path):
    quick = make_server(bank=BANK, log_path=tmp_path / "log.jsonl", timeout=1e-9)
    thread = threading.Thread(target=quick.serve_forever, daemon=True)
    thread.start()
    try:
        status, record = _post(quick, "/api/check", {"part": LAGRANGIAN, "answer": "m l^2 θ̇^2"})
    finally:
        quick.shutdown()
        quick.server_close()
    assert (status, record["status"], record["symbol"]) == (200, "undecided", "?")


def test_without_an_assignment_the_page_shows_the_whole_bank(tmp_path):
    whole = make_server(bank=BANK)
    thread = threading.Thread(target=whole.serve_forever, daemon=True)
    thread.start()
    try:
        page = _call(whole, "GET", "/")[2]
        status, _ = _post(whole, "/api/preview", {"part": "double-pendulum-equal.lagrangian", "answer": "m"})
    finally:
        whole.shutdown()
        whole.server_close()
    keys = re.findall(r'data-part="([^"]+)"', page)
    assert keys == [f"{pid}.{part.id}" for pid in sorted(BANK) for part in BANK[pid].parts]
    assert whole.attempts is None
    assert status == 200


def test_a_port_in_use_raises(server):
    with pytest.raises(OSError):
        make_server(bank=BANK, port=server.server_address[1])


# -- reference answers never leave the server -------------------------------------------------------


def _references() -> list[tuple[str, str]]:
    """(where, text) of every reference and mistake answer in the bank of 6 characters or more;
    not a choice's own words, which the page shows as the options (a test may answer with them)."""
    found = []
    for problem in BANK.values():
        for part in problem.parts:
            shown = {text.strip().lower() for text in part.choices.values()}
            texts = [("answer", expected_answer(problem, part))]
            texts += [(f"mistakes[{i}]", str(m.answer)) for i, m in enumerate(part.mistakes)]
            texts += [(f"tests[{i}]", str(t.answer)) for i, t in enumerate(part.tests)]
            found += [
                (f"{problem.id}.{part.id} {field}", text.strip())
                for field, text in texts
                if len(text.strip()) >= 6 and text.strip().lower() not in shown
            ]
    return found


REFERENCES = _references()


def test_the_bank_has_references_to_look_for():
    assert len(REFERENCES) > 100


def test_no_reference_answer_is_in_the_page(server):
    whole_bank = render_page(problem_views(BANK), title="The problem bank")
    for page in (_call(server, "GET", "/")[2], whole_bank):
        for variant in (page, html.unescape(page)):
            leaks = [where for where, text in REFERENCES if text in variant]
            assert not leaks, f"reference answers in the page: {leaks}"


def _strings(value) -> list[str]:
    if isinstance(value, str):
        return [value]
    if isinstance(value, dict):
        return [s for item in value.values() for s in _strings(item)]
    if isinstance(value, list):
        return [s for item in value for s in _strings(item)]
    return []


def test_no_reference_answer_is_in_any_response(server):
    # Runs last in this module: SEEN holds every body the tests above received.
    assert len(SEEN) > 50
    for body in SEEN:
        try:
            texts = [body, *_strings(json.loads(body))]
        except ValueError:
            texts = [body, html.unescape(body)]
        for text in texts:
            leaks = [where for where, reference in REFERENCES if reference in text]
            assert not leaks, f"reference answers {leaks} in a response: {body[:300]}"


# -- the command ----------------------------------------------------------------------------------


def test_grader_serve_prints_the_url_and_stops_cleanly_on_ctrl_c(tmp_path):
    log = tmp_path / "attempts.jsonl"
    command = [sys.executable, "-m", "grader", "serve", "--assignment", "review", "--port", "0", "--log", str(log)]
    process = subprocess.Popen(command, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        first = process.stdout.readline()
        url = re.search(r"http://127\.0\.0\.1:\d+/", first).group(0)
        assert first == f"Self-check page on {url} — attempts are logged to {log}; Ctrl-C stops.\n"
        with urllib.request.urlopen(url, timeout=30) as response:
            assert response.status == 200
        process.send_signal(signal.SIGINT)
        out, _ = process.communicate(timeout=30)
    finally:
        if process.poll() is None:
            process.kill()
    assert process.returncode == 0
    assert out == "\nstopped\n"


@pytest.mark.parametrize("seconds", [0.5, 1.0, 1.5, 2.0, 3.0])
def test_ctrl_c_while_grader_serve_starts_ends_it_without_a_traceback(tmp_path, seconds):
    # While sympy loads, while the fork server preloads, while workers are handed the bank, or
    # once the page is up: a terminal's Ctrl-C reaches every process of the group, as killpg does.
    # Not earlier: in the interpreter's own first 30 ms or so (its start-up, the console script's
    # imports) no code of ours can catch it, and Python prints a traceback or is simply killed.
    command = [sys.executable, "-m", "grader", "serve", "--port", "0", "--log", str(tmp_path / "log.jsonl")]
    process = subprocess.Popen(
        command, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, start_new_session=True
    )
    try:
        time.sleep(seconds)
        os.killpg(process.pid, signal.SIGINT)
        out, _ = process.communicate(timeout=60)
    finally:
        if process.poll() is None:
            os.killpg(process.pid, signal.SIGKILL)
    assert "Traceback" not in out
    if process.returncode == -signal.SIGINT:
        # on a loaded machine, still before Python handles Ctrl-C; or handled, but it came inside an exec of
        # a string (dataclasses and namedtuples build methods so as grader.cli loads), and CPython then ends the
        # process by SIGINT all the same, once it has said so
        assert out in ("", "\ngrader: interrupted\n")
    elif process.returncode == 130:
        assert out.endswith("\ngrader: interrupted\n")
    else:
        assert (process.returncode, out.endswith("\nstopped\n")) == (0, True), out


def test_grader_serve_with_an_unknown_assignment_exits_2(capsys):
    assert main(["serve", "--assignment", "no-such-assignment", "--port", "0"]) == 2
    assert "no-such-assignment" in capsys.readouterr().err


def test_grader_serve_on_a_port_in_use_exits_2(server, capsys, tmp_path):
    port = str(server.server_address[1])
    assert main(["serve", "--port", port, "--log", str(tmp_path / "log.jsonl")]) == 2
    assert capsys.readouterr().err.startswith("grader serve: cannot start: ")
