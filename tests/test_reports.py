"""Reports: a student's page (HTML and Markdown) and the class summary, against the real bank.

Hand-built grades cover every part status, a manual score and a submission that could not be
graded; hostile student text must come out as text; reference answers only when revealed; the
summary's numbers are checked against values worked out by hand.
"""

from __future__ import annotations

import dataclasses
import math
import re
from collections import Counter
from html.parser import HTMLParser

import pytest
from course import BANK, REVIEW, ROOT

from grader.grade.batch import grade_submission
from grader.grade.part import expected_answer, setting_of
from grader.grade.results import PartGrade, Student, SubmissionGrade
from grader.grade.submissions import Submission
from grader.parse import parse_answer
from grader.report import (
    TEMPLATES,
    common_wrong_answers,
    item_analysis,
    render_student_report,
    render_summary,
    review_queue,
    score_histogram,
)

SCRIPT = "<script>alert(1)</script>"
TEMPLATE_INJECTION = "{{ 7*7 }}"
HOSTILE_COMMENT = "<img src=x onerror=alert(1)> Say why sin θ ≈ θ makes it linear."
HARMONIC_ANSWER = f"because {SCRIPT} {TEMPLATE_INJECTION} and sin θ ≈ θ"
# The text part's model answer: it may appear only when references are revealed.
MODEL_ANSWER = "the equation of a harmonic oscillator"

# Student text that must reach the page as text, never as markup: HTML, Jinja, a Markdown
# fence and an HTML comment that would swallow the rest of the page.
HOSTILE_TEXTS = [
    SCRIPT,
    TEMPLATE_INJECTION,
    "{% for x in range(9) %}x{% endfor %}",
    "</pre></dd></dl><script>alert(1)</script>",
    '"><svg onload=alert(1)>',
    "<!-- everything after this",
    "```\n<script>alert(1)</script>\n```",
    "[click](javascript:alert(1)) ![x](http://evil.example/x.png)",
]


# -- building grades by hand --------------------------------------------------------------


def _read(problem: str, answer: str) -> dict:
    """read_as and read_as_mathml as grading records them: from our own parser and printer."""
    setting = setting_of(BANK[problem])
    read = parse_answer(answer, coords=setting["coords"], known=setting["known"])
    if not read.ok:
        return {"read_as": read.pointer}
    return {"read_as": read.read_as_text, "read_as_mathml": read.read_as_mathml}


def _part(key: str, answer: str, status: str, score: float, maximum: float, **fields) -> PartGrade:
    problem, part = key.split(".")
    math_kinds = ("expression", "equation", "equations", "lagrangian", "number")
    kind = BANK[problem].part(part).kind
    read = _read(problem, answer) if answer.strip() and kind in math_kinds else {}
    return PartGrade(problem, part, maximum, answer, status, score, kind=kind, **{**read, **fields})


def _ada(**replace) -> SubmissionGrade:
    """One student with every status: right, wrong (an anticipated mistake), unreadable, blank,
    undecided, wrong by tolerance, and a text part set aside for a person."""
    parts = (
        _part(
            "plane-pendulum.lagrangian", "1/2 m l^2 thetadot^2 - m g l cos(theta)", "not_equivalent", 0.0, 4.0,
            feedback=(BANK["plane-pendulum"].part("lagrangian").mistakes[0].feedback,),
            diagnosis="mistake", method="mistake",
        ),
        _part("plane-pendulum.motion", "thetaddot = -(g/l) sin(theta)", "equivalent", 3.0, 3.0,
              feedback=("Correct.",), method="accelerations"),
        _part("plane-pendulum.small-oscillations", "sin(θ", "invalid", 0.0, 1.0,
              feedback=("Unbalanced bracket: the `(` at position 4 is never closed.",), diagnosis="invalid",
              method="parse"),
        _part("plane-pendulum.frequency", "", "blank", 0.0, 1.0, feedback=("No answer.",), method="blank"),
        _part("plane-pendulum.period", "6.28", "not_equivalent", 0.0, 1.0,
              feedback=("Not within the accepted tolerance.",), diagnosis="out_of_tolerance", method="numeric"),
        _part("plane-pendulum.why-harmonic", HARMONIC_ANSWER, "undecided", 1.0, 2.0,
              feedback=("A person will read this answer; the rubric found 1 of its 2 ideas.",),
              diagnosis="text_review", method="rubric"),
        _part("double-pendulum.lagrangian", "1/2 (m1 + m2) l1^2 theta1dot^2", "undecided", 0.0, 4.0,
              feedback=("This answer could not be checked in time; a person will look at it.",), method="timeout"),
    )  # fmt: skip
    grade = SubmissionGrade(Student("s001", "Ada Lovelace", "ada@example.edu"), parts)
    return dataclasses.replace(grade, **replace)


def _with_manual_score(grade: SubmissionGrade, key: str, score: float, comment: str) -> SubmissionGrade:
    parts = tuple(
        dataclasses.replace(part, manual_score=score, comment=comment) if part.key == key else part
        for part in grade.parts
    )
    return dataclasses.replace(grade, parts=parts)


def _with_answer(grade: SubmissionGrade, key: str, answer: str) -> SubmissionGrade:
    return dataclasses.replace(
        grade, parts=tuple(dataclasses.replace(p, answer=answer) if p.key == key else p for p in grade.parts)
    )


ERROR = SubmissionGrade(
    Student("s404", "Grace Hopper"), (), status="error", message="could not be graded: MemoryError: <too big>"
)


# -- reading the HTML back ------------------------------------------------------------------

VOID = {"area", "base", "br", "col", "embed", "hr", "img", "input", "link", "meta", "source", "track", "wbr"}


class _Page(HTMLParser):
    """Parses a page strictly enough: every element closed, in order; collects tags, attributes and text."""

    def __init__(self, page: str):
        super().__init__(convert_charrefs=True)
        self.open: list[str] = []
        self.tags: Counter[str] = Counter()
        self.attributes: list[tuple[str, str, str]] = []
        self.problems: list[str] = []
        self.chunks: list[str] = []
        self.style: list[str] = []
        self.feed(page)
        self.close()
        if self.open:
            self.problems.append(f"never closed: {self.open}")

    def handle_starttag(self, tag, attrs):
        self.handle_startendtag(tag, attrs)
        if tag not in VOID:
            self.open.append(tag)

    def handle_startendtag(self, tag, attrs):
        self.tags[tag] += 1
        self.attributes += [(tag, name, value or "") for name, value in attrs]

    def handle_endtag(self, tag):
        if not self.open or self.open[-1] != tag:
            self.problems.append(f"</{tag}> closes {self.open[-1] if self.open else 'nothing'} at {self.getpos()}")
        else:
            self.open.pop()

    def handle_data(self, data):
        (self.style if self.open and self.open[-1] == "style" else self.chunks).append(data)

    @property
    def text(self) -> str:
        return "".join(self.chunks)


def _page(html_page: str) -> _Page:
    page = _Page(html_page)
    assert not page.problems, page.problems
    return page


NAMESPACES = {"http://www.w3.org/1998/Math/MathML", "http://www.w3.org/2000/svg"}


def _self_contained(page: _Page) -> None:
    """No script, no handlers, nothing fetched: links stay in the page, addresses are XML namespaces."""
    for tag in ("script", "link", "iframe", "img", "object", "embed", "base", "audio", "video", "image"):
        assert page.tags[tag] == 0, tag
    for tag, name, value in page.attributes:
        assert not name.startswith("on") and name not in ("src", "srcset", "action", "formaction"), (tag, name)
        assert name != "href" or value.startswith("#"), (tag, value)
        assert name != "xmlns" or value in NAMESPACES, value
        assert "url(" not in value, (tag, name, value)
    style = "".join(page.style)
    assert "url(" not in style and "@import" not in style and "http" not in style


def _markdown_outside_code(markdown: str) -> str:
    """The Markdown with fenced blocks and code spans removed: what a renderer reads as markup."""
    without_fences = re.sub(r"^(`{3,})[^\n]*\n.*?\n\1$", "", markdown, flags=re.S | re.M)
    return re.sub(r"(`+).+?\1", "", without_fences)


# -- the student's report ---------------------------------------------------------------------


def test_templates_are_beside_the_package():
    assert TEMPLATES == ROOT / "templates"
    assert {"student.html.j2", "student.md.j2", "summary.html.j2"} <= {p.name for p in TEMPLATES.iterdir()}


def test_student_report_shows_every_status():
    html_page, markdown = render_student_report(_ada(), assignment=REVIEW, bank=BANK)
    page = _page(html_page)
    _self_contained(page)
    assert page.tags["math"] == sum(bool(part.read_as_mathml) for part in _ada().parts) == 4
    for words in ("✔ right", "✘ not right", "? set aside for a person", "⚠ invalid", "– blank"):
        assert words in page.text and words in markdown
    assert "Review questions — the Lagrangian formulation" in page.text
    assert "Ada Lovelace" in page.text and "s001" in page.text
    assert '<span class="score">4</span><span class="of">/ 16</span>' in html_page and "25.0%" in page.text
    # the score table: a row per part, under its problem's title; a heading row and a total
    assert page.tags["tr"] == 1 + 2 + len(_ada().parts) + 1
    assert "The plane pendulum" in page.text and "The double pendulum" in page.text
    # prompts' LaTeX read as Unicode text, its source kept for a tooltip; the Markdown keeps it as written
    assert "Write the Lagrangian L(θ, θ̇)." in page.text
    assert ("span", "title", "L(\\theta, \\dot\\theta)") in page.attributes
    assert "$" not in page.text and "\\dot" not in page.text
    assert "Write the Lagrangian $L(\\theta, \\dot\\theta)$." in markdown
    # feedback, and the line that shows where an unreadable answer fails
    assert BANK["plane-pendulum"].part("lagrangian").mistakes[0].feedback in page.text
    assert "sin(θ\n   ^" in page.text and "sin(θ\n   ^" in markdown
    # a sentence's `…` is code on the page; the Markdown shows it as written (its backticks escaped)
    assert "<li>Unbalanced bracket: the <code>(</code> at position 4 is never closed.</li>" in html_page
    assert "the \\`(\\` at position 4" in markdown
    assert "| plane-pendulum.period | 0 | 1 | ✘ not right |" in markdown
    assert "provisional" in page.text


def test_reference_answers_only_when_revealed():
    motion = expected_answer(BANK["plane-pendulum"], BANK["plane-pendulum"].part("motion"))
    hidden_html, hidden_markdown = render_student_report(_ada(), assignment=REVIEW, bank=BANK)
    shown_html, shown_markdown = render_student_report(_ada(), assignment=REVIEW, bank=BANK, reveal=True)
    for hidden in (_page(hidden_html).text, hidden_markdown):
        assert "Reference answer" not in hidden and MODEL_ANSWER not in hidden and motion not in hidden
    shown_page = _page(shown_html)
    assert shown_page.text.count("Reference answer") == len(_ada().parts)
    assert MODEL_ANSWER in shown_page.text and MODEL_ANSWER in shown_markdown
    assert motion in shown_markdown
    assert shown_page.tags["math"] > _page(hidden_html).tags["math"]  # references are drawn as math too
    assert "2*pi*sqrt(1/9.81) ≈ 2.006" in shown_page.text  # a number's reference, with its value


def test_manual_score_and_comment():
    grade = _with_manual_score(_ada(), "plane-pendulum.why-harmonic", 1.5, HOSTILE_COMMENT)
    html_page, markdown = render_student_report(grade, assignment=REVIEW, bank=BANK)
    page = _page(html_page)
    text = re.sub(r"\s+", " ", page.text)
    assert "Scored by a person: 1.5 / 2" in text and "(the grader proposed 1)" in text
    assert HOSTILE_COMMENT in page.text and page.tags["img"] == 0
    assert '<span class="score">4.5</span><span class="of">/ 16</span>' in html_page  # the person's score counts
    assert "**Scored by a person: 1.5 / 2**" in markdown
    assert "\\<img src=x onerror=alert(1)\\>" in markdown


def test_error_submission_says_so_without_the_internal_error():
    html_page, markdown = render_student_report(ERROR, assignment=REVIEW, bank=BANK)
    page = _page(html_page)
    assert "This submission could not be graded." in page.text
    assert "not graded" in page.text and page.tags["table"] == 0
    assert "/ 191" in page.text  # the assignment's points, since the grade has no parts
    # the exception is the instructor's to read, in the summary: a student's report does not show it
    assert "MemoryError" not in page.text and "MemoryError" not in markdown
    assert "Your instructor has the details" in page.text and "Your instructor has the details" in markdown


@pytest.mark.parametrize("hostile", HOSTILE_TEXTS)
def test_student_text_stays_text(hostile):
    grade = _with_answer(_ada(), "plane-pendulum.why-harmonic", hostile)
    grade = dataclasses.replace(grade, student=Student("s666", f"Mallory {hostile}"))
    grade = _with_manual_score(grade, "plane-pendulum.period", 0.0, hostile)
    html_page, markdown = render_student_report(grade, assignment=REVIEW, bank=BANK)
    page = _page(html_page)
    _self_contained(page)
    assert page.tags["svg"] == 0
    # as typed, never evaluated: the name (in the title and the header), the answer, the comment
    assert page.text.count(hostile) == 4
    # Markdown: the answer sits verbatim in a fence no backticks inside can close; elsewhere escaped
    assert f"\n{hostile}\n" in markdown
    outside = _markdown_outside_code(markdown)
    assert not re.search(r"(?<!\\)<[A-Za-z!/]", outside), "unescaped HTML outside code"
    assert not re.search(r"(?<!\\)\]\(", outside), "an unescaped link"


def test_student_report_of_a_real_grading():
    # Graded by the grader itself, so the MathML is the printer's own.
    answers = {
        "plane-pendulum.lagrangian": "\\frac12 m l^2 \\dot\\theta^2 + mgl\\cos\\theta",
        "plane-pendulum.motion": "θ̈ = -(g/l) θ",
        "plane-pendulum.why-harmonic": SCRIPT,
        "degrees-of-freedom.plane-pendulum": "1",
        "principles.virtual-displacement-time": "B",
    }
    grade = grade_submission(Submission(Student("s7", "Émilie du Châtelet"), answers), REVIEW, BANK)
    html_page, markdown = render_student_report(grade, assignment=REVIEW, bank=BANK)
    page = _page(html_page)
    _self_contained(page)
    assert page.tags["math"] >= 2 and SCRIPT in page.text
    assert "You used the small-angle approximation, but the full answer is asked for here." in page.text
    assert "(b)is held fixed, δt = 0your answer" in page.text  # the chosen option is marked, its LaTeX read
    assert "- **(b)** is held fixed, $\\delta t = 0$ ← your answer" in markdown


@pytest.mark.parametrize("reveal", [False, True], ids=["for_students", "revealed"])
def test_markdown_golden(golden, reveal):
    grade = _with_manual_score(_ada(), "plane-pendulum.why-harmonic", 1.5, HOSTILE_COMMENT)
    _, markdown = render_student_report(grade, assignment=REVIEW, bank=BANK, reveal=reveal)
    golden("mixed_outcomes_revealed.md" if reveal else "mixed_outcomes.md", markdown)


# -- the class summary -------------------------------------------------------------------------

# Four students, four parts. Part a: 1, 1, 0, 0 of 1; the rest of the test is 3, 1, 2, 0 (plus
# part d, 1 for everyone, which shifts but does not change it). By hand: deviations of a are
# ±1/2, of the rest 3/2, −1/2, 1/2, −3/2, so Σdx·dy = 1, Σdx² = 1, Σdy² = 5, and r = 1/√5 ≈ 0.447.
# Part c is scored by a person (2, 0, 2, 0 of 2) and uncorrelated with a + b (2, 2, 0, 0): r = 0.
# Part d: everyone right, no variance, no correlation: "—".
CLASS_SCORES = [(1, 1, 2, 1), (1, 1, 0, 1), (0, 0, 2, 1), (0, 0, 0, 1)]
WRONG_FREQUENCY = ["g / l", "g/l"]  # read alike


def _class() -> list[SubmissionGrade]:
    grades = []
    for index, (a, b, c, d) in enumerate(CLASS_SCORES):
        wrong = index >= 2
        parts = (
            _part("plane-pendulum.frequency", WRONG_FREQUENCY[index - 2] if wrong else "sqrt(g/l)",
                  "not_equivalent" if wrong else "equivalent", a, 1.0,
                  diagnosis="term_differs" if wrong else None,
                  feedback=("A term differs: a gravity term is not right.",) if wrong else ("Correct.",)),
            _part("plane-pendulum.period", "6.28" if wrong else "2.006", "not_equivalent" if wrong else "equivalent",
                  b, 1.0, diagnosis="out_of_tolerance" if wrong else None),
            _part("plane-pendulum.why-harmonic", f"answer {index}", "undecided", 1.0, 2.0, manual_score=float(c)),
            _part("plane-pendulum.small-oscillations", "l θ̈ + g θ = 0", "equivalent", d, 1.0),
        )  # fmt: skip
        grades.append(SubmissionGrade(Student(f"s{index}", f"Student {index}"), parts))
    return [*grades, ERROR]


def test_item_analysis_by_hand():
    frequency, period, harmonic, small = item_analysis(_class())
    assert frequency.key == "plane-pendulum.frequency" and frequency.count == 4  # the error is not counted
    assert frequency.mean == 0.5 and frequency.mean_share == 0.5 and frequency.full_credit == 0.5
    assert frequency.discrimination == pytest.approx(1 / math.sqrt(5))
    assert period.discrimination == pytest.approx(1 / math.sqrt(5))
    assert harmonic.mean == 1.0 and harmonic.mean_share == 0.5 and harmonic.full_credit == 0.5  # the person's scores
    assert harmonic.discrimination == pytest.approx(0.0, abs=1e-12)
    assert small.discrimination is None and small.full_credit == 1.0


def test_summary():
    html_page = render_summary(_class(), assignment=REVIEW, bank=BANK)
    page = _page(html_page)
    _self_contained(page)
    text = re.sub(r"\s+", " ", page.text)
    # counts: the totals are 5, 3, 3, 1 of 5 points: 100, 60, 60 and 20 percent
    assert "4 students graded" in text and "1 could not be graded" in text
    assert "60.0% mean score" in text and "60.0% median score" in text
    # item analysis rows: part, points, students, mean, full credit, discrimination
    rows = [re.sub(r"\s+", " ", row) for row in re.findall(r"<tr>\s*<td class=\"key\">(.*?)</tr>", html_page, re.S)]
    cells = [re.findall(r">([^<>]*)</td>", "<td>" + row) for row in rows]
    assert ["frequency", "1", "4", "50%", "50%", "0.45"] in cells
    assert ["why-harmonic", "2", "4", "50%", "50%", "0.00"] in cells
    assert ["small-oscillations", "1", "4", "100%", "100%", "—"] in cells
    # the histogram: an inline SVG with a bar per band of 10 %
    assert page.tags["svg"] == 2
    histogram = re.search(r'<svg class="chart histogram".*?</svg>', html_page, re.S)[0]
    assert histogram.count("<rect") == 10 and "<title>60–70%: 2 students</title>" in histogram
    assert score_histogram(_class()) == [0, 0, 1, 0, 0, 0, 2, 0, 0, 1]
    # the most common wrong answers, read alike and counted together
    assert "A term differs: a gravity term is not right." in text
    assert re.search(r"<code>g/l</code>.*?<td class=\"num\">2</td>", html_page, re.S)
    # each part's prompt above its wrong answers, its LaTeX read as text with scripts
    assert '<span class="tex" title="g = 9.81\\,\\mathrm{m/s^2}">g = 9.81 m/s<sup>2</sup></span>, give' in html_page
    assert "$" not in text


def test_common_wrong_answers_count_readings():
    wrong = common_wrong_answers(_class())
    assert list(wrong) == ["plane-pendulum.frequency", "plane-pendulum.period"]
    (frequency,) = wrong["plane-pendulum.frequency"]
    assert (frequency.answer, frequency.example, frequency.count) == ("g/l", "g / l", 2)
    assert frequency.diagnosis == "term_differs"
    (period,) = wrong["plane-pendulum.period"]
    assert (period.answer, period.example, period.count) == ("6.28", "6.28", 2)  # a decimal reads back as one


def test_review_queue_lists_what_waits_for_a_person():
    scored = _with_manual_score(_ada(), "plane-pendulum.why-harmonic", 1.5, "")
    grades = [_ada(), scored, ERROR]
    queue = [(student.id, part.key, part.status) for student, part in review_queue(grades)]
    assert queue == [
        ("s001", "plane-pendulum.small-oscillations", "invalid"),
        ("s001", "plane-pendulum.small-oscillations", "invalid"),
        ("s001", "plane-pendulum.why-harmonic", "undecided"),  # the scored copy is no longer waiting
        ("s001", "double-pendulum.lagrangian", "undecided"),
        ("s001", "double-pendulum.lagrangian", "undecided"),
    ]
    html_page = render_summary(grades, assignment=REVIEW, bank=BANK)
    page = _page(html_page)
    review = re.search(r"<h2>Review queue</h2>.*?</table>", html_page, re.S)[0]
    assert review.count('<span class="chip invalid">') == 2 and review.count('<span class="chip review">') == 3
    assert "1 / 2" in review  # the rubric's proposal for the text part
    _self_contained(page)
    assert SCRIPT in page.text  # the hostile answer, as text
    assert "5 answers to review" in re.sub(r"\s+", " ", page.text)
    # a part's heading quotes its prompt on one line: LaTeX as Unicode text, subscripts included
    assert "Write the Lagrangian L(θ₁, θ₂, θ̇₁, θ̇₂)." in page.text


def test_summary_lists_the_problems_in_the_submissions_no_grade_shows():
    issues = ["class.csv, row 52 (lines 69–70), student 's1049': the row has 99 cells but the header 98; row skipped"]
    text = re.sub(r"\s+", " ", _page(render_summary(_class(), assignment=REVIEW, bank=BANK, input_issues=issues)).text)
    assert "1 problem in the submissions" in text
    assert "Problems in the submissions" in text and issues[0] in text
    assert "Problems in the submissions" not in _page(render_summary(_class(), assignment=REVIEW, bank=BANK)).text


def test_summary_of_a_class_that_could_not_be_graded():
    page = _page(render_summary([ERROR], assignment=REVIEW, bank=BANK))
    text = re.sub(r"\s+", " ", page.text)
    assert "0 students graded" in text and "— mean score" in text and "Nothing is waiting for a person." in text
    assert "Grace Hopper" in text and "could not be graded: MemoryError: <too big>" in text
