"""The book's browser scripts run under Node, fed and read as JSON (tests/js's runners)."""

from __future__ import annotations

import json
import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
MARK_CASES = ROOT / "tests" / "js" / "mark_cases.js"


def node() -> str:
    found = shutil.which("node")
    if found is None:
        pytest.fail("node is missing, so the marking engine cannot be tested: apt-get install nodejs (Node 20)")
    return found


def node_json(script: Path, request):
    """What the Node script `script` writes as JSON, given `request` as JSON on its input."""
    result = subprocess.run([node(), str(script)], input=json.dumps(request), capture_output=True, text=True,
                            timeout=120, check=False)
    assert result.returncode == 0, result.stderr[-3000:]
    return json.loads(result.stdout)


def mark_all(cases: list[dict]) -> list[dict]:
    """The browser's marker (tests/js/mark_cases.js) on {part, answer} cases."""
    return node_json(MARK_CASES, cases)


def mark_questions(cases: list[tuple[dict, dict]]) -> list[dict]:
    """The page's marker (tests/js/mark_questions.js) on (question data, answers by part) cases."""
    return node_json(ROOT / "tests" / "js" / "mark_questions.js", [{"data": d, "answers": a} for d, a in cases])
