"""``compare``: one answer against the expected one, for any kind, as a Verdict.

Contents:
    Kind               a kind of answer: its checker, its options and their defaults
    KINDS              the closed registry, kind name → Kind
    compare(...)       the public entry point

``compare`` owns what every kind shares: reading the submitted answer, refusing
symbols the problem does not define, the time limit, and turning whatever goes
wrong on a student's input into "undecided" rather than an exception. The kind
checkers only compare.
"""

from __future__ import annotations

import math
import re
import time
from collections.abc import Callable, Collection, Iterable, Iterator, Mapping
from dataclasses import dataclass, field, replace
from fractions import Fraction
from functools import partial

import sympy
from sympy.core.function import AppliedUndef

from grader.errors import AuthorError
from grader.judge.chains import (
    ONE_NAME,
    answer_lines,
    chain_sides,
    lines_as_chain,
    partials_read,
    without_dashes,
)
from grader.judge.choice import check_choice
from grader.judge.deadline import CheckTimeout, time_limit
from grader.judge.diagnose import TERM_KEYS, in_sentence
from grader.judge.euler_lagrange import dissipative, euler_lagrange, force_agrees, from_a_lagrangian
from grader.judge.expected import Expected, Outcome, prepare
from grader.judge.expression import check_expression, same_values
from grader.judge.feedback import say, shown
from grader.judge.given import given_values, in_given_names
from grader.judge.lagrangian import check_lagrangian
from grader.judge.lagrangian import euler_lagrange as lagrange_equations
from grader.judge.motion import accelerations_in, check_equation, check_equations
from grader.judge.numbers import COUNT_NAME, read_number
from grader.judge.numeric import NotCompilable
from grader.judge.rounded import exact_readings
from grader.judge.sampling import GROUP, all_equal, constant_difference, evaluate_pairs
from grader.judge.scalar import check_integer, check_number
from grader.judge.text import check_text
from grader.judge.units import (
    DIMENSIONS,
    QUANTITY_WORDS,
    SI_UNITS,
    Mixed,
    cycles_to,
    in_units,
    si,
    unit_counts,
    unit_named,
    units_mistake,
    units_of,
)
from grader.judge.verdict import Verdict
from grader.judge.words import (
    definition_before_formula,
    definition_then_formula,
    euler_lagrange_then_formula,
    formula_then_approximation,
    formula_then_convention,
    formula_then_small_angle_form,
    formula_then_words,
    quantities_named,
    says_otherwise,
    tex_math_as_words,
    text_as_words,
    words_in,
    words_then_formula,
)
from grader.parse import (
    ANSWER,
    LIMITS,
    TIME,
    ParsedAnswer,
    Refusal,
    own_rates,
    parse_answer,
    too_many_digits,
    within_diff_budget,
)
from grader.parse.messages import listed
from grader.parse.names import canonical_name, is_arbitrary_constant, split_derivative, split_quotient, unicode_name
from grader.parse.readback import to_text

__all__ = ["DEFAULT_TIMEOUT", "KINDS", "READINGS_FOR_A_PERSON", "ROUNDED", "Kind", "compare"]

DEFAULT_TIMEOUT = 2.0


@dataclass(frozen=True)
class Kind:
    """A kind of answer.

    Attributes:
        name: as problem files and ``compare(kind=...)`` spell it.
        check: the checker, ``(expected, submitted answer, deadline) -> Outcome``.
        options: the options it accepts, with their defaults.
        parsed: whether answers of this kind are mathematics read by ``parse_answer``.
        shape: what the parsed answer must be (``expression``, ``equation``, ``equations``), if anything.
    """

    name: str
    check: Callable
    options: Mapping[str, object] = field(default_factory=dict)
    parsed: bool = True
    shape: str | None = None


KINDS: dict[str, Kind] = {
    kind.name: kind
    for kind in (
        Kind(
            "expression",
            check_expression,
            {"up_to_constant": False, "name": None, "h_is_energy": True, "asks_more": False},
            shape="expression",
        ),
        Kind("equation", check_equation, shape="equation"),
        Kind("equations", check_equations, shape="equations"),
        Kind(
            "lagrangian", check_lagrangian, {"factor_credit": 0.5, "name": "L", "h_is_energy": True}, shape="expression"
        ),
        Kind("integer", check_integer, {"name": None}, shape="expression"),
        Kind(
            "number",
            check_number,
            {"rtol": 1e-6, "atol": 0.0, "unit": None, "name": None, "values": None},
            shape="expression",
        ),
        Kind(
            "choice",
            check_choice,
            {"options": (), "multiple": False, "meanings": (), "asks_false": False},
            parsed=False,
        ),
        Kind("text", check_text, {"rubric": ()}, parsed=False),
    )
}

# Whatever sympy or our arithmetic raises on a strange but well-formed answer is a
# verdict nobody can trust: it goes to a person, never to the student as "wrong".
_CHECK_FAILURES = (ArithmeticError, ValueError, TypeError, RecursionError, NotCompilable, MemoryError)


def compare(
    expected: str, submitted: str, *, kind: str = "expression", coords: Iterable[str] = (), **options
) -> Verdict:
    """Compare a submitted answer with the expected one.

    Args:
        expected: the reference answer, written by the problem's author.
        submitted: the student's answer, untrusted.
        kind: ``expression``, ``equation``, ``equations``, ``lagrangian``, ``integer``,
            ``number``, ``choice`` or ``text`` (always ``undecided``: a rubric proposes a score).
        coords: the generalized coordinates, functions of time.
        **options: ``known`` (more symbols the problem defines), ``domains``
            (``{"x": "real"}``; by default coordinates are real and other symbols
            positive), ``dimensions`` (``{"l": "length", "g": "acceleration"}``: a wrong
            answer's units are then checked), ``given`` (names an answer may use for a quantity of the problem,
            ``{"p_theta": "m R^2 thetadot"}``: put in place before judging), ``timeout``
            (seconds, default 2), and the kind's own options (``up_to_constant``, ``h_is_energy``, ``asks_more``,
            ``rtol``/``atol``/``unit``/``name`` for numbers, ``options`` for choices: labels, or (label, words) pairs,
            and ``meanings``, the problem's symbols with what they mean…).

    Returns:
        A :class:`Verdict`. Nothing a student types makes this raise or hang.

    Raises:
        AuthorError: an unknown kind or option, a timeout that is no positive number of seconds,
            or an expected answer that cannot be read.

    >>> compare("-(g/l) sin(theta)", "-g sin θ / l", coords=["theta"]).status
    'equivalent'
    """
    if kind not in KINDS:
        raise AuthorError(f"unknown answer kind {kind!r}; the kinds are: {', '.join(KINDS)}")
    spec = KINDS[kind]
    known = tuple(options.pop("known", ()))
    domains = tuple(sorted((options.pop("domains", None) or {}).items()))
    dimensions = tuple(sorted((options.pop("dimensions", None) or {}).items()))
    given = options.pop("given", None) or {}
    timeout = float(options.pop("timeout", DEFAULT_TIMEOUT))
    if not 0 < timeout < math.inf:
        raise AuthorError(f"timeout must be a positive number of seconds, not {timeout:g}")
    unknown = set(options) - set(spec.options)
    if unknown:
        allowed = ", ".join(sorted(spec.options)) or "none"
        raise AuthorError(
            f"option {', '.join(sorted(unknown))} does not apply to kind {kind!r} (its options: {allowed})"
        )
    settings = {**spec.options, **options}
    if settings.get("name") is not None:
        settings["name"] = _names(settings["name"])
    frozen = tuple(sorted((key, _hashable(value)) for key, value in settings.items()))
    prepared = prepare(expected, kind, tuple(coords), known, domains, frozen, parsed=spec.parsed, dimensions=dimensions)
    allowed = {spec.shape, "equation"} if spec.shape == "equations" else {spec.shape}  # one coordinate: one equation
    if spec.parsed and spec.shape and prepared.parsed.kind not in allowed:
        raise AuthorError(
            f"the expected answer of kind {kind!r} must be {_AN[spec.shape]}, not {_AN[prepared.parsed.kind]}"
        )
    if given and not spec.parsed:
        raise AuthorError(f"option given does not apply to kind {kind!r}: its answers are not mathematics")
    if settings.get("unit"):
        _unit(str(settings["unit"]))  # an author's unit we cannot read is said now, not at the first answer
    if settings.get("values") is not None:
        _given_numbers(settings["values"], prepared)  # said now too
    values = given_values(prepared, given) if given else ()
    started = time.monotonic()
    verdict = _judge(spec, prepared, submitted, timeout, values)
    partials = partials_read(submitted) if spec.parsed and spec.shape and _refused(verdict, "partial") else None
    sides_of = submitted  # as typed, or with the derivatives of its steps read (a chain of more sides: below)
    if partials is not None:  # H = θ̇ ∂L/∂θ̇ − L = …, p_φ = ∂/∂φ̇(…) = …: a chain through a derivative written out
        read = _judge(spec, prepared, partials[0], timeout - (time.monotonic() - started), values)
        if read.status != "invalid":
            verdict = _with_steps_left_out(read, *partials[1:], prepared)
        elif _refused(read, "too_many_equals"):
            verdict, sides_of = read, partials[0]
    left = timeout - (time.monotonic() - started)
    forms = _small_angle_forms(spec, prepared, submitted, left, values) if verdict.status != "equivalent" else None
    if forms is not None:  # θ̈ = −(g/l) sin θ, which for small θ gives θ̈ = −(g/l) θ: which is the answer?
        return forms
    # H = p_θ θ̇ − L, then H = …: read as typed, H's value is put into the first line, and L is undefined
    unread = verdict.status == "invalid" or verdict.diagnosis in _UNDEFINED
    chain = lines_as_chain(submitted) if unread and spec.parsed and spec.shape else None
    if chain is not None:  # H = Σ p q̇ − L, then H = …: a chain over lines, as H = Σ p q̇ − L = … is read
        chained = _judge(spec, prepared, chain[0], timeout - (time.monotonic() - started), values)
        through = partials_read(chain[0]) if _refused(chained, "partial") else None
        if through is not None:  # H = θ̇ ∂L/∂θ̇ − L, then H = …: through its derivative, as the chain on one line is
            read = _judge(spec, prepared, through[0], timeout - (time.monotonic() - started), values)
            chained = _with_steps_left_out(read, *through[1:], prepared) if read.status != "invalid" else chained
        sides = chain_sides(chain[0]) if _refused(chained, "too_many_equals") and spec.shape == "expression" else None
        if sides:  # H = p_θ θ̇ − L, then H = m R² θ̇² − (…), then H = …: a chain of more sides, read side by side
            left = timeout - (time.monotonic() - started)
            chained = _judge_lines(spec, prepared, sides, left, values, chained, "side")
        # where the lines could be read as typed, only a definition we know makes the first line one (not L = … + q)
        first = f"{sides[0]} = {sides[-1].partition('=')[2]}" if sides else chain[0]  # the definition, then the value
        known = verdict.status == "invalid" or _defines_as_known(first, prepared, values)
        if chained.status != "invalid" and chained.diagnosis not in _UNDEFINED and known:
            # where an expression is asked, the chain is the answer; in a system, it is one of its lines
            key = "lines_as_chain" if spec.shape == "expression" else "lines_as_one_chain"
            note = say(key, count=chain[1], label=chain[2])
            verdict = replace(chained, feedback=(*chained.feedback, note), notes=(*chained.notes, note))
    several = verdict.diagnosis in _ONE_THING_ASKED or _answered_twice(verdict.answer, prepared)
    # θ̈ = −ω² sin θ, then θ̈ = −(g/l) sin θ: no definition of ω to eliminate, but a last line that
    # needs none; only where that line is right does the reading by lines say more
    unknowns = verdict.diagnosis == "eliminate_unknowns"
    lines, parts = (answer_lines(submitted), "line") if several or unknowns else (None, "")
    if getattr(verdict.answer, "code", None) == "too_many_equals" and spec.shape == "expression":
        lines, parts = chain_sides(sides_of), "side"
    if lines:
        left = timeout - (time.monotonic() - started)
        by_lines = _judge_lines(spec, prepared, lines, left, values, verdict, parts)
        if not unknowns or by_lines.status in ("equivalent", "undecided"):
            verdict = by_lines
        if sides_of is not submitted and verdict is by_lines:
            verdict = _with_steps_left_out(verdict, *partials[1:], prepared)
    said = _said_wrong(submitted, prepared) if spec.parsed and verdict.status == "equivalent" else None
    if said is not None:  # Using L = T + V, we get L = …: right as a value, not as what it says L is
        return _right_but_said(verdict, "statement_for_a_person", statement=said[1], label=said[0])
    operator = _operator_said_wrong(submitted, prepared) if spec.parsed and verdict.status == "equivalent" else None
    if operator is not None:  # Using d/dt(∂V/∂θ̇) − ∂V/∂θ = 0 we get …: right, but not from Lagrange's equation
        return _right_but_said(verdict, "operator_for_a_person", statement=operator)
    left = timeout - (time.monotonic() - started)
    premise = _premise_said_wrong(spec, prepared, submitted, left) if verdict.status == "equivalent" else None
    if premise is not None:  # m l² θ̈ = m g l sin θ ⇒ θ̈ = −(g/l) sin θ: right, but not from what it says it follows
        key = "premise_for_a_person" if spec.shape == "equation" else "premise_value_for_a_person"
        return _right_but_said(verdict, key, statement=premise)
    undefined = _premise_undefined(spec, prepared, submitted) if verdict.status == "equivalent" else None
    if undefined is not None:  # L = 1/0 ⇒ L = …: right, but not from what it says it follows from, which is nothing
        return _right_but_said(verdict, "premise_undefined_for_a_person", statement=undefined, **_GIVES[spec.shape])
    left = timeout - (time.monotonic() - started)
    rounded = _rounded(spec, prepared, submitted, left, values) if verdict.status == "not_equivalent" else None
    if rounded is not None:  # 0.333 m l² θ̇²: right with the decimal written as the 1/3 it rounds
        return _verdict(rounded, verdict.answer)
    listed = without_dashes(submitted) if spec.parsed and verdict.status == "not_equivalent" else None
    left = timeout - (time.monotonic() - started)
    if listed is None or left <= 0:
        return verdict
    if _judge(spec, prepared, listed, left, values).status != "equivalent":
        return verdict  # a bulleted list that is wrong too: as typed
    return _verdict(Outcome("invalid", 0.0, "dashes_ambiguous", method="parse"), verdict.answer)


def _premise_said_wrong(spec: Kind, expected: Expected, submitted: str, timeout: float) -> str | None:
    """``m l² θ̈ = m g l sin θ ⇒ θ̈ = −(g/l) sin θ``, or ``…, so …``: an equation of motion the answer says
    the one it gives follows from, which the parser leaves behind the step, where the two do not agree (the
    first is judged wrong); as typed, or None. Only an equation in the problem's names, with an acceleration
    in it, is judged so. ``L = … ⇒ …`` is read as working, the L, then the equation
    (:func:`_working_before_steps`), which Lagrange's equation with that L must give
    (:func:`_lagrangian_disagrees`)."""
    if spec.shape not in ("equation", "expression") or not _PREMISE_STEP.search(submitted):
        return None  # as nearly every answer: no step, and nothing to split (see _premises)
    started = time.monotonic()
    premises = _premises(submitted, expected)
    if spec.name == "lagrangian":
        bare = "=" not in _PREMISE_STEP.split(submitted)[-1]
        return _premise_of_lagrangian(spec, premises, expected, timeout, bare=bare)
    if spec.shape == "expression":
        return _premise_of_acceleration(premises, expected)
    for premise, read in premises:
        if not (read.ok and read.kind == "equation" and accelerations_in(read.value, expected)):
            continue
        if {symbol.name for symbol in read.symbols} - expected.names - {TIME.name}:
            continue
        left = timeout - (time.monotonic() - started)
        if left <= 0:
            return None
        judged = _judge(spec, expected, premise, left)
        # θ̈ = −(g/l) sin θ ⇒ θ̈ = −(g/l) θ: the full form, then the small-angle one asked for, is a derivation
        if judged.status == "not_equivalent" and judged.diagnosis not in _SMALL_FORMS | _FULL_FORMS:
            return premise
    return None


def _premise_undefined(spec: Kind, expected: Expected, submitted: str) -> str | None:
    """``L = 1/0 ⇒ L = …``: a premise before a step that the parser refuses as having no value (it divides by
    zero, or takes log 0), so that nothing follows from it; as typed, or None. The parser keeps only what
    follows the last step, so the premise was dropped unseen. Its other refusals are read past, as words are:
    honest working writes ẋ of a name of its own, Σ or v⃗, which the parser does not read."""
    if spec.shape not in _GIVES or spec.name in ("integer", "number"):
        return None  # a number's working is read where it is asked for (see read_number)
    return next(
        (premise for premise, read in _premises(submitted, expected) if not read.ok and read.code in _NO_VALUE), None
    )


def _premises(submitted: str, expected: Expected) -> Iterator[tuple[str, ParsedAnswer]]:
    """What stands before each step of a derivation (⇒, so), which the parser leaves behind: each as typed,
    without the punctuation around it, and as read in the problem's names; none where there is no step, or
    the answer is longer than is read so."""
    if len(submitted) > _PREMISE_LENGTH or not _PREMISE_STEP.search(submitted):
        return
    coords, names = expected.setting.coords, sorted(expected.names)
    for premise in _PREMISE_STEP.split(submitted)[:-1]:
        premise = premise.strip(" ,;:.")
        yield premise, parse_answer(premise, coords=coords, known=names)


_NO_VALUE = frozenset({"division_by_zero", "undefined_value"})  # the parser's refusals of a formula with no value
# what the answer after a premise gives, as the note names it, by the part's shape
_GIVES = {
    "expression": {"thing": "value", "graded": "Its value was graded and is right"},
    "equation": {"thing": "equation", "graded": "The equation was graded and is right"},
    "equations": {"thing": "equations", "graded": "The equations were graded and are right"},
}


def _premise_of_lagrangian(
    spec: Kind, premises: Iterable[tuple[str, ParsedAnswer]], expected: Expected, timeout: float, *, bare: bool
) -> str | None:
    """``L = ½ m l² θ̇² − m g l cos θ ⇒ L = ½ m l² θ̇² + m g l cos θ`` where a Lagrangian is asked: a
    Lagrangian before the step, in the problem's names, that is not one of the same motion; as typed, or
    None. A formula with no name is a Lagrangian only before one with none (``bare``): ``½ m l² θ̇² ⇒ L = …``
    may start from T. The parser keeps only what follows the last step; energies before it, ``T = …, V = …
    ⇒ L = …``, are read as lines (:func:`_energies_then_value`) and judged by :func:`_energies_disagree`."""
    started = time.monotonic()
    for premise, read in premises:
        if not read.ok:
            continue
        if read.kind == "equation" and read.value.lhs == _LAGRANGIAN:
            said = read.value.rhs
        elif read.kind == "expression" and bare:
            said = read.value
        else:
            continue
        if {symbol.name for symbol in said.free_symbols} - expected.names - {TIME.name}:
            continue  # a name of the student's own (x = l sin θ ⇒ …): no Lagrangian to judge
        left = timeout - (time.monotonic() - started)
        if left <= 0:
            return None
        if _judge(spec, expected, to_text(said), left).status == "not_equivalent":
            return premise
    return None


def _premise_of_acceleration(premises: Iterable[tuple[str, ParsedAnswer]], expected: Expected) -> str | None:
    """``2 (m₁ + m₂) ẍ = (m₁ − m₂) g, so ẍ = …`` where an acceleration is asked for (the option ``name``
    holds ``xddot``): an equation before the step, in the problem's names and with that acceleration in
    it, which the expected value does not solve; as typed, or None."""
    asked = expected.option("name") or ()
    wanted = [q for q in expected.setting.coords if canonical_name(f"{q}ddot") in asked]
    if len(wanted) != 1:
        return None
    acceleration = expected.setting.acceleration(wanted[0])
    for premise, read in premises:
        if not (read.ok and read.kind == "equation") or {s.name for s in read.symbols} - expected.names - {TIME.name}:
            continue
        plain = expected.setting.plain(read.value.lhs - read.value.rhs)
        if not plain.has(acceleration) or plain.free_symbols & (expected.setting.varying - {acceleration}):
            continue  # an equation of ẍ alone: of θ or ẋ too, the expected value is no solution to test
        if not _same_value(plain.xreplace({acceleration: expected.value}), sympy.S.Zero, expected):
            return premise
    return None


# the steps of a derivation, as the tokenizer reads them (grader.parse.tokens): what stands before one is left
_PREMISE_STEP = re.compile(
    r"==>|-->|=>|->|[→⟶⇒⟹∴]|\\(?:to|rightarrow|longrightarrow|Rightarrow|Longrightarrow|implies|therefore)(?![A-Za-z])"
    r"|\b(?:so|hence|thus|therefore)\b",
    re.I,
)
_PREMISE_LENGTH = 400  # characters: a longer answer is read as typed


def _rounded(spec: Kind, expected: Expected, submitted: str, timeout: float, given: tuple) -> Outcome | None:
    """A wrong formula that is right with its decimals written as the exact numbers they round
    (:func:`~grader.judge.rounded.exact_readings`): still wrong, as 0.333 is not 1/3, and told it is the
    rounding; None for any other answer, or where time runs out."""
    if not (spec.parsed and spec.shape) or not isinstance(submitted, str) or len(submitted) > LIMITS.length:
        return None
    if spec.name == "number":
        return None  # a number is judged within its tolerance: no exact number belongs there (2.02 for 2.006)
    started = time.monotonic()
    for reading, decimals in exact_readings(submitted):
        left = timeout - (time.monotonic() - started)
        if left <= 0:
            return None
        if _judge(spec, expected, reading, left, given).equivalent:
            key = "rounded_decimal" if len(decimals) == 1 else "rounded_decimals"
            details = {"decimals": listed([f"`{decimal}`" for decimal in decimals])}
            return Outcome("not_equivalent", 0.0, key, details, method="rounded")
    return None


def _defines_as_known(chain: str, expected: Expected, given: tuple) -> bool:
    """Whether ``chain`` states on its way a definition whose rightness is known (:func:`_definition_judged`:
    ``H = p_θ θ̇ − L``, ``p_φ = ∂L/∂φ̇``), and no other."""
    names = sorted(expected.names | {symbol.name for symbol, _ in given})
    read = parse_answer(chain, coords=expected.setting.coords, known=names)
    return (
        read.ok
        and bool(read.stated)
        and all(_definition_judged(stated.lhs, stated.rhs, expected) is not None for stated in read.stated)
    )


def _right_but_said(verdict: Verdict, key: str, **details) -> Verdict:
    """A right ``verdict`` that goes to a person for what the answer says on its way (``key``)."""
    feedback = (say(key, **details), *(line for line in verdict.feedback if line != "Correct."))
    return replace(verdict, status="undecided", diagnosis=key, feedback=feedback)


# what a formula is told where the other form is asked: a small-angle form where the full one is, and back
_SMALL_FORMS = frozenset({"small_angle", "potential_small_angle"})
_FULL_FORMS = frozenset({"not_small_angle"})


def _small_angle_forms(spec: Kind, expected: Expected, submitted: str, timeout: float, given: tuple) -> Verdict | None:
    """``θ̈ = −(g/l) sin θ, which for small θ gives θ̈ = −(g/l) θ``: a formula, then words that say its
    small-angle form follows, then that form (:func:`~grader.judge.words.formula_then_small_angle_form`);
    or the two with ≈ between, or ⇒ and words after (:func:`~grader.judge.words.formula_then_approximation`).
    Where the full form is asked, the first is the answer; where the small-angle form is, the last.
    Each is judged, and the one asked for is graded where the other is what the words say it is: the
    other form of the answer asked for (so the remark costs nothing, and is not graded), or, where the
    one graded is wrong, the other form of the right answer. Where one is right and the other is not
    its other form, which is the answer is for a person to say; where neither is right, and neither is
    the other form of the right answer, the answer is wrong whichever was meant. None where there are
    no two such formulas, or one of them cannot be read or holds names the problem does not have."""
    if not (spec.parsed and spec.shape):
        return None
    started = time.monotonic()
    names = sorted(expected.names | {symbol.name for symbol, _ in given})
    coords = expected.setting.coords

    def readable(*formulas: str) -> bool:
        return all(parse_answer(formula, coords=coords, known=names).ok for formula in formulas)

    for first, words, last in formula_then_small_angle_form(submitted, names, coords):
        if readable(first, last):
            return _two_forms_judged(
                spec, expected, (first, last), shown(words), timeout - (time.monotonic() - started), given
            )
    approximated = formula_then_approximation(submitted)  # θ̈ = −(g/l) sin θ ≈ −(g/l) θ
    if approximated is None or not readable(approximated[0], approximated[2]):
        return None
    first, sign, last = approximated
    if spec.shape != "expression" and "=" not in first:
        return None  # θ̈ ≈ −(g/l) θ: one equation, written with ≈
    return _two_forms_judged(spec, expected, (first, last), sign, timeout - (time.monotonic() - started), given)


def _two_forms_judged(spec: Kind, expected: Expected, forms: tuple, words: str, timeout: float, given: tuple):
    """The verdict on a formula and its small-angle form (``forms``), each judged, after ``words``
    (:func:`_one_of_two_forms`); None where one cannot be read or holds words left in a formula
    (… is maybe θ̈ = …), to be read as typed."""
    started = time.monotonic()
    full, small = (_judge(spec, expected, form, timeout - (time.monotonic() - started), given) for form in forms)
    if "invalid" in (full.status, small.status) or {full.diagnosis, small.diagnosis} & _NOT_ONE_FORMULA:
        return None
    return _one_of_two_forms(full, small, words)


# what an answer with a name the problem does not define is told: a unit's letter at its end is one too
_UNDEFINED = frozenset({"undefined_symbol", "undefined_unit_letter", "quantity_for_motion"})
# what a formula is told where words were left in it, or it is two equations: no one formula of the two forms
_NOT_ONE_FORMULA = _UNDEFINED | {"undefined_units", "eliminate_unknowns", "expected_one_equation"}


def _one_of_two_forms(full: Verdict, small: Verdict, words: str) -> Verdict:
    """The verdict on a formula and its small-angle form after ``words``, each judged (see
    :func:`_small_angle_forms`), with the note that says which was graded."""
    if full.equivalent and (small.equivalent or small.diagnosis in _SMALL_FORMS):
        graded, key = full, "small_form_left_out"
    elif small.equivalent and full.diagnosis in _FULL_FORMS:
        graded, key = small, "full_form_left_out"
    elif small.diagnosis in _SMALL_FORMS:  # the full form is asked, and theirs is wrong
        graded, key = full, "small_form_left_out"
    elif full.diagnosis in _FULL_FORMS:  # the small-angle form is asked, and theirs is wrong
        graded, key = small, "full_form_left_out"
    else:
        right = full if full.equivalent else small if small.equivalent else None
        if "undecided" in (full.status, small.status):  # one could not be judged: nothing is said of it
            outcome = Outcome("undecided", right.score if right else 0.0, "undecided", method="forms")
        elif right is not None or full.score or small.score:  # which was meant decides the grade
            score = right.score if right else 0.0
            outcome = Outcome("undecided", score, "forms_for_a_person", {"words": words}, method="forms")
        else:  # wrong whichever was meant
            outcome = Outcome("not_equivalent", 0.0, "forms_both_wrong", {"words": words}, method="forms")
        return _verdict(outcome, (right or full).answer)
    note = say(key, words=words)
    return replace(graded, feedback=(*graded.feedback, note), notes=(*graded.notes, note))


# one equation, or one expression, is asked for, and the answer has several lines
_ONE_THING_ASKED = frozenset({"expected_one_equation", "expected_expression"})


def _answered_twice(answer, expected: Expected) -> bool:
    """``ω = √(l/g); ω₀ = √(g/l)``: lines labelled with the asked quantity's names, two answers."""
    return getattr(answer, "kind", None) == "equations" and len(_asked_lines(answer.value, expected)) > 1


def _judge_lines(
    spec: Kind, expected: Expected, lines: list[str], timeout: float, given: tuple, whole: Verdict, parts="line"
) -> Verdict:
    """One equation (or one expression) asked for, written on several lines: the working on paper,
    ``m l² θ̈ = −m g l sin θ`` then ``θ̈ = −(g/l) sin θ``, or the answer written twice; or, as
    ``parts="side"``, a chain ``L = … = …`` (each given as ``L = side``). Where each reads alone as
    the thing asked for, the last is graded; where it is right but an earlier one is not the same,
    which is the answer is for a person to say. Otherwise the whole, as it was."""
    verdicts, definition = [], None
    for number, line in enumerate(lines):
        started = time.monotonic()
        if timeout <= 0:
            return whole
        label, _, side = line.partition("=")
        if definition is not None and label.strip() == definition.partition("=")[0].strip():
            line = f"{definition} = {side.strip()}"  # p_φ = ∂L/∂φ̇ = … = …: each side after the definition, as typed
        verdict = _judge(spec, expected, line, timeout, given)
        if verdict.status == "invalid" and parts == "side" and number == 0 and len(lines) > 2:
            # ∂L/∂φ̇ or Σ p q̇ − L alone is no value the parser reads, only a chain's definition
            definition = line
            timeout -= time.monotonic() - started
            continue
        if verdict.status == "invalid" or verdict.diagnosis in (*_ONE_THING_ASKED, "expected_equation"):
            return whole
        verdicts.append(verdict)
        timeout -= time.monotonic() - started
    *earlier, last = verdicts
    if last.diagnosis == "number_for_formula":
        return whole  # ω = √(g/l) = 3.13: the formula, then its value for numbers of the student's own
    misstated = _side_misstated(lines, earlier, expected, given) if parts == "side" else None
    if misstated is not None and last.status == "equivalent":  # H = p_θ θ̇ + L = … = …: a wrong definition
        return _right_but_said(last, "statement_for_a_person", **misstated)
    # L = T − V = …: a side in names of the answer's own is its definition, not a step to check
    wrong = [
        str(number)
        for number, verdict in enumerate(earlier, start=1 + (definition is not None))
        if verdict.status != "equivalent" and not (parts == "side" and verdict.diagnosis in _UNDEFINED)
    ]
    count = {"count": len(lines), "parts": f"{parts}s" + (" after the name" if parts == "side" else "")}
    if last.status == "equivalent" and wrong:
        one = len(wrong) == 1
        listed = f"{parts} {wrong[0]}" if one else f"{parts}s {', '.join(wrong)}"
        details = {"lines": listed, "do": "does" if one else "do", "part": parts}
        feedback = (say("last_line_right_earlier_not", **details),)
        # the score the last line earns, proposed to the person who decides
        return replace(last, status="undecided", feedback=feedback, method="lines", diagnosis="lines_differ", notes=())
    note = say("lines_agree" if last.status == "equivalent" else "last_line_graded", **count)
    feedback = tuple(dict.fromkeys([*last.feedback, note]))
    return replace(last, feedback=feedback, notes=(*last.notes, note))


def _side_misstated(lines: list[str], verdicts: list[Verdict], expected: Expected, given: tuple) -> dict | None:
    """Of a chain's sides judged one by one (:func:`_judge_lines`), a side in names of the answer's own
    that is a wrong definition of the quantity (``H = p_θ θ̇ + L = m R² θ̇² − … = …``): what the note on
    it says; None where there is none. Such a side is no step to check against the value, but what it
    says the quantity is may be wrong."""
    names = sorted(expected.names | {symbol.name for symbol, _ in given})
    for line, verdict in zip(lines, verdicts, strict=False):
        if verdict.diagnosis not in _UNDEFINED:
            continue
        read = parse_answer(line, coords=expected.setting.coords, known=names)
        if read.ok and read.kind == "equation" and _wrong_definition(read.value.lhs, read.value.rhs, expected, given):
            return {"statement": _quoted(read, read.value), "label": unicode_name(read.value.lhs.name)}
    return None


def _names(name) -> tuple[str, ...]:
    """The option ``name`` (a name or a list of them) as the names an answer is read with: p_φ is p_phi."""
    names = [name] if isinstance(name, str) else name
    if not (isinstance(names, list | tuple) and names and all(isinstance(n, str) and n for n in names)):
        raise AuthorError(f"option name is the quantity's name or a list of names, not {name!r}")
    return tuple(canonical_name(n) for n in names)


_AN = {"expression": "an expression", "equation": "an equation", "equations": "a system of equations"}


def _hashable(value):
    if isinstance(value, list | tuple | set | frozenset):
        return tuple(_hashable(item) for item in value)
    if isinstance(value, dict):  # meanings={"phi": "azimuthal angle"}
        return tuple(sorted((key, _hashable(item)) for key, item in value.items()))
    return value


def _refused(verdict: Verdict, code: str) -> bool:
    return verdict.status == "invalid" and getattr(verdict.answer, "code", None) == code


def _with_steps_left_out(
    verdict: Verdict, left_out: list[str], label: str, named: tuple, expected: Expected
) -> Verdict:
    """The verdict on a chain read without the steps ``left_out`` (:func:`partials_read`), and the note
    that says so. Where the chain's ``label`` names the Hamiltonian, the Lagrangian or the energy, a step
    left out may be its definition, unchecked (``H = θ̇ ∂L/∂θ − L``): a right value goes to a person, as
    one after a wrong definition does. The sentences show each ∂L/∂q̇ read as p_q as the student typed it."""
    verdict = _as_typed(verdict, named)
    if not left_out:
        return verdict
    s = "s" if len(left_out) > 1 else ""
    note = say("steps_left_out", s=s, steps=shown("; ".join(left_out)))
    name = canonical_name(label) if ONE_NAME.fullmatch(label) else None
    if name in _ENERGY_SUMS and name not in expected.names and verdict.status == "equivalent":
        return replace(
            _right_but_said(verdict, "step_for_a_person"), feedback=(note, say("step_for_a_person")), notes=(note,)
        )
    return replace(verdict, feedback=(*verdict.feedback, note), notes=(*verdict.notes, note))


def _as_typed(verdict: Verdict, named: tuple) -> Verdict:
    """``verdict`` with each momentum's name put in for a quotient (``named``, see :func:`partials_read`)
    shown as the quotient typed again: "as the chain `H = θ̇ ∂L/∂θ̇ − L = …`", not "θ̇  p_{theta}  − L"."""
    if not named:
        return verdict

    def typed(sentence: str) -> str:
        for name, quotient in named:
            # the name is put in with a space on each side; a side quoted as typed ends (or starts) with it
            for spaced in (name, name.rstrip(), name.lstrip()):
                sentence = sentence.replace(spaced, quotient)
        return sentence

    return replace(verdict, feedback=tuple(map(typed, verdict.feedback)), notes=tuple(map(typed, verdict.notes)))


def _judge(spec: Kind, expected: Expected, submitted: str, timeout: float, given: tuple = ()) -> Verdict:
    if timeout <= 0:  # a second reading of the answer, with no time left for it: nobody may say
        return _verdict(Outcome("undecided", 0.0, "undecided", method="timeout"), None)
    answer, conserved, used, typed, read_in, read_notes, read_shown = None, False, (), None, None, (), None
    with_constant, constant = None, None
    try:
        # Reading is timed too: within the parser's caps, sympy can still spend a second
        # building one factor of a hostile answer, and an answer has room for dozens.
        with time_limit(timeout) as deadline:
            if spec.parsed:
                momentum = _lone_momentum(expected, given)
                names = sorted(expected.names | {symbol.name for symbol, _ in given} | set(momentum[:1]))
                answer, read_notes = _read(spec, expected, submitted, names, deadline)
                formula = spec.name in ("expression", "lagrangian")
                # √(g/l) in s: "in" and a unit are no words to read past, nor names of the student's
                unread = not answer.ok or read_notes or _undefined(answer, names)
                unit_said = not answer.ok or (_IN_UNIT.search(submitted) and unread)
                split = _unit_tail(submitted, spec, expected) if formula and unit_said else None
                if split is None and formula and answer.ok and "[" in submitted:
                    split = _unit_in_label(submitted, spec, expected)  # Q_θ [N] = …: the label's unit
                if split is not None:  # −m g r sin θ, N·m: the comma sets a unit apart, and is no list
                    answer, unit, found = split
                    early, note = _unit_said(unit, found, spec, expected)
                    if early is not None:
                        return _verdict(early, answer)
                    read_notes = (note,)  # the words were the unit
                if not answer.ok:
                    return Verdict("invalid", 0.0, (answer.message,), "parse", "invalid", answer)
                read_notes += _misstated(answer, expected, given)
                answer, stated = _without_stated_definitions(answer, expected)
                read_notes += stated
                answer, values = _without_given_values(answer, spec, expected)
                read_notes += values
                read_notes += _given_redefined(answer, expected, given, momentum)
                answer = _asked_defined_after(answer, expected)
                defined, answer = answer, _with_definitions(answer, expected, deadline)
                read_notes += _energies_disagree(answer, spec, expected, deadline) or _energy_moves(
                    answer, spec, expected, deadline
                )
                read_notes += _lagrangian_disagrees(answer, spec, expected, deadline)
                read_notes += _derived_disagrees(answer, spec, expected)
                answer, working = _without_working(answer, spec, expected, defined)
                read_notes += working
                energies = _energies_alone(answer, spec, expected, deadline)
                if energies:
                    return _verdict(energies, answer)
                if _loose_definitions(answer):
                    return _verdict(Outcome("invalid", 0.0, "loose_definitions", method="parse"), answer)
                typed, (answer, used) = answer, _with_given(_as_momentum(answer, momentum), given)
                if momentum and sympy.Symbol(momentum[0]) in typed.symbols:
                    read_notes += (("p_read_as_momentum", {"momentum": unicode_name(momentum[1])}),)
                answer, conserved = _conserved(answer, spec, expected, deadline)
                answer, said = _said_constant(answer, spec, expected)
                read_notes += said
                answer = _name_on_the_left(answer, spec, expected)
                named, answer = answer, _unwrap_named(answer, spec, expected)
                other_name = _another_name if spec.name != "integer" else _another_count
                label = other_name(named, answer, expected)
                read_notes += (label,) if label else ()
                answer = _without_arbitrary_constant(answer, spec, expected)
                with_constant, (answer, constant) = answer, _without_constant_terms(answer, spec, expected)
                read_notes += (constant,) if constant else ()
                read_shown, (answer, early, read_in) = answer, _in_unit(answer, spec, expected)
                early = early or _mismatch(spec, expected, answer)
                if early and used:
                    return _verdict(_with_given_note(early, used), typed)  # as for any verdict: see below
                if early:
                    # as typed: 2.006 m is not read as a time; and 2 or 3 is not shown as the product 6·or
                    return _verdict(early, None if early.key == "number_hedged" else read_shown)
            outcome = spec.check(expected, answer if spec.parsed else submitted, deadline)
            squared = _square_sign_open(named, spec, expected, outcome, deadline) if spec.parsed else outcome
            if squared is not outcome:  # shown as typed: the root it was read as is what a person decides
                outcome, answer = squared, named
            if constant and constant[0] == "constant_unsure" and outcome.score == 0:
                # − m₂ g y on Atwood's machine, wrong with y taken as a constant: more likely a height
                # that moves (m₂'s), in a name the problem does not define; said so, as it was typed
                undefined = _mismatch(spec, expected, with_constant)
                if undefined is not None:
                    return (
                        _verdict(_with_given_note(undefined, used), typed)
                        if used
                        else _verdict(undefined, with_constant)
                    )
            if outcome.key == "other_unit" and read_shown is not None and read_shown.value.free_symbols:
                # 2.006 ms: the unit was typed, and asking whether the number is in ks is no help
                outcome = replace(outcome, key="out_of_tolerance", details={})
            outcome, read_notes = _count_unclear(spec, expected, outcome, read_notes, deadline)
            outcome, read_notes = _for_a_person(outcome, (*read_notes, read_in))
            for note in read_notes:
                if note:
                    outcome = replace(outcome, notes=(*outcome.notes, note))
            # ½ m l θ̇² + m g cos θ, (T − V)/l: the dynamics, and a constant multiple's credit; but no energy
            scaled = outcome.key == "normalization_scaled"
            if spec.parsed and outcome.status == "not_equivalent" and (outcome.score == 0 or scaled):
                outcome = _with_units(outcome, spec, expected, answer)
            if used and spec.name == "expression" and _names_terms(outcome):
                outcome = _terms_in_given_names(outcome, spec, expected, answer, given, deadline)
            if spec.parsed and conserved and outcome.key == "vanishing_factor":
                # ½ m l² θ̇² − m g l cos θ = C: its derivative is θ̇ times the equation, a factor not written
                outcome = replace(outcome, key="conserved_not_motion")
            elif spec.parsed and conserved and outcome.status != "equivalent":
                outcome = replace(_terms_unnamed(outcome), notes=(*outcome.notes, ("conserved_read", {})))
    except CheckTimeout:
        outcome = Outcome("undecided", 0.0, "undecided", method="timeout")
    except _CHECK_FAILURES as failure:
        outcome = Outcome("undecided", 0.0, "undecided", method=f"failed: {type(failure).__name__}")
    if used:
        # Neither the note nor the answer shown back says what p_θ stands for: another part
        # of the problem may ask for just that. The answer is shown as typed.
        if momentum and ("p_read_as_momentum", {"momentum": unicode_name(momentum[1])}) in outcome.notes:
            used = tuple(item for item in used if item[0].name != momentum[1])  # that note said so
        return _verdict(_with_given_note(outcome, used), typed)
    if constant:
        return _verdict(outcome, with_constant)  # shown with the constant the note says was left out
    return _verdict(outcome, answer)  # a number with a unit is shown in the part's unit, the note says so


def _with_given_note(outcome: Outcome, used: tuple) -> Outcome:
    """``outcome`` with the note that the given names (p_θ) were read with the problem's meaning."""
    if not used:
        return outcome
    names = _listing([symbol.name for symbol, _ in used])
    return replace(outcome, notes=(*outcome.notes, ("given_read", {"names": names})))


def _with_units(outcome: Outcome, spec: Kind, expected: Expected, answer: ParsedAnswer) -> Outcome:
    """A wrong answer whose units are wrong, or do not agree among its terms, is told so first:
    √(l/g) is a time, not an angular frequency. The diagnosis follows."""
    setting = expected.setting
    if not setting.dimensions:
        return outcome
    equation = spec.shape != "expression"
    mistake = units_mistake(_expected_units(spec, expected), setting.plain(answer.value), setting, equation=equation)
    if mistake is None:
        return outcome
    key, details = mistake
    said = ((outcome.key, outcome.details),) if outcome.key else ()
    return replace(outcome, key=key, details=details, more=(*said, *outcome.more))


def _expected_units(spec: Kind, expected: Expected):
    """The units of the quantity asked for, where the problem gives its symbols' dimensions and an
    expression is asked for; else None."""
    if "units" not in expected.cache:
        try:
            known = expected.setting.dimensions and spec.shape == "expression"
            expected.cache["units"] = units_of(expected.value, expected.setting) if known else None
        except Mixed:
            expected.cache["units"] = None  # the reference's own units disagree: say nothing
    return expected.cache["units"]


def _names_terms(outcome: Outcome) -> bool:
    return any(key.removesuffix("_in") in TERM_KEYS for key in (outcome.key or "", *(k for k, _ in outcome.more)))


def _terms_in_given_names(
    outcome: Outcome, spec: Kind, expected: Expected, answer: ParsedAnswer, given: tuple, deadline
) -> Outcome:
    """A wrong answer written in the given names (a Hamiltonian in p_θ, p_φ), diagnosed in those
    names: said in the velocities, its terms are ones the student did not write. Where the given
    names do not determine the velocities, it is said in the velocities."""
    written = in_given_names(expected, given)
    if written is None:
        return outcome
    in_names, replacement = written
    value = answer.value.xreplace(replacement)
    redone = spec.check(in_names, ParsedAnswer(answer.text, value, answer.kind), deadline)
    return replace(redone, notes=outcome.notes) if redone.status == "not_equivalent" else outcome


def _terms_unnamed(outcome: Outcome) -> Outcome:
    """The outcome without sentences naming terms: those of a conserved quantity's derivative,
    which the student did not write (``m l² sin θ φ̇ = C`` has no term in cos θ)."""
    more = tuple((key, details) for key, details in outcome.more if key.removesuffix("_in") not in TERM_KEYS)
    if outcome.key in TERM_KEYS:
        return replace(outcome, key="wrong_equation_single", details={}, more=more)
    return replace(outcome, more=more)


def _verdict(outcome: Outcome, answer: ParsedAnswer | None) -> Verdict:
    feedback = [say(outcome.key, **outcome.details)] if outcome.key else []
    feedback += [say(key, **details) for key, details in outcome.more]
    notes = tuple(say(key, **details) for key, details in outcome.notes)
    feedback = list(dict.fromkeys([*feedback, *notes]))  # two terms described alike are one sentence
    diagnosis = None if outcome.status == "equivalent" else outcome.key
    return Verdict(outcome.status, outcome.score, tuple(feedback), outcome.method, diagnosis, answer, notes)


def _with_given(answer: ParsedAnswer, given: tuple) -> tuple[ParsedAnswer, tuple]:
    """The answer with the author's given names (p_θ) put in place, and those it used, each with its value."""
    used = tuple((symbol, v) for symbol, v in given if symbol in answer.symbols)
    if not used:
        return answer, ()
    return _answer_replaced(answer, dict(used)), used


def _lone_momentum(expected: Expected, given: tuple) -> tuple[str, ...]:
    """``("p", "p_theta")`` where the problem has one coordinate and gives its momentum (p_θ), and
    ``p`` is no name of its own: a bare ``p`` can then mean only that momentum, as texts write it for
    one degree of freedom. With two coordinates, ``p`` names none of them; then ``()``."""
    coords = expected.setting.coords
    if len(coords) != 1 or "p" in expected.names:
        return ()
    wanted = canonical_name(f"p_{coords[0]}")
    return ("p", wanted) if any(symbol.name == wanted for symbol, _ in given) else ()


def _as_momentum(answer: ParsedAnswer, momentum: tuple) -> ParsedAnswer:
    """The answer with a bare ``p`` written as the one momentum it means (:func:`_lone_momentum`)."""
    bare = sympy.Symbol(momentum[0]) if momentum else None
    if bare is None or bare not in answer.symbols:
        return answer
    return _answer_replaced(answer, {bare: sympy.Symbol(momentum[1])})


def _answer_replaced(answer: ParsedAnswer, replacement: dict) -> ParsedAnswer:
    """The answer, each of its items (or its one value) with names put in place (:func:`_replaced`)."""
    value = answer.value
    if isinstance(value, tuple):
        return ParsedAnswer(answer.text, tuple(_replaced(item, replacement) for item in value), answer.kind)
    return ParsedAnswer(answer.text, _replaced(value, replacement), answer.kind)


def _replaced(item, replacement: dict):
    """An expression, or an equation side by side (left unevaluated), with names put in place."""
    if isinstance(item, sympy.Eq):
        return sympy.Eq(item.lhs.xreplace(replacement), item.rhs.xreplace(replacement), evaluate=False)
    return item.xreplace(replacement)


def _misstated(answer: ParsedAnswer, expected: Expected, given: tuple = ()) -> tuple:
    """A note where the answer says on its way that its quantity is what it is not:
    ``L = T + V = ½ m l² θ̇² + m g l cos θ`` is right as a value, but not as what it says L is. So
    does a line of working (``T = …; V = …; L = T + V``), or a chain's definition of H or of a
    momentum (``H = Σ p q̇ + L = …``, ``p_φ = ∂L/∂φ = …``)."""
    working = answer.value if answer.kind == "equations" else ()
    for statement in (*answer.stated, *working):
        if _wrong_definition(statement.lhs, statement.rhs, expected, given):
            label = statement.lhs.name
            return (
                ("statement_for_a_person", {"statement": _quoted(answer, statement), "label": unicode_name(label)}),
            )
    return ()


def _quoted(answer: ParsedAnswer, statement: sympy.Eq) -> str:
    """A line or a chain's side of ``answer`` as a note quotes it: as typed, not in sympy's order of terms
    (``L = 2T − H``, not L = −H + 2*T); as read back where the checker made it."""
    typed = answer.as_typed(statement)
    return shown(typed) if typed is not None else _shown_statement(statement)


def _shown_statement(statement: sympy.Eq) -> str:
    """A definition as a student wrote it: ∂L/∂φ̇ for the name the parser reads it as, Σ p q̇ for the
    product of its sum's symbol."""
    terms = []  # a quotient's name is shown as typed by the printer (see unicode_name)
    for term in sympy.Add.make_args(statement.rhs):
        if any(symbol.name in _SUMS for symbol in term.free_symbols):
            rest = sympy.Mul(*(f for f in sympy.Mul.make_args(term) if not (f.is_Symbol and f.name in _SUMS)))
            coefficient, rest = rest.as_coeff_Mul()
            term = coefficient * sympy.Symbol("Σ " + to_text(rest).replace("*", " "))
        terms.append(term)
    return to_text(sympy.Eq(statement.lhs, sympy.Add(*terms), evaluate=False))


def _said_wrong(submitted: str, expected: Expected) -> tuple[str, str] | None:
    """A wrong definition said in words or before ``⇒`` (``Using L = T + V, we get L = …``), which
    the reading of the formula leaves out and :func:`_misstated` cannot see; as said, or None."""
    if _DEFINING_LETTERS & expected.names:
        return None  # a tension T, an energy E of the problem's own: the letters mean something else
    patterns = _SAID_WRONG if _energy_sums(expected) is _ENERGY_SUMS else (*_SAID_WRONG, *_SAID_NOT_ENERGY)
    for label, pattern in patterns:
        found = pattern.search(submitted)
        if found:
            return label, re.sub(r"\s+", " ", found.group().strip()).replace("−", "-")
    return None


def _operator_said_wrong(submitted: str, expected: Expected) -> str | None:
    """The Euler–Lagrange operator an answer applies on its way to the equation it gives, in words
    (``Using d/dt(∂V/∂θ̇) − ∂V/∂θ = 0 we get …``) or as the parser reads it before the equation
    (``d/dt(∂L/∂θ) − ∂L/∂θ̇ = … = 0``), where it is not the true one; as typed, or None."""
    if "dt" not in submitted:
        return None  # as nearly every answer: no d/dt, no operator
    coords = expected.setting.coords
    for words, operator, force, equation in euler_lagrange_then_formula(submitted, sorted(expected.names), coords):
        judged = euler_lagrange(operator, coords, expected.names)
        if judged is False:
            return re.sub(r"\s+", " ", f"{operator} = {force or 0}")
        if force:  # d/dt(∂L/∂ẋ) − ∂L/∂x = −b ẋ: the force must be the one the equation after it needs
            return (
                None
                if _force_agrees(operator, force, equation, expected)
                else re.sub(r"\s+", " ", f"{operator} = {force}")
            )
        if judged and not dissipative(operator) and len(coords) == 1:
            # d/dt(∂L/∂ẋ) − ∂L/∂x = m ẍ + k x + b ẋ = 0, or = 0: m ẍ + k x + b ẋ = 0: what no L gives, but
            # the operator without Rayleigh's term is said to give it
            side = equation.split("=")[0].strip() if words.endswith("=") else None
            read = parse_answer(side or equation, coords=coords, known=sorted(expected.names))
            said = read.value if read.ok and read.kind == "expression" and side else None
            if read.ok and read.kind == "equation" and not side:
                said = read.value.lhs - read.value.rhs
            if said is not None and from_a_lagrangian(said, coords[0]) is False:
                return re.sub(r"\s+", " ", f"{operator} = {side or 0}")
        return None
    return None


def _force_agrees(operator: str, force: str, equation: str, expected: Expected) -> bool:
    """Whether the generalized force an answer writes out for Lagrange's equation agrees with the one
    equation of motion it then gives (:func:`~grader.judge.euler_lagrange.force_agrees`), at that equation's
    scale or at the part's own equation's, which the answer's was judged to be a multiple of; not where
    either cannot be read, or the problem has more than one coordinate: that is for a person."""
    coords, names = expected.setting.coords, sorted(expected.names)
    said = parse_answer(force, coords=coords, known=names)
    motion = parse_answer(equation, coords=coords, known=names)
    if len(coords) != 1 or not said.ok or said.kind != "expression" or not motion.ok or motion.kind != "equation":
        return False
    (reference,) = expected.value if isinstance(expected.value, tuple) else (expected.value,)
    reference = reference.lhs - reference.rhs if isinstance(reference, sympy.Eq) else reference
    try:  # after the verdict, outside its time limit: the force is the student's, so bound the work on it
        with time_limit(_FORCE_SECONDS):
            if force_agrees(operator, said.value, motion.value.lhs - motion.value.rhs, coords[0]):
                return True
            # = −b ẋ: ẍ + (b/m) ẋ + (k/m) x = 0: the right equation divided by m, which fixes no scale of
            # L, and so none of its force; the part's own equation, of the same motion, fixes one
            return force_agrees(operator, said.value, expected.setting.as_typed(reference), coords[0])
    except (CheckTimeout, *_CHECK_FAILURES):
        return False


_FORCE_SECONDS = 0.5


# What a chain or its working may say its quantity is, wrongly, in words or before ⇒: L = T + V, L = K + U,
# L = V − T, L = E, L = H; H or E = T − V, or = L. A side ends where the formula does.
_ENDS = r"(?=\s*(?:$|[=,;.⇒→⟹\n]|[A-Za-z]{2,}))"
_SAID_WRONG = (
    ("L", re.compile(rf"(?<![\w\\])L\s*=\s*(?:[TK]\s*\+\s*[VU]|[VU]\s*\+\s*[TK]|[VU]\s*[-−]\s*[TK]|[EH]){_ENDS}")),
    ("H", re.compile(rf"(?<![\w\\])H\s*=\s*(?:[TK]\s*[-−]\s*[VU]|L){_ENDS}")),
    ("E", re.compile(rf"(?<![\w\\])E\s*=\s*(?:[TK]\s*[-−]\s*[VU]|L){_ENDS}")),
)
# where H is not the energy (the option h_is_energy: a rotating hoop), H = T + V and H = E say it is
_SAID_NOT_ENERGY = (
    ("H", re.compile(rf"(?<![\w\\])H\s*=\s*(?:[TK]\s*\+\s*[VU]|[VU]\s*\+\s*[TK]|E){_ENDS}")),
    ("E", re.compile(rf"(?<![\w\\])E\s*=\s*H{_ENDS}")),
)
_DEFINING_LETTERS = frozenset("TVUKEHL")
_SUMS = frozenset({"Sigma", "sum"})  # Σ and TeX's \sum, as the parser names them in a chain's definition
_KINETIC_K = sympy.Symbol("K")  # K = T, as some texts write the kinetic energy
_LAGRANGIAN, _HAMILTONIAN = sympy.symbols("L H")


def _wrong_definition(label, side, expected: Expected, given: tuple = ()) -> bool:
    """Whether ``label = side``, a definition the answer states, is wrong for the quantity named:
    L or H or E as the wrong sum of energies, or as one another where they differ (L = E, H = L);
    H = Σ p q̇ + L, H = θ p_θ − L; a momentum p_φ as ∂L/∂φ, as ∂L/∂θ̇ or as −∂L/∂φ̇. What the problem
    names is not judged."""
    return _definition_judged(label, side, expected, given) is False


def _definition_judged(label, side, expected: Expected, given: tuple = ()) -> bool | None:
    """Whether ``label = side`` is right for the quantity named (see :func:`_wrong_definition`); None
    where it is no definition of one we know, as ``H = Σ p q̇ − L + V`` or ``L = T − V·not`` are not,
    or the problem names the quantity."""
    if not isinstance(label, sympy.Symbol) or label.name in expected.names:
        return None
    name, sums = label.name, _energy_sums(expected)
    if name in _ENERGY_SUMS:
        if _KINETIC_K.name not in expected.names:
            side = side.xreplace({_KINETIC_K: _KINETIC})
        in_energies = _others_in_energies(side, name, expected)
        # H = T − L is V: a sum the swaps leave one energy says the quantity is that energy
        alone = in_energies is not side and in_energies in _ENERGIES and in_energies.name not in expected.names
        if alone or _in_energies(in_energies, expected.names):
            # where H is not the energy, no sum of T and V is H: nor is 2T − L, which is T + V
            return _energy_multiple(in_energies, [name], sums) == 1
        others = in_energies.free_symbols - {_HAMILTONIAN}
        unknown_h = _HAMILTONIAN.name not in sums and _HAMILTONIAN.name not in expected.names
        if unknown_h and in_energies.has(_HAMILTONIAN) and others <= _ENERGIES:
            # L = 2T − H, L = H − 2V: true where H is T + V, but here H = T₂ − T₀ + V, which no sum of T and V is
            return False
        if side.is_Symbol and side.name in _ENERGY_SUMS and side.name not in expected.names:
            # L = E, L = H, H = L are wrong; H = E is right where H is the energy
            return name == side.name or (name in sums and sums[name] == sums.get(side.name))
        lagrangian = sympy.Symbol("L")
        if name == "H" and any(symbol.name in _SUMS for symbol in side.free_symbols) and side.has(lagrangian):
            rest = side - side.coeff(lagrangian) * lagrangian
            if side.coeff(lagrangian) != -1 or rest.could_extract_minus_sign():
                return False  # H = Σ p q̇ + L, H = L − Σ p q̇
            coefficient, term = rest.as_coeff_Mul()
            return True if coefficient == 1 and term.is_Mul and not term.has(lagrangian) else None  # H = Σ p q̇ − L
        written_out = _sum_written_out(side, lagrangian, expected) if name == "H" and side.has(lagrangian) else None
        return written_out if written_out is not None else _legendre_judged(name, side, expected, given)
    force = re.fullmatch(r"Q_?([A-Za-z]\w*)", name)
    coefficient, quotient = side.as_coeff_Mul()
    derivative = split_quotient(quotient.name) if quotient.is_Symbol else None
    if derivative is not None and derivative.top not in "LTVU":
        derivative = None  # ∂F/∂ẋ, Rayleigh's: no momentum, no force
    if force is not None:  # Q_r = −∂V/∂r; ∂V/∂r, ∂V/∂ṙ, or ∂V/∂θ for Q_r, is wrong
        if derivative is None or derivative.top not in "VU" or coefficient not in (1, -1):
            return None
        return coefficient == -1 and not derivative.dotted and _same_name(derivative.by, force[1])
    momentum = re.fullmatch(r"p_?([A-Za-z]\w*)", name)
    momenta = {sympy.Symbol(canonical_name(f"p_{q}")) for q in expected.setting.coords}
    if momentum and label in momenta and side.free_symbols and side.free_symbols <= momenta:
        return side == label  # p_φ = 2 ∂L/∂φ̇, its ∂L/∂φ̇ read as p_φ (see partials_read): not p_φ
    if not momentum or not derivative:
        return None
    # p_θ₁ is ∂L/∂θ̇₁; −∂L/∂φ̇ and ∂V/∂φ̇ (zero: V has no velocity in it) are no momentum; ∂T/∂φ̇ is, as V has none
    return coefficient == 1 and derivative.top in "LT" and derivative.dotted and _same_name(derivative.by, momentum[1])


def _same_name(typed: str, other: str) -> bool:
    """Whether two spellings of a name are one, with or without their ``_``: theta_1 and theta1."""
    return typed.replace("_", "") == other.replace("_", "")


def _legendre_judged(name: str, side, expected: Expected, given: tuple) -> bool | None:
    """Whether ``H = side`` (or ``L = side``), written in momenta, velocities and L or H (or T and V), is
    H = Σ p q̇ − L (L = Σ p q̇ − H), identically: ``H = θ p_θ − L``, ``H = L − p_θ θ̇``, ``H = p_θ φ̇ + p_φ θ̇ − L``
    and ``L = p_θ θ̇ + H`` are not. Where the problem gives every momentum, a step with the momenta
    worked out (``m R² θ̇² − L``) is judged so too. None for any other side: one in another name, or in
    the problem's parameters where the momenta are not given, or in neither momenta nor parameters, or
    in none of L, H, T and V (a value in the momenta)."""
    if name not in ("H", "L"):
        return None
    coords = expected.setting.coords
    momenta = {sympy.Symbol(canonical_name(f"p_{q}")): q for q in coords}
    if len(coords) == 1 and "p" not in expected.names:
        momenta[sympy.Symbol("p")] = coords[0]  # one coordinate: p is its momentum
    energies = {s for s in (*_ENERGIES, _KINETIC_K, _HAMILTONIAN, _LAGRANGIAN) if s.name not in expected.names}
    names = side.free_symbols - {TIME}
    parameters = {symbol for symbol in names if symbol.name in expected.names}
    if names - parameters - energies - set(momenta) or not names & energies:
        return None  # H = p_θ²/(2 m R²) − …: a value, in the momenta, judged as one
    if not names & set(momenta) and not parameters:
        return None  # H = 2T − L: right only where T is quadratic in the velocities, which is not judged here
    values = {momenta[symbol]: value for symbol, value in given if symbol in momenta}
    if parameters and len(values) < len(coords):
        return None  # m R² θ̇² − L: p_θ θ̇ worked out, which only the momenta's values can check
    own = {q: sympy.Symbol(canonical_name(f"p_{q}")) for q in coords}  # p for p_θ, where it is
    momentum = {symbol: values.get(q, own[q]) for symbol, q in momenta.items()}
    summed = sympy.Add(*(momentum[own[q]] * expected.setting.node(q, 1) for q in coords))
    lagrangian = _KINETIC - _POTENTIAL
    replacement = {
        **momentum, _KINETIC_K: _KINETIC, _POTENTIAL_U: _POTENTIAL, _LAGRANGIAN: lagrangian,
        _HAMILTONIAN: summed - lagrangian,
    }  # fmt: skip
    replacement = {symbol: value for symbol, value in replacement.items() if symbol in energies or symbol in momenta}
    target = summed - lagrangian if name == "H" else lagrangian
    return _same_value(side.xreplace(replacement), target, expected)


def _sum_written_out(side, lagrangian: sympy.Symbol, expected: Expected) -> bool | None:
    """Whether ``H = p_θ θ̇ + p_φ φ̇ − L``, Σ p q̇ − L written out over the problem's coordinates, is
    right: each coordinate's momentum times its velocity once, then − L. A term left out or + L is
    wrong; a side that is no such sum (``H = p_θ θ̇ − L + V``) is None."""
    coords = {name.replace("_", "") for name in expected.setting.coords}
    rest = side - side.coeff(lagrangian) * lagrangian
    found = []
    for term in sympy.Add.make_args(rest):
        momentum, velocity = term.as_independent(sympy.Derivative, as_Add=False)
        named = re.fullmatch(r"p_?(\w*)", momentum.name) if momentum.is_Symbol else None
        if named is None or not isinstance(velocity, sympy.Derivative) or velocity.derivative_count != 1:
            return None
        coordinate = velocity.expr.func.__name__.replace("_", "")
        if named[1].replace("_", "") not in (coordinate, "" if len(coords) == 1 else coordinate):
            return None
        found.append(coordinate)
    if sorted(found) != sorted(set(found)) or not set(found) <= coords or not found:
        return None
    return side.coeff(lagrangian) == -1 and set(found) == coords


def _without_stated_definitions(answer: ParsedAnswer, expected: Expected) -> tuple[ParsedAnswer, tuple]:
    """``L = T − V`` on a line of its own, then ``L = ½ m l² θ̇² + …``: the first states what L is, in
    energies no line gives a value; the second gives L's value. The statement is left out, with a
    note (before, L's value was put into it and T and V were told undefined). A sum of the energies
    that is not the name's own (``L = T + V``) is left out too: :func:`_misstated` has said so."""
    if answer.kind != "equations":
        return answer, ()
    items = answer.value
    labels = [item.lhs for item in items]
    stated = [
        item
        for item in items
        if item.lhs.is_Symbol
        and item.lhs.name in _ENERGY_SUMS
        and item.lhs.name not in expected.names
        and labels.count(item.lhs) > 1
        and _in_energies(item.rhs, expected.names)
        and not item.rhs.free_symbols & set(labels)  # T = …, V = …, L = T − V: T and V have values
    ]
    if not stated or len(stated) == len(items):
        return answer, ()
    rest = tuple(item for item in items if item not in stated)
    right = [item for item in stated if _energy_multiple(item.rhs, [item.lhs.name], _energy_sums(expected)) == 1]
    notes = (("definition_left_out", {"line": _quoted(answer, right[0])}),) if right else ()
    if len(rest) == 1:
        return replace(answer, value=rest[0], kind="equation"), notes
    return replace(answer, value=rest, kind="equations"), notes


def _without_given_values(answer: ParsedAnswer, spec: Kind, expected: Expected) -> tuple[ParsedAnswer, tuple]:
    """``ω = √(g/l), where g = 9.81 m/s²``: where a formula is asked, lines after the first that give the
    problem's constants the values they take (a number, perhaps with its unit) say where the formula will be
    used, and are left out with a note; put in, they made the formula a number, and its label undefined.
    A number's working at the values an answer gives is read where a number is asked (grader.judge.numbers)."""
    if answer.kind != "equations" or spec.name in ("integer", "number"):
        return answer, ()
    first, *rest = answer.value
    values = [item for item in rest if _gives_a_constant(item, expected)]
    if not values:
        return answer, ()
    kept = (first, *(item for item in rest if item not in values))
    names = [item.lhs.name for item in values]
    note = ("values_left_out", {"names": _listing(names), "values": "value" if len(names) == 1 else "values"})
    if len(kept) == 1:
        return replace(answer, value=first, kind="equation"), (note,)
    return replace(answer, value=kept, kind="equations"), (note,)


def _gives_a_constant(item, expected: Expected) -> bool:
    """Whether a line gives one of the problem's constants a number: ``g = 9.81 m/s²``, ``l = 1``."""
    if not (item.lhs.is_Symbol and item.lhs.name in expected.names) or expected.setting.is_state(item.lhs):
        return False
    value = in_units(item.rhs)
    return value is not None and value[0].is_number


def _given_redefined(answer: ParsedAnswer, expected: Expected, given: tuple, momentum: tuple) -> tuple:
    """A note where the answer defines for itself a name the problem gives a meaning, as other than it is
    (``H = p_θ²/(2 m) − …, where p_θ = m R θ̇``; ``With p_φ = m l² sin θ φ̇: H = …``): put in place, the
    student's definition decides the value, and a wrong one can make a wrong formula in that name right."""
    if answer.kind != "equations" or not given:
        return ()
    values = dict(given)
    if momentum:  # p, where it means p_θ
        values[sympy.Symbol(momentum[0])] = values.get(sympy.Symbol(momentum[1]))
    for item in answer.value:
        if not item.lhs.is_Symbol:
            continue
        # Let pθ = 2 m l² θ̇. Then H = p_θ²/…: the momentum given, spelt otherwise, and not put in place
        spelt = _momentum_spelt(item.lhs.name, expected) if item.lhs not in values else None
        value = values.get(item.lhs if spelt is None else sympy.Symbol(spelt))
        if value is None or any(symbol.name not in expected.names for symbol in item.rhs.free_symbols):
            continue
        if spelt is not None and not _same_value(item.rhs, value, expected):
            return (
                ("momentum_spelt_for_a_person", {"name": unicode_name(spelt), "definition": _quoted(answer, item)}),
            )
        if not _same_value(item.rhs, value, expected):
            name = unicode_name(momentum[1] if momentum and item.lhs.name == momentum[0] else item.lhs.name)
            return (("given_redefined_for_a_person", {"name": name, "definition": _quoted(answer, item)}),)
    return ()


def _same_value(mine, theirs, expected: Expected) -> bool:
    """Whether two values agree at a few points, each name at its own value (sin²θ and 1 − cos²θ do).
    Evaluated, not expanded: a definition's side as typed may be (p_θ θ̇ + L)⁹⁹."""
    mine, theirs = expected.setting.plain(mine), expected.setting.plain(theirs)
    symbols = sorted(mine.free_symbols | theirs.free_symbols, key=str)  # V − V cancels in the difference
    for step in _SAME_VALUE_STEPS:
        values = {symbol: sympy.Float(0.5 + (i + 1) * step % 1) for i, symbol in enumerate(symbols)}
        found, scale = sympy.N(mine.xreplace(values) - theirs.xreplace(values)), sympy.N(theirs.xreplace(values))
        if not (found.is_number and scale.is_number and found.is_finite and scale.is_finite):
            return False
        if abs(complex(found)) > 1e-9 * (1 + abs(complex(scale))):
            return False
    return True


_SAME_VALUE_STEPS = (0.6180339887, 0.4142135624)  # the golden ratio's and √2's: no two names share a value


def _with_definitions(answer: ParsedAnswer, expected: Expected, deadline) -> ParsedAnswer:
    """``θ̈ + ω₀² sin θ = 0, ω₀² = g/l`` or ``L = ½ m v², where v = l θ̇``: a name the answer
    defines for itself, put in place. A definition is an equation of its own whose left side
    is a name the problem does not define (or its power) and whose right side uses only names
    it does; and another equation must use the name, or its rate. A rate is put in place as the
    definition's derivative of the same order: ``p = m l² θ̇, ṗ = −m g l sin θ``, or ``½ m ẋ²,
    where x = l sin θ``. What remains is the answer.

    The parser's caps bound each equation, not what one put into another makes: a = 9⁹⁹ g,
    b = a⁹⁹, c = b⁹⁹ … would build numbers of millions of digits. Where a substitution makes
    a number beyond the parser's caps, none is made, and the answer is judged as typed."""
    if answer.kind != "equations":
        return answer
    items = list(answer.value)
    while len(items) > 1:
        deadline.check()
        asked = _asked_line(items, expected)  # ω = √(g/l); T = 2π/ω where ω is asked: ω's line is the answer
        found = next(
            ((i, d) for i, item in enumerate(items) if i != asked and (d := _definition(item, items, expected))), None
        )
        if found is None:
            break
        position, (symbol, value) = found
        del items[position]
        found_rates = {rate for item in items for rate in _rates_of(item, symbol, expected)}
        if any(not within_diff_budget(value, rate.derivative_count) for rate in found_rates):
            return answer
        # p̈ too, where p's rate was put in place from another definition (p = m l² u̇, u = θ)
        rates = {rate: sympy.diff(value, (TIME, rate.derivative_count)) for rate in found_rates}
        items = [_replaced(item, {**rates, symbol: value}) for item in items]
        if any(too_many_digits(number) for item in items for number in item.atoms(sympy.Rational)):
            return answer
    if len(items) == len(answer.value):
        return answer
    if len(items) == 1:
        return ParsedAnswer(answer.text, items[0], "equation")
    return ParsedAnswer(answer.text, tuple(items), "equations")


def _energy_lines(answer: ParsedAnswer, spec: Kind, expected: Expected) -> tuple[dict, list]:
    """The sums of the energies that name a quantity (L = T − V …), and the lines of ``answer`` that name one,
    where working may give energies before it: a system, where a Lagrangian or an expression is asked, in a
    problem that does not use T, V, L or H as its own names. ({}, []) where not."""
    if (
        answer.kind != "equations"
        or spec.name not in ("lagrangian", "expression")
        or _DEFINING_LETTERS & expected.names
    ):
        return {}, []
    sums = _energy_sums(expected)
    return sums, [item for item in answer.value if item.lhs.is_Symbol and item.lhs.name in sums]


def _energies_disagree(answer: ParsedAnswer, spec: Kind, expected: Expected, deadline) -> tuple:
    """``T = m l² θ̇²; V = −m g l cos θ; L = T − V = ½ m l² θ̇² + m g l cos θ``: lines of working that give
    the energies, then the Lagrangian (or H or E, where they are T + V) with a value that their difference
    (sum) is not. The value may be right, but the working says otherwise, as a chain's wrong earlier side
    does: a note for a person. None where the energies come to it, are the problem's names, or cannot be
    compared."""
    sums, named = _energy_lines(answer, spec, expected)
    if len(named) != 1:
        return ()
    (last,) = named  # L = T − V = …, where T = …: the energies may come after it
    energies = {item.lhs: item.rhs for item in answer.value if item.lhs in (_KINETIC, _POTENTIAL, _POTENTIAL_U)}
    potential = _POTENTIAL_U if _POTENTIAL_U in energies else _POTENTIAL
    if _KINETIC not in energies or potential not in energies or len(energies) != 2:
        return ()
    made = sums[last.lhs.name].xreplace({_POTENTIAL: _POTENTIAL_U} if potential == _POTENTIAL_U else {})
    made = made.xreplace(energies)
    if {symbol.name for symbol in (made - last.rhs).free_symbols} - expected.names - {TIME.name}:
        return ()  # a name of the student's own: no value to compare
    try:
        points = expected.points(expected.point_count, group=GROUP)
        pairs = evaluate_pairs(expected.compile(made), expected.compile(last.rhs), points, deadline)
    except _CHECK_FAILURES:
        return ()
    # V = m g l (1 − cos θ), then L without the m g l: a constant of the motion changes no Lagrangian
    if all_equal(pairs) is not False or constant_difference(pairs) is not False:
        return ()
    label, sign = last.lhs.name, "−" if last.lhs.name == "L" else "+"
    details = {"kinetic": "T", "potential": potential.name, "label": label, "sum": f"T {sign} {potential.name}"}
    return (("energies_disagree_for_a_person", details),)


def _energy_moves(answer: ParsedAnswer, spec: Kind, expected: Expected, deadline) -> tuple:
    """``T = m l² θ̇²; L = ½ m l² θ̇² + m g l cos θ``: working that gives T and no V, then the Lagrangian asked
    for (or H or E, where they are T + V), whose velocities T's are not; or that gives a V (U) with velocities
    in it. A potential holds none, so T − L (H − T) must not move with them, whatever V is: T is not derived
    from the expected value, which would take a rotating hoop's ½ m R² ω² sin²θ from its T. The value may be
    right, but the working says otherwise: a note for a person, as where T and V do not make it
    (:func:`_energies_disagree`). Where the expected value has a term linear in the velocities, it may be a
    potential's (q A·v of a charge in a magnetic field), so only what is not linear in them is told. None
    where the working is not so, holds names of the student's own, or cannot be judged."""
    sums, named = _energy_lines(answer, spec, expected)
    asked = {"L"} if spec.name == "lagrangian" else set(expected.option("name") or ())
    if len(named) != 1 or named[0].lhs.name not in asked:
        return ()
    (last,), label = named, named[0].lhs.name
    aliases = {} if _KINETIC_K.name in expected.names else {_KINETIC_K: _KINETIC}  # K = T, as some texts write it
    stated = [(aliases.get(item.lhs, item.lhs), item.rhs) for item in answer.value]
    stated = [(name, value) for name, value in stated if name in _ENERGIES]
    if len(stated) != len({name for name, _ in stated}):
        return ()  # two values of one energy: which is the working is not ours to say
    energies = dict(stated)
    potential = next((symbol for symbol in (_POTENTIAL, _POTENTIAL_U) if symbol in energies), None)
    if potential is not None:
        moving, other = energies[potential], sympy.S.Zero
    elif _KINETIC in energies:  # L = T − V: ∂T/∂q̇ = ∂L/∂q̇; H = T + V: ∂T/∂q̇ = ∂H/∂q̇
        moving, other = energies[_KINETIC], last.rhs
    else:
        return ()
    if {symbol.name for symbol in (moving + other).free_symbols} - expected.names - {TIME.name}:
        return ()
    setting = expected.setting
    velocities = [setting.velocity(q) for q in setting.coords]
    linear = _linear_in_velocities(expected)
    try:
        mine, theirs = setting.plain(moving), setting.plain(other)
        # the squares and products of velocities: ∂²/∂q̇ᵢ∂q̇ⱼ
        mine2 = [sympy.diff(mine, u, w) for i, u in enumerate(velocities) for w in velocities[i:]]
        theirs2 = [sympy.diff(theirs, u, w) for i, u in enumerate(velocities) for w in velocities[i:]]
        deadline.check()
        agrees = all(_same_value(a, b, expected) for a, b in zip(mine2, theirs2, strict=True))
        if agrees and not linear:
            agrees = _linear_part_allowed(mine, theirs, label == "L" and potential is None, setting, expected)
    except _CHECK_FAILURES:
        return ()
    if agrees:
        return ()
    how = " other than linearly" if linear else ""
    if potential is not None:
        return (("potential_moves_for_a_person", {"potential": potential.name, "how": how}),)
    kinetic = next(item.lhs.name for item in answer.value if aliases.get(item.lhs, item.lhs) == _KINETIC)
    subtracted = sums[label].coeff(_POTENTIAL) == -1
    difference, sign = (f"{kinetic} − L", "−") if subtracted else (f"{label} − {kinetic}", "+")
    details = {"label": label, "kinetic": kinetic, "difference": difference, "sum": f"{kinetic} {sign} V", "how": how}
    return (("kinetic_moves_for_a_person", details),)


def _linear_part_allowed(mine, theirs, derivative_allowed: bool, setting, expected: Expected) -> bool:
    """Whether T and the L (or H) that agree in their squares of velocities also agree in the velocities'
    linear part: the same, or, where L is given and ``derivative_allowed``, differing by Σ Aᵢ(q, t) q̇ᵢ that is
    d/dt of a function of the coordinates (∂Aᵢ/∂qⱼ = ∂Aⱼ/∂qᵢ), which changes no equation of motion: ``T = ½ m l² θ̇²;
    L = ½ m l² θ̇² + m g l cos θ + m g l cos θ θ̇`` is honest working, and so is the hoop's T written as
    ½ m R² (θ̇ + ω sin θ)², whose cross term is d/dt(−m R² ω cos θ), before its L, as that L itself is right."""
    velocities = [setting.velocity(q) for q in setting.coords]
    at_rest = dict.fromkeys(velocities, 0)
    linear = [(sympy.diff(mine, u) - sympy.diff(theirs, u)).xreplace(at_rest) for u in velocities]
    if not derivative_allowed:
        return all(_same_value(a, sympy.S.Zero, expected) for a in linear)
    positions = [setting.state[(q, 0)] for q in setting.coords]
    return all(
        _same_value(sympy.diff(linear[i], positions[j]), sympy.diff(linear[j], positions[i]), expected)
        for i in range(len(positions))
        for j in range(i + 1, len(positions))
    )


def _linear_in_velocities(expected: Expected) -> bool:
    """Whether the expected value has a term linear in the velocities: ∂/∂q̇ of it is not 0 where they are."""
    if "linear_in_velocities" not in expected.cache:
        setting, value = expected.setting, expected.value
        velocities = [setting.velocity(q) for q in setting.coords]
        rest = dict.fromkeys(velocities, sympy.S.Zero)
        try:
            found = any(
                not _same_value(sympy.diff(value, u).xreplace(rest), sympy.S.Zero, expected) for u in velocities
            )
        except _CHECK_FAILURES:
            found = True  # the weaker check, which holds either way
        expected.cache["linear_in_velocities"] = found
    return expected.cache["linear_in_velocities"]


def _lagrangian_disagrees(answer: ParsedAnswer, spec: Kind, expected: Expected, deadline) -> tuple:
    """``L = m l² θ̇² − m g l cos θ; m l² θ̈ + m g l sin θ = 0``: working that states the Lagrangian (or T and V),
    and Rayleigh's F where there is one, then equations of motion that Lagrange's equations with them do not
    give. The equations may be right, but the working says otherwise: a note for a person. A Lagrangian off by
    a constant, a factor or d/dt of a function gives the same equations, and agrees. Where friction is in the
    equations and no F is written, the Lagrangian's equations must agree with them at rest, where friction
    vanishes. None where the working states no one Lagrangian, holds names of the student's own, or cannot
    be judged."""
    if answer.kind != "equations" or spec.name not in ("equation", "equations") or _DEFINING_LETTERS & expected.names:
        return ()
    lines: dict = {}
    for item in answer.value:
        if item.lhs.is_Symbol and item.lhs.name in _WORKING_NAMES:
            lines.setdefault(item.lhs, []).append(item.rhs)
    if any(len(values) > 1 for values in lines.values()):
        return ()  # two values of one name: which is the working is not ours to say
    found = {symbol: values[0] for symbol, values in lines.items()}
    potential = found.get(_POTENTIAL, found.get(_POTENTIAL_U))
    if _LAGRANGIAN in found:
        lagrangian, label = found[_LAGRANGIAN], "L"
    elif _KINETIC in found and potential is not None and not {_POTENTIAL, _POTENTIAL_U} <= set(found):
        lagrangian, label = found[_KINETIC] - potential, "T − V" if _POTENTIAL in found else "T − U"
    else:
        return ()
    friction = [(symbol, found[symbol]) for symbol in _RAYLEIGH if symbol in found]
    if len(friction) > 1:
        return ()
    label = f"{label} and {friction[0][0].name}" if friction else label
    friction = [value for _, value in friction]
    names = expected.names | {TIME.name}
    if any(symbol.name not in names for value in (lagrangian, *friction) for symbol in value.free_symbols):
        return ()  # L = T − V where T = …, or a name of the student's own: no equations to compare
    setting = expected.setting
    try:
        plain = setting.plain(lagrangian)
        equations = lagrange_equations(plain, setting)
        if friction:
            dissipation = setting.plain(friction[0])
            rates = [sympy.diff(dissipation, setting.velocity(q)) for q in setting.coords]
            equations = [e + rate for e, rate in zip(equations, rates, strict=True)]
        deadline.check()
        if not friction and len(setting.coords) == 1 and _dissipative(expected):
            agrees = _agrees_at_rest(equations[0], expected)
        else:
            typed = [sympy.Eq(setting.as_typed(e), 0, evaluate=False) for e in equations]
            given = ParsedAnswer(answer.text, typed[0] if len(typed) == 1 else tuple(typed), _SHAPES[len(typed) > 1])
            judged = spec.check(expected, given, deadline)
            # L = ½ m l² θ̇² + m g l cos θ; θ̈ = −(g/l) θ: the full equation, linearized after, is a derivation
            agrees = "equivalent" if judged.key in _FULL_FORMS else judged.status
    except _CHECK_FAILURES:
        agrees = "undecided"
    many = len(setting.coords) > 1
    details = {
        "label": label,
        "it": "them" if friction else "it",
        "equations": "equations" if many else "equation",
        "does": "do" if many else "does",
        "were": "were" if many else "was",
        "are": "are" if many else "is",
    }
    if agrees in (True, "equivalent"):
        return ()
    if agrees in (False, "not_equivalent"):
        return (("lagrangian_disagrees_for_a_person", details),)
    # equations too long to derive or compare: a Lagrangian no one here can follow may give others
    return (("lagrangian_unchecked_for_a_person", details),)


def _derived_disagrees(answer: ParsedAnswer, spec: Kind, expected: Expected) -> tuple:
    """``L = m l² (θ̇² + sin²θ φ̇²) + …; p_φ = m l² sin²θ φ̇``: working that states the Lagrangian, then the
    momentum, or the Hamiltonian, that the part asks for, with a value that ∂L/∂q̇ (Σ p q̇ − L) of that L is
    not; or that states V, then a generalized force that −∂V/∂q is not. The value may be right, but the
    working says otherwise: a note for a person, as for an equation of motion (:func:`_lagrangian_disagrees`).
    None where no one line states L (V) in the problem's names, or the part asks for another quantity."""
    if answer.kind != "equations" or spec.name != "expression" or _DEFINING_LETTERS & expected.names:
        return ()
    setting = expected.setting
    momenta, forces, label = _derived_asked(expected)
    stated = [item.rhs for item in answer.value if item.lhs in ({label, _POTENTIAL_U} if forces else {label})]
    if label is None or len(stated) != 1:
        return ()
    if any(symbol.name not in expected.names | {TIME.name} for symbol in stated[0].free_symbols):
        return ()
    try:
        plain = setting.plain(stated[0])
        if momenta:
            derived, quantity = sympy.diff(plain, setting.velocity(momenta[0])), f"∂L/∂{unicode_name(momenta[0], 1)}"
        elif forces:
            derived, quantity = -sympy.diff(plain, setting.state[(forces[0], 0)]), f"−∂V/∂{unicode_name(forces[0])}"
        else:
            rates = [setting.velocity(q) * sympy.diff(plain, setting.velocity(q)) for q in setting.coords]
            derived, quantity = sympy.Add(*rates) - plain, "Σ p q̇ − L"
        if momenta or forces:
            agrees = _same_value(derived, expected.value, expected)
        else:  # L = … + 5 m g l: another zero of potential, which moves H by a constant
            difference = derived - expected.value
            states = [setting.state[(q, order)] for q in setting.coords for order in (0, 1)]
            agrees = all(_same_value(sympy.diff(difference, s), sympy.S.Zero, expected) for s in (*states, TIME))
    except _CHECK_FAILURES:
        return ()
    details = {"label": "V" if forces else "L", "quantity": quantity}
    return () if agrees else (("derived_disagrees_for_a_person", details),)


def _derived_asked(expected: Expected) -> tuple[list, list, sympy.Symbol | None]:
    """The coordinates whose momenta, and those whose generalized forces, the part asks for (the option
    ``name``), and the working they are derived from: L for a momentum or H, V for a force, else None."""
    asked, coords = expected.option("name") or (), expected.setting.coords
    momenta = [q for q in coords if canonical_name(f"p_{q}") in asked]
    forces = [q for q in coords if canonical_name(f"Q_{q}") in asked]
    return momenta, forces, _LAGRANGIAN if momenta or "H" in asked else _POTENTIAL if forces else None


_WORKING_NAMES = frozenset({"L", "T", "V", "U", "F", "R", "D"})
_RAYLEIGH = sympy.symbols("F R D")  # Rayleigh's dissipation function, as texts name it
_SHAPES = {False: "equation", True: "equations"}


def _dissipative(expected: Expected) -> bool:
    """Whether the expected equation of one coordinate has friction in it: no Lagrangian gives it."""
    if "dissipative" not in expected.cache:
        (equation,) = expected.value if isinstance(expected.value, tuple) else (expected.value,)
        side = equation.lhs - equation.rhs if isinstance(equation, sympy.Eq) else equation
        typed = expected.setting.as_typed(side)  # the reference is kept in plain symbols
        expected.cache["dissipative"] = from_a_lagrangian(typed, expected.setting.coords[0]) is False
    return expected.cache["dissipative"]


def _agrees_at_rest(equation, expected: Expected) -> bool:
    """Whether a Lagrangian's equation (plain symbols) and the expected one, which has friction, are the same
    multiple of one another wherever the velocity is 0: the friction of a dissipation function vanishes there."""
    (q,) = expected.setting.coords
    velocity, acceleration = expected.setting.velocity(q), expected.setting.acceleration(q)
    (reference,) = expected.value if isinstance(expected.value, tuple) else (expected.value,)
    reference = expected.setting.plain(reference.lhs - reference.rhs if isinstance(reference, sympy.Eq) else reference)
    mine, theirs = equation.xreplace({velocity: 0}), reference.xreplace({velocity: 0})
    if not mine.has(acceleration):
        return False  # no kinetic energy: no equation of motion at all
    # A q̈ + B against A' q̈ + B': A' (A q̈ + B) = A (A' q̈ + B') wherever ẋ = 0
    return _same_value(mine * sympy.diff(theirs, acceleration), theirs * sympy.diff(mine, acceleration), expected)


def _without_working(
    answer: ParsedAnswer, spec: Kind, expected: Expected, typed: ParsedAnswer | None = None
) -> tuple[ParsedAnswer, tuple]:
    """``T = ½ m l² θ̇²; V = −m g l cos θ; L = ½ m l² θ̇² + m g l cos θ`` for a Lagrangian, or
    ``L = ½ m l² θ̇² + m g l cos θ; m l² θ̈ + m g l sin θ = 0`` for an equation of motion: lines that
    each give a name of its own to a quantity in the problem's names, a name no other line uses, are
    the working that led to the answer, as on paper. Where an expression is asked for, every line
    must be one, and the answer is the last, named as the answer is (:func:`_names_the_answer`);
    where equations are asked for, the answer is the lines that are not. Where a Lagrangian is asked
    for, the equations of motion derived from it after it (``L = …; m l² θ̈ + m g l sin θ = 0``) are
    left out too. Returns the answer and the notes naming the lines left out, among them the definitions
    put in place (``typed`` is the answer before, see :func:`_definitions_left_out`) in those lines alone."""
    if answer.kind != "equations" or spec.shape is None or spec.name in ("integer", "number"):
        return answer, ()  # a number's working is read where it is asked for (see read_number)
    items = answer.value
    named = [_quantity_named(item, items, expected) for item in items]
    motion = _motion_after(items, named, expected) if spec.name == "lagrangian" else 0
    plural = {"s": "s" if motion > 1 else "", "were": "were" if motion > 1 else "was"}
    notes = (("motion_left_out", plural),) if motion else ()
    items, named = items[: len(items) - motion], named[: len(named) - motion]
    if len(items) == 1:
        return ParsedAnswer(answer.text, items[0], "equation"), notes
    asked = _asked_lines(items, expected) if spec.shape == "expression" else []
    if len(asked) > 1:
        return answer, ()  # two answers for the asked quantity: each line is judged (see _judge_lines)
    if asked and not (asked[0] == len(items) - 1 and all(named)):  # else the last line, after its working
        graded = items[asked[0]]
        others = [_label_of(item.lhs) for item in items if item is not graded]  # T of 2T = …
        others += _definitions_left_out(typed, answer, [graded], expected)
        details = {**_lines_defining(others), "name": _label(graded.lhs, expected)}
        multiples = _multiples_of(graded, items)
        if multiples:  # ω₀ = √(g/l); T = 5 ω₀: T may be the answer, with ω₀'s line its definition
            details["multiples"] = _listing(multiples)
            return ParsedAnswer(answer.text, graded, "equation"), (("others_for_a_person", details), *notes)
        return ParsedAnswer(answer.text, graded, "equation"), (("others_left_out", details), *notes)
    if spec.shape == "expression":
        if not all(named) or not _names_the_answer(named[-1].name, spec):
            return answer, ()
        rest, left = [items[-1]], named[:-1] + _definitions_left_out(typed, answer, items[-1:], expected)
    else:
        rest = [item for item, name in zip(items, named, strict=True) if name is None]
        left = [name for name in named if name is not None]
        if not left or not rest or (spec.shape == "equation" and len(rest) != 1):
            return answer, ()
        left += _definitions_left_out(typed, answer, rest, expected)
    notes = (("working_left_out", _lines_defining(left)), *notes)
    if len(rest) == 1:
        return ParsedAnswer(answer.text, rest[0], "equation"), notes
    return ParsedAnswer(answer.text, tuple(rest), "equations"), notes


def _multiples_of(graded, items) -> list[str]:
    """The labels of ``items`` that each give a quantity as a number times the asked one ``graded`` labels
    (``T = 5 ω₀``, ``f = 2 ω₀``): of its kind, so another value of it, with ``graded`` its definition, as much as
    a quantity derived from it. Not ``T = 2π/ω``, nor ``f = ω/(2π)``, the frequency in cycles, which a
    frequency's line may well be followed by: other quantities, as they should be; nor ``E = H``, the same
    value whichever line is the answer."""
    asked = _label_of(graded.lhs)
    found = []
    for item in items:
        if item is graded or asked not in item.rhs.free_symbols:
            continue
        ratio = item.rhs / asked
        if not ratio.free_symbols and ratio.is_nonzero and ratio not in (1, _CYCLE):
            found.append(_label_of(item.lhs).name)
    return found


_CYCLE = 1 / (2 * sympy.pi)


def _definitions_left_out(
    typed: ParsedAnswer | None, answer: ParsedAnswer, kept: list, expected: Expected
) -> list[sympy.Symbol]:
    """The names of the definitions :func:`_with_definitions` put in place (``typed`` is the answer before)
    that no line of ``kept`` uses, as typed or through another such definition: ``p_θ = m R² θ̇`` put
    into ``H = p_θ²/(2 m R²) − …`` is left out with the line of H, and a note names both."""
    if typed is None or typed.kind != "equations" or typed is answer:
        return []
    before, after = list(typed.value), answer.value
    now = set().union(*(item.free_symbols for item in after))
    removed, remaining = {}, []
    for item in before:
        found = _definition(item, before, expected)
        if found is not None and found[0] not in now and found[0] not in removed:
            removed[found[0]] = item
        else:
            remaining.append(item)
    if not removed or len(remaining) != len(after):
        return []
    # the kept lines as typed: _with_definitions keeps the others in their order
    grown = [line for line, item in zip(remaining, after, strict=True) if any(item is k for k in kept)]
    used: set = set()
    while grown:
        names = {
            name for name in removed for line in grown if name in line.free_symbols or _rates_of(line, name, expected)
        }
        grown = [removed[name] for name in names - used]
        used |= names
    return [name for name in removed if name not in used]


def _lines_defining(names: list) -> dict:
    """How a note names the lines that define ``names``: ``the lines that define `T` and `f` were``."""
    one = len(names) == 1
    return {
        "names": _listing([symbol.name for symbol in names]),
        "lines": "line that defines" if one else "lines that define",
        "were": "was" if one else "were",
    }


def _asked_lines(items, expected: Expected) -> list[int]:
    """Where an answer lists quantities, ``ω = √(g/l); T = 2π√(l/g); f = √(g/l)/(2π)``, and the part
    names the one it asks for (the option ``name``): the positions of the lines labelled so, where
    every line labels a quantity of its own; none where a line labels nothing."""
    names = expected.option("name")
    if not names or len(items) < 2:
        return []
    asked = []
    for number, item in enumerate(items):
        label = _label_of(item.lhs)
        if not isinstance(label, sympy.Symbol) or label == ANSWER or label.name in expected.names:
            return []
        if _is_asked(label.name, names):
            asked.append(number)
    return asked


def _asked_line(items, expected: Expected) -> int | None:
    """The position of the one line labelled with the asked quantity's name (see :func:`_asked_lines`);
    None where no line is, or more than one (``ω = √(l/g); ω₀ = √(g/l)`` is two answers)."""
    asked = _asked_lines(items, expected)
    return asked[0] if len(asked) == 1 else None


def _is_asked(label: str, names: tuple) -> bool:
    """Whether a label names the asked quantity: one of ``names``, spelt with or without its ``_``
    (pφ for p_φ), its stem (p for p_φ), or ∂L/∂φ̇ for p_φ, by its definition."""
    definition = split_quotient(label)
    momentum = definition.by if definition and definition.top == "L" and definition.dotted else None
    same = {label.replace("_", ""), f"p{momentum}" if momentum else None}
    return bool(same & {name.replace("_", "") for name in names}) or label in {name.split("_")[0] for name in names}


def _label_of(side):
    """What a left side names: ω of ω², L of 2L, and the side itself where it is no multiple or power."""
    return side.as_coeff_Mul()[1].as_base_exp()[0]


def _label(side, expected: Expected) -> str:
    """The asked quantity's name as the note says it: ω, whether the student wrote ω or ω²."""
    return expected.setting.describe([_label_of(side).name])


def _motion_after(items: tuple, named: list, expected: Expected) -> int:
    """How many of the last ``items`` are equations of motion (unnamed, in the problem's names, each
    with an acceleration) that follow a line naming L, or quantities named after it (``L = …; p = m l² θ̇;
    m l² θ̈ = …``, which :func:`_asked_lines` leaves out): derived from the answer, not part of it."""
    count = 0
    for item, name in zip(reversed(items), reversed(named), strict=True):
        if name is not None:
            break
        if not accelerations_in(item, expected) or any(
            symbol.name not in expected.names for symbol in item.free_symbols
        ):
            return 0
        count += 1
    if count == len(items) or not any(name is not None and name.name == "L" for name in named[: len(items) - count]):
        return 0
    return count


def _energies_alone(answer: ParsedAnswer, spec: Kind, expected: Expected, deadline) -> Outcome | None:
    """``T = ½ m l² θ̇²; V = −m g l cos θ`` where a Lagrangian is asked for: the two energies, and no
    L. Not the answer, so not equivalent; but the student is told that L = T − V is what is asked
    for, and whether theirs would be right, rather than that T and V are undefined. None for any
    other answer."""
    if spec.name != "lagrangian" or answer.kind != "equations" or len(answer.value) != 2:
        return None
    named = {}
    for item in answer.value:
        name = _quantity_named(item, answer.value, expected)
        named[name.name if name is not None else None] = item.rhs
    if set(named) not in ({"T", "V"}, {"T", "U"}):
        return None
    potential = "V" if "V" in named else "U"
    lagrangian = ParsedAnswer(answer.text, named["T"] - named[potential], "expression")
    right = spec.check(expected, lagrangian, deadline).status == "equivalent"
    key = "energies_without_lagrangian_right" if right else "energies_without_lagrangian"
    return Outcome("not_equivalent", 0.0, key, {"potential": potential}, method="shape")


# The energies a Lagrangian is made of, and the Lagrangian: in working, they come before the answer.
_INGREDIENTS = frozenset({"T", "V", "L"})


def _names_the_answer(name: str, spec: Kind) -> bool:
    """Whether the last line of working may be the answer: ``L = …`` where a Lagrangian is asked for;
    elsewhere a name other than T, V or L (``H = …`` after ``L = …``). ``T = …; V = …`` is not a
    Lagrangian, nor V a kinetic energy."""
    return name == "L" if spec.name == "lagrangian" else name not in _INGREDIENTS


def _quantity_named(item, items: tuple, expected: Expected) -> sympy.Symbol | None:
    """The name ``item`` gives a quantity (``T`` in ``T = ½ m l² θ̇²``) when it is a name the problem
    does not define, the quantity is in the problem's names, and no other of ``items`` uses the name."""
    name = item.lhs
    if not (name.is_Symbol and name != ANSWER and name.name not in expected.names):
        return None
    if is_arbitrary_constant(name.name):
        return None  # C = m l² sin²θ φ̇: a conserved quantity, the equation of motion of φ (see _conserved)
    if any(symbol.name not in expected.names for symbol in item.rhs.free_symbols):
        return None
    if any(name in other.free_symbols for other in items if other is not item):
        return None
    return name


def _loose_definitions(answer: ParsedAnswer) -> bool:
    """Whether an expression came with equations that define none of its names (``½ m v²; u = ẋ``),
    or an equation of a system lacks its ``=``: what is left after the definitions are put in place."""
    return answer.kind == "equations" and answer.value[0].lhs == ANSWER


def _definition(item, items: list, expected: Expected) -> tuple[sympy.Symbol, sympy.Expr] | None:
    """(name, its value) when ``item`` defines a name that another of ``items`` uses; else None.
    The name may carry a power and a number: ``ω₀² = k/m``, ``2γ = b/m``."""
    coefficient, named = item.lhs.as_coeff_Mul()
    base, power = named.as_base_exp()
    if not (base.is_Symbol and base.name not in expected.names and power.is_Integer and power > 0):
        return None
    if not (coefficient.is_Rational and coefficient > 0):
        return None
    if any(symbol.name not in expected.names for symbol in item.rhs.free_symbols):
        return None
    if not any(base in other.free_symbols or _rates_of(other, base, expected) for other in items if other is not item):
        return None
    return base, (item.rhs / coefficient) ** sympy.Rational(1, int(power))  # a positive quantity, as parameters are


def _rates_of(item, name: sympy.Symbol, expected: Expected) -> list[sympy.Derivative]:
    """The rates of a name the answer defines that ``item`` uses: ``ṗ`` for p, of any order."""
    return [rate for rate in own_rates(item, expected.setting.coords) if rate.expr.func.__name__ == name.name]


def _conserved(answer: ParsedAnswer, spec: Kind, expected: Expected, deadline) -> tuple[ParsedAnswer, bool]:
    """``m l² sin²θ φ̇ = const``: a conserved quantity, as the equation of motion of a cyclic
    coordinate is often first written (p_φ = const). Where equations of motion are asked, an
    equation whose one side is an arbitrary constant (``C``, ``C₁``, ``const``, a name the problem
    does not define) and whose other side is a quantity of the motion (coordinates and
    velocities in the problem's names) is read as its time derivative, d/dt (…) = 0.

    Returns the answer and whether any of its equations was so read."""
    if spec.shape not in ("equation", "equations") or answer.kind == "expression":
        return answer, False
    items = answer.value if answer.kind == "equations" else (answer.value,)
    read = []
    for item in items:  # each is within the differentiation budget; dozens of them take a while
        deadline.check()
        read.append(_rate_of_conserved(item, expected))
    if all(item is None for item in read):
        return answer, False
    items = tuple(new if new is not None else old for new, old in zip(read, items, strict=True))
    return ParsedAnswer(answer.text, items if answer.kind == "equations" else items[0], answer.kind), True


def _rate_of_conserved(item: sympy.Eq, expected: Expected) -> sympy.Eq | None:
    """``d/dt (quantity) = 0`` for ``quantity = C``, either way round; None for any other equation."""
    for quantity, constant in ((item.lhs, item.rhs), (item.rhs, item.lhs)):
        if not (constant.is_Symbol and is_arbitrary_constant(constant.name) and constant.name not in expected.names):
            continue
        in_motion = quantity.atoms(AppliedUndef) & set(expected.setting.functions.values())
        names = {symbol.name for symbol in quantity.free_symbols}
        velocities_only = all(d.derivative_count == 1 for d in quantity.atoms(sympy.Derivative))
        if in_motion and names <= expected.names and velocities_only and within_diff_budget(quantity):
            return sympy.Eq(sympy.diff(quantity, TIME), 0, evaluate=False)
    return None


def _said_constant(answer: ParsedAnswer, spec: Kind, expected: Expected) -> tuple[ParsedAnswer, tuple]:
    """``p_φ = m l² sin²θ φ̇ = const`` where an expression is asked: the formula, and a note that the
    answer also says it is conserved, which may be true (p_φ, of a cyclic φ) or not (V), and is not
    what the part asks: a person reads it. Not the name of the quantity asked for, as ``… = C`` would be
    taken for (see :func:`_name_on_the_left`)."""
    value = answer.value
    if spec.shape != "expression" or not isinstance(value, sympy.Eq) or not value.rhs.is_Symbol:
        return answer, ()
    name = value.rhs.name
    if name in expected.names or not is_arbitrary_constant(name) or not value.lhs.free_symbols:
        return answer, ()
    note = ("constant_said_for_a_person", {"said": f"= {unicode_name(name)}"})
    return ParsedAnswer(answer.text, value.lhs, "expression"), (note,)


def _name_on_the_left(answer: ParsedAnswer, spec: Kind, expected: Expected) -> ParsedAnswer:
    """``m l² sin²θ φ̇ = p_φ``: a quantity's value, then its name, read as ``p_φ = m l² sin²θ φ̇``
    where an expression is asked. The right side is a name the problem does not define, alone, or a
    coordinate's rate (``… = ẍ``, or ``… = −ẍ``, left for :func:`_unwrap_named` to negate as ``−ẍ = …``),
    and the left side is in the problem's names (else it is an equation between two of the student's)."""
    value = answer.value
    if spec.shape != "expression" or not isinstance(value, sympy.Eq):
        return answer
    coefficient, rest = value.rhs.as_coeff_Mul()
    rate = coefficient in (1, -1) and isinstance(rest, sympy.Derivative) and isinstance(rest.expr, AppliedUndef)
    if not (value.rhs.is_Symbol or rate or (coefficient == -1 and rest.is_Symbol)):
        return answer
    if rest == ANSWER or (not rate and rest.name in expected.names):
        return answer
    if not value.lhs.free_symbols or any(symbol.name not in expected.names for symbol in value.lhs.free_symbols):
        return answer
    return ParsedAnswer(answer.text, sympy.Eq(value.rhs, value.lhs, evaluate=False), answer.kind)


def _unwrap_named(answer: ParsedAnswer, spec: Kind, expected: Expected) -> ParsedAnswer:
    """``L = ½ m v²`` for a Lagrangian, ``ω = √(g/l)`` or ``ẍ = …`` for an expression: the name is not
    the answer. Nor is ``T − V = …``, a left side only in names the problem does not define."""
    value = answer.value
    if isinstance(value, sympy.Eq) and value.lhs == ANSWER:
        return ParsedAnswer(answer.text, value.rhs, "expression")  # ½ m v², where v = l θ̇: an expression
    if spec.shape != "expression" or not isinstance(value, sympy.Eq) or value.rhs.has(value.lhs):
        return answer
    if _force_named(value.lhs) is not None:  # −∂V/∂θ = …: Q_θ's value, not ∂V/∂θ's
        return ParsedAnswer(answer.text, value.rhs, "expression")
    coefficient, rest = value.lhs.as_coeff_Mul()
    if coefficient == -1 and isinstance(rest, sympy.Derivative | AppliedUndef) and not value.rhs.has(rest):
        return ParsedAnswer(answer.text, -value.rhs, "expression")  # −ẍ = …: the rate's value, negated
    named = isinstance(value.lhs, sympy.Symbol | sympy.Derivative | AppliedUndef)
    undefined = {symbol.name for symbol in value.lhs.free_symbols} - expected.names
    defined = value.lhs.free_symbols - {sympy.Symbol(name) for name in undefined}
    # where a count is asked, 3N = 15 is working, 3N is not the count's name times 3: the value is the last side
    # and where a number is asked, 2.006 s = 2006 ms is the value in two units, not 2.006 times a name s
    if spec.name == "number":
        undefined -= set(SI_UNITS)
    scaled = _scaled_name(value.lhs, undefined, _constants(value.lhs, expected)) if spec.name != "integer" else None
    if scaled is not None:  # 2L = m l² θ̇² + …, L/m = ½ l² θ̇² + …, ω² = g/l: the name's value
        return ParsedAnswer(answer.text, scaled(value.rhs), "expression")
    energies = _in_energies(value.lhs, expected.names)
    multiple = _energy_multiple(value.lhs, expected.option("name"), _energy_sums(expected)) if energies else None
    if multiple is not None:  # V − T = −L, 2(T − V) = 2L: L's value
        return ParsedAnswer(answer.text, value.rhs / multiple, "expression")
    # k L = …: the name times a factor of the student's own is no label, and L is not the value. A
    # sentence read as a product (The Lagrangian is L = …) holds words, which are no factors
    factors = {symbol.name for symbol in value.lhs.free_symbols} - (undefined & _words(value.lhs))
    scaled_by_name = value.lhs.is_Mul and len(factors) > 1
    if named or (undefined and not defined and not value.lhs.atoms(AppliedUndef) and not scaled_by_name):
        return ParsedAnswer(answer.text, value.rhs, "expression")
    if (
        undefined & _DEFINING
        and not scaled_by_name
        and not {symbol.name for symbol in value.rhs.free_symbols} - expected.names
    ):
        return ParsedAnswer(answer.text, value.rhs, "expression")  # p_θ θ̇ − L = …: the definition, worked
    return answer


def _another_name(named: ParsedAnswer, unwrapped: ParsedAnswer, expected: Expected) -> tuple | None:
    """A note where the name :func:`_unwrap_named` took off is not the asked quantity's (the option
    ``name``: the names, as :func:`_names` reads them): ``p_θ = m l² sin²θ φ̇`` where p_φ is asked, or ``f = √(g/l)``
    where ω is. Right as read, it goes to a person (a slip of the label, or two quantities confused);
    p for p_φ is no other name. None where nothing was taken off, or no name is set."""
    names = expected.option("name")
    if not names or unwrapped is named or not isinstance(named.value, sympy.Eq) or named.value.lhs == ANSWER:
        return None
    side = named.value.lhs
    if _in_energies(side, expected.names) and _energy_multiple(side, names, _energy_sums(expected)) is None:
        # T + V = … where L is asked, or where H is and is not the energy
        return ("label_for_a_person", {"label": to_text(side), "name": expected.setting.describe(names[:1])})
    lhs, _ = _over_constants(_label_of(side), _constants(side, expected))  # p_θ of p_θ/m
    described = expected.setting.describe
    rates = dict(_rates_named(names, expected))
    force = _force_named(side)
    if force is not None:  # −∂V/∂r where Q_θ is asked: as typed
        if _is_asked(force, names):
            return None
        said = f"−{unicode_name(lhs.name)}"
    elif isinstance(lhs, sympy.Derivative) and isinstance(lhs.expr, AppliedUndef):
        # where the quantity is named as a coordinate's rate (ẍ), another rate is another quantity:
        # ẋ = (m₁ − m₂) g/(m₁ + m₂) gives a velocity; and where it is not, any rate is (θ̇ = √(g/l) for ω)
        name, order = lhs.expr.func.__name__, lhs.derivative_count
        if rates.get(name) == order:
            return None
        said = unicode_name(name, order)
    elif isinstance(lhs, sympy.Symbol | AppliedUndef):
        label = lhs.name if isinstance(lhs, sympy.Symbol) else lhs.func.__name__
        if _is_asked(label, names) or _measured_as_asked(label, expected):
            return None  # pφ for p_φ, and p; period = 2.006 s
        said = described([label])  # ∂L/∂φ̇ = …, ∂V/∂θ = …: as typed (see unicode_name)
    else:
        return None  # T − V = …, and ẍ = … where the quantity is not named as a rate: no name of one quantity
    asked = _rates_named(names[:1], expected)
    return ("label_for_a_person", {"label": said, "name": unicode_name(*asked[0]) if asked else described(names[:1])})


def _measured_as_asked(label: str, expected: Expected) -> bool:
    """Whether a label is the word for a quantity measured in the part's unit: ``period = 2.006 s`` where the
    period is asked in s. Not "frequency", which is f or ω, in the same units."""
    unit = expected.option("unit")
    dimension = QUANTITY_WORDS.get(label.lower())
    found = unit_named(str(unit)) if unit and dimension else None
    return found is not None and found[1] == DIMENSIONS[dimension]


def _another_count(named: ParsedAnswer, unwrapped: ParsedAnswer, expected: Expected) -> tuple | None:
    """A note where a count is labelled with a name that is not the asked count's: ``k = 15`` or ``N = 6``
    where n = 3N − k is asked, ``3N = 2``, ``T = 2``. Right as read, it goes to a person, as a slip of the
    label or a count of something else (see :func:`_another_name`). None for the asked name, for a word
    for degrees of freedom (``DOF``, ``n_dof``, ``degrees of freedom``) and f or s, as textbooks name the
    count (Landau's s), and for working (``3N − k = 2``), whose value is the count's."""
    names = expected.option("name")
    if not names or unwrapped is named or not isinstance(named.value, sympy.Eq) or named.value.lhs == ANSWER:
        return None
    side = named.value.lhs
    if side.is_Add:
        return None
    labels = [symbol.name for symbol in side.free_symbols]
    if any(_is_asked(label, names) or COUNT_NAME.fullmatch(label) for label in labels):
        return None
    typed = named.text.split("=", 1)[0].strip() if "=" in named.text else to_text(side)
    return ("label_for_a_person", {"label": f"`{shown(typed)}`", "name": expected.setting.describe(names[:1])})


def _force_named(side) -> str | None:
    """``Q_θ`` for the left side ``−∂V/∂θ`` (or ``−∂U/∂θ``), the generalized force as the prompts define
    it (``Q_j = −∂V/∂q_j``); None for any other side."""
    coefficient, quotient = side.as_coeff_Mul()
    found = split_quotient(quotient.name) if coefficient == -1 and quotient.is_Symbol else None
    return canonical_name(f"Q_{found.by}") if found and found.top in "VU" and not found.dotted else None


def _rates_named(names: tuple, expected: Expected) -> list[tuple[str, int]]:
    """The coordinates' rates among the names of the asked quantity, as (coordinate, order): xddot is (x, 2)."""
    return [split for split in map(split_derivative, names) if split and split[0] in expected.setting.coords]


# The sums of the energies that name a quantity: L = T − V, and H = E = T + V (U is V)
_KINETIC, _POTENTIAL, _POTENTIAL_U = sympy.symbols("T V U")
_ENERGIES = frozenset({_KINETIC, _POTENTIAL, _POTENTIAL_U})
_ENERGY_SUMS = {"L": _KINETIC - _POTENTIAL, "H": _KINETIC + _POTENTIAL, "E": _KINETIC + _POTENTIAL}
# where the part says H is not the energy (the option h_is_energy: H = T₂ − T₀ + V on a rotating hoop)
# what a sentence before a formula may name it, where the part names its quantity: "The kinetic energy is …"
# is T, right where T is asked and held against the formula where L is
_ENERGY_NAMES = frozenset({"T", "V"})
_NOT_ENERGY_SUMS = {name: value for name, value in _ENERGY_SUMS.items() if name != "H"}


def _energy_sums(expected: Expected) -> Mapping:
    """The sums of the energies that name a quantity here: H is T + V unless the part says it is not."""
    return _ENERGY_SUMS if expected.option("h_is_energy", True) else _NOT_ENERGY_SUMS


def _others_in_energies(side, name: str, expected: Expected):
    """``side`` with the other quantities it names written as the energies they are here: L as T − V,
    E as T + V, and H as T + V where it is the energy. ``H = 2T − L`` says H = T + V, which a rotating
    hoop's H is not, and ``L = 2T − H`` says L = T − V where H is the energy. A lone name stays, for
    :func:`_definition_judged` to judge as a name (L = E, H = L)."""
    if side.is_Symbol:
        return side
    sums = _energy_sums(expected)
    swaps = {sympy.Symbol(other): sums[other] for other in sums if other != name and other not in expected.names}
    return side.xreplace(swaps)


def _in_energies(side, defined: set[str]) -> bool:
    """Whether a left side is a sum written in T and V (or U) alone, none of them a name the problem
    defines (a tension T): ``T − V``, ``T + U``, ``2(T − V)``."""
    names = side.free_symbols
    return not side.is_Symbol and bool(names) and names <= _ENERGIES and not {name.name for name in names} & defined


def _energy_multiple(side, names, sums: Mapping = _ENERGY_SUMS) -> sympy.Expr | None:
    """The number c where a side in the energies is c times the sum one of ``names`` is, of ``sums``
    (``V − T`` is −1 times L's); None where it is none of them (``T + V`` where L is asked)."""
    side = side.xreplace({_POTENTIAL_U: _POTENTIAL})
    for name in names or ():
        ratio = sympy.cancel(side / sums[name]) if name in sums else None
        if ratio is not None and ratio.is_number and ratio != 0:
            return ratio
    return None


def _words(side) -> set[str]:
    """The names in ``side`` that are words, two letters or more (``The``, ``is``): not a symbol's name (k, p_φ)."""
    return {symbol.name for symbol in side.free_symbols if re.fullmatch(r"[A-Za-z]{2,}", symbol.name)}


_DEFINING = {"L", "H"}  # the names of the quantities H = Σ p q̇ − L defines one by the other


def _scaled_name(lhs, undefined: set[str], constants: Collection[str] = ()):
    """For ``2L`` or ``L/2``, the name times a small fraction, for ``L/m`` or ``2L/(m l²)``, the name
    over the problem's ``constants`` too, and for ``ω²``, ``1/ω`` or ``√ω``, its power: what makes the
    name's value of the other side (halving it, or multiplying it by m; its positive root, as a
    frequency's); None for any other left side."""
    coefficient, rest = lhs.as_coeff_Mul()
    small = coefficient.is_Rational and coefficient.q <= 12 and abs(coefficient.p) <= 100
    rest, over = _over_constants(rest, constants)
    if rest.is_Symbol and rest.name in undefined and coefficient != 0 and (coefficient, over) != (1, 1) and small:
        return lambda rhs: rhs / (coefficient * over)
    base, exponent = lhs.as_base_exp()
    if base.is_Symbol and base.name in undefined and exponent.is_Rational and exponent not in (0, 1):
        return lambda rhs: rhs ** (1 / exponent)
    return None


def _over_constants(side, constants: Collection[str]) -> tuple:
    """``side`` as a name over a product of ``constants``, and that product's reciprocal: (L, 1/m) for
    ``L/m``; (``side``, 1) where it is no such quotient. Over, not times: ``m L = …`` is no way to write
    what L is, and is read as typed."""
    if not side.is_Mul:
        return side, sympy.S.One
    divisors = [
        factor
        for factor in side.args
        if factor.is_Pow and factor.base.is_Symbol and factor.base.name in constants and factor.exp.is_negative
    ]
    if len(divisors) != len(side.args) - 1:
        return side, sympy.S.One
    (name,) = set(side.args) - set(divisors)
    return name, sympy.Mul(*divisors)


def _constants(side, expected: Expected) -> set[str]:
    """The names in ``side`` of the problem's constants (m, l, g): not a coordinate, rate or given name."""
    return {
        symbol.name
        for symbol in side.free_symbols
        if symbol.name in expected.names and not expected.setting.is_state(symbol)
    }


def _square_sign_open(named: ParsedAnswer, spec: Kind, expected: Expected, outcome: Outcome, deadline) -> Outcome:
    """``p_φ² = m² l⁴ sin⁴θ φ̇²``: an even power of the quantity's name, read as its positive root (see
    :func:`_scaled_name`), as a frequency's is. A signed quantity's value need not be that root (here
    m l² sin²θ |φ̇|): where it is not right but the power is the right value's, which root the student
    meant is for a person to say, and nothing is proposed. ``outcome`` as it was otherwise."""
    value = named.value
    if outcome.status == "equivalent" or spec.name != "expression" or not isinstance(value, sympy.Eq):
        return outcome
    base, exponent = value.lhs.as_base_exp()
    if not (base.is_Symbol and base != ANSWER and base.name not in expected.names):
        return outcome
    if not (exponent.is_Integer and exponent > 0 and exponent.is_even):
        return outcome
    equal, _ = same_values(expected, expected.value**exponent, value.rhs, deadline, key=f"power {exponent}")
    if not equal:
        return outcome
    details = {"label": to_text(value.lhs), "power": "a square" if exponent == 2 else "an even power"}
    return Outcome("undecided", 0.0, "square_sign_open", details, method=outcome.method)


def _constant_allowed(spec: Kind, expected: Expected) -> bool:
    """Whether the answer may differ by a constant: a Lagrangian, or an expression with ``up_to_constant``."""
    return spec.name == "lagrangian" or (spec.name == "expression" and bool(expected.option("up_to_constant")))


def _without_arbitrary_constant(answer: ParsedAnswer, spec: Kind, expected: Expected) -> ParsedAnswer:
    """``… + C`` or ``… + const`` where a constant is allowed (a Lagrangian, or an expression with
    ``up_to_constant``): the answer without it, when it is a term of its own and a name the
    problem does not define. Inside a product it stays, and is an undefined name."""
    allowed = _constant_allowed(spec, expected)
    value = answer.value
    if not allowed or answer.kind != "expression":
        return answer
    # V₀ for a potential, L₀ for a Lagrangian: the quantity's own name for its value at the zero chosen, and
    # in a Lagrangian the potential's (L = T − V, with V's zero anywhere)
    named = (*(expected.option("name") or ()), *(("V", "U") if spec.name == "lagrangian" else ()))
    zeros = {f"{name}_0" for name in named}
    present = {
        symbol.name for symbol in value.free_symbols if is_arbitrary_constant(symbol.name) or symbol.name in zeros
    }
    for name in sorted(present - expected.names):
        constant = sympy.Symbol(name)
        rest, term = value.as_independent(constant, as_Add=True)
        if term.free_symbols == {constant} and term.is_polynomial(constant) and sympy.degree(term, constant) == 1:
            return ParsedAnswer(answer.text, rest, "expression")
    return answer


def _without_constant_terms(answer: ParsedAnswer, spec: Kind, expected: Expected) -> tuple[ParsedAnswer, tuple | None]:
    """``½(m₁ + m₂)ẋ² + m₁gx + m₂g(l − x)`` for Atwood's machine, with l the string's length: a name
    the problem does not define, found only in terms that hold no coordinate, velocity or time, is a
    constant of the student's own (a length, another zero of potential energy), where each such term
    is one (:func:`_constant_term`): linear in each such name, as a potential energy is in a height,
    and with names of the problem's in it. Where a constant is allowed, those terms are left out, and the note
    says so; a name found in any other term is said as undefined, as usual. The terms are expanded
    one by one, each within the differentiation budget, so that m₂g(l − x) gives up m₂gl and keeps
    −m₂gx.

    A name written beside a coordinate, as l in m₂g(l − x), measures from where the motion is, and
    is taken as a constant. A name only in terms of its own, as h in ``… + m g h``, may as well be a
    height that moves with the bob (``− m g z``): the note is then ``constant_unsure``, and an answer
    right only with it taken as a constant goes to a person (see :func:`_for_a_person`)."""
    allowed = _constant_allowed(spec, expected)
    undefined = _undefined_symbols(answer, expected)
    if not allowed or answer.kind != "expression" or not undefined:
        return answer, None
    motion = (*expected.setting.functions.values(), TIME)
    kept, tied = [], set()
    for term in sympy.Add.make_args(answer.value):
        if not term.free_symbols & undefined:
            kept.append(term)
            continue
        if term.has(*motion):
            tied |= term.free_symbols & undefined
        if not within_diff_budget(term):
            return answer, None
        for part in sympy.Add.make_args(sympy.expand(term)):
            if part.free_symbols & undefined and not _constant_term(part, undefined, motion):
                return answer, None
            if not part.free_symbols & undefined:
                kept.append(part)
    names = _listing([symbol.name for symbol in undefined])
    one = len(undefined) == 1
    details = {
        "names": names,
        "appear": "appears" if one else "appear",
        "terms": "a term" if one else "terms",
        "which": "a Lagrangian may have and which changes no equation of motion"
        if spec.name == "lagrangian"
        else "this answer may have, as another zero of potential energy",
    }
    if undefined - tied:  # m g h alone: a height of the student's own, or one that moves?
        details |= {"them": "it" if one else "them", "changes": "changes" if one else "change"}
        note = ("constant_unsure", details)
    else:
        note = ("constant_terms_left_out", details)
    return ParsedAnswer(answer.text, sympy.Add(*kept), "expression"), note


# Notes on a reading that a person must confirm before the answer earns credit, each with the note
# it becomes where the answer earns none either way: a name of the student's own alone in a term,
# as a constant (``− m g z``); words after the formula that may say otherwise (``… upward``).
_FOR_A_PERSON = {
    "constant_unsure": "constant_terms_left_out",
    "words_for_a_person": "words_read_past",
    "unit_for_a_person": "unit_left_out",
    "label_for_a_person": "label_other",
    "statement_for_a_person": "statement_wrong",
    "working_false_for_a_person": "working_false",
    "energies_disagree_for_a_person": "energies_disagree",
    "kinetic_moves_for_a_person": "kinetic_moves",
    "potential_moves_for_a_person": "potential_moves",
    "lagrangian_disagrees_for_a_person": "lagrangian_disagrees",
    "lagrangian_unchecked_for_a_person": "lagrangian_unchecked",
    "derived_disagrees_for_a_person": "derived_disagrees",
    "constant_said_for_a_person": "constant_said",
    "given_redefined_for_a_person": "given_redefined",
    "momentum_spelt_for_a_person": "momentum_spelt",
    "others_for_a_person": "others_left_out",
}


# the notes for a person that say nothing of whether the value is right: of one right only in part, as true
_TRUE_IN_PART = frozenset({"constant_unsure", "words_for_a_person"})


# the diagnoses of a value that is right as read, where how it was read is for a person to confirm (a wrong
# Euler–Lagrange operator before it too, or a premise it does not follow from, which compare finds once the
# value is judged)
READINGS_FOR_A_PERSON = frozenset(_FOR_A_PERSON) | {
    "operator_for_a_person",
    "premise_for_a_person",
    "premise_value_for_a_person",
    "premise_undefined_for_a_person",
}
# the diagnoses of a value that is wrong only for the decimals that round its exact numbers (6.28 for 2π)
ROUNDED = frozenset({"rounded_decimal", "rounded_decimals"})


def _for_a_person(outcome: Outcome, notes: tuple) -> tuple[Outcome, tuple]:
    """An answer that earns credit only as it was read, where a person must confirm the reading: the
    outcome becomes undecided, the credit proposed, and the student is told on what it rests. Where
    it earns none, the notes only say how it was read. Returns the outcome and the notes left."""
    unsure = [note for note in notes if note and note[0] in _FOR_A_PERSON]
    if not unsure:
        return outcome, notes
    direction = next((note for note in unsure if note[0] == "words_for_a_person"), None)
    if direction and outcome.key == "sign":
        # −(m₁ − m₂) g/(m₁ + m₂), upwards: the words may be what turns the sign; nothing is proposed
        outcome = replace(outcome, status="undecided", key="sign_words_for_a_person", details=direction[1])
        return outcome, tuple(note for note in notes if note is not direction)
    if outcome.score == 0:
        if outcome.key == "t_plus_v":  # L = T + V = …, as its value says too: said once
            notes = tuple(note for note in notes if not note or note[0] != "statement_for_a_person")
        return outcome, tuple((_FOR_A_PERSON.get(note[0], note[0]), note[1]) if note else note for note in notes)
    if outcome.score < 1 and outcome.status != "equivalent":
        # right in part (2 (T − V), V − T): a note that says "it is right" would be false. It is said as of a
        # wrong answer, after the diagnosis; a person still confirms the proposed credit
        if outcome.key == "v_minus_t":  # L = V − T = …, as its value says too: said once
            notes = tuple(note for note in notes if not note or note[0] != "statement_for_a_person")
            unsure = [note for note in notes if note and note[0] in _FOR_A_PERSON]
            if not unsure:
                return outcome, notes
        notes = tuple(
            (_FOR_A_PERSON[note[0]], note[1]) if note and note[0] in _FOR_A_PERSON and note[0] not in _TRUE_IN_PART
            else note
            for note in notes
        )  # fmt: skip
        unsure = [note for note in notes if note and note[0] in _FOR_A_PERSON]
        if not unsure:
            return replace(outcome, status="undecided"), notes
    said = ((outcome.key, outcome.details),) if outcome.key and outcome.status != "equivalent" else ()
    (key, details), *others = unsure
    outcome = replace(outcome, status="undecided", key=key, details=details, more=(*others, *said, *outcome.more))
    return outcome, tuple(note for note in notes if note not in unsure)


# the readings of a number that leave which number is meant to a person (see grader.judge.numbers.read_number)
_NUMBER_FOR_A_PERSON = frozenset(
    {
        "count_bracket_for_a_person",
        "counts_differ_for_a_person",
        "number_doubted_for_a_person",
        "number_qualified_for_a_person",
        "unit_unknown_for_a_person",
    }
)


def _count_unclear(spec: Kind, expected: Expected, outcome: Outcome, notes: tuple, deadline) -> tuple[Outcome, tuple]:
    """A count whose bracket leaves unclear which number it is (``1 (2)``, see
    :func:`~grader.judge.numbers.read_number`): for a person, whatever it would earn. One read as the
    count with its working (``2 (3 − 1)``), or written close as a product (``2(3 − 1)``), where it earns
    nothing so but would the other way: for a person too. In both, nothing is proposed: the reading
    that earns is not the likelier one. So too a number beside words that may take it back or doubt it
    (``6 − 4 = 2? no, 4``), or make it another (``at most 2``). Returns the outcome and the notes left."""
    unclear = next((note for note in notes if note and note[0] in _NUMBER_FOR_A_PERSON), None)
    if unclear is not None:
        return Outcome("undecided", 0.0, *unclear, method=outcome.method), ()
    other = next((note for note in notes if note and note[0] == "other_reading"), None)
    if other is None:
        return outcome, notes
    notes = tuple(note for note in notes if note is not other)
    if outcome.score > 0:
        return outcome, notes
    read = parse_answer(other[1]["other"], deadline=deadline)
    if not (read.ok and spec.check(expected, read, deadline).score > 0):
        return outcome, notes
    details = {"typed": other[1]["typed"]}
    return Outcome("undecided", 0.0, "count_or_product_for_a_person", details, method=outcome.method), ()


def _constant_term(term: sympy.Expr, names: set, motion: tuple) -> bool:
    """Whether a term in ``names`` (the student's own) is a constant of theirs: ``m₂ g l``, with the
    problem's names in it too, of degree one in each of theirs, and no coordinate, velocity or time
    (``motion``). Not ``m l ẋ²``; not ``½ m v²`` or ``p²/2m``, a speed's or a momentum's; not ``T`` or
    ``V`` alone, the quantities of ``L = T − V``."""
    if term.has(*motion) or not term.free_symbols - names:
        return False
    return all(term.is_polynomial(name) and sympy.degree(term, name) == 1 for name in term.free_symbols & names)


def _read(
    spec: Kind, expected: Expected, submitted: str, names: list, deadline
) -> tuple[ParsedAnswer | Refusal, tuple]:
    """The submitted answer read, and notes on how: a number found in what was written around it
    (:func:`~grader.judge.numbers.read_number`), or a formula without the words after it."""
    coords = expected.setting.coords
    if spec.name not in ("integer", "number"):
        answer = parse_answer(submitted, coords=coords, known=names, deadline=deadline)
        defined = _names_defined(answer, names)
        if defined:  # mr² φ̇, r = l sin θ: r is the answer's own name, and mr is m r
            again = parse_answer(submitted, coords=coords, known=[*names, *defined], deadline=deadline)
            known = {*names, *defined, TIME.name}
            glued = {symbol.name for symbol in answer.symbols} - known
            # only where it splits a glued name: xdot, where x = l sin θ, is the rate of x as read
            if again.ok and {symbol.name for symbol in again.symbols} - known < glued:
                answer = again
        answer = _working_before_steps(answer, submitted, spec, expected, names, deadline)
        if answer.ok and _dimensions_tail(submitted, spec, expected) is not None:
            return answer, ()  # … [ML²T⁻²]: dimensions, not words (see _formula_in_unit)
        answer, notes = _without_words(answer, submitted, expected, names, deadline)
        said = words_in(submitted, names, coords) if expected.option("asks_more") and not notes else None
        if said:  # Dimension of force: Q_θ = …, the label the parser reads past with its colon
            notes = (("words_for_a_person", {"words": shown(said)}),)
        return answer, notes
    reads = partial(_as_number, spec=spec, expected=expected, names=names, deadline=deadline)
    unit = str(expected.option("unit") or "") if spec.name == "number" else ""
    measured = spec.name == "number"  # a count has no decimal comma, nor an uncertainty
    text, answer, notes = read_number(
        submitted,
        reads,
        names,
        decimal_comma=measured,
        unit=unit,
        uncertainty=measured,
        count=not measured,
        asked=expected.option("name") or (),
    )
    if answer is None:  # what read_number could not read: as typed, and said why
        answer = parse_answer(text, coords=coords, known=names, deadline=deadline)
    return answer, notes


def _working_before_steps(answer, submitted: str, spec: Kind, expected: Expected, names: list, deadline):
    """What the parser left behind a derivation's steps (⇒, so, therefore), kept as lines of working where
    a check judges it. ``L = ½ m l² θ̇² + m g l cos θ, so m l² θ̈ = −m g l sin θ`` where a Lagrangian is asked:
    the parser keeps the step's conclusion, an equation of motion; read as the Lagrangian, then the
    equations it derives, which are left out and said so (:func:`_without_working`). ``answer`` where
    the text is not ``L = …`` and then, after each step, an equation with an acceleration or a quantity
    named (``⇒ p = m l² θ̇``: :func:`_quantity_named`), and no L.

    Where equations of motion are asked, ``L = …, so eq₁; eq₂``: the conclusion the parser kept, after
    the L it says it came from, which is working (:func:`_lagrangian_disagrees` checks it); the steps
    between are left out, as they were. So too where a momentum or H is asked, after an L (``L = …, so
    p_φ = …``), or a generalized force after a V: :func:`_derived_disagrees` checks that working; and T
    and V before L or H (:func:`_energies_then_value`)."""
    motion = spec.shape in ("equation", "equations")
    if spec.name == "expression":
        energies = _energies_then_value(answer, submitted, expected, names, deadline)
        if energies is not answer:
            return energies
        return _working_then_derived(answer, submitted, expected, names, deadline)
    if (spec.name != "lagrangian" and not motion) or not answer.ok:
        return answer
    if answer.kind not in (("equation", "equations") if motion else ("equation",)):
        return answer
    if len(submitted) > _STEPS_LENGTH and not motion:  # an L and two equations of motion run longer
        return answer
    concluded = answer.value if answer.kind == "equations" else (answer.value,)
    lines = _STEP.sub("\n", submitted)
    if lines == submitted:
        return answer
    if concluded[0].lhs == _LAGRANGIAN:
        return answer if motion else _energies_then_value(answer, submitted, expected, names, deadline)
    read = parse_answer(lines, coords=expected.setting.coords, known=names, deadline=deadline)
    if not read.ok or read.kind != "equations" or read.value[0].lhs != _LAGRANGIAN:
        return answer
    derived = read.value[1:]
    if motion:
        if any(item.has(_LAGRANGIAN) or not accelerations_in(item, expected) for item in derived):
            return answer
        if tuple(derived[-len(concluded) :]) != tuple(concluded):
            return answer
        return ParsedAnswer(read.text, (read.value[0], *concluded), "equations")
    # L = …, so p = m l² θ̇: a quantity of its own derived from L, left out as after a semicolon
    if any(
        item.has(_LAGRANGIAN)
        or not (accelerations_in(item, expected) or _quantity_named(item, read.value, expected) is not None)
        for item in derived
    ):
        return answer
    return read


def _energies_then_value(answer, submitted: str, expected: Expected, names: list, deadline):
    """``T = ½ m l² θ̇², V = m g l cos θ ⇒ L = …`` (or ``⇒ H = …``): the energies the parser left behind the
    step, then the L or H it kept, as on separate lines, where :func:`_energies_disagree` judges them (before,
    the working was dropped unseen). ``answer`` where the conclusion is not L, H or E, or a line before it
    is not T, V or U."""
    if not (answer.ok and answer.kind == "equation" and answer.value.lhs in _ENERGY_SYMBOLS):
        return answer
    lines = _STEP.sub("\n", submitted)
    if lines == submitted or len(submitted) > _STEPS_LENGTH:
        return answer
    read = parse_answer(lines, coords=expected.setting.coords, known=names, deadline=deadline)
    if not read.ok or read.kind != "equations" or read.value[-1] != answer.value:
        return answer
    if any(item.lhs not in _STATED_BEFORE_L for item in read.value[:-1]) or _DEFINING_LETTERS & expected.names:
        return answer
    return read


_STATED_BEFORE_L = frozenset({_KINETIC, _POTENTIAL, _POTENTIAL_U})
_ENERGY_SYMBOLS = frozenset(map(sympy.Symbol, _ENERGY_SUMS))  # L, H, E


def _working_then_derived(answer, submitted: str, expected: Expected, names: list, deadline):
    """``L = ½ m l² φ̇², so p_φ = m l² sin²θ φ̇`` where the momentum is asked (or H after an L, a generalized
    force after a V): the L the parser left behind the step, then the conclusion it kept, as after a
    semicolon; the steps between are left out. A conclusion that is a value alone (``L = … ⇒ m l² sin²θ φ̇``)
    is named as the part asks, so the L is checked against it too. ``answer`` where the text is not so."""
    momenta, forces, label = _derived_asked(expected)
    if label is not None and not answer.ok and len(submitted) <= _STEPS_LENGTH:
        bare = _value_after_word(submitted, expected, names, deadline)
        read = _working_then_derived(bare, submitted, expected, names, deadline) if bare else bare
        return answer if read is bare else read  # refused as typed where no L stands before the word
    if label is None or not answer.ok or answer.kind not in ("equation", "expression"):
        return answer
    stated = {label, _POTENTIAL_U} if label == _POTENTIAL else {label}
    concluded = answer.value
    if len(submitted) > _STEPS_LENGTH or (answer.kind == "equation" and answer.value.lhs in stated):
        return answer
    if concluded.has(*stated) or not _STEP.search(submitted):
        return answer
    pieces = _STEP.split(submitted)
    coords = expected.setting.coords
    first = parse_answer(pieces[0].strip(" ,;:"), coords=coords, known=names, deadline=deadline)
    last = parse_answer(pieces[-1].strip(" ,;:."), coords=coords, known=names, deadline=deadline)
    if not (first.ok and first.kind == "equation" and first.value.lhs in stated and last.ok):
        return answer
    if last.kind != answer.kind or last.value != answer.value:
        return answer
    if answer.kind == "expression":
        name = canonical_name(f"p_{momenta[0]}") if momenta else canonical_name(f"Q_{forces[0]}") if forces else "H"
        if answer.value.has(sympy.Symbol(name)):
            return answer  # ⇒ p_φ: the name alone, no value, which p_φ = p_φ would not show
        concluded = sympy.Eq(sympy.Symbol(name), answer.value, evaluate=False)
    return ParsedAnswer(submitted, (first.value, concluded), "equations")


def _value_after_word(submitted: str, expected: Expected, names: list, deadline) -> ParsedAnswer | None:
    """``…, so m l² sin²θ φ̇``: the value alone after the one word that steps from what stands before
    it (the tokenizer reads so, hence, thus, therefore as ⇒ only between equations), for
    :func:`_working_then_derived` to read as after ⇒; None where the text is no such answer."""
    pieces = _STEP.split(submitted)
    if len(pieces) != 2 or not _STEP.search(submitted)[0].strip(" ,").isalpha():
        return None
    last = parse_answer(pieces[-1].strip(" ,;:."), coords=expected.setting.coords, known=names, deadline=deadline)
    if not (last.ok and last.kind == "expression"):
        return None
    # ``so that …``, ``so we get …``: words left between the step and the value would be read as its factors
    return None if {symbol.name for symbol in last.value.free_symbols} - expected.names - {TIME.name} else last


# a step of a derivation: ⇒ and its spellings, and the words the tokenizer reads as one (…, so …)
_STEP = re.compile(
    r"\s*(?:⇒|⟹|→|=>|->|\\(?:Rightarrow|Longrightarrow|implies)(?![A-Za-z])|,?\s*\b(?:so|hence|thus|therefore)\b,?)\s*"
)
_STEPS_LENGTH = 400  # characters: a longer answer is read as typed


def _names_defined(answer: ParsedAnswer, names: list) -> list[str]:
    """The names an answer defines for itself (``…, r = l sin θ``) that the problem does not: the
    left side of an equation of a list that is a name alone (or its power)."""
    if not answer.ok or answer.kind != "equations":
        return []
    bases = [_label_of(item.lhs) for item in answer.value if item.lhs != ANSWER]
    defined = {base.name for base in bases if base.is_Symbol and base.name not in names}
    return sorted(defined | {name for base in bases if (name := _difference_name(base, names))})


_DIFFERENCE = frozenset({"Delta", "delta"})


def _difference_name(side, names: list) -> str | None:
    """``Δθ = θ₁ − θ₂``: read as Δ·θ, the name of a difference the answer defines (``Deltatheta``, as
    the parser spells Δθ); None for any other side, and where the problem has a Δ of its own."""
    if not side.is_Mul or len(side.args) != 2 or not all(arg.is_Symbol for arg in side.args):
        return None
    delta = [arg for arg in side.args if arg.name in _DIFFERENCE]
    if len(delta) != 1 or delta[0].name in names:
        return None
    (other,) = set(side.args) - set(delta)
    return f"{delta[0].name}{other.name}"


def _without_words(
    answer: ParsedAnswer, submitted: str, expected: Expected, names: list, deadline
) -> tuple[ParsedAnswer, tuple]:
    """``θ̈ = −(g/l) θ for small angles``, ``m l² sin²θ φ̇ (conserved)``, ``The angular frequency is
    √(g/l)``: the formula, read without the words after or before it, where the answer as typed
    cannot be read or uses names the problem does not have; and the notes that say so. So too
    ``Since L = T − V, L = …``, read as the chain ``L = T − V = …`` it states. Otherwise the answer
    as it was read, and no note."""
    if answer.ok and not _undefined(answer, names):
        zero = _ZERO_THEN_WORDS.search(submitted)
        if zero is None:
            return answer, ()
        # … = 0 (inverted): 0 times the words is 0, and they were lost. Read past as prose, as after any
        # formula; else (… = 0 (or minus), a hedge) read with them kept, as they are after any other side
        read = _formula_before_words(submitted, expected, names, deadline)
        if read is not None:
            return read
        kept = parse_answer(
            submitted[: zero.start()] + "1" + submitted[zero.start() + 1 :],
            coords=expected.setting.coords, known=names, deadline=deadline,
        )  # fmt: skip
        return (kept if kept.ok and _undefined(kept, names) else answer), ()
    coords = expected.setting.coords
    submitted = text_as_words(submitted, names, coords)  # … = 0 \text{(damped)}: TeX's text is words too
    submitted = tex_math_as_words(submitted)  # Since $L = T − V$, $L = …$: the sentence, without its $s
    # the formula before words, where it leaves a name undefined (Since L = T − V, L = … (taking V = 0 at
    # the pivot)), is said as read only where no reading of words before it leaves none
    without = _formula_before_words(submitted, expected, names, deadline)
    if without is not None and not _undefined(without[0], names):
        return without
    # Dimension of force: Q_θ = …, a line's label the parser read past: no sentence before its own label
    labelled = answer.ok and not _undefined(_without_label(answer), names)
    for words, formula in words_then_formula(submitted, names, coords):
        before = (_words_note("words_before_left_out", words, expected), {"words": shown(words)})
        read = parse_answer(formula, coords=coords, known=names, deadline=deadline)
        zero = _ZERO_THEN_WORDS.search(formula)  # … = 0 is wrong: 0 times the words is 0, as at the top
        # The generalized force along r is Q_r = …: a label the sentence names is no undefined name
        undefined = _undefined(read if labelled else _without_label(read), names) if read.ok else True
        if not undefined and zero is None:
            return read, (before,)
        after = _formula_before_words(formula, expected, names, deadline)
        # The Hamiltonian is H = …, the total energy: the label H is named by the sentence, not undefined
        if after is not None and not _undefined(_without_label(after[0]), names):
            return after[0], (before, *after[1])
        if read.ok and not _undefined(read, names):
            return read, (before,)
    for words, _, _, equation in euler_lagrange_then_formula(submitted, names, coords):
        # Applying d/dt(∂L/∂θ̇) − ∂L/∂θ = 0: m l² θ̈ + …, the operator read past (compare judges it)
        read, after = _read_with_remark(equation, expected, names, deadline)
        if read.ok and read.kind == "equation":
            return read, ((_words_note("words_before_left_out", words, expected), {"words": shown(words)}), *after)
    for words, definition, chain in definition_then_formula(submitted, names, coords):
        read, after = _read_with_remark(chain, expected, names, deadline)
        if _states_one_definition(read, expected):
            chained = {"words": shown(words), "chain": f"{definition} = …"}
            return read, ((_words_note("definition_in_words", words, expected), chained), *after)
    # a name the problem gives a meaning (p_θ) is the student's to define too, as after the formula (…, where p_θ = …)
    before = definition_before_formula(submitted, sorted(expected.names), coords)
    if before is not None:  # With p_θ = m R² θ̇: H = …, read as H = …, where p_θ = m R² θ̇ is
        words, definition, formula = before
        read = parse_answer(f"{formula}, where {definition}", coords=coords, known=names, deadline=deadline)
        if read.ok and not _unknown_in_items(read, names):
            if not _uses_defined(formula, definition, coords, names):
                return _unused_definition(read, words, definition, formula, expected, names, deadline)
            said = {"words": shown(words), "definition": definition}
            return _asked_put_in(read, expected), ((_words_note("definition_before", words, expected), said),)
    return without if without is not None else (answer, ())


def _asked_put_in(read: ParsedAnswer, expected: Expected) -> ParsedAnswer:
    """``Let ω₀² = g/l. The frequency is f = 2 ω₀``, read as ``f = 2 ω₀, where ω₀² = g/l``: a sentence that
    defines the asked quantity, then hands over to the value of another. The value handed over to is the
    answer, with the definitions put in (f = 2 √(g/l)), as for a name of the student's own; left as lines,
    the definition of ω₀ would be graded, and the value the answer gives not at all. ``read`` where the
    value is labelled with the asked quantity (ω = ω₀) or the problem's own name, or a definition is no
    plain one."""
    if read.kind != "equations":
        return read
    formula, *definitions = read.value
    asked, label = expected.option("name") or (), formula.lhs
    if not label.is_Symbol or label.name in expected.names or _is_asked(label.name, asked):
        return read
    found = [_definition(item, list(read.value), expected) for item in definitions]
    if None in found or not any(_is_asked(name.name, asked) for name, _ in found):
        return read
    value = formula.rhs.xreplace(dict(found))
    return ParsedAnswer(read.text, sympy.Eq(label, value, evaluate=False), "equation")


def _asked_defined_after(answer: ParsedAnswer, expected: Expected) -> ParsedAnswer:
    """``f = 2 ω₀, where ω₀² = g/l``: a value, then a clause that defines the asked quantity, which the value
    uses. The value before the clause is the answer, read as a sentence that defines first hands over to it
    (:func:`_asked_put_in`); else the line that defines the asked quantity would be graded, and the value not at
    all. ``answer`` where no ``where`` or ``with`` follows its first line, and that line alone."""
    if answer.kind != "equations":
        return answer
    clause = _DEFINING_CLAUSE.search(answer.text)
    first = answer.text[: clause.start()] if clause else ""
    if first.count("=") != 1 or any(mark in first for mark in ";\n"):
        return answer  # ω = √(g/l); T = 2π/ω, where …: which line the clause is of is not the text's to say
    return _asked_put_in(answer, expected)


_DEFINING_CLAUSE = re.compile(r"(?<![\w\\])(?:where|with)(?!\w)", re.I)


def _unused_definition(
    read: ParsedAnswer, words: str, definition: str, formula: str, expected: Expected, names: list, deadline
) -> tuple[ParsedAnswer, tuple]:
    """``With M = m₁ + m₂: ẍ = g (m₁ − m₂)/(m₁ + m₂)``: a name of the student's own, defined and then not
    used, is the formula alone and a note that says so; ``read``, the formula with its definition, where
    the name is the problem's or one whose definitions are judged (``With L = …``: a line of working)."""
    coords = expected.setting.coords
    defined = parse_answer(definition, coords=coords, known=names, deadline=deadline)
    alone = parse_answer(formula, coords=coords, known=names, deadline=deadline)
    if not (defined.ok and defined.kind == "equation" and defined.value.lhs.is_Symbol) or not alone.ok:
        return read, ()
    name, side = defined.value.lhs, defined.value.rhs
    if name.name in names or name.name in _INGREDIENTS or _definition_judged(name, side, expected) is not None:
        return read, ()  # With L = …: m l² θ̈ = …: L is working, which a note on the lines says, not put in
    if _is_asked(name.name, expected.option("name") or ()) or _momentum_spelt(name.name, expected):
        # Let a = g. Then ẍ = …: a second value of the asked quantity; Let pθ = 2 m l² θ̇. Then H = p_θ²/…: the
        # momentum the formula uses, spelt another way. Neither is a name of the student's own
        return read, ()
    if _undefined(_without_label(alone), names):
        return read, ()  # ω = √(g/l): the label the answer names, the part judges (see _another_name)
    return alone, (("definition_unused", {"words": shown(words), "definition": definition}),)


def _momentum_spelt(label: str, expected: Expected) -> str | None:
    """The momentum (``p_theta``) a label may name spelt another way: pθ or P_θ for p_θ, p₁ for the first
    coordinate's, and P where there is one coordinate; None for any other label."""
    coords = expected.setting.coords
    spellings = {f"p{q}".replace("_", "").lower(): q for q in coords}
    spellings |= {f"p{i}": q for i, q in enumerate(coords, 1)} | ({"p": coords[0]} if len(coords) == 1 else {})
    q = spellings.get(label.replace("_", "").lower())
    return canonical_name(f"p_{q}") if q else None


def _uses_defined(formula: str, definition: str, coords, names: list) -> bool:
    """Whether ``formula`` uses the name ``definition`` gives a value (``H = p_θ²/…`` with ``p_θ = …``)."""
    defined = parse_answer(definition, coords=coords, known=names)
    if not defined.ok or defined.kind != "equation" or not defined.value.lhs.is_Symbol:
        return True  # as before: the definition is put in as typed
    name = defined.value.lhs
    read = parse_answer(formula, coords=coords, known=[*names, name.name])
    return not read.ok or name in read.symbols


def _unknown_in_items(read: ParsedAnswer, names: list) -> bool:
    """Whether an answer uses a name neither the problem's nor one an item of it gives a value (``H``, ``p_θ``)."""
    items = read.value if read.kind == "equations" else (read.value,)
    # ω₀² = g/l defines ω₀, as _definition reads it
    labels = {item.lhs.as_coeff_Mul()[1].as_base_exp()[0] for item in items if isinstance(item, sympy.Eq)}
    return any(symbol not in labels and symbol.name not in names for symbol in read.symbols)


def _read_with_remark(text: str, expected: Expected, names: list, deadline) -> tuple[ParsedAnswer | Refusal, tuple]:
    """``text`` read, or without a remark after it where as typed it cannot be read or leaves a name
    unknown (``…, L = ½ m l² θ̇² + … (taking V = 0 at the pivot)``); and the notes on the remark."""
    read = parse_answer(text, coords=expected.setting.coords, known=names, deadline=deadline)
    if _unknown_in_chain(read, names):
        remark = _formula_before_words(text, expected, names, deadline)
        if remark is not None and not _unknown_in_chain(remark[0], names):
            return remark
    return read, ()


def _unknown_in_chain(read: ParsedAnswer | Refusal, names: list) -> bool:
    """Whether a chain could not be read, or uses names neither the problem's nor the one it gives a value."""
    if not read.ok:
        return True
    labels = {statement.lhs for statement in read.stated}
    return any(symbol not in labels and symbol.name not in names for symbol in read.symbols)


def _states_one_definition(read: ParsedAnswer | Refusal, expected: Expected) -> bool:
    """Whether ``Since L = T − V, L = …``, read as the chain ``L = T − V = …`` it states
    (:func:`~grader.judge.words.definition_then_formula`), is that chain: the parser read a definition
    on its way, one whose rightness is known (:func:`_definition_judged`: a right one is read past, a
    wrong one goes to a person, as a chain's does), and no other item gives the quantity a value
    (``…, L = …, L = …``: which is the answer?)."""
    if not read.ok or not read.stated or read.kind == "expression":
        return False
    if any(_definition_judged(statement.lhs, statement.rhs, expected) is None for statement in read.stated):
        return False
    items = read.value if read.kind == "equations" else (read.value,)
    return sum(item.lhs == read.stated[-1].lhs for item in items) == 1


# a zero, then a word or a bracket that opens one: … = 0 (inverted), … = 0 or not
_ZERO_THEN_WORDS = re.compile(r"(?<![\w.])0\s*[(\[]?\s*[^\W\d_]")


def _formula_before_words(text: str, expected: Expected, names: list, deadline) -> tuple[ParsedAnswer, tuple] | None:
    """The formula of ``text`` read without the words after it, and the note; None where there is none."""
    for formula, words in formula_then_words(text, names, expected.setting.coords):
        read = parse_answer(formula, coords=expected.setting.coords, known=names, deadline=deadline)
        if read.ok:  # a name of its own left in the formula (v, where v is the speed) is said as usual
            return read, ((_words_note("words_left_out", words, expected), {"words": shown(words)}),)
    convention = formula_then_convention(text, names)  # … (taking V = 0 at the pivot): the zero, stated
    if convention is not None:
        formula, remark = convention
        read = parse_answer(formula, coords=expected.setting.coords, known=names, deadline=deadline)
        if read.ok:
            return read, ((_words_note("words_left_out", remark, expected), {"words": shown(remark)}),)
    return None


def _words_note(key: str, words: str, expected: Expected) -> str:
    """The note on words read past: for a person to read first where the part asks for more than the
    formula (the option ``asks_more``: its dimensions, say), where they may say otherwise
    (:func:`~grader.judge.words.says_otherwise`), or name a quantity other than the one the part names
    (the option ``name``; L where a Lagrangian is asked). After the formula, any quantity named says what
    it is (``…, which is the Hamiltonian``); before it, a sentence names what follows (``The Lagrangian
    is …``), and only the Lagrangian, the Hamiltonian or the energy, where the part names its own, is
    held against it (``The Hamiltonian is …`` where L is asked)."""
    # words after a formula may hold arithmetic (… (half the power dissipated)); before it, the words
    # read past may hold the definition or the operator that led to it, which are judged on their own
    if says_otherwise(words, formula=key == "words_left_out") or expected.option("asks_more"):
        return "words_for_a_person"  # where the prompt asks for more than the formula, words may be the more
    named, asked = quantities_named(words), set(expected.option("name") or ())
    if key != "words_left_out":
        named = named & (_ENERGY_SUMS.keys() | _ENERGY_NAMES) if asked else set()
    return "words_for_a_person" if named - asked else key


def _undefined(answer: ParsedAnswer, names: list) -> bool:
    return any(symbol.name not in names for symbol in answer.symbols)


def _without_label(answer: ParsedAnswer) -> ParsedAnswer:
    """``H = …`` as its value, where the left side is a name alone, or its power: ``ω² = …`` labels the
    frequency as ``ω² = g/l`` alone does (what its value then is, the answer's reading says); any other answer as
    it is."""
    value = answer.value
    label = value.lhs.base if answer.kind == "equation" and value.lhs.is_Pow and value.lhs.exp.is_Integer else None
    if answer.kind == "equation" and (label or value.lhs).is_Symbol and (label or value.lhs) != TIME:
        return ParsedAnswer(answer.text, value.rhs, "expression")
    return answer


def _as_number(
    text: str, *, spec: Kind, expected: Expected, names: list, deadline, working: bool = False, stated: tuple = ()
) -> ParsedAnswer | None:
    """``text`` read, if it is a number, a number with units where the part has a unit, or a name
    for one (``n = 2``); else None. A side of ``working`` may be a formula in names whose values the
    problem gives (the option ``values``: ``2π√(g/l)`` before ``= 2.006 s``), read at those values; not
    the answer itself, which must be a number. ``stated`` are the values the answer gives names itself
    (``…, where l = 2 m``: pairs of a name and its value in SI units), which are the ones its working uses."""
    answer = parse_answer(text, coords=expected.setting.coords, known=names, deadline=deadline)
    if not answer.ok:
        return None
    final = _final_of_working(answer, expected.option("name") or ())
    answer = _with_definitions(_with_values(final), expected, deadline)  # n = 3N − k; N = 1; k = 2
    value = _unwrap_named(answer, spec, expected).value
    if not isinstance(value, sympy.Expr):
        return None
    if not value.free_symbols or (spec.name == "number" and expected.option("unit") and in_units(value)):
        return answer
    given = _given_numbers(expected.option("values"), expected) if working and spec.name == "number" else {}
    given = given | {name: sympy.Float(value) for name, value in stated} if given else given
    if given and {symbol.name for symbol in value.free_symbols} <= set(given):
        replacement = {symbol: given[symbol.name] for symbol in value.free_symbols}
        return ParsedAnswer(answer.text, value.xreplace(replacement), "expression")
    return None


def _given_numbers(values, expected: Expected) -> dict[str, sympy.Float]:
    """The option ``values`` (``{l: 1.00, g: 9.81}``, the problem's names with the values its prompt
    gives them, in SI units) by name; empty where there is none.

    Raises:
        AuthorError: for values that are no such mapping, or a name the problem does not define."""
    if not values:
        return {}
    # a mapping as the author writes it, or the pairs compare() keeps it as (see _hashable)
    pairs = tuple(values.items()) if isinstance(values, Mapping) else values
    if not isinstance(pairs, tuple) or not all(isinstance(pair, tuple) and len(pair) == 2 for pair in pairs):
        raise AuthorError(f"option values maps the problem's names to numbers, as {{l: 1.00, g: 9.81}}, not {values!r}")
    given = {}
    for name, number in pairs:
        if not isinstance(name, str) or canonical_name(name) not in expected.names:
            raise AuthorError(f"option values names {name!r}, which is no name of this problem")
        if isinstance(number, bool) or not isinstance(number, int | float) or not math.isfinite(number):
            raise AuthorError(f"option values gives {name!r} the value {number!r}, which is no finite number")
        given[canonical_name(name)] = sympy.Float(number)
    return given


def _final_of_working(answer: ParsedAnswer, asked: tuple = ()) -> ParsedAnswer:
    """``3N = 3, k = 2, n = 1``: working where a number is asked for, every item a number and one of
    them worked out (3N): the value of the last name that no other item uses (n; not N, which 3N
    uses: ``3N = 15, N = 5`` gives the value it was worked out with), else of the last item that
    is working (3N = 15; ``3N = 6, 3N − k = 2`` gives 2, as ``6 − 2 = 4, 6 − 4 = 2`` does: the last
    word). Where the part names the quantity (``asked``, the option ``name``), the value of the one
    item of that name, wherever it stands (``n = 2, k = 4``). As it was read where that is not so."""
    if answer.kind != "equations" or not all(item.rhs.is_number and item.lhs != ANSWER for item in answer.value):
        return answer  # 1, since k = 2: a number and words, read as such (numbers.read_number)
    items = answer.value
    named_asked = [item for item in items if item.lhs.is_Symbol and asked and item.lhs.name in asked]
    if len(named_asked) == 1:
        return ParsedAnswer(answer.text, named_asked[0].rhs, "expression")
    if all(item.lhs.is_Symbol for item in items):
        return answer  # n = 2; m = 3: no working, two values, and which is meant is for the student to say
    used = [set().union(*(other.lhs.free_symbols for other in items if other is not item)) for item in items]
    named = [item for item, others in zip(items, used, strict=True) if item.lhs.is_Symbol and item.lhs not in others]
    final = named[-1] if named else next((item for item in reversed(items) if not item.lhs.is_Symbol), None)
    return answer if final is None else ParsedAnswer(answer.text, final.rhs, "expression")


def _with_values(answer: ParsedAnswer) -> ParsedAnswer:
    """``T = 2π√(l/g); l = 1; g = 9.81`` where a number is asked for: the problem's names too given
    their values, put in place in the one equation left. As it was read where that is not so."""
    if answer.kind != "equations":
        return answer
    values = {
        item.lhs: item.rhs for item in answer.value if item.lhs.is_Symbol and item.lhs != ANSWER and item.rhs.is_number
    }
    rest = [item for item in answer.value if item.lhs not in values]
    if not values or len(rest) != 1 or len(values) != len(answer.value) - 1:
        return answer
    (item,) = rest
    return ParsedAnswer(answer.text, _replaced(item, values), "equation")


def _unit(text: str) -> tuple[Fraction, tuple]:
    """A part's unit (``s``, ``m/s^2``, ``rad/s``): its size in SI units and its powers.

    Raises:
        AuthorError: for a unit that is not a product of the units we know.
    """
    found = unit_named(text)
    if found is None:
        known = ", ".join(sorted(SI_UNITS, key=str.lower))
        raise AuthorError(f"unit {text!r} is not a product of powers of the units we know ({known})")
    return found


def _in_unit(answer: ParsedAnswer, spec: Kind, expected: Expected) -> tuple[ParsedAnswer, Outcome | None, tuple | None]:
    """A number written with its unit, where the part names one: ``2.006 s``, or ``2006 ms`` for a
    time asked in seconds, is the number in the part's unit. Another quantity (``2.006 m``) is
    not equivalent, and the student is told what the unit measures. A number alone is taken to
    be in the part's unit, as the question asks. Where a formula is asked for, see
    :func:`_formula_in_unit`.

    Returns the answer to judge, an outcome already decided (or None), and a note saying how a
    number in another unit, or a formula with its unit, was read (or None)."""
    if spec.name in ("expression", "lagrangian"):
        return _formula_in_unit(answer, spec, expected)
    wanted = expected.option("unit") if spec.name == "number" else None
    if not wanted or answer.kind != "expression" or not answer.value.free_symbols:
        return answer, None, None
    found = in_units(answer.value)
    if found is None:
        return answer, None, None  # not a number with a unit: a number is asked for
    number, size, powers = found
    wanted_size, wanted_powers = _unit(str(wanted))  # Hz for rad/s: the same powers, a cycle apart
    if powers != wanted_powers:
        details = {"theirs": si(powers), "wanted": si(wanted_powers)}
        return answer, Outcome("not_equivalent", 0.0, "unit_differs", details, method="units"), None
    cycles = cycles_to(answer.value, str(wanted))
    value = number * sympy.Rational(size / wanted_size) * cycles
    read_in = None
    if size != wanted_size or cycles != 1:
        key = "unit_read" if cycles == 1 else "unit_read_cycles"
        read_in = (key, {"value": f"{float(value):.6g}", "unit": str(wanted)})
    return ParsedAnswer(answer.text, value, "expression"), None, read_in


def _formula_in_unit(
    answer: ParsedAnswer, spec: Kind, expected: Expected
) -> tuple[ParsedAnswer, Outcome | None, tuple | None]:
    """``√(g/l) rad/s``, ``√(g/l) s^-1``: a formula, then its unit, where a formula is asked for.
    The formula is judged, and the note says the unit was left out; a unit none of whose names
    the problem uses, in SI units, multiplying the whole formula. Where the problem gives its
    symbols' dimensions, a unit that does not measure the quantity asked for is said so."""
    value, unchanged = answer.value, (answer, None, None)
    dimensions = _dimensions_tail(answer.text, spec, expected) if answer.kind == "expression" else None
    if dimensions is not None:
        return dimensions
    units = _units_named(answer, expected)
    # … [m]: a unit in square brackets, though its name is the problem's too (the mass m)
    bracketed = not units and answer.text.rstrip().endswith("]")
    if answer.kind != "expression" or not (units or bracketed):
        return unchanged
    tail = _unit_tail(answer.text, spec, expected)
    if tail is None and bracketed:
        return unchanged
    if tail is not None:  # first, for the product took in a unit with a name of the problem's: − m g r sin θ N·m
        answer, unit, found = tail
        formula = answer.value
    else:
        factors = sympy.Mul.make_args(value)
        unit = sympy.Mul(*(factor for factor in factors if factor.free_symbols & units))
        formula = sympy.Mul(*(factor for factor in factors if not factor.free_symbols & units))
        found = in_units(unit)
        if found is None or found[:2] != (1, 1) or not formula.free_symbols:
            return unchanged  # a unit inside the formula, one of another size (ms), or a number with a unit
        if not any(len(symbol.name) > 1 for symbol in units) and unit != sympy.Symbol("s") ** -1:
            return unchanged  # m g h: h is the student's height sooner than hours; 1/s is a unit
    outcome, note = _unit_said(unit, found, spec, expected)
    if outcome is not None:
        return answer, outcome, None
    return ParsedAnswer(answer.text, formula, "expression"), None, note


# a quantity's dimensions after a formula, as a prompt may ask them: [ML²T⁻²], (M L^2 T^-2), ML²T⁻²
_DIMENSION = r"[MLT](?:\s*\^\s*\(?\s*[-−]?[0-9]\s*\)?|[⁻]?[¹²³⁴⁵⁶⁷⁸⁹])?"
_DIMENSIONS = rf"{_DIMENSION}(?:\s*[·⋅*]?\s*{_DIMENSION}){{0,2}}"
_DIMENSIONS_TAIL = re.compile(
    rf"(?P<head>.+?)(?:\s*,\s*|\s*)(?:\[\s*(?P<bracket>{_DIMENSIONS})\s*\]|\(\s*(?P<round>{_DIMENSIONS})\s*\)"
    rf"|(?<=\s)(?P<bare>{_DIMENSION}(?:\s*[·⋅*]?\s*{_DIMENSION}){{1,2}}))\s*\.?\s*",
    re.S,
)
_DIMENSION_POWERS = re.compile(r"([MLT])(?:\s*\^\s*\(?\s*([-−]?[0-9])\s*\)?|([⁻]?[¹²³⁴⁵⁶⁷⁸⁹]))?")
_SUPERSCRIPT_DIGITS = str.maketrans("⁻¹²³⁴⁵⁶⁷⁸⁹", "-123456789")


def _dimensions_tail(text: str, spec: Kind, expected: Expected) -> tuple | None:
    """``−m g r sin θ [ML²T⁻²]``: a formula, then its dimensions in M, L and T (not names of the problem's),
    where a formula is asked: as :func:`_formula_in_unit` returns, the dimensions checked as a unit is and
    left out. None for any other text. Read as typed, M, L and T were names the problem does not define."""
    found = _DIMENSIONS_TAIL.fullmatch(text) if len(text) <= _UNIT_TAIL_LENGTH else None
    if found is None:
        return None
    typed = found["bracket"] or found["round"] or found["bare"]
    powers = [0, 0, 0]
    for letter, caret, superscript in _DIMENSION_POWERS.findall(typed):
        if letter in expected.names:
            return None  # T, the kinetic energy, or L, a length: no dimension
        power = caret or (superscript.translate(_SUPERSCRIPT_DIGITS) if superscript else "1")
        powers["MLT".index(letter)] += int(power.replace("−", "-"))
    formula = parse_answer(found["head"].rstrip(" ,;"), coords=expected.setting.coords, known=sorted(expected.names))
    formula = _unwrap_named(formula, spec, expected) if formula.ok else formula  # Q_θ = …
    if not formula.ok or formula.kind != "expression" or not formula.symbols or _undefined_symbols(formula, expected):
        return None
    units = tuple(Fraction(power) for power in powers)
    wanted = _expected_units(spec, expected)
    if wanted is not None and units != wanted:
        outcome = Outcome("not_equivalent", 0.0, "formula_unit_differs", {"theirs": si(units)}, method="units")
        return formula, outcome, None
    return ParsedAnswer(formula.text, formula.value, "expression"), None, ("dimensions_left_out", {"dimensions": typed})


def _unit_said(unit, found: tuple, spec: Kind, expected: Expected) -> tuple[Outcome | None, tuple | None]:
    """What a unit written after a formula says: that it does not measure the quantity asked for
    (an outcome), or the note that it was left out (one for a person to read where Hz or rad/s may
    say the formula is another quantity)."""
    wanted = _expected_units(spec, expected)
    if wanted is not None and found[2] != wanted:
        # not which unit is wanted: where a prompt asks for the formula's dimensions, that is the answer
        return Outcome("not_equivalent", 0.0, "formula_unit_differs", {"theirs": si(found[2])}, method="units"), None
    key = "unit_left_out" if _same_counts(unit, expected) else "unit_for_a_person"
    return None, (key, {"unit": in_sentence(to_text(unit), times="·")})  # N·m, kg·m²/s²


def _unit_in_label(text: str, spec: Kind, expected: Expected) -> tuple[ParsedAnswer, sympy.Expr, tuple] | None:
    """``Q_θ [N] = −m g r sin θ``, ``L [J] = …``: the formula, and the unit its label is said to be in, in
    square brackets, as :func:`_unit_tail` returns them (a unit only, every word a unit's name, in SI
    units); None for any other text. As read, the unit was a factor of the label, and left out with it."""
    found = _LABEL_UNIT.match(text) if len(text) <= _UNIT_TAIL_LENGTH else None
    if found is None or not _UNIT_TEXT.fullmatch(found["unit"]):
        return None
    if not all(word in SI_UNITS for word in _UNIT_WORD.findall(found["unit"])):
        return None
    unit = parse_answer(found["unit"])
    if not unit.ok or unit.kind != "expression" or not unit.symbols:
        return None
    size = in_units(unit.value)
    if size is None or size[:2] != (1, 1):
        return None
    formula = parse_answer(
        f"{found['label']} = {found['rest']}", coords=expected.setting.coords, known=sorted(expected.names)
    )
    formula = _unwrap_named(formula, spec, expected) if formula.ok else formula
    if not formula.ok or formula.kind != "expression" or _undefined_symbols(formula, expected):
        return None
    return formula, unit.value, size


# a label, its unit in square brackets, and the formula: Q_θ [N m] = …
_LABEL_UNIT = re.compile(r"\s*(?P<label>[^\s\[\]=]+)\s*\[(?P<unit>[^\[\]=]+)\]\s*=(?![=>])(?P<rest>.+)", re.S)


def _unit_tail(text: str, spec: Kind, expected: Expected) -> tuple[ParsedAnswer, sympy.Expr, tuple] | None:
    """``− m g r sin θ N·m``, ``… [N m]``, ``…, kg m²/s²``, ``½ m v² + m g h joules``: the formula and
    the unit written after it, where as read the two were one product, or the unit its last term's.
    The unit is the longest end of the text that is a product of units alone, set apart by a bracket
    or a comma, or of two units or more or a name of several letters (kg, joules), or newtons or joules
    alone (N, J: what mechanics measures forces and energies in, where the problem has no such name and
    its dimensions check the unit; a lone V or T is sooner an energy); what comes before it must be a
    formula in the problem's names (``Q_θ = …`` too, as :func:`_unwrap_named` reads it). None where
    there is no such end. Returns the formula read, the unit and :func:`in_units` of it. Only an end
    whose every word is a unit's name is read."""
    if len(text) > _UNIT_TAIL_LENGTH:
        return None
    for cut in _UNIT_CUTS.finditer(text):
        head, tail = text[: cut.start()], text[cut.end() :]
        set_apart = bool(cut.group().strip())
        tail = tail.strip()
        opener = next((character for character in cut.group() if character in "(["), None)
        if opener:
            if not tail.endswith(")]"["([".index(opener)]):
                continue
            tail = tail[:-1]
        if not tail or not head.strip() or not _UNIT_TEXT.fullmatch(tail):
            continue
        if not all(word in SI_UNITS for word in _UNIT_WORD.findall(tail)):
            continue  # a word that is no unit's: no parse is spent on it (an answer has room for 150 ends)
        unit = parse_answer(tail)
        if not unit.ok or unit.kind != "expression" or not unit.symbols:
            continue
        found = in_units(unit.value)
        names = {symbol.name for symbol in unit.symbols}
        several = len(sympy.Mul.make_args(unit.value)) > 1 or any(len(name) > 1 for name in names)  # N m, joules
        said = bool(re.search(r"\bin\b", cut.group()))  # "in g" names a unit, grams, whatever else g may be
        # − m g r sin θ N: newtons or joules after a formula, as N m is, where the problem has no N or J
        # and gives the dimensions that check it (a normal force N, or an inertia J, is then no unit's size)
        lone = unit.value.is_Symbol and unit.value.name in _LONE_UNITS and _expected_units(spec, expected) is not None
        if found is None or found[0] != 1 or (found[1] != 1 and not said) or not (set_apart or several or lone):
            continue
        if names <= expected.names and not said and opener != "[":
            # nothing here but the problem's names: no unit was written (but "in m" says one, and so does
            # [m], the brackets a unit is written in: read as the mass, … [m] was a formula times m)
            continue
        formula = parse_answer(head.rstrip(" ,;"), coords=expected.setting.coords, known=sorted(expected.names))
        formula = _unwrap_named(formula, spec, expected) if formula.ok else formula  # Q_θ = …
        if not formula.ok or formula.kind != "expression" or not formula.symbols:
            continue  # 3.13 rad/s: a number with its unit is no formula
        if not _undefined_symbols(formula, expected):
            return formula, unit.value, found
    return None


_UNIT_TAIL_LENGTH = 300
_LONE_UNITS = frozenset({"N", "J"})  # units read alone after a formula, as a product of units is
# where a unit may begin after a formula: a comma, an opening bracket, or a space; and "in" may say it is one
_UNIT_CUTS = re.compile(r"(?:\s*[,;]\s*\(?\s*|\s*[(\[]\s*|\s+)(?:in\s+)?")
_IN_UNIT = re.compile(r"(?:^|[\s,;(\[])in\s+\S")
_UNIT_TEXT = re.compile(r"[A-Za-zΩμµ·⋅*/^ 0-9⁰¹²³⁴⁵⁶⁷⁸⁹⁻()-]+")
_UNIT_WORD = re.compile(r"[A-Za-zΩμµ]+")


def _same_counts(unit, expected: Expected) -> bool:
    """Whether a unit of 1/s that counts cycles (Hz) or radians (rad/s) may be the expected formula's:
    one with π in it is a frequency f, in Hz (√(g/l)/2π); one without an angular frequency ω, in
    rad/s. ``√(g/l) Hz`` for ω is 2π out, if the label is meant; a person reads it."""
    counts = unit_counts({symbol.name for symbol in unit.free_symbols})
    if counts is None:
        return True
    return counts == ("cycles" if expected.value.has(sympy.pi) else "radians")


def _units_named(answer: ParsedAnswer, expected: Expected) -> set[sympy.Symbol]:
    """The names an answer uses that the problem does not, when every one is a unit's; else none."""
    undefined = _undefined_symbols(answer, expected)
    return undefined if all(symbol.name in SI_UNITS for symbol in undefined) else set()


def _undefined_symbols(answer: ParsedAnswer, expected: Expected) -> set[sympy.Symbol]:
    """The symbols an answer uses that the problem does not define."""
    return {symbol for symbol in answer.symbols if symbol.name not in expected.names}


def _mismatch(spec: Kind, expected: Expected, answer: ParsedAnswer) -> Outcome | None:
    """What can be said before any comparison: undefined symbols, or the wrong shape of answer."""
    used = answer.symbols
    if spec.name in ("integer", "number") and used:
        if any(symbol.name == "or" for symbol in used):  # 2 or 3: which is for the student to say
            return Outcome("invalid", 0.0, "number_hedged", method="symbols")
        # "2.006 s", "two": often the right number in words or with a unit. Not a number we can
        # grade, so a person decides, and a student checking first is told to write the number.
        return Outcome("invalid", 0.0, "not_a_number", {"names": _listing([s.name for s in used])}, "symbols")
    undefined = [symbol.name for symbol in _undefined_symbols(answer, expected)]
    if undefined and spec.shape == "equation" and answer.kind == "equations":
        # m₁ẍ = m₁g − T; m₂ẍ = T − m₂g: Newton's equations, with the string's tension still in them
        details = {
            "count": len(answer.value),
            "names": _listing(undefined),
            "them": "it" if len(undefined) == 1 else "them",
        }
        return Outcome("not_equivalent", 0.0, "eliminate_unknowns", details, method="symbols")
    if undefined and any(len(symbol.name) > 1 for symbol in _units_named(answer, expected)):
        # 3.13 rad/s where a formula is asked for: units, not names to define
        return Outcome("not_equivalent", 0.0, "undefined_units", {"names": _listing(undefined)}, method="symbols")
    if len(undefined) == 1 and _ends_in_unit_letter(answer.text, undefined[0]):
        # … − k (r − l₀) N: a unit's letter, which _unit_tail does not read past (it may be a name of theirs)
        details = {"name": unicode_name(undefined[0])}
        return Outcome("not_equivalent", 0.0, "undefined_unit_letter", details, method="symbols")
    named = _quantity_for_motion(spec, expected, answer, undefined)
    if named is not None:  # L = ½ m l² θ̇² + …, where the equation of motion is asked: not "L is undefined"
        return Outcome("not_equivalent", 0.0, "quantity_for_motion", named, method="shape")
    if undefined:
        defined = sorted(expected.names - {"t"}, key=lambda name: (name in expected.setting.coords, name))
        return Outcome(
            "not_equivalent", 0.0, "undefined_symbol",
            {"names": _listing(undefined), "defined": expected.setting.describe(defined),
             "which": "it" if len(undefined) == 1 else "each", "first": unicode_name(min(undefined, key=_natural))},
            method="symbols",
        )  # fmt: skip
    wanted, given = spec.shape, answer.kind
    if wanted in ("equation", "equations") and given == "expression":
        return Outcome("not_equivalent", 0.0, "expected_equation", method="shape")
    if wanted == "equation" and given == "equations":
        return Outcome("not_equivalent", 0.0, "expected_one_equation", {"count": len(answer.value)}, method="shape")
    if wanted == "expression" and given != "expression":
        return Outcome("not_equivalent", 0.0, "expected_expression", method="shape")
    if wanted == "equations" and given != "equations" and len(expected.setting.coords) > 1:
        count = len(expected.value) if isinstance(expected.value, tuple) else 1
        if count > 1:
            coords = expected.setting.describe(expected.setting.coords)
            return Outcome("not_equivalent", 0.0, "expected_system", {"count": count, "coords": coords}, method="shape")
    return None


def _quantity_for_motion(spec: Kind, expected: Expected, answer: ParsedAnswer, undefined: list[str]) -> dict | None:
    """Where an equation of motion (or a system of them) is asked for and the answer gives a quantity
    instead, ``L = …``, ``H = …``, ``T = …`` in the problem's names (H's momenta too) and without an
    acceleration: what the sentence that says so needs; else None."""
    if spec.shape not in ("equation", "equations") or answer.kind != "equation" or not answer.value.lhs.is_Symbol:
        return None
    name = answer.value.lhs.name
    momenta = {canonical_name(f"p_{coordinate}") for coordinate in expected.setting.coords}
    if name not in _QUANTITIES or name not in undefined or not set(undefined) - {name} <= momenta:
        return None
    orders = {derivative.derivative_count for derivative in answer.value.rhs.atoms(sympy.Derivative)}
    if any(order > 1 for order in orders):
        return None  # L = m l² θ̈ + …: a label on an equation's side, not the quantity
    if (name in _KINETIC_NAMES) != (1 in orders) and name in _KINETIC_NAMES | _POTENTIAL_NAMES:
        return None  # T = (m₁ − m₂) g, a tension; V = ½ m ẋ²: no such energy, whatever else it is
    system = spec.shape == "equations"
    return {
        "quantity": _QUANTITIES[name],
        "name": unicode_name(name),
        "asked": "the equations of motion are" if system else "an equation of motion is",
        "itself": "the equations themselves" if system else "the equation itself",
    }


_KINETIC_NAMES, _POTENTIAL_NAMES = frozenset("TK"), frozenset("VU")  # a kinetic energy has velocities, a potential none
# the quantities a student may give where the equations of motion are asked, by the letters texts use
_QUANTITIES = {
    "L": "a Lagrangian", "H": "a Hamiltonian", "T": "a kinetic energy", "K": "a kinetic energy",
    "V": "a potential energy", "U": "a potential energy", "E": "an energy",
}  # fmt: skip


_LISTED = 6  # names a sentence lists before it counts the rest
# the units whose symbol is one capital letter, N, J and W: seldom a name in a formula, as m, g, s or h are
_UNIT_LETTERS = frozenset(name for name in SI_UNITS if len(name) == 1 and name.isupper())


def _ends_in_unit_letter(text: str, name: str) -> bool:
    """Whether ``text`` ends in ``name``, alone, and it is a unit's capital letter (``… − k (r − l₀) N``)."""
    return name in _UNIT_LETTERS and re.search(rf"(?<![^\W_]){name}[\s.]*$", text) is not None


def _listing(names: list[str]) -> str:
    """``a``, ``b`` and ``c``, in order, x₂ before x₁₀; past six names, "and 54 more"."""
    quoted = [f"`{unicode_name(name)}`" for name in sorted(names, key=_natural)]
    if len(quoted) > _LISTED:
        return ", ".join(quoted[: _LISTED - 1]) + f" and {len(quoted) - _LISTED + 1} more"
    return listed(quoted)


def _natural(name: str) -> list:
    return [int(part) if part.isdigit() else part for part in re.split(r"([0-9]+)", name)]
