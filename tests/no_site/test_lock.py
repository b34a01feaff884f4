"""pyproject.toml declares the Python dependencies; requirements.txt is their lock.

`make lock` writes the lock with pip-compile: every package the declared ones need, pinned
with its hashes, each with a `# via` comment naming what needs it. The fast tests here read
both files (no network, in `make check`) and fail when they disagree; the `network` test runs
`make lock` into a temporary file and fails when pip-compile would write anything else.
"""

from __future__ import annotations

import re
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

import pytest
from packaging.requirements import Requirement
from packaging.utils import canonicalize_name
from packaging.version import Version

ROOT = Path(__file__).resolve().parents[2]
PYPROJECT = ROOT / "pyproject.toml"
LOCK = ROOT / "requirements.txt"
#: How pip-compile names pyproject.toml in a `# via` comment.
PROJECT_VIA = "physics-figures (pyproject.toml)"


@dataclass
class Pin:
    name: str
    version: str
    hashes: list[str] = field(default_factory=list)
    via: list[str] = field(default_factory=list)


def declared(pyproject_text: str) -> dict[str, Requirement]:
    """Every dependency pyproject.toml declares: the package's own and each extra's."""
    project = tomllib.loads(pyproject_text)["project"]
    lines = list(project.get("dependencies", []))
    for extra in project.get("optional-dependencies", {}).values():
        lines += extra
    requirements = [Requirement(line) for line in lines]
    return {canonicalize_name(r.name): r for r in requirements}


def parse_lock(text: str) -> dict[str, Pin]:
    """requirements.txt as pip-compile writes it: `name==version \\`, its `--hash=` lines, then
    `# via x` or `# via` followed by `#   x` lines. Any other requirement line is an error."""
    pins: dict[str, Pin] = {}
    current: Pin | None = None
    in_via = False
    for number, raw in enumerate(text.splitlines(), 1):
        line = raw.strip()
        if not line:
            current, in_via = None, False
        elif raw.startswith("    --hash=") and current:
            current.hashes.append(line.removeprefix("--hash=").rstrip(" \\"))
        elif line.startswith("# via") and current:
            rest = line.removeprefix("# via").strip()
            current.via += [rest] if rest else []
            in_via = True
        elif line.startswith("#   ") and current and in_via:
            current.via.append(line.removeprefix("#").strip())
        elif line.startswith("#"):
            current, in_via = None, False
        else:
            pin = re.fullmatch(r"([A-Za-z0-9][A-Za-z0-9._-]*)==([^\s\\;]+)\s*\\?", line)
            assert pin, f"requirements.txt line {number} is not a pin (name==version): {raw!r}"
            current, in_via = Pin(canonicalize_name(pin[1]), pin[2]), False
            assert current.name not in pins, f"requirements.txt pins {current.name} twice"
            pins[current.name] = current
    return pins


def disagreements(pyproject_text: str, lock_text: str) -> list[str]:
    """What is wrong between the declared dependencies and the lock, in words (empty: they agree)."""
    wanted = declared(pyproject_text)
    pins = parse_lock(lock_text)
    problems = []
    for name, requirement in sorted(wanted.items()):
        if name not in pins:
            problems.append(f"{requirement} is declared in pyproject.toml but not in the lock")
        elif Version(pins[name].version) not in requirement.specifier:
            problems.append(f"the lock pins {name}=={pins[name].version}, which {requirement} excludes")
    for name, pin in sorted(pins.items()):
        if not pin.hashes:
            problems.append(f"{name}=={pin.version} has no --hash")
        if not pin.via:
            problems.append(f"{name}=={pin.version} has no `# via`: nothing says what needs it")
        if PROJECT_VIA in pin.via and name not in wanted:
            problems.append(f"the lock says pyproject.toml needs {name}, and pyproject.toml does not declare it")
    # What the declared dependencies need, following `# via` backwards: a pin outside it is needed by
    # nothing (left behind when a dependency went, or written by hand).
    needed, todo = set(), [name for name in wanted if name in pins]
    while todo:
        name = todo.pop()
        if name not in needed:
            needed.add(name)
            todo += [other for other, pin in pins.items()
                     if any(canonicalize_name(via) == name for via in pin.via if via != PROJECT_VIA)]
    for name in sorted(set(pins) - needed):
        problems.append(f"the lock pins {name}=={pins[name].version}, which nothing declared needs "
                        f"(via: {', '.join(pins[name].via) or 'nothing'})")
    return problems


def test_the_lock_agrees_with_pyproject():
    problems = disagreements(PYPROJECT.read_text(), LOCK.read_text())
    assert not problems, "requirements.txt and pyproject.toml disagree; run `make lock`:\n" + "\n".join(problems)


def test_the_lock_is_pip_compiles_own():
    header = LOCK.read_text().split("\n\n")[0]
    assert "autogenerated by pip-compile" in header
    assert "--generate-hashes" in header and "--all-extras" in header


# The checker itself, on small locks: each kind of disagreement is caught.
PYPROJECT_TOY = """
[project]
name = "physics-figures"
dependencies = ["numpy==2.4.6"]
[project.optional-dependencies]
test = ["pytest>=9"]
"""
LOCK_TOY = """#
# This file is autogenerated by pip-compile with Python 3.11
#
iniconfig==2.1.0 \\
    --hash=sha256:aaaa
    # via pytest
numpy==2.4.6 \\
    --hash=sha256:bbbb \\
    --hash=sha256:cccc
    # via physics-figures (pyproject.toml)
pytest==9.2.0 \\
    --hash=sha256:dddd
    # via
    #   physics-figures (pyproject.toml)
    #   pytest-cov
"""


def test_the_checker_passes_a_lock_that_agrees():
    assert disagreements(PYPROJECT_TOY, LOCK_TOY) == []
    assert parse_lock(LOCK_TOY)["pytest"].via == [PROJECT_VIA, "pytest-cov"]


@pytest.mark.parametrize(("pyproject", "lock", "problem"), [
    (PYPROJECT_TOY.replace('"numpy==2.4.6"', '"numpy==2.4.6", "sympy"'), LOCK_TOY,
     "sympy is declared in pyproject.toml but not in the lock"),
    (PYPROJECT_TOY.replace("2.4.6", "2.4.7"), LOCK_TOY, "the lock pins numpy==2.4.6, which numpy==2.4.7 excludes"),
    (PYPROJECT_TOY.replace(">=9", "<9"), LOCK_TOY, "the lock pins pytest==9.2.0, which pytest<9 excludes"),
    (PYPROJECT_TOY, LOCK_TOY.replace(" \\\n    --hash=sha256:aaaa", ""), "iniconfig==2.1.0 has no --hash"),
    (PYPROJECT_TOY, LOCK_TOY + "six==1.17.0 \\\n    --hash=sha256:eeee\n    # via python-dateutil\n",
     "the lock pins six==1.17.0, which nothing declared needs (via: python-dateutil)"),
    (PYPROJECT_TOY, LOCK_TOY + "six==1.17.0 \\\n    --hash=sha256:eeee\n",
     "six==1.17.0 has no `# via`"),
    (PYPROJECT_TOY.replace(', "pytest>=9"', "").replace('"pytest>=9"', ""), LOCK_TOY,
     "the lock says pyproject.toml needs pytest, and pyproject.toml does not declare it"),
])
def test_the_checker_finds_each_disagreement(pyproject, lock, problem):
    assert any(found.startswith(problem) for found in disagreements(pyproject, lock)), \
        disagreements(pyproject, lock)


def test_a_line_that_is_not_a_pin_is_an_error():
    with pytest.raises(AssertionError, match="not a pin"):
        parse_lock("-e .\n")
    with pytest.raises(AssertionError, match="not a pin"):
        parse_lock("numpy>=2 \\\n    --hash=sha256:ffff\n")
