"""The build is strict and never stale.

Each test builds a one-page book in a temporary folder with the project's own
Makefile, _config.yml and extensions, so it checks the very command `make book` runs for the site.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import textwrap
from pathlib import Path

import pytest

pytestmark = [pytest.mark.build]

ROOT = Path(__file__).resolve().parents[1]
VENV = ROOT / ".venv"

FRONT_MATTER = """\
---
jupytext:
  text_representation:
    extension: .md
    format_name: myst
kernelspec:
  display_name: Python 3
  language: python
  name: python3
---
"""


def make_book(project: Path, page: str, *, env: dict[str, str] | None = None):
    """Write `page` as the only page of a copy of the project and run `make html` on it."""
    for name in ("Makefile", "_config.yml", "requirements.txt", "pyproject.toml"):
        if not (project / name).exists():
            shutil.copy(ROOT / name, project / name)
    for folder in ("book/_ext", "book/_latex", "book/_templates", "_static", "scripts"):
        if (ROOT / folder).exists() and not (project / folder).exists():
            shutil.copytree(ROOT / folder, project / folder, ignore=shutil.ignore_patterns("__pycache__"))
    for name in ("package.json", "package-lock.json"):
        if not (project / name).exists():
            shutil.copy(ROOT / name, project / name)
    if not (project / "node_modules").exists():  # the project's installed node tools
        (project / "node_modules").symlink_to(ROOT / "node_modules")
    (project / "_toc.yml").write_text("format: jb-book\nroot: book/intro\n")
    (project / "book" / "intro.md").write_text(FRONT_MATTER + textwrap.dedent(page))
    return subprocess.run(
        # -o: use the project's installed venv as it is (never reinstall from the copy).
        ["make", "--no-print-directory", "-o", f"{VENV}/.installed",
         "-o", "node_modules/.package-lock.json", "html", f"VENV={VENV}"],
        cwd=project,
        check=False,  # the tests assert on the exit status
        capture_output=True,
        text=True,
        env={**os.environ, **(env or {})},
        timeout=300,
    )


def built_page(project: Path) -> str:
    return (project / "_build" / "html" / "book" / "intro.html").read_text()


def probe_output(project: Path) -> str:
    """The probe cell's printed line, e.g. 'value: first executed at: 1767...'."""
    found = re.search(r"value: \w+ executed at: \d+", built_page(project))
    assert found, "the probe cell's output is missing from the page"
    return found.group()


BROKEN_PAGES = {
    "broken cross-reference": ("# Title\n\nSee {ref}`no-such-label`.\n", "no-such-label"),
    "cell error": ("# Title\n\n```{code-cell} ipython3\n1 / 0\n```\n", "ZeroDivisionError"),
    "unknown directive": ("# Title\n\n```{no-such-directive}\nx\n```\n", "no-such-directive"),
    # book/_ext/fresh_figures.py cannot keep a value glued from another page fresh
    "glue from another page": ("# Title\n\nSpeed {glue:text}`book/other::speed`.\n",
                               "glues 'book/other::speed' from another page"),
}


@pytest.mark.parametrize("fault", BROKEN_PAGES)
def test_build_fails_on_any_warning_or_cell_error(tmp_path, fault):
    page, evidence = BROKEN_PAGES[fault]
    result = make_book(tmp_path, page)
    assert result.returncode != 0, f"the build passed despite a {fault}"
    assert evidence in result.stdout + result.stderr


def test_a_clean_page_builds(tmp_path):
    result = make_book(tmp_path, "# Title\n\n```{code-cell} ipython3\n6 * 7\n```\n")
    assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-3000:]
    assert "42" in built_page(tmp_path)


PROBE_PAGE = """\
# Probe

```{code-cell} ipython3
import time, physics_figures
print("value:", physics_figures.VALUE, "executed at:", time.time_ns())
```
"""


def test_editing_physics_figures_re_executes_the_page_but_a_no_op_build_does_not(tmp_path):
    # A stand-in physics_figures package, found first by the kernel and the build.
    package = tmp_path / "stand_in" / "physics_figures"
    package.mkdir(parents=True)
    (package / "__init__.py").write_text('VALUE = "first"\n')
    env = {"PYTHONPATH": str(package.parent)}

    assert make_book(tmp_path, PROBE_PAGE, env=env).returncode == 0
    first = probe_output(tmp_path)
    assert first.startswith("value: first")

    assert make_book(tmp_path, PROBE_PAGE, env=env).returncode == 0
    assert probe_output(tmp_path) == first, "a no-op rebuild re-executed the page"

    (package / "__init__.py").write_text('VALUE = "second"\n')
    result = make_book(tmp_path, PROBE_PAGE, env=env)
    assert result.returncode == 0, result.stdout[-3000:]
    assert probe_output(tmp_path).startswith("value: second"), "the page shows the old module's output"
