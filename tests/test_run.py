"""grader grade and grader export, end to end on small classes: files written, exit statuses, regrades."""

from __future__ import annotations

import csv
import io
import json
from pathlib import Path

import pytest

from grader.cli import main

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
    return list(csv.DictReader(io.StringIO(path.read_text(encoding="utf-8"))))


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
    rows = [*CLASS, ["s1", "Ann again", "", "", "", ""], ["", "No id", "", "", "", ""]]
    assert _grade(tmp_path, _class(tmp_path, rows), assignment) == 4
    err = capsys.readouterr().err
    assert "row 5: the row has no student id; row skipped" in err
    assert "row 4: student 's1' also appears at" in err
    assert len(list((tmp_path / "out" / "results").iterdir())) == 2


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
