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
* x 10^n when the rounded size is 10^5 or more, or below 10^-3: 1.5 × 10⁵, 2.0 × 10⁻⁴.
"""

from __future__ import annotations

import math
import re
from decimal import ROUND_HALF_UP, Decimal, localcontext

MINUS = "\N{MINUS SIGN}"
#: Groups the digits of 10 000 and above without letting a line break split them.
DIGIT_GROUP_SEPARATOR = "\N{NARROW NO-BREAK SPACE}"
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
