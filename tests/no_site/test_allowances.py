# ruff: noqa: RUF001, RUF002, RUF003  (typeset text: true minus, times)
"""The schemes' allowances, as data (issue 38, "What to build" 5; departures 1, 2, 3, 5 and 6).

A template declares what a published scheme allows beyond its key, each with the paper:
- values the scheme also accepts, and the value its second route gives from its own rounded
  intermediate ("650 / 5.5"): ``Alternative`` (with ``paper``) and ``Alternative.from_rounded``;
- a minus sign on a size where no direction is asked ("allow −4500 N"): ``Part.allow_minus``;
- the C1 a named mistake keeps where the scheme credits the working it shows:
  ``Mistake.keeps`` with ``Mistake.credited``.
Each earns on the site (the browser's engine, under Node), prints in the sheets' key and grades
alike in Moodle. And every part whose formula uses g names g = 10; a wrong direction is never
read as the g = 10 slip.

The questions here are the bank's templates built with published papers' numbers, as
tests/no_site/real_papers/ poses them; the allowances declared on them are the mechanism's cases.
"""

from __future__ import annotations

import dataclasses
import json
import subprocess
import sys
from pathlib import Path

from support.engine import mark_questions
from support.templates import typed

from physics_figures import bank
from physics_figures.questions import Alternative, Mistake
from physics_figures.worksheets.html import key_body
from physics_figures.worksheets.latex import accept_note, wrong_answers
from physics_figures.worksheets.moodle_answers import graded_answers, interval

ROOT = Path(__file__).resolve().parents[2]

#: 9702/21/M/J/16 Q3(b)(ii): a ball of 0.15 kg hits the floor at 6.2 m s⁻¹ and rebounds at
#: 2.5 m s⁻¹, in contact for 0.12 s; "change in momentum = 0.15 × (6.2 + 2.5) (= 1.305 N s) C1,
#: magnitude of force = 1.305 / 0.12 = 11 (10.9) N A1, (direction of force is) upwards B1".
BOUNCE_16 = {"mass": 0.15, "speed_in": 6.2, "speed_out": 2.5, "contact_ms": 120.0}
#: 9702/22/M/J/25 Q4(b): a ball of 0.25 kg, 5.2 m s⁻¹ before and 3.6 m s⁻¹ after, 0.18 s; the
#: change in momentum's scheme: "C1 for p = mv or 0.25 × 3.6 or 0.25 × 5.2".
BOUNCE_25 = {"mass": 0.25, "speed_in": 5.2, "speed_out": 3.6, "contact_ms": 180.0}
ROUNDED_RULE = "9702/21/M/J/22 Q2(c)(ii): allow 7.2 N m or 7.4 N m from rounded values of F"
MINUS_RULE = "9702/21/M/J/22 Q1(b)(ii): change in momentum = 7.5 (–4.0 – 2.4) C1 = (–) 48 N s A1"
C1_RULE = "9702/22/M/J/25 Q4(b)(i): C1 for p = mv or 0.25 × 3.6 or 0.25 × 5.2"


def _wall(givens: dict, *, index: int, **changes):
    """practice-wall-bounce built with a paper's numbers, one part's data replaced."""
    question = bank.TEMPLATES["practice-wall-bounce"].build(**givens)
    parts = list(question.parts)
    parts[index] = dataclasses.replace(parts[index], **changes)
    return dataclasses.replace(question, parts=tuple(parts))


def _moodle_grade(question, index: int, value: float, *, direction_box: int = 0) -> float | None:
    """The grade Moodle gives a response to a numeric part (its number box, in a Cloze question
    whose direction box gives direction_box marks): its first answer whose range holds it."""
    for grade, centre, width, _ in graded_answers(question, index, direction_box=direction_box):
        low, high = interval(centre, width)
        if low <= value <= high:
            return grade
    return None


def _answer(part, value: str, direction: str | None = None) -> dict:
    return {"value": value, "unit": part.unit,
            "direction": part.answer_direction if direction is None else direction}


# ------------------------------------------------------------------ 1. allow values, second routes


def _rounded_route_question():
    """9702/21/M/J/16 Q3(b)(ii)'s bounce with a contact of 0.14 s: its scheme's second route is
    "(average) acceleration = (6.2 + 2.5) / 0.12 (= 72.5 m s–2) (C1), magnitude of force =
    0.15 × 72.5 (A1)"; here worked from the acceleration rounded to 2 s.f. (62 m s⁻², so
    0.15 × 62 = 9.30 N against the key's 9.32 N), declared as a scheme allows such a route."""
    givens = {**BOUNCE_16, "contact_ms": 140.0}
    mass, contact = givens["mass"], givens["contact_ms"] / 1000
    plain = bank.TEMPLATES["practice-wall-bounce"].build(**givens)
    acceleration = (givens["speed_in"] + givens["speed_out"]) / contact
    route = Alternative.from_rounded(lambda a: mass * a, (acceleration,), 2,
                                     why="F = ma with the acceleration rounded to 62 m s⁻²", paper=ROUNDED_RULE)
    allowed = Alternative(9.4, "a value the scheme allows", paper="9702/22/O/N/16 Q5(b)(iv): allow 0.89")
    return plain, _wall(givens, index=1, alternatives=(route, allowed)), route


def test_a_route_from_the_schemes_rounded_intermediate_earns_full_marks_everywhere():
    plain, question, route = _rounded_route_question()
    part = question.parts[1]
    assert typed(route.value) == "9.30" and typed(part.value) == "9.32"
    answers = {"b": _answer(part, "9.30")}
    before, after = mark_questions([(plain.browser_data(), answers), (question.browser_data(), answers)])
    assert before["results"]["b"]["code"] == "wrong"  # undeclared: refused
    assert after["results"]["b"]["code"] == "alternative", after["results"]["b"]
    assert after["marks"]["byPart"]["b"] == [3, 3]
    assert "9702/21/M/J/22 Q2(c)(ii)" in after["results"]["b"]["message"]
    # the key: accepted, with the paper
    assert "allow 9.3 N" in accept_note(part) and "9702/21/M/J/22 Q2(c)(ii)" in accept_note(part)
    assert "9702/21/M/J/22 Q2(c)(ii)" in key_body(question)
    # Moodle: full marks (it reads 9.30 as 9.3, the key's own 2 s.f. form: CLARIFICATIONS lists
    # trailing zeros among what Moodle cannot tell), and for the route's unrounded value
    assert _moodle_grade(question, 1, 9.30) == 100.0
    assert _moodle_grade(question, 1, 9.302) == 100.0
    assert _moodle_grade(plain, 1, 9.302) != 100.0


def test_a_rounding_the_scheme_allows_is_no_common_wrong_answer():
    """The change in momentum rounded to 1.31 N s (3 s.f.) gives 9.36 N: rounding part-way,
    unless the part declares that route (Alternative.from_rounded): then it is accepted."""
    plain, _, _ = _rounded_route_question()
    part = plain.parts[1]
    early = Alternative.from_rounded(lambda p: p / 0.14, (plain.parts[0].value,), 3,
                                     why="the change in momentum rounded to 1.31 N s", paper=ROUNDED_RULE)
    assert any(typed(value) == typed(early.value) for value, _ in part.rounded_part_way)
    declared = dataclasses.replace(part, alternatives=(early,))
    assert not any(typed(value) == typed(early.value) for value, _ in declared.rounded_part_way)
    question = dataclasses.replace(plain, parts=(plain.parts[0], declared))
    assert not [row for row in wrong_answers(question, 1) if row.name == "rounded part-way"
                and row.written.startswith(typed(early.value))]
    marked = mark_questions([(question.browser_data(), {"b": _answer(part, typed(early.value))})])[0]
    assert marked["results"]["b"]["code"] == "alternative" and marked["marks"]["byPart"]["b"] == [3, 3]


def test_a_schemes_allow_value_earns_full_marks_at_each_written_form():
    _, question, _ = _rounded_route_question()
    part = question.parts[1]
    marked = mark_questions([(question.browser_data(), {"b": _answer(part, value)}) for value in ("9.4", "9.40")])
    for got in marked:
        assert got["results"]["b"]["code"] == "alternative"
        assert got["marks"]["byPart"]["b"] == [3, 3]
    assert _moodle_grade(question, 1, 9.4) == 100.0
    assert "allow 9.4 N" in accept_note(part) and "9702/22/O/N/16 Q5(b)(iv)" in accept_note(part)


def test_an_allow_value_at_two_sf_takes_only_its_two_sf_form_in_moodle():
    """An allowed 0.8627 is written 0.86 (2 s.f.) or 0.863: Moodle takes both, as the book does."""
    part = bank.TEMPLATES["practice-wall-bounce"].build(**BOUNCE_25).parts[1]
    allowed = Alternative(part.value * 0.96, "another route's value", paper=ROUNDED_RULE)
    question = _wall(BOUNCE_25, index=1, alternatives=(allowed,))
    two = float(typed(allowed.value, 2))
    assert _moodle_grade(question, 1, two) == 100.0
    assert _moodle_grade(question, 1, float(typed(allowed.value, 3))) == 100.0


def test_an_alternative_a_named_mistake_gives_too_is_refused():
    part = bank.TEMPLATES["practice-wall-bounce"].build(**BOUNCE_25).parts[0]
    slip = next(m for m in part.mistakes if m.name == "initial momentum only")
    try:
        dataclasses.replace(part, alternatives=(Alternative(slip.value, "a clash", paper=ROUNDED_RULE),))
    except ValueError as error:
        assert "alternatives" in str(error) and "initial momentum only" in str(error)
    else:
        raise AssertionError("an alternative equal to a named mistake was accepted")


# ------------------------------------------------------------------ 2. allow −X on a size


def test_allow_minus_on_a_size_earns_full_marks_only_where_the_part_declares_it():
    impulse = bank.TEMPLATES["quick-check-1"].variant(0)
    part = impulse.parts[0]
    assert part.direction == "none"
    declared = dataclasses.replace(impulse, parts=(dataclasses.replace(part, allow_minus=MINUS_RULE),
                                                   *impulse.parts[1:]))
    minus = {"a": {"value": "-" + typed(part.value), "unit": part.unit}}
    plain, allowed = mark_questions([(impulse.browser_data(), minus), (declared.browser_data(), minus)])
    assert plain["results"]["a"]["code"] == "sign-on-size"  # the default: loses the A1
    assert plain["marks"]["byPart"]["a"][0] < plain["marks"]["byPart"]["a"][1]
    assert allowed["results"]["a"]["code"] == "ignore-sign", allowed["results"]["a"]
    assert allowed["marks"]["byPart"]["a"][0] == allowed["marks"]["byPart"]["a"][1]
    assert "9702/21/M/J/22 Q1(b)(ii)" in allowed["results"]["a"]["message"]
    assert "−" in accept_note(declared.parts[0]) and "9702/21/M/J/22 Q1(b)(ii)" in accept_note(declared.parts[0])
    assert _moodle_grade(declared, 0, -part.value) == 100.0
    assert _moodle_grade(impulse, 0, -part.value) != 100.0


def test_allow_minus_is_only_for_a_size():
    bounce = bank.TEMPLATES["practice-wall-bounce"].build(**BOUNCE_25)
    try:
        dataclasses.replace(bounce.parts[0], allow_minus=MINUS_RULE)
    except ValueError as error:
        assert "allow_minus" in str(error)
    else:
        raise AssertionError("allow_minus was accepted on a part that asks for a direction")


# ------------------------------------------------------------------ 3. the C1 a mistake keeps


def test_a_named_mistake_keeps_the_c1_its_scheme_credits_on_the_site_the_key_and_moodle():
    """9702/22/M/J/25 Q4(b)(i): "u − v instead of u + v" shows p = mv (0.25 × 3.6, 0.25 × 5.2)
    and "initial momentum only" is 0.25 × 5.2: each keeps the C1, and the direction's own B1
    stands where the direction is right. The bank declares it on practice-wall-bounce (a)."""
    question = bank.TEMPLATES["practice-wall-bounce"].build(**BOUNCE_25)
    part = question.parts[0]
    credited = {m.name: m for m in part.mistakes if m.keeps is not None}
    assert set(credited) == {"u - v instead of u + v", "initial momentum only"}
    assert all("9702/22/M/J/25 Q4(b)(i)" in m.credited for m in credited.values())
    marked = mark_questions([(question.browser_data(), {"a": _answer(part, typed(m.value))})
                             for m in credited.values()])
    rows = {row.name: row for row in wrong_answers(question, 0)}
    for mistake, got in zip(credited.values(), marked, strict=True):
        assert got["results"]["a"]["mistake"] == mistake.name
        assert got["marks"]["byPart"]["a"] == [2, 3], (mistake.name, got["marks"])  # the C1 and the B1
        assert rows[mistake.name].marks == "keeps the C1 and the B1: 2/3"
        assert "9702/22/M/J/25 Q4(b)(i)" in rows[mistake.name].feedback
        # Moodle's number box (its direction box gives the B1): the C1 of C1 A1
        assert _moodle_grade(question, 0, float(typed(mistake.value)), direction_box=1) == 50.0
        assert any("9702/22/M/J/25 Q4(b)(i)" in feedback for *_, feedback in graded_answers(question, 0))


def test_keeps_needs_the_paper_that_credits_it():
    try:
        Mistake("initial momentum only", 1.3, "Only the momentum before.", keeps=("method",))
    except ValueError as error:
        assert "credited" in str(error)
    else:
        raise AssertionError("a mistake kept marks with no scheme cited")


# ------------------------------------------------------------------ 5. g = 10 wherever g is used

_G_SCAN = """
import json, math, sys
import physics_figures.bank as before
built = {(key, i): (t.values[i], t.variant(i)) for key, t in before.TEMPLATES.items() for i in range(len(t.values))}
for name in [m for m in sys.modules if m.startswith("physics_figures")]:
    del sys.modules[name]
import physics_figures.constants as constants
constants.G_EARTH = 10.0  # every formula that uses g now gives what a student with g = 10 gets
import physics_figures.bank as after
from physics_figures.parts.numeric import G_TEN_SLIP
found = []
for (key, i), (givens, question) in built.items():
    moved = after.TEMPLATES[key].build(**givens)
    for pid, part, again in zip(question.part_ids, question.parts, moved.parts):
        if part.kind != "numeric" or math.isclose(part.value, again.value, rel_tol=1e-9, abs_tol=1e-15):
            continue
        g_ten = part._size(part.answer_for_g(10.0)) if part.answer_for_g is not None else None
        found.append({"key": key, "variant": i, "part": pid,
                      "named": any(m.name == G_TEN_SLIP for m in part.mistakes),
                      "band_holds": g_ten is not None and part._band_holds(g_ten)})
print(json.dumps(found))
"""


def test_every_part_whose_answer_uses_g_names_the_g_equals_10_slip():
    """The parts whose key moves when g does (every variant rebuilt with g = 10, in a process of
    its own) each name "used g = 10 m s⁻²" (the book's rule: g = 10 loses only the A1), unless
    readings of a graph within half a small square give its g = 10 answer too (then it is right,
    as the schemes take the readings)."""
    result = subprocess.run([sys.executable, "-c", _G_SCAN], check=False, capture_output=True, text=True,
                            timeout=300, cwd=ROOT)
    assert result.returncode == 0, result.stderr[-3000:]
    found = json.loads(result.stdout)
    assert len({row["key"] for row in found}) >= 10, "the scan found too few parts that use g to be trusted"
    lacking = sorted({f"{row['key']} ({row['part']})" for row in found
                      if not row["named"] and not row["band_holds"]})
    assert not lacking, f"parts whose answer uses g but name no g = 10 slip: {lacking}"


# ------------------------------------------------------------------ 6. a wrong direction is no slip


def test_a_wrong_direction_is_not_read_as_the_g_equals_10_slip():
    """rocket-lift-off with 13.1 N on 0.60 kg: a = 12.0 m s⁻² upwards, and g = 10 gives 11.8,
    also 12 at 2 s.f. "12 downwards" is the key's size the wrong way: the scheme takes only the
    direction's B1 (9702/21/M/J/16 Q3(b)(ii): "(direction of force is) upwards B1")."""
    question = bank.TEMPLATES["rocket-lift-off"].build(mass=0.6, thrust=13.1)
    part = question.parts[1]
    assert typed(part.value, 2) == typed(part.answer_for_g(10.0), 2) == "12"
    marked = mark_questions([(question.browser_data(), {"b": _answer(part, "12", "downwards")}),
                             (question.browser_data(), {"b": _answer(part, typed(part.answer_for_g(10.0)))})])
    wrong_way, g_ten = (got["results"]["b"] for got in marked)
    assert wrong_way["code"] == "direction", wrong_way
    assert marked[0]["marks"]["byPart"]["b"] == [2, 3]
    assert g_ten["mistake"] == "used g = 10 m s⁻²" and marked[1]["marks"]["byPart"]["b"] == [2, 3]
    # Moodle's number box takes 12 as right; the direction box alone loses its mark
    assert _moodle_grade(question, 1, 12.0) == 100.0


# ------------------------------------------------------------------ M1 A1 in a numeric part


def test_a_mistake_cannot_keep_an_a1_whose_m1_it_loses():
    """9702/23/O/N/17 Q3(b)(iii): "[both M1 marks required to award this mark] A1". A named
    mistake that keeps the answer's line and loses the method's is refused on a part whose
    scheme codes M1 A1, and stands where the method's line is a C1 (no dependence)."""
    from physics_figures.questions import Mark

    question = bank.TEMPLATES["practice-wall-bounce"].build(**BOUNCE_25)
    part = question.parts[1]
    odd = Mistake("half the change", part.value / 2, "Half.", keeps=("answer", "direction"), credited=C1_RULE)
    stated = dataclasses.replace(part, asks="state", mistakes=(*part.mistakes, odd))
    scheme = tuple(Mark(m.text, "M1", m.part) if m.part == "b" and m.code == "C1" else m for m in question.mark_scheme)
    try:
        dataclasses.replace(question, parts=(question.parts[0], stated), mark_scheme=scheme)
    except ValueError as error:
        assert "M1" in str(error) and "half the change" in str(error)
    else:
        raise AssertionError("a mistake kept the A1 without its M1")
    # with C1 (no dependence) the same declaration stands
    dataclasses.replace(question, parts=(question.parts[0], dataclasses.replace(part, mistakes=(*part.mistakes, odd))))
