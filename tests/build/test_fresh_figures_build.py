"""An edit to a physics_figures module re-executes exactly the pages that use it.

One small book (a copy of the project's Makefile, _config.yml and extensions, and its own
copy of physics_figures, which the build and the kernels import) with three executed pages
and a question page: built cold, then again after a figure module drawn by one page only
is edited. That page must change (its figure and its cell outputs); the other pages must
not be executed again, and a no-op rebuild executes nothing.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import textwrap
from pathlib import Path

import pytest
from test_build import FRONT_MATTER, ROOT, VENV  # the one-page build's front matter and venv

pytestmark = [pytest.mark.build]

#: A cell that prints when it ran: a page executed again prints another time.
PROBE = "```{code-cell} ipython3\nimport time\nprint('executed at', time.time_ns())\n```\n"

PAGES = {
    # draws from figures/collisions.py, the module the test edits
    "collide": """\
        # Collide

        ```{code-cell} ipython3
        from physics_figures.figures import collisions; from physics_figures import scenarios
        collisions.collision_before_after(**scenarios.STICKING_TROLLEYS)
        ```
        """,
    # draws from another figure module
    "table": """\
        # Table

        ```{code-cell} ipython3
        from physics_figures.figures import free_body
        free_body.free_body_book()
        ```
        """,
    # numbers from the models (which the figure modules import, not the other way round)
    "numbers": """\
        # Numbers

        ```{code-cell} ipython3
        from physics_figures.models import stick_together
        print("v =", stick_together(2.0, 3.0, 1.0, 0.0))
        ```
        """,
}
QUESTION_PAGE = "# Question\n\n```{question} quick-check-1\n```\n"


def _project(project: Path) -> None:
    for name in ("Makefile", "_config.yml", "requirements.txt", "pyproject.toml", "package.json",
                 "package-lock.json"):
        shutil.copy(ROOT / name, project / name)
    for folder in ("book/_ext", "book/_latex", "book/_templates", "_static", "scripts", "physics_figures"):
        shutil.copytree(ROOT / folder, project / folder, ignore=shutil.ignore_patterns("__pycache__"))
    (project / "node_modules").symlink_to(ROOT / "node_modules")
    chapters = "".join(f"  - file: book/{name}\n" for name in [*PAGES, "question"])
    (project / "_toc.yml").write_text(f"format: jb-book\nroot: book/intro\nchapters:\n{chapters}")
    (project / "book" / "intro.md").write_text("# Intro\n\nA small book.\n")
    for name, page in PAGES.items():
        (project / "book" / f"{name}.md").write_text(FRONT_MATTER + textwrap.dedent(page) + "\n" + PROBE)
    (project / "book" / "question.md").write_text(QUESTION_PAGE)


def _build(project: Path, target: str = "html") -> str:
    result = subprocess.run(
        ["make", "--no-print-directory", "-o", f"{VENV}/.installed",
         "-o", "node_modules/.package-lock.json", target, f"VENV={VENV}"],
        cwd=project, check=False, capture_output=True, text=True, timeout=600,
        # The copy's physics_figures comes first, for the build and for the kernels.
        env={**os.environ, "PYTHONPATH": str(project)},
    )
    assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-3000:]
    return result.stdout + result.stderr


def _executed(log: str) -> set[str]:
    return set(re.findall(r"/book/(\w+)\.md: Executing notebook", log))


def _page(project: Path, name: str) -> str:
    return (project / "_build" / "html" / "book" / f"{name}.html").read_text()


def _probe(html: str) -> str:
    found = re.findall(r"executed at \d+", html)
    assert len(found) == 1, "the probe cell's output is missing from the page"
    return found[0]


def _svg(project: Path, html: str) -> bytes:
    """The bytes of the page's (first) SVG figure."""
    found = re.findall(r'<img[^>]+src="([^"]+\.svg)"', html)
    assert found, "the page shows no SVG figure"
    return (project / "_build" / "html" / "book" / found[0]).read_bytes()


def test_editing_a_figure_module_re_executes_only_the_pages_that_draw_from_it(tmp_path):
    _project(tmp_path)
    log = _build(tmp_path)
    assert _executed(log) == set(PAGES), "the cold build did not execute every page"
    before = {name: _page(tmp_path, name) for name in [*PAGES, "question"]}
    figure_before = _svg(tmp_path, before["collide"])

    assert _executed(_build(tmp_path)) == set(), "a no-op rebuild executed a page"

    module = tmp_path / "physics_figures" / "figures" / "collisions.py"
    source = module.read_text()
    assert "widths = [0.6 + 0.25 * m for m in masses]" in source
    module.write_text(source.replace("0.6 + 0.25 * m", "0.6 + 0.4 * m"))  # wider blocks
    log = _build(tmp_path)

    assert _executed(log) == {"collide"}, "not exactly the page that draws a collision executed"
    after = {name: _page(tmp_path, name) for name in [*PAGES, "question"]}
    assert _probe(after["collide"]) != _probe(before["collide"]), "the collision page was not executed"
    assert _svg(tmp_path, after["collide"]) != figure_before, "the collision figure is stale"
    for name in ("table", "numbers"):
        assert _probe(after[name]) == _probe(before[name]), f"{name} was executed again"
    for name in ("table", "numbers", "question"):
        assert after[name] == before[name], f"{name} changed, though it uses nothing that changed"
