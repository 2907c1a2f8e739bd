"""Wrong answers that were once marked right, or earned credit they do not deserve, by kind.

Each row is an answer a student could write, the verdict it must get, and what it is told.
"""

from __future__ import annotations

import pytest

from grader import compare

PENDULUM = {"coords": ["theta"], "known": ["m", "g", "l"]}
L_PENDULUM = "1/2 m l^2 thetadot^2 + m g l cos(theta)"
ATWOOD = {"coords": ["x"], "known": ["m1", "m2", "g"]}
L_ATWOOD = "1/2 (m1 + m2) xdot^2 + (m1 - m2) g x"
DOUBLE = {"coords": ["theta1", "theta2"], "known": ["m1", "m2", "l1", "l2", "g"]}
L_DOUBLE = (
    "1/2 (m1 + m2) l1^2 theta1dot^2 + 1/2 m2 l2^2 theta2dot^2 + m2 l1 l2 theta1dot theta2dot cos(theta1 - theta2)"
    " + (m1 + m2) g l1 cos(theta1) + m2 g l2 cos(theta2)"
)

UNDECIDED = "This answer could not be checked automatically; it has been set aside for a person to grade."
ACCELERATIONS = "but a Lagrangian is a function of the coordinates, the velocities and the time alone."

LAGRANGIANS = [
    # (expected, submitted, setting, status, score, first feedback sentence)
    # d/dt(m l² θ θ̇) − m l² θ̇²... written with θ̈: it has no kinetic energy, yet read θ̈ as fixed it passed
    (L_PENDULUM, "m l^2 θ̇^2 + m l^2 θ θ̈ + m g l cos θ", PENDULUM, "not_equivalent", 0.0,
     f"Your Lagrangian has θ̈ in it, {ACCELERATIONS}"),
    # d/dt of a function of the velocity: it raises the order of Lagrange's equations
    (L_PENDULUM, f"{L_PENDULUM} + m l^2 θ̇ θ̈", PENDULUM, "not_equivalent", 0.0,
     f"Your Lagrangian has θ̈ in it, {ACCELERATIONS}"),
    (L_PENDULUM, f"{L_PENDULUM} + m l^2 d^2θ/dt^2", PENDULUM, "not_equivalent", 0.0,
     f"Your Lagrangian has θ̈ in it, {ACCELERATIONS}"),
    (L_PENDULUM, f"{L_PENDULUM} + m l^2 theta'''", PENDULUM, "not_equivalent", 0.0,
     f"Your Lagrangian has θ⃛ in it, {ACCELERATIONS}"),
    (L_ATWOOD, "(m1 + m2) ẋ^2 + (m1 + m2) x ẍ + (m1 - m2) g x", ATWOOD, "not_equivalent", 0.0,
     f"Your Lagrangian has ẍ in it, {ACCELERATIONS}"),
    (L_DOUBLE, f"{L_DOUBLE} + m2 l1^2 θ₁ θ̈₁ + m2 l2^2 θ̈₂", DOUBLE, "not_equivalent", 0.0,
     f"Your Lagrangian has θ̈₁, θ̈₂ in it, {ACCELERATIONS}"),
    # the momentum m l² (θ̇ + sgn θ̇) steps where θ̇ passes 0, which no sample state sees: for a person
    (L_PENDULUM, f"{L_PENDULUM} + m l^2 |θ̇|", PENDULUM, "undecided", 0.0, UNDECIDED),
    (L_PENDULUM, f"{L_PENDULUM} + m l sqrt(l^2 θ̇^2)", PENDULUM, "undecided", 0.0, UNDECIDED),
    (L_PENDULUM, "1/2 m l^2 |θ̇|^2 + m g l cos θ", PENDULUM, "equivalent", 1.0, "Correct."),
    (L_PENDULUM, "1/2 m (sqrt(l^2 θ̇^2))^2 + m g l cos θ", PENDULUM, "equivalent", 1.0, "Correct."),
    (L_PENDULUM, f"{L_PENDULUM} + m g l |θ| θ̇", PENDULUM, "equivalent", 1.0,  # d/dt(θ|θ|/2): no step
     "Correct: your Lagrangian gives the same equations of motion."),
    # an acceleration that cancels is none
    (L_PENDULUM, f"{L_PENDULUM} + m l^2 θ̈ - m l^2 θ̈", PENDULUM, "equivalent", 1.0, "Correct."),
]  # fmt: skip


@pytest.mark.parametrize(("expected", "submitted", "setting", "status", "score", "sentence"), LAGRANGIANS)
def test_a_lagrangian_is_right_only_up_to_d_dt_of_a_function_of_q_and_t(
    expected, submitted, setting, status, score, sentence
):
    verdict = compare(expected, submitted, kind="lagrangian", **setting)
    assert (verdict.status, verdict.score) == (status, score), verdict
    assert sentence in verdict.feedback, verdict
