"""Batch grading: reading submissions, grading a class, a person's scores, and what is written out."""

from __future__ import annotations

import csv
import io
import json
import os
from pathlib import Path

import pytest
from course import BANK, REVIEW
from small_class import small_class

from grader.bank import load_assignment
from grader.errors import GraderError
from grader.export import (
    apply_overrides,
    canvas_csv,
    grade_from_json,
    gradebook_csv,
    moodle_csv,
    read_overrides,
    result_json,
    review_csv,
    scores_long_csv,
    write_atomic,
)
from grader.grade import batch
from grader.grade.batch import assignment_parts, grade_class, grade_submission
from grader.grade.part import grade_answer
from grader.grade.results import PartGrade, Student, SubmissionGrade
from grader.grade.submissions import Submission, read_submissions
from grader.run import file_name

PENDULUM_L = "1/2 m l^2 thetadot^2 + m g l cos(theta)"


def _pendulum_only(tmp_path: Path):
    path = tmp_path / "a.yaml"
    path.write_text("schema_version: 1\nid: a\ntitle: Pendulum\nproblems:\n  - problem: plane-pendulum\n")
    return load_assignment(path, BANK)


def test_a_wide_csv_is_read_and_its_problems_reported_by_row(tmp_path):
    path = tmp_path / "class.csv"
    path.write_text(
        "id,name,email,plane-pendulum.lagrangian,plane-pendulum.nonsense\n"
        's1,"Núñez, María",m@x.org,' + PENDULUM_L + ",x\n"
        "s2,Bob,b@x.org,,\n"
        "s1,Again,a@x.org,x,y\n"
        ",No Id,n@x.org,x,y\n"
        "s3,Extra,e@x.org,x,y,z\n",
        encoding="utf-8",
    )
    submissions, issues = read_submissions(path, ["plane-pendulum.lagrangian"])
    assert [s.student.id for s in submissions] == ["s1", "s2"]
    assert submissions[0].student.name == "Núñez, María"
    assert submissions[0].answers == {"plane-pendulum.lagrangian": PENDULUM_L}
    assert [str(issue) for issue in issues] == [
        f"{path}, row 1, column 5: unknown column 'plane-pendulum.nonsense': not a part of this assignment",
        f"{path}, row 5 (line 5): the row has no student id; row skipped",
        f"{path}, row 6 (line 6), student 's3': the row has 6 cells but the header 5; row skipped",
        f"{path}, row 4 (line 4): student 's1' also appears at {path}, row 2 (line 2); the first one is graded",
    ]


def test_a_folder_of_answer_files_is_read(tmp_path):
    (tmp_path / "s1.yaml").write_text(f"id: s1\nname: Ann\nanswers:\n  plane-pendulum.lagrangian: '{PENDULUM_L}'\n")
    (tmp_path / "s2.json").write_text(json.dumps({"id": "s2", "answers": {"plane-pendulum.nope": "1"}}))
    (tmp_path / "s3.yaml").write_text("id: [unclosed\n")
    submissions, issues = read_submissions(tmp_path, ["plane-pendulum.lagrangian"])
    assert [s.student.id for s in submissions] == ["s1", "s2"]
    assert "unknown part 'plane-pendulum.nope'" in str(issues[0])
    assert str(issues[1]).startswith(f"{tmp_path / 's3.yaml'}: cannot be read")


def test_a_part_answered_twice_in_one_file_is_reported_with_the_answer_read(tmp_path):
    twice = f"id: s1\nanswers:\n  plane-pendulum.lagrangian: '{PENDULUM_L}'\n  plane-pendulum.lagrangian: '0'\n"
    (tmp_path / "s1.yaml").write_text(twice)
    (tmp_path / "s2.json").write_text('{"id": "s2", "answers": {"plane-pendulum.lagrangian": "1",'
                                      ' "plane-pendulum.lagrangian": "2"}}')  # fmt: skip
    (tmp_path / "s3.yaml").write_text("id: s3\nanswers:\n  plane-pendulum.lagrangian: '1'\n")  # once: no issue
    submissions, issues = read_submissions(tmp_path, ["plane-pendulum.lagrangian"])
    assert [s.answers["plane-pendulum.lagrangian"] for s in submissions] == ["0", "2", "1"]  # as YAML and JSON read
    assert [str(issue) for issue in issues] == [
        f"{tmp_path / 's1.yaml'}, line 4: 'plane-pendulum.lagrangian' is given twice; the last one is read",
        f"{tmp_path / 's2.json'}: 'plane-pendulum.lagrangian' is given twice; the last one is read",
    ]


def test_a_cell_longer_than_the_csv_modules_limit_is_read_and_cut(tmp_path):
    path = tmp_path / "class.csv"
    path.write_text(f"id,plane-pendulum.lagrangian\ns1,{'x' * 140_000}\ns2,{PENDULUM_L}\n", encoding="utf-8")
    submissions, issues = read_submissions(path, ["plane-pendulum.lagrangian"])
    assert [len(s.answers["plane-pendulum.lagrangian"]) for s in submissions] == [10_000, len(PENDULUM_L)]
    assert issues == []


def test_a_column_given_twice_is_reported_and_the_first_read(tmp_path):
    path = tmp_path / "class.csv"
    path.write_text(f"id,plane-pendulum.lagrangian,id,plane-pendulum.lagrangian\ns1,{PENDULUM_L},x,y\n")
    submissions, issues = read_submissions(path, ["plane-pendulum.lagrangian"])
    assert (submissions[0].student.id, submissions[0].answers) == ("s1", {"plane-pendulum.lagrangian": PENDULUM_L})
    assert [str(issue) for issue in issues] == [
        f"{path}, row 1, column 3: 'id' is also column 1; that one is read",
        f"{path}, row 1, column 4: 'plane-pendulum.lagrangian' is also column 2; that one is read",
    ]


def test_a_csv_saved_as_windows_1252_is_read_and_said_so(tmp_path):
    path = tmp_path / "class.csv"
    path.write_bytes('id,name,plane-pendulum.lagrangian\ns1,"Núñez, María",½ m l^2 thetadot^2\n'.encode("cp1252"))
    submissions, issues = read_submissions(path, ["plane-pendulum.lagrangian"])
    assert submissions[0].student.name == "Núñez, María"
    assert submissions[0].answers["plane-pendulum.lagrangian"] == "½ m l^2 thetadot^2"
    assert [str(issue) for issue in issues] == [
        f"{path}: not UTF-8 (byte 40); read as Windows-1252 (Latin-1): check accented names and answers,"
        " or save the file as CSV UTF-8"
    ]


def test_nul_characters_are_left_out_and_a_utf16_file_is_read(tmp_path):
    nul = tmp_path / "nul.csv"
    nul.write_bytes(f"id,name,plane-pendulum.lagrangian\ns1,A\x00B,{PENDULUM_L}\x00\n".encode())
    submissions, issues = read_submissions(nul, ["plane-pendulum.lagrangian"])
    assert (submissions[0].student.name, submissions[0].answers["plane-pendulum.lagrangian"]) == ("AB", PENDULUM_L)
    assert [str(issue) for issue in issues] == [f"{nul}: the file holds NUL characters; they are left out"]
    wide = tmp_path / "utf16.csv"
    wide.write_bytes(f"id,name,plane-pendulum.lagrangian\ns1,Núñez,{PENDULUM_L}\n".encode("utf-16"))
    submissions, issues = read_submissions(wide, ["plane-pendulum.lagrangian"])
    assert (submissions[0].student.name, issues) == ("Núñez", [])


PENDULUM_HEADER = "id,name,email,plane-pendulum.lagrangian,plane-pendulum.motion\n"
PENDULUM_KEYS = ["plane-pendulum.lagrangian", "plane-pendulum.motion"]


def test_a_row_with_too_few_cells_is_reported_and_skipped(tmp_path):
    path = tmp_path / "class.csv"
    path.write_text(f"{PENDULUM_HEADER}s1,Ann,a@x.org,{PENDULUM_L},\ns2,Bob,b@x.org,{PENDULUM_L}\n", encoding="utf-8")
    submissions, issues = read_submissions(path, PENDULUM_KEYS)
    assert [s.student.id for s in submissions] == ["s1"]
    assert [str(issue) for issue in issues] == [
        f"{path}, row 3 (line 3), student 's2': the row has 4 cells but the header 5; row skipped"
    ]


def test_a_quote_left_open_is_reported_with_the_lines_it_swallowed(tmp_path):
    path = tmp_path / "class.csv"
    path.write_text(
        f"{PENDULUM_HEADER}s1,Ann,a@x.org,{PENDULUM_L},\n"
        's9,"Broken, Name,x@y,1\n'  # its quote closes in the next student's row
        's2,Bob,b@x.org,"x, y",z\n'
        's5,Ed,e@x.org,"θ̈ = 0\nφ̈ = 0",x,stray\n'  # a line break in an answer, as it should be, and a stray cell
        f's3,Cy,c@x.org,{PENDULUM_L},"θ̈ = -(g/l) sin θ\n'  # a quote that never closes: the right number of cells
        f"s4,Di,d@x.org,{PENDULUM_L},\n",
        encoding="utf-8",
    )
    submissions, issues = read_submissions(path, PENDULUM_KEYS)
    assert [s.student.id for s in submissions] == ["s1"]
    assert [str(issue) for issue in issues] == [
        f"{path}, row 3 (lines 3–4), student 's9': the row has 4 cells but the header 5: the quote that opens cell 2"
        " on line 3 closes only on line 4, and line 4, read into that cell, begins a row of its own"
        " ('s2,Bob,b@x.org,\"x, y\",z'): most likely a quote was left open on line 3; row skipped",
        f"{path}, row 4 (lines 5–6), student 's5': the row has 6 cells but the header 5; row skipped",
        f"{path}, row 5 (lines 7–8), student 's3': the quote that opens cell 5 on line 7 never closes, so the rest of"
        " the file was read into it (line 8 starts 's4,Di,d@x.org,1/2 m l^2 thetadot^2 + m g…'); row skipped",
    ]


def test_a_carriage_return_alone_in_a_cell_does_not_split_its_row(tmp_path):
    path = tmp_path / "class.csv"
    path.write_bytes(f"{PENDULUM_HEADER}s1,\r=1+2,a@x.org,{PENDULUM_L},x\r\ns2,Bob,b@x.org,,\r\n".encode())
    submissions, issues = read_submissions(path, PENDULUM_KEYS)
    assert [(s.student.id, s.student.name, s.answers["plane-pendulum.motion"]) for s in submissions] == [
        ("s1", "=1+2", "x"),
        ("s2", "Bob", ""),
    ]
    assert issues == []


def test_bytes_not_utf8_in_a_utf8_file_are_named_and_their_answer_marked(tmp_path):
    path = tmp_path / "class.csv"
    motion = "θ̈ = -(g/l) sin θ"
    path.write_bytes(
        f'{PENDULUM_HEADER}s1,"Núñez, María",m@x.org,{PENDULUM_L},{motion}\n'.encode()
        + b"s2,Bob,b@x.org,\xbd m l^2 thetadot^2,"
        + motion.encode()
        + b"\n"
    )
    submissions, issues = read_submissions(path, PENDULUM_KEYS)
    assert [(s.student.name, s.answers["plane-pendulum.motion"]) for s in submissions] == [
        ("Núñez, María", motion),
        ("Bob", motion),
    ]
    assert submissions[1].answers["plane-pendulum.lagrangian"] == "� m l^2 thetadot^2"
    assert [sorted(s.garbled) for s in submissions] == [[], ["plane-pendulum.lagrangian"]]
    assert [str(issue) for issue in issues] == [
        f"{path}: a byte not UTF-8 in a file that otherwise is (line 3): read as �, and an answer that holds one goes"
        " to a person",
        f"{path}, row 3 (line 3), student 's2', part plane-pendulum.lagrangian: the answer holds a byte that is not"
        " UTF-8 (0xBD), read as �; it goes to a person to check",
    ]


def test_bytes_not_utf8_in_an_answer_file_are_named_and_their_answer_marked(tmp_path):
    path = tmp_path / "s1.yaml"
    path.write_bytes("id: s1\nname: Núñez\nanswers:\n  plane-pendulum.lagrangian: '".encode() + b"\xbd m l^2'\n")
    submissions, issues = read_submissions(tmp_path, PENDULUM_KEYS)
    assert (submissions[0].student.name, submissions[0].garbled) == ("Núñez", {"plane-pendulum.lagrangian"})
    assert [str(issue) for issue in issues] == [
        f"{path}: a byte not UTF-8 in a file that otherwise is (line 4): read as �, and an answer that holds one goes"
        " to a person",
        f"{path}, part plane-pendulum.lagrangian: the answer holds bytes that are not UTF-8, read as �; it goes to a"
        " person to check",
    ]


def test_part_columns_match_in_any_case_and_those_missing_are_named(tmp_path):
    path = tmp_path / "class.csv"
    path.write_text(f"ID,Name, Plane-Pendulum.Lagrangian \ns1,Ann,{PENDULUM_L}\n", encoding="utf-8")
    submissions, issues = read_submissions(path, PENDULUM_KEYS)
    assert submissions[0].answers == {"plane-pendulum.lagrangian": PENDULUM_L}
    assert [str(issue) for issue in issues] == [
        f"{path}, row 1: no column for 1 part of this assignment, so everyone's answer is blank: plane-pendulum.motion"
    ]


@pytest.mark.parametrize("separator", [";", "\t"])
def test_a_file_separated_by_semicolons_or_tabs_is_read(tmp_path, separator):
    path = tmp_path / "class.csv"
    rows = [["id", "name", "email", *PENDULUM_KEYS], ["s1", "Núñez, María", "m@x.org", PENDULUM_L, "2,5 θ"]]
    with path.open("w", newline="", encoding="utf-8") as file:
        csv.writer(file, delimiter=separator).writerows(rows)
    submissions, issues = read_submissions(path, PENDULUM_KEYS)
    assert (submissions[0].student.name, submissions[0].answers["plane-pendulum.motion"], issues) == (
        "Núñez, María",
        "2,5 θ",
        [],
    )


UNUSABLE_FILES = [
    ("", "{path} is empty: no header and no students"),
    ("\n\n", "{path} is empty: no header and no students"),
    (PENDULUM_HEADER, "{path} has a header but no rows of answers: there is no student to grade"),
    (PENDULUM_HEADER + ",,,,\n", "{path} has a header but no rows of answers: there is no student to grade"),
    (
        "a,b,c\n1,2,3\n",
        "{path}, row 1: the header has no 'id' column: a CSV is expected, separated by commas, with the header id,"
        " name, email, then a column per problem.part; its first line begins 'a,b,c'",
    ),
    (
        "id|name|plane-pendulum.lagrangian\ns1|Ann|x\n",
        "{path}, row 1: the header has no 'id' column: a CSV is expected, separated by commas, with the header id,"
        " name, email, then a column per problem.part; its first line begins 'id|name|plane-pendulum.lagrangian'",
    ),
    (
        "id,name,atwood-machine.lagrangian\ns1,Ann,x\n",
        "{path}, row 1: no column of the header is a part of this assignment (a column per problem.part, such as"
        " 'plane-pendulum.lagrangian'): is it the file for another assignment?",
    ),
]


@pytest.mark.parametrize(
    ("text", "message"),
    UNUSABLE_FILES,
    ids=["empty", "blank", "header-only", "header-and-blank-row", "no-id", "another-separator", "another-assignment"],
)
def test_a_file_that_is_no_class_is_refused_with_what_it_is(tmp_path, text, message):
    path = tmp_path / "class.csv"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(GraderError) as raised:
        read_submissions(path, PENDULUM_KEYS)
    assert str(raised.value) == message.format(path=path)


BILLION_LAUGHS = "\n".join(
    ["id: s4", "a0: &a0 [lol, lol, lol, lol, lol, lol, lol, lol, lol]"]
    + [f"a{i}: &a{i} [{', '.join([f'*a{i - 1}'] * 9)}]" for i in range(1, 9)]
    + ["answers:", "  plane-pendulum.lagrangian: *a8"]
)


def test_hostile_answer_files_are_reported_and_the_rest_read(tmp_path):
    (tmp_path / "s1.json").write_text(json.dumps({"id": "s1", "answers": {"plane-pendulum.lagrangian": PENDULUM_L}}))
    (tmp_path / "s2.json").write_text("[" * 100_000)  # deeper than the JSON reader's stack
    (tmp_path / "s3.yaml").write_text("[" * 20_000)
    (tmp_path / "s4.yaml").write_text(BILLION_LAUGHS)  # 9⁹ items, were the list written out
    (tmp_path / "s5.yaml").write_text("id: {a: 1}\nanswers: {}\n")
    submissions, issues = read_submissions(tmp_path, ["plane-pendulum.lagrangian"])
    assert [(s.student.id, s.answers["plane-pendulum.lagrangian"]) for s in submissions if s.answers] == [
        ("s1", PENDULUM_L),
        ("s4", ""),
    ]
    assert [str(issue) for issue in issues] == [
        f"{tmp_path / 's2.json'}: cannot be read: nested too deeply",
        f"{tmp_path / 's3.yaml'}: cannot be read: nested too deeply",
        f"{tmp_path / 's4.yaml'}: the answer to plane-pendulum.lagrangian is a list, not text; left blank",
        f"{tmp_path / 's5.yaml'}: id, name and email must each be text",
    ]


def test_grading_one_submission_gives_every_part_of_the_assignment(tmp_path):
    assignment = _pendulum_only(tmp_path)
    grade = grade_submission(Submission(Student("s1"), {"plane-pendulum.lagrangian": PENDULUM_L}), assignment, BANK)
    by_key = {part.key: part for part in grade.parts}
    assert list(by_key) == [f"plane-pendulum.{p.id}" for p in BANK["plane-pendulum"].parts]
    assert by_key["plane-pendulum.lagrangian"].status == "equivalent"
    assert by_key["plane-pendulum.lagrangian"].auto_score == 4
    assert by_key["plane-pendulum.motion"].status == "blank"
    assert grade.score == 4 and grade.max_score == BANK["plane-pendulum"].points


def test_an_answer_that_lost_bytes_on_reading_goes_to_a_person_with_its_score_proposed(tmp_path):
    assignment = _pendulum_only(tmp_path)
    answers = {"plane-pendulum.lagrangian": PENDULUM_L, "plane-pendulum.motion": "θ̈ = -(g/l) sin θ �"}
    submission = Submission(Student("s1"), answers, garbled=frozenset({"plane-pendulum.lagrangian"}))
    by_key = {part.key: part for part in grade_submission(submission, assignment, BANK).parts}
    lagrangian = by_key["plane-pendulum.lagrangian"]
    assert (lagrangian.status, lagrangian.auto_score, lagrangian.needs_review) == ("undecided", 4, True)
    assert lagrangian.feedback[-1] == (
        "Part of this answer could not be read from the file it came in (shown as �): a person will check it."
    )
    assert batch.GARBLED not in by_key["plane-pendulum.motion"].feedback  # a � the student typed is theirs


def test_equations_right_for_the_students_own_wrong_lagrangian_earn_method_credit(tmp_path):
    assignment = _pendulum_only(tmp_path)
    answers = {
        "plane-pendulum.lagrangian": "1/2 m l^2 thetadot^2 - m g l cos(theta)",  # T + V
        "plane-pendulum.motion": "m l^2 thetaddot - m g l sin(theta) = 0",  # what T + V implies
    }
    motion = next(
        p for p in grade_submission(Submission(Student("s"), answers), assignment, BANK).parts if p.part == "motion"
    )
    assert (motion.auto_score, motion.method) == (1.5, "error carried forward")
    assert motion.feedback == (
        "Your equations follow correctly from your own Lagrangian, which is not right: method credit.",
    )


@pytest.mark.parametrize(
    "lagrangian",
    [
        # T + V, written as a Lagrangian part reads it: before, only the bare expression carried credit
        "L = 1/2 m l^2 thetadot^2 - m g l cos(theta)",
        "L = T - V = 1/2 m l^2 thetadot^2 - m g l cos(theta)",
        "L = \\frac12 m l^2 \\dot\\theta^2 - mgl\\cos\\theta",
        "T = ½ m l² θ̇²; V = m g l cos θ; L = T − V",
        "1/2 m v^2 - m g l cos(theta), where v = l thetadot",
    ],
)
def test_method_credit_reads_the_lagrangian_as_its_part_does(tmp_path, lagrangian):
    answers = {"plane-pendulum.lagrangian": lagrangian, "plane-pendulum.motion": "l θ̈ = g sin θ"}
    grade = grade_submission(Submission(Student("s"), answers), _pendulum_only(tmp_path), BANK)
    motion = next(p for p in grade.parts if p.part == "motion")
    assert (motion.auto_score, motion.method) == (1.5, "error carried forward"), motion


@pytest.mark.parametrize(
    ("problem", "lagrangian", "motion"),
    [
        ("plane-pendulum", "0", "0 = 0"),
        ("plane-pendulum", "m g l cos θ", "sin θ = 0"),  # no kinetic term: sin θ = 0 is no motion
        ("atwood-machine", "(m1 - m2) g x", "m1 = m2"),
        ("rotating-hoop", "θ̇ sin θ + 5", "1 = 1"),  # a total derivative and a constant: no motion at all
    ],
)
def test_equations_that_determine_no_acceleration_earn_no_method_credit(tmp_path, problem, lagrangian, motion):
    path = tmp_path / "a.yaml"
    path.write_text(f"schema_version: 1\nid: a\ntitle: A\nproblems:\n  - problem: {problem}\n")
    answers = {f"{problem}.lagrangian": lagrangian, f"{problem}.motion": motion}
    grade = grade_submission(Submission(Student("s"), answers), load_assignment(path, BANK), BANK)
    graded = next(p for p in grade.parts if p.part == "motion")
    assert graded.auto_score == 0 and graded.method != "error carried forward"


@pytest.mark.parametrize(
    ("problem", "lagrangian", "motion", "credit"),
    [
        # no energy: its equations are no physics
        ("atwood-machine", "xdot^2", "xddot = 0", False),
        ("spherical-pendulum", "thetadot^2 + phidot^2", "thetaddot = 0; phiddot = 0", False),
        # a listed mistake's, whose hint the student is told instead of its units
        ("plane-pendulum", "1/2 m l thetadot^2 + m g l cos(theta)", "m l thetaddot + m g l sin(theta) = 0", False),
        # a coordinate left out (the potential forgotten): no force, equations easier than those asked
        ("atwood-machine", "1/2 (m1 + m2) xdot^2", "(m1 + m2) xddot = 0", False),
        ("plane-pendulum", "1/2 m l^2 thetadot^2 + m g l", "thetaddot = 0", False),
        ("rotating-hoop", "1/2 m R^2 thetadot^2 + m g R", "thetaddot = 0", False),
        # an acceleration in L: its equations are of a higher order, not those derived from it as if it had none
        ("plane-pendulum", "1/2 m l^2 θ̇^2 + m g l cos θ + 1/2 m l^2 θ^2 θ̈", "m l^2 (1 - θ) θ̈ + m g l sin θ = 0", False),
        # a wrong sign or a wrong term: the work after it is as hard, and earns the credit
        ("atwood-machine", "1/2 (m1 + m2) xdot^2 - (m1 - m2) g x", "(m1 + m2) xddot = -(m1 - m2) g", True),
        ("rotating-hoop", "1/2 m R^2 thetadot^2 + m g R cos θ", "R θ̈ = -g sin θ", True),  # ω forgotten, not θ
    ],
)
def test_method_credit_needs_a_lagrangian_that_makes_the_equations_no_easier(
    tmp_path, problem, lagrangian, motion, credit
):
    path = tmp_path / "a.yaml"
    path.write_text(f"schema_version: 1\nid: a\ntitle: A\nproblems:\n  - problem: {problem}\n")
    answers = {f"{problem}.lagrangian": lagrangian, f"{problem}.motion": motion}
    grade = grade_submission(Submission(Student("s"), answers), load_assignment(path, BANK), BANK)
    graded = next(p for p in grade.parts if p.part == "motion")
    assert (graded.method == "error carried forward") == credit, graded
    assert (graded.auto_score > 0) == credit, graded


def test_an_answer_given_word_for_word_is_graded_once_a_run(tmp_path, monkeypatch):
    assignment = _pendulum_only(tmp_path)
    right, wrong = PENDULUM_L, "1/2 m l^2 thetadot^2 - m g l cos(theta)"
    answers = [right, wrong, right, wrong + " ", right]  # a space makes another answer
    submissions = [Submission(Student(f"s{i}"), {"plane-pendulum.lagrangian": a}) for i, a in enumerate(answers)]
    graded = []

    def counted(problem, part, submitted, **options):
        graded.append((part.id, submitted))
        return grade_answer(problem, part, submitted, **options)

    monkeypatch.setattr(batch, "grade_answer", counted)
    grades = grade_class(submissions, assignment, BANK, jobs=1)
    assert graded == [("lagrangian", right), ("lagrangian", wrong), ("lagrangian", wrong + " ")]
    scores = [next(p for p in g.parts if p.part == "lagrangian").auto_score for g in grades]
    assert scores == [4, 0, 4, 0, 4]
    # and each grade is the one it would get alone
    alone = [grade_submission(s, assignment, BANK) for s in submissions]
    assert [g.parts for g in grades] == [g.parts for g in alone]


def test_carried_forward_credit_is_not_shared_between_different_lagrangians(tmp_path):
    assignment = _pendulum_only(tmp_path)
    motion = "m l^2 thetaddot - m g l sin(theta) = 0"  # what T + V implies
    own = {"plane-pendulum.lagrangian": "1/2 m l^2 thetadot^2 - m g l cos(theta)", "plane-pendulum.motion": motion}
    other = {"plane-pendulum.lagrangian": "m g l cos(theta)", "plane-pendulum.motion": motion}
    grades = grade_class([Submission(Student("a"), own), Submission(Student("b"), other)], assignment, BANK, jobs=1)
    methods = [next(p for p in g.parts if p.part == "motion").method for g in grades]
    assert methods[0] == "error carried forward" and methods[1] != "error carried forward"


def test_assignment_points_weight_a_problem(tmp_path):
    path = tmp_path / "a.yaml"
    item = "{problem: plane-pendulum, parts: [lagrangian, motion], points: 14}"
    path.write_text(f"schema_version: 1\nid: a\ntitle: A\nproblems:\n  - {item}\n")
    parts = assignment_parts(load_assignment(path, BANK), BANK)
    assert [(part.id, points) for _, part, points in parts] == [("lagrangian", 8.0), ("motion", 6.0)]


def _dies_for_s2(submission, assignment, bank, *, timeout, graded):
    if submission.student.id == "s2":
        os._exit(3)  # a worker killed mid-task, as by the kernel's OOM killer
    return SubmissionGrade(submission.student, ())


def test_a_worker_that_dies_costs_only_its_own_submission(monkeypatch):
    monkeypatch.setattr(batch, "grade_submission", _dies_for_s2)
    submissions = [Submission(Student(f"s{i}")) for i in range(1, 6)]
    grades = grade_class(submissions, REVIEW, BANK, jobs=2)
    assert [(g.student.id, g.status) for g in grades] == [
        ("s1", "graded"), ("s2", "error"), ("s3", "graded"), ("s4", "graded"), ("s5", "graded"),
    ]  # fmt: skip
    assert grades[1].message == "could not be graded: the grading process stopped"


def test_an_exception_while_grading_is_that_students_result(monkeypatch):
    def explode(submission, assignment, bank, *, timeout, graded):
        raise RuntimeError("boom")

    monkeypatch.setattr(batch, "grade_submission", explode)
    (grade,) = grade_class([Submission(Student("s1"))], REVIEW, BANK, jobs=1)
    assert (grade.status, grade.message) == ("error", "could not be graded: RuntimeError: boom")


def test_the_gradebook_has_a_points_possible_row_first_and_quotes_names():
    rows = list(csv.reader(io.StringIO(gradebook_csv(small_class(), [("p.a", 2.0), ("p.b", 3.0)]))))
    assert rows[0] == ["id", "name", "email", "p.a", "p.b", "total", "max", "percent", "status"]
    assert rows[1] == ["Points Possible", "", "", "2.0", "3.0", "5.0", "5.0", "100.0", ""]
    assert rows[2] == ["s1", "O'Brien, Pat", "pat@x.org", "2.0", "1.0", "3.0", "5.0", "60.0", "graded"]
    assert rows[3][0] == "s2" and rows[3][-1] == "error"


def test_no_csv_cell_starts_a_spreadsheet_formula(tmp_path):
    hostile = '=HYPERLINK("http://evil.example","click")'
    parts = (PartGrade("p", "a", 2.0, "+cmd|' /C calc'!A0", "undecided", 0.0, ("-2+3",), read_as="@SUM(1)"),)
    grades = [SubmissionGrade(Student("-s1", hostile, "\tx@y"), parts)]
    written = [
        gradebook_csv(grades, [("p.a", 2.0)]),
        scores_long_csv(grades),
        review_csv(grades),
        canvas_csv(grades, assignment="A", assignment_id="1", max_score=2.0),
        moodle_csv(grades, assignment="A"),
    ]
    cells = [cell for text in written for row in csv.reader(io.StringIO(text)) for cell in row]
    assert '\'=HYPERLINK("http://evil.example","click")' in cells and "'+cmd|' /C calc'!A0" in cells
    assert not [cell for cell in cells if cell[:1] in ("=", "+", "@", "\t", "\r") or cell.startswith("-s")]
    # a person copies the student's id from review.csv into the overrides: it still matches
    overrides = tmp_path / "overrides.csv"
    overrides.write_text("student,part,points,comment\n'-s1,p.a,2,fine\n")
    assert read_overrides(overrides, max_points={"p.a": 2.0}) == {("-s1", "p.a"): (2.0, "fine")}


def test_overrides_keep_the_automatic_score_beside_the_persons():
    overrides = {("s1", "p.b"): (3.0, "good argument"), ("s9", "p.a"): (1.0, "")}
    grades, unmatched = apply_overrides(small_class(), overrides)
    part = grades[0].parts[1]
    assert (part.auto_score, part.manual_score, part.final_score, part.comment) == (1.0, 3.0, 3.0, "good argument")
    assert grades[0].score == 5.0
    assert unmatched == ["override for s9, p.a matches no graded part"]
    long = list(csv.DictReader(io.StringIO(scores_long_csv(grades))))
    assert [(row["part"], row["manual_score"], row["comment"]) for row in long if row["student"] == "s1"] == [
        ("p.a", "", ""),
        ("p.b", "3.0", "good argument"),  # the person's comment beside their score
    ]


def test_results_json_has_gradescopes_shape_and_reads_back():
    text = result_json(small_class()[0])
    record = json.loads(text)
    assert (record["score"], record["max_score"]) == (3.0, 5.0)
    assert record["tests"][1] == {"name": "p.b", "score": 1.0, "max_score": 3.0, "status": "failed",
                                  "output": "A person will read this answer."}  # fmt: skip
    assert grade_from_json(text) == small_class()[0]


def test_results_json_tells_the_student_a_persons_score_and_comment():
    grades, _ = apply_overrides(small_class(), {("s1", "p.b"): (3.0, "good argument")})
    tests = json.loads(result_json(grades[0]))["tests"]
    # the part was waiting for a person: what said so is said no more
    assert tests[1]["output"] == "Scored by a person: 3 / 3. good argument"
    assert tests[1]["score"] == 3.0
    assert tests[0]["output"] == json.loads(result_json(small_class()[0]))["tests"][0]["output"]  # not overridden


def test_canvas_import_has_its_identity_columns_and_a_points_possible_row():
    rows = list(
        csv.reader(io.StringIO(canvas_csv(small_class(), assignment="Review", assignment_id="review", max_score=5)))
    )
    assert rows[0] == ["Student", "ID", "SIS User ID", "SIS Login ID", "Section", "Review (review)"]
    assert rows[1] == ["    Points Possible", "", "", "", "", "5.00"]
    assert rows[2] == ["O'Brien, Pat", "", "s1", "pat@x.org", "", "3.00"]


def test_moodle_import_has_an_identity_a_grade_and_a_feedback_column():
    rows = list(csv.reader(io.StringIO(moodle_csv(small_class(), assignment="Review"))))
    assert rows[0] == ["Email address", "Assignment: Review", "Feedback: Review"]
    assert rows[1] == ["pat@x.org", "3.0", "3.00 / 5.00"]


@pytest.mark.parametrize("student_id", ["../../etc/passwd", "a/b", ".hidden", "con", "x" * 300, "s 1"])
def test_a_student_id_never_escapes_the_output_folder(student_id):
    name = file_name(student_id)
    assert "/" not in name and not name.startswith(".") and len(name) < 80
    assert file_name(student_id) == name  # stable across runs


def test_an_atomic_write_leaves_no_temporary_file(tmp_path):
    target = write_atomic(tmp_path / "deep" / "file.csv", "a,b\n")
    assert target.read_text() == "a,b\n"
    assert [p.name for p in target.parent.iterdir()] == ["file.csv"]
