"""What a student is told when an answer cannot be read: every word in one place.

Contents:
    MESSAGES     refusal code → the sentence a student reads
    Refusal      the parser's failure value: code, message, where
    ParseFailure the internal exception that carries a Refusal out of the parser
    listed(items)  ``a``, ``a and b``, ``a, b and c``: names in a sentence, here and in the judge's

Each message says what is wrong in the student's terms and, where there is a
spot to point at, ``Refusal.pointer`` draws a caret under it. Places are counted as
the student sees them: the dot of θ̇ (a combining mark) takes no column of its own,
a full-width character two.
"""

from __future__ import annotations

import unicodedata
from dataclasses import dataclass

__all__ = ["MESSAGES", "ParseFailure", "Refusal", "listed", "refusal"]

MESSAGES: dict[str, str] = {
    "empty": "Your answer is empty.",
    "too_long": "Your answer is {length} characters long; the limit is {limit}.",
    "bad_character": "`{char}` is not something an answer can contain.",
    "lookalike": "`{char}` looks like the letter `{latin}` but is the {name}: type it again as a plain `{latin}`.",
    "arrow": (
        "`{arrow}` is read only between two equations, as a step of a derivation (`a = b {arrow} c = d`"
        " is read as c = d); a limit such as θ → 0 cannot be part of an answer."
    ),
    "partial": (
        "`∂` is read only in the name of what an answer writes out, before `=`, as in p = ∂L/∂φ̇ = …"
        " or d/dt(∂L/∂θ̇) − ∂L/∂θ = … = 0"
    ),
    "euler_lagrange_general": (
        "This is Lagrange's equation in general form, which holds for every system: work it out for this one,"
        " with its {functions} put in, and give the equation of motion it comes to."
    ),
    "euler_lagrange_other": (
        "This is not Lagrange's equation, d/dt(∂L/∂q̇) − ∂L/∂q = 0, nor an equation of motion of this system:"
        " give the equation of motion, worked out for this system."
    ),
    "sum": (
        "`{name}` is read only in a definition on the way to the answer, as in H = \\sum_j p_j \\dot q_j - L = …,"
        " whose last side is graded; anywhere else, write the sum out term by term."
    ),
    "string": "Quotes are not allowed: an answer is mathematics, not text.",
    "prime_position": "A prime (') marks a time derivative and must follow a coordinate's name, as in theta'.",
    "comment": "`#` starts a comment in code; it cannot be part of an answer.",
    "attribute": "`.{name}` looks like attribute access in code; it cannot be part of an answer.",
    "lone_point": "A decimal point needs digits after it, as in 0.5.",
    "assignment": "`{op}` is an assignment or a test in code; write an equation with a single `=`.",
    "unclosed": "Unbalanced bracket: the `{open}` at position {position} is never closed.",
    "unopened": "Unbalanced bracket: the `{close}` at position {position} has no matching opening bracket.",
    "mismatched": "The `{open}` at position {open_position} is closed by `{close}` at position {position}.",
    "too_deep": "Your answer is nested too deeply (more than {limit} levels).",
    "powers_too_deep": "Exponents are nested too deeply here: more than {limit} powers, each in the exponent of the last.",
    "exponent_too_large": "This exponent is too large to handle (the limit is {limit}).",
    "number_too_large": "This number is too large to handle ({digits} digits; the limit is {limit}).",
    "value_too_large": "This value is too large to handle.",
    "diff_too_large": "This derivative is too large to work out here; differentiate by hand, or write it with θ̇ and θ̈.",
    "missing_arguments": "`{name}` needs its arguments in braces, as in \\frac{{a}}{{b}} or \\sqrt{{x}}.",
    "over_side": "`\\over` divides what stands before it in its braces by what stands after it, as in {{m g l \\over 2}}: here one of them is missing.",
    "over_twice": "Two `\\over` in one pair of braces can be read more than one way: give each fraction braces of its own, as in {{a \\over b}} + {{c \\over d}}, or write \\frac{{a}}{{b}}.",
    "name_too_long": "`{name}` is too long for a name (the limit is {limit} characters).",
    "bad_name": "`{name}` is not a name an answer can use: names are letters and digits, joined by single underscores.",
    "unknown_function": "`{name}` is not a function this grader knows. Known functions: {known}.",
    "unknown_command": "`\\{name}` is not a LaTeX command this grader knows.",
    "latex_words": "`{words}` is text, not mathematics: leave units and words out of the answer.",
    "unit_is_a_name": "`{name}` in this unit is also a name of the problem's: leave the unit out of the answer.",
    "function_inverse": "`{name}^-1` is ambiguous: write a{name}(x) for the inverse function or 1/{name}(x) for the reciprocal.",
    "function_power": "A power written on a function name must be a small whole number, as in sin^2(θ).",
    "function_argument_power": "A power after `{name} {argument}` can be read two ways: write {name}^2 {argument} for a"
    " power of {name} {argument}, or {name}({argument}^2) to take the power inside.",
    "missing_argument": "`{name}` needs an argument, as in {name}(θ).",
    "derivative_of_constant": "`{name}` is written as a time derivative, but {base} is not a coordinate of this problem ({coords}).",
    "derivative_order": "Derivatives of order higher than 3 are not accepted here.",
    "leibniz": "`dt` here is not part of a derivative this grader can read: write dθ/dt, d/dt(…), θ̇ or diff(θ, t).",
    "diff_usage": "Write a time derivative as diff(θ, t) or diff(θ, t, 2).",
    "dot_usage": "\\{name} takes one coordinate, as in \\{name}{{\\theta}}.",
    "ambiguous_name": "`{name}` could be read as {first} or as {second}; put a space or `*` between the symbols.",
    "numbers_adjacent": "Two numbers stand side by side here; put an operator between them.",
    "unexpected": "`{token}` was not expected here.",
    "missing_operand": "Something is missing before `{token}`.",
    "unexpected_end": "Your answer ends too early: something is missing after `{token}`.",
    "too_many_equals": "An equation has one `=`; this one has more.",
    "comma": "A comma is not understood here. Write decimals with a point (0.5); list equations as [eq1, eq2] or on separate lines.",
    "not_an_equation": "In a list of equations every item needs an `=`; item {index} has none.",
    "division_by_zero": "This divides by zero.",
    "undefined_value": "Your answer contains a value that is undefined (such as a division by zero or log(0)).",
    "unreadable": "This answer could not be read as mathematics.",
}


_WINDOW = 60  # characters of a long line shown around the spot


@dataclass(frozen=True)
class Refusal:
    """An answer the parser would not accept, and why.

    Attributes:
        code: a stable key into :data:`MESSAGES` (``"unclosed"``, ``"unknown_function"``…).
        message: the sentence shown to the student.
        text: the answer as it was typed.
        start: 0-based offset of the offending spot in ``text``, or ``None``.
        end: offset just past it.
    """

    code: str
    message: str
    text: str
    start: int | None = None
    end: int | None = None

    ok = False  # a Refusal is falsy in the sense that matters: no answer to grade

    @property
    def pointer(self) -> str:
        """The offending line of the answer with a caret under the spot (``""`` when none)."""
        if self.start is None:
            return ""
        line_start = self.text.rfind("\n", 0, self.start) + 1
        line_end = self.text.find("\n", self.start)
        line_end = len(self.text) if line_end == -1 else line_end
        # A long line is shown as a window around the spot, so the caret stays on screen.
        window_start = max(line_start, self.start - _WINDOW // 2)
        window_end = min(line_end, window_start + _WINDOW)
        prefix = "…" if window_start > line_start else ""
        suffix = "…" if window_end < line_end else ""
        width = max(1, _columns(self.text[self.start : min(self.end or self.start + 1, window_end)]))
        column = len(prefix) + _columns(self.text[window_start : self.start])
        return f"{prefix}{self.text[window_start:window_end]}{suffix}\n{' ' * column}{'^' * width}"

    def __str__(self) -> str:
        return f"{self.message}\n{self.pointer}" if self.pointer else self.message


def listed(items: list[str]) -> str:
    """Items as a sentence lists them.

    >>> listed(["`L`"]), listed(["a", "b"]), listed(["a", "b", "c"])
    ('`L`', 'a and b', 'a, b and c')
    """
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]


def refusal(code: str, text: str, start: int | None = None, end: int | None = None, **details) -> Refusal:
    """Build a :class:`Refusal`, with the message filled in from :data:`MESSAGES`."""
    shown = {key: _printable(value) if isinstance(value, str) else value for key, value in details.items()}
    return Refusal(code, MESSAGES[code].format(**shown), text, start, end)


def _columns(text: str) -> int:
    """The columns ``text`` takes on a screen: none for a combining mark (θ̇'s dot) or an
    invisible character, two for a full-width or wide one."""
    return sum(_column(c) for c in text)


def _column(c: str) -> int:
    if _takes_no_place(c):
        return 0
    return 2 if unicodedata.east_asian_width(c) in ("W", "F") else 1


def _takes_no_place(c: str) -> bool:
    """A mark on the character before it (θ̇'s dot) or an invisible one (a zero-width space)."""
    return bool(unicodedata.combining(c)) or unicodedata.category(c) in ("Mn", "Me", "Cf")


def _printable(text: str) -> str:
    """Control and formatting characters (ESC, U+202E…) named, not echoed into a terminal or page."""
    return "".join(c if c.isprintable() else f"U+{ord(c):04X}" for c in text)


class ParseFailure(Exception):
    """Raised inside the parser to abandon a parse; never escapes ``parse_answer``."""

    def __init__(self, code: str, start: int | None = None, end: int | None = None, **details):
        super().__init__(code)
        self.code, self.start, self.end, self.details = code, start, end, details

    def to_refusal(self, text: str) -> Refusal:
        # "at position N" counts characters as they are seen: θ̇ is one, not θ and a dot
        details = {
            key: _seen_position(text, value) if key.endswith("position") else value
            for key, value in self.details.items()
        }
        return refusal(self.code, text, self.start, self.end, **details)


def _seen_position(text: str, position: int) -> int:
    """A 1-based position in ``text``, in characters as seen rather than code points."""
    return 1 + sum(1 for c in text[: position - 1] if not _takes_no_place(c))
