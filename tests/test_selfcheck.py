"""Students checking answers: ``grader check`` (one answer or a YAML file), ``CheckResult``'s
renderings, and the bank-wide promise that a hint never gives the answer away."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from course import BANK

from grader import CheckResult, check, compare, parse_answer
from grader.cli import main
from grader.grade.part import expected_answer, part_options, setting_of
from grader.grade.selfcheck import check_many

LAGRANGIAN = "plane-pendulum.lagrangian"
RIGHT = "1/2 m l^2 thetadot^2 + m g l cos(theta)"
SIGN_HINT = "Check the sign of the potential energy; with θ from the downward vertical the bob is lowest at θ = 0."


# -- grader check PROBLEM.PART ANSWER ----------------------------------------------------------

CHECK_EXITS = [
    # (arguments, exit status, what it prints)
    ([LAGRANGIAN, "1/2 m l^2 θ̇^2 + mgl cos θ"], 0,
     "✔ plane-pendulum.lagrangian: right\n  read as: g*l*m*cos(θ) + l^2*m*θ̇^2/2\n"),
    ([LAGRANGIAN, "{1 \\over 2} m l^2 \\dot\\theta^2 + {m g l \\over 1} \\cos\\theta"], 0,
     "✔ plane-pendulum.lagrangian: right\n  read as: g*l*m*cos(θ) + l^2*m*θ̇^2/2\n"),  # plain TeX's \over
    ([LAGRANGIAN, "1/2 m l^2 thetadot^2 - m g l cos(theta)"], 1,
     f"✘ plane-pendulum.lagrangian: not right\n  {SIGN_HINT}\n  read as: -g*l*m*cos(θ) + l^2*m*θ̇^2/2\n"),
    # a name the problem lacks, glued to its names before a bracket: told as the name it is, not as a function
    ([LAGRANGIAN, "1/2 m l^2 θ̇^2 - mgL(1-cosθ)"], 1,
     "✘ plane-pendulum.lagrangian: not right\n"
     "  Your answer uses `L`, which this problem does not define (it uses g, l, m, θ). Write your answer in those,"
     " or say what it stands for: …, where L = ….\n"
     "  read as: -L*g*m*(1 - cos(θ)) + l^2*m*θ̇^2/2\n"),
    # words that doubt the formula: for a person to read; never `sign` told as a function without its argument
    (["plane-pendulum.motion", "m l^2 θ̈ + m g l sin θ = 0 (not sure about the sign)"], 1,
     "? plane-pendulum.motion: a person will check this\n"
     "  Your answer says `(not sure about the sign)` beside the formula. The formula was graded on its own;"
     " a person will read the words against it.\n"
     "  read as: g*l*m*sin(θ) + l^2*m*θ̈ = 0\n"),
    # a remark in TeX's \\text{…}: words, read past as words after a formula are
    (["damped-oscillator.motion", "m\\ddot x + b \\dot x + k x = 0 \\text{(damped)}"], 0,
     "✔ damped-oscillator.motion: right\n"
     "  Read without the words after it, `(damped)`: the formula is what is graded.\n"
     "  read as: b*ẋ + k*x + m*ẍ = 0\n"),
    (["plane-pendulum.why-harmonic", "sin θ ≈ θ, so the restoring force is proportional to θ"], 1,
     "? plane-pendulum.why-harmonic: a person will check this\n"
     "  A person will read this answer; the rubric found 2 of its 2 ideas.\n"),
    ([LAGRANGIAN, "sin(theta"], 2,
     "invalid plane-pendulum.lagrangian: could not be read\n"
     "  Unbalanced bracket: the `(` at position 4 is never closed.\n"
     "  where: sin(theta\n            ^\n"),
    # read, but not a number: shown as read, and a person will decide
    (["plane-pendulum.period", "2.006 x"], 2,
     "invalid plane-pendulum.period: could not be read\n"
     "  A number is asked for here; your answer contains `x`.\n"
     "  read as: 1003*x/500\n"),
    # a number in the unit asked (s) written in another (ms): read in the part's unit, and said so
    (["plane-pendulum.period", "2006 ms"], 0,
     "✔ plane-pendulum.period: right\n  Read as 2.006 s.\n  read as: 2.006\n"),
    (["constraint-classification.rigid-body-holonomic", "A"], 0,
     "✔ constraint-classification.rigid-body-holonomic: right\n"),
]  # fmt: skip


@pytest.mark.parametrize(("arguments", "status", "printed"), CHECK_EXITS)
def test_check_exit_statuses(capsys, arguments, status, printed):
    assert main(["check", *arguments]) == status
    assert capsys.readouterr().out == printed


USAGE_ERRORS = [
    # (arguments, what it says on stderr)
    (["plane-pendulum.nope", "x"],
     "grader check: problem 'plane-pendulum' has no part 'nope'; its parts are: plane-pendulum.lagrangian, "
     "plane-pendulum.motion, plane-pendulum.small-oscillations, plane-pendulum.frequency, plane-pendulum.period, "
     "plane-pendulum.why-harmonic\n"),
    ([], "grader check: give PROBLEM.PART ANSWER, or --answers FILE [--assignment A]\n"),
    ([LAGRANGIAN], "grader check: give PROBLEM.PART ANSWER, or --answers FILE [--assignment A]\n"),
    ([LAGRANGIAN, RIGHT, "--assignment", "review"],
     "grader check: give PROBLEM.PART ANSWER, or --answers FILE [--assignment A]\n"),
]  # fmt: skip


@pytest.mark.parametrize(("arguments", "message"), USAGE_ERRORS)
def test_check_usage_errors_exit_2(capsys, arguments, message):
    assert main(["check", *arguments]) == 2
    captured = capsys.readouterr()
    assert (captured.out, captured.err) == ("", message)


# -- grader check --answers FILE ----------------------------------------------------------------


def _answers(tmp_path: Path, text: str) -> str:
    path = tmp_path / "my_answers.yaml"
    path.write_text(text, encoding="utf-8")
    return str(path)


def test_answers_all_right_exit_0(capsys, tmp_path):
    path = _answers(tmp_path, f'{LAGRANGIAN}: "{RIGHT}"\nplane-pendulum.period: 2.006\n'
                              "degrees-of-freedom.plane-pendulum: 1\n")  # fmt: skip
    assert main(["check", "--answers", path]) == 0
    assert capsys.readouterr().out.splitlines() == [
        "✔ plane-pendulum.lagrangian: right",
        "  read as: g*l*m*cos(θ) + l^2*m*θ̇^2/2",
        "✔ plane-pendulum.period: right",
        "  read as: 2.006",
        "✔ degrees-of-freedom.plane-pendulum: right",
        "  read as: 1",
    ]


def test_answers_with_one_wrong_exit_1(capsys, tmp_path):
    path = _answers(tmp_path, f'{LAGRANGIAN}: "{RIGHT}"\nplane-pendulum.frequency: sqrt(l/g)\n')
    assert main(["check", "--answers", path]) == 1
    assert capsys.readouterr().out.splitlines()[2] == "✘ plane-pendulum.frequency: not right"


CARRIED = "Your equations follow correctly from your own Lagrangian, which is not right: method credit."


def test_answers_checked_together_carry_the_method_credit_the_class_grade_gives(capsys, tmp_path):
    # equations that follow from the student's own wrong Lagrangian: before, ✘ with a term's hint when
    # checked, and 1.5 of 3 points when graded
    wrong = "1/2 m l^2 θ̇^2 - m g l cos θ"
    answers = {LAGRANGIAN: wrong, "plane-pendulum.motion": "m l^2 θ̈ - m g l sin θ = 0"}
    lagrangian, motion = check_many(answers, bank=BANK)
    assert (lagrangian.score, motion.status, motion.score, motion.hints) == (0.0, "not_equivalent", 0.5, (CARRIED,))
    # alone, the equation has no Lagrangian to follow from
    alone = check("plane-pendulum.motion", answers["plane-pendulum.motion"], bank=BANK)
    assert alone.score == 0 and alone.hints != (CARRIED,)
    path = _answers(tmp_path, f'{LAGRANGIAN}: "{wrong}"\nplane-pendulum.motion: "m l^2 θ̈ - m g l sin θ = 0"\n')
    assert main(["check", "--answers", path]) == 1
    assert f"  {CARRIED}" in capsys.readouterr().out.splitlines()


def test_answers_with_one_unreadable_exit_2(capsys, tmp_path):
    path = _answers(tmp_path, f'{LAGRANGIAN}: "{RIGHT}"\nplane-pendulum.frequency: "sqrt(g/l"\n')
    assert main(["check", "--answers", path]) == 2
    assert "invalid plane-pendulum.frequency: could not be read" in capsys.readouterr().out


def test_answers_with_an_assignment_list_what_is_not_answered(capsys, tmp_path):
    path = _answers(tmp_path, f'{LAGRANGIAN}: "{RIGHT}"\n')
    assert main(["check", "--answers", path, "--assignment", "review"]) == 1
    lines = capsys.readouterr().out.splitlines()
    assert lines[:2] == ["✔ plane-pendulum.lagrangian: right", "  read as: g*l*m*cos(θ) + l^2*m*θ̇^2/2"]
    assert lines[2] == "– degrees-of-freedom.plane-pendulum: not answered"
    assert "– plane-pendulum.motion: not answered" in lines
    assert "– plane-pendulum.lagrangian: not answered" not in lines
    total = sum(len(BANK[p].parts) for p in ("degrees-of-freedom", "constraint-classification", "principles",
        "lagrangian-vs-newtonian", "plane-pendulum", "double-pendulum", "atwood-machine", "spherical-pendulum",
        "rotating-hoop", "damped-oscillator", "generalized-forces"))  # fmt: skip
    assert len(lines) == 2 + total - 1


def test_a_multiple_choice_may_be_a_yaml_list(capsys, tmp_path):
    path = _answers(tmp_path, "constraint-classification.rigid-body-holonomic: [a]\n")
    assert main(["check", "--answers", path]) == 0


def test_answers_are_read_as_typed_not_as_yaml_reads_them(capsys, tmp_path):
    # YAML would read 015 as the octal 13, yes as True and an empty answer as null
    path = _answers(tmp_path, "degrees-of-freedom.free-particles: 015\nrotating-hoop.constraint: yes\n"
                              "plane-pendulum.lagrangian:\n")  # fmt: skip
    assert main(["check", "--answers", path]) == 2  # the empty one is unreadable; the others are checked
    out = capsys.readouterr().out
    assert "✔ degrees-of-freedom.free-particles: right" in out
    assert "`yes` is not one of the options" in out
    assert "invalid plane-pendulum.lagrangian: could not be read" in out


BAD_FILES = [
    # (YAML text, what stderr says after the path)
    ("a: [b\n", "cannot read"),
    ("- just\n- a list\n", "must map problem.part to an answer"),
    ("plane-pendulum.lagrangian: {a: 1}\n", "the answer to plane-pendulum.lagrangian must be text"),
    ("plane-pendulum.nope: x\n", "problem 'plane-pendulum' has no part 'nope'"),
    ("a: " + "[" * 3000 + "]" * 3000 + "\n", "cannot read"),  # deeper than PyYAML's recursion: no traceback
]


@pytest.mark.parametrize(("text", "message"), BAD_FILES)
def test_unreadable_answers_exit_2(capsys, tmp_path, text, message):
    path = _answers(tmp_path, text)
    assert main(["check", "--answers", path]) == 2
    captured = capsys.readouterr()
    assert captured.out == "" and message in captured.err


def test_a_missing_answers_file_exits_2(capsys, tmp_path):
    assert main(["check", "--answers", str(tmp_path / "none.yaml")]) == 2
    assert "cannot read" in capsys.readouterr().err


def test_an_unknown_assignment_exits_2(capsys, tmp_path):
    path = _answers(tmp_path, f'{LAGRANGIAN}: "{RIGHT}"\n')
    assert main(["check", "--answers", path, "--assignment", "no-such-assignment"]) == 2


# -- CheckResult ----------------------------------------------------------------------------------


def test_repr_html_carries_mathml():
    result = check(LAGRANGIAN, "1/2 m l^2 thetadot^2 - m g l cos(theta)")
    page = result._repr_html_()
    assert "<math" in page and page.startswith('<div class="grader-check">')
    assert "✘ plane-pendulum.lagrangian: not right" in page
    assert f"<li>{SIGN_HINT}</li>" in page


def test_repr_html_escapes_what_was_typed():
    page = check(LAGRANGIAN, "<b>sin(theta")._repr_html_()
    assert "<b>" not in page and "&lt;b&gt;" in page


def test_repr_markdown_escapes_backticks():
    markdown = check(LAGRANGIAN, "sin(theta")._repr_markdown_()
    assert markdown.startswith("**invalid plane\\-pendulum.lagrangian: could not be read**".replace("\\-", "-"))
    assert "the \\`(\\` at position 4" in markdown
    assert "`(`" not in markdown.split("```")[0]


def test_check_result_fields():
    result = check(LAGRANGIAN, RIGHT)
    assert isinstance(result, CheckResult) and result.right
    assert (result.key, result.status, result.score, result.hints) == (LAGRANGIAN, "equivalent", 1.0, ("Correct.",))
    assert check(LAGRANGIAN, "   ") == CheckResult(LAGRANGIAN, "invalid", 0.0, ("Your answer is empty.",))


# -- hints never give the answer away -------------------------------------------------------------

MATH_KINDS = ("expression", "equation", "equations", "lagrangian")
TRIM = '.,;:`"“”'
SPAN_WORDS = 12  # the longest run of words read as a formula; hints hold short formulas


def _graded_answers():
    """(problem, part, answer) for every mistake and test answer of every part of the bank."""
    for problem in BANK.values():
        for part in problem.parts:
            for answer in [m.answer for m in part.mistakes] + [t.answer for t in part.tests]:
                yield problem, part, str(answer)


CASES = list(_graded_answers())


def _formulas(hint: str, problem) -> list[str]:
    """Runs of words in a hint that read as mathematics in the problem's own symbols."""
    setting = setting_of(problem)
    allowed = {"t", *setting["coords"], *setting["known"]}
    words = hint.split()
    found = []
    for start in range(len(words)):
        for end in range(start + 1, min(len(words), start + SPAN_WORDS) + 1):
            span = " ".join(words[start:end]).strip(TRIM)
            if len(span) < 3:
                continue
            read = parse_answer(span, coords=setting["coords"], known=setting["known"])
            if not read.ok:
                continue
            values = read.value if isinstance(read.value, tuple) else (read.value,)
            names = {str(symbol) for value in values for symbol in value.free_symbols}
            # A symbol the problem does not define can never make an answer right: skip those runs.
            if names and names <= allowed:
                found.append(span)
    return found


def test_the_bank_has_answers_to_check():
    assert len(CASES) > 150


@pytest.mark.parametrize(
    ("problem", "part", "answer"), CASES, ids=[f"{p.id}.{part.id}:{a[:30]}" for p, part, a in CASES]
)
def test_hints_never_contain_the_reference(problem, part, answer):
    reference = expected_answer(problem, part).strip()
    result = check(f"{problem.id}.{part.id}", answer, bank=BANK)
    hints = [hint for hint in result.hints if hint != "Correct."]
    if part.kind != "choice" and len(reference) >= 3:  # a choice's reference is a letter
        for hint in hints:
            assert reference not in hint, f"the hint for {answer!r} holds the reference: {hint}"
    if part.kind not in MATH_KINDS:
        return
    options = {"kind": part.kind, **setting_of(problem), **part_options(part)}
    for hint in hints:
        for formula in _formulas(hint, problem):
            verdict = compare(reference, formula, **options)
            assert not verdict.equivalent, f"the hint for {answer!r} gives the answer away as {formula!r}: {hint}"


def test_the_formula_finder_finds_a_formula():
    # The scan above must be able to fail: a hint that states the answer is caught.
    problem = BANK["plane-pendulum"]
    hint = "Try L = 1/2 m l² θ̇² + m g l cos θ, which is right."
    formulas = _formulas(hint, problem)
    part = problem.part("lagrangian")
    options = {"kind": part.kind, **setting_of(problem), **part_options(part)}
    assert any(compare(expected_answer(problem, part), f, **options).equivalent for f in formulas)
    assert re.search(r"1/2 m l² θ̇² \+ m g l cos θ", " | ".join(formulas))


@pytest.mark.parametrize(
    ("answer", "hint"),
    [
        ("6.28 sqrt(l/g)", "That is the period of the oscillation, 2π/ω; the angular frequency ω is asked."),
        ("0.159 sqrt(g/l)", "That is the frequency f = ω/(2π), in cycles per second; the angular frequency ω is"),
    ],
)
def test_a_listed_mistake_with_its_numbers_rounded_gets_the_mistakes_hint(answer, hint):
    # 2π as 6.28 and 1/(2π) as 0.159: the mistake is the same, and so is what the student needs to hear
    result = check("plane-pendulum.frequency", answer)
    assert result.status == "not_equivalent"
    assert result.hints[0].startswith(hint)
