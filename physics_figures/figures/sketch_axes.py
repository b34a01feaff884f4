"""The axes a sketch part prints (parts.sketch.SketchAxes): time across, the quantity up, a
light grid at each labelled division, the time axis at zero, as a paper prints the axes to
sketch on. The site draws the student's line on them (static/sketch-pad.js reads the plot
area and the axes' ranges from the SVG's data attributes); the sheets print them blank and the
key prints them with the model line. Nothing is computed here but where a point sits.

Two outputs from one layout, as figures.sketches: ``axes_svg`` (the site inline, Moodle) and
``axes_tikz`` (the worksheets). Colours are the figures' roles, read from the tokens; the
paper stays white in dark mode, as every question graph's does (--graph-paper).
"""

from __future__ import annotations

from html import escape

from ..notation import format_number, plain_number
from ..style import colour
from .sketches import _tikz_colour

LINE, AXES, TEXT, GRID, PAPER = (colour(role) for role in ("figure.blue", "figure.frame", "figure.ink",
                                                            "figure.grid-minor", "figure.paper"))
#: The box in SVG user units (CSS px at natural size) and its plot area.
WIDTH, HEIGHT = 320, 240
LEFT, RIGHT, TOP, BOTTOM = 52.0, 304.0, 30.0, 204.0
#: The same box on paper: centimetres per SVG unit (a 9.6 cm wide figure).
CM_PER_UNIT = 0.03


def _n(value: float, places: int = 2) -> str:
    text = plain_number(format_number(value, decimals=places))
    return text.rstrip("0").rstrip(".") if "." in text else text


def _places(step: float) -> int:
    return next(p for p in range(6) if abs(step * 10**p - round(step * 10**p)) < 1e-9)


def place(axes, t: float, y: float) -> tuple[float, float]:
    """Where (t, y) in the axes' units sits in the box (y down, as SVG draws)."""
    return (LEFT + t / axes.t_max * (RIGHT - LEFT),
            BOTTOM - (y - axes.y_min) / (axes.y_max - axes.y_min) * (BOTTOM - TOP))


#: At most this many numbers along the time axis (a phone's 390 px keeps them apart), and up it.
_MOST_T_LABELS, _MOST_Y_LABELS = 6, 9


def _ticks(low: float, high: float, step: float) -> list[float]:
    count = round((high - low) / step)
    return [low + i * step for i in range(count + 1)]


def _labelled(ticks: list[float], most: int) -> list[float]:
    """Every tick, or every 2nd or 5th (counted from zero) when there are too many to number."""
    every = next(k for k in (1, 2, 5, 10) if len(ticks) / k <= most + 1)
    return [t for i, t in enumerate(ticks) if (i - ticks.index(min(ticks, key=abs))) % every == 0]


def _label(axes) -> str:
    return f"{axes.symbol} / {axes.unit}".replace("^-1", "⁻¹").replace("^-2", "⁻²")


def axes_svg(axes, *, line=None, label: str = "") -> str:
    """The axes as a standalone SVG, with ``line`` (points in the axes' units) drawn on them
    when given. ``label`` names it for a screen reader."""
    t_places, y_places = _places(axes.t_division), _places(axes.y_division)
    grid, text = [], []
    t_ticks, y_ticks = _ticks(0.0, axes.t_max, axes.t_division), _ticks(axes.y_min, axes.y_max, axes.y_division)
    t_shown, y_shown = _labelled(t_ticks, _MOST_T_LABELS), _labelled(y_ticks, _MOST_Y_LABELS)
    for t in t_ticks:
        x, _ = place(axes, t, axes.y_min)
        grid.append(f"M{_n(x)},{_n(TOP)}V{_n(BOTTOM)}")
        if t in t_shown:
            text.append(f'<text x="{_n(x)}" y="{_n(BOTTOM + 15)}" text-anchor="middle">'
                        f"{format_number(t, decimals=t_places)}</text>")
    for y in y_ticks:
        _, v = place(axes, 0.0, y)
        grid.append(f"M{_n(LEFT)},{_n(v)}H{_n(RIGHT)}")
        if y in y_shown:
            text.append(f'<text x="{_n(LEFT - 5)}" y="{_n(v + 4)}" text-anchor="end">'
                        f"{format_number(y, decimals=y_places)}</text>")
    _, zero = place(axes, 0.0, 0.0)
    drawn = ""
    if line:
        points = " ".join(f"{_n(x)},{_n(y)}" for x, y in (place(axes, t, v) for t, v in line))
        drawn = (f'<polyline class="q-sketch-model" points="{points}" fill="none" stroke="{LINE}" '
                 'stroke-width="2.5" stroke-linejoin="round" stroke-linecap="round"/>')
    name = escape(label or f"Axes to sketch on: {axes.quantity} / {_label(axes).split(' / ')[1]} against time / s")
    return (
        f'<svg xmlns="http://www.w3.org/2000/svg" class="q-sketch-axes" viewBox="0 0 {WIDTH} {HEIGHT}" '
        f'width="{WIDTH}" height="{HEIGHT}" role="img" aria-label="{name}" '
        f'data-plot="{_n(LEFT)} {_n(TOP)} {_n(RIGHT)} {_n(BOTTOM)}" '
        f'data-t="0 {_n(axes.t_max, 6)}" data-y="{_n(axes.y_min, 6)} {_n(axes.y_max, 6)}">'
        f'<rect width="{WIDTH}" height="{HEIGHT}" fill="{PAPER}"/>'
        f'<path d="{"".join(grid)}" stroke="{GRID}" stroke-width="0.6" fill="none"/>'
        f'<path d="M{_n(LEFT)},{_n(BOTTOM)}V{_n(TOP - 8)}M{_n(LEFT)},{_n(zero)}H{_n(RIGHT + 6)}" '
        f'stroke="{AXES}" stroke-width="1.4" fill="none"/>'
        f'<g fill="{TEXT}" font-family="sans-serif" font-size="12">{"".join(text)}'
        f'<text x="{_n(LEFT + 6)}" y="{_n(TOP - 12)}"><tspan font-style="italic">{escape(axes.symbol)}</tspan>'
        f"{escape(_label(axes)[len(axes.symbol):])}</text>"
        f'<text x="{_n(RIGHT)}" y="{_n(HEIGHT - 6)}" text-anchor="end"><tspan font-style="italic">t</tspan> / s</text></g>'
        f"{drawn}</svg>")


def axes_tikz(axes, *, line=None) -> str:
    """The axes as a TikZ picture (about 9.6 cm wide), the same layout as the SVG."""

    def cm(x: float, y: float) -> str:
        return f"({_n(x * CM_PER_UNIT, 3)},{_n((HEIGHT - y) * CM_PER_UNIT, 3)})"

    t_places, y_places = _places(axes.t_division), _places(axes.y_division)
    out = ["\\begin{tikzpicture}[font=\\small]"]
    t_ticks, y_ticks = _ticks(0.0, axes.t_max, axes.t_division), _ticks(axes.y_min, axes.y_max, axes.y_division)
    t_shown, y_shown = _labelled(t_ticks, _MOST_T_LABELS), _labelled(y_ticks, _MOST_Y_LABELS)
    for t in t_ticks:
        x, _ = place(axes, t, axes.y_min)
        out.append(f"\\draw[line width=0.3pt,color={_tikz_colour(GRID)}] {cm(x, TOP)} -- {cm(x, BOTTOM)};")
        if t in t_shown:
            out.append(f"\\node[anchor=north] at {cm(x, BOTTOM + 2)} {{{format_number(t, decimals=t_places)}}};")
    for y in y_ticks:
        _, v = place(axes, 0.0, y)
        out.append(f"\\draw[line width=0.3pt,color={_tikz_colour(GRID)}] {cm(LEFT, v)} -- {cm(RIGHT, v)};")
        if y in y_shown:
            out.append(f"\\node[anchor=east] at {cm(LEFT - 2, v)} {{{format_number(y, decimals=y_places)}}};")
    _, zero = place(axes, 0.0, 0.0)
    frame = _tikz_colour(AXES)
    out.append(f"\\draw[->,line width=0.6pt,color={frame}] {cm(LEFT, BOTTOM)} -- {cm(LEFT, TOP - 8)};")
    out.append(f"\\draw[->,line width=0.6pt,color={frame}] {cm(LEFT, zero)} -- {cm(RIGHT + 6, zero)};")
    label = _label(axes).replace("⁻¹", "$^{-1}$").replace("⁻²", "$^{-2}$")
    out.append(f"\\node[anchor=south west] at {cm(LEFT + 4, TOP - 8)} {{\\textit{{{axes.symbol}}}{label[1:]}}};")
    out.append(f"\\node[anchor=north east] at {cm(RIGHT, BOTTOM + 16)} {{\\textit{{t}} / s}};")
    if line:
        coordinates = " -- ".join(cm(*place(axes, t, v)) for t, v in line)
        out.append(f"\\draw[line width=1.2pt,line join=round,color={_tikz_colour(LINE)}] {coordinates};")
    out.append("\\end{tikzpicture}")
    return "".join(out)
