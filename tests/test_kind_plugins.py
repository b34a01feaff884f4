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
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from physics_figures import parts

ROOT = Path(__file__).resolve().parents[1]
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

FIXTURE = ROOT / "tests" / "fixtures" / "toy_kind"
BIN = Path(sys.executable).parent
#: The fixture's topic module (and its kind's module beside it) are found as any topic is: on
#: the Python path. The kind is registered only in the processes that load the topic.
ENV = {**os.environ, "PYTHONPATH": os.pathsep.join(filter(None, [str(FIXTURE), os.environ.get("PYTHONPATH")]))}
KEY = "toy-floats"


def run(*command: str) -> subprocess.CompletedProcess:
    done = subprocess.run(command, env=ENV, capture_output=True, text=True, check=False, timeout=600)
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    return done


@pytest.fixture(scope="module")
def toy_site(tmp_path_factory) -> Path:
    """The toy kind's book, built strictly (any warning fails) outside the fixture."""
    out = tmp_path_factory.mktemp("toy-kind")
    run(str(BIN / "jupyter-book"), "build", str(FIXTURE), "-n", "-W", "--keep-going", "--path-output", str(out))
    return out / "_build" / "html"


@pytest.mark.build
def test_a_kind_of_the_fixtures_is_on_its_page_with_its_script(toy_site):
    page = (toy_site / "toy" / "practice.html").read_text(encoding="utf-8")
    assert f'data-question="{KEY}"' in page
    assert page.count('class="q-yesno"') == 2, "its form: the kind's own form_html"
    assert re.search(r'<fieldset class="q-part" data-part="a" data-kind="yesno">', page)
    assert re.search(r'<script defer="defer" src="\.\./_static/question-kinds/yesno\.js', page), "its browser twin"
    shipped = toy_site / "_static" / "question-kinds" / "yesno.js"
    assert shipped.read_bytes() == (FIXTURE / "yesno.js").read_bytes()


@pytest.mark.build
@pytest.mark.browser
def test_a_kind_of_the_fixtures_is_marked_in_the_browser(toy_site):
    from browser import open_browser, serve_site

    with serve_site(toy_site) as base, open_browser() as browser:
        page = browser.new_page()
        errors = []  # the questions' scripts throw nothing (the bare theme's own thebe clash is not ours)
        page.on("pageerror", lambda e: "/_static/" in (e.stack or "") and "thebe" not in (e.stack or "")
                and errors.append(str(e)))
        page.goto(f"{base}/toy/practice.html", wait_until="load")
        # variant 0: a block of oak, 750 kg m^-3, floats (toy_topic.BODIES)
        page.check(f"#q-{KEY}-a-yes")
        page.click("button.q-check")
        assert page.locator(".q-score").inner_text() == "1/1 mark"
        page.check(f"#q-{KEY}-a-no")
        page.click("button.q-check")
        assert page.locator(".q-score").inner_text() == "0/1 mark"
        assert "Not right: its density, 750" in page.locator(f"#q-{KEY}-a-feedback").inner_text()
        assert not errors, errors


@pytest.mark.build
def test_a_kind_of_the_fixtures_is_on_a_worksheet_and_in_its_key(tmp_path):
    """The LaTeX sheet and key (typeset by xelatex) and the sheet builder's HTML sheet and key."""
    run(str(BIN / "python"), "-m", "physics_figures.worksheets", "--topic", "toy_topic", "--templates", KEY,
        "--versions", "1", "--out", str(tmp_path))
    sheet = (tmp_path / ".tex" / "worksheet-A" / "worksheet-A.tex").read_text(encoding="utf-8")
    key = (tmp_path / ".tex" / "worksheet-A" / "worksheet-key-A.tex").read_text(encoding="utf-8")
    assert "does it float?\\par Answer (yes or no): \\answerline{2cm}\\partmarks{1}" in sheet
    assert re.search(r"\\textbf\{(Yes|No): its density, \d+~kg~m⁻³, is (less|more) than water's", key)
    text = subprocess.run(["pdftotext", str(tmp_path / "worksheet-A.pdf"), "-"], capture_output=True, text=True,
                          check=True).stdout
    assert "Answer (yes or no):" in text
    written = run(str(BIN / "python"), "-c", (
        "import toy_topic\n"
        "from physics_figures.worksheets.html import key_body, sheet_body\n"
        "question = next(q for q in toy_topic.TOPIC.templates[0].variants if 'steel bolt' in q.text)\n"
        "print(sheet_body(question))\nprint(key_body(question))")).stdout
    assert '<p class="sb-answer">Answer (yes or no): <span class="sb-box"></span>' in written
    # it sinks: the key's answer, a number tied to its unit
    assert re.search(r"<strong>No: its density, 7800\xa0kg\xa0m⁻³, is more than water's, 1000\xa0kg\xa0m⁻³\.</strong>",
                     written)


@pytest.mark.build
def test_a_kind_of_the_fixtures_is_in_the_moodle_export(tmp_path):
    from moodle_format import check_file

    xml = tmp_path / "toy-moodle.xml"
    run(str(BIN / "python"), "-m", "physics_figures.worksheets.moodle", "--topic", "toy_topic", str(xml))
    problems, categories = check_file(ET.parse(xml).getroot())
    assert not problems
    asked = categories["$course$/top/Toy kind (9702)/Floating and sinking/Does it float? does it float?"]
    assert [q.get("type") for q in asked] == ["multichoice"] * 6  # its 6 situations, shared with the site
    bolt = next(q for q in asked if "A steel bolt" in q.findtext("questiontext/text"))
    assert [(a.findtext("text"), a.get("fraction")) for a in bolt.findall("answer")] == [("Yes", "0"), ("No", "100")]


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
