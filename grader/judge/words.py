"""Words a student writes about an answer, beside it: read past, and said so.

Contents:
    is_prose(words, names)                     whether words are about the answer, not more of it
    formula_then_words(text, names, coords)    ``θ̈ = −(g/l) θ for small angles``: the formula and its words

On paper an answer comes with words: ``θ̈ = −(g/l) θ for small angles``, ``m l² sin²θ φ̇ is
conserved``, ``a = g (m₁ − m₂)/(m₁ + m₂), with m₁ going down``. A person grades the formula and
reads the words. The checker does the same, and says which words it did not grade, but only
where they cannot be part of the formula: they hold no sign or word of arithmetic (``times l``),
no number, no "or" or "not", and read as names the problem does not have.
"""

from __future__ import annotations

import re
from collections.abc import Collection, Iterator

from grader.judge.units import SI_UNITS
from grader.parse import parse_answer
from grader.parse.names import GREEK_NAMES, IMPLYING_WORDS

__all__ = ["formula_then_words", "is_prose"]

_MATH_SIGNS = frozenset("+-−*/^=√·×<>≤≥")
# words that change a formula: "√(g/l) times l", "… but negative", "… all squared"
_MATH_WORDS = re.compile(
    r"\b(?:times|plus|minus|over|divided|multiplied|squared|cubed|square|root|half|halved|twice|doubled|"
    r"inverse|reciprocal|power|per|third|fourth|negative|opposite|sum|difference|product|ratio|quotient|"
    r"derivative|differentiated|integral|integrated)\b",
    re.I,
)
# a number of its own, "or", or "not": 2 or 3, θ̈ = … or θ̈ = …, not for small angles
_HEDGE = re.compile(r"(?<!\w)[0-9]|\b(?:or|not|never|isn't)\b", re.I)
_WORD = re.compile(r"(?<![A-Za-z0-9_\\])[A-Za-z]{2,}(?![A-Za-z0-9_])")
_OPENS = " ,;:([–—-"  # what may stand between a formula and the words about it
_LENGTH = 400  # characters: longer answers are read as typed


def is_prose(words: str, names: Collection[str]) -> bool:
    """Whether ``words`` are about an answer, not more of it: no sign or word of arithmetic, no
    number in digits, no "or" or "not"; and they cannot be read, or use a name that is neither
    the problem's (``names``) nor a unit."""
    if not words or _MATH_SIGNS & set(words) or _MATH_WORDS.search(words) or _HEDGE.search(words):
        return False
    read = parse_answer(words, known=names)
    if not read.ok:
        return True
    return any(symbol.name not in names and symbol.name not in SI_UNITS for symbol in read.symbols)


def formula_then_words(text: str, names: Collection[str], coords: Collection[str]) -> Iterator[tuple[str, str]]:
    """``θ̈ = −(g/l) θ for small angles``: the ways to read ``text`` as (a formula, prose after it).
    The prose begins at the first word that is none of the problem's names, spellings or
    functions, or at the mark of punctuation before it (``…, a nonlinear equation``), and must be
    prose (:func:`is_prose`). The formula is not checked here: the caller reads each in turn."""
    if len(text) > _LENGTH:
        return
    word = next((found for found in _WORD.finditer(text) if _is_word(found[0], names, coords)), None)
    if word is None:
        return
    cut = word.start()
    while cut and text[cut - 1] in _OPENS:
        cut -= 1
    mark = max(text.rfind(sign, 0, cut) for sign in ",;:(")  # …, a nonlinear equation
    line = text.rfind("\n", 0, cut)
    for start in dict.fromkeys((cut, mark if mark > line else -1)):
        formula, rest = text[:start].rstrip(), text[start:].strip()
        if start > 0 and formula and is_prose(rest.lstrip(_OPENS), names):
            yield formula, rest


def _is_word(word: str, names: Collection[str], coords: Collection[str]) -> bool:
    """Whether ``word`` reads as one name the problem does not have, and no Greek letter's: ``for``,
    ``conserved``; not ``mgl`` (m·g·l), ``thetadot``, ``sin`` or ``omega``."""
    if word.lower() in GREEK_NAMES or word.lower() in IMPLYING_WORDS:
        return False  # So θ̈ = …: a step of the working, which the parser reads
    read = parse_answer(word, coords=coords, known=names)
    if not read.ok or read.kind != "expression" or not read.value.is_Symbol:
        return False
    return read.value.name not in names and read.value.name not in SI_UNITS
