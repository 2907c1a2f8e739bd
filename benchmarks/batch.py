"""Batch grading from a cold start: a synthetic class of 300 students × 15 parts.

Contents:
    the class      answers drawn (seeded) from each part's reference, its tests and its listed
                   mistakes: right and wrong, in plain, Unicode and LaTeX notation, with blanks
    the run        ``python -m grader grade`` as a fresh process, timed from its start to its
                   last file written; its process tree's memory sampled every 20 ms
    output         wall time, verdicts per second, peak memory (the tree's summed RSS), and the
                   targets: ≤ 20 s on 2 cores, ≤ 500 MB; and how many distinct answers the class
                   gave, since an answer given word for word again is graded once a worker

Run: ``python benchmarks/batch.py [--students N] [--jobs N] [--all-distinct]``. With
``--all-distinct`` every answer is made unique (trailing spaces, as many as the student's
number), so each of the verdicts is graded: the checker's cost alone, as no real class is.
"""

from __future__ import annotations

import argparse
import csv
import random
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from grader.bank import load_bank  # noqa: E402
from grader.grade.part import expected_answer  # noqa: E402

PARTS = [  # 15 parts of every kind but text-heavy ones, as a problem set would set them
    ("plane-pendulum", "lagrangian"), ("plane-pendulum", "motion"), ("plane-pendulum", "small-oscillations"),
    ("plane-pendulum", "frequency"), ("plane-pendulum", "period"), ("plane-pendulum", "why-harmonic"),
    ("atwood-machine", "lagrangian"), ("atwood-machine", "motion"), ("atwood-machine", "acceleration"),
    ("double-pendulum", "lagrangian"), ("double-pendulum", "motion"), ("spherical-pendulum", "momentum"),
    ("degrees-of-freedom", "double-pendulum"), ("degrees-of-freedom", "rigid-body"),
    ("spherical-pendulum", "cyclic"),
]  # fmt: skip
TARGET_SECONDS, TARGET_MB = 20.0, 500.0


def _pool(problem, part) -> list[str]:
    answers = [expected_answer(problem, part)] if part.kind != "text" else [str(part.answer or "")]
    answers += [test.answer for test in part.tests] + [mistake.answer for mistake in part.mistakes]
    return [answer for answer in answers if answer] + [""]  # and a blank


def write_class(folder: Path, students: int, distinct: bool = False) -> tuple[Path, Path]:
    bank = load_bank(ROOT / "problems")
    parts = []
    for problem_id, part_id in PARTS:
        problem = bank[problem_id]
        wanted = next((p for p in problem.parts if p.id == part_id), None)
        if wanted is None:  # the bank changed: take the problem's first part of another name
            wanted = problem.parts[0]
        parts.append((problem, wanted))
    rng = random.Random(300)
    submissions = folder / "class.csv"
    with submissions.open("w", newline="", encoding="utf-8") as file:
        writer = csv.writer(file)
        writer.writerow(["id", "name", "email", *(f"{p.id}.{q.id}" for p, q in parts)])
        pools = [_pool(p, q) for p, q in parts]
        for number in range(students):
            answers = [rng.choice(pool) for pool in pools]
            if distinct:
                answers = [answer + " " * number if answer else answer for answer in answers]
            writer.writerow([f"s{number:04d}", f"Student {number}", f"s{number}@example.org", *answers])
    assignment = folder / "synthetic.yaml"
    items = {}
    for problem, part in parts:
        items.setdefault(problem.id, []).append(part.id)
    lines = ["schema_version: 1", "id: synthetic", "title: Synthetic class", "problems:"]
    lines += [f"  - {{problem: {pid}, parts: [{', '.join(ids)}]}}" for pid, ids in items.items()]
    assignment.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return submissions, assignment


def _distinct(submissions: Path) -> int:
    with submissions.open(newline="", encoding="utf-8") as file:
        header, *rows = csv.reader(file)
    return len({(column, row[column]) for row in rows for column in range(3, len(header)) if row[column].strip()})


def _tree_rss(pid: int) -> int:
    """Resident memory of a process and all its descendants, in bytes (Linux /proc)."""
    total, stack = 0, [pid]
    while stack:
        current = stack.pop()
        try:
            status = Path(f"/proc/{current}/status").read_text()
            total += next(int(line.split()[1]) for line in status.splitlines() if line.startswith("VmRSS")) * 1024
            for task in Path(f"/proc/{current}/task").iterdir():
                stack += [int(child) for child in (task / "children").read_text().split()]
        except (OSError, StopIteration, ValueError):
            continue
    return total


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--students", type=int, default=300)
    parser.add_argument("--all-distinct", action="store_true", help="no answer given twice: each one graded")
    parser.add_argument("--jobs", type=int, default=None)
    args = parser.parse_args(argv)
    with tempfile.TemporaryDirectory() as scratch:
        folder = Path(scratch)
        submissions, assignment = write_class(folder, args.students, args.all_distinct)
        command = [sys.executable, "-m", "grader", "grade", str(submissions), "--assignment", str(assignment),
                   "--out", str(folder / "out"), "--bank", str(ROOT / "problems")]  # fmt: skip
        if args.jobs:
            command += ["--jobs", str(args.jobs)]
        start = time.perf_counter()
        process = subprocess.Popen(command, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        peak = 0
        while process.poll() is None:
            peak = max(peak, _tree_rss(process.pid))
            time.sleep(0.02)
        wall = time.perf_counter() - start
        out, err = process.communicate()
        verdicts = args.students * len(PARTS)
        print(f"batch grading, {args.students} students × {len(PARTS)} parts = {verdicts} verdicts")
        # answers given word for word by several students are graded once a worker: say how many there are
        print(f"  distinct answers (part, text): {_distinct(submissions)}")
        print(f"  exit status {process.returncode}; {out.strip().splitlines()[0] if out.strip() else err[-500:]}")
        print(f"  wall time, cold start to last file: {wall:.2f} s   (target ≤ {TARGET_SECONDS:g} s on 2 cores)")
        print(f"  verdicts per second: {verdicts / wall:.0f}")
        print(f"  peak memory, process tree: {peak / 1e6:.0f} MB   (target ≤ {TARGET_MB:g} MB)")
    return 0 if process.returncode in (0, 4) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
