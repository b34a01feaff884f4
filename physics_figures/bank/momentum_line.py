"""Conservation of momentum in a line: collisions, sticking together, explosions and recoil."""

from __future__ import annotations

from ..variants import Template

TEMPLATES: tuple[Template, ...] = ()
