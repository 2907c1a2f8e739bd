"""A class of two for the export tests: one graded on two parts, one whose grading failed."""

from grader.grade.results import PartGrade, Student, SubmissionGrade

MAX_POINTS = {"p.a": 2.0, "p.b": 3.0}


def small_class() -> list[SubmissionGrade]:
    """s1: part a right (2 of 2), part b waiting for a person (1 of 3 proposed); s2: not graded, with
    the internal error a student must never be shown."""
    parts = (
        PartGrade("p", "a", 2.0, "x", "equivalent", 2.0),
        PartGrade("p", "b", 3.0, "y", "undecided", 1.0, ("A person will read this answer.",)),
    )
    return [
        SubmissionGrade(Student("s1", "O'Brien, Pat", "pat@x.org"), parts),
        SubmissionGrade(Student("s2", "Lee", "lee@x.org"), (), "error", "could not be graded: OSError: [Errno 22]"),
    ]
