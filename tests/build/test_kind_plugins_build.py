"""The part kinds' plug-in, built: a toy kind from tests/fixtures/toy_kind is on its page, marked in the
browser, on a worksheet and in the Moodle export, with no shared file edited (the scans of the
source are tests/no_site/test_kind_plugins.py)."""

from __future__ import annotations

import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


FIXTURE = ROOT / "tests" / "fixtures" / "toy_kind"


BIN = Path(sys.executable).parent


#: The fixture's topic module (and its kind's module beside it) are found as any topic is: on
#: the Python path. The kind is registered only in the processes that load the topic.
KEY = "toy-floats"
ENV = {**os.environ, "PYTHONPATH": os.pathsep.join(filter(None, [str(FIXTURE), os.environ.get("PYTHONPATH")]))}


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
