"""Figures as the book shows them: the drawing plus its name, caption and alt text.

A figure cell in a page is one line, e.g. ``book.skydiver_velocity_time(SKYDIVER)``.
It returns a :class:`BookFigure`, whose rich output carries everything the page
needs, so the page never repeats it:

* ``image/svg+xml`` for the HTML site and ``application/pdf`` for the LaTeX/PDF
  book (myst-nb picks one per builder);
* ``text/plain``: the alt text (also what a text-only front end prints);
* ``text/markdown``: a MyST comment ``% physics-figure <name>`` then the caption.

``book/_ext/figure_captions.py`` turns that output into a numbered Sphinx figure
named ``<name>`` (so ``{numref}`<name>``` works) with the caption under it and
the alt text on the image. Caption and alt text are written here, from the
same model objects the drawing uses, so they always agree with it.
"""

from __future__ import annotations

import base64
import io
from dataclasses import dataclass

from matplotlib.figure import Figure

from ..models import stick_together
from ..models.drag import Skydive, ThrowUp
from ..models.momentum_history import MomentumHistory
from ..models.two_d import GlancingCollision
from ..questions import Graph
from .collisions import collision_alt, collision_caption, plot_collision
from .drag import (
    drag_against_speed_alt,
    drag_against_speed_caption,
    plot_drag_against_speed,
    plot_thrown_upwards,
    thrown_upwards_alt,
    thrown_upwards_caption,
)
from .free_body import (
    book_on_table_alt,
    book_on_table_caption,
    plot_book_on_table,
    plot_skydiver_free_bodies,
    skydiver_free_bodies_alt,
    skydiver_free_bodies_caption,
)
from .momentum_graphs import (
    force_time_alt,
    force_time_caption,
    momentum_time_alt,
    momentum_time_caption,
    plot_force_time_area,
    plot_momentum_time,
)
from .question_graph import plot_question_graph, question_graph_alt
from .skydiver import (
    plot_resultant_force,
    plot_velocity_time,
    resultant_force_alt,
    resultant_force_caption,
    velocity_time_alt,
    velocity_time_caption,
)
from .style import book_style
from .vectors import momentum_triangle_alt, momentum_triangle_caption, plot_momentum_triangle

#: First word of the MyST comment that marks a figure output for the Sphinx extension.
FIGURE_MARKER = "physics-figure"


@dataclass(frozen=True)
class BookFigure:
    """A finished figure with its label, caption (MyST) and alt text."""

    name: str
    figure: Figure
    caption: str
    alt: str

    def __post_init__(self) -> None:
        # Constrained layout (with equal-aspect panels) moves the axes a little on every
        # draw; lay out once, then freeze, so every save gives the same bytes.
        with book_style():
            self.figure.draw_without_rendering()
        self.figure.set_layout_engine("none")

    def svg(self) -> str:
        """The figure as SVG text, byte-identical on every run."""
        buffer = io.StringIO()
        with book_style():
            self.figure.savefig(buffer, format="svg", metadata={"Date": None})
        return buffer.getvalue()

    def pdf(self) -> bytes:
        """The figure as vector PDF, byte-identical on every run."""
        buffer = io.BytesIO()
        with book_style():
            self.figure.savefig(buffer, format="pdf", metadata={"CreationDate": None})
        return buffer.getvalue()

    def _repr_mimebundle_(self, include=None, exclude=None) -> dict[str, str]:
        """Jupyter's rich output: every format a builder might pick, plus the words."""
        return {
            "image/svg+xml": self.svg(),
            "application/pdf": base64.b64encode(self.pdf()).decode("ascii"),
            "text/markdown": f"% {FIGURE_MARKER} {self.name}\n\n{self.caption}\n",
            "text/plain": self.alt,
        }

    def __repr__(self) -> str:
        return f"BookFigure({self.name!r}: {self.alt})"


# --- The book's figures, one function per figure name (the name is the {numref} label). ---


def skydiver_velocity_time(skydive: Skydive) -> BookFigure:
    graph = plot_velocity_time(skydive)
    return BookFigure(
        "fig-skydiver-velocity-time",
        graph.axes.figure,
        velocity_time_caption(skydive),
        velocity_time_alt(skydive),
    )


def skydiver_resultant_force(skydive: Skydive) -> BookFigure:
    graph = plot_resultant_force(skydive)
    return BookFigure(
        "fig-skydiver-resultant-force",
        graph.axes.figure,
        resultant_force_caption(skydive),
        resultant_force_alt(skydive),
    )


def free_body_skydiver(skydive: Skydive) -> BookFigure:
    figure, _ = plot_skydiver_free_bodies(skydive)
    return BookFigure(
        "fig-free-body-skydiver",
        figure,
        skydiver_free_bodies_caption(skydive),
        skydiver_free_bodies_alt(skydive),
    )


def drag_against_speed(skydive: Skydive) -> BookFigure:
    graph = plot_drag_against_speed(skydive)
    return BookFigure(
        "fig-drag-against-speed",
        graph.axes.figure,
        drag_against_speed_caption(skydive),
        drag_against_speed_alt(skydive),
    )


def thrown_upwards(with_drag: ThrowUp, without_drag: ThrowUp) -> BookFigure:
    graph = plot_thrown_upwards(with_drag, without_drag)
    return BookFigure(
        "fig-thrown-upwards",
        graph.figure,
        thrown_upwards_caption(with_drag, without_drag),
        thrown_upwards_alt(with_drag, without_drag),
    )


def car_momentum_time(history: MomentumHistory, *, mass: float) -> BookFigure:
    graph = plot_momentum_time(history)
    return BookFigure(
        "fig-car-momentum-time",
        graph.axes.figure,
        momentum_time_caption(history, mass=mass),
        momentum_time_alt(history, mass=mass),
    )


def force_time_area(history: MomentumHistory) -> BookFigure:
    graph = plot_force_time_area(history)
    return BookFigure(
        "fig-force-time-area",
        graph.axes.figure,
        force_time_caption(history),
        force_time_alt(history),
    )


def free_body_book() -> BookFigure:
    return BookFigure(
        "fig-free-body-book",
        plot_book_on_table().figure,
        book_on_table_caption(),
        book_on_table_alt(),
    )


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
    )


def pucks_triangle(collision: GlancingCollision) -> BookFigure:
    graph = plot_momentum_triangle(collision, names=("P", "Q"), figures=2)
    return BookFigure(
        "fig-pucks-triangle",
        graph.axes.figure,
        momentum_triangle_caption(collision, names=("P", "Q")),
        momentum_triangle_alt(collision, names=("P", "Q"), figures=2),
    )


def example4_triangle(collision: GlancingCollision) -> BookFigure:
    graph = plot_momentum_triangle(collision, names=("X", "Y"), figures=3)
    return BookFigure(
        "fig-example4-triangle",
        graph.axes.figure,
        momentum_triangle_caption(collision, names=("X", "Y")),
        momentum_triangle_alt(collision, names=("X", "Y"), figures=3),
    )


def question_graph(graph: Graph) -> BookFigure:
    """The graph a question prints, for one variant (the question directive draws it)."""
    drawn = plot_question_graph(graph)
    return BookFigure("question-graph", drawn.axes.figure, "", question_graph_alt(graph))
