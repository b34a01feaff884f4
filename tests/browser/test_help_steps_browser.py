"""Help before the answer, as a student meets it in Chromium on the quick-check page: "Show a
step" reveals a part's working one step at a time by keyboard, never its answer; the attempt a
Check keeps in the progress store says how many steps were shown, how long the numbers were
on screen and whether it was the first Check on them; New numbers brings the new numbers'
steps; the sign, unit and 1 s.f. slips are kept as named mistakes. Expectations come from
the bank (physics_figures.bank), never typed by hand."""

from __future__ import annotations

import json
import re

import pytest
from support.pages import page_without_errors, question_form

from physics_figures import bank
from physics_figures.notation import format_number

pytestmark = [pytest.mark.site, pytest.mark.browser]

PAGE = "/book/exam/quick-check.html"
KEY = "quick-check-1"  # (a) Δp = FΔt, (b) speed = p / m: two numeric parts
SIGNED = "quick-check-4"  # (a) a signed velocity
STORE = "dynamics-progress-v2"
START = 1_800_000_000  # a fixed clock (s, as Playwright's Python clock takes it): the seconds on screen are known


@pytest.fixture
def page(site):
    browser, base = site
    # Date.now() stands still until the test moves it
    with page_without_errors(browser, base + PAGE, before=lambda page: page.clock.set_fixed_time(START)) as page:
        yield page


def _later(page, seconds: int):
    page.clock.set_fixed_time(page.evaluate("Date.now()") / 1000 + seconds)


def _part(page, part_id, key=KEY):
    return question_form(page, key).locator(f'[data-part="{part_id}"]')


def _attempts(page, key=KEY) -> list[dict]:
    stored = json.loads(page.evaluate(f"localStorage.getItem({STORE!r})") or '{"attempts": []}')
    return [a for a in stored["attempts"] if a["question"] == key]


def _printed_answer(part) -> str:
    return format_number(abs(part.value), part.shown_sig_figs)


def _holds(text: str, number: str) -> bool:
    return re.search(rf"(?<![\d.]){re.escape(number)}(?!\.?\d)", text) is not None


def _answer_right(page, question, key=KEY):
    for part_id, part in zip(question.part_ids, question.parts, strict=True):
        box = _part(page, part_id, key)
        box.locator("input.q-value").fill(format_number(part.value, 3).replace("\u2212", "-"))
        box.locator("input.q-unit").fill(part.unit)


def _new_numbers(page):
    form = question_form(page, KEY)
    before = form.get_attribute("data-variant")
    form.locator("button.q-new").click()
    page.wait_for_function(f"document.querySelector('form[data-question=\"{KEY}\"]').dataset.variant "
                           f"!== {json.dumps(before)}")


def _reveal_all_by_keyboard(page, part_id) -> list[str]:
    """Press the part's Show a step with the keyboard until it is gone; the steps' HTML."""
    box = _part(page, part_id)
    button = box.locator("button.q-step")
    steps = box.locator(".q-steps li")
    shown = 0
    while button.is_visible():
        left = int(re.fullmatch(r"Show a step \((\d+) left\)", button.inner_text()).group(1))
        button.focus()
        page.keyboard.press("Enter" if shown % 2 == 0 else " ")  # a native button: Enter and Space
        shown += 1
        assert steps.count() == shown
        assert button.is_hidden() if left == 1 else button.inner_text() == f"Show a step ({left - 1} left)"
    return [steps.nth(i).inner_html() for i in range(shown)]


def test_steps_come_one_at_a_time_by_keyboard_and_never_give_the_answer(page):
    question = bank.TEMPLATES[KEY].variant(0)
    data = question.browser_data()
    for part_id, part in zip(question.part_ids, question.parts, strict=True):
        box = _part(page, part_id)
        assert box.locator(".q-steps").get_attribute("aria-live") == "polite"
        assert box.locator(".q-steps li").count() == 0
        shown = _reveal_all_by_keyboard(page, part_id)
        # the revisit hint first, then the part's own mark lines, never its A1
        assert shown[0] == part.revisit
        lines = [m["html"] for m in data["marks"] if m["part"] == part_id]
        answer_line = [m["html"] for m in data["marks"] if m["part"] == part_id and m["code"] == "A1"][-1]
        # a later part's line says "your answer to (a)" where the scheme prints (a)'s answer
        earlier = [(pid, _printed_answer(p)) for pid, p in zip(question.part_ids, question.parts, strict=True)
                   if question.part_ids.index(pid) < question.part_ids.index(part_id)]
        ours = lines + [line.replace(printed, f"your answer to ({pid})") for line in lines for pid, printed in earlier]
        assert len(shown) >= 2 and all(step in ours and step != answer_line for step in shown[1:]), shown
        texts = box.locator(".q-steps").inner_text().replace("\u00a0", " ")
        assert not _holds(texts, _printed_answer(part)), texts
        assert not any(_holds(texts, printed) for _, printed in earlier), texts
        # the last step shown, the button is gone and the answer boxes have the focus
        assert page.evaluate("document.activeElement.classList.contains('q-value')")
    # On paper the steps (in the form) are not printed.
    page.emulate_media(media="print")
    assert _part(page, "a").locator(".q-steps li").first.is_hidden()


def test_a_check_keeps_the_help_the_time_and_the_first_try_and_help_is_hard_at_best(page):
    question = bank.TEMPLATES[KEY].variant(0)
    a_steps = _part(page, "a").locator(".q-steps li")
    _part(page, "a").locator("button.q-step").click()
    _part(page, "b").locator("button.q-step").click()
    _part(page, "b").locator("button.q-step").click()
    _later(page, 42)  # 42 s after the numbers came on screen
    _answer_right(page, question)
    question_form(page, KEY).locator("button.q-check").click()
    assert question_form(page, KEY).locator(".q-score").inner_text() == "4/4 marks, with 3 steps of help"
    [attempt] = _attempts(page)
    assert attempt["help"] == 3 and attempt["first"] is True and attempt["seconds"] == 42
    assert attempt["rating"] == 2  # full marks with help: Hard (CLARIFICATIONS, Plan)
    # Clear my answers does not undo the help used on these numbers, nor does a reload
    question_form(page, KEY).locator("button.q-clear").click()
    assert a_steps.count() == 1
    page.reload(wait_until="load")
    assert a_steps.count() == 1 and _part(page, "b").locator(".q-steps li").count() == 2
    _later(page, 5)  # a restored page counts from its load
    _answer_right(page, question)
    question_form(page, KEY).locator("button.q-check").click()
    second = _attempts(page)[-1]
    assert second["help"] == 3 and second["first"] is False and second["seconds"] == 5


def test_without_help_a_quick_first_try_is_easy(page):
    question = bank.TEMPLATES[KEY].variant(0)
    _later(page, 30)
    _answer_right(page, question)
    question_form(page, KEY).locator("button.q-check").click()
    assert question_form(page, KEY).locator(".q-score").inner_text() == "4/4 marks"  # no help: nothing said
    [attempt] = _attempts(page)
    assert attempt["help"] == 0 and attempt["first"] is True and attempt["seconds"] == 30
    assert attempt["rating"] == 4


def test_new_numbers_bring_their_own_steps_and_no_help_yet(page):
    box = _part(page, "a")
    before = _reveal_all_by_keyboard(page, "a")
    form = question_form(page, KEY)
    _later(page, 100)
    _new_numbers(page)
    _later(page, 7)  # the time counts from the new numbers
    variant = int(form.get_attribute("data-variant"))
    question = bank.TEMPLATES[KEY].variant(variant)
    assert box.locator(".q-steps li").count() == 0 and box.locator("button.q-step").is_visible()
    after = _reveal_all_by_keyboard(page, "a")
    assert after != before  # the working's numbers are the new numbers'
    texts = box.locator(".q-steps").inner_text().replace("\u00a0", " ")
    assert not _holds(texts, _printed_answer(question.parts[0])), texts
    _answer_right(page, question)
    form.locator("button.q-check").click()
    [attempt] = _attempts(page)
    assert attempt["variant"] == variant and attempt["help"] == len(after) and attempt["first"] is True
    assert attempt["seconds"] == 7
    # A round of New numbers shows every variant once and comes back to the first: with no help yet.
    while form.get_attribute("data-variant") != "0":
        _new_numbers(page)
    assert box.locator(".q-steps li").count() == 0
    assert box.locator("button.q-step").inner_text() == f"Show a step ({len(before)} left)"


def test_a_sign_a_missing_unit_and_a_1_sf_answer_are_kept_as_named_mistakes(page):
    a, b = bank.TEMPLATES[KEY].variant(0).parts
    _part(page, "a").locator("input.q-value").fill(format_number(a.value, 3))
    _part(page, "b").locator("input.q-value").fill(format_number(b.value, 1))  # 1 s.f.
    _part(page, "b").locator("input.q-unit").fill(b.unit)
    question_form(page, KEY).locator("button.q-check").click()
    assert [_part(page, p).locator(".q-feedback").get_attribute("data-code") for p in "ab"] == [
        "missing-unit", "too-few-sf"]
    assert _attempts(page)[-1]["mistakes"] == ["unit missing or wrong", "1 s.f. answer"]
    signed = bank.TEMPLATES[SIGNED].variant(0).parts[0]
    assert signed.direction == "signed"
    box = _part(page, "a", SIGNED)
    box.locator("input.q-value").fill(format_number(-signed.value, 3).replace("\u2212", "-"))
    box.locator("input.q-unit").fill(signed.unit)
    question_form(page, SIGNED).locator("button.q-check").click()
    assert box.locator(".q-feedback").get_attribute("data-code") == "sign"
    assert "sign or direction" in _attempts(page, SIGNED)[-1]["mistakes"]
