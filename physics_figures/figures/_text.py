"""Numbers and units written the way the notes write them (figures' labels, captions, alt text)."""

from __future__ import annotations

import math

from ..notation import DIGIT_GROUP_SEPARATOR, MINUS, format_number

#: Units as the notes print them (Unicode superscripts keep SVG text plain text).
MOMENTUM_UNIT = "kg m s⁻¹"
VELOCITY_UNIT = "m s⁻¹"
ACCELERATION_UNIT = "m s⁻²"
IMPULSE_UNIT = "N s"


def sig(value: float, figures: int = 2, *, group: str = " ", plus: bool = False) -> str:
    """``value`` to ``figures`` significant figures, as printed in the notes.

    Trailing zeros that are significant are kept (5.0, not 5); large numbers are
    grouped in threes from five digits (3000, 12 000); negative numbers get a true minus sign.
    ``group=""`` writes 12000 (for alt text, which screen readers read as a number).
    """
    if value == 0:
        return "0"
    exponent = math.floor(math.log10(abs(value)))
    decimals = max(figures - 1 - exponent, 0)
    rounded = round(value, figures - 1 - exponent)
    # the notes group digits only from five digits up: 3000 N but 12 000 kg m s⁻¹
    grouping = "," if abs(rounded) >= 10_000 else ""
    text = f"{abs(rounded):{grouping}.{decimals}f}".replace(",", group)
    if rounded < 0:
        return MINUS + text
    return ("+" if plus else "") + text


def plain(text: str) -> str:
    """Alt text reads units in plain characters: m s⁻¹ -> m/s, true minus -> hyphen-minus."""
    return (
        text.replace(MOMENTUM_UNIT, "kg m/s")
        .replace(VELOCITY_UNIT, "m/s")
        .replace(ACCELERATION_UNIT, "m/s²")
        .replace(MINUS, "-")
        .replace(DIGIT_GROUP_SEPARATOR, "")  # 12000 is read aloud as one number
    )


def seconds(time: float) -> str:
    """A time to 0.1 s, as the notes give the car's times (4.0 s, 10.0 s)."""
    return f"{format_number(time, decimals=1)} s"


def a_or_an(number_text: str) -> str:
    """The article before a number read aloud: an 80 kg, an 11 kg, an 18 kg; a 60 kg."""
    digits = number_text.split(".")[0].replace(DIGIT_GROUP_SEPARATOR, "").replace(" ", "")
    spoken_vowel = digits.startswith("8") or (len(digits) in (2, 5) and digits[:2] in ("11", "18"))
    return "an" if spoken_vowel else "a"
