"""Pairs of answers for judging ``grader.compare``: expected, submitted, and the verdict.

Plain data, no logic. Every verdict was derived independently with sympy (Euler–Lagrange
equations, accelerations solved from the equations of motion, trig identities checked
symbolically and at random admissible points), never copied from the lecture notes, which
carry known slips (see /work/shared/seed/README.md).

Contents:
    SYSTEMS            name → coords, known: the mechanical systems the pairs are drawn from
    EXPRESSION_PAIRS   kind "expression": equal for all admissible values
    EQUATION_PAIRS     kind "equation": the same relation (equations of motion: same accelerations)
    EQUATIONS_PAIRS    kind "equations": systems that determine the same accelerations
    LAGRANGIAN_PAIRS   kind "lagrangian": same equations of motion and the same normalization
    PAIRS              all of them

Each pair is ``(system, kind, expected, submitted, equivalent, note)``. Expected answers are in
clean plain notation; submitted ones mix plain ASCII, Unicode (θ̇₁, ², −), primes, ``thetadot``,
``diff(θ, t)`` and LaTeX. For a pair that is not equivalent the note starts with the category of
the mistake where one applies: "sign", "factor", "missing term", "extra term", "small angle",
"T+V", "wrong", "missing equation", "extra equation". In LAGRANGIAN_PAIRS "factor" is kept for a
Lagrangian that is a constant multiple k ≠ 1 of the expected one (same motion, other
normalization: partial credit); a wrong coefficient on one term is "wrong" there.

Semantics assumed (from the checker's brief): coordinates and their time derivatives are real,
every other symbol is positive. Conventions of the systems:

* pendulum: θ from the downward vertical, V = 0 at the pivot: L = ½ m l² θ̇² + m g l cos θ.
* double_pendulum: θ1, θ2 each from the downward vertical, masses m1, m2 on rods l1, l2.
* double_pendulum_equal: equal masses m and lengths l; α (upper rod) and β (lower rod) are both
  measured from the downward vertical (absolute angles, not β relative to α).
* spherical_pendulum: θ from the downward vertical, φ the azimuth:
  L = ½ m l² (θ̇² + sin²θ φ̇²) + m g l cos θ.
* atwood: x is how far m1 has descended (m2 rises by x); l is the (constant) rope length, so m2
  hangs l − x below the pulley. V = −m1 g x − m2 g (l − x); L = ½ (m1 + m2) ẋ² + (m1 − m2) g x + const;
  equation of motion (m1 + m2) ẍ = (m1 − m2) g.
* rotating_hoop: bead on a hoop of radius R turning at constant ω about its vertical diameter; θ from
  the bottom of the hoop. L = ½ m R² (θ̇² + ω² sin²θ) + m g R cos θ (rheonomic: the energy function
  h = ½ m R² θ̇² − ½ m R² ω² sin²θ − m g R cos θ is conserved, the energy T + V is not).
* incline: block sliding without friction on a fixed incline of angle alpha0 (a parameter, α₀);
  x measured down the slope. L = ½ m ẋ² + m g x sin α₀.
* damped_oscillator: L = ½ m ẋ² − ½ k x², Rayleigh dissipation F = ½ b ẋ²; m ẍ + b ẋ + k x = 0.
"""

from __future__ import annotations

SYSTEMS = {
    "pendulum": {"coords": ["theta"], "known": ["m", "g", "l"]},
    "double_pendulum": {"coords": ["theta1", "theta2"], "known": ["m1", "m2", "l1", "l2", "g"]},
    "double_pendulum_equal": {"coords": ["alpha", "beta"], "known": ["m", "g", "l"]},
    "spherical_pendulum": {"coords": ["theta", "phi"], "known": ["m", "g", "l"]},
    "atwood": {"coords": ["x"], "known": ["m1", "m2", "g", "l"]},
    "rotating_hoop": {"coords": ["theta"], "known": ["m", "g", "R", "omega"]},
    "incline": {"coords": ["x"], "known": ["m", "g", "alpha0"]},
    "damped_oscillator": {"coords": ["x"], "known": ["m", "k", "b"]},
}

# -- reference answers (plain notation) ---------------------------------------------------------

PEND_T = "1/2 m l^2 thetadot^2"
PEND_V = "-m g l cos(theta)"
PEND_L = "1/2 m l^2 thetadot^2 + m g l cos(theta)"
PEND_E = "1/2 m l^2 thetadot^2 - m g l cos(theta)"
PEND_EOM = "l thetaddot + g sin(theta) = 0"

DP_T = "1/2 (m1 + m2) l1^2 theta1dot^2 + 1/2 m2 l2^2 theta2dot^2 + m2 l1 l2 theta1dot theta2dot cos(theta1 - theta2)"
DP_V = "-(m1 + m2) g l1 cos(theta1) - m2 g l2 cos(theta2)"
DP_L = DP_T + " + (m1 + m2) g l1 cos(theta1) + m2 g l2 cos(theta2)"
DP_P1 = "(m1 + m2) l1^2 theta1dot + m2 l1 l2 theta2dot cos(theta1 - theta2)"
DP_P2 = "m2 l2^2 theta2dot + m2 l1 l2 theta1dot cos(theta1 - theta2)"
DP_EQ1 = (
    "(m1 + m2) l1 theta1ddot + m2 l2 theta2ddot cos(theta1 - theta2)"
    " + m2 l2 theta2dot^2 sin(theta1 - theta2) + (m1 + m2) g sin(theta1) = 0"
)
DP_EQ2 = "l2 theta2ddot + l1 theta1ddot cos(theta1 - theta2) - l1 theta1dot^2 sin(theta1 - theta2) + g sin(theta2) = 0"
DP_SYSTEM = DP_EQ1 + "; " + DP_EQ2

EQ_T = "m l^2 alphadot^2 + 1/2 m l^2 betadot^2 + m l^2 alphadot betadot cos(alpha - beta)"
EQ_V = "-2 m g l cos(alpha) - m g l cos(beta)"
EQ_L = EQ_T + " + 2 m g l cos(alpha) + m g l cos(beta)"
EQ_EQA = "2 l alphaddot + l betaddot cos(alpha - beta) + l betadot^2 sin(alpha - beta) + 2 g sin(alpha) = 0"
EQ_EQB = "l betaddot + l alphaddot cos(alpha - beta) - l alphadot^2 sin(alpha - beta) + g sin(beta) = 0"
EQ_SYSTEM = EQ_EQA + "; " + EQ_EQB

SPH_T = "1/2 m l^2 (thetadot^2 + sin(theta)^2 phidot^2)"
SPH_L = "1/2 m l^2 (thetadot^2 + sin(theta)^2 phidot^2) + m g l cos(theta)"
SPH_E = "1/2 m l^2 (thetadot^2 + sin(theta)^2 phidot^2) - m g l cos(theta)"
SPH_PPHI = "m l^2 sin(theta)^2 phidot"
SPH_EQT = "thetaddot - sin(theta) cos(theta) phidot^2 + g/l sin(theta) = 0"
SPH_EQP = "sin(theta) phiddot + 2 cos(theta) thetadot phidot = 0"
SPH_SYSTEM = SPH_EQT + "; " + SPH_EQP

ATW_T = "1/2 (m1 + m2) xdot^2"
ATW_V = "-(m1 - m2) g x"
ATW_L = "1/2 (m1 + m2) xdot^2 + (m1 - m2) g x"
ATW_ACC = "(m1 - m2) g/(m1 + m2)"
ATW_EOM = "(m1 + m2) xddot = (m1 - m2) g"

HOOP_T = "1/2 m R^2 (thetadot^2 + omega^2 sin(theta)^2)"
HOOP_L = "1/2 m R^2 (thetadot^2 + omega^2 sin(theta)^2) + m g R cos(theta)"
HOOP_H = "1/2 m R^2 thetadot^2 - 1/2 m R^2 omega^2 sin(theta)^2 - m g R cos(theta)"
HOOP_EOM = "R thetaddot = R omega^2 sin(theta) cos(theta) - g sin(theta)"

INC_L = "1/2 m xdot^2 + m g x sin(alpha0)"
INC_EOM = "xddot = g sin(alpha0)"

DHO_L = "1/2 m xdot^2 - 1/2 k x^2"
DHO_EOM = "m xddot + b xdot + k x = 0"

# -- expressions ---------------------------------------------------------------------------------

EXPRESSION_PAIRS = [
    # pendulum
    ("pendulum", "expression", PEND_T, r"\frac{1}{2} m l^2 \dot{\theta}^2", True, "LaTeX kinetic energy"),
    ("pendulum", "expression", PEND_T, "1/2 m (l θ̇)²", True, "T in factored form, Unicode"),
    ("pendulum", "expression", PEND_T, "1/2 m ((l cos θ θ̇)² + (l sin θ θ̇)²)", True, "Cartesian: sin² + cos² = 1"),
    ("pendulum", "expression", PEND_T, "m l^2 thetadot^2", False, "factor: missing 1/2"),
    ("pendulum", "expression", PEND_V, "-mgl cos θ", True, "mgl splits into m g l"),
    ("pendulum", "expression", PEND_V, "m g l cos(theta)", False, "sign of the potential"),
    (
        "pendulum",
        "expression",
        PEND_V,
        "m g l (1 - cos θ)",
        False,
        "extra term: constant mgl (other zero of V) changes the expression",
    ),
    ("pendulum", "expression", PEND_V, "-m g l sin(theta)", False, "wrong trig function"),
    ("pendulum", "expression", "m g l (1 - cos(theta))", "2 m g l sin^2(θ/2)", True, "half-angle identity"),
    ("pendulum", "expression", PEND_L, "m l^2 theta'^2/2 + mgl cos θ", True, "primes"),
    ("pendulum", "expression", PEND_L, "1/2 m l^2 thetadot^2 - m g l cos(theta)", False, "T+V instead of T-V"),
    ("pendulum", "expression", "m l^2 thetadot", "m l^2 diff(theta, t)", True, "p_theta with diff(theta, t)"),
    ("pendulum", "expression", "m l^2 thetadot", "m l θ̇", False, "factor: l instead of l^2"),
    ("pendulum", "expression", "m l thetadot", "m sqrt(l^2) θ̇", True, "sqrt(l^2) = l for positive l"),
    (
        "pendulum",
        "expression",
        "l thetadot",
        "sqrt(l^2 thetadot^2)",
        False,
        "sign: sqrt(l^2 thetadot^2) is |l thetadot|, thetadot may be negative",
    ),
    ("pendulum", "expression", "sqrt(g/l)", r"\frac{\sqrt{g}}{\sqrt{l}}", True, "frequency of small oscillations"),
    ("pendulum", "expression", "sqrt(g/l)", "√(l/g)", False, "wrong: inverted ratio"),
    ("pendulum", "expression", "2 pi sqrt(l/g)", "2π/√(g/l)", True, "period"),
    ("pendulum", "expression", PEND_E, "m l² θ̇²/2 − m g l (cos²(θ/2) − sin²(θ/2))", True, "double-angle identity"),
    (
        "pendulum",
        "expression",
        PEND_E,
        "1/2 m l^2 thetadot^2 - m g l (1 - theta^2/2)",
        False,
        "small angle: cos θ replaced by 1 - θ²/2",
    ),
    # double pendulum, general masses and lengths
    (
        "double_pendulum",
        "expression",
        DP_T,
        "1/2 (m1+m2) l1^2 θ̇₁² + 1/2 m2 l2^2 θ̇₂² + m2 l1 l2 θ̇₁ θ̇₂ (cos θ₁ cos θ₂ + sin θ₁ sin θ₂)",
        True,
        "cos(θ1-θ2) expanded",
    ),
    (
        "double_pendulum",
        "expression",
        DP_T,
        "1/2 m1 l1^2 theta1dot^2 + 1/2 m2 ((l1 theta1dot cos(theta1) + l2 theta2dot cos(theta2))^2"
        " + (l1 theta1dot sin(theta1) + l2 theta2dot sin(theta2))^2)",
        True,
        "Cartesian velocities squared",
    ),
    (
        "double_pendulum",
        "expression",
        DP_T,
        "1/2 (m1 + m2) l1^2 theta1dot^2 + 1/2 m2 l2^2 theta2dot^2 + m2 l1 l2 theta1dot theta2dot cos(theta1 + theta2)",
        False,
        "sign: cos(θ1+θ2) instead of cos(θ1-θ2)",
    ),
    (
        "double_pendulum",
        "expression",
        DP_T,
        "1/2 (m1 + m2) l2^2 theta1dot^2 + 1/2 m2 l1^2 theta2dot^2 + m2 l1 l2 theta1dot theta2dot cos(theta1 - theta2)",
        False,
        "wrong: l1 and l2 swapped",
    ),
    (
        "double_pendulum",
        "expression",
        DP_T,
        "1/2 m1 l1^2 theta1dot^2 + 1/2 m2 l2^2 theta2dot^2 + m2 l1 l2 theta1dot theta2dot cos(theta1 - theta2)",
        False,
        "missing term: m2 l1^2 theta1dot^2/2",
    ),
    (
        "double_pendulum",
        "expression",
        DP_T,
        "1/2 (m1 + m2) l1^2 theta1dot^2 + 1/2 m2 l2^2 theta2dot^2",
        False,
        "missing term: cross term",
    ),
    (
        "double_pendulum",
        "expression",
        DP_T,
        "1/2 (m1 + m2) l1^2 theta1dot^2 + 1/2 m2 l2^2 theta2dot^2 + m2 l1 l2 theta1dot theta2dot",
        False,
        "small angle: cos(θ1-θ2) replaced by 1",
    ),
    ("double_pendulum", "expression", DP_V, "-m1 g l1 cos θ₁ - m2 g (l1 cos θ₁ + l2 cos θ₂)", True, "V bob by bob"),
    (
        "double_pendulum",
        "expression",
        DP_V,
        "-m1 g l1 cos(theta1) - m2 g l2 cos(theta2)",
        False,
        "missing term: -m2 g l1 cos θ1",
    ),
    (
        "double_pendulum",
        "expression",
        DP_P1,
        r"(m_1+m_2)l_1^2\dot{\theta}_1 + m_2 l_1 l_2\dot{\theta}_2\cos(\theta_1-\theta_2)",
        True,
        "p_theta1 in LaTeX",
    ),
    (
        "double_pendulum",
        "expression",
        DP_P1,
        "(m1 + m2) l1^2 θ̇₁ + m2 l1 l2 θ̇₁ cos(θ₁ − θ₂)",
        False,
        "wrong: θ̇1 instead of θ̇2 in the cross term",
    ),
    (
        "double_pendulum",
        "expression",
        DP_P2,
        "m2 l2 (l2 theta_2' + l1 theta_1' cos(theta2 - theta1))",
        True,
        "p_theta2 factored, primes, cos even",
    ),
    (
        "double_pendulum",
        "expression",
        DP_P2,
        "m_2 l_2^2 theta_2dot + m_2 l_1 l_2 theta_1dot (cos(theta_1) cos(theta_2) + sin(theta_1) sin(theta_2))",
        True,
        "theta_1dot notation, cos of the difference expanded",
    ),
    (
        "double_pendulum",
        "expression",
        DP_P2,
        "m_2 l_2^2 theta_2dot + m_2 l_1 l_2 theta_2dot cos(theta_1 - theta_2)",
        False,
        "wrong: theta_2dot instead of theta_1dot in the cross term",
    ),
    # double pendulum, equal masses and lengths, α and β
    ("double_pendulum_equal", "expression", EQ_T, "1/2 m l^2 (2 α̇² + β̇² + 2 α̇ β̇ cos(α − β))", True, "in factored form"),
    (
        "double_pendulum_equal",
        "expression",
        EQ_T,
        "1/2 m l^2 (alphadot^2 + betadot^2 + 2 alphadot betadot cos(alpha - beta))",
        False,
        "factor: alphadot^2 coefficient should be m l^2",
    ),
    ("double_pendulum_equal", "expression", EQ_V, r"-mgl(2\cos\alpha + \cos\beta)", True, "LaTeX"),
    (
        "double_pendulum_equal",
        "expression",
        EQ_V,
        "-m g l (cos(alpha) + cos(beta))",
        False,
        "missing term: -m g l cos α of the lower bob",
    ),
    (
        "double_pendulum_equal",
        "expression",
        "2 m l^2 alphadot + m l^2 betadot cos(alpha - beta)",
        r"m l^2 (2\dot\alpha + \dot\beta\cos(\alpha-\beta))",
        True,
        "p_alpha",
    ),
    (
        "double_pendulum_equal",
        "expression",
        "m l^2 betadot + m l^2 alphadot cos(alpha - beta)",
        "m l^2 (β' + α' sin(α − β))",
        False,
        "wrong trig function in p_beta",
    ),
    (
        "double_pendulum_equal",
        "expression",
        EQ_T + " - 2 m g l cos(alpha) - m g l cos(beta)",
        EQ_T + " + 2 m g l cos(alpha) + m g l cos(beta)",
        False,
        "sign: T-V given for the energy T+V",
    ),
    # spherical pendulum
    ("spherical_pendulum", "expression", SPH_T, "1/2 m l^2 θ̇² + 1/2 m l^2 sin²θ φ̇²", True, "expanded"),
    ("spherical_pendulum", "expression", SPH_T, "1/2 m l^2 (θ̇² + (1 − cos²θ) φ̇²)", True, "sin² = 1 - cos²"),
    (
        "spherical_pendulum",
        "expression",
        SPH_T,
        "1/2 m l^2 (thetadot^2 + phidot^2)",
        False,
        "factor: missing sin^2 θ on phidot^2",
    ),
    (
        "spherical_pendulum",
        "expression",
        SPH_T,
        "1/2 m l^2 (thetadot^2 + cos(theta)^2 phidot^2)",
        False,
        "wrong trig function",
    ),
    ("spherical_pendulum", "expression", SPH_PPHI, "1/2 m l^2 (1 - cos 2θ) φ̇", True, "double angle"),
    ("spherical_pendulum", "expression", SPH_PPHI, "m l^2 sin(theta) phidot", False, "factor: sin θ not sin² θ"),
    (
        "spherical_pendulum",
        "expression",
        SPH_E,
        r"\frac{1}{2}ml^2\dot\theta^2+\frac{1}{2}ml^2\sin^2\theta\,\dot\phi^2-mgl\cos\theta",
        True,
        "energy in LaTeX",
    ),
    # Atwood machine
    ("atwood", "expression", ATW_T, "1/2 m1 ẋ² + 1/2 m2 (−ẋ)²", True, "T bob by bob"),
    ("atwood", "expression", ATW_V, "(m2 - m1) g x", True, "rearranged"),
    ("atwood", "expression", ATW_V, "-(m1 + m2) g x", False, "sign of the m2 term"),
    ("atwood", "expression", ATW_ACC, "g - 2 m2 g/(m1 + m2)", True, "acceleration rewritten"),
    ("atwood", "expression", ATW_ACC, "(m2 - m1) g/(m1 + m2)", False, "sign"),
    ("atwood", "expression", "2 m1 m2 g/(m1 + m2)", "2g/(1/m₁ + 1/m₂)", True, "rope tension"),
    # bead on a rotating hoop
    ("rotating_hoop", "expression", HOOP_T, "1/2 m R^2 θ̇² + 1/2 m (R ω sin θ)²", True, "expanded, Unicode"),
    (
        "rotating_hoop",
        "expression",
        HOOP_T,
        "1/2 m R^2 (thetadot^2 + omega^2 cos(theta)^2)",
        False,
        "wrong trig function",
    ),
    (
        "rotating_hoop",
        "expression",
        HOOP_H,
        "1/2 m R^2 thetadot^2 + 1/2 m R^2 omega^2 sin(theta)^2 - m g R cos(theta)",
        False,
        "sign: energy T+V given for the conserved h",
    ),
    (
        "rotating_hoop",
        "expression",
        HOOP_H,
        "1/2 m R^2 θ̇² + 1/2 m R^2 ω² cos²θ − 1/2 m R^2 ω² − m g R cos θ",
        True,
        "sin² = 1 - cos²",
    ),
    ("rotating_hoop", "expression", "g/(R omega^2)", r"g R^{-1} \omega^{-2}", True, "cos of the equilibrium angle"),
    (
        "rotating_hoop",
        "expression",
        "sqrt(omega^2 - g^2/(R^2 omega^2))",
        "sqrt(R^2 ω^4 − g^2)/(R ω)",
        True,
        "oscillation frequency about the off-axis equilibrium",
    ),
    (
        "rotating_hoop",
        "expression",
        "sqrt(g/R - omega^2)",
        "sqrt(g/R + omega^2)",
        False,
        "sign of omega^2 in the frequency about the bottom",
    ),
    ("rotating_hoop", "expression", "m R^2 thetadot", "m R^2 (thetadot + omega)", False, "extra term: m R^2 omega"),
    # incline
    ("incline", "expression", "-m g x sin(alpha0)", "-m g x cos(α₀)", False, "wrong trig function"),
    ("incline", "expression", "g sin(alpha0)", r"g\sin\alpha_0", True, "LaTeX, parameter α0"),
    ("incline", "expression", INC_L, "1/2 m ẋ² + m g x tan(α₀) cos(α₀)", True, "tan cos = sin"),
    # damped oscillator
    ("damped_oscillator", "expression", "1/2 b xdot^2", "b ẋ²", False, "factor: missing 1/2 in F"),
    ("damped_oscillator", "expression", "-b xdot", r"-b\dot{x}", True, "generalized friction force -dF/dxdot"),
    ("damped_oscillator", "expression", "-b xdot", "b x'", False, "sign of the friction force"),
    ("damped_oscillator", "expression", "-b xdot^2", "-2 (1/2 b ẋ²)", True, "dE/dt = -2F"),
    ("damped_oscillator", "expression", "sqrt(k/m - b^2/(4 m^2))", "sqrt(4 m k - b^2)/(2 m)", True, "damped frequency"),
    (
        "damped_oscillator",
        "expression",
        "sqrt(k/m - b^2/(4 m^2))",
        "sqrt(k/m)",
        False,
        "missing term: damping shift of the frequency",
    ),
    (
        "damped_oscillator",
        "expression",
        "1/2 m xdot^2 + 1/2 k x^2",
        "1/2 m x'^2 - 1/2 k x^2",
        False,
        "sign: T-V given for the energy",
    ),
    ("damped_oscillator", "expression", "2 sqrt(k m)", "sqrt(4 k m)", True, "critical damping"),
]

# -- single equations ----------------------------------------------------------------------------

EQUATION_PAIRS = [
    # pendulum
    ("pendulum", "equation", PEND_EOM, "m l² θ̈ + m g l sin θ = 0", True, "scaled by m l"),
    ("pendulum", "equation", PEND_EOM, r"\ddot\theta = -\frac{g}{l}\sin\theta", True, "solved, LaTeX"),
    ("pendulum", "equation", PEND_EOM, "diff(theta, t, 2) + g/l sin(theta) = 0", True, "diff notation"),
    ("pendulum", "equation", PEND_EOM, "-m l theta'' = m g sin theta", True, "sides swapped and scaled"),
    ("pendulum", "equation", PEND_EOM, "theta'' = -(g/l) sin(theta)", True, "solved, primes"),
    # dE/dt = m l θ̇ (l θ̈ + g sin θ): at rest (θ̇ = 0) it holds for every θ̈
    ("pendulum", "equation", PEND_EOM, f"d/dt({PEND_E}) = 0", False, "vanishing factor: energy conserved, at rest"),
    ("pendulum", "equation", PEND_EOM, "sin θ (l θ̈ + g sin θ) = 0", False, "vanishing factor: sin θ, at θ = 0"),
    ("pendulum", "equation", PEND_EOM, "(1 + θ̇²)(l θ̈ + g sin θ) = 0", True, "scaled by a factor that never vanishes"),
    ("pendulum", "equation", PEND_EOM, "theta'' = -g/l theta", False, "small angle: sin θ replaced by θ"),
    ("pendulum", "equation", PEND_EOM, "θ̈ = g/l sin θ", False, "sign of the gravity term"),
    ("pendulum", "equation", PEND_EOM, "thetaddot + g sin(theta) = 0", False, "factor: missing 1/l on one term"),
    ("pendulum", "equation", PEND_EOM, "m l^2 thetaddot = m g l cos(theta)", False, "wrong trig function"),
    ("pendulum", "equation", "thetaddot + g/l theta = 0", "l θ̈ = −g θ", True, "linearized equation rearranged"),
    # double pendulum, one equation of the system
    (
        "double_pendulum",
        "equation",
        DP_EQ1,
        "(m₁+m₂) l₁² θ̈₁ + m₂ l₁ l₂ θ̈₂ cos(θ₁−θ₂) + m₂ l₁ l₂ θ̇₂² sin(θ₁−θ₂) + (m₁+m₂) g l₁ sin θ₁ = 0",
        True,
        "theta1 equation scaled by l1",
    ),
    (
        "double_pendulum",
        "equation",
        DP_EQ1,
        "(m1 + m2) l1 theta1ddot + m2 l2 theta2ddot cos(theta1 - theta2) - m2 l2 theta2dot^2 sin(theta2 - theta1)"
        " + (m1 + m2) g sin(theta1) = 0",
        True,
        "sin odd: -sin(θ2-θ1)",
    ),
    (
        "double_pendulum",
        "equation",
        DP_EQ1,
        "theta2'' = -((m1 + m2) l1 theta1'' + m2 l2 theta2'^2 sin(theta1 - theta2) + (m1 + m2) g sin(theta1))"
        "/(m2 l2 cos(theta1 - theta2))",
        True,
        "solved for theta2ddot (divided by cos, nonzero generically)",
    ),
    (
        "double_pendulum",
        "equation",
        DP_EQ1,
        "(m1 + m2) l1 theta1ddot + m2 l2 theta2ddot cos(theta1 - theta2) - m2 l2 theta2dot^2 sin(theta1 - theta2)"
        " + (m1 + m2) g sin(theta1) = 0",
        False,
        "sign of the theta2dot^2 term",
    ),
    (
        "double_pendulum",
        "equation",
        DP_EQ1,
        "(m1 + m2) l1 theta1ddot + m2 l2 theta2ddot cos(theta1 - theta2) + (m1 + m2) g sin(theta1) = 0",
        False,
        "missing term: theta2dot^2 term",
    ),
    (
        "double_pendulum",
        "equation",
        DP_EQ1,
        "(m1 + m2) l1 θ̈₁ + m2 l2 θ̈₂ + (m1 + m2) g θ₁ = 0",
        False,
        "small angle: linearized theta1 equation",
    ),
    (
        "double_pendulum",
        "equation",
        DP_EQ1,
        "(m1 + m2) l1 theta1ddot + m2 l2 theta2ddot cos(theta1 - theta2) + m2 l2 theta2dot^2 sin(theta1 - theta2)"
        " + m1 g sin(theta1) = 0",
        False,
        "missing term: m2 g sin θ1",
    ),
    (
        "double_pendulum",
        "equation",
        DP_EQ1,
        "(m1 + m2) l1 theta1ddot + m2 l1 theta2ddot cos(theta1 - theta2) + m2 l2 theta2dot^2 sin(theta1 - theta2)"
        " + (m1 + m2) g sin(theta1) = 0",
        False,
        "wrong: l1 instead of l2 on the theta2ddot term",
    ),
    (
        "double_pendulum",
        "equation",
        DP_EQ2,
        "m2 l2^2 θ₂'' + m2 l1 l2 θ₁'' cos(θ₁ − θ₂) = m2 l1 l2 θ₁'² sin(θ₁ − θ₂) − m2 g l2 sin θ₂",
        True,
        "theta2 equation scaled by m2 l2, terms moved",
    ),
    (
        "double_pendulum",
        "equation",
        DP_EQ2,
        "θ̈₁ = (l₁ θ̇₁² sin(θ₁ − θ₂) − g sin θ₂ − l₂ θ̈₂)/(l₁ cos(θ₁ − θ₂))",
        True,
        "theta2 equation solved for theta1ddot (divided by cos, nonzero generically)",
    ),
    (
        "double_pendulum",
        "equation",
        DP_EQ2,
        "l2 theta2ddot + l1 theta1ddot (cos(theta1) cos(theta2) + sin(theta1) sin(theta2))"
        " - l1 theta1dot^2 (sin(theta1) cos(theta2) - cos(theta1) sin(theta2)) + g sin(theta2) = 0",
        True,
        "trig of the difference expanded",
    ),
    (
        "double_pendulum",
        "equation",
        DP_EQ2,
        "l2 theta2ddot + l1 theta1ddot cos(theta1 - theta2) + l1 theta1dot^2 sin(theta1 - theta2) + g sin(theta2) = 0",
        False,
        "sign of the theta1dot^2 term",
    ),
    (
        "double_pendulum",
        "equation",
        DP_EQ2,
        "m2 l2 theta2ddot + m2 l1 theta1ddot cos(theta1 - theta2) - m2 l1 theta1dot^2 sin(theta1 - theta2)"
        " + (m1 + m2) g sin(theta2) = 0",
        False,
        "factor: (m1+m2) on the gravity term only",
    ),
    (
        "double_pendulum",
        "equation",
        DP_EQ2,
        "(m1 + m2) l1 theta1ddot + l1 theta1ddot cos(theta1 - theta2) + l2 theta2ddot + m2 l2 theta2ddot cos(theta1 - theta2)"
        " + m2 l2 theta2dot^2 sin(theta1 - theta2) - l1 theta1dot^2 sin(theta1 - theta2)"
        " + (m1 + m2) g sin(theta1) + g sin(theta2) = 0",
        False,
        "wrong: sum of both equations given for the theta2 equation",
    ),
    # double pendulum, equal masses, α and β
    (
        "double_pendulum_equal",
        "equation",
        EQ_EQA,
        "2 m l^2 α̈ + m l^2 β̈ cos(α − β) + m l^2 β̇² sin(α − β) + 2 m g l sin α = 0",
        True,
        "scaled by m l",
    ),
    (
        "double_pendulum_equal",
        "equation",
        EQ_EQA,
        "2 g sin(alpha) = -2 l alpha'' - l beta'' cos(beta - alpha) + l beta'^2 sin(beta - alpha)",
        True,
        "terms moved, differences reversed",
    ),
    (
        "double_pendulum_equal",
        "equation",
        EQ_EQA,
        "l alphaddot + l betaddot cos(alpha - beta) + l betadot^2 sin(alpha - beta) + 2 g sin(alpha) = 0",
        False,
        "factor: coefficient of alphaddot should be 2l",
    ),
    ("double_pendulum_equal", "equation", EQ_EQA, "2 l α̈ + l β̈ + 2 g α = 0", False, "small angle"),
    (
        "double_pendulum_equal",
        "equation",
        EQ_EQB,
        r"\ddot\beta = -\ddot\alpha\cos(\alpha-\beta) + \dot\alpha^2\sin(\alpha-\beta) - \frac{g}{l}\sin\beta",
        True,
        "beta equation solved, LaTeX",
    ),
    (
        "double_pendulum_equal",
        "equation",
        EQ_EQA,
        r"2\ddot\alpha + \ddot\beta(\cos\alpha\cos\beta + \sin\alpha\sin\beta)"
        r" + \dot\beta^2(\sin\alpha\cos\beta - \cos\alpha\sin\beta) + \frac{2g}{l}\sin\alpha = 0",
        True,
        "divided by l, trig of the difference expanded, LaTeX",
    ),
    (
        "double_pendulum_equal",
        "equation",
        EQ_EQB,
        "l betaddot + l alphaddot cos(alpha - beta) - l alphadot^2 sin(alpha - beta) + g sin(alpha) = 0",
        False,
        "wrong: sin alpha instead of sin beta",
    ),
    (
        "double_pendulum_equal",
        "equation",
        EQ_EQB,
        "l betaddot + l alphaddot cos(alpha - beta) - l betadot^2 sin(alpha - beta) + g sin(beta) = 0",
        False,
        "wrong: betadot^2 instead of alphadot^2",
    ),
    # spherical pendulum
    (
        "spherical_pendulum",
        "equation",
        SPH_EQT,
        "m l^2 θ̈ = m l^2 sin θ cos θ φ̇² − m g l sin θ",
        True,
        "theta equation scaled, terms moved",
    ),
    ("spherical_pendulum", "equation", SPH_EQT, "θ̈ − 1/2 sin(2θ) φ̇² + g/l sin θ = 0", True, "double angle"),
    (
        "spherical_pendulum",
        "equation",
        SPH_EQT,
        "thetaddot + sin(theta) cos(theta) phidot^2 + g/l sin(theta) = 0",
        False,
        "sign of the centrifugal term",
    ),
    (
        "spherical_pendulum",
        "equation",
        SPH_EQT,
        "thetaddot + g/l sin(theta) = 0",
        False,
        "missing term: centrifugal phidot^2 term",
    ),
    (
        "spherical_pendulum",
        "equation",
        SPH_EQP,
        "m l^2 sin²θ φ̈ + 2 m l^2 sin θ cos θ θ̇ φ̇ = 0",
        True,
        "phi equation times m l^2 sin θ (state factor)",
    ),
    ("spherical_pendulum", "equation", SPH_EQP, "φ̈ = −2 cot θ θ̇ φ̇", True, "solved for phiddot (divided by sin θ)"),
    (
        "spherical_pendulum",
        "equation",
        SPH_EQP,
        "diff(m l^2 sin(theta)^2 diff(phi, t), t) = 0",
        True,
        "conservation of p_phi as d/dt",
    ),
    (
        "spherical_pendulum",
        "equation",
        SPH_EQP,
        "sin(theta) phiddot + cos(theta) thetadot phidot = 0",
        False,
        "factor: missing 2 on the Coriolis term",
    ),
    ("spherical_pendulum", "equation", SPH_EQP, "φ̈ = 0", False, "missing term: Coriolis term"),
    # Atwood machine
    ("atwood", "equation", ATW_EOM, "ẍ = (m₁ − m₂) g/(m₁ + m₂)", True, "solved"),
    ("atwood", "equation", ATW_EOM, "m1 (xddot - g) + m2 (xddot + g) = 0", True, "bob by bob"),
    ("atwood", "equation", ATW_EOM, "m₁ ẍ + m₂ ẍ = m₁ g − m₂ g", True, "expanded, Unicode"),
    ("atwood", "equation", ATW_EOM, "(m1 + m2) x'' = (m2 - m1) g", False, "sign"),
    ("atwood", "equation", ATW_EOM, "(m1 - m2) xddot = (m1 + m2) g", False, "wrong: mass sums swapped"),
    # bead on a rotating hoop
    ("rotating_hoop", "equation", HOOP_EOM, "m R² θ̈ − m R² ω² sin θ cos θ + m g R sin θ = 0", True, "scaled by m R"),
    ("rotating_hoop", "equation", HOOP_EOM, "θ̈ = 1/2 ω² sin 2θ − (g/R) sin θ", True, "double angle"),
    (
        "rotating_hoop",
        "equation",
        HOOP_EOM,
        "thetaddot = (omega^2 cos(theta) - g/R) sin(theta)",
        True,
        "in factored form",
    ),
    (
        "rotating_hoop",
        "equation",
        HOOP_EOM,
        r"\ddot\theta = -\frac{g}{R}\sin\theta",
        False,
        "missing term: omega^2 term",
    ),
    ("rotating_hoop", "equation", HOOP_EOM, "R θ̈ = R ω² sin θ cos θ + g sin θ", False, "sign of the gravity term"),
    (
        "rotating_hoop",
        "equation",
        HOOP_EOM,
        "R thetaddot = R omega^2 sin(theta) - g sin(theta)",
        False,
        "wrong: omega^2 sin θ without cos θ",
    ),
    ("rotating_hoop", "equation", HOOP_EOM, "thetaddot = -(g/R - omega^2) theta", False, "small angle"),
    ("rotating_hoop", "equation", "cos(theta) = g/(R omega^2)", "R ω² cos θ = g", True, "equilibrium condition"),
    ("rotating_hoop", "equation", "cos(theta) = g/(R omega^2)", "cos θ = R ω²/g", False, "wrong: ratio inverted"),
    # incline
    ("incline", "equation", INC_EOM, "m ẍ − m g sin α₀ = 0", True, "scaled by m"),
    ("incline", "equation", INC_EOM, r"\ddot x - g\sin\alpha_0 = 0", True, "LaTeX, term moved"),
    ("incline", "equation", INC_EOM, r"\ddot{x} = g\cos\alpha_0", False, "wrong trig function"),
    ("incline", "equation", INC_EOM, "m x'' = g sin(alpha0)", False, "factor: m on one side only"),
    # damped oscillator
    ("damped_oscillator", "equation", DHO_EOM, "ẍ = −(b/m) ẋ − (k/m) x", True, "solved"),
    ("damped_oscillator", "equation", DHO_EOM, r"\ddot{x} + \frac{b}{m}\dot{x} + \frac{k}{m}x = 0", True, "LaTeX"),
    ("damped_oscillator", "equation", DHO_EOM, "mxddot + bxdot = -kx", True, "names run together, term moved"),
    ("damped_oscillator", "equation", DHO_EOM, "-k x = m x'' + b x'", True, "sides swapped, primes"),
    ("damped_oscillator", "equation", DHO_EOM, "m ẍ − b ẋ + k x = 0", False, "sign of the damping term"),
    ("damped_oscillator", "equation", DHO_EOM, "m xddot + 2 b xdot + k x = 0", False, "factor: 2 on the damping term"),
    ("damped_oscillator", "equation", DHO_EOM, "m x'' + k x = 0", False, "missing term: damping"),
]

# -- systems of equations ------------------------------------------------------------------------

DP_SOLVED = (
    "theta1ddot = (-g (2 m1 + m2) sin(theta1) - m2 g sin(theta1 - 2 theta2)"
    " - 2 sin(theta1 - theta2) m2 (theta2dot^2 l2 + theta1dot^2 l1 cos(theta1 - theta2)))"
    "/(l1 (2 m1 + m2 - m2 cos(2 theta1 - 2 theta2)));"
    " theta2ddot = 2 sin(theta1 - theta2) (theta1dot^2 l1 (m1 + m2) + g (m1 + m2) cos(theta1)"
    " + theta2dot^2 l2 m2 cos(theta1 - theta2))/(l2 (2 m1 + m2 - m2 cos(2 theta1 - 2 theta2)))"
)
DP_SOLVED_CRAMER = (
    "θ₁'' = (−m₂ l₂ θ₂'² sin(θ₁−θ₂) − (m₁+m₂) g sin θ₁ − m₂ cos(θ₁−θ₂) (l₁ θ₁'² sin(θ₁−θ₂) − g sin θ₂))"
    "/(l₁ (m₁ + m₂ sin²(θ₁−θ₂)))\n"
    "θ₂'' = ((m₁+m₂) (l₁ θ₁'² sin(θ₁−θ₂) − g sin θ₂) + cos(θ₁−θ₂) (m₂ l₂ θ₂'² sin(θ₁−θ₂) + (m₁+m₂) g sin θ₁))"
    "/(l₂ (m₁ + m₂ sin²(θ₁−θ₂)))"
)
EQ_SOLVED = (
    "alphaddot = (-3 g sin(alpha) - g sin(alpha - 2 beta) - 2 sin(alpha - beta) (l betadot^2"
    " + l alphadot^2 cos(alpha - beta)))/(l (3 - cos(2 alpha - 2 beta)));"
    " betaddot = 2 sin(alpha - beta) (2 l alphadot^2 + 2 g cos(alpha) + l betadot^2 cos(alpha - beta))"
    "/(l (3 - cos(2 alpha - 2 beta)))"
)
EQ_SOLVED_CRAMER = (
    "α̈ = (−l β̇² sin(α−β) − 2 g sin α − cos(α−β) (l α̇² sin(α−β) − g sin β))/(l (1 + sin²(α−β)))\n"
    "β̈ = (2 (l α̇² sin(α−β) − g sin β) + cos(α−β) (l β̇² sin(α−β) + 2 g sin α))/(l (1 + sin²(α−β)))"
)

EQUATIONS_PAIRS = [
    # double pendulum, general masses and lengths
    ("double_pendulum", "equations", DP_SYSTEM, "[" + DP_EQ2 + ", " + DP_EQ1 + "]", True, "reordered, bracket list"),
    (
        "double_pendulum",
        "equations",
        DP_SYSTEM,
        "(m₁+m₂) l₁² θ̈₁ + m₂ l₁ l₂ θ̈₂ cos(θ₁−θ₂) + m₂ l₁ l₂ θ̇₂² sin(θ₁−θ₂) + (m₁+m₂) g l₁ sin θ₁ = 0\n"
        "m₂ l₂² θ̈₂ + m₂ l₁ l₂ θ̈₁ cos(θ₁−θ₂) − m₂ l₁ l₂ θ̇₁² sin(θ₁−θ₂) + m₂ g l₂ sin θ₂ = 0",
        True,
        "each equation scaled, Unicode, newline separated",
    ),
    ("double_pendulum", "equations", DP_SYSTEM, DP_SOLVED, True, "explicitly solved accelerations"),
    ("double_pendulum", "equations", DP_SYSTEM, DP_SOLVED_CRAMER, True, "solved by Cramer's rule, primes"),
    (
        "double_pendulum",
        "equations",
        DP_SYSTEM,
        DP_SOLVED_CRAMER.split("\n")[1] + "\n" + DP_SOLVED_CRAMER.split("\n")[0],
        True,
        "solved, theta2 first",
    ),
    (
        "double_pendulum",
        "equations",
        DP_SYSTEM,
        DP_EQ1 + "; theta2ddot = (l1 theta1dot^2 sin(theta1 - theta2) - g sin(theta2)"
        " - l1 theta1ddot cos(theta1 - theta2))/l2",
        True,
        "second equation solved for theta2ddot only",
    ),
    (
        "double_pendulum",
        "equations",
        DP_SYSTEM,
        "(m1 + m2) l1 θ̈₁ + m2 l2 θ̈₂ (cos θ₁ cos θ₂ + sin θ₁ sin θ₂) + m2 l2 θ̇₂² (sin θ₁ cos θ₂ − cos θ₁ sin θ₂)"
        " + (m1 + m2) g sin θ₁ = 0; "
        "l2 θ̈₂ + l1 θ̈₁ (cos θ₁ cos θ₂ + sin θ₁ sin θ₂) − l1 θ̇₁² (sin θ₁ cos θ₂ − cos θ₁ sin θ₂) + g sin θ₂ = 0",
        True,
        "trig of the difference expanded in both",
    ),
    (
        "double_pendulum",
        "equations",
        DP_SYSTEM,
        "(m1 + m2) l1 theta1ddot + l1 theta1ddot cos(theta1 - theta2) + l2 theta2ddot + m2 l2 theta2ddot cos(theta1 - theta2)"
        " + m2 l2 theta2dot^2 sin(theta1 - theta2) - l1 theta1dot^2 sin(theta1 - theta2)"
        " + (m1 + m2) g sin(theta1) + g sin(theta2) = 0; " + DP_EQ2,
        True,
        "eq1 + eq2 replacing eq1",
    ),
    (
        "double_pendulum",
        "equations",
        DP_SYSTEM,
        "(m1 + m2) l1 theta1ddot - m2 l1 theta1ddot cos(theta1 - theta2)^2"
        " + m2 l2 theta2dot^2 sin(theta1 - theta2) + m2 l1 theta1dot^2 sin(theta1 - theta2) cos(theta1 - theta2)"
        " + (m1 + m2) g sin(theta1) - m2 g sin(theta2) cos(theta1 - theta2) = 0; " + DP_EQ2,
        True,
        "theta2ddot eliminated from eq1 (eq1 - m2 cos(θ1-θ2) eq2)",
    ),
    (
        "double_pendulum",
        "equations",
        DP_SYSTEM,
        r"(m_1+m_2)l_1\ddot\theta_1 + m_2 l_2\ddot\theta_2\cos(\theta_1-\theta_2)"
        r" + m_2 l_2\dot\theta_2^2\sin(\theta_1-\theta_2) + (m_1+m_2)g\sin\theta_1 = 0 \\"
        r" l_2\ddot\theta_2 + l_1\ddot\theta_1\cos(\theta_1-\theta_2) - l_1\dot\theta_1^2\sin(\theta_1-\theta_2)"
        r" + g\sin\theta_2 = 0",
        True,
        "LaTeX with \\\\ between equations",
    ),
    ("double_pendulum", "equations", DP_SYSTEM, DP_EQ1, False, "missing equation: only the theta1 equation"),
    (
        "double_pendulum",
        "equations",
        DP_SYSTEM,
        DP_SYSTEM + "; theta1dot = theta2dot",
        False,
        "extra equation: theta1dot = theta2dot",
    ),
    (
        "double_pendulum",
        "equations",
        DP_SYSTEM,
        DP_SYSTEM + "; (m1 + m2) l1 theta1ddot + m2 l2 theta2ddot cos(theta1 - theta2)"
        " + m2 l2 theta2dot^2 sin(theta1 - theta2) + (m1 + m2) g sin(theta1) = 0",
        False,
        "extra equation: theta1 equation repeated",
    ),
    (
        "double_pendulum",
        "equations",
        DP_SYSTEM,
        DP_EQ1 + "; l2 theta2ddot + l1 theta1ddot cos(theta1 - theta2) + l1 theta1dot^2 sin(theta1 - theta2)"
        " + g sin(theta2) = 0",
        False,
        "sign of the theta1dot^2 term in the theta2 equation",
    ),
    (
        "double_pendulum",
        "equations",
        DP_SYSTEM,
        "(m1 + m2) l1 θ̈₁ + m2 l2 θ̈₂ + (m1 + m2) g θ₁ = 0; l2 θ̈₂ + l1 θ̈₁ + g θ₂ = 0",
        False,
        "small angle: linearized system",
    ),
    (
        "double_pendulum",
        "equations",
        DP_SYSTEM,
        DP_EQ1 + "; 2 (m1 + m2) l1 theta1ddot + 2 m2 l2 theta2ddot cos(theta1 - theta2)"
        " + 2 m2 l2 theta2dot^2 sin(theta1 - theta2) + 2 (m1 + m2) g sin(theta1) = 0",
        False,
        "missing equation: the second is twice the first",
    ),
    (
        "double_pendulum",
        "equations",
        DP_SYSTEM,
        DP_EQ1 + "; l1 theta2ddot + l2 theta1ddot cos(theta1 - theta2) - l2 theta1dot^2 sin(theta1 - theta2)"
        " + g sin(theta2) = 0",
        False,
        "wrong: l1 and l2 swapped in the theta2 equation",
    ),
    (
        "double_pendulum",
        "equations",
        DP_SYSTEM,
        "(m1 + m2) l1 theta1ddot + m2 l2 theta2ddot cos(theta1 - theta2) + m2 l2 theta2dot^2 sin(theta1 - theta2)"
        " + m1 g sin(theta1) = 0; " + DP_EQ2,
        False,
        "missing term: m2 g sin θ1 in the theta1 equation",
    ),
    (
        "double_pendulum",
        "equations",
        DP_SYSTEM,
        DP_SOLVED.replace("theta2ddot = 2 sin", "theta2ddot = -2 sin"),
        False,
        "sign of the solved theta2ddot",
    ),
    (
        "double_pendulum",
        "equations",
        DP_SYSTEM,
        DP_SOLVED.replace("cos(2 theta1 - 2 theta2)", "cos(theta1 - theta2)"),
        False,
        "wrong: cos(θ1-θ2) for cos(2θ1-2θ2) in the denominators",
    ),
    # double pendulum, equal masses, α and β
    ("double_pendulum_equal", "equations", EQ_SYSTEM, "[" + EQ_EQB + ", " + EQ_EQA + "]", True, "reordered"),
    (
        "double_pendulum_equal",
        "equations",
        EQ_SYSTEM,
        "2 m l² α̈ + m l² β̈ cos(α − β) + m l² β̇² sin(α − β) + 2 m g l sin α = 0; "
        "m l² β̈ + m l² α̈ cos(α − β) − m l² α̇² sin(α − β) + m g l sin β = 0",
        True,
        "both scaled by m l, Unicode",
    ),
    ("double_pendulum_equal", "equations", EQ_SYSTEM, EQ_SOLVED, True, "explicitly solved accelerations"),
    (
        "double_pendulum_equal",
        "equations",
        EQ_SYSTEM,
        EQ_SOLVED_CRAMER,
        True,
        "solved, denominator l(1 + sin²(α-β)), Unicode",
    ),
    (
        "double_pendulum_equal",
        "equations",
        EQ_SYSTEM,
        "2 alphaddot + betaddot cos(alpha - beta) + betadot^2 sin(alpha - beta) + 2 (g/l) sin(alpha) = 0; "
        "betaddot + alphaddot cos(alpha - beta) - alphadot^2 sin(alpha - beta) + (g/l) sin(beta) = 0",
        True,
        "both divided by l",
    ),
    (
        "double_pendulum_equal",
        "equations",
        EQ_SYSTEM,
        "2 m l^2 α'' + m l^2 β'' cos(β − α) − m l^2 β'^2 sin(β − α) + 2 m g l sin α = 0; "
        "m l^2 β'' + m l^2 α'' cos(β − α) + m l^2 α'^2 sin(β − α) + m g l sin β = 0",
        True,
        "scaled by m l, differences reversed",
    ),
    (
        "double_pendulum_equal",
        "equations",
        EQ_SYSTEM,
        "2 l alpha'' - l beta'' + (l beta'' - l alpha'') cos(alpha - beta) + l (beta'^2 + alpha'^2) sin(alpha - beta)"
        " + 2 g sin(alpha) - g sin(beta) = 0; " + EQ_EQB,
        True,
        "alpha equation minus beta equation, primes",
    ),
    (
        "double_pendulum_equal",
        "equations",
        EQ_SYSTEM,
        r"2l\ddot\alpha + l\ddot\beta\cos(\alpha-\beta) + l\dot\beta^2\sin(\alpha-\beta) + 2g\sin\alpha = 0 \\"
        r" l\ddot\beta + l\ddot\alpha\cos(\alpha-\beta) - l\dot\alpha^2\sin(\alpha-\beta) + g\sin\beta = 0",
        True,
        "LaTeX",
    ),
    ("double_pendulum_equal", "equations", EQ_SYSTEM, EQ_EQA, False, "missing equation: beta equation"),
    (
        "double_pendulum_equal",
        "equations",
        EQ_SYSTEM,
        EQ_SYSTEM + "; alphaddot = betaddot",
        False,
        "extra equation: alphaddot = betaddot",
    ),
    (
        "double_pendulum_equal",
        "equations",
        EQ_SYSTEM,
        "2 α̈ + β̈ + 2 (g/l) α = 0; β̈ + α̈ + (g/l) β = 0",
        False,
        "small angle: linearized system",
    ),
    (
        "double_pendulum_equal",
        "equations",
        EQ_SYSTEM,
        EQ_EQA + "; l betaddot + l alphaddot cos(alpha - beta) + l alphadot^2 sin(alpha - beta) + g sin(beta) = 0",
        False,
        "sign of the alphadot^2 term in the beta equation",
    ),
    (
        "double_pendulum_equal",
        "equations",
        EQ_SYSTEM,
        "2 l alphaddot + l betaddot cos(alpha - beta) + l alphadot^2 sin(alpha - beta) + 2 g sin(alpha) = 0; "
        "l betaddot + l alphaddot cos(alpha - beta) - l betadot^2 sin(alpha - beta) + g sin(beta) = 0",
        False,
        "wrong: alphadot^2 and betadot^2 swapped",
    ),
    (
        "double_pendulum_equal",
        "equations",
        EQ_SYSTEM,
        "l alphaddot + l betaddot cos(alpha - beta) + l betadot^2 sin(alpha - beta) + g sin(alpha) = 0; " + EQ_EQB,
        False,
        "wrong: alpha equation of a single pendulum's mass (coefficients 2 dropped)",
    ),
    (
        "double_pendulum_equal",
        "equations",
        EQ_SYSTEM,
        EQ_SOLVED.replace("(l (3 - cos", "(l (1 - cos"),
        False,
        "wrong: denominator 1 - cos(2α-2β)",
    ),
    (
        "double_pendulum_equal",
        "equations",
        EQ_SYSTEM,
        "2 l alphaddot + l betaddot cos(alpha - beta) + 2 g sin(alpha) = 0; "
        "l betaddot + l alphaddot cos(alpha - beta) + g sin(beta) = 0",
        False,
        "missing term: velocity-squared terms",
    ),
    # spherical pendulum
    (
        "spherical_pendulum",
        "equations",
        SPH_SYSTEM,
        "m l^2 θ̈ − m l^2 sin θ cos θ φ̇² + m g l sin θ = 0; m l^2 sin²θ φ̈ + 2 m l^2 sin θ cos θ θ̇ φ̇ = 0",
        True,
        "from the Lagrangian directly (φ equation times sin θ)",
    ),
    (
        "spherical_pendulum",
        "equations",
        SPH_SYSTEM,
        "thetaddot = sin(theta) cos(theta) phidot^2 - g/l sin(theta); phiddot = -2 cot(theta) thetadot phidot",
        True,
        "solved, cot",
    ),
    (
        "spherical_pendulum",
        "equations",
        SPH_SYSTEM,
        "[phiddot = -2 cos(theta) thetadot phidot/sin(theta), l thetaddot = l sin(theta) cos(theta) phidot^2"
        " - g sin(theta)]",
        True,
        "solved, reordered, bracket list",
    ),
    (
        "spherical_pendulum",
        "equations",
        SPH_SYSTEM,
        SPH_EQT + "; diff(m l^2 sin(theta)^2 diff(phi, t), t) = 0",
        True,
        "p_phi conservation as d/dt",
    ),
    (
        "spherical_pendulum",
        "equations",
        SPH_SYSTEM,
        "θ̈ = sin θ cos θ φ̇² − g/l sin θ; sin²θ φ̈ = −2 sin θ cos θ θ̇ φ̇",
        True,
        "Unicode, phi equation times sin θ",
    ),
    (
        "spherical_pendulum",
        "equations",
        SPH_SYSTEM,
        "diff(theta, t, 2) = sin(theta) cos(theta) diff(phi, t)^2 - g/l sin(theta); "
        "sin(theta) diff(phi, t, 2) = -2 cos(theta) diff(theta, t) diff(phi, t)",
        True,
        "diff notation",
    ),
    (
        "spherical_pendulum",
        "equations",
        SPH_SYSTEM,
        "thetaddot - sin(theta) cos(theta) phidot^2 + g/l sin(theta) + sin(theta) phiddot"
        " + 2 cos(theta) thetadot phidot = 0; " + SPH_EQP,
        True,
        "eq1 + eq2 replacing eq1",
    ),
    (
        "spherical_pendulum",
        "equations",
        SPH_SYSTEM,
        r"\ddot\theta - \frac{1}{2}\sin 2\theta\,\dot\phi^2 + \frac{g}{l}\sin\theta = 0 \\"
        r" \sin\theta\,\ddot\phi + 2\cos\theta\,\dot\theta\,\dot\phi = 0",
        True,
        "LaTeX, double angle",
    ),
    ("spherical_pendulum", "equations", SPH_SYSTEM, SPH_EQT, False, "missing equation: phi equation"),
    (
        "spherical_pendulum",
        "equations",
        SPH_SYSTEM,
        f"{SPH_EQT}; φ̇ ({SPH_EQP.removesuffix(' = 0')}) = 0",
        False,
        "vanishing factor: phi equation times phidot",
    ),
    ("spherical_pendulum", "equations", SPH_SYSTEM, SPH_SYSTEM + "; phidot = 0", False, "extra equation: phidot = 0"),
    (
        "spherical_pendulum",
        "equations",
        SPH_SYSTEM,
        SPH_EQT + "; sin(theta) phiddot + cos(theta) thetadot phidot = 0",
        False,
        "factor: missing 2 in the phi equation",
    ),
    (
        "spherical_pendulum",
        "equations",
        SPH_SYSTEM,
        "thetaddot + sin(theta) cos(theta) phidot^2 + g/l sin(theta) = 0; " + SPH_EQP,
        False,
        "sign of the centrifugal term",
    ),
    ("spherical_pendulum", "equations", SPH_SYSTEM, SPH_EQT + "; φ̈ = 0", False, "missing term: phi equation"),
    (
        "spherical_pendulum",
        "equations",
        SPH_SYSTEM,
        "thetaddot + g/l sin(theta) = 0; " + SPH_EQP,
        False,
        "missing term: centrifugal term",
    ),
    (
        "spherical_pendulum",
        "equations",
        SPH_SYSTEM,
        SPH_EQT + "; sin(theta) phiddot + 2 sin(theta) thetadot phidot = 0",
        False,
        "wrong trig function",
    ),
    (
        "spherical_pendulum",
        "equations",
        SPH_SYSTEM,
        "thetaddot - theta phidot^2 + g/l theta = 0; theta phiddot + 2 thetadot phidot = 0",
        False,
        "small angle",
    ),
]

# -- Lagrangians ---------------------------------------------------------------------------------

LAGRANGIAN_PAIRS = [
    # pendulum
    ("pendulum", "lagrangian", PEND_L, "1/2 m l^2 θ̇² − m g l (1 − cos θ)", True, "V measured from the lowest point"),
    ("pendulum", "lagrangian", PEND_L, r"\frac{1}{2}ml^2\dot\theta^2+mgl\cos\theta + 5", True, "constant added"),
    ("pendulum", "lagrangian", PEND_L, "1/2 m l^2 diff(theta, t)^2 + m g l cos(theta)", True, "diff notation"),
    ("pendulum", "lagrangian", PEND_L, "1/2 m (l theta')^2 - (-m g l cos(theta))", True, "T - V written out, primes"),
    ("pendulum", "lagrangian", PEND_L, "1/2 m l² θ̇² − 2 m g l sin²(θ/2)", True, "half angle: differs by a constant"),
    (
        "pendulum",
        "lagrangian",
        PEND_L,
        "1/2 m l^2 thetadot^2 + m g l cos(theta) + m g l t",
        True,
        "total derivative of a function of t only, d/dt(m g l t^2/2)",
    ),
    (
        "pendulum",
        "lagrangian",
        PEND_L,
        "1/2 m l^2 thetadot^2 + m g l cos(theta) + 2 theta thetadot",
        True,
        "total derivative d/dt(theta^2)",
    ),
    (
        "pendulum",
        "lagrangian",
        PEND_L,
        "1/2 m l^2 θ̇² + m g l cos θ + m l θ̇ cos θ",
        True,
        "total derivative d/dt(m l sin θ)",
    ),
    (
        "pendulum",
        "lagrangian",
        PEND_L,
        "1/2 m l^2 theta'^2 + m g l cos(theta) + theta theta'^2",
        False,
        "extra term: theta thetadot^2 is not a total derivative",
    ),
    ("pendulum", "lagrangian", PEND_L, "m l^2 thetadot^2 + 2 m g l cos(theta)", False, "factor: 2L"),
    ("pendulum", "lagrangian", PEND_L, "1/2 l^2 thetadot^2 + g l cos(theta)", False, "factor: L/m"),
    ("pendulum", "lagrangian", PEND_L, "-1/2 m l^2 θ̇² − m g l cos θ", False, "factor: -L (V - T)"),
    ("pendulum", "lagrangian", PEND_L, "1/2 m l^2 thetadot^2 - m g l cos(theta)", False, "T+V instead of T-V"),
    ("pendulum", "lagrangian", PEND_L, "1/2 m l^2 θ̇² − 1/2 m g l θ²", False, "small angle"),
    ("pendulum", "lagrangian", PEND_L, "1/2 m l^2 thetadot^2 + m g l sin(theta)", False, "wrong trig function"),
    ("pendulum", "lagrangian", PEND_L, "1/2 m l thetadot^2 + m g l cos(theta)", False, "wrong: l instead of l^2 in T"),
    # double pendulum, general
    (
        "double_pendulum",
        "lagrangian",
        DP_L,
        "1/2 (m1+m2) l1^2 θ̇₁² + 1/2 m2 l2^2 θ̇₂² + m2 l1 l2 θ̇₁ θ̇₂ (cos θ₁ cos θ₂ + sin θ₁ sin θ₂)"
        " + (m1+m2) g l1 cos θ₁ + m2 g l2 cos θ₂",
        True,
        "cos(θ1-θ2) expanded",
    ),
    (
        "double_pendulum",
        "lagrangian",
        DP_L,
        DP_T + " - (m1 + m2) g l1 (1 - cos(theta1)) - m2 g l2 (1 - cos(theta2))",
        True,
        "V measured from the lowest position",
    ),
    (
        "double_pendulum",
        "lagrangian",
        DP_L,
        "1/2 m1 l1^2 theta1dot^2 + 1/2 m2 ((l1 theta1dot cos(theta1) + l2 theta2dot cos(theta2))^2"
        " + (l1 theta1dot sin(theta1) + l2 theta2dot sin(theta2))^2) + m1 g l1 cos(theta1)"
        " + m2 g (l1 cos(theta1) + l2 cos(theta2))",
        True,
        "Cartesian form",
    ),
    (
        "double_pendulum",
        "lagrangian",
        DP_L,
        DP_L + " + m2 l1 l2 (theta1dot - theta2dot) cos(theta1 - theta2)",
        True,
        "total derivative d/dt(m2 l1 l2 sin(θ1-θ2))",
    ),
    (
        "double_pendulum",
        "lagrangian",
        DP_L,
        r"\frac{1}{2}(m_1+m_2)l_1^2\dot\theta_1^2 + \frac{1}{2}m_2 l_2^2\dot\theta_2^2"
        r" + m_2 l_1 l_2\dot\theta_1\dot\theta_2\cos(\theta_2-\theta_1) + (m_1+m_2)gl_1\cos\theta_1"
        r" + m_2 g l_2\cos\theta_2",
        True,
        "LaTeX",
    ),
    (
        "double_pendulum",
        "lagrangian",
        DP_L,
        DP_L + " + theta1dot theta2 + theta1 theta2dot",
        True,
        "total derivative d/dt(theta1 theta2)",
    ),
    (
        "double_pendulum",
        "lagrangian",
        DP_L,
        DP_T + " + m1 g l1 cos(theta1) + m2 g l2 cos(theta2)",
        False,
        "missing term: m2 g l1 cos θ1",
    ),
    (
        "double_pendulum",
        "lagrangian",
        DP_L,
        "(m1 + m2) l1^2 theta1dot^2 + m2 l2^2 theta2dot^2 + 2 m2 l1 l2 theta1dot theta2dot cos(theta1 - theta2)"
        " + 2 (m1 + m2) g l1 cos(theta1) + 2 m2 g l2 cos(theta2)",
        False,
        "factor: 2L",
    ),
    (
        "double_pendulum",
        "lagrangian",
        DP_L,
        DP_T + " - (m1 + m2) g l1 cos(theta1) - m2 g l2 cos(theta2)",
        False,
        "T+V instead of T-V",
    ),
    (
        "double_pendulum",
        "lagrangian",
        DP_L,
        "1/2 (m1 + m2) l1^2 theta1dot^2 + 1/2 m2 l2^2 theta2dot^2 + m2 l1 l2 theta1dot theta2dot cos(theta1 + theta2)"
        " + (m1 + m2) g l1 cos(theta1) + m2 g l2 cos(theta2)",
        False,
        "wrong: cos(θ1+θ2) in the cross term",
    ),
    (
        "double_pendulum",
        "lagrangian",
        DP_L,
        "1/2 (m1 + m2) l1^2 theta1dot^2 + 1/2 m2 l2^2 theta2dot^2 + (m1 + m2) g l1 cos(theta1) + m2 g l2 cos(theta2)",
        False,
        "missing term: cross term",
    ),
    (
        "double_pendulum",
        "lagrangian",
        DP_L,
        "1/2 (m1 + m2) l1^2 θ̇₁² + 1/2 m2 l2^2 θ̇₂² + m2 l1 l2 θ̇₁ θ̇₂ − 1/2 (m1 + m2) g l1 θ₁² − 1/2 m2 g l2 θ₂²",
        False,
        "small angle",
    ),
    # double pendulum, equal masses, α and β
    (
        "double_pendulum_equal",
        "lagrangian",
        EQ_L,
        "1/2 m l^2 (2 α̇² + β̇² + 2 α̇ β̇ cos(α − β)) + m g l (2 cos α + cos β)",
        True,
        "in factored form",
    ),
    (
        "double_pendulum_equal",
        "lagrangian",
        EQ_L,
        EQ_L + " + alphadot beta + alpha betadot",
        True,
        "total derivative d/dt(alpha beta)",
    ),
    (
        "double_pendulum_equal",
        "lagrangian",
        EQ_L,
        r"ml^2\dot\alpha^2 + \frac12 ml^2\dot\beta^2 + ml^2\dot\alpha\dot\beta\cos(\beta-\alpha)"
        r" - mgl(3 - 2\cos\alpha - \cos\beta)",
        True,
        "LaTeX, V from the lowest position",
    ),
    (
        "double_pendulum_equal",
        "lagrangian",
        EQ_L,
        "m l² α'² + 1/2 m l² β'² + m l² α' β' cos(β − α) + 2 m g l cos α + m g l cos β − 3 m g l",
        True,
        "primes, constant added",
    ),
    (
        "double_pendulum_equal",
        "lagrangian",
        EQ_L,
        EQ_L + " + alphadot beta",
        False,
        "extra term: alphadot beta alone is not a total derivative",
    ),
    (
        "double_pendulum_equal",
        "lagrangian",
        EQ_L,
        "1/2 m l^2 (alphadot^2 + betadot^2 + 2 alphadot betadot cos(alpha - beta)) + 2 m g l cos(alpha) + m g l cos(beta)",
        False,
        "wrong: coefficient of alphadot^2",
    ),
    (
        "double_pendulum_equal",
        "lagrangian",
        EQ_L,
        "alphadot^2 + 1/2 betadot^2 + alphadot betadot cos(alpha - beta) + 2 g/l cos(alpha) + g/l cos(beta)",
        False,
        "factor: L/(m l^2)",
    ),
    (
        "double_pendulum_equal",
        "lagrangian",
        EQ_L,
        EQ_T + " + m g l cos(alpha) + m g l cos(beta)",
        False,
        "missing term: m g l cos α of the lower bob",
    ),
    (
        "double_pendulum_equal",
        "lagrangian",
        EQ_L,
        "m l^2 alphadot^2 + 1/2 m l^2 betadot^2 + m l^2 alphadot betadot sin(alpha - beta)"
        " + 2 m g l cos(alpha) + m g l cos(beta)",
        False,
        "wrong trig function in the cross term",
    ),
    # spherical pendulum
    (
        "spherical_pendulum",
        "lagrangian",
        SPH_L,
        r"\frac12 m l^2\dot\theta^2 + \frac12 m l^2\sin^2\theta\,\dot\phi^2 + mgl\cos\theta",
        True,
        "LaTeX",
    ),
    (
        "spherical_pendulum",
        "lagrangian",
        SPH_L,
        "1/2 m l^2 (θ̇² + (1 − cos²θ) φ̇²) + m g l cos θ − m g l",
        True,
        "sin² = 1 - cos², constant added",
    ),
    ("spherical_pendulum", "lagrangian", SPH_L, SPH_L + " + m l^2 phidot", True, "total derivative d/dt(m l^2 phi)"),
    (
        "spherical_pendulum",
        "lagrangian",
        SPH_L,
        SPH_L + " + m l^2 sqrt(g/l) thetadot cos(theta)",
        True,
        "total derivative d/dt(m l^2 sqrt(g/l) sin θ)",
    ),
    (
        "spherical_pendulum",
        "lagrangian",
        SPH_L,
        "1/2 m ((l cos θ cos φ θ̇ − l sin θ sin φ φ̇)² + (l cos θ sin φ θ̇ + l sin θ cos φ φ̇)² + (l sin θ θ̇)²)"
        " + m g l cos θ",
        True,
        "Cartesian velocities",
    ),
    (
        "spherical_pendulum",
        "lagrangian",
        SPH_L,
        SPH_L + " + m l^2 thetadot phidot",
        False,
        "extra term: thetadot phidot is not a total derivative",
    ),
    (
        "spherical_pendulum",
        "lagrangian",
        SPH_L,
        "1/2 m l^2 (thetadot^2 + sin(theta)^2 phidot^2) - m g l cos(theta)",
        False,
        "T+V instead of T-V",
    ),
    (
        "spherical_pendulum",
        "lagrangian",
        SPH_L,
        "1/2 m l^2 (thetadot^2 + phidot^2) + m g l cos(theta)",
        False,
        "wrong: missing sin^2 θ on phidot^2",
    ),
    (
        "spherical_pendulum",
        "lagrangian",
        SPH_L,
        "1/2 m l^2 (θ̇² + cos²θ φ̇²) + m g l cos θ",
        False,
        "wrong trig function (θ taken from the horizontal in T only)",
    ),
    (
        "spherical_pendulum",
        "lagrangian",
        SPH_L,
        "m l^2 (theta'^2 + sin^2 theta phi'^2) + 2 m g l cos theta",
        False,
        "factor: 2L",
    ),
    # Atwood machine
    (
        "atwood",
        "lagrangian",
        ATW_L,
        "1/2 m1 ẋ² + 1/2 m2 ẋ² + m1 g x + m2 g (l − x)",
        True,
        "V = -m1 g x - m2 g (l - x) with the rope length",
    ),
    ("atwood", "lagrangian", ATW_L, ATW_L + " + m1 g (x + t xdot)", True, "total derivative d/dt(m1 g t x)"),
    ("atwood", "lagrangian", ATW_L, "1/2 (m₁ + m₂) ẋ² + m₁ g x − m₂ g x", True, "expanded, Unicode"),
    ("atwood", "lagrangian", ATW_L, "(m1 + m2) x'^2/2 - (m2 - m1) g x + m2 g l", True, "rearranged, constant added"),
    (
        "atwood",
        "lagrangian",
        ATW_L,
        ATW_L + " + m1 g t xdot",
        False,
        "extra term: m1 g t xdot alone is not a total derivative",
    ),
    ("atwood", "lagrangian", ATW_L, "1/2 (m1 + m2) xdot^2 + (m1 + m2) g x", False, "sign of the m2 term"),
    ("atwood", "lagrangian", ATW_L, "1/2 (m1 - m2) x'^2 + (m1 - m2) g x", False, "wrong: (m1 - m2) in T"),
    ("atwood", "lagrangian", ATW_L, "1/2 (m₁ + m₂) ẋ² − (m₁ − m₂) g x", False, "T+V instead of T-V"),
    ("atwood", "lagrangian", ATW_L, "(m1 + m2) xdot^2 + 2 (m1 - m2) g x", False, "factor: 2L"),
    # bead on a rotating hoop
    ("rotating_hoop", "lagrangian", HOOP_L, "1/2 m R^2 θ̇² + 1/2 m R^2 ω² sin²θ + m g R cos θ", True, "expanded"),
    (
        "rotating_hoop",
        "lagrangian",
        HOOP_L,
        "1/2 m R^2 (thetadot^2 - omega^2 cos(theta)^2) + m g R cos(theta)",
        True,
        "-cos² = sin² - 1: differs by a constant",
    ),
    (
        "rotating_hoop",
        "lagrangian",
        HOOP_L,
        r"\frac{1}{2}mR^2\left(\dot\theta^2+\omega^2\sin^2\theta\right)+mgR\cos\theta",
        True,
        "LaTeX",
    ),
    (
        "rotating_hoop",
        "lagrangian",
        HOOP_L,
        "1/2 m R^2 θ̇² + 1/4 m R^2 ω² (1 − cos 2θ) + m g R cos θ",
        True,
        "double angle",
    ),
    (
        "rotating_hoop",
        "lagrangian",
        HOOP_L,
        "1/2 m ((R cos(theta) thetadot cos(omega t) - R omega sin(theta) sin(omega t))^2"
        " + (R cos(theta) thetadot sin(omega t) + R omega sin(theta) cos(omega t))^2 + (R sin(theta) thetadot)^2)"
        " + m g R cos(theta)",
        True,
        "Cartesian velocities in the lab frame, explicit t",
    ),
    (
        "rotating_hoop",
        "lagrangian",
        HOOP_L,
        HOOP_L + " + m R^2 omega thetadot",
        True,
        "total derivative d/dt(m R^2 omega theta)",
    ),
    (
        "rotating_hoop",
        "lagrangian",
        HOOP_L,
        HOOP_L + " + m R^2 omega^2 (sin(theta) + t cos(theta) thetadot)",
        True,
        "total derivative d/dt(m R^2 omega^2 t sin θ), explicit t",
    ),
    (
        "rotating_hoop",
        "lagrangian",
        HOOP_L,
        "1/2 m R^2 thetadot^2 - 1/2 m R^2 omega^2 sin(theta)^2 + m g R cos(theta)",
        False,
        "sign of the omega^2 term",
    ),
    (
        "rotating_hoop",
        "lagrangian",
        HOOP_L,
        "1/2 m R^2 (θ̇² + ω² cos²θ) + m g R cos θ",
        False,
        "wrong trig function in the omega^2 term",
    ),
    (
        "rotating_hoop",
        "lagrangian",
        HOOP_L,
        "1/2 m R^2 (θ̇ + ω)² + m g R cos θ",
        False,
        "wrong: omega added to thetadot (rotation about the hoop's axis)",
    ),
    (
        "rotating_hoop",
        "lagrangian",
        HOOP_L,
        "1/2 m R^2 thetadot^2 + m g R cos(theta)",
        False,
        "missing term: omega^2 term (non-rotating hoop)",
    ),
    (
        "rotating_hoop",
        "lagrangian",
        HOOP_L,
        "1/2 m R^2 (thetadot^2 + omega^2 sin(theta)^2) - m g R cos(theta)",
        False,
        "T+V instead of T-V",
    ),
    ("rotating_hoop", "lagrangian", HOOP_L, "m R^2 (θ̇² + ω² sin²θ) + 2 m g R cos θ", False, "factor: 2L"),
    # incline
    ("incline", "lagrangian", INC_L, r"\frac{1}{2}m\dot{x}^2 + mg\sin\alpha_0\, x", True, "LaTeX"),
    (
        "incline",
        "lagrangian",
        INC_L,
        "1/2 m ẋ² − m g t ẋ sin α₀",
        True,
        "differs by the total derivative d/dt(m g t x sin α0)",
    ),
    (
        "incline",
        "lagrangian",
        INC_L,
        "1/2 m ((xdot cos(alpha0))^2 + (xdot sin(alpha0))^2) + m g x sin(alpha0)",
        True,
        "Cartesian velocity",
    ),
    ("incline", "lagrangian", INC_L, "1/2 m ẋ² − m g (−x sin α₀) + 7", True, "constant added, Unicode"),
    (
        "incline",
        "lagrangian",
        INC_L,
        "1/2 m xdot^2 + m g t xdot sin(alpha0)",
        False,
        "sign: +m g t xdot sin α0 reverses the force",
    ),
    ("incline", "lagrangian", INC_L, "1/2 m xdot^2 + m g x cos(alpha0)", False, "wrong trig function"),
    ("incline", "lagrangian", INC_L, "1/2 m x'^2 - m g x sin(alpha0)", False, "T+V instead of T-V"),
    ("incline", "lagrangian", INC_L, "m xdot^2 + 2 m g x sin(alpha0)", False, "factor: 2L"),
    # damped oscillator (the Lagrangian is L = T - V; dissipation goes into F)
    (
        "damped_oscillator",
        "lagrangian",
        DHO_L,
        r"\frac{1}{2}m\dot x^2 - \frac{1}{2}kx^2 + b x\dot x",
        True,
        "b x xdot is the total derivative d/dt(b x^2/2): it adds no damping",
    ),
    ("damped_oscillator", "lagrangian", DHO_L, r"\frac{m\dot x^2}{2} - \frac{k x^2}{2}", True, "LaTeX"),
    (
        "damped_oscillator",
        "lagrangian",
        DHO_L,
        "1/2 m xdot^2 + 1/2 k x^2 + 2 k t x xdot",
        True,
        "looks like T+V but differs from L by the total derivative d/dt(k t x^2)",
    ),
    (
        "damped_oscillator",
        "lagrangian",
        DHO_L,
        "1/2 m ẋ² − 1/2 k x² − 1/2 b ẋ²",
        False,
        "extra term: Rayleigh function put into L",
    ),
    (
        "damped_oscillator",
        "lagrangian",
        DHO_L,
        "exp(b t/m) (1/2 m xdot^2 - 1/2 k x^2)",
        False,
        "wrong: time-dependent factor exp(bt/m) changes the equation of motion",
    ),
    ("damped_oscillator", "lagrangian", DHO_L, "1/2 m xdot^2 + 1/2 k x^2", False, "T+V instead of T-V"),
    ("damped_oscillator", "lagrangian", DHO_L, "m x'^2 - k x^2", False, "factor: 2L"),
    ("damped_oscillator", "lagrangian", DHO_L, "1/2 m xdot^2 - k x^2", False, "wrong: missing 1/2 on the potential"),
]

PAIRS = EXPRESSION_PAIRS + EQUATION_PAIRS + EQUATIONS_PAIRS + LAGRANGIAN_PAIRS
