"""Turning a student's text into tokens: the whitelist, and why it is one.

Contents:
    LIMITS                   the caps on size, nesting, numbers and names
    Token, Name              what the grammar consumes
    tokenize(text)           plain notation (``m g l sin θ``), or LaTeX when the text has a backslash

Threat model
------------
Every character here was typed by someone we do not trust, and the grader runs on a
department's server. We assume the author of an answer will try to:

* run code. sympy's ``sympify`` and ``parse_expr`` call ``eval``, and no restricted
  namespace stops ``Integer.__mro__[-1].__subclasses__()``. So no student text is ever
  handed to ``eval``, ``exec``, ``sympify``, ``parse_expr`` or ``lambdify``: this
  tokenizer accepts a closed set of characters and words, and the grammar builds sympy
  objects itself from the tokens. Attribute access (``.x``), strings, comments,
  assignments, ``__dunder__`` names and unknown functions are refused outright, so
  nothing that resembles code is ever read as mathematics.
* make a Symbol whose *name* is code. ``lambdify`` writes Symbol names into Python
  source (sympy #24990). Names are built only from ASCII letters, digits and single
  underscores (Greek letters are spelled out), never from the raw text.
* exhaust time or memory without running code: ``9^9^9^9``, ``1e999999999``, 10,000
  nested brackets, a 20,000-term sum. The input length, bracket and recursion depth,
  digits in a literal, exponent size and name length are capped here and in the
  grammar; the symbolic checks downstream have their own time limits.
* crash the grader. Whatever is typed, ``parse_answer`` returns a value; it never
  raises. The property tests feed it arbitrary text to keep it so.

Anything not explicitly allowed below is refused with a message that points at it.
"""

from __future__ import annotations

import re
import unicodedata
from dataclasses import dataclass
from fractions import Fraction
from typing import NamedTuple

from grader.parse.messages import ParseFailure
from grader.parse.names import (
    CONSTANT_WORDS,
    FUNCTION_NAMES,
    GREEK_BY_LETTER,
    IMPLYING_WORDS,
    JOINING_WORDS,
    SUBSCRIPT_DIGITS,
    SUBSCRIPT_LETTERS,
    SUPERSCRIPTS,
    function_name,
)

__all__ = ["LIMITS", "Name", "Token", "tokenize", "visible"]


@dataclass(frozen=True)
class Limits:
    """Caps that keep a hostile answer cheap to refuse. Realistic answers are far inside them."""

    length: int = 2000  # characters in an answer
    depth: int = 40  # nested brackets, function calls and signs
    powers: int = 8  # a power in an exponent in an exponent…: sympy's cost grows with the square of the height
    digits: int = 30  # digits in one number
    exponent: int = 100  # magnitude of a numeric exponent
    power_digits: int = 400  # digits of an evaluated numeric power
    name: int = 40  # characters in one name
    derivative_order: int = 3


LIMITS = Limits()


# Name and Token are named tuples rather than frozen dataclasses: as immutable, three times as fast
# to make, and an answer has dozens of them.
class Name(NamedTuple):
    """An identifier as typed: ASCII spelling, time-derivative marks, and how it was written.

    ``raw`` has Greek letters spelled out and Unicode subscripts as ``_digits``
    (``θ̇₁`` → ``theta_1`` with ``dots=1``). ``tex`` marks a run of letters in a
    LaTeX answer: where it is not a name the problem knows, TeX reads it one letter
    at a time (``xy`` is x·y), where plain notation would keep one unknown name.
    """

    raw: str
    dots: int = 0
    primes: int = 0
    tex: bool = False
    unit: bool = False  # a word of a unit in roman type (\mathrm{rad/s}): one symbol, never split


class Token(NamedTuple):
    """One token: its kind, its value, and where it stands in the original text.

    Kinds: ``num`` (value: digit string), ``name`` (value: :class:`Name`), ``func``
    (value: canonical function name, or ``diff``), ``op`` (value: one of
    ``+ - * / ^ = , ; ( ) [ ] { }``), ``sup`` (value: int, a Unicode superscript),
    ``sep`` (a new line or LaTeX ``\\\\`` between equations), ``frac``, ``over`` (TeX's ``\\over``),
    ``sqrt``, ``partial`` (∂), ``sum`` (``\\sum`` or ∑, its limits read past), ``implies`` (⇒: a
    derivation's step, :func:`tokenize` keeps what follows), ``arrow`` (→: the same between two
    equations, refused elsewhere), ``gap`` (``\\quad``, an environment's end: a ``sep`` between two
    equations, nothing elsewhere), ``end``; the grammar adds ``deriv`` (value: the order) where it
    reads Leibniz's d/dt.
    """

    kind: str
    value: object
    start: int
    end: int

    def is_op(self, *ops: str) -> bool:
        return self.kind == "op" and self.value in ops


# The whitelist. Operators by every spelling a keyboard or a PDF produces.
_OPERATORS = {
    "+": "+", "-": "-", "\u2212": "-", "\u2013": "-", "*": "*", "\u00b7": "*", "\u22c5": "*",
    "\u2010": "-", "\u2011": "-", "\u2012": "-", "\ufe63": "-", "\ufe62": "+", "\u2217": "*",  # ‐ ‑ ‒ ﹣ ﹢ ∗
    "\u00d7": "*", "\u2219": "*", "/": "/", "\u00f7": "/", "\u2044": "/", "\u2215": "/", "^": "^", "=": "=",
    "\u2248": "=", "\u2243": "=",  # ≈ ≃: θ̈ ≈ −(g/l) θ for small angles, T ≈ 2.01: the relation asked for
    ",": ",", ";": ";",
    "(": "(", ")": ")", "[": "[", "]": "]", "{": "{", "}": "}", "|": "|", "\u2223": "|",
}  # fmt: skip
_VULGAR_FRACTIONS = {"½": "1/2", "⅓": "1/3", "⅔": "2/3", "¼": "1/4", "¾": "3/4", "⅕": "1/5", "⅛": "1/8"}
_PRIMES = {"'": 1, "\u2019": 1, "\u2032": 1, "\u2033": 2}  # ’: a phone's apostrophe for a prime
# A derivation's steps: what follows ⇒ ⟹ ⇔ ⟺ ∴ (and =>, ==>, <=> typed) is what was derived.
_IMPLIES = {"\u21d2", "\u27f9", "\u21d4", "\u27fa", "\u2234"}
# → ⟶ (and ->, --> typed) are steps too, but only between two equations: θ → 0 is a limit.
_ARROWS = {"\u2192", "\u27f6"}
_TYPED_ARROW = re.compile(r"<=>|==>|=>|-->|->")  # before <= and == (code's tests) and - (minus)
_LATEX_IMPLIES = {"Rightarrow", "implies", "Longrightarrow", "iff", "Leftrightarrow", "Longleftrightarrow", "therefore"}
_LATEX_ARROWS = {"to", "rightarrow", "longrightarrow"}
_COMBINING_DOTS = {"\u0307": 1, "\u0308": 2, "\u20db": 3}
# [0-9], not \d: \d also matches ٣ and ², which are not numbers to us.
_NUMBER = re.compile(r"([0-9]+(?:\.[0-9]+)?|\.[0-9]+)(?:[eE]([+-]?[0-9]+))?")
_DIGITS = frozenset("0123456789")
_SENTENCE_FOLLOWS = re.compile(r"[ \t]+(?=[^\W\d_])")  # after a full stop: a space, then a letter
_ASCII_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*")
_LETTERS = re.compile(r"[A-Za-z]+")
_UNICODE_SUBSCRIPT = re.compile(r"[\u2080-\u2089]+")
_ENDS_IN_SUBSCRIPT = re.compile(r"_[0-9]+$")
_SUBSCRIPTS = SUBSCRIPT_DIGITS | SUBSCRIPT_LETTERS  # θ₁, Qᵣ: a subscript typed as one
_SUBSCRIPT_AFTER_DOT = re.compile(r"_?[0-9]+|[\u2080-\u2089]+|_[A-Za-z0-9\u03b1-\u03c9\u03d1\u03d5\u03f5]+")
_COMMAND_NAME = re.compile(r"\\([A-Za-z]+)")
_TEX_PRIME = re.compile(r"\^\s*\\prime(?![A-Za-z])\s*")  # \theta^\prime
_TEX_PRIMES = re.compile(r"\^\s*(\{)\s*((?:\\prime(?![A-Za-z])\s*)+)")  # \theta^{\prime\prime …
_COMMAND = re.compile(r"\\([A-Za-z]+\*?|.?)")
_ENVIRONMENT = re.compile(r"\s*\{([A-Za-z*]+)\}")
_LEFT_RIGHT = re.compile(r"\\(left|right)(?![A-Za-z])\s*(\.?)")
_ASSIGNMENTS = (":=", "==", "+=", "-=", "*=", "/=", "!=", "<=", ">=")
# What a student might try that we can name, rather than calling it a bad character.
_NAMED_REFUSALS = {"#": "comment", '"': "string", "`": "string"}
# Cyrillic and Greek letters drawn as Latin ones, which a keyboard layout or a pasted text slips in:
# refused, and named, for the student cannot see what is wrong (Greek ο is no physicist's letter)
_OTHER_SCRIPTS = dict(
    zip("аеорсухіјѕһԁԛԝАВЕКМНОРСТХІЈЅοΑΒΕΖΗΙΚΜΝΟΡΤΥΧ", "aeopcyxijshdqwABEKMHOPCTXIJSoABEZHIKMNOPTYX", strict=True)
)
_OTHER_SCRIPT = re.compile("[" + "".join(_OTHER_SCRIPTS) + "]")

_LATEX_NAMES = {name: name for name in set(GREEK_BY_LETTER.values())} | {
    "varphi": "phi", "vartheta": "theta", "varepsilon": "epsilon", "varrho": "rho",
    "varsigma": "sigma", "varpi": "pi", "ell": "l",
}  # fmt: skip
# LaTeX has \arcsin but no \asin, and no command at all for the inverse hyperbolic functions.
_LATEX_FUNCTIONS = {
    name: name for name in FUNCTION_NAMES.values() if name not in ("asin", "acos", "atan", "asinh", "acosh", "atanh")
} | {
    "arcsin": "asin",
    "arccos": "acos",
    "arctan": "atan",
    "ln": "log",
    "sen": "sin",  # babel's Spanish \sen
    "ctg": "cot",  # and its Russian \ctg, as Europe writes the cotangent
    "cotg": "cot",
}
# names followed by an argument in plain notation; Derivative(θ(t), t) as sympy prints it
_CALLABLE = FUNCTION_NAMES | {"diff": "diff", "Derivative": "diff"}
_LATEX_OPERATORS = {
    "cdot": "*", "times": "*", "ast": "*", "div": "/", "approx": "=", "simeq": "=",
    "vert": "|", "lvert": "|", "rvert": "|",
}  # fmt: skip
_LATEX_FONTS = {"mathcal", "mathscr", "mathrm", "mathbf", "mathit", "mathsf", "boldsymbol"}
# \label{eq:L} and \tag{1} name an equation for a document; \text{.} is the sentence's full stop.
_LATEX_ANNOTATIONS = re.compile(r"\s*\{[^{}]{0,40}\}")
# a unit or words in \text or \mathrm, as \mathrm{rad/s} or \text{(not sure about the sign)}: a remark's length
_TEXT_WORDS = re.compile(r"\s*\{[^{}]{0,120}\}")
_TEXT_COMMANDS = {"text", "textrm", "mathrm", "operatorname", "mbox"}  # whose braces may hold a unit or words
# rad/s, m/s^2, kg·m^2: words joined by / ^ or ·, as a compound unit is written in \mathrm or \text
_COMPOUND_UNIT = re.compile(r"\s*\{\s*[A-Za-z]+(?:\s*(?:/|\^|·|\\cdot)\s*\{?-?[A-Za-z0-9]+\}?)+\s*\}")
_UNIT_PIECE = re.compile(r"(?P<word>[A-Za-z]+)|(?P<number>[0-9]+)|(?P<op>\\cdot|[/^·{}-])")
_TEXT_PUNCTUATION = re.compile(r"\s*\{\s*[.,;]?\s*\}")
_OPERATOR_NAME = re.compile(r"\s*\{\s*([A-Za-z]+)\s*\}")
_BRACED_LETTERS = re.compile(r"\{\s*([A-Za-z]+)\s*\}|\s*([A-Za-z])")  # \mathcal{L}, or \mathcal L as TeX reads it
_SIZES = {f"{size}{side}" for size in ("big", "Big", "bigg", "Bigg") for side in ("", "l", "r", "m")}
# \nonumber and \notag: an aligned row's number left out, nothing of the row's mathematics
_LATEX_IGNORED = {"left", "right", "middle", "displaystyle", "textstyle", "limits", "nonumber", "notag", *_SIZES}
# bold type, which says vector; our answers are scalars, so \boldsymbol{\theta} is θ
_BOLD = {"mathbf", "boldsymbol", "bm"}
# L + \text{const.}: the word for any constant, as \mathrm{const} is read, its full stop an abbreviation's
_CONSTANT_WORD = re.compile(r"\s*\{\s*(" + "|".join(CONSTANT_WORDS) + r")\.?\s*\}")
_WORD_BEFORE_EQUALS = re.compile(r"\s*\{\s*([A-Za-z]+)\s*\}(?=\s*=)")  # \text{L} = …: the quantity's name
# \overset{.}{\theta}, \overset{..}{\theta}, \overset{\cdot\cdot}{\theta}: dots set over a name, as \dot, \ddot
_OVERSET_DOTS = re.compile(r"\s*\{\s*((?:(?:\.|\\cdot(?![A-Za-z]))\s*){1,2})\}")
_LATEX_ENVIRONMENTS = {
    "aligned", "align", "align*", "gathered", "gather", "gather*", "split",
    "cases", "equation", "equation*", "multline", "array", "eqnarray", "eqnarray*",
}  # fmt: skip
# the space a row break \\[6pt] leaves below its row: a TeX length (as \\ reads it, past spaces)
_ROW_SPACING = re.compile(
    r"\*?\s*\[\s*[-+]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)\s*(?:pt|em|ex|mm|cm|in|bp|pc|dd|cc|sp|mu)\s*\]"
)
_DIFFERENCES = frozenset({"Delta", "delta"})  # TeX's Δ and δ, glued to the name after them as Δθ is
_ARRAY_COLUMNS = re.compile(r"\s*\{[lcr|@ ]*\}")  # \begin{array}{ll}: how its columns align
# a sum's limits, read past with it: \sum_i, \sum_{j=1}^{n}, \sum\limits_k; ∑_i as typed. What they
# bound is not read: a sum is read only where the side it stands in is passed over (see the grammar)
_SUM_LIMITS = re.compile(
    r"\s*(?:\\(?:no)?limits(?![A-Za-z])\s*)?(?:[_^]\s*(?:\{[A-Za-z0-9=+\- ]{1,16}\}|[A-Za-z0-9])\s*){0,2}"
)


def tokenize(text: str) -> list[Token]:
    """Tokens of an answer, ending with an ``end`` token.

    Raises:
        ParseFailure: for any character or word outside the whitelist.
    """
    tokens = _Tokenizer(text, latex="\\" in text).run()
    if any(token.kind == "gap" for token in tokens):
        tokens = _gaps(tokens)
    if any(token.kind == "arrow" or _is_implying_word(token) for token in tokens):
        tokens = _steps_between_equations(tokens, text)
    if any(token.kind == "implies" for token in tokens):
        tokens = _conclusions(tokens)
    if any(token.is_op("|") for token in tokens):
        tokens = _absolute_values(tokens)
    _check_brackets(tokens)
    return tokens


def _absolute_values(tokens: list[Token]) -> list[Token]:
    """``|x|`` as ``abs(x)``: a bar after a value closes the innermost open bar, if that is the
    innermost bracket; any other bar opens one. So ``|a||b|`` is |a|·|b| and ``||a| − b|`` nests;
    ``|a|b|c|`` is |a|·b·|c|, as it must be read one way."""
    result: list[Token] = []
    stack: list[Token] = []  # the open brackets, a bar as its ``|`` token
    for token in tokens:
        if token.kind == "op" and token.value in _CLOSERS:
            stack.append(token)
        elif token.kind == "op" and token.value in _CLOSERS.values():
            if stack and stack[-1].is_op("|"):
                opener = stack[-1]
                raise ParseFailure(
                    "mismatched", token.start, token.end, open="|", open_position=opener.start + 1,
                    close=token.value, position=token.start + 1,
                )  # fmt: skip
            if stack:
                stack.pop()
        elif token.is_op("|"):
            previous = result[-1] if result else None
            after_value = previous is not None and (
                previous.kind in ("num", "name", "sup") or previous.is_op(")", "]", "}")
            )
            if after_value and stack and stack[-1].is_op("|"):
                stack.pop()
                result.append(Token("op", ")", token.start, token.end))
            else:
                stack.append(token)
                result += [Token("func", "abs", token.start, token.end), Token("op", "(", token.start, token.end)]
            continue
        result.append(token)
    bars = [token for token in stack if token.is_op("|")]
    if bars:
        raise ParseFailure("unclosed", bars[-1].start, bars[-1].end, open="|", position=bars[-1].start + 1)
    return result


def _gaps(tokens: list[Token]) -> list[Token]:
    """TeX's wide spaces (``\\quad``, ``\\qquad``) and an environment's end, read as a new line
    where an equation stands on each side (``\\ddot x = -x \\qquad \\ddot y = -y``), and left out
    elsewhere, as the spaces they are."""
    gaps = [i for i, token in enumerate(tokens) if token.kind == "gap"]
    before, after = _equations_beside(tokens, gaps, -1), _equations_beside(tokens, gaps[::-1], 1)
    kept = []
    for i, token in enumerate(tokens):
        if token.kind != "gap":
            kept.append(token)
        elif before[i] and after[i]:
            kept.append(Token("sep", "\n", token.start, token.end))
    return kept


def _equations_beside(tokens: list[Token], positions: list[int], step: int) -> dict[int, bool]:
    """:func:`_equation_beside` for each of ``positions``, given in the order of ``step``, in
    linear time: a look that reaches the position before goes on as that one's did (a thousand
    ``\\quad`` would otherwise each look back over all the others). Tokens are never ``gap``s by
    the time an arrow or a word looks, so each of those looks alone."""
    seen_before: dict[int, bool] = {}
    last = None
    for i in positions:
        j, seen, found = i + step, False, False
        while 0 <= j < len(tokens) - 1:
            token = tokens[j]
            if j == last:  # from here on the look is the last one's, unless it would cross a line
                beyond = j + step
                crosses = 0 <= beyond < len(tokens) - 1 and tokens[beyond].kind == "sep"
                found = seen_before[last] and not crosses
                break
            if token.is_op("="):
                found = True
                break
            if token.kind in ("implies", "arrow") or _is_implying_word(token) or token.is_op(";"):
                break
            if token.kind == "sep" and seen:
                break
            seen = seen or token.kind != "sep"
            j += step
        seen_before[i] = found
        last = i
    return seen_before


def _is_implying_word(token: Token) -> bool:
    name = token.value if token.kind == "name" else None
    return name is not None and name.raw.lower() in IMPLYING_WORDS and not (name.dots or name.primes)


def _steps_between_equations(tokens: list[Token], text: str) -> list[Token]:
    """→ and the words *so*, *hence*, *thus*, *therefore* read as ⇒ where an equation stands on
    each side (``m ẍ = −k x → ẍ = −(k/m) x``), or starts the answer before one (``So θ̈ = …``).
    Elsewhere a word stays a name, and an arrow is refused: ``θ → 0`` is a limit, not part of an
    answer."""
    steps = list(tokens)
    for i, token in enumerate(tokens):
        if token.kind != "arrow" and not _is_implying_word(token):
            continue
        if (i == 0 or _equation_beside(tokens, i, -1)) and _equation_beside(tokens, i, 1):
            steps[i] = Token("implies", "⇒", token.start, token.end)  # or "so θ̈ = …", where the answer starts
            if token.kind == "name" and tokens[i + 1].is_op(","):
                steps[i + 1] = None  # So, θ̈ = …: the comma after the word is the sentence's
        elif token.kind == "arrow":
            raise ParseFailure("arrow", token.start, token.end, arrow=text[token.start : token.end])
    return [step for step in steps if step is not None]


def _equation_beside(tokens: list[Token], i: int, step: int) -> bool:
    """Whether an ``=`` stands between the token at ``i`` and the next step, ``;`` or line's end,
    looking one way (``step`` −1 or 1); at a line's edge it looks into the next line that way."""
    return _equations_beside(tokens, [i], step)[i]


def _conclusions(tokens: list[Token]) -> list[Token]:
    """What a derivation written with ``⇒`` concludes: on each line (or between ``;``), what
    follows its last ``⇒``. A line that begins with ``⇒``, or follows one that ends with it,
    continues the derivation: it replaces the lines above. ``m l θ̈ = −m g sin θ ⇒ θ̈ = −(g/l) sin θ``
    is the second equation; ``eq₁ ⇒ eq₁′ ⏎ eq₂ ⇒ eq₂′`` and ``eq₁; eq₂ ⇒ eq₂′`` are systems of two.
    A step left behind that defines a name the conclusion uses stays, before it, as a definition:
    ``T = ½ m l² θ̇², V = −m g l cos θ, so L = T − V`` (see :func:`_definitions_used`)."""
    lines: list[list[Token]] = [[]]
    depth = 0
    for token in tokens[:-1]:
        depth += token.is_op("(", "[", "{") - token.is_op(")", "]", "}")
        if token.kind == "sep" or (depth == 0 and token.is_op(";")):
            lines.append([])
        else:
            lines[-1].append(token)
    kept: list[list[Token]] = []
    left: list[list[Token]] = []  # the steps the conclusions replace
    continues = False
    for line in lines:
        if line and (continues or line[0].kind == "implies"):
            left, kept = left + kept, []
        continues = False
        while line and line[-1].kind == "implies":
            line, continues = line[:-1], True
        implications = [i for i, token in enumerate(line) if token.kind == "implies"]
        kept.append(line[implications[-1] + 1 :] if implications else line)
        if implications:
            left.append(line[: implications[-1]])
    result: list[Token] = []
    for line in [*_definitions_used(left, kept), *kept]:
        if result and line:
            result.append(Token("sep", "\n", line[0].start, line[0].start))
        result += line
    return [*result, tokens[-1]]


def _definitions_used(left: list[list[Token]], kept: list[list[Token]]) -> list[list[Token]]:
    """The steps in ``left`` that read ``name = …`` (one ``=``, a name without dots or primes) where
    the conclusions in ``kept`` use the name other than as a label of their own (``L = …``), or
    its rate in their first or last side (``p = m l² θ̇ ⇒ ṗ = …``, ``x = l sin θ ⇒ L = ½ m ẋ² …``:
    the sides the parser keeps of a chain)."""
    pieces = [piece for line in kept for piece in _pieces(line)]
    used = {token.value.raw for piece in pieces for token in _unlabelled(piece)}
    used |= {token.value.raw for piece in pieces for token in _kept_sides(piece) if _rate(token)}
    return [
        piece
        for line in left
        for piece in _pieces(line)
        if _labelled(piece) and piece[0].value.raw in used and sum(token.is_op("=") for token in piece) == 1
    ]


def _pieces(line: list[Token]) -> list[list[Token]]:
    """A line's steps and its items: between ``⇒`` and the commas outside brackets."""
    pieces: list[list[Token]] = [[]]
    depth = 0
    for token in line:
        depth += token.is_op("(", "[", "{") - token.is_op(")", "]", "}")
        if token.kind == "implies" or (depth == 0 and token.is_op(",")):
            pieces.append([])
        else:
            pieces[-1].append(token)
    return [piece for piece in pieces if piece]


def _labelled(piece: list[Token]) -> bool:
    """Whether a step begins ``name =``, with more after it."""
    return len(piece) > 2 and _plain(piece[0]) and piece[1].is_op("=")


def _unlabelled(piece: list[Token]) -> list[Token]:
    """The plain names of a step, but the name it begins with as ``name =``."""
    return [token for token in (piece[2:] if _labelled(piece) else piece) if _plain(token)]


def _kept_sides(piece: list[Token]) -> list[Token]:
    """The tokens of a step before its first ``=`` and after its last: all of it where it has none."""
    equals = [i for i, token in enumerate(piece) if token.is_op("=")]
    return piece[: equals[0]] + piece[equals[-1] + 1 :] if equals else piece


def _rate(token: Token) -> bool:
    """Whether a token is a name with one dot or prime: ``ẋ``, ``p'``."""
    return token.kind == "name" and token.value.dots + token.value.primes == 1


def _plain(token: Token) -> bool:
    """Whether a token is a name without dots or primes."""
    return token.kind == "name" and not (token.value.dots or token.value.primes)


# A Mac keyboard types a dot or two over a letter as the spacing marks ˙ (Option-h) and ¨
# (Option-u, space): read after a letter as the combining ones, θ˙ as θ̇. One character for one,
# so positions in messages still point into the text as typed.
_SPACING_DOTS = {0x02D9: "\u0307", 0x00A8: "\u0308"}
# Letters a PDF or a word processor gives for ours: script ℓ, ℒ, ℋ, ℱ (as \ell and \mathcal do),
# and full-width digits, letters and signs (an East Asian keyboard's). One character for one.
# And the mathematical italic, bold and sans-serif letters and digits a word processor's equation
# editor gives (𝑚, 𝐠, 𝜃, 𝟏), and the script ɡ, each as the letter or digit it styles.
_LOOKALIKES = (
    {0x2113: "l", 0x2112: "L", 0x210B: "H", 0x2131: "F", 0x0261: "g"}
    | {c: chr(c - 0xFEE0) for c in range(0xFF01, 0xFF5F)}
    | {
        c: styled
        for c in range(0x1D400, 0x1D800)
        if len(styled := unicodedata.normalize("NFKC", chr(c))) == 1 and styled.isalnum()
    }
)
# Invisible: zero-width spaces and joiners, a byte order mark, a word joiner, and the left-to-right
# and right-to-left marks that right-to-left text around leaves. Read as a space; a line or paragraph
# separator as a new line. The overrides and isolates (U+202A–202E, U+2066–2069) stay refused: they
# reorder what a reader of the answer sees.
# Word's equation editor copies a function application (U+2061) after every function's name, and an
# invisible times (U+2062) or separator (U+2063) between factors: spaces too, as juxtaposition already
# multiplies. And the typographic spaces, en to hair (U+2000–200A), narrow no-break and medium
# mathematical (U+202F, U+205F), and the ideographic space of an East Asian keyboard.
_INVISIBLE = (
    dict.fromkeys(
        (0x200B, 0x200C, 0x200D, 0x200E, 0x200F, 0x2060, 0xFEFF, 0x2061, 0x2062, 0x2063, 0x202F, 0x205F, 0x3000), " "
    )
    | dict.fromkeys(range(0x2000, 0x200B), " ")
    | {0x2028: "\n", 0x2029: "\n"}
)
# Word's linear format groups with 〖 〗 where a bracket would show (sin⁡〖2θ〗, 〖θ̇〗^2): brackets to us.
_GROUPING = {0x3016: "(", 0x3017: ")"}
_READ_AS = str.maketrans(_SPACING_DOTS | _LOOKALIKES | _INVISIBLE | _GROUPING)  # all, in one pass over the text


def _refuse_other_scripts(text: str) -> None:
    """Refuse a Cyrillic or Greek letter drawn as a Latin one, alone or in a word with Latin
    letters (cоs). A word all in another script (степени) is no slip of the keyboard, and is
    refused as usual, where its first letter is read.

    Raises:
        ParseFailure: ``lookalike``, naming the letter and the one it looks like.
    """
    for found in _OTHER_SCRIPT.finditer(text):
        start, end = found.start(), found.end()
        while start and text[start - 1].isalpha():
            start -= 1
        while end < len(text) and text[end].isalpha():
            end += 1
        word = text[start:end]
        if len(word) == 1 or any("a" <= c.lower() <= "z" for c in word):
            c = found[0]
            name = unicodedata.name(c).capitalize()  # Cyrillic small letter o
            raise ParseFailure("lookalike", found.start(), found.end(), char=c, latin=_OTHER_SCRIPTS[c], name=name)


def visible(text: str) -> str:
    """``text`` as it reads: lookalike letters as ours, invisible characters as spaces, one for one."""
    return text.translate(_READ_AS)


_LIST_MARKER = re.compile(r"[ \t]*([0-9]{1,3})[.)][ \t]+")
_BULLETS = "•◦▪‣⁃"  # never mathematics, so one alone is a bullet too
_BULLET = re.compile(rf"[ \t]*([{_BULLETS}]|\*(?=[ \t]))[ \t]*")


# the rest of a line after its math: closing delimiters, \end{…}, then the line's end or TeX's \\
_LINE_END = re.compile(r"(?:[ \t]|\\[\])]|\$|\\end\{[A-Za-z*]+\})*(?:\n|$|\\\\)")


def _opens_line(text: str, start: int) -> bool:
    """Whether only spaces (or ``$``) stand between the line's start and ``start``."""
    return not text[:start].rsplit("\n", 1)[-1].strip(" \t$")


def _closes_line(text: str, position: int) -> bool:
    """Whether only spaces and the math's closing delimiters follow ``position`` on its line
    (or before TeX's line break ``\\\\``)."""
    return bool(_LINE_END.match(text, position))


def _is_word(token: Token) -> bool:
    """Whether a token is a word (``Lagrangian``, ``Answer``): three ASCII letters or more, and no
    Greek letter's or function's name."""
    raw = token.value.raw if token.kind == "name" else ""
    return len(raw) >= 3 and raw.isascii() and raw.isalpha() and raw.lower() not in _NOT_WORDS


_NOT_WORDS = {name.lower() for name in (*GREEK_BY_LETTER.values(), *FUNCTION_NAMES, *_CALLABLE)}


def _list_markers(text: str) -> dict[int, int]:
    """Where ``1. …`` or ``1) …`` numbers every line of an answer in order, or the same bullet
    (``•``, or ``*`` and a space, as Markdown lists) starts every line: start → end of each
    marker, to be read past. Otherwise none: ``2. l θ̈`` alone may be a factor, as typed. A
    Markdown ``- `` is not read as a bullet: ``- 2 l θ̈₁ + … = 0`` on every line may as well be
    minus signs, and either reading could be wrong (``compare`` asks which is meant, where only
    the other is right)."""
    lines, at = [], 0
    for line in text.split("\n"):
        if line.strip():
            lines.append((at, line))
        at += len(line) + 1
    numbers = [_LIST_MARKER.match(line) for _, line in lines]
    if len(lines) > 1 and all(m and int(m[1]) == k for k, m in enumerate(numbers, start=1)):
        return {start: start + m.end() for (start, _), m in zip(lines, numbers, strict=True)}
    bullets = [_BULLET.match(line) for _, line in lines]
    marks = {m[1] for m in bullets if m}
    if all(bullets) and len(marks) == 1 and (len(lines) > 1 or marks <= set(_BULLETS)):
        return {start: start + m.end() for (start, _), m in zip(lines, bullets, strict=True)}
    return {}


# an equation's number in a line of them: 1) θ̈ = … 2) φ̈ = …, or (1) … (2) …; at the start, or after a space or mark
_INLINE_MARKER = re.compile(r"(?:^|(?<=[ \t,;]))[ \t]*(\(?)([1-9])\)[ \t]+")


def _inline_markers(text: str) -> dict[int, int]:
    """Where one line numbers its equations in order, ``1) … 2) …`` or ``(1) … (2) …``, each number
    before an equation: start → end of each number, to be read past as a new line. Otherwise none:
    ``a = b (2) c`` is 2bc, and ``(1) a = b (3) c = d`` skips a number."""
    found = list(_INLINE_MARKER.finditer(text))
    found = [m for m in found if m[1] == found[0][1]]  # one style: all with their opening bracket, or none
    if len(found) < 2 or found[0].start() != 0 or [int(m[2]) for m in found] != list(range(1, len(found) + 1)):
        return {}
    ends = [m.start() for m in found[1:]] + [len(text)]
    if not all("=" in text[m.end() : end] for m, end in zip(found, ends, strict=True)):
        return {}
    return {m.start(): m.end() for m in found}


# an equation's number at its line's end: a lone whole number in round brackets
_NUMBER_LABEL = re.compile(r"\([ \t]*[0-9]{1,3}[ \t]*\)")
_WIDE_SPACE = re.compile(r"\\q?quad$")


def _end_labels(text: str) -> dict[int, int]:
    """Where a line ends in its equation's number as a document sets it, ``θ̈ = −(g/l) sin θ \\qquad (3)``
    or ``L = T − V   (2)``: start → end of each, to be read past. A lone whole number in round brackets,
    last on its line with something before it, set apart by a TeX wide space, or by two spaces or a
    tab on a line with an ``=`` (``a + b  (2)`` may be 2(a + b), as typed)."""
    labels = {}
    for label in _NUMBER_LABEL.finditer(text):
        if not _closes_line(text, label.end()):
            continue
        spaced = text[: label.start()].rstrip(" \t")  # in two steps, not one regex: no backtracking over spaces
        space = text[len(spaced) : label.start()]
        wide = _WIDE_SPACE.search(spaced[-6:])
        start = len(spaced) - len(wide[0]) if wide else len(spaced)
        row_break = text.rfind("\\\\", 0, start)
        line_start = max(text.rfind("\n", 0, start) + 1, row_break + 2 if row_break >= 0 else 0)
        before = text[line_start:start]
        set_apart = wide or ((len(space) >= 2 or "\t" in space) and "=" in before)
        if set_apart and before.strip(" \t$"):
            labels[start] = label.end()
    return labels


class _Tokenizer:
    def __init__(self, text: str, *, latex: bool):
        self.text, self.latex = visible(text), latex
        self.pos = 0
        self.tokens: list[Token] = []
        if "\n" in text or text.lstrip()[:1] in _BULLETS:
            self.markers = _list_markers(self.text)
        else:
            self.markers = _inline_markers(self.text) if _INLINE_MARKER.match(self.text) else {}
        self.labels = _end_labels(self.text) if "(" in self.text else {}
        self.in_math = self.math_closed = False  # between $ … $, and whether a $ has closed math yet

    def run(self) -> list[Token]:
        text = self.text
        _refuse_other_scripts(text)  # before names are read: Greek ο would be read as omicron, cοs as c·ο·s
        while self.pos < len(text):
            c = text[self.pos]
            if self.pos in self.markers:  # 1. … ⏎ 2. …: a list's numbers, not the equations'
                if self.tokens and self.tokens[-1].kind != "sep":
                    self.tokens.append(Token("sep", "\n", self.pos, self.pos))  # 1) … 2) … on one line
                self.pos = self.markers.pop(self.pos)
            elif self.pos in self.labels:  # … \qquad (3): the equation's number in its document
                self.pos = self.labels.pop(self.pos)
            elif c == "$" and (self.latex or self.text.count("$") % 2 == 0):
                self._dollar()  # $6$ without a backslash in it is TeX's math too
            elif c in " \t\r\u00a0" or (self.latex and c in "&~"):
                self.pos += 1
            elif c in ".," and _closes_line(text, self.pos + 1):
                self.pos += 1  # the full stop or comma that ends a sentence: L = ½ m l² θ̇² − V.
            elif c == "\n" or (c == "." and self._ends_sentence()):
                self._emit("sep", "\n", 1)  # a new line, or a new sentence: … = 0. For β: … = 0
            elif c == "\\" and self.latex:
                self._command()
            elif c in _DIGITS or (c == "." and text[self.pos + 1 : self.pos + 2] in _DIGITS):
                self._number()
            elif c == "." and text[self.pos + 1 : self.pos + 2] in ("^", "*", "/") and self._ends_operand():
                self.pos += 1  # MATLAB's element-wise l.^2, m.*g, a./b: for numbers, the operations themselves
            elif c == ".":
                nxt = text[self.pos + 1 : self.pos + 2]
                if nxt.isalpha() or nxt == "_":
                    name = re.match(r"[\w]*", text[self.pos + 1 :]).group()
                    raise ParseFailure("attribute", self.pos, self.pos + 1 + len(name), name=name)
                raise ParseFailure("lone_point", self.pos, self.pos + 1)
            elif self._is_letter(c):
                self._name()
            elif c in _VULGAR_FRACTIONS:  # ½ m v²: a number, as 1/2 in brackets would be
                self._vulgar_fraction(c)
            elif c in SUPERSCRIPTS:
                self._superscript()
            elif c == "\u221a":  # √
                self._emit("sqrt", "√", 1)
            elif text.startswith("**", self.pos):
                self._emit("op", "^", 2)
            elif c in _IMPLIES or c in _ARROWS or (c in "<=-" and _TYPED_ARROW.match(text, self.pos)):
                self._arrow()
            elif text[self.pos : self.pos + 2] in _ASSIGNMENTS:
                raise ParseFailure("assignment", self.pos, self.pos + 2, op=text[self.pos : self.pos + 2])
            elif c == ":" and self._line_label():
                self.pos += 1  # EOM: …, θ₁: …: the line's label, read past with its colon
            elif c == "_" and self.latex and self._subscript_after_power():
                pass  # \dot\theta^2_1: TeX's θ̇₁², the subscript moved onto the name
            elif (c == "_" or c in _PRIMES) and self.latex and self._marks_after_brace():
                pass  # {\theta}_1, {\dot\theta}': MathType's braces around the name its marks belong to
            elif c in _OPERATORS:
                self._emit("op", _OPERATORS[c], 1)
            elif c in _PRIMES:
                raise ParseFailure("prime_position" if self._after_value() else "string", self.pos, self.pos + 1)
            elif c == "\u2202":  # ∂: only in a quantity's name, ∂L/∂φ̇ = …, which the grammar reads
                self._emit("partial", "∂", 1)
            elif c == "\u2211":  # ∑: only in a definition passed over, H = ∑ p q̇ − L = …, as \sum
                self._sum(self.pos, self.pos + 1)
            elif c in _NAMED_REFUSALS:
                raise ParseFailure(_NAMED_REFUSALS[c], self.pos, self.pos + 1)
            else:
                raise ParseFailure("bad_character", self.pos, self.pos + 1, char=c)
        self.tokens.append(Token("end", None, len(text), len(text)))
        return self.tokens

    # -- pieces ------------------------------------------------------------------

    def _emit(self, kind: str, value: object, length: int) -> None:
        self.tokens.append(Token(kind, value, self.pos, self.pos + length))
        self.pos += length

    def _arrow(self) -> None:
        """⇒ and its spellings as an ``implies`` token; → and its spellings as an ``arrow``,
        which :func:`tokenize` reads as ⇒ where it stands between two equations."""
        typed = _TYPED_ARROW.match(self.text, self.pos)
        spelled = typed[0] if typed else self.text[self.pos]
        certain = spelled in _IMPLIES or spelled.endswith("=>")
        self._emit("implies" if certain else "arrow", "⇒" if certain else "→", len(spelled))

    def _ends_operand(self) -> bool:
        """Whether the last token, right before this character, ends an operand: a number, a name
        or a closing bracket (MATLAB's ``l.^2``)."""
        last = self.tokens[-1] if self.tokens else None
        return last is not None and last.end == self.pos and (last.kind in ("num", "name") or last.is_op(")", "]"))

    def _after_value(self) -> bool:
        return bool(self.tokens) and (self.tokens[-1].kind in ("num", "sup") or self.tokens[-1].is_op(")", "]", "}"))

    def _line_label(self) -> bool:
        """Whether a colon ends the label of an equation, ``EOM:`` or ``θ₁:``, which is then dropped:
        one to three undotted names (the first perhaps followed by a number: ``eq 1:``) that start
        the answer, a line, or an item after ``;`` or ``,``. Before an expression, only a word of
        three letters or more that starts the answer (``Lagrangian: …``): ``m g:`` is no answer,
        and ``lambda x: x`` is code."""
        start = len(self.tokens)
        while start and not (self.tokens[start - 1].kind == "sep" or self.tokens[start - 1].is_op(";", ",")):
            start -= 1
        label = self.tokens[start:]
        if "=" not in self.text[self.pos + 1 :] and not (start == 0 and len(label) == 1 and _is_word(label[0])):
            return False
        if not 1 <= len(label) <= 3 or label[0].kind != "name":
            return False
        if not all(t.kind == "num" or (t.kind == "name" and not t.value.dots and not t.value.primes) for t in label):
            return False
        del self.tokens[start:]
        return True

    def _subscript_after_power(self) -> bool:
        """``x^2_1`` in TeX is x₁²: the subscript that follows a name's power belongs to the name."""
        tokens = self.tokens
        if len(tokens) >= 5 and tokens[-1].is_op("}"):
            opener = max((i for i, t in enumerate(tokens) if t.is_op("{")), default=0)
            power = opener - 1
        else:
            power = len(tokens) - 2
        if power < 1 or not tokens[power].is_op("^") or tokens[power - 1].kind != "name":
            return False
        if not all(t.kind == "num" or t.is_op("{", "}", "-") for t in tokens[power + 1 :]):
            return False
        name_token = tokens[power - 1]
        name = name_token.value
        if "_" in name.raw:
            return False
        raw = [name.raw]
        self._subscript(raw)
        tokens[power - 1] = Token(
            "name", Name("".join(raw), name.dots, name.primes, name.tex), name_token.start, name_token.end
        )
        return True

    def _marks_after_brace(self) -> bool:
        """``{\\theta}_1``, ``{\\dot\\theta}_1``, ``{\\theta}'``: a name alone in braces, then its subscript
        or prime, which TeX puts on the brace and so on the name. Not where the brace is an argument
        (``\\frac{a}{x}_1`` subscripts the fraction) or already has a subscript."""
        tokens = self.tokens
        if len(tokens) < 3 or not (tokens[-3].is_op("{") and tokens[-2].kind == "name" and tokens[-1].is_op("}")):
            return False
        before = tokens[-4] if len(tokens) >= 4 else None
        if before is not None and (before.kind in ("frac", "sqrt") or before.is_op("^", "}")):
            return False
        name: Name = tokens[-2].value
        if self.text[self.pos] == "_" and "_" in name.raw:
            return False
        opener = tokens[-3]
        del tokens[-3:]
        raw = [name.raw]
        if self.text[self.pos] == "_":
            self._subscript(raw)
        at = len(tokens)
        self._finish_name(opener.start, "".join(raw), name.dots)
        marked: Token = tokens[at]  # a power may follow it: {\theta}_1^{\prime 2}
        primes = marked.value.primes + name.primes
        tokens[at] = Token("name", Name(marked.value.raw, name.dots, primes, tex=True), opener.start, marked.end)
        return True

    @staticmethod
    def _is_letter(c: str) -> bool:
        if c.isascii():
            return c.isalpha()
        base = unicodedata.normalize("NFD", c)[0]
        return base in GREEK_BY_LETTER or (base.isascii() and base.isalpha())

    def _ends_sentence(self) -> bool:
        """Whether the full stop at ``pos`` ends a sentence: a space and a capital letter follow it, or
        a space and any letter after an equation (``… = 0. θ̈₂ = …``). ``a . b`` is no sentence."""
        follows = _SENTENCE_FOLLOWS.match(self.text, self.pos + 1)
        if follows is None:
            return False
        if self.text[follows.end()].isupper():
            return True
        since = next((i for i in range(len(self.tokens) - 1, -1, -1) if self.tokens[i].kind == "sep"), -1)
        return any(token.is_op("=") for token in self.tokens[since + 1 :])

    def _number(self) -> None:
        match = _NUMBER.match(self.text, self.pos)
        mantissa, exponent = match[1], match[2]
        digits = len(mantissa.replace(".", "").lstrip("0"))
        if digits > LIMITS.digits:
            raise ParseFailure("number_too_large", match.start(), match.end(), digits=digits, limit=LIMITS.digits)
        if exponent is not None and abs(int(exponent)) > LIMITS.exponent:
            raise ParseFailure("exponent_too_large", match.start(), match.end(), limit=LIMITS.exponent)
        if self.latex and match[0].isdecimal() and self._one_character_argument():
            # TeX reads ``x^23`` as x²·3 and ``\frac12`` as ½: an argument is one digit.
            for i, digit in enumerate(match[0]):
                self.tokens.append(Token("num", digit, self.pos + i, self.pos + i + 1))
        else:
            self.tokens.append(Token("num", match[0], match.start(), match.end()))
        self.pos = match.end()

    def _vulgar_fraction(self, c: str) -> None:
        """½ alone, or a mixed number: 2½ is 5/2, as a person reads it, not 2·½."""
        last = self.tokens[-1] if self.tokens else None
        if last is not None and last.kind == "num" and last.end == self.pos and last.value.isdecimal():
            mixed = int(last.value) + Fraction(_VULGAR_FRACTIONS[c])
            self.tokens[-1] = Token("num", f"{mixed.numerator}/{mixed.denominator}", last.start, self.pos + 1)
            self.pos += 1
        else:
            self._emit("num", _VULGAR_FRACTIONS[c], 1)

    def _superscript(self) -> None:
        start = self.pos
        while self.pos < len(self.text) and self.text[self.pos] in SUPERSCRIPTS:
            self.pos += 1
        digits = "".join(SUPERSCRIPTS[c] for c in self.text[start : self.pos])
        if not re.fullmatch(r"-?\d{1,3}", digits):
            raise ParseFailure("bad_character", start, self.pos, char=self.text[start : self.pos])
        self.tokens.append(Token("sup", int(digits), start, self.pos))

    def _name(self) -> None:
        """A name: letters, digits, underscores, Greek, subscripts; then dots and primes."""
        start, text = self.pos, self.text
        if self.latex:
            run = _LETTERS.match(text, self.pos)
            if run and text[start + 1 : start + 2].isalnum() and self._one_character_argument():
                # TeX reads \frac gl as g/l, \sqrt ab as √a·b and x^ab as xᵃ·b: an argument
                # without braces is one character. Reading gl as one name made \frac gl \sin\theta
                # (g/l)·sin θ into g·l/sin θ.
                self.pos += 1
                self._finish_name(start, text[start], 0)
                return
            if run and function_name(run[0]):  # ``sin x`` typed inside LaTeX still means sine
                self.pos = run.end()
                self.tokens.append(Token("func", function_name(run[0]), start, self.pos))
                return
        raw: list[str] = []
        dots = 0
        in_subscript = False  # inside a run of Unicode subscript digits, θ₁₂
        if not self.latex:  # the common case, plain ASCII, without a character at a time
            ascii_run = _ASCII_NAME.match(text, self.pos)
            if ascii_run and not text.startswith("{", ascii_run.end()):
                raw.append(ascii_run[0])
                self.pos = ascii_run.end()
        while self.pos < len(text):
            c = text[self.pos]
            if c == "_" and raw and (self.latex or text.startswith("{", self.pos + 1)):
                self._subscript(raw)
                break
            decomposed = c if c.isascii() else unicodedata.normalize("NFD", c)
            base, marks = decomposed[0], decomposed[1:]
            if base in GREEK_BY_LETTER:
                raw.append(GREEK_BY_LETTER[base])
            elif base.isascii() and (base.isalnum() or base == "_"):
                raw.append(base)
            elif c in _SUBSCRIPTS:
                raw.append(("" if in_subscript else "_") + _SUBSCRIPTS[c])
            elif c in _COMBINING_DOTS and raw:
                marks = c
            else:
                break
            in_subscript = c in _SUBSCRIPTS
            self.pos += 1
            if marks:
                if any(m not in _COMBINING_DOTS for m in marks):
                    raise ParseFailure("bad_character", self.pos - 1, self.pos, char=c)
                dots += sum(_COMBINING_DOTS[m] for m in marks)
                # a dot ends the name, but its subscript may follow: θ̇₁, θ̇_1, ṗ_θ, θ̇_{1}
                match = _SUBSCRIPT_AFTER_DOT.match(text, self.pos)
                if text.startswith("_{", self.pos):
                    self._subscript(raw)
                elif match:  # ṗ_θ: a letter's subscript too, Greek by name
                    sub = match[0].lstrip("_")
                    raw.append("_" + "".join(GREEK_BY_LETTER.get(d, SUBSCRIPT_DIGITS.get(d, d)) for d in sub))
                    self.pos = match.end()
                break
        self._finish_name(start, "".join(raw), dots)

    def _one_character_argument(self) -> bool:
        """Whether the next token is a TeX macro's argument without braces: the one after
        ``\\frac``, ``\\sqrt`` or ``^``, or the second of ``\\frac`` when the first was one token."""
        tokens = self.tokens
        if not tokens:
            return False
        last = tokens[-1]
        if last.kind == "frac" or (last.kind == "sqrt" and last.value == "\\sqrt") or last.is_op("^"):
            return True  # not after √: √gl is √(gl), whatever else the answer holds
        return len(tokens) >= 2 and tokens[-2].kind == "frac" and last.kind in ("name", "num")

    def _subscript(self, raw: list[str]) -> None:
        """``_1``, ``_{12}``, ``_\\theta``, ``_{cm}``: a subscript written the TeX way."""
        text = self.text
        self.pos += 1  # the underscore
        if text.startswith("{", self.pos):
            close = text.find("}", self.pos)
            if close == -1:
                raise ParseFailure("unclosed", self.pos, self.pos + 1, open="{", position=self.pos + 1)
            inner = text[self.pos + 1 : close]
            self.pos = close + 1
        elif text.startswith("\\", self.pos):
            match = _COMMAND_NAME.match(text, self.pos)
            inner = match[0] if match else text[self.pos : self.pos + 2]
            self.pos += len(inner)
        else:
            inner = text[self.pos : self.pos + 1]
            self.pos += 1
        sub = re.sub(r"\\([A-Za-z]+)\s*", lambda m: _LATEX_NAMES.get(m[1], "\\"), inner).replace(" ", "")
        sub = "".join(GREEK_BY_LETTER.get(c, SUBSCRIPT_DIGITS.get(c, c)) for c in sub)
        if not re.fullmatch(r"[A-Za-z0-9]+", sub):
            raise ParseFailure("bad_name", self.pos - len(inner) - 1, self.pos, name="_" + inner)
        raw.append("_" + sub)

    def _compound_unit(self, unit: re.Match) -> None:
        """``\\mathrm{rad/s}``, ``\\text{m/s^2}``: the unit in its braces, its words whole names (in
        TeX's roman type, rad is one word, not r·a·d); the checker decides they are units."""
        for piece in _UNIT_PIECE.finditer(self.text, unit.start(), unit.end()):
            word, number, operator = piece.group("word", "number", "op")
            if word and len(word) > LIMITS.name:
                raise ParseFailure("name_too_long", piece.start(), piece.end(), name=word[:20] + "…", limit=LIMITS.name)
            if word:
                token = Token("name", Name(word, unit=True), piece.start(), piece.end())
            elif number:
                token = Token("num", number, piece.start(), piece.end())
            else:  # · or \cdot multiplies
                token = Token("op", "*" if operator in ("·", "\\cdot") else operator, piece.start(), piece.end())
            self.tokens.append(token)
        self.pos = unit.end()

    def _finish_name(self, start: int, raw: str, dots: int) -> None:
        end_of_name = self.pos
        primes = 0
        while self.pos < len(self.text) and self.text[self.pos] in _PRIMES:
            primes += _PRIMES[self.text[self.pos]]
            self.pos += 1
        exponent = self._tex_primes() if self.latex and not primes else None
        if exponent is not None:
            primes, exponent = exponent
        subscript = _UNICODE_SUBSCRIPT.match(self.text, self.pos) if primes else None
        if subscript and not _ENDS_IN_SUBSCRIPT.search(raw):  # θ'₁ is θ₁', and lθ'₁ is lθ₁'
            raw += "_" + "".join(SUBSCRIPT_DIGITS[c] for c in subscript[0])
            self.pos = subscript.end()
        if len(raw) > LIMITS.name:
            raise ParseFailure("name_too_long", start, end_of_name, name=raw[:20] + "…", limit=LIMITS.name)
        if "__" in raw or raw.endswith("_") or raw.startswith("_"):
            raise ParseFailure("bad_name", start, end_of_name, name=self.text[start:end_of_name])
        function = None if dots or primes else function_name(raw) or (None if self.latex else _CALLABLE.get(raw))
        if function:
            self.tokens.append(Token("func", function, start, self.pos))
        elif not (dots or primes) and self._after_difference(start):
            delta = self.tokens.pop()  # \Delta\theta as Δθ: one name, whose argument of \cos it all is
            self.tokens.append(Token("name", Name(delta.value.raw + raw, tex=True), delta.start, self.pos))
        else:
            self.tokens.append(Token("name", Name(raw, dots, primes, tex=self.latex), start, self.pos))
        if exponent:  # \theta^{\prime 2}: θ′ squared, the rest of the brace its exponent
            caret, brace = exponent
            self.tokens += [Token("op", "^", caret, caret + 1), Token("op", "{", brace, brace + 1)]

    def _after_difference(self, start: int) -> bool:
        """Whether the name starting at ``start`` follows TeX's ``\\Delta`` or ``\\delta`` (no marks, only
        spaces between): ``\\Delta\\theta`` is then one name, as ``Δθ`` typed is. So ``\\cos\\Delta\\theta``
        is cos(Δθ), as ``cos Δθ`` is, not cos(Δ)·θ; and Δθ, where the answer defines it (``\\Delta\\theta =
        \\theta_1 - \\theta_2``), is read as that name; elsewhere, as TeX reads it, Δ·θ."""
        last = self.tokens[-1] if self.tokens and self.latex else None
        if last is None or last.kind != "name" or last.value.raw not in _DIFFERENCES:
            return False
        return not (last.value.dots or last.value.primes or last.value.unit or self.text[last.end : start].strip())

    def _tex_primes(self) -> tuple[int, tuple[int, int] | None] | None:
        """TeX's primes as a superscript, as its ' is typeset: ``\\theta^\\prime``, ``\\theta^{\\prime\\prime}``,
        or ``\\theta^{\\prime 2}``: the count, and where a power that follows in the same brace
        opens (its ``^`` and ``{``), read past; None when there are none."""
        single = _TEX_PRIME.match(self.text, self.pos)
        if single:
            self.pos = single.end()
            return 1, None
        braced = _TEX_PRIMES.match(self.text, self.pos)
        if not braced:
            return None
        self.pos = braced.end()
        count = braced[2].count("\\prime")
        if self.text.startswith("}", self.pos):
            self.pos += 1
            return count, None
        return count, (braced.start(), braced.start(1))

    # -- LaTeX -------------------------------------------------------------------

    def _command(self) -> None:
        text, start = self.text, self.pos
        match = _COMMAND.match(text, self.pos)
        command = match[1]
        self.pos = match.end()
        if command in ("", ",", ";", ":", "!", " ") or (command in ("[", "(") and _opens_line(text, start)):
            return  # spaces, and \[ or \( that opens the math, as $ does
        if command in ("]", ")") and _closes_line(text, self.pos):
            return
        if command == "\\" or command == "newline":
            if command == "\\" and (spacing := _ROW_SPACING.match(text, self.pos)):
                self.pos = spacing.end()  # \\[6pt]: the space below the row, no factor of the next
            self.tokens.append(Token("sep", "\n", start, self.pos))
        elif command in ("quad", "qquad"):
            self.tokens.append(Token("gap", command, start, self.pos))
        elif command in ("{", "}"):
            self.tokens.append(Token("op", command, start, self.pos))
        elif command in _LATEX_IGNORED:
            if command in ("left", "right") and text.startswith(".", self.pos):
                self.pos += 1
            elif command == "left" and text.startswith("\\{", self.pos) and self._closed_by_nothing():
                self.pos += 2  # \left\{ … \right.: the brace that gathers a system, not a bracket
        elif command in ("begin", "end"):
            env = _ENVIRONMENT.match(text, self.pos)
            if not env or env[1] not in _LATEX_ENVIRONMENTS:
                raise ParseFailure("unknown_command", start, self.pos, name=command)
            self.pos = env.end()
            columns = _ARRAY_COLUMNS.match(text, self.pos) if env[1] == "array" and command == "begin" else None
            if columns:
                self.pos = columns.end()
            if command == "end":  # \end{equation} \begin{equation}: one equation, then another
                self.tokens.append(Token("gap", "end", start, self.pos))
        elif command in _LATEX_OPERATORS:
            self.tokens.append(Token("op", _LATEX_OPERATORS[command], start, self.pos))
        elif command in ("frac", "dfrac", "tfrac"):
            self.tokens.append(Token("frac", "frac", start, self.pos))
        elif command == "over":  # {1 \over 2}: plain TeX's fraction of its group, which the grammar reads
            self.tokens.append(Token("over", "\\over", start, self.pos))
        elif command == "sqrt":
            self.tokens.append(Token("sqrt", "\\sqrt", start, self.pos))
        elif command == "partial":
            self.tokens.append(Token("partial", "∂", start, self.pos))
        elif command == "sum":
            self._sum(start, self.pos)
        elif command in _LATEX_IMPLIES:
            self.tokens.append(Token("implies", "⇒", start, self.pos))
        elif command in _LATEX_ARROWS:
            self.tokens.append(Token("arrow", "→", start, self.pos))
        elif command in _LATEX_FUNCTIONS:
            self.tokens.append(Token("func", _LATEX_FUNCTIONS[command], start, self.pos))
        elif command in _LATEX_NAMES:
            raw = [_LATEX_NAMES[command]]
            self._spaces_before_marks()
            if text.startswith("_", self.pos):
                self._subscript(raw)
            self._finish_name(start, "".join(raw), 0)
        elif command in ("dot", "ddot"):
            self._latex_dot(start, command)
        elif command == "overset" and (dots := _OVERSET_DOTS.match(text, self.pos)):
            self.pos = dots.end()
            self._latex_dot(start, "ddot" if dots[1].count(".") + dots[1].count("\\cdot") == 2 else "dot")
        elif command in ("label", "tag", "tag*") and (annotation := _LATEX_ANNOTATIONS.match(text, self.pos)):
            self.pos = annotation.end()
        elif command == "text" and (punctuation := _TEXT_PUNCTUATION.match(text, self.pos)):
            self.pos = punctuation.end()
        elif (
            command in ("operatorname", "text")
            and (word := _OPERATOR_NAME.match(text, self.pos))
            and (word[1] in FUNCTION_NAMES or (command == "text" and word[1] in JOINING_WORDS | IMPLYING_WORDS))
        ):
            self.pos = word.end()
            if word[1] in FUNCTION_NAMES:  # \operatorname{cos} or \text{cos}, as \cos
                self.tokens.append(Token("func", FUNCTION_NAMES[word[1]], start, self.pos))
            else:  # eq₁ \text{ where } eq₂, eq₁ \text{ so } eq₂: the word between two equations
                self.tokens.append(Token("name", Name(word[1]), start, self.pos))
        elif command in _LATEX_FONTS and (braced := _BRACED_LETTERS.match(text, self.pos)):
            # \mathcal{F}, \mathrm{d}: the letters, in another typeface
            self.pos = braced.end()
            raw = [braced[1] or braced[2]]
            if braced[1] and text.startswith("_", self.pos):  # \mathbf{x}_1
                self._subscript(raw)
            self._finish_name(start, "".join(raw), 0)
        elif command in _BOLD:
            pass  # \boldsymbol{\theta}, \bm\theta: what follows is read as it would be in plain type
        elif command in ("text", "textrm", "mbox") and (word := _CONSTANT_WORD.match(text, self.pos)):
            self.pos = word.end()
            self._finish_name(start, word[1], 0)
        elif command in ("text", "textrm", "mbox") and (word := _WORD_BEFORE_EQUALS.match(text, self.pos)):
            self.pos = word.end()  # \text{L} = …, as \mathrm{L} = …: the name of what the answer writes out
            self._finish_name(start, word[1], 0)
            if self.tokens[-1].kind == "name":  # a word in text is one name: \text{KE} is no K·E
                self.tokens[-1] = Token("name", Name(word[1]), start, self.pos)
        elif command in _TEXT_COMMANDS and (unit := _COMPOUND_UNIT.match(text, self.pos)):
            self._compound_unit(unit)
        elif command in _TEXT_COMMANDS and (words := _TEXT_WORDS.match(text, self.pos)):
            # \,\mathrm{rad/s}, \text{ for small angles}: more than the mathematics
            raise ParseFailure("latex_words", start, words.end(), words=text[start : words.end()])
        else:
            raise ParseFailure("unknown_command", start, self.pos, name=command)

    def _sum(self, start: int, end: int) -> None:
        """``\\sum_i`` or ``∑``, with its limits: a ``sum`` token, which the grammar reads only in a side it
        passes over, the definition in ``H = \\sum_j p_j \\dot q_j - L = …``."""
        self.pos = _SUM_LIMITS.match(self.text, end).end()
        self.tokens.append(Token("sum", self.text[start:end], start, end))

    def _dollar(self) -> None:
        """``$`` or ``$$`` around math is read past; one that opens the math again after it was
        closed, ``$$eq₁$$ $$eq₂$$``, starts another equation, as a new line would."""
        width = 2 if self.text.startswith("$$", self.pos) else 1
        ends_value = self._after_value() or (bool(self.tokens) and self.tokens[-1].kind == "name")
        if not self.in_math and self.math_closed and ends_value:
            self.tokens.append(Token("sep", "\n", self.pos, self.pos + width))
        self.math_closed |= self.in_math
        self.in_math = not self.in_math
        self.pos += width

    def _closed_by_nothing(self) -> bool:
        """Whether the \\left just read is matched by \\right. (no delimiter)."""
        depth = 0
        for match in _LEFT_RIGHT.finditer(self.text, self.pos):
            depth += 1 if match[1] == "left" else -1
            if depth < 0:
                return match[2] == "."
        return False

    def _latex_dot(self, start: int, command: str) -> None:
        """``\\dot{\\theta}_1``, ``\\dot\\theta_1``, ``\\dot{\\theta_1}``, ``\\ddot x``: one name, dotted."""
        self._skip_spaces()
        braced = self.text.startswith("{", self.pos)
        if braced:
            self.pos += 1
            self._skip_spaces()
        before = len(self.tokens)
        c = self.text[self.pos : self.pos + 1]
        if c == "\\":
            self._command()
        elif c and self._is_letter(c):
            self._name()
        if len(self.tokens) != before + 1 or self.tokens[-1].kind != "name":
            raise ParseFailure("dot_usage", start, max(self.pos, start + 1), name=command)
        name = self.tokens.pop().value
        if braced:
            self._skip_spaces()
            if not self.text.startswith("}", self.pos):
                raise ParseFailure("dot_usage", start, self.pos + 1, name=command)
            self.pos += 1
        raw = [name.raw]
        if self.text.startswith("_", self.pos) and "_" not in name.raw:
            self._subscript(raw)
        dots = name.dots + (2 if command == "ddot" else 1)
        self._finish_name(start, "".join(raw), dots)
        if name.primes:
            self.tokens[-1] = Token("name", Name("".join(raw), dots, name.primes, tex=True), start, self.pos)

    def _spaces_before_marks(self) -> None:
        """Read past the spaces after a command's name where its subscript or prime follows: TeX
        ignores them, and MathType writes ``\\theta _1``, ``\\theta '`` and ``\\theta ^{\\prime}``."""
        after = self.pos
        while self.text.startswith(" ", after):
            after += 1
        mark = self.text[after : after + 1]
        if mark == "_" or mark in _PRIMES or _TEX_PRIME.match(self.text, after) or _TEX_PRIMES.match(self.text, after):
            self.pos = after

    def _skip_spaces(self) -> None:
        while self.text.startswith(" ", self.pos):
            self.pos += 1


_CLOSERS = {"(": ")", "[": "]", "{": "}"}
# A new line after one of these, or before one of the next, continues the line above.
_CONTINUES_AFTER = {"+", "-", "*", "/", "^", "=", ",", "(", "[", "{"}
_CONTINUES_BEFORE = {"+", "*", "/", "^", "=", ")", "]", "}"}


def _check_brackets(tokens: list[Token]) -> None:
    """Balanced brackets and bounded depth, checked before any parsing.

    New lines inside brackets, or next to an operator, are spaces and are dropped
    here; the others separate equations. A line that begins with ``-`` continues an
    expression, but starts a new equation in a system.
    """
    stack: list[Token] = []
    kept: list[Token] = []
    for index, token in enumerate(tokens):
        if token.kind == "op" and token.value in _CLOSERS:
            stack.append(token)
            if len(stack) > LIMITS.depth:
                raise ParseFailure("too_deep", token.start, token.end, limit=LIMITS.depth)
        elif token.kind == "op" and token.value in _CLOSERS.values():
            if not stack:
                raise ParseFailure("unopened", token.start, token.end, close=token.value, position=token.start + 1)
            opener = stack.pop()
            if _CLOSERS[opener.value] != token.value:
                raise ParseFailure(
                    "mismatched", token.start, token.end, open=opener.value, open_position=opener.start + 1,
                    close=token.value, position=token.start + 1,
                )  # fmt: skip
        elif token.kind == "sep":
            following = tokens[index + 1]
            if (
                stack
                or (kept and kept[-1].kind == "op" and kept[-1].value in _CONTINUES_AFTER)
                or (following.kind == "op" and following.value in _CONTINUES_BEFORE)
                # looked for only here, where a line starts with a minus: most answers are one line
                or (following.is_op("-") and not any(other.is_op("=") for other in tokens))
            ):
                continue
        kept.append(token)
    if stack:
        opener = stack[-1]
        raise ParseFailure("unclosed", opener.start, opener.end, open=opener.value, position=opener.start + 1)
    tokens[:] = kept
