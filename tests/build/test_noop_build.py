"""A no-op rebuild redoes nothing, and an edit still reaches the site.

The work done when the HTML build finishes is skipped when its inputs did not change
(book/_ext/questions/variants.py: each template's variants and their graphs;
book/_ext/offline: the search texts and the service worker, which read and hash the whole
site). One small book (a copy of the project with its own physics_figures, as
tests/build/test_fresh_figures_build.py makes) with a question that has a graph, built cold, then
without a change, then after an edit to the graph's drawing code, to the question's
numbers in the bank, to a stylesheet alone, and to a page's text: each must reach the site. The page's edit is built
by the LaTeX build (make latex, the first half of make pdf) first, and the HTML build after it
reads that page only: the LaTeX build keeps its own Sphinx environment. (One book for all of
it: each cold build of it costs a test process ten seconds.)
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from test_fresh_figures_build import _build
from test_fresh_figures_build import _project as _fresh_figures_project

pytestmark = [pytest.mark.build]

KEY = "graph-ball-acceleration"  # a template with a graph and New numbers (bank/drag.py)


def _project(project: Path) -> None:
    _fresh_figures_project(project)
    (project / "book" / "question.md").write_text(f"# Question\n\nA ball falls.\n\n```{{question}} {KEY}\n```\n")
    (project / "book" / "answers.md").write_text("# Answers\n\n```{answer-key}\n```\n")
    # three pages, no code cells: nothing to execute (test_fresh_figures_build.py covers that); in
    # parts, as the book's table of contents has: sphinx-jupyterbook-latex then numbers LaTeX's
    # figures by chapter (numfig_secnum_depth), a setting the HTML build does not share
    (project / "_toc.yml").write_text(
        "format: jb-book\nroot: book/intro\nparts:\n"
        "  - caption: One\n    chapters:\n      - file: book/question\n"
        "  - caption: Two\n    chapters:\n      - file: book/answers\n")


def _site(project: Path) -> dict[str, bytes]:
    site = project / "_build" / "html"
    return {p.relative_to(site).as_posix(): p.read_bytes() for p in sorted(site.rglob("*")) if p.is_file()}


def _bundles(project: Path) -> str:
    """The text of the stylesheet bundles the pages link."""
    return "\n".join(path.read_text() for path in (project / "_build" / "html" / "_static" / "site-assets").glob("bundle-*.css"))


def _mtimes(project: Path, names: list[str]) -> dict[str, int]:
    return {name: (project / "_build" / "html" / name).stat().st_mtime_ns for name in names}


def _edit(path: Path, old: str, new: str) -> None:
    text = path.read_text()
    assert old in text, f"{path.name} no longer holds {old!r}: update this test"
    path.write_text(text.replace(old, new, 1))


def test_a_no_op_rebuild_rewrites_nothing_and_every_edit_reaches_the_site(tmp_path):
    _project(tmp_path)
    _build(tmp_path)
    cold = _site(tmp_path)
    variants = sorted(name for name in cold if name.startswith(f"_static/questions/{KEY}"))
    assert f"_static/questions/{KEY}.js" in variants and f"_static/questions/{KEY}-1.svg" in variants
    written_last = [*variants, "sw.js", "_static/search-texts.js"]
    before = _mtimes(tmp_path, written_last)

    log = _build(tmp_path)
    assert "no targets are out of date" in log, log[-2000:]
    assert _site(tmp_path) == cold, "a no-op rebuild changed the site"
    assert _mtimes(tmp_path, written_last) == before, "a no-op rebuild wrote the variants or the service worker again"

    # an output removed by hand is written again, though nothing else changed
    (tmp_path / "_build" / "html" / "_static" / "questions" / f"{KEY}-1.svg").unlink()
    _build(tmp_path)
    assert _site(tmp_path) == cold, "a removed variant graph was not drawn again"

    # the graph's drawing code: every variant's graph is drawn again
    _edit(tmp_path / "physics_figures" / "figures" / "question_graph.py",
          'color=colour("figure.grid-minor"), linewidth=0.5',
          'color=colour("figure.grid-minor"), linewidth=0.7')
    _build(tmp_path)
    drawn = _site(tmp_path)
    for name in (n for n in variants if n.endswith(".svg")):
        assert drawn[name] != cold[name], f"{name} is stale after an edit to the graph's drawing code"
    assert drawn["sw.js"] != cold["sw.js"], "the service worker still lists the old graphs' hashes"

    # the question's numbers in the bank: the variants' data change
    _edit(tmp_path / "physics_figures" / "bank" / "drag.py",
          '{"terminal": Draw(20.0, 10.0, 25.0, 0.5)', '{"terminal": Draw(22.0, 10.0, 25.0, 0.5)')
    _build(tmp_path)
    renumbered = _site(tmp_path)
    assert renumbered[f"_static/questions/{KEY}.js"] != drawn[f"_static/questions/{KEY}.js"], \
        "the variants' script is stale after an edit to the bank"

    # a stylesheet alone: Sphinx copies static files only when it writes some page, so an edit to
    # _static/site.css and nothing else once left the site (and the bundle pages link) as it was.
    # On an element every page has, so the pruned bundle keeps it; a real property with an odd
    # value, as unused custom properties are pruned and the bundle is minified.
    rule, mark = "p { word-spacing: 0.0137em; }", ".0137em"
    assert mark not in _bundles(tmp_path)
    with (tmp_path / "_static" / "site.css").open("a") as css:
        css.write(f"\n{rule}\n")
    _build(tmp_path)
    assert mark in _bundles(tmp_path), "the stylesheet bundle pages link was not rebuilt after an edit to site.css"
    assert "no targets are out of date" in _build(tmp_path), "a build after the stylesheet's was not a no-op"

    # a page's text, built by the LaTeX build first: the HTML build after it reads that page only
    # (the LaTeX build changed none of its environment), and its words reach the search texts
    # (for a copy opened from disk)
    with (tmp_path / "book" / "intro.md").open("a") as page:
        page.write("\nA sentence about zebrafish.\n")
    assert "build succeeded" in _build(tmp_path, "latex")
    log = _build(tmp_path)
    assert "config changed" not in log, "the LaTeX build changed the HTML build's environment:\n" + log[-2000:]
    read = re.findall(r"reading sources\.\.\. \S*\[\s*\d+%\]\S* \S*book/(\w+)", log)
    assert "question" not in read, f"the HTML build after the LaTeX build read an unchanged page again: {read}"
    assert "intro" in read, f"the edited page was not read again: {read}"
    texts = (tmp_path / "_build" / "html" / "_static" / "search-texts.js").read_text()
    assert re.search(r"zebrafish", texts), "the search texts are stale after a page edit"
