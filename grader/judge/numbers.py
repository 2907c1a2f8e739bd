"""Where a part asks for a number or a count: the number a student means, in what they typed.

Contents:
    read_number(text, reads, names, ...)   the text to judge, its reading, and notes saying how it was read
    NUMBER_WORDS                           zero to twenty in words, to their digits

Students write a number inside a sentence, as they would on paper: ``≈ 2.01 s``, ``T = 2π√(l/g)
= 2.01 s``, ``2 (θ₁ and θ₂)``, ``2 degrees of freedom``, ``two``, ``2,01``. The number is what the part
grades, so it is found and graded, and the student is told what was not. Each reading is tried
only when the answer as typed is not a number: ``2 (3)`` is still 6.

A remark after the number must be words, not mathematics: in ``2 π √(l/g)`` for a period, the
√(l/g) is part of the answer, which is a formula where a number is asked for, and is refused as one.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Collection

from grader.judge.words import is_prose
from grader.parse import ParsedAnswer, parse_answer
from grader.parse.names import IMPLYING_WORDS

__all__ = ["NUMBER_WORDS", "read_number"]

# 2,01 or 1,5 (a number with a decimal comma, then perhaps a unit); not 2,006, which is 2006 in English
_DECIMAL_COMMA = re.compile(r"\s*([+-]?[0-9]+),([0-9]{1,2}|[0-9]{4,})(?![0-9,])(.*)", re.DOTALL)

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
# a quantity's name before its value, which is no working: T, T_0, τ, ω₀
_QUANTITY = re.compile(r"[^\W\d_][\w₀-₉]*")

# where a remark may begin after a number: a bracket or a mark of punctuation, a spaced dash, a word,
# or an abbreviation (d.o.f.)
_REMARK = re.compile(r"[(\[{,:;–—]|\s-\s|(?<![A-Za-z0-9_\\])(?:[A-Za-z]{2,}|(?:[A-Za-z]\.){2,})")
_SENTENCE_END = re.compile(r"(?<=[^\d\s.])\.$")
_NUMBER = re.compile(r"(?<![\w.])[0-9]")  # the first digit of a number of its own, not of θ1
# "one" after these is a pronoun (the one that swings), not a number
_PRONOUN_ONE = re.compile(r"\b(?:the|a|this|that|which|each|any|every|no)\s+$", re.I)
_UNIT_WORDS = {"sec", "secs", "msec", "msecs"}  # seconds, not remarks, where no unit is asked for
_REMARKS_TRIED = 12
_SHOWN = 60  # characters of a remark repeated back to the student

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
    unit: bool = False,
    uncertainty: bool = False,
    count: bool = False,
) -> tuple[str, ParsedAnswer | None, tuple]:
    """The text to judge, its reading (None: read it as typed, and say why it fails), and notes.

    ``reads(text)`` is the reading of ``text`` if it is a number (with its unit, where the part has
    one), else None; ``names`` are the problem's, which a remark after the number does not use.
    ``decimal_comma`` reads 2,01 as 2.01; ``unit`` (the part asks for a quantity in a unit) reads
    2.006 sec as 2.006 s, and TeX's 2.006~\\text{s} as 2.006 s; ``uncertainty`` (a measured value may
    have one) reads 2.006 ± 0.001 s as 2.006 s, with a note that the uncertainty was not graded.
    ``count`` (a whole number is asked for) reads ``9 − 3 = 6 ≠ 9`` as 6, a remark ruling out 9.
    """
    unequal = _NOT_EQUAL.fullmatch(text) if count and len(text) <= _LENGTH else None
    if unequal:
        return _unequal(unequal, reads, names)
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
    prepared, notes = _spelled(text, decimal_comma, unit)
    answer = reads(prepared)
    if answer is not None or len(text) > _LENGTH or _SEPARATED.search(text):
        return prepared, answer, notes  # x = 1; y = 2 is a system, not working
    given = _given(text, reads, names, decimal_comma, unit)
    if given is not None:
        return given
    if re.search(_UNEQUAL_SIGN, text):
        return prepared, None, notes  # 6 ≠ 9 = 3·3: the chain's last side is what the answer is not
    bare = _ABOUT_AFTER.sub("", _ABOUT.sub("", text, count=1))
    pieces, stepped = _sides(bare)
    last = len(pieces) - 1
    # the final value; else, of a value and its name alone (2.01 s = T), the first side: not of longer working,
    # whose first side is no answer (6 − 4 = 2 = 4θ), nor across a step (6 − 4 → n), which says what comes last
    first = () if last != 1 or stepped else (0,)
    for index in dict.fromkeys((last, *first)):
        for before, typed, rest in _number_in(pieces[index], names):
            words = NUMBER_WORDS.get(typed.lower().rstrip("."))
            prepared, notes = _spelled(words or typed, decimal_comma, unit)
            answer = reads(prepared)
            if answer is None or (rest and not _is_remark(rest, names, words or typed)):
                continue
            typed = _SENTENCE_END.sub("", typed)  # The period is 2.01 s.
            if before:
                notes += (("number_in_sentence", {"value": typed}),)
            elif rest:
                rest = rest.lstrip(",:;–—- ")
                shown = rest if len(rest) <= _SHOWN else rest[: _SHOWN - 1] + "…"
                notes += (("remark_ignored", {"value": typed, "rest": shown}),)
            elif last and index == last and not all(_QUANTITY.fullmatch(piece) for piece in pieces[:last]):
                notes += (("final_value", {"value": typed}),)  # T = 2π√(l/g) = 2.01 s; not T = 2.0 s (approx)
            elif last:
                notes += (("number_read", {"value": typed}),)
            elif words:
                notes += (("number_word", {"typed": typed, "number": words}),)
            return prepared, answer, notes
    prepared, notes = _spelled(text, decimal_comma, unit)
    return prepared, None, notes


# 9 − 3 = 6 ≠ 9, where a count is asked: the count, then once a number it is not, and nothing after
_UNEQUAL_SIGN = r"≠|!=|=/=|/=|\\neq?(?![A-Za-z])"
_NOT_EQUAL = re.compile(
    rf"(?P<value>(?:(?!{_UNEQUAL_SIGN}).)+?)\s*(?P<sign>{_UNEQUAL_SIGN})\s*"
    rf"(?P<other>[0-9]+|(?:{'|'.join(_WORDS)})\b)\s*\.?\s*",
    re.I | re.S,
)


def _unequal(found: re.Match, reads, names) -> tuple[str, ParsedAnswer | None, tuple]:
    """``9 − 3 = 6 ≠ 9``: the count before ``≠``, read as any count is, with a note that the number it
    rules out was not graded. As typed (refused, for its sign) where that count is the number it rules
    out, or is none."""
    prepared, answer, notes = read_number(found["value"], reads, names, count=True)
    other = int(NUMBER_WORDS.get(found["other"].lower(), found["other"]))
    value = _value_of(answer)
    if value is None or value == other:
        return found[0], None, ()  # 6 ≠ 6 says no count
    typed = next((details["value"] for _, details in notes if "value" in details), _sides(found["value"])[0][-1])
    rest = f"{found['sign']} {found['other']}"
    rest = rest if len(rest) <= _SHOWN else rest[: _SHOWN - 1] + "…"
    return prepared, answer, (*notes, ("remark_ignored", {"value": typed, "rest": rest}))


def _value_of(answer: ParsedAnswer | None):
    """The number an answer read as a number says: its value, or its last side (``n = 2``); else None."""
    if answer is None or answer.kind not in ("expression", "equation"):
        return None
    value = answer.value.rhs if answer.kind == "equation" else answer.value
    return value if value.is_number else None


def _sides(text: str) -> tuple[list[str], bool]:
    """The sides of a chain of working (``6 − 4 = 2 → 4``: 6 − 4, 2 and 4), split where an equals sign
    or a step stands outside brackets (``2 (so two angles)`` is one side); and whether a step did."""
    marks = [(found, False) for found in _EQUALS.finditer(text)] + [(found, True) for found in _STEPS.finditer(text)]
    marks.sort(key=lambda mark: mark[0].start())
    depth = [0] * (len(text) + 1)
    for index, character in enumerate(text):
        depth[index + 1] = depth[index] + (character in "([{") - (character in ")]}")
    pieces, start, stepped = [], 0, False
    for found, step in marks:
        if found.start() >= start and depth[found.start()] == 0:
            pieces.append(text[start : found.start()].strip())
            start, stepped = found.end(), stepped or step
    return [*pieces, text[start:].strip()], stepped


def _given(text: str, reads, names, decimal_comma: bool, unit: bool) -> tuple[str, ParsedAnswer | None, tuple] | None:
    """``2.006 s, since l = 1 m``, ``n = 3N − k, where N = 1, k = 2``: a number or a formula, then the
    values it was worked out with. The number is graded, and the note says the rest was not; a
    formula is graded with the values put in its names. None where the text is no such answer; where
    it is one that reads as no number, the text as typed, for its refusal to say why: the last side
    of ``l = 1`` is no final value."""
    found = _GIVEN.search(text)
    if found is None or not found.start():
        return None
    head, values = text[: found.start()], text[found.end() :]
    prepared, answer, notes = read_number(head, reads, names, decimal_comma=decimal_comma, unit=unit)
    if answer is not None:
        shown = text[found.start() :].strip(" ,")
        shown = shown if len(shown) <= _SHOWN else shown[: _SHOWN - 1] + "…"
        value = next((details["value"] for _, details in notes if "value" in details), head.strip())
        return prepared, answer, (*notes, ("remark_ignored", {"value": value, "rest": shown}))
    joined = f"{head}; {values}"
    answer = reads(joined)  # T = 2π√(l/g); l = 1; g = 9.81: the values put in place
    return (joined, answer, ()) if answer is not None else (text, None, ())  # not = 1, a value it was given


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
_GIVEN = re.compile(r"\s*,?\s*\b(?:where|with|since|for|given|using|as)\s+(?=[^\W\d][\w₀-₉]*\s*=)", re.I)


def _spelled(text: str, decimal_comma: bool, unit: bool) -> tuple[str, tuple]:
    notes = ()
    if decimal_comma:
        text, comma = _decimal_point(text)
        notes = (comma,) if comma else ()
    if unit and len(text) < _LENGTH:
        # TeX's unit after a number: 2.006~\text{s}, 2.006\,\mathrm{ s}, 2006\,\mu\mathrm{s}; the tie ~ is
        # a space there, and \mu the prefix μ
        text = _TIE.sub(" ", _TEX_UNIT.sub(_tex_unit, text))
        text = _TEX_MICRO.sub(" μ", text)
        text = _SEC.sub(r"\1\2s", text)
    return text, notes


_TEX_UNIT = re.compile(
    r"([0-9.])\s*(?:~|\\[,;:! ])?\s*(\\mu\s*|μ)?\\(?:text|textrm|mathrm|rm|mbox)\{\s*([A-Za-z/^0-9 .\\-]+?)\s*\}"
)
# 2006 \mu s, and \mathrm{\mu s} once the braces are gone
_TEX_MICRO = re.compile(r"(?<=[0-9.])\s*(?:~|\\[,;:! ])?\s*\\mu\b\s*(?=(?:s|m|N|J|W|Hz)\b)")


def _tex_unit(found: re.Match) -> str:
    return f"{found[1]} {'μ' if found[2] else ''}{found[3]}"


_TIE = re.compile(r"(?<=[0-9.])~(?=\s*[A-Za-z\\])")


def _decimal_point(text: str) -> tuple[str, tuple | None]:
    """A number written with a decimal comma, as much of Europe writes it, with a point; and the
    note that says so. Three digits after the comma may be thousands: those are left alone, and the
    parser asks for a point."""
    match = _DECIMAL_COMMA.fullmatch(text) if len(text) < _LENGTH else None
    if match is None or "," in match.group(3):
        return text, None
    whole, fraction, rest = match.groups()
    number = f"{whole}.{fraction}"
    return f"{number}{rest}", ("decimal_comma", {"typed": f"{whole},{fraction}", "number": number})


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


def _is_remark(rest: str, names: Collection[str], number: str = "") -> bool:
    """Whether ``rest`` is words about the number, not more of the answer: after the mark that
    opens it, prose (:func:`~grader.judge.words.is_prose`) that does not begin with a digit, is not
    a unit, and names no number in words but ``number`` (2 (the two angles), not 2 (or three))."""
    if _breaks_down(rest, names, number):
        return True
    if (repeated := _REPEATED.fullmatch(rest)) and repeated[1] == number:
        return True  # two (2): the number again, in digits
    words = rest.lstrip("([{,:;–—- ")
    if not words or words[0] in "0123456789." or words.rstrip(".").lower() in _UNIT_WORDS:
        return False  # 2,01, 3 is a list; 2 sec a unit
    if any(NUMBER_WORDS[word.lower()] != number for word in _NUMBER_WORD.findall(_PER_EACH.sub(" ", words))):
        return False
    return is_prose(words, names)


def _breaks_down(rest: str, names: Collection[str], number: str) -> bool:
    """Whether ``rest`` breaks the count ``number`` down, in brackets, into counts of things named
    in words that add up to it: ``(3 translations + 3 rotations)`` for 6, ``(6 coordinates − 1
    constraint)`` for 5. Counts in digits or words (``three``), joined by signs, by and, plus, minus, times, or listed
    between commas (``3 translations, 3 rotations``); words that are none of the problem's names.
    A breakdown that does not add up is no remark: which number is meant is for the student to say."""
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
_PER_EACH = re.compile(r"\bone\s+[A-Za-z]+\s+(?:for\s+each|for\s+every|on\s+each)\b", re.I)
_REPEATED = re.compile(r"\(\s*([0-9]+)\s*\)\.?")
_BRACKETED = re.compile(r"\(([^()]{1,120})\)\.?")
_COUNTED = re.compile(r"(?<![\w\\])[A-Za-z]{2,}(?!\w)")  # translations, rotations, and: not θ1
_SAID_SIGNS = {"and": "+", "plus": "+", "minus": "-", "times": "*"}
_LISTED = re.compile(r"[,;]\s")  # counts listed add up: not 3,5, a decimal comma
_COUNTS = re.compile(r"\s*[0-9]+(?:\s*[-+−*×·]\s*[0-9]+)+\s*")  # 3 + 3, 6 − 1, 3·2 − 1
