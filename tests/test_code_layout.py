"""Rooms a newcomer can read: no module of the book's extensions and no browser script of the
site is longer than MAX_LINES (a longer one holds more than one job: split it by job, as
book/_ext/questions and site_assets are)."""

from __future__ import annotations

from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
MAX_LINES = 500
MODULES = sorted((ROOT / "book" / "_ext").rglob("*.py")) + sorted((ROOT / "book" / "_latex").glob("*.py"))
SCRIPTS = sorted((ROOT / "book" / "_ext").glob("**/static/**/*.js")) + sorted((ROOT / "_static").glob("*.js"))


def test_the_rooms_are_found():
    assert len(MODULES) > 20 and len(SCRIPTS) > 15


@pytest.mark.parametrize("path", MODULES + SCRIPTS, ids=lambda p: str(p.relative_to(ROOT)))
def test_no_module_or_browser_script_is_longer_than_the_limit(path):
    lines = len(path.read_text(encoding="utf-8").splitlines())
    assert lines <= MAX_LINES, f"{path.relative_to(ROOT)} has {lines} lines (at most {MAX_LINES}): split it by job"
