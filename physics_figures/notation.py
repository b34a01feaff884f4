# ruff: noqa: RUF002, RUF003  (typeset text: true minus, times sign, narrow no-break space)
"""How the book writes a number: the one place that rounds and prints.

Every figure label, glued value, question key and answer key goes through
``format_number``; the browser's twin is ``book/_ext/notation/static/notation.js``.
``tests/notation_cases.json`` is run against both, so they cannot drift.

The rules (Cambridge mark schemes and the SI brochure):

* rounding is half away from zero, from the shortest decimal form of the float,
  as a calculator does: 0.125 -> 0.13, 2.85 -> 2.9, -0.125 -> -0.13;
* trailing zeros that are significant stay (5.0, 9.40);
* a true minus sign (U+2212), never -0; an exact zero is 0 at any number of
  significant figures (a value that rounds to zero keeps its places: 0.00);
* the whole part of a number of five digits or more is grouped in threes with a
  narrow no-break space (U+202F): 1500, 30 000;
* x 10^n when the rounded size is 10^5 or more, or below 10^-3: 1.5 × 10⁵, 2.0 × 10⁻⁴;
  a graph's axis never puts it on a label: the axis's label carries the power instead
  (``axis_power``: "p / 10⁵ N s", labels 0, 0.5, 1.0);
* a number is joined to its unit, and a unit's symbols to each other, with a no-break
  space (U+00A0), so "50 m s⁻¹" never breaks across lines: ``format_quantity`` and
  ``unit_text`` write them so, and ``join_units`` mends prose that was typed by hand
  (the book's docutils transform, book/_ext/notation, runs it over every page).
"""

from __future__ import annotations

import math
import re
from decimal import ROUND_HALF_UP, Decimal, localcontext

MINUS = "\N{MINUS SIGN}"
#: Groups the digits of 10 000 and above without letting a line break split them.
DIGIT_GROUP_SEPARATOR = "\N{NARROW NO-BREAK SPACE}"
#: Joins a number to its unit and a unit's symbols to each other (CLARIFICATIONS, Reading).
UNIT_SPACE = "\N{NO-BREAK SPACE}"
TIMES = "\N{MULTIPLICATION SIGN}"
#: Sizes outside [SMALLEST_PLAIN, LARGEST_PLAIN) are written as a power of ten.
SMALLEST_PLAIN = Decimal("0.001")
LARGEST_PLAIN = Decimal(100_000)

_SUPERSCRIPTS = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def round_number(value: float, sig_figs: int | None = None, *, decimals: int | None = None) -> Decimal:
    """``value`` rounded half away from zero to ``sig_figs`` significant figures or to
    ``decimals`` places (give exactly one), keeping significant trailing zeros."""
    if (sig_figs is None) == (decimals is None):
        raise ValueError(f"give exactly one of sig_figs and decimals (got sig_figs={sig_figs!r}, "
                         f"decimals={decimals!r})")
    if sig_figs is not None and (not isinstance(sig_figs, int) or sig_figs < 1):
        raise ValueError(f"sig_figs must be a whole number of at least 1 (got sig_figs={sig_figs!r})")
    if decimals is not None and (not isinstance(decimals, int) or decimals < 0):
        raise ValueError(f"decimals must be a whole number, 0 or more (got decimals={decimals!r})")
    value = float(value)
    if not math.isfinite(value):
        raise ValueError(f"value must be a finite number (got value={value!r})")
    exact = Decimal(repr(value))  # the shortest decimal that is this float: 2.85, not 2.8499…
    if decimals is not None:
        return exact.quantize(Decimal(1).scaleb(-decimals), rounding=ROUND_HALF_UP)
    if exact == 0:  # an exact zero has no significant figures to show: 0
        return Decimal(0)
    with localcontext() as context:
        context.prec = sig_figs
        context.rounding = ROUND_HALF_UP  # Decimal's HALF_UP is half away from zero
        rounded = +exact  # may carry: 9.996 -> 10.0
    return rounded.quantize(Decimal(1).scaleb(rounded.adjusted() - sig_figs + 1))


def _group(whole: str) -> str:
    if len(whole) < 5:  # 1500 stays as it is; 30 000 is grouped
        return whole
    head = len(whole) % 3 or 3
    groups = [whole[:head]] + [whole[i:i + 3] for i in range(head, len(whole), 3)]
    return DIGIT_GROUP_SEPARATOR.join(groups)


def format_number(value: float, sig_figs: int | None = None, *, decimals: int | None = None,
                  plus: bool = False) -> str:
    """``value`` written as the book writes numbers, e.g. format_number(-30012, 2) -> "−30 000".

    Give sig_figs (significant figures) or decimals (decimal places). ``plus=True``
    writes "+" before a positive number (for labels of signed changes).
    """
    rounded = round_number(value, sig_figs, decimals=decimals)
    size = abs(rounded)
    if size != 0 and not SMALLEST_PLAIN <= size < LARGEST_PLAIN:
        exponent = size.adjusted()
        mantissa = format(size.scaleb(-exponent), "f")  # keeps the digits: 1.50 × 10⁵
        body = f"{mantissa} {TIMES} 10{str(exponent).translate(_SUPERSCRIPTS)}"
    else:
        whole, point, fraction = format(size, "f").partition(".")
        body = f"{_group(whole)}{point}{fraction}"
    if rounded < 0 and size != 0:
        return MINUS + body
    return ("+" if plus and size != 0 else "") + body


def axis_power(largest: float, step: float) -> int:
    """The power of ten an axis's numbers are written in, as Cambridge's own graphs write them:
    0 when its labels (up to ``largest`` in size, ``step`` apart) print as plain numbers; else
    the power of ``largest``'s first digit, so each label is a plain number and the axis's label
    carries the power ("p / 10⁵ N s", labels 0, 0.5, 1.0 …), never "× 10ⁿ" on a label."""
    for name, number in (("largest", largest), ("step", step)):
        if not (math.isfinite(number) and number > 0):
            raise ValueError(f"{name} must be a positive finite number (got {name}={number!r})")
    biggest = Decimal(repr(float(largest)))
    if biggest < LARGEST_PLAIN and Decimal(repr(float(step))) >= SMALLEST_PLAIN:
        return 0
    return biggest.adjusted()


def power_text(power: int) -> str:
    """10 to ``power`` as an axis's label writes it: 5 -> "10⁵", -3 -> "10⁻³"."""
    return "10" + str(power).translate(_SUPERSCRIPTS)


def tex_number(text: str) -> str:
    """A number from ``format_number`` for TeX maths: "−1.5 × 10⁵" -> "-1.5 \\times 10^{5}"."""
    text = text.replace(MINUS, "-").replace(DIGIT_GROUP_SEPARATOR, r"\,")
    power = re.search(rf" {TIMES} 10([⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)$", text)
    if power:
        exponent = power[1].translate(str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789"))
        text = text[:power.start()] + rf" \times 10^{{{exponent}}}"
    return text


def plain_number(text: str) -> str:
    """A number from ``format_number`` in plain ASCII (typed answers, alt text read aloud):
    "−30 000" -> "-30000", "1.5 × 10⁵" -> "1.5e5"."""
    text = text.replace(MINUS, "-").replace(DIGIT_GROUP_SEPARATOR, "")
    return re.sub(rf" {TIMES} 10([⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)$",
                  lambda m: "e" + m[1].translate(str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")), text)


#: Units written straight after the number, with no space: 30°, 5 %.
_UNSPACED = ("°", "%", "")


def unit_text(unit: str) -> str:
    """A unit as text, its symbols joined by no-break spaces and its powers raised:
    "m s^-1" -> "m\u00a0s⁻¹", "kg m s^-1" -> "kg\u00a0m\u00a0s⁻¹"."""
    unit = re.sub(r"\^(-?\d+)", lambda m: m.group(1).translate(_SUPERSCRIPTS), unit)
    return UNIT_SPACE.join(unit.split())


def format_quantity(value: float, sig_figs: int | None, unit: str, *, decimals: int | None = None,
                    plus: bool = False) -> str:
    """A value with its unit, never split by a line break: format_quantity(50, 2, "m s^-1")
    -> "50\u00a0m\u00a0s⁻¹"; format_quantity(30, 2, "°") -> "30°"."""
    number = format_number(value, sig_figs, decimals=decimals, plus=plus).replace(" ", UNIT_SPACE)
    written = unit_text(unit)
    return number + ("" if written in _UNSPACED else UNIT_SPACE) + written


#: The unit symbols that ``join_units`` knows in prose: every unit the questions use
#: (tests/no_site/test_notation.py checks that against the bank) and a few the notes add.
UNIT_SYMBOLS = ("kg", "g", "m", "km", "cm", "mm", "s", "ms", "h", "min", "N", "kN", "J", "kJ", "W", "kW",
                "Pa", "kPa", "K", "mol", "rad", "Hz")
_POWER = "(?:[⁻]?[⁰¹²³⁴⁵⁶⁷⁸⁹]+)?"
_SYMBOL = rf"(?:{'|'.join(sorted(UNIT_SYMBOLS, key=len, reverse=True))}){_POWER}(?![A-Za-z0-9])"
#: One or more unit symbols, each after a space or a slash: "kg m s⁻¹", "m/s".
_UNITS = rf"{_SYMBOL}(?:(?:[ \t\n\u00a0\u202f]+|/){_SYMBOL})*"
#: A number as prose writes it: 12 000, 12\u202f000, −0.25, 1.5 × 10⁵.
_NUMBER = (rf"(?<![\w.]){MINUS}?(?:\d{{1,3}}(?:[ \u202f]\d{{3}})+(?![\d.])|\d+(?:\.\d+)?)"
           rf"(?:[ \u00a0\u202f]?{TIMES}[ \u00a0\u202f]?10[⁻]?[⁰¹²³⁴⁵⁶⁷⁸⁹]+)?")
VALUE_WITH_UNIT = re.compile(rf"({_NUMBER})([ \t\n\u00a0]+)({_UNITS})")
#: A unit at the start of a text that follows a number in another node (a glued value).
LEADING_UNIT = re.compile(rf"^([ \t\n]*)({_UNITS})")


def _join_number(number: str) -> str:
    number = re.sub(r"(?<=\d) (?=\d{3})", DIGIT_GROUP_SEPARATOR, number)  # 12 000 -> 12\u202f000
    return number.replace(" ", UNIT_SPACE)  # around × 10ⁿ


def _join_unit_run(units: str) -> str:
    return re.sub(r"[ \t\n]+", UNIT_SPACE, units)


def join_units(text: str, *, after_number: bool = False) -> str:
    """``text`` with every number joined to its unit, and the unit's symbols to each other,
    by no-break spaces: "to 12 000 kg m s" -> "to 12\u202f000\u00a0kg\u00a0m\u00a0s".
    ``after_number``: the text follows a number written elsewhere (a glued value), so a unit
    at its very start is joined to it too: " N. This" -> "\u00a0N. This"."""
    text = VALUE_WITH_UNIT.sub(lambda m: _join_number(m[1]) + UNIT_SPACE + _join_unit_run(m[3]), text)
    if after_number:
        text = LEADING_UNIT.sub(lambda m: (UNIT_SPACE if m[1] else "") + _join_unit_run(m[2]), text)
    return text


#: A value of the working that is exact within this many significant figures prints in full.
WORKING_EXACT_UP_TO = 6


def working_number(value: float) -> str:
    """An intermediate value as a mark scheme writes it: exact in full when it is exact to
    a few figures (0.16 × 25 = 4.0, 900 × 12 = 10 800, 10.125 J), else to 3 s.f. (1.29), so
    the working never rounds part-way to 2 s.f."""
    for sig_figs in range(2, WORKING_EXACT_UP_TO + 1):
        if math.isclose(float(round_number(value, sig_figs)), value, rel_tol=1e-9, abs_tol=1e-12):
            return format_number(value, sig_figs)
    return format_number(value, 3)
