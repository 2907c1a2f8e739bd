"""Names an author gives a meaning in the problem's own names: ``given: {p_theta: m l^2 thetadot}``.

Contents:
    given_values(expected, given)      the given names with their values, read (an author's error raises)
    in_given_names(expected, values)   the expected answer written in those names (H in p_θ, p_φ), or None

An answer may use a given name (a Hamiltonian in the momenta, where the part asks for it in the
velocities): the name is put in place, and the answer is judged as the velocities say. But its
terms are the student's in the momenta: p_φ²/(2 m l²) for p_φ²/(2 m l² sin²θ) is, in the
velocities, a term in sin⁴θ for one in sin²θ, which the student never wrote. So a wrong answer's
terms are named in the given names, against the expected answer written in them.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import replace
from functools import lru_cache

import sympy

from grader.errors import AuthorError
from grader.judge.expected import Expected
from grader.parse import ParsedAnswer, parse_answer
from grader.parse.names import canonical_name

__all__ = ["given_values", "in_given_names"]


def given_values(expected: Expected, given: Mapping) -> tuple[tuple[sympy.Symbol, sympy.Expr], ...]:
    """The author's ``given`` names with their values, read in the problem's names.

    Raises:
        AuthorError: for a value that cannot be read, uses a name the problem does not
            define, or a name the expected answer or the problem already uses.
    """
    if not isinstance(given, Mapping) or not all(isinstance(v, str) for v in given.values()):
        raise AuthorError("option given must map names to expressions, as {p_theta: m R^2 thetadot}")
    items = tuple(sorted((str(name), value) for name, value in given.items()))
    return _read_given(items, expected.setting.coords, tuple(sorted(expected.names)))


@lru_cache(maxsize=256)
def _read_given(items: tuple, coords: tuple, names: tuple) -> tuple[tuple[sympy.Symbol, sympy.Expr], ...]:
    values = []
    for name, text in items:
        if canonical_name(name) in names:
            raise AuthorError(f"given name {name!r} is already a name of this problem or of its expected answer")
        value = parse_answer(text, coords=coords, known=names)
        if not value.ok or value.kind != "expression":
            problem = value.message if not value.ok else "it is not an expression"
            raise AuthorError(f"the value given for {name!r}, {text!r}, cannot be read: {problem}")
        undefined = sorted({s.name for s in value.value.free_symbols} - set(names))
        if undefined:
            raise AuthorError(
                f"the value given for {name!r} uses {', '.join(undefined)}, which the problem does not define"
            )
        values.append((sympy.Symbol(canonical_name(name)), value.value))
    return tuple(values)


def in_given_names(expected: Expected, values: tuple) -> tuple[Expected, dict] | None:
    """The expected answer with the velocities that ``values`` (from :func:`given_values`) define
    written in the given names, as an expected answer of its own whose setting knows those names;
    and the replacement that writes an answer so. None when the given names do not determine
    those velocities (one name for two velocities, or one that is not solved for its velocity).

    Computed once per expected answer and given names.
    """
    cache_key = ("in given names", values)
    if cache_key not in expected.cache:
        expected.cache[cache_key] = _in_given_names(expected, values)
    return expected.cache[cache_key]


def _in_given_names(expected: Expected, values: tuple) -> tuple[Expected, dict] | None:
    setting = expected.setting
    velocities = [setting.node(q, 1) for q in setting.coords]
    unknowns = [v for v in velocities if any(value.has(v) for _, value in values)]
    if not unknowns or len(unknowns) != len(values):
        return None
    try:
        solutions = sympy.solve([symbol - value for symbol, value in values], unknowns, dict=True)
    except (NotImplementedError, *_SYMPY_FAILURES):
        return None
    if len(solutions) != 1 or set(solutions[0]) != set(unknowns):
        return None
    replacement = solutions[0]
    names = tuple(symbol.name for symbol, _ in values)
    value = expected.parsed.value.xreplace(replacement)
    in_names = replace(
        setting,
        known=(*setting.known, *names),
        domains={**setting.domains, **dict.fromkeys(names, "real")},
        given=names,
    )
    answer = ParsedAnswer(expected.text, value, expected.parsed.kind)
    written = Expected(
        expected.text, expected.kind, in_names, answer, in_names.plain(value), expected.names | set(names),
        dict(expected.options),
    )  # fmt: skip
    return written, replacement


_SYMPY_FAILURES = (ArithmeticError, ValueError, TypeError, RecursionError)
