"""Students are named by the name their export carries (issue 37: "a class collapses into one
student"), in Chromium.

Three students answer on one day, each in a fresh browser, and press Export progress: Export asks
each for a name once (nothing is saved until it is given, or Export is pressed again), keeps it in
the store (the next export does not ask) and writes dynamics-progress-NAME-DATE.json carrying it.
The class page shows three named students. Two files that give one name are two rows, each
with its file's name, and a note says so: never merged."""

from __future__ import annotations

import json
from datetime import UTC, datetime

import pytest
from browser import progress_checksum
from support.pages import load_progress_files
from test_class_browser import CLASS_PAGE, PROGRESS, QUICK_CHECK, _answer, _answerable

pytestmark = [pytest.mark.site, pytest.mark.browser]

STUDENTS = ("Amira Khan", "Ben O'Neill", "Zoë Lê")
SAFE = ("Amira-Khan", "Ben-O-Neill", "Zoë-Lê")


def _export_as_a_student_does(site, site_dir, name: str, folder, turn: int):
    """A fresh browser: one answer, then Export, which asks for the name first."""
    browser, base = site
    key, page_path = [q for q in _answerable(site_dir) if q[1] == QUICK_CHECK][turn]
    context = browser.new_context(accept_downloads=True)
    quick = context.new_page()
    quick.goto(base + page_path, wait_until="load")
    _answer(quick, key, ("right", "wrong", "mistake")[turn])
    practice = context.new_page()
    practice.goto(base + PROGRESS, wait_until="load")
    downloads = []
    practice.on("download", lambda download: downloads.append(download))
    practice.get_by_role("button", name="Export progress").click()
    practice.wait_for_function("document.querySelector('.pp-status').textContent.startsWith('Type your name')")
    assert practice.evaluate("document.activeElement.id") == "pp-student"
    practice.get_by_label("Your name").fill(name)
    with practice.expect_download() as download:
        practice.get_by_role("button", name="Export progress").click()
    path = folder / download.value.suggested_filename
    download.value.save_as(path)
    assert len(downloads) == 1  # the first press asked, and saved nothing
    practice.reload(wait_until="load")  # the name is kept: the next export does not ask
    assert practice.get_by_label("Your name").input_value() == name
    with practice.expect_download() as again:
        practice.get_by_role("button", name="Export progress").click()
    assert again.value.suggested_filename == path.name
    context.close()
    return path


def test_three_students_exporting_on_one_day_are_three_named_students(site, site_dir, tmp_path):
    browser, base = site
    today = datetime.now(UTC).strftime("%Y-%m-%d")
    files = []
    for turn, name in enumerate(STUDENTS):
        folder = tmp_path / str(turn)  # each student's own download folder: the names differ anyway
        folder.mkdir()
        files.append(_export_as_a_student_does(site, site_dir, name, folder, turn))
    assert [p.name for p in files] == [f"dynamics-progress-{safe}-{today}.json" for safe in SAFE]
    assert [json.loads(p.read_text(encoding="utf-8"))["student"] for p in files] == list(STUDENTS)

    context = browser.new_context()
    page = context.new_page()
    page.goto(base + CLASS_PAGE, wait_until="load")
    load_progress_files(page, files)
    assert page.locator(".cp-status").inner_text() == "Loaded 3 files. The class: 3 students."
    rows = page.locator(".cp-table tbody tr")
    assert [r.get_attribute("data-student") for r in rows.all()] == sorted(STUDENTS)
    assert [r.locator("th").inner_text() for r in rows.all()] == sorted(STUDENTS)
    assert page.locator(".cp-notes").is_hidden()
    context.close()


def test_two_files_that_give_one_name_are_two_rows_with_a_note(site, site_dir, tmp_path):
    browser, base = site
    first = _export_as_a_student_does(site, site_dir, "Sam Lee", tmp_path, 0)
    second = tmp_path / "sam-lee-again.json"
    # another student's export under the same name (nothing answered yet): checked, and loaded
    second.write_text(json.dumps({**json.loads(first.read_text()), "attempts": [], "sha256": progress_checksum([])}),
                      encoding="utf-8")
    context = browser.new_context()
    page = context.new_page()
    page.goto(base + CLASS_PAGE, wait_until="load")
    load_progress_files(page, [first, second])
    load_progress_files(page, [first])  # the same file again is the same file: not a third row
    rows = page.locator(".cp-table tbody tr")
    assert [(r.get_attribute("data-student"), r.get_attribute("data-file")) for r in rows.all()] == [
        ("Sam Lee", first.name), ("Sam Lee", second.name)]
    assert [r.locator("th").inner_text() for r in rows.all()] == [f"Sam Lee ({first.name})",
                                                                 f"Sam Lee ({second.name})"]
    assert [int(r.locator("td.cp-total").get_attribute("data-attempts")) for r in rows.all()] == [1, 0]
    note = page.locator(".cp-notes li")
    assert note.count() == 1 and note.get_attribute("data-name") == "Sam Lee"
    assert note.inner_text().startswith(f"2 files give the name Sam Lee ({first.name}, {second.name}): "
                                        "each is a row of its own, not added together.")
    assert page.locator(".cp-status").inner_text() == (
        "Loaded 1 file (1 file loaded before: read again, not added twice). The class: 2 students "
        "(1 name is given by two files or more: see the note).")
    context.close()
