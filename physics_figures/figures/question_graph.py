# ruff: noqa: RUF002  (typeset text: en dashes in graph names)
"""The graph a question prints (a momentum–time, force–time or velocity–time graph), drawn
from one variant's :class:`physics_figures.pictures.Graph`: straight lines through its
points on a grid of small squares, as an exam paper prints a graph to read from. The
numbers are the question's; nothing is computed here.
"""

from __future__ import annotations

import functools
import html
import itertools
import math
import re
from collections.abc import Callable
from typing import NamedTuple

import matplotlib as mpl
from matplotlib.axes import Axes
from matplotlib.font_manager import FontProperties
from matplotlib.lines import Line2D
from matplotlib.markers import TICKDOWN, TICKLEFT
from matplotlib.textpath import text_to_path
from matplotlib.ticker import FixedLocator, FuncFormatter

from ..notation import LARGEST_PLAIN, axis_power, format_number, power_text, round_number
from ..pictures import Graph
from ..style import colour
from ._text import plain
from .book_figure import BookFigure
from .style import GUIDE, MAIN, SHADE, SMALL_TEXT, book_style, new_axes, styled, unit_label

#: A labelled grid line every 1, 2, 5 or 10 small squares: the first that gives at most
#: this many labels along an axis, with room between neighbouring labels.
_MOST_LABELS = 8
_LABEL_EVERY = (1, 2, 5, 10)
#: Points of clear paper between two neighbouring labels, at the least (half a label's size).
_LABEL_GAP = 6.0
#: Points between the time axis and its labels: a little more than the book's 3.5, so where the
#: axes meet the first time label stays clear of the lowest value label.
_TIME_LABEL_PAD = 5.0


#: Inches: about 310 pt of SVG, so 12 pt ticks are >= 11 CSS px in a 320 px wide box.
QUESTION_GRAPH_SIZE = (4.2, 3.3)
#: The id of the plot area (the grid's frame) in the SVG: the enlarged view zooms by its size.
PLOT_AREA_ID = "q-graph-area"
#: The id of the small squares' lines in the SVG: one path of many straight pieces.
SMALL_SQUARES_ID = "q-graph-small-squares"


class QuestionGraph(NamedTuple):
    axes: Axes
    line: Line2D


class AxisScale(NamedTuple):
    """How an axis is labelled: a label every ``step`` (SI), each written as value / 10^power
    to ``places`` decimal places (power 0: the plain value)."""

    step: float
    power: int
    places: int

    def text(self, value: float) -> str:
        return format_number(value / 10.0**self.power, decimals=self.places)


def _decimals(step: float) -> int:
    """Decimal places that write every multiple of ``step`` exactly (0.25 -> 2)."""
    for places in range(6):
        scaled = step * 10**places
        if math.isclose(scaled, round(scaled), abs_tol=1e-9):
            return places
    return 6


def _scale(low: float, high: float, step: float) -> AxisScale:
    power = axis_power(max(abs(low), abs(high)), step)
    return AxisScale(step, power, _decimals(step / 10.0**power))


@functools.cache
def _text_size(text: str) -> tuple[float, float]:
    """Width and height in points of a tick label, as matplotlib lays it out (the height of a
    line of text, as Text measures it)."""
    with book_style():
        prop = FontProperties(size=mpl.rcParams["xtick.labelsize"])
        width = text_to_path.get_text_width_height_descent(text, prop, ismath=False)[0]
        height = text_to_path.get_text_width_height_descent("lp", prop, ismath=False)[1]
    return width, height


def _labels(low: float, high: float, scale: AxisScale) -> list[str]:
    count = round((high - low) / scale.step)
    return [scale.text(low + i * scale.step) for i in range(count + 1)]


def _choose(low: float, high: float, division: float, room: Callable[[AxisScale], float],
            across: bool) -> AxisScale:
    """The first labelling, every 1, 2, 5 or 10 small squares, with at most _MOST_LABELS labels
    whose neighbours leave _LABEL_GAP between them along an axis ``room(scale)`` points long."""
    for every in _LABEL_EVERY:
        scale = _scale(low, high, division * every)
        labels = _labels(low, high, scale)
        size = max(_text_size(label)[0 if across else 1] for label in labels)
        if len(labels) - 1 <= _MOST_LABELS and room(scale) * scale.step / (high - low) >= size + _LABEL_GAP:
            return scale
    return _scale(low, high, division * _LABEL_EVERY[-1])


def axis_scales(graph: Graph) -> tuple[AxisScale, AxisScale]:
    """(time axis, value axis): where each is labelled and how its labels are written. The plot
    area's size is worked out from the figure's as the layout leaves it (the labels and pads
    around it), so the choice is the same wherever the graph is drawn and read."""
    with book_style():
        rc = mpl.rcParams
        pad = 72 * rc["figure.constrained_layout.w_pad"]
        below = rc["xtick.major.size"] + _TIME_LABEL_PAD  # the time axis's ticks and their labels' pad
        beside = rc["ytick.major.size"] + rc["ytick.major.pad"]
        label = 1.2 * rc["axes.labelsize"] + rc["axes.labelpad"]
    width, height = (72 * side for side in QUESTION_GRAPH_SIZE)
    line = _text_size("0")[1]
    # below: the time labels and the axis's label; above: half the top value label
    value = _choose(graph.value_min, graph.value_max, graph.value_division,
                    lambda _: height - 2 * pad - line - below - label - line / 2, across=False)
    widest = max(_text_size(text)[0] for text in _labels(graph.value_min, graph.value_max, value))
    # left: the value labels and the axis's label; right: half the last time label
    time = _choose(0.0, graph.time_max, graph.time_division,
                   lambda scale: (width - 2 * pad - widest - beside - label
                                  - _text_size(scale.text(graph.time_max))[0] / 2), across=True)
    return time, value


def _axis(axis, low: float, high: float, division: float, scale: AxisScale) -> list[float]:
    """Label every few small squares; return where the other small squares' lines go."""
    count = round((high - low) / scale.step)
    axis.set_major_locator(FixedLocator([low + i * scale.step for i in range(count + 1)]))
    axis.set_major_formatter(FuncFormatter(lambda value, _: scale.text(value)))
    every = round(scale.step / division)
    first, last = math.ceil(low / division - 1e-9), math.floor(high / division + 1e-9)
    return [k * division for k in range(first, last + 1) if (k - first) % every]


def _unit(unit: str, power: int) -> str:
    """An axis's unit with the power of ten its labels are written in: "10⁵ N s"."""
    return f"{power_text(power)} {unit}" if power else unit


def _small_squares(ax: Axes, across: list[float], up: list[float]) -> None:
    """The lines of the small squares and their short ticks on the axes, each as one drawn
    line, not as matplotlib's minor ticks: about ninety Tick objects, each five artists made
    and laid out again on every draw, were most of the time a graph took to draw."""
    (x_low, x_high), (y_low, y_high) = ax.get_xlim(), ax.get_ylim()
    xs, ys = [], []
    for x in across:
        xs += [x, x, math.nan]
        ys += [y_low, y_high, math.nan]
    for y in up:
        xs += [x_low, x_high, math.nan]
        ys += [y, y, math.nan]
    # under the labelled lines (the axis, ticks and major grid, sit at zorder 0.5)
    ax.add_line(Line2D(xs, ys, color=colour("figure.grid-minor"), linewidth=0.5, zorder=0.4,
                       gid=SMALL_SQUARES_ID))
    for positions, transform, marker, rc in (
        ((across, [0.0] * len(across)), ax.get_xaxis_transform(), TICKDOWN, "xtick"),
        (([0.0] * len(up), up), ax.get_yaxis_transform(), TICKLEFT, "ytick"),
    ):
        ticks = Line2D(*positions, transform=transform, linestyle="none", marker=marker,
                       markersize=mpl.rcParams[f"{rc}.minor.size"],
                       markeredgewidth=mpl.rcParams[f"{rc}.minor.width"],
                       color=mpl.rcParams[f"{rc}.color"], clip_on=False, zorder=0.45)
        ticks.set_in_layout(False)  # inside the labels' reach: the layout need not measure them
        ax.add_line(ticks)


@styled
def plot_question_graph(graph: Graph, *, ax: Axes | None = None) -> QuestionGraph:
    """The graph on a grid of small squares, labelled every few squares, for reading."""
    # narrower than a book figure: a question's graph sits inside the question's box,
    # about 320 CSS px wide on a 390 px phone, and its labels must stay >= 11 CSS px there
    ax = new_axes(ax, figsize=QUESTION_GRAPH_SIZE)
    times = [t for t, _ in graph.points]
    values = [v for _, v in graph.points]
    ax.set_xlim(0, graph.time_max)
    ax.set_ylim(graph.value_min, graph.value_max)
    time_scale, value_scale = axis_scales(graph)
    across = _axis(ax.xaxis, 0.0, graph.time_max, graph.time_division, time_scale)
    up = _axis(ax.yaxis, graph.value_min, graph.value_max, graph.value_division, value_scale)
    ax.tick_params(axis="x", which="major", pad=_TIME_LABEL_PAD)
    _small_squares(ax, across, up)
    ax.grid(which="major", color=colour("figure.grid-major"), linewidth=0.8)
    ax.set_axisbelow(True)
    ax.patch.set_gid(PLOT_AREA_ID)
    if graph.value_min < 0:
        ax.axhline(0, color=GUIDE, linewidth=1.0)
    if graph.shaded:
        ax.fill_between(times, values, 0, color=SHADE, alpha=0.35, linewidth=0)
    (line,) = ax.plot(times, values, color=MAIN, zorder=3)
    ax.set_xlabel(unit_label("time", _unit("s", time_scale.power)))
    ax.set_ylabel(unit_label(graph.quantity, _unit(graph.unit, value_scale.power)))
    return QuestionGraph(ax, line)


def _shape(graph: Graph) -> str:
    """The drawn line in words, with no number on it: which way each straight piece goes and
    where it meets or crosses the time axis (the turns' times and values are what a part reads)."""
    values = [v for _, v in graph.points]
    if graph.curve:
        slopes = [b - a for a, b in itertools.pairwise(values)]
        start = " from zero" if values[0] == 0 else ""
        if all(s >= 0 for s in slopes) and all(b <= a + 1e-12 for a, b in itertools.pairwise(slopes)):
            return (f"A smooth curve rises{start}, steeply at first, then less and less steeply, and "
                    "levels off.")
        return f"A smooth curve {'rises' if values[-1] > values[0] else 'falls'}{start}."
    flat = 1e-9 * (graph.value_max - graph.value_min)
    pieces: list[list] = []  # [way, first value, last value] of each run of pieces going one way
    for a, b in itertools.pairwise(values):
        way = "level" if abs(b - a) <= flat else ("rises" if b > a else "falls")
        if pieces and pieces[-1][0] == way:
            pieces[-1][2] = b
        else:
            pieces.append([way, a, b])
    words = []
    for way, first, last in pieces:
        if way == "level":
            side = "on" if first == 0 else ("above" if first > 0 else "below")
            words.append(f"is level {side} the time axis")
            continue
        phrase = f"{way} steadily"
        if first == 0:
            phrase += " from zero"
        if first * last < 0:
            phrase += " through the time axis"
        if last == 0:
            phrase += " to zero"
        words.append(phrase)
    return "The line " + ", then ".join(words) + "."


def question_graph_alt(graph: Graph) -> str:
    """The graph in words, for a reader who cannot see it: its axes, their scales and the
    shape of the line. It gives no value a part asks to be read off it (issue 25: the alt text
    gave the readings away), so no point of the line is written."""
    t_places, v_places = _decimals(graph.time_division), _decimals(graph.value_division)

    def time(value: float) -> str:
        return format_number(value, decimals=t_places)

    def amount(value: float) -> str:
        if abs(value) >= LARGEST_PLAIN:  # in powers of ten, with only the figures it has: "1.5 x 10^5"
            figures = len(str(round(abs(value))).rstrip("0"))
            return format_number(value, max(figures, 2))
        return format_number(value, decimals=v_places)

    return plain(
        f"A {graph.name} graph: {graph.quantity} in {graph.unit} from {amount(graph.value_min)} to "
        f"{amount(graph.value_max)} against time in s from 0 to {time(graph.time_max)}, on small "
        f"squares of {time(graph.time_division)} s by {amount(graph.value_division)} {graph.unit}. "
        f"{_shape(graph)}" + (" The area under the line is shaded." if graph.shaded else "")
    )


def _plot_area(svg: str) -> tuple[float, float, float, float, float, float]:
    """The plot area's frame in the SVG's own units, (left, top, right, bottom), and the
    viewBox's width and height."""
    view = re.search(r'viewBox="([\d.\s-]+)"', svg)
    area = re.search(rf'<g id="{PLOT_AREA_ID}">\s*<path d="([^"]+)"', svg)
    if view is None or area is None:
        raise ValueError(f"svg must hold a viewBox and the plot area <g id={PLOT_AREA_ID!r}> "
                         "(plot_question_graph draws it)")
    width, height = (float(x) for x in view[1].split()[2:4])
    xs, ys = zip(*_path_points(area[1]), strict=True)
    return min(xs), min(ys), max(xs), max(ys), width, height


def _path_points(d: str) -> list[tuple[float, float]]:
    """The points of absolute path data of moves and lines, as matplotlib writes it
    ("M 52.16 200.36 L 293.38 200.36 …") or as the site compacts it ("M52.16 200.36H293.38V10.32z",
    book/_ext/svg_compact.py)."""
    points: list[tuple[float, float]] = []
    for command, numbers in re.findall(r"([MLHVz])([^MLHVz]*)", d):
        values = [float(x) for x in re.findall(r"-?\d+(?:\.\d+)?(?:e-?\d+)?", numbers)]
        x, y = points[-1] if points else (0.0, 0.0)
        if command in "ML":
            points += list(zip(values[0::2], values[1::2], strict=True))
        elif command == "H":
            points += [(value, y) for value in values]
        elif command == "V":
            points += [(x, value) for value in values]
    return points


def small_square(svg: str, graph: Graph) -> tuple[float, float]:
    """A small square's width and height as fractions of the drawn image's width, measured in
    its SVG (the plot area's frame over the viewBox): the enlarged view zooms until half a
    square is big enough to read from (book/_ext/questions/static/graph-view.js)."""
    left, top, right, bottom, width, _ = _plot_area(svg)
    across = round(graph.time_max / graph.time_division)
    up = round((graph.value_max - graph.value_min) / graph.value_division)
    return ((right - left) / across / width, (bottom - top) / up / width)


#: How a reading names each quantity: "t = 1.5 s, v = 12.5 m s⁻¹".
SYMBOLS = {"time": "t", "velocity": "v", "momentum": "p", "force": "F"}


def _axis_data(label: str, unit: str, low: float, high: float, division: float, scale: AxisScale) -> dict:
    power = 10.0**scale.power
    return {"symbol": SYMBOLS.get(label, label), "label": label, "unit": unit, "min": low, "max": high,
            "square": division, "large": scale.step,
            # the power of ten the axis's labels are written in ("p / 10⁵ N s"), and the places of
            # a reading in those labels' terms, on a small square's line and half-way between two
            "power": scale.power, "places": [_decimals(division / power), _decimals(division / 2 / power)]}


_TICK_TEXT = re.compile(r'<text style="([^"]*)" x="([-\d.]+)" y="([-\d.]+)"[^>]*>([^<]*)</text>')


def _numbers_edges(svg: str) -> list[float]:
    """Where the axes' numbers end, as fractions of the image: the left edge of the value
    axis's (over its width) and the foot of the time axis's (over its height). The enlarged
    view keeps both in sight as it opens (graph-view.js)."""
    *_, width, height = _plot_area(svg)
    left, foot = width, 0.0
    for style, x, y, text in _TICK_TEXT.findall(svg):
        if f"font-size: {SMALL_TEXT:g}px" not in style:  # a tick label, not an axis's label
            continue
        size, line = _text_size(html.unescape(text))
        if "text-anchor: end" in style:
            left = min(left, float(x) - size)
        elif "text-anchor: middle" in style:
            foot = max(foot, float(y) + 0.25 * line)
    return [float(round_number(left / width, decimals=5)), float(round_number(foot / height, decimals=5))]


def cursor_data(svg: str, graph: Graph) -> dict:
    """What the graph cursor (book/_ext/questions/static/graph-cursor.js) reads: both axes as
    drawn here (label, unit, ends, small and large square, the power of ten of their labels),
    the line's readings at each half small square of time (Graph.readings: the question's own
    numbers, to half a small square, in SI), and the plot area as fractions of the image's
    width and height (left, top, right, bottom), where a tap on the enlarged graph is turned
    into a time, and where the axes' numbers end (left of the value axis's, foot of the time
    axis's), which the enlarged view keeps in sight as it opens."""
    left, top, right, bottom, width, height = _plot_area(svg)
    time_scale, value_scale = axis_scales(graph)
    return {
        "time": _axis_data("time", "s", 0.0, graph.time_max, graph.time_division, time_scale),
        "value": _axis_data(graph.quantity, graph.unit, graph.value_min, graph.value_max, graph.value_division,
                            value_scale),
        "readings": list(graph.readings()),
        "area": [float(round_number(side, decimals=5)) for side in (left / width, top / height, right / width, bottom / height)],
        "numbers": _numbers_edges(svg),
    }


# --- The book's figures from this module (see book_figure.py); a page calls one of these. ---


def question_graph(graph: Graph) -> BookFigure:
    """The graph a question prints, for one variant (the question directive draws it)."""
    drawn = plot_question_graph(graph)
    return BookFigure("question-graph", drawn.axes.figure, "", question_graph_alt(graph))
