"""Definitions, units and the difference between mass and weight."""

from __future__ import annotations

from ..variants import Template

TEMPLATES: tuple[Template, ...] = ()
