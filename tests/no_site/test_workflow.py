"""The GitHub Actions workflow that builds, tests and publishes the book: valid against
GitHub's workflow schema (check-jsonschema's copy, so it runs offline), and doing what the
README promises a teacher who forks the repository."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
WORKFLOW = ROOT / ".github" / "workflows" / "book.yml"


def test_the_workflow_is_valid_against_githubs_schema():
    result = subprocess.run(
        [sys.executable, "-m", "check_jsonschema", "--builtin-schema", "vendor.github-workflows", str(WORKFLOW)],
        capture_output=True, text=True, check=False)
    assert result.returncode == 0, result.stdout + result.stderr


def test_the_workflow_runs_make_test_in_debian_12_and_publishes_the_site():
    text = WORKFLOW.read_text(encoding="utf-8")
    assert "image: debian:12" in text
    assert "make test" in text
    assert "path: _build/html" in text and "actions/deploy-pages" in text
    assert "GitHub Actions" in (ROOT / "README.md").read_text(encoding="utf-8")
