"""First steps and printing, in a real browser (headless Debian Chromium, playwright).

Issue "Reading, printing and first steps", items 6-11: a hint under a page's first unit box,
a unit in the wrong case, feedback that links the section teaching its idea, "Try a similar
one" after a worked example, the definitions self-test, fields named for their part, Clear my
answers with an undo, and printing (the title once; questions without answers by default,
with answers as a choice).
"""

from __future__ import annotations

import json

import pytest
from support.pages import page_without_errors

pytestmark = [pytest.mark.site, pytest.mark.browser]

QUICK = "/book/exam/quick-check.html"
DEFINITIONS = "/book/exam/method-definitions.html"


@pytest.fixture
def page(site):
    browser, base = site
    with page_without_errors(browser) as page:
        page.base = base
        yield page


def _go(page, path: str):
    page.goto(page.base + path, wait_until="load")


def test_the_first_unit_box_of_a_page_has_a_hint_on_typing_units(page):
    _go(page, QUICK)
    hints = page.locator(".q-unit-hint")
    assert hints.count() == 1
    hint = hints.first
    assert hint.is_visible()
    text = hint.inner_text()
    for example in ("N s", "kg m s^-1", "kg m/s", "m s^-2", "case-sensitive"):
        assert example in text
    # Right under the page's first unit box, and read with it by a screen reader.
    first_unit = page.locator("input.q-unit").first
    assert hint.get_attribute("id") in first_unit.get_attribute("aria-describedby").split()
    unit_box, hint_box = first_unit.bounding_box(), hint.bounding_box()
    assert 0 <= hint_box["y"] - (unit_box["y"] + unit_box["height"]) < 60


def test_a_unit_in_the_wrong_case_says_units_are_case_sensitive(page):
    _go(page, QUICK)
    page.fill("#q-quick-check-1-b-value", "7.5")
    page.fill("#q-quick-check-1-b-unit", "M/S")
    page.press("#q-quick-check-1-b-unit", "Enter")
    feedback = page.locator("#q-quick-check-1-b-feedback").inner_text()
    assert "Units are case-sensitive" in feedback and "You probably meant m/s." in feedback


def test_feedback_that_names_an_idea_links_the_section_that_teaches_it(page):
    _go(page, QUICK)
    page.fill("#q-quick-check-1-b-value", "30")  # the bank's named mistake "momentum times mass"
    page.fill("#q-quick-check-1-b-unit", "m/s")
    page.press("#q-quick-check-1-b-unit", "Enter")
    # Every section the bank can name, and every documented rule's row, has its link on the page
    # (none was dropped for a missing page or heading).
    from physics_figures import marking
    from physics_figures.bank.sections import SECTIONS

    links = json.loads(page.locator("script.q-sections").text_content())
    assert set(links) == set(SECTIONS) | {f"rule:{rule['id']}" for rule in marking.documented_rules()}
    link = page.locator("#q-quick-check-1-b-feedback a.q-idea")
    assert link.count() == 1
    assert "momentum" in link.get_attribute("href")
    # The link leads to the section, which exists: its heading is there.
    href = link.get_attribute("href")
    link.click()
    page.wait_for_load_state("load")
    anchor = href.rpartition("#")[2]
    assert anchor and page.locator(f"[id='{anchor}']").count() == 1
    assert "Linear momentum" in page.locator(f"[id='{anchor}'] h2").first.inner_text()
    # A value to 1 s.f. links the rule it breaks, in the rule table.
    _go(page, QUICK)
    page.fill("#q-quick-check-1-b-value", "8")
    page.fill("#q-quick-check-1-b-unit", "m/s")
    page.press("#q-quick-check-1-b-unit", "Enter")
    link = page.locator("#q-quick-check-1-b-feedback a.q-idea")
    assert link.get_attribute("href").endswith("getting-the-marks.html#rule-too-few-sf")
    # A right answer has no link.
    _go(page, QUICK)
    page.fill("#q-quick-check-1-b-value", "7.5")
    page.fill("#q-quick-check-1-b-unit", "m/s")
    page.press("#q-quick-check-1-b-unit", "Enter")
    assert page.locator("#q-quick-check-1-b-feedback a").count() == 0


@pytest.mark.parametrize("number", [1, 2, 3, 4, 5])
def test_each_worked_example_ends_with_try_a_similar_one(page, number):
    _go(page, f"/book/exam/example-{number}.html")
    line = page.locator("p.q-try-similar")
    assert line.count() == 1
    assert line.inner_text().startswith("Try a similar one:")
    kind = page.locator("form.q-form").first.get_attribute("data-type")
    link = line.locator("a")
    target = link.get_attribute("href").rpartition("#")[2]
    link.click()
    page.wait_for_load_state("load")
    form = page.locator(f"#{target} form.q-form")
    assert form.get_attribute("data-type") == kind  # a question of the same type
    assert "/example-" not in page.url  # to practise, not another worked example


def test_question_fields_are_named_for_their_part(page):
    _go(page, QUICK)
    assert page.get_by_label("(a) value").first.get_attribute("id") == "q-quick-check-1-a-value"
    assert page.get_by_label("(b) unit").first.get_attribute("id") == "q-quick-check-1-b-unit"
    assert page.get_by_label("(b) direction").count() >= 1  # quick check 3(b)
    labels = page.locator("#question-quick-check-1 label.q-field span").all_inner_texts()
    assert labels == ["(a) value", "(a) unit", "(b) value", "(b) unit"]
    # A question of one part needs no letter.
    assert page.locator("#question-quick-check-2 label.q-field span").all_inner_texts() == ["Value", "Unit"]


def test_clear_my_answers_can_be_undone(page):
    _go(page, QUICK)
    page.fill("#q-quick-check-5-b-value", "19.4")
    page.fill("#q-quick-check-5-b-unit", "N")
    page.press("#q-quick-check-5-b-unit", "Enter")
    page.click("#question-quick-check-5 button.q-clear")
    assert page.input_value("#q-quick-check-5-b-value") == ""
    undo = page.locator("#question-quick-check-5 button.q-undo")
    assert undo.is_visible()
    assert page.evaluate("document.activeElement.classList.contains('q-undo')")
    undo.click()
    assert page.input_value("#q-quick-check-5-b-value") == "19.4"
    assert page.locator("#q-quick-check-5-b-feedback").inner_text() == "✓ Correct."
    assert not undo.is_visible()
    # Cleared, then typed into again: the undo is gone (nothing overwritten by surprise).
    page.click("#question-quick-check-5 button.q-clear")
    page.fill("#q-quick-check-5-a-value", "1")
    assert not undo.is_visible()


def test_definitions_self_test_by_keyboard_kept_with_the_progress(page):
    _go(page, DEFINITIONS)
    box = page.locator(".admonition.self-test")
    cards = box.locator("li.st-card")
    count = cards.count()
    assert count == 8  # the notes' six definitions and the three laws, as the page lists them
    assert box.locator(".st-status").inner_text() == f"Known: 0 of {count} definitions."
    toggle = box.locator("button.st-toggle")
    toggle.focus()
    page.keyboard.press("Enter")
    assert toggle.get_attribute("aria-pressed") == "true"
    first = cards.first
    assert not first.locator(".st-definition").is_visible()  # hidden: say it first
    assert "Mass" in first.inner_text()
    # Focus is on the first card's Show button: Enter reveals, then Enter on "I knew it".
    assert page.evaluate("document.activeElement.classList.contains('st-reveal')")
    page.keyboard.press("Enter")
    assert first.locator(".st-definition").is_visible()
    assert "resists a change in its motion" in first.locator(".st-definition").inner_text()
    assert page.evaluate("document.activeElement.dataset.mark") == "known"
    page.keyboard.press("Enter")
    # On to the second card; reveal it and mark it not yet (Tab to the second button).
    page.keyboard.press("Enter")
    page.keyboard.press("Tab")
    assert page.evaluate("document.activeElement.dataset.mark") == "not-yet"
    page.keyboard.press("Enter")
    assert box.locator(".st-status").inner_text() == f"Known: 1 of {count} definitions."
    stored = json.loads(page.evaluate("localStorage.getItem('dynamics-progress-v2')"))
    # each mark is also an attempt at its card, for the spaced review
    assert stored["version"] == 2
    assert [(a["question"], a["earned"]) for a in stored["attempts"]] == [("definition:mass", 1),
                                                                          ("definition:weight", 0)]
    assert stored["definitions"]["version"] == 1
    assert stored["definitions"]["cards"]["mass"]["mark"] == "known"
    assert stored["definitions"]["cards"]["weight"]["mark"] == "not-yet"
    # Kept: a reload shows the same count; the practice page still reads the store.
    page.reload(wait_until="load")
    assert page.locator(".st-status").inner_text() == f"Known: 1 of {count} definitions."
    _go(page, "/book/exam/your-practice.html")
    assert "cannot be read" not in page.locator(".pp-status").inner_text()


def _visible_text_in_print(page) -> str:
    page.emulate_media(media="print")
    return page.locator("body").inner_text()


def test_without_javascript_the_self_test_has_no_dead_buttons(site):
    browser, base = site
    context = browser.new_context(java_script_enabled=False)
    page = context.new_page()
    page.goto(base + DEFINITIONS, wait_until="load")
    box = page.locator(".admonition.self-test")
    assert box.locator(".st-bar").count() == 1  # in the page from the start (no layout shift)
    assert not box.locator(".st-bar").is_visible()
    assert box.locator("li").count() == 8 and box.locator("li").first.is_visible()
    context.close()


@pytest.mark.parametrize("path,title", [("/book/understand/weight.html", "Weight"),
                                        (QUICK, "Quick check"),
                                        ("/book/exam/example-2.html", "Example 2")])
def test_a_printed_page_starts_with_its_title_once(page, path, title):
    _go(page, path)
    page.emulate_media(media="print")
    heading = page.locator("article.bd-article h1").first
    assert heading.is_visible()
    assert title in heading.inner_text()  # "5. Weight": numbered as on screen
    text = _visible_text_in_print(page)
    first_line = next(line for line in text.splitlines() if line.strip())
    assert first_line.strip() == heading.inner_text().strip()
    assert sum(1 for line in text.splitlines() if line.strip() == heading.inner_text().strip()) == 1


def test_a_question_page_prints_without_answers_unless_asked(page):
    _go(page, QUICK)
    # A student who checked an answer has opened the worked answer on screen.
    page.fill("#q-quick-check-1-a-value", "15")
    page.fill("#q-quick-check-1-a-unit", "N s")
    page.press("#q-quick-check-1-a-unit", "Enter")
    page.locator("#question-quick-check-1 .q-worked summary").click()
    page.emulate_media(media="print")
    assert page.locator(".q-answer-lines").first.is_visible()  # lines to write on
    lines = page.locator("#question-quick-check-1 .q-answer-lines").bounding_box()
    assert lines["height"] > 100  # with room for working
    for worked in page.locator(".q-worked").all():
        assert not worked.is_visible()
    for question in page.locator("section.q").all():  # no mark scheme in any question
        assert " C1" not in question.inner_text() and " A1" not in question.inner_text()
    # "Print with answers" is offered on screen, and prints the worked answers this once.
    page.emulate_media(media="screen")
    button = page.get_by_role("button", name="Print with answers")
    assert button.is_visible()
    page.evaluate("window.print = () => { window.printed = true; }")
    button.click()
    assert page.evaluate("window.printed")
    page.emulate_media(media="print")
    assert page.locator("#question-quick-check-1 .q-worked").is_visible()
    assert page.locator("#question-quick-check-2 .q-worked").is_visible()  # never checked: still printed
    page.evaluate("window.dispatchEvent(new Event('afterprint'))")
    assert not page.locator("#question-quick-check-2 .q-worked").is_visible()


def test_a_printed_worked_example_keeps_its_solution(page):
    _go(page, "/book/exam/example-2.html")
    page.emulate_media(media="print")
    text = page.locator("body").inner_text()
    assert "Take the direction the ball bounces back as positive" in text
    assert page.locator(".q-print").count() == 0  # no choice needed: the solution is the point


def test_the_landing_page_says_where_to_start_and_lists_what_there_is(page):
    _go(page, "/book/intro.html")
    start = page.get_by_role("link", name="Start here")
    assert start.first.is_visible()
    assert start.first.get_attribute("href").endswith("recap.html")
    # The parts, each with a time estimate and a link to each of its pages.
    parts = page.locator("ul.book-map-parts > li")
    assert parts.count() == 3
    for part in parts.all():
        assert " minutes): " in part.inner_text()
        assert part.locator("a").count() >= 1
    # Every explorable, linked to the page where it runs.
    explorables = page.locator("ul.book-map-explorables > li a")
    assert explorables.count() == 4
    targets = [a.get_attribute("href") for a in explorables.all()]
    # Every page of questions, linked (worked examples are listed with the examples).
    questions = page.locator("ul.book-map-questions > li a")
    assert questions.count() >= 7
    question_pages = [a.get_attribute("href") for a in questions.all()]
    for href in targets:
        _go(page, "/book/" + href)
        assert page.locator(".explorable").count() == 1, href
    for href in question_pages:
        _go(page, "/book/" + href)
        assert page.locator("form.q-form").count() >= 1, href


def test_the_footer_names_an_open_textbook_not_endorsed_by_cambridge(page):
    _go(page, "/book/understand/weight.html")
    footer = page.locator(".bd-footer-content").inner_text()
    assert "An open textbook for the Cambridge International AS & A Level Physics (9702) syllabus" in footer
    assert "not produced or endorsed by Cambridge" in footer
    assert "By Cambridge" not in page.locator("body").inner_text()
