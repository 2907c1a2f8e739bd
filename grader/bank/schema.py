"""The problem format: what a problem file holds, every field's default, and its checks.

Contents:
    SCHEMA_VERSION, PART_KINDS, SEED_ID
    Problem, Part, Symbol, Mistake, RubricIdea, PartTest, Assignment, AssignmentItem
    problem_from_data(data, where)      a validated Problem from plain YAML data
    assignment_from_data(data, where)   a validated Assignment

The page for authors is docs/problem-format.md. Validation here is of the data's shape
and of what can be checked without reading mathematics (a part's kind, its options, a
``derive_from`` that names a Lagrangian part); reading the reference answers and
grading them against themselves is ``grader validate``'s work, a layer up.
"""

from __future__ import annotations

import datetime
import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

from grader.errors import AuthorError

__all__ = [
    "PART_KINDS",
    "SCHEMA_VERSION",
    "SEED_ID",
    "Assignment",
    "AssignmentItem",
    "BankError",
    "Mistake",
    "Part",
    "PartTest",
    "Problem",
    "RubricIdea",
    "Symbol",
    "assignment_from_data",
    "problem_from_data",
]

SCHEMA_VERSION = 1
# The kinds a part may have, and the options each takes (grader.judge.KINDS has the same
# answer kinds; a test keeps the two in step, since the bank may not import the checker).
PART_KINDS: dict[str, frozenset[str]] = {
    "integer": frozenset({"name"}),
    "number": frozenset({"rtol", "atol", "unit", "name", "values"}),
    "choice": frozenset({"multiple", "asks_false"}),
    "expression": frozenset({"up_to_constant", "name", "h_is_energy", "asks_more"}),
    "equation": frozenset(),
    "equations": frozenset(),
    "lagrangian": frozenset({"factor_credit", "name", "h_is_energy"}),
    "text": frozenset(),
}
# options that are true or false, checked so when the bank loads
_YES_OR_NO = frozenset({"h_is_energy", "asks_more", "asks_false"})
SEED_ID = re.compile(r"[SLAE][0-9]{1,2}")
_ID = re.compile(r"[a-z0-9][a-z0-9_-]*")
_NAME = re.compile(r"[A-Za-z][A-Za-z0-9]*(_[A-Za-z0-9]+)?")  # p_phi, Q_theta, omega_0
_DOMAINS = ("real", "positive", "negative", "nonzero", "integer")
# The dimensions a symbol may have (grader.judge.units.DIMENSIONS has the same; a test keeps them in step).
DIMENSIONS = (
    "dimensionless", "angle", "mass", "length", "time", "area", "velocity", "acceleration",
    "angular velocity", "frequency", "angular acceleration", "momentum", "angular momentum",
    "moment of inertia", "force", "torque", "energy", "power", "force per length", "mass per time", "pressure",
)  # fmt: skip
_DERIVABLE = ("equation", "equations")
_MATHEMATICS = ("expression", "equation", "equations", "lagrangian")  # the kinds whose answers are read as mathematics


class BankError(AuthorError):
    """A problem or assignment file is wrong: the message names file, line, problem, part and field."""

    def __init__(self, message: str, *, path: str = "", line: int | None = None, problem: str = "", part: str = ""):
        where = ", ".join(
            bit
            for bit in (
                f"{path}:{line}" if path and line else path,
                f"problem {problem}" if problem else "",
                f"part {part}" if part else "",
            )
            if bit
        )
        super().__init__(f"{where}: {message}" if where else message)
        self.reason, self.path, self.line, self.problem, self.part = message, path, line, problem, part


@dataclass(frozen=True)
class Symbol:
    """A coordinate or a parameter, with what it means."""

    name: str
    meaning: str = ""
    dimension: str = ""
    domain: str = "positive"  # coordinates: "real"


@dataclass(frozen=True)
class Mistake:
    """An anticipated wrong answer: its feedback and the credit it earns."""

    answer: str
    feedback: str
    score: float = 0.0


@dataclass(frozen=True)
class RubricIdea:
    """One idea a text answer must contain, with the phrasings that show it."""

    idea: str
    points: float
    phrasings: tuple[str, ...]
    about: tuple[str, ...] = ()  # the words naming what the phrasings must be said of: [scleronomic]
    not_about: tuple[str, ...] = ()  # rival terms they may be said of instead: [rheonomic]


@dataclass(frozen=True)
class PartTest:
    """An answer with the score it must get (and words its feedback must contain)."""

    answer: str
    score: float
    feedback_contains: str = ""


@dataclass(frozen=True)
class Part:
    """One graded part of a problem. See docs/problem-format.md for each field."""

    id: str
    kind: str
    points: float
    prompt: str = ""
    answer: object = None
    derive_from: str = ""
    options: Mapping[str, object] = field(default_factory=dict)
    choices: Mapping[str, str] = field(default_factory=dict)
    given: Mapping[str, str] = field(default_factory=dict)  # names an answer may use: p_theta → m R^2 thetadot
    mistakes: tuple[Mistake, ...] = ()
    rubric: tuple[RubricIdea, ...] = ()
    tests: tuple[PartTest, ...] = ()
    method_credit: float = 0.5  # derive_from parts: equations right for the student's own wrong Lagrangian


@dataclass(frozen=True)
class Problem:
    """A problem of the bank."""

    id: str
    title: str
    seed: tuple[str, ...]
    parts: tuple[Part, ...]
    prompt: str = ""
    topic: str = ""
    tags: tuple[str, ...] = ()
    coordinates: tuple[Symbol, ...] = ()
    parameters: tuple[Symbol, ...] = ()
    path: str = ""

    @property
    def points(self) -> float:
        return sum(part.points for part in self.parts)

    def part(self, part_id: str) -> Part:
        for part in self.parts:
            if part.id == part_id:
                return part
        raise KeyError(part_id)


@dataclass(frozen=True)
class AssignmentItem:
    """A problem of an assignment: which parts (all when empty) and, optionally, its weight in points."""

    problem: str
    parts: tuple[str, ...] = ()
    points: float | None = None  # None: the parts' own points


@dataclass(frozen=True)
class Assignment:
    id: str
    title: str
    items: tuple[AssignmentItem, ...]
    due: datetime.date | None = None
    path: str = ""


# -- validation ------------------------------------------------------------------------


class _Reader:
    """Reads fields out of plain data, raising BankError that say where (with line numbers)."""

    def __init__(self, path: str, lines: Mapping[tuple, int], problem: str = "", part: str = ""):
        self.path, self.lines, self.problem, self.part = path, lines, problem, part

    def fail(self, location: tuple, message: str):
        line = None
        for end in range(len(location), -1, -1):  # the nearest enclosing node that has a line
            line = self.lines.get(location[:end])
            if line:
                break
        raise BankError(message, path=self.path, line=line, problem=self.problem, part=self.part)

    def mapping(self, value, location: tuple, allowed: set[str], name: str) -> dict:
        if not isinstance(value, dict):
            self.fail(location, f"{name} must be a mapping of fields, not {type(value).__name__}")
        unknown = sorted(set(value) - allowed)
        if unknown:
            self.fail(
                (*location, unknown[0]),
                f"unknown field {unknown[0]!r} in {name}; allowed: {', '.join(sorted(allowed))}",
            )
        return value

    def get(
        self,
        data: dict,
        location: tuple,
        key: str,
        kind: type | tuple,
        default=...,
        check: Callable | None = None,
        what: str = "",
    ):
        if key not in data:
            if default is ...:
                self.fail(location, f"missing field {key!r}" + (f" ({what})" if what else ""))
            return default
        value = data[key]
        if (isinstance(kind, tuple) and bool in kind) or kind is bool:
            ok = isinstance(value, kind)
        else:
            ok = isinstance(value, kind) and not isinstance(value, bool)
        if not ok:
            names = " or ".join(k.__name__ for k in (kind if isinstance(kind, tuple) else (kind,)))
            self.fail((*location, key), f"field {key!r} must be {names}, not {type(value).__name__}: {value!r}")
        if check is not None and not check(value):
            self.fail((*location, key), f"field {key!r} is {value!r}; {what}")
        return value

    def entries(self, data: dict, location: tuple, key: str, allowed: set[str], name: str, default=...):
        """Each mapping in the list field ``key``, with where it stands: (location, fields)."""
        for index, raw in enumerate(self.get(data, location, key, list, default)):
            here = (*location, key, index)
            yield here, self.mapping(raw, here, allowed, name)


def problem_from_data(data, *, path: str = "", lines: Mapping[tuple, int] | None = None) -> Problem:
    """A validated :class:`Problem` from plain data (as read from YAML).

    Raises:
        BankError: naming the file, line, problem, part and field, what is wrong and what is allowed.
    """
    reader = _Reader(path, lines or {})
    top = reader.mapping(
        data, (), {"schema_version", "id", "title", "seed", "topic", "tags", "symbols", "prompt", "parts"}, "a problem"
    )
    version = reader.get(top, (), "schema_version", int, what=f"this grader reads schema_version {SCHEMA_VERSION}")
    if version != SCHEMA_VERSION:
        reader.fail(("schema_version",), f"schema_version is {version}; this grader reads {SCHEMA_VERSION}")
    problem_id = reader.get(top, (), "id", str, check=_ID.fullmatch, what="use lower-case letters, digits, - and _")
    reader.problem = problem_id
    seed = reader.get(top, (), "seed", list, what="the seed item ids it covers, e.g. [S10, L16]")
    if not seed:
        reader.fail(("seed",), "seed is empty; list the seed items this problem covers, e.g. [S10, L16]")
    for index, item in enumerate(seed):
        if not isinstance(item, str) or not SEED_ID.fullmatch(item):
            reader.fail(("seed", index), f"seed item {item!r} is not an id such as S1, L16, A3 or E5")
    coordinates, parameters = _symbols(reader, top.get("symbols", {}))
    raw_parts = reader.get(top, (), "parts", list, what="a list of parts")
    if not raw_parts:
        reader.fail(("parts",), "a problem needs at least one part")
    parts = []
    for index, raw in enumerate(raw_parts):
        parts.append(_part(reader, raw, ("parts", index), {p.id for p in parts}))
    reader.part = ""
    by_id = {part.id: part for part in parts}
    for index, part in enumerate(parts):
        if part.derive_from:
            source = by_id.get(part.derive_from)
            if source is None or source.kind != "lagrangian":
                reader.part = part.id
                reader.fail(
                    ("parts", index, "derive_from"),
                    f"derive_from is {part.derive_from!r}; it must name a lagrangian part of this problem"
                    f" ({', '.join(p.id for p in parts if p.kind == 'lagrangian') or 'there is none'})",
                )
    return Problem(
        id=problem_id,
        title=reader.get(top, (), "title", str),
        seed=tuple(seed),
        parts=tuple(parts),
        prompt=reader.get(top, (), "prompt", str, ""),
        topic=reader.get(top, (), "topic", str, ""),
        tags=tuple(reader.get(top, (), "tags", list, [])),
        coordinates=coordinates,
        parameters=parameters,
        path=path,
    )


def _symbols(reader: _Reader, raw) -> tuple[tuple[Symbol, ...], tuple[Symbol, ...]]:
    symbols = reader.mapping(raw, ("symbols",), {"coordinates", "parameters"}, "symbols")
    result = []
    for group, default in (("coordinates", "real"), ("parameters", "positive")):
        entries = reader.get(symbols, ("symbols",), group, dict, {})
        found = []
        for name, spec in entries.items():
            location = ("symbols", group, name)
            spec = reader.mapping(spec if spec is not None else {}, location, {"meaning", "dimension", "domain"}, name)
            domain = reader.get(spec, location, "domain", str, default, check=_DOMAINS.__contains__,
                                what=f"allowed: {', '.join(_DOMAINS)}")  # fmt: skip
            dimension = reader.get(spec, location, "dimension", str, "", check=("", *DIMENSIONS).__contains__,
                                   what=f"allowed: {', '.join(DIMENSIONS)}")  # fmt: skip
            found.append(Symbol(str(name), reader.get(spec, location, "meaning", str, ""), dimension, domain))
        result.append(tuple(found))
    return result[0], result[1]


_PART_FIELDS = {
    "id",
    "prompt",
    "kind",
    "points",
    "answer",
    "derive_from",
    "options",
    "choices",
    "given",
    "mistakes",
    "rubric",
    "tests",
    "method_credit",
}


def _part(reader: _Reader, raw, location: tuple, taken: set[str]) -> Part:
    reader.part = raw.get("id", "") if isinstance(raw, dict) and isinstance(raw.get("id"), str) else ""
    data = reader.mapping(raw, location, _PART_FIELDS, "a part")
    part_id = reader.get(data, location, "id", str, check=_ID.fullmatch, what="use lower-case letters, digits, - and _")
    reader.part = part_id
    if part_id in taken:
        reader.fail((*location, "id"), f"part id {part_id!r} is used twice in this problem")
    kind = reader.get(
        data, location, "kind", str, check=PART_KINDS.__contains__, what=f"allowed: {', '.join(PART_KINDS)}"
    )
    points = reader.get(
        data, location, "points", (int, float), check=lambda p: p > 0, what="points must be more than 0"
    )
    options = reader.get(data, location, "options", dict, {})
    for key in options:
        if key not in PART_KINDS[kind]:
            allowed = ", ".join(sorted(PART_KINDS[kind])) or "none"
            reader.fail(
                (*location, "options", key), f"option {key!r} does not apply to kind {kind!r} (its options: {allowed})"
            )
    for key in sorted(_YES_OR_NO & options.keys()):
        if not isinstance(options[key], bool):
            reader.fail((*location, "options", key), f"{key} is true or false, not {options[key]!r}")
    name = options.get("name")
    if name is not None and not _names(name):
        reader.fail(
            (*location, "options", "name"), "name is the quantity's name, or a list of names, as p_phi or [V, U]"
        )
    derive_from = reader.get(data, location, "derive_from", str, "")
    if derive_from and kind not in _DERIVABLE:
        reader.fail(
            (*location, "derive_from"), f"derive_from applies to kinds {' and '.join(_DERIVABLE)}, not {kind!r}"
        )
    answer = data.get("answer")
    if answer is None and not derive_from and kind != "text":
        reader.fail(location, "missing field 'answer' (the reference answer; or derive_from a lagrangian part)")
    if answer is not None and not isinstance(answer, str | int | float | list):
        reader.fail((*location, "answer"), f"answer must be text, a number or a list, not {type(answer).__name__}")
    choices = reader.get(data, location, "choices", dict, {})
    if kind == "choice":
        if not choices:
            reader.fail(location, "a choice part needs 'choices': a mapping of label to option text")
        labels = [answer] if isinstance(answer, str) else answer
        for label in labels or ():
            if str(label) not in {str(key) for key in choices}:
                reader.fail(
                    (*location, "answer"),
                    f"answer {label!r} is not one of the choices ({', '.join(map(str, choices))})",
                )
    given = reader.get(data, location, "given", dict, {})
    if given and kind not in _MATHEMATICS:
        reader.fail((*location, "given"), f"given applies to kinds {', '.join(_MATHEMATICS)}, not {kind!r}")
    for name, value in given.items():
        if not (isinstance(name, str) and isinstance(value, str | int | float)):
            reader.fail((*location, "given", str(name)), "given maps a name to its value, as p_theta: m R^2 thetadot")
    rubric = tuple(_rubric(reader, data, location)) if kind == "text" else ()
    if kind == "text" and not rubric:
        reader.fail(
            location, "a text part needs a 'rubric': the ideas an answer must contain, with points and phrasings"
        )
    if "rubric" in data and kind != "text":
        reader.fail((*location, "rubric"), f"rubric applies to text parts, not {kind!r}")
    return Part(
        id=part_id, kind=kind, points=float(points), prompt=reader.get(data, location, "prompt", str, ""),
        answer=answer, derive_from=derive_from, options=options, choices={str(k): str(v) for k, v in choices.items()},
        given={name: str(value) for name, value in given.items()},
        mistakes=tuple(_mistakes(reader, data, location)), rubric=rubric, tests=tuple(_tests(reader, data, location)),
        method_credit=float(reader.get(data, location, "method_credit", (int, float), 0.5, check=_score,
                                       what="a share of the points, from 0 to 1")),
    )  # fmt: skip


def _names(value) -> bool:
    """Whether ``value`` is a name or a non-empty list of names (the option ``name``)."""
    names = [value] if isinstance(value, str) else value
    return isinstance(names, list) and bool(names) and all(isinstance(n, str) and _NAME.fullmatch(n) for n in names)


def _score(value) -> bool:
    return 0 <= value <= 1


def _mistakes(reader: _Reader, data: dict, location: tuple):
    for here, item in reader.entries(data, location, "mistakes", {"answer", "feedback", "score"}, "a mistake", []):
        yield Mistake(
            answer=str(reader.get(item, here, "answer", (str, int, float))),
            feedback=reader.get(item, here, "feedback", str, what="what the student is told"),
            score=float(reader.get(item, here, "score", (int, float), 0, check=_score, what="a score is from 0 to 1")),
        )


_RUBRIC_FIELDS = {"idea", "points", "phrasings", "about", "not_about"}
_GAP = re.compile(r"…|\.\.\.")  # in a phrasing, any words of the same clause (grader.judge.text)


def _rubric(reader: _Reader, data: dict, location: tuple):
    for here, item in reader.entries(data, location, "rubric", _RUBRIC_FIELDS, "a rubric idea", []):
        phrasings = reader.get(item, here, "phrasings", list, what="the words that show the idea")
        if not phrasings or not all(isinstance(p, str) and p.strip() for p in phrasings):
            reader.fail((*here, "phrasings"), "phrasings must be a non-empty list of words or phrases")
        for index, phrasing in enumerate(phrasings):
            if not all(piece.strip() for piece in _GAP.split(phrasing)):
                reader.fail(
                    (*here, "phrasings", index),
                    f"phrasing {phrasing!r} has a … with no words on one side; … stands for words between two others",
                )
        about, not_about = (_terms(reader, item, here, key) for key in ("about", "not_about"))
        if not_about and not about:
            reader.fail(
                (*here, "not_about"), "not_about needs 'about': the words naming what this idea's phrasings describe"
            )
        both = sorted({term.casefold() for term in about} & {term.casefold() for term in not_about})
        if both:
            reader.fail(
                (*here, "not_about"),
                f"{both[0]!r} is in both about and not_about: a term is the idea's own subject or a rival, not both",
            )
        yield RubricIdea(
            idea=reader.get(item, here, "idea", str),
            points=float(reader.get(item, here, "points", (int, float), check=lambda p: p > 0, what="more than 0")),
            phrasings=tuple(phrasings),
            about=about,
            not_about=not_about,
        )


def _terms(reader: _Reader, item: dict, here: tuple, key: str) -> tuple[str, ...]:
    terms = reader.get(item, here, key, list, [])
    if not all(isinstance(term, str) and term.strip() and not _GAP.search(term) for term in terms):
        reader.fail((*here, key), f"{key} must be a list of words or phrases, as [scleronomic] or [rheonomic]")
    return tuple(terms)


def _tests(reader: _Reader, data: dict, location: tuple):
    for here, item in reader.entries(data, location, "tests", {"answer", "score", "feedback_contains"}, "a test", []):
        yield PartTest(
            answer=str(reader.get(item, here, "answer", (str, int, float))),
            score=float(reader.get(item, here, "score", (int, float), check=_score, what="a score is from 0 to 1")),
            feedback_contains=reader.get(item, here, "feedback_contains", str, ""),
        )


def assignment_from_data(data, *, path: str = "", lines: Mapping[tuple, int] | None = None) -> Assignment:
    """A validated :class:`Assignment`; problem ids are checked against the bank by the loader."""
    reader = _Reader(path, lines or {})
    top = reader.mapping(data, (), {"schema_version", "id", "title", "due", "problems"}, "an assignment")
    if reader.get(top, (), "schema_version", int) != SCHEMA_VERSION:
        reader.fail(("schema_version",), f"schema_version must be {SCHEMA_VERSION}")
    due = top.get("due")
    if due is not None and not isinstance(due, datetime.date):
        reader.fail(("due",), f"due must be a date such as 2026-12-01, not {due!r}")
    items = []
    for here, entry in reader.entries(top, (), "problems", {"problem", "parts", "points"}, "an assignment item"):
        points = reader.get(entry, here, "points", (int, float), None, check=lambda p: p > 0, what="more than 0")
        problem = reader.get(entry, here, "problem", str)
        parts = tuple(reader.get(entry, here, "parts", list, []))
        items.append(AssignmentItem(problem, parts, None if points is None else float(points)))
    return Assignment(
        id=reader.get(top, (), "id", str, check=_ID.fullmatch, what="use lower-case letters, digits, - and _"),
        title=reader.get(top, (), "title", str),
        items=tuple(items),
        due=due,
        path=path,
    )
