"""The units a Moodle numerical question declares: each form of the part's unit that the book's
unit reader (book/_ext/questions/static/answer-reading.js) accepts in another prefix or spelling,
written without spaces, with Moodle's multiplier.

The forms come from the reader's own tables (its prefixes, base units, unprefixed units and unit
words, read through Node), not from a list of our own, and each is read back by the reader's
``parseUnit``: a form is kept only if the book reads it as the part's quantity at that scale.

* **Prefixes.** Each of the book's prefixes on the unit's first symbol (79.4 cm s⁻² for 0.794 m s⁻²;
  kN; g for kg; kN s), and the book's unprefixed units of the same kind whose size is a power of
  ten of it (t for kg, sec for s, deg for °).
* **Spellings.** Powers written ``^-2``, ``-2`` or ``⁻²``, with or without a slash (m/s²), and in
  words where every symbol has one ("metres per second squared", "newtons").
* **Without spaces.** Moodle deletes every space of a response before it matches a unit, so
  "cm s^-2" is stored as "cms^-2".

Left out: units whose size is not a power of ten of the part's (km/h, min, h, rad). Moodle compares
a response in the part's own unit, against bands set by significant figures in that unit: a right
value rounded in km/h can fall outside them, so Moodle would refuse answers the book accepts, and
a wider band would accept values the book refuses. A student who types them gets Moodle's "wrong
unit" outcome: strict, not lenient.
"""

from __future__ import annotations

import functools
import itertools
import json
import math
import re
import subprocess
from pathlib import Path

#: The book's unit reader, run under Node.
READER = Path(__file__).resolve().parents[2] / "book" / "_ext" / "questions" / "static" / "answer-reading.js"
_SCRIPT = """
const r = require(process.argv[1]); let s = '';
process.stdin.on('data', c => s += c).on('end', () => {
  const readings = JSON.parse(s).map(t => {
    const p = r.parseUnit(t);
    return p.ok && !p.empty ? p.readings.map(x => [x.scale, x.dims]) : [];
  });
  process.stdout.write(JSON.stringify({tables: r.tables, readings: readings}));
});
"""
_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")
_FACTOR = re.compile(r"([A-Za-zµμ°%]+)(?:\^(-?\d+))?")


def _reader(texts: list[str]) -> dict:
    """The reader's tables, and its readings [(scale, dims), ...] of each text."""
    try:
        done = subprocess.run(["node", "-e", _SCRIPT, str(READER)], input=json.dumps(texts),
                              capture_output=True, text=True, check=True)
    except (OSError, subprocess.CalledProcessError) as error:
        raise RuntimeError(f"the book's unit reader ({READER}) did not run under Node: {error}") from error
    return json.loads(done.stdout)


@functools.cache
def tables() -> dict:
    """The book's unit tables: {"base", "unprefixed", "words", "prefixes"} as answer-reading.js has them."""
    return _reader([])["tables"]


def symbols(unit: str) -> list[tuple[str, int]]:
    """A unit as the bank writes it, into its symbols and powers: "m s^-2" or "m/s^2" ->
    [("m", 1), ("s", -2)]."""
    top, _, bottom = unit.partition("/")
    out = []
    for sign, chunk in ((1, top), (-1, bottom)):
        for token in chunk.split():
            found = _FACTOR.fullmatch(token)
            if not found:
                raise ValueError(f"unit={unit!r}: cannot read {token!r} (write symbols with powers, as 'kg m s^-1')")
            out.append((found[1], sign * int(found[2] or 1)))
    if not out:
        raise ValueError(f"unit={unit!r}: no symbol in it")
    return out


def _scale(symbol: str) -> tuple[float, list[int]] | None:
    """A symbol's size in SI and its dimensions, by the book's tables (a prefix on a base unit)."""
    table = tables()
    for units in (table["base"], table["unprefixed"]):
        if symbol in units:
            return units[symbol][0], units[symbol][1]
    prefix, base = symbol[:1], symbol[1:]
    if prefix in table["prefixes"] and base in table["base"]:
        return table["prefixes"][prefix] * table["base"][base][0], table["base"][base][1]
    return None


def scale(factors: list[tuple[str, int]]) -> float:
    """The size of a unit in SI, by the book's tables."""
    size = 1.0
    for symbol, power in factors:
        found = _scale(symbol)
        if found is None:
            raise ValueError(f"unit symbol={symbol!r} is not one the book reads (answer-reading.js)")
        size *= found[0] ** power
    return size


def _decade(ratio: float) -> bool:
    return ratio > 0 and abs(math.log10(ratio) - round(math.log10(ratio))) < 1e-9


def _sizes(factors: list[tuple[str, int]]) -> list[list[tuple[str, int]]]:
    """The unit itself, then its first symbol in each of the book's prefixes, then the book's
    unprefixed units of the same kind a power of ten of it (t for kg, sec for s, deg for °)."""
    table = tables()
    (first, power), rest = factors[0], factors[1:]
    size, dims = _scale(first) or (None, None)
    if size is None or power <= 0:
        return [factors]
    base = first if first in table["base"] else first[1:] if first[1:] in table["base"] else None
    out = [factors]
    if base is not None:
        out += [[(prefix + base, power), *rest] for prefix in ["", *table["prefixes"]]]
    out += [[(other, power), *rest] for other, (other_size, other_dims) in table["unprefixed"].items()
            if other_dims == dims and _decade(other_size / size)]
    return out


def _power(text: str, power: int, style: str) -> str:
    if power == 1:
        return text
    return text + {"caret": f"^{power}", "bare": str(power), "super": str(power).translate(_SUPERSCRIPT)}[style]


def _spellings(factors: list[tuple[str, int]]) -> list[str]:
    """How students type the unit (with spaces): "m s^-2", "m s-2", "m s⁻²", "m/s^2", "m/s2", "m/s²"."""
    top = [(s, p) for s, p in factors if p > 0]
    bottom = [(s, -p) for s, p in factors if p < 0]
    out = []
    for style in ("caret", "bare", "super"):
        out.append(" ".join(_power(s, p, style) for s, p in factors))
    if top and bottom:
        for style in ("caret", "bare", "super"):
            under = " ".join(_power(s, p, style) for s, p in bottom)
            out.append(" ".join(_power(s, p, style) for s, p in top) + "/" + (under if len(bottom) == 1 else f"({under})"))
    return out


def _words(factors: list[tuple[str, int]]) -> list[str]:
    """The unit in the book's unit words ("newton seconds", "metres per second squared"), where
    every symbol has a word and no power but a denominator's square."""
    names: dict[str, list[str]] = {}
    for word, symbol in tables()["words"].items():
        names.setdefault(symbol, []).append(word)
    if any(symbol not in names or power not in (1, -1, -2) for symbol, power in factors):
        return []
    top = [names[s] for s, p in factors if p > 0]  # "kilogram metres", not "kilograms metres"
    top = [[w for w in words if not w.endswith("s")] for words in top[:-1]] + top[-1:]
    bottom = [[f"per {w}" + (" squared" if p == -2 else "") for w in names[s] if not w.endswith("s")]
              for s, p in factors if p < 0]
    return [" ".join(words) for words in itertools.product(*top, *bottom)] if top else []


@functools.cache
def forms(unit: str, also: str = "") -> tuple[tuple[str, str, float], ...]:
    """(typed, stored, multiplier) of each form the book accepts of the part's unit: typed as a
    student types it, stored without spaces as Moodle matches it, and the value in that form = the
    value in the part's unit x multiplier. The unit itself first, in its slash form when it has a
    negative power (Moodle shows the first unit after its right answer). ``also``: the part's other
    ways of writing the unit ("N s or kg m s^-1", "m s^-1 (m/s)")."""
    own = symbols(unit)
    units = [own] + [symbols(chunk.strip()) for chunk in also.replace("(", " or ").replace(")", "").split(" or ")
                     if chunk.strip() and _readable(chunk.strip())]
    candidates = []
    for factors in units:
        for size in _sizes(factors):
            candidates += [(typed, scale(own) / scale(size)) for typed in _spellings(size) + _words(size)]
    spelt = _spellings(own)
    candidates.insert(0, (spelt[-1] if "/" in spelt[-1] else spelt[0], 1.0))
    found = _reader([unit] + [typed for typed, _ in candidates])["readings"]
    expected, readings = found[0][0][1], found[1:]
    out, stored = [], set()
    for (typed, multiplier), found in zip(candidates, readings, strict=True):
        name = typed.replace(" ", "")
        read = [s for s, dims in found if dims == expected and math.isclose(scale(own) / s, multiplier, rel_tol=1e-9)]
        if name in stored or not read:
            continue  # another form's spelling, or not what the book reads it as
        stored.add(name)
        out.append((typed, name, multiplier))
    return tuple(out)


def _readable(chunk: str) -> bool:
    try:
        symbols(chunk)
    except ValueError:
        return False
    return all(_scale(s) is not None for s, _ in symbols(chunk))
