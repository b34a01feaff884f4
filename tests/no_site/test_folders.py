"""The test folders follow the markers (issue 39, "A house for the tests"): tests/no_site/ holds what
`make check` runs, and tests/site/, tests/browser/, tests/build/ and tests/network/ what needs the
built site, Chromium, a build of its own or PyPI. tests/conftest.py gives each test its folder's
marker and refuses a collection where a test's markers name another folder; this reads the
modules' own marks, so a module moved to the wrong folder fails here, in `make check`."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest
from conftest import FOLDERS, NO_SITE_FOLDER, TESTS, folder_for

#: What is not a test module though it sits under tests/.
NOT_TESTS = ("fixtures", "js", "js_explorables", "support")


def marks_in(node: ast.AST) -> set[str]:
    """The folder markers that `pytest.mark.X` names anywhere in `node`."""
    return {inner.attr for inner in ast.walk(node) if isinstance(inner, ast.Attribute)
            and ast.unparse(inner.value) == "pytest.mark" and inner.attr in FOLDERS}


def _pytestmark(body: list[ast.stmt]) -> set[str]:
    return set().union(*(marks_in(statement) for statement in body if isinstance(statement, ast.Assign)
                         and any(getattr(target, "id", "") == "pytestmark" for target in statement.targets)))


def marks_of_tests(source: str) -> dict[str, set[str]]:
    """Each test of a module (test_x or Class::test_x) and the folder markers it carries: the
    module's pytestmark, its class's, its decorators' (parametrize's marks= too)."""
    tree = ast.parse(source)
    module = _pytestmark(tree.body)
    found = {}
    for node in tree.body:
        if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef) and node.name.startswith("test"):
            found[node.name] = module | set().union(*map(marks_in, node.decorator_list))
        elif isinstance(node, ast.ClassDef) and node.name.startswith("Test"):
            outer = module | _pytestmark(node.body) | set().union(*map(marks_in, node.decorator_list))
            for method in node.body:
                if isinstance(method, ast.FunctionDef | ast.AsyncFunctionDef) and method.name.startswith("test"):
                    found[f"{node.name}::{method.name}"] = outer | set().union(*map(marks_in, method.decorator_list))
    return found


def misplaced(path: Path, source: str) -> list[str]:
    """The tests of the module at `path` whose markers name a folder other than the one it sits in."""
    folder = path.relative_to(TESTS).parts[0]
    wrong = []
    for test, marks in marks_of_tests(source).items():
        # the folder's own marker is given by the folder (conftest), so a test need not write it
        wanted = folder_for(marks | ({folder} if folder in FOLDERS else set()))
        if wanted != folder:
            wrong.append(f"{path.relative_to(TESTS)}::{test} is marked {sorted(marks)}: it belongs in tests/{wanted}/")
    return wrong


def modules_under_tests() -> list[Path]:
    return sorted(path for path in TESTS.rglob("test_*.py") if path.relative_to(TESTS).parts[0] not in NOT_TESTS)


def test_every_test_module_sits_in_a_folder_of_its_markers():
    modules = modules_under_tests()
    assert len(modules) > 100
    loose = [path.name for path in modules if len(path.relative_to(TESTS).parts) == 1]
    assert not loose, f"test modules directly in tests/ (put each in the folder of its markers): {loose}"
    assert {path.relative_to(TESTS).parts[0] for path in modules} == {*FOLDERS, NO_SITE_FOLDER}
    wrong = [line for path in modules for line in misplaced(path, path.read_text(encoding="utf-8"))]
    assert not wrong, "\n".join(wrong)


BROWSER_MODULE = '''
import pytest

pytestmark = [pytest.mark.site, pytest.mark.browser]


def test_a_page_in_chromium(page):
    ...
'''

MIXED_MODULE = '''
import pytest


def test_a_model():
    ...


@pytest.mark.build
def test_a_book_of_its_own(tmp_path):
    ...


@pytest.mark.parametrize("n", [1, pytest.param(2, marks=pytest.mark.site)])
def test_a_page(n):
    ...
'''


@pytest.mark.parametrize(("folder", "source", "expected"), [
    ("no_site", BROWSER_MODULE, ["test_a_page_in_chromium belongs in tests/browser/"]),
    ("site", BROWSER_MODULE, ["test_a_page_in_chromium belongs in tests/browser/"]),
    ("browser", BROWSER_MODULE, []),
    ("no_site", MIXED_MODULE, ["test_a_book_of_its_own belongs in tests/build/",
                               "test_a_page belongs in tests/site/"]),
    ("build", MIXED_MODULE, []),  # a test of tests/build/ carries build, whatever else it needs
])
def test_the_check_finds_a_test_in_the_wrong_folder(folder, source, expected):
    found = misplaced(TESTS / folder / "test_example.py", source)
    said = [f"{line.split('::')[1].split(' ')[0]} belongs in {line.rsplit(' ', 1)[1]}" for line in found]
    assert said == expected
