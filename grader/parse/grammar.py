"""From tokens to sympy objects: the grammar of answers.

Contents:
    TIME                  the symbol ``t`` the coordinates depend on
    coordinate(name)      a coordinate as a function of t, one object per name (time_derivative: its rates)
    Context               what a problem defines: coordinates and known symbols
    parse_tokens(...)     tokens → an expression, an ``Eq``, or a tuple of ``Eq``

The grammar, loosest binding first::

    answer   := item (SEP item)*  |  '[' item (',' item)* ']'
    item     := over ('=' over)?
    over     := expr ('\\over' expr)?                      # TeX's fraction of its group: a \\over b
    expr     := term (('+' | '-') term)*
    term     := signed (('*' | '/') signed | factor)*      # juxtaposition multiplies
    signed   := ('+' | '-') signed | factor
    factor   := primary (SUP | '^' signed)?                 # right-associative
    primary  := number | name | function | group | frac | sqrt
    group    := '(' over ')' | '[' over ']' | '{' over '}'

Juxtaposition has the precedence of ``*`` and ``/`` and everything associates to
the left, so ``1/2 m l^2`` is m·l²/2. Every sympy object is built here from a
token the whitelist accepted; numbers are exact rationals (``0.5`` is 1/2).
"""

from __future__ import annotations

import math
import re
from collections.abc import Collection, Iterable
from dataclasses import dataclass, field
from functools import cached_property, lru_cache

import sympy
from sympy.core.function import AppliedUndef
from sympy.core.traversal import iterargs

from grader.parse.functions import COMPLEX, SYMPY
from grader.parse.messages import ParseFailure, listed
from grader.parse.names import (
    CONSTANT_WORDS,
    FUNCTION_NAMES,
    GREEK_BY_LETTER,
    GREEK_NAMES,
    JOINING_WORDS,
    canonical_name,
    is_arbitrary_constant,
    split_derivative,
    split_prefixed_derivative,
    stand_in,
    unicode_name,
)
from grader.parse.tokens import LIMITS, Name, Token

__all__ = ["ANSWER", "TIME", "Context", "coordinate", "holds_any", "parse_tokens", "time_derivative", "too_many_digits"]

TIME = sympy.Symbol("t", real=True)
# The name an expression followed by the definitions of its names stands under: ``½ m v², v = l θ̇``
# reads as answer = ½ m v²; v = l θ̇, as ``L = ½ m v², v = l θ̇`` reads L = …
ANSWER = sympy.Symbol("answer")


@lru_cache(maxsize=256)
def coordinate(name: str) -> sympy.Expr:
    """The coordinate ``name`` (canonical) as a function of :data:`TIME`, one object for every
    context and setting that has it: the checker looks an answer's θ(t) and θ̇ up in dictionaries
    of its own (plain symbols, compiled variables), and the same object is found at once, where
    an equal one built apart is compared with it node by node."""
    return sympy.Function(name, real=True)(TIME)


@lru_cache(maxsize=1024)
def time_derivative(q: sympy.Expr, order: int) -> sympy.Expr:
    """d^order q/dt^order, one object for each, as :func:`coordinate` is (and slow to build)."""
    return sympy.Derivative(q, (TIME, order))


_OPENERS = {"(": ")", "[": "]", "{": "}"}
_ANGLE_FUNCTIONS = frozenset({"sin", "cos", "tan", "cot", "sec", "csc"})
_STARTS_FACTOR = ("num", "name", "func", "frac", "sqrt", "deriv", "sum")
# What a sum (``\sum_j``, ∑) stands for while a side is read: no name a student can type, so it is
# found again after. A sum is read only in a side the chain passes over, the definition in
# ``H = \sum_j p_j \dot q_j - L = …`` (whose index has no values here); left in the answer, it is refused.
_SUM = sympy.Dummy("sum")
_GREEK = "|".join(sorted(set(GREEK_BY_LETTER.values()), key=len, reverse=True))
_GREEK_NAME = re.compile(rf"(?:{_GREEK})(?:_[A-Za-z0-9]+)?$")
_NUMBERED_THEN_LETTERS = re.compile(r"_[0-9]+[A-Za-z]+$")  # ω_0t: a subscript's number, then a letter glued on
# A Greek letter spelled out inside a glued name (γx is "gammax" by then) is a piece of its own even
# where the problem does not define it: the fewest pieces then make γ·x, never g·a·m·m·a·x.
# Two-letter spellings (mu, nu, pi, xi) are left out: "sinu" is sin u.
_SPELLED = frozenset(name for name in GREEK_BY_LETTER.values() if len(name) >= 3)
_PLAIN_NAME = re.compile(r"[A-Za-z][A-Za-z0-9]*(?:_[A-Za-z0-9]+)*")  # a name as canonical_name spells one
# One TeX symbol: a spelled-out Greek letter (from θ typed inside a run) or one letter,
# each with its subscript; or a run of digits.
_TEX_PIECE = re.compile(rf"(?:{_GREEK}|[A-Za-z])(?:_[A-Za-z0-9]+)?|[0-9]+")


@dataclass(frozen=True)
class Context:
    """The names a problem gives meaning to.

    Attributes:
        coords: canonical name → the coordinate as a function of :data:`TIME`.
        known: canonical name → the problem's symbol (with whatever assumptions it carries).
    """

    coords: dict[str, sympy.Expr] = field(default_factory=dict)
    known: dict[str, sympy.Symbol] = field(default_factory=dict)
    _derivatives: dict = field(default_factory=dict, repr=False, compare=False)
    _applied: dict = field(default_factory=dict, repr=False, compare=False)

    @classmethod
    def build(cls, coords: Iterable = (), known: Iterable = ()) -> Context:
        """A context from names (any spelling) or ready sympy objects."""
        coords, known = tuple(coords), tuple(known)
        try:
            return _built(coords, known)
        except TypeError:  # unhashable: built afresh
            return cls._build(coords, known)

    @classmethod
    def _build(cls, coords: tuple, known: tuple) -> Context:
        coord_map = {}
        for coord in coords:
            if isinstance(coord, str):
                name = canonical_name(coord)
                coord_map[name] = coordinate(name)
            else:
                coord_map[coord.func.__name__] = coord
        known_map = {}
        for symbol in known:
            if isinstance(symbol, str):
                known_map[canonical_name(symbol)] = sympy.Symbol(canonical_name(symbol))
            else:
                known_map[symbol.name] = symbol
        return cls(coord_map, known_map)

    @cached_property
    def coordinate_set(self) -> frozenset:
        return frozenset(self.coords.values())

    def derivative(self, coordinate: sympy.Expr, order: int) -> sympy.Expr:
        """A coordinate's time derivative of ``order``, built once for the problem: a sympy
        ``Derivative`` is slow to build, and every θ̇ of every answer needs one."""
        key = (coordinate, order)
        if key not in self._derivatives:
            self._derivatives[key] = time_derivative(coordinate, order)
        return self._derivatives[key]

    def applied(self, name: str, argument) -> sympy.Expr:
        """The function ``name`` of ``argument``, built once for the problem where the argument is a
        coordinate or the difference of two (sin θ, cos(θ₁ − θ₂)), as :meth:`derivative` is: sympy
        evaluates a function of a new argument afresh, asking that argument's assumptions, and with
        its cache emptied cos(θ₁ − θ₂) takes a millisecond. Most answers of a problem have one."""
        if argument not in self.angles:
            return SYMPY[name](argument)
        key = (name, argument)
        if key not in self._applied:
            self._applied[key] = SYMPY[name](argument)
        return self._applied[key]

    @cached_property
    def angles(self) -> frozenset:
        """The coordinates, and the difference of each two (θ₁ − θ₂ and θ₂ − θ₁)."""
        coordinates = list(self.coords.values())
        return frozenset(coordinates) | {a - b for a in coordinates for b in coordinates if a != b}

    def describe_coords(self) -> str:
        """The coordinates as a student writes them: θ₁, θ₂, not theta_1, theta_2."""
        return ", ".join(unicode_name(name) for name in self.coords) or "it has none"


@lru_cache(maxsize=256)
def _built(coords: tuple, known: tuple) -> Context:
    # A problem's context is the same for every answer to it; building it creates sympy
    # function classes, which is slow and which sympy's own cache may have dropped.
    return Context._build(coords, known)


def parse_tokens(
    tokens: list[Token],
    context: Context,
    text: str,
    deadline=None,
    stated: list | None = None,
    typed: list | None = None,
):
    """An expression, an ``Eq``, or a tuple of ``Eq`` (a system), from the tokens of ``text``.

    ``stated``, if given, receives the middle sides a chain named what the quantity is, each as
    ``Eq(label, side)``: ``L = T − V`` of ``L = T − V = ½ m l² θ̇² + …``, whose value is the last side.
    ``typed``, if given, receives each of those and each equation of a system with the text it was read
    from, as ``(Eq, text)``: what a note quotes back, where a printed Eq would put the terms in sympy's order.

    ``deadline``, if given, is asked to ``check()`` before each term and factor is built:
    within the caps, sympy may still take a second to build one (``(l^-100)^(1/3)`` raised
    to a symbolic power expands (a + ib)¹⁰⁰), and a long answer has dozens.

    Raises:
        ParseFailure: when the tokens do not form an answer.
        whatever ``deadline.check()`` raises once the time is up.
    """
    parser = _Parser(tokens, context, text, deadline)
    value = parser.answer()
    if stated is not None:
        stated.extend(parser.stated)
    if typed is not None:
        typed.extend(parser.typed)
    return value


class _Parser:
    def __init__(self, tokens: list[Token], context: Context, text: str, deadline=None):
        self.tokens, self.context, self.text = (
            _as_system(_line_labels(_leibniz(tokens, context), context)),
            context,
            text,
        )
        self.deadline = deadline
        self.i = 0
        self.depth = 0
        self.powers = 0  # exponents open around the cursor, as in x^(y^(z…))
        self.splits: dict[str, list | None] = {}
        self.rates: dict[str, tuple[int, int]] = {}  # a name of the answer's own → where its rate is first used
        self.stated: list[sympy.Eq] = []  # the middle sides of chains: see parse_tokens
        self.typed: list[tuple[sympy.Eq, str]] = []  # see parse_tokens
        self.sums: list[Token] = []  # the sums read, \sum or ∑, but those in a side passed over
        self.summed = False  # whether any sum was read: none may be left in the answer

    # -- cursor ----------------------------------------------------------------

    @property
    def token(self) -> Token:
        return self.tokens[self.i]

    def advance(self) -> Token:
        token = self.tokens[self.i]
        self.i += 1
        return token

    def expect(self, closer: str, opener: Token) -> None:
        if not self.token.is_op(closer):
            self.fail_here()
        self.advance()

    def _decimal_comma_next(self) -> None:
        """Refuse the comma of ``1/0,498``, where the 0 just read is a number's whole part: not 1/0."""
        comma = self.token
        after = self.tokens[self.i + 1] if self.i + 1 < len(self.tokens) else comma
        last = self.tokens[self.i - 1]
        if (
            comma.is_op(",")
            and after.kind == "num"
            and last.kind == "num"
            and last.end == comma.start == after.start - 1
        ):
            raise ParseFailure("comma", comma.start, comma.end)

    def fail_here(self):
        token = self.token
        if token.kind == "partial":
            raise ParseFailure("partial", token.start, token.end)
        if token.kind == "end":
            last = self.tokens[self.i - 1] if self.i else token
            if self.i == 0:
                raise ParseFailure("empty")
            raise ParseFailure("unexpected_end", last.start, last.end, token=self.source(last))
        if token.is_op(","):
            raise ParseFailure("comma", token.start, token.end)
        if token.is_op("=", "*", "/", "^", ")", "]", "}") or token.kind in ("sup", "sep"):
            raise ParseFailure("missing_operand", token.start, token.end, token=self.show(token))
        raise ParseFailure("unexpected", token.start, token.end, token=self.show(token))

    def source(self, token: Token) -> str:
        """A token as the student typed it, for messages."""
        return self.text[token.start : token.end]

    def show(self, token: Token) -> str:
        return "a new line" if token.kind == "sep" else self.source(token)

    def deeper(self, token: Token) -> None:
        self.depth += 1
        if self.depth > LIMITS.depth:
            raise ParseFailure("too_deep", token.start, token.end, limit=LIMITS.depth)

    # -- answer, item ----------------------------------------------------------

    def answer(self):
        items = self.list_of_items() if self._is_bracketed_list() else self.separated_items()
        if self.token.kind != "end":
            self.fail_here()
        self._sums_passed_over(items)
        self._rates_defined(items)
        if len(items) == 1:
            return items[0][1]
        (token, first), rest = items[0], items[1:]
        if not isinstance(first, sympy.Eq) and all(isinstance(item, sympy.Eq) for _, item in rest):
            items[0] = (token, sympy.Eq(ANSWER, first, evaluate=False))  # ½ m v², where v = l θ̇
        for index, (token, item) in enumerate(items, start=1):
            if not isinstance(item, sympy.Eq):
                raise ParseFailure("not_an_equation", token.start, token.end, index=index)
        return tuple(item for _, item in items)

    def _sums_passed_over(self, items: list) -> None:
        """Refuse a sum left in the answer: its terms are not written, so only a side passed over may hold
        one (``H = \\sum_j p_j \\dot q_j - L = …``, as ``H = Σ p q̇ − L = …`` is read)."""
        if self.summed and any(_SUM in item.free_symbols for _, item in items):
            if not self.sums:  # a side read twice (see _chained): none to point at
                raise ParseFailure("sum", name="\\sum")
            first = self.sums[0]  # the first in a side kept (see item)
            raise ParseFailure("sum", first.start, first.end, name=self.source(first))

    def _rates_defined(self, items: list) -> None:
        """Refuse the rate of a name (``ṗ``, ``d/dt(p)``) unless an equation of the answer defines the
        name, ``p = m l² θ̇``: a name nothing defines is no quantity that changes in time."""
        if not self.rates:
            return  # as nearly every answer: no walk through it
        values = [item for _, item in items]
        defined = {item.lhs.name for item in values if isinstance(item, sympy.Eq) and item.lhs.is_Symbol}
        used = {name for item in values for name in self.rates_in(item)}  # not in a side a chain left out
        for name, (start, end) in self.rates.items():
            if name in used and name not in defined:
                raise ParseFailure(
                    "derivative_of_constant", start, end,
                    name=self.text[start:end], base=unicode_name(name), coords=self.context.describe_coords(),
                )  # fmt: skip

    def rate(self, symbol: sympy.Symbol, start: int, end: int) -> sympy.Expr:
        """``ṗ`` where the answer defines p for itself (``p = m l² θ̇, ṗ = −m g l sin θ``): the time
        derivative of p as a function of time, which ``compare`` replaces with the derivative of
        what defines p. Where nothing does, the answer is refused at its end."""
        self.rates.setdefault(symbol.name, (start, end))
        return sympy.Derivative(sympy.Function(symbol.name, real=True)(TIME), TIME)

    def rates_in(self, value) -> set[str]:
        """The names of the answer's own whose rates ``value`` holds."""
        return {rate.expr.func.__name__ for rate in own_rates(value, self.context.coords)}

    def own(self, value) -> bool:
        """Whether ``value`` is a name the problem does not define, which the answer may."""
        return isinstance(value, sympy.Symbol) and value not in (TIME, _SUM) and value.name not in self.context.known

    def _is_bracketed_list(self) -> bool:
        """``[eq1, eq2]``, ``{eq1, eq2}`` or ``[eq]``: a bracket or brace spanning the whole answer
        with a comma or an ``=`` at its top level (otherwise it is only grouping, as in ``[a + b] c``)."""
        if not self.token.is_op("[", "{"):
            return False
        depth = 0
        is_list = False
        for j in range(self.i, len(self.tokens)):
            token = self.tokens[j]
            if token.kind == "op" and token.value in _OPENERS:
                depth += 1
            elif token.kind == "op" and token.value in _OPENERS.values():
                depth -= 1
                if depth == 0:
                    return is_list and self.tokens[j + 1].kind == "end"
            elif depth == 1 and token.is_op(",", "="):
                is_list = True
        return False

    def list_of_items(self):
        opener = self.advance()  # [ or {
        items = [self._item_typed()]
        while self.token.is_op(",", ";"):  # [eq₁, eq₂] as Maxima writes it, [eq₁; eq₂] as Matlab does
            self.advance()
            items.append(self._item_typed())
        self.expect(_OPENERS[opener.value], opener)
        return items

    def separated_items(self):
        items = []
        while True:
            while self.token.kind == "sep" or self.token.is_op(";"):
                self.advance()
            if self.token.kind == "end":
                break
            items.append(self._item_typed())
            if not (self.token.kind == "sep" or self.token.is_op(";")):
                break
        if not items:
            self.fail_here()
        return items

    def _item_typed(self):
        """:meth:`item`, an equation kept with its text in :attr:`typed`."""
        first, value = found = self.item()
        if isinstance(value, sympy.Eq):
            self.typed.append((value, self.text[first.start : self.tokens[self.i - 1].end]))
        return found

    def item(self):
        first, start = self.token, self.i
        found = self._euler_lagrange_operator(start)
        if found is not None:
            # d/dt(∂L/∂θ̇) − ∂L/∂θ = m l² θ̈ + m g l sin θ = 0: the operator, then the equation it gives
            operator, terms = found
            self.i = operator + 1
            moved = self._dissipation_moved(operator + 1)
            if moved is not None:  # d/dt(∂L/∂ẋ) − ∂L/∂x = −∂F/∂ẋ: Rayleigh's term on the right, alone
                self.i, sign, name = moved
                terms = [*terms, ("+" if sign == "-" else "-", name)]
            lhs = self.over() if moved is None else sympy.Integer(0)
            if not self.token.is_op("="):
                if self.token.kind == "end" and TIME not in lhs.free_symbols:
                    # d/dt(∂L/∂ẋ) − ∂L/∂x = 0 (or = Q) alone: no equation of this system, not the expression 0
                    code = "euler_lagrange_general" if _is_lagrange(terms) else "euler_lagrange_other"
                    raise ParseFailure(
                        code, first.start, self.tokens[self.i - 1].end,
                        functions=self._operator_functions(start, self.i if moved else operator),
                    )  # fmt: skip
                return first, lhs  # what the operator comes to, without "= 0": an expression
            self.advance()
            rhs = self.over()
            if self.token.is_op("="):
                raise ParseFailure("too_many_equals", self.token.start, self.token.end)
            return first, sympy.Eq(lhs, rhs, evaluate=False)
        label = self.label()
        lhs = label if label is not None else self.over()
        if not self.token.is_op("="):
            return first, lhs
        named = self.text[first.start : self.tokens[self.i - 1].end]
        self.advance()
        summed = len(self.sums)
        side = opening = self.token
        rhs = self.side(label)
        while label is not None and self.token.is_op("=") and self._defines(rhs):
            # L = T − V = ½ m l² θ̇² + …: the quantity, its definition, and the answer, which is the last
            # side. Not F = m ẍ = −k x, whose middle side is part of an equation (see _chained).
            statement, end = sympy.Eq(label, rhs, evaluate=False), self.tokens[self.i - 1].end
            # the first as typed, a later one (L = … = T − V = …) after the label
            typed = self.text[first.start : end] if side is opening else f"{named} = {self.text[side.start : end]}"
            self.stated.append(statement)
            self.typed.append((statement, typed))
            self.advance()
            del self.sums[summed:]  # a sum in the definition passed over is read: H = \sum_j p_j \dot q_j - L = …
            side = self.token
            rhs = self.side(label)
        if self.token.is_op("="):
            equals = self.advance()
            # p_φ = m l² sin²θ φ̇ = const, or m l² sin²θ φ̇ = p_φ = const: a quantity, named, said to be conserved
            named = label is not None or (rhs.is_Symbol and rhs is not TIME and rhs.name not in self.context.known)
            if named and self._is_arbitrary_constant(self.i):
                quantity = rhs if label is not None else lhs
                return first, sympy.Eq(quantity, sympy.Symbol(canonical_name(self.advance().value.raw)), evaluate=False)
            if self.token.kind == "end":
                self.fail_here()  # p = m ẋ =: nothing after the last `=`
            chained = self._chained(rhs) if label is not None else None
            if chained is None:
                raise ParseFailure("too_many_equals", equals.start, equals.end)
            return first, chained
        return first, sympy.Eq(lhs, rhs, evaluate=False)

    def _chained(self, middle):
        """``F = m ẍ = −k x``: a quantity named, then the equation of motion it stands in, which
        the chain says too (m ẍ = −k x). Both sides are in the problem's names and one holds an
        acceleration; anything else (``ω = √(g/l) = 3.13``) is None, the cursor left as it was."""
        start = self.i
        last = self.over()
        accelerating = any(d.derivative_count >= 2 for side in (middle, last) for d in side.atoms(sympy.Derivative))
        if self.token.is_op("=") or not accelerating or self._defines(middle) or self._defines(last):
            self.i = start
            return None
        return sympy.Eq(middle, last, evaluate=False)

    def _is_arbitrary_constant(self, i: int) -> bool:
        """Whether the tokens at ``i`` are a name for any constant (``const``, ``C₁``) that the
        problem does not define, and the end of an item."""
        token = self.tokens[i]
        if token.kind != "name" or token.value.dots or token.value.primes:
            return False  # the end token among them: `p = m ẋ =` has no side after its last `=`
        name, after = canonical_name(token.value.raw), self.tokens[i + 1]
        ends = after.kind in ("end", "sep") or after.is_op(",", ";") or _is_joining_word(after)
        return ends and is_arbitrary_constant(name) and name not in self.context.known

    def _is_variable(self, token: Token) -> bool:
        """Whether a token is what a quantity depends on, as in L(θ, θ̇, t): a coordinate, its
        velocity, or time. An acceleration is not: I(θ̈) = … is I·θ̈."""
        if token.kind != "name":
            return False
        meaning = self.lookup(canonical_name(token.value.raw))
        order = token.value.dots + token.value.primes
        if meaning is TIME:
            return order == 0
        if isinstance(meaning, sympy.Derivative):
            return order == 0 and meaning.derivative_count == 1
        return meaning in self.context.coordinate_set and order <= 1

    @staticmethod
    def _is_generic_variable(token: Token) -> bool:
        """Whether a token may be a variable in a list of them, as q, q̇, p or t in L(q, q̇, t)."""
        return token.kind == "name" and token.value.dots + token.value.primes <= 1

    def _defines(self, side) -> bool:
        """Whether a side is written in names the problem does not define (T − V, ½ m v², ½ m ẋ²)."""
        defined = set(self.context.known.values()) | {TIME}
        return any(symbol not in defined for symbol in side.free_symbols) or bool(self.rates_in(side))

    def side(self, label):
        """The next side of an equation; after a label, ∂L/∂φ̇ or −∂V/∂r may be one (a definition)."""
        if label is not None:
            negated = self.token.is_op("-")  # Q_r = −∂V/∂r = …, as the prompts define a generalized force
            quotient = self._partial_quotient(self.i + negated)
            if quotient is not None and self.tokens[quotient[0]].is_op("="):
                self.i, name = quotient
                return -sympy.Symbol(name) if negated else sympy.Symbol(name)
        return self.over()

    def _euler_lagrange_operator(self, i: int) -> tuple[int, list[tuple[str, str]]] | None:
        """``d/dt(∂L/∂θ̇) − ∂L/∂θ`` at ``i``, bracketed or not, in plain notation or TeX's, with
        any further derivatives (``+ ∂F/∂ẋ``, Rayleigh's dissipation function), and followed by
        ``=``: the position of that ``=``, and each term's sign and name (``dL_dthetadot``); None if
        there is none."""
        tokens = self.tokens
        if tokens[i].kind != "deriv" or tokens[i].value != (1, False):
            return None
        closer = _OPENERS.get(tokens[i + 1].value) if tokens[i + 1].kind == "op" else None
        momentum = self._partial_quotient(i + 2 if closer else i + 1)
        if momentum is None:
            return None
        j = momentum[0]
        if closer:
            if not tokens[j].is_op(closer):
                return None
            j += 1
        force = self._partial_quotient(j + 1) if tokens[j].is_op("-") else None
        terms = [("+", momentum[1]), ("-", force[1])] if force is not None else []
        while force is not None and tokens[force[0]].is_op("+", "-"):
            dissipation = self._partial_quotient(force[0] + 1)  # + ∂F/∂q̇, Rayleigh's function
            if dissipation is None:
                return None
            terms.append((tokens[force[0]].value, dissipation[1]))
            force = dissipation
        if force is None or not tokens[force[0]].is_op("="):
            return None
        return force[0], terms

    def _dissipation_moved(self, i: int) -> tuple[int, str, str] | None:
        """``−∂F/∂ẋ`` at ``i``, the whole right side of an Euler–Lagrange operator's ``=``: the position
        after it, its sign and its name (``dF_dxdot``); None where the side is anything else."""
        tokens = self.tokens
        sign = tokens[i].value if tokens[i].is_op("+", "-") else "+"
        quotient = self._partial_quotient(i + (sign != "+" or tokens[i].is_op("+")))
        if quotient is None or tokens[quotient[0]].kind != "end":
            return None
        return quotient[0], sign, quotient[1]

    def _operator_functions(self, start: int, end: int) -> str:
        """The functions an Euler–Lagrange operator between ``start`` and ``end`` differentiates, as
        typed: ``L``, or ``L`` and ``F`` with Rayleigh's; each is the first of a quotient's two ∂."""
        tops = [self.tokens[j + 1] for j in range(start, end) if self.tokens[j].kind == "partial"][::2]
        shown = list(dict.fromkeys(f"`{self.source(token)}`" for token in tops))
        return listed(shown)

    def _partial_quotient(self, i: int) -> tuple[int, str] | None:
        """``∂L/∂φ̇`` or ``\\frac{\\partial L}{\\partial \\dot\\phi}`` at ``i``: the position after it, and
        a name for it (``dL_dphidot``); None if there is none."""
        tokens = self.tokens

        def derivative(j: int) -> tuple[int, str] | None:  # ∂ and a name
            if tokens[j].kind == "partial" and tokens[j + 1].kind == "name":
                name = tokens[j + 1].value
                return j + 2, canonical_name(name.raw) + "dot" * (name.dots + name.primes)
            return None

        if tokens[i].kind == "frac" and tokens[i + 1].is_op("{"):
            top = derivative(i + 2)
            if top and tokens[top[0]].is_op("}") and tokens[top[0] + 1].is_op("{"):
                bottom = derivative(top[0] + 2)
                if bottom and tokens[bottom[0]].is_op("}"):
                    return bottom[0] + 1, f"d{top[1]}_d{bottom[1]}"
            return None
        top = derivative(i)
        if top and tokens[top[0]].is_op("/"):
            bottom = derivative(top[0] + 1)
            if bottom:
                return bottom[0], f"d{top[1]}_d{bottom[1]}"
        return None

    def label(self) -> sympy.Expr | None:
        """The name of the quantity an answer writes out, as in ``L(θ, θ̇) = …`` or ``L = T − V = …``:
        a name the problem does not define, alone or with a bracket of names, before ``=``; or a
        quotient of ∂s, negated too (``−∂V/∂θ = …``, a generalized force as the prompts define one).

        A defined name is never a label: ``m(ẍ) = −k x`` is m·ẍ, and ``ml = …`` is m·l.
        """
        tokens, i = self.tokens, self.i
        token = tokens[i]
        negated = token.is_op("-")
        quotient = self._partial_quotient(i + negated)
        if quotient is not None and tokens[quotient[0]].is_op("="):  # ∂L/∂φ̇ = …
            self.i, name = quotient
            return -sympy.Symbol(name) if negated else sympy.Symbol(name)
        if token.kind != "name" or token.value.dots or token.value.primes:
            return None
        j = i + 1
        if tokens[j].is_op("(") and tokens[j + 1].kind == "name":
            j += 1
            # with commas, a list of what the quantity depends on, generic ones too: H(q, p), L(q, q̇, t);
            # one name alone must be the problem's: I(θ̈) = … is I·θ̈, and m(v) m·v
            listed = self._is_variable if not tokens[j + 1].is_op(",") else self._is_generic_variable
            while listed(tokens[j]) and tokens[j + 1].is_op(","):
                j += 2
            if not (listed(tokens[j]) and tokens[j + 1].is_op(")")):
                return None
            j += 2
        if not tokens[j].is_op("="):
            return None
        canonical = canonical_name(token.value.raw)
        if self.lookup(canonical) is not None or self._spelled_rate(sympy.Symbol(canonical)):
            return None  # pdot = …, as ṗ = …: a rate, not a name
        stood = None if token.value.tex else stand_in(canonical)
        if stood is not None and _is_coordinate_or_derivative(self.lookup(stood), self.context):
            return None  # thdd = …, as θ̈ = …: th for θ as on the right side, not a name of the answer's own
        if not _GREEK_NAME.match(canonical) and self.split(token.value.raw, token):  # mgl: m·g·l
            return None
        if token.value.tex and len(self.tex_letters(token.value.raw)) > 1:  # in TeX, mv is m·v
            return None
        self.i = j
        return sympy.Symbol(canonical)

    # -- arithmetic ------------------------------------------------------------

    def over(self):
        """An expression, or TeX's ``a \\over b``: all of a group, or of a side, before ``\\over`` over
        all of it after (``{m g l \\over 2}``, ``{1 \\over 2} m l^2``). Two in one group are refused,
        as TeX refuses them: which divides which is anyone's guess."""
        if self.token.kind == "over":
            raise ParseFailure("over_side", self.token.start, self.token.end)
        numerator = self.expr()
        if self.token.kind != "over":
            return numerator
        over = self.advance()
        after = self.token
        if after.kind == "over":
            raise ParseFailure("over_twice", after.start, after.end)
        if not (after.kind in _STARTS_FACTOR or after.is_op("(", "[", "{", "+", "-")):
            raise ParseFailure("over_side", over.start, over.end)
        denominator = self.expr()
        if self.token.kind == "over":
            raise ParseFailure("over_twice", self.token.start, self.token.end)
        return _quotient(numerator, denominator, over)

    def expr(self):
        terms = [self.term()]
        while self.token.is_op("+", "-"):
            if self.deadline is not None:
                self.deadline.check()
            op = self.advance()
            term = self.term()
            terms.append(-term if op.value == "-" else term)
        return _sum(terms)

    def term(self):
        factors = [self.signed()]
        previous_was_number = self.tokens[self.i - 1].kind == "num"
        while True:
            if self.deadline is not None:
                self.deadline.check()
            token = self.token
            if token.is_op("*", "/"):
                self.advance()
                factor = self.signed()
                if token.value == "/" and self._glued_denominator(factors):
                    factor *= self.factor()  # p²/2m, mg/2l: over 2m and 2l, as over lsinθ; but 1/2m is ½ m
                if token.value == "/":
                    if factor == 0:
                        self._decimal_comma_next()
                        raise ParseFailure("division_by_zero", token.start, token.end)
                    factor = _power(factor, sympy.Integer(-1), token)
                factors.append(factor)
            elif token.kind in _STARTS_FACTOR or token.is_op("(", "[", "{"):
                # Digits that touch were split on purpose (TeX's x^23); a space between is a slip.
                if token.kind == "num" and previous_was_number and self.tokens[self.i - 1].end != token.start:
                    raise ParseFailure("numbers_adjacent", token.start, token.end)
                factors.append(self.factor())
            else:
                break
            previous_was_number = self.tokens[self.i - 1].kind == "num"
        product = _product(factors)
        _check_size(product, self.tokens[self.i - 1])  # 9^99·9^99·… is within every limit but one
        return product

    def _glued_denominator(self, numerator: list) -> bool:
        """Whether the number just read after ``/`` is glued to a name that is in the denominator with
        it: ``p²/2m`` is p²/(2m), as a physicist reads it. Not after a number alone (``1/2m`` is
        ½ m, as ``1/2 m`` is), nor across a space (``m g l/2 cos θ``)."""
        last, token = self.tokens[self.i - 1], self.token
        if last.kind != "num" or token.kind != "name" or last.end != token.start:
            return False
        return any(not factor.is_number for factor in numerator)

    def signed(self):
        token = self.token
        if token.is_op("-", "+"):
            self.advance()
            self.deeper(token)
            value = self.signed()
            self.depth -= 1
            return -value if token.value == "-" else value
        return self.factor()

    def factor(self, primary=None):
        prefix = []
        if primary is not None:
            base = primary
        elif self.token.kind == "name":
            # In ``kx^2`` the power belongs to x alone: split names keep their pieces apart.
            *prefix, base = self.name(self.advance())
        else:
            base = self.primary()
        return _product([*prefix, self.exponent_of(base)])

    def exponent_of(self, base):
        token = self.token
        if token.kind == "sup":
            self.advance()
            return _power(base, sympy.Integer(token.value), token)
        if token.is_op("^"):
            self.advance()
            self.deeper(token)
            self.powers += 1
            if self.powers > LIMITS.powers:
                raise ParseFailure("powers_too_deep", token.start, token.end, limit=LIMITS.powers)
            exponent = self.signed()
            self.powers -= 1
            self.depth -= 1
            return _power(base, exponent, token)
        return base

    # -- primaries -------------------------------------------------------------

    def primary(self):
        token = self.token
        if token.kind == "num":
            self.advance()
            return sympy.Rational(token.value)
        if token.kind == "name":
            return _product(self.name(self.advance()))
        if token.kind == "func":
            self.advance()
            return self.function(token)
        if token.kind == "deriv":
            self.advance()
            return self.leibniz(token)
        if token.kind == "sum":
            self.sums.append(self.advance())
            self.summed = True
            return _SUM
        if token.kind == "frac":
            self.advance()
            numerator = self.argument(token)
            return _quotient(numerator, self.argument(token), token)
        if token.kind == "sqrt":
            self.advance()
            if self.token.is_op("[") and token.value == "\\sqrt":  # \sqrt[3]{x}
                index = self.group()
                return _power(self.argument(token), 1 / index, token)
            return sympy.sqrt(self.argument(token))
        if token.kind == "op" and token.value in _OPENERS:
            return self.group()
        self.fail_here()

    def group(self):
        opener = self.advance()
        self.deeper(opener)
        value = self.over()
        self.expect(_OPENERS[opener.value], opener)
        self.depth -= 1
        return value

    def argument(self, owner: Token):
        """The argument of ``\\frac``, ``\\sqrt`` or ``√``: a group, or a single token as in TeX."""
        token = self.token
        if token.kind == "op" and token.value in _OPENERS:
            return self.group()
        if token.kind in ("num", "name", "frac", "sqrt", "func"):
            self.deeper(owner)  # √√√…x nests as deeply as brackets do
            value = self.primary()
            self.depth -= 1
            return value
        if token.kind == "end":
            raise ParseFailure("missing_arguments", owner.start, owner.end, name=self.source(owner))
        self.fail_here()

    def function(self, token: Token):
        name = token.value
        if name == "diff":
            return self.diff(token)
        power = None
        if self.token.kind == "sup" or self.token.is_op("^"):
            power = self.function_power(token)
        bare = not (self.token.kind == "op" and self.token.value in _OPENERS)
        if bare:  # a bracketed argument counts its own level
            self.deeper(token)
        argument, after = self.function_argument(token)
        value = _apply(name, argument, token, self.context)
        if bare:
            self.depth -= 1
        value = value if power is None else _power(value, sympy.Integer(power), token)
        return value if after is sympy.S.One else value * after  # × 1 would cost a sympy product

    def function_power(self, function: Token) -> int:
        """``sin^2 θ``, ``\\sin^{2}\\theta``, ``sin²θ``: the power of the function's value."""
        token = self.advance()
        if token.kind == "sup":
            value = str(token.value)
        else:
            braced = self.token.is_op("{", "(")
            if braced:
                opener = self.advance()
            value = ""
            if self.token.is_op("-"):
                value = "-"
                self.advance()
            if self.token.kind != "num":
                raise ParseFailure("function_power", token.start, self.token.end)
            value += self.advance().value
            if braced:
                self.expect(_OPENERS[opener.value], opener)
        if value == "-1":
            raise ParseFailure("function_inverse", function.start, self.tokens[self.i - 1].end, name=function.value)
        if not value.isdigit() or not 1 <= int(value) <= 9:
            raise ParseFailure("function_power", token.start, self.tokens[self.i - 1].end)
        return int(value)

    def function_argument(self, function: Token, name: str | None = None):
        """A bracketed argument, or a bare one: ``sin θ``, ``sin 2θ``, ``cos θ₁²``, ``\\sin\\frac{θ}{2}``;
        and what follows it in the same glued name but is not in it (see :meth:`name_argument`)."""
        token = self.token
        if token.kind == "op" and token.value in _OPENERS:
            return self.group(), sympy.S.One
        if token.kind == "num":
            coefficient = self.primary()
            if self.token.kind == "name":
                argument, after = self.name_argument(name or function.value)
                return self._times_time(coefficient * argument, after, name or function.value)
            return self.factor(coefficient), sympy.S.One
        if token.kind == "name":
            argument, after = self.name_argument(name or function.value)
            return self._times_time(argument, after, name or function.value)
        if token.kind in ("frac", "sqrt"):
            return self.factor(), sympy.S.One
        if token.kind == "func":
            return self.primary(), sympy.S.One
        if token.kind == "end" or token.kind == "sep" or token.kind == "op":
            raise ParseFailure("missing_argument", function.start, function.end, name=self.source(function))
        self.fail_here()

    def _times_time(self, argument, after, function: str):
        """``cos ω t`` and TeX's ``\\cos\\omega t`` as cos(ωt), as ``cos ωt`` is: a bare angle of the
        problem's constants, then t on its own, is a phase that grows in time (cos(ω)·t is no
        quantity anyone writes). Not where the angle holds the motion (``sin θ t``), nor t raised
        to a power; otherwise the argument and what follows it, as they were."""
        token = self.token
        if (
            function not in _ANGLE_FUNCTIONS
            or after is not sympy.S.One
            or not (token.kind == "name" and token.value.raw == "t" and not token.value.dots + token.value.primes)
            or not argument.free_symbols
            or argument.has(TIME)
        ):
            return argument, after
        following = self.tokens[self.i + 1]  # t is no last token: the end is
        if following.kind == "sup" or following.is_op("^", "("):
            return argument, after
        self.advance()
        return argument * TIME, after

    def name_argument(self, function: str):
        """A glued name as a function's bare argument, and the factor after it that is not in it.
        A power on a trigonometric function's bare argument (``sin θ^2``) is refused as ambiguous.

        ``cos ωt`` is cos(ωt) and ``sin kx`` sin(kx), but ``sin²θφ̇²`` is sin²θ · φ̇²: a velocity
        or an acceleration is never part of an angle, so a trigonometric function's argument ends
        before one (``sqrt lθ̇`` stays √(lθ̇)).
        """
        named = self.token
        *prefix, base = self.name(self.advance())
        pieces = [*prefix, base]
        angle = function in _ANGLE_FUNCTIONS
        cut = next(
            (i for i, piece in enumerate(pieces) if angle and i and isinstance(piece, sympy.Derivative)), len(pieces)
        )
        if cut == len(pieces):
            if angle and (self.token.kind == "sup" or self.token.is_op("^")):
                # sin θ² is sin(θ²) to a mathematician and sin²θ to most who write it in a Lagrangian
                raise ParseFailure(
                    "function_argument_power", named.start, self.token.end, name=function, argument=self.source(named)
                )
            return sympy.Mul(*prefix, self.exponent_of(base)), sympy.S.One
        return sympy.Mul(*pieces[:cut]), sympy.Mul(*pieces[cut:-1], self.exponent_of(base))

    def diff(self, token: Token):
        """``diff(θ, t)``, ``diff(θ, t, 2)`` and sympy's ``Derivative(θ(t), (t, 2))``: time
        derivatives written as a call."""
        if not self.token.is_op("("):
            raise ParseFailure("diff_usage", token.start, token.end)
        opener = self.advance()
        self.deeper(opener)
        target = self.expr()
        order = 0
        while self.token.is_op(","):
            self.advance()
            variable = self.token
            if self._is_time():
                self.advance()
                order += 1
            elif variable.kind == "num" and order == 1 and variable.value.isdigit():
                self.advance()
                order = int(variable.value)
            elif order == 0 and variable.is_op("(") and self._is_time(1) and self.tokens[self.i + 2].is_op(","):
                counted = self.tokens[self.i + 3]
                if not (counted.kind == "num" and counted.value.isdigit() and self.tokens[self.i + 4].is_op(")")):
                    raise ParseFailure("diff_usage", variable.start, counted.end)
                self.i += 5
                order = int(counted.value)
            else:
                raise ParseFailure("diff_usage", variable.start, variable.end)
        if not self.token.is_op(")") or order == 0:
            raise ParseFailure("diff_usage", token.start, self.token.end)
        self.advance()
        self.depth -= 1
        return self.differentiate(target, order, token)

    def _is_time(self, ahead: int = 0) -> bool:
        token = self.tokens[self.i + ahead]
        return token.kind == "name" and canonical_name(token.value.raw) == "t" and not token.value.primes

    def leibniz(self, token: Token):
        """``d/dt (…)``, ``\\frac{d}{dt}\\left(…\\right)``, ``dθ/dt``, ``\\frac{d^2x}{dt^2}``: the time derivative
        of the factor that follows (rewritten to this token by :func:`_leibniz`).

        A target written inside the notation is only that: in ``\\frac{dx}{dt}^2`` the square
        is the derivative's, as in (dx/dt)², not x²'s.
        """
        order, inside = token.value
        if self.token.kind == "end":
            raise ParseFailure("missing_argument", token.start, token.end, name=self.source(token))
        self.deeper(token)
        target = self.group() if inside else self.factor()
        self.depth -= 1
        return self.differentiate(target, order, token)

    def differentiate(self, target, order: int, token: Token):
        if order > LIMITS.derivative_order:
            raise ParseFailure("derivative_order", token.start, self.tokens[self.i - 1].end)
        if _is_coordinate(target, self.context):  # diff(θ, t): built directly, as θ̇ is
            return self.context.derivative(target, order)
        if isinstance(target, sympy.Derivative) and _is_coordinate(target.expr, self.context):
            total = order + target.derivative_count
            if total > LIMITS.derivative_order:
                raise ParseFailure("derivative_order", token.start, self.tokens[self.i - 1].end)
            return self.context.derivative(target.expr, total)
        end = self.tokens[self.i - 1].end
        if not within_diff_budget(target, order):
            raise ParseFailure("diff_too_large", token.start, end)
        own = sorted((symbol for symbol in target.free_symbols if self.own(symbol)), key=str)
        if own and (order > 1 or len(own) > _OWN_RATES):
            raise ParseFailure(
                "derivative_of_constant", token.start, end,
                name=self.text[token.start : end], base=unicode_name(own[0].name),
                coords=self.context.describe_coords(),
            )  # fmt: skip
        derivative = sympy.diff(target, TIME, order)
        # d/dt (m p): p is a name of the answer's own, and may change in time (p = m l² θ̇)
        derivative += sum(sympy.diff(target, symbol) * self.rate(symbol, token.start, end) for symbol in own)
        # d/dt (d/dt (m θ̇)) nests past the order cap that θ⃛ and diff(θ, t, 3) meet
        if any(d.derivative_count > LIMITS.derivative_order for d in derivative.atoms(sympy.Derivative)):
            raise ParseFailure("derivative_order", token.start, self.tokens[self.i - 1].end)
        return derivative

    # -- names -----------------------------------------------------------------

    def name(self, token: Token) -> list:
        """The values a name stands for: one, or several for a split name (``mgl``)."""
        name: Name = token.value
        pieces = list(self.resolve(name, token))  # a copy: a split is kept for the name's next use, undotted
        order = name.dots + name.primes
        if order and len(pieces) == 1 and not _is_coordinate(pieces[0], self.context):
            pieces = self._before_a_coordinate(name) or pieces
        if order == 1 and len(pieces) == 1 and self.own(pieces[0]):
            pieces[0], order = self.rate(pieces[0], token.start, token.end), 0  # ṗ, where p = m l² θ̇
        elif not order and len(pieces) == 1 and self.own(pieces[0]) and (base := self._spelled_rate(pieces[0])):
            pieces[0] = self.rate(base, token.start, token.end)  # pdot, as ṗ
        if order:
            last = pieces[-1]
            if not _is_coordinate(last, self.context):
                base = canonical_name(name.raw) if len(pieces) == 1 else str(last)
                raise ParseFailure(
                    "derivative_of_constant", token.start, token.end,
                    name=self.source(token), base=unicode_name(base), coords=self.context.describe_coords(),
                )  # fmt: skip
            if order > LIMITS.derivative_order:
                raise ParseFailure("derivative_order", token.start, token.end)
            pieces[-1] = self.context.derivative(last, order)
        if len(pieces) == 1 and _is_coordinate_or_derivative(pieces[0], self.context):
            self._skip_time_argument()
        values, i = [], 0
        while i < len(pieces):
            value, i = self.chain(pieces, i, token)
            values.append(value)
        return values

    def _spelled_rate(self, value: sympy.Symbol) -> sympy.Symbol | None:
        """``xdot`` for a name of the answer's own, x (not the problem's): x, whose rate it is, as
        of ``ẋ``; None for any other name, and for ``xddot`` (a rate of a rate is not read)."""
        split = split_derivative(value.name)
        if split is None and value.name.endswith("dot") and not value.name.endswith("ddot"):
            split = (canonical_name(value.name.removesuffix("dot").rstrip("_")), 1)  # p_thetadot: p_θ's
        if split is None or split[1] != 1 or "dot" not in value.name or not split[0]:  # x_d may be a name
            return None
        base = sympy.Symbol(split[0])
        return base if self.own(base) and split[0] not in self.context.coords else None

    def _before_a_coordinate(self, name: Name) -> list | None:
        """``γẋ`` where γ is not the problem's (the answer may define it: ``2γ = b/m``): the dot
        is on x, so the name is γ times ẋ. A glued dotted name that ends in a coordinate is an
        undefined name times that coordinate; None when it does not end in one."""
        canonical = canonical_name(name.raw)
        endings = [c for c in self.context.coords if canonical.endswith(c) and len(canonical) > len(c)]
        if not endings:
            return None
        coordinate = max(endings, key=len)
        prefix = canonical[: -len(coordinate)]
        if prefix.endswith("_") or not _PLAIN_NAME.fullmatch(prefix):
            return None  # ṗ_θ: θ is p's subscript, and the dot p's
        return [self.lookup(prefix) or sympy.Symbol(prefix), self.context.coords[coordinate]]

    def chain(self, pieces, i, token):
        """Pieces of a split name, where a function piece takes the piece after it (``mglsintheta``)."""
        piece = pieces[i]
        if isinstance(piece, str):  # a function name
            if i + 2 < len(pieces) and isinstance(pieces[i + 1], sympy.Integer) and not isinstance(pieces[i + 2], str):
                return _apply(piece, pieces[i + 1] * pieces[i + 2], token, self.context), i + 3  # sin2θ is sin(2θ)
            if i + 1 < len(pieces):
                argument, j = self.chain(pieces, i + 1, token)
                return _apply(piece, argument, token, self.context), j
            argument, after = self.function_argument(token, piece)
            value = _apply(piece, argument, token, self.context)
            return (value if after is sympy.S.One else value * after), i + 1
        return piece, i + 1

    def _skip_time_argument(self) -> None:
        """``theta(t)`` is the coordinate itself; so are Mathematica's ``θ[t]`` (``θ'[t]``) and sympy's
        LaTeX ``\\theta{\\left(t \\right)}``, whose brace holds the bracket."""
        braced = self.token.is_op("{")
        at = self.i + braced
        if self._is_time_argument(at) and (not braced or self.tokens[at + 3].is_op("}")):
            self.i = at + 3 + braced

    def _is_time_argument(self, i: int) -> bool:
        """Whether the tokens at ``i`` are ``(t)`` or ``[t]``."""
        t = self.tokens
        closer = _OPENERS.get(t[i].value) if t[i].is_op("(", "[") else None
        return closer is not None and _is_raw(t[i + 1], "t") and t[i + 2].is_op(closer)

    def resolve(self, name: Name, token: Token) -> list:
        """The meaning of a name: one piece, or several when known symbols are juxtaposed."""
        canonical = canonical_name(name.raw)
        whole = self.lookup(canonical)
        if name.unit:  # rad in \mathrm{rad/s}: a unit's own name, unless the problem uses it for one of its own
            if whole is not None:
                raise ParseFailure("unit_is_a_name", token.start, token.end, name=self.source(token))
            return [sympy.Symbol(canonical)]
        if whole is not None:
            return [whole]
        if _GREEK_NAME.match(canonical):
            # ω₀t is ω₀·t where ω₀ and t are both known, as m₁x is m₁·x; else one name: lambda is λ, never l·a·m·b·d·a
            pieces = self.split(name.raw, token) if _NUMBERED_THEN_LETTERS.search(canonical) else None
            return pieces or [sympy.Symbol(canonical)]
        if canonical == "dt" and "d" not in self.context.known:
            # d/dt, dθ/dt and \frac{d\theta}{dt} would otherwise be read as quotients, and the d's cancel.
            raise ParseFailure("leibniz", token.start, token.end)
        pieces = self.split(name.raw, token)
        if pieces:
            return pieces
        # w for ω, th₁ for θ₁: the last reading of a name, after the problem's own names and splits
        greek = None if name.tex else stand_in(canonical)
        if greek is not None and (whole := self.lookup(greek)) is not None:
            return [whole]
        if name.tex and canonical in CONSTANT_WORDS:
            return [sympy.Symbol(canonical)]  # a word, not c·o·n·s·t: the constant a student may add
        if name.tex:
            return self.tex_letters(name.raw)
        if self.token.is_op("(") and self.token.start == token.end and len(canonical) > 1 and not name.primes:
            pieces = self._with_one_undefined(name.raw, token)
            if pieces:
                return pieces
            # eval(x), open(f), Integer(1): a call of something that is no function here
            known = ", ".join(sorted(set(FUNCTION_NAMES)))
            raise ParseFailure("unknown_function", token.start, token.end, name=self.source(token), known=known)
        return [sympy.Symbol(canonical)]

    def _with_one_undefined(self, raw: str, token: Token) -> list | None:
        """``mgL(1 − cos θ)`` where the problem has m, g and l: a glued name before a bracket, of the
        problem's names and one letter it does not have, as m·g·L. So L is told as a name the problem
        does not define, as in ``m g L(1 − cos θ)``, not mgL as a function we do not know. None where
        no one letter, or more than one, makes such a reading: ``foo(x)`` and ``eval(x)`` stay unknown
        functions, each of letters the problem has not."""
        readings = []
        for i, letter in enumerate(raw):
            before, after = raw[:i], raw[i + 1 :]
            if not (letter.isascii() and letter.isalpha()) or self.lookup(letter) is not None:
                continue  # e and t mean something here
            if after[:1] == "_" or after[:1].isdigit():
                continue  # mgL_1: the subscript is the letter's, a name no split here reads
            pieces = [self._pieces_of(before, token), self._pieces_of(after, token)]
            if None not in pieces:
                readings.append([*pieces[0], sympy.Symbol(letter), *pieces[1]])
        return readings[0] if len(readings) == 1 else None

    def _pieces_of(self, raw: str, token: Token) -> list | None:
        """The problem's names (and functions) that ``raw`` is glued of, one or more; [] for no text;
        None where it is not so glued, or a piece is no name of the problem's (η in getattr)."""
        if not raw:
            return []
        whole = self._piece(raw)
        pieces = [whole] if whole is not None else self.split(raw, token)
        return None if pieces is None or any(self.own(piece) for piece in pieces) else pieces

    def tex_letters(self, raw: str) -> list:
        """A LaTeX run that is no known name, read as TeX does: one symbol per letter."""
        pieces = []
        for match in _TEX_PIECE.finditer(raw):
            piece = match[0]
            if piece.isdecimal():
                pieces.append(sympy.Integer(piece))
            else:
                pieces.append(self.lookup(canonical_name(piece)) or sympy.Symbol(canonical_name(piece)))
        return pieces

    def lookup(self, canonical: str):
        """A name that means one thing here, or ``None``."""
        context = self.context
        if canonical == "t":
            return TIME  # the coordinates' time, even where a problem also lists t among its symbols
        if canonical in context.coords:
            return context.coords[canonical]
        if canonical in context.known:
            return context.known[canonical]
        derivative = split_derivative(canonical)
        if derivative is None and "d" not in context.known:
            derivative = split_prefixed_derivative(canonical)
        if derivative and derivative[0] in context.coords:
            return context.derivative(context.coords[derivative[0]], derivative[1])
        if canonical == "pi":
            return sympy.pi
        if canonical == "e":
            return sympy.E
        return None

    def split(self, raw: str, token: Token) -> list | None:
        """``mgl`` → m, g, l when each is known: the split into fewest known pieces.

        Returns ``None`` when no split exists; refuses a name with two equally short splits.
        """
        if raw not in self.splits:  # an answer repeats its names: split each once
            self.splits[raw] = self._split(raw, token)
        return self.splits[raw]

    def _split(self, raw: str, token: Token) -> list | None:
        n = len(raw)
        best: list[list | None] = [None] * (n + 1)  # best[i]: the fewest-piece splits of raw[:i]
        best[0] = [[]]
        for end in range(1, n + 1):
            for start in range(max(0, end - LIMITS.name), end):
                if best[start] is None:
                    continue
                if raw[start] == "_":
                    continue  # an underscore joins a piece to the one before (m_l is m·l, once)
                piece = raw[start:end].rstrip("_")
                meaning = self._piece(piece)
                if meaning is None and piece in _SPELLED:
                    meaning = sympy.Symbol(canonical_name(piece))  # γ glued to known names: γ·x, γ undefined
                candidates = [[*split, (piece, meaning)] for split in best[start]]
                if meaning is None and piece.isdecimal():
                    # a number inside a name only as a function's coefficient, as in sin2θ:
                    # elsewhere m1 must stay m₁, never m·1
                    meaning = sympy.Integer(piece)
                    candidates = [
                        [*split, (piece, meaning)] for split in best[start] if split and isinstance(split[-1][1], str)
                    ]
                if meaning is None or not candidates:
                    continue
                if best[end] is None or len(candidates[0]) < len(best[end][0]):
                    best[end] = candidates[:2]
                elif len(candidates[0]) == len(best[end][0]):
                    best[end] = (best[end] + candidates)[:2]
        if best[n] is None or len(best[n][0]) < 2:
            return None
        if len(best[n]) > 1:
            first, second = ("·".join(p for p, _ in split) for split in best[n][:2])
            raise ParseFailure(
                "ambiguous_name", token.start, token.end, name=self.source(token), first=first, second=second
            )
        return [meaning for _, meaning in best[n][0]]

    def _piece(self, piece: str):
        if not piece or piece[0].isdigit():
            return None
        if piece in FUNCTION_NAMES:
            return FUNCTION_NAMES[piece]
        if piece == "e" and "e" not in self.context.known:
            return None  # m e is more likely a typo than m times Euler's number
        return self.lookup(canonical_name(piece))


def _leibniz(tokens: list[Token], context: Context) -> list[Token]:
    """Leibniz's notation rewritten to one ``deriv`` token before the target; its value is
    (order, whether the target was inside the notation, as in ``dθ/dt``, not after it).

    ``d/dt``, ``\\frac{d}{dt}``, ``dθ/dt``, ``d²x/dt²``, ``\\frac{d\\theta}{dt}``, ``\\frac{d^2 x}{dt^2}``;
    not where the problem itself defines d or dt as symbols.
    """
    if {"d", "dt"} & set(context.known) or not any(_is_raw(token, "dt") or _is_raw(token, "t") for token in tokens):
        return tokens  # no dt (nor d t) anywhere: nothing to rewrite
    return _leibniz_in(tokens, context.coords, context.known)


def _leibniz_in(tokens: list[Token], coords: Collection[str], known: Collection[str] = ()) -> list[Token]:
    out: list[Token] = []
    i = 0
    while i < len(tokens):
        found = _leibniz_at(tokens, i, coords, known)
        if found is None:
            out.append(tokens[i])
            i += 1
            continue
        order, target, end = found
        out.append(Token("deriv", (order, bool(target)), tokens[i].start, tokens[end - 1].end))
        if len(target) > 3:  # d(m d(x)/dt)/dt: a bracket read whole may hold Leibniz's notation of its own
            target = _leibniz_in([*target, Token("end", None, target[-1].end, target[-1].end)], coords, known)[:-1]
        out += target
        i = end
    return out


def _is_lagrange(terms: list[tuple[str, str]]) -> bool:
    """Whether an operator's terms (sign, quotient's name) are d/dt(∂L/∂q̇) − ∂L/∂q, perhaps + ∂F/∂q̇
    (Rayleigh's function, as F, R or D): not ∂V, nor q and q̇ swapped, nor a minus before ∂F."""
    (_, momentum), (_, force), *dissipation = terms
    if not force.startswith("dL_d") or momentum != force + "dot":
        return False
    velocity = momentum.removeprefix("dL")
    return all(sign == "+" and name in (f"d{f}{velocity}" for f in "FRD") for sign, name in dissipation)


def _as_system(tokens: list[Token]) -> list[Token]:
    """Equations written one after another as people write them: ``eq₁, eq₂``, ``eq₁ and eq₂`` or
    ``eq₁, where eq₂`` (each side of the comma or the word an equation, or a chain such as
    ``p = … = const``) separated as ``;`` separates them, and
    the numbers of a system's equations, ``(1) eq₁ ⏎ (2) eq₂``, ``eq₁ (1) ⏎ eq₂ (2)``, ``(a) …`` or
    ``(i) …``, left out when every equation has its own, in order: they are labels, not factors.
    """
    if not any(token.kind == "sep" or token.is_op(",", ";") or _is_joining_word(token) for token in tokens):
        return tokens  # one item, no comma: most answers
    top = _top_level(tokens)
    pieces = _split_at(
        tokens, top, lambda token: token.is_op(",", ";") or token.kind == "sep" or _is_joining_word(token)
    )
    equations = [any(tokens[j].is_op("=") for j in piece if j in top) for piece in pieces]
    # every piece an equation; or an expression, then definitions (½ m v², where v = l θ̇), each of
    # a name: 9,81 θ + θ̈ = 0 is a decimal comma, which the parser then asks to be a point
    defined = all(tokens[piece[0]].kind == "name" for piece in pieces[1:])
    if len(pieces) > 1 and all(equations[1:]) and (equations[0] or defined):
        joins = {j for j in top if tokens[j].is_op(",") or _is_joining_word(tokens[j])}
        tokens = [Token("sep", ";", t.start, t.end) if j in joins else t for j, t in enumerate(tokens)]
    items = _split_at(tokens, top, lambda token: token.is_op(";") or token.kind == "sep")
    if len(items) < 2:
        return tokens
    if any(len(item) <= 3 for item in items):
        return tokens
    for labels in ([item[:3] for item in items], [item[-3:] for item in items]):  # before each, or after
        if labels[0] == items[0][-3:] and not all(_set_apart(tokens, label[0]) for label in labels):
            continue  # m = sin(1); m = sin(2): an argument, not an equation's number
        if all(_is_number_label(tokens, label, number) for number, label in enumerate(labels, start=1)):
            dropped = {j for label in labels for j in label}
            return [token for j, token in enumerate(tokens) if j not in dropped]
    return tokens


# what may follow a line's label, apart from it by a space: a name, a function, a fraction; not a bracket,
# a number or an operator, which go on a product as typed: (2)(m)(g), (2) (m g), (2) 3 x, (2) · x
_AFTER_LABEL = ("name", "func", "frac", "sqrt", "deriv", "partial")


def _line_labels(tokens: list[Token], context: Context) -> list[Token]:
    """A line's number or coordinate in brackets before its equation, as a document numbers it or a
    student says which coordinate it is for: ``(2) L = ½ m l² θ̇² + …``, ``(θ) m l² θ̈ = …``, left out.
    Only a whole number or a coordinate alone in round brackets that starts the answer or a line, set
    apart by a space from the name, function or fraction that follows, on a line with an ``=``. A
    factor is never bracketed so: ``(1/2) m v²``, ``(2)(m)(g)`` and ``a = b; (2) c = d`` stay products."""
    if not any(token.is_op("(") for token in tokens):
        return tokens
    dropped: set[int] = set()
    for i in range(len(tokens) - 3):
        if i and tokens[i - 1].kind != "sep":
            continue
        opener, inside, closer, after = tokens[i : i + 4]
        if not (opener.is_op("(") and closer.is_op(")") and after.kind in _AFTER_LABEL and after.start > closer.end):
            continue
        number = _is_whole_number(inside)
        coordinate = inside.kind == "name" and _is_raw(inside, inside.value.raw)
        coordinate = coordinate and canonical_name(inside.value.raw) in context.coords
        if (number or coordinate) and _one_equation(tokens, i + 3):
            dropped |= {i, i + 1, i + 2}
    return [token for j, token in enumerate(tokens) if j not in dropped] if dropped else tokens


def _one_equation(tokens: list[Token], i: int) -> bool:
    """Whether the line from ``i`` on is an equation (an ``=`` before its end) and holds no other
    number set apart in brackets: ``(1) a = b (3) c = d`` numbers two equations out of order, which
    :func:`~grader.parse.tokens.tokenize` would not read as numbers, and neither is the first."""
    equals = False
    for j in range(i, len(tokens)):
        token = tokens[j]
        if token.kind in ("sep", "end"):
            return equals
        equals = equals or token.is_op("=")
        apart = token.start > tokens[j - 1].end
        if apart and token.is_op("(") and _is_whole_number(tokens[j + 1]) and tokens[j + 2].is_op(")"):
            return False
    return equals


def _is_whole_number(token: Token) -> bool:
    return token.kind == "num" and token.value.isdecimal()


def _top_level(tokens: list[Token]) -> set[int]:
    """The positions of the tokens outside every bracket."""
    top, depth = set(), 0
    for j, token in enumerate(tokens):
        if token.kind == "op" and token.value in _OPENERS.values():
            depth -= 1
        if depth == 0:
            top.add(j)
        if token.kind == "op" and token.value in _OPENERS:
            depth += 1
    return top


def _split_at(tokens: list[Token], top: set[int], separates) -> list[list[int]]:
    """The positions of the tokens between top-level separators (the end token left out)."""
    pieces, piece = [], []
    for j, token in enumerate(tokens[:-1]):
        if j in top and separates(token):
            if piece:
                pieces.append(piece)
            piece = []
        else:
            piece.append(j)
    if piece:
        pieces.append(piece)
    return pieces


_ROMAN = ("i", "ii", "iii", "iv", "v", "vi", "vii", "viii", "ix", "x")


def _set_apart(tokens: list[Token], opener: int) -> bool:
    """Whether the bracket at ``opener`` stands apart from what comes before it, as an equation's
    number does (``θ̈ = −ω² θ (1)``): a space between, and no function before it whose argument it
    could be (``m = sin(1)``, ``sin (1)``, ``a(1)``)."""
    before = tokens[opener - 1]
    return tokens[opener].start > before.end and before.kind != "func"


def _is_number_label(tokens: list[Token], positions: list[int], number: int) -> bool:
    """Whether the tokens at ``positions`` are ``(number)``: ``(2)``, ``(b)`` or ``(ii)``."""
    opener, value, closer = (tokens[j] for j in positions)
    if not (opener.is_op("(") and closer.is_op(")")):
        return False
    if value.kind == "num":
        return value.value == str(number)
    spelled = ("abcdefghij"[number - 1], _ROMAN[number - 1]) if number <= 10 else ()
    return value.kind == "name" and not (value.value.dots or value.value.primes) and value.value.raw in spelled


def _is_joining_word(token: Token) -> bool:
    """*and*, *where* or *with* between two equations: ``θ̈ = −ω² sin θ, where ω² = g/l``."""
    return _is_raw(token, *JOINING_WORDS)


def _is_raw(token: Token, *raws: str) -> bool:
    """Whether the token is a name typed as one of ``raws``, without dots or primes."""
    return token.kind == "name" and token.value.raw in raws and not (token.value.dots or token.value.primes)


def _after_dt(tokens: list[Token], i: int) -> int | None:
    """The index after ``dt`` (or ``d t``) at ``i``, or None."""
    if i < len(tokens) and _is_raw(tokens[i], "dt"):
        return i + 1
    if i + 1 < len(tokens) and _is_raw(tokens[i], "d") and _is_raw(tokens[i + 1], "t"):
        return i + 2
    return None


def _order(tokens: list[Token], i: int) -> tuple[int, int]:
    """(order, next index) of an optional power after d or dt: ^2, ^{2}, ²."""
    if i < len(tokens) and tokens[i].kind == "sup":
        return int(tokens[i].value), i + 1
    if i + 1 < len(tokens) and tokens[i].is_op("^") and tokens[i + 1].kind == "num" and tokens[i + 1].value.isdecimal():
        return int(tokens[i + 1].value), i + 2
    if (
        i + 3 < len(tokens) and tokens[i].is_op("^") and tokens[i + 1].is_op("{")
        and tokens[i + 2].kind == "num" and tokens[i + 3].is_op("}")
    ):  # fmt: skip
        return int(tokens[i + 2].value), i + 4
    return 1, i


def _numerator(
    tokens: list[Token], coords: Collection[str], known: Collection[str] = ()
) -> tuple[int, list[Token]] | None:
    """(order, target) for ``d``, ``d²``, ``dθ``, ``d^2 x``, ``d\\theta`` or ``dθ̇``, else None; not for a
    name of its own that begins with d (``delta/dt`` is δ over dt, never d(elta)/dt)."""
    if not tokens or tokens[0].kind != "name" or tokens[0].value.primes:
        return None
    first = tokens[0]
    if first.value.raw == "d" and not first.value.dots:
        order, rest = _order(tokens, 1)
        return order, tokens[rest:]
    if first.value.raw.startswith("d") and len(tokens) == 1:  # dθ, dx: one name
        whole = canonical_name(first.value.raw)
        if whole in GREEK_NAMES or whole in coords or whole in known:
            return None
        rest, dots = first.value.raw[1:], first.value.dots
        if dots and canonical_name(rest) not in coords:
            return None  # dθ̇ is θ̇'s; but δ̇ has its dot on δ, never on "elta"
        name = Name(rest, dots=dots, tex=first.value.tex)
        return 1, [Token("name", name, first.start + 1, first.end)]
    return None


def _bracketed_numerator(tokens: list[Token], i: int) -> tuple[int, list[Token], int] | None:
    """``d(m l² θ̇)/dt`` or ``d²(…)/dt²`` at ``i``: (order, the bracket, the index after dt), else None.
    Its bracket may be any length, where :func:`_leibniz_at` looks only a few tokens ahead for the /."""
    order, opener = _order(tokens, i + 1)
    if not tokens[opener].is_op("(", "["):
        return None
    closer = _closing(tokens, opener)
    if closer is None or not tokens[closer + 1].is_op("/"):
        return None
    after_dt = _after_dt(tokens, closer + 2)
    if after_dt is None:
        return None
    dt_order, end = _order(tokens, after_dt)
    return (order, tokens[opener : closer + 1], end) if dt_order == order else None


def _leibniz_at(
    tokens: list[Token], i: int, coords: Collection[str], known: Collection[str] = ()
) -> tuple[int, list[Token], int] | None:
    token = tokens[i]
    if _is_raw(token, "d"):
        found = _bracketed_numerator(tokens, i)
        if found is not None:
            return found
    if token.is_op("("):  # (d/dt) θ, (d/dt)² θ, (d/dt)^2 θ: the operator in brackets, and its power
        inner = _leibniz_at(tokens, i + 1, coords, known)
        if inner is None or inner[:2] != (1, []) or not tokens[inner[2]].is_op(")"):
            return None
        after = inner[2] + 1
        if tokens[after].kind == "sup":
            return int(tokens[after].value), [], after + 1
        if tokens[after].is_op("^") and tokens[after + 1].kind == "num" and tokens[after + 1].value.isdigit():
            return int(tokens[after + 1].value), [], after + 2
        return 1, [], after
    if token.kind == "frac" and i + 1 < len(tokens) and tokens[i + 1].is_op("{"):
        numerator_end = _closing(tokens, i + 1)
        if numerator_end is None or not tokens[numerator_end + 1].is_op("{"):
            return None
        denominator_end = _closing(tokens, numerator_end + 1)
        if denominator_end is None:
            return None
        numerator = _numerator(tokens[i + 2 : numerator_end], coords, known)
        denominator = tokens[numerator_end + 2 : denominator_end]
        after_dt = _after_dt(denominator, 0)
        if numerator is None or after_dt is None:
            return None
        order, rest = _order(denominator, after_dt)
        if rest != len(denominator) or order != numerator[0]:
            return None
        target = numerator[1]
        if target:
            opener, closer = Token("op", "(", token.start, token.start), Token("op", ")", token.end, token.end)
            target = [opener, *target, closer]
        return order, target, denominator_end + 1
    numerator_end = i + 1
    while numerator_end < len(tokens) and not tokens[numerator_end].is_op("/") and numerator_end - i < 5:
        numerator_end += 1
    after_dt = _after_dt(tokens, numerator_end + 1) if numerator_end < len(tokens) - 1 else None
    if after_dt is None:
        return None
    numerator = _numerator(tokens[i:numerator_end], coords, known)
    if numerator is None:
        return None
    order, end = _order(tokens, after_dt)
    if order != numerator[0]:
        return None
    target = numerator[1]
    if target:
        opener, closer = Token("op", "(", token.start, token.start), Token("op", ")", token.end, token.end)
        target = [opener, *target, closer]
    return order, target, end


def _closing(tokens: list[Token], i: int) -> int | None:
    depth = 0
    for j in range(i, len(tokens)):
        if tokens[j].is_op("{", "(", "["):
            depth += 1
        elif tokens[j].is_op("}", ")", "]"):
            depth -= 1
            if depth == 0:
                return j
    return None


def _apply(name: str, argument, token: Token, context: Context):
    # sympy evaluates sin, abs or log of a constant numerically, and needs precision in
    # proportion to its size: sin(exp(exp(100))) would never return.
    if argument.is_number and not _magnitude(argument) <= _MAX_MAGNITUDE:
        raise ParseFailure("value_too_large", token.start, token.end)
    value = context.applied(name, argument)
    if holds_any(value, _NOT_A_NUMBER):
        raise ParseFailure("undefined_value", token.start, token.end)
    return value


_NOT_A_NUMBER = frozenset({sympy.zoo, sympy.nan})


def holds_any(value, atoms: frozenset) -> bool:
    """Whether any node of ``value`` is one of ``atoms`` (zoo, nan…). One walk, hashing atoms only:
    ``value.has(*atoms)`` hashes every node, then walks once more for each atom to match it, and a
    new answer's value is new to its cache."""
    return any(node.is_Atom and node in atoms for node in iterargs(value))


def _product(factors: list):
    """``sympy.Mul(*factors)``: most products the grammar builds have one factor, which is the
    product itself; sympy would hash it for its cache to say so. A non-expression goes to
    sympy, which refuses it as before."""
    if len(factors) == 1 and isinstance(factors[0], sympy.Expr):
        return factors[0]
    return sympy.Mul(*factors)


def _sum(terms: list):
    """``sympy.Add(*terms)``, as :func:`_product`: most sums the grammar builds have one term."""
    if len(terms) == 1 and isinstance(terms[0], sympy.Expr):
        return terms[0]
    return sympy.Add(*terms)


def _quotient(numerator, denominator, token: Token):
    """``\\frac{numerator}{denominator}`` or ``{numerator \\over denominator}``, refusing a division by
    zero, and a value too large to build or to check."""
    if denominator == 0:
        raise ParseFailure("division_by_zero", token.start, token.end)
    quotient = numerator * _power(denominator, sympy.Integer(-1), token)
    _check_size(quotient, token)
    return quotient


def _power(base, exponent, token: Token):
    """``base ** exponent``, refusing what would be too large to build or to check."""
    if exponent.is_Number:
        if abs(exponent) > LIMITS.exponent:
            raise ParseFailure("exponent_too_large", token.start, token.end, limit=LIMITS.exponent)
        if base.is_Rational and exponent.is_Integer:
            digits = (_digits(base.p) + _digits(base.q)) * abs(int(exponent))
            if digits > LIMITS.power_digits:
                raise ParseFailure("exponent_too_large", token.start, token.end, limit=LIMITS.exponent)
        if base == 0 and exponent.is_negative:
            raise ParseFailure("division_by_zero", token.start, token.end)
    elif exponent.is_number and not _magnitude(exponent) <= LIMITS.exponent:
        # A numeric but unevaluated exponent (sqrt(2)^(9^9), x^exp(exp(100))) is bounded by
        # its size, estimated in floats: sympy's evalf of such a tower never returns.
        raise ParseFailure("exponent_too_large", token.start, token.end, limit=LIMITS.exponent)
    value = sympy.Pow(base, exponent)
    # sympy folds (x^a)^b into x^(ab): the folded exponent must be bounded too.
    if value.is_Pow and value.exp.is_Number and abs(value.exp) > LIMITS.exponent:
        raise ParseFailure("exponent_too_large", token.start, token.end, limit=LIMITS.exponent)
    _check_size(value, token)
    return value


# names of the answer's own whose rates one d/dt may take: d/dt (m p) has one; a product of n such
# names gives n terms of n factors, and 60 of them took seconds
_OWN_RATES = 4

# operations ** (order + 1): d/dt of a product of n factors is n terms of n factors each, so
# the result grows as the square. d/dt of 63 operations, d²/dt² of 15, d³/dt³ of 7.
_DIFF_BUDGET = 4000
_MAX_MAGNITUDE = 1e300  # for constants that are not rational, just inside what a float holds


def _check_size(value, token: Token) -> None:
    """Refuse a constant too large to print or to evaluate: ((√2)^99)^99 has 146,000 digits,
    and so does the coefficient sympy multiplies out of (10⁻¹⁰⁰ l)⁻¹⁰⁰ or x·10⁹⁹·10⁹⁹·…"""
    if not value.is_number:  # a constant: is_number stops at the first symbol, free_symbols walks all
        # The parts were checked as they were built; only combining them makes new coefficients.
        for term in sympy.Add.make_args(value):
            coefficient = term.as_coeff_Mul()[0]
            if coefficient.is_Rational and too_many_digits(coefficient):
                raise ParseFailure("value_too_large", token.start, token.end)
        return
    too_large = too_many_digits(value) if value.is_Rational else not _magnitude(value) <= _MAX_MAGNITUDE
    if too_large:
        raise ParseFailure("value_too_large", token.start, token.end)


def _magnitude(value) -> float:
    """An estimate of |value| for a constant, in floats: inf where it overflows.

    Our own walk rather than evalf, which on exp(exp(exp(100))) asks for 10⁴³ bits.
    """
    try:
        return abs(_float(value))
    except (OverflowError, ValueError, ZeroDivisionError):
        return math.inf


def _float(value) -> complex:
    if value.is_Rational:
        return complex(int(value.p) / int(value.q))
    if value is sympy.pi:
        return complex(math.pi)
    if value is sympy.E:
        return complex(math.e)
    if value is sympy.I:
        return 1j
    if value.is_Add:
        return sum(_float(arg) for arg in value.args)
    if value.is_Mul:
        return math.prod(_float(arg) for arg in value.args)
    if value.is_Pow:
        return _float(value.base) ** _float(value.exp)
    function = COMPLEX.get(type(value).__name__)
    if function is None or len(value.args) != 1:
        raise ValueError(f"no float estimate for {type(value).__name__}")
    return complex(function(_float(value.args[0])))


def own_rates(value, coords) -> set[sympy.Derivative]:
    """The rates in ``value`` of names the answer defines for itself (``ṗ`` where p = m l² θ̇), as
    the parser writes them: derivatives of functions of time that are none of ``coords``."""
    return {
        rate
        for rate in value.atoms(sympy.Derivative)
        if isinstance(rate.expr, AppliedUndef) and rate.expr.func.__name__ not in coords
    }


def within_diff_budget(value, order: int = 1) -> bool:
    """Whether ``value`` is small enough to differentiate ``order`` times in t: each
    differentiation of a product multiplies its terms (see :data:`_DIFF_BUDGET`)."""
    return sympy.count_ops(value, visual=False) ** (order + 1) <= _DIFF_BUDGET


def too_many_digits(number: sympy.Rational) -> bool:
    """Whether a rational number holds more digits, numerator and denominator together, than
    :data:`LIMITS` allow an answer's constants: the parser's cap, which the checker keeps too."""
    return _digits(number.p) + _digits(number.q) > LIMITS.power_digits


def _digits(n: int) -> int:
    return 1 if n == 0 else int(math.log10(abs(n))) + 1


def _is_coordinate(value, context: Context) -> bool:
    return value in context.coordinate_set


def _is_coordinate_or_derivative(value, context: Context) -> bool:
    if isinstance(value, sympy.Derivative):
        value = value.expr
    return _is_coordinate(value, context)
