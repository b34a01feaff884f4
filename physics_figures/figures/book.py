"""Every figure of the book in one namespace, for scripts and notebooks outside the book.

The book's pages do not import this module: each page imports the one figure module it
draws from (e.g. ``from physics_figures.figures import collisions``), so an edit to one
figure module re-executes only the pages that draw from it (``book/_ext/fresh_figures.py``
keys each page on the modules it imports; importing this module would tie a page to
all of them). :class:`~physics_figures.figures.book_figure.BookFigure` explains what a
book figure carries.
"""

from __future__ import annotations

from .book_figure import FIGURE_MARKER, BookFigure
from .collisions import collision_before_after
from .drag import drag_against_speed, thrown_upwards
from .free_body import free_body_book, free_body_skydiver
from .momentum_graphs import car_momentum_time, force_time_area
from .question_graph import question_graph
from .skydiver import skydiver_resultant_force, skydiver_velocity_time
from .vectors import example4_triangle, pucks_triangle

__all__ = [
    "FIGURE_MARKER",
    "BookFigure",
    "car_momentum_time",
    "collision_before_after",
    "drag_against_speed",
    "example4_triangle",
    "force_time_area",
    "free_body_book",
    "free_body_skydiver",
    "pucks_triangle",
    "question_graph",
    "skydiver_resultant_force",
    "skydiver_velocity_time",
    "thrown_upwards",
]
