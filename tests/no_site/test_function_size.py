"""Functions a reader can hold (issue 39, item 4): no function over 80 lines.

ESLint holds the JavaScript to it (max-lines-per-function 80, complexity 15: eslint.config.mjs)
and ruff the Python's paths and statements (C901 at 15, PLR0915 at 50: pyproject.toml), both in
`make check`. This test checks that those limits stay configured, and counts the lines of every
Python function itself, which no ruff rule does. No file is exempt: neither configuration turns
a limit off for a file, and no source file turns one off in a comment.
"""

import ast
import re
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
MAX_LINES = 80
MAX_COMPLEXITY = 15
MAX_STATEMENTS = 50
# The Python that ruff checks (the Makefile's LINTED).
PYTHON_DIRS = ("physics_figures", "tests", "book/_ext", "book/_latex", "scripts")
# The JavaScript that ESLint checks: the site's scripts and the Node tests.
JS_DIRS = ("book/_ext", "tests", "scripts", "physics_figures")
LIMITS = ("max-lines-per-function", "complexity", "C901", "PLR0915")


def long_python_functions(source, limit=MAX_LINES):
    """(name, first line, lines) of each function in source longer than limit lines."""
    found = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            lines = node.end_lineno - node.lineno + 1
            if lines > limit:
                found.append((node.name, node.lineno, lines))
    return found


def python_files():
    for folder in PYTHON_DIRS:
        yield from sorted((ROOT / folder).rglob("*.py"))


def test_the_line_count_finds_a_long_function():
    body = "\n".join(f"    x{i} = {i}" for i in range(MAX_LINES))
    source = f"def long():\n{body}\n\ndef short():\n    return 1\n"
    assert long_python_functions(source) == [("long", 1, MAX_LINES + 1)]


def test_no_python_function_is_over_80_lines():
    over = {}
    for path in python_files():
        long = long_python_functions(path.read_text(encoding="utf-8"))
        if long:
            over[path.relative_to(ROOT).as_posix()] = [(name, lines) for name, _, lines in long]
    assert not over, f"functions over {MAX_LINES} lines (name, lines): {over}"


def eslint_config():
    return (ROOT / "eslint.config.mjs").read_text(encoding="utf-8")


def test_eslint_limits_every_javascript_function():
    config = eslint_config()
    assert re.search(
        r'files: \["\*\*/\*\.js", "\*\*/\*\.mjs"\],\s*rules: \{\s*'
        r'"max-lines-per-function": \["error", \{ max: ' + str(MAX_LINES) + r" \}\],\s*"
        r'complexity: \["error", ' + str(MAX_COMPLEXITY) + r"\],",
        config,
    ), (
        "eslint.config.mjs must hold every .js and .mjs file to 80 lines and complexity 15 a function"
    )


def test_no_file_turns_a_limit_off():
    """Neither ESLint's configuration nor a comment in a source file turns a function limit off."""
    offs = re.findall(r'"(?:max-lines-per-function|complexity)": "off"', eslint_config())
    assert not offs, f"eslint.config.mjs turns a function limit off: {offs}"
    sources = [path for folder in JS_DIRS for pattern in ("*.js", "*.mjs") for path in (ROOT / folder).rglob(pattern)]
    sources += list(python_files())
    turned_off = [
        path.relative_to(ROOT).as_posix()
        for path in sources
        if re.search(r"(eslint-disable|noqa)[^\n]*(" + "|".join(LIMITS) + ")", path.read_text(encoding="utf-8"))
    ]
    assert not turned_off, f"a comment turns a function limit off in: {turned_off}"


def test_ruff_limits_every_python_function():
    lint = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["tool"]["ruff"][
        "lint"
    ]
    assert {"C901", "PLR0915"} <= set(lint["extend-select"])
    assert lint["mccabe"]["max-complexity"] == MAX_COMPLEXITY
    assert lint["pylint"]["max-statements"] == MAX_STATEMENTS
    exempt = {name: rules for name, rules in lint.get("per-file-ignores", {}).items()
              if {"C901", "PLR0915"} & set(rules)}
    assert not exempt, f"pyproject.toml exempts files from the function limits: {exempt}"
