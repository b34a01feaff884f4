"""Question templates: fresh numbers that are sensible, distinct and tell every named mistake
apart from the key; one formula per later part, the same in Python and in the browser."""

from __future__ import annotations

import json
import math
import re
import shutil
import subprocess
from pathlib import Path

import pytest
from conftest import variant_param

from physics_figures import bank, textformat
from physics_figures.questions import Question
from physics_figures.variants import (
    KINDS,
    MIN_RESERVE,
    MIN_SITUATIONS,
    MIN_VARIANTS,
    Draw,
    Template,
    accepted_band,
    confusable_mistakes,
    repeats_the_site,
)

ROOT = Path(__file__).resolve().parents[2]
TEMPLATES = list(bank.TEMPLATES.values())
VARIANTS = [variant_param(t, i, t, i) for t in TEMPLATES for i in range(len(t.values))]


@pytest.mark.parametrize("template", TEMPLATES, ids=lambda t: t.key)
def test_each_template_has_enough_distinct_variants(template):
    least = MIN_VARIANTS + MIN_RESERVE if {"numeric", "graph"} & set(template.kinds) else MIN_SITUATIONS
    # a worked example's try-first part keeps its printed numbers; a one-wording statement (a
    # definition) says why it has one variant: neither counts toward the variant rules
    if template.try_first or template.one_wording:
        least = 1
    assert template.least_variants == least
    assert len(template.values) >= least
    assert len({json.dumps(v, sort_keys=True) for v in template.values}) == len(template.values)
    # a graph question may keep its words: its graph then carries the new numbers
    texts = {(q.text, q.graph) for q in template.variants}
    assert len(texts) == len(template.values), "two variants print the same text and graph"
    assert set(template.kinds) == {getattr(p, "kind", "numeric") for q in template.variants for p in q.parts}
    assert template.type in bank.TOPIC.type_keys and set(template.kinds) <= set(KINDS)


@pytest.mark.parametrize(("template", "index"), VARIANTS)
def test_every_variant_is_sensible_and_tells_its_mistakes_apart(template, index):
    question = template.variant(index)
    assert isinstance(question, Question) and question.key == template.key
    textformat.parse(question.text)
    for given in question.givens:  # printed at the precision the exam gives
        assert given.text in textformat.to_plain(question.text), (given.name, given.text)
    for part in question.parts:
        if part.kind == "mcq":  # four different options, one the key, each wrong one a named mistake
            assert sum(not option.mistake for option in part.options) == 1
            continue
        if part.kind in ("explain", "sketch", "text"):  # marked on its own marking points (a sketch: its features)
            assert any(question.parts_of(mark) == (question.part_ids[question.parts.index(part)],)
                       for mark in question.mark_scheme if mark.code)
            continue
        assert math.isfinite(part.value)
        assert part.direction == "signed" or part.value > 0, f"{part.prompt} is {part.value}"
        values = [m.value for m in part.mistakes if m.unit is None and m.direction is None]
        assert len(values) == len(set(values)), f"{part.prompt}: two named mistakes give one value"
    assert not confusable_mistakes(question)


@pytest.mark.parametrize(("template", "index"), VARIANTS)
def test_a_later_parts_formula_gives_its_key_in_python(template, index):
    question = template.variant(index)
    answers = {pid: p.value for pid, p in zip(question.part_ids, question.parts, strict=True)}
    for part in question.parts:
        if part.ecf:  # a size is the formula's size (the browser takes it too)
            worked = part.ecf.evaluate(answers)
            assert (worked if part.direction == "signed" else abs(worked)) == pytest.approx(part.value, rel=1e-12)


def test_the_browser_evaluates_every_ecf_formula_as_python_does():
    """sympy's JavaScript printer writes the formula the browser runs: run it in node on
    every variant's numbers and compare with the key physics_figures computes."""
    node = shutil.which("node")
    assert node, "node is missing: scripts/ensure-debian-packages html installs it"
    cases = []
    for template in TEMPLATES:
        for question in template.variants:
            answers = {pid: p.value for pid, p in zip(question.part_ids, question.parts, strict=True)}
            for pid, part in zip(question.part_ids, question.parts, strict=True):
                if part.ecf:
                    data = part.ecf.browser_data()
                    args = [answers[a] if a in answers else data["values"][a] for a in data["args"]]
                    cases.append({"js": data["js"], "names": data["args"], "args": args,
                                  "expected": part.value, "where": f"{question.key} ({pid})"})
    assert cases, "no template has an ecf part yet"
    script = ("const cases = JSON.parse(require('fs').readFileSync(0, 'utf8'));"
              "console.log(JSON.stringify(cases.map(c => Function(...c.names, 'return ' + c.js)(...c.args))));")
    got = json.loads(subprocess.run([node, "-e", script], input=json.dumps(cases), capture_output=True,
                                    text=True, check=True).stdout)
    for case, value in zip(cases, got, strict=True):
        assert abs(value) == pytest.approx(abs(case["expected"]), rel=1e-12), case["where"]


def test_the_accepted_band_is_what_rounds_to_the_key_at_2_sf():
    assert accepted_band(686.7) == (685.0, 695.0)
    assert accepted_band(0.0154) == pytest.approx((0.0145, 0.0155))


def test_a_draw_grid_is_at_exam_precision_and_a_bad_grid_is_refused():
    assert Draw(5.0, 2.0, 3.0, 0.5).grid == (2.0, 2.5, 3.0)
    assert Draw(0.2, 0.1, 0.3, 0.1).grid == (0.1, 0.2, 0.3)
    with pytest.raises(ValueError, match=r"step must divide high - low"):
        Draw(1.0, 0.0, 1.0, 0.3)


def test_a_template_that_cannot_find_its_variants_says_so():
    original = bank.TEMPLATES["quick-check-1"]
    narrow = Template("quick-check-1", "force-momentum", ("numeric",), "narrow", original.build,
                      {"force": Draw(5.0, 5.0, 6.0, 1.0)})
    with pytest.raises(ValueError, match=r"found only 2 of 20 variants .* widen its draws"):
        narrow.values  # noqa: B018


def test_multiple_choice_options_come_in_increasing_order_from_named_mistakes():
    from physics_figures.questions import choices_in_order

    options, answer = choices_in_order(11.6, {"a": (21.4, "x"), "b": (31.2, "y"), "c": (11.4, "z")},
                                       sig_figs=3, unit="N")
    assert [o.text.split()[0] for o in options] == ["11.4", "11.6", "21.4", "31.2"] and answer == "B"
    with pytest.raises(ValueError, match=r"must print differently from the key"):
        choices_in_order(11.6, {"a": (11.62, "x"), "b": (31.2, "y"), "c": (11.4, "z")}, sig_figs=3, unit="N")


def test_a_template_names_a_type_and_a_real_kind():
    """A template names a type (its topic checks which: tests/no_site/test_topics.py) and real kinds."""
    build = bank.TEMPLATES["quick-check-1"].build
    with pytest.raises(ValueError, match=r"type must name one of its topic's question types"):
        Template("x", "", ("numeric",), "x", build)
    with pytest.raises(ValueError, match=r"kinds must be some of"):
        Template("x", "drag", ("essay",), "x", build)


@pytest.mark.parametrize(("template", "index"), VARIANTS)
def test_feedback_hints_and_prompts_are_plain_text(template, index):
    """The page shows feedback, hints and prompts as text (not HTML): a tag would show as
    typed. Units there are written with Unicode superscripts (m s⁻²)."""
    tag = re.compile(r"</?(sup|sub|em|strong)>")
    for part in template.variant(index).parts:
        texts = [part.prompt, getattr(part, "revisit", ""), getattr(part, "direction_hint", "")]
        texts += [m.feedback for m in getattr(part, "mistakes", ())]
        texts += [o.feedback for o in getattr(part, "options", ())]
        assert not [text for text in texts if tag.search(text)], template.key


RESERVED = [t for t in TEMPLATES if not t.shares_variants and len(t.values) > 1]


@pytest.mark.parametrize("template", RESERVED, ids=lambda t: t.key)
def test_no_reserve_variant_repeats_a_site_variants_givens_or_answers(template):
    """Issue 37: a sheet's question (the reserve) never prints a site variant's givens, nor gives a
    key (to 3 s.f.) that a site variant gives for the same part: graph-skydiver-terminal's reserve
    had a site variant's mass (the same drag), drag-law-terminal-ratio a site variant's masses and
    speed under the other law."""
    site = [template.variant(i) for i in template.site_variants]
    repeats = {i: repeats_the_site(template.variant(i), site) for i in template.reserve_variants}
    assert template.reserve_variants and not {i: r for i, r in repeats.items() if r}, template.key


def test_repeats_the_site_names_a_repeated_answer_and_givens_under_another_law():
    from physics_figures.bank.drag import drag_law_terminal_ratio, skydiver_velocity_time

    found = repeats_the_site(skydiver_velocity_time(terminal=61.0, mass=70.0),
                             [skydiver_velocity_time(terminal=45.0, mass=70.0)])
    assert found == ["drag force at terminal velocity = 687, as in site variant 0"]
    found = repeats_the_site(drag_law_terminal_ratio(1, 45.0, 65.0, 5.5), [drag_law_terminal_ratio(2, 45.0, 65.0, 5.5)])
    assert found[0] == "the givens of site variant 0"
