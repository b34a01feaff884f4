"""The class at a glance (book/teachers-class.md) as a teacher meets it, in Chromium.

Five students answer real questions on the site in their own browsers (right, wrong, with a
named mistake, and once again after a wrong answer), exporting their progress from Your
practice after every answer: 30 real exports. The teacher loads them all at once, with a
malformed file, a file of another book and an edited one: the three are refused with their
names and why, the 30 load, and every student's and every type's marks and attempts, the
class's mistakes, each question's share of full marks and the CSV agree with totals this
test computes from the files themselves. The export's checksum is checked against Python's
SHA-256 of the serialisation the format documents (progress-file.js), on http:// and file://.

Templates are found from what the pages place (the bank grows; nothing here assumes one)."""

from __future__ import annotations

import csv
import io
import json
from collections import Counter

import pytest
from browser import axe_violations, progress_checksum, question_pages
from support.pages import embedded, load_progress_files

from physics_figures import bank
from physics_figures.notation import format_number, plain_number

pytestmark = [pytest.mark.site, pytest.mark.browser]

CLASS_PAGE = "/book/teachers-class.html"
PROGRESS = "/book/exam/your-practice.html"
QUICK_CHECK = "/book/exam/quick-check.html"
STUDENTS, ANSWERS_EACH = 5, 6  # 30 exports
MODES = ("right", "wrong", "mistake")


def _answerable(site_dir) -> list[tuple[str, str]]:
    """(template key, page) of questions whose parts are all numbers: the quick check's, then
    one from each practice page of a type the quick check does not ask, up to two more."""
    placed = question_pages(site_dir)

    def numeric(key):
        template = bank.TEMPLATES.get(key)
        return template and not template.try_first and all(p.kind == "numeric" for p in template.variant(0).parts)

    chosen = [(key, page) for key, page in placed.items() if page == QUICK_CHECK and numeric(key)]
    types = {bank.TEMPLATES[key].type for key, _ in chosen}
    for key, page in placed.items():
        if len(chosen) >= 7:
            break
        if page != QUICK_CHECK and numeric(key) and bank.TEMPLATES[key].type not in types:
            chosen.append((key, page))
            types.add(bank.TEMPLATES[key].type)
    assert len(chosen) >= ANSWERS_EACH - 1, chosen
    return chosen


def _answer(tab, key: str, mode: str) -> None:
    """Variant 0 (the page's own numbers), typed as a student types: every part right, or the
    first part wrong, or the first part with a named mistake (wrong when it has none)."""
    question = bank.TEMPLATES[key].variant(0)
    form = tab.locator(f'form.q-form[data-question="{key}"]')
    for index, part in enumerate(question.parts):
        value = part.value
        if index == 0 and mode == "mistake":
            plain = [m for m in part.mistakes if m.unit is None and m.direction is None]
            value = plain[0].value if plain else part.value * 7.3
        elif index == 0 and mode == "wrong":
            value = part.value * 7.3
        box = form.locator("fieldset.q-part").nth(index)
        typed = plain_number(format_number(value if part.direction == "signed" else abs(value), 3))  # "2.00", not "2"
        box.locator("input.q-value").fill(typed)
        box.locator("input.q-unit").fill(part.unit)
        if part.direction == "choice":
            box.locator("select.q-direction").select_option(part.answer_direction)
    form.locator("button.q-check").click()
    assert form.locator(".q-score").inner_text()


def _export(tab, path, name: str) -> dict:
    """Export progress under the student's name (typed into Your name, as Export asks)."""
    tab.get_by_label("Your name").fill(name)
    with tab.expect_download() as download:
        tab.get_by_role("button", name="Export progress").click()
    download.value.save_as(path)
    return json.loads(path.read_text(encoding="utf-8"))


@pytest.fixture(scope="module")
def exports(site, site_dir, tmp_path_factory) -> list:
    """30 files exported from Your practice by five students answering on the site."""
    browser, base = site
    folder = tmp_path_factory.mktemp("class")
    questions = _answerable(site_dir)
    files = []
    for student in range(STUDENTS):
        context = browser.new_context(accept_downloads=True)
        errors = []
        tabs = {}

        def tab(path, context=context, errors=errors, tabs=tabs):
            if path not in tabs:
                tabs[path] = context.new_page()
                tabs[path].on("pageerror", lambda error: errors.append(str(error)))
                tabs[path].goto(base + path, wait_until="load")
            return tabs[path]

        practice = tab(PROGRESS)
        for turn in range(ANSWERS_EACH):
            if turn == ANSWERS_EACH - 1:  # again, right, after the first answer (often wrong)
                key, page = questions[student % len(questions)]
                mode = "right"
            else:
                key, page = questions[(student + turn) % len(questions)]
                mode = MODES[(student + 2 * turn) % len(MODES)]
            _answer(tab(page), key, mode)
            files.append(folder / f"student-{len(files) + 1:02d}.json")
            _export(practice, files[-1], files[-1].stem)  # each export a student of its own
        context.close()
        assert not errors
    return files


def _expected(data: dict, files) -> dict:
    """What the page must show, from the files: per student and type (earned, available,
    attempts) with the best attempt at each question (by share of its marks, the first on a
    tie), the mistakes' counts and students, and each question's attempts and full marks."""
    of_type = {t["key"]: kind["type"] for kind in data["types"] for t in kind["templates"]}
    table, mistakes, makers, questions = {}, Counter(), {}, {}
    for path in files:
        attempts = [a for a in json.loads(path.read_text())["attempts"] if a["question"] in of_type]
        best = {}
        for a in attempts:
            if a["question"] not in best or a["earned"] / a["available"] > best[a["question"]]["earned"] / best[
                    a["question"]]["available"]:
                best[a["question"]] = a
            for name in a["mistakes"]:
                mistakes[name] += 1
                makers.setdefault(name, set()).add(path.stem)
            entry = questions.setdefault(a["question"], {"students": set(), "attempts": 0, "full": 0, "best": set()})
            entry["students"].add(path.stem)
            entry["attempts"] += 1
            entry["full"] += a["earned"] == a["available"]
        for key, a in best.items():
            if a["earned"] == a["available"]:
                questions[key]["best"].add(path.stem)
        row = {kind["type"]: [0, 0, 0] for kind in data["types"]}
        for a in attempts:
            row[of_type[a["question"]]][2] += 1
        for key, a in best.items():
            row[of_type[key]][0] += a["earned"]
            row[of_type[key]][1] += a["available"]
        row["total"] = [sum(cell[i] for cell in row.values()) for i in range(3)]
        table[path.stem] = row
    table[""] = {kind: [sum(r[kind][i] for r in table.values()) for i in range(3)] for kind in next(iter(table.values()))}
    return {"table": table, "mistakes": {n: (c, len(makers[n])) for n, c in mistakes.items()}, "makers": makers,
            "questions": questions}


def _bad_files(files, folder) -> dict:
    """A malformed file, one of another book and one edited by hand, each from a real export."""
    text = files[0].read_text()
    other = json.loads(files[1].read_text())
    other["book"] = "waves"
    edited = json.loads(files[-1].read_text())
    attempt = next(a for a in edited["attempts"] if a["earned"] < a["available"])
    attempt["earned"] += 1  # still a possible attempt: only the checksum tells
    bad = {"broken.json": text[: len(text) // 2], "other-book.json": json.dumps(other, indent=1),
           "edited.json": json.dumps(edited, indent=1)}
    for name, content in bad.items():
        (folder / name).write_text(content, encoding="utf-8")
    return {name: folder / name for name in bad}


def test_exports_name_the_book_and_carry_the_checksum_of_their_records(site, exports):
    browser, base = site
    context = browser.new_context()
    page = context.new_page()
    page.goto(base + CLASS_PAGE, wait_until="load")
    book = embedded(page, "cp-data")["book"]
    context.close()
    assert book == bank.TOPIC.key
    for path in exports:
        saved = json.loads(path.read_text())
        assert (saved["version"], saved["book"]) == (2, book)
        assert saved["sha256"] == progress_checksum(saved["attempts"])
    assert len(exports) == 30
    assert len({len(json.loads(p.read_text())["attempts"]) for p in exports}) == ANSWERS_EACH


def test_thirty_files_load_and_every_total_matches_the_files_and_the_bad_ones_are_refused(site, exports, tmp_path):
    browser, base = site
    context = browser.new_context(accept_downloads=True)
    errors = []
    page = context.new_page()
    page.on("pageerror", lambda error: errors.append(str(error)))
    page.goto(base + CLASS_PAGE, wait_until="load")
    data = embedded(page, "cp-data")
    bad = _bad_files(exports, tmp_path)
    load_progress_files(page, [*exports[:15], *bad.values(), *exports[15:]])

    _check_refused(page, bad)
    expected = _expected(data, exports)
    _check_class_table(page, expected, len(exports))
    _check_common_mistakes(page, expected)
    _check_question_shares(page, expected)

    with page.expect_download() as download:
        page.get_by_role("button", name="Download CSV").click()
    raw = download.value.path().read_bytes()
    assert raw.startswith(b"\xef\xbb\xbf")
    _check_csv(list(csv.reader(io.StringIO(raw.decode("utf-8-sig"), newline=""))), data, expected)
    assert not errors
    context.close()


def _check_refused(page, bad: dict) -> None:
    """The status line counts the loaded and the refused files, and each bad file is refused with why."""
    assert page.locator(".cp-status").inner_text() == "Loaded 30 files; refused 3 (below, with why). The class: 30 students."
    refused = {li.get_attribute("data-file"): li.inner_text() for li in page.locator(".cp-refused li").all()}
    assert set(refused) == set(bad)
    assert refused["broken.json"].startswith("broken.json was refused: ") and "not JSON" in refused["broken.json"]
    assert 'another book ("waves")' in refused["other-book.json"]
    assert "do not match their checksum: it was changed after it was exported" in refused["edited.json"]


def _check_class_table(page, expected: dict, students: int) -> None:
    """Each student's row and the class's: every cell's marks and attempts as the files give them."""
    rows = page.locator(".cp-table tr[data-student]")
    assert rows.count() == students + 1  # the students and the class
    shown = {}
    for row in rows.all():
        cells = {}
        for td in row.locator("td").all():
            numbers = [int(td.get_attribute(f"data-{n}")) for n in ("earned", "available", "attempts")]
            text = td.inner_text()
            if numbers[2]:
                assert text.startswith(f"{numbers[0]}/{numbers[1]}") and f"{numbers[2]} attempt" in text
            else:
                assert text == "not tried"
            cells[td.get_attribute("data-type")] = numbers
        shown[row.get_attribute("data-student")] = cells
    assert shown == expected["table"]
    assert any(cells["total"][0] < cells["total"][1] for cells in shown.values())  # not every answer right


def _check_common_mistakes(page, expected: dict) -> None:
    """The ten commonest mistakes, most made first, each with its count and the students who made it."""
    mistakes = page.locator(".cp-mistakes li")
    assert mistakes.count() == min(10, len(expected["mistakes"])) > 0
    counts = []
    for li in mistakes.all():
        name = li.inner_text().rsplit(": ", 1)[0]
        counts.append(int(li.get_attribute("data-count")))
        assert (counts[-1], int(li.get_attribute("data-students"))) == expected["mistakes"][name]
        who = li.locator(".cp-by").inner_text().rsplit(" (", 1)[1].removesuffix(")").split(", ")
        assert who == sorted(expected["makers"][name])  # the students who made it, by name
    assert counts == sorted(counts, reverse=True)
    assert counts[-1] >= sorted((c for c, _ in expected["mistakes"].values()), reverse=True)[len(counts) - 1]


def _check_question_shares(page, expected: dict) -> None:
    """Each question's row: students who tried it, with full marks, attempts and the share of full marks."""
    questions = page.locator(".cp-questions tbody tr")
    assert questions.count() == len(expected["questions"])
    for tr in questions.all():
        entry = expected["questions"][tr.get_attribute("data-key")]
        cells = [td.inner_text() for td in tr.locator("td").all()]
        share = round(100 * entry["full"] / entry["attempts"])
        assert cells[1:] == [str(len(entry["students"])), str(len(entry["best"])), str(entry["attempts"]),
                             f"{share}% ({entry['full']} of {entry['attempts']})"]


def _check_csv(lines: list[list[str]], data: dict, expected: dict) -> None:
    """The CSV's three sections (book/teachers-class.md): the table, a type not tried left
    "not tried" with no marks; the mistakes with who made them; each question's share."""
    names = [kind["name"] for kind in data["types"]] + ["Total"]
    assert lines[0] == ["Student", "File"] + [f"{n}: {what}" for n in names for what in
                                              ("marks earned", "marks available", "attempts")] + ["Checksum"]
    keys = [kind["type"] for kind in data["types"]] + ["total"]
    table = lines[1:lines.index([])]
    from_csv = {}
    for line in table:
        cells = {}
        for i, k in enumerate(keys):
            earned, available, attempts = line[2 + 3 * i: 5 + 3 * i]
            if attempts == "0":
                assert (earned, available) == ("not tried", ""), line
                earned = available = "0"
            cells[k] = [int(earned), int(available), int(attempts)]
        from_csv["" if line[0] == "Class" else line[0]] = cells
        assert line[-1] == ("" if line[0] == "Class" else "checked")
    assert from_csv == expected["table"]
    mistakes = lines[lines.index(["Mistake", "Times", "Students", "Who"]) + 1:]
    mistakes = mistakes[:mistakes.index([])]
    assert {m[0]: (int(m[1]), int(m[2])) for m in mistakes} == expected["mistakes"]
    assert {m[0]: m[3].split("; ") for m in mistakes} == {n: sorted(w) for n, w in expected["makers"].items()}
    head = lines.index(["Question", "Key", "Type", "Students who tried it", "Students with full marks", "Attempts",
                        "Attempts with full marks", "Share of full marks (%)"])
    questions = {q[1]: q[3:] for q in lines[head + 1:]}
    assert questions == {key: [str(len(e["students"])), str(len(e["best"])), str(e["attempts"]), str(e["full"]),
                               str(round(100 * e["full"] / e["attempts"]))] for key, e in expected["questions"].items()}


def test_the_page_says_nothing_is_uploaded_and_what_the_checksum_catches(site):
    browser, base = site
    context = browser.new_context()
    page = context.new_page()
    requests = []
    page.on("request", lambda request: requests.append(request.url))
    page.goto(base + CLASS_PAGE, wait_until="load")
    text = page.locator("main").inner_text()
    assert "Nothing is uploaded." in text
    assert "catches a casual edit, not a determined student" in text
    page.get_by_label("Choose progress files").set_input_files(
        files=[{"name": "x.json", "mimeType": "application/json", "buffer": b"{}"}])
    page.wait_for_function("document.querySelector('.cp-refused li')")
    assert all(url.startswith(base) for url in requests)  # reading a file asked no server
    context.close()


def test_from_the_unzipped_site_export_and_load_work_on_file_urls(site, site_dir, exports, tmp_path):
    """file:// pages: Web Crypto is there (a file URL is a secure context in Chromium)."""
    browser, _ = site
    context = browser.new_context(accept_downloads=True)
    page = context.new_page()
    page.goto(site_dir.as_uri() + PROGRESS, wait_until="load")
    attempts = json.loads(exports[3].read_text())["attempts"]
    page.evaluate("(a) => localStorage.setItem('dynamics-progress-v1', JSON.stringify({version: 1, attempts: a}))",
                  attempts)
    saved = _export(page, tmp_path / "from-disk.json", "from-disk")  # a format 1 store, upgraded: every attempt kept
    assert [a["at"] for a in saved["attempts"]] == [a["at"] for a in attempts]
    assert saved["sha256"] == progress_checksum(saved["attempts"]) and saved["book"] == bank.TOPIC.key
    page.goto(site_dir.as_uri() + CLASS_PAGE, wait_until="load")
    load_progress_files(page, [tmp_path / "from-disk.json"])
    assert page.locator(".cp-status").inner_text().startswith("Loaded 1 file.")
    assert page.locator('.cp-table tr[data-student="from-disk"]').count() == 1
    context.close()


@pytest.mark.parametrize("scheme", ["light", "dark"])
def test_the_page_passes_axe_with_a_class_loaded_and_works_from_the_keyboard(site, exports, scheme):
    browser, base = site
    context = browser.new_context(color_scheme=scheme)
    page = context.new_page()
    page.goto(base + CLASS_PAGE, wait_until="load")
    page.locator(".cp-choose-label").evaluate("label => label.scrollIntoView()")
    for _ in range(200):  # the header's and the page's links, then the file input
        page.keyboard.press("Tab")
        if page.evaluate("document.activeElement.id") == "cp-choose":
            break
    assert page.evaluate("document.activeElement.id") == "cp-choose"
    ring = page.evaluate("getComputedStyle(document.querySelector('.cp-choose-label')).outlineStyle")
    assert ring != "none"  # the hidden input's label shows where focus is
    load_progress_files(page, exports[:6])
    assert axe_violations(page) == []
    page.keyboard.press("Tab")
    assert page.evaluate("document.activeElement.textContent") == "Download CSV"
    context.close()
