"""How fast and how right ``compare`` is, against sympy's own equality tests, in one run.

Contents:
    the pairs        tests/compare_pairs.py: derived verdicts over eight mechanics systems
    our timing       median and p99 per verdict once the expected answer is prepared, each
                     submitted answer new to sympy's cache (as a student's answer is)
    baselines        the same pairs judged by ``simplify(a - b) == 0`` and by ``a.equals(b)``, given the answers
                     already parsed; our time is also split into reading and judging
    output           a table of times, ratios and accuracy; wrong verdicts listed

Run: ``python benchmarks/compare.py`` (``--quick`` runs the baselines on a sample only, every fourth
pair; ``--repeat N`` times each pair in N passes, 3 by default). The figure is the full run's: the
sample holds more of simplify's slow pairs, and its simplify median ran 26 to 42 ms in runs where
the whole table's was 19 ms, so a quick run's ratio is a rough guide and tends high.
Targets: median ≤ 2 ms, p99 ≤ 50 ms, ≥ 30× faster than the simplify baseline, no wrong verdict.

Each pair's time is the best of its passes, for every method alike, and every pass begins
with sympy's cache emptied, so each is a first sight of the answer. On a shared machine one
pass's median moves by a fifth from run to run; the best of three is what the code costs.
The first pass alone is printed too. A baseline's pair that took more than
:data:`REPEAT_ABOVE` once is not timed again: its best cannot move a median or a p99.

The baselines get the same parsed sympy objects with the problem's assumptions
(positive parameters, real coordinates); equations are compared as lhs − rhs and
systems equation by equation, which is all they can do. They are given no time limit
beyond a per-pair budget, past which their answer counts as "no verdict".
"""

from __future__ import annotations

import math
import statistics
import sys
import time
from pathlib import Path

import sympy
from sympy.core.cache import clear_cache

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "tests"))

from compare_pairs import PAIRS, SYSTEMS  # noqa: E402

from grader import compare, parse_answer  # noqa: E402
from grader.judge.expected import prepare  # noqa: E402
from grader.judge.setting import Setting  # noqa: E402

BASELINE_BUDGET = 5.0  # seconds per pair before a baseline's answer counts as no verdict
REPEAT_ABOVE = 0.5  # seconds: a baseline's pair slower than this is timed once


def _setting(system: str) -> dict:
    spec = SYSTEMS[system]
    return {"coords": spec["coords"], "known": spec["known"], "domains": spec.get("domains")}


def time_ours(pairs, repeat: int = 1) -> tuple[list[float], list[float], list[tuple], list[float]]:
    """Each pair's verdict time, the time of reading its submitted answer alone (each the
    best of ``repeat`` passes), the wrong verdicts, and the first pass's verdict times.

    A first pass prepares (caches) every expected answer, including what feedback on a
    wrong answer derives from it. sympy's cache is then emptied, so each submitted answer
    is new to the process, as a student's is: it was seen in the first pass, and without
    this the timed pass would find its sympy objects already built.
    """
    for system, kind, expected, submitted, _, _ in pairs:
        compare(expected, submitted, kind=kind, **_setting(system))
    # reading is timed as compare reads: with the symbols of the expected answer known too
    read_with = [_read_with(system, kind, expected) for system, kind, expected, _, _, _ in pairs]
    passes, wrong = [], []
    for number in range(repeat):
        clear_cache()
        times = []
        for system, kind, expected, submitted, equivalent, note in pairs:
            start = time.perf_counter()
            verdict = compare(expected, submitted, kind=kind, **_setting(system))
            times.append(time.perf_counter() - start)
            if number == 0 and (verdict.equivalent != equivalent or not verdict.feedback):
                wrong.append((system, kind, expected, submitted, equivalent, verdict.status, note))
        passes.append(times)
    readings = []
    for _ in range(repeat):
        clear_cache()
        reading = []
        for (_, _, _, submitted, _, _), (coords, known) in zip(pairs, read_with, strict=True):
            start = time.perf_counter()
            parse_answer(submitted, coords=coords, known=known)
            reading.append(time.perf_counter() - start)
        readings.append(reading)
    return _best(passes), _best(readings), wrong, passes[0]


def _best(passes: list[list[float]]) -> list[float]:
    return [min(times) for times in zip(*passes, strict=True)]


def _read_with(system: str, kind: str, expected: str) -> tuple[tuple, list]:
    """The coordinates and known names ``compare`` reads a submitted answer with."""
    spec = _setting(system)
    domains = tuple(sorted((spec["domains"] or {}).items()))
    prepared = prepare(expected, kind, tuple(spec["coords"]), tuple(spec["known"]), domains)
    return prepared.setting.coords, sorted(prepared.names)


def _plain_pair(system: str, expected: str, submitted: str):
    """Both answers as sympy objects with the problem's assumptions, as a baseline would get them."""
    spec = _setting(system)
    setting = Setting.build(spec["coords"], spec["known"], spec["domains"])
    first = parse_answer(expected, coords=spec["coords"], known=spec["known"])
    names = sorted({s.name for s in _items_symbols(first.value)} | set(setting.known))
    second = parse_answer(submitted, coords=spec["coords"], known=names)
    values = [setting.plain(first.value), setting.plain(second.value)]
    assumed = {}
    for value in values:
        for symbol in _items_symbols(value):
            flags = {"real": True} if setting.domain(symbol) != "positive" else {"positive": True}
            assumed[symbol] = sympy.Symbol(symbol.name, **flags)
    return [_zeroed(value).xreplace(assumed) if not isinstance(value, tuple) else
            tuple(_zeroed(v).xreplace(assumed) for v in value) for value in values]  # fmt: skip


def _items_symbols(value) -> set:
    items = value if isinstance(value, tuple) else (value,)
    return set().union(*(item.free_symbols for item in items))


def _zeroed(value):
    return value.lhs - value.rhs if isinstance(value, sympy.Eq) else value


def _baseline_verdict(method: str, a, b) -> bool | None:
    if isinstance(a, tuple) or isinstance(b, tuple):
        if not (isinstance(a, tuple) and isinstance(b, tuple)) or len(a) != len(b):
            return False
        return all(_baseline_verdict(method, x, y) for x, y in zip(a, b, strict=True))
    if method == "simplify":
        return sympy.simplify(a - b) == 0
    return a.equals(b)


def time_baseline(method: str, pairs, repeat: int = 1) -> tuple[list[float], int, int]:
    """Times (the best of ``repeat`` passes), wrong verdicts and pairs with no verdict (of the
    first pass) for one sympy method."""
    wrong, undecided = 0, 0
    plain = [_plain_pair(system, expected, submitted) for system, _, expected, submitted, _, _ in pairs]
    times = [math.inf] * len(pairs)
    for number in range(repeat):
        clear_cache()  # as for ours: no pair's sympy objects are left from an earlier pass
        for i, ((a, b), (_, _, _, _, equivalent, _)) in enumerate(zip(plain, pairs, strict=True)):
            if number and times[i] > REPEAT_ABOVE:
                continue
            start = time.perf_counter()
            verdict = _baseline_verdict(method, a, b)
            elapsed = time.perf_counter() - start
            times[i] = min(times[i], elapsed)
            if number:
                continue
            if verdict is None or elapsed > BASELINE_BUDGET:
                undecided += 1
            elif verdict != equivalent:
                wrong += 1
    return times, wrong, undecided


def p99(times: list[float]) -> float:
    ordered = sorted(times)
    return ordered[min(len(ordered) - 1, int(0.99 * len(ordered)))]


def main(argv: list[str]) -> int:
    quick = "--quick" in argv
    repeat = int(argv[argv.index("--repeat") + 1]) if "--repeat" in argv else 3
    pairs = PAIRS
    print(
        f"compare benchmark: {len(pairs)} pairs ({sum(p[4] for p in pairs)} equivalent);"
        f" each pair's time is the best of {repeat} passes"
    )
    ours, reading, wrong, first = time_ours(pairs, repeat)
    judging = [max(total - read, 1e-7) for total, read in zip(ours, reading, strict=True)]
    rows = [("grader.compare", ours, len(wrong), 0), ("  of which judging", judging, len(wrong), 0)]
    sample = pairs[::4] if quick else pairs
    for method in ("simplify", "equals"):
        times, bad, none = time_baseline(method, sample, repeat)
        rows.append((f"sympy {method}" + (" (sample)" if quick else ""), times, bad, none))
    print(f"{'method':28} {'median ms':>10} {'p99 ms':>9} {'max ms':>9} {'wrong':>6} {'no verdict':>11} {'ratio':>8}")
    base = statistics.median(ours)
    for name, times, bad, none in rows:
        median = statistics.median(times)
        print(
            f"{name:28} {median * 1e3:10.2f} {p99(times) * 1e3:9.2f} {max(times) * 1e3:9.2f} {bad:6d} {none:11d}"
            f" {median / base:7.1f}x"
        )
    by_kind: dict[str, list[float]] = {}
    for (_, kind, *_), elapsed in zip(pairs, ours, strict=True):
        by_kind.setdefault(kind, []).append(elapsed)
    for kind, times in by_kind.items():
        median = statistics.median(times)
        print(f"  {kind:12} n={len(times):3d}  median {median * 1e3:6.2f} ms  p99 {p99(times) * 1e3:6.2f} ms")
    simplify_median = statistics.median(rows[2][1])
    sampled_note = " (a sample: see the module notes)" if quick else ""
    print(
        f"simplify / compare{sampled_note}: {simplify_median / base:.1f}x with compare charged for reading the"
        f" answer and simplify not; {simplify_median / statistics.median(judging):.1f}x like for like (judging only)"
    )
    # the median falls where right answers end and wrong ones begin: each half's own, against simplify
    # on the same pairs (in a quick run, the sample's), says which of the two sets the figure
    sampled = list(range(0, len(pairs), 4)) if quick else list(range(len(pairs)))
    simplify_times = rows[2][1]
    for equivalent, half in ((True, "right answers"), (False, "wrong answers")):
        ours_half = [ours[i] for i, pair in enumerate(pairs) if pair[4] == equivalent]
        theirs = [simplify_times[j] for j, i in enumerate(sampled) if pairs[i][4] == equivalent]
        ratio = statistics.median(theirs) / statistics.median(ours_half)
        print(f"  {half:14} median {statistics.median(ours_half) * 1e3:5.2f} ms; simplify / compare {ratio:5.1f}x")
    first_median, first_p99 = statistics.median(first) * 1e3, p99(first) * 1e3
    print(f"grader.compare, first pass alone: median {first_median:.2f} ms, p99 {first_p99:.2f} ms")
    print("targets: median <= 2 ms, p99 <= 50 ms, >= 30x faster than simplify, 0 wrong")
    for item in wrong:
        print("WRONG:", item)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
