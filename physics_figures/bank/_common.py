# ruff: noqa: RUF001, RUF002  (typeset text: true minus, times)
"""What the bank's modules share: the units answers are typed in, and how working prints a number."""

from __future__ import annotations

import math

from ..notation import format_number, round_number
from ..questions import reading_places

#: Every usual form of a unit, for the marker's messages.
N_S = "N s or kg m s^-1"
M_S = "m s^-1 (m/s)"
M_S2 = "m s^-2 (m/s^2)"
#: Units in the text format (physics_figures.textformat).
PER_S = "m s<sup>−1</sup>"
PER_S2 = "m s<sup>−2</sup>"

#: A value of the working that is exact within this many significant figures prints in full.
_EXACT_UP_TO = 6


def w(value: float) -> str:
    """An intermediate value as a mark scheme writes it: exact in full when it is exact to
    a few figures (0.16 × 25 = 4.0, 900 × 12 = 10 800, 10.125 J), else to 3 s.f. (1.29), so
    the working never rounds part-way to 2 s.f."""
    for sig_figs in range(2, _EXACT_UP_TO + 1):
        if math.isclose(float(round_number(value, sig_figs)), value, rel_tol=1e-9, abs_tol=1e-12):
            return format_number(value, sig_figs)
    return format_number(value, 3)


def reading_rule(tolerance: float, unit: str) -> str:
    """What a graph question says about its readings (text format): the marker accepts half
    a small square either way."""
    exact = next(format_number(tolerance, sig_figs) for sig_figs in range(1, _EXACT_UP_TO + 1)
                 if math.isclose(float(round_number(tolerance, sig_figs)), tolerance, rel_tol=1e-9))
    return f"Readings from the graph are marked right to within half a small square (± {exact} {unit})."


def reading(value: float, tolerance: float) -> str:
    """A value read from a graph, written to the places of its small squares (12.5, 240)."""
    return format_number(value, decimals=reading_places(tolerance))
