"""book/_ext/fresh_figures.py: which physics_figures modules each page imports, and its digest.

The build test (tests/build/test_incremental_build.py) edits a module and rebuilds; these check
the static analysis it rests on, quickly, against the book's own pages.
"""

from __future__ import annotations

import textwrap
from pathlib import Path

import fresh_figures  # book/_ext (tests/conftest.py puts it on the path)
import pytest
from fresh_figures import ImportGraph

ROOT = Path(__file__).resolve().parents[2]

PAGES = sorted((ROOT / "book").rglob("*.md"))


def _kernel_modules(graph: ImportGraph, page: Path) -> set[str]:
    cells = fresh_figures._code_cells(page.stem, str(page), page.read_text()) or []
    return graph.closure(graph.imported_by_cells(cells))


@pytest.fixture(scope="module")
def graph() -> ImportGraph:
    return ImportGraph()


@pytest.fixture(scope="module")
def page_modules(graph) -> dict[str, set[str]]:
    return {page.relative_to(ROOT).with_suffix("").as_posix(): _kernel_modules(graph, page) for page in PAGES}


def test_only_the_collision_page_imports_the_collision_figure_module(page_modules):
    users = {page for page, modules in page_modules.items() if "physics_figures.figures.collisions" in modules}
    assert users == {"book/understand/conservation-of-momentum"}


def test_each_figure_module_is_imported_by_the_pages_that_draw_from_it_only(page_modules):
    drawn_by = {
        "collisions": {"book/understand/conservation-of-momentum"},
        "drag": {"book/understand/friction-drag-terminal-velocity"},
        "skydiver": {"book/understand/friction-drag-terminal-velocity"},
        "free_body": {"book/understand/friction-drag-terminal-velocity", "book/understand/third-law"},
        "momentum_graphs": {"book/understand/momentum-time-graph"},
        "vectors": {"book/understand/momentum-in-two-dimensions", "book/exam/example-4"},
    }
    for module, pages in drawn_by.items():
        users = {page for page, modules in page_modules.items() if f"physics_figures.figures.{module}" in modules}
        assert users == pages, module
    assert not any("physics_figures.figures.book" in modules for modules in page_modules.values()), \
        "a page imports the figures.book facade, which ties it to every figure module"


def test_the_figures_package_re_exports_nothing(graph):
    assert graph.direct("physics_figures.figures") == frozenset()
    assert graph.direct("physics_figures") == frozenset()


def test_relative_imports_and_the_packages_on_the_way_are_followed(graph):
    closure = graph.closure(["physics_figures.figures.collisions"])
    assert {"physics_figures", "physics_figures.figures", "physics_figures.figures.style",
            "physics_figures.figures.book_figure", "physics_figures.models",
            "physics_figures.models.collisions", "physics_figures.notation"} <= closure
    assert "physics_figures.figures.drag" not in closure
    assert "physics_figures.bank" not in closure


def _package(tmp_path: Path, monkeypatch) -> ImportGraph:
    files = {
        "__init__.py": "",
        "a.py": "from . import b\nfrom .sub import deep\n",
        "b.py": "def f():\n    from .c import X  # a lazy import counts too\n",
        "c.py": "X = 1\n",
        "lonely.py": "Y = 2\n",
        "sub/__init__.py": "",
        "sub/deep.py": "from .. import c\nfrom ..c import X\n",
    }
    for name, text in files.items():
        path = tmp_path / "fakepkg" / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    monkeypatch.syspath_prepend(str(tmp_path))
    return ImportGraph("fakepkg")


def test_a_digest_changes_with_the_modules_imported_and_only_with_them(tmp_path, monkeypatch):
    graph = _package(tmp_path, monkeypatch)
    assert graph.closure(["fakepkg.a"]) == {"fakepkg", "fakepkg.a", "fakepkg.b", "fakepkg.c",
                                           "fakepkg.sub", "fakepkg.sub.deep"}
    before = graph.digest(["fakepkg.a"])
    (tmp_path / "fakepkg" / "lonely.py").write_text("Y = 3\n")
    assert ImportGraph("fakepkg").digest(["fakepkg.a"]) == before
    (tmp_path / "fakepkg" / "sub" / "deep.py").write_text("from .. import c\nX = 2\n")
    assert ImportGraph("fakepkg").digest(["fakepkg.a"]) != before


def test_what_an_earlier_build_parsed_is_reused_only_while_the_file_is_unchanged(tmp_path, monkeypatch):
    """A no-op build parses no module (ImportGraph.parsed is kept in the environment); an
    edit to a module's imports, or to the data files it names, is still seen."""
    graph = _package(tmp_path, monkeypatch)
    assert graph.closure(["fakepkg.lonely"]) == {"fakepkg", "fakepkg.lonely"}
    parsed = graph.parsed
    assert {"fakepkg.lonely", "fakepkg"} <= set(parsed)
    again = ImportGraph("fakepkg", parsed=parsed)
    monkeypatch.setattr("ast.parse", lambda *a, **k: pytest.fail("an unchanged module was parsed again"))
    assert again.closure(["fakepkg.lonely"]) == {"fakepkg", "fakepkg.lonely"}
    monkeypatch.undo()
    monkeypatch.syspath_prepend(str(tmp_path))
    (tmp_path / "fakepkg" / "lonely.py").write_text("from . import c\nDATA = 'table.json'\n")
    (tmp_path / "fakepkg" / "table.json").write_text("{}")
    edited = ImportGraph("fakepkg", parsed=parsed)
    assert edited.closure(["fakepkg.lonely"]) == {"fakepkg", "fakepkg.lonely", "fakepkg.c"}
    assert tmp_path / "fakepkg" / "table.json" in edited.files(["fakepkg.lonely"])


def test_cells_import_what_they_name_and_unreadable_cells_import_everything(tmp_path, monkeypatch):
    graph = _package(tmp_path, monkeypatch)
    assert graph.imported_by_cells(["%matplotlib inline\nfrom fakepkg.sub import deep\nimport os"]) == {
        "fakepkg", "fakepkg.sub", "fakepkg.sub.deep"}
    assert graph.imported_by_cells(["x = (\n"]) == graph.every_module()


def test_the_hidden_cell_carries_the_digest_and_is_removed_from_the_page():
    page = textwrap.dedent("""\
        ---
        kernelspec:
          display_name: Python 3
          language: python
          name: python3
        ---
        # Page

        ```{code-cell} ipython3
        from physics_figures.figures import collisions
        ```
        """)
    text = fresh_figures._with_digest_cell("page.md", page, "0" * 64)
    from myst_nb.core.read import read_myst_markdown_notebook

    cells = read_myst_markdown_notebook(text).cells
    assert cells[-1].cell_type == "code"
    assert cells[-1].source == f"{fresh_figures.CELL_MARK} {'0' * 64}"
    assert cells[-1].metadata["tags"] == ["remove-cell"]
    assert [c.source for c in read_myst_markdown_notebook(page).cells] == [c.source for c in cells[:-1]]


def test_glue_from_another_page_is_found_and_the_books_pages_use_none():
    found = fresh_figures.CROSS_PAGE_GLUE.findall
    assert found("Speed {glue:text}`book/understand/weight::g_moon:.2f` here.") == ["book/understand/weight::g_moon:.2f"]
    assert found("```{glue:figure} other/page::fig-a\n```\n") == ["other/page::fig-a"]
    assert found("{glue:text}`terminal_speed:.1f` and {glue}`mass`") == []
    for page in PAGES:
        assert not found(page.read_text()), f"{page.relative_to(ROOT)} glues a value from another page"
