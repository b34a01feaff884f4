# ruff: noqa: RUF001, RUF002, RUF003  (typeset text: true minus, times)
"""What the bank's modules share: the units answers are typed in, and how working prints a number."""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Sequence

from ..notation import WORKING_EXACT_UP_TO as _EXACT_UP_TO
from ..notation import format_number, round_number
from ..notation import working_number as w  # noqa: F401 (the templates print their working with w)
from ..questions import DEFAULT_CHECK_SIG_FIGS, Mistake, format_reading

#: Every usual form of a unit, for the marker's messages.
N_S = "N s or kg m s^-1"
M_S = "m s^-1 (m/s)"
M_S2 = "m s^-2 (m/s^2)"
#: Units in the text format (physics_figures.textformat).
PER_S = "m s<sup>−1</sup>"
PER_S2 = "m s<sup>−2</sup>"



def stated_figures(value: float, least: int = 2, most: int = 4) -> int:
    """The significant figures a given is stated to: the fewest, from ``least``, that print it
    exactly (a paper's 0.247 kg is stated to 3, a drawn 0.65 kg to 2), at most ``most``. A given
    printed to fewer figures than it has would make the printed text give another answer."""
    for sig_figs in range(least, most + 1):
        if math.isclose(float(round_number(value, sig_figs)), value, rel_tol=1e-9, abs_tol=1e-12):
            return sig_figs
    return most


def one_of_each(key: float, mistakes: Sequence[Mistake], sig_figs: int = DEFAULT_CHECK_SIG_FIGS, *,
                signed: bool = False) -> tuple[Mistake, ...]:
    """The named mistakes that the marker can tell apart: a mistake whose value, to ``sig_figs``
    (by default the figures the marker tells them apart at, the rule table's check),
    is the key's or an earlier mistake's is dropped. Some givens make two routes meet (a shell at
    rest has no momentum before to forget), and a paper's numbers may be such givens. signed: a
    signed part compares the values with their signs."""
    size = (lambda value: value) if signed else abs
    kept, seen = [], {format_number(size(key), sig_figs)}
    for mistake in mistakes:
        if mistake.unit is None and mistake.direction is None:
            typed = format_number(size(mistake.value), sig_figs)
            if typed in seen:
                continue
            seen.add(typed)
        kept.append(mistake)
    return tuple(kept)


def reading_rule(tolerance: float, unit: str) -> str:
    """What a graph question says about its readings (text format): the marker accepts half
    a small square either way."""
    exact = next(format_number(tolerance, sig_figs) for sig_figs in range(1, _EXACT_UP_TO + 1)
                 if math.isclose(float(round_number(tolerance, sig_figs)), tolerance, rel_tol=1e-9))
    return f"Readings from the graph are marked right to within half a small square (± {exact} {unit})."


def reading(value: float, tolerance: float) -> str:
    """A value read from a graph, written to the places of its small squares (12.5, 240), and
    in powers of ten to at most 3 figures (1.12 × 10⁵)."""
    return format_reading(value, tolerance)


def _figures(value: float, sig_figs: int, in_full_up_to: int) -> tuple[str, float]:
    """value as the working prints it with sig_figs figures (in full when it is exact to at most
    in_full_up_to figures, as w() prints it), and the number that text stands for."""
    for exact in range(2, max(in_full_up_to, sig_figs) + 1):
        rounded = float(round_number(value, exact))
        if math.isclose(rounded, value, rel_tol=1e-9, abs_tol=1e-12):
            return format_number(value, exact), rounded
    return format_number(value, sig_figs), float(round_number(value, sig_figs))


#: A power of ten as notation.format_number prints it (10⁻⁴), read back.
_FROM_SUPERSCRIPTS = str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")


def _last_place(printed: str) -> float:
    """The place of a printed number's last digit: 0.01 for 42.25, 10 for 9970."""
    digits = re.sub(r"[^\d.]", "", printed)
    if "." in digits:
        return 10.0 ** -len(digits.split(".")[1])
    return 10.0 ** (len(digits) - len(digits.rstrip("0"))) if digits.strip("0") else 1.0


def enough_figures(values: Sequence[float], step: Callable[..., float], printed_result: str,
                   in_full_up_to: int = _EXACT_UP_TO) -> tuple[str, ...]:
    """The inputs of a working step, printed with the fewest figures that give its printed
    result: as w() prints them (3 s.f. unless exact in full), else with 4, 5, then 6 s.f.,
    until step(inputs as printed) rounds to printed_result at its last digit, as an examiner
    checks it. in_full_up_to=3 prints a value exact to 4 figures at 3 s.f. first (687 for 686.7),
    when the working carries an answer printed to 3 s.f."""
    mantissa, _, power = printed_result.partition("×")  # "1.75 × 10⁻⁴": the power scales both
    scale = 10.0 ** int(power.strip()[2:].translate(_FROM_SUPERSCRIPTS)) if power else 1.0
    place = _last_place(mantissa) * scale
    target = float(re.sub(r"[^\d.\-]", "", mantissa.replace("−", "-"))) * scale
    for sig_figs in range(3, _EXACT_UP_TO + 1):
        printed = [_figures(value, sig_figs, in_full_up_to) for value in values]
        got = step(*(number for _, number in printed))
        if min(abs(got - target), abs(abs(got) - abs(target))) <= place / 2 * (1 + 1e-9):
            return tuple(text for text, _ in printed)
    raise ValueError(f"no printing of {values!r} to {_EXACT_UP_TO} s.f. gives {printed_result!r}")


#: What the schemes credit in a wrong change in momentum of a ball that turns round: the
#: working shows a momentum as mass × speed, so it keeps the C1 though the change is wrong
#: (the speeds subtracted, or one momentum alone). Mistake.credited cites it.
MOMENTUM_WORKING_C1 = "9702/22/M/J/25 Q4(b)(i): C1 for p = mv or 0.25 × 3.6 or 0.25 × 5.2"
