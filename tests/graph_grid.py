"""The grid of a question's graph as drawn, read from its SVG: what the tests of the enlarged
view measure a small square by (the drawing's own grid lines, not the data the view zooms by)."""

from __future__ import annotations

import itertools
import re

#: A path clipped to the plot area: the labelled grid lines (one path each) and the small
#: squares' lines (one path of many pieces, physics_figures/figures/question_graph.py).
_CLIPPED_PATH = re.compile(r'<path d="([^"]+)" clip-path=')
#: A command of path data and its numbers, as matplotlib writes it ("M 52.16 200.36 L …") or
#: as the site compacts it ("M52.16 200.36V10.32", book/_ext/svg_compact.py).
_COMMAND = re.compile(r"([MLHV])\s*((?:-?[\d.]+(?:e-?\d+)?[\s,]*)*)")


def _pieces(d: str):
    """Each grid line of absolute path data: a subpath of one move and one straight line, as
    (x1, y1, x2, y2). A subpath of several lines is the plotted line, not the grid (its level
    stretches would read as grid lines)."""
    subpaths: list[list[tuple[float, float, float, float]]] = []
    x = y = None
    for command, numbers in _COMMAND.findall(d):
        values = [float(v) for v in re.findall(r"-?[\d.]+(?:e-?\d+)?", numbers)]
        if command == "M":
            x, y = values[-2:]
            subpaths.append([])
            continue
        end = {"L": tuple(values[-2:]), "H": (values[-1], y), "V": (x, values[-1])}[command]
        subpaths[-1].append((x, y, *end))
        x, y = end
    return [lines[0] for lines in subpaths if len(lines) == 1]


def grid_lines(svg: str) -> tuple[float, float, list[float], list[float]]:
    """The viewBox's width and height, the x of every vertical grid line (left first) and the
    y of every horizontal one (top first), in the SVG's own units."""
    width, height = map(float, re.search(r'viewBox="([^"]+)"', svg)[1].split()[2:])
    across, up = set(), set()
    for x1, y1, x2, y2 in (piece for path in _CLIPPED_PATH.finditer(svg) for piece in _pieces(path[1])):
        if x1 == x2 and y1 != y2:
            across.add(round(x1, 3))
        elif y1 == y2 and x1 != x2:
            up.add(round(y1, 3))
    across, up = _one_each(across), _one_each(up)
    assert len(across) > 5 and len(up) > 5, "the SVG shows no grid of small squares"
    return width, height, across, up


#: Lines nearer than this (SVG units, a tenth of a pixel) are one line: the compacted SVG writes
#: coordinates to 0.01, so a grid line and the spine over it may differ in the last place.
SAME_LINE = 0.1


def _one_each(lines: set[float]) -> list[float]:
    """The lines, left to right (or top to bottom), each drawn line once."""
    kept: list[float] = []
    for line in sorted(lines):
        if not kept or line - kept[-1] >= SAME_LINE:
            kept.append(line)
    return kept


def grid_squares(svg: str) -> tuple[float, float, float, float]:
    """(the viewBox's width and height, the gap between neighbouring vertical grid lines and the
    gap between neighbouring horizontal ones), in the SVG's own units: the last two are a small
    square's width and height."""
    width, height, across, up = grid_lines(svg)

    def gap(lines: list[float]) -> float:
        return min(b - a for a, b in itertools.pairwise(lines))

    return width, height, gap(across), gap(up)
