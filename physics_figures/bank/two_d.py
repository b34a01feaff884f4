"""Momentum in two dimensions: components and glancing collisions."""

from __future__ import annotations

from ..variants import Template

TEMPLATES: tuple[Template, ...] = ()
