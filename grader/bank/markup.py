"""Bank text as authors write it, read for display: paragraphs of plain, bold and LaTeX runs.

Contents:
    Segment                 one run of text: plain, bold (``**…**``) or LaTeX (between ``$``)
    paragraphs(text)        bank text as paragraphs of segments
    segments(paragraph)     one paragraph's segments
    inline(text)            text shown on one line (a choice), as segments
    tex_runs(tex)           LaTeX math as Unicode text, in runs marked sub, sup or bold
    plain_text(paragraph)   a paragraph as one line of Unicode text (scripts as ² or ^(…))

Prompts, choices and reference texts are written in Markdown with ``$…$`` LaTeX. The
self-check page and the HTML reports show them without a math renderer (pages are
self-contained and offline), so the notation they use is read here, once, for both.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

__all__ = ["Segment", "inline", "paragraphs", "plain_text", "segments", "tex_runs"]


@dataclass(frozen=True)
class Segment:
    """A run of prompt text: plain, bold (``**…**``) or LaTeX (between ``$``), always shown as text.

    LaTeX is shown as Unicode text (``\\dot\\theta`` as θ̇) with its sub- and superscripts in
    ``runs``, and the source kept for a tooltip: the page loads no math renderer.
    """

    text: str
    style: str = ""  # "", "bold" or "tex"
    runs: tuple[tuple[str, str], ...] = ()  # tex: (text, "" | "sub" | "sup" | "bold")


def segments(paragraph: str) -> tuple[Segment, ...]:
    """A paragraph split into plain, ``**…**`` and ``$…$`` runs.

    >>> [(s.style, s.text) for s in segments(r"**Rigid body.** Is $|\\mathbf r| = c$ holonomic?")]
    [('bold', 'Rigid body.'), ('', ' Is '), ('tex', '|\\\\mathbf r| = c'), ('', ' holonomic?')]
    """
    runs = []
    for piece in re.split(r"(\$[^$]+\$|\*\*[^*]+\*\*)", paragraph):
        if not piece:
            continue
        if piece.startswith("$") and piece.endswith("$") and len(piece) > 1:
            runs.append(Segment(piece[1:-1], "tex", tex_runs(piece[1:-1])))
        elif piece.startswith("**") and piece.endswith("**") and len(piece) > 4:
            runs.append(Segment(piece[2:-2], "bold"))
        else:
            runs.append(Segment(piece))
    return tuple(runs)


# -- LaTeX as Unicode text -----------------------------------------------------------------

_GREEK = (
    "alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta", "theta", "iota", "kappa", "lambda", "mu",
    "nu", "xi", "omicron", "pi", "rho", "sigma", "tau", "upsilon", "phi", "chi", "psi", "omega",
)  # fmt: skip
_TEX_SYMBOLS = {
    **{name: chr(0x3B1 + i + (1 if i >= 17 else 0)) for i, name in enumerate(_GREEK)},  # no final sigma
    **{name.capitalize(): chr(0x391 + i + (1 if i >= 17 else 0)) for i, name in enumerate(_GREEK)},
    "varphi": "φ", "vartheta": "ϑ", "varepsilon": "ε", "ell": "ℓ", "hbar": "ℏ",
    "partial": "∂", "nabla": "∇", "sum": "∑", "prod": "∏", "int": "∫", "infty": "∞",
    "cdot": "·", "times": "×", "pm": "±", "mp": "∓", "ll": "≪", "gg": "≫", "le": "≤", "leq": "≤",
    "ge": "≥", "geq": "≥", "ne": "≠", "neq": "≠", "approx": "≈", "equiv": "≡", "sim": "∼", "propto": "∝",
    "dots": "…", "ldots": "…", "cdots": "⋯", "to": "→", "rightarrow": "→", "Rightarrow": "⇒",
    "sin": "sin", "cos": "cos", "tan": "tan", "cot": "cot", "exp": "exp", "ln": "ln", "log": "log",
    "left": "", "right": "", "big": "", "Big": "", ",": " ", ";": " ", ":": " ", "!": "", " ": " ",
    "quad": " ", "qquad": " ", "{": "{", "}": "}", "|": "‖", "%": "%", "$": "$", "_": "_",
}  # fmt: skip
_ACCENTS = {"dot": "\u0307", "ddot": "\u0308", "hat": "\u0302", "bar": "\u0304", "tilde": "\u0303", "vec": "\u20d7"}
_FONTS = {"mathbf", "mathrm", "mathit", "mathsf", "mathcal", "boldsymbol", "text", "textrm", "operatorname"}
_CALLIGRAPHIC = {"F": "ℱ", "L": "ℒ", "H": "ℋ", "E": "ℰ"}
_FRACTION_MACROS = {"frac", "tfrac", "dfrac"}
_PREFIXES = {"partial", "delta", "nabla", "Delta"}  # ∂V, δq: written against what follows
_FUNCTIONS = {"sin", "cos", "tan", "cot", "exp", "ln", "log"}
_FRACTIONS = {("1", "2"): "½", ("1", "3"): "⅓", ("1", "4"): "¼", ("3", "4"): "¾"}
_TEX_TOKEN = re.compile(r"\\[A-Za-z]+|\\.|[{}^_]|\s+|[^\\{}^_\s]")


def tex_runs(tex: str) -> tuple[tuple[str, str], ...]:
    """LaTeX math as Unicode text, in runs marked for sub- and superscript and bold (vectors).

    A small reading of the notation prompts use (Greek letters, accents, fractions, scripts);
    anything else stays as it is written.

    >>> tex_runs(r"L(\\theta, \\dot\\theta)")
    (('L(θ, θ̇)', ''),)
    >>> tex_runs(r"\\frac{\\partial T}{\\partial \\dot q_j} = \\mathbf F_i")
    (('∂T/∂q̇', ''), ('j', 'sub'), (' = ', ''), ('F', 'bold'), ('i', 'sub'))
    >>> tex_runs(r"T = \\tfrac12 m l^2 \\dot\\theta^2, |\\theta| \\ll 1, \\unknown")
    (('T = ½ m l', ''), ('2', 'sup'), (' θ̇', ''), ('2', 'sup'), (', |θ| ≪ 1, \\\\unknown', ''))
    """
    tokens = _TEX_TOKEN.findall(tex)
    runs, _ = _tex_sequence(tokens, 0)
    merged: list[list[str]] = []
    for text, script in runs:
        if merged and merged[-1][1] == script:
            merged[-1][0] += text
        elif text:
            merged.append([text, script])
    return tuple((text, script) for text, script in merged)


def _tex_sequence(tokens: list[str], at: int, *, group: bool = False) -> tuple[list[tuple[str, str]], int]:
    runs: list[tuple[str, str]] = []
    while at < len(tokens):
        if tokens[at] == "}":
            if group:
                return runs, at + 1
            at += 1  # a stray brace: TeX would refuse it; we skip it
            continue
        atom, at = _tex_atom(tokens, at)
        runs += atom
    return runs, at


def _skip_space(tokens: list[str], at: int) -> int:
    while at < len(tokens) and tokens[at].isspace():
        at += 1
    return at


def _tex_atom(tokens: list[str], at: int) -> tuple[list[tuple[str, str]], int]:
    """One token or group (and what a macro takes) as runs; the position after it."""
    token = tokens[at]
    at += 1
    if token == "{":
        return _tex_sequence(tokens, at, group=True)
    if token in ("^", "_"):
        script = "sup" if token == "^" else "sub"
        atom, at = _tex_atom(tokens, _skip_space(tokens, at)) if _skip_space(tokens, at) < len(tokens) else ([], at)
        return [(text, script) for text, _ in atom], at
    if not token.startswith("\\"):
        return [(token, "")], at
    name = token[1:]
    if name in _ACCENTS or name in _FONTS or name in _FRACTION_MACROS or name in _PREFIXES:
        at = _skip_space(tokens, at)  # between a macro and its argument a space only ends the name
    if name in _ACCENTS and at < len(tokens):
        atom, at = _tex_atom(tokens, at)
        if atom and atom[0][0]:
            first, script = atom[0]
            atom[0] = (first[0] + _ACCENTS[name] + first[1:], script)
        return atom, at
    if name in _FONTS and at < len(tokens):
        atom, at = _tex_atom(tokens, at)
        if name == "mathcal":
            atom = [("".join(_CALLIGRAPHIC.get(c, c) for c in text), script) for text, script in atom]
        if name in ("mathbf", "boldsymbol"):  # vectors
            atom = [(text, script or "bold") for text, script in atom]
        return atom, at
    if name in _FRACTION_MACROS and at < len(tokens):
        numerator, at = _tex_atom(tokens, _skip_space(tokens, at))
        denominator, at = _tex_atom(tokens, _skip_space(tokens, at)) if at < len(tokens) else ([], at)
        plain = ("".join(t for t, _ in numerator), "".join(t for t, _ in denominator))
        if plain in _FRACTIONS:
            return [(_FRACTIONS[plain], "")], at
        after = [(" ", "")] if at < len(tokens) and (tokens[at].startswith("\\") or tokens[at].isalnum()) else []
        return [*_bracketed(numerator), ("/", ""), *_bracketed(denominator), *after], at
    if name in _TEX_SYMBOLS:
        symbol = _TEX_SYMBOLS[name]
        if name in _FUNCTIONS:  # r\\sin\\theta reads r sin θ
            if at >= 2 and tokens[at - 2].isalnum():
                symbol = " " + symbol
            if at < len(tokens) and tokens[at] not in ("(", "^", "_") and not tokens[at].isspace():
                symbol += " "
        return [(symbol, "")], at
    return [(token, "")], at


def _bracketed(runs: list[tuple[str, str]]) -> list[tuple[str, str]]:
    text = "".join(t for t, _ in runs).strip()
    if len(text) > 1 and any(c in text for c in " +-−="):
        return [("(", ""), *runs, (")", "")]
    return runs


def inline(text) -> tuple[Segment, ...]:
    """Bank text shown on one line, a choice's: its lines and spaces joined, then its segments.

    >>> [s.text for s in inline("a **b**\\n  $x$")]
    ['a ', 'b', ' ', 'x']
    """
    return segments(" ".join(str(text).split()))


def paragraphs(text: str) -> tuple[tuple[Segment, ...], ...]:
    """Bank text as paragraphs of segments: wrapped lines join, blank lines separate.

    >>> [[s.text for s in p] for p in paragraphs("A bob\\nhangs.\\n\\nUse θ.\\n")]
    [['A bob hangs.'], ['Use θ.']]
    """
    blocks = re.split(r"\n\s*\n", text or "")
    return tuple(segments(" ".join(block.split())) for block in blocks if block.strip())


_SUPERSCRIPTS = str.maketrans("0123456789+-−=()n", "⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻⁻⁼⁽⁾ⁿ")
_SUBSCRIPTS = str.maketrans("0123456789+-−=()", "₀₁₂₃₄₅₆₇₈₉₊₋₋₌₍₎")


def plain_text(paragraph: tuple[Segment, ...]) -> str:
    """A paragraph as one line of Unicode text, for where no markup fits (a table's heading).

    >>> plain_text(segments(r"**Find** $T = \\tfrac12 m l^2 \\dot\\theta^2$ for $\\theta_1$, $x_{ab}$, $e^{-st}$."))
    'Find T = ½ m l² θ̇² for θ₁, x_ab, e^(-st).'
    """
    text = []
    for segment in paragraph:
        if segment.style != "tex":
            text.append(segment.text)
            continue
        for run, script in segment.runs:
            table, mark = {"sup": (_SUPERSCRIPTS, "^"), "sub": (_SUBSCRIPTS, "_")}.get(script, (None, ""))
            if table is None:
                text.append(run)
            elif all(c in "0123456789+-−=()" or (script == "sup" and c == "n") for c in run):
                text.append(run.translate(table))
            else:
                text.append(mark + (run if len(run) == 1 else f"({run})" if script == "sup" else run))
    return "".join(text)
