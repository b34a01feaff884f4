"""The build is strict: any warning, broken reference or cell error fails it, naming the page.

Each test builds a small book in a temporary folder with the project's own Makefile,
_config.yml and extensions, so it checks the very command `make book` runs for the site. That
the build is never stale: tests/build/test_incremental_build.py.
"""

from __future__ import annotations

import shutil
import subprocess
import textwrap
from pathlib import Path

import pytest

pytestmark = [pytest.mark.build]

ROOT = Path(__file__).resolve().parents[2]
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


def make_book(project: Path, page: str, *, more_pages: dict[str, str] | None = None):
    """Write `page` as the first page of a copy of the project (and `more_pages`, {name: text},
    as chapters after it) and run `make html` on it."""
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
    chapters = "".join(f"  - file: book/{name}\n" for name in more_pages or {})
    (project / "_toc.yml").write_text("format: jb-book\nroot: book/intro\n" + (f"chapters:\n{chapters}" if chapters else ""))
    (project / "book" / "intro.md").write_text(FRONT_MATTER + textwrap.dedent(page))
    for name, text in (more_pages or {}).items():
        (project / "book" / f"{name}.md").write_text(FRONT_MATTER + textwrap.dedent(text))
    return subprocess.run(
        # -o: use the project's installed venv as it is (never reinstall from the copy).
        ["make", "--no-print-directory", "-o", f"{VENV}/.installed",
         "-o", "node_modules/.package-lock.json", "html", f"VENV={VENV}"],
        cwd=project,
        check=False,  # the tests assert on the exit status
        capture_output=True,
        text=True,
        timeout=300,
    )


BROKEN_PAGES = {
    "broken cross-reference": ("# Title\n\nSee {ref}`no-such-label`.\n", "no-such-label"),
    "cell error": ("# Title\n\n```{code-cell} ipython3\n1 / 0\n```\n", "ZeroDivisionError"),
    "unknown directive": ("# Title\n\n```{no-such-directive}\nx\n```\n", "no-such-directive"),
    # book/_ext/fresh_figures.py cannot keep a value glued from another page fresh
    "glue from another page": ("# Title\n\nSpeed {glue:text}`book/other::speed`.\n",
                               "glues 'book/other::speed' from another page"),
}


def _page_name(fault: str) -> str:
    return fault.replace(" ", "-")


#: A failing cell stops the build there (myst-nb raises), so it gets a book of its own.
STOPS_THE_BUILD = ("cell error",)


def _broken_book(project: Path, faults: list[str]) -> subprocess.CompletedProcess:
    return make_book(project, "# Title\n\nA clean page.\n",
                     more_pages={_page_name(fault): BROKEN_PAGES[fault][0] for fault in faults})


@pytest.fixture(scope="module")
def broken_builds(tmp_path_factory) -> dict[str, subprocess.CompletedProcess]:
    """{fault: the build that met it}: the faults that let the build go on share one book (each
    build costs ~15 s); each that stops it has its own."""
    builds = {fault: _broken_book(tmp_path_factory.mktemp("broken"), [fault]) for fault in STOPS_THE_BUILD}
    others = [fault for fault in BROKEN_PAGES if fault not in STOPS_THE_BUILD]
    shared = _broken_book(tmp_path_factory.mktemp("broken"), others)
    return builds | dict.fromkeys(others, shared)


@pytest.mark.parametrize("fault", BROKEN_PAGES)
def test_build_fails_on_any_warning_or_cell_error(broken_builds, fault):
    build = broken_builds[fault]
    assert build.returncode != 0, f"the build passed despite a {fault}"
    # Reported against its own page: with -W that report alone fails the build.
    log = build.stdout + build.stderr
    evidence = BROKEN_PAGES[fault][1]
    assert evidence in log, f"the build did not report the {fault}: {log[-3000:]}"
    assert f"book/{_page_name(fault)}" in log, f"nothing in the log names the page with the {fault}"
