"""A second topic is one declaration and its pages: tests/fixtures/second_topic (Kinematics: two
pages, one question type, one template) builds with the book's own extensions, its question is
marked in Chromium, and the teacher's kit (worksheets and Moodle) takes it with --topic. No
shared module names it: the fixture is never published."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ET
from html import escape
from pathlib import Path

import pytest
from browser import open_browser, serve_site
from moodle_format import check_file

from physics_figures.topics import storage_keys

ROOT = Path(__file__).resolve().parents[2]
FIXTURE = ROOT / "tests" / "fixtures" / "second_topic"
BIN = Path(sys.executable).parent
#: The fixture's topic module is found the way any topic is: on the Python path.
ENV = {**os.environ, "PYTHONPATH": os.pathsep.join(filter(None, [str(FIXTURE), os.environ.get("PYTHONPATH")]))}
KEY = "kinematics-speeding-up"
#: The fixture book's own storage keys: its id is its topic's key (kinematics_topic.TOPIC).
KEYS = storage_keys("kinematics")


@pytest.fixture(scope="module")
def fixture_site(tmp_path_factory) -> Path:
    """The second topic's book, built strictly (any warning fails) outside the fixture."""
    out = tmp_path_factory.mktemp("second-topic")
    done = subprocess.run([str(BIN / "jupyter-book"), "build", str(FIXTURE), "-n", "-W", "--keep-going",
                           "--path-output", str(out)], env=ENV, capture_output=True, text=True, check=False,
                          timeout=600)
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    return out / "_build" / "html"


@pytest.mark.build
def test_the_second_topic_builds_with_its_pages_and_question(fixture_site):
    practice = (fixture_site / "kinematics" / "practice.html").read_text(encoding="utf-8")
    assert f'data-question="{KEY}" data-type="suvat"' in practice
    assert 'class="q-new"' in practice, "its ten variants give New numbers"
    assert (fixture_site / "_static" / "questions" / f"{KEY}.js").is_file()
    # feedback links the topic's own section, by the id its data names
    assert '"equations": {"href": "equations.html#the-equations-of-motion"' in practice
    assert (fixture_site / "kinematics" / "equations.html").is_file()


@pytest.mark.build
def test_the_second_topic_s_pages_name_its_own_storage_keys(fixture_site):
    """Every page names the keys the book keeps its records under, from its own id: a second
    topic's book keeps its own with no script edited."""
    pages = [page.read_text(encoding="utf-8") for page in sorted(fixture_site.rglob("*.html")) if "_static" not in page.parts]
    pages = [page for page in pages if 'http-equiv="Refresh"' not in page]  # index.html sends to the first page
    assert len(pages) > 2
    meta = f'<meta name="book-storage" content="{escape(json.dumps(KEYS, separators=(",", ":")))}">'
    assert all(meta in page for page in pages), meta
    assert KEYS["progress"] == "kinematics-progress-v2" and KEYS["cache"] == "kinematics-"


@pytest.mark.build
@pytest.mark.browser
def test_the_second_topic_is_marked_in_the_browser(fixture_site):
    with serve_site(fixture_site) as base, open_browser() as browser:
        page = browser.new_page()
        errors = []  # the questions' scripts throw nothing (the bare theme's own thebe clash is not ours)
        page.on("pageerror", lambda e: "/_static/" in (e.stack or "") and "thebe" not in (e.stack or "")
                and errors.append(str(e)))
        page.goto(f"{base}/kinematics/practice.html", wait_until="load")
        box = f"#q-{KEY}-a"
        page.fill(f"{box}-value", "2.0")  # (10 - 4) / 3, the printed variant's key
        page.fill(f"{box}-unit", "m s^-2")
        page.click("button.q-check")
        assert page.locator(".q-score").inner_text() == "2/2 marks"
        page.fill(f"{box}-value", "3.3")  # 10 / 3: the named mistake, initial speed left out
        page.click("button.q-check")
        feedback = page.locator(f"{box}-feedback")
        assert "You divided the final speed by the time" in feedback.inner_text()
        assert feedback.locator("a.q-idea").get_attribute("href") == "equations.html#the-equations-of-motion"
        assert page.locator(".q-score").inner_text() == "0/2 marks"
        assert not errors, errors
        # the attempts and the answers are kept under the book's own keys, none of Dynamics's
        stored = page.evaluate("Object.keys(localStorage)")
        assert KEYS["progress"] in stored and any(key.startswith(KEYS["answers"]) for key in stored), stored
        assert not [key for key in stored if key.startswith("dynamics-")], stored


@pytest.mark.build
def test_the_second_topic_is_in_the_teachers_kit(tmp_path):
    """The site's sheets of the topic (its worksheet and end-of-topic test, versions A-C with
    keys) and its Moodle file, each by the topic's module."""
    done = subprocess.run([str(BIN / "python"), "-m", "physics_figures.worksheets", "--topic", "kinematics_topic",
                           "--site", "--out", str(tmp_path / "sheets")], env=ENV, capture_output=True, text=True,
                          check=False, timeout=600)
    assert done.returncode == 0, done.stderr
    names = sorted(p.name for p in (tmp_path / "sheets").glob("*.pdf"))
    assert names == sorted(f"{sheet}-{key}{letter}.pdf" for sheet in ("worksheet-suvat", "end-of-topic-test")
                           for key in ("", "key-") for letter in "ABC")
    text = subprocess.run(["pdftotext", str(tmp_path / "sheets" / "end-of-topic-test-A.pdf"), "-"],
                          capture_output=True, text=True, check=True).stdout
    assert "Kinematics: end-of-topic test" in text and "cyclist speeds up uniformly" in text
    xml = tmp_path / "kinematics-moodle.xml"
    done = subprocess.run([str(BIN / "python"), "-m", "physics_figures.worksheets.moodle", "--topic",
                           "kinematics_topic", str(xml)], env=ENV, capture_output=True, text=True, check=False,
                          timeout=600)
    assert done.returncode == 0, done.stderr
    problems, categories = check_file(ET.parse(xml).getroot())
    assert not problems
    suvat = "$course$/top/Kinematics (9702)/Equations of uniformly accelerated motion"
    assert list(categories) == [suvat, f"{suvat}/Cyclist speeding up acceleration"]  # its type, its part
    assert [q.get("type") for q in categories[f"{suvat}/Cyclist speeding up acceleration"]] == ["numerical"] * 10
