"""Where a part asks for a number or a count: the number a student means, in what they typed.

Contents:
    read_number(text, reads, names, ...)   the text to judge, its reading, and notes saying how it was read
    NUMBER_WORDS                           zero to twenty in words, to their digits

Students write a number inside a sentence, as they would on paper: ``≈ 2.01 s``, ``T = 2π√(l/g)
= 2.01 s``, ``2 (θ₁ and θ₂)``, ``2 degrees of freedom``, ``two``, ``2,01``, ``6 − 4 → 2``. The number
is what the part grades, so it is found and graded, and the student is told what was not. Each
reading is tried only when the answer as typed is not a number: for a measured value, ``2 (3)`` is
still 6. A count is the exception: after one, brackets are more often its working than a factor,
so ``2 (6 − 4)`` is 2, and ``1 (2)``, which may be either, goes to a person. Working over several
lines (``6 − 2 = 4; 6 − 4 = 2``) is graded at its last line, as a chain on one line is at its last side. Of
values stated side by side (``T = 2.006 s, f = 0.498 Hz``), the one in the unit asked for is graded.

Words that take a number back or doubt it (``6 − 4 = 2? no, 4``, ``maybe 2``), or may make it another
(``at most 2``, ``2 for each bob``, ``two hundred``, and for a count, which is exact, ``about 2``), are not
read past: which number is the answer is then for a person to say. Nor is the first side of ``6 − 4 = 2
…`` graded where the last cannot be read: only before the quantity's name (``2.01 s = T``).

A remark after the number must be words, not mathematics: in ``2 π √(l/g)`` for a period, the
√(l/g) is part of the answer, which is a formula where a number is asked for, and is refused as one.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Collection
from enum import IntEnum
from functools import lru_cache

import sympy

from grader.judge.feedback import SHOWN, shown
from grader.judge.units import PREFIX_WORDS, SI_UNITS, in_units, unit_like, unit_named
from grader.judge.words import is_prose, says_otherwise
from grader.parse import ParsedAnswer, parse_answer
from grader.parse.messages import listed
from grader.parse.names import GREEK_BY_LETTER, GREEK_NAMES, IMPLYING_WORDS, unicode_name

__all__ = ["COUNT_NAME", "NUMBER_WORDS", "read_number"]

# 2,01 or 1,5 (a number with a decimal comma, then perhaps a unit); not 2,006, which is 2006 in English. But
# 0,498 is 0.498: a thousands separator never follows a lone 0, so three digits after 0, are decimals too
_DECIMAL_COMMA = re.compile(
    r"\s*([+-]?[0-9]+),([0-9]{1,2}|[0-9]{4,}|(?<=(?<![0-9])0,)[0-9]{3})(?![0-9,])(.*)", re.DOTALL
)

# the same inside arithmetic (2π/√9,81), not in a name (m1,5) nor after a point (1.2,5)
_DECIMAL_COMMA_INSIDE = re.compile(r"(?<![\w.,])([0-9]+),([0-9]{1,2}|[0-9]{4,}|(?<=(?<![0-9])0,)[0-9]{3})(?![\w,.])")
# where the answer writes a decimal comma that is plainly one (2π/√9,81 ≈ 2,006 s), its 2,006 is one too: no
# one writes 9,81 for 9.81 and 2,006 for 2006 in the same line
_ANY_DECIMAL_COMMA = re.compile(r"\s*([+-]?[0-9]+),([0-9]+)(?![0-9,])(.*)", re.DOTALL)
_ANY_DECIMAL_COMMA_INSIDE = re.compile(r"(?<![\w.,])([0-9]+),([0-9]+)(?![\w,.])")


class _Commas(IntEnum):
    """How a part reads a comma between digits: not at all, as a decimal comma where no thousands
    separator can be, or as one before three digits too, where the answer writes another plainly."""

    NONE = 0
    DECIMAL = 1
    EVERY = 2


def _commas(text: str, decimal_comma: bool) -> _Commas:
    """:class:`_Commas` for ``text``: EVERY where every comma in it stands between digits and one of them
    can be no thousands separator (9,81)."""
    if not decimal_comma:
        return _Commas.NONE
    given = _GIVEN.search(text) if len(text) < _LENGTH else None
    if given is not None and given.start() and "," in given[0]:
        # 2,006 s, with g = 9,81.: the comma before the values is the sentence's, read as their bracket is
        text = f"{text[: given.start()]} ({given[0].lstrip(' ,')}{text[given.end() :].rstrip(' .')})"
    plain = len(text) < _LENGTH and _DECIMAL_COMMA_INSIDE.search(text)
    if plain and len(_ANY_DECIMAL_COMMA_INSIDE.findall(text)) == text.count(","):
        return _Commas.EVERY
    return _Commas.DECIMAL


# ``2.006 sec``, ``2006 msec``, ``2.006 seconds``: after a number, at the end, the word for seconds, not the secant
_SEC = re.compile(r"([0-9.]\s*)(m?)(?:secs?|seconds?)\.?\s*$")

# ``≈ 2.01 s``, ``about 2 s``, ``2.0 s (approx.)``: the tolerance says how near is near enough
_ABOUT = re.compile(r"^\s*(?:≈|≃|~|\\approx|\\simeq|\\sim|about|approx\.?|approximately|roughly|ca\.|circa)\s*", re.I)
_ABOUT_AFTER = re.compile(r"\s*\(?\s*(?:approx\.?|approximately|roughly)\s*\)?\s*$", re.I)

# the signs a chain of working is written with: T = 2π√(l/g) ≈ 2.01 s; not the = of <=, >=, != or =/=, whose
# right side is no value of the answer (n >= 2 is not 2)
_EQUALS = re.compile(r"\\approx|\\simeq|[≈≃]|(?<![<>!/=])=(?![=/>])")
# and its steps, as on paper: 6 − 4 → 2, 3N − k ⇒ 1, two constraints, so 1. The answer is the value after the
# last; the parser reads these only between equations
_STEPS = re.compile(
    r"==>|-->|=>|->|[→⟶⇒⟹∴]|\\(?:to|rightarrow|longrightarrow|Rightarrow|Longrightarrow|implies|therefore)(?![A-Za-z])"
    rf"|\b(?:{'|'.join(sorted(IMPLYING_WORDS))})\b",
    re.I,
)

_SEPARATED = re.compile(r"[;\n]|\\\\")
_LISTED_NAME = re.compile(r",\s*([^\W\d_][\w₀-₉']*)\s*$")  # the "2, k" of n = 2, k = 4: a new name after a value
# a quantity's name before its value, which is no working: T, T_0, τ, ω₀
_QUANTITY = re.compile(r"[^\W\d_][\w₀-₉]*")
# a quantity's name after its value, which the value may stand before (2.01 s = T, 2 = n, 2 = DOF, 2 = d.o.f.,
# 2.01 s = the period): one name, or "the" and one word, and nothing else
_NAME_AFTER = re.compile(r"(?:the\s+)?(?:[^\W\d_][\w₀-₉']*|(?:[A-Za-z]\.){2,})\.?", re.I)
# a word of a count's label that is no quantity of a problem's: DOF, n_dof, freedom (of degrees of freedom),
# coordinates (of generalized coordinates), answer, total, and f or s, as textbooks name the count (Landau's s);
# k, N, 3N, T or constraints is another quantity's
COUNT_NAME = re.compile(r"[fs]|\w*(?:dof|freedom|coordinate|answer|total|result)\w*|ans", re.I)
# words that take a number back or doubt it: 6 − 4 = 2? no, 4; 6 − 4 = 2 is wrong, it is 4; maybe 2. Not the
# "no" of 15 (no constraints), before a word, which says what was counted
_CORRECTION = re.compile(
    r"\bno\b(?!\s+(?!(?:wait|sorry|actually|the|that|this|it's)\b)[^\W\d_]{3,})(?!\.\s*of\b)"  # No. of: number of
    r"|\b(?:nope|not|never|wait|wrong|incorrect|false|mistakes?|mistaken|oops|sorry|actually|instead|rather|"
    r"correction|corrected|scratch|ignore|typo|meant|should|redo|maybe|perhaps|probably|possibly|unsure|"
    r"uncertain|I\s+think|I\s+guess|I\s+believe)\b|\?",
    re.I,
)
_JOINING = frozenset({"or", "and", "but", "yes", "so"})  # a single word after =, and no name

# where a remark may begin after a number: a bracket or a mark of punctuation, a spaced dash, a word,
# or an abbreviation (d.o.f.)
_REMARK = re.compile(r"[(\[{,:;–—]|\s-\s|(?<![A-Za-z0-9_\\])(?:[A-Za-z]{2,}|(?:[A-Za-z]\.){2,})")
_SENTENCE_END = re.compile(r"(?<=[^\d\s.])\.$")
_NUMBER = re.compile(r"(?<![\w.])[0-9]")  # the first digit of a number of its own, not of θ1
# "one" after these is a pronoun (the one that swings), not a number
_PRONOUN_ONE = re.compile(r"\b(?:the|a|this|that|which|each|any|every|no)\s+$", re.I)
_FIRST_WORD = re.compile(r"[(\[]?\s*([^\W\d_]+)\b\.?(?!\w)")  # the word a remark begins with, where it may be a unit
_UNIT_WORDS = {"sec", "secs", "msec", "msecs"}  # seconds, not remarks, where no unit is asked for
_PRECISION = re.compile(
    r"(?:(?:rounded|correct|accurate|given)\s+)?(?:(?:to|at)\s+)?[0-9]{1,2}\s*(?:significant\s+|sig\.?\s+)?"
    r"(?:figures?|digits?|decimal\s+places?|decimals|sig\.?\s*figs?|s\.?\s?f\.?|d\.?\s?p\.?)[)\].]?\s*",
    re.I,
)
_PER_CENT = re.compile(r"%|\bper\s*cent\b", re.I)
_UNIT_NAMED = re.compile(r"(?<![^\W\d_])[^\W\d_]{2,}(?![^\W\d_])")  # a unit named in a remark: not s or m, a letter
_REMARKS_TRIED = 12

_WORDS = [
    "zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "eleven", "twelve",
    "thirteen", "fourteen", "fifteen", "sixteen", "seventeen", "eighteen", "nineteen", "twenty",
]  # fmt: skip
NUMBER_WORDS = {word: str(value) for value, word in enumerate(_WORDS)}
_NUMBER_WORD = re.compile(r"\b(?:" + "|".join(_WORDS) + r")\b", re.I)

_LENGTH = 200  # longer answers are read as typed: these readings are for a number and a few words


def read_number(
    text: str,
    reads: Callable[[str], ParsedAnswer | None],
    names: Collection[str],
    *,
    decimal_comma: bool = False,
    unit: str = "",
    uncertainty: bool = False,
    count: bool = False,
    asked: Collection[str] = (),
) -> tuple[str, ParsedAnswer | None, tuple]:
    """The text to judge, its reading (None: read it as typed, and say why it fails), and notes.

    ``reads(text)`` is the reading of ``text`` if it is a number (with its unit, where the part has
    one), else None; ``names`` are the problem's, which a remark after the number does not use.
    ``decimal_comma`` reads 2,01 as 2.01; ``unit`` (the unit the part asks for a quantity in, if any) reads
    2.006 sec as 2.006 s, and TeX's 2.006~\\text{s} as 2.006 s, and of values stated side by side
    (``T = 2.006 s, f = 0.498 Hz``) grades the one in that unit; ``uncertainty`` (a measured value may
    have one) reads 2.006 ± 0.001 s as 2.006 s, with a note that the uncertainty was not graded.
    ``count`` (a whole number is asked for) reads ``9 − 3 = 6 ≠ 9`` as 6, a remark ruling out 9, as
    is ``2 (not 4)``. ``asked`` are the names of the quantity asked for, where the part gives them: of
    ``n = 6 − 4 = 2, k = 4``, n's value is graded.

    Words that take a number back or doubt it (``6 − 4 = 2? no, 4``), or may make it another (``at most
    2``), send the answer to a person, with a note that says so: which is the answer is not for the checker
    to say.
    """
    # a side of working is read again: for the final value, for working that does not hold, and beside words
    reads = lru_cache(maxsize=None)(reads)
    text = _count_spelled(text) if count and len(text) <= _LENGTH else text
    decimal_comma = max(decimal_comma, _commas(text, decimal_comma))  # EVERY, as decided for the whole answer
    prepared, answer, notes = _read_number(
        text, reads, names, decimal_comma=decimal_comma, unit=unit, uncertainty=uncertainty, count=count, asked=asked
    )
    if answer is not None and unit and not count and not any(note[0] in _FOR_A_PERSON for note in notes):
        notes = _stated_values_false(text, answer, reads, names, notes, asked)
    lines = _lines(text) if len(text) <= _LENGTH and _SEPARATED.search(text) else [text]
    said = lines[0] if len(lines) == 1 else text
    ruled_out = _ruled_out(said) if count else None
    said = ruled_out["value"] if ruled_out else said  # 2 (not 4): its "not" rules 4 out, and doubts no number
    return _qualified(said, _doubted(said, (prepared, answer, notes), reads), count)


# a value an answer gives one of the problem's names: …, where l = 2 m; g = 9.81 m/s^2
_STATED_VALUE = re.compile(
    r"(?<![\w.])([^\W\d_][\w₀-₉]*)\s*=\s*([+-]?[0-9]+(?:\.[0-9]+)?(?:[eE][+-]?[0-9]+)?(?:\s*[A-Za-z][A-Za-z/^0-9]*)?)"
    r"[^\S\n]*(?=$|[,;.)\n]|\s+(?:and|where|with)\b)"
)
_READ_PAST = frozenset({"final_value", "remark_ignored", "statements_left_out", "number_read", "number_in_sentence"})
_STATED_TRIED = 4


def _stated_values_false(
    text: str, answer: ParsedAnswer, reads, names: Collection[str], notes: tuple, asked: Collection[str] = ()
) -> tuple:
    """``notes``, or where the answer gives the problem's names values of its own (``T = 2π√(l/g) = 2.006 s,
    where l = 2 m``) at which its working does not come to the value graded, the note that sends it to a
    person: read past, the values were the ones the problem gives, and the working held. So too where it
    gives the asked quantity (``asked``) another value (``2.006 s, where T = 3.13 s``)."""
    if len(text) > _LENGTH:
        return notes
    stated = {}
    final = _last_side(answer)
    for found in list(_STATED_VALUE.finditer(text))[:_STATED_TRIED]:
        read = parse_answer(found[2]) if found[1] in names or found[1] in asked else None
        value = in_units(read.value) if read is not None and read.ok and read.kind == "expression" else None
        if value is None or not value[0].is_number:
            continue
        if found[1] not in names:  # the asked quantity's own value: the one graded, or another
            if not _agree(read.value, final, count=False):
                kept = tuple(note for note in notes if note[0] not in {"working_false_for_a_person", *_READ_PAST})
                typed = shown(_SENTENCE_END.sub("", text.strip()))
                return (*kept, ("working_false_for_a_person", {"value": shown(answer.text), "working": typed}))
            continue
        stated[found[1]] = float(value[0] * sympy.Rational(value[1]))
    if not stated:
        return notes
    pattern = re.compile(r"(?<![^\W\d_])(?:" + "|".join(map(re.escape, stated)) + r")(?![\w])")
    held = []
    for side in _sides(text)[0][:_SIDES]:
        if not pattern.search(side) or _QUANTITY.fullmatch(side) or re.search(r"[,;]", side):
            continue  # l = 2 m: the name itself, not working in it; 2 m, g: the end of one statement
        read = reads(side, working=True, stated=tuple(sorted(stated.items())))
        if read is not None and not _agree(_last_side(read), final, count=False):
            # one note on the working, the whole of it: the chain's own was the working up to the where
            kept = tuple(note for note in notes if note[0] not in {"working_false_for_a_person", *_READ_PAST})
            typed = shown(_SENTENCE_END.sub("", text.strip()))
            value = next((details["value"] for key, details in notes if key in _READ_PAST and "value" in details), "")
            return (*kept, ("working_false_for_a_person", {"value": value or answer.text, "working": typed}))
        if read is not None:
            held.append(side)
    if held and any(note[0] == "working_false_for_a_person" for note in notes):
        # T = 2π√(l/g) = 2.837 s, where l = 2 m: the working holds, at a value the problem does not give
        own = [name for name in sorted(stated) if not _same_at(held, {name: stated[name]}, reads)]
        kept = tuple(note for note in notes if note[0] not in {"working_false_for_a_person", *_READ_PAST})
        details = {
            "names": listed([f"`{unicode_name(name)}`" for name in own]),
            "values": "value" if len(own) == 1 else "values",
            "ones": "one" if len(own) == 1 else "ones",
        }
        return (*kept, ("own_values", details)) if own else notes
    return notes


def _same_at(sides: list[str], stated: dict, reads) -> bool:
    """Whether each of ``sides`` comes to the same number at the ``stated`` values as at the problem's."""
    for side in sides:
        mine, given = reads(side, working=True, stated=tuple(stated.items())), reads(side, working=True)
        if mine is None or given is None or not _agree(_last_side(mine), _last_side(given), count=False):
            return False
    return True


def _count_spelled(text: str) -> str:
    """A count as students glue it to what it counts, spelt as the reading knows it: ``2-DOF`` and ``2DOF`` as
    ``2 DOF``, ``degrees-of-freedom`` as ``degrees of freedom``, ``a single degree of freedom`` as ``one …``."""
    text = _GLUED_DOF.sub(" ", text)
    text = _HYPHENED_DOF.sub(lambda found: found[0].replace("-", " ").replace("\u2010", " "), text)
    return _SINGLE.sub("one ", text)


_GLUED_DOF = re.compile(r"(?<=[0-9])\s*[-\u2010]?\s*(?=dofs?\b)", re.I)
_HYPHENED_DOF = re.compile(r"\bdegrees?[-\u2010]of[-\u2010]freedom\b", re.I)
_SINGLE = re.compile(
    r"\b(?:a|one)\s+single\s+(?=(?:degree|dof|d\.o\.f|generali[sz]ed\s+coordinate|coordinate|angle)s?\b)", re.I
)


def _read_number(
    text: str,
    reads: Callable[[str], ParsedAnswer | None],
    names: Collection[str],
    *,
    decimal_comma: bool,
    unit: str,
    uncertainty: bool,
    count: bool,
    asked: Collection[str] = (),
) -> tuple[str, ParsedAnswer | None, tuple]:
    """:func:`read_number`, but for the words around the number that a person must read."""
    unequal = _NOT_EQUAL.fullmatch(text) if count and len(text) <= _LENGTH else None
    if unequal:
        return _unequal(unequal, reads, names, asked=asked)
    ruled_out = _ruled_out(text) if count else None
    if ruled_out:
        return _unequal(
            ruled_out, reads, names, rest=ruled_out["rest"].lstrip(", "), asked=asked
        )  # as other remarks are
    uncertain = _UNCERTAIN.fullmatch(text) if uncertainty and len(text) <= _LENGTH else None
    if uncertain:  # 2.006 ± 0.001 s, (2.006 ± 0.001) s, 2.006(1) s: the value is graded, its uncertainty is not
        if uncertain["cvalue"]:
            name, number, after = uncertain["cname"], uncertain["cvalue"], uncertain["cunit"]
            error = f"({uncertain['digits']})"
        else:
            name, number, after = uncertain["name"], uncertain["value"], uncertain["unit"] or uncertain["before"]
            error = f"± {uncertain['error']}"
        value = f"{name or ''}{number} {after or ''}".strip()
        prepared, answer, notes = read_number(value, reads, names, decimal_comma=decimal_comma, unit=unit)  # no ± left
        if answer is not None:
            return prepared, answer, (*notes, ("uncertainty_left_out", {"error": error}))
    inside = list(_UNCERTAINTY_INSIDE.finditer(text)) if uncertainty and not uncertain and len(text) <= _LENGTH else []
    if len(inside) == 1:  # The period is 2.006 ± 0.001 s.
        (inside,) = inside
        rest = text[: inside.start()] + text[inside.end() :]
        prepared, answer, notes = read_number(rest, reads, names, decimal_comma=decimal_comma, unit=unit)
        if answer is not None:
            return prepared, answer, (*notes, ("uncertainty_left_out", {"error": inside[0].strip()}))
    stated = _stated_in_unit(text, reads, names, decimal_comma, unit, uncertainty) if unit and not count else None
    if stated is not None:
        return stated
    plain = len(text) <= _LENGTH and not _SEPARATED.search(text) and not re.search(_UNEQUAL_SIGN, text)
    if count and plain:  # 2 (6 − 4), n = 2 (6 − 4): before the product as typed is read
        bracketed = _count_with_bracket(_sides(text)[0][-1], reads, names)
        if bracketed is not None:
            return bracketed
    if len(text) <= _LENGTH and _SEPARATED.search(text):
        lines = _lines(text)
        if len(lines) == 1 and lines[0] != text:  # 6 − 4 = 2; with nothing after: one line, as typed
            return _read_number(
                lines[0],
                reads,
                names,
                decimal_comma=decimal_comma,
                unit=unit,
                uncertainty=uncertainty,
                count=count,
                asked=asked,
            )
        worked = _worked_over_lines(
            text, reads, names, decimal_comma=decimal_comma, unit=unit, count=count, asked=asked
        )
        if worked is not None:
            return worked
    reasoned = _reasoned(text, reads, names, decimal_comma, unit, count, asked) if len(text) <= _LENGTH else None
    if reasoned is not None:
        return reasoned
    # n = 2 since k = 4: read as typed, a list whose last new name, k, would be taken for the answer
    given = _given(text, reads, names, decimal_comma, unit, count, asked) if len(text) <= _LENGTH else None
    if given is not None and given[1] is not None:
        return given
    prepared, notes = _spelled(text, decimal_comma, unit)
    answer = reads(prepared)
    if answer is not None and len(text) <= _LENGTH and not _SEPARATED.search(text):
        notes += _steps_false(text, answer, (reads, decimal_comma, unit, count))
    if answer is not None or len(text) > _LENGTH or _SEPARATED.search(text):
        return prepared, answer, notes  # x = 1; y = 2 is a system, not working
    if given is not None:
        return given
    if re.search(_UNEQUAL_SIGN, text):
        return prepared, None, notes  # 6 ≠ 9 = 3·3: the chain's last side is what the answer is not
    bare = _ABOUT_AFTER.sub("", _ABOUT.sub("", text, count=1))
    pieces, runs = _sides(bare)
    last = len(pieces) - 1
    listed = _listed(text, pieces, reads, names, decimal_comma, unit, count, asked)
    if listed is not None:
        return listed
    # the final value; else, of a value and its name alone (2.01 s = T), the first side: not of longer working,
    # whose first side is no answer (6 − 4 = 2 = 4θ), nor across a step (6 − 4 → n), which says what comes last,
    # nor before anything but a name, where the last side may take it back (6 − 4 = 2? no, 4) or be another
    # number (3 − 2 = 1 or 2, 3 − 2 = 1 x 2)
    first = (0,) if last == 1 and len(runs) == 1 and _is_name(pieces[1]) else ()
    for index in dict.fromkeys((last, *first)):
        for before, typed, rest in _number_in(pieces[index], names):
            if count and _COUNT_THEN_BRACKET.fullmatch(typed):
                continue  # 2 (3), then words: no product of a count and its bracket (see _count_with_bracket)
            words = NUMBER_WORDS.get(typed.lower().rstrip("."))
            prepared, notes = _spelled(words or typed, decimal_comma, unit)
            answer = reads(prepared)
            if answer is None or (rest and not _is_remark(rest, names, words or typed, unit)):
                continue
            typed = _SENTENCE_END.sub("", typed).rstrip(" ,;")  # The period is 2.01 s. 1, the angle θ
            word = _FIRST_WORD.match(rest) if unit and not count and not answer.symbols else None
            if word and unit_like(word[1]):  # 2.006 flubsec: a unit we do not know may make it another number
                return prepared, answer, (("unit_unknown_for_a_person", {"value": typed, "unit": word[1]}),)
            said = _words_beside(f"{before} {rest}") if last and index == last else ""
            numbers = (reads, decimal_comma, unit, count)
            if said and _other_values(pieces[:last], answer, *numbers):
                # 6 − 4 = 2, so also 4: words beside a value the working does not come to may offer a second
                return prepared, answer, (("number_doubted_for_a_person", {"words": said}),)
            # 4 − 1 = 2, 3·5 = 16 → 15: working that does not hold, a slip or a value not worked out
            at_last = last and index == last
            working = _false_working(pieces, runs, _last_side(answer), numbers, bare.strip()) if at_last else None
            first = (
                _count_said(pieces[:last], _last_side(answer)) if count and said and last and index == last else None
            )
            if first and _ASKED.match(rest.lstrip(",:;–—- ")):
                # 2 degrees of freedom, so 1 generalized coordinate: the count said twice, once otherwise
                return prepared, answer, (("counts_differ_for_a_person", {"first": first, "value": typed}),)
            if working:
                notes += (("working_false_for_a_person", {"value": typed, "working": shown(working)}),)
            elif before:
                notes += (("number_in_sentence", {"value": typed}),)
            elif rest:
                rest = rest.lstrip(",:;–—- ")
                other = count and _counts_other(words or typed, rest, names)
                key, details = ("number_qualified_for_a_person", "words") if other else ("remark_ignored", "rest")
                notes += ((key, {"value": typed, details: shown(rest)}),)
            elif other := (_other_label(pieces, index, asked) if count and last == 1 else None):
                # 2 = k, No. of constraints = 2, where n is asked: the value of another quantity, or a slip
                notes += (
                    ("label_for_a_person", {"label": f"`{shown(other)}`", "name": unicode_name(next(iter(asked)))}),
                )
            elif last and index == last and not all(_QUANTITY.fullmatch(piece) for piece in pieces[:last]):
                notes += (("final_value", {"value": typed}),)  # T = 2π√(l/g) = 2.01 s; not T = 2.0 s (approx)
            elif last:
                notes += (("number_read", {"value": typed}),)
            elif words:
                notes += (("number_word", {"typed": typed, "number": words}),)
            return prepared, answer, notes
    prepared, notes = _spelled(text, decimal_comma, unit)
    return prepared, None, notes


_LINES = 6  # lines of working, at the most
_SIDES = 12  # sides of the lines before the last, at the most: each is read


def _worked_over_lines(
    text: str, reads, names, *, decimal_comma: bool, unit: str, count: bool, asked: Collection[str]
) -> tuple[str, ParsedAnswer | None, tuple] | None:
    """``6 − 2 = 4; 6 − 4 = 2``, or the same on lines: working over several lines, each before the last
    a chain of numbers (``6 − 2 = 4``, ``2π√(1/9.81) = 2.006 s``), is graded at the value of the last
    line, read as any line is, as a chain on one line is (``6 − 2 = 4 → 2``): the final value, with
    the note that the working before it is not graded. Where the lines disagree, the last is the
    student's last word; but words beside it may say it is not (``6 − 4 = 2`` then ``also 4``, ``4 as
    well``), and send the answer to a person, as words that take a line back or doubt it do
    (:func:`_doubted`). None where ``text`` is no such working: lines that name their values
    (``n = 2; m = 3``, ``3N = 6; k = 4; n = 2``) are read as a list, and numbers alone (``2; 4``) offer
    a choice."""
    lines = _lines(text)
    if not 2 <= len(lines) <= _LINES:
        return None
    *working, final = lines
    sides = [_sides(line) for line in working]
    if sum(len(pieces) for pieces, _ in sides) > _SIDES:
        return None
    values, false = [], None  # each line's last; the first line whose sides do not come to it
    for line, (pieces, runs) in zip(working, sides, strict=True):
        read = [reads(_spelled(piece, decimal_comma, unit)[0]) for piece in pieces] if len(pieces) > 1 else [None]
        if None in read:
            return None
        values.append(_last_side(read[-1]))
        if false is None and _false_working(pieces, runs, values[-1], (reads, decimal_comma, unit, count), line):
            false = line
    prepared, answer, notes = _read_number(
        final, reads, names, decimal_comma=decimal_comma, unit=unit, uncertainty=False, count=count, asked=asked
    )  # an uncertainty in the text was read past before (see _UNCERTAINTY_INSIDE)
    if answer is None:
        return None
    said = _words_beside(final)
    if said and not all(_agree(value, _last_side(answer), count) for value in values):
        return prepared, answer, (("number_doubted_for_a_person", {"words": said}),)
    if any(note[0] == "working_false_for_a_person" for note in notes):
        return prepared, answer, notes
    value = next((details["value"] for _, details in notes if "value" in details), _sides(final)[0][-1])
    notes = tuple(note for note in notes if note[0] not in ("final_value", "number_read"))
    if false is not None:
        return prepared, answer, (("working_false_for_a_person", {"value": value, "working": shown(false)}), *notes)
    return prepared, answer, (("final_value", {"value": value}), *notes)


# a word beside a line's number, not a name of one letter (n = 4, T = 3 s)
_WORD = re.compile(r"(?<![\w\\])[^\W\d_]{2,}(?!\w)")


def _words_beside(text: str) -> str:
    """The words of ``text``, as a phrase (``as well``, ``The answer is``): not a name of one letter,
    a step (so, hence) or a number in words."""
    said = (word for word in _WORD.findall(text) if word.lower() not in (*IMPLYING_WORDS, *NUMBER_WORDS))
    return shown(" ".join(said))


def _other_values(pieces: list[str], answer: ParsedAnswer, reads, decimal_comma: bool, unit: str, count: bool) -> bool:
    """Whether a side of working (``pieces``) that reads as a number is not the value ``answer`` says;
    and where there are too many sides to read, whether one may be."""
    if len(pieces) > _SIDES:
        return True
    final = _last_side(answer)
    values = [reads(_spelled(piece, decimal_comma, unit)[0]) for piece in pieces if piece]
    return not all(_agree(_last_side(value), final, count) for value in values if value is not None)


_ROUNDED = 0.05  # a measured value rounded (2π√(1/9.81) = 2.006 s, then 2.0 s) is no other value


def _agree(value, other, count: bool) -> bool:
    """Whether two values of working say the same: a count's the same number; a measured value's the
    same to within its rounding, in SI units (2.006 s = 2006 ms), where a side without a unit may be in
    SI units or in the other side's (2π√(1/9.81) = 2006 ms, 2006 = 2006 ms); never two sides in units
    of different dimensions (2.006 kg = 2.006 s)."""
    if value == other:
        return True
    if count:
        return False
    first, second = in_units(value), in_units(other)
    if first is None or second is None:
        return False  # a value with a name in it: not said to agree
    (number, size, powers), (other_number, other_size, other_powers) = first, second
    in_si = (number * sympy.Rational(size), other_number * sympy.Rational(other_size))
    if powers == other_powers:
        return _near(*in_si)
    if any(powers) and any(other_powers):
        return False
    return _near(*in_si) or _near(number, other_number)


def _near(value, other) -> bool:
    try:
        ratio = complex((value / other).evalf(15))
    except (TypeError, ValueError, ArithmeticError):
        return False  # 0: not said to agree
    return abs(ratio - 1) <= _ROUNDED


def _last_side(answer: ParsedAnswer):
    """The value a number read says: its last side (``n = 2``: 2)."""
    return answer.value.rhs if answer.kind == "equation" else answer.value


def _lines(text: str) -> list[str]:
    """The lines of ``text``, cut at new lines, ``;`` and TeX's ``\\\\`` outside brackets; blank ones left out."""
    depth, cuts = 0, [0]
    for index, character in enumerate(text):
        depth += (character in "([{") - (character in ")]}")
        found = _SEPARATED.match(text, index)
        if found and depth == 0 and index >= cuts[-1]:
            cuts += [index, found.end()]
    cuts.append(len(text))
    lines = [text[start:end].strip() for start, end in zip(cuts[::2], cuts[1::2], strict=True)]
    return [line for line in lines if line]


# the notes that leave which number is meant to a person
_FOR_A_PERSON = frozenset({"number_doubted_for_a_person", "number_qualified_for_a_person", "unit_unknown_for_a_person"})
_LAST_NUMBERS = 6  # numbers tried from the end of an answer, for the one shown beside a doubt
_DIGITS = re.compile(r"(?<![\w.])[0-9]+(?:\.[0-9]+)?(?![\w.])")


def _doubted(text: str, read: tuple[str, ParsedAnswer | None, tuple], reads) -> tuple[str, ParsedAnswer | None, tuple]:
    """``read`` (the text to judge, its reading, notes), or where ``text`` takes a number back or doubts
    it (``6 − 4 = 2 is wrong, it is 4``, ``6 − 4 = 2? No wait = 4``), a note that sends it to a person.
    Words read past beside a number (a remark, the working before it) may say it is not the answer;
    where no number could be read, working with such words is shown by its last number, for the
    person (nothing is proposed). Where there is no working either (``2? no, 4``), the answer is
    refused as typed, for the student to write again."""
    prepared, answer, notes = read
    if any(note[0] in _FOR_A_PERSON for note in notes):
        return read
    said = _said(_CORRECTION, text)
    if not said:
        return read
    if answer is None:
        if len(text) > _LENGTH or len(_sides(text)[0]) < 2:
            return read
        for typed in [found[0] for found in _DIGITS.finditer(text)][::-1][:_LAST_NUMBERS]:
            answer = reads(typed)
            if answer is not None:
                prepared = typed
                break
        else:
            return read
    return prepared, answer, (("number_doubted_for_a_person", {"words": said}),)


# words that make a number another, or no one number: less than 2, at most 2, 2 or more, max 2, 2 for each bob
# (4), 2 dozen, two hundred, 2 pairs, 1 pair (not 2 (a pair of angles)). Minimum and maximum only against the
# number: 2 (the minimum number of coordinates) says what a count of degrees of freedom is
_QUALIFYING = re.compile(
    r"\b(?:less|fewer|more|greater|larger|smaller|bigger|higher|lower)\s+than\b|\bat\s+(?:most|least)\b"
    r"|\bup\s+to\b|\bor\s+(?:more|less|fewer|so)\b|\b(?:(?:for|on)\s+)?(?:each|every)\b|\b(?:per|apiece)\b"
    r"|\b(?:max|maximum|min|minimum)\b\.?(?=\s*[0-9])"
    r"|(?<=[0-9])\s*[(,]?\s*(?:max|maximum|minimum)\b(?=\s*\)?\s*[.,;]?\s*$)"
    r"|\b(?:dozens?|hundreds?|thousands?|millions?|billions?|pairs)\b|(?:(?<=[0-9])|(?<=[0-9]\s)|(?<=\bone\s))pair\b",
    re.I,
)
# and beside a count, which is exact, words of an approximation: about 2, ≈ 2, 2 (roughly)
_APPROXIMATING = re.compile(
    r"\b(?:about|around|roughly|approximately|approx|nearly|almost|circa|ca|ish)\b|[≈≃~]"
    r"|\\(?:approx|simeq|sim)(?![A-Za-z])",
    re.I,
)


def _qualified(text: str, read: tuple[str, ParsedAnswer | None, tuple], count: bool) -> tuple:
    """``read`` (the text to judge, its reading, notes), or where words beside its number may make it
    another (``less than 2``, ``2 for each bob``, ``two hundred``, and for a count ``about 2``), a note
    that sends it to a person: graded as the bare number, such an answer could pass where it says
    something else. "One coordinate for each bob", after a count, says what each counts, and is read
    past (see :func:`_is_remark`)."""
    prepared, answer, notes = read
    if answer is None or any(note[0] in _FOR_A_PERSON for note in notes):
        return read
    words = _PER_EACH.sub(" ", text)
    said = _said(_QUALIFYING, words) or (_said(_APPROXIMATING, words) if count else "")
    if not said:
        return read
    sides = [side for side in _sides(prepared)[0] if side] or [prepared.strip()]  # n ≈ 2: the 2
    value = next((details["value"] for _, details in notes if "value" in details), sides[-1])
    return prepared, answer, (("number_qualified_for_a_person", {"value": value, "words": said}),)


def _said(words: re.Pattern, text: str) -> str:
    """What ``words`` finds in ``text``, as typed, each once, for a note: ``?, no``."""
    said: dict[str, str] = {}
    for found in words.finditer(text):
        typed = " ".join(found[0].strip(" (,").split())  # 2 (max): max
        said.setdefault(typed.lower(), typed)
    return shown(", ".join(said.values()))


def _other_label(pieces: list[str], index: int, asked: Collection[str]) -> str | None:
    """Where a count and one label are set equal, the label where it names another quantity than the count
    ``asked`` (``k`` of ``2 = k``, ``No. of constraints`` of ``No. of constraints = 2``), as typed; else None.
    A label the parser reads (``k = 2``) is compare's to judge; these are read here."""
    label = pieces[1] if index == 0 else pieces[0]
    if not asked or (index and not _WORDS_LABEL.fullmatch(label)):
        return None
    return None if _names_count(label, asked) else label.strip()


_WORDS_LABEL = re.compile(r"\s*[^\W\d_][\w.']*(?:\s+[^\W\d_][\w.']*)*\s*")  # No. of constraints: words alone


def _names_count(side: str, asked: Collection[str]) -> bool:
    """Whether a name after a count (``2 = n``, ``2 = the DOF``) is the asked count's, or a word for one."""
    return any(word in asked or COUNT_NAME.fullmatch(word) for word in _LABEL_WORD.findall(side))


_LABEL_WORD = re.compile(r"[^\W\d_][\w₀-₉']*")  # n, DOF, and the words of "No. of DOF", d.o.f. as d, o, f


def _is_name(side: str) -> bool:
    """Whether ``side`` is a quantity's name alone (T, n, DOF, the period), not words that take the value
    before it back (no, wrong) or more of the answer."""
    if len(side) > SHOWN or not _NAME_AFTER.fullmatch(side) or _CORRECTION.search(side):
        return False
    return side.rstrip(".").lower() not in _JOINING


# 9 − 3 = 6 ≠ 9, where a count is asked: the count, then once a number it is not, and nothing after
_UNEQUAL_SIGN = r"≠|!=|=/=|/=|\\neq?(?![A-Za-z])"
_NOT_EQUAL = re.compile(
    rf"(?P<value>(?:(?!{_UNEQUAL_SIGN}).)+?)\s*(?P<sign>{_UNEQUAL_SIGN})\s*"
    rf"(?P<other>[0-9]+|(?:{'|'.join(_WORDS)})\b)\s*\.?\s*",
    re.I | re.S,
)


# 2 (not 4), n = 2, not 4, where a count is asked: the count, then a number it is not, as ≠ 4 says it
_RULED_OUT = re.compile(
    rf"(?P<value>.+?)\s*(?P<rest>(?P<open>\(\s*|,\s*)not\s+(?P<other>[0-9]+|(?:{'|'.join(_WORDS)})\b)\s*"
    r"(?P<close>\)?))\s*\.?\s*",
    re.I | re.S,
)


def _ruled_out(text: str) -> re.Match | None:
    """``2 (not 4)``, ``2, not 4``: the count and the number it rules out, in a bracket or after a comma."""
    found = _RULED_OUT.fullmatch(text) if len(text) <= _LENGTH else None
    if found is None or found["open"].startswith("(") != bool(found["close"]):
        return None
    return found


def _unequal(
    found: re.Match, reads, names, rest: str | None = None, asked: Collection[str] = ()
) -> tuple[str, ParsedAnswer | None, tuple]:
    """``9 − 3 = 6 ≠ 9``, ``2 (not 4)``: the count before ``≠`` (or the bracket), read as any count is,
    with a note that the number it rules out (``rest``, as typed; else ``≠ 9``) was not graded. As typed
    (refused, for its sign or its "not") where that count is the number it rules out, or is none."""
    prepared, answer, notes = read_number(found["value"], reads, names, count=True, asked=asked)
    other = int(NUMBER_WORDS.get(found["other"].lower(), found["other"]))
    value = _value_of(answer)
    if value is None or value == other:
        return found[0], None, ()  # 6 ≠ 6 says no count
    typed = next((details["value"] for _, details in notes if "value" in details), _sides(found["value"])[0][-1])
    rest = rest or f"{found['sign']} {found['other']}"
    return prepared, answer, (*notes, ("remark_ignored", {"value": typed, "rest": shown(rest)}))


def _value_of(answer: ParsedAnswer | None):
    """The number an answer read as a number says: its value, or its last side (``n = 2``); else None."""
    if answer is None or answer.kind not in ("expression", "equation"):
        return None
    value = answer.value.rhs if answer.kind == "equation" else answer.value
    return value if value.is_number else None


def _listed(
    text: str, pieces: list[str], reads, names, decimal_comma: bool, unit: str, count: bool, asked: Collection[str]
):
    """``n = 3N − k = 6 − 4 = 2, k = 4``: statements joined by a comma, the last a name's value with no
    working, where that name was used in the working before it. It is a value the working was done
    with, not the answer: the statement before it is graded, with a note that the value was not (as
    ``2, since k = 4`` is). So too where the working is labelled with the name ``asked`` and the value
    is another's (``n = 6 − 4 = 2, k = 4``, where n is asked). None for any other text, whose last
    statement is graded (``ω = √9.81 = 3.13, T = 2π/3.13 = 2.006 s``, and ``n = 2, k = 4``, where which
    name is asked is not known)."""
    last = len(pieces) - 1
    found = _LISTED_NAME.search(pieces[last - 1]) if last >= 2 else None
    if found is None:
        return None
    name = found[1]
    start = 1 if _QUANTITY.fullmatch(pieces[0]) else 0  # the working, not its label: n = 2, n = 4 is two values of n
    before = " = ".join(pieces[start : last - 1])
    said = list(_NAME_SAID.finditer(text))
    # one such value: more, and the head is read again for each, each time read whole (a hostile answer's cost)
    labelled = start and pieces[0] in asked and name not in asked
    if len(said) == 1 and said[0][1] == name and (labelled or re.search(rf"(?<!\w){re.escape(name)}(?!\w)", before)):
        head, rest = text[: said[0].start()], text[said[0].start() + 1 :].strip()
        prepared, answer, notes = read_number(
            head, reads, names, decimal_comma=decimal_comma, unit=unit, count=count, asked=asked
        )
        if answer is None:
            return None
        value = next((details["value"] for _, details in notes if "value" in details), head.strip())
        return prepared, answer, (*notes, ("remark_ignored", {"value": value, "rest": shown(rest)}))
    return None


_STATEMENTS = 4  # values stated side by side, at the most: each is read
# a statement of a value: a name, then = (not ==, <=, =>)
_STATEMENT = re.compile(r"\s*[^\W\d_][\w₀-₉']*\s*(?:(?<![<>!=])=(?![=>])|[≈≃]|\\approx|\\simeq)")


def _stated_in_unit(
    text: str, reads, names, decimal_comma: bool, unit: str, uncertainty: bool
) -> tuple[str, ParsedAnswer | None, tuple] | None:
    """``T = 2.006 s, f = 0.498 Hz``, ``f = 0.498 Hz; T = 2.006 s``, ``T = 2.006 s (f = 0.498 Hz)``: values
    stated side by side, each with its unit, just one of them in ``unit``, the part's: that one is
    graded, as it would be alone, with a note that the others were not. None for any other text: where
    two are in the part's unit (``T = 2.006 s, T = 3 s``), or one has no unit and so may be in it
    (``T = 2.006 s, ω = 3.13``), which is the answer is not for the checker to say."""
    statements = _statements(text) if len(text) <= _LENGTH else None
    if statements is None or not 2 <= len(statements) <= _STATEMENTS:
        return None
    wanted = unit_named(unit)
    if wanted is None:
        return None  # the author's error, said where the part's unit is read (compare._unit)
    read, in_unit = [], []
    for statement in statements:
        prepared, answer, notes = read_number(
            statement, reads, names, decimal_comma=decimal_comma, unit=unit, uncertainty=uncertainty
        )
        value = _last_side(answer) if answer is not None else None
        found = in_units(value) if isinstance(value, sympy.Expr) and value.free_symbols else None
        if found is None:
            return None  # no value, or one with no unit
        read.append((prepared, answer, notes))
        if found[2] == wanted[1]:
            in_unit.append(len(read) - 1)
    if len(in_unit) != 1:
        return None
    (graded,) = in_unit
    others = ", ".join(statement for index, statement in enumerate(statements) if index != graded)
    prepared, answer, notes = read[graded]
    details = {"graded": shown(statements[graded]), "unit": unit, "others": shown(others)}
    return prepared, answer, (*notes, ("statements_left_out", details))


def _statements(text: str) -> list[str] | None:
    """The statements of values in ``text`` (``T = 2.006 s``, ``f = 0.498 Hz``), as typed: cut at commas,
    semicolons and new lines outside brackets, and a last bracket that states a value (``(f = 0.498 Hz)``).
    After a comma, what states no value belongs to the statement before it (``T = 2,01 s``, a decimal
    comma). None where ``text`` begins with no statement, or another mark is followed by none."""
    depth, start, pieces, separator = 0, 0, [], ""
    for index, character in enumerate(text):
        if character == "(" and depth == 0 and text.rstrip(" .").endswith(")"):
            inside = text[index + 1 : len(text.rstrip(" .")) - 1]
            if _balanced(inside) and _STATEMENT.match(inside):
                pieces.append((separator, text[start:index]))
                pieces.append(("(", inside))
                start, separator = None, ""
                break
        depth += (character in "([{") - (character in ")]}")
        if depth == 0 and (character in ",;\n" or text.startswith("\\\\", index)):
            pieces.append((separator, text[start:index]))
            start, separator = index + 1, character
    if start is not None:
        pieces.append((separator, text[start:]))
    statements: list[str] = []
    for separator, piece in pieces:
        piece = piece.strip(" \\\n")
        if _STATEMENT.match(piece):
            statements.append(piece)
        elif statements and separator == "," and piece:
            statements[-1] = f"{statements[-1]},{piece if piece[0].isdigit() else ' ' + piece}"
        elif piece or separator not in ",;\n":
            return None
    return statements


def _balanced(text: str) -> bool:
    depth = 0
    for character in text:
        depth += (character in "([{") - (character in ")]}")
        if depth < 0:
            return False
    return depth == 0


_NAME_SAID = re.compile(r",\s*([^\W\d_][\w₀-₉']*)\s*(?:[=≈≃]|\\approx|\\simeq)")  # …, k = 4


def _sides(text: str) -> tuple[list[str], tuple[int, ...]]:
    """The sides of a chain of working (``6 − 4 = 2 → 4``: 6 − 4, 2 and 4), split where an equals sign
    or a step stands outside brackets (``2 (so two angles)`` is one side); and where each run of sides
    joined by equals signs alone begins, the runs a step separates (``(0, 2)``; ``(0,)`` where no step
    stands): the sides of a run claim to be equal, and a step that what follows it follows from the run
    before (see :func:`_false_working`)."""
    marks = [(found, False) for found in _EQUALS.finditer(text)] + [(found, True) for found in _STEPS.finditer(text)]
    marks.sort(key=lambda mark: mark[0].start())
    depth = [0] * (len(text) + 1)
    for index, character in enumerate(text):
        depth[index + 1] = depth[index] + (character in "([{") - (character in ")]}")
    pieces, start, runs = [], 0, [0]
    for found, step in marks:
        if found.start() >= start and depth[found.start()] == 0:
            pieces.append(text[start : found.start()].strip())
            start = found.end()
            if step:
                runs.append(len(pieces))
    return [*pieces, text[start:].strip()], tuple(runs)


def _false_working(pieces: list[str], runs: tuple, final, numbers: tuple, typed: str = "") -> str | None:
    """The first run of working (``pieces`` and ``runs``, as :func:`_sides` gives them) whose sides are
    not equal, as typed; None where each holds. ``final`` is the value of the last side as graded, and
    ``numbers`` how sides are read (``reads``, ``decimal_comma``, ``unit``, ``count``). A run is checked
    from its last side back to the first side that is no number: in ``ω = √(9.81) = 3.13, T = 2π/3.13 =
    2.006 s`` the sides after ``3.13, T``, which ends one statement and begins the next. A step says what
    follows from the run before it: where that run is arithmetic alone (perhaps after a name) and the run
    after it comes to another number (``6 − 4 → 3``, ``2 hence 3 − 2 = 1``, ``n = 2 ⇒ n = 1``), the working
    does not hold, and the chain is shown as ``typed``. Not where the two runs name different quantities:
    ``g = 9.81 ⇒ T = 2.006 s`` gives a value, then another."""
    reads, decimal_comma, unit, count = numbers
    if len(pieces) > _SIDES:
        return None
    previous = None  # what the run before a step comes to, where it is arithmetic alone, and its label
    for start, end in zip(runs, [*runs[1:], len(pieces)], strict=True):
        run = pieces[start:end]
        values = [final] if end == len(pieces) else []
        read_all = True
        label = run[0] if len(run) > 1 and _QUANTITY.fullmatch(run[0]) else None  # g = 9.81: not 9.81 grams
        for side in reversed(run[:-1] if values else run):
            if side is run[0] and label is not None:
                break
            # a side of working may be a formula in names the problem gives values (2π√(l/g) = 2.006 s)
            read = reads(_spelled(side, decimal_comma, unit)[0], working=True) if side else None
            reason = _REASON.split(side)[-1] if read is None and side and _REASON.search(side) else None
            if reason:  # 1 because 3 − 1 = 1: the reason's arithmetic is working too, and the first of it
                read = reads(_spelled(reason, decimal_comma, unit)[0], working=True)
                if read is not None:
                    values.append(_last_side(read))
                read_all = False
                break
            if read is None:
                read_all = False
                break
            values.append(_last_side(read))
        if not all(_agree(value, values[0], count) for value in values[1:]):
            return " = ".join(run).rstrip(",;: ")  # 3·5 = 16, so 15: the comma is the step's
        if previous is not None and values and label == previous[1] and not _agree(previous[0], values[0], count):
            return typed or " = ".join(pieces)
        previous = (values[0], label) if values and read_all else None
    return None


def _steps_false(text: str, answer: ParsedAnswer, numbers: tuple) -> tuple:
    """The note on a chain with a step that reads as typed (``2 hence 3 − 2 = 1``: the parser keeps what
    follows the step, or takes the words before it for a name) where its runs do not come to one number
    (:func:`_false_working`); none where they do, or no step stands in it."""
    pieces, runs = _sides(text)
    if len(runs) < 2:
        return ()
    false = _false_working(pieces, runs, _last_side(answer), numbers, text.strip())
    return (("working_false_for_a_person", {"value": pieces[-1], "working": shown(false)}),) if false else ()


# the word that gives a value its reason, whose arithmetic follows: 1 because 3 − 2 = 1, 1, since 3 − 2 = 1
_REASON = re.compile(r"\b(?:because|since|as|given(?:\s+that)?)\b", re.I)


def _reasoned(
    text: str, reads, names, decimal_comma: bool, unit: str, count: bool, asked: Collection[str]
) -> tuple[str, ParsedAnswer | None, tuple] | None:
    """``1 because 3 − 2 = 1``, ``2, since 3 − 2 = 1``: a value, then the arithmetic that is its reason.
    The value before the reason word is the answer, and the reason its working: where a side of it that
    reads as a number is another value, the note says the working does not hold. As typed, the parser
    makes the word a factor (``3·because − 1 = 1``) and the reason's last side the value, whatever came
    before it. None where no value comes before the word, or the reason states values of names
    (``because N = 1 and k = 2``, as :func:`_given` reads them) or ends in no number."""
    found = _REASON.search(text)
    if found is None:
        return None
    head, (*sides, last) = text[: found.start()].rstrip(" ,;:"), _sides(text[found.end() :])[0]
    if sides and sides[0].strip() in asked:
        sides = sides[1:]  # 2 because n = 3 − 2 = 1: the asked count's name labels the working
    elif not sides or _QUANTITY.fullmatch(sides[0]):
        sides = sides if not sides else None
    if not head or sides is None or len(sides) > _SIDES:
        return None
    value = reads(_spelled(last, decimal_comma, unit)[0])
    if value is None:
        return None
    prepared, answer, notes = read_number(
        head, reads, names, decimal_comma=decimal_comma, unit=unit, count=count, asked=asked
    )
    if answer is None:  # 10^400 because 1 = 1: a number too long to read is no reason to grade the 1
        return (head, None, ()) if _NUMBER.search(head) else None
    stated = _last_side(answer)
    typed = next((details["value"] for _, details in notes if "value" in details), _sides(head)[0][-1])
    read = [reads(_spelled(side, decimal_comma, unit)[0]) for side in sides if side]
    if not all(_agree(_last_side(side), stated, count) for side in (*read, value) if side is not None):
        return prepared, answer, (("working_false_for_a_person", {"value": typed, "working": shown(text.strip())}),)
    rest = shown(text[found.start() :].strip())
    return prepared, answer, notes or (("remark_ignored", {"value": typed, "rest": rest}),)


# a count, then brackets and nothing after them: 2 (6 − 4), 1 (2), 15 (5 particles), two (2)
_COUNT_THEN_BRACKET = re.compile(
    rf"\s*(?P<count>[0-9]+|(?:{'|'.join(_WORDS)}))(?P<space>\s*)(?P<rest>[(\[].*[)\]])\s*\.?\s*", re.I | re.S
)
_ARITHMETIC = re.compile(r"[0-9\s.+\-−‒*×·/()\[\]]+")  # digits and signs alone: no ^, whose powers can be huge
# what a degree-of-freedom count counts: 2 (3 degrees of freedom) gives two counts of one thing
_ASKED = re.compile(r"\b(?:degrees?\s+of\s+freedom|freedoms?|dofs?|generali[sz]ed\s+coordinates?)\b", re.I)
# things a count of degrees of freedom is worked out from, which a bracket may say how many there are of:
# 15 (5 particles). A list, not any word: 2 (3 in total), 2 (3 really) offer another count
_THING = [
    "particle", "bob", "bead", "point", "atom", "rod", "string", "pendulum", "link", "spring", "wheel", "disc", "disk",
    "sphere", "ball", "object", "constraint", "coordinate", "angle", "equation", "translation", "rotation", "position",
]  # fmt: skip
_THINGS = frozenset({*_THING, *(f"{thing}s" for thing in _THING), "mass", "masses", "body", "bodies", "axis", "axes"})
_DESCRIBED = re.compile(r"\s*(?:[0-9]+|[A-Za-z]+)\s+(?:[A-Za-z]{2,}\s+)?(?P<thing>[A-Za-z]{2,})\s*")  # 5 free particles
# of those, what a count of degrees of freedom may count, one each (1 angle, not 1 constraint); angles always
# are: 2 (three angles) is another count, where 2 (6 Cartesian coordinates) says what it was counted from
_COORDINATE = ["coordinate", "angle", "translation", "rotation", "position", "equation"]
_COORDINATES = frozenset({*_COORDINATE, *(f"{thing}s" for thing in _COORDINATE)})
_ANGLES = frozenset({"angle", "angles"})
# a count of what is asked, at the end of a side of working: It has 2 degrees of freedom
_STATES_COUNT = re.compile(
    rf"(?<![\w.])(?P<count>[0-9]{{1,4}}|{'|'.join(_WORDS)})\s+(?:[A-Za-z]{{2,}}\s+)?"
    r"(?:degrees?\s+of\s+freedom|dofs?|generali[sz]ed\s+coordinates?)$",
    re.I,
)
# coordinates named one by one after a count, in brackets or not: (θ and φ), θ₁, θ₂
_LISTED_NAMES = re.compile(r"\s*(?:,|\band\b|&)\s*", re.I)
_COORDINATE_NAME = re.compile(r"[^\W\d_][0-9₀-₉']*")
# what a list of coordinates after a count may follow: what is counted, then a colon, a dash or a bracket, or
# words that say the list names them (1 dof: θ and r; 2 degrees of freedom (θ₁, θ₂); 1, namely θ)
_LIST_LEAD = re.compile(
    r"\s*(?:(?:degrees?\s+of\s+freedom|freedoms?|dofs?|d\.o\.f\.|(?:generali[sz]ed\s+)?coordinates?)\s*)?"
    r"(?:[:(\-–—]\s*)?(?:(?:namely|i\.e\.|viz\.?|that\s+is)\s*[:,]?\s*)?",
    re.I,
)
# a count then what it counts, as a remark: 1 constraint, 5 free particles (not 1 degree of freedom)
_COUNTS_THING = re.compile(r"\s*(?:[A-Za-z]{2,}\s+)?(?P<thing>[A-Za-z]{2,})\b")


def _count_with_bracket(piece: str, reads, names) -> tuple[str, ParsedAnswer | None, tuple] | None:
    """A count followed by brackets, where a count is asked: which number it says, and notes. None
    where ``piece`` is no such thing, or the brackets hold words the remarks after a number are read as.

    As typed, ``1 (2)`` is the product 2; written after a count, a bracket is more often its working
    (``2 (6 − 4)``, ``6 (3 translations + 3 rotations)``) or what it counts (``15 (5 particles)``). So
    the count is graded where its bracket comes to it, or names how many things it was counted from.
    Where the bracket comes to another number (``1 (2)``, ``2 (3 coordinates − 2 constraints)``), which
    is the answer is unclear, and a note sends it to a person. A product written close (``2(3 − 1)``) is
    read as one; and where the other reading, count or product, would earn what this one does not, a
    note sends it to a person too (see :func:`grader.judge.compare._count_unclear`)."""
    found = _COUNT_THEN_BRACKET.fullmatch(piece)
    groups = _groups(found["rest"]) if found else None
    if not groups:
        return None
    typed, rest = found["count"], found["rest"]
    number = int(NUMBER_WORDS.get(typed.lower(), typed))
    answer = reads(str(number))
    if answer is None:
        return None  # more digits than the parser reads: as typed, and refused
    remark = ("remark_ignored", {"value": typed, "rest": shown(rest)})
    unclear = ("count_bracket_for_a_person", {"value": typed, "rest": shown(rest)})
    spaced = bool(found["space"]) or not typed.isdigit()  # two(2) is no product either
    if _ARITHMETIC.fullmatch(rest):
        worked = parse_answer(rest)
        if not (worked.ok and worked.kind == "expression" and worked.value.is_number):
            return None  # (1/0): as typed, and refused
        if worked.value != number:
            return (str(number), answer, (unclear,)) if spaced else None  # 3(2) is 6, as written
        product = number * worked.value
        if not typed.isdigit() or product == number:
            return str(number), answer, (remark,)
        if spaced:
            return str(number), answer, (remark, ("other_reading", {"typed": piece.strip(), "other": str(product)}))
        written = reads(piece)
        other = ("other_reading", {"typed": piece.strip(), "other": str(number)})
        return (piece, written, (other,)) if written is not None else None
    counted = _counted(groups[0], names) if len(groups) == 1 and spaced else None
    if counted is None:
        return None
    value, summed = counted
    described = _DESCRIBED.fullmatch(groups[0])
    thing = described and not summed and described["thing"].lower() in _THINGS
    angles = thing and described["thing"].lower() in _ANGLES
    # 2 (one coordinate): fewer of what is counted than the count; 2 (6 coordinates) is what it is counted from
    fewer = thing and described["thing"].lower() in _COORDINATES and value < number
    if value == number or (thing and not angles and not fewer and not _ASKED.search(groups[0])):
        return str(number), answer, (remark,)
    if summed or angles or fewer or _ASKED.search(groups[0]):
        return str(number), answer, (unclear,)
    return None  # 2 (one coordinate for each bob): words, read as remarks are


def _count_said(pieces: list[str], final) -> str | None:
    """The count of what is asked that a side of working ends by stating, where it is not ``final``, as
    typed: ``It has 2 degrees of freedom``; not ``3 degrees of freedom, minus 2 constraints``, a count
    worked from. None where there is none."""
    for piece in pieces:
        found = _STATES_COUNT.search(piece.rstrip(" ,.;:"))
        if found and int(NUMBER_WORDS.get(found["count"].lower(), found["count"])) != final:
            return found["count"]
    return None


def _counts_other(number: str, rest: str, names: Collection[str]) -> bool:
    """Whether the words after a count say it counts something else (``1 constraint``, ``5 particles``), or
    more counts with it that add up to another number (``one angle and one length``), or name more or fewer
    coordinates than it (``1 (θ and φ)``): which number is the answer is for a person. Not ``1 degree of
    freedom``, ``1 generalized coordinate``, ``1 angle``, ``2 (θ₁ and θ₂)``."""
    found = _COUNTS_THING.match(rest)
    if found and found["thing"].lower() in _THINGS - _COORDINATES:
        return True
    listed = _names_listed(rest, names)
    if listed:  # 1 (θ and φ), 1 dof: θ and r, 2 (θ): more or fewer coordinates named than counted
        return number.isdigit() and len(listed) != int(number)
    named, exact = _coordinates_named(rest) if number.isdigit() else (0, False)
    if named > int(number) or (exact and named and named != int(number)):
        return True  # 1 (θ) and one for φ, 1, and another for φ, 2 (θ₁ only), 1 (both angles)
    counted = _counted(f"{number} {rest}", names) if number.isdigit() else None
    return counted is not None and counted[1] and counted[0] != int(number)


def _coordinates_named(rest: str) -> tuple[int, bool]:
    """How many coordinates words after a count name, where they are no list (:func:`_names_listed`), and
    whether that is all of them: its Greek letters (``θ``, ``phi_2``), each once, and two for ``both angles``,
    are all; ``another`` or ``a second`` (``2 (another angle for the second bob)``) adds one to one it implies,
    and says no more than that there are at least so many (``6 (a second triple for rotation)``). Not those
    said to be fixed or that would be needed only if something were otherwise (``1 (θ — φ is fixed)``,
    ``1 (another would be needed if l varied)``). 0 where they name none, or hold a count of their own in
    digits (``6 (3 translations + 3 rotations: φ, θ, ψ)`` names the rotations only: a breakdown, see
    :func:`_breaks_down`)."""
    if _NUMBER.search(rest):
        return 0, False
    greek, more, both = set(), 0, False
    for clause in _CLAUSE.split(rest):
        whole = _NOT_COUNTED.search(clause) and _ALL_NOT_COUNTED.search(clause)
        for part in _AND.split(clause):
            if whole or _NOT_COUNTED.search(part):
                continue  # θ and φ fixed: θ, and φ fixed; with φ and r fixed: neither
            greek |= {token.lower() for token in _COORDINATE_WORD.findall(part) if _is_greek(token)}
            more += len(_ANOTHER.findall(part))
            both = both or _BOTH.search(part) is not None
    named = max(len(greek), 1 + more if more else 0, 2 if both else 0)
    return named, bool(greek or both)


def _is_greek(token: str) -> bool:
    """Whether ``token`` is a Greek letter, perhaps with an index, as typed or spelt out (θ₁, phi_2)."""
    spelt = _SPELLED_GREEK.fullmatch(token)
    return token[0] in GREEK_BY_LETTER or (spelt is not None and spelt[1].lower() in GREEK_NAMES)


_COORDINATE_WORD = re.compile(r"(?<![\\\w])[^\W\d_][\w₀-₉']*")  # θ₁, theta_1, and words, of which the Greek count
# a coordinate added to the count; not the second bob, whose coordinate it is
_ANOTHER = re.compile(r"\b(?:another|a\s+second|the\s+second\s+(?:angle|coordinate|one)|one\s+more)\b", re.I)
_CLAUSE = re.compile(r"[,;:()\[\]—–]|\s-\s|\b(?:but|while|whereas)\b", re.I)
_AND = re.compile(r"\band\b", re.I)
# a coordinate that is not one the count counts: φ fixed, r = l constant, another would be needed if l varied;
# not φ no longer fixed, which says it is one
_NOT_COUNTED = re.compile(
    r"(?<!\bnot\s)(?<!n't\s)(?<!\bno\s)(?<!\blonger\s)\b(?:fixed|constant|const|held|frozen)\b"
    r"|\b(?:if|unless|otherwise)\b",
    re.I,
)
_ALL_NOT_COUNTED = re.compile(r"^\s*(?:with|keeping|holding)\b|\b(?:are|both)\s+(?:fixed|constant|held)\b", re.I)
_BOTH = re.compile(r"\bboth\s+(?:the\s+)?(?:angles|coordinates)\b", re.I)


def _names_listed(rest: str, names: Collection[str]) -> list[str] | None:
    """The coordinates a remark after a count lists, where it is such a list, perhaps after what is
    counted and a colon or a bracket (``(θ and φ)``, ``dof: θ and r``, ``degrees of freedom (θ)``,
    ``namely θ and r``); None where it holds anything else. A coordinate is named by a letter (θ, φ₁,
    x') or by a name of the problem (theta)."""
    inside = _LIST_LEAD.sub("", rest, count=1).strip(" .").removeprefix("(").removesuffix(")").strip()
    listed = _LISTED_NAMES.split(inside) if inside else []
    if not listed or not all(_COORDINATE_NAME.fullmatch(name) or _spelled_name(name, names) for name in listed):
        return None
    return listed


def _spelled_name(name: str, names: Collection[str]) -> bool:
    """Whether ``name`` is a coordinate spelt out: a name of the problem, or a Greek letter's (theta, theta_1, phi2)."""
    found = _SPELLED_GREEK.fullmatch(name)
    return name in names or (found is not None and found[1].lower() in GREEK_NAMES)


_SPELLED_GREEK = re.compile(r"([A-Za-z]{2,})_?[0-9₀-₉]*")


def _groups(text: str) -> list[str] | None:
    """What each bracket of ``text`` holds, where ``text`` is brackets side by side (``(6 − 4)``,
    ``(2)(1)``); None where anything stands between them, or they do not close."""
    groups, closing, start = [], [], 0
    for index, character in enumerate(text):
        if character in "([":
            start = start if closing else index + 1
            closing.append(")" if character == "(" else "]")
        elif character in ")]":
            if not closing or character != closing.pop():
                return None
            if not closing:
                groups.append(text[start:index])
        elif not closing and not character.isspace():
            return None
    return groups if groups and not closing else None


def _counted(inside: str, names: Collection[str]) -> tuple[object, bool] | None:
    """``5 particles``, ``3 translations + 3 rotations``, ``the 2 angles``: the counts of things named in
    words that a bracket holds, added up, and whether there were several. None where it holds no count,
    or words that are none of this: the problem's names, a hedge or a doubt (``or 3``, ``maybe 3``),
    arithmetic in words alone (``three minus one``)."""
    words = _COUNTED.findall(inside)
    things = [word for word in words if word.lower() not in (*_SAID_SIGNS, *NUMBER_WORDS)]
    if not things or any(word in names for word in words) or says_otherwise(inside):
        return None
    if not is_prose(" ".join(things), names):
        return None
    arithmetic = _LISTED.sub(" + ", _COUNTED.sub(_as_count, inside))
    if not _SOME_COUNTS.fullmatch(arithmetic):
        return None
    read = parse_answer(arithmetic)
    if not (read.ok and read.kind == "expression" and read.value.is_number):
        return None
    return read.value, bool(_SIGN.search(arithmetic))


def _given(
    text: str, reads, names, decimal_comma: bool, unit: str, count: bool, asked: Collection[str]
) -> tuple[str, ParsedAnswer | None, tuple] | None:
    """``2.006 s, since l = 1 m``, ``n = 3N − k, where N = 1, k = 2``: a number or a formula, then the
    values it was worked out with. The number is graded, and the note says the rest was not; a
    formula is graded with the values put in its names. None where the text is no such answer; where
    it is one that reads as no number, the text as typed, for its refusal to say why: the last side
    of ``l = 1`` is no final value."""
    found = _GIVEN.search(text)
    if found is None or not found.start():
        return None
    head, values = text[: found.start()], text[found.end() :]
    if found.group().strip() == "(" and any(name in asked for name in _GIVEN_NAME.findall(values)):
        return None  # 2 (n = 3): another value of the asked quantity, no value it was worked out with
    bracketed = "(" in found.group()
    if bracketed:  # the remark's own bracket closes the answer, and nothing in it is left open
        values = values.rstrip(" .")
        if not values.endswith(")") or not _balanced(values[:-1]):
            return None
        values = values[:-1]
    prepared, answer, notes = read_number(
        head, reads, names, decimal_comma=decimal_comma, unit=unit, count=count, asked=asked
    )
    if answer is not None:
        rest = text[found.start() :].strip(" ,")
        rest = shown(rest.rstrip(" .")[1:-1].strip() if bracketed else rest)
        value = next((details["value"] for _, details in notes if "value" in details), head.strip())
        working = _given_working(head, values, reads, answer, count)
        if working is not None:  # n = 3N − k = 1, where N = 1, k = 1: 3N − k is 2 with them
            final = _sides(head)[0][-1].strip()
            return prepared, answer, (("working_false_for_a_person", {"value": final, "working": shown(working)}),)
        return prepared, answer, (*notes, ("remark_ignored", {"value": value, "rest": rest}))
    joined = f"{head}; {values}"
    answer = reads(joined)  # T = 2π√(l/g); l = 1; g = 9.81: the values put in place
    return (joined, answer, ()) if answer is not None else (text, None, ())  # not = 1, a value it was given


def _given_working(head: str, values: str, reads, answer: ParsedAnswer, count: bool) -> str | None:
    """The working in ``head`` (``n = 3N − k = 1``) that the ``values`` it was worked out with (``N = 1, k = 1``)
    do not bring to the value ``answer`` says, as the student wrote it with them; None where each side
    comes to it, or cannot be read with them."""
    pieces, _ = _sides(head)
    final = _last_side(answer)
    for piece in pieces[:-1]:
        if _QUANTITY.fullmatch(piece.strip()):
            continue  # n, the label
        read = reads(f"{piece}, where {values}")
        if read is not None and not _agree(_last_side(read), final, count):
            return f"{piece.strip()}, where {values.strip()}"
    return None


_DECIMAL = r"[0-9]+(?:[.,][0-9]*)?(?:[eE][-+]?[0-9]+)?|[.,][0-9]+"
_PLUS_MINUS = r"±|\+-|\+/-|\\pm"
_UNIT_WORD = r"[A-Za-zμµ]{1,3}\b"  # s, ms, μs: a unit before the ± (2.006 s ± 0.001 s)
# the uncertainty after a number in a sentence, or in per cent: 2.006 ± 0.001 s, 2.006 s ± 0.05 %
_UNCERTAINTY_INSIDE = re.compile(rf"(?<=[0-9.\w])\s*(?:{_PLUS_MINUS})\s*(?:{_DECIMAL})(?:\s*%)?")
_UNCERTAIN = re.compile(
    rf"\s*(?P<name>[^\W\d][\w₀-₉]*\s*=\s*)?(?P<open>\()?\s*(?P<value>[-+−]?(?:{_DECIMAL}))\s*"
    rf"(?:(?P<before>{_UNIT_WORD})\s*)?(?:{_PLUS_MINUS})\s*(?P<error>{_DECIMAL})\s*"
    rf"(?(open)\)|)\s*(?P<unit>(?:[^\W\d]|\\)[^±=;]*)?\s*"
    # or the concise form of metrology, 2.006(5) s: the uncertainty in the last digits
    rf"|\s*(?P<cname>[^\W\d][\w₀-₉]*\s*=\s*)?(?P<cvalue>[-+−]?[0-9]*\.[0-9]+)\((?P<digits>[0-9]{{1,3}})\)"
    rf"\s*(?P<cunit>(?:[^\W\d]|\\)[^±=;()]*)?\s*"
)


# where the values an answer was worked out with begin: ", where l = 1", " since k = 2", " for l = 1 m"
# …, with g = 9.81, or the same in brackets at the end: 2.006 s (with g = 9.81)
# …, or a bracket of values alone: 2 (k = 4), n = 2 (k = 4, N = 2)
_GIVEN = re.compile(
    r"\s*(?:(?:,?\s*|\(\s*)\b(?:where|with|since|for|given|using|as)\s+|\s\(\s*)(?=[^\W\d][\w₀-₉]*\s*=)", re.I
)
_GIVEN_NAME = re.compile(r"(?:^|[,;(]|\band\b)\s*([^\W\d][\w₀-₉]*)\s*=", re.I)  # the names a remark gives values


def _spelled(text: str, decimal_comma: bool, unit: str) -> tuple[str, tuple]:
    notes = ()
    if decimal_comma:
        text, comma = _decimal_point(text, every=decimal_comma == _Commas.EVERY)
        notes = (comma,) if comma else ()
    if len(text) < _LENGTH:
        text = _TIMES_TEN.sub(" × ", text)
    if unit and len(text) < _LENGTH:
        # TeX's unit after a number: 2.006~\text{s}, 2.006\,\mathrm{ s}, 2006\,\mu\mathrm{s}; the tie ~ is
        # a space there, and \mu the prefix μ
        text = _TIE.sub(" ", _TEX_UNIT.sub(_tex_unit, text))
        text = _TEX_MICRO.sub(" μ", text)
        text = _SEC.sub(r"\1\2s", _PREFIX_APART.sub(lambda apart: (apart[1] + apart[2]).lower(), text))
    return text, notes


# 2006 x 10^-3: the letter for ×, where a number is asked and x can be no variable; read as typed, 2006·x·10⁻³
# was refused, and 2.006x10^0 right only as 2.006·x₁₀⁰
_TIMES_TEN = re.compile(r"(?<=[0-9.])\s*[xX]\s*(?=10\s*\^)")
# 2.006 milli seconds, micro-seconds: one unit, not a number then a remark (seconds) after a word (milli)
_PREFIX_APART = re.compile(rf"(?<=[0-9.\s])({'|'.join(PREFIX_WORDS)})[\s-]+(secs?|seconds?)\b", re.I)
_TEX_UNIT = re.compile(
    r"([0-9.])\s*(?:~|\\[,;:! ])?\s*(\\mu\s*|μ)?\\(?:text|textrm|mathrm|rm|mbox)\{\s*([A-Za-z/^0-9 .\\-]+?)\s*\}"
)
# 2006 \mu s, and \mathrm{\mu s} once the braces are gone
_TEX_MICRO = re.compile(r"(?<=[0-9.])\s*(?:~|\\[,;:! ])?\s*\\mu\b\s*(?=(?:s|m|N|J|W|Hz)\b)")


def _tex_unit(found: re.Match) -> str:
    return f"{found[1]} {'μ' if found[2] else ''}{found[3]}"


_TIE = re.compile(r"(?<=[0-9.])~(?=\s*[A-Za-z\\])")


def _decimal_point(text: str, *, every: bool = False) -> tuple[str, tuple | None]:
    """A number written with a decimal comma, as much of Europe writes it, with a point; and the
    note that says so. Three digits after the comma may be thousands: those are left alone, and the
    parser asks for a point; but not with ``every`` (see :func:`_commas`)."""
    match = (_ANY_DECIMAL_COMMA if every else _DECIMAL_COMMA).fullmatch(text) if len(text) < _LENGTH else None
    if match is None:
        return _decimal_points_inside(text, every=every)
    if "," in match.group(3):
        return text, None
    whole, fraction, rest = match.groups()
    number = f"{whole}.{fraction}"
    return f"{number}{rest}", ("decimal_comma", {"typed": f"{whole},{fraction}", "number": number})


def _decimal_points_inside(text: str, *, every: bool = False) -> tuple[str, tuple | None]:
    """``2π/√9,81``: numbers with a decimal comma inside the arithmetic, each read as
    :func:`_decimal_point` reads one alone, with the note that says so; ``text`` as typed where any
    of its commas is none (``T = 2,01 s, f = …`` lists; ``2π/√9,810`` may be 9810)."""
    if "," not in text or len(text) >= _LENGTH:
        return text, None
    pattern = _ANY_DECIMAL_COMMA_INSIDE if every else _DECIMAL_COMMA_INSIDE
    found = list(pattern.finditer(text))
    if not found or len(found) != text.count(","):
        return text, None
    read = pattern.sub(r"\1.\2", text)
    if len(found) == 1:
        return read, ("decimal_comma", {"typed": found[0][0], "number": found[0][0].replace(",", ".")})
    typed = [number[0] for number in found]
    return read, (
        "decimal_commas",
        {"typed": _listed_as_typed(typed), "numbers": listed([number.replace(",", ".") for number in typed])},
    )


def _listed_as_typed(numbers: list[str]) -> str:
    """``1,00`` and ``9,81``, each set in backticks as a note repeats what was typed.

    >>> _listed_as_typed(["1,00", "9,81", "2,5"])
    '`1,00`, `9,81` and `2,5`'
    """
    return listed([f"`{number}`" for number in numbers])


def _number_in(piece: str, names: Collection[str]):
    """``(words before, number, remark)`` readings of ``piece``: the number first, then in a
    sentence (``The system has 2 degrees of freedom``), after words that are not mathematics."""
    for number, rest in _number_then_remark(piece):
        yield "", number, rest
    starts = [found.start() for found in (_NUMBER.search(piece), _first_number_word(piece)) if found]
    start = min(starts, default=0)
    if start and _is_remark(piece[:start], names):
        for number, rest in _number_then_remark(piece[start:]):
            yield piece[:start].strip(), number, rest


def _first_number_word(piece: str) -> re.Match | None:
    """The first number in words (It has two degrees of freedom), where "one" is no pronoun."""
    for found in _NUMBER_WORD.finditer(piece):
        if found[0].lower() != "one" or not _PRONOUN_ONE.search(piece[: found.start()]):
            return found
    return None


def _number_then_remark(piece: str):
    """``(number, remark)`` splits of ``piece``: the whole of it first, then before each place a
    remark may begin, the longest number first."""
    if piece:
        yield piece, ""
    starts = [match.start() for match in _REMARK.finditer(piece)][:_REMARKS_TRIED]
    for start in reversed(starts):
        number, rest = piece[:start].strip(), piece[start:].strip()
        if number:
            yield number, rest


def _unit_of(word: str):
    """The unit a word of a remark names, in any case a student types it (Min, MINUTES, hz); or None."""
    spelling = next((each for each in (word, word.lower(), word.capitalize()) if each in SI_UNITS), None)
    return SI_UNITS[spelling] if spelling else None


def _is_remark(rest: str, names: Collection[str], number: str = "", unit: str = "") -> bool:
    """Whether ``rest`` is words about the number, not more of the answer: after the mark that
    opens it, prose (:func:`~grader.judge.words.is_prose`) that does not begin with a digit, is not
    a unit, names no number in words but ``number`` (2 (the two angles), not 2 (or three)), and
    names no unit but ``unit``, the part's, nor per cent (2.006 (in minutes), 2.006 percent)."""
    if _breaks_down(rest, names, number):
        return True
    if (repeated := _REPEATED.fullmatch(rest)) and repeated[1] == number:
        return True  # two (2): the number again, in digits
    words = rest.lstrip("([{,:;–—- ")
    if _PRECISION.fullmatch(words):
        return True  # 2.006 s, to 4 figures: how it was rounded, whose digit is no other number
    if _RATE_REMARK.fullmatch(words):
        return True  # 15 (3 per particle), 2, one angle per bob: what each thing counts, no other number
    if not words or words[0] in "0123456789." or words.rstrip(".").lower() in _UNIT_WORDS:
        return False  # 2,01, 3 is a list; 2 sec a unit
    if _PER_CENT.search(words):
        return False
    if unit and any(_unit_of(word) not in (None, unit_named(unit)) for word in _UNIT_NAMED.findall(words)):
        return False
    if any(NUMBER_WORDS[word.lower()] != number for word in _NUMBER_WORD.findall(_PER_EACH.sub(" ", words))):
        return False
    return is_prose(words, names)


def _breaks_down(rest: str, names: Collection[str], number: str) -> bool:
    """Whether ``rest`` breaks the count ``number`` down, in brackets, into counts of things named
    in words that add up to it: ``(3 translations + 3 rotations)`` for 6, ``(6 coordinates − 1
    constraint)`` for 5. Counts in digits or words (``three``), joined by signs, by and, plus, minus, times, or listed
    between commas (``3 translations, 3 rotations``); words that are none of the problem's names.
    A breakdown that does not add up is no remark: which number is meant is for the student to say
    (or, where a count is asked, a person: see :func:`_count_with_bracket`)."""
    found = _BRACKETED.fullmatch(rest)
    if found is None or not number.isdigit():
        return False
    words = _COUNTED.findall(found[1])
    things = [word for word in words if word.lower() not in (*_SAID_SIGNS, *NUMBER_WORDS)]
    if not things or any(word in names for word in words):
        return False  # (three minus one) counts nothing: another number, no breakdown
    arithmetic = _LISTED.sub(" + ", _COUNTED.sub(_as_count, found[1]))
    if not _COUNTS.fullmatch(arithmetic):
        return False
    read = parse_answer(arithmetic)
    return read.ok and read.kind == "expression" and read.value == int(number)


def _as_count(word: re.Match) -> str:
    """A word of a breakdown as arithmetic: and is +, three is 3 (``three translations and three
    rotations``), a name of what is counted nothing."""
    said = word[0].lower()
    if said in NUMBER_WORDS:
        return f" {NUMBER_WORDS[said]} "
    return _SAID_SIGNS.get(said, " ")


# "one coordinate for each bob": a count per thing, not another number for the answer ("one angle per
# rod" stays a hedge: per is a word of arithmetic, as in kg per m)
# a remark that is a count per thing: 3 per particle, one angle each, 3 for each particle
_RATE_REMARK = re.compile(
    r"(?:[0-9]{1,2}|one|two|three|four|five|six)\s+(?:[A-Za-z]+\s+)?"
    r"(?:(?:per|for\s+each|for\s+every|on\s+each)\s+[A-Za-z]+|each)\s*[)\].]?\s*",
    re.I,
)
_PER_EACH = re.compile(r"\bone\s+[A-Za-z]+\s+(?:for\s+each|for\s+every|on\s+each)\b", re.I)
_REPEATED = re.compile(r"\(\s*([0-9]+)\s*\)\.?")
_BRACKETED = re.compile(r"\(([^()]{1,120})\)\.?")
_COUNTED = re.compile(r"(?<![\w\\])[A-Za-z]{2,}(?!\w)")  # translations, rotations, and: not θ1
_SAID_SIGNS = {"and": "+", "plus": "+", "minus": "-", "times": "*"}
_LISTED = re.compile(r"[,;]\s(?:\s*\+)?")  # counts listed add up: not 3,5, a decimal comma; ", and" once
_COUNTS = re.compile(r"\s*[0-9]+(?:\s*[-+−*×·]\s*[0-9]+)+\s*")  # 3 + 3, 6 − 1, 3·2 − 1
_SOME_COUNTS = re.compile(r"\s*[0-9]+(?:\s*[-+−*×·]\s*[0-9]+)*\s*")  # and 5, of 5 particles
_SIGN = re.compile(r"[-+−*×·]")
