"""An incremental build: a no-op rebuild redoes nothing, and every edit reaches the site.

One small book, built with the project's own Makefile: a copy of its Makefile, _config.yml,
extensions and its own copy of physics_figures (which the build and the kernels import first).
It has three executed pages, one drawing from figures/collisions.py, one from another figure
module and one printing the models' numbers, a question with a graph and New numbers, and an
answer key. Built cold, then:

- without a change: nothing is executed or written again (book/_ext/questions/variants.py skips
  each template's variants and graphs, book/_ext/offline the search texts and the service
  worker, when their inputs did not change);
- after an output is removed by hand: it is written again;
- after an edit to figures/collisions.py: exactly the page that draws from it is executed again
  (book/_ext/fresh_figures.py), with its new figure;
- after an edit to the graph's drawing code, to the question's numbers in the bank, to a
  stylesheet alone and to a page's text: each reaches the site. The page's edit is built by the
  LaTeX build (make latex, the first half of make pdf) first, and the HTML build after it reads
  that page only: the LaTeX build keeps its own Sphinx environment.

One book for all of it: each cold build of it costs a test process ten seconds.
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

KEY = "graph-ball-acceleration"  # a template with a graph and New numbers (bank/drag.py)
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
    # numbers from the models (which the figure modules import, not the other way round), and a
    # cell whose value (not a print) is its output
    "numbers": """\
        # Numbers

        ```{code-cell} ipython3
        from physics_figures.models import stick_together
        print("v =", stick_together(2.0, 3.0, 1.0, 0.0))
        ```

        ```{code-cell} ipython3
        1234 * 5
        ```
        """,
}
CELL_VALUE = "6170"  # 1234 * 5, the numbers page's last cell


def _project(project: Path) -> None:
    for name in ("Makefile", "_config.yml", "requirements.txt", "pyproject.toml", "package.json",
                 "package-lock.json"):
        shutil.copy(ROOT / name, project / name)
    for folder in ("book/_ext", "book/_latex", "book/_templates", "_static", "scripts", "physics_figures"):
        shutil.copytree(ROOT / folder, project / folder, ignore=shutil.ignore_patterns("__pycache__"))
    (project / "node_modules").symlink_to(ROOT / "node_modules")
    (project / "book" / "intro.md").write_text("# Intro\n\nA small book.\n")
    for name, page in PAGES.items():
        (project / "book" / f"{name}.md").write_text(FRONT_MATTER + textwrap.dedent(page) + "\n" + PROBE)
    (project / "book" / "question.md").write_text(f"# Question\n\nA ball falls.\n\n```{{question}} {KEY}\n```\n")
    (project / "book" / "answers.md").write_text("# Answers\n\n```{answer-key}\n```\n")
    # in parts, as the book's table of contents has: sphinx-jupyterbook-latex then numbers LaTeX's
    # figures by chapter (numfig_secnum_depth), a setting the HTML build does not share
    one = "".join(f"      - file: book/{name}\n" for name in [*PAGES, "question"])
    (project / "_toc.yml").write_text(
        f"format: jb-book\nroot: book/intro\nparts:\n  - caption: One\n    chapters:\n{one}"
        "  - caption: Two\n    chapters:\n      - file: book/answers\n")


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


def _site(project: Path) -> dict[str, bytes]:
    site = project / "_build" / "html"
    return {p.relative_to(site).as_posix(): p.read_bytes() for p in sorted(site.rglob("*")) if p.is_file()}


def _page(site: dict[str, bytes], name: str) -> str:
    return site[f"book/{name}.html"].decode()


def _probe(html: str) -> str:
    found = re.findall(r"executed at \d+", html)
    assert len(found) == 1, "the probe cell's output is missing from the page"
    return found[0]


def _svg(site: dict[str, bytes], html: str) -> bytes:
    """The bytes of the page's (first) SVG figure."""
    found = re.findall(r'<img[^>]+src="([^"]+\.svg)"', html)
    assert found, "the page shows no SVG figure"
    return site[os.path.normpath(f"book/{found[0]}")]


def _bundles(project: Path) -> str:
    """The text of the stylesheet bundles the pages link."""
    return "\n".join(path.read_text() for path in (project / "_build" / "html" / "_static" / "site-assets").glob("bundle-*.css"))


def _mtimes(project: Path, names: list[str]) -> dict[str, int]:
    return {name: (project / "_build" / "html" / name).stat().st_mtime_ns for name in names}


def _edit(path: Path, old: str, new: str) -> None:
    text = path.read_text()
    assert old in text, f"{path.name} no longer holds {old!r}: update this test"
    path.write_text(text.replace(old, new, 1))


def _cold_then_no_op(project: Path) -> dict[str, bytes]:
    """The cold build executes every page; the build after it executes and writes nothing."""
    assert _executed(_build(project)) == set(PAGES), "the cold build did not execute every page"
    cold = _site(project)
    assert CELL_VALUE in _page(cold, "numbers"), "a code cell's value is missing from its page"
    variants = sorted(name for name in cold if name.startswith(f"_static/questions/{KEY}"))
    assert f"_static/questions/{KEY}.js" in variants and f"_static/questions/{KEY}-1.svg" in variants
    written_last = [*variants, "sw.js", "_static/search-texts.js"]
    before = _mtimes(project, written_last)

    log = _build(project)
    assert "no targets are out of date" in log, log[-2000:]
    assert _executed(log) == set(), "a no-op rebuild executed a page"
    assert _site(project) == cold, "a no-op rebuild changed the site"
    assert _mtimes(project, written_last) == before, "a no-op rebuild wrote the variants or the service worker again"

    # an output removed by hand is written again, though nothing else changed
    (project / "_build" / "html" / "_static" / "questions" / f"{KEY}-1.svg").unlink()
    _build(project)
    assert _site(project) == cold, "a removed variant graph was not drawn again"
    return cold


def _figure_module_edit(project: Path, before: dict[str, bytes]) -> None:
    """An edit to figures/collisions.py executes exactly the page that draws from it again."""
    _edit(project / "physics_figures" / "figures" / "collisions.py",
          "widths = [0.6 + 0.25 * m for m in masses]", "widths = [0.6 + 0.4 * m for m in masses]")  # wider blocks
    assert _executed(_build(project)) == {"collide"}, "not exactly the page that draws a collision executed"
    after = _site(project)
    collide = _page(after, "collide")
    assert _probe(collide) != _probe(_page(before, "collide")), "the collision page was not executed"
    assert _svg(after, collide) != _svg(before, _page(before, "collide")), "the collision figure is stale"
    for name in ("table", "numbers"):
        assert _probe(_page(after, name)) == _probe(_page(before, name)), f"{name} was executed again"
    for name in ("table", "numbers", "question"):
        assert _page(after, name) == _page(before, name), f"{name} changed, though it uses nothing that changed"


def _question_edits(project: Path) -> None:
    """The graph's drawing code: every variant's graph is drawn again; the question's numbers in
    the bank: the variants' data change."""
    before = _site(project)
    _edit(project / "physics_figures" / "figures" / "question_graph.py",
          'color=colour("figure.grid-minor"), linewidth=0.5',
          'color=colour("figure.grid-minor"), linewidth=0.7')
    _build(project)
    drawn = _site(project)
    for name in (n for n in before if n.startswith(f"_static/questions/{KEY}") and n.endswith(".svg")):
        assert drawn[name] != before[name], f"{name} is stale after an edit to the graph's drawing code"
    assert drawn["sw.js"] != before["sw.js"], "the service worker still lists the old graphs' hashes"

    _edit(project / "physics_figures" / "bank" / "drag.py",
          '{"terminal": Draw(20.0, 10.0, 25.0, 0.5)', '{"terminal": Draw(22.0, 10.0, 25.0, 0.5)')
    _build(project)
    assert _site(project)[f"_static/questions/{KEY}.js"] != drawn[f"_static/questions/{KEY}.js"], \
        "the variants' script is stale after an edit to the bank"


def _stylesheet_edit(project: Path) -> None:
    """A stylesheet alone: Sphinx copies static files only when it writes some page, so an edit
    to _static/site.css and nothing else once left the site (and the bundle pages link) as it
    was. On an element every page has, so the pruned bundle keeps it; a real property with an
    odd value, as unused custom properties are pruned and the bundle is minified."""
    rule, mark = "p { word-spacing: 0.0137em; }", ".0137em"
    assert mark not in _bundles(project)
    with (project / "_static" / "site.css").open("a") as css:
        css.write(f"\n{rule}\n")
    _build(project)
    assert mark in _bundles(project), "the stylesheet bundle pages link was not rebuilt after an edit to site.css"
    assert "no targets are out of date" in _build(project), "a build after the stylesheet's was not a no-op"


def _page_edit_after_latex(project: Path) -> None:
    """A page's text, built by the LaTeX build first: the HTML build after it reads that page
    only (the LaTeX build changed none of its environment), and its words reach the search
    texts (for a copy opened from disk)."""
    with (project / "book" / "intro.md").open("a") as page:
        page.write("\nA sentence about zebrafish.\n")
    assert "build succeeded" in _build(project, "latex")
    log = _build(project)
    assert "config changed" not in log, "the LaTeX build changed the HTML build's environment:\n" + log[-2000:]
    read = re.findall(r"reading sources\.\.\. \S*\[\s*\d+%\]\S* \S*book/(\w+)", log)
    assert not {"question", *PAGES} & set(read), f"the HTML build after the LaTeX build read an unchanged page again: {read}"
    assert "intro" in read, f"the edited page was not read again: {read}"
    texts = (project / "_build" / "html" / "_static" / "search-texts.js").read_text()
    assert re.search(r"zebrafish", texts), "the search texts are stale after a page edit"


def test_a_no_op_rebuild_does_nothing_and_every_edit_reaches_the_site(tmp_path):
    _project(tmp_path)
    cold = _cold_then_no_op(tmp_path)
    _figure_module_edit(tmp_path, cold)
    _question_edits(tmp_path)
    _stylesheet_edit(tmp_path)
    _page_edit_after_latex(tmp_path)
