"""The self-check page: what a student may see of the bank, and the HTML built from it.

Contents:
    PartView, ProblemView            the page's data: prompts, kinds, points, choices, symbols
    problem_views(bank, assignment)  the problems on the page, in the assignment's order
    render_page(views, title=)       the page, one self-contained HTML document

Prompts and choices are read by :mod:`grader.bank.markup`, as the HTML reports read them.

What a student may see is chosen field by field here (an allow-list): a Part's ``answer``,
``mistakes``, ``tests`` and ``rubric`` hold the reference and what the bank knows of wrong
answers, and none of them is ever copied into a view. The template receives only views.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from functools import lru_cache

import jinja2

from grader.bank import Assignment, Part, Problem
from grader.bank.markup import Segment, inline, paragraphs
from grader.grade.part import setting_of
from grader.judge.units import unit_of
from grader.parse import parse_answer
from grader.report import TEMPLATES

__all__ = ["MATH_KINDS", "PartView", "ProblemView", "problem_views", "render_page"]

TEMPLATE = "serve.html.j2"
# Kinds whose answers are read as mathematics and previewed as MathML; the others as text.
MATH_KINDS = frozenset({"expression", "equation", "equations", "lagrangian"})
# Notation, never a worked example: an example answer could be some part's reference.
_PLACEHOLDERS = {
    "choice": "the letter of your choice",
    "integer": "a whole number",
    "number": "a number; 3.14, 1e-3 and sqrt(2)/2 all work",
    "text": "a few sentences",
    "lagrangian": "T − V in the problem's symbols; θ̇ as thetadot",
    "equation": "left = right; θ̈ as thetaddot",
    "equations": "one equation a line, or separated by ;",
    "expression": "in the problem's symbols",
}


@dataclass(frozen=True)
class PartView:
    """What the page shows of a part: never its answer, mistakes, tests or rubric."""

    key: str  # problem.part
    id: str
    kind: str
    points: float
    prompt: tuple[tuple[Segment, ...], ...]  # paragraphs
    choices: tuple[tuple[str, tuple[Segment, ...]], ...]  # (label, text)
    multiple: bool
    placeholder: str
    derived_from: str = ""  # problem.part of the Lagrangian these equations follow from; its answer is sent along

    @property
    def math(self) -> bool:
        return self.kind in MATH_KINDS


@dataclass(frozen=True)
class ProblemView:
    id: str
    title: str
    prompt: tuple[tuple[Segment, ...], ...]
    # (name as typed, as shown, meaning, SI unit or ""): the names a student may use
    symbols: tuple[tuple[str, str, str, str], ...]
    parts: tuple[PartView, ...]


def _part_view(problem: Problem, part: Part) -> PartView:
    return PartView(
        key=f"{problem.id}.{part.id}",
        id=part.id,
        kind=part.kind,
        points=part.points,
        prompt=paragraphs(part.prompt),
        choices=tuple((str(label), inline(text)) for label, text in part.choices.items()),
        multiple=bool(part.options.get("multiple", False)),
        placeholder=_PLACEHOLDERS.get(part.kind, ""),
        derived_from=f"{problem.id}.{part.derive_from}" if part.derive_from else "",
    )


def _shown(name: str, problem: Problem) -> str:
    """A symbol as the grader prints it back (theta1 as θ₁)."""
    setting = setting_of(problem)
    read = parse_answer(name, coords=setting["coords"], known=setting["known"])
    return read.read_as_text if read.ok else name


def problem_views(bank: Mapping[str, Problem], assignment: Assignment | None = None) -> tuple[ProblemView, ...]:
    """The problems on the page: the assignment's parts in its order, or the whole bank by id."""
    if assignment is None:
        chosen = [(bank[problem_id], ()) for problem_id in sorted(bank)]
    else:
        chosen = [(bank[item.problem], item.parts) for item in assignment.items]
    views = []
    for problem, part_ids in chosen:
        names = (*problem.coordinates, *problem.parameters)
        symbols = tuple(
            (symbol.name, _shown(symbol.name, problem), symbol.meaning, unit_of(symbol.dimension)) for symbol in names
        )
        parts = tuple(_part_view(problem, p) for p in problem.parts if not part_ids or p.id in part_ids)
        views.append(ProblemView(problem.id, problem.title, paragraphs(problem.prompt), symbols, parts))
    return tuple(views)


@lru_cache(maxsize=1)
def _environment() -> jinja2.Environment:
    return jinja2.Environment(
        loader=jinja2.FileSystemLoader(TEMPLATES),
        autoescape=True,  # every value is text: prompts hold <, & and $ freely
        undefined=jinja2.StrictUndefined,
        trim_blocks=True,
        lstrip_blocks=True,
    )


def render_page(views: tuple[ProblemView, ...], *, title: str) -> str:
    """The whole page: inline CSS and script, nothing fetched from elsewhere."""
    part_count = sum(len(view.parts) for view in views)
    return _environment().get_template(TEMPLATE).render(problems=views, title=title, part_count=part_count)
