"""The command line: what it prints and its exit statuses."""

from __future__ import annotations

import json
import subprocess
import sys

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


def test_compare_given_names_a_quantity_an_answer_may_use(capsys):
    hamiltonian = "1/2 m R^2 thetadot^2 - m g R cos(theta)"
    arguments = ["compare", "--coords", "theta", "--known", "m,R,g", "--given", "p_theta=m R^2 thetadot"]
    assert main([*arguments, hamiltonian, "p_θ²/(2 m R²) − m g R cos θ"]) == 0
    assert "Read with the problem's own meaning of `p_θ`." in capsys.readouterr().out
    with pytest.raises(SystemExit) as exit_info:
        main(["compare", "--given", "p_theta", "x", "x"])
    assert exit_info.value.code == 2


def test_compare_dimensions_check_a_wrong_answers_units(capsys):
    arguments = ["compare", "--known", "g,l", "--dimension", "g=acceleration", "--dimension", "l=length"]
    assert main([*arguments, "sqrt(g/l)", "sqrt(l/g)"]) == 1
    assert "Your answer is measured in s, but the quantity asked for is measured in 1/s" in capsys.readouterr().out
    assert main(["compare", "--known", "g,l", "--dimension", "g=metres", "sqrt(g/l)", "sqrt(l/g)"]) == 2
    assert "dimension of 'g' is 'metres'" in capsys.readouterr().err


def test_compare_unit_lets_a_number_carry_its_unit(capsys):
    assert main(["compare", "--kind", "number", "--unit", "s", "2.006", "2006 ms"]) == 0
    assert "Read as 2.006 s." in capsys.readouterr().out


def test_a_reader_that_stops_early_gets_no_traceback():
    # `grader compare … | head -1`: the pipe closes before the grader has written its lines
    command = [sys.executable, "-m", "grader", "compare", "--coords", "x", "x^2", "x*x"]
    with subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE) as process:
        process.stdout.close()  # the reader is gone before the first line
        errors = process.stderr.read().decode()
        status = process.wait(timeout=60)
    assert errors == ""
    assert status == 141


def test_ctrl_c_ends_a_command_with_status_130_and_no_traceback(capsys, monkeypatch):
    def pressed(*_, **__):
        raise KeyboardInterrupt

    monkeypatch.setattr("grader.cli.parse_answer", pressed)
    assert main(["parse", "x"]) == 130
    assert capsys.readouterr().err == "\ngrader: interrupted\n"


def test_importing_grader_loads_nothing_heavy_until_a_name_is_used():
    # What lets `grader` catch a Ctrl-C while sympy loads (grader/__main__.py).
    script = (
        "import sys, grader\n"
        "assert 'sympy' not in sys.modules and 'pandas' not in sys.modules, 'loaded early'\n"
        "from grader import compare, check\n"
        "assert compare('x', 'x + 0', coords=['x']).equivalent and callable(check)\n"
        "assert {'compare', 'parse_answer', 'AuthorError'} <= set(dir(grader))\n"
        "import grader.cli\n"
        "assert 'pandas' not in sys.modules, 'grader check and serve write no CSV'\n"
        "try:\n    grader.no_such_name\nexcept AttributeError as error:\n    print(error)\n"
    )
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120)
    assert (done.returncode, done.stderr) == (0, "")
    assert done.stdout == "module 'grader' has no attribute 'no_such_name'\n"


L_PENDULUM = "1/2 m l^2 thetadot^2 + m g l cos(theta)"
COMPARE_EXITS = [
    # (arguments, exit status, first line)
    (["--kind", "equation", "--coords", "theta", "m l^2 thetaddot + m g l sin(theta) = 0", "θ̈ = -(g/l) sin θ"], 0,
     "equivalent (score 1, by accelerations)"),
    (["--kind", "lagrangian", "--coords", "theta", L_PENDULUM, "1/2 m l^2 θ̇^2 - m g l cos θ"], 1,
     "not equivalent (score 0, by numeric)"),
    (["x", "sin(x"], 2, "invalid (score 0, by parse)"),
    # without --kind, the kind is the expected answer's: an equation, a system, else an expression
    (["--coords", "theta", "thetaddot = -g/l sin(theta)", "l θ̈ + g sin θ = 0"], 0,
     "equivalent (score 1, by accelerations)"),
    (["--coords", "x,y", "xddot = -x; yddot = -y", "xddot + yddot = -x - y; yddot = -y"], 0,
     "equivalent (score 1, by accelerations)"),
    (["--timeout", "1e-9", "--coords", "theta", "sin(theta)", "cos(theta)"], 3, "undecided (score 0, by timeout)"),
]  # fmt: skip


@pytest.mark.parametrize(("arguments", "status", "first_line"), COMPARE_EXITS)
def test_compare_exit_statuses(capsys, arguments, status, first_line):
    # a shared machine may stall a check past the default 2 s: only the row that means to time out does
    generous = [] if "--timeout" in arguments else ["--timeout", "60"]
    assert main(["compare", *generous, *arguments]) == status
    assert capsys.readouterr().out.splitlines()[0] == first_line


def test_compare_explains_the_mistake_and_shows_how_the_answer_was_read(capsys):
    main(["compare", "--kind", "lagrangian", "--coords", "theta", "1/2 m l^2 thetadot^2 + m g l cos(theta)",
          "1/2 m l^2 θ̇^2 - m g l cos θ"])  # fmt: skip
    assert capsys.readouterr().out.splitlines()[1:] == [
        "  It looks like you wrote L = T + V; the Lagrangian is L = T − V.",
        "read as: -g*l*m*cos(θ) + l^2*m*θ̇^2/2",
    ]


def test_an_answer_the_time_limit_stopped_before_it_was_read_shows_no_empty_reading(capsys):
    assert main(["compare", "--timeout", "1e-9", "--coords", "theta", "sin(theta)", "cos(theta)"]) == 3
    assert capsys.readouterr().out.splitlines() == [
        "undecided (score 0, by timeout)",
        "  This answer could not be checked automatically; it has been set aside for a person to grade.",
    ]


def test_compare_json_has_the_verdict_fields(capsys):
    main(["compare", "--json", "--known", "m", "2m", "m+m"])
    record = json.loads(capsys.readouterr().out)
    assert record["status"] == "equivalent" and record["equivalent"] is True and record["read_as"] == "2*m"


def test_an_unreadable_expected_answer_is_a_usage_error_on_stderr(capsys):
    assert main(["compare", "x +", "x"]) == 2
    assert "The expected answer 'x +' cannot be read" in capsys.readouterr().err


def test_problems_list_shows_id_title_seed_and_points(capsys):
    assert main(["problems", "list"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines[0].split() == ["id", "title", "seed", "points"]
    pendulum = next(line for line in lines if line.startswith("plane-pendulum "))
    assert "E3 A3" in pendulum


def test_problems_show_hides_answers_unless_asked(capsys):
    assert main(["problems", "show", "plane-pendulum"]) == 0
    assert "answer:" not in capsys.readouterr().out
    assert main(["problems", "show", "plane-pendulum", "--answers"]) == 0
    assert "answer: 1/2 m l^2 thetadot^2 + m g l cos(theta)" in capsys.readouterr().out
    # a part's given names stand for parts of the answer, so they are shown with it
    assert main(["problems", "show", "spherical-pendulum"]) == 0
    assert "given:" not in capsys.readouterr().out
    assert main(["problems", "show", "spherical-pendulum", "--answers"]) == 0
    assert "    given: p_phi = m l^2 sin(theta)^2 phidot\n" in capsys.readouterr().out


def test_problems_show_lists_the_symbols_to_type_with_their_units(capsys):
    assert main(["problems", "show", "plane-pendulum"]) == 0
    out = capsys.readouterr().out
    assert "Symbols:\n  theta  angle of the string from the downward vertical (rad)\n" in out
    assert "  g      gravitational acceleration (m/s²)\n" in out
    assert "(frequency) expression, 1 point\n" in out and "(lagrangian) lagrangian, 4 points\n" in out


def test_problems_show_of_an_unknown_problem_is_a_usage_error(capsys):
    assert main(["problems", "show", "no-such-problem"]) == 2
    assert "no problem 'no-such-problem'" in capsys.readouterr().err


def test_validate_exit_statuses(capsys):
    assert main(["validate"]) == 0
    assert capsys.readouterr().out.splitlines()[-1].endswith("problems checked, 0 failures")
    broken = "tests/broken_problems/unknown_kind.yaml"
    assert main(["validate", broken]) == 1
    assert "field 'kind' is 'lagrangean'" in capsys.readouterr().out


TIME_LIMIT_COMMANDS = [
    ["compare", "x", "x"],
    ["check", "plane-pendulum.lagrangian", "x"],
    ["serve", "--port", "0"],
    ["grade", "class.csv", "--assignment", "review", "--out", "out"],
]


@pytest.mark.parametrize("command", TIME_LIMIT_COMMANDS, ids=[command[0] for command in TIME_LIMIT_COMMANDS])
@pytest.mark.parametrize("timeout", ["-1", "0", "nan", "inf", "soon"])
def test_a_time_limit_must_be_a_positive_number_of_seconds(capsys, command, timeout):
    # 0 or less would make every check fail (a timer that cannot be set), not stop at once
    with pytest.raises(SystemExit) as exit_info:
        main([*command, "--timeout", timeout])
    assert exit_info.value.code == 2
    assert f"--timeout: expected a positive number of seconds, not '{timeout}'" in capsys.readouterr().err
