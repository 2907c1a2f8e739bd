"""Writing grades out: gradebooks, per-student results, review queues, LMS imports; atomically.

Contents:
    write_atomic, write_all_atomic     a temporary file, then a rename: no half-written file, no half-written set
    result_json, grade_from_json       results/<student>.json (Gradescope's shape) and back
    gradebook_csv, scores_long_csv, review_csv
    read_overrides, apply_overrides, overrides_csv   a person's scores over the grader's
    canvas_csv, moodle_csv             LMS gradebook imports
    csv_file                           a CSV's text as its file's bytes, which Excel reads as UTF-8
"""

from grader.export.atomic import write_all_atomic, write_atomic
from grader.export.gradebook import (
    canvas_csv,
    grade_from_json,
    gradebook_csv,
    moodle_csv,
    result_json,
    review_csv,
    scores_long_csv,
)
from grader.export.overrides import apply_overrides, overrides_csv, read_overrides
from grader.export.spreadsheet import csv_file

__all__ = [
    "apply_overrides",
    "canvas_csv",
    "csv_file",
    "grade_from_json",
    "gradebook_csv",
    "moodle_csv",
    "overrides_csv",
    "read_overrides",
    "result_json",
    "review_csv",
    "scores_long_csv",
    "write_all_atomic",
    "write_atomic",
]
