"""Every program the build, the tests and the scripts run is one that `make` installs.

scripts/debian-programs.txt is the one declared table (program -> make step -> Debian
packages). scripts/ensure-debian-packages reads it, and the Makefile calls it for each
step; these tests read the code's own calls (Python's syntax tree, not a grep) and check
that nothing is run that the table leaves out, so a fresh machine has everything.
"""

from __future__ import annotations

import ast
import re
import subprocess
import sys
from functools import cache
from pathlib import Path

from support.programs import ENSURE, TABLE, table

ROOT = Path(__file__).resolve().parents[2]
#: Where code that runs programs lives.
SOURCES = ("tests", "scripts", "book/_ext", "book/_latex", "physics_figures")
#: On every machine of this kind before `make` runs (Python, make, git, node from the base image).
BASE_PROGRAMS = {"python", "python3", "make", "git", "bash", "sh"}
SUBPROCESS_CALLS = {"run", "Popen", "check_output", "check_call", "call"}


def _call_name(call: ast.Call) -> str:
    func = call.func
    return func.attr if isinstance(func, ast.Attribute) else getattr(func, "id", "")


def _first_word(node: ast.AST) -> str | None:
    """The program of a command: "x" or ["x", ...] or ("x", ...)."""
    if isinstance(node, ast.List | ast.Tuple) and node.elts:
        node = node.elts[0]
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return node.value
    return None


def wrappers_in(source: Path) -> set[str]:
    """The functions a file defines around a subprocess call: def poppler(*command): subprocess.run(command)."""
    tree = ast.parse(source.read_text(), filename=str(source))
    return {function.name for function in ast.walk(tree) if isinstance(function, ast.FunctionDef) and any(
        isinstance(n, ast.Call) and _call_name(n) in SUBPROCESS_CALLS for n in ast.walk(function))}


def programs_run_by(source: Path, wrappers: frozenset[str] = frozenset()) -> set[str]:
    """Programs a Python file runs: subprocess calls (and wrappers around them, its own or
    `wrappers`, tests/support's) whose command starts with a literal, shutil.which("x"), and
    absolute paths of programs ("/usr/bin/x") it names."""
    tree = ast.parse(source.read_text(), filename=str(source))
    runners = set(SUBPROCESS_CALLS) | wrappers_in(source) | wrappers
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Call) and node.args:
            name = _call_name(node)
            if name == "which" or name in runners:
                word = _first_word(node.args[0])
                if word:
                    found.add(Path(word).name if word.startswith("/") else word)
        elif (isinstance(node, ast.Constant) and isinstance(node.value, str)
              and re.fullmatch(r"/usr/s?bin/[\w.+-]+", node.value)):
            found.add(Path(node.value).name)
    return found


@cache  # two tests read it: the sources are parsed once (the tests only read the result)
def all_programs() -> dict[str, set[str]]:
    """program -> the files that run it."""
    runs: dict[str, set[str]] = {}
    shared = frozenset().union(*(wrappers_in(source) for source in (ROOT / "tests" / "support").glob("*.py")))
    for folder in SOURCES:
        for source in sorted((ROOT / folder).rglob("*.py")):
            if ".venv" in source.parts:
                continue
            for program in programs_run_by(source, shared):
                runs.setdefault(program, set()).add(source.relative_to(ROOT).as_posix())
    return runs


def venv_programs() -> set[str]:
    """What requirements.txt puts in the venv's bin/ (jupyter-book, ruff, sphinx-build, ...)."""
    return {path.name for path in Path(sys.executable).parent.iterdir()}


def test_the_scan_sees_the_programs_the_code_is_known_to_run():
    # Guards the scanner itself: these calls exist today, in these shapes.
    runs = all_programs()
    assert "tests/site/test_pdf.py" in runs["pdftotext"]  # a shared wrapper: poppler("pdftotext", ...)
    assert "book/_ext/site_assets/stylesheets.py" in runs["node"]  # shutil.which("node")
    assert {"chromium", "chromium-headless-shell"} <= set(runs)  # scripts/browser.py


def test_every_program_the_code_runs_is_in_the_table():
    known = set(table()) | BASE_PROGRAMS | venv_programs()
    missing = {program: sorted(files) for program, files in all_programs().items() if program not in known}
    assert not missing, (f"these programs are run but {TABLE.relative_to(ROOT)} does not say which "
                         f"Debian package installs them: {missing}")


def test_the_install_script_reads_the_table():
    for step in {step for step, _ in table().values()}:
        listed = subprocess.run([str(ENSURE), "--list", step], capture_output=True, text=True, check=True).stdout
        rows = {line.split()[0]: line.split()[1:] for line in listed.splitlines()}
        expected = {program: packages for program, (s, packages) in table().items() if s == step}
        assert rows == expected, f"step {step}: the script lists {rows}, the table says {expected}"


def _make_graph() -> tuple[dict[str, set[str]], dict[str, list[str]]]:
    """Makefile targets -> prerequisites (and targets a recipe runs with $(MAKE)), and recipes."""
    needs: dict[str, set[str]] = {}
    recipes: dict[str, list[str]] = {}
    target = None
    for line in (ROOT / "Makefile").read_text().splitlines():
        if line.startswith("\t") and target:
            recipes[target].append(line.strip())
            # $(MAKE) [options] TARGET... (up to the shell's next operator)
            for made in re.finditer(r"\$\(MAKE\)((?:\s+[\w./=-]+)+)", line):
                needs[target].update(w for w in made[1].split() if not w.startswith("-") and "=" not in w)
        elif (rule := re.match(r"^([\w./$()-]+):(?!=)\s*(.*)$", line)) and not line.startswith("."):
            target = rule[1]
            needs.setdefault(target, set()).update(rule[2].split())
            recipes.setdefault(target, [])
        elif not line.startswith("\t"):
            target = None if line.strip() and not line.startswith("#") else target
    return needs, recipes


def _reachable(needs: dict[str, set[str]], start: str) -> set[str]:
    seen, todo = set(), [start]
    while todo:
        target = todo.pop()
        if target in seen:
            continue
        seen.add(target)
        todo.extend(need.replace("$(VENV)", ".venv") for need in needs.get(target, ()))
    return seen


def test_make_test_installs_every_step_of_the_table():
    needs, recipes = _make_graph()
    reached = _reachable(needs, "test")
    for step in sorted({step for step, _ in table().values()}):
        installers = [t for t, lines in recipes.items()
                      if any(re.search(rf"scripts/ensure-debian-packages {step}$", r) for r in lines)]
        assert installers, f"no Makefile recipe runs `scripts/ensure-debian-packages {step}`"
        assert set(installers) & reached, (f"`make test` never reaches the targets that install step "
                                           f"{step} ({installers})")
