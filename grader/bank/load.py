"""Reading the problem bank from YAML files, with line numbers for every error.

Contents:
    read_yaml(path)             data and a map from each field's path to its line
    repeated_keys(node)         each key a YAML mapping gives twice, which YAML would keep the last of
    load_problem(path)          one validated Problem
    load_bank(folder)           every problem under a folder, by id (duplicates refused)
    load_assignment(path, bank) one Assignment, its problems and parts checked against the bank
"""

from __future__ import annotations

from pathlib import Path

import yaml

from grader.bank.schema import Assignment, BankError, Problem, assignment_from_data, problem_from_data

__all__ = ["default_bank_path", "load_assignment", "load_bank", "load_problem", "read_yaml", "repeated_keys"]

MAX_FILE_BYTES = 1_000_000  # a problem is a page, not a data dump
# Values in a file once its aliases are expanded: the bank's largest problem has under 1,000. Nine
# anchors, each a list of nine aliases of the one before, are 9⁹ values from 200 bytes.
MAX_VALUES = 100_000


def read_yaml(path: Path) -> tuple[object, dict[tuple, int]]:
    """The file's data (safe YAML: no Python objects) and the 1-based line of each field.

    Raises:
        BankError: not YAML; nested deeper than the reader's stack; more than MAX_VALUES values
            once aliases are expanded; or a key twice in one mapping, where YAML would silently
            keep the last (a part's second ``answer:`` would replace its first).
    """
    text = _read_text(path)
    try:
        node = yaml.compose(text, Loader=yaml.SafeLoader)
        lines: dict[tuple, int] = {}
        _index(node, (), lines, [0], path)
        data = yaml.safe_load(text)
    except yaml.YAMLError as error:
        mark = getattr(error, "problem_mark", None)
        line = mark.line + 1 if mark else None
        raise BankError(
            f"this is not valid YAML: {getattr(error, 'problem', error)}", path=str(path), line=line
        ) from None
    except RecursionError:  # [[[[…: PyYAML reads nesting by recursion
        raise BankError("the file is nested too deeply to read", path=str(path)) from None
    return data, lines


def _read_text(path: Path) -> str:
    try:
        if path.stat().st_size > MAX_FILE_BYTES:
            raise BankError(f"the file is larger than {MAX_FILE_BYTES} bytes", path=str(path))
        return path.read_text(encoding="utf-8")
    except UnicodeDecodeError:
        raise BankError("the file is not UTF-8 text", path=str(path)) from None
    except OSError as error:
        raise BankError(f"cannot read the file: {error.strerror}", path=str(path)) from None


def _index(node, location: tuple, lines: dict, count: list[int], path: Path) -> None:
    """Record each field's line in ``lines``, counting values in ``count`` as aliases expand them."""
    if node is None:
        return
    count[0] += 1
    if count[0] > MAX_VALUES:
        raise BankError(f"the file holds more than {MAX_VALUES} values once its aliases are expanded", path=str(path))
    lines[location] = node.start_mark.line + 1
    if isinstance(node, yaml.MappingNode):
        for key, line, first in repeated_keys(node)[:1]:
            raise BankError(
                f"field {key!r} is given a second time (first on line {first}); YAML would silently keep only the last",
                path=str(path),
                line=line,
            )
        for key, value in node.value:
            line = key.start_mark.line + 1
            if not isinstance(key, yaml.ScalarNode):  # ? [a, b] : 1, which no field of the format is
                raise BankError("a field's name must be a word, not a list or a mapping", path=str(path), line=line)
            lines[(*location, key.value)] = line
            _index(value, (*location, key.value), lines, count, path)
            lines[(*location, key.value)] = line
    elif isinstance(node, yaml.SequenceNode):
        for index, item in enumerate(node.value):
            _index(item, (*location, index), lines, count, path)


def repeated_keys(node: yaml.MappingNode) -> list[tuple[str, int, int]]:
    """Each key a YAML mapping gives again, with the line it is given again on and the line it was first
    given on: YAML itself keeps the last value, silently. A merge key (``<<``) may be given again."""
    first: dict[str, int] = {}
    repeated = []
    for key, _ in node.value:
        if not isinstance(key, yaml.ScalarNode) or key.tag == "tag:yaml.org,2002:merge":
            continue
        line = key.start_mark.line + 1
        if key.value in first:
            repeated.append((key.value, line, first[key.value]))
        else:
            first[key.value] = line
    return repeated


def default_bank_path() -> Path:
    """./problems when there is one, else the bank beside the installed package."""
    here = Path("problems")
    return here if here.is_dir() else Path(__file__).resolve().parents[2] / "problems"


def load_problem(path: str | Path) -> Problem:
    """One problem file, validated; raises :class:`BankError` addressed to its author."""
    path = Path(path)
    data, lines = read_yaml(path)
    problem = problem_from_data(data, path=str(path), lines=lines)
    if problem.id != path.stem:
        raise BankError(f"the problem id is {problem.id!r} but the file is named {path.name!r}; make them match",
                        path=str(path), line=lines.get(("id",)), problem=problem.id)  # fmt: skip
    return problem


def load_bank(folder: str | Path) -> dict[str, Problem]:
    """Every ``*.yaml`` problem under ``folder`` (assignments excluded), by id."""
    folder = Path(folder)
    problems: dict[str, Problem] = {}
    for path in sorted(folder.rglob("*.yaml")):
        if "assignments" in path.relative_to(folder).parts:
            continue
        problem = load_problem(path)
        if problem.id in problems:
            raise BankError(f"problem id {problem.id!r} is also used by {problems[problem.id].path}", path=str(path))
        problems[problem.id] = problem
    return problems


def load_assignment(path: str | Path, bank: dict[str, Problem]) -> Assignment:
    """An assignment, with every problem and part it names found in ``bank``."""
    path = Path(path)
    data, lines = read_yaml(path)
    assignment = assignment_from_data(data, path=str(path), lines=lines)
    for index, item in enumerate(assignment.items):
        problem = bank.get(item.problem)
        if problem is None:
            raise BankError(f"problem {item.problem!r} is not in the bank", path=str(path),
                            line=lines.get(("problems", index)))  # fmt: skip
        for part in item.parts:
            if part not in {p.id for p in problem.parts}:
                raise BankError(f"problem {item.problem!r} has no part {part!r}", path=str(path),
                                line=lines.get(("problems", index)), problem=item.problem)  # fmt: skip
    return assignment
