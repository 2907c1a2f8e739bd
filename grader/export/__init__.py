"""Writing grades out: gradebooks, per-student results, review queues, LMS imports; atomically.

Contents:
    write_atomic                       a temporary file, then a rename: no half-written file
    result_json, grade_from_json       results/<student>.json (Gradescope's shape) and back
    gradebook_csv, scores_long_csv, review_csv
    read_overrides, apply_overrides    a person's scores over the grader's
    canvas_csv, moodle_csv             LMS gradebook imports
"""

from grader.export.atomic import write_atomic
from grader.export.gradebook import (
    apply_overrides,
    canvas_csv,
    grade_from_json,
    gradebook_csv,
    moodle_csv,
    read_overrides,
    result_json,
    review_csv,
    scores_long_csv,
)

__all__ = [
    "apply_overrides",
    "canvas_csv",
    "grade_from_json",
    "gradebook_csv",
    "moodle_csv",
    "read_overrides",
    "result_json",
    "review_csv",
    "scores_long_csv",
    "write_atomic",
]
