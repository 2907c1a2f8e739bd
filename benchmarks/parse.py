"""How long ``parse_answer`` takes: realistic answers, and hostile ones up to the size cap.

Run as ``python3 benchmarks/parse.py``. Contents:

    REALISTIC       ~30 answers of about 100 characters: Lagrangians and equations of motion
                    (pendulum, double pendulum, Atwood machine, spherical pendulum) in plain,
                    Unicode and LaTeX notation, each with its coordinates and known symbols
    adversarial()   inputs up to the 2000-character cap: long sums and products, deep but
                    allowed brackets, long names, many derivatives, LaTeX fractions
    baseline        sympy.parse_expr on the same answers printed in sympy syntax, as a
                    speed reference ONLY: parse_expr calls eval and is never used on student text
    main()          measures, prints one table with the targets, exits 0

Three timings of each realistic answer. "Cold": sympy's cache is cleared before the
parse, as for the first answer a fresh process sees. "In a class": the cache is cleared,
the other answers to the same problem are parsed, then this one is timed: an answer new
to a grader that has already read its classmates', which is what batch grading and a
self-check server do. "Same answer again": everything cached, for reference.
"""

from __future__ import annotations

import gc
import statistics
import sys
import time
from pathlib import Path

# Run from a checkout without installing: the package sits next to this folder.
sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

import sympy
from sympy.core.cache import clear_cache
from sympy.parsing.sympy_parser import parse_expr

from grader import TIME, parse_answer

TARGET_MEDIAN_MS = 1.0  # a ~100-character answer
TARGET_WORST_MS = 50.0  # anything up to the cap
CAP = 2000
REPEATS = 40  # timed parses of each realistic answer: 30 answers → 1200 samples
HOSTILE_REPEATS = 5  # timed parses of each adversarial input; the slowest one counts

PENDULUM = (["theta"], ["m", "g", "l", "b", "A", "omega"])
DOUBLE = (["theta_1", "theta_2"], ["m_1", "m_2", "l_1", "l_2", "g"])
ATWOOD = (["x"], ["m_1", "m_2", "g", "I", "R"])
SPHERICAL = (["theta", "phi"], ["m", "g", "l"])

# Each system's answers: (notation, text). Long ones are split only to fit the line length.
_PENDULUM_ANSWERS = [
    ("plain", "L = 1/2 m (l thetadot cos(theta))^2 + 1/2 m (l thetadot sin(theta))^2 + m g l cos(theta)"),
    ("unicode", "L = m/2 (l θ̇ cos θ)² + m/2 (l θ̇ sin θ)² + m g l cos θ − b l θ̇ t + A l sin(ω t)"),
    (
        "latex",
        r"L = \frac{1}{2} m \left(l \dot{\theta} \cos\theta\right)^2"
        r" + \frac{1}{2} m \left(l \dot{\theta} \sin\theta\right)^2 + m g l \cos\theta",
    ),
    ("plain", "m l^2 thetaddot + b l^2 thetadot + m g l sin(theta) = A l cos(omega t) + m l^2 omega^2 theta"),
    ("unicode", "θ̈ = −(g/l) sin θ − (b/m) θ̇ + A/(m l) cos(ω t) − ω² sin θ cos θ"),
    ("latex", r"\ddot{\theta} + \frac{b}{m}\dot{\theta} + \frac{g}{l}\sin\theta = \frac{A}{m l}\cos(\omega t)"),
    ("plain", "theta'' = -g/l*sin(theta) - b/m*theta' + A/(m*l)*cos(omega*t) - omega**2*sin(theta)*cos(theta)"),
]
_DOUBLE_ANSWERS = [
    (
        "plain",
        "L = 1/2 (m1 + m2) l1^2 theta1dot^2 + 1/2 m2 l2^2 theta2dot^2"
        " + m2 l1 l2 theta1dot theta2dot cos(theta1 - theta2)",
    ),
    ("unicode", "L = (m₁ + m₂) l₁² θ̇₁²/2 + m₂ l₂² θ̇₂²/2 + m₂ l₁ l₂ θ̇₁ θ̇₂ cos(θ₁ − θ₂) + (m₁ + m₂) g l₁ cos θ₁"),
    (
        "latex",
        r"L = \frac{1}{2}(m_1 + m_2) l_1^2 \dot\theta_1^2 + \frac{1}{2} m_2 l_2^2 \dot\theta_2^2"
        r" + m_2 l_1 l_2 \dot\theta_1 \dot\theta_2 \cos(\theta_1 - \theta_2)",
    ),
    (
        "plain",
        "(m1 + m2) l1 theta1ddot + m2 l2 theta2ddot cos(theta1 - theta2) + m2 l2 theta2dot^2 sin(theta1 - theta2) = 0",
    ),
    ("unicode", "l₂ θ̈₂ + l₁ θ̈₁ cos(θ₁ − θ₂) − l₁ θ̇₁² sin(θ₁ − θ₂) + g sin θ₂ = 0"),
    (
        "latex",
        r"l_2 \ddot\theta_2 + l_1 \ddot\theta_1 \cos(\theta_1 - \theta_2)"
        r" - l_1 \dot\theta_1^2 \sin(\theta_1 - \theta_2) + g \sin\theta_2 = 0",
    ),
    (
        "plain",
        "[theta1'' = -g (2 m1 + m2) sin(theta1)/(l1 (m1 + m2)),"
        " theta2'' = -g/l2 sin(theta2) + l1/l2 theta1'^2 sin(theta1 - theta2)]",
    ),
    ("unicode", "V = −(m₁ + m₂) g l₁ cos θ₁ − m₂ g l₂ cos θ₂; T = (m₁ + m₂) l₁² θ̇₁²/2 + m₂ l₂² θ̇₂²/2"),
]
_ATWOOD_ANSWERS = [  # with a massive pulley
    ("plain", "L = 1/2 (m1 + m2) xdot^2 + 1/2 I xdot^2/R^2 + (m1 - m2) g x + 1/2 m1 xdot^2 - 1/2 m1 xdot^2"),
    ("unicode", "L = (m₁ + m₂ + I/R²) ẋ²/2 + (m₁ − m₂) g x − (m₁ + m₂) g x/2 + (m₁ + m₂) g x/2"),
    ("latex", r"L = \frac{1}{2}\left(m_1 + m_2 + \frac{I}{R^2}\right)\dot{x}^2 + \left(m_1 - m_2\right) g x"),
    ("plain", "x'' = (m1 - m2) g / (m1 + m2 + I/R^2); (m1 + m2 + I/R^2) xddot - (m1 - m2) g = 0"),
    ("unicode", "(m₁ + m₂ + I/R²) ẍ = (m₁ − m₂) g; T₁ = m₁ (g − ẍ); T₂ = m₂ (g + ẍ)"),
    (
        "latex",
        r"\ddot{x} = \frac{(m_1 - m_2) g}{m_1 + m_2 + I/R^2}"
        r" \\ \left(m_1 + m_2 + \frac{I}{R^2}\right)\ddot x = (m_1 - m_2) g",
    ),
    ("plain", "diff(x, t, 2) (m_1 + m_2 + I/R**2) = (m_1 - m_2)*g + 0*diff(x, t)*m_1"),
]
_SPHERICAL_ANSWERS = [
    ("plain", "L = 1/2 m l^2 (thetadot^2 + sin(theta)^2 phidot^2) + m g l cos(theta)"),
    ("unicode", "m l²/2 (θ̇² + sin²θ φ̇²) + m g l cos θ − (m l² θ̇²/2 + m l² sin²θ φ̇²/2 + m g l cos θ)"),
    ("latex", r"L = \frac{1}{2} m l^2 \left(\dot\theta^2 + \sin^2\theta\,\dot\phi^2\right) + m g l\cos\theta"),
    (
        "plain",
        "thetaddot = sin(theta) cos(theta) phidot^2 - g/l sin(theta);"
        " phiddot sin(theta)^2 + 2 thetadot phidot sin(theta) cos(theta) = 0",
    ),
    ("unicode", "θ̈ = sin θ cos θ φ̇² − (g/l) sin θ\nφ̈ sin²θ + 2 θ̇ φ̇ sin θ cos θ = 0"),
    (
        "latex",
        r"\ddot\theta = \sin\theta\cos\theta\,\dot\phi^2 - \frac{g}{l}\sin\theta"
        r" \\ \sin^2\theta\,\ddot\phi + 2\dot\theta\dot\phi\sin\theta\cos\theta = 0",
    ),
    ("plain", "p_phi = m l^2 sin(theta)^2 phi'; E = 1/2 m l^2 (theta'^2 + sin(theta)^2 phi'^2) - m g l cos(theta)"),
    ("unicode", "m l² θ̈ − m l² sin θ cos θ φ̇² + m g l sin θ = 0; m l² sin²θ φ̈ + 2 m l² sin θ cos θ θ̇ φ̇ = 0"),
]

# (system, notation, answer, context)
REALISTIC = [
    (system, notation, text, context)
    for system, context, answers in [
        ("pendulum", PENDULUM, _PENDULUM_ANSWERS),
        ("double pendulum", DOUBLE, _DOUBLE_ANSWERS),
        ("Atwood machine", ATWOOD, _ATWOOD_ANSWERS),
        ("spherical pendulum", SPHERICAL, _SPHERICAL_ANSWERS),
    ]
    for notation, text in answers
]


def adversarial() -> list[tuple[str, str, tuple]]:
    """(label, text, context): the slowest things a student may type, up to the cap."""
    none = ([], [])
    rows = [
        ("sum of 1000 terms", "+".join(["x"] * 1000), none),
        ("sum of 166 pendulum terms", "+".join(["m g l cos θ"] * 166), PENDULUM),
        ("product of 1000 factors", "*".join(["m"] * 1000), PENDULUM),
        ("999 juxtaposed names", " ".join(["m g l"] * 333), PENDULUM),
        ("20 nested brackets, 47 times", "+".join(["(" * 20 + "x" + ")" * 20] * 47), none),
        ("40 nested brackets", "(" * 40 + "x" + ")" * 40, none),
        ("x^x^…^x, 8 levels (the limit)", "x" + "^x" * 8, none),
        ("x^x^…^x, 40 levels", "x" + "^x" * 40, none),
        ("sin(sin(…)), 20 levels", "sin(" * 20 + "θ" + ")" * 20, PENDULUM),
        ("46 names of 40 letters", " + ".join(["a" * 40] * 46), none),
        ("130 names to split, mglmglmglmgl", " + ".join(["mglmglmglmgl"] * 130), PENDULUM),
        ("240 derivatives in four spellings", " ".join(["theta''' theta'' θ̇ thetaddot"] * 60), PENDULUM),
        ("111 diff() calls", "+".join(["diff(theta, t, 3)"] * 111), PENDULUM),
        (
            "diff of an 8-factor product, order 3",
            "diff(" + "*".join(f"sin({i}θ)" for i in range(1, 9)) + ", t, 3)",
            PENDULUM,
        ),
        ("LaTeX fracs, 39 nested", "\\frac{" * 39 + "x" + "}{2}" * 39, none),
        ("LaTeX fracs, 60 terms", "+".join([r"\frac{1}{2} m l^2 \dot{\theta}^2"] * 60), PENDULUM),
        ("system of 200 equations", "\n".join(["x = m g l"] * 200), ([], ["m", "g", "l"])),
        # each \quad asks whether an equation stands on either side of it
        ("280 \\quad, one = at the end", ("x\\quad " * 280)[:1990] + " = 1", ([], ["x"])),
        ("400 steps of a derivation", "a=b->" * 399 + "a=b", ([], ["a", "b"])),
        ("64 numbers of 30 digits", "*".join(["123456789012345678901234567891"] * 64), none),
        # the densest function calls: three characters each, and two
        ("666 absolute values |x|", "".join(["|x|"] * 666), none),
        ("999 square roots √x", "√x" * 999, none),
        ("a definition chain of 120 names", ", ".join(["x"] + [f"a{i} = x" for i in range(120)])[:1999], none),
        # refused ones: a refusal must be as cheap as an answer
        ("refused: 1999 open brackets", "(" * 1999 + "x", none),
        ("refused: 1999 minus signs", "-" * 1999 + "x", none),
        ("refused: 1999 bars", "|" * 1999, none),
        ("refused: unknown command at the end", "x+" * 990 + "\\input{x}", none),
        ("refused: bad character at the end", "x+" * 999 + "@", none),
        ("refused: 2001 characters", "x" * (CAP + 1), none),
    ]
    for label, text, _ in rows[:-1]:
        assert len(text) <= CAP, (label, len(text))  # the table itself must stay within the cap
    return rows


# -- measuring --------------------------------------------------------------------


def _time_once(function, *args, cold: bool = True, **kwargs) -> float:
    """Seconds for one call; cold: with sympy's cache cleared first (outside the timing)."""
    if cold:
        clear_cache()
    start = time.perf_counter()
    function(*args, **kwargs)
    return time.perf_counter() - start


class _CollectorPaused:
    """Hold off the cyclic garbage collector during a round of timings, as timeit does;
    a full collection with sympy loaded takes longer than a parse, and would land at random."""

    def __enter__(self):
        gc.collect()
        gc.disable()

    def __exit__(self, *exc):
        gc.enable()


def _percentile(samples: list[float], fraction: float) -> float:
    ordered = sorted(samples)
    return ordered[min(len(ordered) - 1, round(fraction * (len(ordered) - 1)))]


def _sympy_syntax(value) -> str:
    """The parsed answer printed by sympy itself: Eq(...), Derivative(theta(t), t), **."""
    return sympy.sstr(value, order="none")


def _sympy_names(value) -> dict:
    """What parse_expr must resolve: every symbol and coordinate of the answer, so that
    ``I``, ``E`` or ``L`` are the problem's symbols and not sympy's constants."""
    items = value if isinstance(value, tuple) else (value,)
    names = {"t": TIME, "Eq": sympy.Eq, "Derivative": sympy.Derivative}
    for item in items:
        names.update({symbol.name: symbol for symbol in item.free_symbols})
        names.update({f.func.__name__: f.func for f in item.atoms(sympy.core.function.AppliedUndef)})
    return names


def measure_realistic() -> tuple[list[float], list[float], list[float], list[int]]:
    """Seconds per parse: ours cold, ours warm (the same answer again), parse_expr cold."""
    ours, warm, baseline, lengths = [], [], [], []
    prepared = []
    for system, notation, text, (coords, known) in REALISTIC:
        answer = parse_answer(text, coords=coords, known=known)
        if not answer.ok:  # a parser change broke this answer: say so, and time the others
            print(f"warning: not timed, refused ({system}, {notation}): {text!r}\n{answer}\n")
            continue
        sympy_text, names = _sympy_syntax(answer.value), _sympy_names(answer.value)
        if parse_expr(sympy_text, local_dict=names) != answer.value:  # the baseline must read the same thing
            print(f"warning: the sympy-syntax rewrite of {text!r} reads differently: {sympy_text!r}\n")
        prepared.append((text, coords, known, sympy_text, names))
        lengths.append(len(text))
    for _ in range(3):  # warm up: imports, printers, first-call paths
        for text, coords, known, sympy_text, names in prepared:
            parse_answer(text, coords=coords, known=known)
            parse_expr(sympy_text, local_dict=names)
    for _ in range(REPEATS):
        with _CollectorPaused():
            for text, coords, known, sympy_text, names in prepared:
                ours.append(_time_once(parse_answer, text, coords=coords, known=known))
                warm.append(_time_once(parse_answer, text, coords=coords, known=known, cold=False))
                baseline.append(_time_once(parse_expr, sympy_text, local_dict=names))
    return ours, warm, baseline, lengths


def measure_in_class() -> list[float]:
    """Seconds per parse of an answer new to a process that has read the other answers to its problem."""
    times = []
    for _ in range(REPEATS // 4):
        with _CollectorPaused():
            for index, (system, _, text, (coords, known)) in enumerate(REALISTIC):
                clear_cache()
                for other, (other_system, _, other_text, (c, k)) in enumerate(REALISTIC):
                    if other != index and other_system == system:
                        parse_answer(other_text, coords=c, known=k)
                times.append(_time_once(parse_answer, text, coords=coords, known=known, cold=False))
    return times


def measure_adversarial() -> list[tuple[str, int, str, float]]:
    results = []
    for label, text, (coords, known) in adversarial():
        answer = parse_answer(text, coords=coords, known=known)  # warm-up, and the verdict
        verdict = "accepted" if answer.ok else answer.code
        with _CollectorPaused():
            worst = max(_time_once(parse_answer, text, coords=coords, known=known) for _ in range(HOSTILE_REPEATS))
        results.append((label, len(text), verdict, worst))
    return results


# -- reporting --------------------------------------------------------------------


def _verdict(value_ms: float, target_ms: float) -> str:
    return "meets target" if value_ms <= target_ms else "MISSES target"


def _row(label: str, median: str, p99: str, note: str = "") -> None:
    print(f"  {label:34} {median:>10} {p99:>10}   {note}".rstrip())


def main() -> int:
    ours, warm, baseline, lengths = measure_realistic()
    in_class = measure_in_class()
    class_median, class_p99 = statistics.median(in_class) * 1e3, _percentile(in_class, 0.99) * 1e3
    median, p99 = statistics.median(ours) * 1e3, _percentile(ours, 0.99) * 1e3
    warm_median, warm_p99 = statistics.median(warm) * 1e3, _percentile(warm, 0.99) * 1e3
    base_median, base_p99 = statistics.median(baseline) * 1e3, _percentile(baseline, 0.99) * 1e3
    hostile = measure_adversarial()
    worst_label, worst_length, _, worst = max(hostile, key=lambda row: row[3])
    worst_ms = worst * 1e3

    print(f"parse_answer, Python {sys.version.split()[0]}, sympy {sympy.__version__}")
    print()
    print(f"Realistic answers: {len(lengths)}, {min(lengths)}–{max(lengths)} characters "
          f"(median {statistics.median(lengths):.0f}), {REPEATS} timed parses each")  # fmt: skip
    _row("", "median", "p99", "target")
    _row(
        "parse_answer, in a class",
        f"{class_median:.3f} ms",
        f"{class_p99:.3f} ms",
        f"median ≤ {TARGET_MEDIAN_MS:g} ms: {_verdict(class_median, TARGET_MEDIAN_MS)}",
    )
    _row(
        "parse_answer, cold",
        f"{median:.3f} ms",
        f"{p99:.3f} ms",
        f"median ≤ {TARGET_MEDIAN_MS:g} ms: {_verdict(median, TARGET_MEDIAN_MS)}",
    )
    _row("sympy.parse_expr (baseline only)", f"{base_median:.3f} ms", f"{base_p99:.3f} ms")
    _row("ratio cold parse_answer / parse_expr", f"{median / base_median:.2f}×", f"{p99 / base_p99:.2f}×")
    _row(
        "parse_answer, same answer again",
        f"{warm_median:.3f} ms",
        f"{warm_p99:.3f} ms",
        "warm sympy cache, for reference",
    )
    print("  parse_expr runs its input through eval: it is a speed reference, never used on student text.")
    print()
    print(f"Adversarial inputs up to the {CAP}-character cap, slowest of {HOSTILE_REPEATS} parses each")
    print(f"  {'input':38} {'chars':>5}  {'verdict':18} {'worst':>10}")
    for label, length, verdict, seconds in hostile:
        print(f"  {label:38} {length:5}  {verdict:18} {seconds * 1e3:7.2f} ms")
    print(f"  worst case: {worst_ms:.2f} ms ({worst_label}, {worst_length} characters); "
          f"target ≤ {TARGET_WORST_MS:g} ms: {_verdict(worst_ms, TARGET_WORST_MS)}")  # fmt: skip
    return 0


if __name__ == "__main__":
    sys.exit(main())
