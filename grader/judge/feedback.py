"""Every sentence the checker says to a student, in one place.

Contents:
    FEEDBACK         diagnosis key → sentence template
    say(key, **kw)   the sentence, filled in
    shown(text)      a student's words as a sentence repeats them, cut short past SHOWN characters

The sentences name the kind of mistake, never the expected answer itself.
"""

from __future__ import annotations

__all__ = ["FEEDBACK", "SHOWN", "say", "shown"]

FEEDBACK: dict[str, str] = {
    "equivalent": "Correct.",
    "equivalent_up_to_constant": "Correct: it differs from the expected answer only by a constant, which is allowed here.",
    "lagrangian_gauge": "Correct: your Lagrangian gives the same equations of motion.",
    "sign": "The overall sign is wrong.",
    "factor": "Your answer is off by a constant factor: missing a factor {factor}?",
    "normalization": "Your Lagrangian gives the right equations of motion, but it is {factor} × (T − V); the convention L = T − V fixes the normalization.",
    "normalization_scaled": "Your Lagrangian gives the right equations of motion, but it is a constant multiple of T − V; the convention L = T − V fixes the normalization.",
    "v_minus_t": "Your Lagrangian has the opposite sign: it is V − T; the Lagrangian is L = T − V.",
    "lagrangian_accelerations": "Your Lagrangian has {names} in it, but a Lagrangian is a function of the"
    " coordinates, the velocities and the time alone.",
    "t_plus_v": "It looks like you wrote L = T + V; the Lagrangian is L = T − V.",
    "missing_term": "A term is missing: {description}.",
    "extra_term": "There is a term too many: {description}.",
    "term_differs": "A term differs: {description}.",
    "missing_term_in": "In your equation {index}, a term is missing: {description}.",
    "extra_term_in": "In your equation {index}, there is a term too many: {description}.",
    "term_differs_in": "In your equation {index}, a term differs: {description}.",
    "units_differ": "Your answer is measured in {theirs}, but the quantity asked for is measured in {wanted}:"
    " check the dimensions of each factor.",
    "units_mixed": "The terms of your {where} are not all measured in the same units ({units}):"
    " terms that add up must have the same dimensions.",
    "units_argument": "In your {where}, `{function}` is applied to a quantity measured in {units}:"
    " the argument of {function} must be a pure number.",
    "decimal_comma": "Read `{typed}` as {number}: a decimal comma.",
    "decimal_commas": "Read {typed} as {numbers}: decimal commas.",
    "other_unit": "Not within the accepted tolerance. Is your number in {unit}? The answer is asked in {wanted}.",
    "unit_read": "Read as {value} {unit}.",
    "unit_read_cycles": "Read as {value} {unit}: a cycle is 2π rad, so 1 Hz is 2π rad/s (ω = 2πf).",
    "words_left_out": "Read without the words after it, `{words}`: the formula is what is graded.",
    "constant_terms_left_out": "{names} {appear} only in {terms} with no coordinate or velocity: a constant, which"
    " {which}. It was left out.",
    "constant_unsure": "{names} {appear} only in {terms} with no coordinate or velocity, and this problem does not"
    " define {them}. Your answer was judged with {them} as a constant; if {names} {changes} with the motion, write"
    " {them} in the problem's coordinates. A person will check this answer.",
    "motion_left_out": "The equation{s} of motion after your Lagrangian {were} not graded: the Lagrangian is what is"
    " asked for here.",
    "working_left_out": "The {lines} {names} {were} read as your working, not as your answer.",
    "lines_as_chain": "Your {count} lines, each `{label} = …`, were read as one chain, {label} = … = …: its last"
    " side was graded.",
    "lines_as_one_chain": "Your {count} lines, each `{label} = …`, were read as one chain, {label} = … = …, as if"
    " written on one line.",
    "small_form_left_out": "Graded your formula before `{words}`; the small-angle form after it was not graded.",
    "full_form_left_out": "Graded your formula after `{words}`; the full form before it was not graded.",
    "forms_for_a_person": "Your formula after `{words}` is not the small-angle form of the one before it, as your"
    " words say: a person will decide which is your answer.",
    "forms_both_wrong": "Neither your formula before `{words}` nor the one after it is right.",
    "steps_left_out": "Read without the step{s} `{steps}`: a derivative written out is not checked; the last side"
    " was graded.",
    "step_for_a_person": "Its last side is right; a person will check the step that defines it.",
    "values_left_out": "Read without the {values} you gave {names}: the formula is what is graded.",
    "definition_left_out": "The line `{line}` states what the name means; the line that gives its value was graded.",
    "others_left_out": "The {lines} {names} {were} not graded: {name} is what is asked for here.",
    "others_for_a_person": "The {lines} {names} {were} not graded: {name} is what is asked for here. But your"
    " answer gives {multiples} as a number times {name}, which may be your answer instead. Graded on your line"
    " for {name}, it is right; a person will check which you meant.",
    "words_read_past": "Read without the words `{words}`: the formula is what is graded.",
    "sign_words_for_a_person": "Your formula has the opposite sign, and your answer says `{words}` beside it: a"
    " person will read whether the words turn the sign.",
    "words_for_a_person": "Your answer says `{words}` beside the formula. The formula was graded on its own;"
    " a person will read the words against it.",
    "words_before_left_out": "Read without the words before it, `{words}`: the formula is what is graded.",
    "definition_before": "Read without the words `{words}`, with your `{definition}` put in place in the formula"
    " after it.",
    "definition_unused": "Read without the words `{words}`: your `{definition}` is not used in the formula after"
    " it, which was graded as it stands.",
    "definition_in_words": "Read without the words `{words}`, as the chain `{chain}`: its last side was graded.",
    "unit_for_a_person": "Your formula is labelled `{unit}`. Graded without its unit, it is right; but a"
    " frequency in Hz counts cycles and an angular frequency in rad/s radians, 2π apart (ω = 2πf). A person"
    " will check which you meant.",
    "label_for_a_person": "Your answer is labelled {label}, but the quantity asked for is {name}. Read as {name},"
    " it is right; a person will check which you meant.",
    "constant_said_for_a_person": "Your answer ends `{said}`, which says the quantity is constant: that is not"
    " asked here. Its formula was graded and is right; a person will check this answer.",
    "constant_said": "Read without `{said}`, which says the quantity is constant: its formula was graded.",
    "label_other": "Your answer is labelled {label}, but the quantity asked for is {name}.",
    "statement_for_a_person": "Your answer says `{statement}` on the way to its value, which is not what {label}"
    " is. Its value was graded and is right; a person will check this answer.",
    "statement_wrong": "Your answer says `{statement}` on the way to its value, which is not what {label} is.",
    "given_redefined_for_a_person": "Your answer defines `{definition}`, which is not the problem's {name}. Read"
    " with your definition put in place, it is right; a person will check this answer.",
    "given_redefined": "Your answer defines `{definition}`, which is not the problem's {name}.",
    "momentum_spelt_for_a_person": "Your answer defines `{definition}`, which is not the problem's {name}, then"
    " uses {name} itself. Read with the problem's {name}, it is right; a person will check which you meant.",
    "momentum_spelt": "Your answer defines `{definition}`, which is not the problem's {name}, then uses {name} itself.",
    "operator_for_a_person": "Your answer says `{statement}` on the way to its equation, which is not Lagrange's"
    " equation. The equation was graded and is right; a person will check this answer.",
    "dimensions_left_out": "Read without its dimensions, `{dimensions}`: the formula is what is graded.",
    "unit_left_out": "Read without its unit, `{unit}`: the formula is what is graded.",
    "final_value": "Graded your final value, `{value}`; the working before it is not graded.",
    "working_false_for_a_person": "Your final value, `{value}`, was graded and is right, but your working,"
    " `{working}`, does not hold: a person will check this answer.",
    "energies_disagree_for_a_person": "Your working gives {kinetic} and {potential}, but {sum} with them is not"
    " the value your answer gives {label}. Its value was graded and is right; a person will check this answer.",
    "energies_disagree": "Your working gives {kinetic} and {potential}, but {sum} with them is not the value your"
    " answer gives {label}.",
    "kinetic_moves_for_a_person": "Your working gives {kinetic}, but {difference} with the value your answer gives {label}"
    " depends on the velocities{how}, which a potential energy V does not: so {label} = {sum} cannot hold. Its value"
    " was graded and is right; a person will check this answer.",
    "kinetic_moves": "Your working gives {kinetic}, but {difference} with the value your answer gives {label} depends on the"
    " velocities{how}, which a potential energy V does not: so {label} = {sum} cannot hold.",
    "potential_moves_for_a_person": "Your working gives {potential}, which depends on the velocities{how}: a"
    " potential energy does not. Its value was graded and is right; a person will check this answer.",
    "potential_moves": "Your working gives {potential}, which depends on the velocities{how}: a potential energy"
    " does not.",
    "lagrangian_disagrees_for_a_person": "Your working gives {label}, but Lagrange's {equations} with {it} {does}"
    " not give the {equations} of motion your answer gives. Your {equations} {were} graded and {are} right; a"
    " person will check this answer.",
    "lagrangian_disagrees": "Your working gives {label}, but Lagrange's {equations} with {it} {does} not give a"
    " right {equations} of motion either.",
    "lagrangian_unchecked_for_a_person": "Your working gives {label}, but your {equations} could not be checked"
    " against Lagrange's {equations} with {it}. Your {equations} {were} graded and {are} right; a person will"
    " check this answer.",
    "lagrangian_unchecked": "Your working gives {label}, but your {equations} could not be checked against"
    " Lagrange's {equations} with {it}.",
    "derived_disagrees_for_a_person": "Your working gives {label}, but {quantity} with it is not the value your answer"
    " gives. Its value was graded and is right; a person will check this answer.",
    "derived_disagrees": "Your working gives {label}, but {quantity} with it is not right either.",
    "premise_for_a_person": "Your answer says `{statement}` before the equation it gives, as what that equation"
    " follows from, but the two do not agree. The equation was graded and is right; a person will check this"
    " answer.",
    "premise_value_for_a_person": "Your answer says `{statement}` before the value it gives, as what that value"
    " follows from, but the two do not agree. Its value was graded and is right; a person will check this answer.",
    "premise_undefined_for_a_person": "Your answer says `{statement}` before the {thing} it gives, as what it follows"
    " from, but that has no value: it divides by zero, or is otherwise undefined. {graded}; a person will"
    " check this answer.",
    "working_false": "Graded your final value, `{value}`; your working, `{working}`, does not hold.",
    "own_values": "Your working holds with the {values} you gave {names}, not with the {ones} the problem gives.",
    "remark_ignored": "Graded the number `{value}`; what follows it (`{rest}`) is not graded.",
    "number_in_sentence": "Graded the number `{value}`; the words around it are not graded.",
    "uncertainty_left_out": "Read without its uncertainty, `{error}`: the value is what is graded.",
    "statements_left_out": "Graded `{graded}`, your value in {unit}; the rest of your answer (`{others}`) is not"
    " graded.",
    "number_read": "Graded the number `{value}`; the rest of your answer is not graded.",
    "number_word": "Read `{typed}` as {number}.",
    "counts_differ_for_a_person": "Your answer gives two counts of the same thing, {first} and then {value}: a"
    " person will decide which number is your answer.",
    "count_bracket_for_a_person": "Your count `{value}` is followed by `{rest}`, which does not come to {value}:"
    " a person will decide which number is your answer.",
    "number_doubted_for_a_person": "Your answer says `{words}`, which may take back or doubt a number of it: a"
    " person will decide which number is your answer.",
    "number_qualified_for_a_person": "Your number `{value}` comes with `{words}`, which may make it another number,"
    " or no one number: a person will decide what your answer is.",
    "unit_unknown_for_a_person": "Your number `{value}` comes with `{unit}`, which may be a unit the checker does"
    " not know, and make it another number: a person will check your answer.",
    "count_or_product_for_a_person": "Your answer `{typed}` may be a count with its working in brackets, or the"
    " product of the two, and these are different numbers: a person will check which you meant.",
    "unit_differs": "Your answer is in {theirs}, but the quantity asked for is measured in {wanted}.",
    "formula_unit_differs": "Your answer is in {theirs}, which is not how the quantity asked for is measured:"
    " check its dimensions.",
    "units_power": "In your {where}, a quantity measured in {units} stands where only a pure number can:"
    " in an exponent, or raised to a power that is not a number.",
    "constant_offset": "Your answer is right but for an added constant, which is not allowed here: does the"
    " problem fix a zero, of potential energy say, that your answer does not use?",
    "constant_offset_kinetic": "Your answer is right but for an added constant: a kinetic energy has none, it is"
    " zero when nothing moves.",
    "small_angle": "You used the small-angle approximation, but the full answer is asked for here.",
    "small_angle_in": "In your equation {index}, you used the small-angle approximation, but the full answer is"
    " asked for here.",
    # "kinetic" and "potential" energy would be wrong words where T has a part without velocities (a hoop
    # turned at a fixed rate): the terms are told by what they hold
    "potential_wrong": "The terms of your Lagrangian with velocities are right, but not the terms without{factor}.",
    "potential_missing": "The terms of your Lagrangian with velocities are right, but there are none without: where"
    " is the potential energy?",
    "potential_small_angle": "The terms of your Lagrangian with velocities are right, but the terms without are in"
    " their small-angle form, and the full form is asked for here.",
    "kinetic_wrong": "The terms of your Lagrangian without velocities are right, but not the terms with them.",
    "square_sign_open": "Your answer gives `{label}`: {power} leaves the sign open, and the quantity asked for"
    " may be negative. A person will check which root you meant.",
    "some_signs": "Your answer is right only for some signs of {names}, which may be negative here:"
    " remember that √(x²) is |x|, not x.",
    "not_small_angle": "The small-angle (linearized) form is asked for here; your answer keeps the full trigonometric functions.",
    "undefined_symbol": "Your answer uses {names}, which this problem does not define (it uses {defined})."
    " Write your answer in those, or say what {which} stands for: …, where {first} = ….",
    "undefined_unit_letter": "Your answer ends in `{name}`, which this problem does not define. If it is a unit,"
    " leave it out, or write it in square brackets after the formula: … [{name}]. If it is a name of your own,"
    " say what it stands for: …, where {name} = ….",
    "undefined_units": "Your answer uses {names}, which this problem does not define: units, it seems."
    " A formula in the problem's own symbols is asked for here, and its units follow from theirs.",
    "expected_equation": "An equation (with `=`) is asked for here, but your answer is an expression.",
    "quantity_for_motion": "Your answer gives {quantity}, `{name} = …`, where {asked} asked for: write {itself}.",
    "lines_agree": "Your answer has {count} {parts}, each the same; the last was graded.",
    "last_line_graded": "Your answer has {count} {parts}; the last was graded as your answer.",
    "last_line_right_earlier_not": "Your last {part} is right, but {lines} {do} not say the same: a person"
    " will decide which is your answer.",
    "expected_one_equation": "One equation is asked for here; your answer has {count}.",
    "eliminate_unknowns": "One equation is asked for here; your answer has {count}, with {names}, which this problem"
    " does not define. Eliminate {them} between your equations, to leave one in the problem's own names.",
    "expected_expression": "An expression is asked for here, but your answer is an equation.",
    "dashes_ambiguous": "Each line of your answer starts with `- `. Read as minus signs, your answer is not right;"
    " read as a list's bullets, it is. Which is meant? Write a minus sign against its term (−2 l θ̈), or leave"
    " the bullets out.",
    "energies_without_lagrangian": "Your answer gives T and {potential} but no Lagrangian: the answer asked for is"
    " L = T − {potential}, written out. Check your energies too: T − {potential} from yours is not right.",
    "energies_without_lagrangian_right": "Your answer gives T and {potential} but no Lagrangian: the answer asked"
    " for is L = T − {potential}, written out. T − {potential} from yours would be right.",
    "loose_definitions": "The first item of your answer has no `=`. An expression may be followed only by"
    " definitions of the names it uses (…, where v = l θ̇); in a list of equations, every item needs an `=`.",
    "expected_system": "A system of {count} equations is asked for here (one per coordinate: {coords}).",
    "missing_equation": "The equation for {coords} is missing.",
    "extra_equation": "You gave {given} equations; this system needs exactly {count}, one per coordinate.",
    "wrong_equation": "Your equation for {coords} is not right; {right}.",
    "wrong_equations": "Your equations do not determine the right accelerations for {coords}.",
    "dependent_equations": "Your equations are not independent: they do not determine every acceleration.",
    "given_read": "Read with the problem's own meaning of {names}.",
    "p_read_as_momentum": (
        "Read `p` as `{momentum}`, with the problem's own meaning: the problem has one coordinate,"
        " so p is its momentum."
    ),
    "conserved_read": "`… = const` was read as a conserved quantity: what was compared is its time derivative,"
    " d/dt (…) = 0.",
    "vanishing_factor": "Your equation is right only where a factor of it is not zero: at rest, or where a"
    " coordinate is 0, it no longer says what the acceleration is. Divide that factor out.",
    "conserved_not_motion": "`… = const` was read as a conserved quantity, and that is not an equation of motion:"
    " its time derivative is the equation of motion times a velocity, which says nothing at rest. Differentiate it"
    " and divide by that velocity.",
    "vanishing_factor_between": "Your equation is right only where a factor of it is not zero: where that factor is"
    " zero, it no longer says what the acceleration is. Divide that factor out.",
    "vanishing_factor_system_between": "One of your equations is right only where a factor of it is not zero: where"
    " that factor is zero, your equations no longer determine every acceleration. Divide that factor out.",
    "vanishing_factor_system": "One of your equations is right only where a factor of it is not zero: at rest,"
    " or where a coordinate is 0, your equations no longer determine every acceleration. Divide that factor out.",
    "trivial_equation": "Equation {index} holds for every motion, so it says nothing about this one.",
    "equation_without_acceleration": "Equation {index} has no acceleration ({accelerations}) in it, so it is no"
    " equation of motion.",
    "trivial_extra_equation": "Equation {index} holds for every motion, so it says nothing about this one: leave"
    " it out. This system needs exactly {count} equations, one per coordinate.",
    "not_equation_of_motion": "This should be an equation of motion, with the accelerations ({accelerations}) in it.",
    "not_linear": "Your equation is not linear in the accelerations ({accelerations}), as every equation of motion"
    " from Lagrange's equations is: is an acceleration squared, or inside a function?",
    "not_linear_in": "Your equation {index} is not linear in the accelerations, as every equation of motion from"
    " Lagrange's equations is.",
    "wrong_equation_single": "This equation does not say the same as the expected one.",
    "root_multiplicity": (
        "Your equation holds for the same values, but not each as often: a repeated root,"
        " as in (x − a)² = 0, says more than x = a."
    ),
    "wrong": "Not equivalent to the expected answer.",
    "factor_depends": "Your answer depends on {others} as the right answer does, but not on {names}: check how"
    " your answer depends on {names}.",
    "factor_depends_extra": "Your answer depends on {others} as the right answer does, but the right answer does"
    " not depend on {names}.",
    "factor_depends_instead": "Your answer depends on {others} as the right answer does, and on {names} where the"
    " right answer depends on {instead}.",
    "factor_depends_all": "Your answer depends on {names}, but not as the right answer does: check how it"
    " depends on each.",
    "factor_lacks": "Your answer does not depend on {names}, and the right answer does.",
    "factor_extra": "The right answer does not depend on {names}.",
    "rounded_decimal": "Your answer would be right with {decimals} written exactly: it is a rounded decimal where"
    " an exact number belongs (a fraction, or one with π or a root).",
    "rounded_decimals": "Your answer would be right with {decimals} written exactly: they are rounded decimals"
    " where exact numbers belong (fractions, or ones with π or roots).",
    "number_for_formula": "A formula in the problem's symbols is asked for here; your answer is a number.",
    "factor_depends_how": "Your answer depends on {others} as the right answer does, but on {names} in another way:"
    " check how your answer depends on {names}.",
    "undecided": "This answer could not be checked automatically; it has been set aside for a person to grade.",
    "not_a_number": "A number is asked for here; your answer contains {names}.",
    "number_hedged": "One number is asked for here, and your answer offers a choice (`or`): give the one you mean.",
    "not_an_integer": "A whole number is asked for here.",
    "out_of_tolerance": "Not within the accepted tolerance.",
    "choice_unknown": "{labels} is not one of the options ({options}).",
    "choice_count": "Choose {count}.",
    "choice_wrong": "Not the right choice.",
    "choice_conflict": "Your label {label} and your words `{words}` name different options: give one of them.",
    "choice_read": "Read as the option you wrote out: {labels}.",
    "choice_read_remark": "Read as the option you wrote out: {labels}; what follows it (`{rest}`) is not graded.",
    "choice_read_beside": "Read as the option you wrote out: {labels}; the words beside it (`{rest}`) are not graded.",
    "choice_remark": "Graded your choice, {labels}; what follows it (`{rest}`) is not graded.",
    "choice_scribbled": "Your answer {typed} names an option, then a formula that says nothing of it: is the formula"
    " your choice? Give the option's label alone, or words after it that say why.",
    "choice_hedged": "One option is asked for here, and your answer {typed} offers another, or doubts or denies the"
    " one it names: give the one you mean.",
    "choices_hedged": "Your answer {typed} offers another option, or doubts or denies one it names: give just the"
    " options you mean.",
    "text_review": "A person will read this answer; the rubric found {found} of its {total} ideas.",
    "text_review_discounted": "A person will read this answer; the rubric found {found} of its {total} ideas. It did"
    " not count {discounted} more that your answer negates, doubts or says of something else.",
    "mistake": "{feedback}",
}


def say(key: str, **details) -> str:
    """The sentence for ``key``, with ``details`` filled in."""
    return FEEDBACK[key].format(**details)


SHOWN = 60  # characters of a student's words repeated back to them


def shown(text: str) -> str:
    """``text`` as a sentence repeats it: cut short, with "…", where it is longer than :data:`SHOWN`."""
    return text if len(text) <= SHOWN else text[: SHOWN - 1] + "…"
