"""The ``text`` kind: a rubric proposes a score, and a person always confirms it.

Contents:
    check_text(expected, submitted, deadline)   the kind's checker
    RubricReading                               points proposed, ideas found, missed and discounted
    rubric_score(text, rubric)                  what the rubric makes of a text

Free text is never graded automatically: the verdict is always ``undecided`` (set
aside for a person), carrying the rubric's proposal so the grader starts from it.

How a phrasing is read: no grammar, only rules a person can check by eye, each in a sentence.
A proposal errs towards too little, which the person reviewing raises, never towards full
credit for a statement turned round.

* It is found as a substring once case, spacing, apostrophes and contractions are made
  uniform ("doesn't" is "does not", "cannot" is "can not"). ``…`` in a phrasing stands for
  any words of one clause: ``not … explicitly`` is found in "does not contain t explicitly".
* It does not count where it is negated: a negation (not, no, never, none, nothing, neither,
  nor, without, ≠; pas, nicht, kein…) among the six words before it in its clause or in its
  ``…``, a "≠" just after it ("T + V ≠ H"), or a negating prefix on its first word (non-, un,
  in, im, ir: ``conserved`` in "non-conserved", ``dependent`` in "independent"). A negation
  among the phrasing's own words is its meaning.
* Nor where it is taken back: later in its sentence ("…, which is false", "— not true in
  general", "(wrong)", "but they are wrong"), by the next sentence ("That is not true.", "Not
  really.", "Nope.", "The opposite is true."), by a remark on all said before it ("None of this
  is true.", "Both statements are false.", "I am joking."), or by a denial before its "that"
  ("it is not true that …", "I do not think that …"), which a "that" joined to it shares ("…
  that A and that B").
* Nor where it is doubted: after maybe, perhaps, possibly, probably, "I guess" or what others
  say ("some say", "you might think", "a common mistake is to think") as a negation would stand,
  before "I'm not sure" or "I think" ending its sentence, in a question not answered yes ("…
  conserved? No."; a why or how question takes its statement for granted), offered with "or"
  beside a phrasing of the rival idea, no term named between ("time dependent or time
  independent"), or with "or" right beside another claim of its own shape, which turns it round
  or repeats one of its words ("conserved or not", "sin θ ≈ θ or sin θ ≈ 1"), unless the rubric
  credits that one too ("proportional to θ or to the angle").
* An idea with ``about`` terms counts only where it is said of one of them. It is said of the
  nearest term (of ``about`` or ``not_about``) named before it in its clause, else after it in
  its clause; else the same in its sentence; else of the last term named before it; else, with
  no term named yet, of the question's own subject, where the question has one: where a term the
  idea is not about is another idea's subject, of neither. A phrasing just before a term
  describes it ("a conserved momentum"). With "respectively", a list of terms pairs with its
  descriptions in order ("A and B are X and Y, respectively"), or where they are too few to
  follow, with neither.
* An ellipsis that ends a clause said of the idea's term ("… and scleronomic if it does not",
  "rheonomic ones do") stands for the last claim a rival idea counted in its sentence or the one
  before, read with "not" where it says not and without the claim's own "not" where it does not:
  "rheonomic if time appears explicitly, and scleronomic if it does not" finds ``not …
  explicitly`` for scleronomic.
* A term does not stand for itself when it is denied ("H is not equal to T + V when …"),
  negated by a prefix ("non-holonomic" for holonomic), inside a longer term, set against the
  subject ("unlike Newton's method"), listed with a rival ("Newton's and Lagrange's methods
  both …", "A and B constraints are …"), or after "of", "conjugate to" or "associated with"
  another term, whose owner it names ("the momentum conjugate to a cyclic coordinate q"). A
  one-letter term is a name of its own: ``q`` is named in "if q does not appear", not in
  "square" or "q̇".

Clauses end at . ; : , ! ? and at words that begin another (and, but, while, whereas, so,
then, since, because, if, when, which, that …), but not at "or": "does not use energies or
generalized coordinates" denies both. Sentences end at . ; ! ?. Inside brackets only a
sentence's end counts, so ``f(r, t) = 0`` is one piece.
"""

from __future__ import annotations

import bisect
import re
import unicodedata
from dataclasses import dataclass

from grader.judge.deadline import Deadline
from grader.judge.expected import Expected, Outcome

__all__ = ["MAX_TEXT_LENGTH", "RubricReading", "check_text", "rubric_score"]

MAX_TEXT_LENGTH = 5000
GAP = "..."  # "…" after NFKC: in a phrasing, any words of the same clause

# apostrophes a keyboard or a word processor may give "doesn't"
_APOSTROPHES = str.maketrans({"’": "'", "‘": "'", "ʼ": "'", "´": "'", "`": "'"})
# "not only" affirms: "it not only uses scalar energies but also…"; "≠" denies what it relates,
# so "t + v" in "H ≠ T + V" is negated, as in "H is not T + V"
_UNEQUAL = r"≠|!=|=/=|\\neq?\b"
# the negations of languages students mix in: "la force n'est pas proportionnelle", "nicht konstant"
_FOREIGN_NEGATION = r"pas|jamais|nicht|kein|keine|keinen|nie|niet|nunca"
_NEGATION = re.compile(
    rf"\b(?:not(?! only\b| just\b)|no|never|none|nothing|neither|nor|without|{_FOREIGN_NEGATION})\b|{_UNEQUAL}"
)
# and what stands just before it: "T + V ≠ H"
_UNEQUAL_AFTER = re.compile(rf"\s*(?:{_UNEQUAL})")
# "doesn't" and "cannot" read as "does not" and "can not", so the phrasing "not be written" is
# found in "can't be written", and one negation word serves them all
_CONTRACTED = re.compile(r"n't\b|(?<=\bcan)not\b")
# how many words before a phrasing a negation may stand and still be its own: "cannot in general
# be written as f(r, t) = 0" is negated, "a coordinate that does not appear in L has its momentum
# conserved" is not
NEGATION_REACH = 6
_REACH_CHARACTERS = 40 * NEGATION_REACH  # so that a long clause is not split again for each phrasing
# a prefix glued to a word that turns it into its opposite: "non-holonomic", "unconserved",
# "independent", "impossible", "irreversible"; "non holonomic" is written so too
_NEGATING_PREFIX = re.compile(r"(?<![^\W\d_])(?:(?:non|un|in|im|ir)-?|non )$")
# a term set against the subject is not the subject: "unlike Newton's method, it uses energies"
_CONTRAST = re.compile(
    r"\b(?:unlike|than|instead of|as opposed to|compared (?:with|to)|in contrast (?:with|to))(?: the| a| an)? $"
)
# a one-letter term standing alone: not inside a word, not "e.g." or "i.e.", not a velocity (q̇, q̈, q')
_LETTER_NAME = r"(?<![^\W\d_]|\.){}(?![^\W\d_]|[\u0300-\u036f]|\.[^\W\d_]|'(?!s\b))"
# an aside in brackets negates nothing outside it: "the momentum (p_k, not q̇_k) is conserved"
_ASIDE = re.compile(r"\([^()]*\)|\[[^\[\]]*\]")
_SENTENCE_END = re.compile(r"[;?]|!(?!=)|\.(?=\s|$)")  # "!=" is a relation, not a cry
# not "or": a negation reaches across it ("does not use energies or generalized coordinates")
_CLAUSE_END = re.compile(
    r"[,:]|\b(?:and|but|while|whereas|so|then|hence|thus|therefore|since|because|if|when|whenever|"
    r"although|though|unlike|which|that|whose|where)\b"
)
# what says a statement is not so (or doubts it) after it, "…, which is false", "That is not
# true.", "Not really.", "The opposite is true.", "I'm not sure", "…, I think.", ending its clause
# or giving a reason: "not true for the energy" takes back nothing said before it, nor does the
# "no" that answers the next question ("Yes, H is conserved. No, H ≠ E.")
_FALSE = (
    r"(?:(?:totally|completely|entirely|simply|just|all|very|obviously|of course) )?"
    r"(?:not (?:true|correct|right|valid|the case|so|sure|certain|really|quite|exactly|at all)|false|wrong"
    r"|incorrect|untrue|unsure|nonsense|a lie|lies|guess|think|believe|suppose|maybe|perhaps|probably|possibly"
    r"|do not know|no idea|or (?:maybe |perhaps |probably )?not|or is it"
    r"|no,? wait|wait,? no|(?:lol|haha),? no|scratch that|never mind|(?:just )?(?:joking|kidding)|jk|a joke"
    r"|(?:the )?(?:opposite|reverse|other way (?:round|around))(?: is (?:true|the case))?"
    r"|(?:none|neither)(?: of (?:this|these|that|those|them|it|the two))?(?: statements?| claims?)?"
    r" (?:is|are) (?:true|correct|right|so))"
    r"(?:\s+(?:in general|at all|here|either|though|so))?(?=\s*(?:[—–),.;:!?]|$|\b(?:because|since|as|but|and)\b))"
)
# and "Not!", "No." or "Nope." on their own: "… when they are not." stands for the claim before it
_BARE_DENIAL = r"(?:(?:of course|obviously|certainly|definitely) )?(?:not|no|nope)(?=\s*(?:[.!?;)]|$))"
_FALSITY_REMARK = re.compile(
    rf"\W*(?:{_BARE_DENIAL}|(?:(?:actually|in fact|really),? )?"
    r"(?:(?:this|it|that|which|i|they|these|those|the (?:statement|claim))\W+)?"
    rf"(?:(?:is|was|are|s|am|m|re|would be) )?{_FALSE})"
)
# a doubt before a statement, as a negation would stand: "maybe time independent"; what others say
# or think is not what the student says ("some say", "a common mistake is to think")
_SOME_SAY = (
    r"(?:some|many|most) (?:people |students |books )?(?:say|claim|think|believe)"
    r"|people (?:often |usually |commonly )?(?:say|claim|think|believe)|you (?:might|may|could|would) (?:think|say)"
    r"|(?:it is|it's) (?:often |commonly |widely |sometimes )?(?:said|claimed|believed|thought)"
    r"|(?:mistake|misconception|myth|error) (?:is )?to (?:say|think|believe|claim)"
)
_DOUBT = re.compile(rf"\b(?:maybe|perhaps|possibly|probably|i guess|{_SOME_SAY})\b")
_DASHED_FALSITY = re.compile(
    rf"(?:[—–(]| - | -- )\W*(?:{_BARE_DENIAL}|(?:(?:both|all|i)\W+(?:(?:are|am|m) )?)?{_FALSE})"
)
# a remark that takes back all said before it, not only its sentence: "None of this is true.",
# "Both statements are false.", "My answer is wrong.", "I am joking.", "Ignore the above."
_ALL_OF_IT = (
    r"(?:all|both|everything(?: above| i (?:said|wrote))?|all (?:of )?(?:this|these|that|those|them|it|the above)"
    r"|both of (?:these|them|those)|the above|(?:all|both) (?:of )?(?:the |my |these |those )?"
    r"(?:statements|claims|sentences|answers)|(?:this|my|the above) answer)(?: above)?"
)
_RETRACTION = re.compile(
    r"(?:^|[.;:!?,(—–]|\s--?\s|\b(?:but|and|though|however)\b)\W{0,4}(?P<remark>"
    r"none of (?:this|these|that|those|it|them|the above|what i (?:said|wrote))(?: above)?"
    r" (?:is|are|was|were) (?:true|correct|right|valid|so)"
    rf"|{_ALL_OF_IT}(?: (?:is|are|was|were))?(?: all)?"
    r" (?:(?:totally|completely|entirely) )?(?:false|wrong|incorrect|untrue|nonsense|not (?:true|correct|so))"
    r"|(?:i am|i'm|im|just) (?:just )?(?:joking|kidding)|jk|(?:this|it) (?:is|was) (?:all )?a joke"
    r"|(?:i am|i'm) not sure (?:about|of) (?:any|all) of (?:this|it|that|these)"
    r"|(?:please )?(?:ignore|disregard) (?:all of |everything )?(?:this|that|the above|above|everything))"
    r"(?=\s*(?:[—–),.;:!?]|$))"
)
# a question states nothing unless answered yes; one asking why or how takes its statement for granted
_WHY = re.compile(r"\W*(?:why|how)\b")
_YES = re.compile(r"\W*(?:yes|yeah|yep|indeed|correct|true)\b")
# a denial before "that" ("it is not true that …", "I do not think that …", "a misconception that …")
_DENIAL = re.compile(
    r"\b(?:not(?! only\b| doubt)|never(?! doubt)|no(?! doubt)|false|wrong|incorrect|untrue|myth|misconception"
    rf"|mistake|{_SOME_SAY})\b"
)
# what joins a "that" to an earlier one, whose denial it shares: "it is false that A and that B"
_JOINED = re.compile(r"(?:\band|\bor|\bnor|,)\s*$")
_THAT = re.compile(r"\bthat\b")
# "A and B are X and Y, respectively": the word, and what parts the terms of such a list (the rest
# of a term's word, as "scleronom" names "scleronomic", and a noun such as "constraints")
_RESPECTIVELY = re.compile(r"\brespectively\b|\bresp\b\.?")
_LIST_GAP = re.compile(r"[^\W\d_]*(?:'s)?(?:\s+[^\W\d_]+)?\s*(?:,\s*(?:and\s+|or\s+)?|\s(?:and|or)\s+)(?:the\s+)?")
# between a term and another that names what it belongs to, which is not what is spoken of
_COMPLEMENT = re.compile(
    r"[^\W\d_]*(?:_\w{1,3})?\)?\s+(?:of|conjugate to|associated with|corresponding to|belonging to)\s+"
    r"(?:(?:the|a|an|its|their|each|every|this|that|cyclic|ignorable|generalized|generalised)\s+)*"
)
_APPOSITION = re.compile(r"[^\W\d_]*\s+")  # and the name right after it: "a cyclic coordinate q"
# between a phrasing and the term it stands before as an adjective: "a conserved (generalized) momentum"
_ATTRIBUTE = re.compile(r"\s+(?:(?:generalized|generalised|canonical|conjugate|angular|linear)\s+)?")
_OR = re.compile(r"\bor\b")
# a clause that ends on its verb, which stands for the claim before it: "scleronomic if it does not",
# "rheonomic when it does"; and a negation that begins a claim, which it turns round
_ELLIPSIS = re.compile(
    r"\b(?:it|they|one|ones|this|that|these|those)\s+(?:does|do|did|is|are|was|were|has|have)(?P<not>\s+not)?"
    r"(?:\s+(?:so|too))?(?=\s*(?:$|[—–(),.;:!?]))"
)
_LEADING_NEGATION = re.compile(r"^(?:not|no|never)\s+")
# a phrasing offered beside another of its own shape: "sin θ ≈ θ or sin θ ≈ 1", "proportional to θ or to
# 1", "conserved or not", "not conserved or it is conserved"
_OR_AFTER = re.compile(r"\s+or\s+")
_OR_BEFORE = re.compile(r"(?<![^\W\d_])or\s+(?:(?:it|they|this|that)(?: is| are| was|'s|'re)\s+)?$")
_OR_TURNED = re.compile(r"\W*(?:not|no|never|(?:it|they|this|that)(?: is| are| was| does| do| has| can|'s|'re))\b")
_LINKING_WORDS = frozenset(("the", "a", "an", "is", "are", "be", "it", "its", "of", "in", "and", "not", "no", "never"))
# what follows a list of terms of which a phrasing is said together: "A and B constraints", "A and B both"
_LIST_TAIL = re.compile(r"[^\W\d_]*(?:'s)?\s+(?:(?:constraints|methods|ones|formulations|approaches)\b|both\b)")
# a full stop after these is no sentence's end: "e.g. a pendulum", "i.e. scleronomic", "q_1, ..., q_n"
_ABBREVIATION = re.compile(r"(?:(?<![^\W\d_])(?:e\.g|i\.e|eg|ie|cf|vs|resp|approx)|\.)$")


def _normal(text: str) -> str:
    """Case, compatibility forms (… as ...), apostrophes, contractions and spaces made uniform."""
    text = unicodedata.normalize("NFKC", text).casefold().translate(_APOSTROPHES)
    return re.sub(r"\s+", " ", _CONTRACTED.sub(" not", text)).strip()


@dataclass(frozen=True)
class RubricReading:
    """What a rubric makes of one text.

    Attributes:
        points: the points proposed, those of the ideas found.
        found: the ideas found, in the rubric's order.
        missing: the ideas not found, in the rubric's order (``discounted`` among them).
        discounted: the ideas whose phrasings the text holds, but only negated, doubted or said of
            another term than the idea's: a person should read these first.
    """

    points: float
    found: tuple[str, ...]
    missing: tuple[str, ...]
    discounted: tuple[str, ...] = ()


class _Reading:
    """A normalised text cut into clauses and sentences, with the boundaries' spans sorted."""

    def __init__(self, text: str):
        self.text = text
        self.clauses, self.sentences = _boundaries(text)
        self.clause_ends = [start for start, _ in self.clauses]
        self.sentence_ends = [start for start, _ in self.sentences]
        # where the last remark that takes back all before it stands ("None of this is true.")
        self.retracted = max((match.start("remark") for match in _RETRACTION.finditer(text)), default=-1)

    def clause(self, start: int, end: int) -> tuple[int, int]:
        return _around(self.clauses, self.clause_ends, start, end, len(self.text))

    def sentence(self, start: int, end: int) -> tuple[int, int]:
        return _around(self.sentences, self.sentence_ends, start, end, len(self.text))


def _boundaries(text: str) -> tuple[list[tuple[int, int]], list[tuple[int, int]]]:
    """The spans that end clauses, and those that end sentences (which end clauses too)."""
    sentences = [
        match.span()
        for match in _SENTENCE_END.finditer(text)
        if not (match.group() == "." and _ABBREVIATION.search(text, max(0, match.start() - 8), match.start()))
    ]
    # a comma or an "and" inside brackets belongs to a formula or an aside: f(r, t), (a, b);
    # a sentence's end closes any bracket left open, so one stray "(" cannot join the whole text
    depth, inside, sentence_at = 0, [], {start for start, _ in sentences}
    for index, char in enumerate(text):
        if index in sentence_at:
            depth = 0
        elif char in "([{":
            depth += 1
        elif char in ")]}" and depth:
            depth -= 1
        inside.append(depth > 0)
    clauses = [match.span() for match in _CLAUSE_END.finditer(text) if not inside[match.start()]]
    return sorted(set(clauses) | set(sentences)), sentences


def _around(spans, starts, start: int, end: int, length: int) -> tuple[int, int]:
    """The stretch between the last boundary that ends by ``start`` and the first that starts from ``end``."""
    after = bisect.bisect_left(starts, end)
    high = spans[after][0] if after < len(spans) else length
    low = 0
    for index in range(min(after, len(spans)) - 1, -1, -1):  # boundaries inside the phrasing are its own
        if spans[index][1] <= start:
            low = spans[index][1]
            break
    return low, high


def _occurrences(reading: _Reading, phrasing: str):
    """Each place a phrasing is found: (start, end, negated). A phrasing with gaps is found piece by
    piece, in order, within the clause of its first piece."""
    pieces = [piece.strip() for piece in phrasing.split(GAP)]
    text, first = reading.text, pieces[0]
    start = text.find(first)
    while start >= 0:
        end = start + len(first)
        low, high = reading.clause(start, end)
        negated = _negated_before(reading, low, start, first)
        for piece in pieces[1:]:
            found = text.find(piece, end, high)
            if found < 0:
                break
            negated = negated or bool(_NEGATION.search(text, end, found))
            end = found + len(piece)
        else:
            yield start, end, negated or bool(_UNEQUAL_AFTER.match(text, end)) or _taken_back(reading, end)
        start = text.find(first, start + 1)


def _negated_before(reading: _Reading, low: int, start: int, phrasing: str) -> bool:
    """Whether a negation among the words just before ``start`` in its clause, or a negating prefix
    glued to the phrasing, turns it into its opposite; or its clause is what a denial before it
    says is not so ("it is not true that …")."""
    text = reading.text
    if phrasing[:1].isalpha() and _NEGATING_PREFIX.search(text, max(0, start - 4), start):
        return True
    before = _ASIDE.sub(" ", text[max(low, start - _REACH_CHARACTERS) : start])
    window = " ".join(before.split()[-NEGATION_REACH:])
    if _NEGATION.search(window) or _DOUBT.search(window):
        return True
    return _denied_that(reading, low - 4)


def _denied_that(reading: _Reading, that: int) -> bool:
    """Whether the "that" at ``that`` follows a denial ("it is not true that …"), its own or, where
    it is joined to an earlier one by "and" or "or", that one's: "it is false that A and that B"."""
    text = reading.text
    sentence, _ = reading.sentence(that, that)
    for _ in range(NEGATION_REACH):  # how many "that"s a denial reaches
        if text[max(0, that) : that + 4] != "that":
            return False
        denial, _ = reading.clause(that, that)
        words = text[denial:that].split()
        # three words hold a denial ("it is not true that"), six one by others ("a common
        # misconception is to think that")
        if _DENIAL.search(" ".join(words[-3:])) or _DOUBT.search(" ".join(words[-NEGATION_REACH:])):
            return True
        if not _JOINED.search(text, max(sentence, that - 6), that):
            return False
        earlier = [match.start() for match in _THAT.finditer(text, sentence, that - 1)]
        if not earlier:
            return False
        that = earlier[-1]
    return False


def _taken_back(reading: _Reading, end: int) -> bool:
    """Whether what was said up to ``end`` is taken back after it: by a remark later in its
    sentence ("which is false", "— not true in general", "I'm not sure"), by the next sentence
    ("That is wrong."), or in a question not answered yes ("… is conserved? No.")."""
    text = reading.text
    if end <= reading.retracted:
        return True
    _, high = reading.sentence(end, end)
    if _DASHED_FALSITY.search(text, end, high):
        return True
    index = bisect.bisect_left(reading.clause_ends, end)
    for boundary_start, boundary_end in reading.clauses[index:]:
        if boundary_start >= high:
            break
        if _FALSITY_REMARK.match(text, boundary_end, high):
            return True
    if high >= len(text):
        return False
    following = reading.sentence(high + 1, high + 1)[1]
    if text[high] == "?":  # "why is it conserved?" takes for granted what it asks about
        return not _YES.match(text, high + 1, following) and not _WHY.match(text, reading.sentence(end, end)[0])
    return bool(_FALSITY_REMARK.match(text, high + 1, following))


def _mentions(reading: _Reading, about, not_about) -> tuple[list[tuple[int, int, bool]], list[int]]:
    """Where the idea's terms are named as what is spoken of: (start, end, whether it is the idea's
    own), in order, and their starts. A term inside a longer one is not named there ("holonomic" in "non-holonomic");
    a term with a negating prefix glued to it names something else; a term set against another
    ("unlike Newton's") is not what is spoken of, nor one that names what the term before it
    belongs to ("the momentum conjugate to a cyclic coordinate q")."""
    text, found = reading.text, []
    for terms, own in ((about, True), (not_about, False)):
        for term in {_normal(term) for term in terms}:
            for start in _term_starts(text, term):
                negated = term[:1].isalpha() and bool(_NEGATING_PREFIX.search(text, max(0, start - 4), start))
                found.append((start, start + len(term), own and not negated))
    found.sort(key=lambda mention: (mention[0], -mention[1]))
    kept, reach, complement = [], -1, None
    for mention in found:
        if mention[1] <= reach:
            continue  # inside a longer term, which is what is named there
        reach = max(reach, mention[1])
        if _CONTRAST.search(text, max(0, mention[0] - 24), mention[0]):
            continue
        if kept and (
            _COMPLEMENT.fullmatch(text, kept[-1][1], mention[0])
            or (complement is not None and _APPOSITION.fullmatch(text, complement, mention[0]))
        ):
            complement = mention[1]
            continue
        kept.append(mention)
    return kept, [mention[0] for mention in kept]


def _term_starts(text: str, term: str):
    """Where a term is named. A one-letter term is a name of its own: `q` in "if q does not appear",
    not in "quantity", "e.g.", the velocity "q̇" or "q'"."""
    if len(term) == 1 and term.isalpha():
        return (match.start() for match in re.finditer(_LETTER_NAME.format(re.escape(term)), text))
    return _find_all(text, term)


def _find_all(text: str, piece: str):
    start = text.find(piece)
    while start >= 0:
        yield start
        start = text.find(piece, start + 1)


def _said_of_own(reading: _Reading, mentions, starts, start: int, end: int, *, rivals: bool) -> bool:
    """Whether the term the phrasing at ``start:end`` is said of is the idea's own. With ``rivals``
    (a term the idea is not about is another idea's subject), a phrasing said of no term at all is
    of neither: in "constraints can be time dependent or time independent", which is which is not said."""
    respective = _respective(reading, mentions, starts, start, end)
    if respective is not None:
        return respective
    after = bisect.bisect_left(starts, end)
    if after < len(mentions) and _ATTRIBUTE.fullmatch(reading.text, end, starts[after]):
        return mentions[after][2]  # it describes the term it stands before: "a conserved momentum"
    for low, high in (reading.clause(start, end), reading.sentence(start, end)):
        first, last = bisect.bisect_left(starts, low), bisect.bisect_left(starts, end)
        if last > first:  # named before it (or in it)
            return _own_subject(reading, mentions, last - 1, start)
        if last < len(mentions) and starts[last] < high:  # named after it
            return mentions[last][2]
    earlier = bisect.bisect_left(starts, start)
    if earlier:
        return _own_subject(reading, mentions, earlier - 1, start)
    return not rivals  # else the question's own subject, where it has only one


def _respective(reading: _Reading, mentions, starts, start: int, end: int) -> bool | None:
    """In a sentence with "respectively", whether the phrasing is said of the idea's own term by
    the order of the list, the n-th description of the n-th term ("A and B are X and Y,
    respectively"); None where no list of terms is named there."""
    text = reading.text
    low, high = reading.sentence(start, end)
    if not _RESPECTIVELY.search(text, low, high):
        return None
    named = mentions[bisect.bisect_left(starts, low) : bisect.bisect_left(starts, high)]
    terms = named[:1]
    for mention in named[1:]:
        if not _LIST_GAP.fullmatch(text, terms[-1][1], mention[0]):
            break
        terms.append(mention)
    if len(terms) < 2 or terms[0][0] <= start < terms[-1][1]:
        return None
    after = start >= terms[-1][1]  # the descriptions follow the terms, or come before them
    region = (terms[-1][1], high) if after else (low, terms[0][0])
    cuts = [span for span in reading.clauses if region[0] <= span[0] and span[1] <= region[1]]
    edges = [region[0], *(edge for span in cuts for edge in span), region[1]]
    pieces = [
        (edges[index], edges[index + 1])
        for index in range(0, len(edges), 2)
        if _RESPECTIVELY.sub("", text[edges[index] : edges[index + 1]]).strip(" ,.;:!?")
    ]
    if len(pieces) < len(terms):
        return False  # the order cannot be followed, so which is which is not said
    pieces = pieces[-len(terms) :] if after else pieces[: len(terms)]
    for (piece_start, piece_end), term in zip(pieces, terms, strict=True):
        if piece_start <= start < piece_end:
            return term[2]
    return False


def _own_subject(reading: _Reading, mentions, index: int, start: int) -> bool:
    """Whether the term ``mentions[index]``, named before a phrasing, is the idea's own and not
    denied: in "H is not equal to T + V when the constraints are scleronomic", scleronomic is said
    of a denied T + V; nor one of a list that holds a rival ("Newton's and Lagrange's methods both
    use energies" says nothing of Lagrange's alone)."""
    mention = mentions[index]
    if not mention[2] or mention[0] >= start:  # a term inside the phrasing is its own words
        return mention[2]
    if _LIST_TAIL.match(reading.text, mention[1]):
        while index and _LIST_GAP.fullmatch(reading.text, mentions[index - 1][1], mentions[index][0]):
            index -= 1
            if not mentions[index][2]:
                return False
    low, _ = reading.clause(mention[0], mention[1])
    return not _negated_before(reading, low, mention[0], "")


def _found(reading: _Reading, phrasings):
    """Each place one of ``phrasings`` is found, as ``_occurrences`` gives it."""
    for phrasing in phrasings:
        yield from _occurrences(reading, _normal(phrasing))


def _hedged(reading: _Reading, starts, start: int, end: int, alternatives) -> bool:
    """Whether a rival idea's phrasing is offered beside this one with "or", no term named between
    them, in its clause: "scleronomic constraints are time dependent or time independent"."""
    clause = reading.clause(start, end)
    for other_start, other_end, _ in alternatives:
        low, high = (end, other_start) if other_start >= end else (other_end, start)
        if (
            low <= high
            and reading.clause(other_start, other_end) == clause
            and _OR.search(reading.text, low, high)
            and bisect.bisect_left(starts, low) == bisect.bisect_left(starts, high)
        ):
            return True
    return False


def _words(text: str) -> list[str]:
    """The words that give a piece its shape: of two letters or more, neither a number, a linking word
    nor a negation, which is not a shape but a meaning."""
    words = (word.strip(".,;:!?()[]{}\"'") for word in text.split())
    return [word for word in words if len(word) > 1 and word not in _LINKING_WORDS and not word.isdigit()]


def _alternative(reading: _Reading, start: int, end: int, credited) -> bool:
    """Whether the phrasing at ``start:end`` is offered with "or" beside another claim of its own shape,
    in its clause: the other side turns it round ("conserved or not", "… or it is conserved") or
    repeats one of its words ("sin θ ≈ θ or sin θ ≈ 1", "proportional to θ or to 1"); unless what it
    offers, read in the phrasing's place, is credited too (``credited(piece)``: "proportional to θ
    or to the angle", "linear in θ or proportional to θ")."""
    text = reading.text
    low, high = reading.clause(start, end)
    after = _OR_AFTER.match(text, end, high)
    if after:
        other = text[after.end() : high]
    else:
        before = _OR_BEFORE.search(text, max(low, start - 20), start)
        if not before:
            return False
        other = text[low : before.start()]
    own = _words(text[start:end])
    if not (_OR_TURNED.match(other) or set(own).intersection(_words(other))):
        return False
    if after and other.split() and other.split()[0] in own:  # "to θ or to the angle": "to the angle" in its place
        phrase = text[start:end]
        other = phrase[: phrase.find(other.split()[0])] + other
    return not credited(other)


def rubric_score(text: str, rubric) -> RubricReading:
    """What ``rubric`` makes of ``text``: the points proposed, the ideas found and missed.

    ``rubric`` is a sequence of (idea, points, phrasings) or (idea, points, phrasings, about,
    not_about); an idea counts when one of its phrasings is found in the text, not negated,
    and (with ``about``) said of one of the ``about`` terms rather than of a ``not_about`` one.

    >>> rubric = [("small angle", 1.0, ("sin θ ≈ θ",)), ("proportional", 1.0, ("proportional",))]
    >>> rubric_score("For small angles sin θ ≈ θ", rubric)
    RubricReading(points=1.0, found=('small angle',), missing=('proportional',), discounted=())
    >>> rubric_score("sin θ ≈ θ, but the force is not proportional to θ", rubric).discounted
    ('proportional',)
    >>> scleronomic = [("fixed in time", 1.0, ("time independent",), ("scleronom",), ("rheonom",))]
    >>> rubric_score("Scleronomic ones are time independent", scleronomic).points
    1.0
    >>> rubric_score("Scleronomic ones depend on t and rheonomic ones are time independent", scleronomic).points
    0.0
    """
    ideas = [(idea, worth, phrasings, *(*binding, (), ())[:2]) for idea, worth, phrasings, *binding in rubric]
    return _score(_Reading(_normal(text[:MAX_TEXT_LENGTH])), ideas, alternatives=True)


def _score(reading: _Reading, ideas, *, alternatives: bool) -> RubricReading:
    """``rubric_score`` of a text read; with ``alternatives``, a phrasing offered with "or" beside
    another of its shape counts only where the other is credited too (read with no such check, so
    "a or a or a …" is read once more, not once for each "or")."""
    found, missing, discounted, points = [], [], [], 0.0
    # the subjects the question asks about: two (scleronomic and rheonomic) where one idea's rival is
    # another's own; then a phrasing said of no term is said of neither
    subjects = {_normal(term) for *_, about, _ in ideas for term in about}
    places: dict[int, list] = {}  # a rival idea's phrasings found, once asked for

    def found_places(index: int):
        if index not in places:
            places[index] = list(_found(reading, ideas[index][2]))
        return places[index]

    def credited(rival_ideas):
        others = [idea for other, idea in enumerate(ideas) if other not in rival_ideas]
        return lambda piece: bool(_score(_Reading(piece), others, alternatives=False).found)

    contexts: dict[int, tuple] = {}

    def context(index: int):
        """An idea's rival terms, rival ideas, and the places its terms are named."""
        if index not in contexts:
            *_, about, not_about = ideas[index]
            rival_terms = {_normal(term) for term in not_about} & subjects
            rival_ideas = [
                other
                for other, (*_, other_about, _) in enumerate(ideas)
                if other != index and rival_terms & {_normal(term) for term in other_about}
            ]
            contexts[index] = (rival_terms, rival_ideas, *(_mentions(reading, about, not_about) if about else ([], [])))
        return contexts[index]

    def counts(index: int, start: int, end: int, negated: bool) -> bool:
        rival_terms, rival_ideas, mentions, starts = context(index)
        return (
            not negated
            and (not ideas[index][3] or _said_of_own(reading, mentions, starts, start, end, rivals=bool(rival_terms)))
            # what a rival idea says of the same subject, offered as an alternative: "time
            # dependent or time independent"
            and not any(_hedged(reading, starts, start, end, found_places(other)) for other in rival_ideas)
            # or beside another claim of its own shape: "sin θ ≈ θ or sin θ ≈ 1"
            and not (alternatives and _alternative(reading, start, end, credited(rival_ideas)))
        )

    def elided(index: int) -> bool:
        """Whether an ellipsis said of the idea's term stands for a rival's claim turned round:
        "rheonomic if time appears explicitly, and scleronomic if it does not"."""
        _, rival_ideas, mentions, starts = context(index)
        for match in _ELLIPSIS.finditer(reading.text):
            if not _said_of_own(reading, mentions, starts, match.start(), match.end(), rivals=True):
                continue
            low, _ = reading.sentence(match.start(), match.start())
            if low:  # or the sentence before: "Rheonomic ones contain t explicitly. Scleronomic ones do not."
                low, _ = reading.sentence(low - 1, low - 1)
            before = [
                (start, end)
                for other in rival_ideas
                for start, end, negated in found_places(other)
                if low <= start and end <= match.start() and counts(other, start, end, negated)
            ]
            if before:
                start, end = max(before)
                claim = _LEADING_NEGATION.sub("", reading.text[start:end])  # "not contain t explicitly": "contain …"
                claim = "not " + claim if match.group("not") else claim
                if any(not negated for *_, negated in _found(_Reading(claim), ideas[index][2])):
                    return True
        return False

    for index, (idea, worth, _, about, _) in enumerate(ideas):
        seen = counted = False
        for start, end, negated in _found(reading, ideas[index][2]):
            seen = True
            counted = counts(index, start, end, negated)
            if counted:
                break
        if not counted and about and context(index)[1] and _ELLIPSIS.search(reading.text):
            counted = elided(index)
        if counted:
            found.append(idea)
            points += worth
        else:
            missing.append(idea)
            if seen:
                discounted.append(idea)
    return RubricReading(points, tuple(found), tuple(missing), tuple(discounted))


def check_text(expected: Expected, submitted: str, deadline: Deadline) -> Outcome:
    rubric = expected.option("rubric") or ()
    total = sum(idea[1] for idea in rubric) or 1.0
    reading = rubric_score(submitted if isinstance(submitted, str) else "", rubric)
    details = {"found": len(reading.found), "total": len(rubric)}
    if reading.discounted:
        key, details = "text_review_discounted", {**details, "discounted": len(reading.discounted)}
    else:
        key = "text_review"
    return Outcome("undecided", reading.points / total, key, details, method="rubric")
