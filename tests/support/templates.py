"""The bank's templates as the tests take them, and answers written as a student writes them."""

from __future__ import annotations

from physics_figures import bank
from physics_figures import questions as q
from physics_figures.notation import format_number, plain_number


def printed(key: str) -> q.Question:
    """A template's printed version (variant 0): what a first visit and the PDFs show."""
    return bank.TEMPLATES[key].variant(0)


def numbered_variants(key: str) -> list[tuple[int, dict]]:
    """A template's variants with their indices."""
    return list(enumerate(bank.TEMPLATES[key].variants))


def typed(value: float, sig_figs: int = 3) -> str:
    """A value as a student types it: ASCII digits, no grouping, to `sig_figs` figures."""
    return plain_number(format_number(value, sig_figs))


def sig3(x: float) -> str:
    """An answer written to 3 s.f., trailing zeros kept ("8.00", "133")."""
    return f"{x:#.3g}".rstrip(".")
