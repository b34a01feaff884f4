"""The tests' house (issue 39, items 5 and 6): no product script imports a test, no helper is
defined in two test modules, a measured figure is the median of its runs, never the best of
them; and the review's leftovers stay gone: no comment calls questions.js the marking engine,
one ValueError check, one SOURCE_DATE_EPOCH, and the worksheets use no private helper of a topic."""

from __future__ import annotations

import ast
import difflib
import re
from pathlib import Path

import pytest
from browser import LIGHTHOUSE_RUNS, median_scores

from physics_figures import checks
from physics_figures.reproducible import SOURCE_DATE_EPOCH

ROOT = Path(__file__).resolve().parents[2]
TESTS = ROOT / "tests"


def _imported(source: Path) -> set[str]:
    """The top-level names of the modules a file imports, and the folders it puts on sys.path."""
    tree = ast.parse(source.read_text(), filename=str(source))
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found |= {alias.name.split(".")[0] for alias in node.names}
        elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
            found.add(node.module.split(".")[0])
        elif _puts_on_path(node) and any(isinstance(inner, ast.Constant) and inner.value == "tests"
                                         for arg in node.args for inner in ast.walk(arg)):
            found.add("tests")  # sys.path.insert(0, str(ROOT / "tests")); a data file's path is no import
    return found


def _puts_on_path(node: ast.AST) -> bool:
    """node is a call of sys.path.insert or sys.path.append."""
    return (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)
            and node.func.attr in ("insert", "append") and ast.unparse(node.func.value) == "sys.path")


def test_no_script_imports_a_test():
    test_modules = {path.stem for path in TESTS.rglob("*.py")} | {"tests", "support", "conftest"}
    reaching = {source.relative_to(ROOT).as_posix(): sorted(_imported(source) & test_modules)
                for source in sorted((ROOT / "scripts").glob("*.py"))}
    reaching = {name: modules for name, modules in reaching.items() if modules}
    assert not reaching, f"scripts import from tests/ (share it from scripts/ instead): {reaching}"


def test_lighthouse_takes_the_median_of_its_runs_not_the_best():
    assert LIGHTHOUSE_RUNS == 3
    one_low = [{"performance": 0.99, "seo": 1.0}, {"performance": 0.71, "seo": 1.0}, {"performance": 0.98, "seo": 1.0}]
    assert median_scores(one_low)["performance"] == 0.98
    twice_low = [{"performance": 0.99}, {"performance": 0.71}, {"performance": 0.80}]
    assert median_scores(twice_low)["performance"] == 0.80  # the best of them would pass at 0.99
    assert median_scores([{"seo": None}, {"seo": 1.0}, {"seo": 1.0}])["accessibility"] == 0.0  # not scored: 0
    with pytest.raises(ValueError, match="runs: 2 Lighthouse runs"):
        median_scores(one_low[:2])


#: Two helpers of one name are copies when their bodies (docstrings aside) are this alike.
NEAR_SAME = 0.6
#: A body shorter than this (in characters of code) is a thin call of a shared helper (a
#: fixture's `with page_without_errors(browser, url) as page: yield page`): such bodies look
#: alike by their shape, so two of them are copies only when they are the same to the letter.
THIN = 100
#: Two helpers of any names are copies when their bodies are the same to the letter and this long.
SAME_UNDER_ANOTHER_NAME = 30


def _helpers(module: Path) -> dict[str, str]:
    """A test module's top-level functions and classes (fixtures included, tests aside), each
    name with its body as source, its docstring left out."""
    helpers = {}
    for node in ast.parse(module.read_text(), filename=str(module)).body:
        if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef) and \
                not node.name.startswith(("test_", "Test")):
            body = node.body[1:] if ast.get_docstring(node) is not None else node.body
            helpers[node.name] = ast.unparse(ast.Module(body=body, type_ignores=[]))
    return helpers


def _alike(first: str, second: str) -> float | None:
    """How alike two helpers' bodies are, or None when they do not count as copies."""
    if first == second:
        return 1.0
    if min(len(first), len(second)) < THIN:
        return None
    ratio = difflib.SequenceMatcher(None, first, second).ratio()
    return ratio if ratio >= NEAR_SAME else None


def copied_helpers(root: Path) -> list[str]:
    """Each helper that two modules under `root` define with the same or a near-same body,
    and each body that two modules define under other names."""
    defined: dict[str, list[tuple[str, str]]] = {}
    for module in sorted(root.rglob("*.py")):
        for name, body in _helpers(module).items():
            defined.setdefault(name, []).append((module.relative_to(root).as_posix(), body))
    copies = []
    for name, places in sorted(defined.items()):
        for i, (first, first_body) in enumerate(places):
            copies += [f"{name}: {first} ~ {second} ({alike:.2f} alike)" for second, second_body in places[i + 1:]
                       if (alike := _alike(first_body, second_body)) is not None]
    by_body: dict[str, list[str]] = {}
    for name, places in defined.items():
        for module, body in places:
            if len(body) >= SAME_UNDER_ANOTHER_NAME:
                by_body.setdefault(body, []).append(f"{module}'s {name}")
    copies += [" ~ ".join(sorted(where)) + " (the same body)" for where in by_body.values()
               if len({place.split("'s ")[0] for place in where}) > 1 and len({place.split("'s ")[1] for place in where}) > 1]
    return copies


def test_no_helper_is_defined_in_two_test_modules():
    copies = copied_helpers(TESTS)
    assert not copies, "define each in tests/support/ once and import it:\n" + "\n".join(copies)


# ------------------------------------------------------------------ the review's leftovers

#: Where the product's code and its words live (the tests and the README say what it does too).
PRODUCT = ("physics_figures", "book/_ext", "book/_latex", "scripts", "tests")
SOURCE_ENDINGS = {".py", ".js", ".mjs", ".css", ".json", ".md", ".yml", ".sty"}


def _sources(*folders: str):
    """Each source file under the folders (generated, cached and vendored files aside), with its path."""
    for folder in folders:
        for path in sorted((ROOT / folder).rglob("*")):
            if path.suffix in SOURCE_ENDINGS and path.is_file() and not {"__pycache__", "node_modules", "vendor"} & set(
                    path.parts):
                yield path


def _lines_matching(pattern: re.Pattern, *folders: str, leave_out=()) -> list[str]:
    return [f"{path.relative_to(ROOT)}:{number}: {line.strip()}"
            for path in _sources(*folders) if path.relative_to(ROOT).as_posix() not in leave_out
            for number, line in enumerate(path.read_text(encoding="utf-8", errors="replace").splitlines(), 1)
            if pattern.search(line)]


#: questions.js is the page (the form, New numbers, the store); marking.js and the kinds'
#: markers are the engine. A sentence naming the engine (or what marks) that goes on to
#: questions.js, with no "page" and no closing bracket on the way, calls it the engine.
QUESTIONS_JS_AS_ENGINE = re.compile(r"(engine|marks with|applied by)(?:(?!page)[^.;:)]){0,60}\bquestions\.js")
#: A comment's line breaks and markers (#:, //, *), read as the space they stand for.
COMMENT_BREAK = re.compile(r"\n\s*(?:#:?|//|\*)?\s*")


def test_no_comment_calls_questions_js_the_marking_engine():
    found = [f"{path.relative_to(ROOT)}: ...{match[0]}"
             for path in [*_sources(*PRODUCT), ROOT / "README.md"]
             for match in QUESTIONS_JS_AS_ENGINE.finditer(COMMENT_BREAK.sub(" ", path.read_text(encoding="utf-8")))]
    assert not found, "the engine is marking.js and the kinds' markers; questions.js is the page:\n" + "\n".join(found)


def _body(function: ast.FunctionDef) -> str:
    body = function.body[1:] if ast.get_docstring(function) is not None else function.body
    return ast.unparse(ast.Module(body=body, type_ignores=[]))


def test_the_value_error_check_is_defined_once():
    """physics_figures/checks.py's require is the one check of a given's rule: no module
    writes its body again (there were four copies of it, each _require)."""
    one = _body(ast.parse(Path(checks.__file__).read_text()).body[-1])
    copies = [f"{path.relative_to(ROOT)}: {node.name}"
              for path in _sources("physics_figures", "book/_ext", "book/_latex", "scripts")
              if path.suffix == ".py" and path != Path(checks.__file__)
              for node in ast.walk(ast.parse(path.read_text()))
              if isinstance(node, ast.FunctionDef) and _body(node) == one]
    assert not copies, f"import physics_figures.checks.require instead: {copies}"


def test_source_date_epoch_has_one_value():
    """The Makefile exports SOURCE_DATE_EPOCH and physics_figures.reproducible holds it for a
    script run alone: the two agree, and no other file types the number."""
    exported = re.search(r"^export SOURCE_DATE_EPOCH \?= (\d+)$", (ROOT / "Makefile").read_text(), re.MULTILINE)
    assert exported and int(exported[1]) == SOURCE_DATE_EPOCH, exported
    typed = _lines_matching(re.compile(rf"\b{SOURCE_DATE_EPOCH}\b"), *PRODUCT,
                            leave_out={"physics_figures/reproducible.py"})
    assert not typed, f"read physics_figures.reproducible.SOURCE_DATE_EPOCH instead: {typed}"


def test_the_worksheets_use_no_private_helper_of_a_topic():
    """A sheet is built for any topic: physics_figures/worksheets imports nothing private
    from a topic's module (it took the working's number format from bank._common)."""
    reaching = [f"{path.relative_to(ROOT)}: {node.module}"
                for path in _sources("physics_figures/worksheets") if path.suffix == ".py"
                for node in ast.walk(ast.parse(path.read_text()))
                if isinstance(node, ast.ImportFrom) and node.module
                and any(part.startswith("_") for part in node.module.split(".")) and "bank" in node.module]
    assert not reaching, f"give it a public name outside the topic: {reaching}"
