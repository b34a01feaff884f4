"""Momentum-time and force-time graphs (Notes, "Reading a momentum-time graph"), drawn
from a :class:`physics_figures.models.momentum_history.MomentumHistory`.

The gradient of the momentum-time graph is the resultant force; the area under the
force-time graph is the change in momentum. Both numbers come from the model
(``segments``, ``segment_forces`` and ``models.impulse``).
"""

from __future__ import annotations

from typing import NamedTuple

from matplotlib.axes import Axes
from matplotlib.collections import PolyCollection
from matplotlib.lines import Line2D
from matplotlib.text import Text

from ..models import impulse
from ..models.momentum_history import MomentumHistory
from ..notation import format_number
from ._data import Column, axes_sentence, axis_words, description, figure_data
from ._text import IMPULSE_UNIT, MOMENTUM_UNIT, VELOCITY_UNIT, a_or_an, plain, seconds
from .book_figure import BookFigure, FigureData
from .style import GUIDE, MAIN, PAPER, SHADE, new_axes, styled, unit_label


class MomentumTimeGraph(NamedTuple):
    """Artists of a momentum-time graph."""

    axes: Axes
    line: Line2D
    corners: Line2D
    segment_labels: list[Text]  # one per segment: its gradient, the resultant force


class ForceTimeGraph(NamedTuple):
    """Artists of a force-time graph with the areas shaded."""

    axes: Axes
    line: Line2D
    areas: list[PolyCollection]  # one per segment with a force
    area_labels: list[Text]  # the change in momentum each area stands for


def _force_text(force: float) -> str:
    return "0" if force == 0 else f"{format_number(force, 2)} N"


@styled
def plot_momentum_time(history: MomentumHistory, *, ax: Axes | None = None) -> MomentumTimeGraph:
    """Momentum against time, each straight segment labelled with its gradient (force)."""
    ax = new_axes(ax)
    (line,) = ax.plot(history.times, history.momenta, color=MAIN, zorder=3)
    (corners,) = ax.plot(
        history.times, history.momenta, linestyle="none", marker="o", color=MAIN, zorder=4
    )
    labels = []
    for segment in history.segments:
        # a rising segment is labelled high up (3/4 of the way along), a falling one low
        # down (3/4 of the way along), both just inside the graph, so the two never meet
        along = 0.5 if segment.force == 0 else 0.75
        point = (
            segment.t0 + along * (segment.t1 - segment.t0),
            segment.p0 + along * (segment.p1 - segment.p0),
        )
        offset, ha, va = (
            ((10, -4), "left", "top")
            if segment.force > 0
            else ((-10, -4), "right", "top")
            if segment.force < 0
            else ((0, 8), "center", "bottom")
        )
        labels.append(
            ax.annotate(
                f"gradient = {_force_text(segment.force)}",
                xy=point,
                xytext=offset,
                textcoords="offset points",
                ha=ha,
                va=va,
            )
        )
    top = max(history.momenta)
    ax.set_xlim(history.times[0], history.times[-1])
    ax.set_ylim(min(0, min(history.momenta)), top * 1.3)
    ax.set_xlabel(unit_label("time t", "s"))
    ax.set_ylabel(unit_label("momentum p", MOMENTUM_UNIT))
    ax.yaxis.set_major_formatter(lambda value, _: format_number(value, 3) if value else "0")
    return MomentumTimeGraph(ax, line, corners, labels)


@styled
def plot_force_time_area(history: MomentumHistory, *, ax: Axes | None = None) -> ForceTimeGraph:
    """Resultant force against time; each shaded area is labelled with its change in momentum."""
    ax = new_axes(ax)
    times, forces = [], []
    for segment in history.segments:
        times += [segment.t0, segment.t1]
        forces += [segment.force, segment.force]
    (line,) = ax.plot(times, forces, color=MAIN, zorder=3)
    ax.axhline(0, color=GUIDE, linewidth=1.0, zorder=2)
    areas, labels = [], []
    for segment in history.segments:
        if segment.force == 0:
            continue
        areas.append(
            ax.fill_between(
                [segment.t0, segment.t1],
                [segment.force, segment.force],
                color=SHADE,
                alpha=0.45,
                hatch="//" if segment.force > 0 else "\\\\",
                edgecolor=MAIN,
                linewidth=0,
                zorder=1,
            )
        )
        change = impulse(segment.force, segment.t1 - segment.t0)
        labels.append(
            ax.text(
                (segment.t0 + segment.t1) / 2,
                segment.force / 2,
                f"area = Δp\n= {format_number(change, 2, plus=True)} {IMPULSE_UNIT}",
                ha="center",
                va="center",
                bbox={"facecolor": PAPER, "edgecolor": "none", "pad": 2},
                zorder=5,
            )
        )
    low, high = min(forces), max(forces)
    ax.set_xlim(history.times[0], history.times[-1])
    ax.set_ylim(min(low, 0) * 1.15, max(high, 0) * 1.15)
    ax.set_xlabel(unit_label("time t", "s"))
    ax.set_ylabel(unit_label("resultant force F", "N"))
    return ForceTimeGraph(ax, line, areas, labels)


def momentum_time_caption(history: MomentumHistory, *, mass: float) -> str:
    forces = ", ".join(_force_text(f) for f in history.segment_forces)
    return (
        f"Momentum–time graph of {a_or_an(format_number(mass, 2))} {format_number(mass, 2)} kg car. The gradient of each straight "  # noqa: RUF001 (typography)
        f"segment is the resultant force on the car: {forces}."
    )


def momentum_time_alt(history: MomentumHistory, *, mass: float) -> str:
    return plain(_momentum_time_words(history, mass=mass))


def _momentum_time_words(history: MomentumHistory, *, mass: float) -> str:
    parts = []
    for s in history.segments:
        if s.force == 0:
            how = f"stays at {format_number(s.p0, 2)} {MOMENTUM_UNIT}"
        else:
            how = (
                f"{'rises' if s.force > 0 else 'falls'} in a straight line from "
                f"{format_number(s.p0, 2)} to {format_number(s.p1, 2)} {MOMENTUM_UNIT}"
            )
        parts.append(
            f"from {seconds(s.t0)} to {seconds(s.t1)} it {how} (gradient {_force_text(s.force)})"
        )
    speed = max(history.velocity_at(history.times, mass))
    return (
        f"Momentum-time graph of {a_or_an(format_number(mass, 2))} {format_number(mass, 2)} kg car: "
        + "; ".join(parts)
        + ". "
        f"The top speed is {format_number(speed, 2)} {VELOCITY_UNIT}."
    )


def momentum_time_data(history: MomentumHistory, *, mass: float) -> FigureData:
    """The drawn corners, each with the gradient (resultant force) of the segment after it."""
    gradients = [*history.segment_forces, None]  # the last corner starts no segment
    return figure_data(
        f"Momentum of the {format_number(mass, 2)} kg car at each corner of the graph",
        [Column("time t / s", list(history.times), decimals=1),
         Column(f"momentum p / {MOMENTUM_UNIT}", list(history.momenta), 3),
         Column("gradient until the next corner (resultant force) / N", gradients, 2)],
    )


def momentum_time_description(history: MomentumHistory, *, mass: float) -> str:
    return description(
        axes_sentence(axis_words("time t", history.times[0], history.times[-1], "s"),
                      axis_words("momentum p", min(0, min(history.momenta)), 1.3 * max(history.momenta),
                                 MOMENTUM_UNIT)),
        _momentum_time_words(history, mass=mass),
        "The Data table lists each corner of the graph and the gradient of the segment after it.",
    )


def force_time_caption(history: MomentumHistory) -> str:
    return (
        "Resultant force against time for the same car. Each shaded area, force × time, "  # noqa: RUF001 (typography)
        "is the change in momentum in that interval: the two areas are equal and opposite, "
        "so the car ends with the momentum it started with."
    )


def force_time_alt(history: MomentumHistory) -> str:
    return plain(_force_time_words(history))


def _force_time_words(history: MomentumHistory) -> str:
    parts = [
        f"{_force_text(s.force)} from {seconds(s.t0)} to {seconds(s.t1)}"
        + (
            f", shaded area {format_number(impulse(s.force, s.t1 - s.t0), 2)} {IMPULSE_UNIT}"
            if s.force
            else ""
        )
        for s in history.segments
    ]
    return (
        "Force-time graph of the car, made of horizontal steps: "
        + "; ".join(parts)
        + ". Each shaded area is the change in momentum over that time."
    )


def force_time_data(history: MomentumHistory) -> FigureData:
    """Each drawn step: its times, its force and its area (the change in momentum)."""
    segments = history.segments
    return figure_data(
        "Resultant force on the car in each interval, and the area under it",
        [Column("from t / s", [s.t0 for s in segments], decimals=1),
         Column("to t / s", [s.t1 for s in segments], decimals=1),
         Column("resultant force F / N", [s.force for s in segments], 2),
         Column(f"area = change in momentum Δp / {IMPULSE_UNIT}",
                [impulse(s.force, s.t1 - s.t0) for s in segments], 2)],
    )


def force_time_description(history: MomentumHistory) -> str:
    forces = history.segment_forces
    return description(
        axes_sentence(axis_words("time t", history.times[0], history.times[-1], "s"),
                      axis_words("resultant force F", 1.15 * min(min(forces), 0), 1.15 * max(max(forces), 0), "N")),
        _force_time_words(history),
        "The Data table lists each step with its area.",
    )


# --- The book's figures from this module (see book_figure.py); a page calls one of these. ---


def car_momentum_time(history: MomentumHistory, *, mass: float) -> BookFigure:
    graph = plot_momentum_time(history)
    return BookFigure(
        "fig-car-momentum-time",
        graph.axes.figure,
        momentum_time_caption(history, mass=mass),
        momentum_time_alt(history, mass=mass),
        momentum_time_description(history, mass=mass),
        momentum_time_data(history, mass=mass),
    )


def force_time_area(history: MomentumHistory) -> BookFigure:
    graph = plot_force_time_area(history)
    return BookFigure(
        "fig-force-time-area",
        graph.axes.figure,
        force_time_caption(history),
        force_time_alt(history),
        force_time_description(history),
        force_time_data(history),
    )
