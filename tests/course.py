"""The course the tests grade: the repository's problem bank and its review assignment, read once."""

from pathlib import Path

from grader.bank import load_assignment, load_bank

ROOT = Path(__file__).resolve().parent.parent
BANK = load_bank(ROOT / "problems")
REVIEW = load_assignment(ROOT / "problems" / "assignments" / "review.yaml", BANK)
