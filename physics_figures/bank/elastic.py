"""Elastic and inelastic collisions: relative speeds, kinetic energy kept or lost."""

from __future__ import annotations

from ..variants import Template

TEMPLATES: tuple[Template, ...] = ()
