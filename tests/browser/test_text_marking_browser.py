"""Text marking on the built site, in Chromium (issue 38, Done when): every typed answer of
tests/fixtures/text_answers.json is typed into its define/state question's textarea and Checked,
with no box ticked. The marks in the form's .q-score ("k/n marks") must equal the examiner's on
at least 95 % of them, and no answer that uses a wording a scheme rejects may earn full marks.
The agreement per template is written to _build/text-marking-agreement.json for the closing
note. An explain part (several points) stays self-marked: the points the marker finds come
ticked, for the student to confirm, and the attempt records that it was self-confirmed."""

from __future__ import annotations

import collections
import json
from pathlib import Path

import pytest
from browser import serve_site
from support.pages import question_page

from physics_figures import bank

pytestmark = [pytest.mark.site, pytest.mark.browser]

ROOT = Path(__file__).resolve().parents[2]
CORPUS = json.loads((ROOT / "tests" / "fixtures" / "text_answers.json").read_text())["answers"]
REPORT = ROOT / "_build" / "text-marking-agreement.json"


@pytest.fixture(scope="module")
def served(site_dir, browser):
    with serve_site(site_dir) as base_url:
        yield browser, base_url


def open_variant(served, site_dir, key: str, variant: int):
    """The page of template `key` showing `variant` (as a student who had pressed New numbers
    comes back to it: questions.js keeps the variant in the store)."""
    browser, base_url = served
    context = browser.new_context()
    page = context.new_page()
    url = base_url + question_page(site_dir, key)
    page.goto(url, wait_until="load")
    if variant:
        page.evaluate("([key, v]) => localStorage.setItem('dynamics-questions:variant:' + key, "
                      "JSON.stringify({variant: v}))", [key, variant])
        page.goto(url, wait_until="load")
        page.wait_for_function(f"document.querySelector('form[data-question=\"{key}\"]').dataset.variant === '{variant}'")
    return context, page.locator(f'form.q-form[data-question="{key}"]')


def test_every_typed_answer_is_marked_as_the_examiner_marks_it(served, site_dir):
    by_page = collections.defaultdict(list)
    for row in CORPUS:
        by_page[(row["template"], row["variant"])].append(row)
    agree, total, rejected_full, disagree = collections.Counter(), collections.Counter(), [], []
    for (key, variant), rows in by_page.items():
        context, form = open_variant(served, site_dir, key, variant)
        part = form.locator('fieldset.q-part[data-kind="text"]')
        assert part.locator("textarea").count() == 1  # the interface kept for checks outside
        available = bank.TEMPLATES[key].variant(variant).marks
        for row in rows:
            part.locator("textarea").fill(row["answer"])
            form.locator("button.q-check").click()
            assert form.locator("input.q-tick:checked").count() == 0  # no box ticked
            score = form.locator(".q-score").inner_text()
            earned, _, out_of = score.partition(" ")[0].partition("/")
            assert score.endswith((" mark", " marks")) and int(out_of) == available, score
            total[key] += 1
            if int(earned) == row["marks"]:
                agree[key] += 1
            else:
                disagree.append((key, row["answer"], row["marks"], int(earned)))
            if row["rejected_wording"] and int(earned) == available:
                rejected_full.append(row["answer"])
        context.close()
    report = {key: {"agree": agree[key], "answers": total[key]} for key in sorted(total)}
    REPORT.write_text(json.dumps({"per_template": report, "agree": sum(agree.values()), "answers": len(CORPUS),
                                  "disagreements": disagree}, ensure_ascii=False, indent=1) + "\n")
    assert sum(total.values()) == len(CORPUS) >= 150
    assert sum(agree.values()) >= 0.95 * len(CORPUS), disagree
    assert rejected_full == []


def test_the_feedback_names_each_point_and_an_undecided_point_is_ticked_by_the_student(served, site_dir):
    context, form = open_variant(served, site_dir, "state-momentum-conservation", 0)
    part = form.locator('fieldset.q-part[data-kind="text"]')
    part.locator("textarea").fill("The total momentum of the system. It stays constant.")
    form.locator("button.q-check").click()
    feedback = part.locator(".q-feedback").inner_text()
    assert "Cannot tell whether your answer makes this point" in feedback
    assert "Missing: provided no resultant external force" in feedback
    assert form.locator(".q-score").inner_text() == "0/2 marks"
    ticks = part.locator("input.q-tick")
    assert ticks.nth(0).is_enabled() and ticks.nth(1).is_disabled()
    ticks.nth(0).check()  # the student says the answer makes it: kept as self-marked
    assert form.locator(".q-score").inner_text() == "1/2 marks"
    progress = form.page.evaluate("JSON.parse(localStorage.getItem('dynamics-progress-v2'))")
    mine = [a for a in progress["attempts"] if a["question"] == "state-momentum-conservation"]
    assert [(a["earned"], a.get("selfMarked")) for a in mine] == [(1, True)]
    part.locator("textarea").fill("The total momentum of an isolated system stays constant.")
    form.locator("button.q-check").click()
    assert form.locator(".q-score").inner_text() == "2/2 marks"
    assert "Made: The total momentum" in part.locator(".q-feedback").inner_text()
    context.close()


def test_an_explain_part_comes_with_the_points_it_makes_ticked_to_confirm(served, site_dir):
    context, form = open_variant(served, site_dir, "terminal-velocity-explained", 0)
    assert form.get_attribute("data-kind") == "explain"
    form.locator("textarea.q-explain").fill(
        "As the skydiver speeds up the air resistance increases, so the resultant force decreases. "
        "When the air resistance equals the weight the velocity is constant.")
    form.locator("button.q-check").click()
    ticks = form.locator("input.q-tick")
    assert [ticks.nth(i).is_checked() for i in range(3)] == [True, True, True]
    assert form.locator(".q-score").inner_text() == "3/3 marks"
    ticks.nth(0).uncheck()  # the student changes a tick: the marks follow
    assert form.locator(".q-score").inner_text() == "2/3 marks"
    progress = form.page.evaluate("JSON.parse(localStorage.getItem('dynamics-progress-v2'))")
    mine = [a for a in progress["attempts"] if a["question"] == "terminal-velocity-explained"]
    assert [(a["earned"], a.get("selfMarked"), a.get("selfConfirmed")) for a in mine] == [(2, True, True)]
    context.close()
