"""Words a student writes about an answer, beside it: read past, and said so.

Contents:
    is_prose(words, names)                     whether words are about the answer, not more of it
    says_otherwise(words)                      whether they may say the formula is other than written
    quantities_named(words)                    the quantities they name: ``the Hamiltonian`` is H
    formula_then_words(text, names, coords)    ``θ̈ = −(g/l) θ for small angles``: the formula and its words
    words_then_formula(text, names, coords)    ``The equation of motion is m l θ̈ = …``: the words and the formula
    definition_then_formula(text, names, coords)
                                               ``Since L = T − V, L = …``: the words, the definition, the chain
    definition_before_formula(text, names, coords)
                                               ``With p_θ = m R² θ̇: H = …``: the words, a name's definition, the formula
    euler_lagrange_then_formula(text, names, coords)
                                               ``Applying d/dt(∂L/∂θ̇) − ∂L/∂θ = 0: …``: words, operator, equation
    formula_then_convention(text, names)       ``L = … (taking V = 0 at the pivot)``: the formula and its remark
    formula_then_small_angle_form(text, names, coords)
                                               ``θ̈ = … sin θ, which for small θ gives θ̈ = … θ``: both formulas
    text_as_words(text, names, coords)         ``… = 0 \\text{(damped)}`` as ``… = 0 (damped)``: TeX's text, as words
    tex_math_as_words(text)                    ``Since $L = T − V$, $L = …$`` as the sentence without its ``$``s
    words_in(text, names, coords)              the words of prose anywhere in the text

On paper an answer comes with words: ``θ̈ = −(g/l) θ for small angles``, ``m l² sin²θ φ̇ is
conserved``, ``a = g (m₁ − m₂)/(m₁ + m₂), with m₁ going down``. A person grades the formula and
reads the words. So it is with a sentence that leads to the formula: ``The angular frequency is
√(g/l)``. The checker does the same, and says which words it did not grade, but only
where they cannot be part of the formula: they hold no sign or word of arithmetic (``times l``),
no number, no "or" or "not", and read as names the problem does not have. Words that may say
the formula is other than written (``… upward``, ``… inverted``), doubt it (``… (not sure about
the sign)``), deny (``… (friction is not in L)``: "not", and no "or" nor arithmetic), hold words of
arithmetic alone (``… (half the power dissipated)``), close it with signs or numbers (``… (underdamped if
b² < 4mk)``, ``…, downward for m₁ when m₁ > m₂``) or judge it (``…, which is false``), are read past too,
but :func:`says_otherwise` marks
them for a person to read before a right formula earns its credit; so are words that name a quantity
(:func:`quantities_named`: ``…, which is the Hamiltonian``) other than the one the part asks for.

A remark in brackets after a formula may state where the potential energy is zero, ``(taking V = 0
at the pivot)``: words, and ``V = 0`` (or ``U = 0``) in a name the problem does not have. It says how
the formula was worked out, not what it is, and changes no grade; it is read past as words are. Any
other ``=`` in a remark after its words may be more of the answer: it is read as typed.

A sentence may state what the quantity is on the way to its value: ``Since L = T − V, L = ½ m l² θ̇²
+ …``, ``The Lagrangian L = T − V is …``, ``Applying d/dt(∂L/∂θ̇) − ∂L/∂θ = 0: m l² θ̈ + … = 0``. That is
the chain ``L = T − V = …`` the parser reads (or the Euler–Lagrange operator before the equation it gives),
written with words: :func:`definition_then_formula` (or :func:`euler_lagrange_then_formula`, in any spelling
of the operator) finds it, and ``compare`` judges the definition as the chain's (or the operator, by
:func:`~grader.judge.euler_lagrange.euler_lagrange`). Only words that begin such a sentence (``Since``,
``Using``, ``The``…) and hand over to the value (``,``, ``:``, ``we have``, ``is``) are read past; a condition
(``If``), ``not`` or a word in the definition leaves the answer as typed.

Words between two formulas may say the second is the first's small-angle form: ``θ̈ = −(g/l) sin θ,
which for small θ gives θ̈ = −(g/l) θ``. Which of the two is the answer depends on what was asked;
:func:`formula_then_small_angle_form` only finds them, and ``compare`` decides.
"""

from __future__ import annotations

import re
from collections.abc import Collection, Iterator

from sympy import Derivative

from grader.judge.euler_lagrange import euler_lagrange, moved_left
from grader.judge.units import SI_UNITS
from grader.parse import parse_answer
from grader.parse.names import GREEK_NAMES, IMPLYING_WORDS

__all__ = [
    "definition_before_formula",
    "definition_then_formula",
    "euler_lagrange_then_formula",
    "formula_then_approximation",
    "formula_then_convention",
    "formula_then_small_angle_form",
    "formula_then_words",
    "is_prose",
    "quantities_named",
    "says_otherwise",
    "tex_math_as_words",
    "text_as_words",
    "words_in",
    "words_then_formula",
]

_MATH_SIGNS = frozenset("+-−*/^=√·×<>≤≥≠±∓‒‐‑⁻﹣－")  # with the dashes a minus may be typed as
# words that change a formula: "√(g/l) times l", "… but negative", "… all squared"
_MATH_WORDS = re.compile(
    r"\b(?:times|plus|minus|over|divided|multiplied|squared|cubed|square|root|half|halved|twice|doubled|"
    r"inverse|reciprocal|power|per|third|fourth|negative|opposite|sum|difference|product|ratio|quotient|"
    r"derivative|differentiated|integral|integrated)\b",
    re.I,
)
_NUMBER = re.compile(r"(?<!\w)[0-9]")  # a number of its own: for angles below 10 degrees
# "or" or "not": θ̈ = … or θ̈ = …, not for small angles
_HEDGE = re.compile(r"\b(?:or|not|never|isn't)\b", re.I)
# words that doubt the formula beside them: "(not sure about the sign)", "maybe minus". Whatever else
# they say, in words, a person reads them: a formula they doubt earns no credit without one.
_DOUBT = re.compile(
    r"\b(?:not\s+(?:sure|certain)|unsure|uncertain|maybe|perhaps|probably|possibly|I\s+think|I\s+guess)\b", re.I
)
# words that may say the formula is other than written, or set what its sign means: "… upward",
# "… inverted", "… except the cosine is a sine", "θ from the horizontal" (whose cos θ is another's
# sin θ); or state its dimensions, which a prompt may ask for ("… dimensionless", "units of force").
# A person reads them against the formula.
_OTHERWISE = re.compile(
    r"\b(?:up|upward|upwards|down|downward|downwards|horizontal|horizontally|clockwise|anticlockwise|counterclockwise|"
    r"inverted|invert|flipped|flip|reversed|reverse|swapped|swap|interchanged|except|instead|replaced|"
    r"replace|wrong|mistake|typo|actually|should|meant|dimension|dimensions|dimensionless|units?\s+of)\b(?!\s+to\b)",
    re.I,
)
# words that judge the formula beside them, or say it is a slip ("…, which is false", "(sign error)", "but the
# sign is off", "(I copied this)"): a formula its student disowns is read by a person, whatever it is
_JUDGED = re.compile(
    r"\b(?:false|untrue|incorrect|invalid|error|errors|erroneous|off|bogus|nonsense|copied|sign|signs)\b", re.I
)
# words that name a quantity of mechanics, which say what the formula beside them is ("…, which is the
# Hamiltonian", "(the total energy)", "the torque of gravity"): the Lagrangian and the Hamiltonian by the names
# a part may ask for (the option ``name``), any other by its word
_QUANTITY = re.compile(
    r"\b(?:lagrangian|hamiltonian|routhian|(?:(?:kinetic|potential)\s+)?energ(?:y|ies)|force|torque|momentum|momenta"
    r"|work|action|impulse)s?\b",
    re.I,
)
_QUANTITY_NAMES = {
    "lagrangian": "L",
    "hamiltonian": "H",
    "energy": "E",
    "kinetic energy": "T",
    "potential energy": "V",
}
# words that only say what kind of quantity the formula is ("…, it is a force", "(torque)", "an
# angle"): a statement of its dimensions in other words, which a prompt may ask for
_A_QUANTITY = re.compile(
    r"^\W*(?:(?:it|this|that|which)\s+(?:is|has)\s+|is\s+|has\s+)?(?:an?\s+|the\s+)?(?:units?\s+of\s+(?:an?\s+)?)?"
    r"(?:force|torque|energy|work|length|distance|mass|angle|time|speed|velocity|momentum|acceleration|"
    r"frequency|power|pressure)s?\W*$",
    re.I,
)
# words that state the formula's dimensions or units ("its dimensions are those of energy, N·m", "Dimensions:
# [M L² T⁻²]", "units: N m"), in symbols and signs as often as in words: a person reads them, whatever they hold
_DIMENSIONS_SAID = re.compile(
    r"^\W*(?:(?:its|the|which|it|this)\s+(?:has\s+|have\s+|is\s+in\s+)?(?:the\s+)?)?(?:dimensions?|units?)\b", re.I
)
# a word against a bracket is a function the parser does not know, not prose: floor(θ), Re(e^(iθ))
_APPLIED = re.compile(r"[A-Za-z]\(")
_WORD = re.compile(r"(?<![A-Za-z0-9_\\])[A-Za-z]{2,}(?![A-Za-z0-9_])")
_OPENS = " ,;:([–—-"  # what may stand between a formula and the words about it
# where a sentence hands over to its formula: "The Lagrangian is …", "… we get …", "Equation of motion: …"
_HANDING_OVER = frozenset(
    {"is", "are", "was", "becomes", "become", "gives", "give", "yields", "yield", "reads", "read", "get", "gets"}
    | {"obtain", "obtains", "find", "finds", "have"}
)
_LEADS_TO = re.compile(rf"\b(?:{'|'.join(sorted(_HANDING_OVER))})\b|:", re.I)
_LENGTH = 400  # characters: longer answers are read as typed
# TeX's commands whose braces may hold words, and the spaces set before them: \,\text{for small angles}
_TEXT_COMMAND = re.compile(r"\\(?:text|textrm|mathrm|operatorname|mbox)(?![A-Za-z])")
_TEX_SPACES = ("\\,", "\\;", "\\:", "\\!", "\\quad", "\\qquad", "~")
_TEXT_GROUPS = 4  # \text{…} of words in one answer, at the most: a remark before the formula, one after


def is_prose(words: str, names: Collection[str], *, doubt: bool = False) -> bool:
    """Whether ``words`` are about an answer, not more of it: no sign or word of arithmetic, no
    number in digits, no "or" or "not"; and they cannot be read, or use a name that is neither
    the problem's (``names``) nor a unit. With ``doubt``, words that doubt the answer (``not sure
    about the sign, maybe minus``) may say "or", "not" and arithmetic in words, and words that deny
    (``friction is not in L``) "not": they are for a person to read (:func:`says_otherwise`), beside a
    formula; not beside a number, where they may offer another."""
    words = _EULER_LAGRANGE.sub("EulerLagrange", words)  # a name's hyphen, not a minus sign
    words = _WORD_HYPHEN.sub(lambda found: _joined(found, names), words)  # small-angle: no minus sign either
    if not words or _MATH_SIGNS & set(words) or _NUMBER.search(words):
        return False
    doubted = doubt and (_DOUBT.search(words) or _denies_only(words))
    if not doubted and (_MATH_WORDS.search(words) or _HEDGE.search(words)):
        return False
    if _APPLIED.search(words):
        return False
    read = parse_answer(words, known=names)
    if not read.ok:
        return True
    return any(symbol.name not in names and symbol.name not in SI_UNITS for symbol in read.symbols)


def _arithmetic_said(remark: str, names: Collection[str]) -> bool:
    """``(half the power dissipated)``: a remark of words alone, some of arithmetic, none a name of the
    problem's, and no sign, number or "or". After a formula they may change it (``… times half``), but are
    no more of it: a person reads them (:func:`says_otherwise`). Not ``times l``, the formula's arithmetic
    spelled out."""
    if not _MATH_WORDS.search(remark) or _HEDGE.search(remark) or _MATH_SIGNS & set(remark):
        return False
    return all(_is_word(word, names, ()) for word in _TOKEN.findall(remark))


_TOKEN = re.compile(r"[^\W_]+")  # a word, a name or a number, in any script: half, l, θ, 2
# two words of prose joined by a hyphen: small-angle, time-independent, z-component (not θ-φ, g-l or theta-phi)
_WORD_HYPHEN = re.compile(r"(?<![\w\\])([A-Za-z]+)-([A-Za-z]{3,})(?!\w)")


def _joined(found: re.Match, names: Collection[str]) -> str:
    """``small-angle`` as one word, where both are words of prose; else as typed, a minus sign between names."""
    if all(_is_word(word, names, ()) for word in found.groups()):
        return found[1] + found[2]
    return found[0]


def _denied(remark: str) -> bool:
    """``(not T + V)``: a remark in brackets that ends the answer and denies what follows "not", a formula
    as well as words. It says what the answer is not; a person reads it (:func:`says_otherwise`)."""
    return _DENIED.match(remark) is not None and "\n" not in remark and _closing_bracket(remark) is not None


_DENIED = re.compile(r"\(\s*(?:not|never|isn't)\b", re.I)


def _closing_remark(rest: str, names: Collection[str], coords: Collection[str]) -> bool:
    """``(a torque, N·m)``, ``(= E, conserved)``, ``, downward for m₁ when m₁ > m₂``: a remark that closes
    the answer, with its commas, signs and numbers: in brackets, begun by a sign that relates (``=``, ``<``)
    and holding a word of prose, or begun by a word of prose (or an article); or after a comma, begun by a
    word of prose. They may say the formula is other than written, or more than it (:func:`says_otherwise`,
    beside a formula): a person reads them. Not with "or", which may offer another formula (``(or
    minus)``), nor an ``=`` after words, which may be more of the answer (``(taking V = 0.5 at the pivot)``,
    or the next equation of a system: ``…, θ̈ = …``)."""
    if "\n" in rest or _OR.search(rest) or not says_otherwise(rest, formula=True):
        return False
    if rest.startswith("("):
        end = _closing_bracket(rest)
        if end is None:
            return False
        inside = rest[1:end]
        if _RELATES.match(inside):
            return any(_is_word(word[0], names, coords) for word in _WORD.finditer(inside))
    elif rest.startswith(","):
        inside = rest[1:]
    else:
        return False
    first = _FIRST_WORD.match(inside)
    return first is not None and _first_equals(inside) is None and _is_word(first["word"], names, coords)


def _closing_bracket(rest: str) -> int | None:
    """Where the bracket that opens ``rest`` closes, if nothing but marks of punctuation follow it; else None."""
    depth = 0
    for i, character in enumerate(rest):
        depth += (character in "([{") - (character in ")]}")
        if depth == 0:
            return None if rest[i + 1 :].strip(" .;!") else i
    return None


_RELATES = re.compile(r"\s*(?:=|≈|~|<|>|≤|≥|≠|\\approx)")  # (= E, conserved), (≈ 0.5 J)
_FIRST_WORD = re.compile(r"\s*(?:(?:an?|i\.e\.)\s+)?(?P<word>[A-Za-z]{2,})(?![\w(])", re.I)


def _denies_only(words: str) -> bool:
    """``(friction is not in L)``: words that say "not" and no "or" nor arithmetic; beside a formula they
    are no second formula, and a person reads what they deny (:func:`says_otherwise`)."""
    return bool(_NOT.search(words)) and not _OR.search(words) and not _MATH_WORDS.search(words)


_NOT = re.compile(r"\b(?:not|never|isn't)\b", re.I)
_OR = re.compile(r"\bor\b", re.I)


def says_otherwise(words: str, *, formula: bool = False) -> bool:
    """Whether prose read past may say the formula is other than written, or what its sign means
    (``upward``, ``inverted``, ``except …``), or doubts it (``not sure about the sign``) or denies, or judges it
    (``which is false``, ``sign error``), or says what kind of quantity it is (``it is a force``): a
    person must read it before the formula earns credit. With ``formula``, words read past beside a
    formula, so too where they hold arithmetic, in words (``half the power dissipated``) or signs and
    numbers (``(underdamped if b² < 4mk)``): they may change it. Not beside a number, whose words
    may count in words (``3 translations plus 3 rotations``)."""
    return bool(
        _OTHERWISE.search(words)
        or _DOUBT.search(words)
        or _NOT.search(words)
        or _JUDGED.search(words)
        or _A_QUANTITY.match(words)
        or _dimensions(words)
        or (formula and _arithmetic(words))
    )


def _arithmetic(words: str) -> bool:
    """Whether words hold arithmetic, in words or signs, a number, "or", or a function applied; not
    where the potential energy is zero (``taking V = 0 at the pivot``), nor a hyphen between words."""
    words = _HYPHEN.sub("", _ZERO_OF_POTENTIAL.sub(" ", words))
    return bool(
        _MATH_SIGNS & set(words)
        or _NUMBER.search(words)
        or _MATH_WORDS.search(words)
        or _HEDGE.search(words)
        or _APPLIED.search(words)
    )


_HYPHEN = re.compile(r"(?<=[A-Za-z])[-‐‑](?=[A-Za-z])")  # small-angle, z-component


def quantities_named(words: str) -> frozenset[str]:
    """The quantities ``words`` name: ``L``, ``H``, ``E``, ``T`` or ``V`` for the Lagrangian, the
    Hamiltonian, the energy, the kinetic or the potential energy, any other by its word in lower case
    (``torque``).

    >>> sorted(quantities_named(", which is the total energy, not a force"))
    ['E', 'force']
    >>> sorted(quantities_named("The kinetic energy is"))
    ['T']
    """
    found = (" ".join(word.lower().split()) for word in _QUANTITY.findall(words))
    found = (re.sub(r"energ\w*$", "energy", word) if "energ" in word else word.removesuffix("s") for word in found)
    return frozenset(_QUANTITY_NAMES.get(word, word) for word in found)


def _dimensions(words: str) -> bool:
    return bool(_DIMENSIONS_SAID.match(words))


def formula_then_words(text: str, names: Collection[str], coords: Collection[str]) -> Iterator[tuple[str, str]]:
    """``θ̈ = −(g/l) θ for small angles``: the ways to read ``text`` as (a formula, prose after it).
    The prose begins at the first word that is none of the problem's names, spellings or
    functions, or at the mark of punctuation before it (``…, a nonlinear equation``), and must be
    prose (:func:`is_prose`), or a remark in brackets that ends the text and denies (``(not T + V)``).
    The formula is not checked here: the caller reads each in turn."""
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
        remark = rest.lstrip(_OPENS)
        if not (start > 0 and formula):
            continue
        prose = is_prose(remark, names, doubt=True) or _dimensions(remark) or _arithmetic_said(remark, names)
        if prose or _denied(rest) or _closing_remark(rest, names, coords):
            yield formula, rest


def words_then_formula(text: str, names: Collection[str], coords: Collection[str]) -> Iterator[tuple[str, str]]:
    """``The equation of motion is m l θ̈ = −m g sin θ``: the ways to read ``text`` as (a sentence, the
    formula it leads to). The sentence begins with a word that is none of the problem's names (after
    a leading "So" or "Hence"), ends with a word that hands over to a formula (``is``, ``gives``,
    ``we get``) or a colon, and must be prose (:func:`is_prose`). The formula is not checked here."""
    if len(text) > _LENGTH:
        return
    start, first = 0, None
    for word in _WORD.finditer(text):
        if text[start : word.start()].strip(" ,"):
            return  # a sign, a number or a letter before the first word: a formula comes first
        if word[0].lower() not in IMPLYING_WORDS:
            first = word
            break
        start = word.end()
    if first is None or not _is_word(first[0], names, coords):
        return
    for lead in _LEADS_TO.finditer(text, first.end()):
        words, formula = text[: lead.end()].strip(), text[lead.end() :].strip(" ,:")
        if formula and is_prose(_without_squared(words, formula, names, coords), names, doubt=True):
            yield words, formula
    if first[0].lower() in _METHOD:  # From the Euler–Lagrange equation, m l² θ̈ + … = 0
        said, end = _words_from(text, first.start(), names, coords)
        if text[end:].lstrip().startswith(","):
            comma = text.index(",", end) + 1
            # …, it follows that m l² θ̈ + … = 0: words that hand over to the formula after the comma
            between, after = _words_from(text, comma, names, coords, handing=True)
            if not _hands_over(between):
                between, after = [], comma
            words, formula = text[:after].strip(), text[after:].strip()
            if formula and is_prose(" ".join((*said, *between)), names, doubt=True):
                yield words, formula


# words that begin a sentence naming how the formula after its comma was found. Not a condition ("If θ is
# small, …", "For small angles, …"): what that sets is not the formula's, and is read as typed.
_METHOD = frozenset({"from", "using", "applying", "by"})
# words that begin a sentence stating what the quantity is before its value: "Since L = T − V, L = …",
# "The Lagrangian L = T − V is …", "With L = T − V: L = …", "Let L = T − V. Then L = …". Again not a
# condition ("If L = …").
_STATING = _METHOD | {"since", "as", "because", "with", "given", "here", "the", "our", "this", "let"}
# words that hand over from a definition to the value: "…, we have L = …", "…, so L = …"; the words
# between are these alone (not "…, the Hamiltonian is …", which may say the value is another quantity's)
_HANDS_OVER_TO_VALUE = _HANDING_OVER | IMPLYING_WORDS | {"then", "that"}
_BETWEEN = _HANDS_OVER_TO_VALUE | {"we", "this", "which", "it", "and", "one", "follows"}
_BEFORE_A_WORD = re.compile(r"[ \t]+[A-Za-z]{2}")
# a word of prose as a sentence has it: Lagrange's, and Euler–Lagrange with any dash (not T−V: capitals after)
_PROSE_WORD = re.compile(r"(?<![\w\\])(?:Euler\s?[-–‐‑]\s?Lagrange|[A-Za-z]{2,}(?:['’]s)?)(?![\w'’])")
_EULER_LAGRANGE = re.compile(r"\bEuler\s?[-–‐‑]\s?Lagrange\b")


def definition_then_formula(
    text: str, names: Collection[str], coords: Collection[str]
) -> Iterator[tuple[str, str, str]]:
    """``Since L = T − V, L = ½ m l² θ̇² + …``: the ways to read ``text`` as (the words, the definition
    as typed, the chain it states with the value: ``L = T − V = ½ m l² θ̇² + …``, as the parser reads
    it). The sentence begins with a word that states (``Since``, ``Using``, ``With``, ``The``…), and
    perhaps more words (``the Lagrangian``), then the definition: a name, ``=`` and a side without
    words; then ``,``, ``;`` or ``:``, or words that end in one that hands over (``we have``, ``is``,
    ``so``), or the chain's next ``=``; then the value, after the name again unless words or a colon
    hand over to it. The words must be prose (:func:`is_prose`). Neither the definition nor the value is
    checked here."""
    sentence = _defining_sentence(text, names, coords)
    if sentence is None:
        return
    said, left, side, stop, after, handed, _ = sentence
    value = text[after:].strip()
    value_equals = _first_equals(value)
    name = _name(left, names, coords)
    if name is None or not value:
        return
    if text[stop] != "=" and value_equals is not None:  # …, L = ½ m l² θ̇² + …: the value, named again
        if _name(value[:value_equals], names, coords) != name:
            return  # Since L = T − V, H = …: another quantity's value
        value, handed = value[value_equals + 1 :].strip(), True
        left = text[after:].strip()[:value_equals].strip()  # L(θ, θ̇), as the value is named
    if handed and value:
        yield said, f"{left} = {side}", f"{left} = {side} = {value}"


def definition_before_formula(
    text: str, names: Collection[str], coords: Collection[str]
) -> tuple[str, str, str] | None:
    """``With p_θ = m R² θ̇: H = p_θ²/(2 m R²) − …``: a sentence that defines a name of the student's own,
    then the value of another quantity in it, as (the words, the definition as typed, the formula), the
    sentence as :func:`definition_then_formula` reads one (``Using ω₀ = √(g/l), we have ω = ω₀``); None
    for any other text, and where the value is the defined name's own (that is a chain). The value is
    named (``H = …``) or handed over to (``… : p_θ²/(2 m R²) − …``). Neither is checked here."""
    sentence = _defining_sentence(text, names, coords, several=True)
    if sentence is None or text[sentence[3]] == "=":
        return None  # Since L = T − V = …: a chain
    said, left, side, _, after, handed, more = sentence
    # ω₀² = g/l: the name squared, as a frequency is defined (the answer's reading takes the root)
    value, name = text[after:].strip(), _name(_SQUARED.sub("", left), names, coords)
    value_equals = _first_equals(value)
    named = _name(value[:value_equals], names, coords) if value_equals is not None else None
    if name is None or not value or named == name or not (named or handed):
        return None
    if named is not None and named in {_name(_SQUARED.sub("", other[0]), names, coords) for other in more}:
        return None  # With γ = …, ω₀² = …: ω₀ = …: the value is a defined name's own
    return said, " and ".join(f"{one} = {its}" for one, its in ((left, side), *more)), value


_DEFINITIONS = 4  # names defined in one sentence, at the most
_FULL_STOP = re.compile(r"(?<!\.)\.(?=\s)")  # a point before a space ends a sentence: no number's, nor …
_SQUARED = re.compile(r"\s*(?:²|\^\s*2|\^\s*\{\s*2\s*\}|\*\*\s*2)\s*$")


def _defining_sentence(
    text: str, names: Collection[str], coords: Collection[str], *, several: bool = False
) -> tuple | None:
    """A sentence that states a definition, then hands over to a value (:func:`definition_then_formula`):
    (the words, the definition's left side and its side, where the side stops, where the value starts,
    whether words or a colon hand over to it, the further definitions as (left side, side)); None where
    ``text`` begins with no such sentence. With ``several``, more definitions may follow the first, after
    ``,``, ``;`` or ``and`` (``With γ = b/(2m), ω₀² = k/m: …``), where a colon or words hand over after the
    last; else, and where they do not, the sentence defines one name."""
    first = _PROSE_WORD.match(text, len(text) - len(text.lstrip()))
    if len(text) > _LENGTH or first is None or first[0].lower() not in _STATING:
        return None  # as nearly every answer: no sentence that states
    lead, start = _words_from(text, 0, names, coords)
    if not lead:
        return None
    equals = _stop(text, start, names, coords)
    if equals is None or text[equals] != "=":
        return None
    left = text[start:equals].strip()
    stop = _stop(text, equals + 1, names, coords)
    # Let p_θ = m R² θ̇. Then H = …: the sentence's full stop ends the side, as a comma does
    full_stop = _FULL_STOP.search(text, equals + 1, len(text) if stop is None else stop)
    stop = full_stop.start() if full_stop else stop
    side = text[equals + 1 : stop].strip() if stop is not None else ""
    if not side or any(_is_word(word[0], names, coords) for word in _WORD.finditer(side)):
        return None  # L = T − V (not T + V): words in the definition may make it another
    if several:
        more, last = _more_definitions(text, stop, names, coords)
        if more:
            sentence = _handing_over(text, start, last, names, coords, lead)
            if sentence is not None and sentence[-1]:
                return sentence[0], left, side, last, *sentence[1:], tuple(more)
    sentence = _handing_over(text, start, stop, names, coords, lead)
    return None if sentence is None else (sentence[0], left, side, stop, *sentence[1:], ())


def _handing_over(text: str, start: int, stop: int, names, coords, lead: list[str]) -> tuple | None:
    """How the definitions from ``start`` to ``stop`` hand over to the value (:func:`_defining_sentence`):
    (the words, where the value starts, whether words or a colon hand over to it); None where they do not."""
    if text[stop] == "=":  # Since L = T − V = …: the chain as typed
        between, after, handed = [], stop + 1, True
    else:
        between, after = _words_from(text, stop + (text[stop] in ",;:."), names, coords, handing=True)
        if between and not _hands_over(between):
            # Let ω₀² = g/l. The frequency is ω = ω₀: a sentence of its own that names the value, as one alone
            named = _sentence_naming(text, stop, names, coords) if text[stop] in ".;" else None
            if named is None:
                return None  # …, not L = …: words that do not hand over to the value
            between, after = named
        handed = bool(between) or text[stop] == ":"
    if not is_prose(" ".join((*lead, *between)), names, doubt=True):
        return None
    said = " … ".join(part for part in (text[:start].strip(), text[stop:after].strip(" ,;:=.")) if part)
    return re.sub(r"\s+", " ", said), after, handed


def _sentence_naming(text: str, stop: int, names, coords) -> tuple[list[str], int] | None:
    """The words of the sentence after ``stop`` that hand over to a value, as :func:`words_then_formula`
    reads a sentence alone (``The frequency is ω = …``), and where the value starts; None where there is none."""
    rest = text[stop + 1 :]
    for words, formula in words_then_formula(rest, names, coords):
        return _PROSE_WORD.findall(_without_squared(words, formula, names, coords)), stop + 1 + rest.rfind(formula)
    return None


def _without_squared(words: str, formula: str, names, coords) -> str:
    """``The frequency squared is ω² = g/l``: the words without the one ``squared``, where the formula names a
    quantity's square, as the words say it does; there the word says what the label says, and changes no value
    (ω² = g/l alone is read as ω = √(g/l)). ``words`` as typed anywhere else: ``… is ω = √(g/l) squared``."""
    said = _SQUARED_WORD.findall(words)
    equals = _first_equals(formula) if len(said) == 1 else None
    label = formula[:equals] if equals is not None else ""
    if not _SQUARED.search(label) or _name(_SQUARED.sub("", label), names, coords) is None:
        return words
    return _SQUARED_WORD.sub(" ", words)


_SQUARED_WORD = re.compile(r"\bsquared\b", re.I)


def _more_definitions(text: str, stop: int, names, coords) -> tuple[list[tuple[str, str]], int]:
    """The definitions after the one that stops at ``stop``, each after ``,``, ``;`` or ``and`` (``, and``),
    as (left side, side), and where the last stops: a name (or its square), ``=`` and a side without words,
    that ends at ``,``, ``;``, ``:`` or a word, not at a chain's next ``=``."""
    more: list[tuple[str, str]] = []
    while len(more) < _DEFINITIONS and (text[stop] in ",;" or text[stop].isalpha()):
        between, start = _words_from(text, stop + (text[stop] in ",;"), names, coords)
        if [word.lower() for word in between] not in ([], ["and"]) or (not between and text[stop] not in ",;"):
            break
        equals = _stop(text, start, names, coords)
        if equals is None or text[equals] != "=":
            break
        left = text[start:equals].strip()
        end = _stop(text, equals + 1, names, coords)
        full_stop = _FULL_STOP.search(text, equals + 1, len(text) if end is None else end)
        end = full_stop.start() if full_stop else end
        side = text[equals + 1 : end].strip() if end is not None else ""
        if end is None or text[end] == "=" or not side or _name(_SQUARED.sub("", left), names, coords) is None:
            break
        if any(_is_word(word[0], names, coords) for word in _WORD.finditer(side)):
            break
        more.append((left, side))
        stop = end
    return more, stop


def euler_lagrange_then_formula(
    text: str, names: Collection[str], coords: Collection[str]
) -> Iterator[tuple[str, str, str, str]]:
    """``Applying d/dt(∂L/∂θ̇) − ∂L/∂θ = 0: m l² θ̈ + m g l sin θ = 0``: the ways to read ``text`` as (all
    before the equation, the Euler–Lagrange operator as typed, the generalized force it is said to equal
    where that is written out, ``−b ẋ``, else "", the equation it gives). Words that state
    may begin it (``Applying``, ``Using``, ``From``…); after the operator's ``= 0`` (or ``= −b ẋ``), a ``,``, ``;`` or
    ``:``, a step (``⇒``), or words that hand over (``we get``), lead to the equation;
    or the equation is what the operator comes to, after its ``=`` (``d/dt(∂L/∂θ̇) − ∂L/∂θ = m l² θ̈ + … = 0``).
    The operator is any of Lagrange's shape (:func:`~grader.judge.euler_lagrange.euler_lagrange`): whether it
    is the true one is for the caller to judge. The words must be prose (:func:`is_prose`); the equation is
    not checked."""
    if len(text) > _LENGTH or "dt" not in text:
        return  # as nearly every answer: no operator
    starts = [len(text) - len(text.lstrip())]
    first = _PROSE_WORD.match(text, starts[0])
    if first is not None:
        if first[0].lower() not in _STATING:
            return
        lead, _ = _words_from(text, 0, names, coords)
        # the longest run of words first; dL of dL/dθ is a word too, as read alone
        starts = [found.end() for found in _PROSE_WORD.finditer(text)][: len(lead)][::-1]
    for start in starts:
        equals = _first_equals(text[start:])
        if equals is None:
            return
        equals += start
        operator = text[start:equals].strip()
        if euler_lagrange(operator, coords, names) is not None:
            break
    else:
        return
    stop = _stop(text, equals + 1, names, coords, stops=_LINE_ENDS)  # the operator's line, then the equation's
    side = text[equals + 1 : stop].strip() if stop is not None else text[equals + 1 :].strip()
    between: list[str] = []
    moved = moved_left(operator, side) if side != "0" else None
    if moved is None and side != "0":
        # = −dF/dẋ: Rayleigh's term written with d, whose dF reads as a word of prose and so ends the side early
        punctuated = _stop(text, equals + 1, names, coords, stops=_LINE_ENDS, prose=False)
        if punctuated is not None:
            moved = moved_left(operator, text[equals + 1 : punctuated].strip())
            stop = punctuated if moved is not None else stop
    if moved is not None:  # d/dt(∂L/∂ẋ) − ∂L/∂x = −∂F/∂ẋ: Rayleigh's term on the right, as = 0 with it on the left
        operator, side = moved, "0"
    force = ""
    if side != "0" and stop is not None and text[stop] in _LINE_ENDS and _written_force(side, names, coords):
        force, side = side, "0"  # = −b ẋ: the generalized force written out, which the caller judges
    if side != "0":  # d/dt(∂L/∂θ̇) − ∂L/∂θ = m l² θ̈ + … = 0: what the operator comes to
        after = equals + 1
    elif stop is None or text[stop] == "=":
        return
    else:
        between, after = _words_from(text, stop + (text[stop] in _LINE_ENDS), names, coords, handing=True)
        if between and not _hands_over(between):
            return  # …, not …: words that do not hand over to the equation
    equation = text[after:].strip(" ,;:")
    words = " ".join((*_PROSE_WORD.findall(text[:start]), *between))
    if equation and _first_equals(equation) is not None and (not words or is_prose(words, names, doubt=True)):
        yield re.sub(r"\s+", " ", text[:after].strip()), operator, force, equation


# what ends the operator's line before the equation it gives: punctuation, a new line, or a step (⇒)
_LINE_ENDS = ",;:\n⇒→⟹"


def _written_force(side: str, names: Collection[str], coords: Collection[str]) -> bool:
    """Whether ``side`` is a generalized force written out in the problem's names (``−b ẋ``), not its
    name (``Q``, ``Q_x``) nor what the operator comes to (``m l² θ̈ + …``, which holds an acceleration)."""
    read = parse_answer(side, coords=coords, known=names)
    if not read.ok or read.kind != "expression" or read.value.is_Symbol:
        return False
    if {symbol.name for symbol in read.value.free_symbols} - {*names, "t"}:
        return False
    return not any(rate.derivative_count > 1 for rate in read.value.atoms(Derivative))


def _words_from(
    text: str, start: int, names: Collection[str], coords: Collection[str], *, handing: bool = False
) -> tuple[list[str], int]:
    """The words of prose from ``start``, one after another with only spaces between, none of them
    the problem's names (:func:`_is_word`; with ``handing``, ``so`` or ``hence`` too), and where they end."""
    words, end = [], start
    for found in _PROSE_WORD.finditer(text, start):
        if text[end : found.start()].strip():
            break
        word = _EULER_LAGRANGE.sub("EulerLagrange", re.sub(r"['’]s$", "", found[0]))
        # a unit's name spelled out before another word is prose too: Newton's second law
        spelled = len(word) > 3 and word in SI_UNITS and _BEFORE_A_WORD.match(text, found.end()) is not None
        if not (_is_word(word, names, coords) or spelled or (handing and word.lower() in IMPLYING_WORDS)):
            break
        words.append(found[0])
        end = found.end()
    return words, end


def _hands_over(between: list[str]) -> bool:
    """Whether the words between a statement and what follows it hand over to it (``we get``, ``so``):
    they end in such a word, and hold no word but those that may stand between."""
    return bool(between) and between[-1].lower() in _HANDS_OVER_TO_VALUE and not set(map(str.lower, between)) - _BETWEEN


def _stop(
    text: str, start: int, names: Collection[str], coords: Collection[str], stops: str = ",;:", *, prose: bool = True
) -> int | None:
    """Where a side that starts at ``start`` ends: at its first of ``stops`` (``,``, ``;``, ``:``) or ``=``
    outside brackets, or (with ``prose``) a word of prose there; None where it runs to the end."""
    words = set()
    if prose:
        words = {found.start() for found in _WORD.finditer(text, start) if _is_word(found[0], names, coords)}
        words |= {found.start() for found in _WORD.finditer(text, start) if found[0].lower() in IMPLYING_WORDS}
    depth = 0
    for i in range(start, len(text)):
        character = text[i]
        depth += (character in "([{") - (character in ")]}")
        if depth or (i and text[i - 1] == "\\"):
            continue  # inside brackets, or TeX's \, and \: (spaces)
        if character in stops or _EQUALS.match(text, i) or i in words:
            return i
    return None


# `=` that is not part of =>, ==, <=, >= or :=
_EQUALS = re.compile(r"(?<![=<>:!])=(?![=>])")


def _first_equals(text: str) -> int | None:
    """Where the first ``=`` of ``text`` outside brackets is; None where there is none."""
    depth = 0
    for i, character in enumerate(text):
        depth += (character in "([{") - (character in ")]}")
        if not depth and _EQUALS.match(text, i):
            return i
    return None


def _name(text: str, names: Collection[str], coords: Collection[str]) -> str | None:
    """The name ``text`` reads as, where it is one the problem does not define (``L``, ``p_φ``, and
    ``L(θ, θ̇)`` as the prompts write it); else None."""
    read = parse_answer(_ARGUMENTS.sub("", text), coords=coords, known=names)
    if not read.ok or read.kind != "expression" or not read.value.is_Symbol or read.value.name in names:
        return None
    return read.value.name


_ARGUMENTS = re.compile(r"\s*\([^()]*\)\s*$")  # L(θ, θ̇): what a quantity is a function of


# words that say what follows is a small-angle form: "which for small θ gives", "linearized:"
_SMALL = re.compile(r"\b(?:small|smaller|lineari[sz](?:ed|ing|ation)|linear)\b", re.I)
# where such words hand over to the formula: as a sentence does (gives, becomes, :), or a comma
_HANDS_OVER = re.compile(rf"{_LEADS_TO.pattern}|,", re.I)


def formula_then_small_angle_form(
    text: str, names: Collection[str], coords: Collection[str]
) -> Iterator[tuple[str, str, str]]:
    """``θ̈ = −(g/l) sin θ, which for small θ gives θ̈ = −(g/l) θ``: the ways to read ``text`` as (a
    formula, words that say its small-angle form follows, that form). The words begin at the first
    word that is none of the problem's names, spellings or functions, say ``small`` (or ``linear``,
    ``linearized``), end with a word that hands over to a formula (``gives``, ``becomes``, ``is``), a
    colon or a comma, and must be prose (:func:`is_prose`: no ``or``, ``not`` or sign). The formulas
    are not checked here."""
    if len(text) > _LENGTH or not _SMALL.search(text):
        return  # as nearly every answer: no word to look for
    word = next((found for found in _WORD.finditer(text) if _is_word(found[0], names, coords)), None)
    if word is None:
        return
    formula = text[: word.start()].rstrip(" \t\n,;:.—–")
    if not formula:
        return
    for lead in _HANDS_OVER.finditer(text, word.start()):
        words, after = text[word.start() : lead.end()].rstrip(" ,:"), text[lead.end() :].strip(" ,:")
        if after and _SMALL.search(words) and is_prose(words, names):
            yield formula, words, after


def formula_then_approximation(text: str) -> tuple[str, str, str] | None:
    """``θ̈ = −(g/l) sin θ ≈ −(g/l) θ`` or ``θ̈ + (g/l) sin θ = 0 ⇒ θ̈ + (g/l) θ = 0 for small θ``: (the
    formula, the sign between, the formula it approximates to), the last with the left side of the
    first where it has none of its own, and without the words that say the angle is small. Only one
    ``≈`` (or ``\\approx``), or one ``⇒`` (``=>``, ``\\Rightarrow``) whose conclusion says so in words;
    None for any other text. The formulas are not checked here."""
    if len(text) > _LENGTH:
        return None
    for sign in _APPROXIMATELY:
        if text.count(sign) == 1:
            first, last = (part.strip(" ,;") for part in text.split(sign))
            last = _SMALL_TAIL.sub("", last).strip(" ,;")
            break
    else:
        signs = [sign for sign in _IMPLIES if text.count(sign) == 1]
        if len(signs) != 1:
            return None
        sign = signs[0]
        first, last = (part.strip(" ,;") for part in text.split(sign))
        if not _SMALL_TAIL.search(last):
            return None  # m l θ̈ = −m g sin θ ⇒ θ̈ = −(g/l) sin θ: a step, not an approximation
        last = _SMALL_TAIL.sub("", last).strip(" ,;")
    if not first or not last:
        return None
    if "=" in first and "=" not in last:
        if first.count("=") != 1:
            return None
        last = f"{first.split('=')[0].strip()} = {last}"  # θ̈ = −(g/l) sin θ ≈ −(g/l) θ: θ̈ = −(g/l) θ
    return first, sign, last


_APPROXIMATELY = ("≈", "\\approx", "~=")
_IMPLIES = ("⇒", "=>", "\\Rightarrow", "\\implies", "⟹")
# words at the end that say the angle is small: "for small θ", "(small angles)", "when θ ≪ 1"
_SMALL_TAIL = re.compile(
    r"[\s,;(]*(?:for|when|if|at)?\s*(?:small|lineari[sz]ed)\b[^=≈]*$|[\s,;(]*(?:for|when)\s*\S+\s*(?:≪|<<)\s*1\)?\s*$",
    re.I,
)


# the zero of potential energy a remark states: V = 0, U=0 (not V = 0.5, V = 0x, nor \\nabla V = 0)
_ZERO_OF_POTENTIAL = re.compile(r"(?<![\w\\])(?P<name>[VU])\s*=\s*0(?![\w.])")
_CLOSERS = {")": "(", "]": "["}


def formula_then_convention(text: str, names: Collection[str]) -> tuple[str, str] | None:
    """``L = ½ m l² θ̇² + m g l cos θ (taking V = 0 at the pivot)``: the formula, and the remark in
    brackets that ends the answer, or after its last comma where a word begins it (``…, taking V = 0
    at the pivot``), where it states the zero of potential energy and is otherwise prose
    (:func:`is_prose`): one ``V = 0`` or ``U = 0``, the name not the problem's, and words around it.
    None for any other text: ``(V = 0 or V = m g l)``, ``(θ = 0 at the top)``, ``…, V = 0``, a bracket
    that does not end the answer, or one without words."""
    if len(text) > _LENGTH:
        return None
    text = text.rstrip().removesuffix(".").rstrip()
    opener = _opening_of_last_bracket(text)
    if opener is not None:
        inner, remark = text[opener + 1 : -1], text[opener:]
    else:  # …, taking V = 0 at the pivot: a word after the comma begins a remark, not an equation
        opener = _last_comma(text)
        inner = remark = text[opener + 1 :].strip() if opener is not None else ""
        if _PROSE_WORD.match(remark) is None:
            return None
    zeros = list(_ZERO_OF_POTENTIAL.finditer(inner))
    if len(zeros) != 1 or zeros[0]["name"] in names:
        return None
    zero = zeros[0]
    words = f"{inner[: zero.start()]} {inner[zero.end() :]}".strip(" ,;:")
    formula = text[:opener].rstrip(" ,;")
    if not formula or not is_prose(words, names, doubt=True):
        return None
    return formula, remark


def _last_comma(text: str) -> int | None:
    """Where the last comma of ``text`` outside brackets is; None where there is none."""
    depth = 0
    for i in range(len(text) - 1, -1, -1):
        depth += (text[i] in _CLOSERS) - (text[i] in _CLOSERS.values())
        if not depth and text[i] == ",":
            return i
    return None


def _opening_of_last_bracket(text: str) -> int | None:
    """Where the bracket that closes ``text`` opens; None where it does not end in one, or it is not
    balanced."""
    if not text or text[-1] not in _CLOSERS:
        return None
    depth = 0
    for i in range(len(text) - 1, -1, -1):
        depth += (text[i] in _CLOSERS) - (text[i] in _CLOSERS.values())
        if depth == 0:
            return i if text[i] == _CLOSERS[text[-1]] else None
    return None


def text_as_words(text: str, names: Collection[str], coords: Collection[str]) -> str:
    """``… = 0 \\text{(damped)}`` as ``… = 0 (damped)``: each ``\\text{…}`` (or ``\\mbox``, ``\\mathrm``…)
    that the parser reads as words, not as mathematics (a unit, ``\\text{L} =``, ``\\text{ where }``), as
    the words it holds, with TeX's spaces before it left out; so they are found as words beside a
    formula are, and said back as typed inside the braces. The text as typed where there are none."""
    for _ in range(_TEXT_GROUPS):
        if _TEXT_COMMAND.search(text) is None:
            break
        read = parse_answer(text, coords=coords, known=names)
        if read.ok or read.code != "latex_words":
            break
        group = text[read.start : read.end]
        words = group[group.index("{") + 1 : -1]
        text = f"{_without_tex_spaces(text[: read.start])} {words} {text[read.end :]}"
    return text


def tex_math_as_words(text: str) -> str:
    """``Since $L = T − V$, $L = \\frac12 m l^2 \\dot\\theta^2 + …$`` as ``Since L = T − V, L = \\frac12 …``:
    TeX's inline mathematics (``$…$``, ``$$…$$``, ``\\(…\\)``) in a sentence, without the signs that set it
    apart from the words, so the sentence reads as one typed without them. The text as typed where it
    holds no such mathematics, a ``$`` left unpaired, or no word outside the mathematics.

    >>> tex_math_as_words("Since $L = T - V$, $L = m$")
    'Since L = T - V, L = m'
    """
    if len(text) > _LENGTH or ("$" not in text and "\\(" not in text):
        return text  # as nearly every answer: no mathematics set apart
    outside = _TEX_MATH.sub(" ", text)
    if "$" in outside or "\\(" in outside or "\\)" in outside:
        return text  # a sign left unpaired: not read apart
    if not _PROSE_WORD.search(outside):
        return text  # mathematics alone, which the parser reads
    return _TEX_MATH.sub(lambda found: found[1] if found[1] is not None else found[2], text)


# TeX's inline mathematics set apart from words: $…$, $$…$$ or \(…\)
_TEX_MATH = re.compile(r"\$\$?([^$]+?)\$\$?|\\\((.+?)\\\)", re.S)


def _without_tex_spaces(text: str) -> str:
    """``text`` without the spaces it ends in, TeX's (``\\,``, ``\\quad``, ``~``) too."""
    while True:
        text = text.rstrip()
        space = next((space for space in _TEX_SPACES if text.endswith(space)), None)
        if space is None:
            return text
        text = text[: -len(space)]


def words_in(text: str, names: Collection[str], coords: Collection[str]) -> str:
    """The words of prose anywhere in ``text``, from the first to the last, as typed; ``""`` where there
    are none. A word is as :func:`_is_word` has it: ``Dimension of force`` of ``Dimension of force: Q_θ = …``,
    but not ``So``, ``sin`` or a unit's name.

    >>> words_in("Dimension of force: Q_θ = −m g r sin θ", ["g", "m", "r", "theta"], ["r", "theta"])
    'Dimension of force'
    """
    if len(text) > _LENGTH:
        return ""
    found = [word for word in _WORD.finditer(text) if _is_word(word[0], names, coords)]
    return text[found[0].start() : found[-1].end()] if found else ""


def _is_word(word: str, names: Collection[str], coords: Collection[str]) -> bool:
    """Whether ``word`` reads as one name the problem does not have, and no Greek letter's: ``for``,
    ``conserved``; not ``mgl`` (m·g·l), ``thetadot``, ``sin`` or ``omega``."""
    if word.lower() in GREEK_NAMES or word.lower() in IMPLYING_WORDS:
        return False  # So θ̈ = …: a step of the working, which the parser reads
    read = parse_answer(word, coords=coords, known=names)
    if not read.ok or read.kind != "expression" or not read.value.is_Symbol:
        return False
    return read.value.name not in names and read.value.name not in SI_UNITS
