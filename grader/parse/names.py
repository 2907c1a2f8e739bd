"""Names in answers: Greek letters, subscripts, and one canonical spelling per name.

Contents:
    GREEK_BY_LETTER, GREEK_NAMES   Unicode Greek letters and their ASCII names
    CONSTANT_WORDS                 "const", "constant": words for an arbitrary constant
    JOINING_WORDS                  "and", "where", "with": words between two equations
    IMPLYING_WORDS                 "so", "hence", "thus", "therefore": a derivation's steps, as ⇒
    SUBSCRIPT_DIGITS, SUBSCRIPT_LETTERS, SUPERSCRIPTS   Unicode sub- and superscript characters
    function_name(raw)             ``sin``, ``Sin``, ``SIN``, ``ArcSin`` → ``sin``/``asin``: a function, as typed
    canonical_name(raw)            the one spelling of a name (``theta1`` → ``theta_1``)
    split_derivative(name)         ``theta1dot`` → (``theta_1``, 1)
    split_prefixed_derivative(name)  ``dtheta1`` → (``theta_1``, 1)
    Quotient, split_quotient(name) ``dL_dphidot`` → (``L``, ``phi``, dotted): ∂L/∂φ̇ as the grammar names it
    is_arbitrary_constant(name)    ``C``, ``C_1``, ``const``: a name for any constant
    stand_in(name)                 ``w_0`` → ``omega_0``: ASCII letters typed for a Greek one
    unicode_name(name)             ``theta_1`` → ``θ₁``, for reading an answer back
    superscript(number)            ``-2`` → ``⁻²``, for a power written out

Every spelling of one name is one symbol: ``theta1``, ``theta_1``, ``θ₁`` and
``\\theta_1`` all become the canonical ``theta_1``. Canonical names are ASCII
letters, digits and single underscores, so they are safe to show and to hand to
printers.
"""

from __future__ import annotations

import re
import unicodedata
from functools import lru_cache
from typing import NamedTuple

__all__ = [
    "CONSTANT_WORDS",
    "FUNCTION_NAMES",
    "GREEK_BY_LETTER",
    "GREEK_NAMES",
    "IMPLYING_WORDS",
    "JOINING_WORDS",
    "SUBSCRIPT_DIGITS",
    "SUBSCRIPT_LETTERS",
    "SUPERSCRIPTS",
    "Quotient",
    "canonical_name",
    "function_name",
    "is_arbitrary_constant",
    "split_derivative",
    "split_prefixed_derivative",
    "split_quotient",
    "stand_in",
    "superscript",
    "unicode_name",
]

# Words a student adds for "some constant" (L + const): one name each, even in TeX, where other
# runs of letters that are no name are read a letter at a time. The checker leaves them out
# where a constant is allowed.
CONSTANT_WORDS = ("const", "constant")
_NUMBERED_CONSTANT = re.compile(r"^C(?:_[0-9]+)?$")  # C, C₁, C₂
JOINING_WORDS = frozenset({"and", "where", "with"})  # eq₁, where eq₂: a system, the grammar reads
IMPLYING_WORDS = frozenset({"so", "hence", "thus", "therefore"})  # eq₁ so eq₂: eq₂, the tokenizer reads

# Unicode letter → ASCII name. Variant forms (ϑ, ϕ, ϵ, ς) are the same letter to a
# student, so they share a name; µ (the micro sign) is how some keyboards type μ.
GREEK_BY_LETTER: dict[str, str] = {
    "α": "alpha", "β": "beta", "γ": "gamma", "δ": "delta", "ε": "epsilon", "ϵ": "epsilon",
    "ζ": "zeta", "η": "eta", "θ": "theta", "ϑ": "theta", "ι": "iota", "κ": "kappa",
    "λ": "lambda", "μ": "mu", "µ": "mu", "ν": "nu", "ξ": "xi", "ο": "omicron", "π": "pi",
    "ρ": "rho", "σ": "sigma", "ς": "sigma", "τ": "tau", "υ": "upsilon", "φ": "phi",
    "ϕ": "phi", "χ": "chi", "ψ": "psi", "ω": "omega",
    "Γ": "Gamma", "Δ": "Delta", "Θ": "Theta", "Λ": "Lambda", "Ξ": "Xi", "Π": "Pi",
    "Σ": "Sigma", "Υ": "Upsilon", "Φ": "Phi", "Ψ": "Psi", "Ω": "Omega",
}  # fmt: skip

# ASCII name → the Unicode letter used when reading an answer back.
GREEK_NAMES: dict[str, str] = {}
for _letter, _name in GREEK_BY_LETTER.items():
    GREEK_NAMES.setdefault(_name, _letter)

SUBSCRIPT_DIGITS = {chr(0x2080 + d): str(d) for d in range(10)}
# The letters Unicode has as subscripts, as in Qᵣ or vₓ (each is read as _r, _x).
SUBSCRIPT_LETTERS = dict(zip("ₐₑₒₓₕₖₗₘₙₚₛₜᵢᵣᵤᵥⱼ", "aeoxhklmnpstiruvj", strict=True))
SUPERSCRIPTS = {"²": "2", "³": "3", "¹": "1", "⁰": "0", "⁻": "-"} | {chr(0x2070 + d): str(d) for d in range(4, 10)}
_SUBSCRIPT_OUT = {v: k for k, v in SUBSCRIPT_DIGITS.items()}
_SUPERSCRIPT_OUT = str.maketrans({v: k for k, v in SUPERSCRIPTS.items()})

# The whitelist of functions, by every name a student may use, to the canonical one.
FUNCTION_NAMES: dict[str, str] = {
    "sin": "sin", "cos": "cos", "tan": "tan", "cot": "cot", "sec": "sec", "csc": "csc",
    "asin": "asin", "arcsin": "asin", "acos": "acos", "arccos": "acos",
    "atan": "atan", "arctan": "atan", "sinh": "sinh", "cosh": "cosh", "tanh": "tanh",
    "coth": "coth", "sech": "sech", "csch": "csch", "asinh": "asinh", "arsinh": "asinh", "arcsinh": "asinh",
    "acosh": "acosh", "arcosh": "acosh", "arccosh": "acosh", "atanh": "atanh", "artanh": "atanh", "arctanh": "atanh",
    "exp": "exp", "log": "log", "ln": "log", "sqrt": "sqrt", "abs": "abs",
    "sign": "sign", "sgn": "sign", "signum": "sign",
    "sen": "sin", "senh": "sinh", "arcsen": "asin",  # sine as Spanish and Portuguese write it
    "ctg": "cot", "cotg": "cot",  # the cotangent as much of Europe writes it (not tg: t·g is a product)
}  # fmt: skip
# The same names as a phone's first capital (Sin), caps lock (SIN) or Mathematica (Sin[θ], ArcTan) type
# them. No other casing: sIn is a slip of no keyboard's. Two capitals stay letters (LN may be L·N).
_CASED_FUNCTIONS = {
    spelled: canonical
    for name, canonical in FUNCTION_NAMES.items()
    for spelled in (name.capitalize(), name.upper() if len(name) > 2 else None)
    if spelled
} | {
    "Arc" + name[3:].capitalize(): canonical
    for name, canonical in FUNCTION_NAMES.items()
    if name[:3] == "arc" and name[3:] in FUNCTION_NAMES
}


def function_name(raw: str) -> str | None:
    """The canonical function a name spells (``sin``, ``Sin``, ``SIN``; Mathematica's ``ArcTan``), or None.

    >>> function_name("sin"), function_name("Cos"), function_name("SQRT"), function_name("ArcTan")
    ('sin', 'cos', 'sqrt', 'atan')
    >>> function_name("sIn") is None, function_name("LN") is None, function_name("tg") is None
    (True, True, True)
    """
    return FUNCTION_NAMES.get(raw) or _CASED_FUNCTIONS.get(raw)


_TRAILING_DIGITS = re.compile(r"^([A-Za-z]+)_?([0-9]+)$")
# A derivative's suffix: dot, ddot (dotdot, doubledot), or _d, _dd as code spells them; a subscript may stand
# either side.
_SUFFIX = r"(?:_?(?P<dots>d?dot|dotdot|doubledot)|_(?P<ds>dd?))"
# Lazy base so that ``thetaddot`` is theta + ddot, not thetad + dot.
_DERIVATIVE = re.compile(rf"^(?P<base>[A-Za-z]+?(?:_?[0-9]+)?){_SUFFIX}(?:_?(?P<sub>[0-9]+))?$")
_PREFIXED = re.compile(r"^(?P<ds>dd?)(?P<base>[A-Za-z]+(?:_[0-9]+)?)$")


# varphi is φ, as \varphi and ϕ are: the variant letter's name, followed by nothing, an index or dots
# (varphidot, varphi_1). Not varpi: π is a number, and no student's variant of it.
_VARIANT = re.compile(r"(?:^|(?<=_))var(?=(?:phi|theta|epsilon|rho|sigma)(?:$|[_0-9]|d))")  # p_varphi too


@lru_cache(maxsize=4096)  # every name of every answer, and each piece of a glued one: the same few recur
def canonical_name(raw: str) -> str:
    """The one spelling of a name, with Greek letters spelled out in ASCII.

    >>> canonical_name("theta1"), canonical_name("θ₁"), canonical_name("l2")
    ('theta_1', 'theta_1', 'l_2')
    >>> canonical_name("p_θ"), canonical_name("x_cm"), canonical_name("mgl")
    ('p_theta', 'x_cm', 'mgl')
    >>> canonical_name("varphidot"), canonical_name("vartheta_1"), canonical_name("varpi"), canonical_name("various")
    ('phidot', 'theta_1', 'varpi', 'various')
    >>> canonical_name("p_varphi"), canonical_name("a_variance")
    ('p_phi', 'a_variance')
    """
    ascii_name = _VARIANT.sub("", "".join(_ascii_char(c) for c in raw))
    match = _TRAILING_DIGITS.match(ascii_name)
    if match:
        return f"{match[1]}_{match[2]}"
    return ascii_name


def _ascii_char(c: str) -> str:
    if c in GREEK_BY_LETTER:
        return GREEK_BY_LETTER[c]
    if c in SUBSCRIPT_DIGITS:
        return "_" + SUBSCRIPT_DIGITS[c]
    return c


def split_derivative(name: str) -> tuple[str, int] | None:
    """Split a ``dot``/``ddot`` suffix (or ``_d``/``_dd``, as in code) off a canonical name.

    Returns the canonical base name and the number of dots, or ``None`` when the
    name has no such suffix. Whether the base is a coordinate is the caller's
    question.

    >>> split_derivative("thetaddot"), split_derivative("theta_1dot"), split_derivative("xdot_2")
    (('theta', 2), ('theta_1', 1), ('x_2', 1))
    >>> split_derivative("theta_dd"), split_derivative("theta_1_d"), split_derivative("theta_dotdot")
    (('theta', 2), ('theta_1', 1), ('theta', 2))
    >>> split_derivative("theta") is None
    True
    """
    match = _DERIVATIVE.match(name)
    if not match:
        return None
    base = match["base"]
    if match["sub"]:
        if _TRAILING_DIGITS.match(base):
            return None  # two subscripts, as in theta1dot2: not a name we know
        base = f"{base}_{match['sub']}"
    return canonical_name(base), 2 if match["dots"] in _TWO_DOTS or match["ds"] == "dd" else 1


_TWO_DOTS = ("ddot", "dotdot", "doubledot")


# Letters typed for a Greek one on a keyboard without it: w for ω (it looks the part), th, ph.
_STAND_IN = re.compile(rf"^(?P<letters>w|th|ph)(?P<rest>(?:_?[0-9]+)?{_SUFFIX}?(?:_?[0-9]+)?)$")
_STOOD_FOR = {"w": "omega", "th": "theta", "ph": "phi"}
# th1dd, thd: a rate glued on as d or dd, as students shorten dot on an angle; not on w, whose wd is no ω̇
_GLUED_RATE = re.compile(r"^(?P<letters>th|ph)(?P<number>_?[0-9]+)?(?P<ds>dd?)$")


def stand_in(name: str) -> str | None:
    """The Greek name that ASCII letters stand in for, as ``w`` for ω: the caller uses it only
    where the problem defines that name and not the letters themselves.

    >>> stand_in("w_0"), stand_in("th_1dot"), stand_in("ph"), stand_in("wx"), stand_in("th1dd")
    ('omega_0', 'theta_1dot', 'phi', None, 'theta1ddot')
    """
    glued = _GLUED_RATE.match(name)
    if glued:
        dots = "ddot" if glued["ds"] == "dd" else "dot"
        return canonical_name(_STOOD_FOR[glued["letters"]] + (glued["number"] or "") + dots)
    match = _STAND_IN.match(name)
    if not match:
        return None
    return canonical_name(_STOOD_FOR[match["letters"]] + match["rest"])


def is_arbitrary_constant(name: str) -> bool:
    """Whether a canonical name is what students write for any constant: ``C``, ``C_1``,
    ``const``, ``constant`` (whether the problem defines it is the caller's question).

    >>> is_arbitrary_constant("C_2"), is_arbitrary_constant("const"), is_arbitrary_constant("c")
    (True, True, False)
    """
    return name in CONSTANT_WORDS or _NUMBERED_CONSTANT.match(name) is not None


def split_prefixed_derivative(name: str) -> tuple[str, int] | None:
    """Split a ``d``/``dd`` prefix off a canonical name, as code spells a rate: ``dtheta``, ``ddx``.

    Only where the problem has no symbol ``d`` (else ``dx`` is d·x), which is the caller's
    question, as is whether the base is a coordinate.

    >>> split_prefixed_derivative("dtheta_1"), split_prefixed_derivative("ddx")
    (('theta_1', 1), ('x', 2))
    """
    match = _PREFIXED.match(name)
    if not match:
        return None
    return match["base"], len(match["ds"])


# A Greek letter glued after letters, as in iθ (canonical "itheta"): shown as typed. Spellings of three
# letters or more, as the grammar takes them for pieces of a glued name; "sinu" is no "siν".
_GLUED_GREEK = re.compile(
    "(?P<head>[A-Za-z]+?)(?P<greek>"
    + "|".join(sorted((name for name in GREEK_NAMES if len(name) >= 3), key=len, reverse=True))
    + ")"
)


# ∂V/∂θ and ∂L/∂φ̇ as the grammar names them (dV_dtheta, dL_dphidot): a letter, then a coordinate
_QUOTIENT = re.compile(r"d([A-Za-z])_d([A-Za-z]\w*?)(_?dot)?")


class Quotient(NamedTuple):
    """A partial derivative the grammar reads as one name: ∂``top``/∂``by``, or ∂``top``/∂(``by``)˙."""

    top: str  # what is differentiated: L, T, V, U, F
    by: str  # the coordinate, as the name was spelt: theta_1 or theta1
    dotted: bool  # by its velocity


def split_quotient(name: str) -> Quotient | None:
    """The parts of a partial derivative's name (see :func:`unicode_name`); None for any other name.

    >>> split_quotient("dL_dtheta_1dot"), split_quotient("dV_dr")
    (Quotient(top='L', by='theta_1', dotted=True), Quotient(top='V', by='r', dotted=False))
    >>> split_quotient("dx"), split_quotient("p_theta")
    (None, None)
    """
    found = _QUOTIENT.fullmatch(name)
    return Quotient(found[1], found[2], bool(found[3])) if found else None


def unicode_name(name: str, dots: int = 0) -> str:
    """A canonical name as a student would write it by hand, in Unicode.

    >>> unicode_name("theta_1", dots=1), unicode_name("p_theta"), unicode_name("x_cm")
    ('θ̇₁', 'p_θ', 'x_cm')
    >>> unicode_name("itheta"), unicode_name("xomega_0"), unicode_name("sinu")
    ('iθ', 'xω₀', 'sinu')

    A partial derivative the parser reads as one name, as a chain's label, is shown as typed:

    >>> unicode_name("dV_dtheta"), unicode_name("dL_dphidot"), unicode_name("dF_dxdot")
    ('∂V/∂θ', '∂L/∂φ̇', '∂F/∂ẋ')
    """
    quotient = split_quotient(name)
    if quotient:
        return f"∂{unicode_name(quotient.top)}/∂{unicode_name(quotient.by, int(quotient.dotted))}"
    base, _, sub = name.partition("_")
    glued = None if base in GREEK_NAMES else _GLUED_GREEK.fullmatch(base)
    text = glued["head"] + GREEK_NAMES[glued["greek"]] if glued else GREEK_NAMES.get(base, base)
    text += {0: "", 1: "\u0307", 2: "\u0308", 3: "\u20db"}.get(dots, "")
    if sub:
        if sub.isdigit():
            text += "".join(_SUBSCRIPT_OUT[d] for d in sub)
        else:
            text += "_" + GREEK_NAMES.get(sub, sub)
    return unicodedata.normalize("NFC", text)  # ẋ as one character where Unicode has one


def superscript(number: int) -> str:
    """An integer in Unicode superscripts, as a power is written out.

    >>> superscript(2), superscript(-12)
    ('²', '⁻¹²')
    """
    return str(number).translate(_SUPERSCRIPT_OUT)
