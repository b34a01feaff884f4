"""The quick-check page in a real browser (headless Debian Chromium, driven by playwright).

Against the built site (`site_dir`; SITE_DIR points at a site built elsewhere), served by
a local static server: a student types answers, presses Enter or Check, reads the
feedback in the role="status" element, reloads, and clears. Answers are the notes'
(Notes, "Quick check" > "Answers", 3 and 4).
"""

from __future__ import annotations

import pytest
from browser import VIEWPORTS, axe_violations, serve_site
from design_tokens import rgb

from physics_figures import bank
from physics_figures.notation import join_units
from physics_figures.style import colour as token

pytestmark = [pytest.mark.site, pytest.mark.browser]

PAGE = "/book/exam/quick-check.html"


@pytest.fixture(scope="module")
def browser_and_url(site_dir, browser):
    if not (site_dir / PAGE.lstrip("/")).exists():
        pytest.fail(f"{site_dir}{PAGE} is missing: the quick check page is not in the built site")
    with serve_site(site_dir) as base_url:
        yield browser, base_url + PAGE


def _open(browser, url, **context_options):
    context = browser.new_context(**context_options)
    page = context.new_page()
    errors = []  # from the questions' script only (the theme's own errors are checked elsewhere)
    page.on("console", lambda m: m.type == "error" and "questions" in m.location.get("url", "")
            and errors.append(m.text))
    page.on("pageerror", lambda e: any(s in (e.stack or "") for s in ("questions.js", "marking.js", "answer-reading.js", "question-kinds")) and errors.append(str(e)))
    page.goto(url, wait_until="load")
    return context, page, errors


def _feedback(page, question: str, part: str):
    return page.locator(f"#q-quick-check-{question}-{part}-feedback")


def test_typing_an_answer_and_pressing_enter_marks_it(browser_and_url):
    browser, url = browser_and_url
    context, page, errors = _open(browser, url)
    page.fill("#q-quick-check-4-a-value", "-2.0")
    page.fill("#q-quick-check-4-a-unit", "m/s")
    page.press("#q-quick-check-4-a-unit", "Enter")
    status = _feedback(page, 4, "a")
    assert status.get_attribute("role") == "status"
    assert status.inner_text() == "✓ Correct."
    # The other part, left empty, is asked for; the worked answer can now be opened.
    assert "Type a number" in _feedback(page, 4, "b").inner_text()
    worked = page.locator("#question-quick-check-4 .q-worked")
    assert worked.is_visible()
    worked.locator("summary").click()
    assert "C1" in worked.inner_text() and "A1" in worked.inner_text()
    assert not errors
    context.close()


def test_a_sign_slip_gets_its_own_message_and_direction_is_chosen_from_a_list(browser_and_url):
    browser, url = browser_and_url
    context, page, errors = _open(browser, url)
    page.fill("#q-quick-check-4-a-value", "2.0")
    page.fill("#q-quick-check-4-a-unit", "m s^-1")
    page.click("#question-quick-check-4 button.q-check")
    assert "sign is wrong" in _feedback(page, 4, "a").inner_text()
    page.fill("#q-quick-check-3-b-value", "11.6")
    page.fill("#q-quick-check-3-b-unit", "m s⁻²")
    page.select_option("#q-quick-check-3-b-direction", "downwards")
    page.press("#q-quick-check-3-b-value", "Enter")
    assert "still falling, but slowing down" in _feedback(page, 3, "b").inner_text()
    page.select_option("#q-quick-check-3-b-direction", "upwards")
    page.press("#q-quick-check-3-b-value", "Enter")
    assert _feedback(page, 3, "b").inner_text() == "✓ Correct."
    assert not errors
    context.close()


def _sign_note(key: str, variant: int) -> str:
    """The note above a signed part, as form.py writes it, with this variant's words."""
    positive = next(p.positive for p in bank.TEMPLATES[key].variant(variant).parts if p.direction == "signed")
    return f"Give a signed value: positive is {join_units(positive)}."


def test_the_sign_note_names_the_new_numbers_masses_after_new_numbers_and_a_reload(browser_and_url):
    """The note names the ball by its mass ("the 1.0 kg ball"): New numbers, and a page opened
    on the numbers a student had (a Start card), give it the numbers' own."""
    browser, url = browser_and_url
    context, page, errors = _open(browser, url)
    form = page.locator('form.q-form[data-question="quick-check-4"]')
    note = page.locator("#q-quick-check-4-a-note")
    assert note.inner_text() == _sign_note("quick-check-4", 0)
    form.locator("button.q-new").click()
    page.wait_for_function("document.querySelector('form[data-question=\"quick-check-4\"]').dataset.variant !== '0'")
    variant = int(form.get_attribute("data-variant"))
    assert _sign_note("quick-check-4", variant) != _sign_note("quick-check-4", 0)  # the masses differ
    assert note.inner_text() == _sign_note("quick-check-4", variant)
    assert page.locator("#q-quick-check-4-b-note").inner_text() == _sign_note("quick-check-4", variant)
    page.reload(wait_until="load")
    assert form.get_attribute("data-variant") == str(variant)
    assert note.inner_text() == _sign_note("quick-check-4", variant)
    assert not errors
    context.close()


#: A mock test that draws one of `wanted` ("key:variant"), stored for the page to take up.
WITH_ONE_OF = """(wanted) => {
    const index = JSON.parse(document.querySelector('script.mock-index').textContent);
    for (let seed = 0; seed < 5000; seed++) {
        const test = MockDraw.draw(index, '2', 30, seed);
        if (test.questions.some(q => wanted.includes(q.question + ':' + q.variant))) {
            Object.assign(test, {version: 1, at: Date.now(), answers: {}, warned: []});
            localStorage.setItem('dynamics-mock-v1', JSON.stringify(test));
            return test;
        }
    }
    return null;
}"""


def _signed(key: str) -> bool:
    return any(getattr(p, "direction", "") == "signed" for p in bank.TEMPLATES[key].variant(0).parts)


def test_the_sign_note_in_a_mock_test_names_the_drawn_variant_s_masses(browser_and_url):
    """The mock test writes each question's form from its template's (variant 0's words) and
    relabels it: the note names the drawn variant's masses."""
    browser, url = browser_and_url
    signed = [key for key in bank.TEMPLATES if _signed(key)]
    wanted = [f"{key}:{v}" for key in signed for v in bank.TEMPLATES[key].site_variants
              if _sign_note(key, v) != _sign_note(key, 0)]
    assert wanted, "no template's sign note changes with its numbers"
    context, page, errors = _open(browser, url.replace("quick-check.html", "mock-test.html"))
    test = page.evaluate(WITH_ONE_OF, wanted)
    assert test, f"no mock test draws one of {wanted}"
    page.reload(wait_until="load")
    page.locator(".mock-q").first.wait_for()
    drawn = [(i, q["question"], q["variant"]) for i, q in enumerate(test["questions"]) if q["question"] in signed]
    assert any(f"{key}:{v}" in wanted for _, key, v in drawn)
    for index, key, variant in drawn:
        note = page.locator(f'.mock-q[data-index="{index}"] .q-note').first
        assert note.inner_text() == _sign_note(key, variant), (key, variant)
    assert not errors
    context.close()


def test_answers_survive_a_reload_and_clear_forgets_them(browser_and_url):
    browser, url = browser_and_url
    context, page, errors = _open(browser, url)
    page.fill("#q-quick-check-5-b-value", "19.4")
    page.fill("#q-quick-check-5-b-unit", "N")
    page.press("#q-quick-check-5-b-unit", "Enter")
    page.fill("#q-quick-check-1-a-value", "15")  # typed, not yet checked
    page.reload(wait_until="load")
    assert page.input_value("#q-quick-check-5-b-value") == "19.4"
    assert page.input_value("#q-quick-check-5-b-unit") == "N"
    assert _feedback(page, 5, "b").inner_text() == "✓ Correct."  # a checked answer is marked again
    assert page.input_value("#q-quick-check-1-a-value") == "15"
    page.click("#question-quick-check-5 button.q-clear")
    assert page.input_value("#q-quick-check-5-b-value") == ""
    assert _feedback(page, 5, "b").inner_text() == ""
    assert not page.locator("#question-quick-check-5 .q-worked").is_visible()
    page.reload(wait_until="load")
    assert page.input_value("#q-quick-check-5-b-value") == ""
    assert page.input_value("#q-quick-check-1-a-value") == "15"  # only that question was cleared
    assert not errors
    context.close()


def test_without_javascript_each_question_has_an_answer_line_and_no_dead_boxes(browser_and_url):
    browser, url = browser_and_url
    context, page, _ = _open(browser, url, java_script_enabled=False)
    question = page.locator("#question-quick-check-1")
    assert question.locator(".q-answer-lines").is_visible()
    assert "final momentum = " in question.locator(".q-answer-lines").inner_text()
    assert not question.locator("form").is_visible()
    assert not question.locator(".q-worked").is_visible()
    assert page.locator(".q-print").count() == 1 and not page.locator(".q-print").is_visible()
    context.close()


def test_usable_at_390_px_in_dark_mode_with_no_accessibility_violations(browser_and_url):
    browser, url = browser_and_url
    context, page, errors = _open(browser, url, viewport=VIEWPORTS["mobile"])
    page.evaluate("document.documentElement.dataset.theme = 'dark'")
    page.fill("#q-quick-check-2-a-value", "1.0")
    page.fill("#q-quick-check-2-a-unit", "m/s")
    page.press("#q-quick-check-2-a-unit", "Enter")
    box = page.locator("#question-quick-check-2").bounding_box()
    assert box["x"] >= 0 and box["x"] + box["width"] <= VIEWPORTS["mobile"]["width"]
    for field in ("value", "unit"):
        field_box = page.locator(f"#q-quick-check-2-a-{field}").bounding_box()
        assert field_box["x"] + field_box["width"] <= box["x"] + box["width"]
        assert field_box["height"] >= 36  # big enough to tap
    colour = page.locator("#q-quick-check-2-a-feedback").evaluate("e => getComputedStyle(e).color")
    # the dark theme's green, not the light one
    assert colour == "rgb({}, {}, {})".format(*rgb(token("site.q-right", "dark")))
    violations = axe_violations(page, context_selector="section.q")
    assert not violations, violations
    assert not errors
    context.close()
