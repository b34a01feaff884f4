
"""What every part kind shares: the constants of marking, the ids of parts, and the helpers
that write a number and a unit and refuse an impossible value."""

from __future__ import annotations

import re
from typing import ClassVar

from .. import marking
from ..notation import format_number

#: How a part treats direction: a size only, a signed value along a stated positive
#: direction, or a size plus a direction chosen from a list.
DIRECTION_MODES = ("none", "signed", "choice")
#: Cambridge 9702 accepts 2 or more significant figures unless a question says otherwise;
#: the key is trusted to 3 s.f., so an answer worked with intermediates rounded to 3 s.f.
#: still agrees with it (the rule table, marking_rules.json).
DEFAULT_MIN_SIG_FIGS = marking.rules()["sig_figs"]["min"]
DEFAULT_CHECK_SIG_FIGS = marking.rules()["sig_figs"]["check"]
MARK_CODES = ("C1", "M1", "A1", "B1", "")
#: What a part asks for. M1 (with its dependent A1) belongs only to the last three: a plain
#: calculation earns C1 for its steps and A1 for its answer.
ASKS = ("calculate", "show that", "explain", "state")
#: Rounding an intermediate value to these significant figures is "rounding part-way".
PART_WAY_SIG_FIGS = (2, 3)
#: The values of g students use instead of the data's 9.81 m s^-2.
G_TEN, G_NINE_EIGHT = 10.0, 9.8

_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


#: A question's parts are (a), (b), ...; an ecf formula names earlier answers by these ids.
PART_IDS = tuple("abcdefghij")


def number(value: float, sig_figs: int) -> str:
    """A value as the book writes it, e.g. number(686.7, 3) -> "687" (notation.format_number)."""
    return format_number(value, sig_figs)


def unit_text(unit: str) -> str:
    """A unit for plain text: "m s^-1" -> "m s⁻¹"."""
    return re.sub(r"\^(-?\d+)", lambda m: m.group(1).translate(_SUPERSCRIPT), unit)


def _require(ok: bool, name: str, value, rule: str) -> None:
    if not ok:
        raise ValueError(f"{name} {rule} (got {name}={value!r})")


class NoValue:
    """What a part that asks for no number (a choice, an explanation) answers when the marker,
    the sheets or Moodle ask it numeric questions: no value, no named mistakes of its own, no
    direction and nothing carried forward."""

    value: ClassVar[None] = None
    mistakes: ClassVar[tuple] = ()
    direction: ClassVar[str] = "none"
    ecf: ClassVar[None] = None
    ecf_methods: ClassVar[tuple] = ()
