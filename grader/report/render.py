"""Reports as text: one student's (HTML and Markdown), and the class summary (HTML).

Contents:
    render_student_report(grade, assignment=, bank=, reveal=)   (HTML, Markdown) for one student
    render_summary(grades, assignment=, bank=, input_issues=)   HTML for the instructor
    TEMPLATES                                                   where the Jinja templates live
    STATUS_LABELS                                               how each part status is shown

Nothing here writes files or prints: the caller decides where reports go.

Escaping: everything a student typed is text, never markup. HTML templates autoescape; the
only values marked safe are the MathML strings our own printer produced (``_mathml``).
Markdown has no autoescape in Jinja, so the Markdown environment escapes every value through
``finalize`` unless a filter has already made it safe (a code span or block, or bank text).
Pages are self-contained: inline CSS and SVG, no JavaScript, no fonts or links to fetch.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import jinja2
from markupsafe import Markup

from grader.bank import Assignment, Part, Problem
from grader.bank.markup import Segment, inline, paragraphs, plain_text
from grader.grade.batch import assignment_parts
from grader.grade.part import expected_answer, setting_of
from grader.grade.results import PartGrade, SubmissionGrade
from grader.parse import parse_answer
from grader.report.analysis import (
    ItemStats,
    class_counts,
    common_wrong_answers,
    item_analysis,
    review_queue,
    score_histogram,
)
from grader.report.charts import histogram_chart, share_chart

__all__ = ["STATUS_LABELS", "TEMPLATES", "StatusLabel", "render_student_report", "render_summary"]


def _templates() -> Path:
    """The templates: the repository's ``templates/`` in a checkout (or an editable install),
    the package's ``templates`` folder where a wheel put them."""
    checkout = Path(__file__).resolve().parents[2] / "templates"
    return checkout if checkout.is_dir() else Path(__file__).resolve().parents[1] / "templates"


TEMPLATES = _templates()
MATH_KINDS = ("expression", "equation", "equations", "lagrangian")
LOW_DISCRIMINATION = 0.2  # a common rule of thumb: below it, a part barely separates strong from weak


@dataclass(frozen=True)
class StatusLabel:
    """How a part's status is shown: a symbol, words, and a CSS class."""

    symbol: str
    words: str
    css: str

    def __str__(self) -> str:
        return f"{self.symbol} {self.words}"


STATUS_LABELS = {
    "equivalent": StatusLabel("✔", "right", "right"),
    "not_equivalent": StatusLabel("✘", "not right", "wrong"),
    "undecided": StatusLabel("?", "set aside for a person", "review"),
    "invalid": StatusLabel("⚠", "invalid: the answer could not be read", "invalid"),
    "blank": StatusLabel("–", "blank", "blank"),
}


# -- the student's report -------------------------------------------------------------


@dataclass(frozen=True)
class _PartView:
    grade: PartGrade
    prompt: tuple[tuple[Segment, ...], ...]  # paragraphs
    prompt_text: str  # as written, for Markdown
    choices: tuple[tuple[str, str], ...]  # (label, text as written)
    label: StatusLabel
    mathml: Markup | None
    reference: str | None
    reference_mathml: Markup | None

    @property
    def provisional(self) -> bool:
        """The points are the grader's proposal until a person confirms them."""
        return self.grade.needs_review

    @property
    def chosen(self) -> frozenset[str]:
        """The choice labels the student gave, as the choices spell them."""
        given = {label.casefold() for label in re.split(r"[\s,;]+", self.grade.answer) if label}
        return frozenset(label for label, _ in self.choices if label.casefold() in given)

    @property
    def shown_choices(self) -> tuple[tuple[str, tuple[Segment, ...]], ...]:
        return tuple((label, inline(text)) for label, text in self.choices)

    @property
    def reference_paragraphs(self) -> tuple[tuple[Segment, ...], ...]:
        return paragraphs(self.reference or "")


@dataclass(frozen=True)
class _ProblemView:
    id: str
    title: str
    prompt: tuple[tuple[Segment, ...], ...]  # paragraphs
    prompt_text: str  # as written, for Markdown
    parts: tuple[_PartView, ...]


def _mathml(text: str) -> Markup | None:
    # Safe by construction: grader.parse's printer builds this from a parsed expression
    # (names, numbers, operators it knows), never by pasting the student's characters.
    return Markup(text) if text else None


def _lookup(bank: dict[str, Problem], grade: PartGrade) -> tuple[Problem | None, Part | None]:
    """The bank's problem and part for a grade; None for one the bank no longer has."""
    problem = bank.get(grade.problem)
    if problem is None:
        return None, None
    try:
        return problem, problem.part(grade.part)
    except KeyError:
        return problem, None


def _reference(problem: Problem, part: Part) -> tuple[str, Markup | None]:
    """The reference answer as text, and as MathML when it is mathematics."""
    expected = expected_answer(problem, part)
    if part.kind == "choice":
        labels = [label.strip() for label in expected.split(",")]
        shown = [f"{label}: {part.choices[label]}" if label in part.choices else label for label in labels]
        return "; ".join(shown), None
    if part.kind not in (*MATH_KINDS, "number"):
        return expected, None
    setting = setting_of(problem)
    read = parse_answer(expected, coords=setting["coords"], known=setting["known"])
    if not read.ok:
        return expected, None
    if part.kind == "number":
        # 2*pi*sqrt(1/9.81) is clearer as typed, with its value, than as an exact fraction of surds
        try:
            return f"{expected} ≈ {float(read.value):.4g}", None
        except (TypeError, ValueError):  # not a plain number after all
            return expected, None
    return expected, _mathml(read.read_as_mathml)


def _part_view(bank: dict[str, Problem], grade: PartGrade, reveal: bool) -> _PartView:
    problem, part = _lookup(bank, grade)
    reference, reference_mathml = _reference(problem, part) if reveal and part is not None else (None, None)
    return _PartView(
        grade=grade,
        prompt=paragraphs(part.prompt) if part is not None else (),
        prompt_text=part.prompt.strip() if part is not None else "",
        choices=tuple(part.choices.items()) if part is not None else (),
        label=STATUS_LABELS[grade.status],
        mathml=_mathml(grade.read_as_mathml),
        reference=reference,
        reference_mathml=reference_mathml,
    )


def _problem_views(grade: SubmissionGrade, bank: dict[str, Problem], reveal: bool) -> list[_ProblemView]:
    """The parts grouped by problem, in the order they were graded."""
    groups: dict[str, list[_PartView]] = {}
    for part in grade.parts:
        groups.setdefault(part.problem, []).append(_part_view(bank, part, reveal))
    views = []
    for problem_id, parts in groups.items():
        problem = bank.get(problem_id)
        title, prompt = (problem.title, problem.prompt) if problem else (problem_id, "")
        views.append(_ProblemView(problem_id, title, paragraphs(prompt), prompt.strip(), tuple(parts)))
    return views


def _assignment_points(assignment: Assignment, bank: dict[str, Problem]) -> float:
    return sum(points for _, _, points in assignment_parts(assignment, bank))


def render_student_report(
    grade: SubmissionGrade, *, assignment: Assignment, bank: dict[str, Problem], reveal: bool = False
) -> tuple[str, str]:
    """One student's report, as (HTML, Markdown).

    Args:
        grade: the student's grades; one with status ``error`` renders its message.
        assignment, bank: what was set, for titles, prompts and (with ``reveal``) references.
        reveal: show the reference answers. Off by default: reports often go out before
            the deadline for late work has passed.

    Returns:
        A self-contained HTML page and the same report in Markdown.
    """
    context = {
        "assignment": assignment,
        "grade": grade,
        "student": grade.student,
        "max_score": grade.max_score if grade.parts else _assignment_points(assignment, bank),
        "problems": _problem_views(grade, bank, reveal),
        "labels": STATUS_LABELS,
        "reveal": reveal,
    }
    html_page = _environments()[0].get_template("student.html.j2").render(context)
    markdown = _environments()[1].get_template("student.md.j2").render(context)
    return html_page, markdown


# -- the class summary ----------------------------------------------------------------


def render_summary(
    grades: Sequence[SubmissionGrade],
    *,
    assignment: Assignment,
    bank: dict[str, Problem],
    input_issues: Sequence[str] = (),
) -> str:
    """The instructor's summary of a class, as a self-contained HTML page.

    Counts, a histogram of percent scores, each part's mean, an item analysis, the most
    common wrong answers per part, the queue of answers waiting for a person, and what was wrong
    in the submissions (``input_issues``: rows skipped, columns unknown), which no grade shows.
    """
    items = item_analysis(grades)
    by_problem: dict[str, list[ItemStats]] = {}
    for item in items:
        by_problem.setdefault(item.problem, []).append(item)
    titles = {problem_id: bank[problem_id].title if problem_id in bank else problem_id for problem_id in by_problem}
    prompts = {}  # part key → the prompt's paragraphs
    for grade in grades:
        for part in grade.parts:
            if part.key not in prompts:
                _, found = _lookup(bank, part)
                prompts[part.key] = paragraphs(found.prompt) if found is not None else ()
    # in a table's heading, on one line without markup
    prompt_lines = {key: " ".join(plain_text(paragraph) for paragraph in shown) for key, shown in prompts.items()}
    means = [(titles[problem], [(item.part, item.mean_share) for item in rows]) for problem, rows in by_problem.items()]
    context = {
        "assignment": assignment,
        "max_score": _assignment_points(assignment, bank),
        "counts": class_counts(grades),
        "histogram": histogram_chart(score_histogram(grades)),
        "means": share_chart(means),
        "items": items,
        "items_by_problem": by_problem,
        "titles": titles,
        "low_discrimination": LOW_DISCRIMINATION,
        "wrong_answers": common_wrong_answers(grades),
        "prompts": prompts,
        "prompt_lines": prompt_lines,
        "review": review_queue(grades),
        "errors": [grade for grade in grades if grade.status == "error"],
        "input_issues": list(input_issues),
        "labels": STATUS_LABELS,
    }
    return _environments()[0].get_template("summary.html.j2").render(context)


# -- templates and their filters ----------------------------------------------------------


def _points(value: float) -> str:
    """Points as people write them: 3, 2.5, 0.67.

    >>> _points(3.0), _points(2.5), _points(2 / 3), _points(-0.0)
    ('3', '2.5', '0.67', '0')
    """
    return f"{round(value, 2) + 0.0:g}"


def _percent(value: float | None, digits: int = 1) -> str:
    """A percent (given as 0–100), or a dash for none.

    >>> _percent(78.7654), _percent(None)
    ('78.8%', '—')
    """
    return "—" if value is None else f"{value:.{digits}f}%"


def _share(value: float | None) -> str:
    """A share (0–1) as a percent."""
    return "—" if value is None else f"{100 * value:.0f}%"


def _correlation(value: float | None) -> str:
    """A correlation to two places, with a true minus sign, or a dash when undefined.

    >>> _correlation(0.4472), _correlation(-0.1), _correlation(None)
    ('0.45', '−0.10', '—')
    """
    return "—" if value is None else f"{value:.2f}".replace("-", "−")


class _MarkdownText(str):
    """Text already safe to place in Markdown."""


# ASCII punctuation with a meaning in CommonMark, wherever it appears; a backslash makes it literal.
_MARKDOWN_INLINE = re.compile(r"([\\`*_\[\]<>|&~])")
# ... and what starts a heading, list, quote, rule or setext underline at the beginning of a line.
_MARKDOWN_LINE_START = re.compile(r"^([ \t]*)([#+\-=>]|\d+(?=[.)]))", re.MULTILINE)


def _markdown_escape(text: str) -> str:
    r"""Text that a Markdown renderer shows as itself, never as markup or HTML.

    >>> print(_markdown_escape("<script>alert(1)</script> *x* {{ 7*7 }}"))
    \<script\>alert(1)\</script\> \*x\* {{ 7\*7 }}
    >>> print(_markdown_escape("# heading"), _markdown_escape("1. item"))
    \# heading 1\. item
    >>> print(repr(_markdown_escape("a\r# heading")))  # CommonMark ends a line at a bare CR too
    'a\n\\# heading'
    """
    text = text.replace("\r\n", "\n").replace("\r", "\n")
    text = _MARKDOWN_INLINE.sub(r"\\\1", text)

    def escape(match: re.Match) -> str:
        marker = match[2]  # a digit cannot be escaped: escape the . or ) after it instead
        return f"{match[1]}{marker}\\" if marker[0].isdigit() else f"{match[1]}\\{marker}"

    return _MARKDOWN_LINE_START.sub(escape, text)


def _markdown_value(value) -> str:
    """Jinja's ``finalize`` for Markdown: every value escaped unless a filter made it safe."""
    if isinstance(value, _MarkdownText):
        return value
    if isinstance(value, int | float) and not isinstance(value, bool):
        return str(value)
    return _markdown_escape(str(value))  # str() of StrictUndefined raises, as it should


def _code_block(text: str, language: str = "text") -> _MarkdownText:
    r"""A fenced code block holding ``text`` verbatim: its fence is longer than any run of backticks inside.

    >>> print(_code_block("a ``` b"))
    ````text
    a ``` b
    ````
    """
    longest = max((len(run) for run in re.findall(r"`+", text)), default=0)
    fence = "`" * max(3, longest + 1)
    return _MarkdownText(f"{fence}{language}\n{text}\n{fence}")


def _code_span(text: str) -> _MarkdownText:
    """An inline code span holding ``text`` (on one line) verbatim.

    >>> print(_code_span("a`b"), _code_span("x"))
    `` a`b `` `x`
    """
    text = " ".join(text.split())
    longest = max((len(run) for run in re.findall(r"`+", text)), default=0)
    ticks = "`" * (longest + 1)
    padded = f" {text} " if longest or text.startswith("`") or text.endswith("`") else text
    return _MarkdownText(f"{ticks}{padded}{ticks}")


def _bank_text(text: str) -> _MarkdownText:
    """Text from the problem bank, written by its authors in Markdown and LaTeX: kept as it is."""
    return _MarkdownText(text)


def _safe_markdown(function):
    return lambda *arguments: _MarkdownText(function(*arguments))


_FILTERS = {"points": _points, "percent": _percent, "share": _share, "correlation": _correlation}


@lru_cache(maxsize=1)
def _environments() -> tuple[jinja2.Environment, jinja2.Environment]:
    """(HTML, Markdown) template environments over TEMPLATES."""
    common = {
        "loader": jinja2.FileSystemLoader(TEMPLATES),
        "undefined": jinja2.StrictUndefined,
        "trim_blocks": True,
        "lstrip_blocks": True,
        "keep_trailing_newline": True,
    }
    html_env = jinja2.Environment(
        autoescape=jinja2.select_autoescape(("html", "html.j2", "css.j2"), default_for_string=True, default=True),
        **common,
    )
    markdown_env = jinja2.Environment(autoescape=False, finalize=_markdown_value, **common)
    html_env.filters.update(_FILTERS)
    # Numbers as we format them hold no markup; marked safe, 73.9% is not escaped as if it began a list.
    markdown_env.filters.update({name: _safe_markdown(number) for name, number in _FILTERS.items()})
    markdown_env.filters.update(code_block=_code_block, code_span=_code_span, bank_text=_bank_text)
    return html_env, markdown_env
