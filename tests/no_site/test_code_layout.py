"""Rooms a newcomer can read: no module of the book's extensions and no browser script of the
site is longer than MAX_LINES (a longer one holds more than one job: split it by job, as
book/_ext/questions and site_assets are)."""

from __future__ import annotations

import ast
import graphlib
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
MAX_LINES = 500
MODULES = sorted((ROOT / "book" / "_ext").rglob("*.py")) + sorted((ROOT / "book" / "_latex").glob("*.py"))
SCRIPTS = sorted((ROOT / "book" / "_ext").glob("**/static/**/*.js")) + sorted((ROOT / "_static").glob("*.js"))


def test_the_rooms_are_found():
    assert len(MODULES) > 20 and len(SCRIPTS) > 15


@pytest.mark.parametrize("path", MODULES + SCRIPTS, ids=lambda p: str(p.relative_to(ROOT)))
def test_no_module_or_browser_script_is_longer_than_the_limit(path):
    lines = len(path.read_text(encoding="utf-8").splitlines())
    assert lines <= MAX_LINES, f"{path.relative_to(ROOT)} has {lines} lines (at most {MAX_LINES}): split it by job"


def import_graph() -> dict[str, set[str]]:
    """Our modules (physics_figures.*, and the extensions under their own names) and the
    modules of ours each imports, anywhere in it (a late import is an arrow too)."""
    files = [*(ROOT / "physics_figures").rglob("*.py"), *MODULES]
    mods = {_module_name(path): path for path in files}
    graph: dict[str, set[str]] = {name: set() for name in mods}
    for name, path in mods.items():
        package = name if path.name == "__init__.py" else name.rpartition(".")[0]
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                targets = [alias.name for alias in node.names]
            elif isinstance(node, ast.ImportFrom):
                base = package.split(".")[: len(package.split(".")) - node.level + 1] if node.level else []
                module = ".".join([*base, *([node.module] if node.module else [])])
                subs = [f"{module}.{alias.name}" for alias in node.names if f"{module}.{alias.name}" in mods]
                targets = subs + ([module] if len(subs) < len(node.names) else [])
            else:
                continue
            for target in targets:
                while target and target not in mods:  # physics_figures.models.drag.x -> ...drag
                    target = target.rpartition(".")[0]
                if target and target != name:
                    graph[name].add(target)
    return graph


def _module_name(path: Path) -> str:
    relative = path.relative_to(ROOT)
    if relative.parts[0] == "book":  # book/_ext/questions/form.py -> questions.form
        relative = relative.relative_to(*relative.parts[:2])
    parts = list(relative.with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def test_the_import_graph_has_no_circle():
    graph = import_graph()
    assert len(graph) >= 80
    list(graphlib.TopologicalSorter(graph).static_order())  # CycleError names the circle


def _folder(module: str) -> str:
    """The folder a module lives in, as a node of the graph between folders: a sub-package of
    physics_figures (physics_figures.figures.drag -> physics_figures.figures), a module at its
    top (physics_figures.questions stays itself: its folder holds every layer), an extension
    (questions.form -> questions)."""
    names = module.split(".")
    return ".".join(names[:2]) if names[0] == "physics_figures" else names[0]


def test_no_circle_runs_between_folders():
    """No circle between folders either (issue 39): figures/ -> questions.py -> parts/ -> figures/
    was one, though no two files imported each other. Each folder is one node, with an arrow
    wherever one of its modules imports another folder's module."""
    folders: dict[str, set[str]] = {}
    for name, imports in import_graph().items():
        folders.setdefault(_folder(name), set()).update(_folder(i) for i in imports if _folder(i) != _folder(name))
    assert {"physics_figures.figures", "physics_figures.parts", "physics_figures.questions"} <= set(folders)
    list(graphlib.TopologicalSorter(folders).static_order())  # CycleError names the circle


#: Arrows run one way: models -> figures and questions -> the site. Each layer may not import these.
NEVER = {
    "physics_figures.models": ("physics_figures.figures", "physics_figures.bank", "physics_figures.parts",
                               "physics_figures.questions", "physics_figures.worksheets", "matplotlib"),
    # a figure draws a question's graph and diagram from their data (physics_figures.pictures),
    # never from the part kinds or the questions that use them (issue 39: that ran in a circle)
    "physics_figures.figures": ("physics_figures.bank", "physics_figures.topics", "physics_figures.worksheets",
                                "physics_figures.parts", "physics_figures.questions"),
    "physics_figures.pictures": ("physics_figures.figures", "physics_figures.parts", "physics_figures.questions",
                                 "physics_figures.bank", "matplotlib"),
    "physics_figures.parts": ("physics_figures.bank", "physics_figures.worksheets", "physics_figures.topics"),
    "physics_figures.marking": ("physics_figures.bank", "physics_figures.parts", "physics_figures.questions"),
    "physics_figures.topics": ("physics_figures.bank", "physics_figures.worksheets"),
    "physics_figures.bank": ("physics_figures.worksheets",),
}


def test_no_arrow_runs_back_up():
    graph = import_graph()
    ours = {name.split(".")[0] for name in graph} - {"physics_figures"}  # the extensions
    for name, imports in graph.items():
        if name.startswith("physics_figures"):
            assert not {i.split(".")[0] for i in imports} & ours, f"{name} imports the site's extensions"
        for layer, forbidden in NEVER.items():
            if name == layer or name.startswith(layer + "."):
                wrong = sorted(i for i in imports if any(i == f or i.startswith(f + ".") for f in forbidden))
                assert not wrong, f"{name} imports {wrong}, a layer above it"
