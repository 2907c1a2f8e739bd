"""compare against the derived verdicts of tests/compare_pairs.py.

Eight mechanics systems (simple, double and spherical pendulum, the double pendulum
in α and β, the Atwood machine, a bead on a rotating hoop, an inclined plane, a
damped oscillator), 40+ pairs per kind, in mixed notations. Each verdict there was
derived with sympy, never taken from the lecture notes.
"""

from __future__ import annotations

from collections import Counter

import pytest
from compare_pairs import PAIRS, SYSTEMS

from grader import compare


def _judge(system, kind, expected, submitted):
    setting = SYSTEMS[system]
    return compare(
        expected, submitted, kind=kind, coords=setting["coords"], known=setting["known"], domains=setting.get("domains")
    )


def _id(pair) -> str:
    system, kind, _, submitted, equivalent, _ = pair
    return f"{kind}-{system}-{'eq' if equivalent else 'ne'}-{submitted[:40]}"


def test_every_kind_has_forty_pairs_of_each_verdict_mix():
    counts = Counter(kind for _, kind, *_ in PAIRS)
    assert all(counts[kind] >= 40 for kind in ("expression", "equation", "equations", "lagrangian")), counts
    for kind in counts:
        verdicts = Counter(equivalent for _, k, _, _, equivalent, _ in PAIRS if k == kind)
        assert verdicts[True] >= 15 and verdicts[False] >= 15, (kind, verdicts)


@pytest.mark.parametrize("pair", PAIRS, ids=[_id(pair) for pair in PAIRS])
def test_verdict_matches_the_derived_one(pair):
    system, kind, expected, submitted, equivalent, note = pair
    verdict = _judge(system, kind, expected, submitted)
    if equivalent:
        assert verdict.status == "equivalent", (note, verdict)
        assert verdict.score == 1.0
    else:
        # Wrong answers are decided, never set aside as undecided, and never get full credit.
        assert verdict.status == "not_equivalent", (note, verdict)
        assert verdict.score < 1.0
        assert verdict.feedback, note
        for sentence in verdict.feedback:
            assert expected not in sentence


# The mistakes whose name the feedback must give, by the note's first words.
NAMED = {
    "T+V": {"t_plus_v", "term_differs"},
    "extra equation": {"extra_equation"},
    "missing equation": {"missing_equation", "expected_system", "dependent_equations"},
    "vanishing factor": {"vanishing_factor", "vanishing_factor_system"},
}


@pytest.mark.parametrize(
    "pair",
    [pair for pair in PAIRS if not pair[4] and pair[5].startswith(tuple(NAMED))],
    ids=_id,
)
def test_feedback_names_the_mistake_where_the_note_does(pair):
    system, kind, expected, submitted, _, note = pair
    verdict = _judge(system, kind, expected, submitted)
    category = next(name for name in NAMED if note.startswith(name))
    assert verdict.diagnosis in NAMED[category], (note, verdict)
