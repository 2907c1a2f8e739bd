"""How often ``compare`` agrees with STACK's public answer-test table.

Contents:
    the data         ../shared/conformance/stack/ (GRADER_STACK_DIR overrides); skipped cleanly when absent
    SCOPE, NOT_RUN   the tests run (AlgEquiv, SysEquiv, EqualComAss) and why the others are not
    CONVENTIONS      per-row reasons for deliberate differences; any other disagreement is our error
    ACCIDENTAL       rows that agree only through a bug in our checker
    DOMAIN_NOTES     why "every symbol real" changes a verdict, row by row
    ERRATA           rows whose label in the table is mathematically wrong
    not_applicable   rows we cannot express (sets, inequalities, complex numbers…), with the reason
    translate, case  STACK's caret text → what an author and a student would type to us, and the target
    judge            one row through ``compare``
    main, print_*    agreement per test, every disagreement, the notes above, the time

Run: ``python3 benchmarks/stack_conformance.py``. Target: ≥ 95 % agreement on AlgEquiv.

The table is STACK's (GPL-3.0) and stays outside this repository: the script only reads it.
"""

from __future__ import annotations

import json
import os
import re
import sys
import time
from collections import defaultdict
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from grader import AuthorError, compare, parse_answer  # noqa: E402
from grader.parse.names import FUNCTION_NAMES  # noqa: E402

DATA = Path(os.environ.get("GRADER_STACK_DIR") or ROOT.parent / "shared/conformance/stack")
TABLE = "stack_answertests.jsonl"
TIMEOUT = 2.0

SCOPE = {
    "AlgEquiv": "algebraic equivalence: what `compare` decides",
    "SysEquiv": "systems of equations: one-equation systems as our `equation` kind, larger ones not applicable",
    "EqualComAss": "equality up to commutativity and associativity: run as algebraic equality (see the rule)",
}
NOT_RUN = {
    "SubstEquiv": "equivalence up to renaming variables: we never rename a student's symbols",
    "NumRelative": "numerical tolerance tests: our `number` kind, not the algebraic checker under test here",
    "NumAbsolute": "numerical tolerance tests: our `number` kind, not the algebraic checker under test here",
    "CasEqual": "equality of Maxima's internal trees: no mathematical meaning outside Maxima",
    "AlgEquivNouns": "Maxima's noun forms (unevaluated diff/int): no counterpart in our parser",
    "stack_answertests_calculus.jsonl": "Diff, Int, Antidiff: calculus answer tests, out of scope",
}

# Rows carrying these features ask for mathematics our answer kinds do not express.
UNSUPPORTED_FEATURES = {
    "set": "sets",
    "list": "lists of expressions",
    "inequality": "inequalities",
    "not_equal": "`#` (not equal)",
    "boolean": "logic (true/false)",
    "complex": "complex numbers (%i)",
    "infinity": "infinity",
    "calculus": "derivatives or integrals in x (we have time derivatives only)",
    "sum/product": "sums and products",
    "undefined_function": "undefined functions such as F(x)",
}

# STACK spells these the Maxima way and the table rewrote them for sympy; a student
# types Euler's number as `e` and absolute values as `abs(...)` to us (`E` is a plain
# symbol in mechanics: an energy or Young's modulus).
SPELLINGS = {
    "e->E": (r"\bE\b", "e"),
    "%e->E": (r"\bE\b", "e"),
    "abs->Abs": (r"\bAbs\(", "abs("),
}

# Answers past these documented caps (README, parse/tokens.py LIMITS) are refused by
# design, as a guard against hostile input: STACK's (x-a)^6000 rows test what we exclude.
LIMIT_REFUSALS = {"too_long", "too_deep", "exponent_too_large", "number_too_large", "name_too_long"}

STATUS_OF_EXPECTED = {1: "equivalent", 0: "not_equivalent", -2: "not_equivalent", -3: "equivalent"}

# Rows where we differ from STACK on purpose, each written after looking at the row.
# A disagreement whose id is not here is counted as our error.
_SUBSCRIPT = "`x1` and `x_1` are one symbol on purpose (our parser spells them the same: θ₁, theta1, theta_1)"
_EXACT = "a decimal is read as the exact number it denotes (452.0 is 452); STACK refuses to equate floats"
_TOLERANCE = (
    "the numeric check's documented tolerance (1e-13 of the terms' scale, check/numeric.py) lets a"
    " decimal correct to 14+ digits count as the number it approximates"
)
_REAL = "every symbol is real here, and negative values break the identity: "
_RATIO = (
    "the same roots, each as often: e^(st) never vanishes, so s²e^(st) = 0 and s² = 0 share their double root;"
    " STACK wants the two sides' differences in a constant ratio"
)
CONVENTIONS = {
    "stack-AlgEquiv-006": _SUBSCRIPT,
    "stack-AlgEquiv-096": _SUBSCRIPT,
    "stack-AlgEquiv-032": _EXACT,
    "stack-AlgEquiv-043": _EXACT + " (100.4 − 80.0 is exactly 20.4)",
    "stack-AlgEquiv-037": _EXACT + " (0.99999999 is exactly 99999999/10⁸, not 99999998/99999999)",
    "stack-AlgEquiv-246": _RATIO,
    "stack-AlgEquiv-034": _TOLERANCE,
    "stack-AlgEquiv-040": _TOLERANCE,
    "stack-AlgEquiv-083": _TOLERANCE,
    "stack-AlgEquiv-092": _REAL + "((x−2)³)^k ≠ (x−2)^(3k) when x < 2 and k is not an integer",
    "stack-AlgEquiv-155": _REAL + "log(a²b) = 2 log a + log b needs a, b > 0 (our positive default agrees)",
    "stack-AlgEquiv-272": (
        "√ of a negative is imaginary and √ is one-to-one, so √x = √y says x = y;"
        " STACK's equation test reads √x as defined for x ≥ 0 only"
    ),
    # Rows where the principal branch (sympy's, and ours) disagrees with STACK's simplifier.
    "stack-AlgEquiv-080": _REAL + "√(1/x) = i/√|x| but 1/√x = −i/√|x| for x < 0",
    "stack-AlgEquiv-099": _REAL + "√(k/m)·√(m/k) = −1 when k/m < 0",
    "stack-AlgEquiv-101": _REAL + "1/√(k/m) = −√(m/k) when k/m < 0",
    "stack-AlgEquiv-127": _REAL + "(−cos x)^n ≠ (−1)^n cos(x)^n when cos x < 0 and n is not an integer",
    "stack-AlgEquiv-167": _REAL + "−log u and log(1/u) differ by 2πi when u < 0 (|x| > 1)",
}

# Rows that agree with STACK only through a bug in our checker, printed so that nobody
# counts on them. (Empty since signed zeros, roots on the grid and poles were fixed.)
ACCIDENTAL: dict[str, str] = {}

# Why declaring every symbol real changes our verdict, for each row where it does.
_POSITIVE = "the two agree for positive symbols only: "
DOMAIN_NOTES = {
    "stack-AlgEquiv-071": _POSITIVE + "√(x²) = |x|",
    "stack-AlgEquiv-075": _POSITIVE + "√(x²) = |x|",
    "stack-AlgEquiv-088": _POSITIVE + "(a^b)^c = a^(bc) needs a > 0",
    "stack-AlgEquiv-208": _POSITIVE + "(a^b)^c = a^(bc) needs a > 0",
    "stack-AlgEquiv-155": _POSITIVE + "log(a²b) = 2 log a + log b needs a, b > 0",
    "stack-AlgEquiv-210": _POSITIVE + "(u^(1/u))^(u+1) = u^((u+1)/u) needs u = n + 1 > 0",
    "stack-AlgEquiv-092": _POSITIVE + "((x−2)³)^k = (x−2)^(3k) needs x > 2",
    "stack-AlgEquiv-254": "a positive a is never 0, and multiplying by it keeps the relation; a real a may be 0",
    "stack-AlgEquiv-259": _POSITIVE + "x² = y² also allows y = −x",
    "stack-AlgEquiv-273": _POSITIVE + "x² = a also allows x = −√a",
    "stack-AlgEquiv-277": _POSITIVE + "x² + y² = 1 also allows y = −√(1 − x²)",
    "stack-AlgEquiv-333": _POSITIVE + "|x| = |y| also allows y = −x",
    "stack-AlgEquiv-099": _POSITIVE + "√(k/m)·√(m/k) = −1 when k/m < 0",
    "stack-AlgEquiv-246": "for s > 0 neither relation holds anywhere: no root to compare, the ratio test decides",
    "stack-AlgEquiv-269": "for a, b > 0 neither relation holds anywhere: no root to compare, the ratio test decides",
    "stack-SysEquiv-018": _POSITIVE + "(x − 1)(x + 1) = 0 also allows x = −1",
    "stack-SysEquiv-019": _POSITIVE + "(x − 1)(x + 1)y = 0 also allows x = −1 and y = 0",
}

# Rows whose label in the table is mathematically wrong, checked by hand (and with sympy):
# the target is the mathematics, and the row counts under "STACK convention".
ERRATA = {
    "stack-AlgEquiv-476": (
        "not_equivalent",
        "labelled -3 (mathematically equal), but b(√2−1)/3·(1+√2) = b/3 ≠ b: the relations differ",
    ),
    "stack-AlgEquiv-157": (
        "equivalent",
        "labelled 0, but |x−3|·|x+3| = |x²−9| and both logs are of positive reals: equal wherever defined (-3)",
    ),
}

# EqualComAss: STACK's 0 for an answer that is mathematically equal but written in
# another form (ansnote "AlgEquiv-true"). We judge mathematical equality by design.
FORM_ONLY = "(AlgEquiv-true)"


@dataclass(frozen=True)
class Case:
    """One row as we run it."""

    row: dict
    expected: str  # the teacher's answer, as the author would write it to us
    submitted: str  # the student's answer, as typed
    kind: str
    target: str  # the status we must return ("author_error" when the teacher's answer must be refused)
    by_math: bool  # STACK's verdict is a convention; the target is mathematics'


def load(path: Path) -> list[dict]:
    with path.open(encoding="utf-8") as lines:
        return [json.loads(line) for line in lines if line.strip()]


def calls(text: str) -> list[tuple[str, int]]:
    """Each function call in ``text``: its name and how many arguments it has."""
    found = []
    for match in re.finditer(r"([A-Za-z_][A-Za-z_0-9]*)\(", text):
        depth, commas = 0, 0
        for char in text[match.end() - 1 :]:
            depth += char in "([{"
            depth -= char in ")]}"
            commas += char == "," and depth == 1
            if depth == 0:
                break
        found.append((match.group(1), commas + 1))
    return found


def items(text: str) -> list[str] | None:
    """The items of a bracketed list ``[a, b]``, or None when ``text`` is not one."""
    text = text.strip()
    if not (text.startswith("[") and text.endswith("]")):
        return None
    parts, depth, start = [], 0, 1
    for i, char in enumerate(text[1:-1], start=1):
        depth += char in "([{"
        depth -= char in ")]}"
        if char == "," and depth == 0:
            parts.append(text[start:i])
            start = i + 1
    return [*parts, text[start:-1]]


def not_applicable(row: dict) -> str | None:
    """Why we cannot run this row, or None."""
    if not row.get("translatable", True):
        return "not translatable from Maxima"
    features = [UNSUPPORTED_FEATURES[f] for f in row["features"] if f in UNSUPPORTED_FEATURES]
    if row["test"] == "SysEquiv":
        # Our `equations` kind compares equations of motion (linear in the accelerations);
        # STACK compares solution sets of polynomial systems. One equation is our `equation`.
        system = items(row["tans_caret"]) or [row["tans_caret"]]
        if len(system) > 1:
            return f"a system of {len(system)} algebraic equations (our `equations` kind is for equations of motion)"
        features = [f for f in features if f != UNSUPPORTED_FEATURES["list"]]
    if features:
        return ", ".join(features)
    for field in ("tans_caret", "sans_caret"):
        answer = parse_answer(translate(row, field))
        if not answer.ok and answer.code in LIMIT_REFUSALS:
            return f"beyond our documented input limits ({answer.code})"
    text = translate(row, "tans_caret") + " " + translate(row, "sans_caret")
    for name, arguments in calls(text):
        if name not in FUNCTION_NAMES:
            return f"`{name}` is not in our function vocabulary"
        if arguments > 1:
            return f"`{name}` with {arguments} arguments (a logarithm's base…) is not in our vocabulary"
    return None


def translate(row: dict, field: str) -> str:
    text = row[field]
    for rewrite in row["rewrites"]:
        if rewrite in SPELLINGS:
            pattern, spelling = SPELLINGS[rewrite]
            text = re.sub(pattern, spelling, text)
    return text


def target(row: dict) -> tuple[str, bool]:
    """The status we must return, and whether it is mathematics' rather than STACK's verdict."""
    if row["id"] in ERRATA:
        return ERRATA[row["id"]][0], True
    expected = row["expected"]
    if expected == -1:
        return ("author_error" if "TAns" in row["ansnote"] else "invalid"), False
    if row["test"] == "EqualComAss" and expected == 0 and FORM_ONLY in row["ansnote"]:
        return "equivalent", True
    return STATUS_OF_EXPECTED[expected], expected in (-2, -3)


def case(row: dict) -> Case:
    expected, submitted = translate(row, "tans_caret"), translate(row, "sans_caret")
    if row["test"] == "SysEquiv":
        # An author writes one equation without brackets; the student's text stays as typed.
        (only,) = items(expected) or [expected]
        expected = only
        # A teacher's "[1]" is no equation: an expression part, which a student's equation does not answer.
        kind = "equation" if "=" in only else "expression"
    else:
        kind = "equation" if "=" in expected else "expression"
    return Case(row, expected, submitted, kind, *target(row))


def symbols(*texts: str) -> set[str]:
    """The names of the symbols in the texts that can be read."""
    names = set()
    for text in texts:
        answer = parse_answer(text)
        if answer.ok:
            values = answer.value if isinstance(answer.value, tuple) else (answer.value,)
            names |= {symbol.name for value in values for symbol in value.free_symbols}
    return names


@dataclass(frozen=True)
class Result:
    status: str
    feedback: str
    seconds: float
    read_as: str = ""
    method: str = ""


def judge(c: Case, *, real: bool = True) -> Result:
    """One row through ``compare``.

    STACK's questions use every symbol of either answer freely, so the problem defines
    them all (otherwise `1` against `cos(x)^2+sin(x)^2` would be refused for `x`), and
    STACK's x, a, n may be negative: each is real unless ``real`` is False.
    """
    names = sorted(symbols(c.expected, c.submitted))
    domains = dict.fromkeys(names, "real") if real else None
    start = time.perf_counter()
    try:
        verdict = compare(c.expected, c.submitted, kind=c.kind, known=names, domains=domains, timeout=TIMEOUT)
    except AuthorError as error:
        return Result("author_error", str(error).splitlines()[0], time.perf_counter() - start)
    seconds = time.perf_counter() - start
    return Result(verdict.status, " ".join(verdict.feedback), seconds, verdict.read_as, verdict.method)


def _judged(applicable: dict[str, list[tuple[Case, Result]]]) -> list[tuple[Case, Result]]:
    return [pair for test in SCOPE for pair in applicable[test]]


def _agrees(c: Case, result: Result) -> bool:
    return result.status == c.target


def main() -> int:
    if not (DATA / TABLE).is_file():
        print(f"STACK conformance skipped: {DATA / TABLE} is not there (set GRADER_STACK_DIR to run it).")
        return 0
    start = time.perf_counter()
    rows = [row for row in load(DATA / TABLE) if row["test"] in SCOPE]
    applicable: dict[str, list[tuple[Case, Result]]] = defaultdict(list)
    skipped: dict[str, dict[str, list[str]]] = defaultdict(lambda: defaultdict(list))
    for row in rows:
        reason = not_applicable(row)
        if reason:
            skipped[row["test"]][reason].append(row["id"])
        else:
            c = case(row)
            applicable[row["test"]].append((c, judge(c)))
    # Run again with our positive default, to show where declaring the symbols real mattered.
    defaults = [(c, result, judge(c, real=False)) for c, result in _judged(applicable)]
    sensitive = [(c, real, default) for c, real, default in defaults if default.status != real.status]
    elapsed = time.perf_counter() - start

    print_header()
    print_agreement(applicable, skipped)
    print_disagreements(applicable)
    print_errata()
    print_accidental(applicable)
    print_sensitive(sensitive)
    print_not_applicable(skipped)
    slowest = max(_judged(applicable), key=lambda pair: pair[1].seconds)
    print(
        f"\nTime: {elapsed:.1f} s for {len(rows)} rows ({2 * len(_judged(applicable))} compare calls, timeout"
        f" {TIMEOUT:g} s each; slowest real-domain call {1000 * slowest[1].seconds:.0f} ms, {slowest[0].row['id']})."
    )
    return 0


def print_header() -> None:
    print(f"STACK answer tests ({DATA / TABLE}) through grader.compare\n")
    print("Run:")
    for test, meaning in SCOPE.items():
        print(f"  {test:<14} {meaning}")
    print("Not run:")
    for test, why in NOT_RUN.items():
        print(f"  {test:<14} {why}")
    print(
        "\nRules:\n"
        "  * Typed text is the caret form, with Maxima's `e` for Euler's `E` and `abs(` for `Abs(`.\n"
        "  * The problem defines every symbol of either answer, each declared real (STACK's x, a, n may be\n"
        "    negative), so our positive default for parameters does not apply; where it matters is listed.\n"
        "  * STACK 1 → equivalent, 0 → not_equivalent, -1 → invalid (student) or AuthorError (teacher);\n"
        "    -2/-3 (STACK's verdict is not mathematics') → mathematics, counted as 'STACK convention'.\n"
        "  * EqualComAss: a 0 that STACK gives only because the form is not simplified (ansnote\n"
        "    'AlgEquiv-true') is judged by mathematics, 'equivalent': we grade values, not forms.\n"
        "    Its 1s and its mathematically false 0s are STACK's verdict as it stands.\n"
        "  * SysEquiv: a one-equation system runs as our `equation` kind (the author writes the equation\n"
        "    without brackets, the student's text stays as typed); larger systems are not applicable.\n"
        "  * A disagreement is a 'convention' only where CONVENTIONS explains it; otherwise it is our error.\n"
    )


def print_agreement(applicable, skipped) -> None:
    columns = ("agreement", "+ conventions", "STACK verdict", "STACK convention", "n/a")
    print(f"{'test':<12} {columns[0]:>20} {columns[1]:>14} {columns[2]:>14} {columns[3]:>17} {columns[4]:>4}")
    for test in SCOPE:
        results = applicable[test]
        size = max(len(results), 1)
        agree = [c for c, r in results if _agrees(c, r)]
        explained = len(agree) + sum(c.row["id"] in CONVENTIONS for c, r in results if not _agrees(c, r))
        own = f"{sum(not c.by_math for c in agree)}/{sum(not c.by_math for c, _ in results)}"
        convention = f"{sum(c.by_math for c in agree)}/{sum(c.by_math for c, _ in results)}"
        na = sum(len(ids) for ids in skipped[test].values())
        print(
            f"{test:<12} {len(agree):>4}/{len(results):<3} = {100 * len(agree) / size:5.1f} %"
            f" {100 * explained / size:12.1f} % {own:>14} {convention:>17} {na:>4}"
        )
    print(
        "  agreement: our status is the target; + conventions: also counting the deliberate differences;\n"
        "  STACK verdict / STACK convention: agreement on rows whose target is STACK's verdict / mathematics'."
    )


def print_disagreements(applicable) -> None:
    ours = []
    print("\nDisagreements:")
    for c, result in _judged(applicable):
        if _agrees(c, result):
            continue
        row, convention = c.row, CONVENTIONS.get(c.row["id"])
        if convention is None:
            ours.append(row["id"])
        print(f"\n  {row['id']}  [{f'convention: {convention}' if convention else 'OUR ERROR'}]")
        print(f"    tans {c.expected!r}  sans {c.submitted!r}  kind {c.kind}")
        stack = f"{row['expected']}" + (" (target from mathematics)" if c.by_math else "")
        print(f"    STACK {stack} → want {c.target}; we say {result.status}, method {result.method or '-'}")
        if result.read_as and result.status != "invalid":  # an invalid answer's read_as is the pointer
            print(f"    read as: {result.read_as}")
        if result.feedback:
            print(f"    feedback: {result.feedback}")
    print(f"\n  Our errors ({len(ours)}): {', '.join(ours) or 'none'}")


def print_errata() -> None:
    print("\nRows whose label in the table is mathematically wrong (target corrected, counted as 'STACK convention'):")
    for row_id, (status, why) in ERRATA.items():
        print(f"  {row_id}: target {status}; {why}")


def print_accidental(applicable) -> None:
    print("\nRows that agree only through a bug in our checker (once it is fixed, they differ on purpose):")
    lucky = [(c, r) for c, r in _judged(applicable) if c.row["id"] in ACCIDENTAL and _agrees(c, r)]
    for bug in dict.fromkeys(ACCIDENTAL.values()):
        print(f"  bug: {bug}")
        for c, result in lucky:
            if ACCIDENTAL[c.row["id"]] == bug:
                print(f"    {c.row['id']}: tans {c.expected!r}  sans {c.submitted!r}, we say {result.status}")
                print(f"      once fixed, a convention: {CONVENTIONS[c.row['id']]}")


def print_sensitive(sensitive) -> None:
    print("\nRows where declaring the symbols real changed our verdict (our default: positive parameters):")
    for c, real, default in sensitive:
        agrees = "agrees" if _agrees(c, real) else "disagrees"
        print(f"  {c.row['id']}: tans {c.expected!r}  sans {c.submitted!r}")
        print(f"    real → {real.status} ({agrees} with the target), positive → {default.status}")
        print(f"    {DOMAIN_NOTES.get(c.row['id'], 'NOT YET EXPLAINED')}")
    if not sensitive:
        print("  none")


def print_not_applicable(skipped) -> None:
    print("\nNot applicable (not in the agreement's denominator):")
    for test in SCOPE:
        for reason, ids in sorted(skipped[test].items()):
            numbers = ", ".join(i.rsplit("-", 1)[1] for i in ids)
            print(f"  {test} ({len(ids)}) {reason}: {numbers}")


if __name__ == "__main__":
    sys.exit(main())
