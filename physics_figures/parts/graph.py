# ruff: noqa: RUF002, RUF003  (typeset text: the times sign in readings written in powers of ten)

"""The graph part kind: a value read from the question's graph, right within half a small
square, and the graph itself. Its browser twin is the numeric marker
(question-kinds/numeric.js), which reads a part's tolerance."""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field
from typing import ClassVar

from ..notation import (
    LARGEST_PLAIN,
    SMALLEST_PLAIN,
    axis_power,
    format_number,
    power_text,
    round_number,
    unit_text,
)
from .common import _require
from .numeric import Part


def reading_places(tolerance: float) -> int:
    """Decimal places a reading is written to: those of a small square, twice the tolerance
    (0.5 -> 1, 0.05 -> 2, 20 -> 0)."""
    division = 2 * tolerance
    for places in range(7):
        if math.isclose(division * 10**places, round(division * 10**places), abs_tol=1e-9):
            return places
    return 7


#: A reading written in powers of ten keeps at most this many figures, as the key's working does
#: ("1.12 × 10⁵", not the "1.12000 × 10⁵" that the places of a small square of 10 000 would give).
MOST_POWER_FIGURES = 3


def reading_sig_figs(value: float, tolerance: float) -> int:
    """Significant figures a reading of ``value`` is written to, right within ``tolerance``:
    down to the places of a small square as a plain number (12.5 on squares of 0.5, 240 on
    20s); in powers of ten, down to the place of the tolerance's first figure, at most
    MOST_POWER_FIGURES (1.12 × 10⁵ on squares of 10 000)."""
    _require(tolerance > 0, "tolerance", tolerance, "must be positive: half a small square")
    if value == 0:
        return 1
    lead = math.floor(math.log10(abs(value)))
    plain = max(1, lead + 1 + reading_places(tolerance))
    if SMALLEST_PLAIN <= abs(round_number(value, plain)) < LARGEST_PLAIN:
        return plain
    return max(1, min(MOST_POWER_FIGURES, lead - math.floor(math.log10(tolerance)) + 1))


def format_reading(value: float, tolerance: float) -> str:
    """A value read from a graph as the key writes it: 12.5, 240, 0.50, 1.12 × 10⁵."""
    places = reading_places(tolerance)
    if value == 0 or SMALLEST_PLAIN <= abs(round_number(value, decimals=places)) < LARGEST_PLAIN:
        return format_number(value, decimals=places)
    return format_number(value, reading_sig_figs(value, tolerance))


@dataclass(frozen=True)
class GraphPart(Part):
    """A value read from the question's graph. It is right within ``tolerance`` (SI) either
    way, half the smallest grid division along the axis read, as the question states; a
    reading needs no particular number of significant figures."""

    tolerance: float = field(default=0.0, kw_only=True)
    min_sig_figs: int = field(default=1, kw_only=True)
    kind: ClassVar[str] = "graph"
    reads_graph: ClassVar[bool] = True
    moodle_how: ClassVar[str] = " (read from the graph)"

    def __post_init__(self):
        _require(self.tolerance > 0, "tolerance", self.tolerance,
                 "must be positive: half the smallest grid division of the axis read")
        # the key prints to the places of a small square (12.5 on squares of 0.5, 240 on 20s),
        # and in powers of ten to at most 3 figures (1.12 × 10⁵)
        object.__setattr__(self, "shown_sig_figs", reading_sig_figs(self.value, self.tolerance))
        super().__post_init__()

    @property
    def band(self) -> tuple[float, float]:
        """The readings the marker takes as right."""
        return (self.value - self.tolerance, self.value + self.tolerance)

    def band_text(self) -> str:
        """The band as the key states it: "81 500 to 86 500"; on an axis labelled in a power of
        ten, in the axis's own numbers with the power ("1.305 to 1.355, in 10⁵ N s"), never a
        number of more than 3 figures times a power of ten."""
        low, high = self.band
        power = axis_power(max(abs(low), abs(high)), 2 * self.tolerance)
        if not power:
            places = reading_places(self.tolerance)
            return f"{format_number(low, decimals=places)} to {format_number(high, decimals=places)}"
        scale = 10.0**power
        places = next(p for p in range(12) if all(
            math.isclose(end / scale, float(round_number(end / scale, decimals=p)), rel_tol=1e-9) for end in (low, high)))
        return (f"{format_number(low / scale, decimals=places)} to {format_number(high / scale, decimals=places)}, "
                f"in {power_text(power)} {unit_text(self.unit)}")

    def _accepted(self, value: float) -> bool:
        low, high = self.band
        return low - 1e-9 * abs(self.tolerance) <= value <= high + 1e-9 * abs(self.tolerance)

    def _check_mistakes_differ(self) -> None:
        """Each named mistake must lie outside the key's band and outside each other's."""
        plain = [m for m in self.mistakes if m.unit is None and m.direction is None]
        for mistake in plain:
            _require(not self._accepted(self._size(mistake.value)), "mistakes", mistake.name,
                     f"gives {mistake.value!r}, within the reading's tolerance {self.tolerance!r} "
                     f"of the key {self.value!r}: the marker could not tell them apart")
        for first, second in itertools.combinations(plain, 2):
            _require(abs(first.value - second.value) > 2 * self.tolerance, "mistakes", second.name,
                     f"is within two tolerances of '{first.name}': the marker could not tell them apart")

    def browser_data(self, part_id: str) -> dict:
        return {**super().browser_data(part_id), "tolerance": self.tolerance}

    def working_cm(self, marks: int, sheet) -> float:
        """A reading needs no working: a little room above its answer line."""
        return 0.6


#: A value axis has at most this many small squares (Graph allows 60), labelled every 5 or 10.
_MOST_SQUARES = 50


def value_axis(high: float, low: float = 0.0) -> tuple[float, float, float]:
    """(value_min, value_max, value_division) of a graph's value axis that holds ``low`` to
    ``high`` with a little room above (and below a negative ``low``): small squares of 1, 2 or
    5 x 10^n, at most 50 of them, the ends on a labelled line (every 5 squares). So a
    cyclist's 900 N s gets 0 to 1000 in squares of 20, a lorry's 60 000 N s 0 to 70 000 in
    squares of 2000: the axis grows with the momentum instead of stopping at 1000 N s."""
    _require(math.isfinite(high) and math.isfinite(low) and high > 0 and low <= 0, "high", (low, high),
             "must be a positive top above a low of 0 or below")
    room = 0.05 * (high - low)
    top, bottom = high + room, (low - room if low < 0 else 0.0)
    wanted = (top - bottom) / _MOST_SQUARES
    power = 10.0 ** math.floor(math.log10(wanted))
    division = next(step * power for step in (1, 2, 5, 10) if step * power >= wanted * (1 - 1e-12))
    label = 5 * division
    value_max = math.ceil(top / label - 1e-9) * label
    value_min = -math.ceil(-bottom / label - 1e-9) * label if bottom < 0 else 0.0
    while (value_max - value_min) / division > 60:  # rounding both ends out can pass Graph's limit
        division *= 2
    return float(value_min), float(value_max), float(division)
