"""Free-body diagrams: the skydiver at A, C and D, and a book on a table with its
third-law pairs (Notes, "Friction, drag and terminal velocity" and "Newton's third law").

Arrows start on the body, point the way the force acts and are labelled, as the
mark schemes ask. The skydiver's arrow lengths are to scale with the model's forces;
an arrow too long for the panel is drawn broken (a gap) with its value written on it.
"""

from __future__ import annotations

from typing import NamedTuple

from matplotlib.axes import Axes
from matplotlib.figure import Figure
from matplotlib.patches import Circle, Rectangle
from matplotlib.text import Annotation

from ..models.drag import Skydive
from ..notation import format_number
from ..style import colour
from ._data import Column, description, figure_data
from ._text import ACCELERATION_UNIT, VELOCITY_UNIT, plain
from .book_figure import BookFigure, FigureData
from .style import FORCE_COLOURS, INK, PAPER, SMALL_TEXT, book_style, styled

#: Line style of each kind of force, so pairs match in greyscale too.
FORCE_STYLES = {"weight": "-", "drag": "-", "gravitational": "-", "contact": "--"}


class ForceArrow(NamedTuple):
    """An arrow: ``arrow.xyann`` is its tail, ``arrow.xy`` its tip (data units)."""

    arrow: Annotation
    label: Annotation


class FreeBodyDiagram(NamedTuple):
    """Artists of one free-body panel."""

    axes: Axes
    arrows: dict[str, ForceArrow]


def _draw_arrow(ax, tail, tip, *, kind, text, text_side="right", text_at=None) -> ForceArrow:
    arrow = ax.annotate(
        "",
        xy=tip,
        xytext=tail,
        arrowprops={
            "arrowstyle": "-|>,head_length=0.6,head_width=0.3",
            "color": FORCE_COLOURS[kind],
            "linewidth": 2.4,
            "linestyle": FORCE_STYLES[kind],
            "shrinkA": 0,
            "shrinkB": 0,
        },
    )
    middle = ((tail[0] + tip[0]) / 2, (tail[1] + tip[1]) / 2)
    label = ax.annotate(
        text,
        xy=middle if text_at is None else text_at,
        xytext=(8 if text_side == "right" else -8, 0),
        textcoords="offset points",
        ha="left" if text_side == "right" else "right",
        va="center",
        fontsize=SMALL_TEXT,
    )
    return ForceArrow(arrow, label)


def _blank(ax: Axes, *, width: float, height: float) -> None:
    ax.set_xlim(-width / 2, width / 2)
    ax.set_ylim(-height / 2, height / 2)
    ax.set_aspect("equal")
    ax.set_axis_off()


@styled
def plot_skydiver_free_body(
    skydive: Skydive, point: str, *, ax: Axes, max_length: float = 2.4
) -> FreeBodyDiagram:
    """Forces on the skydiver at one of the model's points, lengths in proportion.

    The weight arrow is one unit long; the drag is ``drag / weight`` units, drawn
    broken if longer than ``max_length``.
    """
    w, d = skydive.weight, _drag_at(skydive, point)
    body = 0.3
    ax.add_patch(Circle((0, 0), body, facecolor=PAPER, edgecolor=INK, linewidth=1.6))
    arrows = {
        "weight": _draw_arrow(
            ax, (0, -body), (0, -body - 1.0), kind="weight", text=f"W = {format_number(w, 3)} N"
        )
    }
    if d > 0:
        length = d / w
        shown = min(length, max_length)
        arrows["drag"] = _draw_arrow(
            ax,
            (0, body),
            (0, body + shown),
            kind="drag",
            text=f"D = {format_number(d, 3)} N" + ("\n(not to scale)" if length > max_length else ""),
        )
        if length > max_length:  # a white gap across the shaft marks the break
            y = body + shown * 0.45
            ax.plot([-0.12, 0.12], [y - 0.05, y + 0.05], color=PAPER, linewidth=6, zorder=5)
            ax.plot([-0.12, 0.12], [y - 0.12, y - 0.02], color=INK, linewidth=1, zorder=6)
            ax.plot([-0.12, 0.12], [y + 0.08, y + 0.18], color=INK, linewidth=1, zorder=6)
    _blank(ax, width=3.2, height=2 * (body + max_length) + 0.2)
    ax.set_title(point, fontweight="bold")
    return FreeBodyDiagram(ax, arrows)


def _drag_at(skydive: Skydive, point: str) -> float:
    """Drag at a point, N. At C and E the skydiver is at terminal velocity, so the drag is
    the model's drag at that terminal velocity (the model's point is where the velocity is
    within 1 % of it, where the drag is 2 % short of the weight)."""
    return skydive.terminal_drag.get(point, skydive.point_drag[point])


@styled
def plot_skydiver_free_bodies(
    skydive: Skydive, *, points: tuple[str, ...] = ("A", "C", "D")
) -> tuple[Figure, list[FreeBodyDiagram]]:
    """One free-body panel per point, side by side, on a common scale."""
    with book_style():
        figure = Figure(figsize=(5.6, 4.2), layout="constrained")
        axes = figure.subplots(1, len(points))
    panels = [
        plot_skydiver_free_body(skydive, p, ax=ax) for p, ax in zip(points, axes, strict=True)
    ]
    return figure, panels


def skydiver_free_bodies_caption(skydive: Skydive, points=("A", "C", "D")) -> str:
    return (
        f"Forces on the {format_number(skydive.mass, 2)} kg skydiver at "
        + ", ".join(points[:-1])
        + f" and {points[-1]}, arrow lengths in proportion to the forces (down positive). "
        "At A there is no drag; at C the drag equals the weight; "
        + _at_d(skydive)
        + "."
    )


def _at_d(skydive: Skydive) -> str:
    """D in words: the drag, the resultant force and the deceleration, in g too."""
    drag, decel = skydive.point_drag["D"], -skydive.point_acceleration["D"]
    return (
        f"at D, just after the parachute opens, where the deceleration is largest, the drag "
        f"({format_number(drag, 3)} N) is {format_number(drag / skydive.weight, 2)} times the weight, so the "
        f"resultant force is {format_number(drag - skydive.weight, 3)} N upwards: a deceleration of "
        f"{format_number(decel, 3)} {ACCELERATION_UNIT}, about {format_number(decel / skydive.g, 2)} g"
    )


def skydiver_free_bodies_alt(skydive: Skydive, points=("A", "C", "D")) -> str:
    return plain(_skydiver_free_bodies_words(skydive, points))


def _skydiver_free_bodies_words(skydive: Skydive, points=("A", "C", "D")) -> str:
    parts = []
    for p in points:
        d = _drag_at(skydive, p)
        v = skydive.points[p][1]
        drag = (
            "no drag arrow"
            if d == 0
            else f"drag {format_number(d, 3)} N upwards"
            + (" (drawn broken, too long to fit)" if d > 2.4 * skydive.weight else "")
        )
        parts.append(
            f"at {p} (speed {format_number(v, 2)} {VELOCITY_UNIT}): weight "
            f"{format_number(skydive.weight, 3)} N downwards and {drag}"
        )
    return (
        f"Three free-body diagrams of the {format_number(skydive.mass, 2)} kg skydiver, a circle with "
        "vertical arrows: " + "; ".join(parts) + ". "
        + (_at_d(skydive)[0].upper() + _at_d(skydive)[1:] + "." if "D" in points else "")
    )


class ThirdLawDiagram(NamedTuple):
    """Artists of the book-on-a-table diagram."""

    figure: Figure
    on_book: dict[str, ForceArrow]  # "weight" (Earth on book), "contact" (table on book)
    partners: dict[str, ForceArrow]  # "gravitational" (book on Earth), "contact" (book on table)


@styled
def plot_book_on_table() -> ThirdLawDiagram:
    """Forces on a book resting on a table (left) and their third-law partners (right).

    The notes give no mass, so the forces are drawn equal (the book is in equilibrium)
    and labelled with letters: W and its pair on the Earth; R and its pair on the table.
    """
    with book_style():
        figure = Figure(figsize=(5.6, 3.6), layout="constrained")
        left, right = figure.subplots(1, 2)
    for ax in (left, right):
        _blank(ax, width=3.4, height=3.4)
        ax.add_patch(Rectangle((-0.8, -0.15), 1.6, 0.15, facecolor=colour("figure.table"), edgecolor=INK))
        ax.add_patch(
            Rectangle(
                (-0.45, 0.0), 0.9, 0.35, facecolor=PAPER, edgecolor=INK, linewidth=1.6
            )
        )
        ax.add_patch(Circle((0, -4.2), 2.8, facecolor=colour("figure.earth"), edgecolor=INK))
        ax.text(0, -1.45, "Earth", ha="center", va="top", fontsize=SMALL_TEXT)
        ax.text(0.8, -0.2, "table", ha="right", va="top", fontsize=SMALL_TEXT)
        ax.text(0, 0.17, "book", ha="center", va="center", fontsize=SMALL_TEXT)
    left.set_title("forces on the book", fontsize="medium")
    right.set_title("their third-law pairs", fontsize="medium")
    on_book = {
        "weight": _draw_arrow(
            left,
            (-0.3, 0.17),
            (-0.3, -0.95),
            kind="weight",
            text="W: Earth\npulls book",
            text_side="left",
            text_at=(-0.85, -0.6),
        ),
        "contact": _draw_arrow(
            left,
            (0.3, 0.35),
            (0.3, 1.47),
            kind="contact",
            text="R: table\npushes book",
            text_at=(0.3, 1.0),
        ),
    }
    partners = {
        "gravitational": _draw_arrow(
            right,
            (-0.3, -1.4),
            (-0.3, -0.28),
            kind="gravitational",
            text="W: book\npulls Earth",
            text_side="left",
            text_at=(-0.85, -0.8),
        ),
        "contact": _draw_arrow(
            right,
            (0.3, -0.15),
            (0.3, -1.27),
            kind="contact",
            text="R: book\npushes table",
            text_at=(0.3, -0.75),
        ),
    }
    return ThirdLawDiagram(figure, on_book, partners)


def book_on_table_caption() -> str:
    return (
        "A book resting on a table. Left: the two forces on the book, its weight W and the "
        "contact force R from the table; they are equal because the book is in equilibrium "
        "(first law), not because they are a pair. Right: their third-law pairs, which act "
        "on the Earth and on the table."
    )


def skydiver_free_bodies_data(skydive: Skydive, points=("A", "C", "D")) -> FigureData:
    """The forces each panel draws (the arrows' lengths are in proportion to them)."""
    drags = [_drag_at(skydive, p) for p in points]
    return figure_data(
        f"Forces on the {format_number(skydive.mass, 2)} kg skydiver at each point",
        [Column("point", list(points)),
         Column(f"speed / {VELOCITY_UNIT}", [skydive.points[p][1] for p in points], 2),
         Column("weight, down / N", [skydive.weight] * len(points), 3),
         Column("drag, up / N", drags, 3),
         Column("resultant force, down / N", [skydive.weight - d for d in drags], 3)],
    )


_COUNT_WORDS = {1: "One", 2: "Two", 3: "Three", 4: "Four", 5: "Five"}


def skydiver_free_bodies_description(skydive: Skydive, points=("A", "C", "D")) -> str:
    return description(
        f"{_COUNT_WORDS.get(len(points), str(len(points)))} panels side by side, one for each point, without axes; in each the "
        "skydiver is a circle, the weight an arrow down from it and the drag an arrow up, "
        "lengths in proportion to the forces.",
        _skydiver_free_bodies_words(skydive, points),
        "The Data table lists the forces at each point.",
    )


#: The forces the book-on-a-table diagram draws: (label, what it is, on, by, direction,
#: panel); the notes give no mass, so there are no values, only the pairs.
_BOOK_FORCES = (
    ("W", "weight (gravitational)", "book", "Earth", "down", "left: forces on the book"),
    ("R", "contact", "book", "table", "up", "left: forces on the book"),
    ("W", "gravitational", "Earth", "book", "up", "right: their third-law pairs"),
    ("R", "contact", "table", "book", "down", "right: their third-law pairs"),
)


def book_on_table_data() -> FigureData:
    """The four drawn forces: each pair acts on different bodies, same type, opposite ways."""
    return figure_data(
        "The forces in the diagram of a book on a table",
        [Column(heading, [force[i] for force in _BOOK_FORCES])
         for i, heading in enumerate(("force", "type", "acts on", "exerted by", "direction", "panel"))],
    )


def book_on_table_description() -> str:
    return description(
        "Two panels side by side, without axes or values (the notes give no mass).",
        book_on_table_alt(),
        "The Data table lists each force: its type, the body it acts on, the body that exerts it, "
        "and its direction.",
    )


def book_on_table_alt() -> str:
    return (
        "Two diagrams of a book on a table above the Earth. Left, forces on the book: the "
        "weight W, the Earth pulling the book down, and the contact force R, the table "
        "pushing the book up, equal in length. Right, their third-law pairs: the book "
        "pulling the Earth up with a gravitational force W, and the book pushing the table "
        "down with a contact force R. Arrows of the same type match in colour and line style."
    )


# --- The book's figures from this module (see book_figure.py); a page calls one of these. ---


def free_body_skydiver(skydive: Skydive) -> BookFigure:
    figure, _ = plot_skydiver_free_bodies(skydive)
    return BookFigure(
        "fig-free-body-skydiver",
        figure,
        skydiver_free_bodies_caption(skydive),
        skydiver_free_bodies_alt(skydive),
        skydiver_free_bodies_description(skydive),
        skydiver_free_bodies_data(skydive),
    )


def free_body_book() -> BookFigure:
    return BookFigure(
        "fig-free-body-book",
        plot_book_on_table().figure,
        book_on_table_caption(),
        book_on_table_alt(),
        book_on_table_description(),
        book_on_table_data(),
    )
