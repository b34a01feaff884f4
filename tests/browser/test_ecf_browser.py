"""Error carried forward on every dependent part of the bank, in Chromium: for each part
whose formula uses earlier answers, the student gets those earlier parts wrong, works the
part from their own wrong values, and the page gives it full marks as "ecf".

The tests share a tab per page (several questions sit on one practice page): each test starts
as a student trying again, with Clear my answers, so each question's page loads once, not once
a part (fifty-odd loads of the same few pages were most of this module's time)."""

from __future__ import annotations

import re

import pytest

from physics_figures import bank
from physics_figures.notation import format_number, plain_number

pytestmark = [pytest.mark.site, pytest.mark.browser]

@pytest.fixture(scope="module")
def question_tab(question_site):
    """``tab(key)``: the loaded page that asks the question ``key``, one tab a page for the whole
    module, with its form cleared (Clear my answers); and the script errors of every tab, which
    each test checks last."""
    browser, base_url, pages = question_site
    context = browser.new_context()
    tabs, errors = {}, []

    def tab(key: str):
        assert key in pages, f"no page places {key}"
        if pages[key] not in tabs:
            page = context.new_page()
            page.on("pageerror", lambda error: errors.append(str(error)))
            page.goto(base_url + pages[key], wait_until="load")
            tabs[pages[key]] = page
        page = tabs[pages[key]]
        page.locator(f'form.q-form[data-question="{key}"] button.q-clear').click()
        return page

    yield tab, errors
    context.close()


#: Wrong by these factors, in order, until one is neither right nor a named mistake.
WRONG_FACTORS = (1.25, 1.4, 0.7, 1.6)


def _dependent_parts():
    for template in bank.TEMPLATES.values():
        question = template.variant(0)
        for index, part in enumerate(question.parts):
            if part.ecf is not None:
                yield pytest.param(template.key, index, id=f"{template.key}-{question.part_ids[index]}")


DEPENDENT = list(_dependent_parts())


def _wrong(part, nth: int) -> float:
    """A value for an earlier part that the marker takes as wrong and as no named mistake; the
    nth part used is wrong by another factor (scaled alike, an angle from two would be right)."""
    for factor in WRONG_FACTORS[nth:] + WRONG_FACTORS[:nth]:
        value = part.value * factor + (4 * part.tolerance if part.kind == "graph" else 0)
        if not part._accepted(value) and not part._named(abs(value) if part.direction != "signed" else value):
            return value
    raise AssertionError(f"{part.prompt}: no wrong value to carry")


def _typed(value: float) -> str:
    return plain_number(format_number(value, 4))


def _fill(form, part_id: str, part, value: float, direction: str) -> None:
    box = form.locator(f'[data-part="{part_id}"]')
    box.locator("input.q-value").fill(_typed(value if part.direction == "signed" else abs(value)))
    box.locator("input.q-unit").fill(part.unit)
    if part.direction == "choice":
        box.locator("select.q-direction").select_option(direction)


@pytest.mark.parametrize(("key", "index"), DEPENDENT)
def test_a_part_worked_from_wrong_earlier_answers_earns_its_marks_as_ecf(question_tab, key, index):
    tab, errors = question_tab
    question = bank.TEMPLATES[key].variant(0)
    target = question.parts[index]
    answers = {pid: p.value for pid, p in zip(question.part_ids, question.parts, strict=True)}
    for nth, used in enumerate(target.ecf.uses):
        answers[used] = _wrong(question.parts[question.part_ids.index(used)], nth)
    carried = target.ecf.evaluate(answers)
    form = tab(key).locator(f'form.q-form[data-question="{key}"]')
    assert form.get_attribute("data-variant") == "0"
    for pid, part in zip(question.part_ids[:index], question.parts[:index], strict=True):
        if part.kind in ("numeric", "graph"):
            _fill(form, pid, part, answers[pid], part.answer_direction)
    _fill(form, question.part_ids[index], target, carried, target.answer_direction)
    form.locator("button.q-check").click()
    box = form.locator(f'[data-part="{question.part_ids[index]}"]')
    for used in target.ecf.uses:  # the earlier parts really were wrong
        assert form.locator(f'[data-part="{used}"] .q-feedback').get_attribute("data-code") != "correct"
    assert box.locator(".q-feedback").get_attribute("data-code") == "ecf", box.locator(".q-feedback").inner_text()
    earned, available = re.match(r"(\d+)/(\d+) marks? \(ecf\)", box.locator(".q-part-marks").inner_text()).groups()
    assert earned == available != "0"
    assert not errors, errors


@pytest.mark.parametrize("key", ["puck-components", "explosion-two-pieces"])
def test_sin_and_cos_swapped_in_a_and_b_earns_ecf_in_c_and_d_on_the_page(question_tab, key):
    """The examiner's case (issue 37): sin and cos swapped in (a) and (b), typed to 2 s.f.;
    (c) and (d) worked from those values with all their figures, typed to 3 s.f.: each earns
    all its marks as ecf (it scored 0/3 and 1/3)."""
    tab, errors = question_tab
    question = bank.TEMPLATES[key].variant(0)
    parts = dict(zip(question.part_ids, question.parts, strict=True))
    swapped = {pid: next(m.value for m in parts[pid].mistakes if m.name == "sin and cos swapped") for pid in "ab"}
    form = tab(key).locator(f'form.q-form[data-question="{key}"]')
    for pid, sig_figs in (("a", 2), ("b", 2), ("c", 3), ("d", 3)):
        value = swapped[pid] if pid in "ab" else parts[pid].ecf.evaluate(swapped)
        box = form.locator(f'[data-part="{pid}"]')
        box.locator("input.q-value").fill(plain_number(format_number(
            value if parts[pid].direction == "signed" else abs(value), sig_figs)))
        box.locator("input.q-unit").fill(parts[pid].unit)
        if parts[pid].direction == "choice":
            box.locator("select.q-direction").select_option(parts[pid].answer_direction)
    form.locator("button.q-check").click()
    for pid in "cd":
        box = form.locator(f'[data-part="{pid}"]')
        assert box.locator(".q-feedback").get_attribute("data-code") == "ecf", box.locator(".q-feedback").inner_text()
        earned, available = re.match(r"(\d+)/(\d+) marks? \(ecf\)", box.locator(".q-part-marks").inner_text()).groups()
        assert earned == available != "0"
    assert not errors, errors
