"""The tests' house (issue 39, items 5 and 6): no product script imports a test, and a
measured figure is the median of its runs, never the best of them."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest
from browser import LIGHTHOUSE_RUNS, median_scores

ROOT = Path(__file__).resolve().parents[1]
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
    test_modules = {path.stem for path in TESTS.glob("*.py")} | {"tests", "support", "conftest"}
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


@pytest.mark.site
def test_question_data_keeps_within_40_kb_gzip_a_template(site_dir):
    """A template's question data (issue 39, "Lighter first visits"): its inline data on the page
    that asks it and the file of variants New numbers (or the mock test) loads, gzip as a host
    sends them, at most QUESTION_DATA_BYTES. The forms in the files are the mock test's, so only
    a template it can ask carries one (an explanation's form never did any work there)."""
    import gzip
    import re

    from browser import QUESTION_DATA_BYTES

    inline: dict[str, bytes] = {}
    for page in sorted(site_dir.rglob("*.html")):
        text = page.read_text(encoding="utf-8")
        for data in re.findall(r'<script type="application/json" class="q-data">(.*?)</script>', text, re.DOTALL):
            key = re.search(r'"id": "([^"]+)"', data)[1]
            inline.setdefault(key, data.encode())
    files = {path.stem: path.read_bytes() for path in (site_dir / "_static" / "questions").glob("*.js")}
    assert files, "no question data file"
    sizes = {key: len(gzip.compress(inline.get(key, b""), mtime=0)) + len(gzip.compress(data, mtime=0))
             for key, data in files.items()}
    over = {key: size for key, size in sizes.items() if size > QUESTION_DATA_BYTES}
    assert not over, f"question data over {QUESTION_DATA_BYTES:,} B gzip: {over}"
    explained = [key for key, data in files.items() if b"q-explain" in data and b"QuestionForms" in data]
    assert not explained, f"an explanation's form in its data file, which the mock test never draws: {explained}"
