# ruff: noqa: RUF001  (feedback is typeset text: true minus, times and Greek letters)
"""Questions that mark like an examiner, computed from the models.

A page asks a question with the ``question`` directive (book/_ext/questions) and names
one function here, e.g. ``:answer: physics_figures.questions:quick_check_1``. The function
returns a ``Question``: the numbers its text states (``givens``), one ``Part`` per answer
box, and the mark scheme. Each part knows its answer (SI units, from the models), the
unit, how many significant figures it needs, whether direction matters, and its named
mistakes: the classic wrong methods, each worked from the same inputs, each with
feedback that names the mistake and the idea to revisit. The browser marks with this
data (book/_ext/questions/static/questions.js); the answer key prints it.

Mark-scheme lines are MyST Markdown ($...$ maths); feedback is plain text. Each line names
the part it belongs to and its Cambridge code: C1 for a calculation step (compensatory: a
right final answer earns it without the working), M1 and a dependent A1 only where a part
asks to show that, explain or state a principle, A1 for the answer, B1 for a single point.

A part also keeps its working (``Step`` values) and how the answer follows from them, so
the answers that rounding part-way through would give are computed here, and the browser
says "rounded part-way" only for those. A part whose answer depends on g names the g = 10
mistake and the g = 9.8 slip from the same formula.
"""

from __future__ import annotations

import itertools
import math
import re
from collections.abc import Callable, Mapping
from dataclasses import KW_ONLY, dataclass, field
from typing import ClassVar

import sympy

from . import textformat
from .constants import G_EARTH, G_MOON
from .models import (
    acceleration,
    change_in_momentum,
    elastic_collision,
    explosion_from_rest,
    kinetic_energy,
    lift_contact_force,
    mass_from_weight,
    missing_momentum,
    momentum,
    relative_speed,
    stick_together,
    stream_force,
    time_for_momentum_change,
    total_kinetic_energy,
    towing,
    velocity_from_momentum,
    weight,
)
from .notation import format_number, round_number, tex_number

#: How a part treats direction: a size only, a signed value along a stated positive
#: direction, or a size plus a direction chosen from a list.
DIRECTION_MODES = ("none", "signed", "choice")
#: Cambridge 9702 accepts 2 or more significant figures unless a question says otherwise.
DEFAULT_MIN_SIG_FIGS = 2
#: The key is trusted to 3 s.f.: an answer worked with intermediates rounded to 3 s.f.
#: still agrees with it at that precision.
DEFAULT_CHECK_SIG_FIGS = 3
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
    """A value as the book writes it, for TeX maths, e.g. number(686.7, 3) -> "687"."""
    return tex_number(format_number(value, sig_figs))


def unit_text(unit: str) -> str:
    """A unit for plain text: "m s^-1" -> "m s⁻¹"."""
    return re.sub(r"\^(-?\d+)", lambda m: m.group(1).translate(_SUPERSCRIPT), unit)


def unit_markdown(unit: str) -> str:
    """A unit for MyST Markdown: "m s^-1" -> "m s$^{-1}$"."""
    return re.sub(r"\^(-?\d+)", r"$^{\1}$", unit)


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
    """

    name: str
    value: float
    feedback: str
    _: KW_ONLY
    unit: str | None = None
    direction: str | None = None

    def __post_init__(self):
        _require(math.isfinite(self.value), "value", self.value, "must be a finite number")
        _require(bool(self.feedback.strip()), "feedback", self.feedback, "must not be empty")


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
        _require(not unknown, "formula", self.formula, f"uses {sorted(unknown)}, which are not in values")

    @property
    def uses(self) -> tuple[str, ...]:
        """The earlier parts the formula reads."""
        return tuple(sorted(s.name for s in self.formula.free_symbols if s.name in PART_IDS))

    def evaluate(self, answers: Mapping[str, float]) -> float:
        known = {**self.values, **{part: answers[part] for part in self.uses}}
        return float(self.formula.subs({sympy.Symbol(name): value for name, value in known.items()}))

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
                "is out in the second significant figure, which loses the accuracy mark (A1).")
            object.__setattr__(self, "mistakes", (*self.mistakes, g_ten))
        for mistake in self.mistakes:
            _require(mistake.direction is None or mistake.direction in self.choices,
                     "mistake.direction", mistake.direction, f"must be one of choices={self.choices}")

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
    def g_nine_eight(self) -> float | None:
        """The answer with g = 9.8 m s⁻², when the marker would not already accept it."""
        if self.answer_for_g is None:
            return None
        value = self._size(self.answer_for_g(G_NINE_EIGHT))
        return None if self._accepted(value) or self._named(value) else value

    @property
    def rounded_part_way(self) -> tuple[tuple[float, str], ...]:
        """(answer, what was rounded) for each way of rounding the working to 2 or 3 s.f.
        early that the marker would not accept as right and that is no named mistake."""
        if self.answer_from is None:
            return ()
        found: dict[str, tuple[float, str]] = {}
        indices = range(len(self.working))
        for sig_figs in PART_WAY_SIG_FIGS:
            for size in range(1, len(self.working) + 1):
                for chosen in itertools.combinations(indices, size):
                    values = [_round_sf(step.value, sig_figs) if i in chosen else step.value
                              for i, step in enumerate(self.working)]
                    answer = self._size(self.answer_from(*values))
                    key = number(answer, self.check_sig_figs)
                    if self._accepted(answer) or self._named(answer) or key in found:
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
                 "feedback": m.feedback}
                for m in self.mistakes
            ],
            "gNineEight": self.g_nine_eight,
            "roundedPartWay": [{"value": value, "rounded": what} for value, what in self.rounded_part_way],
            "ecf": self.ecf.browser_data() if self.ecf else None, "kind": self.kind,
        }


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
                             "mistake": o.mistake, "feedback": o.feedback}
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
    """One line of the mark scheme (MyST Markdown), the mark it earns and its part(s).

    part: the ids of the parts the line belongs to ("a", or "ab" for working that
    serves two parts); "" in a one-part question means that part.
    """

    text: str
    code: str = ""
    part: str = ""

    def __post_init__(self):
        _require(self.code in MARK_CODES, "code", self.code, f"must be one of {MARK_CODES}")

    @property
    def markdown(self) -> str:
        return f"{self.text} **{self.code}**" if self.code else self.text


@dataclass(frozen=True)
class Question:
    """A question's data: the numbers its text states, its parts and its mark scheme."""

    key: str
    givens: tuple[Given, ...]
    parts: tuple[Part | ChoicePart | ExplainPart, ...]
    mark_scheme: tuple[Mark, ...]
    #: The question as the student reads it (physics_figures.textformat), for a template;
    #: empty when the page states it (worked examples' try-first parts).
    text: str = ""

    def __post_init__(self):
        _require(re.fullmatch(r"[a-z0-9]+(-[a-z0-9]+)*", self.key) is not None, "key", self.key,
                 "must be lower-case words joined by hyphens")
        _require(len(self.parts) >= 1, "parts", self.parts, "must hold at least one part")
        _require(any(m.code for m in self.mark_scheme), "mark_scheme", self.mark_scheme,
                 "must award at least one mark")
        self._check_mark_codes()
        self._check_ecf()
        if self.text:
            textformat.parse(self.text)  # raises ValueError naming a bad tag

    def _check_ecf(self) -> None:
        """A later part's formula must give its key from the earlier keys: one source."""
        answers = dict(zip(self.part_ids, (p.value for p in self.parts), strict=True))
        for index, part in enumerate(self.parts):
            if part.ecf is None:
                continue
            _require(all(PART_IDS.index(u) < index for u in part.ecf.uses), "ecf", part.ecf.formula,
                     f"may use only earlier parts than ({self.part_ids[index]}) in {self.key}")
            worked = part.ecf.evaluate(answers)
            if part.direction != "signed":
                worked = abs(worked)
            _require(math.isclose(worked, part.value, rel_tol=1e-9, abs_tol=1e-12), "ecf", part.ecf.formula,
                     f"must give ({self.part_ids[index]})'s key {part.value!r} in {self.key}, not {worked!r}")

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
        """What the marking script needs: the parts and, per mark line, its part(s) and code."""
        return {"id": self.key,
                "parts": [p.browser_data(i) for i, p in zip(self.part_ids, self.parts, strict=True)],
                "marks": [{"parts": list(self.parts_of(m)), "code": m.code,
                           "html": textformat.to_html(m.text, paragraphs=False) if self.text else ""}
                          for m in self.mark_scheme if m.code]}

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

    def mark_scheme_markdown(self) -> str:
        """One bullet a line; with several parts, a line opens with its part(s) when they change."""
        lines, last = [], ""
        for mark in self.mark_scheme:
            label = ""
            if len(self.parts) > 1 and mark.part and mark.part != last:
                label = f"**({', '.join(mark.part)})** "
                last = mark.part
            lines.append(f"- {label}{mark.markdown}")
        return "\n".join(lines)


def _f(value: float, sig_figs: int) -> str:
    return number(value, sig_figs)


_N_S = "N s or kg m s^-1"
_M_S = "m s^-1 (m/s)"
_M_S2 = "m s^-2 (m/s^2)"

# --------------------------------------------------------------- Quick check (notes)


def quick_check_1() -> Question:
    """Quick check 1 is a template of the bank (physics_figures/bank/force_momentum.py)."""
    from .bank import TEMPLATES  # the bank builds on this module

    return TEMPLATES["quick-check-1"].variant(0)


def quick_check_2() -> Question:
    """Notes, Quick check 2: rifle 4.0 kg, bullet 0.010 kg at 400 m s^-1 -> recoil 1.0 m s^-1 backwards."""
    rifle, bullet, bullet_speed = 4.0, 0.010, 400.0
    v = explosion_from_rest(bullet, rifle, bullet_speed)  # signed: the bullet's way is positive
    bullet_momentum = momentum(bullet, bullet_speed)
    return Question(
        key="quick-check-2",
        givens=(Given("rifle mass", rifle, "kg", 2), Given("bullet mass", bullet, "kg", 2),
                Given("bullet speed", bullet_speed, "m s^-1", 3)),
        parts=(
            Part("recoil speed of the rifle", abs(v), "m s^-1", "speed", units=_M_S, shown_sig_figs=2,
                 sign_means="it moves backwards, opposite to the bullet",
                 revisit="The total momentum is zero before firing, so it is zero after: "
                         "0 = m₁v₁ + m₂v₂.",
                 mistakes=(
                     Mistake("mass ratio upside down", rifle * bullet_speed / bullet,
                             "The masses are the wrong way up. The rifle's momentum equals the "
                             "bullet's: 4.0 v = 0.010 × 400, so v = 0.010 × 400 / 4.0."),
                     Mistake("bullet's momentum given as speed", bullet_momentum,
                             "0.010 × 400 = 4.0 is the bullet's momentum (in N s). Divide it by the "
                             "rifle's mass to get the rifle's speed."),
                     Mistake("mass in grams", bullet * 1000 * bullet_speed / rifle,
                             "You used the bullet's mass in g. Convert to kg: 0.010 kg."),
                     Mistake("kinetic energy conserved", bullet_speed * math.sqrt(bullet / rifle),
                             "You set the kinetic energies equal. In an explosion kinetic energy "
                             "increases (from the chemical energy of the charge); only momentum is "
                             "conserved."),
                 )),
        ),
        mark_scheme=(
            Mark(f"Total momentum is zero before, so $0 = {_f(bullet, 2)} \\times {_f(bullet_speed, 3)} "
                 f"+ {_f(rifle, 2)}v$", "C1"),
            Mark(f"$v = {_f(v, 2)}$ m s$^{{-1}}$: the recoil speed is {_f(abs(v), 2)} m s$^{{-1}}$, "
                 "backwards", "A1"),
        ),
    )


def quick_check_3() -> Question:
    """Notes, Quick check 3: 70 kg skydiver -> drag 687 N; 1500 N drag -> 11.6 m s^-2 upwards."""
    mass, open_drag = 70.0, 1500.0
    drag = weight(mass)  # at terminal velocity the resultant force is zero
    a = acceleration(open_drag - drag, mass)
    return Question(
        key="quick-check-3",
        givens=(Given("mass", mass, "kg", 2), Given("drag with the parachute open", open_drag, "N", 2)),
        parts=(
            Part("drag force at terminal velocity", drag, "N", "force", shown_sig_figs=3,
                 asks="state", answer_for_g=lambda g: weight(mass, g=g),
                 revisit="At terminal velocity the resultant force is zero, so the drag equals the "
                         "weight, mg.",
                 mistakes=(
                     Mistake("mass given as force", mass,
                             "70 is her mass in kg. The drag equals her weight, W = mg = 70 × 9.81."),
                     Mistake("divided by g", mass / G_EARTH,
                             "You divided by g. Weight = mass × g, and at terminal velocity drag = weight."),
                     Mistake("drag is zero", 0.0,
                             "At terminal velocity the resultant force is zero, not the drag: the drag "
                             "has grown to equal the weight."),
                 )),
            Part("acceleration when the parachute opens", a, "m s^-2", "acceleration", units=_M_S2,
                 shown_sig_figs=3, direction="choice", choices=("upwards", "downwards"),
                 answer_direction="upwards",
                 working=(Step("drag at terminal velocity (her weight)", drag, "N"),),
                 answer_from=lambda w: acceleration(open_drag - w, mass),
                 answer_for_g=lambda g: acceleration(open_drag - weight(mass, g=g), mass),
                 direction_hint="The drag (1500 N) is bigger than the weight, so the resultant force "
                                "and the acceleration are upwards.",
                 revisit="Resultant force = drag − weight; a = resultant force / mass.",
                 mistakes=(
                     Mistake("still falling, so acceleration downwards", a,
                             "She is still falling, but slowing down: the resultant force (drag − "
                             "weight) is upwards, so the acceleration is upwards.", direction="downwards"),
                     Mistake("drag used as the resultant force", acceleration(open_drag, mass),
                             "You used the drag as the resultant force. The weight still acts: "
                             "resultant = 1500 − 687 N."),
                     Mistake("weight added to drag", acceleration(open_drag + drag, mass),
                             "You added the weight to the drag. They act in opposite directions: "
                             "resultant = drag − weight."),
                     Mistake("acceleration of free fall", G_EARTH,
                             "g is the acceleration with no drag at all. Here work out the resultant "
                             "force (drag − weight) and divide by the mass."),
                 )),
        ),
        mark_scheme=(
            Mark(f"At terminal velocity the resultant force is zero, so drag $= mg = {_f(mass, 2)} "
                 f"\\times {G_EARTH} = {_f(drag, 3)}$ N", "B1", "a"),
            Mark(f"$a = \\frac{{{_f(open_drag, 2)} - {_f(drag, 3)}}}{{{_f(mass, 2)}}}$", "C1", "b"),
            Mark(f"$= {_f(a, 3)}$ m s$^{{-2}}$", "A1", "b"),
            Mark("**upwards** (she slows down while still falling)", "B1", "b"),
        ),
    )


def quick_check_4() -> Question:
    """Notes, Quick check 4: 1.0 kg at 6.0 m s^-1 hits 2.0 kg at rest, elastic -> -2.0 and 4.0 m s^-1."""
    m1, u1, m2, u2 = 1.0, 6.0, 2.0, 0.0
    v1, v2 = elastic_collision(m1, u1, m2, u2)
    p_before = momentum(m1, u1)
    approach = relative_speed(u1, u2)
    ke_before = kinetic_energy(m1, u1)
    stuck = stick_together(m1, u1, m2, u2)
    forward = "the direction the 1.0 kg ball moves at first"
    revisit = ("Use two equations: momentum (m₁u₁ + m₂u₂ = m₁v₁ + m₂v₂) and, because it is elastic, "
               "relative speed of approach = relative speed of separation.")
    return Question(
        key="quick-check-4",
        givens=(Given("m1", m1, "kg", 2), Given("u1", u1, "m s^-1", 2), Given("m2", m2, "kg", 2)),
        parts=(
            Part("velocity of the 1.0 kg ball", v1, "m s^-1", "velocity", units=_M_S, shown_sig_figs=2,
                 direction="signed", positive=forward, revisit=revisit,
                 mistakes=(
                     Mistake("assumed the first ball stops", 0.0,
                             "The moving ball only stops when the masses are equal. Here the 2.0 kg "
                             "ball is heavier, so the 1.0 kg ball bounces back."),
                     Mistake("bounces back at full speed", -u1,
                             "It can't bounce back at its full speed: the 2.0 kg ball moves off, "
                             "taking momentum and kinetic energy. Solve the two equations together."),
                 )),
            Part("velocity of the 2.0 kg ball", v2, "m s^-1", "velocity", units=_M_S, shown_sig_figs=2,
                 direction="signed", positive=forward, revisit=revisit,
                 mistakes=(
                     Mistake("treated as sticking together", stuck,
                             "That is the common velocity if they stuck together, an inelastic "
                             "collision. This one is elastic: use the relative speeds too."),
                     Mistake("assumed the first ball stops", velocity_from_momentum(p_before, m2),
                             "You assumed the 1.0 kg ball stops. That happens only for equal masses; "
                             "use momentum and relative speeds together."),
                     Mistake("swapped velocities", u1,
                             "Balls swap velocities only when their masses are equal. Here they "
                             "are not: solve momentum and relative speeds together."),
                 )),
        ),
        mark_scheme=(
            Mark(f"Momentum: ${_f(p_before, 2)} = v_1 + {_f(m2, 2)}v_2$", "C1", "ab"),
            Mark(f"Elastic, so relative speeds: ${_f(approach, 2)} = v_2 - v_1$", "C1", "ab"),
            Mark(f"Adding: ${_f(p_before + approach * m1, 2)} = {_f(m1 + m2, 1)}v_2$, so "
                 f"$v_2 = {_f(v2, 2)}$ m s$^{{-1}}$ forwards", "A1", "b"),
            Mark(f"$v_1 = {_f(v1, 2)}$ m s$^{{-1}}$, i.e. {_f(abs(v1), 2)} m s$^{{-1}}$ back the way it came",
                 "A1", "a"),
            Mark(f"(Check: kinetic energy {_f(ke_before, 2)} J before; "
                 f"${_f(kinetic_energy(m1, v1), 2)} + {_f(kinetic_energy(m2, v2), 2)} = "
                 f"{_f(total_kinetic_energy((m1, m2), (v1, v2)), 2)}$ J after.)"),
        ),
    )


def quick_check_5() -> Question:
    """Notes, Quick check 5: 12 kg backpack on the Moon -> mass 12 kg, weight 19.4 N."""
    mass = 12.0
    moon_weight = weight(mass, g=G_MOON)
    return Question(
        key="quick-check-5",
        givens=(Given("mass", mass, "kg", 2), Given("g on the Moon", G_MOON, "m s^-2", 3)),
        parts=(
            Part("mass on the Moon", mass, "kg", "mass", shown_sig_figs=2,
                 revisit="Mass is the property that resists a change in motion: it is the same "
                         "everywhere.",
                 mistakes=(
                     Mistake("mass scaled with g", mass * G_MOON / G_EARTH,
                             "Mass doesn't change with g: it is the same on the Moon. Only the "
                             "weight changes."),
                     Mistake("mass divided by g", mass / G_MOON,
                             "Mass doesn't depend on g at all: the backpack's mass is still 12 kg."),
                 )),
            Part("weight on the Moon", moon_weight, "N", "weight", shown_sig_figs=3,
                 revisit="Weight = mass × gravitational field strength, W = mg, with the Moon's g.",
                 mistakes=(
                     Mistake("used the Earth's g", weight(mass),
                             "You used g on the Earth (9.81). On the Moon g = 1.62 m s⁻²."),
                     Mistake("mass given as weight", mass,
                             "12 is the mass in kg. Weight is a force: W = mg."),
                     Mistake("divided by g", mass / G_MOON,
                             "You divided by g. Weight = mass × g."),
                 )),
        ),
        mark_scheme=(
            Mark(f"Mass = {_f(mass, 2)} kg (it doesn't change)", "B1", "a"),
            Mark(f"Weight $= mg = {_f(mass, 2)} \\times {G_MOON}$", "C1", "b"),
            Mark(f"$= {_f(moon_weight, 3)}$ N", "A1", "b"),
        ),
    )


QUICK_CHECK = (quick_check_1, quick_check_2, quick_check_3, quick_check_4, quick_check_5)

# --------------------------------------------------------------------- Practice


def practice_tennis_ball() -> Question:
    """A mass given in g: momentum of a 57 g ball served at 50 m s^-1."""
    grams, speed = 57.0, 50.0
    mass = grams / 1000
    p = momentum(mass, speed)
    return Question(
        key="practice-tennis-ball",
        givens=(Given("mass", grams, "g", 2), Given("speed", speed, "m s^-1", 2)),
        parts=(
            Part("momentum of the ball", p, "N s", "momentum", units=_N_S, shown_sig_figs=2,
                 revisit="Momentum = mass × velocity, with the mass in kg.",
                 mistakes=(
                     Mistake("mass left in grams", grams * speed,
                             "You used the mass in g. Convert to kg first: 57 g = 0.057 kg."),
                     Mistake("kinetic energy instead of momentum", kinetic_energy(mass, speed),
                             "That is the kinetic energy, ½mv², in J. Momentum is mv, in N s.", unit="J"),
                     Mistake("mass divided by speed", mass / speed,
                             "You divided the mass by the speed. Momentum is mass × velocity."),
                 )),
        ),
        mark_scheme=(
            Mark(f"$m = {_f(grams, 2)}$ g $= {_f(mass, 2)}$ kg, so $p = mv = {_f(mass, 2)} \\times {_f(speed, 2)}$",
                 "C1"),
            Mark(f"$= {_f(p, 2)}$ N s", "A1"),
        ),
    )


def practice_wall_bounce() -> Question:
    """Change in momentum and force for a ball bouncing back: m(u + v), not m(u - v)."""
    mass, speed_in, speed_out, contact_ms = 0.16, 15.0, 10.0, 20.0
    # Away from the wall is positive, so the ball arrives with a negative velocity.
    dp = change_in_momentum(mass, -speed_in, speed_out)
    contact = contact_ms / 1000
    force = dp / contact
    choices = ("towards the wall", "away from the wall")
    slip = mass * (speed_in - speed_out)
    return Question(
        key="practice-wall-bounce",
        givens=(Given("mass", mass, "kg", 2), Given("speed in", speed_in, "m s^-1", 2),
                Given("speed out", speed_out, "m s^-1", 2), Given("contact time", contact_ms, "ms", 2)),
        parts=(
            Part("change in momentum of the ball", dp, "N s", "change in momentum", units=_N_S,
                 shown_sig_figs=2, direction="choice", choices=choices,
                 answer_direction="away from the wall",
                 direction_hint="The ball's momentum changes from towards the wall to away from it.",
                 revisit="Take one direction as positive: Δp = mv − mu with u negative, so |Δp| = m(u + v).",
                 mistakes=(
                     Mistake("u - v instead of u + v", slip,
                             "You used m(u − v). The ball reverses, so the velocities have opposite "
                             "signs: Δp = m(u + v)."),
                     Mistake("initial momentum only", momentum(mass, speed_in),
                             "That is only the momentum before. Δp = final momentum − initial "
                             "momentum, with signs."),
                 )),
            Part("average force exerted on the ball by the wall", force, "N", "force", shown_sig_figs=2,
                 direction="choice", choices=choices, answer_direction="away from the wall",
                 direction_hint="The force on the ball is in the direction of its change in momentum.",
                 revisit="Average force = change in momentum ÷ contact time, with the time in s.",
                 mistakes=(
                     Mistake("milliseconds not converted", dp / contact_ms,
                             "You divided by 20 instead of 0.020: convert ms to s."),
                     Mistake("u - v carried through", slip / contact,
                             "You used m(u − v) for the change in momentum. The ball reverses: "
                             "Δp = m(u + v)."),
                     Mistake("force on the wall", force,
                             "That is the force of the ball on the wall (its Newton's third law "
                             "pair). The wall pushes the ball away from the wall.",
                             direction="towards the wall"),
                 )),
        ),
        mark_scheme=(
            Mark(f"Away from the wall positive: $\\Delta p = mv - mu = {_f(mass, 2)} \\times {_f(speed_out, 2)} "
                 f"- {_f(mass, 2)} \\times (-{_f(speed_in, 2)})$", "C1", "a"),
            Mark(f"$= {_f(dp, 2)}$ N s, away from the wall", "A1", "a"),
            Mark(f"$F = \\frac{{\\Delta p}}{{\\Delta t}} = \\frac{{{_f(dp, 2)}}}{{{_f(contact, 2)}}}$", "C1", "b"),
            Mark(f"$= {_f(force, 2)}$ N, away from the wall", "A1", "b"),
        ),
    )


def practice_car_slowing() -> Question:
    """F = ma with signs: resistive force bigger than the driving force."""
    mass, driving, resistive = 800.0, 1500.0, 2300.0
    resultant = driving - resistive
    a = acceleration(resultant, mass)
    return Question(
        key="practice-car-slowing",
        givens=(Given("mass", mass, "kg", 2), Given("driving force", driving, "N", 2),
                Given("resistive force", resistive, "N", 2)),
        parts=(
            Part("acceleration of the car", a, "m s^-2", "acceleration", units=_M_S2, shown_sig_figs=2,
                 direction="signed", positive="forwards",
                 revisit="Resultant force = forces forwards − forces backwards; a = F / m, "
                         "with its sign.",
                 mistakes=(
                     Mistake("forces added", acceleration(driving + resistive, mass),
                             "You added the two forces. They act in opposite directions: "
                             "resultant = 1500 − 2300 N."),
                     Mistake("driving force only", acceleration(driving, mass),
                             "You used only the driving force. F = ma needs the resultant force."),
                 )),
        ),
        mark_scheme=(
            Mark(f"Resultant force $= {_f(driving, 2)} - {_f(resistive, 2)} = {_f(resultant, 2)}$ N", "C1"),
            Mark(f"$a = \\frac{{{_f(resultant, 2)}}}{{{_f(mass, 2)}}} = {_f(a, 2)}$ m s$^{{-2}}$ "
                 "(the car slows down)", "A1"),
        ),
    )


def practice_lift() -> Question:
    """Contact force in a lift accelerating downwards: R = m(g - a)."""
    mass, a_down = 58.0, 1.5
    contact = lift_contact_force(mass, -a_down)
    return Question(
        key="practice-lift",
        givens=(Given("mass", mass, "kg", 2), Given("acceleration", a_down, "m s^-2", 2)),
        parts=(
            Part("contact force from the floor", contact, "N", "force", shown_sig_figs=3,
                 answer_for_g=lambda g: lift_contact_force(mass, -a_down, g=g),
                 revisit="Take up as positive: R − mg = ma, with a negative for a downward acceleration.",
                 mistakes=(
                     Mistake("g + a used", lift_contact_force(mass, a_down),
                             "You used m(g + a), which is for accelerating upwards. Accelerating "
                             "down, the floor pushes less: R = m(g − a)."),
                     Mistake("weight only", weight(mass),
                             "That is the weight, the contact force at steady speed. The lift "
                             "accelerates, so R − mg = ma."),
                     Mistake("resultant force given", mass * a_down,
                             "That is the resultant force, ma. The contact force is R = m(g − a)."),
                 )),
        ),
        mark_scheme=(
            Mark(f"Up positive: $R - mg = ma$ with $a = -{_f(a_down, 2)}$ m s$^{{-2}}$", "C1"),
            Mark(f"$R = {_f(mass, 2)}({G_EARTH} - {_f(a_down, 2)}) = {_f(contact, 3)}$ N", "A1"),
        ),
    )


def practice_mars_rock() -> Question:
    """Mass and weight on another planet: mass stays, weight scales with g."""
    mars_weight, g_mars = 5.4, 3.7
    mass = mass_from_weight(mars_weight, g=g_mars)
    earth_weight = weight(mass)
    return Question(
        key="practice-mars-rock",
        givens=(Given("weight on Mars", mars_weight, "N", 2), Given("g on Mars", g_mars, "m s^-2", 2)),
        parts=(
            Part("mass of the rock", mass, "kg", "mass", shown_sig_figs=2,
                 revisit="W = mg, so m = W / g, with the g where the weight was measured.",
                 mistakes=(
                     Mistake("multiplied by g", mars_weight * g_mars,
                             "You multiplied by g. W = mg, so m = W / g."),
                     Mistake("used the Earth's g", mass_from_weight(mars_weight),
                             "You used the Earth's g. The 5.4 N was measured on Mars, so divide by 3.7."),
                 )),
            Part("weight of the rock on the Earth", earth_weight, "N", "weight", shown_sig_figs=3,
                 working=(Step("mass", mass, "kg"),), answer_from=lambda m: weight(m),
                 answer_for_g=lambda g: weight(mass, g=g),
                 revisit="The mass is the same on the Earth; W = mg with g = 9.81 m s⁻².",
                 mistakes=(
                     Mistake("weight unchanged", mars_weight,
                             "Weight depends on g, so it changes from Mars to the Earth. The mass is "
                             "what stays the same."),
                     Mistake("mass given as weight", mass,
                             "That is the mass in kg. Weight is a force: W = mg."),
                 )),
        ),
        mark_scheme=(
            Mark(f"$m = \\frac{{W}}{{g}} = \\frac{{{_f(mars_weight, 2)}}}{{{_f(g_mars, 2)}}}$", "C1", "a"),
            Mark(f"$= {_f(mass, 2)}$ kg (the same everywhere)", "A1", "a"),
            Mark(f"On the Earth $W = mg = {_f(mass, 4)} \\times {G_EARTH}$ (the unrounded mass: "
                 f"{_f(mass, 2)} kg would give {_f(weight(_round_sf(mass, 2)), 3)} N)", "C1", "b"),
            Mark(f"$= {_f(earth_weight, 3)}$ N", "A1", "b"),
        ),
    )


def practice_hose() -> Question:
    """Force from a steady stream: F = (Δm/Δt) v."""
    per_second, speed = 4.0, 15.0
    force = stream_force(per_second, speed)
    return Question(
        key="practice-hose",
        givens=(Given("mass per second", per_second, "kg s^-1", 2), Given("speed", speed, "m s^-1", 2)),
        parts=(
            Part("force the hose exerts on the water", force, "N", "force", shown_sig_figs=2,
                 revisit="Force = rate of change of momentum: each second 4.0 kg gains a speed of "
                         "15 m s⁻¹, so F = (Δm/Δt) v.",
                 mistakes=(
                     Mistake("speed squared", per_second * speed**2,
                             "You squared the speed. F = (Δm/Δt) v: the mass per second is already "
                             "given (ρAv² is for a jet described by its area)."),
                     Mistake("weight of water", weight(per_second),
                             "That is the weight of 4.0 kg of water. The force comes from the "
                             "momentum given to the water each second."),
                     Mistake("kinetic energy per second", kinetic_energy(per_second, speed),
                             "That is the kinetic energy given to the water each second, a power "
                             "in W. Force = momentum per second.", unit="W"),
                 )),
        ),
        mark_scheme=(
            Mark(f"$F = \\frac{{\\Delta m}}{{\\Delta t}} v = {_f(per_second, 2)} \\times {_f(speed, 2)}$", "C1"),
            Mark(f"$= {_f(force, 2)}$ N", "A1"),
        ),
    )


def practice_trolleys_stick() -> Question:
    """Head-on, stick together, with signs; then the kinetic energy transferred."""
    m1, u1, m2, u2 = 2.0, 3.0, 1.0, -1.5
    v = stick_together(m1, u1, m2, u2)
    before = total_kinetic_energy((m1, m2), (u1, u2))
    after = kinetic_energy(m1 + m2, v)
    lost = before - after
    no_sign = stick_together(m1, u1, m2, -u2)
    positive = "the direction the 2.0 kg trolley moves at first"
    return Question(
        key="practice-trolleys-stick",
        givens=(Given("m1", m1, "kg", 2), Given("u1", u1, "m s^-1", 2), Given("m2", m2, "kg", 2),
                Given("speed 2", -u2, "m s^-1", 2)),
        parts=(
            Part("velocity after the collision", v, "m s^-1", "velocity", units=_M_S, shown_sig_figs=2,
                 direction="signed", positive=positive,
                 revisit="Momentum before = momentum after, with a minus sign for the trolley "
                         "moving the other way: m₁u₁ + m₂u₂ = (m₁ + m₂)v.",
                 mistakes=(
                     Mistake("sign of the second trolley left out", no_sign,
                             "The 1.0 kg trolley moves the other way, so its momentum is negative: "
                             "2.0 × 3.0 + 1.0 × (−1.5)."),
                     Mistake("second trolley ignored", momentum(m1, u1) / (m1 + m2),
                             "You left out the 1.0 kg trolley's momentum. It is moving, the other way."),
                 )),
            Part("kinetic energy transferred to other forms", lost, "J", "energy", shown_sig_figs=3,
                 working=(Step("common velocity", v, "m s^-1", 2),),
                 answer_from=lambda common: before - kinetic_energy(m1 + m2, common),
                 revisit="Work out the total kinetic energy before and after separately; the "
                         "difference is the energy transferred.",
                 mistakes=(
                     Mistake("kinetic energy conserved", 0.0,
                             "Kinetic energy is conserved only in an elastic collision. Trolleys "
                             "that stick together always lose some."),
                     Mistake("kinetic energy after only", after,
                             "That is the kinetic energy after. Subtract it from the kinetic energy "
                             "before."),
                     Mistake("wrong velocity carried on", before - kinetic_energy(m1 + m2, no_sign),
                             "Your velocity after is wrong: the 1.0 kg trolley's momentum is negative."),
                 )),
        ),
        mark_scheme=(
            Mark(f"${_f(m1, 2)} \\times {_f(u1, 2)} + {_f(m2, 2)} \\times ({_f(u2, 2)}) = "
                 f"{_f(m1 + m2, 2)}v$", "C1", "a"),
            Mark(f"$v = {_f(v, 2)}$ m s$^{{-1}}$ in the 2.0 kg trolley's direction", "A1", "a"),
            Mark(f"$E_k$ before $= \\tfrac12 \\times {_f(m1, 2)} \\times {_f(u1, 2)}^2 + \\tfrac12 \\times "
                 f"{_f(m2, 2)} \\times {_f(abs(u2), 2)}^2 = {_f(before, 5)}$ J; after $= \\tfrac12 \\times "
                 f"{_f(m1 + m2, 2)} \\times {_f(v, 2)}^2 = {_f(after, 4)}$ J", "C1", "b"),
            Mark(f"Transferred $= {_f(before, 5)} - {_f(after, 4)} = {_f(lost, 3)}$ J", "A1", "b"),
        ),
    )


def practice_stopping_time() -> Question:
    """Constant force, find the time: Δt = Δp / F."""
    mass, speed, force = 900.0, 12.0, 3600.0
    dp = momentum(mass, speed)
    duration = time_for_momentum_change(dp, force)
    return Question(
        key="practice-stopping-time",
        givens=(Given("mass", mass, "kg", 2), Given("speed", speed, "m s^-1", 2),
                Given("force", force, "N", 2)),
        parts=(
            Part("time to stop", duration, "s", "time", shown_sig_figs=2,
                 revisit="Force × time = change in momentum, so Δt = Δp / F.",
                 mistakes=(
                     Mistake("force over momentum", force / dp,
                             "That is F / Δp, upside down: Δt = Δp / F."),
                     Mistake("mass over force", mass / force,
                             "You left out the speed. The change in momentum is mv = 900 × 12."),
                 )),
        ),
        mark_scheme=(
            Mark(f"$\\Delta p = mv = {_f(mass, 2)} \\times {_f(speed, 2)} = {number(dp, 3)}$ N s", "C1"),
            Mark(f"$\\Delta t = \\frac{{\\Delta p}}{{F}} = \\frac{{{number(dp, 3)}}}{{{_f(force, 2)}}} = "
                 f"{_f(duration, 2)}$ s", "A1"),
        ),
    )


def practice_towing() -> Question:
    """Connected bodies: the whole first, then one body on its own."""
    driving, masses, resistive = 2400.0, (1000.0, 500.0), (300.0, 150.0)
    towed = towing(driving, masses, resistive)
    a, tension = towed.acceleration, towed.tensions[0]
    total = sum(masses)
    return Question(
        key="practice-towing",
        givens=(Given("car mass", masses[0], "kg", 2), Given("trailer mass", masses[1], "kg", 2),
                Given("driving force", driving, "N", 2), Given("car resistance", resistive[0], "N", 2),
                Given("trailer resistance", resistive[1], "N", 2)),
        parts=(
            Part("acceleration", a, "m s^-2", "acceleration", units=_M_S2, shown_sig_figs=2,
                 revisit="Treat the car and trailer as one object: external forces only, total mass.",
                 mistakes=(
                     Mistake("resistive forces left out", acceleration(driving, total),
                             "You left out the resistive forces. Resultant = 2400 − 300 − 150 N."),
                     Mistake("trailer's resistance left out", acceleration(driving - resistive[0], total),
                             "You left out the 150 N resistive force on the trailer. Treating the car "
                             "and trailer as one object, every external force counts: "
                             "2400 − 300 − 150 N."),
                     Mistake("car's resistance left out", acceleration(driving - resistive[1], total),
                             "You left out the 300 N resistive force on the car. Treating the car "
                             "and trailer as one object, every external force counts: "
                             "2400 − 300 − 150 N."),
                     Mistake("car's mass only", acceleration(driving - sum(resistive), masses[0]),
                             "You used only the car's mass. The driving force accelerates the car "
                             "and the trailer: use the total mass, 1500 kg."),
                 )),
            Part("tension in the tow bar", tension, "N", "force", shown_sig_figs=2,
                 working=(Step("acceleration", a, "m s^-2", 2),),
                 answer_from=lambda acc: resistive[1] + masses[1] * acc,
                 revisit="F = ma for the trailer alone: T − resistive force on the trailer = "
                         "trailer mass × a.",
                 mistakes=(
                     Mistake("trailer's resistance left out", masses[1] * a,
                             "That is the trailer's resultant force, ma. The tension must also "
                             "overcome the trailer's 150 N resistance: T − 150 = 500a."),
                     Mistake("resistance subtracted", masses[1] * a - resistive[1],
                             "The resistance acts backwards on the trailer, so the tension is "
                             "bigger than ma: T = 500a + 150."),
                 )),
        ),
        mark_scheme=(
            Mark(f"Whole: resultant $= {_f(driving, 2)} - {_f(resistive[0], 2)} - {_f(resistive[1], 2)} = "
                 f"{_f(towed.resultant_force, 3)}$ N", "C1", "a"),
            Mark(f"$a = \\frac{{{_f(towed.resultant_force, 3)}}}{{{_f(total, 2)}}} = {_f(a, 2)}$ "
                 "m s$^{-2}$", "A1", "a"),
            Mark(f"Trailer alone: $T - {_f(resistive[1], 2)} = {_f(masses[1], 2)} \\times {_f(a, 2)}$", "C1", "b"),
            Mark(f"$T = {_f(tension, 2)}$ N", "A1", "b"),
        ),
    )


def practice_pucks() -> Question:
    """Momentum in two dimensions: conserve along and across the line separately."""
    mass_a, speed_a, speed_after, angle = 0.40, 2.5, 1.5, 40.0
    p_before = momentum(mass_a, speed_a)
    p_after = momentum(mass_a, speed_after)
    b = missing_momentum(p_before, p_after, angle)
    components = (Step("component along the line", b.along, "N s"),
                  Step("component across the line", b.across, "N s"))
    return Question(
        key="practice-pucks",
        givens=(Given("mass", mass_a, "kg", 2), Given("speed before", speed_a, "m s^-1", 2),
                Given("speed after", speed_after, "m s^-1", 2), Given("angle", angle, "°", 2)),
        parts=(
            Part("momentum of B after the collision", b.magnitude, "N s", "momentum", units=_N_S,
                 shown_sig_figs=2, working=components,
                 answer_from=lambda along, across: math.hypot(along, across),
                 revisit="Momentum is a vector: conserve the components along and across the "
                         "original line separately, then combine them with Pythagoras.",
                 mistakes=(
                     Mistake("sizes subtracted", p_before - p_after,
                             "You subtracted the sizes. Momentum is a vector: resolve along and "
                             "across the line and conserve each."),
                     Mistake("across component only", b.across,
                             "That is only the component across the line. Combine it with the "
                             "component along the line: p = √(along² + across²)."),
                 )),
            Part("angle between B's motion and A's original line", b.angle_deg, "°", "angle",
                 units="° (degrees)", shown_sig_figs=3, working=components,
                 answer_from=lambda along, across: math.degrees(math.atan2(across, along)),
                 revisit="tan θ = across component / along component, on the other side of the line.",
                 mistakes=(
                     Mistake("same angle as A", angle,
                             "B need not move at A's angle. Work out its components and use "
                             "tan θ = across / along."),
                     Mistake("angle from the perpendicular", 90.0 - b.angle_deg,
                             "You measured the angle from the line at right angles. Give it from "
                             "A's original line: tan θ = across / along."),
                 )),
        ),
        mark_scheme=(
            Mark(f"Along: ${_f(p_before, 2)} = {_f(p_after, 2)} \\cos {_f(angle, 2)}^\\circ + p_{{\\text{{along}}}}$, "
                 f"so $p_{{\\text{{along}}}} = {_f(b.along, 3)}$ N s", "C1", "ab"),
            Mark(f"Across: $p_{{\\text{{across}}}} = {_f(p_after, 2)} \\sin {_f(angle, 2)}^\\circ = "
                 f"{_f(b.across, 3)}$ N s", "C1", "ab"),
            Mark(f"$p_B = \\sqrt{{{_f(b.along, 3)}^2 + {_f(b.across, 3)}^2}} = {_f(b.magnitude, 2)}$ N s",
                 "A1", "a"),
            Mark(f"$\\theta = \\tan^{{-1}} \\frac{{{_f(b.across, 3)}}}{{{_f(b.along, 3)}}} = "
                 f"{_f(b.angle_deg, 3)}^\\circ$ on the other side of the line", "A1", "b"),
        ),
    )


PRACTICE = (practice_tennis_ball, practice_wall_bounce, practice_car_slowing, practice_lift,
            practice_mars_rock, practice_hose, practice_trolleys_stick, practice_stopping_time,
            practice_towing, practice_pucks)


def all_questions() -> tuple[Question, ...]:
    """Every question the book asks, in book order."""
    return tuple(make() for make in QUICK_CHECK + PRACTICE)
