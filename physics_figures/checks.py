"""The one check that a value given to the bank's code keeps its rule (templates, parts,
topics, worksheets): a ValueError naming the argument, the value and the rule. The models
check their numbers with models/_checks.py, which also names a unit and an index. Below every
layer that checks its data (parts, pictures), so that the data a figure draws need not import
the part kinds to refuse a bad value."""

from __future__ import annotations


def require(ok: bool, name: str, value, rule: str) -> None:
    """Raise ValueError("NAME RULE (got NAME=VALUE)") unless ok."""
    if not ok:
        raise ValueError(f"{name} {rule} (got {name}={value!r})")
