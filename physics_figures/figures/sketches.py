"""The small sketch graphs of a "which graph?" item (parts.choice.Sketch): axes with arrows, 0 at
the origin, the value's symbol and t, and the line, with no scale, as a Paper 1 item draws its
options A to D. The numbers are the template's; nothing is computed here but where a point sits
in the box.

Two outputs from one layout: ``sketch_svg`` (the site inline, and Moodle as a file: a few hundred
bytes each, no matplotlib) and ``sketch_tikz`` (the worksheets and the PDF book). The colours are
the figures' roles (figures.style: MAIN for the line, FRAME for the axes, INK for text), read
from the tokens without loading matplotlib, which a page of four sketches does not need.
"""

from __future__ import annotations

from html import escape

from ..notation import format_number, plain_number
from ..style import colour

#: The roles of figures.style (MAIN, FRAME, INK, PAPER), by their tokens.
LINE, AXES, TEXT, BACKGROUND = (colour(role) for role in ("figure.blue", "figure.frame", "figure.ink", "figure.paper"))
#: The box, in SVG user units (CSS px at natural size), and the plotting area inside it.
WIDTH, HEIGHT = 132, 96
LEFT, RIGHT, TOP, BOTTOM = 18.0, 120.0, 14.0, 82.0
#: The same box on paper: centimetres per SVG unit.
CM_PER_UNIT = 0.03
#: Room above and below the line, as a share of the values' span.
_HEADROOM = 0.08


def _layout(sketch) -> tuple[list[tuple[float, float]], float]:
    """The line's points in the box (y down, as SVG draws), and the height of the time axis."""
    values = [y for _, y in sketch.points]
    low, high = min(0.0, *values), max(0.0, *values)
    if high == low:  # a line on the time axis: put the axis in the middle
        low, high = -1.0, 1.0
    pad = _HEADROOM * (high - low)
    low, high = (low - pad if low < 0 else low), high + pad
    duration = max(t for t, _ in sketch.points)

    def place(t: float, y: float) -> tuple[float, float]:
        return (LEFT + t / duration * (RIGHT - LEFT), BOTTOM - (y - low) / (high - low) * (BOTTOM - TOP))

    return [place(t, y) for t, y in sketch.points], place(0.0, 0.0)[1]


def _n(value: float, places: int = 1) -> str:
    """A coordinate as SVG and TikZ read it: plain digits, a hyphen-minus, no trailing zeros."""
    text = plain_number(format_number(value, decimals=places))
    return text.rstrip("0").rstrip(".") if "." in text else text


def sketch_svg(sketch) -> str:
    """The sketch as a standalone SVG (xmlns set, so Moodle can ship it as a file), named for
    a screen reader by its shape in words (``sketch.describe()``)."""
    line, axis = _layout(sketch)
    alt = escape(sketch.describe())
    path = " ".join(f"{_n(x)},{_n(y)}" for x, y in line)
    return (
        f'<svg xmlns="http://www.w3.org/2000/svg" class="q-sketch" viewBox="0 0 {WIDTH} {HEIGHT}" '
        f'width="{WIDTH}" height="{HEIGHT}" role="img" aria-label="{alt}">'
        f'<rect width="{WIDTH}" height="{HEIGHT}" fill="{BACKGROUND}"/>'
        f'<g stroke="{AXES}" stroke-width="1.2" fill="none">'
        f'<path d="M{_n(LEFT)},{_n(BOTTOM + 4)}V{_n(TOP - 8)}M{_n(LEFT - 3)},{_n(TOP - 4)}l3,-4 3,4"/>'
        f'<path d="M{_n(LEFT)},{_n(axis)}H{_n(RIGHT + 8)}M{_n(RIGHT + 4)},{_n(axis - 3)}l4,3 -4,3"/></g>'
        f'<polyline points="{path}" fill="none" stroke="{LINE}" stroke-width="2.4" stroke-linejoin="round"'
        ' stroke-linecap="round"/>'
        f'<g fill="{TEXT}" font-family="sans-serif" font-size="13">'
        f'<text x="{_n(LEFT + 5)}" y="{_n(TOP - 1)}" font-style="italic">{escape(sketch.symbol)}</text>'
        f'<text x="{_n(RIGHT + 2)}" y="{_n(axis + 15 if axis + 15 <= HEIGHT else axis - 6)}" '
        f'font-style="italic">t</text>'
        f'<text x="{_n(LEFT - 11)}" y="{_n(axis + 12 if axis + 12 <= HEIGHT else axis + 4)}">0</text></g></svg>')


def _tikz_colour(hex_colour: str) -> str:
    red, green, blue = (int(hex_colour[i:i + 2], 16) for i in (1, 3, 5))
    return f"{{rgb,255:red,{red};green,{green};blue,{blue}}}"


def sketch_tikz(sketch) -> str:
    """The sketch as a TikZ picture (about 4 cm wide), the same layout as the SVG."""
    line, axis = _layout(sketch)

    def cm(x: float, y: float) -> str:  # SVG units (y down) to TikZ centimetres (y up)
        return f"({_n(x * CM_PER_UNIT, 3)},{_n((HEIGHT - y) * CM_PER_UNIT, 3)})"

    coordinates = " -- ".join(cm(x, y) for x, y in line)
    return (
        "\\begin{tikzpicture}[font=\\small]"
        f"\\draw[->,line width=0.5pt,color={_tikz_colour(AXES)}] {cm(LEFT, BOTTOM + 4)} -- {cm(LEFT, TOP - 8)};"
        f"\\draw[->,line width=0.5pt,color={_tikz_colour(AXES)}] {cm(LEFT, axis)} -- {cm(RIGHT + 8, axis)};"
        f"\\draw[line width=1.2pt,line join=round,color={_tikz_colour(LINE)}] {coordinates};"
        f"\\node[anchor=south west,inner sep=1pt] at {cm(LEFT + 2, TOP - 6)} {{\\textit{{{sketch.symbol}}}}};"
        f"\\node[anchor=north,inner sep=2pt] at {cm(RIGHT + 6, axis)} {{\\textit{{t}}}};"
        f"\\node[anchor=north east,inner sep=1pt] at {cm(LEFT, axis)} {{0}};"
        "\\end{tikzpicture}")
