"""The self-check page end to end, in a real headless browser (Debian's chromium and chromedriver).

Typing shows how the answer is read (MathML, fetched as the student types), Check shows the
verdict and the hint, and the page runs under its own Content-Security-Policy without an error.
Skipped only when the browser or its driver is not installed (``apt-get install chromium
chromium-driver``; .ci/run installs them in CI).
"""

from __future__ import annotations

import json
import threading
from pathlib import Path

import pytest

CHROMIUM = Path("/usr/bin/chromium")
CHROMEDRIVER = Path("/usr/bin/chromedriver")
if not (CHROMIUM.exists() and CHROMEDRIVER.exists()):
    pytest.skip(
        f"needs {CHROMIUM} and {CHROMEDRIVER} (apt-get install chromium chromium-driver)", allow_module_level=True
    )

from course import BANK, REVIEW  # noqa: E402
from selenium import webdriver  # noqa: E402  (after the skip: nothing to drive without a browser)
from selenium.common.exceptions import StaleElementReferenceException, TimeoutException  # noqa: E402
from selenium.webdriver.common.by import By  # noqa: E402
from selenium.webdriver.support import expected_conditions  # noqa: E402
from selenium.webdriver.support.ui import WebDriverWait  # noqa: E402

from grader.serve import make_server  # noqa: E402

KEY = "plane-pendulum.lagrangian"
SIGN_HINT = "Check the sign of the potential energy; with θ from the downward vertical the bob is lowest at θ = 0."


@pytest.fixture(scope="module")
def server(tmp_path_factory):
    log = tmp_path_factory.mktemp("browser") / "attempts.jsonl"
    server = make_server(bank=BANK, assignment=REVIEW, log_path=log)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    yield server
    server.shutdown()
    server.server_close()


@pytest.fixture(scope="module")
def browser():
    options = webdriver.ChromeOptions()
    options.binary_location = str(CHROMIUM)
    for argument in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                     "--window-size=1200,900"):  # fmt: skip
        options.add_argument(argument)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=webdriver.ChromeService(executable_path=str(CHROMEDRIVER)), options=options)
    yield driver
    driver.quit()


def _part(driver, key: str = KEY):
    return driver.find_element(By.CSS_SELECTOR, f'article.part[data-part="{key}"]')


def _type(driver, text: str, key: str = KEY) -> None:
    box = driver.find_element(By.ID, f"answer-{key}")
    box.clear()
    box.send_keys(text)


def _check(driver, status: str, key: str = KEY):
    """Click Check and wait for a verdict of ``status``; the result element."""
    part = _part(driver, key)
    part.find_element(By.CSS_SELECTOR, "button.check").click()
    selector = f'article.part[data-part="{key}"] .result.{status}'
    try:
        return WebDriverWait(driver, 20).until(
            expected_conditions.visibility_of_element_located((By.CSS_SELECTOR, selector))
        )
    except TimeoutException:  # say what came instead, so that a failure here can be read
        shown = part.find_element(By.CSS_SELECTOR, ".result")
        button = part.find_element(By.CSS_SELECTOR, "button.check").text  # "Checking…": the request is pending
        raise AssertionError(
            f"wanted {status}; the result is {shown.get_attribute('class')!r}: {shown.text!r};"
            f" the button says {button!r}"
        ) from None


def _previewed(driver, key: str = KEY):
    """Wait for the preview of the answer typed to show it read; the preview element."""
    selector = f'article.part[data-part="{key}"] .preview math'
    WebDriverWait(driver, 20).until(expected_conditions.presence_of_element_located((By.CSS_SELECTOR, selector)))
    return _part(driver, key).find_element(By.CSS_SELECTOR, ".preview")


def test_type_preview_check_and_hint(server, browser):
    browser.get(server.url)
    assert browser.title == "Self-check — Review questions — the Lagrangian formulation"
    browser.find_element(By.ID, "student").send_keys("ada")

    _type(browser, "1/2 m l^2 thetadot^2 + m g l cos(theta)")
    assert _previewed(browser).find_element(By.CSS_SELECTOR, ".caption").text == "READ AS"

    result = _check(browser, "equivalent")
    assert result.find_element(By.CSS_SELECTOR, ".verdict").text == "✔\nright"
    assert result.find_elements(By.CSS_SELECTOR, ".read math")
    assert not result.find_elements(By.CSS_SELECTOR, "ul.hints li")

    _type(browser, "1/2 m l^2 thetadot^2 - m g l cos(theta)")
    result = _check(browser, "not_equivalent")
    assert result.find_element(By.CSS_SELECTOR, ".verdict").text == "✘\nnot right"
    assert [li.text for li in result.find_elements(By.CSS_SELECTOR, "ul.hints li")] == [SIGN_HINT]

    lines = server.attempts.path.read_text(encoding="utf-8").splitlines()
    assert [(r["student"], r["part"], r["status"]) for r in map(json.loads, lines)] == [
        ("ada", KEY, "equivalent"),
        ("ada", KEY, "not_equivalent"),
    ]


def test_an_unreadable_answer_is_pointed_at(server, browser):
    browser.get(server.url)
    _type(browser, "sin(theta")
    refusal = f'article.part[data-part="{KEY}"] .preview div.refusal'
    message = WebDriverWait(browser, 20).until(
        expected_conditions.presence_of_element_located((By.CSS_SELECTOR, refusal))
    )
    assert message.text == "Unbalanced bracket: the ( at position 4 is never closed."
    assert [code.text for code in message.find_elements(By.TAG_NAME, "code")] == ["("]  # `(` shown as code
    result = _check(browser, "invalid")
    assert result.find_element(By.CSS_SELECTOR, ".verdict").text == "invalid\ncould not be read"
    assert result.find_element(By.CSS_SELECTOR, ".read pre").text == "sin(theta\n   ^"
    assert result.find_element(By.CSS_SELECTOR, ".read .caption").text == "where:"


PERIOD = "plane-pendulum.period"


def _check_period(browser, answer: str, status: str):
    _type(browser, answer, PERIOD)
    return _check(browser, status, PERIOD)


def test_a_number_with_a_word_is_shown_as_read(server, browser):
    browser.get(server.url)
    result = _check_period(browser, "2.006 x", "invalid")
    assert [li.text for li in result.find_elements(By.CSS_SELECTOR, "ul.hints li")] == [
        "A number is asked for here; your answer contains x."
    ]
    assert [code.text for code in result.find_elements(By.CSS_SELECTOR, "ul.hints li code")] == ["x"]
    assert result.find_element(By.CSS_SELECTOR, ".read .caption").text == "read as:"
    assert result.find_elements(By.CSS_SELECTOR, ".read math")


def test_a_number_in_another_unit_is_read_in_the_one_asked(server, browser):
    browser.get(server.url)
    result = _check_period(browser, "2006 ms", "equivalent")
    assert [li.text for li in result.find_elements(By.CSS_SELECTOR, "ul.hints li")] == ["Read as 2.006 s."]


def test_after_a_check_the_answer_is_shown_as_the_check_read_it(server, browser):
    # The preview reads the unit's N·m as names, m the mass among them; the check sets the unit apart.
    key = "generalized-forces.q-theta"
    browser.get(server.url)
    _type(browser, "−m g r sin θ N·m", key)
    assert "N" in _previewed(browser, key).text
    result = _check(browser, "equivalent", key)
    assert _part(browser, key).find_element(By.CSS_SELECTOR, ".preview").text == ""
    shown = result.find_element(By.CSS_SELECTOR, ".read math").text
    assert "r" in shown and "N" not in shown
    _type(browser, "−m g r sin θ", key)  # edited: the preview is back
    assert "N" not in _previewed(browser, key).text


def test_hostile_text_stays_text(server, browser):
    browser.get(server.url)
    _type(browser, "<img src=x onerror=document.title='owned'>")
    result = _check(browser, "invalid")
    assert not result.find_elements(By.TAG_NAME, "img")
    assert browser.title.startswith("Self-check")


def test_the_page_runs_without_errors(server, browser):
    # A CSP violation or a script error shows in the console.
    browser.get(server.url)
    _type(browser, "m g l")
    _check(browser, "not_equivalent")
    problems = [entry for entry in browser.get_log("browser") if entry["level"] == "SEVERE"]
    problems = [entry for entry in problems if "favicon.ico" not in entry["message"]]
    assert problems == []


MOTION = "plane-pendulum.motion"


def test_equations_from_the_students_own_lagrangian_on_the_page_earn_the_method_credit(server, browser):
    # the page sends the Lagrangian typed above along with the equations: as the class grade does
    browser.get(server.url)
    _type(browser, "1/2 m l^2 thetadot^2 + m g l sin(theta)")  # sin for cos
    _type(browser, "m l^2 thetaddot - m g l cos(theta) = 0", MOTION)  # what that Lagrangian implies
    # each preview, as it comes, makes its part taller: a click before the last moved the button away
    _previewed(browser)
    _previewed(browser, MOTION)
    result = _check(browser, "not_equivalent", MOTION)
    assert result.find_element(By.CSS_SELECTOR, ".verdict").text == "✘\nnot right (partial credit: 50%)"
    hints = [li.text for li in result.find_elements(By.CSS_SELECTOR, "ul.hints li")]
    assert hints == ["Your equations follow correctly from your own Lagrangian, which is not right: method credit."]
    _type(browser, "", KEY)  # no Lagrangian typed: the equations alone, wrong
    _check(browser, "not_equivalent", MOTION)
    # the verdict before was not_equivalent too, and stays shown until the new one comes: wait for its words
    verdict = f'article.part[data-part="{MOTION}"] .result.not_equivalent .verdict'
    alone = "✘\nnot right"
    # the result is drawn anew as the answer comes: an element found may be replaced before its text is read
    waiting = WebDriverWait(browser, 20, ignored_exceptions=(StaleElementReferenceException,))
    waiting.until(lambda driver: driver.find_element(By.CSS_SELECTOR, verdict).text == alone)
