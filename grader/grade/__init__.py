"""Grading against the problem bank: one answer to one part, and checking the bank itself.

Contents:
    grade_answer(problem, part, submitted)   a Verdict, with the part's mistakes and rubric applied
    expected_answer(problem, part)           the reference, derived where the part says so
    validate_bank(paths)                     every problem and assignment, graded against itself
    Failure                                  one thing ``grader validate`` found wrong
"""

from grader.grade.part import expected_answer, grade_answer
from grader.grade.validate import Failure, validate_bank

__all__ = ["Failure", "expected_answer", "grade_answer", "validate_bank"]
