"""Dimensional analysis: what an answer is measured in, from the dimensions of the problem's symbols.

Contents:
    DIMENSIONS                   a dimension's name → its powers of mass, length and time
    QUANTITY_WORDS               a quantity's word (period) → its dimension's name
    PREFIX_WORDS                 a unit prefix's word (milli) → its symbol (m)
    units_of(expr, setting)      the powers of an expression in plain symbols; None where unknown
    Mixed                        raised where terms of a sum, or a function's argument, disagree
    units_mistake(expected, value)  what a wrong answer's units say, as a feedback key and details
    si(units), unit_of(dimension)  powers as a student reads them: ``kg·m²/s²``; a dimension's unit
    SI_UNITS, in_units(value)    a number written with its unit: ``2006 ms`` is 2006 × 1/1000 s
    unit_like(word)              whether a word after a number may be a unit we do not know (flubsec)
    unit_named(text), other_units(text)   a part's unit, and the others that measure the same
    cycles_to(value, unit)       2π from Hz to rad/s: the same SI units, a cycle apart
    unit_counts(names)           whether units by these names count cycles (Hz) or radians (rad/s)

A problem declares each symbol's dimension (``m: mass``, ``g: acceleration``); a coordinate's
derivatives are divided by time once per dot, and t is a time. ``√(l/g)`` is then a time and
cannot be the angular frequency √(g/l), and ``θ̈ = −g θ`` adds 1/s² to m/s². Only a wrong answer
is looked at, and only when every symbol in it has a declared dimension.
"""

from __future__ import annotations

from fractions import Fraction
from functools import lru_cache
from typing import TYPE_CHECKING

import sympy
from sympy.core.function import AppliedUndef

from grader.parse import TIME, parse_answer
from grader.parse.names import superscript

if TYPE_CHECKING:  # setting.py reads DIMENSIONS from here
    from grader.judge.setting import Setting

__all__ = [
    "DIMENSIONS",
    "PREFIX_WORDS",
    "QUANTITY_WORDS",
    "SI_UNITS",
    "Mixed",
    "cycles_to",
    "in_units",
    "other_units",
    "si",
    "unit_counts",
    "unit_like",
    "unit_named",
    "unit_of",
    "units_mistake",
    "units_of",
]

Units = tuple[Fraction, Fraction, Fraction]  # powers of mass, length, time

_NONE: Units = (Fraction(0), Fraction(0), Fraction(0))

DIMENSIONS: dict[str, Units] = {
    name: tuple(Fraction(power) for power in powers)
    for name, powers in {
        "dimensionless": (0, 0, 0), "angle": (0, 0, 0),
        "mass": (1, 0, 0), "length": (0, 1, 0), "time": (0, 0, 1), "area": (0, 2, 0),
        "velocity": (0, 1, -1), "acceleration": (0, 1, -2),
        "angular velocity": (0, 0, -1), "frequency": (0, 0, -1), "angular acceleration": (0, 0, -2),
        "momentum": (1, 1, -1), "angular momentum": (1, 2, -1), "moment of inertia": (1, 2, 0),
        "force": (1, 1, -2), "torque": (1, 2, -2), "energy": (1, 2, -2), "power": (1, 2, -3),
        "force per length": (1, 0, -2), "mass per time": (1, 0, -1), "pressure": (1, -1, -2),
    }.items()
}  # fmt: skip

# The words for quantities a label may be (period = 2.006 s), by what each measures; not frequency, f or ω
QUANTITY_WORDS = {
    "period": "time", "time": "time", "duration": "time", "length": "length", "distance": "length",
    "mass": "mass", "speed": "velocity", "velocity": "velocity", "acceleration": "acceleration",
    "force": "force", "torque": "torque", "energy": "energy", "work": "energy", "power": "power",
    "momentum": "momentum",
}  # fmt: skip

# Functions whose argument must be a pure number, and so is their value. (sign takes any
# quantity, as in friction's −μ m g sign(ẋ), and is a pure number; |x| keeps x's units.)
_PURE = {"sin", "cos", "tan", "cot", "sec", "csc", "asin", "acos", "atan", "sinh", "cosh", "tanh", "coth",
         "sech", "csch", "asinh", "acosh", "atanh", "exp", "log"}  # fmt: skip


class Mixed(Exception):
    """Terms of a sum in different units (``found``: each, in order), or a function of a quantity
    with units (``function``: its name, ``found``: the argument's; ``power`` for an exponent, or
    the base of a variable exponent)."""

    def __init__(self, found: list[Units], function: str = ""):
        super().__init__(function or "a sum of unlike terms")
        self.found, self.function = found, function


def units_of(expr, setting: Setting) -> Units | None:
    """The powers of mass, length and time of ``expr`` (plain symbols, as :meth:`Setting.plain`
    gives them); None when a symbol in it has no declared dimension, or it holds an object this
    does not know.

    Raises:
        Mixed: terms of a sum in different units, or a function of a quantity with units.
    """
    if expr.is_Number or expr.is_NumberSymbol or expr is sympy.I:
        return _NONE
    if expr.is_Symbol:
        return _symbol_units(expr, setting)
    if expr.is_Add:
        found = [units_of(term, setting) for term in expr.args]
        if any(units is None for units in found):
            return None
        if len(set(found)) > 1:
            raise Mixed(found)
        return found[0]
    if expr.is_Mul:
        total = _NONE
        for factor in expr.args:
            units = units_of(factor, setting)
            if units is None:
                return None
            total = tuple(a + b for a, b in zip(total, units, strict=True))
        return total
    if expr.is_Pow:
        base, exponent = units_of(expr.base, setting), units_of(expr.exp, setting)
        if base is None or exponent is None:
            return None
        if expr.exp.is_Rational:
            return tuple(power * Fraction(int(expr.exp.p), int(expr.exp.q)) for power in base)
        for units, what in ((exponent, "power"), (base, "power")):
            if units != _NONE:
                raise Mixed([units], what)
        return _NONE
    name = type(expr).__name__
    if len(expr.args) == 1 and (name in _PURE or name in ("Abs", "re", "im", "sign")):
        units = units_of(expr.args[0], setting)
        if name == "sign" and units is not None:
            return _NONE
        if units is None or name not in _PURE:
            return units
        if units != _NONE:
            raise Mixed([units], name)
        return _NONE
    return None


def _symbol_units(symbol: sympy.Symbol, setting: Setting) -> Units | None:
    if symbol == TIME:
        return DIMENSIONS["time"]
    name, order = symbol.name, 0
    if setting.is_state(symbol) and "__" in name:
        name, dots = name.split("__")
        order = int(dots)
    dimension = setting.dimensions.get(name)
    if dimension is None:
        return None
    mass, length, time = DIMENSIONS[dimension]
    return mass, length, time - order


def units_mistake(expected, value, setting: Setting, *, equation: bool) -> tuple[str, dict] | None:
    """What the units of a wrong answer say: (feedback key, details), or None when they are
    right, or cannot be known.

    ``value`` is the answer in plain symbols: an expression, an ``Eq`` or a tuple of them;
    ``expected`` is the expected answer's units (for an expression), or None. An equation's
    terms must agree with each other; an expression must also be measured as the expected one is.
    """
    items = value if isinstance(value, tuple) else (value,)
    for number, item in enumerate(items, 1):
        whole = item.lhs - item.rhs if isinstance(item, sympy.Eq) else item
        if whole.atoms(AppliedUndef, sympy.Derivative):
            return None  # a function of time the plain symbols do not cover
        if whole == 0:
            continue  # zero has whatever units it needs
        where = f"equation {number}" if len(items) > 1 else ("equation" if equation else "answer")
        try:
            units = units_of(whole, setting)
        except Mixed as mixed:
            if mixed.function == "power":
                return "units_power", {"where": where, "units": si(mixed.found[0])}
            if mixed.function:
                return "units_argument", {"where": where, "function": mixed.function, "units": si(mixed.found[0])}
            shown = list(dict.fromkeys(si(found) for found in mixed.found))
            return "units_mixed", {"where": where, "units": " and ".join(shown)}
        if not equation and units is not None and expected is not None and units != expected:
            return "units_differ", {"theirs": si(units), "wanted": si(expected)}
    return None


def _si_unit(size, dimension: str) -> tuple[Fraction, Units]:
    return Fraction(size), DIMENSIONS[dimension]


# The units a number may be written in, by the names the parser reads them as: name → (its size
# in SI units, what it measures).
SI_UNITS: dict[str, tuple[Fraction, Units]] = {
    **dict.fromkeys(("s", "second", "seconds"), _si_unit(1, "time")),
    "ms": _si_unit(Fraction(1, 1000), "time"),
    **dict.fromkeys(("min", "minute", "minutes"), _si_unit(60, "time")),
    **dict.fromkeys(("h", "hour", "hours"), _si_unit(3600, "time")),
    **dict.fromkeys(("m", "metre", "metres", "meter", "meters"), _si_unit(1, "length")),
    "cm": _si_unit(Fraction(1, 100), "length"),
    "mm": _si_unit(Fraction(1, 1000), "length"),
    "km": _si_unit(1000, "length"),
    **dict.fromkeys(("kg", "kilogram", "kilograms"), _si_unit(1, "mass")),
    **dict.fromkeys(("g", "gram", "grams"), _si_unit(Fraction(1, 1000), "mass")),
    **dict.fromkeys(("N", "newton", "newtons"), _si_unit(1, "force")),
    **dict.fromkeys(("J", "joule", "joules"), _si_unit(1, "energy")),
    "Nm": _si_unit(1, "torque"),  # N·m run together: a word after the formula, else
    **dict.fromkeys(("W", "watt", "watts"), _si_unit(1, "power")),
    **dict.fromkeys(("Hz", "hertz"), _si_unit(1, "frequency")),
    **dict.fromkeys(("Pa", "pascal", "pascals"), _si_unit(1, "pressure")),
    **dict.fromkeys(("rad", "radian", "radians"), _si_unit(1, "angle")),
}
# The prefixed units by their symbols: ns, μs (read as mus) and us, ks; kN, MJ, mW, kHz, mrad. Every
# prefix is known, so that none is taken for a word after the number (2.006 ps was graded as 2.006 s).
_PREFIXES = {"f": Fraction(1, 10**15), "p": Fraction(1, 10**12), "n": Fraction(1, 10**9), "mu": Fraction(1, 10**6),
             "u": Fraction(1, 10**6), "m": Fraction(1, 1000), "c": Fraction(1, 100), "d": Fraction(1, 10),
             "h": Fraction(100), "k": Fraction(1000), "M": Fraction(10**6), "G": Fraction(10**9),
             "T": Fraction(10**12)}  # fmt: skip
_BASES = ("s", "m", "N", "J", "W", "Hz", "rad")
SI_UNITS |= {
    prefix + unit: (size * SI_UNITS[unit][0], SI_UNITS[unit][1])
    for prefix, size in _PREFIXES.items()
    for unit in _BASES
    if prefix + unit not in SI_UNITS and (unit != "rad" or prefix == "m")
}
# Other words for units of time, as students write them: unread, 2.006 days was graded as 2.006 s, the
# word taken for a remark after the number. A unit's name may start a sentence (2.006 Seconds).
_SPELLED = {
    "mins": SI_UNITS["min"],
    **dict.fromkeys(("hr", "hrs"), SI_UNITS["h"]),
    **dict.fromkeys(("millisecond", "milliseconds", "msec", "msecs"), SI_UNITS["ms"]),
    **dict.fromkeys(("microsecond", "microseconds"), SI_UNITS["mus"]),
    **dict.fromkeys(("nanosecond", "nanoseconds"), SI_UNITS["ns"]),
    **dict.fromkeys(("kilosecond", "kiloseconds"), SI_UNITS["ks"]),
    **dict.fromkeys(("day", "days"), _si_unit(86400, "time")),
    **dict.fromkeys(("week", "weeks", "wk", "wks"), _si_unit(7 * 86400, "time")),
    **dict.fromkeys(("year", "years", "yr", "yrs"), _si_unit(31557600, "time")),  # a Julian year
}
# and the prefixed seconds spelled or cut short: 2.006 nsec, nanosec, picoseconds, millis were graded as 2.006 s
PREFIX_WORDS = {"femto": "f", "pico": "p", "nano": "n", "micro": "mu", "milli": "m", "centi": "c", "deci": "d",
                 "kilo": "k", "mega": "M", "giga": "G", "tera": "T"}  # fmt: skip
_SPELLED |= {
    word + ending: SI_UNITS[prefix + "s"]
    for word, prefix in PREFIX_WORDS.items()
    for ending in ("sec", "secs", "second", "seconds")
}
_SPELLED |= {
    prefix + ending: SI_UNITS[prefix + "s"]
    for prefix in ("f", "p", "n", "u", "mu", "c", "k", "M", "G")
    for ending in ("sec", "secs")
}
_SPELLED["millis"] = SI_UNITS["ms"]
_CAPITALIZED = ("second", "seconds", "minute", "minutes", "hour", "hours", "hertz", "day", "days")
SI_UNITS |= _SPELLED
SI_UNITS |= {word.capitalize(): SI_UNITS[word] for word in _CAPITALIZED}
_UNUSUAL = frozenset(  # the prefixed units a number is not asked about being in (ms for s, but not ps)
    prefix + unit for prefix in _PREFIXES if prefix not in ("n", "mu", "m", "k", "M") for unit in _BASES
) - {"cm"}
_UNUSUAL |= {*_SPELLED, *(word.capitalize() for word in _CAPITALIZED)}  # a name's other spellings


_TIME_ENDINGS = ("sec", "secs", "second", "seconds")
_UNIT_STEMS = tuple(sorted({name.lower() for name in SI_UNITS if len(name) >= 3}))


def unit_like(word: str) -> bool:
    """Whether a word after a number may be a unit the checker does not know, which makes it another
    number: the start of a unit's name (``sec``, ``mill``), a word for seconds (``flubsec``), or one with
    a prefix (``millisex``). Graded as the bare number, 2.006 of such a unit was right."""
    word = word.lower().rstrip(".")
    if word in _UNIT_STEMS or word.endswith(_TIME_ENDINGS) or word.startswith(tuple(PREFIX_WORDS)):
        return True
    return len(word) >= 3 and any(stem.startswith(word) for stem in _UNIT_STEMS)


def in_units(value) -> tuple[sympy.Expr, Fraction, Units] | None:
    """``value`` (an expression) as a number times units: (the number, the units' size in SI,
    their powers); None when it holds a symbol that is no unit, or a unit other than to an
    integer power. ``9.81 m/s^2`` is (9.81, 1, m/s²); ``2006 ms`` is (2006, 1/1000, s)."""
    number, size, powers = [], Fraction(1), [Fraction(0)] * 3
    for factor in sympy.Mul.make_args(value):
        base, exponent = factor.as_base_exp()
        if not factor.free_symbols:
            number.append(factor)
        elif base.is_Symbol and base.name in SI_UNITS and exponent.is_Integer:
            unit_size, unit_powers = SI_UNITS[base.name]
            size *= unit_size ** int(exponent)
            powers = [have + int(exponent) * power for have, power in zip(powers, unit_powers, strict=True)]
        else:
            return None
    return sympy.Mul(*number), size, tuple(powers)


# Hz counts cycles per second and rad/s radians: the same SI units, 1/s, yet a cycle is 2π radians,
# and f = ω/2π is the slip students make with them. A plain 1/s (s⁻¹) says neither, and is read as
# either as it stands.
_CYCLES = frozenset({"Hz", "hertz"})
_RADIANS = frozenset({"rad", "radian", "radians"})


def cycles_to(value, unit: str) -> sympy.Expr:
    """What a number written in ``value``'s units is multiplied by, beyond their sizes, to be in
    ``unit``: 2π from Hz to rad/s, 1/(2π) from rad/s to Hz, else 1."""
    theirs, wanted = unit_counts({symbol.name for symbol in value.free_symbols}), _unit_counts(unit)
    if theirs == wanted or None in (theirs, wanted):
        return sympy.Integer(1)
    return 2 * sympy.pi if theirs == "cycles" else 1 / (2 * sympy.pi)


@lru_cache(maxsize=64)
def _unit_counts(text: str) -> str | None:
    read = parse_answer(text)
    return unit_counts({symbol.name for symbol in read.symbols}) if read.ok else None


def unit_counts(names: set[str]) -> str | None:
    """Whether units by these names count cycles (Hz) or radians (rad/s); None for neither, or both."""
    cycles, radians = bool(names & _CYCLES), bool(names & _RADIANS)
    return None if cycles == radians else "cycles" if cycles else "radians"


@lru_cache(maxsize=64)
def unit_named(text: str) -> tuple[Fraction, Units] | None:
    """A unit as an author writes it (``s``, ``m/s^2``, ``rad/s``): its size in SI units and its
    powers; None when it is not a product of powers of :data:`SI_UNITS`."""
    read = parse_answer(text)
    found = in_units(read.value) if read.ok and read.kind == "expression" else None
    return None if found is None or found[0] != 1 else (found[1], found[2])


def other_units(text: str) -> list[tuple[str, sympy.Expr]]:
    """The units that measure what ``text`` does, each with its size in ``text``'s units: ms for s
    is 1/1000, Hz for rad/s is 2π. The part's own unit, and other names of it, are left out."""
    size, powers = unit_named(text)
    found = [
        (name.replace("mu", "μ", 1) if name.startswith("mu") else name, sympy.Rational(other / size))
        for name, (other, its) in SI_UNITS.items()
        if its == powers and other != size and _usual(name)
    ]
    counts = _unit_counts(text) if powers == DIMENSIONS["frequency"] and size == 1 else None
    if counts == "radians":  # rad/s and Hz: a cycle apart
        found.append(("Hz", 2 * sympy.pi))
    elif counts == "cycles":
        found.append(("rad/s", 1 / (2 * sympy.pi)))
    return found


def _usual(name: str) -> bool:
    """Whether a unit is one a student may have meant (ms, cm, km, min; not ps, or us beside μs)."""
    return name not in _UNUSUAL


def unit_of(dimension: str) -> str:
    """A dimension's SI unit as a student reads it (``m/s²``); ``rad`` for an angle, and nothing
    for a pure number or a dimension we do not know (a symbol given none)."""
    if dimension == "angle":
        return "rad"
    if dimension not in DIMENSIONS or dimension == "dimensionless":
        return ""
    return si(DIMENSIONS[dimension])


def si(units: Units) -> str:
    """Powers of mass, length and time in SI units, as a student writes them.

    >>> si((Fraction(1), Fraction(2), Fraction(-2))), si((Fraction(0), Fraction(0), Fraction(-1)))
    ('kg·m²/s²', '1/s')
    >>> si((Fraction(0), Fraction(1, 2), Fraction(0))), si(_NONE)
    ('m^(1/2)', 'no units (a pure number)')
    """
    if units == _NONE:
        return "no units (a pure number)"
    above = [_power(unit, power) for unit, power in zip(("kg", "m", "s"), units, strict=True) if power > 0]
    below = [_power(unit, -power) for unit, power in zip(("kg", "m", "s"), units, strict=True) if power < 0]
    top = "·".join(above) or "1"
    if not below:
        return top
    return f"{top}/{below[0]}" if len(below) == 1 else f"{top}/({'·'.join(below)})"


def _power(unit: str, power: Fraction) -> str:
    if power == 1:
        return unit
    if power.denominator == 1:
        return unit + superscript(power.numerator)
    return f"{unit}^({power})"
