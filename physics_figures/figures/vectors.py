"""The momentum vector triangle of a glancing collision (Notes, "Momentum in two dimensions"
and Example 4), drawn from a :class:`physics_figures.models.two_d.GlancingCollision`.

The momentum before runs along the original line. The two momenta after, joined tip to
tail, end where it ends: the momentum before is their resultant, because momentum is
conserved. (It is not a closed triangle, three vectors adding to zero: that is an
explosion from rest.) Dotted lines
show the components along and across the line that the working uses.
"""

from __future__ import annotations

from typing import NamedTuple

from matplotlib.axes import Axes
from matplotlib.lines import Line2D
from matplotlib.text import Annotation

from ..models.two_d import GlancingCollision
from ..notation import format_number
from ._data import Column, description, figure_data
from ._text import IMPULSE_UNIT, plain
from .book_figure import BookFigure, FigureData
from .style import GUIDE, MAIN, PALETTE, SECOND, SMALL_TEXT, new_axes, styled


class TriangleDiagram(NamedTuple):
    """Artists of a momentum triangle. Each arrow: ``.xyann`` tail, ``.xy`` tip (N s)."""

    axes: Axes
    before: Annotation
    moving_after: Annotation  # the body that was moving (P, X), starts at the origin
    struck_after: Annotation  # the struck body (Q, Y), tail on the tip of moving_after
    components: list[Line2D]  # dotted: along and across parts of each momentum after
    labels: list[Annotation]


def _arrow(ax, tail, tip, *, colour, style="-"):
    return ax.annotate(
        "",
        xy=tip,
        xytext=tail,
        arrowprops={
            "arrowstyle": "-|>,head_length=0.7,head_width=0.3",
            "color": colour,
            "linewidth": 2.4,
            "linestyle": style,
            "shrinkA": 0,
            "shrinkB": 0,
        },
        zorder=4,
    )


def _triangle_labels(ax, collision: GlancingCollision, names, figures):
    """The momentum triangle's labels: both momenta after, the one before, and the components."""
    moving, struck = names
    before_tip = collision.before_vector
    corner = collision.known_vector
    end = collision.triangle[2]
    along_m, across_m = corner
    m = collision.missing
    small = {"textcoords": "offset points", "fontsize": SMALL_TEXT}
    return [
        ax.annotate(
            f"{moving} before: {format_number(collision.p_before, 3)} {IMPULSE_UNIT}",
            xy=(before_tip[0] / 2, 0),
            xytext=(0, -6),
            ha="center",
            va="top",
            **small,
        ),
        ax.annotate(
            f"{moving} after:\n{format_number(collision.p_known, figures)} {IMPULSE_UNIT} at "
            f"{format_number(collision.angle_known_deg, 2)}°",
            xy=(along_m / 2, across_m / 2),
            xytext=(-8, 4),
            ha="right",
            va="bottom",
            **small,
        ),
        ax.annotate(
            f"{struck} after:\n{format_number(m.magnitude, max(figures, 3))} {IMPULSE_UNIT} at {format_number(m.angle_deg, 3)}°",
            xy=((corner[0] + end[0]) / 2, (corner[1] + end[1]) / 2),
            xytext=(10, 4),
            ha="left",
            va="bottom",
            **small,
        ),
        ax.annotate(
            f"across {format_number(across_m, 3)}",
            xy=(along_m, across_m / 2),
            xytext=(-5, 0),
            ha="right",
            va="center",
            color=GUIDE,
            rotation=90,
            **small,
        ),
        ax.annotate(
            f"along {format_number(m.along, 3)}",
            xy=((corner[0] + end[0]) / 2, corner[1]),
            xytext=(0, 4),
            ha="center",
            va="bottom",
            color=GUIDE,
            **small,
        ),
    ]


@styled
def plot_momentum_triangle(
    collision: GlancingCollision,
    *,
    ax: Axes | None = None,
    names: tuple[str, str] = ("P", "Q"),
    figures: int = 2,
) -> TriangleDiagram:
    """Tip-to-tail momentum triangle with the components of both momenta after.

    ``figures``: significant figures of the given momentum after (the notes give 2 for
    the pucks, 3 for Example 4); the computed one has at least 3, like its components.
    """
    ax = new_axes(ax, figsize=(5.6, 4.0))
    origin = (0.0, 0.0)
    before_tip = collision.before_vector
    corner = collision.known_vector
    end = collision.triangle[2]
    before = _arrow(ax, origin, before_tip, colour=GUIDE, style="--")
    moving_after = _arrow(ax, origin, corner, colour=MAIN)
    struck_after = _arrow(ax, corner, end, colour=SECOND)

    dotted = {"color": PALETTE["black"], "linestyle": ":", "linewidth": 1.3, "zorder": 2}
    components = [
        ax.plot([corner[0], corner[0]], [0, corner[1]], **dotted)[0],  # across, moving body
        ax.plot([corner[0], end[0]], [corner[1], corner[1]], **dotted)[0],  # along, struck
    ]
    labels = _triangle_labels(ax, collision, names, figures)
    across_m = corner[1]  # the momentum after's component across the line
    pad = 0.12 * collision.p_before
    ax.set_xlim(-pad, collision.p_before + 3 * pad)
    ax.set_ylim(-2 * pad, across_m + 2.5 * pad)
    ax.set_aspect("equal")
    ax.set_axis_off()
    return TriangleDiagram(ax, before, moving_after, struck_after, components, labels)


def momentum_triangle_caption(collision: GlancingCollision, *, names=("P", "Q")) -> str:
    moving, struck = names
    return (
        f"Momentum vector triangle for {moving} hitting {struck}, which was at rest. "
        f"The momenta after, {moving} then {struck}, joined tip to tail, end where the "
        f"momentum before ({format_number(collision.p_before, 3)} {IMPULSE_UNIT}, dashed) ends: the "
        f"momentum before is their resultant, because momentum is conserved along the line "
        f"and across it."
    )


def momentum_triangle_alt(
    collision: GlancingCollision, *, names=("P", "Q"), figures: int = 2
) -> str:
    return plain(momentum_triangle_words(collision, names=names, figures=figures))


def momentum_triangle_words(collision: GlancingCollision, *, names=("P", "Q"), figures: int = 2) -> str:
    moving, struck = names
    m = collision.missing
    along_m, across_m = collision.known_vector
    return (
        f"Vector triangle. A dashed arrow along the original line shows {moving}'s momentum "
        f"before, {format_number(collision.p_before, 3)} {IMPULSE_UNIT}. From its start, an arrow for "
        f"{moving} after, {format_number(collision.p_known, figures)} {IMPULSE_UNIT} at "
        f"{format_number(collision.angle_known_deg, 2)} degrees above the line (components "
        f"{format_number(along_m, 3)} along, {format_number(across_m, 3)} across). From its tip, an arrow for "
        f"{struck} after, {format_number(m.magnitude, max(figures, 3))} {IMPULSE_UNIT} at {format_number(m.angle_deg, 3)} "
        f"degrees below the line (components {format_number(m.along, 3)} along, {format_number(m.across, 3)} "
        f"across), ending at the tip of the dashed arrow: the momentum before is the "
        f"resultant of the two momenta after."
    )


def momentum_triangle_data(collision: GlancingCollision, *, names=("P", "Q"), figures: int = 2) -> FigureData:
    """The three drawn arrows: size, angle to the original line, and the components the
    dotted lines show (across is + on the moving body's side)."""
    moving, struck = names
    m = collision.missing
    arrows = (
        (f"{moving} before (dashed)", collision.p_before, 0.0, collision.before_vector),
        (f"{moving} after", collision.p_known, collision.angle_known_deg, collision.known_vector),
        (f"{struck} after", m.magnitude, -m.angle_deg, collision.missing_vector),
    )
    return figure_data(
        f"The momenta in the vector triangle for {moving} hitting {struck}",
        [Column("arrow", [a[0] for a in arrows]),
         Column(f"momentum / {IMPULSE_UNIT}", [a[1] for a in arrows], max(figures, 3)),
         Column("angle to the original line / ° (+ towards the first arrow after)", [a[2] for a in arrows], 3),
         Column(f"along the line / {IMPULSE_UNIT}", [a[3][0] for a in arrows], 3),
         Column(f"across the line / {IMPULSE_UNIT}", [a[3][1] for a in arrows], 3)],
    )


def momentum_triangle_description(collision: GlancingCollision, *, names=("P", "Q"), figures: int = 2) -> str:
    return description(
        "A vector diagram drawn to scale, without axes; the original line runs left to right.",
        momentum_triangle_words(collision, names=names, figures=figures),
        "The Data table lists each arrow with its components along and across the line.",
    )


# --- The book's figures from this module (see book_figure.py); a page calls one of these. ---


def _triangle(name: str, collision: GlancingCollision, names: tuple[str, str], figures: int) -> BookFigure:
    graph = plot_momentum_triangle(collision, names=names, figures=figures)
    return BookFigure(
        name,
        graph.axes.figure,
        momentum_triangle_caption(collision, names=names),
        momentum_triangle_alt(collision, names=names, figures=figures),
        momentum_triangle_description(collision, names=names, figures=figures),
        momentum_triangle_data(collision, names=names, figures=figures),
    )


def pucks_triangle(collision: GlancingCollision) -> BookFigure:
    return _triangle("fig-pucks-triangle", collision, ("P", "Q"), 2)


def example4_triangle(collision: GlancingCollision) -> BookFigure:
    return _triangle("fig-example4-triangle", collision, ("X", "Y"), 3)
