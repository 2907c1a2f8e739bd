"""What is written out: every CSV's cells, a person's scores read back and checked, LMS imports, all-or-none writes."""

from __future__ import annotations

import csv
import io
import os
import signal
import stat

import pytest
from small_class import MAX_POINTS, small_class

from grader.errors import GraderError
from grader.export import (
    canvas_csv,
    gradebook_csv,
    moodle_csv,
    overrides_csv,
    read_overrides,
    review_csv,
    scores_long_csv,
    write_all_atomic,
    write_atomic,
)
from grader.grade.results import PartGrade, Student, SubmissionGrade

# -- CSV cells ---------------------------------------------------------------------------------


def _every_csv(grades, overrides) -> dict[str, str]:
    return {
        "gradebook": gradebook_csv(grades, [("p.a", 2.0)]),
        "scores_long": scores_long_csv(grades),
        "review": review_csv(grades),
        "canvas": canvas_csv(grades, assignment="A", assignment_id="1", max_score=2.0),
        "moodle": moodle_csv(grades, assignment="A"),
        "overrides": overrides_csv(overrides),
    }


@pytest.mark.parametrize("name", ["gradebook", "scores_long", "review", "canvas", "moodle", "overrides"])
def test_a_line_break_in_a_cell_never_starts_a_row(name):
    # A bare carriage return ends a row in a spreadsheet: unquoted, "=1+2" would start the next one.
    answer, read_as = "x\r=cmd|' /C calc'!A0", "y\r@SUM(1)"
    parts = (PartGrade("p", "a", 2.0, answer, "undecided", 0.0, ("T = 1\r\nV = 2",), read_as=read_as),)
    grades = [SubmissionGrade(Student("s1", "Bob\r=1+2", "bob\r=1+2@x.org"), parts)]
    text = _every_csv(grades, {("s1", "p.a"): (1.0, "ok\r=1+2")})[name]
    rows = list(csv.reader(io.StringIO(text, newline="")))  # as a spreadsheet reads it: \r, \n and \r\n end rows
    assert len(rows) > 1 and all(len(row) == len(rows[0]) for row in rows)
    cells = [cell for row in rows for cell in row]
    assert not [cell for cell in cells if cell[:1] in ("=", "+", "@", "\t", "\r", "\n")]
    assert "\r" not in text  # a line break in a cell is the files' own, "\n", inside quotes
    assert {"Bob\n=1+2", "bob\n=1+2@x.org", "y\n@SUM(1)", "ok\n=1+2"} & set(cells)  # the text kept, on lines


# -- a person's scores ---------------------------------------------------------------------------

BAD_POINTS = [
    # (points as typed, the part): not a number from 0 to what the part is worth
    ("nan", "p.a"), ("inf", "p.a"), ("-inf", "p.a"), ("1e400", "p.a"), ("-0.5", "p.a"), ("2.5", "p.a"),
    ("10", "p.b"), ("abc", "p.a"), ("2,5,1", "p.b"),
]  # fmt: skip


@pytest.mark.parametrize(("points", "part"), BAD_POINTS)
def test_override_points_must_be_a_number_from_0_to_the_parts_worth(tmp_path, points, part):
    path = tmp_path / "overrides.csv"
    path.write_text(f'student,part,points,comment\ns1,p.b,1,fine\ns2,{part},"{points}",typo\n')
    with pytest.raises(GraderError) as error:
        read_overrides(path, max_points=MAX_POINTS)
    assert str(error.value) == (
        "the overrides cannot be used:\n"
        f"  {path}, row 3 (student 's2', part '{part}'): points must be a number from 0 to"
        f" {MAX_POINTS[part]:g}, what the part is worth, not '{points}'"
    )


def test_every_bad_override_row_is_listed_and_two_points_for_one_part_are_one(tmp_path):
    path = tmp_path / "overrides.csv"
    path.write_text("student,part,points\ns1,p.a,1\ns1,p.b,3\ns1,p.a,1\ns1,p.a,2\ns2,p.a,nan\n,p.a,1\n")
    with pytest.raises(GraderError) as error:
        read_overrides(path, max_points=MAX_POINTS)
    assert str(error.value).splitlines()[1:] == [
        f"  {path}, row 5 (student 's1', part 'p.a'): points '2', but row 2 gives this part 1",
        f"  {path}, row 6 (student 's2', part 'p.a'): points must be a number from 0 to 2, what the part is worth,"
        " not 'nan'",
        f"  {path}, row 7: points '1' for no student",
    ]


def test_empty_points_are_not_scored_yet_and_a_part_not_in_the_assignment_is_left_to_match(tmp_path):
    path = tmp_path / "overrides.csv"
    path.write_text("student,part,points,comment\ns1,p.a,,later\ns1,p.a,2,full\ns1,q.z,7,\n")
    assert read_overrides(path, max_points=MAX_POINTS) == {("s1", "p.a"): (2.0, "full"), ("s1", "q.z"): (7.0, "")}


@pytest.mark.parametrize("header", ["student,part,score,comment", "student;points;comment", "id,part,points", ""])
def test_an_overrides_header_without_student_part_and_points_is_an_error(tmp_path, header):
    path = tmp_path / "overrides.csv"
    path.write_text(f"{header}\ns1,p.a,1\n")
    with pytest.raises(GraderError, match=r"row 1: the header needs the columns student, part and points"):
        read_overrides(path, max_points=MAX_POINTS)


def test_a_missing_overrides_file_is_an_error_naming_it(tmp_path):
    with pytest.raises(GraderError, match=r"^cannot read the overrides .*nope\.csv: No such file or directory$"):
        read_overrides(tmp_path / "nope.csv", max_points=MAX_POINTS)


def test_review_csv_filled_in_is_an_overrides_file_also_as_excel_saves_it(tmp_path):
    review = list(csv.reader(io.StringIO(review_csv(small_class()))))
    assert review[0][4:8] == ["proposed_points", "max_points", "points", "comment"]
    assert [row[6:8] for row in review[1:]] == [["", ""], ["", ""]]  # for a person to fill in
    review[1][6:8] = ["2,5", "Sound argument"]  # s1's p.b, scored with a decimal comma
    path = tmp_path / "review.csv"
    # Excel where a comma is the decimal mark: a byte-order mark, ";" between cells, CRLF
    with path.open("w", encoding="utf-8-sig", newline="") as file:
        csv.writer(file, delimiter=";").writerows(review)
    assert read_overrides(path, max_points=MAX_POINTS) == {("s1", "p.b"): (2.5, "Sound argument")}


def test_saved_overrides_read_back_as_they_were(tmp_path):
    overrides = {("-s1", "p.a"): (1.5, "=not a formula"), ("s2", "p.b"): (0.0, ""), ("s3", "p.b"): (3.0, "a\nb")}
    path = write_atomic(tmp_path / "overrides.csv", overrides_csv(overrides))
    assert read_overrides(path, max_points=MAX_POINTS) == overrides


# -- LMS imports -----------------------------------------------------------------------------------


def test_an_lms_import_has_no_row_and_no_error_text_for_a_student_who_could_not_be_graded():
    for text in (
        canvas_csv(small_class(), assignment="Review", assignment_id="review", max_score=5),
        moodle_csv(small_class(), assignment="Review"),
    ):
        assert "Errno" not in text and "could not be graded" not in text
        rows = list(csv.reader(io.StringIO(text)))
        assert [row for row in rows if "s2" in row or "lee@x.org" in row] == []
        assert [row for row in rows if "s1" in row or "pat@x.org" in row] != []


# -- writing -----------------------------------------------------------------------------------------


def test_a_set_of_files_is_written_all_or_none(tmp_path):
    write_all_atomic({tmp_path / "a.csv": "old a", tmp_path / "sub" / "b.csv": "old b"})

    def failing():
        yield tmp_path / "a.csv", "new a"
        yield tmp_path / "sub" / "c.csv", "new c"
        raise RuntimeError("rendering failed")

    with pytest.raises(RuntimeError):
        write_all_atomic(failing(), remove=[tmp_path / "sub" / "b.csv"])
    assert (tmp_path / "a.csv").read_text() == "old a" and (tmp_path / "sub" / "b.csv").read_text() == "old b"
    assert sorted(p.name for p in tmp_path.rglob("*") if p.is_file()) == ["a.csv", "b.csv"]  # no temporaries
    write_all_atomic({tmp_path / "a.csv": "new a"}, remove=[tmp_path / "sub" / "b.csv"])
    assert sorted(p.name for p in tmp_path.rglob("*") if p.is_file()) == ["a.csv"]


def test_a_ctrl_c_among_the_renames_is_raised_once_every_file_is_in_place(tmp_path, monkeypatch):
    write_all_atomic({tmp_path / "a.csv": "old a", tmp_path / "b.csv": "old b", tmp_path / "c.csv": "old c"})
    replace = os.replace

    def pressed_during_the_first(source, target):
        if not pressed:
            pressed.append(target)
            signal.raise_signal(signal.SIGINT)  # handled before raise_signal returns, as a terminal's is
        replace(source, target)

    pressed = []
    monkeypatch.setattr(os, "replace", pressed_during_the_first)
    with pytest.raises(KeyboardInterrupt):
        write_all_atomic({tmp_path / "a.csv": "new a", tmp_path / "b.csv": "new b"}, remove=[tmp_path / "c.csv"])
    assert pressed == [tmp_path / "a.csv"]
    assert sorted((p.name, p.read_text()) for p in tmp_path.iterdir()) == [("a.csv", "new a"), ("b.csv", "new b")]


def test_files_are_written_with_the_permissions_the_umask_gives(tmp_path):
    previous = os.umask(0o027)
    try:
        path = write_atomic(tmp_path / "gradebook.csv", "student\n")
    finally:
        os.umask(previous)
    assert stat.S_IMODE(path.stat().st_mode) == 0o640  # not mkstemp's 0600: a TA in the group reads it
