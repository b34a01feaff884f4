"""Exports made before exports carried the book's id and a checksum (issue 37's blocker), on the
class page and in Your practice's Import, in Chromium.

tests/fixtures/progress_v1_class/ holds thirty format 1 exports made on the site as it was at
8b882df by thirty students answering differently (make_exports.py says how). They load on the
class page with every attempt, each labelled "older export, not checked" on the page and in
the CSV, and each student's totals per type are the ones this test works out from the files
(the best attempt at each question tried, every attempt counted). One of them imports into Your
practice, said to be unchecked; a file that names another book, or whose records fail their
checksum, is still refused by both."""

from __future__ import annotations

import csv
import io
import json
from pathlib import Path

import pytest
from browser import progress_checksum
from support.pages import load_progress_files

pytestmark = [pytest.mark.site, pytest.mark.browser]

CLASS_PAGE = "/book/teachers-class.html"
PROGRESS = "/book/exam/your-practice.html"
OLDER = "older export, not checked"
FILES = sorted((Path(__file__).parents[1] / "fixtures" / "progress_v1_class").glob("student-*.json"))


def _expected(types: list[dict], path: Path) -> dict:
    """{type: [earned, available, attempts]} and "total", from the file's attempts: per
    question its best attempt (the highest share of its marks), every attempt counted."""
    of_type = {t["key"]: kind["type"] for kind in types for t in kind["templates"]}
    row = {kind["type"]: [0, 0, 0] for kind in types}
    best: dict[str, dict] = {}
    for a in json.loads(path.read_text(encoding="utf-8"))["attempts"]:
        row[of_type[a["question"]]][2] += 1
        if a["question"] not in best or a["earned"] / a["available"] > best[a["question"]]["earned"] / best[
                a["question"]]["available"]:
            best[a["question"]] = a
    for key, a in best.items():
        row[of_type[key]][0] += a["earned"]
        row[of_type[key]][1] += a["available"]
    row["total"] = [sum(cell[i] for cell in row.values()) for i in range(3)]
    return row


def test_the_fixtures_are_thirty_different_older_exports():
    files = [json.loads(p.read_text(encoding="utf-8")) for p in FILES]
    assert len(files) == 30
    assert all(f["version"] == 1 and "book" not in f and "sha256" not in f and "student" not in f for f in files)
    answered = {json.dumps(sorted((a["question"], a["earned"]) for a in f["attempts"])) for f in files}
    assert len(answered) == 30  # no two students answered alike
    assert any(a["mistakes"] for f in files for a in f["attempts"])
    assert any(len({a["question"] for a in f["attempts"]}) < len(f["attempts"]) for f in files)  # a question twice
    assert len({json.dumps(f.get("definitions", {}).get("cards", {}), sort_keys=True) for f in files}) > 5


def test_thirty_older_exports_load_with_every_attempt_and_each_students_totals_match(site, tmp_path):
    browser, base = site
    context = browser.new_context(accept_downloads=True)
    errors = []
    page = context.new_page()
    page.on("pageerror", lambda error: errors.append(str(error)))
    page.goto(base + CLASS_PAGE, wait_until="load")
    types = json.loads(page.locator("script.cp-data").text_content())["types"]
    load_progress_files(page, FILES)
    assert page.locator(".cp-status").inner_text() == (
        "Loaded 30 files (30 older exports, not checked). The class: 30 students.")
    assert page.locator(".cp-refused li").count() == 0

    shown = {}
    for row in page.locator(".cp-table tbody tr").all():
        assert row.get_attribute("data-checked") == "no"
        assert row.locator("th .cp-older").inner_text() == OLDER
        assert row.locator("th .cp-older").is_visible()
        shown[row.get_attribute("data-file")] = {
            td.get_attribute("data-type"): [int(td.get_attribute(f"data-{n}")) for n in ("earned", "available", "attempts")]
            for td in row.locator("td").all()}
    assert shown == {p.name: _expected(types, p) for p in FILES}
    for path in FILES:  # every attempt of every file is counted
        assert shown[path.name]["total"][2] == len(json.loads(path.read_text())["attempts"])

    with page.expect_download() as download:
        page.get_by_role("button", name="Download CSV").click()
    lines = list(csv.reader(io.StringIO(download.value.path().read_bytes().decode("utf-8-sig"), newline="")))
    table = lines[1:lines.index([])]
    assert [(line[1], line[-1]) for line in table[:-1]] == [(p.name, OLDER) for p in FILES]
    assert not errors
    context.close()


def test_your_practice_imports_an_older_export_unchecked_and_refuses_a_changed_one(site, tmp_path):
    browser, base = site
    context = browser.new_context()
    page = context.new_page()
    page.goto(base + PROGRESS, wait_until="load")
    path = next(p for p in FILES if any(a["earned"] < a["available"] for a in json.loads(p.read_text())["attempts"]))
    older = json.loads(path.read_text())
    status = page.locator(".pp-status")

    def imported(name, content) -> str:
        before = status.inner_text()
        page.get_by_label("Import progress from a file").set_input_files(
            files=[{"name": name, "mimeType": "application/json", "buffer": json.dumps(content).encode()}])
        page.wait_for_function("(before) => document.querySelector('.pp-status').textContent !== before", arg=before)
        return status.inner_text()

    other = {**older, "book": "waves"}
    edited = {**older, "book": "dynamics", "sha256": progress_checksum(older["attempts"])}
    edited["attempts"] = [{**a, "earned": a["available"]} for a in older["attempts"]]
    assert imported("other.json", other).startswith("Nothing was imported from other.json: ")
    assert "do not match their checksum" in imported("edited.json", edited)
    definitions = len(older.get("definitions", {}).get("cards", {}))
    assert imported(path.name, older) == (
        f"Imported {len(older['attempts']) + definitions} attempts from {path.name} (an {OLDER}).")
    context.close()
