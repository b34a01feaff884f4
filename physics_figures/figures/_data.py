"""A figure's data table and the words around it, built from what the figure plots.

Each figure module passes the same arrays and points its plot function draws (the model's
own), so the "Data" table beside a figure prints what the figure shows: a curve is read at
round values of its x-axis along the drawn line (``np.interp``, what a ruler gives, not a
second model run), and its marked points are listed as they are drawn.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from typing import NamedTuple

import numpy as np

from ..notation import MINUS, format_number, join_units
from .book_figure import FigureData

#: A curve is read at about this many round values of its x-axis (plus its marked points):
#: enough to follow its shape, few enough to read.
READINGS_PER_CURVE = 12


class Column(NamedTuple):
    """One column of a data table: its heading (with the unit), its values, and how they
    are written: ``sig_figs`` or ``decimals``; a value that is a str is written as it is."""

    heading: str
    values: Sequence[float | str | None]
    sig_figs: int | None = None
    decimals: int | None = None

    def cell(self, value: float | str | None) -> str:
        if value is None:
            return "–"  # noqa: RUF001 (an en dash: no value in this row)
        if isinstance(value, str):
            return value
        return format_number(float(value), self.sig_figs, decimals=self.decimals)


def figure_data(caption: str, columns: Sequence[Column]) -> FigureData:
    """The table of ``columns`` (all the same length) under ``caption``."""
    lengths = {len(c.values) for c in columns}
    if len(lengths) != 1:
        raise ValueError(f"columns have {sorted(lengths)} values; every column needs the same number")
    rows = tuple(
        tuple(c.cell(c.values[i]) for c in columns) for i in range(lengths.pop())
    )
    return FigureData(caption, tuple(c.heading for c in columns), rows)


def round_steps(low: float, high: float, *, count: int = READINGS_PER_CURVE) -> np.ndarray:
    """At least ``count`` round values from ``low`` to ``high`` (steps of 1, 2 or 5 times a power of ten)."""
    if not high > low:
        raise ValueError(f"high = {high!r} must be more than low = {low!r} to place readings")
    rough = (high - low) / count
    power = 10.0 ** np.floor(np.log10(rough))
    step = max(m * power for m in (1, 2, 5) if m * power <= rough)
    start = np.ceil(low / step - 1e-9) * step
    return np.round(np.arange(start, high + step * 1e-9, step), 10)


def read_along(xs: Sequence[float], ys: Sequence[float], at: Sequence[float]) -> np.ndarray:
    """The drawn line through (xs, ys) read at ``at``: straight between its samples, as drawn."""
    return np.interp(np.asarray(at, dtype=float), np.asarray(xs, dtype=float), np.asarray(ys, dtype=float))


def curve_rows(
    xs: Sequence[float], ys: Sequence[float], marked: dict[str, tuple[float, float]] | None = None,
    *, count: int = READINGS_PER_CURVE,
) -> tuple[list[str], list[float], list[float]]:
    """(labels, x, y) of a curve: its readings at round x, and its marked points (labelled)
    in their place, in order of x."""
    marked = marked or {}
    at = round_steps(float(np.min(xs)), float(np.max(xs)), count=count)
    # a reading where a marked point already sits would print the same row twice
    at = [x for x in at if not any(np.isclose(x, mx) for mx, _ in marked.values())]
    rows = [("", float(x), float(y)) for x, y in zip(at, read_along(xs, ys, at), strict=True)]
    rows += [(label, float(x), float(y)) for label, (x, y) in marked.items()]
    rows.sort(key=lambda row: (row[1], row[0] == ""))
    labels, x_values, y_values = (list(column) for column in zip(*rows, strict=True))
    return labels, x_values, y_values


def axis_words(name: str, low: float, high: float, unit: str) -> str:
    """An axis in words: "time t (s) from 0 to 60"."""
    return f"{name} ({unit}) from {format_number(low, 2)} to {format_number(high, 2)}"


def axes_sentence(horizontal: str, vertical: str) -> str:
    """The opening of a graph's description: which quantity is on which axis."""
    return f"The horizontal axis is {horizontal}; the vertical axis is {vertical}."


def description(*sentences: str) -> str:
    """A description as the page prints it: the true minus sign (alt text words write
    "-20"), and numbers joined to their units (no line break between them)."""
    text = " ".join(s.strip() for s in sentences if s.strip())
    return join_units(re.sub(r"(?<![\w.])-(?=\d)", MINUS, text))
