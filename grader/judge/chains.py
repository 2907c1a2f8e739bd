"""How an answer's text is cut into lines, and into the sides of a chain it writes, before it is read.

Contents:
    answer_lines(text)     the lines of an answer (new lines, ``;``), where it has two to six
    lines_as_chain(text)   lines that each give one name a value, joined as the one chain they are
    chain_sides(text)      ``L = … = …`` on one line, as ``L = side`` for each side
    partials_read(text)    a chain whose steps write out a partial derivative (``H = θ̇ ∂L/∂θ̇ − L = …``)
    without_dashes(text)   lines that each start with a dash, without it
    ONE_NAME               a name alone: no product, no call

Text in, text out: what each piece means is for ``grader.judge.compare`` to judge.
"""

from __future__ import annotations

import re
from collections.abc import Callable

from grader.parse import LIMITS, parse_answer
from grader.parse.names import canonical_name, is_arbitrary_constant, split_quotient, unicode_name

__all__ = [
    "ONE_NAME",
    "answer_lines",
    "chain_sides",
    "lines_as_chain",
    "partials_read",
    "without_dashes",
]

_MAX_LINES = 6


def lines_as_chain(text: str) -> tuple[str, int, str] | None:
    """``H = Σ p q̇ − L`` then ``H = ½ m l² θ̇² − …``, or ``p_φ = ∂L/∂φ̇`` then ``p_φ = m l² sin²θ φ̇``:
    lines that each give one name a value, read as the one chain ``H = Σ p q̇ − L = ½ m l² θ̇² − …``
    that they are (the parser reads a chain's definitions on the way as such, and grades its last
    side). In TeX too (``p_\\phi = \\frac{\\partial L}{\\partial \\dot\\phi} \\\\ p_\\phi = …``, each line in
    its ``$…$`` or not); and where other lines follow or come before, as a system's equations do,
    each run of lines that name one quantity is one chain, the others kept as they are. Returns the
    answer so read, the count of lines of the first such run and its name as a student reads it;
    None where no two lines in a row name one quantity."""
    lines = _chain_lines(text)
    if lines is None:
        return None
    runs: list[list[tuple[str | None, str, str]]] = []  # of (name, label, side): lines in a row that name one
    for line in lines:
        name, label, side = _labelled_line(line)
        if runs and name is not None and runs[-1][-1][0] == name:
            runs[-1].append((name, label, side))
        else:
            runs.append([(name, label, side) if name is not None else (None, "", line.strip())])
    chains = [run for run in runs if len(run) > 1]
    if not chains:
        return None
    joined = [f"{run[0][1]} = " + " = ".join(side for *_, side in run) if run[0][0] else run[0][2] for run in runs]
    return "\n".join(joined), len(chains[0]), unicode_name(chains[0][0][0])


# TeX's row break, \\ (with the space below it, \\[6pt]), which ends a line as a new line does
_ROW_BREAK = re.compile(r"\\\\(?:\s*\[[^\]\n]{0,12}\])?")
# the math's delimiters around a line: $…$, $$…$$, \[…\], \(…\)
_OPENS_MATH = re.compile(r"^\s*(?:\$\$?|\\\[|\\\()")
_CLOSES_MATH = re.compile(r"(?:\$\$?|\\\]|\\\))\s*$")


def _chain_lines(text: str) -> list[str] | None:
    """The lines of ``text`` as :func:`answer_lines` finds them, TeX's ``\\\\`` ending one too, each without the
    math's delimiters around it; None where there are not two to six."""
    if not isinstance(text, str) or len(text) > LIMITS.length:
        return None
    lines = answer_lines(_ROW_BREAK.sub("\n", text))
    return [_CLOSES_MATH.sub("", _OPENS_MATH.sub("", line)) for line in lines] if lines else None


def _labelled_line(line: str) -> tuple[str | None, str, str]:
    """A line that gives a name a value, ``p_\\phi = …``: (the name, its label as typed, what follows
    its first ``=``); (None, "", "") for any other line. The label is read alone, as a name (H, ``p_φ``,
    TeX's ``p_{\\phi}``): ``2L``, ``θ̈`` or ``L(θ)`` name no quantity a chain gives values."""
    label, *sides = _cut(line, lambda i, depth: depth == 0 and _EQUALS.match(line, i) is not None)
    read = parse_answer(label) if sides and label.strip() and len(label) <= _LABEL_LENGTH else None
    if read is None or not read.ok or read.kind != "expression" or not read.value.is_Symbol:
        return None, "", ""
    return read.value.name, label.strip(), "=".join(sides).strip().rstrip(",")


_LABEL_LENGTH = 40  # characters of a label: a name, with its subscript in TeX


def answer_lines(text: str) -> list[str] | None:
    """The lines of ``text`` (split at new lines and at ``;`` outside brackets), where it has two
    to six; else None."""
    if not isinstance(text, str) or len(text) > LIMITS.length:
        return None
    cut = _cut(text, lambda i, depth: text[i] == "\n" or (text[i] == ";" and depth == 0))
    lines = [line for line in cut if line.strip()]
    return lines if 2 <= len(lines) <= _MAX_LINES else None


def _cut(text: str, at: Callable[[int, int], bool]) -> list[str]:
    """``text`` cut at (and without) each one-character separator ``at(position, depth)`` accepts,
    where depth counts the brackets open there."""
    pieces, depth, start = [], 0, 0
    for i, character in enumerate(text):
        depth += (character in "([{") - (character in ")]}")
        if at(i, depth):
            pieces.append(text[start:i])
            start = i + 1
    return [*pieces, text[start:]]


# `=` that is not part of =>, ==, <=, >= or :=
_EQUALS = re.compile(r"(?<![=<>:!])=(?![=>])")


# a chain's label: a name (L, p_φ, L(θ, θ̇)), or a momentum by its definition (∂L/∂φ̇)
_SIDES_LABEL = re.compile(r"\s*(?:[^\W\d][\w\s(),'̇]*|∂\s*[A-Za-z]\w*\s*/\s*∂\s*[^\W\d]\w*̇\s*)")


ONE_NAME = re.compile(r"[^\W\d]\w*")  # L_z, p_z, E: a name alone, no product (m l²) nor call (L(θ))


def chain_sides(text: str) -> list[str] | None:
    """``L = ½ m (l θ̇)² + … = ½ m l² θ̇² + …`` on one line: ``L = `` with each side after it, where
    the first is a name (a label) and there are two to six sides after it; else None."""
    if not isinstance(text, str) or len(text) > LIMITS.length or "\n" in text.strip():
        return None
    label, *sides = _cut(text, lambda i, depth: depth == 0 and _EQUALS.match(text, i) is not None)
    if not _SIDES_LABEL.fullmatch(label) or not 2 <= len(sides) <= _MAX_LINES:
        return None
    sides = [side.strip() for side in sides]
    if not all(sides):
        return None
    lines = [f"{label.strip()} = {side}" for side in sides]
    if is_arbitrary_constant(canonical_name(sides[-1])):  # ẍ = … = const: the value before it is said constant
        lines[-1] = f"{sides[-2]} = {sides[-1]}"
    elif ONE_NAME.fullmatch(sides[-1]) and not ONE_NAME.fullmatch(sides[-2]):
        lines[-1] = f"{sides[-1]} = {sides[-2]}"  # p_φ = m l² sin²θ φ̇ = L_z: the value named again, not a value
    return lines


# a line that starts with a dash and a space: a Markdown list's bullet, or a minus sign?
_DASHED = re.compile(r"[ \t]*[-–][ \t]+")


def without_dashes(text: str) -> str | None:
    """``text`` without the ``- `` that starts each of its lines, where it has two lines or more
    and each starts so; else None. As typed, each dash is a minus sign: where that reading is
    wrong and this one right, which was meant is for the student to say."""
    if not isinstance(text, str) or len(text) > LIMITS.length:
        return None
    lines = [line for line in text.split("\n") if line.strip()]
    if len(lines) < 2 or not all(_DASHED.match(line) for line in lines):
        return None
    return "\n".join(line[_DASHED.match(line).end() :] for line in lines)


def partials_read(text: str) -> tuple[str, list[str], str, tuple[tuple[str, str], ...]] | None:
    """``H = θ̇ ∂L/∂θ̇ − L = …``, ``p_φ = ∂/∂φ̇(½ m l² sin²θ φ̇²) = …``, ``Q_θ = F·∂r/∂θ = …``: a chain on
    one line whose steps write out a partial derivative, which the parser reads only as a chain's
    label. ∂L/∂q̇ among a step's factors is the momentum p_q it defines, so that ``H = q̇ ∂L/∂q̇ − L``
    is judged as the definition ``H = p_q q̇ − L`` is; a step with any other ∂ is left out. Returns the
    chain so written, which grades its last side, the steps left out, as typed, the chain's label, and
    each momentum's name as put in with the quotient it stands for (to show the student their own);
    None where ``text`` is no such chain, or its last side has a ∂ of its own."""
    if not isinstance(text, str) or len(text) > LIMITS.length or "\n" in text.strip() or _ROW_BREAK.search(text):
        return None  # lines are chains of their own (see lines_as_chain)
    if answer_lines(text) is not None:
        return None  # lines cut at `;` too: H = θ̇ ∂L/∂θ̇ − L; H = … is not H = θ̇ p_θ − L and H = … apart
    label, *sides = _cut(text, lambda i, depth: depth == 0 and _EQUALS.match(text, i) is not None)
    if len(sides) < 2 or _PARTIAL.search(sides[-1]) or len(label) > _LABEL_LENGTH:
        return None
    read = parse_answer(label) if not _SIDES_LABEL.fullmatch(label) else None  # Q_\theta, p_{\phi}: TeX's labels
    if read is not None and not (read.ok and read.kind == "expression" and read.value.is_Symbol):
        return None
    steps, left_out, named = [], [], {}
    for number, side in enumerate(sides[:-1]):
        step = _MOMENTUM_QUOTIENT.sub(lambda found: _momentum_named(found, named), side)
        if number == 0 and _QUOTIENT_ALONE.fullmatch(side):
            steps.append(side)  # p_φ = ∂L/∂θ̇ = …: a quotient alone after the label, the parser judges as a definition
        elif _PARTIAL.search(step):
            left_out.append(side.strip())
        else:
            steps.append(step)
    if not left_out and steps == sides[:-1]:
        return None  # no ∂ in the steps: the parser's refusal is about something else
    return "=".join([label, *steps, sides[-1]]), left_out, label.strip(), tuple(named.items())


def _momentum_named(found: re.Match, named: dict[str, str]) -> str:
    """``∂L/∂θ̇`` as ``p_{theta}``, the name of the momentum it defines, noted in ``named`` with the
    quotient as typed; any other quotient as typed."""
    read = parse_answer(f"{found[0]} = 0")
    if not read.ok or read.kind != "equation" or not read.value.lhs.is_Symbol:
        return found[0]
    quotient = split_quotient(read.value.lhs.name)
    if not (quotient and quotient.top == "L" and quotient.dotted):
        return found[0]
    name = f" p_{{{quotient.by.replace('_', '')}}} "  # θ₁'s p_{theta1}, read in TeX too
    named[name] = found[0]
    return name


_PARTIAL = re.compile(r"∂|\\partial(?![A-Za-z])")
_QUOTIENT_ALONE = re.compile(
    r"\s*[-−]?\s*(?:∂\s*[A-Za-z]\w*\s*/\s*∂\s*[^\s=+\-−*/·⋅()\[\]{}]{1,20}"
    r"|\\frac\s*\{\s*\\partial\s*[A-Za-z]\s*\}\s*\{\s*\\partial\s*(?:[^{}]|\{[^{}]*\}){1,30}\})\s*"
)
# ∂L/∂θ̇ written inline (θ̇, thetadot, \dot\theta, \dot{\theta}) or as TeX's \frac{\partial L}{\partial \dot\theta}
_MOMENTUM_QUOTIENT = re.compile(
    r"∂\s*L\s*/\s*∂\s*(?:\\dot\s*(?:\{[^{}]{1,20}\}|\\?[A-Za-z]+)|[^\s=+\-−*/·⋅()\[\]{}]{1,20})"
    r"|\\frac\s*\{\s*\\partial\s*L\s*\}\s*\{\s*\\partial\s*(?:[^{}]|\{[^{}]*\}){1,30}\}"
)
