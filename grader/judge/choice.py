"""The ``choice`` kind: which of a part's options an answer names, and whether it names one answer.

Contents:
    check_choice     one or several option labels, in any order and case, or an option's own words or formula
    choice_labels    the labels in a typed choice answer
    chosen           the labels a choice answer names, read as check_choice reads them

An answer is read without TeX's wrappers (``\\text{b}``, ``$b$``): by its labels, by an option's words or
formula (also said in a sentence, or by what the problem says a symbol means), or by a label with words
after it; what follows the option is read past and said. Words that hedge, doubt or deny it, or a remark
that names another option or takes it back, make it no one answer (:func:`_hedges`). Where the question
asks which option is false (``asks_false``), saying an option is false names it, and saying it is true or
correct doubts it.
"""

from __future__ import annotations

import re
from functools import lru_cache
from typing import NamedTuple

from grader.judge.deadline import Deadline
from grader.judge.expected import Expected, Outcome
from grader.judge.feedback import shown
from grader.judge.numbers import NUMBER_WORDS
from grader.parse import visible
from grader.parse.messages import ParseFailure
from grader.parse.names import FUNCTION_NAMES, GREEK_BY_LETTER, GREEK_NAMES, canonical_name, split_derivative
from grader.parse.tokens import tokenize

__all__ = ["check_choice", "choice_labels", "chosen"]

MAX_CHOICE_LENGTH = 200
_LABEL = re.compile(r"[A-Za-z0-9]{1,20}")
_SEPARATORS = re.compile(r"(?:\s*[,;/&]\s*|\s+and\s+|\s+)")


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
    multiple = bool(expected.option("multiple"))
    meanings, asks_false = expected.option("meanings") or (), bool(expected.option("asks_false"))
    reading = _read_choice(submitted, texts, multiple=multiple, meanings=meanings, asks_false=asks_false)
    if reading.conflict:
        details = {"label": reading.conflict[0], "words": reading.conflict[1]}
        return Outcome("invalid", 0.0, "choice_conflict", details, "labels")
    if reading.hedged:
        return Outcome("invalid", 0.0, "choices_hedged" if multiple else "choice_hedged", {"typed": _typed(submitted)})
    if reading.scribbled:
        return Outcome("invalid", 0.0, "choice_scribbled", {"typed": _typed(submitted)}, "labels")
    given = reading.labels
    if given is None:
        details = {"labels": _typed(submitted), "options": ", ".join(options) or "?"}
        return Outcome("invalid", 0.0, "choice_unknown", details, "labels")
    unknown = [label for label in given if options and label not in options]
    if unknown:
        # "e" is a label that is not there; "the first one" is words, shown as typed
        words = any(len(label) > 2 for label in unknown)
        labels = _typed(submitted) if words else ", ".join(unknown)
        return Outcome("invalid", 0.0, "choice_unknown", {"labels": labels, "options": ", ".join(options)}, "labels")
    if not multiple and len(set(given)) > 1:
        return Outcome("not_equivalent", 0.0, "choice_count", {"count": "one option"}, "labels")
    right = set(given) == wanted
    return Outcome(
        "equivalent" if right else "not_equivalent",
        float(right),
        "equivalent" if right else "choice_wrong",
        method="option text" if reading.words else "labels",
        notes=_reading_notes(reading),
    )


def _typed(submitted) -> str:
    """A choice answer as a refusal repeats it: as typed, cut short with "…" as every note cuts it."""
    return f"`{shown(submitted.strip())}`" if isinstance(submitted, str) and submitted.strip() else "This"


def _reading_notes(reading: _Reading) -> tuple:
    """How the answer was read: the option its words name, and what was read past after it."""
    rest = reading.remark.strip().lstrip(",;:–—- ").strip()
    labels = ", ".join(reading.words or reading.labels)
    if reading.before:  # holonomic and rheonomic: the words on both sides of the option, which were not graded
        rest = " … ".join(words for words in (reading.before, rest) if words)
        return (("choice_read_beside", {"labels": labels, "rest": shown(rest)}),)
    rest = shown(rest)
    if not rest:
        return (("choice_read", {"labels": labels}),) if reading.words else ()
    return (("choice_read_remark" if reading.words else "choice_remark", {"labels": labels, "rest": rest}),)


def chosen(submitted: str, options, *, multiple: bool = False, meanings=(), asks_false=False) -> list[str] | None:
    """The labels a choice answer names, as the checker reads them (``b (rheonomic)`` is b), or
    None where it names no option's label or words, names two options at once, or hedges."""
    texts = _option_texts(options)
    reading = _read_choice(submitted, texts, multiple=multiple, meanings=meanings, asks_false=asks_false)
    return None if reading.conflict or reading.hedged or reading.scribbled else reading.labels


class _Reading(NamedTuple):
    """A choice answer as read: the labels it names (or None); those read from an option's words (or
    None); what was read past after the option (a remark, a reason); a label with words that name
    another option (or None); whether it hedges, doubts or takes back what it names; and a claim read past
    before the option (``holonomic`` of "holonomic and rheonomic"); and whether what follows the option is a
    formula that says nothing of it (:func:`_scribbled`)."""

    labels: list[str] | None = None
    words: list[str] | None = None
    remark: str = ""
    conflict: tuple[str, str] | None = None
    hedged: bool = False
    before: str = ""
    scribbled: bool = False


def _read_choice(submitted, texts: dict[str, str], *, multiple: bool, meanings=(), asks_false=False) -> _Reading:
    """How ``submitted`` reads as a choice among ``texts`` (label → the option's words), where the
    problem's symbols mean ``meanings`` ((name, meaning) pairs), and the question asks for the false
    option where ``asks_false``."""
    submitted = visible(submitted).strip() if isinstance(submitted, str) else submitted  # b​, ｂ: b
    if isinstance(submitted, str) and len(submitted) <= MAX_CHOICE_LENGTH:
        submitted = _without_tex(submitted).strip()  # \text{b}, $b$: b
    given = choice_labels(submitted) if isinstance(submitted, str) else None
    if not isinstance(submitted, str) or (given is not None and all(label in texts for label in given)):
        return _Reading(given)
    if len(submitted) > MAX_CHOICE_LENGTH:
        return _Reading(given)
    before, after = (_FALSE_BEFORE, _FALSE_AFTER) if asks_false else (_SAID_BEFORE, _SAID_AFTER)
    core = after.sub("", before.sub("", submitted, count=1), count=1)
    said = choice_labels(core)
    if said and all(label in texts for label in said):
        return _Reading(said)  # the answer is b, I choose b, option b, b is correct
    readings = _readings(texts, meanings)
    claim, _ = _claim(submitted)
    remarked = _REMARK.fullmatch(claim)  # c is false (it needs multipliers): the claim, then a remark
    claim = remarked["claim"] if remarked and _balanced(remarked["remark"]) else claim
    core_of_claim = after.sub("", before.sub("", claim, count=1), count=1)
    said = choice_labels(core_of_claim) if core_of_claim != claim else None
    if said and all(label in texts for label in said):  # b is correct, since …; c is false, because …
        remark = submitted[len(claim) :]
        hedged = _hedges(submitted, said, remark, readings, texts, asks_false=asks_false)
        return _Reading(hedged=True) if hedged else _Reading(said, None, remark, scribbled=_scribbled(remark, said))
    said = _named(core, readings) if core != submitted else None
    if said:
        return _Reading([said], [said])  # I choose rheonomic
    words = None
    found = _labels_first(submitted, texts)  # a, c (since …)
    if found is None:
        found = _by_text(submitted, readings, multiple=multiple)  # "non-holonomic", "φ": an option's words
        words = found[0] if found else None
    if found is None:
        labelled = _labelled(submitted, texts, readings)  # b (rheonomic), b, since …
        if labelled and labelled[1]:
            return _Reading(given, conflict=labelled[:2])
        found = ([labelled[0]], labelled[2]) if labelled else None
    joined = _joined(submitted, readings, texts) if found is None and not multiple else None
    if joined:  # holonomic and rheonomic, where rheonomic or scleronomic is asked
        label, before_it, remark = joined
        if _hedges(submitted, [label], remark, readings, texts, asks_false=asks_false):
            return _Reading(hedged=True)
        return _Reading([label], [label], remark, before=before_it, scribbled=_scribbled(remark, [label]))
    labels, remark = found or (None, "")
    if _hedges(submitted, labels, remark, readings, texts, asks_false=asks_false):
        return _Reading(hedged=True)
    return _Reading(labels or given, words, remark, scribbled=bool(labels) and _scribbled(remark, labels))


# TeX's wrappers of text, and of mathematics, in which an answer typed in a TeX box may set its choice
_TEX_TEXT = re.compile(
    r"\\(?:text|textrm|textbf|textit|textsf|texttt|textup|mathrm|mathbf|mathit|mathsf|emph|mbox)\s*\{([^{}]*)\}"
)
_TEX_MATH = re.compile(r"\$\$?([^$]*)\$\$?|\\\((.*?)\\\)|\\\[(.*?)\\\]", re.S)
_TEX_DEPTH = 3  # wrappers one within another, at the most: $\textbf{\text{b}}$


def _without_tex(text: str) -> str:
    r"""``\text{b}``, ``$b$``, ``\textbf{(b)}`` as ``b`` and ``(b)``: what TeX's text and math wrappers hold,
    each as typed inside them, so the choice reads as one typed without TeX.

    >>> _without_tex(r"\text{b}"), _without_tex(r"$\textbf{(b)}$"), _without_tex(r"$a$ and $c$")
    ('b', '(b)', 'a and c')
    """
    for _ in range(_TEX_DEPTH):
        plain = _TEX_TEXT.sub(r"\1", text)
        plain = _TEX_MATH.sub(lambda found: next(group for group in found.groups() if group is not None), plain)
        if plain == text:
            break
        text = plain
    return text


def _scribbled(remark: str, labels) -> bool:
    """Whether what follows an option is a formula and no words (``= k θ̈``, ``, l sin ω``, ``(m g l)``):
    scribbles, a step of another part perhaps, that say nothing of the choice, and may be meant for it
    (``(b) = k θ̈``: is b that formula?). A remark with words (``since l = l(t)``) is read past, and so is a
    relation (``(r ≥ a)``: why the option holds), but for the label set equal to a formula (``(b) = …``).
    Function names, Greek letters by name and a rate spelled out (``thetadot``) are no words. The chosen
    option's own label is no formula (``rheonomic, b``)."""
    text = remark.strip().lstrip(",;:–—-. ").strip()
    said = choice_labels(text)
    if not text or (said and set(said) <= set(labels)):
        return False
    equated = text.startswith("=")
    words = [
        word
        for word in _WORD.findall(text)
        if word.lower() not in FUNCTION_NAMES and word.lower() not in GREEK_NAMES and not split_derivative(word)
    ]
    return not words and (equated or not _RELATION.search(text))


# a word of a remark: three Latin letters or more with a vowel (not m g R glued, mgR), not a TeX command
# (\sin, \theta); and the signs of a relation
_WORD = re.compile(r"(?<![\\A-Za-zÀ-ÿ])(?=[A-Za-zÀ-ÿ]*[aeiouyAEIOUYÀ-ÿ])[A-Za-zÀ-ÿ]{3,}")
_RELATION = re.compile(r"[=<>≤≥≠≈≃∝]|\\(?:geq?|leq?|neq?|approx|propto|sim)(?![A-Za-z])")


def _joined(submitted: str, readings: dict[str, str | None], texts: dict[str, str]) -> tuple[str, str, str] | None:
    """``rheonomic and holonomic``, ``holonomic and rheonomic, since l = l(t)``: two claims joined by
    "and" (a constraint classified both ways where one way is asked), one of which names an option
    and the other no other, nor takes it back (``θ and not r``): that option's label, the claim
    before it ("" where it comes first) and what follows it. None for any other answer."""
    pieces = _AND.split(submitted, maxsplit=1)
    if len(pieces) != 2:
        return None
    first, second = (_by_text(piece, readings, multiple=False) for piece in pieces)
    if bool(first) == bool(second):
        return None
    labels, remark = first or second
    other = pieces[1] if first else pieces[0]
    if _takes_another(other, set(labels), readings, texts):
        return None
    if first:
        return labels[0], "", remark + submitted[len(pieces[0]) :]
    return labels[0], other.strip(" ,;:"), remark


_AND = re.compile(r"\s+(?:and|&)\s+", re.I)


# words that say a label is the answer, before or after it: "the answer is b", "I choose b", "b is correct"
_SAID = (
    r"(?:(?:my|the)\s+)?(?:(?:final|correct|right)\s+)?(?:answer|ans\.?|option|choice)(?:\s+is\b|\s*:|\b|(?<=\.))"
    r"|I\s+(?:choose|chose|pick|picked|select|selected|go\s+with|say)\b"
)
_SAID_BEFORE = re.compile(rf"\A\s*(?:{_SAID})\s*", re.I)
_SAID_AFTER = re.compile(
    r"\s+is\s+(?:the\s+|my\s+)?(?:(?:correct|right)(?:\s+(?:answer|option|choice|one))?|answer)\s*[.!]?\s*$", re.I
)
# the same where the question asks which option is false: "c is false", "the false statement is c";
# a bare "c is correct" may say that c is true, the opposite, and is no such claim
_FALSE_WORDS = r"(?:false|wrong|incorrect|untrue)"
_FALSE_BEFORE = re.compile(
    rf"\A\s*(?:{_SAID}|(?:the\s+)?(?:{_FALSE_WORDS}\s+(?:one|statement)|statement)(?:\s+is\b|\s*:|\b))\s*", re.I
)
_FALSE_AFTER = re.compile(
    r"\s+(?:is\s+(?:(?:the\s+|my\s+)?(?:(?:correct|right)\s+(?:answer|option|choice)|answer)"
    rf"|(?:the\s+)?(?:{_FALSE_WORDS}|not\s+true)(?:\s+(?:one|statement))?)|is\s*n['’]t\s+true)\s*[.!]?\s*$",
    re.I,
)


def _labels_first(submitted: str, texts: dict[str, str]) -> tuple[list[str], str] | None:
    """``a, c (since …)``: two or more of the options' labels, then what follows them; None where the
    answer does not start so (``b, a constraint …`` is a label and a reason: the article is no label)."""
    found = _LABEL_LIST.match(submitted)
    if found is None:
        return None
    labels = [label.lower() for label in re.findall(r"[A-Za-z0-9]+", re.sub(r"\band\b", " ", found[0]))]
    return (labels, submitted[found.end() :]) if all(label in texts for label in labels) else None


# labels, each a word of its own before a mark or the end (so not the article in "a constraint")
_ONE_LABEL = r"\(?[A-Za-z0-9]{1,3}\)?(?=\s*(?:[,;:/&().!–—-]|and\b|$))"
_LABEL_LIST = re.compile(rf"\s*{_ONE_LABEL}(?:\s*(?:[,;/&]|\band\b)\s*{_ONE_LABEL})+")


def _option_texts(options) -> dict[str, str]:
    """label → the option's words, from labels alone (``("a", "b")``) or (label, text) pairs."""
    pairs = (option if isinstance(option, tuple) else (option, "") for option in options)
    return {str(label).lower(): str(text) for label, text in pairs}


def _by_text(submitted: str, readings: dict[str, str | None], *, multiple: bool) -> tuple[list[str], str] | None:
    """The labels whose options a student wrote out in words, and what was read past after them; or
    None: the whole answer one option's words; or its claim before a reason or a remark in brackets
    (``rheonomic`` for "rheonomic, since the constraint depends explicitly on time", ``scleronomic (no
    explicit t)``), also said in a sentence (``φ is cyclic``); or (where several may be chosen) each
    piece between commas one's. Whether what was read past hedges is for :func:`_hedges` to say."""
    bare = submitted.rstrip(".!").strip()  # rheonomic!, −∂V/∂q_j., (rheonomic): as b!, b. and (b) are b
    if bare.startswith("(") and bare.endswith(")") and _balanced(bare[1:-1]):
        bare = bare[1:-1].strip()
    whole = _named(bare, readings)
    if whole:
        return [whole], ""
    if multiple:
        pieces = [piece for piece in re.split(r"\s*[,;]\s*|\s+and\s+", submitted) if piece.strip()]
        labels = [_named(piece, readings) for piece in pieces]
        return (labels, "") if labels and all(labels) else None
    claim, _ = _claim(submitted)
    remarked = _REMARK.fullmatch(claim)
    body = remarked["claim"] if remarked and _balanced(remarked["remark"]) else claim
    label = _named(claim, readings)  # −d/dt(∂V/∂q̇_j): brackets of the option's own
    if label:
        return [label], submitted[len(claim) :]
    label = _named(body, readings) or _said_of(body, readings)  # φ is cyclic (θ): the sentence, then a remark
    return ([label], submitted[len(body) :]) if label else None


def _readings(texts: dict[str, str], meanings=()) -> dict[str, str | None]:
    """What each option is known by (:func:`_keys`), to its label, or to None where two options read
    alike: its words, its claim before the reason, and a formula of its own between commas
    (``is held fixed, $\\delta t = 0$``); and where an option is one of the problem's symbols, what the
    problem says it means (:func:`_described`)."""
    readings: dict[str, str | None] = {}
    for label, text in texts.items():
        formulas = [piece for piece in re.split(r"\s*[,;]\s*", text) if _MATH.fullmatch(piece)]
        for key in set().union(*(_option_keys(words) for words in (text, _claim(text)[0], *formulas))):
            readings[key] = label if readings.get(key, label) == label else None  # two options alike name neither
    for key, label in _described(readings, meanings).items():
        readings[key] = label if readings.get(key, label) == label else None
    return readings


def _described(readings: dict[str, str | None], meanings) -> dict[str, str]:
    """The problem's own words for the symbols that are options, to their labels: ``azimuthal angle``
    and ``the azimuthal angle`` (its head, before the first preposition or mark) and the whole of
    "azimuthal angle about the vertical through the pivot", for an option φ where the symbol table
    says so. A head two of the problem's symbols share names neither (``angle`` for θ and φ)."""
    owners: dict[str, set[str]] = {}  # the problem's words → the symbols they describe
    for name, meaning in meanings:
        head = _HEAD.match(str(meaning))
        for words in {str(meaning), head["head"] if head else ""} - {""}:
            for key in {_plain(words), _plain("the " + words)}:
                owners.setdefault(key, set()).add(str(name))
    described = {}
    for key, names in owners.items():
        labels = {readings.get("$" + formula) for name in names for formula in _formulas(name)}
        if len(names) == 1 and len(labels) == 1 and None not in labels:
            described[key] = labels.pop()
    return described


# a description's head: "polar angle" of "polar angle of the string from the downward vertical"
_HEAD = re.compile(
    r"\s*(?P<head>[^\W\d_][\w\s'-]*?)\s*(?=$|[,;:(]|\b(?:of|about|from|at|in|on|to|with|along|between|through|"
    r"around|measured|for|relative|as|by)\b)",
    re.I,
)


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
    ``θ only`` and ``only θ`` name θ, where no option's own words say "only"; or None."""
    only = _ONLY.fullmatch(text)
    if only and not _keys(text) & readings.keys():  # conservative systems only: an option's own words
        return _named(only["after"] or only["before"], readings)
    keys = _keys(text)
    described = _DESCRIBED.fullmatch(text)
    if described:  # the azimuthal angle φ: the letter, and the words where the problem says what they mean
        keys |= {"$" + formula for formula in _formulas(described["letter"])}
        keys |= _keys(text[: described.start("letter")])
    found = {readings.get(key) for key in keys} - {None}
    denied = _NOT.fullmatch(text) if not found else None
    if denied:
        found = {readings.get(_plain("non" + denied["words"]))} - {None}
    return found.pop() if len(found) == 1 else None


_ONLY = re.compile(r"\s*(?:only|just)\s+(?P<after>\S.*?)\s*|\s*(?P<before>\S.*?)\s+only\s*", re.I | re.S)

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


@lru_cache(maxsize=4096)  # a remark is looked up word by word, and a class types the same words
def _formulas(text: str) -> frozenset[str]:
    """A formula as compared: the parser's tokens, each name in its one spelling, so that ``−∂V/∂q_j``
    and ``$-\\partial V / \\partial q_j$`` are alike and keep their sign and dots, while case counts
    (V is not v); also the value after a quantity's name (``Q_j = −∂V/∂q_j``); and a number in
    words as its digits (``zero``, 0). None where the parser does not read the text."""
    number = NUMBER_WORDS.get(text.strip().lower())
    if number is not None:
        return frozenset({number})
    try:
        tokens = [token for token in tokenize(_TYPEFACE.sub(lambda found: found[1] or "", text)) if token.kind != "end"]
    except ParseFailure:
        return frozenset()
    spelled = _inline_fractions(tokens, [_spelled(token) for token in tokens])
    formulas = {"".join(spelled)}
    named = len(tokens) > 2 and tokens[0].kind == "name" and tokens[1].is_op("=")
    named = named and not tokens[0].value.dots and _QUANTITY.fullmatch(tokens[0].value.raw)
    if named and not any(token.is_op("=") for token in tokens[2:]):  # not ∂V/∂q_j = −∂V/∂q_j
        formulas.add("".join(spelled[2:]))
    return frozenset(formulas)


def _inline_fractions(tokens: list, spelled: list[str]) -> list[str]:
    """``\\frac{\\partial V}{\\partial q_j}`` spelled as ``∂V/∂q_j`` and ``\\frac{d}{dt}`` as ``d/dt``, as options
    and students write them inline: a fraction of two groups that are each one name or number, after
    a ∂ perhaps. A longer group keeps its \\frac: ``m g/2 l`` is no reading of ``\\frac{m g}{2 l}``."""
    inline, i = [], 0
    while i < len(tokens):
        top = _one_name_group(tokens, i + 1) if tokens[i].kind == "frac" else None
        bottom = _one_name_group(tokens, top) if top is not None else None
        if bottom is not None:
            inline += [*spelled[i + 2 : top - 1], "/", *spelled[top + 1 : bottom - 1]]
            i = bottom
        else:
            inline.append(spelled[i])
            i += 1
    return inline


def _one_name_group(tokens: list, start: int) -> int | None:
    """Where the group ``{name}`` or ``{∂ name}`` (a number for a name too) that opens at ``start`` ends,
    just after its ``}``; None where none opens there."""
    kinds = [token.kind if token.kind != "op" else token.value for token in tokens[start : start + 4]]
    for shape in (["{", "partial", "name", "}"], ["{", "name", "}"], ["{", "num", "}"]):
        if kinds[: len(shape)] == shape:
            return start + len(shape)
    return None


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


def _labelled(submitted: str, texts: dict[str, str], readings: dict[str, str | None]) -> tuple[str, str, str] | None:
    """``b (rheonomic)``, ``b) rheonomic``, ``b: rheonomic``, ``b, since l = l(t)``: a label, then its
    option's words, or after a mark of punctuation or in brackets (``b (the hoop rotates)``) a
    remark. Returns the label, "" and what was read past (nothing after the option's own words, but
    what follows them); or the label and the words where they name another option (``b
    (scleronomic)``); or None."""
    match = _LABELLED.fullmatch(submitted)
    if match is None or match["label"].lower() not in texts:
        return None
    label, words = match["label"].lower(), _unbracketed(match["words"])
    named = _by_text(words, readings, multiple=False)
    if named:
        return (label, "", named[1]) if named[0] == [label] else (label, words, "")
    labels = choice_labels(words)
    doubted = _TAKEN_BACK.fullmatch(words) or _DOUBT.search(words)  # b (no), b (50/50): read, to be refused
    if labels and all(len(other) <= 2 for other in labels) and not doubted:
        return None  # a, e: labels, one of them no option
    bracketed = match["words"].startswith("(") and match["words"].endswith(")")  # b (the hoop rotates)
    closed = submitted[match.end("label") : match.end("label") + 1] == ")"  # b) the hoop rotates: a list's mark
    if match["mark"].strip() or closed or bracketed or _REASON.match(" " + words):
        return label, "", match["words"]
    return None


def _unbracketed(words: str) -> str:
    """Words after a label without the brackets around them, or a bracket left open or closed by the
    label's (``b (rheonomic)``, ``b (rheonomic``): not the bracket that closes the words' own ``l(t)``."""
    words = words.strip(" .[(")
    while words[-1:] in (")", "]") and not _balanced(words.replace("[", "(").replace("]", ")")):
        words = words[:-1].rstrip(" .")
    return words


# a label, then words: b (rheonomic), (b) rheonomic, b. rheonomic, b - since …
_LABELLED = re.compile(r"\s*\(?(?P<label>[A-Za-z0-9]{1,3})\)?(?P<mark>\s*[).:,;–—-]\s*|\s+)(?P<words>\S.*?)\s*", re.S)

# where an option's reason begins: "rheonomic, since …", "holonomic because …"
_REASON = re.compile(r",|;|:|\s+(?:since|because)\s+")


def _hedges(
    submitted: str, labels, remark: str, readings: dict[str, str | None], texts: dict[str, str], *, asks_false=False
) -> bool:
    """Whether an answer is no one answer: it doubts or denies an option, or offers another, in words
    that are not the named options' own (``rheonomic (maybe scleronomic)``, ``b (false)``, ``φ is cyclic
    (θ too)``, ``rheonomic, unless …``, ``b?``); or what was read past after the option names another
    or takes it back (``rheonomic (scleronomic)``, ``φ, θ``, ``b (no)``, ``φ (not φ)``), where it is no
    reason (``φ, because θ appears in L``: a reason may name another option, to say why not). Where no
    option was read, whether the answer names one, and doubts it or names another too (``b or a``).
    Where the question asks which option is false, ``false`` names it and ``true`` doubts it (``c (true)``).
    A word taken back says the opposite: ``b (no error)``, ``b (not a trap)`` affirm b, and ``b (not valid)``
    denies it. A clause about another option is a reason where it says what the question says of options
    not chosen (``b, a is untrue``; ``c, as d holds``), and a doubt where it says the opposite
    (``b (a is correct)``)."""
    own = " ".join(texts[label] for label in (labels or texts) if label in texts).lower()  # d) both: no hedge

    def said_of(found: re.Match) -> str:
        """Of what the denial or truth word ``found`` is said: taken ``back`` (b (no error), b (not valid)), of
        ``another`` option and of none chosen (b, a is untrue; c, as d holds), or of the ``chosen`` one."""
        if _negated(submitted, found):
            return "back"
        return "another" if labels and _about_another(submitted, found, set(labels), readings, texts) else "chosen"

    matches = list(_DOUBT.finditer(submitted))
    doubts = [found[0].lower() for found in matches if not _DENIAL.fullmatch(found[0])]
    denials = [(found[0].lower(), said_of(found)) for found in matches if _DENIAL.fullmatch(found[0])]
    truths = [(found[0].lower(), said_of(found)) for found in _TRUE.finditer(submitted)]
    if not asks_false:  # b (false) doubts b; b (not valid) and b (a is correct) too; b, a is untrue is a reason
        doubts += [word for word, said in denials if said == "chosen"]
        doubts += [f"not {word}" for word, said in truths if said == "back"]
        doubts += ["true" for _, said in truths if said == "another"]
    else:  # c) false: the claim asked for; c (true), c (correct): it is no answer, or the opposite one
        own += f" {_DENIALS} a lie"
        untrue = {word for word, said in truths if said == "back"}
        doubts = [doubt for doubt in doubts if doubt.split()[-1] not in untrue]  # c (not true): c is false
        doubts += [word for word, said in truths if said == "chosen"]  # c, as d holds: a reason
        doubts += ["true" for _, said in denials if said == "back"]  # c (not false)
        doubts += ["another" for _, said in denials if said == "another"]  # c, a is false too
    doubted = any(not re.search(rf"(?<!\w){re.escape(doubt)}(?!\w)", own) for doubt in doubts)
    if labels is None:
        named, _ = _mentioned(submitted, readings, texts)
        return bool(named) and (doubted or len(named) > 1)
    equated = submitted.split("=", 1)[0].strip() if "=" in submitted else ""  # r = θ, b = −∂V/∂q_j: two options
    equated = equated.lower() if equated.lower() in texts else _named(equated, readings) if equated else None
    if equated and equated not in labels:
        return True
    return doubted or any(_takes_another(piece, set(labels), readings, texts) for piece in _remark_pieces(remark))


# words that call an option false, which deny it, or where the false statement is asked name it: "non-holonomic
# is inaccurate", "b (a trap)"; "lie" only as a noun ("a lie"), not the particle that may lie outside the sphere
_DENIALS = (
    "false wrong incorrect untrue inaccurate erroneous mistaken invalid bogus nonsense fake mistake mistakes "
    "error errors myth misconception trap"
)
# words that doubt or deny an option, or offer another beside it, wherever they stand
_DOUBT = re.compile(
    r"\b(?:or|nor|maybe|perhaps|possibly|probably|either|neither|both|too|also|unless|actually|false|wrong|"
    r"incorrect|unsure|uncertain|unlikely|guess|guessing|idk|dunno|nope|nah|wait|oops)\b"
    rf"|\b(?:{'|'.join(_DENIALS.split())})\b|\ba\s+lie\b"
    r"|\b(?:not\s+(?:sure|certain|really|quite|right|correct|true|likely)|as\s+well|I\s+think|(?:might|could)\s+be)\b"
    r"|[?？¿‽⁇⁈⁉؟⸮]|\d\s*%|\b50\s*[/:-]\s*50\b",
    re.I,
)


# where the false statement is asked, words that call an option true: "c (valid)", "c, which holds"
_TRUE = re.compile(r"\b(?:true|correct|right|valid|accurate|holds)\b", re.I)
# the words that deny an option, of those _DOUBT finds
_DENIAL = re.compile(rf"(?:false|wrong|incorrect|{'|'.join(_DENIALS.split())}|a\s+lie)", re.I)
# what takes the word after it back: no error, not a trap, without mistakes, isn't wrong, is no myth
_NEGATION = re.compile(r"(?:\b(?:no|not|never|without)|n[’']t)\s+(?:an?\s+)?$", re.I)


def _negated(text: str, found: re.Match) -> bool:
    """Whether the word ``found`` in ``text`` is taken back by the words just before it: ``not valid``."""
    return bool(_NEGATION.search(text[max(0, found.start() - 20) : found.start()]))


def _about_another(text: str, found: re.Match, labels: set[str], readings, texts: dict[str, str]) -> bool:
    """Whether the clause of ``text`` the word ``found`` stands in says it of an option not among ``labels``,
    and of none of them: ``a is untrue``, ``since holonomic is invalid here``, ``b and d are valid``."""
    start = max(text.rfind(mark, 0, found.start()) for mark in _CLAUSE_MARKS) + 1
    ends = [end for end in (text.find(mark, found.end()) for mark in _CLAUSE_MARKS) if end >= 0]
    clause = _CLAUSE_OPENING.sub("", text[start : min(ends, default=len(text))])
    subject = _SUBJECT.match(clause)
    named = (
        set(_LABEL.findall(subject[1].lower())) & texts.keys() if subject else _mentioned(clause, readings, texts)[0]
    )
    return bool(named) and not named & labels


_CLAUSE_MARKS = (",", ";", ":", "(", ")", "—", "–")
_CLAUSE_OPENING = re.compile(r"^\s*(?:(?:since|because|as|and|but|while|whereas|though|although|so)\b\s*)*", re.I)
# the options a clause is about, by their labels: a is …, b and d are …, d holds, b would be …
_SUBJECT = re.compile(
    r"\s*(?:options?\s+)?([a-z](?:\s*(?:,|and|or)\s*[a-z])*)\s+(?:is|are|was|were|would|holds?|seems?)\b", re.I
)
_LABEL = re.compile(r"\b[a-z]\b")


def _remark_pieces(remark: str) -> list[str]:
    """What was read past after an option, in pieces: a remark in brackets, and what follows it."""
    text = remark.strip()
    pieces = []
    if text.startswith("("):
        depth = 0
        for end, c in enumerate(text):
            depth += (c == "(") - (c == ")")
            if depth == 0:
                pieces.append(text[1:end])
                text = text[end + 1 :]
                break
        else:
            pieces.append(text[1:])
            text = ""
    text = text.strip().lstrip(",;:–—-.").strip()
    return [piece for piece in (*pieces, text) if piece.strip()]


def _takes_another(text: str, labels: set[str], readings: dict[str, str | None], texts: dict[str, str]) -> bool:
    """Whether ``text``, read past after the options ``labels``, names another option or takes one
    back: ``θ``, ``scleronomic, …``, ``(no)``, ``(not φ)``, ``… I'd say not``. A clarifying ``not``
    before another option confirms the choice (``rheonomic, not scleronomic``, ``b (not a)``), and a
    reason (``since …``, ``because …``) may name another option, to say why not."""
    if _TAKEN_BACK.fullmatch(text) or _ENDS_DENIED.search(text):
        return True
    denial = _denied(text, readings, texts)
    if denial:
        return denial[0] in labels or _takes_another(denial[1] or "", labels, readings, texts)
    if _BECAUSE.match(text):
        return False
    named, denied = _mentioned(text, readings, texts)
    return bool(named - labels or denied & labels)


# a remark that takes the option back: (no), (not really), (nope); … or not, … I'd say not
_TAKEN_BACK = re.compile(r"\W*(?:no|not|never)(?:\s+(?:this|that|it|so))?\W*", re.I)
_ENDS_DENIED = re.compile(r"(?:\bno|\bnot|n't)\W*$", re.I)
_BECAUSE = re.compile(r"\s*(?:since|because|as|given|due|for)\b", re.I)


def _mentioned(text: str, readings: dict[str, str | None], texts: dict[str, str]) -> tuple[set[str], set[str]]:
    """The options ``text`` names anywhere, by their words or formulas (``… but scleronomic``, ``… θ
    appears in L``) or, where it is labels among words that join them (``(but a)``, ``(=a)``), by their
    labels; and those it names after ``not`` (``not θ``). Labels among other words are no option's
    (``r ≥ a``, ``a constraint``)."""
    tokens = _TOKEN.findall(text)[:_TOKENS]
    named, denied = set(), set()
    start = 0
    while start < len(tokens):
        for size in range(min(_SPAN, len(tokens) - start), 0, -1):
            found = {readings.get(key) for key in _keys(" ".join(tokens[start : start + size]))} - {None}
            if len(found) == 1:
                said_not = start and tokens[start - 1].lower() == "not"
                (denied if said_not else named).add(found.pop())
                start += size
                break
        else:
            start += 1
    words = [token.strip("=+→<>≠-–—.'\"").lower() for token in tokens]
    if all(not word or word in texts or word in _JOINING for word in words):
        for before, word in zip(["", *words], words, strict=False):
            if word in texts:
                (denied if before == "not" else named).add(word)
    return named, denied


_TOKEN = re.compile(r"[=≠→+]|[^\s,;:()\[\]{}!?=≠→+]+")  # a sign apart: (=θ) names θ
_TOKENS = 60  # words of a remark looked at: a choice answer is short (MAX_CHOICE_LENGTH)
_SPAN = 5  # words of a remark that may name one option, at the most
# words that join labels into a hedge or a correction, saying nothing of their own: (but a), (I mean a)
_JOINING = frozenset({
    "and", "but", "or", "nor", "maybe", "perhaps", "possibly", "probably", "rather", "i", "mean", "well", "then",
    "again", "like", "same", "as", "instead", "of", "vs", "versus", "except", "sometimes", "more", "plus", "also",
    "too", "either", "both", "actually", "unless", "than", "no", "not", "yes", "ok", "is", "it", "the", "answer",
    "option", "choice", "could", "might", "be", "wait", "sorry", "oops", "meant", "make", "that", "change", "to",
    "correction", "typo", "say", "so", "ie", "i.e",
})  # fmt: skip


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
_IS = re.compile(r"\s+(?:is|are)\s+|['’]s\s+", re.I)  # it is, it's
_DENIES = re.compile(r"\b(?:not|no|or)\b|n't\b", re.I)


def _plain(text: str) -> str:
    """An option's words as compared: no TeX, markup, case, spaces or a word's hyphens; Greek letters by
    name; the textbooks' other names for a kind of constraint as ours; and a kind of constraint with
    the noun after it (``holonomic constraints``, ``a rheonomic constraint``) as the kind."""
    text = "".join(GREEK_BY_LETTER.get(c, c) for c in text)
    text = _WORD_HYPHEN.sub("", text)  # non-holonomic; a minus is kept: −∂V/∂q_j is not ∂V/∂q_j
    text = _SAME_KIND.sub(lambda found: _SAME_KINDS[found[0]], re.sub(r"[\s$\\{}*_.]", "", text).lower())
    return _KIND_NOUN.sub(r"\g<kind>", text)


# non-holonomic, non - holonomic, and non–holonomic with the en dash a word processor puts there
_WORD_HYPHEN = re.compile(r"(?<=[^\W\d_])\s*[-\u2010-\u2013]\s*(?=[^\W\d_])")


# Goldstein's scleronomous and rheonomous, and anholonomic, are scleronomic, rheonomic, nonholonomic
_SAME_KINDS = {"scleronomous": "scleronomic", "rheonomous": "rheonomic", "anholonomic": "nonholonomic"}
_SAME_KIND = re.compile("|".join(_SAME_KINDS))
# (a) holonomic, scleronomic, rheonomic constraint(s): the article goes only with the noun, where it is no label
_KIND_NOUN = re.compile(r"^(?:an?|the)?(?P<kind>(?:non)?holonomic|scleronomic|rheonomic)constraints?$")
