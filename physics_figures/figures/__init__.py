"""Matplotlib drawings of what ``physics_figures.models`` computes (never any physics here).

Plot functions take the model objects first, options as keywords, ``ax=None`` (draw into
that Axes, or a new Figure), and return a NamedTuple of the artists. Each figure module
also writes its caption and alt text from the same objects. ``book`` wraps them for the
pages; ``style`` is the one place the look is set.
"""

from .collisions import plot_collision
from .drag import plot_drag_against_speed, plot_thrown_upwards
from .free_body import plot_book_on_table, plot_skydiver_free_bodies, plot_skydiver_free_body
from .momentum_graphs import plot_force_time_area, plot_momentum_time
from .skydiver import plot_resultant_force, plot_velocity_time
from .vectors import plot_momentum_triangle

__all__ = [
    "plot_book_on_table",
    "plot_collision",
    "plot_drag_against_speed",
    "plot_force_time_area",
    "plot_momentum_time",
    "plot_momentum_triangle",
    "plot_resultant_force",
    "plot_skydiver_free_bodies",
    "plot_skydiver_free_body",
    "plot_thrown_upwards",
    "plot_velocity_time",
]
