"""``python -m grader`` and the ``grader`` command.

The command line itself is :mod:`grader.cli`. It is imported here, inside a ``try``: loading
sympy and pandas takes a second or two, and a Ctrl-C in that time should end the command with
its status, not with a traceback through the import machinery.
"""

import sys

EXIT_INTERRUPTED = 130  # grader.cli.EXIT_INTERRUPTED, which a Ctrl-C may have stopped loading


def main() -> int:
    """Run the command line; returns the exit status."""
    try:
        from grader.cli import main as run
    except KeyboardInterrupt:
        print("\ngrader: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
    return run()


if __name__ == "__main__":
    sys.exit(main())
