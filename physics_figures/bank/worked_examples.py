"""The try-first parts of the worked examples: the printed numbers only (no New numbers),
and not counted among the bank's templates."""

from __future__ import annotations

from ..variants import Template

TEMPLATES: tuple[Template, ...] = ()
