"""How the book refuses an impossible value (the house rule): a ValueError that names the
argument, the value and the rule. Below every layer that checks its data (parts, pictures), so
that the data a figure draws need not import the part kinds to refuse a bad value."""

from __future__ import annotations


def require(ok: bool, name: str, value, rule: str) -> None:
    """Raise ValueError("NAME RULE (got NAME=VALUE)") unless ok."""
    if not ok:
        raise ValueError(f"{name} {rule} (got {name}={value!r})")
