# ruff: noqa: RUF001  (feedback is typeset text: true minus, times and Greek letters)
"""The question schema: questions that mark like an examiner, computed from the models.

The questions themselves live in the bank (physics_figures/bank/, one module per question
type), each a ``Template`` whose ``build(**givens)`` returns a ``Question``: its text (in
the text format of physics_figures.textformat), the numbers the text states
(``givens``), one ``Part`` per answer box, and the mark scheme. Each part knows its answer
(SI units, from the models), the unit, how many significant figures it needs, whether
direction matters, and its named mistakes: the classic wrong methods, each worked from
the same inputs, each with feedback that names the mistake and the idea to revisit. The
browser marks with this data (book/_ext/questions/static/questions.js); the answer key
prints it.

Mark-scheme lines are in the text format too. Each names the part it belongs to and its
Cambridge code: C1 for a calculation step (compensatory: a right final answer earns it
without the working), M1 and a dependent A1 only where a part asks to show that, explain
or state a principle, A1 for the answer, B1 for a single point.

A part also keeps its working (``Step`` values) and how the answer follows from them, so
the answers that rounding part-way through would give are computed here, and the browser
says "rounded part-way" only for those. A part whose answer depends on g names the g = 10
mistake and the g = 9.8 slip from the same formula. A later part that uses an earlier
part's answer carries an ``Ecf`` formula, so a wrong earlier answer is carried forward.
"""

from __future__ import annotations

import itertools
import math
import re
from collections.abc import Callable, Mapping
from dataclasses import KW_ONLY, dataclass, field
from functools import cached_property
from typing import ClassVar

import sympy

from . import marking, textformat
from .constants import G_EARTH
from .notation import format_number, round_number

#: How a part treats direction: a size only, a signed value along a stated positive
#: direction, or a size plus a direction chosen from a list.
DIRECTION_MODES = ("none", "signed", "choice")
#: Cambridge 9702 accepts 2 or more significant figures unless a question says otherwise;
#: the key is trusted to 3 s.f., so an answer worked with intermediates rounded to 3 s.f.
#: still agrees with it (the rule table, marking_rules.json).
DEFAULT_MIN_SIG_FIGS = marking.rules()["sig_figs"]["min"]
DEFAULT_CHECK_SIG_FIGS = marking.rules()["sig_figs"]["check"]
MARK_CODES = ("C1", "M1", "A1", "B1", "")
#: What a part asks for. M1 (with its dependent A1) belongs only to the last three: a plain
#: calculation earns C1 for its steps and A1 for its answer.
ASKS = ("calculate", "show that", "explain", "state")
#: Rounding an intermediate value to these significant figures is "rounding part-way".
PART_WAY_SIG_FIGS = (2, 3)
#: The values of g students use instead of the data's 9.81 m s^-2.
G_TEN, G_NINE_EIGHT = 10.0, 9.8

_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


#: A question's parts are (a), (b), ...; an ecf formula names earlier answers by these ids.
PART_IDS = tuple("abcdefghij")


def number(value: float, sig_figs: int) -> str:
    """A value as the book writes it, e.g. number(686.7, 3) -> "687" (notation.format_number)."""
    return format_number(value, sig_figs)


def unit_text(unit: str) -> str:
    """A unit for plain text: "m s^-1" -> "m s⁻¹"."""
    return re.sub(r"\^(-?\d+)", lambda m: m.group(1).translate(_SUPERSCRIPT), unit)


def _require(ok: bool, name: str, value, rule: str) -> None:
    if not ok:
        raise ValueError(f"{name} {rule} (got {name}={value!r})")


@dataclass(frozen=True)
class Given:
    """A number the question's text states, as it is written there (e.g. 5.0 N)."""

    name: str
    value: float
    unit: str
    sig_figs: int

    @property
    def text(self) -> str:
        """The number as the question prints it, e.g. "5.0"."""
        return number(self.value, self.sig_figs)


@dataclass(frozen=True)
class Mistake:
    """A classic wrong answer, computed from the question's inputs.

    value: what the wrong method gives, in SI units (signed for a signed part, else a
    size). unit: only when the mistake gives another quantity (e.g. "J" for kinetic
    energy instead of momentum). direction: only when the mistake is a wrong direction.
    feedback: names the mistake and the idea to revisit (plain text).
    kind: what the mistake is, for the marks it keeps (marking_rules.json): "slip" (g = 10,
    a power-of-ten or prefix slip: keeps the C1 and M1), "direction" (keeps all but the
    direction's mark; the default when ``direction`` is set) or "physics" (a wrong formula or
    idea: keeps nothing; the default otherwise). keeps: the roles it keeps where a published
    scheme says otherwise than its kind ("method", "answer", "direction").
    """

    name: str
    value: float
    feedback: str
    _: KW_ONLY
    unit: str | None = None
    direction: str | None = None
    kind: str = ""
    keeps: tuple[str, ...] | None = None

    def __post_init__(self):
        _require(math.isfinite(self.value), "value", self.value, "must be a finite number")
        _require(bool(self.feedback.strip()), "feedback", self.feedback, "must not be empty")
        if not self.kind:
            object.__setattr__(self, "kind", "direction" if self.direction else "physics")
        _require(self.kind in marking.MISTAKE_KINDS, "kind", self.kind, f"must be one of {marking.MISTAKE_KINDS}")
        _require(self.keeps is None or set(self.keeps) <= set(marking.ROLES), "keeps", self.keeps,
                 f"must be some of {marking.ROLES}")

    @property
    def loses(self) -> tuple[str, ...]:
        """The roles of the part's mark lines this mistake loses."""
        if self.keeps is not None:
            return tuple(role for role in marking.ROLES if role not in self.keeps)
        return marking.mistake_losses(self.kind)


@dataclass(frozen=True)
class Alternative:
    """A value the mark scheme also accepts for a part (SI units): from another valid route
    ("4500 or 4600"), or what the scheme's own rounded working gives. ``why`` says which, for
    the feedback."""

    value: float
    why: str

    def __post_init__(self):
        object.__setattr__(self, "value", float(self.value))
        _require(math.isfinite(self.value), "value", self.value, "must be a finite number")
        _require(bool(self.why.strip()), "why", self.why, "must say where the value comes from")


@dataclass(frozen=True)
class Step:
    """One intermediate quantity of a part's working, e.g. the rock's mass before its weight.

    value: SI, unrounded; sig_figs: the precision the working prints it with.
    """

    name: str
    value: float
    unit: str
    sig_figs: int = 3

    def __post_init__(self):
        object.__setattr__(self, "value", float(self.value))
        _require(math.isfinite(self.value), "value", self.value, "must be a finite number")


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

    @cached_property
    def _function(self):
        """The formula as a plain Python function of its symbols, sorted by name (sympy's
        substitution is slow, and every variant is checked with it)."""
        names = sorted(s.name for s in self.formula.free_symbols)
        return names, sympy.lambdify([sympy.Symbol(name) for name in names], self.formula, "math")

    def evaluate(self, answers: Mapping[str, float]) -> float:
        known = {**self.values, **{part: answers[part] for part in self.uses}}
        names, function = self._function
        return float(function(*(known[name] for name in names)))

    def browser_data(self) -> dict:
        symbols = sorted(s.name for s in self.formula.free_symbols)
        return {"js": sympy.jscode(self.formula), "args": symbols, "uses": list(self.uses),
                "values": {name: self.values[name] for name in symbols if name not in PART_IDS}}


def _round_sf(value: float, sig_figs: int) -> float:
    return float(round_number(value, sig_figs))


@dataclass(frozen=True)
class Part:
    """One answer box: prompt, answer (SI units) and how to mark it.

    unit: the SI unit the answer is in, as typed ("N s", "m s^-2"); units: every usual
    form, for messages. min_sig_figs: fewer is marked "give more significant figures".
    shown_sig_figs: the precision the key prints (the notes' precision).
    direction: "none" (a size), "signed" (positive is ``positive``) or "choice" (a size
    plus one of ``choices``; the right one is ``answer_direction``). sign_means: for a
    size, what a minus sign would say (e.g. "backwards"), when the signed form is right too.
    asks: what the part asks for (ASKS); only "show that", "explain" and "state" earn M1.
    working: the intermediate values, and answer_from: the answer as a function of them
    (in order); with both, ``rounded_part_way`` lists what rounding them early gives.
    answer_for_g: the answer as a function of g, for a part whose answer depends on g;
    it adds the named mistake "used g = 10 m s⁻²" and the g = 9.8 slip.
    """

    prompt: str
    value: float
    unit: str
    quantity: str
    _: KW_ONLY
    units: str = ""
    shown_sig_figs: int = 2
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
    asks: str = "calculate"
    working: tuple[Step, ...] = ()
    answer_from: Callable[..., float] | None = field(default=None, compare=False, repr=False)
    answer_for_g: Callable[[float], float] | None = field(default=None, compare=False, repr=False)
    ecf: Ecf | None = None
    #: Other valid methods for error carried forward (e.g. the tension from the hanging mass
    #: as well as from the block): each is tried in turn.
    ecf_also: tuple[Ecf, ...] = ()
    #: Values the scheme also accepts (another route, a range's ends are not needed: see GraphPart).
    alternatives: tuple[Alternative, ...] = ()
    kind: ClassVar[str] = "numeric"

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
        _require((self.answer_from is None) == (not self.working), "working", self.working,
                 "and answer_from go together")
        _require(not self.ecf_also or self.ecf is not None, "ecf_also", self.ecf_also,
                 "needs ecf, the first method, too")
        if self.answer_from is not None:
            # The working must lead to the answer, or "rounded part-way" would be a guess.
            worked = self.answer_from(*(step.value for step in self.working))
            _require(math.isclose(worked, self.value, rel_tol=1e-9, abs_tol=1e-12), "answer_from",
                     worked, f"must give the part's value {self.value!r} from the working")
        if self.answer_for_g is not None:
            at_981 = self.answer_for_g(G_EARTH)
            _require(math.isclose(at_981, self.value, rel_tol=1e-9), "answer_for_g", at_981,
                     f"must give the part's value {self.value!r} at g = {G_EARTH}")
            g_ten = Mistake(
                "used g = 10 m s⁻²", self._size(self.answer_for_g(G_TEN)),
                "You used g = 10 m s⁻². The data give g = 9.81 m s⁻²: with 10 the answer "
                "is out in the second significant figure, which loses the accuracy mark (A1).",
                kind="slip")
            object.__setattr__(self, "mistakes", (*self.mistakes, g_ten))
        for mistake in self.mistakes:
            _require(mistake.direction is None or mistake.direction in self.choices,
                     "mistake.direction", mistake.direction, f"must be one of choices={self.choices}")
        self._check_mistakes_differ()

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

    def _named(self, value: float) -> bool:
        return any(m.unit is None and m.direction is None
                   and number(m.value, self.check_sig_figs) == number(value, self.check_sig_figs)
                   for m in self.mistakes)

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
        return None if self._accepted(value) or self._named(value) else value

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
                    if self._accepted(answer) or self._named(answer) or key in found or key == g_slip:
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
        space = "" if self.unit == "°" else " "
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
            "signMeans": self.sign_means,
            "revisit": self.revisit,
            "mistakes": [
                {"name": m.name, "value": m.value, "unit": m.unit, "direction": m.direction,
                 "feedback": m.feedback, "loses": list(m.loses)}
                for m in self.mistakes
            ],
            "alternatives": [{"value": a.value, "why": a.why} for a in self.alternatives],
            "gNineEight": self.g_nine_eight,
            "roundedPartWay": [{"value": value, "rounded": what} for value, what in self.rounded_part_way],
            "ecf": [method.browser_data() for method in self.ecf_methods], "kind": self.kind,
        }


def reading_places(tolerance: float) -> int:
    """Decimal places a reading is written to: those of a small square, twice the tolerance
    (0.5 -> 1, 0.05 -> 2, 20 -> 0)."""
    division = 2 * tolerance
    for places in range(7):
        if math.isclose(division * 10**places, round(division * 10**places), abs_tol=1e-9):
            return places
    return 7


@dataclass(frozen=True)
class GraphPart(Part):
    """A value read from the question's graph. It is right within ``tolerance`` (SI) either
    way, half the smallest grid division along the axis read, as the question states; a
    reading needs no particular number of significant figures."""

    tolerance: float = field(default=0.0, kw_only=True)
    min_sig_figs: int = field(default=1, kw_only=True)
    kind: ClassVar[str] = "graph"

    def __post_init__(self):
        _require(self.tolerance > 0, "tolerance", self.tolerance,
                 "must be positive: half the smallest grid division of the axis read")
        # the key prints to the places of a small square (12.5 on squares of 0.5, 240 on 20s)
        whole_digits = math.floor(math.log10(abs(self.value))) + 1 if self.value else 1
        object.__setattr__(self, "shown_sig_figs", max(1, whole_digits + reading_places(self.tolerance)))
        super().__post_init__()

    @property
    def band(self) -> tuple[float, float]:
        """The readings the marker takes as right."""
        return (self.value - self.tolerance, self.value + self.tolerance)

    def _accepted(self, value: float) -> bool:
        low, high = self.band
        return low - 1e-9 * abs(self.tolerance) <= value <= high + 1e-9 * abs(self.tolerance)

    def _check_mistakes_differ(self) -> None:
        """Each named mistake must lie outside the key's band and outside each other's."""
        plain = [m for m in self.mistakes if m.unit is None and m.direction is None]
        for mistake in plain:
            _require(not self._accepted(self._size(mistake.value)), "mistakes", mistake.name,
                     f"gives {mistake.value!r}, within the reading's tolerance {self.tolerance!r} "
                     f"of the key {self.value!r}: the marker could not tell them apart")
        for first, second in itertools.combinations(plain, 2):
            _require(abs(first.value - second.value) > 2 * self.tolerance, "mistakes", second.name,
                     f"is within two tolerances of '{first.name}': the marker could not tell them apart")

    def browser_data(self, part_id: str) -> dict:
        return {**super().browser_data(part_id), "tolerance": self.tolerance}


@dataclass(frozen=True)
class Graph:
    """A graph that a question prints, drawn from its variant's own numbers: straight lines
    through ``points`` (time in s, value in SI units), on a grid of small squares
    ``time_division`` by ``value_division``. ``name`` says what it is ("momentum-time"),
    ``quantity`` and ``unit`` label the value axis (unit in plain text, e.g. "N s");
    ``shaded`` shades the area under the line (an impulse); ``curve`` says the points are
    close enough to draw a smooth curve."""

    name: str
    quantity: str
    unit: str
    points: tuple[tuple[float, float], ...]
    time_division: float
    value_division: float
    time_max: float
    value_max: float
    value_min: float = 0.0
    shaded: bool = False
    #: Many points close together that draw a smooth curve (e.g. v = v_t tanh(g t / v_t)).
    curve: bool = False

    def __post_init__(self):
        object.__setattr__(self, "points", tuple((float(t), float(v)) for t, v in self.points))
        _require(len(self.points) >= 2, "points", self.points, "must hold at least two points")
        _require(self.time_division > 0 and self.value_division > 0, "time_division",
                 (self.time_division, self.value_division), "and value_division must be positive")
        _require(self.value_min < self.value_max, "value_min", self.value_min,
                 f"must be below value_max={self.value_max}")
        for name, span, division in (("time_max", self.time_max, self.time_division),
                                     ("value_max", self.value_max - self.value_min, self.value_division)):
            count = span / division
            _require(abs(count - round(count)) < 1e-6 and 2 <= round(count) <= 60, name, span,
                     f"must be 2 to 60 whole small squares of {division}")
        times = [t for t, _ in self.points]
        _require(all(b > a for a, b in itertools.pairwise(times)), "points", self.points,
                 "must be in increasing time")
        _require(times[0] >= 0 and times[-1] <= self.time_max + 1e-12, "points", self.points,
                 f"must lie within 0 to time_max={self.time_max} s")
        _require(all(self.value_min - 1e-12 <= v <= self.value_max + 1e-12 for _, v in self.points),
                 "points", self.points, f"must lie within value_min={self.value_min} to value_max={self.value_max}")

    def value_at(self, time: float) -> float:
        """The value the drawn line passes through at ``time`` (what a student reads off)."""
        for (t0, v0), (t1, v1) in itertools.pairwise(self.points):
            if t0 <= time <= t1:
                return v0 + (v1 - v0) * (time - t0) / (t1 - t0)
        raise ValueError(f"time must lie on the drawn line, {self.points[0][0]} to "
                         f"{self.points[-1][0]} s (got time={time!r})")


OPTION_LETTERS = ("A", "B", "C", "D")


@dataclass(frozen=True)
class Option:
    """One option of a multiple-choice part (text format). A wrong option names the mistake or
    misconception it stands for, with the feedback a student gets for choosing it."""

    text: str
    mistake: str = ""
    feedback: str = ""

    def __post_init__(self):
        textformat.parse(self.text)
        _require(bool(self.mistake) == bool(self.feedback), "feedback", self.feedback,
                 "goes with a named mistake: a wrong option has both, the key has neither")


@dataclass(frozen=True)
class ChoicePart:
    """A Paper 1-style multiple-choice part: options A to D, one of them right (``answer``).
    The wrong options are named mistakes worked from the same givens, or named misconceptions."""

    prompt: str
    options: tuple[Option, ...]
    answer: str
    revisit: str
    kind: ClassVar[str] = "mcq"
    asks: ClassVar[str] = "state"
    value: ClassVar[None] = None
    mistakes: ClassVar[tuple] = ()
    direction: ClassVar[str] = "none"
    ecf: ClassVar[None] = None
    ecf_methods: ClassVar[tuple] = ()

    def __post_init__(self):
        _require(len(self.options) == len(OPTION_LETTERS), "options", len(self.options),
                 f"must be {len(OPTION_LETTERS)}, one per letter {OPTION_LETTERS}")
        _require(self.answer in OPTION_LETTERS, "answer", self.answer, f"must be one of {OPTION_LETTERS}")
        for letter, option in zip(OPTION_LETTERS, self.options, strict=True):
            right = letter == self.answer
            _require(right != bool(option.mistake), "options", letter,
                     "must name a mistake for each wrong option and none for the key")
        texts = [textformat.to_plain(o.text) for o in self.options]
        _require(len(set(texts)) == len(texts), "options", texts, "must all differ")
        _require(bool(self.revisit.strip()), "revisit", self.revisit, "must name the idea to revisit")

    @property
    def answer_text(self) -> str:
        return f"{self.answer}: {textformat.to_plain(self.options[OPTION_LETTERS.index(self.answer)].text)}"

    def browser_data(self, part_id: str) -> dict:
        return {"id": part_id, "kind": self.kind, "prompt": self.prompt, "answer": self.answer,
                "revisit": self.revisit,
                "options": [{"letter": letter, "html": textformat.to_html(o.text, paragraphs=False),
                             "mistake": o.mistake, "feedback": o.feedback,
                             **({"loses": list(marking.mistake_losses("physics"))} if o.mistake else {})}
                            for letter, o in zip(OPTION_LETTERS, self.options, strict=True)]}


def choices_in_order(key: float, wrong: dict[str, tuple[float, str]], *, sig_figs: int, unit: str
                     ) -> tuple[tuple[Option, ...], str]:
    """Options for a numerical multiple-choice part, in increasing order as Paper 1 prints them:
    the key and three named mistakes {name: (value, feedback)} worked from the same givens.
    Returns (options, the key's letter)."""
    _require(len(wrong) == len(OPTION_LETTERS) - 1, "wrong", sorted(wrong),
             f"must hold {len(OPTION_LETTERS) - 1} named mistakes")
    space = "" if unit == "°" else " "
    rows = sorted([(key, "", "")] + [(value, name, feedback) for name, (value, feedback) in wrong.items()])
    texts = [f"{format_number(value, sig_figs)}{space}{unit}" for value, _, _ in rows]
    _require(len(set(texts)) == len(texts), "wrong", texts,
             f"must print differently from the key and each other at {sig_figs} s.f.")
    options = tuple(Option(text, name, feedback) for text, (_, name, feedback) in zip(texts, rows, strict=True))
    answer = OPTION_LETTERS[[name for _, name, _ in rows].index("")]
    return options, answer


@dataclass(frozen=True)
class ExplainPart:
    """A describe-and-explain part. The student writes an answer, then ticks the marking points
    of its mark-scheme lines that they made, and scores themselves against them."""

    prompt: str
    model_answer: str
    kind: ClassVar[str] = "explain"
    asks: ClassVar[str] = "explain"
    value: ClassVar[None] = None
    mistakes: ClassVar[tuple] = ()
    direction: ClassVar[str] = "none"
    ecf: ClassVar[None] = None
    ecf_methods: ClassVar[tuple] = ()
    revisit: ClassVar[str] = ""

    def __post_init__(self):
        textformat.parse(self.model_answer)

    @property
    def answer_text(self) -> str:
        return textformat.to_plain(self.model_answer)

    def browser_data(self, part_id: str) -> dict:
        return {"id": part_id, "kind": self.kind, "prompt": self.prompt,
                "model": textformat.to_html(self.model_answer)}


@dataclass(frozen=True)
class Mark:
    """One line of the mark scheme (physics_figures.textformat), the mark it earns and its part(s).

    part: the ids of the parts the line belongs to ("a", or "ab" for working that
    serves two parts); "" in a one-part question means that part. A line of two parts is
    earned in one of them (``Question.owner``), so a right part never shows fewer than its
    own marks. earns: "direction" for the B1 that is a direction's own (it alone is lost
    for a wrong direction); otherwise the line's code says what it earns (marking.py).
    """

    text: str
    code: str = ""
    part: str = ""
    _: KW_ONLY
    earns: str = ""

    def __post_init__(self):
        _require(self.code in MARK_CODES, "code", self.code, f"must be one of {MARK_CODES}")
        _require(not self.earns or self.code == "B1", "earns", self.earns,
                 "is for a B1 line (a direction's own mark); C1, M1 and A1 earn what their code says")
        if self.earns:
            marking.line_roles(self.code, earns=self.earns)  # raises ValueError naming a bad role
        _require("$" not in self.text, "text", self.text,
                 "must be in the text format (m s<sup>−1</sup>, ×, −), not $...$ maths")
        textformat.parse(self.text)  # raises ValueError naming a bad tag


@dataclass(frozen=True)
class Question:
    """A question's data: the numbers its text states, its parts and its mark scheme."""

    key: str
    givens: tuple[Given, ...]
    parts: tuple[Part | GraphPart | ChoicePart | ExplainPart, ...]
    mark_scheme: tuple[Mark, ...]
    #: The question as the student reads it (physics_figures.textformat), for a template;
    #: empty when the page states it (worked examples' try-first parts).
    text: str = ""
    #: The graph the question prints, when a part reads from it (GraphPart).
    graph: Graph | None = None

    def __post_init__(self):
        readings = [p for p in self.parts if p.kind == "graph"]
        _require(bool(readings) == (self.graph is not None), "graph", self.graph,
                 f"goes with a part read from it (GraphPart) in {self.key}: both or neither")
        if self.graph is not None:
            halves = (self.graph.time_division / 2, self.graph.value_division / 2)
            for part in readings:
                _require(any(math.isclose(part.tolerance, h, rel_tol=1e-9) for h in halves), "tolerance",
                         part.tolerance, f"must be half a small square of the graph, {halves} ({self.key})")
        _require(re.fullmatch(r"[a-z0-9]+(-[a-z0-9]+)*", self.key) is not None, "key", self.key,
                 "must be lower-case words joined by hyphens")
        _require(len(self.parts) >= 1, "parts", self.parts, "must hold at least one part")
        _require(any(m.code for m in self.mark_scheme), "mark_scheme", self.mark_scheme,
                 "must award at least one mark")
        self._check_mark_codes()
        self._check_ecf()
        self._check_direction_lines()
        if self.text:
            textformat.parse(self.text)  # raises ValueError naming a bad tag

    def _check_ecf(self) -> None:
        """Every method of a later part must give its key from the earlier keys: one source."""
        answers = dict(zip(self.part_ids, (p.value for p in self.parts), strict=True))
        for index, part in enumerate(self.parts):
            for method in part.ecf_methods:
                _require(all(PART_IDS.index(u) < index for u in method.uses), "ecf", method.formula,
                         f"may use only earlier parts than ({self.part_ids[index]}) in {self.key}")
                worked = method.evaluate(answers)
                if part.direction != "signed":
                    worked = abs(worked)
                _require(math.isclose(worked, part.value, rel_tol=1e-9, abs_tol=1e-12), "ecf", method.formula,
                         f"must give ({self.part_ids[index]})'s key {part.value!r} in {self.key}, not {worked!r}")

    def _check_direction_lines(self) -> None:
        """A line that earns a direction belongs to a part that asks for one."""
        for mark in self.mark_scheme:
            if mark.earns == "direction":
                part = self.parts[self.part_ids.index(self.owner(mark))]
                _require(part.direction != "none", "earns", mark.earns,
                         f"'direction' needs a part that asks for a direction ({self.key}: {mark.text!r})")

    def owner(self, mark: Mark) -> str:
        """The part whose marks a line counts in. A line of two parts ("(a, b) C1 C1") goes to
        the one of them with fewer marks so far (the earlier on a tie), so the working's marks
        stay spread over the parts it serves and each is earned on that part's own terms."""
        return self._owners[self.mark_scheme.index(mark)]

    @cached_property
    def _owners(self) -> list[str]:
        counts = dict.fromkeys(self.part_ids, 0)
        owners: list[str] = [""] * len(self.mark_scheme)
        shared = []
        for index, mark in enumerate(self.mark_scheme):
            if not mark.code:
                continue
            parts = self.parts_of(mark)
            if len(parts) == 1:
                owners[index] = parts[0]
                counts[parts[0]] += 1
            else:
                shared.append((index, parts))
        for index, parts in shared:
            fewest = min(parts, key=lambda part: (counts[part], parts.index(part)))
            owners[index] = fewest
            counts[fewest] += 1
        return owners

    def part_marks(self) -> list[int]:
        """The marks of each part, [2] on a paper: the one number the site, the sheets and
        Moodle print."""
        owners = [o for o in self._owners if o]
        return [owners.count(part_id) for part_id in self.part_ids]

    def line_roles(self, mark: Mark) -> tuple[str, ...]:
        """What a line earns (marking.py). In a part that asks for a direction but has no line
        of its own for it, the answer line carries the direction: a wrong one loses the A1."""
        roles = marking.line_roles(mark.code, earns=mark.earns)
        part_id = self.owner(mark)
        part = self.parts[self.part_ids.index(part_id)]
        own_line = any(m.earns == "direction" for m in self.mark_scheme if m.code and self.owner(m) == part_id)
        if part.direction != "none" and not own_line and "answer" in roles:
            roles = (*roles, "direction")
        return roles

    def part_lines(self, part_id: str) -> list[tuple[str, tuple[str, ...]]]:
        """(code, roles) of each mark line that counts in a part, in the scheme's order."""
        return [(m.code, self.line_roles(m)) for m in self.mark_scheme if m.code and self.owner(m) == part_id]

    def scheme_alternatives(self, index: int) -> tuple[Alternative, ...]:
        """What the scheme's own working gives for a later part: its formula worked from the
        earlier answers as the key prints them, where that differs from the key at the
        marker's precision (an examiner credits it)."""
        part = self.parts[index]
        if part.kind != "numeric" or not part.ecf_methods:
            return ()
        printed = {pid: round_number(p.value, p.shown_sig_figs) if p.value is not None else None
                   for pid, p in zip(self.part_ids, self.parts, strict=True)}
        found: dict[str, Alternative] = {}
        for method in part.ecf_methods:
            if any(printed[u] is None for u in method.uses):
                continue
            value = method.evaluate({u: float(printed[u]) for u in method.uses})
            value = value if part.direction == "signed" else abs(value)
            typed = number(value, part.check_sig_figs)
            if part._accepted(value) or part._named(value) or typed in found:
                continue
            found[typed] = Alternative(value, "the value the scheme's working gives from the "
                                              "earlier answers as printed")
        return tuple(found.values())

    def _check_mark_codes(self) -> None:
        """9702's codes: M1 only where a part asks to show, explain or state; every A1
        after a C1 or M1 of its own part (an answer alone is a B1)."""
        earned: set[str] = set()
        for mark in self.mark_scheme:
            if not mark.code:
                continue
            parts = self.parts_of(mark)
            for part_id in parts:
                part = self.parts[self.part_ids.index(part_id)]
                if mark.code == "M1":
                    _require(part.asks != "calculate", "code", mark.code,
                             f"M1 is for show that, explain or state, not for a calculation step "
                             f"({self.key} ({part_id}): {mark.text!r}); use C1")
                if mark.code == "A1":
                    _require(part_id in earned, "code", mark.code,
                             f"A1 needs a C1 or M1 before it in its part ({self.key} ({part_id}): "
                             f"{mark.text!r}); a result on its own is B1")
            if mark.code in ("C1", "M1"):
                earned.update(parts)

    def parts_of(self, mark: Mark) -> tuple[str, ...]:
        """The ids of the parts a mark line belongs to."""
        if not mark.part:
            _require(len(self.parts) == 1, "part", mark.part,
                     f"must name the part of each mark line in {self.key}, which has several")
            return ("a",)
        for part_id in mark.part:
            _require(part_id in self.part_ids, "part", mark.part, f"must be among {self.part_ids}")
        return tuple(mark.part)

    @property
    def part_ids(self) -> tuple[str, ...]:
        """"a", "b", ... (one part alone has the id "a" too)."""
        return PART_IDS[:len(self.parts)]

    def label(self, index: int) -> str:
        """"(a) " before a part's prompt when there are several parts, else ""."""
        return f"({self.part_ids[index]}) " if len(self.parts) > 1 else ""

    @property
    def marks(self) -> int:
        return sum(1 for m in self.mark_scheme if m.code)

    def browser_data(self) -> dict:
        """What the marking script needs: the parts and, per mark line, the part it counts in,
        its code and the roles it plays (marking.py)."""
        parts = []
        for index, (part_id, part) in enumerate(zip(self.part_ids, self.parts, strict=True)):
            data = part.browser_data(part_id)
            extra = self.scheme_alternatives(index)
            if extra:
                data["alternatives"] = data["alternatives"] + [{"value": a.value, "why": a.why} for a in extra]
            parts.append(data)
        lines = [m for m in self.mark_scheme if m.code]
        return {"id": self.key, "parts": parts,
                "marks": [self._line_data(m, index, lines) for index, m in enumerate(lines)]}

    def _line_data(self, mark: Mark, index: int, lines: list[Mark]) -> dict:
        data = {"part": self.owner(mark), "code": mark.code, "roles": list(self.line_roles(mark)),
                "html": textformat.to_html(mark.text, paragraphs=False) if self.text else ""}
        part = self.parts[self.part_ids.index(data["part"])]
        if part.kind == "explain" and mark.code == "A1":
            # a self-marked A1 depends on the M1 before it in its part (9702's M1 A1)
            before = [i for i in range(index) if lines[i].code == "M1" and self.owner(lines[i]) == data["part"]]
            if before:
                data["needs"] = before[-1]
        return data

    def variant_data(self) -> dict:
        """One variant for the browser's New numbers: its text, mark scheme and marking data."""
        return {"text": self.text_html(), "scheme": self.mark_scheme_html(), **self.browser_data()}

    def mark_lines(self) -> list[tuple[str, str, str]]:
        """(part label, text, code) per mark-scheme line; the label only when the part changes."""
        lines, last = [], ""
        for mark in self.mark_scheme:
            label = ""
            if len(self.parts) > 1 and mark.part and mark.part != last:
                label, last = f"({', '.join(mark.part)})", mark.part
            lines.append((label, mark.text, mark.code))
        return lines

    def text_html(self) -> str:
        """The question's text as HTML (from physics_figures.textformat)."""
        return textformat.to_html(self.text)

    def mark_scheme_html(self) -> str:
        """The mark scheme as an HTML list, for a question written in the text format."""
        items = "".join(
            f"<li><p>{f'<strong>{label}</strong> ' if label else ''}"
            f"{textformat.to_html(text, paragraphs=False)}{f' <strong>{code}</strong>' if code else ''}</p></li>"
            for label, text, code in self.mark_lines())
        return f"<ul>{items}</ul>"

