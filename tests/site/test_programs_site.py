"""After make test, every program outside the venv that the table names is installed (the table
itself is checked in tests/no_site/test_programs.py)."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from support.programs import ENSURE, table

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.site
def test_after_make_test_every_program_in_the_table_is_here():
    absent = [p for p in table() if not (Path(p).exists() if p.startswith("/") else shutil.which(p))]
    assert not absent, f"`make test` should have installed {absent}: see {ENSURE.relative_to(ROOT)}"
