"""Every CSV column the grader writes, in one place.

Column names are part of what instructors' spreadsheets and LMS imports rely on: change one
here, deliberately, and the writers follow.
"""

from __future__ import annotations

# gradebook.csv: one row per student, a points-possible row first
STUDENT_ID, NAME, EMAIL = "id", "name", "email"
TOTAL, MAX, PERCENT, STATUS = "total", "max", "percent", "status"
POINTS_POSSIBLE = "Points Possible"

# scores_long.csv: one row per student and part
LONG = (
    "student",
    "part",
    "auto_score",
    "manual_score",
    "final_score",
    "max_score",
    "verdict",
    "feedback_key",
    "read_as",
    "comment",  # a person's, with their score
)

# review.csv: what needs a person; points and comment are left empty for the person to fill in,
# and the file is then an overrides file (its student, part, points and comment are OVERRIDE's)
REVIEW = (
    "student",
    "name",
    "part",
    "status",
    "proposed_points",
    "max_points",
    "points",
    "comment",
    "answer",
    "read_as",
    "feedback",
)

# overrides.csv, as instructors write it: student, part and points are needed, comment is not
OVERRIDE = ("student", "part", "points", "comment")

# Canvas gradebook import
CANVAS_IDENTITY = ("Student", "ID", "SIS User ID", "SIS Login ID", "Section")
CANVAS_POINTS_POSSIBLE = "    Points Possible"  # Canvas expects exactly four leading spaces

# Moodle grade import
MOODLE_IDENTITY = "Email address"
