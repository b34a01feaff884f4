# ruff: noqa: RUF002  (typeset text: en dashes in graph names)
"""The graph a question prints (a momentum–time, force–time or velocity–time graph), drawn
from one variant's :class:`physics_figures.questions.Graph`: straight lines through its
points on a grid of small squares, as an exam paper prints a graph to read from. The
numbers are the question's; nothing is computed here.
"""

from __future__ import annotations

import math
from typing import NamedTuple

from matplotlib.axes import Axes
from matplotlib.lines import Line2D
from matplotlib.ticker import FixedLocator, FuncFormatter, MultipleLocator

from ..notation import format_number
from ..questions import Graph
from ..style import colour
from ._text import plain
from .book_figure import BookFigure
from .style import GUIDE, MAIN, SHADE, new_axes, styled, unit_label

#: A labelled grid line every 1, 2, 5 or 10 small squares: the first that gives at most
#: this many labels along an axis.
_MOST_LABELS = 8
_LABEL_EVERY = (1, 2, 5, 10)


#: Inches: about 310 pt of SVG, so 12 pt ticks are >= 11 CSS px in a 320 px wide box.
QUESTION_GRAPH_SIZE = (4.2, 3.3)


class QuestionGraph(NamedTuple):
    axes: Axes
    line: Line2D


def _decimals(step: float) -> int:
    """Decimal places that write every multiple of ``step`` exactly (0.25 -> 2)."""
    for places in range(6):
        scaled = step * 10**places
        if math.isclose(scaled, round(scaled), abs_tol=1e-9):
            return places
    return 6


def _label_step(span: float, division: float) -> float:
    for every in _LABEL_EVERY:
        if span / (division * every) <= _MOST_LABELS:
            return division * every
    return division * _LABEL_EVERY[-1]


def _axis(axis, low: float, high: float, division: float) -> None:
    step = _label_step(high - low, division)
    places = _decimals(step)
    count = round((high - low) / step)
    axis.set_major_locator(FixedLocator([low + i * step for i in range(count + 1)]))
    axis.set_major_formatter(FuncFormatter(lambda value, _: format_number(value, decimals=places)))
    axis.set_minor_locator(MultipleLocator(division))


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
    _axis(ax.xaxis, 0.0, graph.time_max, graph.time_division)
    _axis(ax.yaxis, graph.value_min, graph.value_max, graph.value_division)
    ax.grid(which="minor", color=colour("figure.grid-minor"), linewidth=0.5)
    ax.grid(which="major", color=colour("figure.grid-major"), linewidth=0.8)
    ax.set_axisbelow(True)
    if graph.value_min < 0:
        ax.axhline(0, color=GUIDE, linewidth=1.0)
    if graph.shaded:
        ax.fill_between(times, values, 0, color=SHADE, alpha=0.35, linewidth=0)
    (line,) = ax.plot(times, values, color=MAIN, zorder=3)
    ax.set_xlabel(unit_label("time", "s"))
    ax.set_ylabel(unit_label(graph.quantity, graph.unit))
    return QuestionGraph(ax, line)


def question_graph_alt(graph: Graph) -> str:
    """The graph in words, for a reader who cannot see it: its axes and every corner, each
    number to the places of the grid's small squares."""
    t_places, v_places = _decimals(graph.time_division), _decimals(graph.value_division)

    def time(value: float) -> str:
        return format_number(value, decimals=t_places)

    def amount(value: float) -> str:
        return format_number(value, decimals=v_places)

    # a curve is read out where it crosses the labelled times (0, 5, 10 s ...), as one reads it
    points = graph.points
    if graph.curve:
        step = _label_step(graph.time_max, graph.time_division)
        points = tuple(p for p in points if math.isclose(p[0] / step, round(p[0] / step), abs_tol=1e-9))
    corners = ", then ".join(f"({time(t)} s, {amount(v)} {graph.unit})" for t, v in points)
    lines = "A smooth curve passes through" if graph.curve else "Straight lines join"
    return plain(
        f"A {graph.name} graph: {graph.quantity} in {graph.unit} from {amount(graph.value_min)} to "
        f"{amount(graph.value_max)} against time in s from 0 to {time(graph.time_max)}, on small "
        f"squares of {time(graph.time_division)} s by {amount(graph.value_division)} {graph.unit}. "
        f"{lines} {corners}." + (" The area under the line is shaded." if graph.shaded else "")
    )


# --- The book's figures from this module (see book_figure.py); a page calls one of these. ---


def question_graph(graph: Graph) -> BookFigure:
    """The graph a question prints, for one variant (the question directive draws it)."""
    drawn = plot_question_graph(graph)
    return BookFigure("question-graph", drawn.axes.figure, "", question_graph_alt(graph))
