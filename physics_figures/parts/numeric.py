# ruff: noqa: RUF002  (docstrings quote the schemes' words, with their true minus, dash and times)

"""The numeric part kind: a calculated value, with its unit, direction, named mistakes, the
working that rounding part-way follows, error carried forward and alternatives. Its browser
twin is book/_ext/questions/static/question-kinds/numeric.js."""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable, Mapping
from dataclasses import KW_ONLY, dataclass, field
from functools import cache, cached_property
from html import escape
from typing import ClassVar

import sympy

from .. import marking
from ..constants import G_EARTH
from ..notation import format_number, round_number
from .common import (
    ASKS,
    DEFAULT_CHECK_SIG_FIGS,
    DEFAULT_MIN_SIG_FIGS,
    DIRECTION_MODES,
    G_NINE_EIGHT,
    G_TEN,
    PART_IDS,
    PART_WAY_SIG_FIGS,
    SCRIPTS,
    UNIT_HINT,
    PartKind,
    _require,
    feedback_html,
    field_label,
    input_html,
    number,
    prompt_html,
    unit_text,
)

#: The name of the slip a part whose answer uses g names (Part.answer_for_g): the book's rule,
#: "g = 10 loses only the A1".
G_TEN_SLIP = "used g = 10 m s⁻²"


@dataclass(frozen=True)
class Mistake:
    """A classic wrong answer, computed from the question's inputs.

    value: what the wrong method gives, in SI units (signed for a signed part, else a
    size). unit: only when the mistake gives another quantity (e.g. "J" for kinetic
    energy instead of momentum). direction: only when the mistake is a wrong direction.
    feedback: names the mistake and the idea to revisit (plain text). see: the section of the
    book that teaches that idea, where it is not the part's own (an id of the bank's sections).
    kind: what the mistake is, for the marks it keeps (marking_rules.json): "slip" (g = 10,
    a power-of-ten or prefix slip: keeps the C1 and M1), "direction" (keeps all but the
    direction's mark; the default when ``direction`` is set) or "physics" (a wrong formula or
    idea: keeps nothing; the default otherwise).

    keeps: the roles of the part's lines it keeps where a published scheme says otherwise than
    its kind ("method": the C1 and M1 lines, "answer", "direction"), e.g. ``("method",)`` for
    a wrong answer whose working the scheme credits with its C1. credited: the scheme that
    says so, cited with its words (required with ``keeps``), e.g. "9702/22/M/J/25 Q4(b)(i):
    C1 for p = mv or 0.25 × 3.6 or 0.25 × 5.2"; the key prints it beside what the answer
    keeps. A direction's own B1 is kept or lost by the direction chosen, whatever the value
    (a B mark stands on its own), unless the mistake is itself a wrong direction.
    """

    name: str
    value: float
    feedback: str
    _: KW_ONLY
    unit: str | None = None
    direction: str | None = None
    kind: str = ""
    keeps: tuple[str, ...] | None = None
    credited: str = ""
    see: str | None = None

    def __post_init__(self):
        _require(math.isfinite(self.value), "value", self.value, "must be a finite number")
        _require(bool(self.feedback.strip()), "feedback", self.feedback, "must not be empty")
        if not self.kind:
            object.__setattr__(self, "kind", "direction" if self.direction else "physics")
        _require(self.kind in marking.MISTAKE_KINDS, "kind", self.kind, f"must be one of {marking.MISTAKE_KINDS}")
        _require(self.keeps is None or set(self.keeps) <= set(marking.ROLES), "keeps", self.keeps,
                 f"must be some of {marking.ROLES}")
        _require(self.keeps is None or bool(self.credited.strip()), "credited", self.credited,
                 f"must cite the published scheme that keeps {self.keeps} for this working (paper, question, words)")

    @property
    def loses(self) -> tuple[str, ...]:
        """The roles of the part's mark lines this mistake loses."""
        if self.keeps is not None:
            # a value's mistake leaves the direction to the direction chosen (the engine's
            # directionWrong); only a wrong direction loses that role by itself
            return tuple(role for role in marking.ROLES if role not in self.keeps
                         and (role != "direction" or self.direction is not None))
        return marking.mistake_losses(self.kind)


@dataclass(frozen=True)
class Alternative:
    """A value the mark scheme also accepts for a part (SI units): a scheme's "allow" value
    ("allow 0.89"), a second route's ("allow 4500 or 4600 for either method"), or what the
    scheme's own rounded working gives ("7.2 or 7.4 from rounded values of F"; see
    ``from_rounded``). It earns every line the key earns (the outcome "alternative") on the
    site, and the sheets' keys and Moodle accept it too.

    why: where the value comes from, for the feedback and the key ("the force from the change
    in momentum rounded to 1.3 N s"). paper: the published scheme that allows it, cited with
    its words ("9702/21/M/J/22 Q2(c)(ii): allow 7.2 N m or 7.4 N m from rounded values of F");
    empty only for what the book derives itself (Question.scheme_alternatives).
    """

    value: float
    why: str
    _: KW_ONLY
    paper: str = ""

    def __post_init__(self):
        object.__setattr__(self, "value", float(self.value))
        _require(math.isfinite(self.value), "value", self.value, "must be a finite number")
        _require(bool(self.why.strip()), "why", self.why, "must say where the value comes from")

    @classmethod
    def from_rounded(cls, route: Callable[..., float], intermediates: tuple[float, ...],
                     sig_figs: int | tuple[int | None, ...], *, why: str, paper: str) -> Alternative:
        """The value a scheme's route gives from its own rounded intermediates ("650 / 5.5"):
        ``route`` (the model's own function of the intermediates, in order) called with each
        intermediate (SI, unrounded) rounded to ``sig_figs`` significant figures, one number
        for all or one per intermediate (None: that one is used as it is)."""
        figures = (sig_figs,) * len(intermediates) if isinstance(sig_figs, int) else tuple(sig_figs)
        _require(len(figures) == len(intermediates), "sig_figs", sig_figs,
                 f"must give one precision per intermediate ({len(intermediates)})")
        _require(all(f is None or f >= 1 for f in figures), "sig_figs", sig_figs, "must be 1 or more (or None)")
        rounded = [value if f is None else _round_sf(value, f) for value, f in zip(intermediates, figures, strict=True)]
        return cls(route(*rounded), why, paper=paper)

    @property
    def reason(self) -> str:
        """Why it is accepted, as feedback and the key say it: "why (paper)"."""
        return f"{self.why} ({self.paper})" if self.paper else self.why


@dataclass(frozen=True)
class Step:
    """One intermediate quantity of a part's working, e.g. the rock's mass before its weight.

    value: SI, unrounded; sig_figs: the precision the working prints it with (by default the
    figures the key is trusted to, the rule table's check).
    """

    name: str
    value: float
    unit: str
    sig_figs: int = DEFAULT_CHECK_SIG_FIGS

    def __post_init__(self):
        object.__setattr__(self, "value", float(self.value))
        _require(math.isfinite(self.value), "value", self.value, "must be a finite number")


@dataclass(frozen=True)
class Reading:
    """A value the student reads off the question's graph on the way to a part's answer (a
    time where the line turns, say), unasked by any part of its own: ``value`` is where the
    drawn line is (SI), ``tolerance`` half a small square of the axis it is read on."""

    name: str
    value: float
    tolerance: float

    def __post_init__(self):
        object.__setattr__(self, "value", float(self.value))
        _require(math.isfinite(self.value), "value", self.value, "must be a finite number")
        _require(self.tolerance > 0, "tolerance", self.tolerance,
                 "must be positive: half the smallest grid division of the axis read")


@dataclass(frozen=True)
class Ecf:
    """How a later part follows from earlier ones, for error carried forward.

    formula: a sympy expression of the givens (symbols named as in ``values``) and of
    earlier parts' answers (symbols named by part id: a, b, ...), in SI units. Python
    evaluates it; sympy's JavaScript printer writes the same formula for the browser,
    which marks a later part against the student's own earlier answer.
    """

    formula: sympy.Expr
    values: Mapping[str, float]

    def __post_init__(self):
        names = {symbol.name for symbol in self.formula.free_symbols}
        _require(bool(names & set(PART_IDS)), "formula", self.formula,
                 "must use an earlier part's answer (a, b, ...): else no error is carried")
        unknown = names - set(self.values) - set(PART_IDS)
        clashes = sorted(set(self.values) & set(PART_IDS))
        _require(not clashes, "values", dict(self.values),
                 f"names {clashes}, which are part ids (a, b, ...): give a given a longer name")
        _require(not unknown, "formula", self.formula, f"uses {sorted(unknown)}, which are not in values")

    @property
    def uses(self) -> tuple[str, ...]:
        """The earlier parts the formula reads."""
        return tuple(sorted(s.name for s in self.formula.free_symbols if s.name in PART_IDS))

    def evaluate(self, answers: Mapping[str, float]) -> float:
        known = {**self.values, **{part: answers[part] for part in self.uses}}
        names, function = _as_function(self.formula)
        return float(function(*(known[name] for name in names)))

    def browser_data(self) -> dict:
        symbols = sorted(s.name for s in self.formula.free_symbols)
        return {"js": sympy.jscode(self.formula), "args": symbols, "uses": list(self.uses),
                "values": {name: self.values[name] for name in symbols if name not in PART_IDS}}


@cache
def _as_function(formula: sympy.Expr) -> tuple[list[str], Callable]:
    """A formula as a plain Python function of its symbols, sorted by name. sympy's
    substitution is slow, and every variant of a template checks the same formula: it is
    written once per formula, not once per variant."""
    names = sorted(s.name for s in formula.free_symbols)
    return names, sympy.lambdify([sympy.Symbol(name) for name in names], formula, "math")


def _round_sf(value: float, sig_figs: int) -> float:
    return float(round_number(value, sig_figs))


@dataclass(frozen=True)
class Part(PartKind):
    """One answer box: prompt, answer (SI units) and how to mark it.

    unit: the SI unit the answer is in, as typed ("N s", "m s^-2"); units: every usual
    form, for messages. min_sig_figs: fewer is marked "give more significant figures".
    shown_sig_figs: the precision the key prints (the notes' precision).
    direction: "none" (a size), "signed" (positive is ``positive``) or "choice" (a size
    plus one of ``choices``; the right one is ``answer_direction``). sign_means: for a
    size, what a minus sign would say (e.g. "backwards"), when the signed form is right too.
    allow_minus: for a size whose scheme says "allow −X" or "ignore sign" where no direction
    is asked, the scheme cited with its words ("9702/21/M/J/22 Q1(b)(ii): = (–) 48 N s"): a
    minus sign then earns every line (the outcome "ignore-sign"); without it a minus sign on a
    size loses the A1 (CLARIFICATIONS, Papers).
    asks: what the part asks for (ASKS); only "show that", "explain" and "state" earn M1.
    working: the intermediate values, and answer_from: the answer as a function of them
    (in order); with both, ``rounded_part_way`` lists what rounding them early gives.
    answer_for_g: the answer as a function of g, for a part whose answer depends on g;
    it adds the named mistake "used g = 10 m s⁻²" (G_TEN_SLIP: loses only the A1) and the
    g = 9.8 slip. Every part whose answer uses g must give it (tests/no_site/test_allowances.py rebuilds
    the bank with g = 10 and finds any that does not); where readings of a graph within half a
    small square give the g = 10 answer too, it is right and no slip is named.
    alternatives (Alternative, each with its paper) and allow_minus: what the part's scheme
    allows beyond the key; a named mistake's ``keeps`` with ``credited``: the lines a scheme
    credits in a wrong answer. Each earns on the site, prints in the keys and grades in Moodle.
    """

    prompt: str
    value: float
    unit: str
    quantity: str
    _: KW_ONLY
    units: str = ""
    shown_sig_figs: int = DEFAULT_MIN_SIG_FIGS  # by default the figures the A1 needs
    min_sig_figs: int = DEFAULT_MIN_SIG_FIGS
    check_sig_figs: int = DEFAULT_CHECK_SIG_FIGS
    direction: str = "none"
    positive: str = ""
    choices: tuple[str, ...] = ()
    answer_direction: str = ""
    direction_hint: str = ""
    sign_means: str = ""
    mistakes: tuple[Mistake, ...] = ()
    revisit: str = ""
    #: The section of the book a wrong answer sends the student to (an id of the bank's sections).
    see: str | None = None
    asks: str = "calculate"
    working: tuple[Step, ...] = ()
    answer_from: Callable[..., float] | None = field(default=None, compare=False, repr=False)
    answer_for_g: Callable[[float], float] | None = field(default=None, compare=False, repr=False)
    ecf: Ecf | None = None
    #: Other valid methods for error carried forward (e.g. the tension from the hanging mass
    #: as well as from the block): each is tried in turn.
    ecf_also: tuple[Ecf, ...] = ()
    #: Values the scheme also accepts, each with the paper that allows it: its "allow" values,
    #: its second routes', and a route's from the scheme's own rounded intermediate
    #: (Alternative.from_rounded). A range's ends are not needed: see GraphPart and readings.
    alternatives: tuple[Alternative, ...] = ()
    allow_minus: str = ""
    #: The values read off the question's graph that the answer is worked from, and the answer as
    #: a function of them (in order; the model's own function): every answer that readings
    #: within half a small square give is right (``band``).
    readings: tuple[Reading, ...] = ()
    answer_from_readings: Callable[..., float] | None = field(default=None, compare=False, repr=False)
    kind: ClassVar[str] = "numeric"
    has_value: ClassVar[bool] = True
    mock_paper: ClassVar[str] = "2"
    browser_script: ClassVar[str] = str(SCRIPTS / "numeric.js")
    #: What Moodle's question adds to the prompt (a reading says it is read from the graph).
    moodle_how: ClassVar[str] = ""

    def __post_init__(self):
        object.__setattr__(self, "value", float(self.value))
        _require(math.isfinite(self.value), "value", self.value, "must be a finite number")
        _require(self.direction in DIRECTION_MODES, "direction", self.direction,
                 f"must be one of {DIRECTION_MODES}")
        _require(self.direction == "signed" or self.value >= 0, "value", self.value,
                 "must be a size (>= 0) unless direction is 'signed'")
        _require(self.direction != "signed" or bool(self.positive), "positive", self.positive,
                 "must say which way is positive for a signed part")
        _require(self.direction != "choice" or self.answer_direction in self.choices,
                 "answer_direction", self.answer_direction, f"must be one of choices={self.choices}")
        _require(1 <= self.min_sig_figs <= self.check_sig_figs, "min_sig_figs", self.min_sig_figs,
                 f"must be between 1 and check_sig_figs={self.check_sig_figs}")
        _require(bool(self.revisit.strip()), "revisit", self.revisit,
                 "must name the idea to revisit after a wrong answer")
        _require(self.asks in ASKS, "asks", self.asks, f"must be one of {ASKS}")
        _require(not self.sign_means or self.direction == "none", "sign_means", self.sign_means,
                 "is only for a part that asks for a size (direction 'none')")
        _require(not self.allow_minus or self.direction == "none", "allow_minus", self.allow_minus,
                 "is only for a part that asks for a size (direction 'none'); where the direction is "
                 "asked separately a minus sign is ignored anyway")
        _require((self.answer_from is None) == (not self.working), "working", self.working,
                 "and answer_from go together")
        _require(not self.ecf_also or self.ecf is not None, "ecf_also", self.ecf_also,
                 "needs ecf, the first method, too")
        if self.answer_from is not None:
            # The working must lead to the answer, or "rounded part-way" would be a guess.
            worked = self.answer_from(*(step.value for step in self.working))
            _require(math.isclose(worked, self.value, rel_tol=1e-9, abs_tol=1e-12), "answer_from",
                     worked, f"must give the part's value {self.value!r} from the working")
        _require((self.answer_from_readings is None) == (not self.readings), "readings", self.readings,
                 "and answer_from_readings go together")
        if self.readings:
            # one source: the readings, exact, give the key
            read = self._size(self.answer_from_readings(*(r.value for r in self.readings)))
            _require(math.isclose(read, self.value, rel_tol=1e-9, abs_tol=1e-12), "answer_from_readings",
                     read, f"must give the part's value {self.value!r} from the readings as drawn")
        if self.answer_for_g is not None:
            at_981 = self.answer_for_g(G_EARTH)
            _require(math.isclose(at_981, self.value, rel_tol=1e-9), "answer_for_g", at_981,
                     f"must give the part's value {self.value!r} at g = {G_EARTH}")
            g_ten = Mistake(
                G_TEN_SLIP, self._size(self.answer_for_g(G_TEN)),
                "You used g = 10 m s⁻². The data give g = 9.81 m s⁻²: with 10 the answer "
                "is out in the second significant figure, which loses the accuracy mark (A1).",
                kind="slip")
            # worked from readings of a graph, a g = 10 answer that readings within half a small
            # square give too is right (Part.band): no slip is named then
            if not self._band_holds(g_ten.value):
                object.__setattr__(self, "mistakes", (*self.mistakes, g_ten))
        for mistake in self.mistakes:
            _require(mistake.direction is None or mistake.direction in self.choices,
                     "mistake.direction", mistake.direction, f"must be one of choices={self.choices}")
        self._check_mistakes_differ()
        self._check_alternatives()

    def _check_alternatives(self) -> None:
        """An accepted value the marker could not tell from a named mistake at check_sig_figs
        would take that mistake's marks or its own by the order of the checks: refused."""
        for alternative in self.alternatives:
            typed = number(self._size(alternative.value), self.check_sig_figs)
            clash = [m.name for m in self.mistakes if m.unit is None and m.direction is None
                     and number(self._size(m.value), self.check_sig_figs) == typed]
            _require(not clash, "alternatives", alternative,
                     f"gives {typed}, as the named mistake {clash} does: the marker could not tell them apart")

    def _check_mistakes_differ(self) -> None:
        """The marker names the first mistake a typed value matches at check_sig_figs, so two
        named mistakes (or, for a signed part, a mistake and the sign slip) must differ there."""
        seen: dict[str, str] = {}
        slip = number(-self.value, self.check_sig_figs) if self.direction == "signed" else None
        for mistake in self.mistakes:
            if mistake.unit is not None or mistake.direction is not None:
                continue
            typed = number(self._size(mistake.value), self.check_sig_figs)
            _require(typed not in seen, "mistakes", mistake.name,
                     f"gives {typed}, as '{seen.get(typed)}' does: the marker could not tell them apart")
            _require(typed != slip or self.value == 0, "mistakes", mistake.name,
                     f"gives {typed}, the right answer with the wrong sign: the marker could not "
                     "tell it from a sign slip")
            seen[typed] = mistake.name

    def _size(self, value: float) -> float:
        return value if self.direction == "signed" else abs(value)

    def _accepted(self, value: float) -> bool:
        """The marker takes value, typed to 3 s.f., as right (it trusts the key to 3 s.f.)."""
        return number(value, self.check_sig_figs) == number(self.value, self.check_sig_figs)

    def _allowed(self, value: float) -> bool:
        """The marker takes value, typed to 3 s.f., as a value the scheme also accepts."""
        typed = number(self._size(value), self.check_sig_figs)
        return any(number(self._size(a.value), self.check_sig_figs) == typed for a in self.alternatives)

    def _named(self, value: float) -> bool:
        return any(m.unit is None and m.direction is None
                   and number(m.value, self.check_sig_figs) == number(value, self.check_sig_figs)
                   for m in self.mistakes)

    @cached_property
    def band(self) -> tuple[float, float] | None:
        """The answers that readings within half a small square give, lowest and highest (SI;
        None for a part worked from no reading). A reading carried into a later part keeps its
        tolerance there: the 9702 Paper 3 specimen scheme (for examination from 2016), Q1's
        y-intercept, takes a "read-off ... substituted into y = mx + c" that is "accurate to half
        a small square in both x and y directions", and 9702/23/M/J/16 Q3(b)(ii) marks a worked
        answer "(allow ± ½ small square in readings) A1". The extremes are sought at the corners
        and the middles of the readings' box (the bank's formulas are monotonic in each reading
        there, so its ends are at corners)."""
        if not self.readings:
            return None
        steps = [(r.value - r.tolerance, r.value, r.value + r.tolerance) for r in self.readings]
        answers = [self._size(self.answer_from_readings(*box)) for box in itertools.product(*steps)]
        return (min(answers), max(answers))

    def _band_holds(self, value: float) -> bool:
        """Whether the answers readings within half a small square give hold value, or it
        written to 2 s.f. (variants.confusable_mistakes refuses a named mistake there)."""
        if self.band is None:
            return False
        typed = float(round_number(value, DEFAULT_MIN_SIG_FIGS)) if value else 0.0
        return self.band[0] <= value <= self.band[1] or self.band_takes(typed, DEFAULT_MIN_SIG_FIGS)

    def band_takes(self, typed: float, sig_figs: int) -> bool:
        """Whether a value written to sig_figs s.f. could be an answer from readings within the
        band, rounded (the browser's twin: question-kinds/numeric.js, withinBand)."""
        if self.band is None or typed == 0:
            return False
        low, high = self.band
        half = 5 * 10.0 ** (math.floor(math.log10(abs(typed))) - sig_figs)
        slack = 1e-9 * max(abs(low), abs(high))
        return typed - half <= high + slack and typed + half >= low - slack

    @property
    def ecf_methods(self) -> tuple[Ecf, ...]:
        """Every valid method that carries an earlier answer forward to this part."""
        return () if self.ecf is None else (self.ecf, *self.ecf_also)

    @property
    def g_nine_eight(self) -> float | None:
        """The answer with g = 9.8 m s⁻², when the marker would not already accept it."""
        if self.answer_for_g is None:
            return None
        value = self._size(self.answer_for_g(G_NINE_EIGHT))
        taken = self._accepted(value) or self._named(value) or self._allowed(value) or self._band_holds(value)
        return None if taken else value

    @property
    def rounded_part_way(self) -> tuple[tuple[float, str], ...]:
        """(answer, what was rounded) for each way of rounding the working to 2 or 3 s.f.
        early that the marker would not accept as right and that is no named mistake (nor
        the g = 9.8 slip, which the marker names first)."""
        if self.answer_from is None:
            return ()
        found: dict[str, tuple[float, str]] = {}
        # The marker says "g = 9.8" first for that value: it is no rounding to report.
        g_slip = None if self.g_nine_eight is None else number(self.g_nine_eight, self.check_sig_figs)
        indices = range(len(self.working))
        for sig_figs in PART_WAY_SIG_FIGS:
            for size in range(1, len(self.working) + 1):
                for chosen in itertools.combinations(indices, size):
                    values = [_round_sf(step.value, sig_figs) if i in chosen else step.value
                              for i, step in enumerate(self.working)]
                    answer = self._size(self.answer_from(*values))
                    key = number(answer, self.check_sig_figs)
                    if (self._accepted(answer) or self._named(answer) or self._allowed(answer) or key in found
                            or key == g_slip):
                        continue
                    what = " and ".join(
                        f"the {self.working[i].name} to {number(values[i], sig_figs)}"
                        f"{' ' if self.working[i].unit != '°' else ''}{unit_text(self.working[i].unit)}"
                        for i in chosen)
                    found[key] = (answer, what)
        return tuple(found.values())

    @property
    def answer_text(self) -> str:
        """The answer as the key prints it (plain text), e.g. "11.6 m s⁻² upwards"."""
        space = "" if self.unit in ("°", "") else " "  # a ratio ("") has no unit
        text = f"{format_number(self.value, self.shown_sig_figs)}{space}{unit_text(self.unit)}"
        if self.direction == "choice":
            text += f" {self.answer_direction}"
        if self.direction == "signed":
            text += f" (positive: {self.positive})"
        return text

    def browser_data(self, part_id: str) -> dict:
        """What the marking script needs (JSON-ready)."""
        return {
            "id": part_id, "prompt": self.prompt, "value": self.value, "unit": self.unit,
            "units": unit_text(self.units or self.unit), "quantity": self.quantity,
            "minSf": self.min_sig_figs, "checkSf": self.check_sig_figs,
            "direction": self.direction, "positive": self.positive, "choices": list(self.choices),
            "answerDirection": self.answer_direction, "directionHint": self.direction_hint,
            "signMeans": self.sign_means, "allowMinus": self.allow_minus,
            "revisit": self.revisit, "see": self.see,
            "mistakes": [
                {"name": m.name, "value": m.value, "unit": m.unit, "direction": m.direction,
                 "feedback": m.feedback, "loses": list(m.loses), "see": m.see}
                for m in self.mistakes
            ],
            "alternatives": [{"value": a.value, "why": a.reason} for a in self.alternatives],
            # the answers that readings within half a small square give (only where read)
            **({"band": list(self.band)} if self.readings else {}),
            "gNineEight": self.g_nine_eight,
            "roundedPartWay": [{"value": value, "rounded": what} for value, what in self.rounded_part_way],
            "ecf": [method.browser_data() for method in self.ecf_methods], "kind": self.kind,
        }

    # ------------------------------------------------------- the kind's hooks (parts/__init__.py)

    @classmethod
    def form_html(cls, part: dict, question: dict, *, base: str, label: str, page: dict) -> str:
        """Boxes for the value, its unit (and its direction), the feedback, and help by steps."""
        hint = not page.get("unit-hint")
        page["unit-hint"] = True  # the hint is under the page's first unit box only
        return _value_boxes(base, part, label, hint) + feedback_html(base) + _help_html(label)

    def print_lines(self, label: str, marks: int, paper) -> list:
        """A dotted line for the value (and its direction), drawn by the question sheet from its data."""
        line = f"{label}{self.prompt} = " + "." * 28
        if self.direction == "choice":
            line += " direction: " + "." * 16
        # the question sheet draws its own line from this data (book/_latex/latex_question_sheets.py)
        return [paper.line(line + f" [{marks}]", classes=["q-answer-line"], prompt=f"{label}{self.prompt}",
                           marks=marks, direction=self.direction == "choice")]

    def working_cm(self, marks: int, sheet) -> float:
        """The working space a sheet leaves above the answer line."""
        return sheet.WORKING_CM_PER_MARK * marks

    def latex_sheet(self, question, index: int, marks: int, sheet) -> str:
        tex = sheet.tex
        space = self.working_cm(marks, sheet)
        line = f"{tex(question.label(index) + self.prompt)} = \\answerline{{4.2cm}}\\ {tex(unit_text(self.unit))}"
        if self.direction == "choice":
            line += "\\par\\nopagebreak\\vspace{6pt}\\hfill direction: \\answerline{4.2cm}\\hspace{2.5em}"
        return (f"\\par\\needspace{{{format_number(space + 1.2, decimals=1)}cm}}"
                f"\\vspace{{{format_number(space, decimals=1)}cm}}\n"
                f"\\needspace{{3\\baselineskip}}{line}\\partmarks{{{marks}}}\\par")

    def latex_key(self, question, index: int, marks: int, sheet) -> list[str]:
        tex = sheet.tex
        label = question.label(index) or "Answer "
        out = [(f"\\textbf{{{tex(label)}{tex(self.prompt)} = {tex(self.answer_text)}}}{tex(sheet.accept_note(self))} "
                f"\\hfill [{marks}]")]
        if self.working:
            out.append(tex(sheet.working_text(self)))
        note = sheet.ecf_note(question, index)
        if note:
            out.append("\\emph{" + tex(note) + "}")
        rows = sheet.wrong_answers(question, index)
        if rows:
            items = "\n".join(f"\\item \\textbf{{{tex(row.written)}}}: \\emph{{{tex(row.name)}}} "
                              f"(\\textbf{{{tex(row.marks)}}}). {tex(row.feedback)}" for row in rows)
            out.append("\\textbf{Common wrong answers} (the mistake each shows, and what it scores)\n"
                       "{\\small\\begin{itemize}[leftmargin=1.5em,itemsep=1pt,topsep=2pt]\n"
                       + items + "\n\\end{itemize}}")
        return out

    def html_sheet(self, question, index: int, marks: int, sheet) -> str:
        marks_html = sheet.marks_html
        prompt = prompt_html(question.label(index) + self.prompt)
        direction = ('<p class="sb-answer">direction: <span class="sb-blank"></span></p>'
                     if self.direction == "choice" else "")
        return (f'<div class="sb-part"><div class="sb-working" style="height: {self.working_cm(marks, sheet):g}cm"></div>'
                f'<p class="sb-answer">{prompt} = <span class="sb-blank"></span> {prompt_html(unit_text(self.unit))} '
                f"{marks_html(marks)}</p>{direction}</div>")

    def html_key(self, question, index: int, marks: int, sheet) -> str:
        marks_html = sheet.marks_html
        label = question.label(index) or "Answer "
        out = [(f'<p class="sb-key-answer"><strong>{prompt_html(label + self.prompt)} = '
                f"{prompt_html(self.answer_text)}</strong>{prompt_html(sheet.accept_note(self))} {marks_html(marks)}</p>")]
        if self.working:
            out.append(f"<p>{prompt_html(sheet.working_text(self))}</p>")
        note = sheet.ecf_note(question, index)
        if note:
            out.append(f"<p><em>{prompt_html(note)}</em></p>")
        rows = sheet.wrong_answers(question, index)
        if rows:
            items = "".join(f"<li><strong>{prompt_html(row.written)}</strong>: <em>{prompt_html(row.name)}</em> "
                            f'(<strong class="sb-kept">{prompt_html(row.marks)}</strong>). '
                            f"{prompt_html(row.feedback)}</li>" for row in rows)
            out.append("<p><strong>Common wrong answers</strong> (the mistake each shows, and what it scores)</p>"
                       f'<ul class="sb-wrong">{items}</ul>')
        return "".join(out)

    def moodle(self, out, item, question, index: int) -> None:
        """A numerical question; with a direction to choose, a Cloze question (size and direction)."""
        unit = escape(unit_text(self.unit), quote=False)  # Moodle's text: no tie between number and unit
        if self.direction == "choice":
            out.cloze(item.name, item.idnumber, item.stem + item.ask + f"{self.moodle_how}. Type the size as a "
                      f"number in {unit} and choose the direction.</p>", item.marks, item.general, item.files,
                      question, index)
            return
        sign = f" Give a signed value: positive is {escape(self.positive, quote=False)}." if self.direction == "signed" else ""
        typing = f"Type the number and its unit ({unit})" if self.unit else "Type the number as a decimal (it has no unit)"
        out.numerical(item.name, item.idnumber, item.stem + item.ask + f"{self.moodle_how}.{sign} {typing}.</p>",
                      item.marks, item.general, item.files, question, index)


def _value_boxes(base: str, part: dict, label: str, hint: bool) -> str:
    feedback, html = f"{base}-feedback", []
    if part["direction"] == "signed":
        # the span is what question-relabel.js rewrites with another variant's words
        html.append(f'<p class="q-note" id="{base}-note">Give a signed value: positive is '
                    f'<span class="q-positive">{prompt_html(part["positive"])}</span>.</p>')
        feedback += f" {base}-note"
    html.append('<div class="q-fields">')
    html.append(input_html("q-value", f"{base}-value", escape(field_label(label, "Value")), feedback))
    html.append(input_html("q-unit", f"{base}-unit", escape(field_label(label, "Unit")),
                           f"{base}-unit-hint {feedback}" if hint else feedback))
    if part["direction"] == "choice":
        options = "".join(f'<option value="{escape(c)}">{escape(c)}</option>' for c in part["choices"])
        html.append(f'<label class="q-field" for="{base}-direction"><span>'
                    f'{escape(field_label(label, "Direction"))}</span>'
                    f'<select class="q-direction" id="{base}-direction" aria-describedby="{feedback}">'
                    f'<option value="">Choose…</option>{options}</select></label>')
    html.append("</div>")
    if hint:
        html.append(f'<p class="q-unit-hint" id="{base}-unit-hint">{escape(UNIT_HINT)}</p>')
    return "".join(html)


def _help_html(label: str) -> str:
    """Help before the answer (static/help-steps.js): the steps of the working shown so far,
    read out as each comes (a polite live region), and the button that shows the next; the
    script fills both from the question's data, and New numbers changes them."""
    name = escape(field_label(label, "Steps of the working"))
    return (f'<div class="q-help"><ol class="q-steps" aria-live="polite" aria-label="{name}"></ol>'
            '<button type="button" class="q-step">Show a step</button></div>')
