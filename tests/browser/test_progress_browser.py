"""'Your practice' as a student meets it, in Chromium: answers checked on the quick-check
page show up by type (a line each, its details folded: templates tried, marks, the named
mistake), survive a reload, go out to a file (format 2) and come back, clear with undo, a bad
file is refused without loss, and Practise this type lands on a question with new numbers and
focus in it. The plan at the top is tests/browser/test_plan_browser.py's.

Templates are found from the list the page embeds (the bank grows; nothing here assumes
one template)."""

from __future__ import annotations

import json
import re

import pytest
from browser import axe_violations
from support.pages import embedded, open_page, stored, watched_context

from physics_figures import bank

pytestmark = [pytest.mark.site, pytest.mark.browser]

PROGRESS = "/book/exam/your-practice.html"
QUICK_CHECK = "/book/exam/quick-check.html"
STORE = "dynamics-progress-v2"


@pytest.fixture
def context(site):
    with watched_context(*site, accept_downloads=True) as context:
        yield context


def _on_quick_check(data) -> tuple[dict, dict, object]:
    """A template the quick-check page places whose first part has a named mistake of the
    same quantity: (its type entry, its entry, the mistake)."""
    for kind in data["types"]:
        for entry in kind["templates"]:
            if entry["page"] != "quick-check.html":
                continue
            parts = bank.TEMPLATES[entry["key"]].variant(0).parts
            plain = [m for m in parts[0].mistakes if m.unit is None and m.direction is None]
            if plain:
                return kind, entry, plain[0]
    pytest.fail("no template on the quick-check page has a named mistake to make")


def _number(value: float) -> str:
    return f"{value:.3g}"


def _answer_with_a_mistake(page, key: str, mistake) -> str:
    """Variant 0: the first part answered with `mistake`, the others right; the score."""
    question = bank.TEMPLATES[key].variant(0)
    form = page.locator(f'form.q-form[data-question="{key}"]')
    for index, part in enumerate(question.parts):
        box = form.locator("fieldset.q-part").nth(index)
        value = mistake.value if index == 0 else part.value
        box.locator("input.q-value").fill(_number(value if part.direction == "signed" else abs(value)))
        box.locator("input.q-unit").fill(part.unit)
        if part.direction == "choice":
            box.locator("select.q-direction").select_option(part.answer_direction)
    form.locator("button.q-check").click()
    assert form.locator("fieldset.q-part").first.locator(".q-feedback").get_attribute("data-code") == "mistake"
    return form.locator(".q-score").inner_text()


def _section(page, kind: str):
    """A type's details, opened (its line is the summary)."""
    section = page.locator(f'.pp-type[data-type="{kind}"]')
    if section.get_attribute("open") is None:
        section.locator("summary").click()
    return section


def test_every_type_is_listed_by_its_name_with_what_the_bank_has(context):
    page = open_page(context, PROGRESS)
    data = embedded(page, "pp-data")
    assert [kind["type"] for kind in data["types"]] == list(bank.TOPIC.type_keys)
    for kind in data["types"]:
        section = _section(page, kind["type"])
        assert section.locator("summary .pp-name").inner_text() == kind["name"]
        assert [t["key"] for t in kind["templates"]] == [t.key for t in bank.by_type(kind["type"])]
        summary = section.locator(".pp-summary").inner_text()
        if kind["templates"]:
            assert "none tried yet" in summary
            assert section.locator(".pp-line").inner_text() == f"no marks yet · 0 of {len(kind['templates'])} tried"
        else:
            assert summary.startswith("Not in the bank yet")


def test_progress_follows_answers_survives_reload_export_clear_and_import(context, tmp_path):
    page = open_page(context, PROGRESS)
    kind, entry, mistake = _on_quick_check(embedded(page, "pp-data"))
    questions = open_page(context, QUICK_CHECK)
    score = _answer_with_a_mistake(questions, entry["key"], mistake)

    page.reload(wait_until="load")
    section = _section(page, kind["type"])

    def shows_the_attempt():
        section = _section(page, kind["type"])
        summary = section.locator(".pp-summary").inner_text()
        assert summary.startswith(f"Tried 1 of {len(kind['templates'])} question")
        assert f"Marks: {score}" in summary
        assert section.locator(".pp-mistakes").is_visible()
        assert f"{mistake.name} (once)" in section.locator(".pp-mistakes").inner_text()
        assert f"best {score}" in section.locator(f'li[data-key="{entry["key"]}"]').inner_text()

    shows_the_attempt()
    page.reload(wait_until="load")
    shows_the_attempt()

    page.get_by_label("Your name").fill("Amira Khan")  # Export asks for it once; the file carries it
    with page.expect_download() as download:
        page.get_by_role("button", name="Export progress").click()
    assert re.fullmatch(r"dynamics-progress-Amira-Khan-\d{4}-\d\d-\d\d\.json", download.value.suggested_filename)
    exported = tmp_path / download.value.suggested_filename
    download.value.save_as(exported)
    saved = json.loads(exported.read_text())
    assert saved["version"] == 2 and saved["student"] == "Amira Khan"
    assert [a["question"] for a in saved["attempts"]] == [entry["key"]]
    assert list(saved["schedule"]) == [entry["key"]]
    assert saved["attempts"][0]["mistakes"] == [mistake.name]

    page.get_by_role("button", name="Clear progress").click()
    assert "none tried yet" in section.locator(".pp-summary").inner_text()
    assert json.loads(stored(page, STORE))["attempts"] == []  # kept empty: the format 1 store is never read again
    assert page.evaluate("document.activeElement.textContent") == "Undo clear"
    page.reload(wait_until="load")
    assert "none tried yet" in _section(page, kind["type"]).locator(".pp-summary").inner_text()

    page.get_by_label("Import progress from a file").set_input_files(str(exported))
    section = _section(page, kind["type"])
    page.wait_for_function("document.querySelector('.pp-status').textContent.startsWith('Imported')")
    assert page.locator(".pp-status").inner_text().startswith(f"Imported 1 attempt from {exported.name}")
    assert page.locator(".pp-status").get_attribute("aria-live") == "polite"
    shows_the_attempt()
    # the same file again adds nothing
    page.get_by_label("Import progress from a file").set_input_files(str(exported))
    page.wait_for_function("document.querySelector('.pp-status').textContent.includes('were here already')")
    shows_the_attempt()


@pytest.mark.parametrize(("content", "reason"), [
    (b"this is not progress", "not JSON"),
    (json.dumps({"version": 1, "attempts": [{"question": "x"}]}).encode(), "attempt 1 of 1 has no question type"),
    (json.dumps({"version": 7, "attempts": []}).encode(), "newer version of the book (format 7)"),
])
def test_a_bad_file_is_refused_with_the_reason_and_nothing_is_lost(context, content, reason):
    page = open_page(context, PROGRESS)
    kind, entry, mistake = _on_quick_check(embedded(page, "pp-data"))
    _answer_with_a_mistake(open_page(context, QUICK_CHECK), entry["key"], mistake)
    page.reload(wait_until="load")
    before = stored(page, STORE)
    assert before
    page.get_by_label("Import progress from a file").set_input_files(
        files=[{"name": "progress.json", "mimeType": "application/json", "buffer": content}])
    page.wait_for_function("document.querySelector('.pp-status').textContent.startsWith('Nothing')")
    status = page.locator(".pp-status").inner_text()
    assert status.startswith("Nothing was imported from progress.json: ")
    assert reason in status
    assert status.endswith("Your progress here is unchanged.")
    assert stored(page, STORE) == before
    assert _section(page, kind["type"]).locator(".pp-summary").inner_text().startswith("Tried 1 of")


def test_practise_this_type_lands_on_a_question_with_new_numbers_and_focus_in_it(context):
    page = open_page(context, PROGRESS)
    kind = next(k for k in embedded(page, "pp-data")["types"] if any(t["page"] for t in k["templates"]))
    link = _section(page, kind["type"]).get_by_role("link", name="Practise this type")
    key = link.get_attribute("data-next")
    assert key == next(t["key"] for t in kind["templates"] if t["page"])  # nothing tried: the first
    link.click()
    page.wait_for_function(
        f"(document.querySelector('form.q-form[data-question=\"{key}\"]') || {{}}).getAttribute && "
        f"document.querySelector('form.q-form[data-question=\"{key}\"]').getAttribute('data-variant') !== '0'")
    # the page moves focus into the question once its new numbers are in (it may be a frame later)
    page.wait_for_function(f"document.getElementById('question-{key}').contains(document.activeElement)",
                           timeout=10_000)
    assert "new=" not in page.url  # used up: a reload keeps these numbers
    assert page.url.endswith(f"#question-{key}")


def test_without_javascript_the_page_says_what_it_is_for_and_what_it_needs(site):
    browser, base = site
    context = browser.new_context(java_script_enabled=False)
    page = context.new_page()
    page.goto(base + PROGRESS, wait_until="load")
    assert "The cards due today show here." in page.locator("main").inner_text()  # what it is for
    assert page.locator(".pp-needs-js").is_visible()
    assert "JavaScript" in page.locator(".pp-needs-js").inner_text()
    assert not page.locator(".pp-file").is_visible()  # its buttons would do nothing
    assert page.locator(".pp-type").count() == len(bank.TOPIC.type_keys)
    context.close()
    context = browser.new_context()
    page = context.new_page()
    page.goto(base + PROGRESS, wait_until="load")
    page.emulate_media(media="print")
    assert page.locator(".pp-needs-js").is_visible()
    assert not page.locator(".pp-file").is_visible()
    context.close()


@pytest.mark.parametrize("scheme", ["light", "dark"])
def test_the_page_passes_axe_with_progress_shown(site, scheme):
    browser, base = site
    context = browser.new_context(color_scheme=scheme)
    page = context.new_page()
    page.goto(base + PROGRESS, wait_until="load")
    kind, entry, mistake = _on_quick_check(embedded(page, "pp-data"))
    questions = context.new_page()
    questions.goto(base + QUICK_CHECK, wait_until="load")
    _answer_with_a_mistake(questions, entry["key"], mistake)
    page.reload(wait_until="load")
    assert _section(page, kind["type"]).locator(".pp-mistakes").is_visible()
    assert axe_violations(page) == []
    page.get_by_role("button", name="Clear progress").click()  # the undo button shows
    assert page.locator(".pp-undo").is_visible()
    assert axe_violations(page) == []
    context.close()


def test_the_file_controls_work_from_the_keyboard_with_visible_focus(context):
    page = open_page(context, PROGRESS)
    page.get_by_role("button", name="Export progress").focus()
    page.keyboard.press("Tab")
    assert page.evaluate("document.activeElement.id") == "pp-import"
    ring = page.evaluate("getComputedStyle(document.querySelector('.pp-import-label')).outlineStyle")
    assert ring != "none"  # the hidden input's label shows where focus is
    page.keyboard.press("Tab")
    # nothing kept yet: Clear is disabled, so Tab goes on past it
    assert page.get_by_role("button", name="Clear progress").is_disabled()
    assert page.evaluate("document.activeElement.textContent") != "Clear progress"
