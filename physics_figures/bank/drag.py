"""Drag and terminal velocity: the skydiver, falling through a fluid, resultant force and acceleration."""

from __future__ import annotations

from ..variants import Template

TEMPLATES: tuple[Template, ...] = ()
