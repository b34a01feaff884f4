"""Error carried forward after a named mistake (issue 37; CLARIFICATIONS, "ecf after a named
mistake"): an earlier part's answer is the student's answer, whatever mistake it shows, and a
later part worked correctly from it earns ecf, whether the student typed the later answer from
the earlier one as typed (2 s.f.) or from all its figures (3 s.f.). The browser's engine marks
the bank's own data under Node; the key (the sheets' and Moodle's ecf note) says the same.

Also the later parts an examiner marks by the student's own route (issue 37, "ecf where the
later part can be done without the earlier one"): practice-pucks (b) by sin or cos from a
wrong (a), Quick check 5 (b) from the student's own wrong mass.
"""

from __future__ import annotations

import math
import re

import pytest
from support.engine import mark_questions

from physics_figures import bank
from physics_figures.notation import format_number, plain_number
from physics_figures.worksheets.latex import ecf_note

SWAPPED = "sin and cos swapped"


def _typed(value: float, sig_figs: int) -> str:
    """As a student types it, its figures beyond doubt (660 to 2 s.f. is written 6.6e2)."""
    text = plain_number(format_number(value, sig_figs))
    digits = re.sub(r"[^0-9]", "", text).lstrip("0")
    if "." not in text and len(digits) > sig_figs:
        text = f"{value:.{sig_figs - 1}e}"
    return text


def _answer(part, value: float, sig_figs: int) -> dict:
    shown = value if part.direction == "signed" else abs(value)
    return {"value": _typed(shown, sig_figs), "unit": part.unit, "direction": part.answer_direction}


@pytest.mark.parametrize("key", ["puck-components", "explosion-two-pieces"])
def test_sin_and_cos_swapped_in_a_and_b_carries_into_c_and_d_as_ecf(key):
    """The examiner's case, in every variant: sin and cos swapped in (a) and (b), typed to 2 s.f.
    as the key prints (and to 3 s.f.); (c) and (d) worked from those values (all their figures)
    typed to 3 s.f., and to 2 s.f.: each earns all its marks as ecf (before the fix, at 3 s.f.
    (d) scored 1/3 and (c) 0/3)."""
    cases, where = [], []
    for variant, question in enumerate(bank.TEMPLATES[key].variants):
        parts = dict(zip(question.part_ids, question.parts, strict=True))
        swapped = {pid: next(m.value for m in parts[pid].mistakes if m.name == SWAPPED) for pid in "ab"}
        marks = dict(zip(question.part_ids, question.part_marks(), strict=True))
        for earlier_sf in (2, 3):
            for later_sf in (3, 2):
                answers = {pid: _answer(parts[pid], swapped[pid], earlier_sf) for pid in "ab"}
                for pid in "cd":
                    answers[pid] = _answer(parts[pid], parts[pid].ecf.evaluate(swapped), later_sf)
                cases.append((question.browser_data(), answers))
                where.append((variant, marks))
    wrong = []
    for (variant, marks), (_, answers), marked in zip(where, cases, mark_questions(cases), strict=True):
        results = marked["results"]
        assert [results[p].get("mistake") for p in "ab"] == [SWAPPED, SWAPPED], results
        wrong += [(variant, pid, answers, results[pid]["message"]) for pid in "cd"
                  if (results[pid]["code"], marked["marks"]["byPart"][pid]) != ("ecf", [marks[pid], marks[pid]])]
    assert not wrong, wrong


def _carried_cases():
    """(template key, variant, part id, mistake, the earlier parts it follows from) for every
    named mistake of the bank that follows from the same mistake earlier."""
    for template in bank.TEMPLATES.values():
        for index, question in enumerate(template.variants):
            for part_index in range(len(question.parts)):
                for name, uses in question.carried_mistakes(part_index).items():
                    yield template.key, index, question.part_ids[part_index], name, uses


CARRIED = list(_carried_cases())


def test_the_bank_has_named_mistakes_that_follow_from_earlier_ones():
    """The cases below are not empty: puck-components' and explosion-two-pieces' (c) and (d)
    follow from the swap in (a) and (b)."""
    found = {(key, part_id, name) for key, variant, part_id, name, _ in CARRIED if variant == 0}
    for key in ("puck-components", "explosion-two-pieces"):
        assert {(key, "c", SWAPPED), (key, "d", SWAPPED)} <= found


def test_every_named_mistake_carried_from_an_earlier_part_earns_ecf():
    """Each named mistake of a later part that follows from the same mistake in the earlier
    parts (Question.carried_mistakes), in every variant: those typed to 2 s.f., the later part
    to 3 s.f. from their full values, earns all its marks as ecf. (An earlier g = 10 that rounds
    to the key at 2 s.f. is the key there, so it is typed to 3 s.f.)"""
    cases, owns = [], []
    for key, variant, part_id, name, uses in CARRIED:
        question = bank.TEMPLATES[key].variant(variant)
        parts = dict(zip(question.part_ids, question.parts, strict=True))
        shown = {u: next(m.value for m in parts[u].mistakes if m.name == name) for u in uses}
        answers = {u: _answer(parts[u], value, 2 if _typed(abs(value), 2) != _typed(abs(parts[u].value), 2) else 3)
                   for u, value in shown.items()}
        target = parts[part_id]
        answers[part_id] = _answer(target, next(m.value for m in target.mistakes if m.name == name), 3)
        cases.append((question.browser_data(), answers))
        owns.append(question.part_marks()[question.part_ids.index(part_id)])
    wrong = [(case, answers, marked["results"][case[2]]["message"])
             for case, (_, answers), own, marked in zip(CARRIED, cases, owns, mark_questions(cases), strict=True)
             if (marked["results"][case[2]]["code"], marked["marks"]["byPart"][case[2]]) != ("ecf", [own, own])]
    assert not wrong, wrong


def test_the_key_says_a_named_mistake_carried_forward_earns_ecf():
    """The sheets' and Moodle's ecf note (worksheets.latex.ecf_note) names the mistake that
    follows from the earlier parts' and says it earns ecf, as the site marks it."""
    question = bank.TEMPLATES["puck-components"].variant(0)
    for index in (2, 3):
        note = ecf_note(question, index)
        assert f"{SWAPPED} in (a), (b)" in note and "earns these marks too" in note, note


# ------------------------------------------------ a later part worked by the student's own route


def _own_route(question, route: str, a: float) -> float:
    """(b) as a student works it from their own (a): the angle by sin or cos of B's momentum
    (components from the givens, as the key's working has them), or the weight m g."""
    b = question.parts[1]
    if route == "weight":
        return a * question.givens[1].value
    along, across = (step.value for step in b.working)
    return math.degrees(math.asin(across / a) if route == "sin" else math.acos(along / a))


@pytest.mark.parametrize(("key", "route"), [("practice-pucks", "sin"), ("practice-pucks", "cos"),
                                             ("quick-check-5", "weight")])
def test_a_part_worked_by_the_students_own_route_from_a_wrong_earlier_answer_earns_ecf(key, route):
    """In every variant: (a) wrong (and no named mistake), (b) worked by the student's own
    route from (a) as typed: (b) earns all its marks as ecf."""
    cases = []
    for question in bank.TEMPLATES[key].variants:
        first, second = question.parts
        a = next(first.value * f for f in (1.1, 1.25, 0.9)
                 if not first._accepted(first.value * f) and not first._named(first.value * f))
        b = _own_route(question, route, float(_typed(a, 3)))  # from (a) as typed: all the figures it has
        cases.append((question.browser_data(), {"a": _answer(first, a, 3), "b": _answer(second, b, 3)}))
    own = bank.TEMPLATES[key].variant(0).part_marks()[1]
    marked = mark_questions(cases)
    assert all(m["results"]["a"]["code"] != "correct" for m in marked)
    wrong = [(answers, m["results"]["b"]["message"]) for (_, answers), m in zip(cases, marked, strict=True)
             if (m["results"]["b"]["code"], m["marks"]["byPart"]["b"]) != ("ecf", [own, own])]
    assert not wrong, wrong
