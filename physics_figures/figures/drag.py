"""Drag against speed and a ball thrown upwards with and without drag (Notes, "Friction,
drag and terminal velocity"), drawn from :mod:`physics_figures.models.drag` objects.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from matplotlib.lines import Line2D

from ..models import drag_force
from ..models.drag import Skydive, ThrowUp
from ..notation import format_number
from ._data import (
    Column,
    axes_sentence,
    axis_words,
    curve_rows,
    description,
    figure_data,
    read_along,
    round_steps,
)
from ._text import VELOCITY_UNIT, plain
from .book_figure import BookFigure, FigureData
from .style import (
    FIGSIZE,
    GUIDE,
    INK,
    MAIN,
    PAPER,
    SECOND,
    book_style,
    new_axes,
    styled,
    unit_label,
)


class DragGraph(NamedTuple):
    """Artists of the drag-against-speed graph."""

    axes: Axes
    drag_curve: Line2D
    weight_line: Line2D
    crossing: Line2D  # marker where drag = weight: the terminal velocity


@styled
def plot_drag_against_speed(
    skydive: Skydive, *, ax: Axes | None = None, samples: int = 200
) -> DragGraph:
    """Drag D = k v² against speed for the freefalling skydiver, with the weight line.

    The curve and the line cross at the terminal velocity. ``samples`` is only how
    finely the curve is drawn (speeds from 0 to 1.3 times the terminal velocity).
    """
    ax = new_axes(ax)
    v_t = skydive.terminal_velocity_freefall
    speeds, drags = _drag_curve(skydive, samples)
    (curve,) = ax.plot(speeds, drags, color=MAIN, label="drag")
    weight_line = ax.axhline(skydive.weight, color=SECOND, linestyle="--", label="weight")
    (crossing,) = ax.plot(
        [v_t],
        [skydive.weight],
        marker="o",
        color=INK,
        markerfacecolor=PAPER,
        markeredgewidth=1.6,
        linestyle="none",
        zorder=4,
    )
    ax.annotate(
        f"terminal velocity\n{format_number(v_t, 2)} {VELOCITY_UNIT}: drag = weight",
        xy=(v_t, skydive.weight),
        xytext=(-12, 14),
        textcoords="offset points",
        ha="right",
        va="bottom",
    )
    ax.annotate(
        f"weight {format_number(skydive.weight, 3)} N",
        xy=(0, skydive.weight),
        xytext=(6, -6),
        textcoords="offset points",
        va="top",
        color=SECOND,
    )
    ax.annotate(
        "drag",
        xy=(speeds[-1], curve.get_ydata()[-1]),
        xytext=(-6, 0),
        textcoords="offset points",
        ha="right",
        va="center",
        color=MAIN,
    )
    ax.set_xlim(0, speeds[-1])
    ax.set_ylim(0, 1.8 * skydive.weight)
    ax.set_xlabel(unit_label("speed v", VELOCITY_UNIT))
    ax.set_ylabel(unit_label("force", "N"))
    return DragGraph(ax, curve, weight_line, crossing)


def _drag_curve(skydive: Skydive, samples: int = 200) -> tuple[np.ndarray, np.ndarray]:
    """The drag curve the figure draws and its table reads: speeds from 0 to 1.3 v_t."""
    speeds = np.linspace(0, 1.3 * skydive.terminal_velocity_freefall, samples)
    return speeds, drag_force(skydive.drag_constant_freefall, speeds)


def drag_against_speed_data(skydive: Skydive) -> FigureData:
    """The drawn drag curve read at round speeds, and where it crosses the weight."""
    speeds, drags = _drag_curve(skydive)
    crossing = {"terminal velocity": (skydive.terminal_velocity_freefall, skydive.weight)}
    labels, at, forces = curve_rows(speeds, drags, crossing)
    return figure_data(
        f"Drag on the {format_number(skydive.mass, 2)} kg skydiver against speed "
        f"(weight {format_number(skydive.weight, 3)} N)",
        [Column("point", labels), Column(f"speed v / {VELOCITY_UNIT}", at, 3),
         Column("drag / N", forces, 3)],
    )


def drag_against_speed_description(skydive: Skydive) -> str:
    return description(
        axes_sentence(axis_words("speed v", 0, 1.3 * skydive.terminal_velocity_freefall, VELOCITY_UNIT),
                      axis_words("force", 0, 1.8 * skydive.weight, "N")),
        _drag_against_speed_words(skydive),
        "The Data table reads the drag curve at round speeds.",
    )


def drag_against_speed_caption(skydive: Skydive) -> str:
    return (
        f"Drag on the {format_number(skydive.mass, 2)} kg skydiver against speed. The drag grows from zero "
        f"as the speed grows; where it reaches the weight, {format_number(skydive.weight, 3)} N, the "
        f"resultant force is zero: that speed, {format_number(skydive.terminal_velocity_freefall, 2)} "
        f"{VELOCITY_UNIT}, is the terminal velocity."
    )


def drag_against_speed_alt(skydive: Skydive) -> str:
    return plain(_drag_against_speed_words(skydive))


def _drag_against_speed_words(skydive: Skydive) -> str:
    return (
        f"Graph of force against speed. The drag curve starts at the origin and rises ever "
        f"more steeply. A dashed horizontal line marks the weight of the {format_number(skydive.mass, 2)} "
        f"kg skydiver, {format_number(skydive.weight, 3)} N. The curve crosses the line at "
        f"{format_number(skydive.terminal_velocity_freefall, 2)} {VELOCITY_UNIT}, the terminal velocity, "
        f"where drag equals weight."
    )


class ThrowGraph(NamedTuple):
    """Artists of the thrown-upwards figure (velocity and height against time)."""

    figure: Figure
    velocity_axes: Axes
    height_axes: Axes
    with_drag: tuple[Line2D, Line2D]  # (velocity, height)
    without_drag: tuple[Line2D, Line2D]


@styled
def plot_thrown_upwards(
    with_drag: ThrowUp, without_drag: ThrowUp, *, axes: tuple[Axes, Axes] | None = None
) -> ThrowGraph:
    """Velocity (up positive) and height against time, with drag (solid) and in a vacuum
    (dashed), for the same throw. ``axes``: two Axes to draw into, or None for a new Figure.
    """
    if axes is None:
        with book_style():
            figure = Figure(figsize=(FIGSIZE[0], 5.4), layout="constrained")
            axes = tuple(figure.subplots(2, 1, sharex=True))
    ax_v, ax_h = axes
    lines = {}
    for throw, name, colour, style in (
        (without_drag, "in a vacuum", SECOND, "--"),
        (with_drag, "with air resistance", MAIN, "-"),
    ):
        (v,) = ax_v.plot(throw.time, throw.velocity, color=colour, linestyle=style, label=name)
        (h,) = ax_h.plot(throw.time, throw.height, color=colour, linestyle=style, label=name)
        ax_h.plot(
            [throw.time_to_top],
            [throw.max_height],
            marker="o",
            color=colour,
            markerfacecolor=PAPER,
            markeredgewidth=1.6,
            linestyle="none",
        )
        lines[name] = (v, h)
    ax_v.axhline(0, color=GUIDE, linewidth=1.0)
    ax_v.set_ylabel(unit_label("velocity (up)", VELOCITY_UNIT))
    ax_v.legend(loc="upper right")
    ax_h.set_ylabel(unit_label("height", "m"))
    ax_h.set_xlabel(unit_label("time t", "s"))
    ax_h.set_ylim(0, without_drag.max_height * 1.2)
    ax_v.set_xlim(0, max(without_drag.time_of_flight, with_drag.time_of_flight))
    u = without_drag.launch_speed
    ax_v.set_ylim(-u * 1.1, u * 1.1)
    return ThrowGraph(ax_v.figure, ax_v, ax_h, lines["with air resistance"], lines["in a vacuum"])


def thrown_upwards_caption(with_drag: ThrowUp, without_drag: ThrowUp) -> str:
    return (
        f"A ball thrown straight up at {format_number(with_drag.launch_speed, 2)} {VELOCITY_UNIT}, with air "
        f"resistance (solid) and in a vacuum (dashed), up positive. With drag it slows faster "
        f"on the way up, reaches {format_number(with_drag.max_height, 3)} m instead of "
        f"{format_number(without_drag.max_height, 3)} m, sooner, and comes back at "
        f"{format_number(with_drag.return_speed, 3)} {VELOCITY_UNIT} instead of "
        f"{format_number(without_drag.return_speed, 2)} {VELOCITY_UNIT}. It takes longer to come down "
        f"({format_number(with_drag.time_of_flight - with_drag.time_to_top, 3)} s) than to go up "
        f"({format_number(with_drag.time_to_top, 3)} s)."
    )


def thrown_upwards_alt(with_drag: ThrowUp, without_drag: ThrowUp) -> str:
    return plain(_thrown_upwards_words(with_drag, without_drag))


def _thrown_upwards_words(with_drag: ThrowUp, without_drag: ThrowUp) -> str:
    return (
        f"Two graphs against time for a ball thrown up at {format_number(with_drag.launch_speed, 2)} "
        f"{VELOCITY_UNIT}, each with two curves. Velocity, up positive: in a vacuum (dashed) "
        f"a straight line from {format_number(without_drag.launch_speed, 2)} down to "
        f"-{format_number(without_drag.return_speed, 2)} {VELOCITY_UNIT} at "
        f"{format_number(without_drag.time_of_flight, 2)} s; with air resistance (solid) a curve that "
        f"falls more steeply at first, crosses zero earlier, at "
        f"{format_number(with_drag.time_to_top, 2)} s instead of {format_number(without_drag.time_to_top, 2)} s, "
        f"and ends at only -{format_number(with_drag.return_speed, 3)} {VELOCITY_UNIT} at "
        f"{format_number(with_drag.time_of_flight, 2)} s. Height: both are hump-shaped; with air "
        f"resistance the top is {format_number(with_drag.max_height, 3)} m instead of "
        f"{format_number(without_drag.max_height, 3)} m."
    )


def thrown_upwards_data(with_drag: ThrowUp, without_drag: ThrowUp) -> FigureData:
    """Both drawn throws read at the same round times (a dash once a ball has landed),
    with the marked tops in their places."""
    throws = (with_drag, without_drag)
    times = round_steps(0.0, max(t.time_of_flight for t in throws), count=8)

    def reading(throw: ThrowUp, quantity: str, t: float) -> float | None:
        if t > throw.time_of_flight:
            return None
        return float(read_along(throw.time, getattr(throw, quantity), [t])[0])

    rows = [("", float(t), *(reading(throw, q, t) for q in ("velocity", "height") for throw in throws))
            for t in times]
    for label, throw in (("top, with air resistance", with_drag), ("top, in a vacuum", without_drag)):
        velocity = [0.0 if other is throw else None for other in throws]
        height = [throw.max_height if other is throw else None for other in throws]
        rows.append((label, throw.time_to_top, *velocity, *height))
    rows.sort(key=lambda row: row[1])
    columns = list(zip(*rows, strict=True))
    headings = [
        ("point", None),
        ("time t / s", 3),
        (f"velocity with air resistance / {VELOCITY_UNIT}", 3),
        (f"velocity in a vacuum / {VELOCITY_UNIT}", 3),
        ("height with air resistance / m", 3),
        ("height in a vacuum / m", 3),
    ]
    return figure_data(
        f"Velocity (up positive) and height of the ball thrown up at "
        f"{format_number(with_drag.launch_speed, 2)} {VELOCITY_UNIT}",
        [Column(h, values, sig) for (h, sig), values in zip(headings, columns, strict=True)],
    )


def thrown_upwards_description(with_drag: ThrowUp, without_drag: ThrowUp) -> str:
    end = max(with_drag.time_of_flight, without_drag.time_of_flight)
    u = without_drag.launch_speed
    return description(
        f"Two graphs share the horizontal axis, {axis_words('time t', 0, end, 's')}. The upper "
        f"graph's vertical axis is {axis_words('velocity, up positive', -1.1 * u, 1.1 * u, VELOCITY_UNIT)}; "
        f"the lower graph's is {axis_words('height', 0, 1.2 * without_drag.max_height, 'm')}.",
        _thrown_upwards_words(with_drag, without_drag),
        "The Data table reads both throws at the same times; a dash means that ball has landed.",
    )


# --- The book's figures from this module (see book_figure.py); a page calls one of these. ---


def drag_against_speed(skydive: Skydive) -> BookFigure:
    graph = plot_drag_against_speed(skydive)
    return BookFigure(
        "fig-drag-against-speed",
        graph.axes.figure,
        drag_against_speed_caption(skydive),
        drag_against_speed_alt(skydive),
        drag_against_speed_description(skydive),
        drag_against_speed_data(skydive),
    )


def thrown_upwards(with_drag: ThrowUp, without_drag: ThrowUp) -> BookFigure:
    graph = plot_thrown_upwards(with_drag, without_drag)
    return BookFigure(
        "fig-thrown-upwards",
        graph.figure,
        thrown_upwards_caption(with_drag, without_drag),
        thrown_upwards_alt(with_drag, without_drag),
        thrown_upwards_description(with_drag, without_drag),
        thrown_upwards_data(with_drag, without_drag),
    )
