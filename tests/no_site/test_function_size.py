"""Functions a reader can hold (issue 39, item 4): no function over 80 lines.

ESLint holds the JavaScript to it (max-lines-per-function 80, complexity 15: eslint.config.mjs)
and ruff the Python's paths and statements (C901 at 15, PLR0915 at 50: pyproject.toml), both in
`make check`. This test checks that those limits stay configured, and counts the lines of every
Python function itself, which no ruff rule does. What is not split yet is named here and in the
two configurations, and each list only shrinks: an entry that no longer needs its exemption fails.
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

# Python functions over MAX_LINES, not split yet: path -> function names. None is left (issue 39,
# item 4: the bank's last long templates and scripts/bench.py's main were split); it only shrinks.
PYTHON_LEFT: dict[str, set[str]] = {}


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
        name = path.relative_to(ROOT).as_posix()
        long = long_python_functions(path.read_text(encoding="utf-8"))
        if long:
            over[name] = {function for function, _, _ in long}
        new = {function for function, _, _ in long} - PYTHON_LEFT.get(name, set())
        assert not new, f"{name}: functions over {MAX_LINES} lines: {sorted(new)}"
    # The list of what is left only shrinks: a function split since is taken off it.
    for name, functions in PYTHON_LEFT.items():
        split = functions - over.get(name, set())
        assert not split, (
            f"{name}: {sorted(split)} now fit in {MAX_LINES} lines: take them off PYTHON_LEFT"
        )


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


def test_the_javascript_left_to_split_exists():
    """Each file exempted in eslint.config.mjs (LEFT_TO_SPLIT) still exists; none else is."""
    config = eslint_config()
    left = re.search(r"const LEFT_TO_SPLIT = \[(.*?)\];", config, re.DOTALL)
    assert left, "eslint.config.mjs names what is left to split in LEFT_TO_SPLIT"
    files = re.findall(r'"([^"]+)"', left.group(1))
    assert all((ROOT / name).is_file() for name in files), files
    offs = re.findall(r'"max-lines-per-function": "off"', config)
    assert len(offs) == 1, "only LEFT_TO_SPLIT may turn the function limit off"


def test_ruff_limits_every_python_function():
    lint = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["tool"]["ruff"][
        "lint"
    ]
    assert {"C901", "PLR0915"} <= set(lint["extend-select"])
    assert lint["mccabe"]["max-complexity"] == MAX_COMPLEXITY
    assert lint["pylint"]["max-statements"] == MAX_STATEMENTS
    # an exemption is only for a file named as left to split, and only for these two rules
    for name, rules in lint.get("per-file-ignores", {}).items():
        assert (ROOT / name).is_file(), name
        assert name in PYTHON_LEFT, f"{name} is exempt from {rules} in pyproject.toml but not left to split"
        assert set(rules) <= {"C901", "PLR0915"}, (name, rules)
