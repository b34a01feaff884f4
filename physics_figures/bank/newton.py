"""Newton's laws, weight and the third law: F = ma, lifts, towing, action-reaction pairs."""

from __future__ import annotations

from ..variants import Template

TEMPLATES: tuple[Template, ...] = ()
