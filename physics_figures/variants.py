"""Question templates and their variants: fresh numbers, drawn the way an exam writes them.

A ``Template`` is a question with its givens left open: ``build(**values)`` makes the
``Question`` (text, parts, keys from the models, mark scheme) for one set of values.
Variant 0 is the printed version (the notes' numbers); the others are drawn from each
given's ``Draw`` with a seed fixed by the template's key, so every build gives the same
variants. A draw is refused when the physics refuses it (the models raise ValueError),
when it repeats an earlier variant, or when a named mistake would land inside the band
that the key accepts at 2 significant figures (then the marker could not tell them apart).
A reserve variant (the teacher's kit) is refused, too, when it prints a site variant's givens
or gives one of a site variant's answers (``repeats_the_site``): a student who has met the site's
question must not meet its numbers, or a key they remember, on a sheet.
"""

from __future__ import annotations

import math
import random
from collections import Counter
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from functools import cached_property

from . import marking, parts
from .checks import require as _require
from .notation import round_number
from .parts.numeric import G_TEN_SLIP
from .questions import Question

#: What a template asks for (data-kind): the part kinds, by name (physics_figures.parts.KINDS).
KINDS = parts.KINDS
#: Fresh-number templates give the site at least this many variants, and keep at least
#: MIN_RESERVE more that the site never ships: the teacher's worksheets, tests and Moodle
#: file draw only from those (issue 26), so no student has met a sheet's numbers. Templates
#: that vary their situation instead (conceptual, multiple choice, explain) give at least
#: MIN_SITUATIONS, split the same way once they have SHARED_BELOW or more; with fewer, the
#: site and the sheets share them (CLARIFICATIONS, Teachers; the "For teachers" page lists them).
MIN_VARIANTS = 10
MIN_RESERVE = 10
MIN_SITUATIONS = 4
SHARED_BELOW = 8
#: A multiple-choice template's key is no one letter in more than this share of its variants.
MOST_OF_ONE_LETTER = 0.4
_MAX_TRIES = 2000


@dataclass(frozen=True)
class Draw:
    """A given: the value the printed version states, and the grid fresh values come from
    (low to high in steps of ``step``, at the precision an exam prints)."""

    printed: float
    low: float
    high: float
    step: float

    def __post_init__(self):
        _require(self.step > 0, "step", self.step, "must be positive")
        _require(self.low <= self.high, "low", self.low, f"must not be above high={self.high}")
        count = (self.high - self.low) / self.step
        _require(abs(count - round(count)) < 1e-6, "step", self.step,
                 f"must divide high - low = {self.high - self.low} into whole steps")

    @cached_property  # a template's draws read it once a try, thousands of times
    def grid(self) -> tuple[float, ...]:
        count = round((self.high - self.low) / self.step)
        # rounded to the step's own places, so 0.1 steps give 2.3, not 2.3000000000000003
        places = max(0, -math.floor(math.log10(self.step)) + 2)
        return tuple(float(round_number(self.low + i * self.step, decimals=places))
                     for i in range(count + 1))


#: The s.f. rule (marking_rules.json): the figures the A1 needs, and those the key is trusted to.
FIGURES = marking.sig_figs()


def accepted_band(key: float, sig_figs: int = FIGURES["min"]) -> tuple[float, float]:
    """The values a marker takes as the key at ``sig_figs`` s.f.: those that round to it."""
    rounded = float(round_number(key, sig_figs))
    if rounded == 0:
        return (0.0, 0.0)
    half = 10 ** (math.floor(math.log10(abs(rounded))) - sig_figs + 1) / 2
    return (rounded - half, rounded + half)


def confusable_mistakes(question: Question) -> list[str]:
    """Named mistakes whose value the key's 2 s.f. band accepts (the marker could not tell)."""
    found = []
    for part in question.parts:
        if not part.has_value:  # e.g. a choice or an explanation: no band
            continue
        # a reading from a graph is right within half a small square; a calculation at 2 s.f.,
        # and one worked from readings anywhere their half squares take it, written at 2 s.f.
        low, high = part.band if part.reads_graph else accepted_band(part.value)
        for mistake in part.mistakes:
            # g = 10 is 2 % off: its answer often rounds to the key at 2 s.f., which a scheme's A1
            # takes (to 3 s.f. the marker names it, and a wrong direction stays only that)
            if mistake.name == G_TEN_SLIP and not part.reads_graph and not part._accepted(mistake.value):
                continue
            same_kind = mistake.unit is None and mistake.direction is None
            typed = float(round_number(mistake.value, FIGURES["min"])) if mistake.value else 0.0
            if same_kind and (low <= mistake.value <= high
                              or (not part.reads_graph and part.band_takes(typed, FIGURES["min"]))):
                found.append(f"{part.prompt}: {mistake.name}")
    return found


def rounding_ties(question: Question) -> list[str]:
    """Named answers a marker could take for the key because the key sits on a rounding tie at
    3 s.f. (292.5, 4.905): which way it rounds then hangs on the last bit of a float, so a slip
    (g = 9.8, rounding part-way) typed as 292 or 4.90 could read as the key, in the browser or
    in Python. A drawn variant with one is refused (an exam writer, too, would pick other numbers)."""
    found = []
    for part in question.parts:
        if not part.has_value or part.reads_graph or not part.value:
            continue
        scaled = abs(part.value) * 10.0 ** (FIGURES["check"] - 1 - math.floor(math.log10(abs(part.value))))
        if abs(scaled - math.floor(scaled) - 0.5) > 1e-6:
            continue
        unit = abs(part.value) / scaled  # one unit of the 3rd significant figure
        forms = {round(math.floor(scaled) * unit, 12), round(math.ceil(scaled) * unit, 12)}
        named = [(m.name, m.value) for m in part.mistakes if m.unit is None and m.direction is None]
        named += [("g = 9.8", part.g_nine_eight)] if part.g_nine_eight is not None else []
        named += [(what, value) for value, what in part.rounded_part_way]
        for name, value in named:
            if value and round(float(round_number(abs(value), FIGURES["check"])), 12) in forms:
                found.append(f"{part.prompt}: {name} ({value!r}) against the key {part.value!r}")
    return found


def _answers(question: Question) -> dict[str, float]:
    """Each number a key gives (a calculated or read part), to the 3 s.f. a key prints."""
    return {part.prompt: float(round_number(part.value, FIGURES["check"])) for part in question.parts
            if part.has_value}


def repeats_the_site(question: Question, site: list[Question]) -> list[str]:
    """How a reserve variant repeats the site's: its printed givens (and graph) all equal a site
    variant's (a given the text does not print, such as which drag law, does not tell them apart), or a
    part's key, to 3 s.f., is that part's key in a site variant (say, the same mass, so the same
    weight). Empty when it repeats none (issue 37)."""
    found = []
    givens = (tuple((g.name, g.text, g.unit) for g in question.givens), question.graph)
    answers = _answers(question)
    for index, other in enumerate(site):
        if givens[0] and givens == (tuple((g.name, g.text, g.unit) for g in other.givens), other.graph):
            found.append(f"the givens of site variant {index}")
        found += [f"{prompt} = {value:g}, as in site variant {index}"
                  for prompt, value in _answers(other).items() if answers.get(prompt) == value]
    return found


@dataclass(frozen=True)
class Template:
    """A question whose numbers are drawn afresh. ``build(**values)`` gives its Question.

    key: the stable id (data-question); type: one of its topic's question types (the
    topic checks it: physics_figures.topics); kinds: from KINDS.
    draws: the givens that vary; variant_count: how many variants to make. A try-first
    part of a worked example has no draws (one variant, the printed numbers), and neither
    has a one-wording statement (``one_wording``).
    """

    key: str
    type: str
    kinds: tuple[str, ...]
    title: str
    build: Callable[..., Question] = field(repr=False)
    draws: Mapping[str, Draw] = field(default_factory=dict)
    variant_count: int = MIN_VARIANTS + MIN_RESERVE
    #: A worked example's try-first part: the printed numbers only, not one of the bank's.
    try_first: bool = False
    #: Why an explain or conceptual template's answer is the same text in every variant (say, one
    #: definition asked in several wordings); else each variant's answer follows its situation
    #: (issue 25: tests/no_site/test_findings.py).
    same_answer_because: str = ""
    #: A define/state template whose wording cannot change without changing the physics (a
    #: definition has one right wording): why, in a sentence. It has no draws and one variant,
    #: and the variant rules skip it (CLARIFICATIONS, Papers: it counts as a template but not
    #: toward the variant rules; the sentence is the "says why it cannot" an explanation owes).
    one_wording: str = ""

    def __post_init__(self):
        _require(bool(self.type), "type", self.type, "must name one of its topic's question types")
        _require(bool(self.kinds) and set(self.kinds) <= set(KINDS), "kinds", self.kinds,
                 f"must be some of {tuple(KINDS)}")
        if self.same_answer_because:
            _require(bool(self.same_answer_because.strip()), "same_answer_because", self.same_answer_because,
                     "must say why the answer cannot follow the variant, in words")
            _require(any(not KINDS[kind].has_value for kind in self.kinds), "same_answer_because",
                     self.same_answer_because, "is only for an explain or multiple-choice template (a part with no "
                     f"value), not a {'/'.join(self.kinds)} one")
        _require(not (self.try_first and self.draws), "draws", dict(self.draws),
                 "must be empty for a worked example's try-first part (it keeps the printed numbers)")
        if self.one_wording:
            self._check_one_wording()
        elif not self.try_first:
            _require(bool(self.draws), "draws", dict(self.draws),
                     f"must say how {self.key}'s givens vary (only a try-first part or a one-wording "
                     "statement has none)")
            _require(self.variant_count >= self.least_variants, "variant_count", self.variant_count,
                     f"must be at least {self.least_variants} for a {'/'.join(self.kinds)} template")

    def _check_one_wording(self) -> None:
        _require(all(KINDS[kind].answered_in_words for kind in self.kinds), "one_wording", self.one_wording,
                 f"is for a define/state template, whose parts are answered in words (got kinds={self.kinds!r})")
        _require(not self.draws, "one_wording", self.one_wording,
                 f"means one variant, so {self.key} must have no draws (got draws={dict(self.draws)!r})")
        _require(not self.try_first, "one_wording", self.one_wording,
                 "is for the bank's statements, not a worked example's try-first part")
        _require(len(self.one_wording.split()) >= 5, "one_wording", self.one_wording,
                 "must say in a sentence why the wording cannot change without changing the physics")

    @property
    def least_variants(self) -> int:
        """The fewest variants the rules allow: MIN_VARIANTS for fresh numbers, MIN_SITUATIONS for
        a template that varies its situation, and 1 for a try-first part or a one-wording statement
        (neither counts toward the variant rules)."""
        if self.try_first or self.one_wording:
            return 1
        return MIN_VARIANTS + MIN_RESERVE if self.fresh_numbers else MIN_SITUATIONS

    @property
    def fresh_numbers(self) -> bool:
        """Its variants are fresh numbers (a calculation or a graph), not fresh situations."""
        return any(KINDS[kind].has_value for kind in self.kinds)

    @property
    def shares_variants(self) -> bool:
        """The site and the teacher's sheets use the same variants: a one-wording statement, a
        try-first part, or a template of fewer than SHARED_BELOW situations."""
        return not self.fresh_numbers and len(self.values) < SHARED_BELOW

    @property
    def site_variants(self) -> range:
        """The variants the site ships (New numbers): the first MIN_VARIANTS of fresh numbers,
        the first half (rounded up) of the situations, or all of them when they are shared.
        Variant 0, the printed one, is always the site's."""
        total = len(self.values)
        if self.shares_variants:
            return range(total)
        return range(min(total, MIN_VARIANTS) if self.fresh_numbers else total - total // 2)

    @property
    def reserve_variants(self) -> range:
        """The variants only the teacher's kit uses (all of them when they are shared)."""
        return range(len(self.values)) if self.shares_variants else range(len(self.site_variants), len(self.values))

    def _site_count(self) -> int:
        """How many of the variant_count variants the site will ship (site_variants, known before
        they are drawn); all of them when they are shared."""
        total = self.variant_count
        if not self.fresh_numbers and total < SHARED_BELOW:
            return total
        return min(total, MIN_VARIANTS) if self.fresh_numbers else total - total // 2

    @cached_property
    def values(self) -> tuple[dict[str, float], ...]:
        """The givens of every variant; variant 0 is the printed one."""
        return tuple(values for values, _ in self._drawn)

    @cached_property
    def _drawn(self) -> tuple[tuple[dict[str, float], Question], ...]:
        """Every variant's givens with the question they build (each draw is built once)."""
        printed = {name: draw.printed for name, draw in self.draws.items()}
        question = self._checked(printed, printed=True)
        chosen = [(printed, question)]
        if not self.draws:
            return tuple(chosen)
        rng = random.Random(self.key)  # the same variants in every build
        site_count = self._site_count()
        letters = (Counter(_key_letters(question)), Counter())  # the site's variants', the reserve's
        printed_as = {_printed_as(question)}  # a variant must print differently from the others
        for _ in range(_MAX_TRIES):
            if len(chosen) == self.variant_count:
                return tuple(chosen)
            values = {name: rng.choice(draw.grid) for name, draw in self.draws.items()}
            if any(values == taken for taken, _ in chosen):
                continue
            question = self._checked(values)
            in_site = len(chosen) < site_count
            site = [] if in_site else [q for _, q in chosen[:site_count]]
            group, size = (letters[0], site_count) if in_site else (letters[1], self.variant_count - site_count)
            if (question is not None and self._letters_fit(question, group, size)
                    and _printed_as(question) not in printed_as and not repeats_the_site(question, site)):
                chosen.append((values, question))
                group.update(_key_letters(question))
                printed_as.add(_printed_as(question))
        raise ValueError(f"template {self.key} found only {len(chosen)} of {self.variant_count} "
                         f"variants in {_MAX_TRIES} draws: widen its draws")

    def _checked(self, values: dict[str, float], *, printed: bool = False) -> Question | None:
        """The question these givens build, or None when a draw is refused."""
        try:
            question = self.build(**values)
        except ValueError:
            if printed:
                raise
            return None
        confused = confusable_mistakes(question)
        if printed:
            _require(not confused, "printed", values,
                     f"gives named mistakes inside the key's 2 s.f. band in {self.key}: {confused}")
            return question  # the notes' numbers are what they are
        return None if confused or rounding_ties(question) else question

    def _letters_fit(self, question: Question, letters: Counter, size: int) -> bool:
        """A multiple-choice draw is refused when its key's letter already has its share of the
        variants it joins (issue 25: no letter is the key in more than MOST_OF_ONE_LETTER of them),
        counted over the site's variants and over the reserve's apart (issue 37: B was the key in 5
        of the site's 10), so the letter never gives the answer away in what a student meets."""
        drawn = _key_letters(question)
        most = MOST_OF_ONE_LETTER * size * len(drawn)
        return all(letters[letter] + drawn.count(letter) <= most for letter in set(drawn))

    def variant(self, index: int) -> Question:
        return self.variants[index]

    @cached_property
    def variants(self) -> tuple[Question, ...]:
        """Every variant's question (frozen, so built once and shared)."""
        return tuple(question for _, question in self._drawn)


def _printed_as(question: Question) -> tuple:
    """What a student sees of a variant: its text and its graph (a graph question may keep
    its words, and two givens may round to the same printed numbers)."""
    return (question.text, question.graph)


def _key_letters(question: Question) -> list[str]:
    return [part.answer for part in question.parts if part.answer_grid]
