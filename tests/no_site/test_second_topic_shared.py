"""A second topic takes no edit to shared code: nothing outside tests/ names the fixture topic's
module or template (its builds are tests/build/test_second_topic.py)."""

from __future__ import annotations

import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
KEY = "kinematics-speeding-up"  # the fixture topic's template


def test_no_shared_module_knows_the_second_topic():
    """The topic took no edit to shared code: nothing outside tests/ names its module or its
    template (the README may point at it as an example; it is no code)."""
    tracked = subprocess.run(["git", "ls-files", "--cached", "--others", "--exclude-standard"], cwd=ROOT,
                             capture_output=True, text=True, check=True).stdout.split()
    shared = [ROOT / name for name in tracked
              if not name.startswith("tests/") and not name.endswith(".md") and (ROOT / name).is_file()]
    assert len(shared) > 100
    for path in shared:
        text = path.read_text(encoding="utf-8", errors="ignore")
        for name in ("kinematics_topic", "second_topic", KEY):
            assert name not in text, f"{path.relative_to(ROOT)} names {name}"
