# ruff: noqa: RUF002  (docstrings are typeset: true minus, Greek letters)
"""Marks as the published schemes give them, on the bank's own questions: the data the site
ships (Question.browser_data) marked whole by the browser's engine under Node.

Each case is a row of the rule table (physics_figures/marking_rules.json; the docs' table in
book/exam/getting-the-marks.md cites the papers).
"""

from __future__ import annotations

import json
import re
import subprocess
from pathlib import Path

import pytest
from support.engine import mark_questions, node
from support.templates import typed

from physics_figures import bank, marking
from physics_figures.constants import G_EARTH

ROOT = Path(__file__).resolve().parents[2]
ENGINE = ROOT / "book" / "_ext" / "questions" / "static" / "marking.js"


def one(key: str, answers: dict, variant: int = 0) -> dict:
    data = bank.TEMPLATES[key].variant(variant).browser_data()
    return mark_questions([(data, answers)])[0]


def right(part, sig_figs: int = 3) -> dict:
    return {"value": typed(part.value, sig_figs), "unit": part.unit, "direction": part.answer_direction}


QC3 = bank.TEMPLATES["quick-check-3"].variant(0)


def test_the_right_size_in_the_wrong_direction_loses_only_the_direction_mark():
    b = QC3.parts[1]
    for direction in ("downwards", ""):  # the named mistake "still falling", and no direction chosen
        marked = one("quick-check-3", {"b": {**right(b), "direction": direction}})
        assert marked["marks"]["byPart"]["b"] == [2, 3], direction
        assert marked["lost"]["b"] == "2/3 marks: the direction mark (B1) is lost; the method mark (C1) and the accuracy mark (A1) stand."


def test_g_equals_10_loses_only_the_a1_and_says_so():
    b = QC3.parts[1]
    marked = one("quick-check-3", {"b": {**right(b), "value": typed(b.answer_for_g(10.0))}})
    assert marked["results"]["b"]["mistake"] == "used g = 10 m s⁻²"
    assert marked["marks"]["byPart"]["b"] == [2, 3]
    assert marked["lost"]["b"] == "2/3 marks: the accuracy mark (A1) is lost; the method mark (C1) and the direction mark (B1) stand."
    assert "A1" in marked["results"]["b"]["message"]


@pytest.mark.parametrize(("key", "part_id", "value"), [
    ("quick-check-3", "b", "1e1"),   # 11.6 to 1 s.f.
    ("quick-check-1", "b", "8"),     # 7.5 to 1 s.f. (half away from zero)
    ("practice-wall-bounce", "b", "200"),
])
def test_a_one_sf_answer_loses_only_the_a1_and_says_so(key, part_id, value):
    question = bank.TEMPLATES[key].variant(0)
    index = question.part_ids.index(part_id)
    part = question.parts[index]
    marked = one(key, {part_id: {**right(part), "value": value}})
    result = marked["results"][part_id]
    got, available = marked["marks"]["byPart"][part_id]
    if result["code"] == "correct":  # the key itself prints to 1 s.f. here (200 N): nothing to lose
        assert got == available
        return
    assert result["code"] == "too-few-sf", result
    assert result["message"].startswith("1 s.f.: the A1 needs 2 or more")
    assert (got, available) == (available - 1, available)


def test_a_minus_sign_on_a_size_whose_direction_is_asked_separately_loses_nothing():
    b = QC3.parts[1]
    marked = one("quick-check-3", {"b": {**right(b), "value": "-" + typed(b.value)}})
    assert marked["results"]["b"]["code"] == "ignore-sign"
    assert marked["marks"]["byPart"]["b"] == [3, 3]


def test_a_wrong_or_missing_unit_never_earns_full_marks():
    a, b = QC3.parts
    cases = [("a", {"value": typed(a.value), "unit": ""}), ("a", {"value": typed(a.value), "unit": "kg"}),
             ("b", {**right(b), "unit": ""}), ("b", {**right(b), "unit": "m/s"})]
    data = QC3.browser_data()
    marked = mark_questions([(data, {part_id: answer}) for part_id, answer in cases])
    for (part_id, answer), got in zip(cases, marked, strict=True):
        earned, available = got["marks"]["byPart"][part_id]
        assert earned < available, (part_id, answer)
    assert marked[0]["marks"]["byPart"]["a"] == [0, 1]  # a one-mark part: the mark is the A1's
    assert marked[2]["marks"]["byPart"]["b"] == [2, 3]


def test_a_power_of_ten_slip_keeps_the_c1():
    question = bank.TEMPLATES["practice-wall-bounce"].variant(0)
    slip = next(m for m in question.parts[1].mistakes if m.name == "milliseconds not converted")
    assert slip.kind == "slip"
    marked = one("practice-wall-bounce", {"b": {**right(question.parts[1]), "value": typed(slip.value)}})
    assert marked["marks"]["byPart"]["b"] == [2, 3]  # the C1 and the direction's B1
    assert marked["lost"]["b"] == "2/3 marks: the accuracy mark (A1) is lost; the method mark (C1) and the direction mark (B1) stand."


def test_every_part_right_earns_its_own_marks_whatever_the_other_parts_say():
    """Each part answered right with the others left blank: it shows every one of its marks."""
    cases, where = [], []
    for key, template in bank.TEMPLATES.items():
        question = template.variant(0)
        data = question.browser_data()
        marks = question.part_marks()
        for index, (part_id, part) in enumerate(zip(question.part_ids, question.parts, strict=True)):
            if part.kind in ("explain", "text"):  # marked from words: tests/no_site/test_text_marking.py
                continue
            if part.kind == "sketch":  # its model line, drawn
                cases.append((data, {part_id: {"line": [list(point) for point in part.model]}}))
                where.append((key, part_id, marks[index]))
                continue
            answer = {"choice": part.answer} if part.kind == "mcq" else right(part, max(part.shown_sig_figs, 3))
            cases.append((data, {part_id: answer}))
            where.append((key, part_id, marks[index]))
    for (key, part_id, own), got in zip(where, mark_questions(cases), strict=True):
        assert got["marks"]["byPart"][part_id] == [own, own], (key, part_id, got["results"][part_id])


def test_a_right_answer_after_wrong_earlier_parts_is_right():
    """graph-ball-acceleration (c): 4.22 m s⁻², the scheme's working from the readings as printed,
    and the key itself, earn (c)'s marks with (a) and (b) wrong."""
    question = bank.TEMPLATES["graph-ball-acceleration"].variant(0)
    c = question.parts[2]
    wrong = {"a": {"value": "30", "unit": "m/s"}, "b": {"value": "9.0", "unit": "m/s"}}
    for value in ("4.22", typed(c.value)):
        marked = one("graph-ball-acceleration", {**wrong, "c": {"value": value, "unit": "m s^-2"}})
        assert marked["marks"]["byPart"]["c"] == [2, 2], (value, marked["results"]["c"])


def test_ecf_credits_each_method_the_template_declares():
    """block-and-hanging-mass (b): the tension from the block (T − F = m₁a) and from the hanging
    mass (m₂g − T = m₂a), each with the student's own wrong acceleration."""
    question = bank.TEMPLATES["block-and-hanging-mass"].variant(0)
    assert len(question.parts[1].ecf_methods) == 2
    block_mass, hanging_mass, friction = (g.value for g in question.givens)
    own_a = 3.0
    for tension in (friction + block_mass * own_a, hanging_mass * (G_EARTH - own_a)):
        marked = one("block-and-hanging-mass", {"a": {"value": "3.0", "unit": "m s^-2"},
                                                "b": {"value": typed(tension), "unit": "N"}})
        assert marked["results"]["b"]["code"] == "ecf", tension
        assert marked["marks"]["byPart"]["b"] == [2, 2]


def test_a_declared_alternative_value_is_accepted():
    question = bank.TEMPLATES["graph-ball-acceleration"].variant(0)
    data = question.browser_data()
    alternatives = data["parts"][2]["alternatives"]
    assert alternatives, "graph-ball-acceleration (c) declares the scheme's own working as an alternative"
    for alternative in alternatives:
        marked = mark_questions([(data, {"c": {"value": typed(alternative["value"]), "unit": "m s^-2"}})])[0]
        assert marked["results"]["c"]["code"] == "alternative"
        assert marked["marks"]["byPart"]["c"] == [2, 2]


def test_no_marking_rule_is_written_in_the_engine():
    """The rule table is physics_figures/marking_rules.json: the engine and its part kinds name no
    mark code, have no significant-figure number of their own and no list of what an outcome
    loses, and every outcome they can give is in the table."""
    kinds = sorted((ENGINE.parent / "question-kinds").glob("*.js"))
    assert kinds, "no part kind scripts"
    scripts = [ENGINE, ENGINE.parent / "answer-reading.js", ENGINE.parent / "sig-figs.js", *kinds]  # the engine, not the page code
    engine = "".join(script.read_text(encoding="utf-8") for script in scripts)
    code_only = re.sub(r"/\*.*?\*/|//[^\n]*", "", engine, flags=re.DOTALL)
    assert not re.search(r"\"[ABCM]1\"", code_only), "a mark code in the engine's code"
    assert not re.search(r"minSf \|\| \d|checkSf \|\| \d", code_only), "a significant-figure default in the engine"
    assert not re.search(r"ALL_BUT_A1|WRONG_WAY|NOT_AN_ERROR|lose: \"", code_only)
    codes = set(re.findall(r"(?:\bout\(|\boutcome\(|\bcode: )\s*\"([a-z0-9.-]+)\"", code_only))
    codes |= set(re.findall(r"\? \"([a-z-]+)\" : \"([a-z-]+)\"", code_only)[0]) if re.search(
        r"\? \"([a-z-]+)\" : \"([a-z-]+)\"", code_only) else set()
    table = set(marking.rules()["outcomes"])
    assert codes, "no outcome codes found in the engine"
    assert codes - {"self-marked"} <= table, f"outcomes with no rule: {sorted(codes - table)}"


def test_ecf_carries_on_through_a_part_that_was_itself_ecf():
    """example-1-try: (a) wrong (resistive forces left out), (b) worked from it, (c) from (b):
    both later parts earn their marks as ecf."""
    data = bank.TEMPLATES["example-1-try"].variant(0).browser_data()
    marked = mark_questions([(data, {"a": {"value": "1.875", "unit": "m s^-2"}, "b": {"value": "950", "unit": "N"},
                                     "c": {"value": "950", "unit": "N", "direction": "backwards"}})])[0]
    assert [marked["results"][p]["code"] for p in "abc"] == ["mistake", "ecf", "ecf"]


@pytest.mark.parametrize(("key", "part_id"), [("elastic-both-moving", "c"), ("sphere-in-liquid", "c")])
def test_the_second_method_of_a_later_part_carries_a_wrong_earlier_answer(key, part_id):
    """elastic-both-moving (c) by momentum as well as by relative speeds; sphere-in-liquid (c)
    from the drag alone (W − U = D, so the resultant at half the speed is D / 2)."""
    question = bank.TEMPLATES[key].variant(0)
    index = question.part_ids.index(part_id)
    part = question.parts[index]
    assert len(part.ecf_methods) == 2
    answers = {pid: p.value for pid, p in zip(question.part_ids, question.parts, strict=True)}
    wrong = {used: answers[used] * 1.3 for used in part.ecf_methods[1].uses}
    own = part.ecf_methods[1].evaluate({**answers, **wrong})
    typed_answers = {pid: {"value": typed(v, 4), "unit": question.parts[question.part_ids.index(pid)].unit}
                     for pid, v in {**answers, **wrong}.items() if pid < part_id}
    typed_answers[part_id] = {"value": typed(own, 4), "unit": part.unit}
    marked = one(key, typed_answers)
    assert marked["results"][part_id]["code"] == "ecf", marked["results"][part_id]
    own_marks = question.part_marks()[index]
    assert marked["marks"]["byPart"][part_id] == [own_marks, own_marks]


def test_a_template_may_declare_an_alternative_value():
    """A value from another valid route, declared on the part (Part.alternatives), earns the
    part's marks as the key does, with its reason."""
    import dataclasses

    from physics_figures.questions import Alternative

    question = bank.TEMPLATES["quick-check-1"].variant(0)
    other = dataclasses.replace(question.parts[1], alternatives=(Alternative(7.4, "another route's value"),))
    data = dataclasses.replace(question, parts=(question.parts[0], other)).browser_data()
    marked = mark_questions([(data, {"b": {"value": "7.4", "unit": "m/s"}})])[0]
    assert marked["results"]["b"]["code"] == "alternative"
    assert "another route's value" in marked["results"]["b"]["message"]
    assert marked["marks"]["byPart"]["b"] == [2, 2]


def test_every_part_kind_has_its_python_class_and_its_browser_marker():
    """physics_figures.parts.KINDS and the kinds registered in QuestionKinds (static/question-kinds.js,
    from the scripts in static/question-kinds/) name the same kinds, and every template's kinds are
    among them."""
    from physics_figures import parts
    from physics_figures.variants import KINDS

    registry = ENGINE.parent / "question-kinds.js"
    listed = subprocess.run([node(), "-e", f"console.log(JSON.stringify(require({json.dumps(str(registry))}).names()))"],
                            check=True, capture_output=True, text=True, timeout=60)
    registered = set(json.loads(listed.stdout))
    assert registered == set(parts.KINDS) == set(KINDS)
    assert {kind for template in bank.TEMPLATES.values() for kind in template.kinds} <= registered


def test_every_slip_a_record_names_is_an_outcome_of_the_rule_table():
    """The slips Your practice counts as mistakes (CLARIFICATIONS, Plan: a sign error, a missing
    unit, a 1 s.f. answer) name outcomes the rule table has, each under one name, and link to a
    rule that is one of them."""
    outcomes = marking.rules()["outcomes"]
    named = [code for slip in marking.slips().values() for code in slip["outcomes"]]
    assert sorted(set(named)) == sorted(named), "an outcome is under two slips"
    assert set(named) <= set(outcomes), f"slips name outcomes the table lacks: {set(named) - set(outcomes)}"
    for name, slip in marking.slips().items():
        assert slip["rule"] in slip["outcomes"], f"{name!r} links to a rule it does not cover"
    assert {"sign", "missing-unit", "too-few-sf"} <= set(marking.outcome_slips())


@pytest.mark.parametrize(("typed", "padded"), [("60", True), ("60.", True), ("6.0e1", True), ("6e1", False)])
def test_the_1_sf_feedback_is_the_rule_tables_in_the_browser_and_in_python(typed, padded):
    """The key to 1 s.f., written with or without zeros after it (60. for 64 N is 64 N to
    1 s.f.), is one slip: all but the A1, and the one feedback the table gives (Moodle's rows
    and the sheets fill it with physics_figures.marking.too_few_sf_feedback)."""
    part = QC3.parts[0]  # the drag, in N
    data = QC3.browser_data()
    data["parts"][0]["value"] = 64.2  # the case: a key of 64 N
    answer = {"a": {"value": typed, "unit": part.unit}}
    marked = mark_questions([(data, answer)])[0]
    result = marked["results"]["a"]
    assert result["code"] == "too-few-sf", result
    assert result["message"] == marking.too_few_sf_feedback(1, padded=padded)
    assert "Work to 3 s.f.; give 2 or more." in result["message"]
    got, available = marked["marks"]["byPart"]["a"]
    assert (got, available) == (available - 1, available)


def test_too_few_sf_feedback_refuses_a_count_that_is_not_too_few():
    with pytest.raises(ValueError, match="few must be at least 1 and fewer than min_sf=2"):
        marking.too_few_sf_feedback(2)


def test_feedback_names_each_mark_by_the_rule_table_s_names():
    """The engine glosses a code with the table's "mark_names" (the book's glossary: an A1 is the
    accuracy mark), which the page ships with the outcomes."""
    names = marking.mark_names()
    assert names["A1"] == "accuracy mark" and names["C1"] == "method mark" and names["direction"] == "direction mark"
    b = QC3.parts[1]
    marked = one("quick-check-3", {"b": {**right(b), "direction": "downwards"}})
    assert f"the {names['direction']} (B1) is lost" in marked["lost"]["b"]
