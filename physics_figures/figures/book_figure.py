"""A figure as the book shows it: the drawing plus its name, caption and alt text.

Each figure module ends with the book's figures it draws, one function per figure name
(the name is the ``{numref}`` label), e.g. ``skydiver.skydiver_velocity_time(SKYDIVER)``.
A page imports only the module it draws from, so an edit to one figure module re-executes
only the pages that draw from it (``book/_ext/fresh_figures.py``). Each function returns a
:class:`BookFigure`, whose rich output carries everything the page needs, so the page never
repeats it:

* ``image/svg+xml`` for the HTML site and ``application/pdf`` for the LaTeX/PDF
  book (myst-nb picks one per builder);
* ``text/plain``: the alt text (also what a text-only front end prints);
* ``text/markdown``: a MyST comment ``% physics-figure <name>`` then the caption.

``book/_ext/figure_captions.py`` turns that output into a numbered Sphinx figure
named ``<name>`` (so ``{numref}`<name>``` works) with the caption under it and
the alt text on the image. Caption and alt text are written in the figure modules, from
the same model objects the drawing uses, so they always agree with it.
"""

from __future__ import annotations

import base64
import io
from dataclasses import dataclass

from matplotlib.figure import Figure

from .style import book_style

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
