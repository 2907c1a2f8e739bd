"""grader grade and grader export, end to end on small classes: files written, exit statuses, regrades."""

from __future__ import annotations

import codecs
import csv
import io
import json
from pathlib import Path

import pytest

from grader.cli import main
from grader.grade import batch
from grader.run import EXPORTS

ROOT = Path(__file__).resolve().parent.parent
BANK = ROOT / "problems"
L = "1/2 m l^2 thetadot^2 + m g l cos(theta)"


@pytest.fixture
def assignment(tmp_path: Path) -> Path:
    path = tmp_path / "pendulum.yaml"
    path.write_text(
        "schema_version: 1\nid: pendulum\ntitle: Pendulum quiz\nproblems:\n"
        "  - {problem: plane-pendulum, parts: [lagrangian, motion, why-harmonic]}\n"
    )
    return path


def _class(tmp_path: Path, rows: list[list[str]]) -> Path:
    path = tmp_path / "class.csv"
    with path.open("w", newline="", encoding="utf-8") as file:
        writer = csv.writer(file)
        writer.writerow(["id", "name", "email", "plane-pendulum.lagrangian", "plane-pendulum.motion",
                         "plane-pendulum.why-harmonic"])  # fmt: skip
        writer.writerows(rows)
    return path


def _rows(path: Path) -> list[dict]:
    """A CSV's rows, as Excel reads the file: every CSV we write starts with a byte-order mark,
    without which Excel takes UTF-8 for Windows-1252."""
    data = path.read_bytes()
    assert data.startswith(codecs.BOM_UTF8), path
    return list(csv.DictReader(io.StringIO(data.decode("utf-8-sig"))))


def _grade(tmp_path, submissions, assignment, *more) -> int:
    return main(["grade", str(submissions), "--assignment", str(assignment), "--out", str(tmp_path / "out"),
                 "--bank", str(BANK), "--jobs", "1", *more])  # fmt: skip


CLASS = [
    [
        "s1",
        "Ann <script>alert(1)</script>",
        "ann@x.org",
        L,
        "θ̈ = -(g/l) sin θ",
        "small angle: sin θ ≈ θ, so the restoring force is proportional to θ",
    ],
    ["s2", "Bob, Jr.", "bob@x.org", "1/2 m l^2 thetadot^2 - m g l cos(theta)", "", ""],
]


def test_grading_a_class_writes_every_output(tmp_path, assignment, capsys):
    assert _grade(tmp_path, _class(tmp_path, CLASS), assignment) == 0
    out = tmp_path / "out"
    assert sorted(p.name for p in (out / "results").iterdir()) == ["s1.json", "s2.json"]
    assert sorted(p.name for p in (out / "reports").iterdir()) == ["s1.html", "s1.md", "s2.html", "s2.md"]
    for name in ("gradebook.csv", "scores_long.csv", "review.csv", "summary.html", "input-issues.txt"):
        assert (out / name).is_file(), name
    gradebook = _rows(out / "gradebook.csv")
    assert gradebook[0]["id"] == "Points Possible"
    assert [(row["id"], row["total"]) for row in gradebook[1:]] == [("s1", "9.0"), ("s2", "0.0")]
    assert json.loads((out / "results" / "s1.json").read_text())["score"] == 9.0
    assert "<script>alert(1)</script>" not in (out / "reports" / "s1.html").read_text()
    review = _rows(out / "review.csv")
    assert [row["part"] for row in review] == ["plane-pendulum.why-harmonic"]
    assert "graded 2 of 2 students" in capsys.readouterr().out


def test_input_problems_are_listed_and_the_rest_graded_with_exit_4(tmp_path, assignment, capsys):
    rows = [*CLASS, ["s1", "Ann again", "", "", "", ""], ["", "No id", "", "", "", ""], ["s3", "Cut", "", L]]
    assert _grade(tmp_path, _class(tmp_path, rows), assignment) == 4
    err = capsys.readouterr().err
    assert "row 5 (line 5): the row has no student id; row skipped" in err
    assert "row 4 (line 4): student 's1' also appears at" in err
    assert "row 6 (line 6), student 's3': the row has 4 cells but the header 6; row skipped" in err
    assert len(list((tmp_path / "out" / "results").iterdir())) == 2


def test_a_byte_not_utf8_costs_no_other_answer_and_sends_its_own_to_a_person(tmp_path, assignment, capsys):
    submissions = tmp_path / "class.csv"
    header = "id,name,email,plane-pendulum.lagrangian,plane-pendulum.motion,plane-pendulum.why-harmonic\n"
    submissions.write_bytes(
        f'{header}s1,"Núñez, María",m@x.org,{L},θ̈ = -(g/l) sin θ,\n'.encode()
        + f"s2,Bob,b@x.org,{L}\xa0,,\n".encode("cp1252")
    )
    assert _grade(tmp_path, submissions, assignment) == 4
    assert (
        f"input: {submissions}, row 3 (line 3), student 's2', part plane-pendulum.lagrangian: the answer holds a byte"
        " that is not UTF-8 (0xA0), read as �; it goes to a person to check"
    ) in capsys.readouterr().err
    gradebook = _rows(tmp_path / "out" / "gradebook.csv")
    assert [(row["name"], row["total"]) for row in gradebook[1:]] == [("Núñez, María", "7.0"), ("Bob", "0.0")]
    review = {(row["student"], row["part"]): row["feedback"] for row in _rows(tmp_path / "out" / "review.csv")}
    assert "a person will check it" in review["s2", "plane-pendulum.lagrangian"]


UNUSABLE_CLASSES = [
    ("", "is empty: no header and no students"),
    ("student;name\n", "row 1: the header has no 'id' column: a CSV is expected"),
    ("id,name,email,plane-pendulum.lagrangian\n", "has a header but no rows of answers: there is no student to grade"),
    ("id,name,atwood-machine.lagrangian\ns1,Ann,x\n", "no column of the header is a part of this assignment"),
    ("id,name,plane-pendulum.lagrangian\n,No id,x\n", "no student in {path} can be graded, so nothing was written:"),
]


@pytest.mark.parametrize(
    ("text", "message"), UNUSABLE_CLASSES, ids=["empty", "no-id", "header-only", "another-assignment", "no-row-read"]
)
def test_a_class_file_that_cannot_be_used_exits_2_and_leaves_the_last_outputs(
    tmp_path, assignment, capsys, text, message
):
    assert _grade(tmp_path, _class(tmp_path, CLASS), assignment) == 0
    before = {path: path.read_bytes() for path in (tmp_path / "out").rglob("*") if path.is_file()}
    unusable = tmp_path / "unusable.csv"
    unusable.write_text(text, encoding="utf-8")
    capsys.readouterr()
    assert _grade(tmp_path, unusable, assignment) == 2
    assert message.format(path=unusable) in capsys.readouterr().err
    assert {path: path.read_bytes() for path in (tmp_path / "out").rglob("*") if path.is_file()} == before


def test_usage_errors_exit_2(tmp_path, assignment, capsys):
    assert _grade(tmp_path, tmp_path / "missing.csv", assignment) == 2
    assert "cannot read the submissions" in capsys.readouterr().err
    assert _grade(tmp_path, _class(tmp_path, CLASS), tmp_path / "no-such-assignment.yaml") == 2


def test_a_persons_scores_survive_a_regrade_and_only_regrades_one_student(tmp_path, assignment):
    submissions = _class(tmp_path, CLASS)
    overrides = tmp_path / "overrides.csv"
    overrides.write_text("student,part,points,comment\ns1,plane-pendulum.why-harmonic,1.5,half an argument\n")
    assert _grade(tmp_path, submissions, assignment, "--overrides", str(overrides)) == 0
    changed = [["s2", "Bob, Jr.", "bob@x.org", L, "", ""]]
    assert _grade(tmp_path, _class(tmp_path, [*CLASS[:1], *changed]), assignment, "--only", "s2") == 0
    rows = {row["student"] + " " + row["part"]: row for row in _rows(tmp_path / "out" / "scores_long.csv")}
    kept = rows["s1 plane-pendulum.why-harmonic"]
    assert (kept["auto_score"], kept["manual_score"], kept["final_score"]) == ("2.0", "1.5", "1.5")
    assert rows["s2 plane-pendulum.lagrangian"]["final_score"] == "4.0"  # regraded
    assert sorted(p.name for p in (tmp_path / "out" / "results").iterdir()) == ["s1.json", "s2.json"]


@pytest.mark.parametrize(("target", "file"), [("canvas", "canvas.csv"), ("moodle", "moodle.csv")])
def test_exports_for_an_lms(tmp_path, assignment, target, file):
    _grade(tmp_path, _class(tmp_path, CLASS), assignment)
    out = tmp_path / "out"
    assert main(["export", str(out), "--to", target, "--assignment", str(assignment), "--bank", str(BANK)]) == 0
    lines = 4 if target == "canvas" else 3  # a header, Canvas's points-possible row, a row per student
    assert (out / "exports" / file).read_text(encoding="utf-8").count("\n") == lines


def test_gradescope_export_is_one_results_json_per_student(tmp_path, assignment):
    _grade(tmp_path, _class(tmp_path, CLASS), assignment)
    out = tmp_path / "out"
    assert main(["export", str(out), "--to", "gradescope", "--assignment", str(assignment), "--bank", str(BANK)]) == 0
    record = json.loads((out / "exports" / "gradescope" / "s2" / "results.json").read_text())
    assert set(record) == {"score", "max_score", "tests", "extra_data"}


def test_export_before_grading_is_a_usage_error(tmp_path, assignment, capsys):
    assert main(["export", str(tmp_path), "--to", "canvas", "--assignment", str(assignment), "--bank", str(BANK)]) == 2
    assert "holds no results" in capsys.readouterr().err


def _files(out: Path) -> dict[str, bytes]:
    return {str(path.relative_to(out)): path.read_bytes() for path in sorted(out.rglob("*")) if path.is_file()}


def _export(out: Path, target: str, assignment: Path) -> int:
    return main(["export", str(out), "--to", target, "--assignment", str(assignment), "--bank", str(BANK)])


def _not_graded(*students: str):
    """grade_submission, failing for ``students`` as a bad time limit or a crash would."""
    grade_submission = batch.grade_submission

    def grade(submission, *arguments, **options):
        if submission.student.id in students:
            raise OSError(22, "Invalid argument")
        return grade_submission(submission, *arguments, **options)

    return grade


def test_an_export_leaves_out_who_could_not_be_graded_and_says_so(tmp_path, assignment, capsys, monkeypatch):
    monkeypatch.setattr(batch, "grade_submission", _not_graded("s2"))
    out = tmp_path / "out"
    assert _grade(tmp_path, _class(tmp_path, CLASS), assignment) == 4
    capsys.readouterr()
    for target in EXPORTS:
        assert _export(out, target, assignment) == 4
        assert capsys.readouterr().err.startswith(
            "grader export: s2 (Bob, Jr.) could not be graded and is left out, so the LMS keeps their grade as it is;"
            " grade them again with grader grade … --only s2\n"
        )
    canvas, moodle = _rows(out / "exports" / "canvas.csv"), _rows(out / "exports" / "moodle.csv")
    assert [row["SIS User ID"] for row in canvas] == ["", "s1"]  # the points-possible row, then who was graded
    assert [row["Email address"] for row in moodle] == ["ann@x.org"]
    assert "Errno" not in (out / "exports" / "moodle.csv").read_text(encoding="utf-8")
    assert sorted(path.name for path in (out / "exports" / "gradescope").iterdir()) == ["s1"]


def test_an_export_says_how_many_answers_still_wait_for_a_person(tmp_path, assignment, capsys):
    out = tmp_path / "out"
    assert _grade(tmp_path, _class(tmp_path, CLASS), assignment) == 0
    waiting = len(_rows(out / "review.csv"))
    assert waiting  # the text answers, each with the rubric's proposal
    capsys.readouterr()
    assert _export(out, "canvas", assignment) == 0
    assert capsys.readouterr().err == (
        f"grader export: {waiting} answer(s) still wait for a person (review.csv): these grades hold their proposed"
        " points; fill in review.csv's points and grade again with --overrides\n"
    )


def test_a_regrade_of_fewer_students_exports_only_them(tmp_path, assignment):
    out = tmp_path / "out"
    assert _grade(tmp_path, _class(tmp_path, CLASS), assignment) == 0
    assert _export(out, "gradescope", assignment) == 0
    assert _grade(tmp_path, _class(tmp_path, CLASS[:1]), assignment) == 0  # a class of one into the same folder
    assert sorted(_files(out / "results")) == ["s1.json"]
    assert sorted(_files(out / "reports")) == ["s1.html", "s1.md"]
    for target in EXPORTS:
        assert _export(out, target, assignment) == 0
    assert [row["SIS User ID"] for row in _rows(out / "exports" / "canvas.csv")] == ["", "s1"]
    assert [row["Email address"] for row in _rows(out / "exports" / "moodle.csv")] == ["ann@x.org"]
    assert sorted(_files(out / "exports" / "gradescope")) == ["s1/results.json"]
    # --only regrades one student and keeps the rest of this run, and nothing of the one before
    assert _grade(tmp_path, _class(tmp_path, CLASS), assignment, "--only", "s1") == 0
    assert [row["id"] for row in _rows(out / "gradebook.csv")] == ["Points Possible", "s1"]


def test_a_regrade_writes_the_lms_imports_again_as_export_would(tmp_path, assignment, capsys):
    out, submissions = tmp_path / "out", _class(tmp_path, CLASS)
    assert _grade(tmp_path, submissions, assignment) == 0
    for target in ("canvas", "gradescope"):
        assert _export(out, target, assignment) == 0
    posted = _files(out / "exports")
    overrides = tmp_path / "overrides.csv"
    overrides.write_text("student,part,points,comment\ns2,plane-pendulum.lagrangian,3,nearly\n")
    capsys.readouterr()
    assert _grade(tmp_path, submissions, assignment, "--overrides", str(overrides)) == 0
    assert (
        f"LMS imports made again from these grades: canvas, gradescope in {out / 'exports'}" in capsys.readouterr().out
    )
    again = _files(out / "exports")
    assert sorted(again) == sorted(posted)  # no moodle.csv: it was never asked for
    assert [row["Pendulum quiz (pendulum)"] for row in _rows(out / "exports" / "canvas.csv")][1:] == ["9.00", "3.00"]
    assert json.loads(again["gradescope/s2/results.json"])["score"] == 3.0
    for target in ("canvas", "gradescope"):
        assert _export(out, target, assignment) == 0
    assert _files(out / "exports") == again  # what export itself writes from the new grades


def test_every_csv_starts_with_a_byte_order_mark_so_excel_reads_utf8(tmp_path, assignment):
    out = tmp_path / "out"
    rows = [["s3", "Zoë Müller", "z@x.org", "½ m l² θ̇² + m g l cos θ", "θ̈ = −(g/l) sin θ", "weil sin θ ≈ θ"]]
    overrides = tmp_path / "overrides.csv"
    overrides.write_text("student,part,points,comment\ns3,plane-pendulum.why-harmonic,2,gut\n")
    assert _grade(tmp_path, _class(tmp_path, rows), assignment, "--overrides", str(overrides)) == 0
    for target in ("canvas", "moodle"):
        assert _export(out, target, assignment) == 0
    written = [*out.glob("*.csv"), *(out / "exports").glob("*.csv")]
    assert sorted(path.name for path in written) == [
        "canvas.csv",
        "gradebook.csv",
        "moodle.csv",
        "overrides.csv",
        "review.csv",
        "scores_long.csv",
    ]
    for path in written:
        assert path.read_bytes().count(codecs.BOM_UTF8) == 1, path  # once, at the start (_rows checks where)
    assert _rows(out / "gradebook.csv")[1]["name"] == "Zoë Müller"


BAD_OVERRIDE_POINTS = [("nan", "4"), ("inf", "4"), ("-1", "4"), ("10", "4"), ("abc", "4")]


@pytest.mark.parametrize(("points", "worth"), BAD_OVERRIDE_POINTS)
def test_bad_override_points_stop_the_run_before_grading_and_change_nothing(
    tmp_path, assignment, capsys, monkeypatch, points, worth
):
    submissions, out = _class(tmp_path, CLASS), tmp_path / "out"
    kept = tmp_path / "kept.csv"
    kept.write_text("student,part,points,comment\ns1,plane-pendulum.why-harmonic,1.5,half an argument\n")
    assert _grade(tmp_path, submissions, assignment, "--overrides", str(kept)) == 0
    before = _files(out)
    monkeypatch.setattr("grader.run.grade_class", lambda *a, **k: pytest.fail("graded despite bad overrides"))
    bad = tmp_path / "bad.csv"
    bad.write_text(
        f"student,part,points,comment\ns1,plane-pendulum.motion,3,ok\ns2,plane-pendulum.lagrangian,{points},x\n"
    )
    assert _grade(tmp_path, submissions, assignment, "--overrides", str(bad)) == 2
    assert capsys.readouterr().err == (
        "grader grade: the overrides cannot be used:\n"
        f"  {bad}, row 3 (student 's2', part 'plane-pendulum.lagrangian'): points must be a number from 0 to {worth},"
        f" what the part is worth, not '{points}'\n"
    )
    assert _files(out) == before  # the saved overrides.csv too


def test_a_run_that_fails_while_writing_changes_no_output(tmp_path, assignment, monkeypatch):
    out = tmp_path / "out"
    assert _grade(tmp_path, _class(tmp_path, CLASS), assignment) == 0
    before = _files(out)

    def broken_summary(*arguments, **options):
        raise RuntimeError("the summary cannot be made")

    monkeypatch.setattr("grader.run.render_summary", broken_summary)
    changed = [["s1", "Ann", "ann@x.org", "", "", ""]]  # a class of one, other scores: every output would change
    with pytest.raises(RuntimeError):
        _grade(tmp_path, _class(tmp_path, changed), assignment)
    assert _files(out) == before  # no temporary file left behind either


def test_usage_errors_are_found_before_grading(tmp_path, assignment, capsys, monkeypatch):
    submissions = _class(tmp_path, CLASS)
    monkeypatch.setattr("grader.run.grade_class", lambda *a, **k: pytest.fail("graded despite a usage error"))
    assert _grade(tmp_path, submissions, assignment, "--overrides", str(tmp_path / "nope.csv")) == 2
    assert (
        capsys.readouterr().err
        == f"grader grade: cannot read the overrides {tmp_path / 'nope.csv'}: No such file or directory\n"
    )
    header = tmp_path / "header.csv"
    header.write_text("student,part,score\ns1,plane-pendulum.motion,3\n")
    assert _grade(tmp_path, submissions, assignment, "--overrides", str(header)) == 2
    assert capsys.readouterr().err == (
        f"grader grade: {header}, row 1: the header needs the columns student, part and points (and may have"
        " comment); points is missing\n"
    )
    assert not (tmp_path / "out").exists()
    (tmp_path / "out").write_text("a file, not a folder")
    assert _grade(tmp_path, submissions, assignment) == 2
    assert capsys.readouterr().err == f"grader grade: the output folder {tmp_path / 'out'} is a file\n"
    for timeout in ("-1", "0", "nan"):
        with pytest.raises(SystemExit) as exit_info:
            _grade(tmp_path, submissions, assignment, "--timeout", timeout)
        assert exit_info.value.code == 2
        assert f"expected a positive number of seconds, not '{timeout}'" in capsys.readouterr().err


def test_review_csv_with_its_points_filled_in_is_fed_back_as_overrides(tmp_path, assignment):
    submissions, out = _class(tmp_path, CLASS), tmp_path / "out"
    assert _grade(tmp_path, submissions, assignment) == 0
    review = _rows(out / "review.csv")
    assert [(row["student"], row["part"], row["points"], row["comment"]) for row in review] == [
        ("s1", "plane-pendulum.why-harmonic", "", "")
    ]
    review[0] |= {"points": "1.5", "comment": "half an argument"}  # the person scores it, in the file itself
    with (out / "review.csv").open("w", encoding="utf-8", newline="") as file:
        writer = csv.DictWriter(file, fieldnames=list(review[0]))
        writer.writeheader()
        writer.writerows(review)
    assert _grade(tmp_path, submissions, assignment, "--overrides", str(out / "review.csv")) == 0
    scored = next(row for row in _rows(out / "scores_long.csv") if row["part"] == "plane-pendulum.why-harmonic"
                  and row["student"] == "s1")  # fmt: skip
    assert (scored["auto_score"], scored["manual_score"], scored["final_score"]) == ("2.0", "1.5", "1.5")
    assert _rows(out / "review.csv") == []  # scored: nothing left for a person
    assert _rows(out / "overrides.csv") == [
        {"student": "s1", "part": "plane-pendulum.why-harmonic", "points": "1.5", "comment": "half an argument"}
    ]
