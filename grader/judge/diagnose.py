"""Naming the mistake: which term differs, and how it can be described without revealing it.

Contents:
    terms(expr, varying=, expanded=)              an expression's terms, keyed by shape
    term_changes(expected, submitted, setting)    missing / extra / differing terms, from two such
    describe_term(term, setting)                  "a velocity-dependent term", "a term in cos(θ₁ − θ₂)"
    small_angle(expr, setting)                    sin u → u, cos u → 1 (and 1 − u²/2)
    taylor(expr, setting, order)                  expansion about the equilibrium q = q̇ = q̈ = 0
    symbolic_zero(expr, setting)                  sympy's last word, with the problem's assumptions

Descriptions name the *kind* of term a student can look for in their own answer;
they never print the expected term itself.
"""

from __future__ import annotations

import itertools

import sympy

from grader.judge.setting import Setting
from grader.parse.names import unicode_name
from grader.parse.readback import to_text

__all__ = ["describe_term", "has_angle_functions", "small_angle", "symbolic_zero", "taylor", "term_changes", "terms"]

MAX_TERMS = 60  # beyond this, listing terms says nothing useful
_TRIG = (sympy.sin, sympy.cos, sympy.tan, sympy.cot, sympy.sec, sympy.csc)


def terms(expr, *, varying: set | None = None, expanded: bool = False) -> dict:
    """The terms of ``expr`` expanded, keyed by their shape (the term without its numeric coefficient).

    With ``varying`` (a set of symbols), only the terms that involve one of them: what a
    constant the answer may add does not hide. ``expanded`` says ``expr`` already is.
    """
    collected: dict = {}
    for term in sympy.Add.make_args(expr if expanded else sympy.expand(expr)):
        if varying is not None and not term.free_symbols & varying:
            continue
        coefficient, shape = term.as_coeff_Mul()
        collected[shape] = collected.get(shape, 0) + coefficient
    return {shape: c for shape, c in collected.items() if c != 0}


def term_changes(expected_terms: dict, submitted_terms: dict, setting: Setting) -> list[tuple[str, str]]:
    """How the submitted terms differ from the expected ones (each as :func:`terms` gives them):
    [(key, description)].

    Keys are ``missing_term``, ``extra_term`` and ``term_differs``. An empty list
    means the comparison is not informative (too many terms, or none differ by shape).
    """
    if len(expected_terms) > MAX_TERMS or len(submitted_terms) > MAX_TERMS:
        return []
    changes = []
    for shape, coefficient in expected_terms.items():
        if shape not in submitted_terms:
            changes.append(("missing_term", describe_term(shape, setting)))
        elif submitted_terms[shape] != coefficient:
            how = "has the wrong sign" if submitted_terms[shape] == -coefficient else "has the wrong factor"
            changes.append(("term_differs", f"{describe_term(shape, setting, definite=True)} {how}"))
    for shape in submitted_terms:
        if shape not in expected_terms:
            changes.append(("extra_term", describe_term(shape, setting)))
    return changes


def describe_term(term, setting: Setting, *, definite: bool = False) -> str:
    """What kind of term this is, in words a student can act on.

    >>> s = Setting.build(["theta_1", "theta_2"], ["m", "g", "l"])
    >>> describe_term(sympy.Symbol("theta_1__1") ** 2 * sympy.Symbol("m"), s)
    'a velocity-dependent term'
    >>> describe_term(sympy.cos(sympy.Symbol("theta_1") - sympy.Symbol("theta_2")), s)
    'a term in cos(θ₁ - θ₂)'
    """
    article = "the" if definite else "a"
    symbols = term.free_symbols
    velocities = {setting.velocity(q) for q in setting.coords}
    accelerations = {setting.acceleration(q) for q in setting.coords}
    trig = [f for f in term.atoms(*_TRIG) if f.args[0].free_symbols & set(setting.state.values())]
    if trig:  # the first by its printed form, when there are several
        first = trig[0] if len(trig) == 1 else min(trig, key=str)
        within = f" in {to_text(setting.as_typed(first))}"  # θ̇, not theta__1
    else:
        within = ""
    if symbols & accelerations:
        return f"{article} term with an acceleration{within}"
    if symbols & velocities:
        return f"{article} velocity-dependent term{within}"
    if trig:
        return f"{article} term{within}"
    if sympy.Symbol("g") in symbols:
        return f"{article} gravity term"
    if not symbols:
        return f"{article} constant term"
    if not symbols & set(setting.state.values()):
        return f"{article} term without coordinates or velocities"
    coordinates = sorted(symbols & set(setting.state.values()), key=str)
    shown = [unicode_name(s.name) if "__" not in s.name else to_text(setting.as_typed(s)) for s in coordinates]
    return f"{article} term in {', '.join(shown)}"


def has_angle_functions(expr, setting: Setting) -> bool:
    """Whether a trigonometric function of a coordinate occurs in ``expr``."""
    coordinates = {setting.state[(q, 0)] for q in setting.coords}
    return any(f.args[0].free_symbols & coordinates for f in expr.atoms(*_TRIG))


def small_angle(expr, setting: Setting) -> list:
    """The small-angle forms of ``expr``: sin u → u, tan u → u, and cos u → 1 or 1 − u²/2."""
    coordinates = {setting.state[(q, 0)] for q in setting.coords}

    def involves(u) -> bool:
        return bool(u.free_symbols & coordinates)

    def replace(rules):
        return expr.replace(
            lambda e: isinstance(e, tuple(rules)) and involves(e.args[0]),
            lambda e: rules[type(e)](e.args[0]),
        )

    linear = {sympy.sin: lambda u: u, sympy.tan: lambda u: u}
    forms = [replace({**linear, sympy.cos: cosine}) for cosine in (lambda u: sympy.Integer(1), lambda u: 1 - u**2 / 2)]
    return [form for form in forms if form != expr]


def taylor(expr, setting: Setting, order: int):
    """The expansion of ``expr`` to ``order`` about q = q̇ = q̈ = 0 (the equilibrium at the origin)."""
    variables = sorted(expr.free_symbols & set(setting.state.values()), key=str)
    at_zero = dict.fromkeys(variables, 0)
    result = expr.subs(at_zero)
    for degree in range(1, order + 1):
        for combination in itertools.combinations_with_replacement(variables, degree):
            derivative = sympy.diff(expr, *combination).subs(at_zero)
            if derivative != 0:
                multiplicity = sympy.Mul(*(sympy.factorial(combination.count(v)) for v in set(combination)))
                result += derivative * sympy.Mul(*combination) / multiplicity
    return result


def symbolic_zero(expr, setting: Setting) -> bool:
    """Whether sympy can show ``expr`` is zero, with the problem's domains as assumptions."""
    assumed = {}
    for symbol in expr.free_symbols:
        domain = setting.domain(symbol)
        flags = {"real": {"real": True}, "positive": {"positive": True}, "negative": {"negative": True}}.get(
            domain, {"real": True}
        )
        assumed[symbol] = sympy.Symbol(symbol.name, **flags)
    return sympy.simplify(expr.xreplace(assumed)) == 0
