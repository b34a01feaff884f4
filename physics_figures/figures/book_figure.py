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
* ``text/markdown``: a MyST comment ``% physics-figure <name>``, the caption, then (as an
  HTML block) the "Data" disclosure: the longer description and the plotted values as a
  table (:class:`FigureData`), for readers who cannot see the drawing (issue 28).

``book/_ext/figure_captions.py`` turns that output into a numbered Sphinx figure
named ``<name>`` (so ``{numref}`<name>``` works) with the caption under it and
the alt text on the image. Caption and alt text are written in the figure modules, from
the same model objects the drawing uses, so they always agree with it.
"""

from __future__ import annotations

import base64
import html
import io
from dataclasses import dataclass

from matplotlib.figure import Figure

from ..notation import join_units
from .style import book_style

#: First word of the MyST comment that marks a figure output for the Sphinx extension.
FIGURE_MARKER = "physics-figure"


@dataclass(frozen=True)
class FigureData:
    """The values a figure plots, as the table of its "Data" disclosure.

    ``headings`` carry the units ("time t / s"); ``rows`` are the cells already written
    the way the book writes numbers (``figures._data`` builds them from the very arrays
    and points the drawing plots, so the table and the figure cannot disagree).
    """

    caption: str
    headings: tuple[str, ...]
    rows: tuple[tuple[str, ...], ...]

    def __post_init__(self) -> None:
        for row in self.rows:
            if len(row) != len(self.headings):
                raise ValueError(
                    f"row {row!r} has {len(row)} cells; a row needs one per heading "
                    f"({len(self.headings)}: {self.headings!r})"
                )

    def html(self, caption_id: str) -> str:
        """The table as HTML on one line (a blank line would end Markdown's HTML block), in
        a box that scrolls sideways on a narrow phone instead of the page: a region named by
        the caption, focusable so that a keyboard can scroll it."""
        head = "".join(f'<th scope="col">{html.escape(h)}</th>' for h in self.headings)
        body = "".join(
            "<tr>" + "".join(f"<td>{html.escape(join_units(cell))}</td>" for cell in row) + "</tr>"
            for row in self.rows
        )
        return (
            f'<div class="figure-data-scroll" role="region" tabindex="0" aria-labelledby="{caption_id}">'
            f'<table class="figure-data-table"><caption id="{caption_id}">'
            f"{html.escape(join_units(self.caption))}</caption>"
            f"<thead><tr>{head}</tr></thead><tbody>{body}</tbody></table></div>"
        )


def description_id(name: str) -> str:
    """The id of a figure's description paragraph, which its image's aria-describedby names."""
    return f"{name}-description"


@dataclass(frozen=True)
class BookFigure:
    """A finished figure with its label, caption (MyST), alt text, and, for the book's
    figures, its longer description and its data (the "Data" disclosure beside it)."""

    name: str
    figure: Figure
    caption: str
    alt: str
    description: str = ""
    data: FigureData | None = None

    def data_html(self) -> str:
        """The description, then the "Data" disclosure: the description again and the table.

        The image's aria-describedby names the first paragraph, which is ``hidden``: a
        browser reads a hidden element it is pointed to, but not one inside a closed
        <details> (Chromium leaves that out of the description), and a screen reader
        reading on does not meet it twice. Sighted readers find it in the disclosure.
        """
        if self.data is None or not self.description:
            return ""
        words = html.escape(self.description)
        return (
            f'<p class="figure-description" id="{description_id(self.name)}" hidden>{words}</p>'
            '<details class="figure-data"><summary>Data and description</summary>'
            f'<p>{words}</p>{self.data.html(f"{self.name}-data")}</details>'
        )

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
            "text/markdown": f"% {FIGURE_MARKER} {self.name}\n\n{self.caption}\n\n{self.data_html()}\n",
            "text/plain": self.alt,
        }

    def __repr__(self) -> str:
        return f"BookFigure({self.name!r}: {self.alt})"
