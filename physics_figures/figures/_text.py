"""Numbers and units written the way the notes write them (figures' labels, captions, alt text)."""

from __future__ import annotations

from ..notation import DIGIT_GROUP_SEPARATOR, MINUS, format_number

#: Units as the notes print them (Unicode superscripts keep SVG text plain text).
MOMENTUM_UNIT = "kg m s⁻¹"
VELOCITY_UNIT = "m s⁻¹"
ACCELERATION_UNIT = "m s⁻²"
IMPULSE_UNIT = "N s"


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
