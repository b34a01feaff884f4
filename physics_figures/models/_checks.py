"""Input checks shared by every model, so that every message has the same shape:

    ValueError: mass must be positive (got mass=-2.0 kg)

The message names the argument, gives the value (with its SI unit) and states the rule.
Each check returns the value as a float (scalar input) or a float ndarray (array input).
"""

from collections.abc import Sequence

import numpy as np


def _shown(name: str, value: float, unit: str) -> str:
    text = f"{name}={float(value)!r}"
    return f"{text} {unit}" if unit else text


def fail(name: str, value, rule: str, *, unit: str = "", index: int | None = None):
    """Raise the uniform ValueError: '<name> <rule> (got <name>=<value> <unit>)'."""
    where = "" if index is None else f" at index {index}"
    raise ValueError(f"{name} {rule} (got {_shown(name, value, unit)}{where})")


def number(name: str, value, *, unit: str = ""):
    """A finite real number, or an array of them (NaN and infinity are refused).

    Something that is not a number at all (a string, None) raises TypeError.
    """
    array = None if isinstance(value, str | bytes) else np.asarray(value)
    if array is None or array.dtype.kind not in "biuf":
        raise TypeError(f"{name} must be a number (got {name}={value!r})")
    array = array.astype(float)
    bad = ~np.isfinite(array)
    if bad.any():
        if array.ndim == 0:
            fail(name, array, "must be a finite number", unit=unit)
        first = int(np.flatnonzero(bad)[0])
        fail(name, array.flat[first], "must be a finite number", unit=unit, index=first)
    return float(array) if array.ndim == 0 else array


def require(name, value, ok, rule: str, *, unit: str = ""):
    """Return value if ok holds everywhere, else fail at the first element that breaks it."""
    ok = np.asarray(ok)
    if ok.all():
        return value
    if np.ndim(value) == 0:
        fail(name, value, rule, unit=unit)
    first = int(np.flatnonzero(~ok)[0])
    fail(name, np.asarray(value).flat[first], rule, unit=unit, index=first)
    return value  # pragma: no cover (fail always raises)


def positive(name: str, value, *, unit: str = ""):
    """A finite number > 0 (masses, durations, drag constants, densities...)."""
    value = number(name, value, unit=unit)
    return require(name, value, value > 0, "must be positive", unit=unit)


def non_negative(name: str, value, *, unit: str = ""):
    """A finite number >= 0 (times, speeds, sizes of momenta...)."""
    value = number(name, value, unit=unit)
    return require(name, value, value >= 0, "must not be negative", unit=unit)


def nonzero(name: str, value, *, unit: str = ""):
    """A finite number other than zero (a divisor)."""
    value = number(name, value, unit=unit)
    return require(name, value, value != 0, "must not be zero", unit=unit)


def between(name: str, value, low: float, high: float, *, unit: str = "", why: str = ""):
    """A finite number with low <= value <= high; `why` explains the rule to the reader."""
    value = number(name, value, unit=unit)
    rule = f"must be between {low:g} and {high:g}{unit and ' ' + unit}"
    if why:
        rule += f" ({why})"
    return require(name, value, (value >= low) & (value <= high), rule, unit=unit)


def sequence(name: str, values, *, unit: str = "", minimum_length: int = 1) -> np.ndarray:
    """A one-dimensional list of finite numbers with at least `minimum_length` entries."""
    if isinstance(values, str | bytes) or np.ndim(values) != 1:
        raise TypeError(f"{name} must be a list of numbers (got {name}={values!r})")
    array = number(name, values, unit=unit)
    if array.size < minimum_length:
        raise ValueError(
            f"{name} must have at least {minimum_length} entries (got {array.size}: {name}={values!r})"
        )
    return array


def same_length(**named: Sequence) -> None:
    """All the given sequences have the same number of entries."""
    lengths = {name: len(values) for name, values in named.items()}
    if len(set(lengths.values())) > 1:
        shown = ", ".join(f"len({name})={length}" for name, length in lengths.items())
        raise ValueError(f"{' and '.join(lengths)} must have the same length (got {shown})")


def strictly_increasing(name: str, values: np.ndarray, *, unit: str = "") -> np.ndarray:
    """Each entry larger than the one before it."""
    steps = np.diff(values)
    if (steps <= 0).any():
        i = int(np.flatnonzero(steps <= 0)[0]) + 1
        fail(
            name, values[i], f"must be strictly increasing (entry {i} is not after "
            f"entry {i - 1}, {float(values[i - 1])!r}{unit and ' ' + unit})", unit=unit, index=i,
        )
    return values
