"""The ``grader`` command: a thin layer over the library, and the only code that prints or exits.

Commands:
    grader parse ANSWER [--coords q1,q2] [--known m,g,l] [--json]   how an answer is read

Exit statuses: 0 success; 2 invalid input or usage error.
"""

from __future__ import annotations

import argparse
import json
import sys
from collections.abc import Sequence

from grader import parse_answer

EXIT_OK = 0
EXIT_INVALID = 2


def _names(value: str) -> list[str]:
    return [name.strip() for name in value.split(",") if name.strip()]


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="grader", description=__doc__.splitlines()[0])
    commands = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")

    parse = commands.add_parser("parse", help="show how an answer is read", description="Show how an answer is read.")
    parse.add_argument("answer", help="the answer, in plain, Unicode or LaTeX notation")
    parse.add_argument("--coords", type=_names, default=[], help="generalized coordinates, e.g. theta1,theta2")
    parse.add_argument("--known", type=_names, default=[], help="other symbols the problem defines, e.g. m,g,l")
    parse.add_argument("--json", action="store_true", help="print JSON")
    parse.set_defaults(run=_run_parse)
    return parser


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
    return args.run(args)


if __name__ == "__main__":
    sys.exit(main())
