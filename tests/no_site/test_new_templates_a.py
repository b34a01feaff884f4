# ruff: noqa: RUF003  (comments quote the working as typeset: true minus, times)
"""The numeric templates for four of issue 25's gaps, checked against numbers worked by hand.

Each printed variant's keys are worked here from the printed givens with the formula a student
writes (not through the template or the models), with the source of the number in a comment:
the notes' own answer where the notes print one. Then the real named mistakes the issue lists
("momentum added as scalars", "one body's mass used for both", "the kinetic energy
'conserved' in an inelastic collision"), the two models the templates need, and a ratio's
answer, which has no unit, in the browser's marker and in Moodle.
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from moodle_format import check_file
from support.engine import mark_all
from support.templates import printed

from physics_figures import bank
from physics_figures.models import (
    acceleration_from_distance,
    change_in_momentum,
    mass_from_momentum_change,
)
from physics_figures.worksheets import moodle as moodle_export

#: The gaps of issue 25 these templates practise, with their question types.
NEW = {"sticking-fraction-lost": "elastic", "bounce-energy-ratio": "elastic",
       "headed-ball-force-speed": "force-momentum", "mass-from-momentum-change": "force-momentum",
       "stopping-force-distance": "newton", "collision-third-law": "momentum-line"}


ROOT = Path(__file__).resolve().parents[2]


def keys(key: str) -> list[float]:
    return [part.value for part in printed(key).parts]


def mistake(key: str, part: int, name: str) -> float:
    (value,) = [m.value for m in printed(key).parts[part].mistakes if m.name == name]
    return value


# ------------------------------------------------------------------ the templates


@pytest.mark.parametrize(("key", "question_type"), NEW.items())
def test_each_new_template_is_numeric_of_its_type_with_ten_variants_on_its_page(key, question_type):
    template = bank.TEMPLATES[key]
    assert (template.type, template.kinds) == (question_type, ("numeric",))
    assert len(template.values) >= 10
    assert template in bank.by_type(question_type)


def test_kinetic_energy_lost_as_a_fraction_is_the_notes_25_percent():
    # Notes, "Elastic and inelastic collisions": 3.0 kg at 4.0 m s⁻¹ sticks to 1.0 kg at rest,
    # 3.0 × 4.0 = 4.0v so v = 3.0 m s⁻¹; 24 J before, 18 J after: 6.0 J, 25 %, is transferred.
    speed, fraction = keys("sticking-fraction-lost")
    assert speed == pytest.approx(3.0 * 4.0 / (3.0 + 1.0))
    assert fraction == pytest.approx((24 - 18) / 24)
    assert printed("sticking-fraction-lost").parts[1].answer_text == "0.25"  # a ratio: no unit, no space


def test_kinetic_energy_after_over_before_when_a_ball_bounces_back():
    # By hand: 0.20 × 3.0 = 0.20 × (−0.60) + 0.60v, so v = 0.72 / 0.60 = 1.2 m s⁻¹;
    # ½ × 0.20 × 0.60² + ½ × 0.60 × 1.2² = 0.468 J after, ½ × 0.20 × 3.0² = 0.90 J before.
    speed, ratio = keys("bounce-energy-ratio")
    assert speed == pytest.approx(0.20 * (3.0 + 0.60) / 0.60)
    assert ratio == pytest.approx((0.5 * 0.20 * 0.60**2 + 0.5 * 0.60 * 1.2**2) / (0.5 * 0.20 * 3.0**2))
    assert ratio == pytest.approx(0.52)


def test_force_and_speed_from_a_given_change_in_momentum():
    # By hand: F = Δp / Δt = 3.6 / 0.012 = 300 N; the ball turns round, so 3.6 = 0.43(v + 3.0).
    force, speed = keys("headed-ball-force-speed")
    assert force == pytest.approx(3.6 / 0.012)
    assert speed == pytest.approx(3.6 / 0.43 - 3.0)


def test_mass_from_a_force_acting_for_a_time():
    # By hand: Δp = FΔt = 6.0 × 2.5 = 15 N s; m = 15 / (4.2 − 1.2) = 5.0 kg.
    change, mass = keys("mass-from-momentum-change")
    assert change == pytest.approx(15.0)
    assert mass == pytest.approx(5.0)
    # turned round: the puck's velocity changes by the sum of its speeds
    puck = next(q for q in bank.TEMPLATES["mass-from-momentum-change"].variants if "to the left" in q.text)
    force, duration, before, after = (g.value for g in puck.givens)
    assert puck.parts[1].value == pytest.approx(force * duration / (after + before))


def test_braking_force_from_a_stopping_distance():
    # By hand (notes, How to do it 1., "find a from v² = u² + 2as, then F = ma"):
    # 0 = 20² − 2 × a × 50, so a = 4.0 m s⁻²; F = 1500 × 4.0 = 6000 N (or Fs = ½mu²: 300 000 / 50).
    deceleration, force = keys("stopping-force-distance")
    assert deceleration == pytest.approx(20.0**2 / (2 * 50.0))
    assert force == pytest.approx(1500 * 4.0) == pytest.approx(0.5 * 1500 * 20.0**2 / 50.0)


def test_third_law_in_a_collision_is_the_notes_example_3():
    # Notes, Example 3: A 0.60 kg at 2.5 m s⁻¹ hits B 0.40 kg at rest and moves on at 0.50 m s⁻¹;
    # (b) v = 3.0 m s⁻¹; (d) Δp of B = 0.40 × 3.0 = 1.2 N s, F = 1.2 / 0.050 = 24 N.
    change, speed, force = keys("collision-third-law")
    question = printed("collision-third-law")
    assert change == pytest.approx(1.2) and speed == pytest.approx(3.0) and force == pytest.approx(24.0)
    assert [p.answer_direction for p in question.parts] == ["to the right", "", "to the right"]


def test_the_third_law_template_gives_b_what_a_loses_in_every_variant():
    for question in bank.TEMPLATES["collision-third-law"].variants:
        values = {g.name: g.value for g in question.givens}
        mass_a, mass_b = values["mass of A"], values["mass of B"]
        lost_by_a = mass_a * (values["speed of A"] - values.get("speed of A after", 0.0))
        assert question.parts[0].value == pytest.approx(lost_by_a)
        assert question.parts[1].value == pytest.approx(lost_by_a / mass_b - values.get("speed of B", 0.0))


# ------------------------------------------------------------- the issue's real mistakes


def test_the_issues_named_mistakes_are_worked_from_the_printed_numbers():
    # momentum added as scalars: A's rebound taken as positive, 0.20 × (3.0 − 0.60) / 0.60
    assert mistake("bounce-energy-ratio", 0, "momentum added as scalars") == pytest.approx(0.8)
    # the ball's reversal ignored: Δp = m(v − u), v = 3.6 / 0.43 + 3.0
    assert mistake("headed-ball-force-speed", 1, "momentum added as scalars") == pytest.approx(3.6 / 0.43 + 3.0)
    # one body's mass used for both: A's mass for the pair (v = u) and B's mass with A's Δv
    assert mistake("sticking-fraction-lost", 0, "one body's mass used for both") == pytest.approx(4.0)
    assert mistake("collision-third-law", 0, "one body's mass used for both") == pytest.approx(0.40 * 2.0)
    # kinetic energy "conserved" in an inelastic collision: ½ × 3.0 × 4.0² = ½ × 4.0 v², and no energy lost
    assert mistake("sticking-fraction-lost", 0, "kinetic energy conserved") == pytest.approx(math.sqrt(24 / 2))
    assert mistake("sticking-fraction-lost", 1, "kinetic energy conserved") == 0.0
    # the ratio inverted, and the fraction kept given for the fraction lost
    assert mistake("bounce-energy-ratio", 1, "ratio inverted") == pytest.approx(0.90 / 0.468)
    assert mistake("sticking-fraction-lost", 1, "fraction kept, not lost") == pytest.approx(18 / 24)
    # v² = u² + 2as without the square, and with the speed taken as constant (t = s / u)
    assert mistake("stopping-force-distance", 0, "forgot to square the speed") == pytest.approx(20 / 100)
    assert mistake("stopping-force-distance", 0, "time taken as distance ÷ speed") == pytest.approx(400 / 50)


def test_the_scalar_mistake_is_named_only_where_a_body_turns_round_or_moves_the_other_way():
    """With B at rest, adding its speed as a scalar changes nothing: the mistake would be the key."""
    for question in bank.TEMPLATES["collision-third-law"].variants:
        names = {m.name for m in question.parts[1].mistakes}
        b_moves = any(g.name == "speed of B" for g in question.givens)
        assert ("momentum added as scalars" in names) == b_moves


# --------------------------------------------------------------------- the models


@settings(max_examples=100, deadline=None)
@given(u=st.floats(0.0, 60.0), v=st.floats(0.0, 60.0), s=st.floats(0.1, 500.0))
def test_acceleration_from_distance_satisfies_v2_u2_2as(u, v, s):
    a = acceleration_from_distance(u, v, s)
    assert v**2 == pytest.approx(u**2 + 2 * a * s, rel=1e-9, abs=1e-9)


@pytest.mark.parametrize(("args", "message"), [
    ((20.0, 0.0, 0.0), r"^distance must be positive \(got distance=0\.0 m\)$"),
    ((-1.0, 0.0, 5.0), r"^u must not be negative \(got u=-1\.0 m s\^-1\)$"),
])
def test_acceleration_from_distance_refuses_an_impossible_value_by_name(args, message):
    with pytest.raises(ValueError, match=message):
        acceleration_from_distance(*args)


@settings(max_examples=100, deadline=None)
@given(mass=st.floats(0.01, 1000.0), u=st.floats(-50.0, 50.0), v=st.floats(-50.0, 50.0))
def test_mass_from_momentum_change_undoes_the_change_in_momentum(mass, u, v):
    if abs(v - u) < 1e-3:
        return
    assert mass_from_momentum_change(change_in_momentum(mass, u, v), u, v) == pytest.approx(mass, rel=1e-9)


@pytest.mark.parametrize(("args", "message"), [
    ((15.0, 2.0, 2.0), r"^v must differ from u=2\.0 m s\^-1"),
    ((-15.0, 1.2, 4.2), r"^change_in_momentum must be in the direction of the change in velocity"),
])
def test_mass_from_momentum_change_refuses_an_impossible_value_by_name(args, message):
    with pytest.raises(ValueError, match=message):
        mass_from_momentum_change(*args)


@pytest.mark.parametrize(("build", "bad", "message"), [
    ("stopping-force-distance", {"distance": 20.0}, r"distance must let the car stop at no more than 6\.5"),
    ("headed-ball-force-speed", {"change": 1.0}, r"change must exceed the ball's momentum before"),
    ("bounce-energy-ratio", {"back": 2.0}, r"back=2\.0 m s\^-1 would create kinetic energy"),
    ("collision-third-law", {"after_a": 1.5, "mass_b": 1.0}, r"leaves B .* behind A"),
])
def test_an_impossible_variant_is_refused_by_name(build, bad, message):
    with pytest.raises(ValueError, match=message):
        bank.TEMPLATES[build].build(**bad)


# ------------------------------------------------------- a ratio: an answer with no unit


def test_the_browser_takes_a_ratio_as_a_decimal_or_a_percentage_and_names_a_lost_percent_sign():
    part = printed("sticking-fraction-lost").parts[1]
    data = part.browser_data("b")
    typed = [("0.25", ""), ("25", "%"), ("25 %", ""), ("25", ""), ("0.25", "J")]
    results = mark_all([{"part": data, "answer": {"value": v, "unit": u, "direction": ""}} for v, u in typed])
    assert [r["code"] for r in results] == ["correct", "correct", "correct", "mistake", "wrong-unit"]
    assert results[3]["mistake"] == "percentage without %"


def test_moodle_asks_a_ratio_as_a_number_with_no_unit():
    tree, _ = moodle_export.export([bank.TEMPLATES["sticking-fraction-lost"], bank.TEMPLATES["bounce-energy-ratio"]])
    root = ET.fromstring(ET.tostring(tree.getroot(), encoding="unicode"))
    problems, _ = check_file(root)
    assert not problems, problems[:5]
    ratios = [q for q in root.findall("question") if q.findtext("idnumber", "").endswith("-b")]
    assert len(ratios) == 20
    for question in ratios:
        assert (question.findtext("showunits"), question.findtext("unitgradingtype")) == ("3", "0")
        assert question.find("units") is None
        assert "it has no unit" in question.findtext("questiontext/text")
