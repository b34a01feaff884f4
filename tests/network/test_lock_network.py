"""The lock, resolved again by pip-compile from PyPI (the offline checks of the lock are
tests/no_site/test_lock.py)."""

from __future__ import annotations

import difflib
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
LOCK = ROOT / "requirements.txt"


@pytest.mark.network
def test_pip_compile_writes_the_lock_as_it_is(tmp_path):
    """The real check: pip-compile, run as `make lock` runs it, from the lock as it stands (so it
    keeps the pins and only resolves), writes the same file. Differs when pyproject.toml changed
    and `make lock` was not run, or when requirements.txt was edited by hand."""
    fresh = tmp_path / "requirements.txt"
    fresh.write_text(LOCK.read_text())
    made = subprocess.run(["make", "--no-print-directory", "lock", f"LOCK_OUT={fresh}"], check=False, cwd=ROOT,
                          capture_output=True, text=True)
    assert made.returncode == 0, f"make lock failed:\n{made.stdout}\n{made.stderr}"

    def body(text: str) -> list[str]:  # the header names the output file
        return [line for line in text.splitlines() if "--output-file=" not in line]

    diff = list(difflib.unified_diff(body(LOCK.read_text()), body(fresh.read_text()), "requirements.txt",
                                     "pip-compile's", lineterm="", n=1))
    assert not diff, ("pip-compile writes a different lock from pyproject.toml: run `make lock` and commit "
                      "requirements.txt\n" + "\n".join(diff[:60]))
