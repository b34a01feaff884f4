"""The git hooks (.pre-commit-config.yaml) run what `make check` runs: the same commands, word
for word once the Makefile's variables are filled in, so a commit the hooks pass is one
`make check` passes."""

from __future__ import annotations

import re
import shlex
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parents[2]


def makefile_variables(text: str) -> dict[str, str]:
    return {m[1]: m[2].strip() for m in re.finditer(r"^(\w+)\s*[:?]?=[ \t]*(.*)$", text, re.MULTILINE)}


def recipe(text: str, target: str) -> str:
    """A target's recipe, its continued lines joined."""
    body = re.search(rf"^{target}:.*\n((?:\t.*\n)+)", text, re.MULTILINE)
    assert body, f"the Makefile has no recipe for {target}"
    return body[1].replace("\\\n", " ")


def check_commands(text: str) -> set[tuple[str, ...]]:
    """The tools `make check` runs (and its jslint step), as argument lists."""
    variables = makefile_variables(text)
    commands = set()
    for target in ("check", "jslint"):
        for command in re.split(r"\|\||&&|[;&\n]|\s[{}]\s", recipe(text, target)):
            if command.strip().startswith("$(MAKE)"):  # the jslint step, read on its own
                continue
            while re.search(r"\$\((\w+)\)", command):  # BIN := $(VENV)/bin: fill in until none is left
                command = re.sub(r"\$\((\w+)\)", lambda m: variables[m[1]], command)
            command = command.strip()
            if command.startswith((".venv/", "node_modules/")):
                commands.add(tuple(shlex.split(command)))
    return commands


def hook_commands() -> dict[str, tuple[str, ...]]:
    config = yaml.safe_load((ROOT / ".pre-commit-config.yaml").read_text())
    return {hook["id"]: tuple(shlex.split(hook["entry"]))
            for repo in config["repos"] for hook in repo["hooks"]}


def test_the_check_recipe_is_read():
    commands = check_commands((ROOT / "Makefile").read_text())
    assert {command[0] for command in commands} == {
        ".venv/bin/ruff", ".venv/bin/python", "node_modules/.bin/eslint", "node_modules/.bin/prettier"}


def test_the_hooks_run_what_make_check_runs():
    hooks = hook_commands()
    check = check_commands((ROOT / "Makefile").read_text())
    missing = check - set(hooks.values())
    assert not missing, f"make check runs these and no pre-commit hook does: {sorted(missing)}"
    # every hook is one of make check's commands, or the lock test on its own (a part of them)
    extra = {hook: command for hook, command in hooks.items()
             if command not in check and hook != "lock"}
    assert not extra, f"these hooks run what make check does not: {extra}"
    assert "tests/no_site/test_lock.py" in hooks["lock"]


def test_the_hooks_use_no_outside_repository():
    # only PyPI and npm are reachable from these machines: a hook from GitHub cannot be fetched
    config = yaml.safe_load((ROOT / ".pre-commit-config.yaml").read_text())
    assert [repo["repo"] for repo in config["repos"]] == ["local"]
    assert {hook["language"] for hook in config["repos"][0]["hooks"]} == {"system"}
