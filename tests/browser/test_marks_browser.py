"""Each rule of the docs' marking table (book/exam/getting-the-marks.md, from
physics_figures/marking_rules.json), tried in Chromium on the page that asks the question:
the student types an answer, presses Check, and the part shows the marks the rule gives
and, where it lost some, says which."""

from __future__ import annotations

import re

import pytest
from support.pages import page_without_errors
from support.templates import typed

from physics_figures import bank, marking
from physics_figures.constants import G_EARTH

pytestmark = [pytest.mark.site, pytest.mark.browser]

QC3 = bank.TEMPLATES["quick-check-3"].variant(0)
BLOCK = bank.TEMPLATES["block-and-hanging-mass"].variant(0)
WALL = bank.TEMPLATES["practice-wall-bounce"].variant(0)
BALL = bank.TEMPLATES["graph-ball-acceleration"].variant(0)


def _tension_from_hanging_mass(own_a: float) -> float:
    hanging = next(g.value for g in BLOCK.givens if g.name == "hanging mass")
    return hanging * (G_EARTH - own_a)


ACCELERATION = typed(QC3.parts[1].value)  # 11.6 m s⁻² upwards
RIGHT_B = {"value": ACCELERATION, "unit": "m s^-2", "direction": "upwards"}

#: rule id -> (template, the answers typed per part, the part looked at, its marks, a phrase
#: its feedback must hold). Each row of the docs' table has one.
CASES = {
    "correct": ("quick-check-3", {"b": RIGHT_B}, "b", (3, 3), "Correct"),
    "alternative": ("graph-ball-acceleration",
                    {"a": {"value": "30", "unit": "m/s"}, "b": {"value": "9.0", "unit": "m/s"},
                     "c": {"value": typed(BALL.scheme_alternatives(2)[0].value), "unit": "m s^-2"}},
                    "c", (2, 2), "Accepted"),
    "ignore-sign": ("quick-check-3", {"b": {**RIGHT_B, "value": "-" + ACCELERATION}}, "b", (3, 3),
                    "minus sign is ignored"),
    "ecf": ("block-and-hanging-mass",
            {"a": {"value": "3.0", "unit": "m s^-2"},
             "b": {"value": typed(_tension_from_hanging_mass(3.0)), "unit": "N"}}, "b", (2, 2), "ecf"),
    "too-few-sf": ("quick-check-3", {"b": {**RIGHT_B, "value": "1e1"}}, "b", (2, 3),
                   "1 s.f.: the A1 needs 2 or more"),
    "missing-unit": ("quick-check-3", {"a": {"value": typed(QC3.parts[0].value), "unit": ""}}, "a", (0, 1),
                     "give the unit"),
    "wrong-unit": ("quick-check-3", {"b": {**RIGHT_B, "unit": "m/s"}}, "b", (2, 3), "the accuracy mark (A1) is lost"),
    "prefix": ("quick-check-1", {"a": {"value": "15", "unit": "kN s"}}, "a", (1, 2), "prefix"),
    "direction": ("quick-check-3", {"b": {**RIGHT_B, "direction": "downwards"}}, "b", (2, 3),
                  "the direction mark (B1) is lost; the method mark (C1) and the accuracy mark (A1) stand"),
    "mistake-slip": ("quick-check-3", {"b": {**RIGHT_B, "value": typed(QC3.parts[1].answer_for_g(10.0))}}, "b",
                     (2, 3), "the accuracy mark (A1) is lost; the method mark (C1) and the direction mark (B1) stand"),
    "mistake-physics": ("quick-check-3", {"b": {**RIGHT_B, "value": typed(1500 / 70)}}, "b", (1, 3),
                        "the method mark (C1) and the accuracy mark (A1) are lost; the direction mark (B1) stands"),
    "wrong": ("quick-check-3", {"b": {**RIGHT_B, "value": "42"}}, "b", (1, 3), "the method mark (C1) and the accuracy mark (A1) are lost"),
    "compensatory": ("quick-check-1", {"b": {"value": "7.5", "unit": "m/s"}}, "b", (2, 2), "Correct"),
    "dependent-a1": ("terminal-velocity-explained", {"a": {"text": "It speeds up less.", "ticks": [0, 2]}},
                     "a", (1, 3), ""),
    "graph-range": ("graph-ball-acceleration",
                    {"a": {"value": typed(BALL.parts[0].value + BALL.parts[0].tolerance, 4), "unit": "m/s"}},
                    "a", (1, 1), "Correct"),
    "marks-per-part": ("quick-check-4", {"b": {"value": "4.0", "unit": "m/s"}, "a": {"value": "3.0", "unit": "m/s"}},
                       "b", (2, 2), "Correct"),
}


def test_every_rule_of_the_docs_table_has_a_case_here():
    assert sorted(CASES) == sorted(row["id"] for row in marking.documented_rules())


def test_the_rule_table_is_on_the_marks_page_with_its_papers(site_dir):
    html = (site_dir / "book" / "exam" / "getting-the-marks.html").read_text(encoding="utf-8")
    for row in marking.documented_rules():
        assert f'id="rule-{row["id"]}"' in html, row["id"]
        for source in row["sources"]:
            assert source["paper"] in html, source["paper"]


@pytest.mark.parametrize("rule", sorted(CASES))
def test_a_rule_marks_as_the_table_says_on_its_page(question_site, rule):
    browser, base_url, pages = question_site
    key, answers, looked_at, (earned, available), phrase = CASES[rule]
    with page_without_errors(browser, base_url + pages[key]) as page:
        form = page.locator(f'form.q-form[data-question="{key}"]')
        for part_id, answer in answers.items():
            box = form.locator(f'[data-part="{part_id}"]')
            if "text" in answer:
                box.locator("textarea.q-explain").fill(answer["text"])
                continue
            box.locator("input.q-value").fill(answer["value"])
            box.locator("input.q-unit").fill(answer["unit"])
            if answer.get("direction"):
                box.locator("select.q-direction").select_option(answer["direction"])
        form.locator("button.q-check").click()
        for part_id, answer in answers.items():  # a self-marked part is scored by its ticks
            for tick in answer.get("ticks", ()):
                form.locator(f'[data-part="{part_id}"] input.q-tick').nth(tick).check()
        box = form.locator(f'[data-part="{looked_at}"]')
        feedback = box.locator(".q-feedback").inner_text().replace("\u00a0", " ")
        several = form.locator("fieldset.q-part").count() > 1
        shown = box.locator(".q-part-marks").inner_text() if several else form.locator(".q-score").inner_text()
        assert shown.startswith(f"{earned}/{available} mark"), (rule, shown, feedback)
        assert phrase in feedback, (rule, feedback)
        # a tick only beside a part that earned all its marks; one that lost some says which
        assert feedback.startswith("✓") == (earned == available) or feedback[:1] not in "✓✗", feedback
        if 0 < earned < available:
            assert re.search(r"\([ABCM]1\).* (is|are) lost", feedback), feedback  # each code glossed
