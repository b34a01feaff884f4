"""The grid of a question's graph as drawn, read from its SVG: what the tests of the enlarged
view measure a small square by (the drawing's own grid lines, not the data the view zooms by)."""

from __future__ import annotations

import itertools
import re

#: A path clipped to the plot area: the labelled grid lines (one path each) and the small
#: squares' lines (one path of many pieces, physics_figures/figures/question_graph.py).
_CLIPPED_PATH = re.compile(r'<path d="([^"]+)" clip-path=')
#: One straight piece of such a path: a move, then a line to the next point.
_PIECE = re.compile(r"M (-?[\d.]+) (-?[\d.]+)\s+L (-?[\d.]+) (-?[\d.]+)\s*(?=M|$)")


def grid_lines(svg: str) -> tuple[float, float, list[float], list[float]]:
    """The viewBox's width and height, the x of every vertical grid line (left first) and the
    y of every horizontal one (top first), in the SVG's own units."""
    width, height = map(float, re.search(r'viewBox="([^"]+)"', svg)[1].split()[2:])
    across, up = set(), set()
    pieces = (piece.groups() for path in _CLIPPED_PATH.finditer(svg) for piece in _PIECE.finditer(path[1]))
    for x1, y1, x2, y2 in (map(float, piece) for piece in pieces):
        if x1 == x2 and y1 != y2:
            across.add(round(x1, 3))
        elif y1 == y2 and x1 != x2:
            up.add(round(y1, 3))
    assert len(across) > 5 and len(up) > 5, "the SVG shows no grid of small squares"
    return width, height, sorted(across), sorted(up)


def grid_squares(svg: str) -> tuple[float, float, float, float]:
    """(the viewBox's width and height, the gap between neighbouring vertical grid lines and the
    gap between neighbouring horizontal ones), in the SVG's own units: the last two are a small
    square's width and height."""
    width, height, across, up = grid_lines(svg)

    def gap(lines: list[float]) -> float:
        return min(b - a for a, b in itertools.pairwise(lines))

    return width, height, gap(across), gap(up)
