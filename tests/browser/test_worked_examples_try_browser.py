"""Example 1's try-first question in Chromium: a wrong (a) carries forward, the solution opens
after Check (or first, if asked), and printed the box is answer lines (the questions' sources:
tests/no_site/test_worked_examples_try.py)."""

from __future__ import annotations

import pytest
from support.pages import fill_part, page_without_errors, question_form

TRY = "example-1-try"  # the question example 1's page asks a student to try


@pytest.fixture(scope="module")
def example_1(site_dir, browser):
    from browser import serve_site

    with serve_site(site_dir) as base_url:
        yield browser, base_url + "/book/exam/example-1.html"


@pytest.fixture
def page(example_1):
    browser, url = example_1
    with page_without_errors(browser, url) as page:
        yield page


def _answer(page, part: str, value: str, unit: str, direction: str = ""):
    fill_part(question_form(page, TRY), part, value, unit, direction)


def _solution_open(page) -> bool:
    solution = page.locator(".solution.try-first")
    return "toggle-hidden" not in (solution.get_attribute("class") or "") and \
        page.get_by_text("Treat the car and trailer as one object.").is_visible()


@pytest.mark.site
@pytest.mark.browser
def test_a_wrong_a_carries_forward_and_the_solution_opens_after_check(page):
    assert not _solution_open(page), "the solution is hidden until the student tries"
    assert question_form(page, TRY).locator("button.q-new").count() == 0
    # (a) wrong: the resistive forces left out, 3000 / 1600 = 1.875; (b) follows from it:
    # T = 200 + 400 x 1.875 = 950 N; (c) the trailer pulls the car back with that 950 N.
    _answer(page, "a", "1.875", "m s^-2")
    _answer(page, "b", "950", "N")
    _answer(page, "c", "950", "N", "backwards")
    question_form(page, TRY).locator("button.q-check").click()
    a, b, c = (question_form(page, TRY).locator(f'[data-part="{p}"]') for p in "abc")
    assert a.locator(".q-feedback").get_attribute("data-code") == "mistake"
    assert "resistive forces" in a.locator(".q-feedback").inner_text()
    assert a.locator(".q-part-marks").inner_text() == "0/2 marks"
    for later in (b, c):
        assert later.locator(".q-feedback").get_attribute("data-code") == "ecf"
        assert later.locator(".q-part-marks").inner_text() == "2/2 marks (ecf)"
    assert question_form(page, TRY).locator(".q-score").inner_text() == "4/6 marks"
    page.wait_for_function("!document.querySelector('.solution.try-first').classList.contains('toggle-hidden')")
    assert _solution_open(page)
    # The right size the wrong way round loses only the direction's B1.
    _answer(page, "a", "1.5", "m s^-2")
    _answer(page, "b", "800", "N")
    _answer(page, "c", "800", "N", "forwards")
    question_form(page, TRY).locator("button.q-check").click()
    assert c.locator(".q-part-marks").inner_text() == "1/2 marks"
    assert question_form(page, TRY).locator(".q-score").inner_text() == "5/6 marks"


@pytest.mark.site
@pytest.mark.browser
def test_the_solution_opens_once_and_the_student_can_open_it_first(page):
    # Opened by the student before any attempt: it is the notes' ordinary dropdown.
    page.locator(".solution.try-first .toggle-button").click()
    assert _solution_open(page)
    page.locator(".solution.try-first .toggle-button").click()
    assert not _solution_open(page)
    # The first Check opens it; closed again, a later Check leaves it closed.
    _answer(page, "a", "1.5", "m s^-2")
    question_form(page, TRY).locator("button.q-check").click()
    assert _solution_open(page)
    page.locator(".solution.try-first .toggle-button").click()
    question_form(page, TRY).locator("button.q-check").click()
    assert not _solution_open(page)
    # After a reload the attempt is restored, and so is the open solution.
    page.reload(wait_until="load")
    assert question_form(page, TRY).locator(".q-score").inner_text() == "2/6 marks"
    assert _solution_open(page)


@pytest.mark.site
@pytest.mark.browser
def test_printed_the_example_keeps_its_solution_and_the_box_is_answer_lines(page):
    page.emulate_media(media="print")
    assert not question_form(page, TRY).is_visible()
    lines = page.locator("#question-example-1-try .q-answer-lines")
    assert lines.is_visible()
    assert "(a) acceleration of the car and trailer =" in lines.inner_text()
    assert page.get_by_text("Treat the car and trailer as one object.").is_visible()
