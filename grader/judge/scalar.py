"""The kinds that are not formulas of the motion: ``integer``, ``number``, ``choice``.

Contents:
    check_integer    a whole number, exactly (``6/2`` is 3)
    check_number     a number within a tolerance: |submitted − expected| ≤ atol + rtol·|expected|
    check_choice     one or several option labels, in any order and case, or an option's own words or formula
    choice_labels    the labels in a typed choice answer
    chosen           the labels a choice answer names, read as check_choice reads them
"""

from __future__ import annotations

import re

import sympy

from grader.judge.deadline import Deadline
from grader.judge.expected import Expected, Outcome
from grader.judge.numbers import NUMBER_WORDS
from grader.judge.units import other_units
from grader.parse import ParsedAnswer, visible
from grader.parse.messages import ParseFailure
from grader.parse.names import GREEK_BY_LETTER, canonical_name, split_derivative
from grader.parse.tokens import tokenize

__all__ = ["check_choice", "check_integer", "check_number", "choice_labels", "chosen"]

DIGITS = 30
MAX_CHOICE_LENGTH = 200
_LABEL = re.compile(r"[A-Za-z0-9]{1,20}")
_SEPARATORS = re.compile(r"(?:\s*[,;/&]\s*|\s+and\s+|\s+)")


def check_integer(expected: Expected, answer: ParsedAnswer, deadline: Deadline) -> Outcome:
    value = _whole(answer.value) if answer.value.is_number else answer.value
    if not (value.is_number and value.is_Integer):
        return Outcome("not_equivalent", 0.0, "not_an_integer", method="exact")
    equal = value == expected.parsed.value
    return Outcome(
        "equivalent" if equal else "not_equivalent", float(equal), "equivalent" if equal else "wrong", method="exact"
    )


def _whole(value):
    """``value`` as a sympy Integer when it is one exactly, else as it is.

    A rational is one only if its denominator is 1 (15 + 10⁻²⁹ is not 15). Anything else
    (log(8)/log(2)) is guessed by ``nsimplify``, whose guess has a tolerance, so the guess
    must agree with the value to 50 digits.
    """
    if value.is_Rational:
        return value
    guess = sympy.nsimplify(value)
    if guess.is_Integer and abs((value - guess).evalf(DIGITS + 30)) < sympy.Float(10) ** -50:
        return guess
    return value


def check_number(expected: Expected, answer: ParsedAnswer, deadline: Deadline) -> Outcome:
    rtol, atol = float(expected.option("rtol")), float(expected.option("atol"))
    target = complex(expected.parsed.value.evalf(DIGITS))
    deadline.check()
    value = complex(answer.value.evalf(DIGITS))
    method = f"tolerance rtol={rtol:g} atol={atol:g}"
    if abs(value - target) <= atol + rtol * abs(target):
        return Outcome("equivalent", 1.0, "equivalent", method=method)
    unit = expected.option("unit")
    for name, size in other_units(str(unit)) if unit else ():
        # 2006 for a period asked in s: the right number in ms, written without its unit
        in_other = target / complex(size)
        if abs(value - in_other) <= atol / abs(complex(size)) + rtol * abs(in_other):
            return Outcome("not_equivalent", 0.0, "other_unit", {"unit": name, "wanted": str(unit)}, method)
    return Outcome("not_equivalent", 0.0, "out_of_tolerance", method=method)


def choice_labels(text: str) -> list[str] | None:
    """The labels in ``text`` (``"a, C"`` → ``['a', 'c']``), or None when it is not a list of labels."""
    stripped = text.strip().rstrip(".!").strip().strip("[](){}").strip()  # b. as b; b? asks, and is no answer
    if not stripped or len(text) > MAX_CHOICE_LENGTH:
        return None
    labels = [label.lower() for label in _SEPARATORS.split(stripped) if label]
    if not all(_LABEL.fullmatch(label) for label in labels):
        return None
    return labels


def check_choice(expected: Expected, submitted: str, deadline: Deadline) -> Outcome:
    wanted = set(choice_labels(expected.text) or ())
    texts = _option_texts(expected.option("options") or ())
    options = list(texts)
    given, read, conflict = _read_choice(submitted, texts, multiple=bool(expected.option("multiple")))
    if conflict:
        details = {"label": conflict[0], "words": conflict[1]}
        return Outcome("invalid", 0.0, "choice_conflict", details, "labels")
    if given is None:
        shown = f"`{submitted.strip()[:40]}`" if isinstance(submitted, str) and submitted.strip() else "This"
        details = {"labels": shown, "options": ", ".join(options) or "?"}
        return Outcome("invalid", 0.0, "choice_unknown", details, "labels")
    unknown = [label for label in given if options and label not in options]
    if unknown:
        # "e" is a label that is not there; "the first one" is words, shown as typed
        words = any(len(label) > 2 for label in unknown)
        shown = f"`{submitted.strip()[:40]}`" if words else ", ".join(unknown)
        return Outcome("invalid", 0.0, "choice_unknown", {"labels": shown, "options": ", ".join(options)}, "labels")
    if not expected.option("multiple") and len(set(given)) > 1:
        return Outcome("not_equivalent", 0.0, "choice_count", {"count": "one option"}, "labels")
    right = set(given) == wanted
    notes = (("choice_read", {"labels": ", ".join(read)}),) if read else ()
    return Outcome(
        "equivalent" if right else "not_equivalent",
        float(right),
        "equivalent" if right else "choice_wrong",
        method="option text" if read else "labels",
        notes=notes,
    )


def chosen(submitted: str, options, *, multiple: bool = False) -> list[str] | None:
    """The labels a choice answer names, as the checker reads them (``b (rheonomic)`` is b), or
    None where it names no option's label or words, or names two options at once."""
    given, _, conflict = _read_choice(submitted, _option_texts(options), multiple=multiple)
    return None if conflict or given is None else given


def _read_choice(submitted, texts: dict[str, str], *, multiple: bool) -> tuple[list | None, list | None, tuple | None]:
    """(the labels given, or None; those read from words, or None; a label and words naming
    another option, or None)."""
    submitted = visible(submitted).strip() if isinstance(submitted, str) else submitted  # b​, ｂ: b
    given = choice_labels(submitted) if isinstance(submitted, str) else None
    if not isinstance(submitted, str) or (given is not None and all(label in texts for label in given)):
        return given, None, None
    # "non-holonomic" or "φ" for option b: the option's own words, where they name one option
    read = _by_text(submitted, texts, multiple=multiple)
    labelled = None if read else _labelled(submitted, texts)
    if labelled and labelled[1]:
        return given, None, labelled
    return read or ([labelled[0]] if labelled else given), read, None


def _option_texts(options) -> dict[str, str]:
    """label → the option's words, from labels alone (``("a", "b")``) or (label, text) pairs."""
    pairs = (option if isinstance(option, tuple) else (option, "") for option in options)
    return {str(label).lower(): str(text) for label, text in pairs}


def _by_text(submitted: str, texts: dict[str, str], *, multiple: bool) -> list[str] | None:
    """The labels whose options a student wrote out in words, or None: the whole answer one
    option's words, or its claim before the reason (``rheonomic`` for "rheonomic, since the
    constraint depends explicitly on time"); or (where several may be chosen) each piece
    between commas one's."""
    if len(submitted) > MAX_CHOICE_LENGTH:
        return None
    readings = _readings(texts)
    whole = _named(submitted, readings)
    if not whole and not multiple:  # "rheonomic because l depends on t": the claim, then the reason
        claim, rest = _claim(submitted)
        whole = _named(claim, readings) or _with_remark(claim, readings, texts) or _said_of(claim, readings)
        if whole and rest is not None and _names_another(rest, whole, readings, texts):
            return None  # "φ, θ", "rheonomic, maybe scleronomic": a list or a hedge, no claim and reason
    if whole or not multiple:
        return [whole] if whole else None
    labels = [_named(piece, readings) for piece in re.split(r"\s*[,;]\s*|\s+and\s+", submitted) if piece.strip()]
    return labels if labels and all(labels) else None


def _readings(texts: dict[str, str]) -> dict[str, str | None]:
    """What each option is known by (:func:`_keys`), to its label, or to None where two options read
    alike: its words, its claim before the reason, and a formula of its own between commas
    (``is held fixed, $\\delta t = 0$``)."""
    readings: dict[str, str | None] = {}
    for label, text in texts.items():
        formulas = [piece for piece in re.split(r"\s*[,;]\s*", text) if _MATH.fullmatch(piece)]
        for key in set().union(*(_option_keys(words) for words in (text, _claim(text)[0], *formulas))):
            readings[key] = label if readings.get(key, label) == label else None  # two options alike name neither
    return readings


def _option_keys(words: str) -> set[str]:
    """What an option's words are compared by: a formula set in $…$ (and a number in words) only as a
    formula, so that its sign, dots and case count; other words, and a formula the parser does not
    read (``$\\sum_i …$``), as words."""
    formula = _MATH.fullmatch(words.strip()) or words.strip().lower() in NUMBER_WORDS
    keys = {"$" + found for found in _formulas(words)} if formula else set()
    return keys or {_plain(words)} - {""}


_MATH = re.compile(r"\$[^$]+\$")


def _named(text: str, readings: dict[str, str | None]) -> str | None:
    """The label of the one option that ``text`` names, by its words or as its formula, or by a
    coordinate's description and its letter (``the azimuthal angle φ``); ``not holonomic`` names the
    option that says so in one word, ``non-holonomic``, where there is one, and never ``holonomic``;
    or None."""
    keys = _keys(text)
    described = _DESCRIBED.fullmatch(text)
    if described:
        keys |= {"$" + formula for formula in _formulas(described["letter"])}
    found = {readings.get(key) for key in keys} - {None}
    denied = _NOT.fullmatch(text) if not found else None
    if denied:
        found = {readings.get(_plain("non" + denied["words"]))} - {None}
    return found.pop() if len(found) == 1 else None


# the words a hedge starts with: φ, or θ; rheonomic, maybe …; b; not b
_HEDGES = "or|nor|maybe|perhaps|possibly|probably|both|neither|either|not|no"
_NOT = re.compile(r"\s*not\s+(?P<words>\S.*?)\s*\.?\s*", re.I | re.S)  # not holonomic, not θ
# a coordinate described, then its letter: the azimuthal angle φ, the generalized coordinate q₁; not a hedge
_DESCRIBED = re.compile(
    rf"\s*(?:the\s+)?(?:(?!(?:{_HEDGES}|non)\b)[^\W\d_]+\s+){{0,2}}"
    r"(?:angle|coordinate|variable)\s+(?P<letter>\S+?)\s*\.?",
    re.I,
)


def _keys(text: str) -> set[str]:
    """What ``text`` is compared by: its words (:func:`_plain`), and where it reads as a formula, the
    formula (:func:`_formulas`), marked with a ``$`` that words as compared never have."""
    return ({_plain(text)} | {"$" + formula for formula in _formulas(text)}) - {""}


def _formulas(text: str) -> set[str]:
    """A formula as compared: the parser's tokens, each name in its one spelling, so that ``−∂V/∂q_j``
    and ``$-\\partial V / \\partial q_j$`` are alike and keep their sign and dots, while case counts
    (V is not v); also the value after a quantity's name (``Q_j = −∂V/∂q_j``); and a number in
    words as its digits (``zero``, 0). None where the parser does not read the text."""
    number = NUMBER_WORDS.get(text.strip().lower())
    if number is not None:
        return {number}
    try:
        tokens = [token for token in tokenize(_TYPEFACE.sub(lambda found: found[1] or "", text)) if token.kind != "end"]
    except ParseFailure:
        return set()
    spelled = [_spelled(token) for token in tokens]
    formulas = {"".join(spelled)}
    named = len(tokens) > 2 and tokens[0].kind == "name" and tokens[1].is_op("=")
    named = named and not tokens[0].value.dots and _QUANTITY.fullmatch(tokens[0].value.raw)
    if named and not any(token.is_op("=") for token in tokens[2:]):  # not ∂V/∂q_j = −∂V/∂q_j
        formulas.add("".join(spelled[2:]))
    return formulas


def _spelled(token) -> str:
    """A token as :func:`_formulas` compares it: a name in its one spelling, with its dots and primes."""
    if token.kind != "name":
        return str(token.value)
    name, dots = canonical_name(token.value.raw), token.value.dots
    if not dots:
        name, dots = split_derivative(name) or (name, 0)  # thetadot is θ̇
    return name + "." * dots + "'" * token.value.primes


# a vector's or a word's typeface, which says nothing of the formula: \mathbf r_i, \vec{r}
_TYPEFACE = re.compile(r"\\(?:mathbf|boldsymbol|bm|vec)\s*(?:\{([^{}]*)\}|(?=\S))")
# the name before a formula's value, as a prompt names it: Q_j, W, a Latin letter and its index
_QUANTITY = re.compile(r"[A-Za-z](?:_[A-Za-z0-9]+)?")


def _claim(text: str) -> tuple[str, str | None]:
    """``rheonomic, since …``: the claim before the first mark of a reason outside brackets, and the
    reason after it, or None where there is none. A comma in brackets is the remark's own:
    ``non-holonomic (r ≥ a, an inequality)`` is one claim."""
    for mark in _REASON.finditer(text):
        before = text[: mark.start()]
        if before.count("(") <= before.count(")"):
            return before, text[mark.end() :]
    return text, None


def _names_another(rest: str, label: str, readings: dict[str, str | None], texts: dict[str, str]) -> bool:
    """Whether what follows an option's words names another option, alone or as labels (``φ, θ``,
    ``rheonomic, c``), or starts with a hedge (``…, or θ``, ``…, maybe …``, ``…, both``): then the
    answer is no claim with its reason. A clarifying ``not`` before another option confirms the choice
    (``rheonomic, not scleronomic``); before the same option it takes it back (``b; not b``)."""
    denial = _denied(rest, readings, texts)
    if denial:
        return denial[0] == label or _names_another(denial[1] or "", label, readings, texts)
    if _HEDGE.match(rest):
        return True
    if _named(rest, readings) not in (None, label):
        return True
    labels = choice_labels(rest)
    return bool(labels) and all(other in texts for other in labels) and set(labels) != {label}


def _denied(text: str, readings: dict[str, str | None], texts: dict[str, str]) -> tuple[str, str | None] | None:
    """``not θ``, ``not scleronomic, since …``, ``not a``: the option that a clarifying ``not`` sets
    aside, by its label, words or formula, and what follows it (or None); None where the text is no
    such denial of one option."""
    claim, rest = _claim(text)
    found = _NOT.fullmatch(claim)
    if found is None:
        return None
    label = found["words"].lower() if found["words"].lower() in texts else _named(found["words"], readings)
    return (label, rest) if label else None


def _labelled(submitted: str, texts: dict[str, str]) -> tuple[str, str] | None:
    """``b (rheonomic)``, ``b) rheonomic``, ``b: rheonomic``, ``b, since l = l(t)``: a label, then its
    option's words, or after a mark of punctuation or in brackets (``b (the hoop rotates)``) a reason
    naming no other option. Returns the
    label and "" ; or the label and the words where they name another option (``b (scleronomic)``);
    or None."""
    match = _LABELLED.fullmatch(submitted) if len(submitted) <= MAX_CHOICE_LENGTH else None
    if match is None or match["label"].lower() not in texts:
        return None
    label, words = match["label"].lower(), match["words"].strip(" ()[].")
    named = _by_text(words, texts, multiple=False)
    if named:
        return (label, "") if named == [label] else (label, words)
    readings = _readings(texts)
    denial = _denied(words, readings, texts)
    if denial:  # b, not a
        return None if _names_another(words, label, readings, texts) else (label, "")
    labels = choice_labels(words)
    if (labels and all(len(other) <= 2 for other in labels)) or _OR.search(words) or _HEDGE.match(words):
        return None  # a, e: labels, one of them no option's; b - or maybe a, b; not b: a hedge
    bracketed = match["words"].startswith("(") and match["words"].endswith(")")  # b (the hoop rotates)
    return (label, "") if match["mark"].strip() or bracketed or _REASON.match(" " + words) else None


# a label, then words: b (rheonomic), (b) rheonomic, b. rheonomic, b - since …
_LABELLED = re.compile(r"\s*\(?(?P<label>[A-Za-z0-9]{1,3})\)?(?P<mark>\s*[).:,;–—-]\s*|\s+)(?P<words>\S.*?)\s*", re.S)

# where an option's reason begins: "rheonomic, since …", "holonomic because …"
_REASON = re.compile(r",|;|:|\s+(?:since|because)\s+")
_OR = re.compile(r"\bor\b", re.I)  # a hedge between options: b - or maybe a
# what a hedge starts with, after an option: "φ, or θ", "rheonomic, maybe …", "b; not b", "φ, both"
_HEDGE = re.compile(rf"\s*(?:{_HEDGES})\b", re.I)


def _with_remark(claim: str, readings: dict[str, str | None], texts: dict[str, str]) -> str | None:
    """``scleronomic (no explicit t)``: one option's words, then a remark in brackets that names no
    other option, does not hedge with "or" and does not take the option back (``φ (not φ)``; ``φ
    (not θ)`` confirms it); None for any other answer."""
    found = _REMARK.fullmatch(claim)
    if found is None or not _balanced(found["remark"]) or _OR.search(found["remark"]):
        return None
    named = _named(found["claim"], readings)
    others = {_named(remark, readings) for remark in (found["remark"], _claim(found["remark"])[0])}
    if others - {None, named}:
        return None  # not rheonomic (scleronomic, …)
    denial = _denied(found["remark"], readings, texts)
    return None if denial and denial[0] == named else named  # φ (not θ), not φ (not φ)


def _balanced(text: str) -> bool:
    """Whether every bracket in ``text`` closes one opened before it: ``l = l(t)``, not ``a) (b``."""
    depth = 0
    for c in text:
        depth += (c == "(") - (c == ")")
        if depth < 0:
            return False
    return depth == 0


# an option's words, then a remark in brackets: holonomic (an equation among the coordinates), rheonomic (l = l(t))
_REMARK = re.compile(r"(?P<claim>[^()]+?)\s*\((?P<remark>.*)\)\s*\.?\s*", re.S)


def _said_of(claim: str, readings: dict[str, str | None]) -> str | None:
    """``φ is cyclic``, ``both are cyclic``, ``The constraint is holonomic``: a sentence whose subject
    or whose predicate, not both, is one option's words; None for any other, and for a sentence
    that says "not", "no" or "or" (``θ is not cyclic``), which names no option by its words, but
    for a predicate ``not holonomic`` that names one (``non-holonomic``)."""
    parts = _IS.split(claim, maxsplit=1)
    if len(parts) != 2:
        return None
    negated = _NOT.fullmatch(parts[1])
    if _DENIES.search(parts[0]) or _DENIES.search(negated["words"] if negated else parts[1]):
        return None
    if negated and _named(parts[1], readings) is None:
        return None  # θ is not cyclic: not θ
    named = {_named(part, readings) for part in parts} - {None}
    return named.pop() if len(named) == 1 else None


# where a sentence says what its subject is, and the words that deny it or hedge
_IS = re.compile(r"\s+(?:is|are)\s+", re.I)
_DENIES = re.compile(r"\b(?:not|no|or)\b|n't\b", re.I)


def _plain(text: str) -> str:
    """An option's words as compared: no TeX, markup, case, spaces or a word's hyphens; Greek letters by
    name; and the textbooks' other names for a kind of constraint as ours."""
    text = "".join(GREEK_BY_LETTER.get(c, c) for c in text)
    text = _WORD_HYPHEN.sub("", text)  # non-holonomic; a minus is kept: −∂V/∂q_j is not ∂V/∂q_j
    return _SAME_KIND.sub(lambda found: _SAME_KINDS[found[0]], re.sub(r"[\s$\\{}*_.]", "", text).lower())


_WORD_HYPHEN = re.compile(r"(?<=[^\W\d_])\s*[-\u2010\u2011]\s*(?=[^\W\d_])")  # non-holonomic, non - holonomic


# Goldstein's scleronomous and rheonomous, and anholonomic, are scleronomic, rheonomic, nonholonomic
_SAME_KINDS = {"scleronomous": "scleronomic", "rheonomous": "rheonomic", "anholonomic": "nonholonomic"}
_SAME_KIND = re.compile("|".join(_SAME_KINDS))
