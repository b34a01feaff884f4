"""The book's colours, read from ``tokens.json`` beside this file: the one place a colour
is written. The site's CSS (book/_ext/design_tokens.py), the figures
(physics_figures.figures.style), the PDF book's LaTeX and the web app manifest all read it.

A role is ``section.name`` ("figure.blue", "site.q-right"); a role with light and dark
values gives the one asked for; a value that names another role is that role's colour.
"""

from __future__ import annotations

import functools
import json
import re
from pathlib import Path

TOKENS = Path(__file__).with_name("tokens.json")
MODES = ("light", "dark")
_ROLE = re.compile(r"[a-z]+\.[a-z-]+")


@functools.cache
def tokens() -> dict:
    """The whole tokens file."""
    return json.loads(TOKENS.read_text(encoding="utf-8"))


def names(section: str) -> list[str]:
    """The roles of one section ("site", "figure", ...), in the file's order."""
    return [name for name in tokens()[section] if name != "about"]


def colour(role: str, mode: str = "light") -> str:
    """The colour of `role` (``section.name``) in `mode` ("light" or "dark")."""
    section, name = role.split(".", 1)
    value = tokens()[section][name]
    if isinstance(value, dict):
        value = value[mode]
    return colour(value, mode) if _ROLE.fullmatch(value) else value
