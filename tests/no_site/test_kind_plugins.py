"""Part kinds are whole plug-ins (issue 38, "What to build" 1): a kind is one Python module and one
JS module, found through one registry per language (physics_figures.parts.KINDS and
QuestionKinds in book/_ext/questions/static/question-kinds.js), and no other code branches on a
kind's name: it asks the part's kind (its hooks and properties) instead. The scan below reads the
book's code (physics_figures, book/_ext, scripts; Python and JavaScript) and fails on any
comparison with a kind's name, any list of kind names and any look-up of a kind by its name
outside the kinds' own modules and the two registries. The bank's templates name their kinds
as data (``Template(..., ("graph", "numeric"), ...)``): that is what a template asks, not a branch."""

from __future__ import annotations

import inspect
import re
import subprocess
from pathlib import Path

import pytest

from physics_figures import parts

ROOT = Path(__file__).resolve().parents[2]
SCANNED = ("physics_figures", "book/_ext", "scripts")
REGISTRIES = (ROOT / "physics_figures" / "parts" / "__init__.py",
              ROOT / "book" / "_ext" / "questions" / "static" / "question-kinds.js")


def kind_modules() -> set[Path]:
    """Each registered kind's two modules: its class's file and its browser twin."""
    found = set()
    for kind in parts.KINDS.values():
        found.add(Path(inspect.getsourcefile(kind)).resolve())
        found.add(Path(kind.browser_script).resolve())
    return found


def branches(text: str, names) -> list[str]:
    """The places in ``text`` (Python or JavaScript) that branch on, list or look up a kind by
    one of ``names``: each as the line it is on."""
    name = "|".join(re.escape(n) for n in sorted(names, key=len, reverse=True))
    quoted = rf"""(?P<q>["'])(?:{name})(?P=q)"""
    patterns = [
        # a comparison with a kind's name, on a line that speaks of a kind: part.kind == "mcq",
        # "graph" !== p.kind, kind === 'explain'
        rf"kind[\w\[\]\"'.]*\)?\s*[!=]==?\s*{quoted}",
        rf"{quoted}\s*[!=]==?\s*[\w.\[\]\"']*kind",
        # membership: kind in ("numeric", "graph"), "graph" in t.kinds, kinds.indexOf("mcq")
        rf"kind[\w\[\]\"'.]*\)?\s+(?:not\s+)?in\s*[(\[{{][^)\]}}]*{quoted}",
        rf"{quoted}\s+(?:not\s+)?in\s+[\w.\[\]\"']*kind",
        rf"kind\w*\.(?:indexOf|includes)\(\s*{quoted}",
        rf"\[[^\]]*{quoted}[^\]]*\]\s*\.\s*(?:indexOf|includes)\(",
        # a switch's case
        rf"\bcase\s+{quoted}",
        # a kind by its name: KINDS["numeric"], QuestionKinds.get("mcq"), kinds: ["mcq"],
        # the default kind of a part that names none (part.kind || "numeric", .get("kind", "numeric"))
        rf"KINDS\s*\[\s*{quoted}",
        rf"\bKINDS\.(?:{name})\b",
        rf"Kinds\.(?:get|of)\(\s*{{?\s*(?:kind:\s*)?{quoted}",
        rf"kinds\s*[:=]\s*[\[(]\s*{quoted}",
        rf"kind\W{{0,3}}\s*(?:\|\||\?\?|\bor\b|,)\s*{quoted}",
        # a fieldset found by its kind's name: [data-kind="graph"]
        rf"data-kind\s*=\s*\\?{quoted}",
        rf"data-kind\s*=\s*\\?[\"']?(?:{name})\b",
    ]
    # a list of the kinds: a tuple, list or set of strings that holds two kind names or more
    strings = r"""[(\[{]\s*(?:(["'])[^"'\n]*\1\s*,\s*)+(["'])[^"'\n]*\2\s*,?\s*[)\]}]"""
    collections = [match for match in re.finditer(strings, text)
                   if len(re.findall(quoted, match[0])) >= 2]
    found = [_line(text, match) for match in collections]
    for pattern in patterns:
        found += [_line(text, match) for match in re.finditer(pattern, text)]
    return found


def _line(text: str, match: re.Match) -> str:
    """The line a match starts on."""
    start = text.rfind("\n", 0, match.start()) + 1
    end = text.find("\n", match.start())
    return text[start:end if end >= 0 else None].strip()


def _without_template_kinds(text: str) -> str:
    """The bank's templates' kinds, data that says what a template asks, blanked out:
    Template("key", "type", ("graph", "numeric"), ...) and kinds=(...)."""
    text = re.sub(r"""(Template\(\s*["'][^"']*["'],\s*["'][^"']*["'],\s*)\([^)]*\)""", r"\1()", text)
    return re.sub(r"\bkinds\s*=\s*\([^)]*\)", "kinds=()", text)


def scanned_files() -> list[Path]:
    skip = kind_modules() | {path.resolve() for path in REGISTRIES}
    files = []
    for folder in SCANNED:
        for path in sorted((ROOT / folder).rglob("*")):
            if path.suffix in (".py", ".js") and "node_modules" not in path.parts and path.resolve() not in skip:
                files.append(path)
    return files


def test_no_code_outside_the_kinds_branches_on_a_kinds_name():
    files = scanned_files()
    assert len(files) > 100, "the scan reads the book's code"
    assert any(path.suffix == ".js" for path in files) and any(path.suffix == ".py" for path in files)
    offences = [f"{path.relative_to(ROOT)}: {line}" for path in files
                for line in branches(_without_template_kinds(path.read_text(encoding="utf-8")), parts.KINDS)]
    assert not offences, "branches on a kind's name outside the kinds:\n" + "\n".join(offences)


@pytest.mark.parametrize("line", [
    'if part.kind == "mcq":',
    "if (part.kind === 'explain') {",
    'space = 0.6 if part.kind == "graph" else 1.5',
    'if kind not in ("mcq", "explain"):',
    'jobs = [t for t in templates if "graph" in t.kinds]',
    'if (KINDS.indexOf(part.kind || "numeric") < 0) return [];',
    'var KINDS = ["numeric", "graph"];',
    'case "mcq":',
    'kind = part.get("kind", "numeric")',
    'var outcome = KINDS.numeric.outcome;',
    '1: { name: "Paper 1", kinds: ["mcq"] },',
    "question.querySelectorAll('fieldset.q-part[data-kind=\"graph\"] input.q-value')",
    'return template.kinds.length === 1 && template.kinds[0] === "mcq";',
    'KIND_SCRIPTS = ("numeric", "choice", "explain")',
])
def test_the_scan_finds_each_way_of_branching_on_a_kinds_name(line):
    """Each way the code branched on a kind's name before the kinds were plug-ins (issue 38:
    "47 lines in 12 files"), as it was written, is found."""
    assert branches(line, parts.KINDS), line


@pytest.mark.parametrize("line", [
    'if part.reads_graph:',
    'Template("quick-check-3", "drag", ("numeric",), "Quick check 3", skydiver_parachute_opens,',
    'return new Date().toLocaleDateString("en-GB", { day: "numeric", month: "long" });',
    '<input inputmode="numeric">',
    'if kind == "explosion":',
    'ASKS = ("calculate", "show that", "explain", "state")',
    'if any(item.get("graph") for item in asked):',
])
def test_the_scan_leaves_what_is_no_branch_on_a_kind(line):
    assert not branches(_without_template_kinds(line), parts.KINDS), line


# ---- a kind of a test's own, added with no change to a shared file ----------------------------

KEY = "toy-floats"


def test_no_shared_file_names_the_kind_of_the_fixtures():
    """The toy kind took no edit to a shared file: nothing outside tests/ names it, its modules
    or its topic."""
    tracked = subprocess.run(["git", "ls-files", "--cached", "--others", "--exclude-standard"], cwd=ROOT,
                             capture_output=True, text=True, check=True).stdout.split()
    shared = [ROOT / name for name in tracked if not name.startswith("tests/") and (ROOT / name).is_file()]
    assert len(shared) > 100
    for path in shared:
        text = path.read_text(encoding="utf-8", errors="ignore")
        for name in ("yesno", "toy_kind", "toy_topic", KEY):
            assert name not in text, f"{path.relative_to(ROOT)} names {name}"
