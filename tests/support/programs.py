"""The table of the programs outside the venv (scripts/debian-programs.txt) and the script that
installs them: read by tests/no_site/test_programs.py and, after make test, tests/site/test_programs_site.py."""

from __future__ import annotations

from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
TABLE = ROOT / "scripts" / "debian-programs.txt"
ENSURE = ROOT / "scripts" / "ensure-debian-packages"


def table() -> dict[str, tuple[str, list[str]]]:
    """program -> (make step, Debian packages)."""
    rows = {}
    for line in TABLE.read_text().splitlines():
        if line.strip() and not line.startswith("#"):
            program, step, *packages = line.split()
            rows[program] = (step, packages)
    return rows
