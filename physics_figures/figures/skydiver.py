"""The skydiver's velocity-time and resultant force-time graphs (Notes, "Friction, drag and
terminal velocity"), drawn from a :class:`physics_figures.models.drag.Skydive`.

Down is positive, as in the notes. Points A to E sit where the model puts them
(``Skydive.points``); the two terminal velocities are dashed lines. The parachute opens
over a few seconds, so D, the largest deceleration, comes a little after the opening,
which is marked with a dotted vertical line.
"""

from __future__ import annotations

from typing import NamedTuple

from matplotlib.axes import Axes
from matplotlib.lines import Line2D
from matplotlib.text import Text

from ..models.drag import Skydive
from ..notation import format_number
from ._data import Column, axes_sentence, axis_words, curve_rows, description, figure_data
from ._text import ACCELERATION_UNIT, VELOCITY_UNIT, a_or_an, plain
from .book_figure import BookFigure, FigureData
from .style import GUIDE, INK, MAIN, PAPER, SMALL_TEXT, new_axes, styled, unit_label

POINT_LABELS = ("A", "B", "C", "D", "E")
# Where each letter sits relative to its marker (points), so letters never sit on the curve.
_LABEL_OFFSETS = {"A": (8, 4), "B": (8, -14), "C": (-4, 8), "D": (7, 2), "E": (6, -16)}


class SkydiveGraph(NamedTuple):
    """Artists of a skydiver graph."""

    axes: Axes
    curve: Line2D
    markers: Line2D  # the model's points of A to E, in that order
    point_labels: dict[str, Text]
    guides: tuple[Line2D, ...]  # reference lines: terminal velocities, or zero and weight
    opening: tuple[Line2D, Text]  # dotted line and label at the time the parachute opens


def _mark_points(ax: Axes, xy: dict[str, tuple[float, float]]) -> tuple[Line2D, dict[str, Text]]:
    labels = [p for p in POINT_LABELS if p in xy]  # B and C only if reached before opening
    (markers,) = ax.plot(
        [xy[p][0] for p in labels],
        [xy[p][1] for p in labels],
        linestyle="none",
        marker="o",
        markerfacecolor=PAPER,
        markeredgecolor=INK,
        markeredgewidth=1.6,
        zorder=4,
    )
    texts = {
        p: ax.annotate(
            p,
            xy=xy[p],
            xytext=_LABEL_OFFSETS[p],
            textcoords="offset points",
            fontweight="bold",
            zorder=5,
        )
        for p in labels
    }
    return markers, texts


@styled
def plot_velocity_time(skydive: Skydive, *, ax: Axes | None = None) -> SkydiveGraph:
    """Velocity against time, with A-E at the model's points and both terminal velocities."""
    ax = new_axes(ax)
    (curve,) = ax.plot(skydive.time, skydive.velocity, color=MAIN, zorder=3)
    guides = []
    # labels sit above each dashed line where the curve is far away: the first at the
    # right end (the curve is down at the second terminal velocity there), the second
    # from 15 % of the way in (the curve is high above it there, up to the opening)
    for v_t, name, x, ha in (
        (skydive.terminal_velocity_freefall, "terminal velocity", skydive.duration, "right"),
        (skydive.terminal_velocity_parachute, "with parachute", 0.15 * skydive.duration, "left"),
    ):
        guides.append(ax.axhline(v_t, color=GUIDE, linestyle="--", linewidth=1.3, zorder=2))
        ax.annotate(
            f"{name} {format_number(v_t, 2)} {VELOCITY_UNIT}",
            xy=(x, v_t),
            xytext=(0, 4),
            textcoords="offset points",
            ha=ha,
            va="bottom",
            color=GUIDE,
            fontsize=SMALL_TEXT,
        )
    markers, labels = _mark_points(ax, dict(skydive.points))
    ax.set_xlim(0, skydive.duration)
    ax.set_ylim(0, skydive.terminal_velocity_freefall * 1.18)
    opening = _mark_opening(ax, skydive, skydive.velocity_at(skydive.parachute_opens_at))
    ax.set_xlabel(unit_label("time t", "s"))
    ax.set_ylabel(unit_label("velocity v (down)", VELOCITY_UNIT))
    return SkydiveGraph(ax, curve, markers, labels, tuple(guides), opening)


def _mark_opening(ax: Axes, skydive: Skydive, curve_at_opening: float) -> tuple[Line2D, Text]:
    """A dotted line from the time axis up to the curve at the opening, labelled along it,
    so that D is seen to come after it. Call after the y-limits are set."""
    t_open = skydive.parachute_opens_at
    (line,) = ax.plot([t_open, t_open], [ax.get_ylim()[0], curve_at_opening], color=GUIDE,
                      linestyle=":", linewidth=1.1, zorder=1)
    label = ax.annotate(
        "parachute opens",
        xy=(skydive.parachute_opens_at, 0.03),
        xycoords=("data", "axes fraction"),
        xytext=(-3, 0),
        textcoords="offset points",
        rotation=90,
        ha="right",
        va="bottom",
        fontsize=SMALL_TEXT,
        color=GUIDE,
    )
    return line, label


@styled
def plot_resultant_force(
    skydive: Skydive, *, ax: Axes | None = None, clip_at_weights: float = 5.0
) -> SkydiveGraph:
    """Resultant force (down positive) against time, with A-E at the model's points.

    The force just after the parachute opens is several weights upwards (about four for
    the notes' skydiver, at D). The axis stops at ``clip_at_weights`` weights; a harder
    opening that goes further has its off-scale value written next to D.
    """
    ax = new_axes(ax)
    (curve,) = ax.plot(skydive.time, skydive.resultant_force, color=MAIN, zorder=3)
    zero = ax.axhline(0, color=GUIDE, linestyle="--", linewidth=1.3, zorder=2)
    w = skydive.weight
    bottom = -clip_at_weights * w
    points = {p: (t, _resultant_at(skydive, p)) for p, (t, _) in skydive.points.items()}
    shown = {p: (t, max(f, bottom)) for p, (t, f) in points.items()}
    markers, labels = _mark_points(ax, shown)
    f_d = points["D"][1]
    if f_d < bottom:
        ax.annotate(
            f"{format_number(f_d, 3)} N at D\n(off the scale)",
            xy=shown["D"],
            xytext=(-12, 0),
            textcoords="offset points",
            fontsize=SMALL_TEXT,
            ha="right",
            va="bottom",
        )
    weight_line = ax.axhline(w, color=GUIDE, linestyle=":", linewidth=1.3, zorder=2)
    ax.annotate(
        f"weight {format_number(w, 3)} N",
        xy=(skydive.duration, w),
        xytext=(0, -4),
        textcoords="offset points",
        ha="right",
        va="top",
        fontsize=SMALL_TEXT,
        color=GUIDE,
    )
    ax.set_xlim(0, skydive.duration)
    ax.set_ylim(bottom * 1.08, w * 1.35)
    opening = _mark_opening(ax, skydive, w - skydive.drag_at(skydive.parachute_opens_at))
    ax.set_xlabel(unit_label("time t", "s"))
    ax.set_ylabel(unit_label("resultant force (down)", "N"))
    return SkydiveGraph(ax, curve, markers, labels, (zero, weight_line), opening)


def _resultant_at(skydive: Skydive, point: str) -> float:
    """Resultant force at a labelled point, N, as the model gives it."""
    return skydive.point_resultant_force[point]


def _time(skydive: Skydive, point: str) -> str:
    return format_number(skydive.points[point][0], 2)


def _opening(skydive: Skydive) -> str:
    """How the parachute opens and where D is, in words shared by captions and alt text."""
    t_open = skydive.parachute_opens_at
    decel = -skydive.point_acceleration["D"]
    return (
        f"The parachute opens at {format_number(t_open, 2)} s (dotted line) and takes "
        f"{format_number(skydive.opening_duration, 2)} s to fill. The deceleration is largest at D, "
        f"{format_number(skydive.points['D'][0] - t_open, 2)} s after the opening, where the curve is "
        f"steepest: {format_number(decel, 3)} {ACCELERATION_UNIT}, about {format_number(decel / skydive.g, 2)} g"
    )


def velocity_time_caption(skydive: Skydive) -> str:
    v1, v2 = skydive.terminal_velocity_freefall, skydive.terminal_velocity_parachute
    return (
        f"Velocity–time graph of {a_or_an(format_number(skydive.mass, 2))} {format_number(skydive.mass, 2)} kg skydiver, down positive. "  # noqa: RUF001 (typography)
        f"The velocity levels off at the terminal velocity {format_number(v1, 2)} {VELOCITY_UNIT} (C). "
        f"{_opening(skydive)}. The velocity falls steeply, then less and less steeply, to a new "
        f"terminal velocity of {format_number(v2, 2)} {VELOCITY_UNIT} (E). Dashed lines: the two terminal "
        "velocities."
    )


def velocity_time_alt(skydive: Skydive) -> str:
    return plain(_velocity_time_words(skydive))


def _velocity_time_words(skydive: Skydive) -> str:
    p = skydive.points
    text = (
        f"Velocity-time graph of {a_or_an(format_number(skydive.mass, 2))} {format_number(skydive.mass, 2)} kg skydiver, taking down as positive. "
        f"The velocity starts at 0 at A with a gradient of g = {format_number(skydive.g, 3)} "
        f"{ACCELERATION_UNIT}, rises ever less steeply through B ({format_number(p['B'][1], 2)} "
        f"{VELOCITY_UNIT} at {_time(skydive, 'B')} s) and levels at "
        f"{format_number(skydive.terminal_velocity_freefall, 2)} {VELOCITY_UNIT} (C, reached at about "
        f"{_time(skydive, 'C')} s). {_opening(skydive)} (D is at t = "
        f"{format_number(skydive.points['D'][0], 3)} s, {format_number(skydive.points['D'][1], 2)} {VELOCITY_UNIT}). The "
        f"velocity falls steeply, then less and less steeply, and levels at "
        f"{format_number(skydive.terminal_velocity_parachute, 2)} {VELOCITY_UNIT} (E, at about "
        f"{_time(skydive, 'E')} s). Dashed horizontal lines mark the two terminal velocities."
    )
    return text


def resultant_force_caption(skydive: Skydive) -> str:
    return (
        f"Resultant force on the {format_number(skydive.mass, 2)} kg skydiver against time, down positive. "
        f"It starts at the weight, {format_number(skydive.weight, 3)} N (A), and falls to zero at terminal "
        f"velocity (C). As the parachute fills it swings quickly to a large upward value, "
        f"largest at D ({format_number(_resultant_at(skydive, 'D'), 3)} N, about "
        f"{format_number(-skydive.point_acceleration['D'] / skydive.g, 2)} g), and returns to zero (E)."
    )


def resultant_force_alt(skydive: Skydive) -> str:
    return plain(_resultant_force_words(skydive))


def _resultant_force_words(skydive: Skydive) -> str:
    return (
        f"Graph of resultant force against time for {a_or_an(format_number(skydive.mass, 2))} {format_number(skydive.mass, 2)} kg skydiver, "
        f"down positive. At A the resultant force is the whole weight, "
        f"{format_number(skydive.weight, 3)} N. It decreases through B "
        f"({format_number(_resultant_at(skydive, 'B'), 3)} N) to zero at C, when the drag equals the "
        f"weight. The parachute opens at t = {format_number(skydive.parachute_opens_at, 2)} s and takes "
        f"{format_number(skydive.opening_duration, 2)} s to fill: the resultant force swings within a second "
        f"to its largest upward value at D, t = {format_number(skydive.points['D'][0], 3)} s, "
        f"{format_number(_resultant_at(skydive, 'D'), 3)} N (the minus sign: upwards), a "
        f"deceleration of about {format_number(-skydive.point_acceleration['D'] / skydive.g, 2)} g, then "
        f"shrinks back to zero at E as the skydiver slows to "
        f"{format_number(skydive.terminal_velocity_parachute, 2)} {VELOCITY_UNIT}."
    )


def velocity_time_data(skydive: Skydive) -> FigureData:
    """The drawn velocity curve read at round times, with A to E where they are drawn."""
    labels, times, velocities = curve_rows(skydive.time, skydive.velocity, dict(skydive.points))
    return figure_data(
        f"Velocity of the {format_number(skydive.mass, 2)} kg skydiver against time, down positive",
        [Column("point", labels), Column("time t / s", times, 3),
         Column(f"velocity v / {VELOCITY_UNIT}", velocities, 3)],
    )


def resultant_force_data(skydive: Skydive) -> FigureData:
    """The drawn resultant-force curve read at round times, with A to E at the model's values."""
    marked = {p: (t, _resultant_at(skydive, p)) for p, (t, _) in skydive.points.items()}
    labels, times, forces = curve_rows(skydive.time, skydive.resultant_force, marked)
    return figure_data(
        f"Resultant force on the {format_number(skydive.mass, 2)} kg skydiver against time, down positive",
        [Column("point", labels), Column("time t / s", times, 3),
         Column("resultant force / N", forces, decimals=0)],
    )


def velocity_time_description(skydive: Skydive) -> str:
    top = skydive.terminal_velocity_freefall * 1.18  # the plot's y-limit
    return description(
        axes_sentence(axis_words("time t", 0, skydive.duration, "s"),
                      axis_words("velocity v, down positive", 0, top, VELOCITY_UNIT)),
        _velocity_time_words(skydive),
        "The Data table reads the curve every few seconds, with A to E in their places.",
    )


def resultant_force_description(skydive: Skydive, *, clip_at_weights: float = 5.0) -> str:
    w = skydive.weight
    return description(
        axes_sentence(axis_words("time t", 0, skydive.duration, "s"),
                      axis_words("resultant force, down positive", -clip_at_weights * w * 1.08,
                                 w * 1.35, "N")),
        _resultant_force_words(skydive),
        "The Data table reads the curve every few seconds, with A to E in their places.",
    )


# --- The book's figures from this module (see book_figure.py); a page calls one of these. ---


def skydiver_velocity_time(skydive: Skydive) -> BookFigure:
    graph = plot_velocity_time(skydive)
    return BookFigure(
        "fig-skydiver-velocity-time",
        graph.axes.figure,
        velocity_time_caption(skydive),
        velocity_time_alt(skydive),
        velocity_time_description(skydive),
        velocity_time_data(skydive),
    )


def skydiver_resultant_force(skydive: Skydive) -> BookFigure:
    graph = plot_resultant_force(skydive)
    return BookFigure(
        "fig-skydiver-resultant-force",
        graph.axes.figure,
        resultant_force_caption(skydive),
        resultant_force_alt(skydive),
        resultant_force_description(skydive),
        resultant_force_data(skydive),
    )
