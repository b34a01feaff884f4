"""The sketch part kind: the student draws a line on printed axes (or builds it from segments
by keyboard), and it is marked on the features a scheme names, each a B1 (CLARIFICATIONS,
Papers). Each marking point lists, as data, the features of the line it needs and those that
lose it; the features are read from the drawn line in the graph's own units (s, and the
quantity's SI unit) by its browser twin, book/_ext/questions/static/question-kinds/sketch.js.
The key and Moodle's grader information print the same points in words (``describe``)."""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field
from html import escape
from typing import ClassVar

from ..notation import format_number
from .common import DEFAULT_CHECK_SIG_FIGS, SCRIPTS, NoValue, _require, feedback_html, unit_text

#: What a feature says of the line: where it starts or ends (zero, positive, negative), that it
#: rises, falls or is level over a stretch of time (with its gradient constant, increasing or
#: decreasing, and a value it is level at), a step, a change of sign, and its largest value.
FEATURES = ("start", "end", "rising", "falling", "level", "step", "sign-change", "peak")
VALUE_CLASSES = ("zero", "positive", "negative")
GRADIENTS = ("constant", "increasing", "decreasing")
_GRADIENT_WORDS = {"constant": "in a straight line", "increasing": "ever more steeply",
                   "decreasing": "ever less steeply"}
_STARTS = {"zero": "starts at zero, at t = 0", "positive": "starts above zero, at t = 0",
           "negative": "starts below zero, at t = 0"}
_ENDS = {"zero": "is back at zero at the end", "positive": "ends above zero", "negative": "ends below zero"}


def _s(value: float) -> str:
    """A time or value as the key prints it (to the figures the key is trusted to, no trailing noise)."""
    return format_number(value, DEFAULT_CHECK_SIG_FIGS) if value else "0"


@dataclass(frozen=True)
class Feature:
    """One thing the line does. ``what`` is one of FEATURES; ``start`` and ``stop`` (s) bound
    a rising, falling or level stretch; ``gradient`` says how its gradient changes; ``at`` is
    the value a level stretch is at (within ``within`` value tolerances) or the time of a step;
    ``value`` classes a start or an end; ``way`` is a step's "up" or "down"; ``count`` is the
    exact number of sign changes (None: at least one); ``above`` is the least largest value."""

    what: str
    start: float | None = None
    stop: float | None = None
    gradient: str | None = None
    at: float | None = None
    value: str | None = None
    way: str | None = None
    count: int | None = None
    above: float | None = None
    within: float | None = None

    def __post_init__(self):
        _require(self.what in FEATURES, "what", self.what, f"must be one of {FEATURES}")
        if self.what in ("rising", "falling", "level"):
            _require(self.start is not None and self.stop is not None and self.stop > self.start,
                     "stop", (self.start, self.stop), f"must follow start: a {self.what} stretch has a span")
        if self.what in ("start", "end"):
            _require(self.value in VALUE_CLASSES, "value", self.value, f"must be one of {VALUE_CLASSES}")
        _require(self.gradient is None or self.gradient in GRADIENTS, "gradient", self.gradient,
                 f"must be one of {GRADIENTS}")
        _require(self.what != "step" or self.at is not None, "at", self.at, "must give a step's time")
        _require(self.way in (None, "up", "down"), "way", self.way, "must be 'up' or 'down'")
        _require(self.what != "peak" or self.above is not None, "above", self.above,
                 "must give the value a peak reaches")

    def browser_data(self) -> dict:
        names = {"start": "from", "stop": "to"}
        data = {"is": self.what}
        for name in ("start", "stop", "gradient", "at", "value", "way", "count", "above", "within"):
            if getattr(self, name) is not None:
                data[names.get(name, name)] = getattr(self, name)
        return data

    def describe(self, unit: str) -> str:
        """The feature in words, for the key and the grader: "rising in a straight line from
        0 to 2.00 s"."""
        unit = unit_text(unit)
        if self.what in ("start", "end"):
            return (_STARTS if self.what == "start" else _ENDS)[self.value]
        if self.what == "step":
            return f"a sudden step{' ' + self.way if self.way else ''} at t = {_s(self.at)} s"
        if self.what == "sign-change":
            return ("changes sign" if self.count is None
                    else "never changes sign" if self.count == 0 else f"changes sign {self.count} times")
        if self.what == "peak":
            return f"reaches at least {_s(self.above)} {unit}"
        words = self.what + (f" {_GRADIENT_WORDS[self.gradient]}" if self.gradient else "")
        if self.what == "level" and self.at is not None:
            words += f" at {_s(self.at)} {unit}"
        return f"{words} from t = {_s(self.start)} s to {_s(self.stop)} s"


@dataclass(frozen=True)
class SketchPoint:
    """A marking point (B1): its text as the scheme words it, the features it needs, the
    features that lose it, and the paper whose scheme it follows ("9702/21/M/J/23 Q3(c)")."""

    text: str
    needs: tuple[Feature, ...]
    source: str
    loses: tuple[Feature, ...] = ()

    def __post_init__(self):
        _require(bool(self.needs), "needs", self.needs, "must name at least one feature of the line")
        _require(self.source.startswith(("9702/", "8702/")), "source", self.source,
                 "must cite the published 9702 paper whose scheme gives this point")

    def describe(self, unit: str) -> str:
        needs = "; ".join(f.describe(unit) for f in self.needs)
        loses = "; ".join(f.describe(unit) for f in self.loses)
        return f"needs: {needs}" + (f"; lost if: {loses}" if loses else "")


@dataclass(frozen=True)
class SketchAxes:
    """The printed axes: time from 0 to ``t_max`` (s) in divisions of ``t_division``, the
    quantity (``symbol``, ``unit`` in plain text) from ``y_min`` to ``y_max`` in ``y_division``s."""

    quantity: str
    symbol: str
    unit: str
    t_max: float
    t_division: float
    y_max: float
    y_division: float
    y_min: float = 0.0

    def __post_init__(self):
        _require(self.t_max > 0 and self.t_division > 0, "t_max", self.t_max, "must be positive")
        _require(self.y_max > self.y_min and self.y_division > 0, "y_max", self.y_max,
                 f"must be above y_min={self.y_min}")
        for name, span, division in (("t_max", self.t_max, self.t_division),
                                     ("y_max", self.y_max - self.y_min, self.y_division)):
            count = span / division
            _require(abs(count - round(count)) < 1e-6 and 2 <= round(count) <= 20, name, span,
                     f"must be 2 to 20 whole divisions of {division}")

    def browser_data(self) -> dict:
        return {"t": [0.0, self.t_max], "y": [self.y_min, self.y_max], "quantity": self.quantity,
                "symbol": self.symbol, "unit": unit_text(self.unit),
                "tDivision": self.t_division, "yDivision": self.y_division}


@dataclass(frozen=True)
class SketchTolerance:
    """How exactly a feature must be drawn, as shares of the axes: a value within ``value`` of
    the y span is at it (and zero within it), a time within ``time`` of the t span, a change of
    more than ``step`` of the y span within that time is a step, and two gradients differ when
    they differ by more than ``curve`` of the larger."""

    value: float = 0.05
    time: float = 0.04
    step: float = 0.2
    curve: float = 0.3

    def __post_init__(self):
        for name in ("value", "time", "step", "curve"):
            share = getattr(self, name)
            _require(0 < share < 0.5, name, share, "must be a share of the axes between 0 and 0.5")

    def browser_data(self) -> dict:
        return {"value": self.value, "time": self.time, "step": self.step, "curve": self.curve}


@dataclass(frozen=True)
class WrongSketch:
    """A wrong line a student draws, named, with the marking points it still earns (by index):
    the tests draw it by pointer and build it by keyboard, and the key says what it keeps."""

    name: str
    line: tuple[tuple[float, float], ...]
    keeps: tuple[int, ...]


@dataclass(frozen=True)
class SketchPart(NoValue):
    """A sketch on the question's axes, marked on its points (each a B1). ``model`` is the
    right line (the key's figure, and what the tests draw); ``wrong`` are lines students draw,
    with the points each keeps."""

    prompt: str
    axes: SketchAxes
    points: tuple[SketchPoint, ...]
    model: tuple[tuple[float, float], ...]
    wrong: tuple[WrongSketch, ...] = ()
    tolerance: SketchTolerance = field(default_factory=SketchTolerance)
    #: The section a sketch that misses a feature sends the student back to (bank.sections).
    see: str | None = None
    kind: ClassVar[str] = "sketch"
    asks: ClassVar[str] = "sketch"
    revisit: ClassVar[str] = ""
    #: Its question may print a graph to sketch from (9702/21/M/J/23 Q3: force X from a
    #: momentum-time graph).
    drawn_from_graph: ClassVar[bool] = True
    #: The marker, and the page's side of the part (it asks the pad: static/sketch-pad.js,
    #: loaded with sketch.css only on the pages that ask a sketch).
    browser_script: ClassVar[str] = str(SCRIPTS / "sketch.js")
    page_assets: ClassVar[tuple[str, ...]] = ("sketch-pad.js", "sketch.css")

    def __post_init__(self):
        object.__setattr__(self, "model", _line(self.model))
        _require(len(self.model) >= 2, "model", self.model, "must hold at least two points")
        _require(bool(self.points), "points", self.points, "must hold the scheme's marking points")
        self._check_inside(self.model, "model")
        for wrong in self.wrong:
            self._check_inside(_line(wrong.line), f"wrong '{wrong.name}'")
            _require(all(0 <= i < len(self.points) for i in wrong.keeps), "keeps", wrong.keeps,
                     f"must index the {len(self.points)} marking points")

    def _check_inside(self, line, name: str) -> None:
        times = [t for t, _ in line]
        _require(all(b >= a for a, b in itertools.pairwise(times)), name, line, "must run forward in time")
        _require(all(0 <= t <= self.axes.t_max + 1e-9 and self.axes.y_min - 1e-9 <= y <= self.axes.y_max + 1e-9
                     for t, y in line), name, line, "must lie inside the axes")

    @property
    def answer_text(self) -> str:
        """The key in words: each marking point with the features it reads."""
        return " ".join(f"{point.text} (B1: {point.describe(self.axes.unit)})." for point in self.points)

    def browser_data(self, part_id: str) -> dict:
        from ..figures.sketch_axes import axes_svg  # SVG text only: no matplotlib

        return {"id": part_id, "kind": self.kind, "prompt": self.prompt, "see": self.see,
                "axes": self.axes.browser_data(),
                "svg": axes_svg(self.axes),
                "tolerance": self.tolerance.browser_data(),
                "points": [{"text": p.text, "needs": [f.browser_data() for f in p.needs],
                            "loses": [f.browser_data() for f in p.loses]} for p in self.points]}

    # ------------------------------------------------------- the kind's hooks (parts/__init__.py)

    @classmethod
    def form_html(cls, part: dict, question: dict, *, base: str, label: str, page: dict) -> str:
        """The axes to draw on (the drawing area alone takes touch for the pen), Undo and Clear,
        and the keyboard builder, whose every step is announced."""
        return _form_html(base, part) + feedback_html(base)

    def print_lines(self, label: str, marks: int, paper) -> list:
        """On paper and without JavaScript: the prompt, the blank axes, the marks."""
        from ..figures.sketch_axes import axes_svg, axes_tikz  # SVG and TikZ text only

        return [paper.line(f"{label}{self.prompt}"), *paper.figure(axes_svg(self.axes), axes_tikz(self.axes)),
                paper.line(f"[{marks}]")]

    def _features(self) -> list[str]:
        return [f"{point.text} (B1; {point.describe(self.axes.unit)}; {point.source})" for point in self.points]

    def latex_sheet(self, question, index: int, marks: int, sheet) -> str:
        from ..figures.sketch_axes import axes_tikz

        return (f"\\par\\vspace{{4pt}}\\needspace{{8cm}}{sheet.tex(question.label(index) + self.prompt)}\\par"
                f"\\begin{{center}}{axes_tikz(self.axes)}\\end{{center}}\\partmarks{{{marks}}}\\par")

    def latex_key(self, question, index: int, marks: int, sheet) -> list[str]:
        """The model line on the axes, then each feature that earns a B1, with its paper."""
        from ..figures.sketch_axes import axes_tikz

        tex = sheet.tex
        items = "\n".join(f"\\item {tex(item)}" for item in self._features())
        return [f"\\textbf{{{tex(question.label(index))}A sketch marked on its features}} \\hfill [{marks}]",
                f"\\begin{{center}}{axes_tikz(self.axes, line=self.model)}\\end{{center}}",
                f"\\begin{{itemize}}[leftmargin=1.5em,itemsep=0pt,topsep=2pt]\n{items}\n\\end{{itemize}}"]

    def html_sheet(self, question, index: int, marks: int, sheet) -> str:
        from ..figures.sketch_axes import axes_svg

        return (f'<div class="sb-part"><p>{escape(question.label(index) + self.prompt)}</p>'
                f'<figure class="sb-graph">{axes_svg(self.axes)}</figure>'
                f'<p class="sb-answer">{sheet.marks_html(marks)}</p></div>')

    def html_key(self, question, index: int, marks: int, sheet) -> str:
        from ..figures.sketch_axes import axes_svg

        items = "".join(f"<li>{escape(item)}</li>" for item in self._features())
        return (f'<p class="sb-key-answer"><strong>{escape(question.label(index))}A sketch marked on its features'
                f'</strong> {sheet.marks_html(marks)}</p><figure class="sb-graph">'
                f"{axes_svg(self.axes, line=self.model)}</figure><ul>{items}</ul>")

    def moodle(self, out, item, question, index: int) -> None:
        """No sketch type in Moodle: an essay on the printed axes (a file), with each feature's
        B1 and the sketches students draw as the grader's information (CLARIFICATIONS, Papers)."""
        from ..figures.sketch_axes import HEIGHT, WIDTH, axes_svg

        axes_file = f"{item.idnumber}-axes.svg"
        axes = (f'<p><img src="@@PLUGINFILE@@/{axes_file}" alt="{escape(self.axes.quantity)} against time: axes '
                f'to sketch on" width="{WIDTH}" height="{HEIGHT}"></p><p>Sketch the line on these axes (on paper, '
                "or as a drawing you attach) and describe its shape: where it starts, where it rises, falls or is "
                "level, and how its gradient changes.</p>")
        features = "".join(f"<li>{escape(text)}</li>" for text in self._features())
        wrong = "".join(f"<li>{escape(w.name)}: {len(w.keeps)}/{len(self.points)}</li>" for w in self.wrong)
        grader = (f"<p><strong>Marking the sketch: one B1 for each feature</strong></p><ul>{features}</ul>"
                  + (f"<p><strong>Sketches students draw, and their marks</strong></p><ul>{wrong}</ul>" if wrong else "")
                  + item.scheme + item.how_marked)
        out.essay(item.name, item.idnumber, item.stem + item.ask + f" [{item.marks}]</p>" + axes, item.marks,
                  item.general, {**item.files, axes_file: axes_svg(self.axes).encode()}, grader)


def _form_html(base: str, part: dict) -> str:
    """The part's form on the page, from its browser data: the axes to draw on (the SVG, whose
    drawing area alone takes touch for the pen), Undo and Clear, and the keyboard builder (a
    start value, then segments), whose every step is announced in the status line."""
    unit = part["axes"]["unit"]
    options = "".join(f'<option value="{value}">{words}</option>' for value, words in (
        ("rising", "rising"), ("falling", "falling"), ("level", "level"), ("step-up", "a step up"),
        ("step-down", "a step down")))
    shapes = "".join(f'<option value="{value}">{words}</option>' for value, words in (
        ("straight", "straight"), ("steeper", "getting steeper (curving up)"),
        ("less", "getting less steep (curving over)")))
    field = ('<label class="q-field" for="{id}"><span>{label}</span>'
             '<input type="number" step="any" class="q-sketch-{name}" id="{id}"{value}></label>')
    return (
        f'<div class="q-sketch-pad" data-unit="{escape(unit)}">'
        f'<div class="q-sketch-draw">{part["svg"]}</div>'
        '<div class="q-sketch-tools"><button type="button" class="q-sketch-undo">Undo</button>'
        '<button type="button" class="q-sketch-clear">Clear the line</button></div>'
        '<details class="q-sketch-keys"><summary>Build the line from segments (keyboard)</summary>'
        + field.format(id=f"{base}-start", label=f"Start value at t = 0 ({unit})", name="start", value=' value="0"')
        + '<button type="button" class="q-sketch-set-start">Start the line here</button>'
        f'<label class="q-field" for="{base}-kind"><span>Next segment</span>'
        f'<select class="q-sketch-kind" id="{base}-kind">{options}</select></label>'
        f'<label class="q-field" for="{base}-shape"><span>Its gradient</span>'
        f'<select class="q-sketch-shape" id="{base}-shape">{shapes}</select></label>'
        + field.format(id=f"{base}-until", label="Until t = (s)", name="until", value="")
        + field.format(id=f"{base}-to", label=f"To the value ({unit})", name="to", value="")
        + '<button type="button" class="q-sketch-add">Add the segment</button></details>'
        f'<p class="q-sketch-status" aria-live="polite" id="{base}-status"></p></div>')


def _line(points) -> tuple[tuple[float, float], ...]:
    line = tuple((float(t), float(y)) for t, y in points)
    _require(all(math.isfinite(t) and math.isfinite(y) for t, y in line), "line", line, "must be finite numbers")
    return line
