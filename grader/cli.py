"""The ``grader`` command: a thin layer over the library, and the only code that prints or exits.

Commands:
    grader compare EXPECTED SUBMITTED [--kind K] [--coords q1,q2] [--json]    judge an answer
                   [--given p=…] [--dimension l=length]
    grader parse ANSWER [--coords q1,q2] [--known m,g,l] [--json]           how an answer is read
    grader problems list | show ID [--answers]                             the problem bank
    grader validate [PATH ...]                                             the bank tests itself
    grader grade SUBMISSIONS --assignment A --out DIR [--jobs N] [--only ID] grade a class
    grader export DIR --to canvas|moodle|gradescope                        LMS imports (of who was graded)
    grader check PROBLEM.PART ANSWER | --answers FILE [--assignment A]     a student checks answers
    grader serve [--assignment A] [--port P] [--log FILE] [--workers N]    the self-check web page

Exit statuses: 0 equivalent (or read, or all graded); 1 not equivalent (or validation
failures); 2 invalid input or usage error; 3 undecided (set aside for a person); 4 some
submissions could not be graded (listed; an export leaves them out); 130 interrupted (Ctrl-C);
141 the reader of the output went away (`grader … | head`).
"""

from __future__ import annotations

import argparse
import json
import math
import os
import sys
from collections.abc import Sequence
from dataclasses import fields
from pathlib import Path

import yaml
from tqdm import tqdm

from grader import KINDS, AuthorError, GraderError, compare, parse_answer
from grader.bank import BankError, default_bank_path, load_assignment, load_bank
from grader.grade import expected_answer, validate_bank
from grader.grade.batch import assignment_parts
from grader.grade.selfcheck import check_many, find_part
from grader.judge.units import unit_of
from grader.run import EXPORTS, export_grades, grade_assignment
from grader.serve import make_server

EXIT_OK = 0
EXIT_WRONG = 1
EXIT_INVALID = 2
EXIT_UNDECIDED = 3
EXIT_SOME_FAILED = 4
EXIT_PIPE_CLOSED = 141  # as a shell reports a process stopped by SIGPIPE: `grader … | head`
EXIT_INTERRUPTED = 130  # as a shell reports a process stopped by SIGINT: Ctrl-C
_EXIT_BY_STATUS = {
    "equivalent": EXIT_OK,
    "not_equivalent": EXIT_WRONG,
    "invalid": EXIT_INVALID,
    "undecided": EXIT_UNDECIDED,
}


def _names(value: str) -> list[str]:
    return [name.strip() for name in value.split(",") if name.strip()]


def _definition(value: str) -> tuple[str, str]:
    name, equals, expression = value.partition("=")
    if not (equals and name.strip() and expression.strip()):
        raise argparse.ArgumentTypeError(f"expected NAME=VALUE, as p_theta='m R^2 thetadot' or l=length, not {value!r}")
    return name.strip(), expression.strip()


def _seconds(value: str) -> float:
    """A time limit: a positive number of seconds (0 or less would fail every check)."""
    try:
        seconds = float(value)
    except ValueError:
        seconds = math.nan
    if not (seconds > 0 and math.isfinite(seconds)):
        raise argparse.ArgumentTypeError(f"expected a positive number of seconds, not {value!r}")
    return seconds


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="grader",
        description="Grades answers in analytical mechanics: reads them, judges them, grades a class, and lets"
        " students check their answers first.",
    )
    commands = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")

    parse = commands.add_parser("parse", help="show how an answer is read", description="Show how an answer is read.")
    parse.add_argument("answer", help="the answer, in plain, Unicode or LaTeX notation")
    parse.add_argument("--coords", type=_names, default=[], help="generalized coordinates, e.g. theta1,theta2")
    parse.add_argument("--known", type=_names, default=[], help="other symbols the problem defines, e.g. m,g,l")
    parse.add_argument("--json", action="store_true", help="print JSON")
    parse.set_defaults(run=_run_parse)

    judge = commands.add_parser(
        "compare", help="judge a submitted answer against the expected one", description="Judge an answer."
    )
    judge.add_argument("expected", help="the reference answer")
    judge.add_argument("submitted", help="the answer to judge")
    judge.add_argument(
        "--kind", choices=sorted(KINDS), help="the kind of answer (default: as the expected answer is written:"
        " an equation, a system of equations, or else an expression)",
    )  # fmt: skip
    judge.add_argument("--coords", type=_names, default=[], help="generalized coordinates, e.g. theta1,theta2")
    judge.add_argument("--known", type=_names, default=[], help="more symbols the problem defines")
    judge.add_argument("--timeout", type=_seconds, default=2.0, help="seconds before the verdict is 'undecided'")
    judge.add_argument("--up-to-constant", action="store_true", help="expressions: allow an additive constant")
    judge.add_argument("--unit", help="numbers: the unit asked for, e.g. s or m/s^2; an answer may carry its unit")
    judge.add_argument(
        "--given", type=_definition, action="append", default=[], metavar="NAME=VALUE",
        help="a name an answer may use for a quantity, e.g. p_theta='m R^2 thetadot' (repeatable)",
    )  # fmt: skip
    judge.add_argument(
        "--dimension", type=_definition, action="append", default=[], metavar="NAME=DIMENSION", dest="dimensions",
        help="a symbol's dimension, e.g. l=length or g=acceleration (repeatable): a wrong answer's units are checked",
    )  # fmt: skip
    judge.add_argument("--json", action="store_true", help="print JSON")
    judge.set_defaults(run=_run_compare)

    problems = commands.add_parser("problems", help="list the problem bank, or show a problem")
    _add_bank_option(problems)
    which = problems.add_subparsers(dest="action", required=True, metavar="ACTION")
    which.add_parser("list", help="id, title, seed items and points of every problem").set_defaults(run=_run_list)
    show = which.add_parser("show", help="a problem's prompt and parts")
    show.add_argument("id")
    show.add_argument("--answers", action="store_true", help="also show the reference answers")
    show.set_defaults(run=_run_show)

    validate = commands.add_parser("validate", help="check the problem bank against itself")
    validate.add_argument("paths", nargs="*", type=Path, help="files or folders (default: the bank)")
    validate.set_defaults(run=_run_validate)

    grade = commands.add_parser("grade", help="grade a class's submissions for an assignment")
    grade.add_argument("submissions", type=Path, help="a wide CSV (id, name, email, problem.part…) or a folder")
    grade.add_argument("--assignment", required=True, help="an assignment id (problems/assignments/ID.yaml) or file")
    grade.add_argument("--out", type=Path, required=True, help="the folder to write results into")
    grade.add_argument("--jobs", type=int, default=None, help="worker processes (default: the machine's cores)")
    grade.add_argument("--timeout", type=_seconds, default=2.0, help="seconds per check before 'undecided'")
    grade.add_argument("--only", metavar="STUDENT", help="regrade one student, keeping everyone else's results")
    grade.add_argument("--overrides", type=Path, help="CSV of a person's scores: student, part, points, comment")
    grade.add_argument("--reveal", action="store_true", help="show reference answers in the students' reports")
    _add_bank_option(grade)
    grade.set_defaults(run=_run_grade)

    export = commands.add_parser("export", help="write an LMS import of graded results")
    export.add_argument("out", type=Path, help="the folder grader grade wrote")
    export.add_argument("--to", choices=EXPORTS, required=True)
    export.add_argument("--assignment", required=True, help="the assignment id or file")
    _add_bank_option(export)
    export.set_defaults(run=_run_export)

    checker = commands.add_parser(
        "check", help="check answers to bank parts, as a student would", description="Check answers to bank parts."
    )
    checker.add_argument("part", nargs="?", help="problem.part, e.g. plane-pendulum.lagrangian")
    checker.add_argument("answer", nargs="?", help="the answer")
    checker.add_argument("--answers", type=Path, help="a YAML mapping of problem.part to answer")
    checker.add_argument("--assignment", help="with --answers: list the assignment's parts left unanswered")
    checker.add_argument("--timeout", type=_seconds, default=2.0, help="seconds per check before 'undecided'")
    _add_bank_option(checker)
    checker.set_defaults(run=_run_check)

    serve = commands.add_parser("serve", help="a local web page where students check their answers")
    serve.add_argument("--assignment", help="an assignment id or file (default: every problem of the bank)")
    serve.add_argument("--host", default="127.0.0.1", help="the address to listen on (default: %(default)s)")
    serve.add_argument("--port", type=int, default=8000, help="the port (default: %(default)s; 0 picks a free one)")
    serve.add_argument("--log", type=Path, default=Path("attempts.jsonl"), help="attempts log (default: %(default)s)")
    serve.add_argument("--timeout", type=_seconds, default=2.0, help="seconds per check before 'undecided'")
    serve.add_argument("--workers", type=int, help="processes that check answers (default: one per core)")
    _add_bank_option(serve)
    serve.set_defaults(run=_run_serve)
    return parser


def _assignment(args: argparse.Namespace):
    """The bank and the assignment, or None after saying what is wrong."""
    bank = _load(args.bank)
    if bank is None:
        return None, None
    path = Path(args.assignment)
    if not path.suffix:
        path = args.bank / "assignments" / f"{args.assignment}.yaml"
    try:
        return bank, load_assignment(path, bank)
    except BankError as error:
        print(f"grader: {error}", file=sys.stderr)
        return None, None


def _run_grade(args: argparse.Namespace) -> int:
    bank, assignment = _assignment(args)
    if assignment is None:
        return EXIT_INVALID
    bar = {}

    def start(total: int) -> None:
        if sys.stderr.isatty():  # a progress bar on a terminal, quiet logs otherwise
            bar["bar"] = tqdm(total=total, unit="student", file=sys.stderr)

    def advance(done: int) -> None:
        if "bar" in bar:
            bar["bar"].update(done)

    try:
        summary = grade_assignment(
            args.submissions, assignment, bank, args.out, jobs=args.jobs, timeout=args.timeout, only=args.only,
            overrides=args.overrides, reveal=args.reveal, progress=advance, on_start=start,
        )  # fmt: skip
    except GraderError as error:
        print(f"grader grade: {error}", file=sys.stderr)
        return EXIT_INVALID
    except OSError as error:  # the outputs are written all or none: none was changed
        print(f"grader grade: cannot write the outputs into {args.out}: {error}", file=sys.stderr)
        return EXIT_INVALID
    finally:
        if "bar" in bar:
            bar["bar"].close()
    for issue in summary.issues:
        print(f"input: {issue}", file=sys.stderr)
    graded = sum(grade.status == "graded" for grade in summary.grades)
    print(f"graded {graded} of {len(summary.grades)} students into {summary.out}/")
    print(f"  gradebook: {summary.out / 'gradebook.csv'}   summary: {summary.out / 'summary.html'}")
    print(f"  reports: {summary.out / 'reports'}/   for a person to look at: {summary.review_count} answers in "
          f"{summary.out / 'review.csv'}")  # fmt: skip
    if summary.exports:
        print(f"  LMS imports made again from these grades: {', '.join(summary.exports)} in {summary.out / 'exports'}")
    for failure in summary.failed:
        print(f"  could not be graded: {failure}")
    return EXIT_SOME_FAILED if summary.failed or summary.issues else EXIT_OK


def _run_export(args: argparse.Namespace) -> int:
    bank, assignment = _assignment(args)
    if assignment is None:
        return EXIT_INVALID
    max_score = sum(points for *_, points in assignment_parts(assignment, bank))
    try:
        summary = export_grades(args.out, args.to, assignment=assignment, max_score=max_score)
    except GraderError as error:
        print(f"grader export: {error}", file=sys.stderr)
        return EXIT_INVALID
    except OSError as error:
        print(f"grader export: cannot write into {args.out / 'exports'}: {error}", file=sys.stderr)
        return EXIT_INVALID
    written = summary.written
    print(f"wrote {len(written)} file(s): {written[0] if len(written) == 1 else args.out / 'exports' / args.to}")
    for student in summary.not_graded:
        who = f"{student.id} ({student.name})" if student.name else student.id
        print(f"grader export: {who} could not be graded and is left out, so the LMS keeps their grade as it is;"
              f" grade them again with grader grade … --only {student.id}", file=sys.stderr)  # fmt: skip
    if summary.waiting:
        waiting = f"grader export: {summary.waiting} answer(s) still wait for a person (review.csv):"
        print(f"{waiting} these grades hold their proposed points; fill in review.csv's points and grade again"
              " with --overrides", file=sys.stderr)  # fmt: skip
    return EXIT_SOME_FAILED if summary.not_graded else EXIT_OK


def _run_check(args: argparse.Namespace) -> int:
    if args.answers is None and (args.part is None or args.answer is None or args.assignment):
        print("grader check: give PROBLEM.PART ANSWER, or --answers FILE [--assignment A]", file=sys.stderr)
        return EXIT_INVALID
    if args.answers is not None and args.part is not None:
        print("grader check: give either PROBLEM.PART ANSWER or --answers FILE, not both", file=sys.stderr)
        return EXIT_INVALID
    bank, assignment = _assignment(args) if args.assignment else (_load(args.bank), None)
    if bank is None:
        return EXIT_INVALID
    answers = {args.part: args.answer} if args.answers is None else _read_answers(args.answers)
    if answers is None:
        return EXIT_INVALID
    try:
        for key in answers:
            find_part(key, bank)
    except GraderError as error:
        print(f"grader check: {error}", file=sys.stderr)
        return EXIT_INVALID
    results = check_many(answers, bank=bank, timeout=args.timeout)  # with each other: method credit
    print("\n".join(str(result) for result in results))
    missing = [] if assignment is None else [
        f"{problem.id}.{part.id}" for problem, part, _ in assignment_parts(assignment, bank)
        if f"{problem.id}.{part.id}" not in answers
    ]  # fmt: skip
    for key in missing:
        print(f"– {key}: not answered")
    if any(result.status == "invalid" for result in results):
        return EXIT_INVALID
    return EXIT_OK if all(result.right for result in results) and not missing else EXIT_WRONG


def _read_answers(path: Path) -> dict[str, str] | None:
    """problem.part → answer from a student's YAML file, or None after saying what is wrong."""
    try:
        # every answer as typed: YAML's own reading makes 015 the octal 13, yes True and an empty one null
        data = yaml.load(path.read_text(encoding="utf-8"), Loader=yaml.BaseLoader)  # strings, lists and maps only
    except (OSError, UnicodeDecodeError, yaml.YAMLError) as error:
        print(f"grader check: cannot read {path}: {error}", file=sys.stderr)
        return None
    except RecursionError:  # [[[[…: PyYAML reads nesting by recursion
        print(f"grader check: cannot read {path}: it is nested too deeply", file=sys.stderr)
        return None
    if not isinstance(data, dict):
        print(f"grader check: {path} must map problem.part to an answer", file=sys.stderr)
        return None
    answers = {}
    for key, value in data.items():
        if isinstance(value, list) and all(isinstance(item, str | int) for item in value):
            value = ", ".join(str(item) for item in value)  # a multiple choice written as a YAML list
        if isinstance(value, dict | list) or value is None:
            print(f"grader check: {path}: the answer to {key} must be text", file=sys.stderr)
            return None
        answers[str(key)] = str(value)
    return answers


def _run_serve(args: argparse.Namespace) -> int:
    bank, assignment = _assignment(args) if args.assignment else (_load(args.bank), None)
    if bank is None:
        return EXIT_INVALID
    try:
        server = make_server(
            bank=bank,
            assignment=assignment,
            host=args.host,
            port=args.port,
            log_path=args.log,
            timeout=args.timeout,
            workers=args.workers,
        )
    except OSError as error:
        print(f"grader serve: cannot start: {error}", file=sys.stderr)
        return EXIT_INVALID
    print(f"Self-check page on {server.url} — attempts are logged to {args.log}; Ctrl-C stops.", flush=True)
    if args.host not in ("127.0.0.1", "localhost", "::1"):
        print(f"  listening on {args.host}: other computers can reach this page", flush=True)
    try:
        server.serve_forever()
    except KeyboardInterrupt:
        print("\nstopped")
    finally:
        server.server_close()
    return EXIT_OK


def _add_bank_option(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--bank", type=Path, default=default_bank_path(), help="the bank's folder (default: %(default)s)"
    )


def _load(bank: Path):
    try:
        return load_bank(bank)
    except BankError as error:
        print(f"grader: {error}", file=sys.stderr)
        return None


def _run_list(args: argparse.Namespace) -> int:
    problems = _load(args.bank)
    if problems is None:
        return EXIT_INVALID
    rows = [(p.id, p.title, " ".join(p.seed), f"{p.points:g}") for p in problems.values()]
    widths = [max(len(row[i]) for row in [("id", "title", "seed", "points"), *rows]) for i in range(4)]
    for row in [("id", "title", "seed", "points"), *rows]:
        print("  ".join(cell.ljust(width) for cell, width in zip(row, widths, strict=True)).rstrip())
    return EXIT_OK


def _run_show(args: argparse.Namespace) -> int:
    problems = _load(args.bank)
    if problems is None:
        return EXIT_INVALID
    problem = problems.get(args.id)
    if problem is None:
        print(f"grader: no problem {args.id!r} in {args.bank} (see: grader problems list)", file=sys.stderr)
        return EXIT_INVALID
    print(f"{problem.title} [{problem.id}] — seed {', '.join(problem.seed)}, {_points(problem.points)}\n")
    if problem.prompt:
        print(problem.prompt.rstrip() + "\n")
    symbols = (*problem.coordinates, *problem.parameters)
    if symbols:  # the names an answer may use, as it types them
        width = max(len(symbol.name) for symbol in symbols)
        print("Symbols:")
        for symbol in symbols:
            unit = unit_of(symbol.dimension)
            print(f"  {symbol.name:<{width}}  {symbol.meaning}{f' ({unit})' if unit else ''}".rstrip())
        print()
    for part in problem.parts:
        print(f"({part.id}) {part.kind}, {_points(part.points)}")
        if part.prompt:
            print(f"    {part.prompt.strip()}")
        for label, text in part.choices.items():
            print(f"      {label}) {text}")
        if args.answers:
            print(f"    answer: {expected_answer(problem, part)}")
            for name, value in part.given.items():  # what an answer may use, and what it stands for
                print(f"    given: {name} = {value}")
    return EXIT_OK


def _points(points: float) -> str:
    return f"{points:g} point{'' if points == 1 else 's'}"


def _run_validate(args: argparse.Namespace) -> int:
    paths = args.paths or [default_bank_path()]
    problems, failures = validate_bank(paths)
    for failure in failures:
        print(failure)
    print(f"{len(problems)} problems checked, {len(failures)} failures")
    return EXIT_OK if not failures else EXIT_WRONG


def _run_compare(args: argparse.Namespace) -> int:
    options = {"up_to_constant": True} if args.up_to_constant else {}
    if args.unit:
        options["unit"] = args.unit
    if args.given:
        options["given"] = dict(args.given)
    if args.dimensions:
        options["dimensions"] = dict(args.dimensions)
    kind = args.kind or _written_kind(args.expected, args.coords, args.known)
    try:
        verdict = compare(
            args.expected, args.submitted, kind=kind, coords=args.coords, known=args.known,
            timeout=args.timeout, **options,
        )  # fmt: skip
    except AuthorError as error:
        print(f"grader compare: {error}", file=sys.stderr)
        return EXIT_INVALID
    if args.json:
        record = {field.name: getattr(verdict, field.name) for field in fields(verdict) if field.name != "answer"}
        record |= {"equivalent": verdict.equivalent, "read_as": verdict.read_as}
        print(json.dumps(record, ensure_ascii=False, indent=2))
    else:
        print(f"{verdict.status.replace('_', ' ')} (score {verdict.score:g}, by {verdict.method})")
        for sentence in verdict.feedback:
            print(f"  {sentence}")
        if verdict.status == "invalid":
            print("\n".join(f"  {line}" for line in verdict.read_as.splitlines()))
        elif verdict.read_as:  # an answer the time limit stopped before it was read has no reading to show
            print(f"read as: {verdict.read_as}")
    return _EXIT_BY_STATUS[verdict.status]


def _written_kind(expected: str, coords: list[str], known: list[str]) -> str:
    # Without --kind, `grader compare "θ̈ = …" "…"` means an equation: the expected answer says
    # so. An unreadable one is left to compare, whose error names what is wrong with it.
    read = parse_answer(expected, coords=coords, known=known)
    return read.kind if read.ok else "expression"


def _run_parse(args: argparse.Namespace) -> int:
    result = parse_answer(args.answer, coords=args.coords, known=args.known)
    if result.ok:
        record = {
            "ok": True,
            "kind": result.kind,
            "text": result.read_as_text,
            "latex": result.read_as_latex,
            "mathml": result.read_as_mathml,
        }
        lines = [f"read as ({result.kind}): {record['text']}", f"LaTeX: {record['latex']}"]
    else:
        record = {"ok": False, "code": result.code, "message": result.message, "start": result.start}
        lines = [f"invalid: {result}"]
    print(json.dumps(record, ensure_ascii=False, indent=2) if args.json else "\n".join(lines))
    return EXIT_OK if result.ok else EXIT_INVALID


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; returns the exit status."""
    args = _parser().parse_args(argv)
    try:
        status = args.run(args)
        sys.stdout.flush()  # here, where a reader that went away can be caught, not at exit
    except BrokenPipeError:
        # `grader check … | head` stopped reading: nothing more to say, and no traceback.
        # Python would still flush at exit into the closed pipe; stdout goes nowhere now.
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return EXIT_PIPE_CLOSED
    except KeyboardInterrupt:
        # Ctrl-C: what was written is whole (every output file is renamed into place), and a
        # traceback would only hide that. `grader serve` catches its own, to say it stopped.
        print("\ngrader: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
    return status


if __name__ == "__main__":
    sys.exit(main())
