# ruff: noqa: RUF001, RUF002, RUF003  (question text is typeset: true minus, times, Greek letters)
"""The drag-law and two-dimensional templates of issue 25, checked against formulas worked by
hand from each variant's printed text: never through the template's own physics (the models).

A drag law given in the question (F = kv, F = kv²): at terminal speed kvⁿ = mg, so k = mg / vⁿ
and vₜ ∝ m^(1/n) (notes, "Drag, air resistance and terminal velocity": "with a given drag
formula ... set it equal to W and solve"). Two dimensions: resolve p cos θ along and p sin θ
across, conserve each (notes, "Momentum in two dimensions")."""

from __future__ import annotations

import math
import re

import pytest
from support.templates import numbered_variants

from physics_figures import textformat
from physics_figures.bank import TEMPLATES
from physics_figures.notation import format_number

G = 9.81  # the data sheet's g (notes: Key facts)


def _printed(question) -> dict[str, float]:
    """Each given as the question prints it, read back from the text as a number."""
    words = textformat.to_plain(question.text)
    values = {}
    for given in question.givens:
        assert given.text in words, (question.key, given.name)
        values[given.name] = float(given.text.replace("\u2212", "-").replace("\u202f", ""))
    return values


def _law_power(question) -> int:
    """The power of v in the law the text states: F = kv² or F = kv."""
    words = textformat.to_plain(question.text)
    found = re.search(r"F = kv(2?)\b", words)
    assert found, question.key
    return 2 if found[1] else 1


def _same(part, hand: float) -> None:
    """The key is the hand value, exactly and as printed."""
    assert part.value == pytest.approx(hand, rel=1e-9, abs=1e-12), part.prompt
    assert format_number(part.value, part.shown_sig_figs) == format_number(hand, part.shown_sig_figs)


@pytest.mark.parametrize(("index", "question"), numbered_variants("drag-law-constant"))
def test_drag_law_constant_is_the_weight_over_the_terminal_speed_to_the_laws_power(index, question):
    given, power = _printed(question), _law_power(question)
    weight = given["mass"] / 1000 * G  # printed in g
    drag, k = question.parts
    _same(drag, weight)
    _same(k, weight / given["terminal speed"] ** power)
    assert k.unit == ("kg m^-1" if power == 2 else "kg s^-1")
    wrong_power = {m.name: m.value for m in k.mistakes}["speed not squared" if power == 2 else "speed squared"]
    assert wrong_power == pytest.approx(weight / given["terminal speed"] ** (3 - power))


@pytest.mark.parametrize(("index", "question"), numbered_variants("drag-law-terminal-ratio"))
def test_a_heavier_ball_falls_faster_by_the_root_of_the_mass_ratio_for_kv2_and_the_ratio_for_kv(index, question):
    given, power = _printed(question), _law_power(question)
    ratio = given["mass of B"] / given["mass of A"]
    speed_b, accel = question.parts
    _same(speed_b, given["terminal speed of A"] * ratio ** (1 / power))
    # at A's terminal speed the drag on B is A's weight: a = (m_B − m_A) g / m_B, whatever the law
    _same(accel, G * (given["mass of B"] - given["mass of A"]) / given["mass of B"])


@pytest.mark.parametrize(("index", "question"), numbered_variants("stokes-terminal-speed"))
def test_stokes_terminal_speed_is_the_weight_less_the_upthrust_over_6_pi_eta_r(index, question):
    given = _printed(question)
    r = given["radius"] / 1000  # printed in mm
    volume = 4 / 3 * math.pi * r**3
    lift = given["density of the liquid"] * G * volume  # upthrust ρgV
    upthrust, speed = question.parts
    _same(upthrust, lift)
    # weight = 6πηrv + upthrust at terminal speed
    _same(speed, (given["mass"] / 1000 * G - lift) / (6 * math.pi * given["viscosity"] * r))
    forgot = {m.name: m.value for m in speed.mistakes}["upthrust forgotten"]
    assert forgot == pytest.approx(given["mass"] / 1000 * G / (6 * math.pi * given["viscosity"] * r))


@pytest.mark.parametrize(("index", "question"), numbered_variants("puck-components"))
def test_puck_components_conserve_momentum_along_and_across_x(index, question):
    given = _printed(question)
    theta = math.radians(given["angle"])
    p_after = given["mass of A"] * given["speed of A after"]
    a_x, a_y = p_after * math.cos(theta), p_after * math.sin(theta)
    b_x, b_y = given["mass of A"] * given["speed of A before"] - a_x, a_y
    x_part, y_part, speed, angle = question.parts
    _same(x_part, a_x)
    _same(y_part, a_y)
    _same(speed, math.hypot(b_x, b_y) / given["mass of B"])
    _same(angle, math.degrees(math.atan(b_y / b_x)))
    assert angle.answer_direction == "on the other side of the x-direction from A"
    swapped_x = {m.name: m.value for m in x_part.mistakes}["sin and cos swapped"]
    assert swapped_x == pytest.approx(p_after * math.sin(theta))  # sin where cos belongs
    scalar = {m.name: m.value for m in speed.mistakes}["momentum added as scalars"]
    assert scalar == pytest.approx(given["mass of A"] * (given["speed of A before"] - given["speed of A after"])
                                   / given["mass of B"])


@pytest.mark.parametrize(("index", "question"), numbered_variants("explosion-two-pieces"))
def test_the_other_piece_of_an_explosion_cancels_the_first_across_and_keeps_the_rest_along(index, question):
    given = _printed(question)
    words = textformat.to_plain(question.text)
    first = re.search(r"° (north|south) of east", words)[1]
    theta = math.radians(given["angle"])
    p_piece = given["mass of the piece"] * given["speed of the piece"]
    east = given["mass of the shell"] * given["speed of the shell"] - p_piece * math.cos(theta)
    across = p_piece * math.sin(theta)
    rest = given["mass of the shell"] - given["mass of the piece"]
    east_part, across_part, speed, angle = question.parts
    _same(east_part, east)
    _same(across_part, across)
    _same(speed, math.hypot(east, across) / rest)
    _same(angle, math.degrees(math.atan(across / abs(east))))
    other = "south" if first == "north" else "north"
    assert angle.answer_direction == f"{other} of {'east' if east > 0 else 'west'}"
    named = {m.name: m.value for m in speed.mistakes}
    p_shell = given["mass of the shell"] * given["speed of the shell"]
    assert named["momentum added as scalars"] == pytest.approx(abs(p_shell - p_piece) / rest)
    swapped_east = p_shell - p_piece * math.sin(theta)
    swapped = math.hypot(swapped_east, p_piece * math.cos(theta)) / rest
    assert named["sin and cos swapped"] == pytest.approx(swapped)


def test_the_law_and_the_direction_change_with_the_variant():
    """No give-away: each drag template asks both laws, and the explosion's other piece goes
    north and south, east and west, across its variants."""
    for key in ("drag-law-constant", "drag-law-terminal-ratio"):
        assert {_law_power(q) for q in TEMPLATES[key].variants} == {1, 2}, key
    directions = {q.parts[3].answer_direction for q in TEMPLATES["explosion-two-pieces"].variants}
    assert {d.split()[0] for d in directions} == {"north", "south"}
    assert {d.split()[-1] for d in directions} == {"east", "west"}


def test_the_printed_variants_match_the_worked_numbers():
    """Variant 0, worked by hand: 45 g (a golf ball, 4.3 cm) at 33 m s⁻¹ with F = kv²: k = 0.4415 / 33²
    = 4.05 × 10⁻⁴, 4.1 × 10⁻⁴ kg m⁻¹ at 2 s.f.; 20 g and 80 g: v_B = 16 × √4 = 32 m s⁻¹; the pucks: 0.60 cos 40° = 0.46 N s; the shell:
    10 − 6.0 cos 40° = 5.4 N s east, 6.0 sin 40° = 3.9 N s south, 4.4 m s⁻¹ at 35.5° south of east."""
    assert [p.answer_text for p in TEMPLATES["drag-law-constant"].variant(0).parts] == ["0.441 N", "4.1 × 10⁻⁴ kg m⁻¹"]
    assert TEMPLATES["drag-law-terminal-ratio"].variant(0).parts[0].answer_text == "32 m s⁻¹"
    # 0.11 g, r = 1.5 mm in a liquid of 1260 kg m⁻³, η = 1.4 Pa s: U = 1260 × 9.81 × 1.414 × 10⁻⁸ N,
    # v = (1.079 × 10⁻³ − 1.75 × 10⁻⁴) / (6π × 1.4 × 1.5 × 10⁻³) = 0.023 m s⁻¹ (Re = 0.06: Stokes holds)
    stokes = [p.answer_text for p in TEMPLATES["stokes-terminal-speed"].variant(0).parts]
    assert stokes == ["1.75 × 10⁻⁴ N", "0.023 m s⁻¹"]
    assert TEMPLATES["puck-components"].variant(0).parts[0].answer_text == "0.46 N s"
    shell = [p.answer_text for p in TEMPLATES["explosion-two-pieces"].variant(0).parts]
    assert shell == ["5.4 N s (positive: east)", "3.9 N s", "4.4 m s⁻¹", "35.5° south of east"]


@pytest.mark.parametrize(("key", "values", "message"), [
    ("drag-law-terminal-ratio", {"grams_a": 50.0, "grams_b": 50.0}, r"grams_b must be more than grams_a"),
    ("stokes-terminal-speed", {"grams": 0.90, "radius_mm": 1.5}, r"grams and radius_mm must give a ball of glass to lead"),
    ("puck-components", {"speed_after": 2.5}, r"speed_after must be less than speed_before=2\.5"),
    ("puck-components", {"m2": 0.20, "speed_after": 2.4, "angle": 70.0}, r"would create kinetic energy"),
    ("explosion-two-pieces", {"piece": 2.0}, r"mass_piece must be less than mass=2\.0 kg"),
])
def test_an_impossible_variant_is_refused_naming_the_value_and_the_rule(key, values, message):
    with pytest.raises(ValueError, match=message):
        TEMPLATES[key].build(**values)
