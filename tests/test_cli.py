"""The command line: what it prints and its exit statuses."""

from __future__ import annotations

import json

import pytest

from grader.cli import main


def test_parse_prints_how_the_answer_was_read(capsys):
    status = main(["parse", "--coords", "theta", "--known", "m,g,l", "1/2 m l^2 θ̇^2 + mgl cos θ"])
    assert status == 0
    assert capsys.readouterr().out.splitlines()[0] == "read as (expression): g*l*m*cos(θ) + l^2*m*θ̇^2/2"


def test_parse_refuses_with_a_caret_and_exit_status_2(capsys):
    assert main(["parse", "sin(θ"]) == 2
    assert capsys.readouterr().out == (
        "invalid: Unbalanced bracket: the `(` at position 4 is never closed.\nsin(θ\n   ^\n"
    )


def test_parse_json(capsys):
    assert main(["parse", "--json", "--coords", "x", "x'' = -x"]) == 0
    record = json.loads(capsys.readouterr().out)
    assert record["kind"] == "equation"
    assert record["text"] == "ẍ = -x"
    assert record["mathml"].startswith("<math")


def test_usage_error_exits_2():
    with pytest.raises(SystemExit) as exit_info:
        main(["parse"])
    assert exit_info.value.code == 2
