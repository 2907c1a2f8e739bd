"""The problem bank: problems and assignments as validated data.

Contents:
    load_problem, load_bank, load_assignment   read YAML files, errors addressed to authors
    Problem, Part, Symbol, Mistake, RubricIdea, PartTest, Assignment, AssignmentItem
    BankError                                  a file is wrong: file, line, problem, part, field
    PART_KINDS, SCHEMA_VERSION                 what the format allows

The format is documented for authors in docs/problem-format.md.
"""

from grader.bank.load import default_bank_path, load_assignment, load_bank, load_problem, read_yaml, repeated_keys
from grader.bank.schema import (
    DIMENSIONS,
    PART_KINDS,
    SCHEMA_VERSION,
    Assignment,
    AssignmentItem,
    BankError,
    Mistake,
    Part,
    PartTest,
    Problem,
    RubricIdea,
    Symbol,
)

__all__ = [
    "DIMENSIONS",
    "PART_KINDS",
    "SCHEMA_VERSION",
    "Assignment",
    "AssignmentItem",
    "BankError",
    "Mistake",
    "Part",
    "PartTest",
    "Problem",
    "RubricIdea",
    "Symbol",
    "default_bank_path",
    "load_assignment",
    "load_bank",
    "load_problem",
    "read_yaml",
    "repeated_keys",
]
