"""Reports of batch grading: a page per student and a summary for the instructor.

Contents:
    render_student_report(grade, assignment=, bank=, reveal=)   (HTML, Markdown) of one student's grades
    render_summary(grades, assignment=, bank=, input_issues=)   the class summary, HTML
    item_analysis(grades), ItemStats                            each part's mean, full credit, discrimination
    class_counts, score_histogram, common_wrong_answers, review_queue   the summary's other numbers

Functions return text; writing it to files is the caller's (the CLI's) work.
Templates live in the repository's ``templates/`` folder, which an installed wheel carries as ``grader/templates``.
"""

from grader.report.analysis import (
    ClassCounts,
    ItemStats,
    WrongAnswer,
    class_counts,
    common_wrong_answers,
    item_analysis,
    review_queue,
    score_histogram,
)
from grader.report.render import STATUS_LABELS, TEMPLATES, render_student_report, render_summary

__all__ = [
    "STATUS_LABELS",
    "TEMPLATES",
    "ClassCounts",
    "ItemStats",
    "WrongAnswer",
    "class_counts",
    "common_wrong_answers",
    "item_analysis",
    "render_student_report",
    "render_summary",
    "review_queue",
    "score_histogram",
]
