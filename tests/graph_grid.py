"""The grid of a question's graph as drawn, read from its SVG: what the tests of the enlarged
view measure a small square by (the drawing's own grid lines, not the data the view zooms by)."""

from __future__ import annotations

import itertools
import re

#: A straight line of two points, clipped to the plot area: matplotlib's grid lines.
_CLIPPED_LINE = re.compile(r'<path d="M (-?[\d.]+) (-?[\d.]+) \s*L (-?[\d.]+) (-?[\d.]+) \s*" clip-path=')


def grid_squares(svg: str) -> tuple[float, float, float, float]:
    """(the viewBox's width and height, the gap between neighbouring vertical grid lines and the
    gap between neighbouring horizontal ones), in the SVG's own units: the last two are a small
    square's width and height."""
    width, height = map(float, re.search(r'viewBox="([^"]+)"', svg)[1].split()[2:])
    across, up = set(), set()
    for match in _CLIPPED_LINE.finditer(svg):
        x1, y1, x2, y2 = map(float, match.groups())
        if x1 == x2 and y1 != y2:
            across.add(round(x1, 3))
        elif y1 == y2 and x1 != x2:
            up.add(round(y1, 3))
    assert len(across) > 5 and len(up) > 5, "the SVG shows no grid of small squares"

    def gap(lines: set[float]) -> float:
        return min(b - a for a, b in itertools.pairwise(sorted(lines)))

    return width, height, gap(across), gap(up)
