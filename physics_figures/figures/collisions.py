"""A straight-line collision before and after, with the totals of momentum and kinetic
energy (Notes, "Conservation of momentum" and "Elastic and inelastic collisions").

Totals come from :func:`physics_figures.models.total_momentum` and
:func:`~physics_figures.models.total_kinetic_energy`; velocities are signed, right positive.
"""

from __future__ import annotations

from typing import NamedTuple

from matplotlib.axes import Axes
from matplotlib.patches import Rectangle
from matplotlib.text import Annotation, Text

from ..models import stick_together, total_kinetic_energy, total_momentum
from ..notation import format_number
from ._data import Column, description, figure_data
from ._text import MOMENTUM_UNIT, VELOCITY_UNIT, a_or_an, plain
from .book_figure import BookFigure, FigureData
from .style import INK, MAIN, PAPER, SECOND, SMALL_TEXT, new_axes, styled


class CollisionDiagram(NamedTuple):
    """Artists of the before/after diagram."""

    axes: Axes
    bodies: dict[str, list[Rectangle]]  # "before", "after"
    velocity_arrows: dict[str, list[Annotation]]
    totals: dict[str, Text]  # "before", "after": the momentum and kinetic energy line


def _row(ax, y, masses, velocities, *, joined):
    """Draw one row of blocks at height y; return (blocks, arrows)."""
    colours = (MAIN, SECOND)
    widths = [0.6 + 0.25 * m for m in masses]  # wider block for more mass
    blocks, arrows = [], []
    x = 0.5 if joined else 0.3
    for i, (m, w) in enumerate(zip(masses, widths, strict=True)):
        block = Rectangle(
            (x, y),
            w,
            0.7,
            facecolor=PAPER,
            edgecolor=colours[i],
            linewidth=2,
            hatch="" if i == 0 else "//",
        )
        ax.add_patch(block)
        ax.text(
            x + w / 2,
            y + 0.35,
            f"{format_number(m, 2)} kg",
            ha="center",
            va="center",
            fontsize=SMALL_TEXT,
            bbox={"facecolor": PAPER, "edgecolor": "none", "pad": 1},
        )
        blocks.append(block)
        x += w + (0 if joined else 1.8)
    # one arrow per body (one for the joined pair), from its right face, length ∝ speed
    movers = (
        [(blocks[-1], velocities[-1])] if joined else list(zip(blocks, velocities, strict=True))
    )
    for block, v in movers:
        right = block.get_x() + block.get_width()
        if v == 0:
            arrows.append(
                ax.annotate("at rest", xy=(right + 0.1, y + 0.35), va="center", fontsize=SMALL_TEXT)
            )
            continue
        start = (right + 0.1, y + 0.35) if v > 0 else (block.get_x() - 0.1, y + 0.35)
        tip = (start[0] + 0.35 * v, start[1])
        arrows.append(
            ax.annotate(
                "",
                xy=tip,
                xytext=start,
                arrowprops={
                    "arrowstyle": "-|>",
                    "color": INK,
                    "linewidth": 2,
                    "shrinkA": 0,
                    "shrinkB": 0,
                },
            )
        )
        ax.text(
            (start[0] + tip[0]) / 2,
            y + 0.5,
            f"{format_number(abs(v), 2)} {VELOCITY_UNIT}",
            ha="center",
            va="bottom",
            fontsize=SMALL_TEXT,
        )
    return blocks, arrows


@styled
def plot_collision(
    masses: tuple[float, float],
    velocities_before: tuple[float, float],
    velocities_after: tuple[float, float],
    *,
    ax: Axes | None = None,
) -> CollisionDiagram:
    """Two bodies before and after a straight-line collision, with the totals."""
    ax = new_axes(ax, figsize=(5.6, 3.0))
    joined = velocities_after[0] == velocities_after[1]
    bodies, arrows, totals = {}, {}, {}
    for name, y, velocities, together in (
        ("before", 1.6, velocities_before, False),
        ("after", 0.0, velocities_after, joined),
    ):
        bodies[name], arrows[name] = _row(ax, y, masses, velocities, joined=together)
        ax.text(-0.1, y + 0.35, name, ha="right", va="center", fontweight="bold")
        p = total_momentum(masses, velocities)
        ek = total_kinetic_energy(masses, velocities)
        totals[name] = ax.text(
            8.0,
            y + 0.35,
            f"total p = {format_number(p, 2)} {MOMENTUM_UNIT}\ntotal Eₖ = {format_number(ek, 2)} J",
            ha="right",
            va="center",
            fontsize=SMALL_TEXT,
        )
    ax.set_xlim(-1.2, 8.0)
    ax.set_ylim(-0.2, 2.5)
    ax.set_aspect("equal")
    ax.set_axis_off()
    return CollisionDiagram(ax, bodies, arrows, totals)


def _totals(masses, before, after):
    return (
        total_momentum(masses, before),
        total_kinetic_energy(masses, before),
        total_momentum(masses, after),
        total_kinetic_energy(masses, after),
    )


def collision_caption(masses, velocities_before, velocities_after) -> str:
    p0, e0, p1, e1 = _totals(masses, velocities_before, velocities_after)
    return (
        f"{a_or_an(format_number(masses[0], 2)).capitalize()} {format_number(masses[0], 2)} kg trolley at {format_number(velocities_before[0], 2)} {VELOCITY_UNIT} hits a "
        f"{format_number(masses[1], 2)} kg trolley at rest and they stick together. The total momentum "
        f"is {format_number(p0, 2)} {MOMENTUM_UNIT} before and "
        f"{format_number(p1, 2)} {MOMENTUM_UNIT} after; the kinetic energy falls from "
        f"{format_number(e0, 2)} J to {format_number(e1, 2)} J, so the collision is inelastic."
    )


def collision_alt(masses, velocities_before, velocities_after) -> str:
    return plain(_collision_words(masses, velocities_before, velocities_after))


def _collision_words(masses, velocities_before, velocities_after) -> str:
    p0, e0, p1, e1 = _totals(masses, velocities_before, velocities_after)
    return (
        f"Before: {a_or_an(format_number(masses[0], 2))} {format_number(masses[0], 2)} kg block moving right at {format_number(velocities_before[0], 2)} "
        f"{VELOCITY_UNIT} towards {a_or_an(format_number(masses[1], 2))} {format_number(masses[1], 2)} kg block at rest; total momentum "
        f"{format_number(p0, 2)} {MOMENTUM_UNIT}, total kinetic energy {format_number(e0, 2)} J. After: the blocks "
        f"joined, moving right at {format_number(velocities_after[0], 2)} {VELOCITY_UNIT}; total momentum "
        f"{format_number(p1, 2)} {MOMENTUM_UNIT}, total kinetic energy {format_number(e1, 2)} J."
    )


def collision_data(masses, velocities_before, velocities_after) -> FigureData:
    """Each drawn body's mass and velocities, and the totals the figure prints."""
    p0, e0, p1, e1 = _totals(masses, velocities_before, velocities_after)
    bodies = [f"{format_number(m, 2)} kg block" for m in masses]
    return figure_data(
        "Velocities (right positive) before and after the collision, and the totals",
        [Column("body or total", [*bodies, "total momentum / kg m s⁻¹", "total kinetic energy / J"]),
         Column(f"before (velocity / {VELOCITY_UNIT}, or total)", [*velocities_before, p0, e0], 2),
         Column(f"after (velocity / {VELOCITY_UNIT}, or total)", [*velocities_after, p1, e1], 2)],
    )


def collision_description(masses, velocities_before, velocities_after) -> str:
    return description(
        "A diagram in two rows, without axes: before the collision above, after it below, "
        "each block labelled with its mass, each moving block with an arrow to the right, its "
        "length in proportion to its speed, and the totals at the right of each row.",
        _collision_words(masses, velocities_before, velocities_after),
        "The Data table lists each block's velocity before and after, and the totals.",
    )


# --- The book's figures from this module (see book_figure.py); a page calls one of these. ---


def collision_before_after(*, m1: float, u1: float, m2: float, u2: float) -> BookFigure:
    """The notes' sticking trolleys (keywords as in ``scenarios.STICKING_TROLLEYS``)."""
    v = stick_together(m1, u1, m2, u2)
    masses, before, after = (m1, m2), (u1, u2), (v, v)
    graph = plot_collision(masses, before, after)
    return BookFigure(
        "fig-collision-before-after",
        graph.axes.figure,
        collision_caption(masses, before, after),
        collision_alt(masses, before, after),
        collision_description(masses, before, after),
        collision_data(masses, before, after),
    )
