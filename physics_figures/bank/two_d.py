# ruff: noqa: RUF001  (question text is typeset: true minus, times, Greek letters)
"""Momentum in two dimensions: components and glancing collisions."""

from __future__ import annotations

from ..variants import Template

TEMPLATES: tuple[Template, ...] = ()
