"""The one style of every figure in the book.

Everything visual that is shared lives here: the rcParams, the palette and the
line styles. Figures are read in three places, so the style serves all three:

* print and greyscale: each series differs by line style or marker as well as
  colour, and lines are thick enough to survive a photocopier;
* a phone: a figure is 5.6 in (about 410 pt of SVG) and spans the whole 390 px screen
  (_static/figures.css), and no text in it is smaller than 12 pt, so every label is
  drawn at least 11 CSS px high there (tests/test_figure_text_browser.py measures it);
* colour-blind readers: the Okabe-Ito palette (Okabe & Ito, "Color Universal
  Design", 2008), which stays distinct under the common colour-vision deficiencies.

The SVGs keep their text as text (``svg.fonttype: none``): small files, selectable
and searchable, and a screen reader can reach the labels. ``svg.hashsalt`` and
the empty metadata make the bytes the same on every run.
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import ParamSpec, TypeVar

import matplotlib as mpl
from matplotlib.axes import Axes
from matplotlib.figure import Figure

from ..style import colour

#: Okabe-Ito colours by name (physics_figures/style/tokens.json, "figure"), so a figure
#: says *what* a colour means through the roles below.
PALETTE = {
    name: colour(f"figure.{name}")
    for name in ("black", "orange", "sky", "green", "yellow", "blue", "vermilion", "purple")
}
#: What each colour stands for across the chapter.
MAIN = PALETTE["blue"]  # the quantity the figure is about
SECOND = PALETTE["vermilion"]  # the thing it is compared with
GUIDE = colour("figure.guide")  # asymptotes, reference lines (dark grey reads on paper and on the card)
INK = colour("figure.ink")  # text, outlines of bodies
FRAME = colour("figure.frame")  # axes and ticks
PAPER = colour("figure.paper")  # bodies and labels' backgrounds, white as the card
SHADE = PALETTE["sky"]  # filled areas
FORCE_COLOURS = {
    "weight": PALETTE["blue"],
    "drag": PALETTE["vermilion"],
    "contact": PALETTE["green"],
    "gravitational": PALETTE["purple"],
}

#: Line styles that still tell two series apart in greyscale.
LINESTYLES = ("-", "--", ":", "-.")

#: Size of a full-width figure, inches (5.6 in = 538 CSS px at 96 dpi).
FIGSIZE = (5.6, 3.6)
#: The smallest text in any figure, points: ticks, legends, annotations. A 390 px phone
#: shows a full-width figure at about 0.93 CSS px a point, so this is >= 11 CSS px there
#: (CLARIFICATIONS, Reading: figure text). Never "small" or "x-small": they go below it.
SMALL_TEXT = 12.0

RC_PARAMS: dict[str, object] = {
    # text: one sans-serif family, large enough for a phone
    "font.family": "sans-serif",
    "font.sans-serif": ["DejaVu Sans", "Liberation Sans", "Arial", "sans-serif"],
    "font.size": 12.5,
    "axes.titlesize": 12.5,
    "axes.labelsize": 12.5,
    "xtick.labelsize": SMALL_TEXT,
    "ytick.labelsize": SMALL_TEXT,
    "legend.fontsize": SMALL_TEXT,
    "mathtext.default": "regular",
    # lines: thick, round, distinct
    "lines.linewidth": 2.2,
    "lines.markersize": 7,
    "lines.solid_capstyle": "round",
    "axes.prop_cycle": mpl.cycler(
        color=[MAIN, SECOND, PALETTE["green"], PALETTE["orange"]],
        linestyle=list(LINESTYLES),
    ),
    # axes: a plain frame with the origin visible, no chart junk
    "axes.spines.top": False,
    "axes.spines.right": False,
    "axes.linewidth": 1.0,
    "axes.edgecolor": FRAME,
    "axes.labelcolor": INK,
    "text.color": INK,
    "xtick.color": FRAME,
    "ytick.color": FRAME,
    "axes.grid": False,
    "axes.xmargin": 0.0,
    "axes.ymargin": 0.0,
    "legend.frameon": False,
    # a transparent figure with a white plot area: on the site a light card sits behind it
    "figure.figsize": FIGSIZE,
    "figure.dpi": 100,
    "figure.facecolor": "none",
    "axes.facecolor": "none",
    "savefig.facecolor": "none",
    "savefig.bbox": "tight",
    "savefig.pad_inches": 0.08,
    # reproducible, small vector output
    "svg.fonttype": "none",
    "svg.hashsalt": "physics-figures",
    "pdf.fonttype": 42,
    "path.simplify": True,
}


@contextmanager
def book_style() -> Iterator[None]:
    """Apply the book's rcParams inside a ``with`` block (restored after)."""
    with mpl.rc_context(RC_PARAMS):
        yield


P = ParamSpec("P")
R = TypeVar("R")


def styled(plot: Callable[P, R]) -> Callable[P, R]:
    """Run a plotting function inside :func:`book_style`.

    Matplotlib reads rcParams when each artist is made (and the SVG options
    when it saves), so the whole drawing must happen inside the style.
    """

    @functools.wraps(plot)
    def wrapper(*args: P.args, **kwargs: P.kwargs) -> R:
        with book_style():
            return plot(*args, **kwargs)

    return wrapper


def new_axes(ax: Axes | None, *, figsize: tuple[float, float] = FIGSIZE) -> Axes:
    """Return ``ax``, or the Axes of a new Figure in the book style.

    The Figure is made with ``matplotlib.figure.Figure`` rather than pyplot, so
    it is not registered with a GUI or inline backend: nothing is shown twice
    and nothing leaks if the caller never closes it.
    """
    if ax is not None:
        return ax
    with book_style():
        fig = Figure(figsize=figsize, layout="constrained")
        return fig.add_subplot()


def unit_label(quantity: str, unit: str) -> str:
    """Axis label in the form the 9702 papers use: ``quantity / unit``."""
    return f"{quantity} / {unit}"
