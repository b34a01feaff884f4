# ruff: noqa: RUF001, RUF002, RUF003  (question text is typeset: true minus, times, Greek letters)
"""Issue 37, the new templates read as an examiner would: each finding, checked over every variant."""

from __future__ import annotations

import dataclasses
import math
import re
from decimal import Decimal

import pytest
from support.templates import numbered_variants
from test_new_templates_b import _law_power, _printed
from working_lines import wrong_steps

from physics_figures import textformat
from physics_figures.bank import TEMPLATES
from physics_figures.models import reynolds_number, sphere_drag_constant, stokes_reynolds_number
from physics_figures.parts import OPTION_LETTERS


@pytest.mark.parametrize(("index", "question"), numbered_variants("drag-law-terminal-ratio"))
def test_masses_the_wrong_way_up_says_a_s_speed_was_divided(index, question):
    """The slip divides A's terminal speed by the factor (v_A ÷ √(m_B / m_A)): the feedback names A."""
    given, power = _printed(question), _law_power(question)
    (wrong,) = [m for m in question.parts[0].mistakes if m.name == "masses the wrong way up"]
    factor = (given["mass of B"] / given["mass of A"]) ** (1 / power)
    assert wrong.value == pytest.approx(given["terminal speed of A"] / factor)
    assert wrong.feedback.startswith("You divided A's terminal speed by"), wrong.feedback
    assert "B's terminal speed" not in wrong.feedback


#: The ball falling through air, worked by hand: D = ½CρAv² with a sphere's C = 0.47 and air's
#: ρ = 1.2 kg m⁻³ (9702/21/M/J/24 Q1 gives that density for a sphere falling in air), A = πd²/4.
C_SPHERE, RHO_AIR, G = 0.47, 1.2, 9.81


def _reached(grams: float, diameter_cm: float) -> float:
    """The terminal speed a ball of this mass and diameter reaches in air, by hand."""
    area = math.pi * (diameter_cm / 100) ** 2 / 4
    return math.sqrt(grams / 1000 * G / (0.5 * C_SPHERE * RHO_AIR * area))


def _density(grams: float, diameter_cm: float) -> float:
    return grams / 1000 / (math.pi * (diameter_cm / 100) ** 3 / 6)


@pytest.mark.parametrize(("index", "question"), numbered_variants("drag-law-constant"))
def test_the_balls_size_mass_and_terminal_speed_agree(index, question):
    """Issue 37: the 45 g "small ball" was about 30 cm across by its drag. The story now gives the
    ball's diameter; its density is a real ball's (a table-tennis ball, 80 kg m⁻³, to solid rubber,
    1500), and its terminal speed is the one that ball reaches in air, to the 2 s.f. printed."""
    given = _printed(question)
    assert 80 <= _density(given["mass"], given["diameter"]) <= 1500
    speed = _reached(given["mass"], given["diameter"])
    assert given["terminal speed"] == float(f"{speed:.2g}"), (given, speed)


@pytest.mark.parametrize(("index", "question"), numbered_variants("drag-law-terminal-ratio"))
def test_both_balls_are_real_and_fall_at_plausible_speeds_under_either_law(index, question):
    """Issue 37: the linear-law variants made B fall at 65–86 m s⁻¹. A's terminal speed is what a
    ball of its mass and size reaches; the law's prediction for B stays within 30 % of what B
    reaches (F = kv only predicts B well for masses not far apart)."""
    given, power = _printed(question), _law_power(question)
    for mass in (given["mass of A"], given["mass of B"]):
        assert 80 <= _density(mass, given["diameter"]) <= 1500
    assert given["terminal speed of A"] == float(f"{_reached(given['mass of A'], given['diameter']):.2g}")
    predicted = question.parts[0].value
    assert predicted == pytest.approx(_reached(given["mass of B"], given["diameter"]), rel=0.3), power
    assert predicted < 50


def _checkable(question):
    """The question with its scheme written as tests/working_lines.py reads arithmetic: a number
    printed with a power of ten (3.35 × 10⁻⁸) in full, with the same figures (0.0000000335); π as
    its number."""
    powers = str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")

    def in_full(found: re.Match) -> str:
        return format(Decimal(found[1]).scaleb(int(found[2].translate(powers))), "f")

    def text(line: str) -> str:
        line = re.sub(r"(\d+(?:\.\d+)?) × 10([⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)", in_full, line)
        line = re.sub(r"(\d+(?:\.\d+)?) × 10<sup>([−-]?\d+)</sup>",
                      lambda m: format(Decimal(m[1]).scaleb(int(m[2].replace("−", "-"))), "f"), line)
        return line.replace("π", f" × {math.pi!r}")

    return dataclasses.replace(question, mark_scheme=tuple(
        dataclasses.replace(mark, text=text(mark.text)) for mark in question.mark_scheme))


@pytest.mark.parametrize(("index", "question"), numbered_variants("stokes-terminal-speed"))
def test_stokes_working_gives_the_printed_answers_from_its_printed_numbers(index, question):
    """Issue 37: (a)'s working printed V to 3 s.f., and ρgV from it gave another third figure than
    the key in 9 of 20 variants. Each step, worked from its numbers as printed, gives its result:
    (a)'s upthrust from the radius (no rounded volume printed) and (b)'s speed."""
    wrong, checked = wrong_steps(_checkable(question))
    assert checked >= 2 and not wrong, wrong


@pytest.mark.parametrize(("index", "question"), numbered_variants("stokes-terminal-speed"))
def test_stokes_law_holds_for_every_variant(index, question):
    """Issue 37: the Reynolds number reached 0.997. Stokes' law holds in creeping flow: Re = ρvd/η
    (d the diameter) below 0.1, where Oseen's correction (3Re/16) stays under 2 %."""
    given = _printed(question)
    speed = question.parts[1].value
    reynolds = given["density of the liquid"] * speed * 2 * given["radius"] / 1000 / given["viscosity"]
    assert reynolds < 0.1, reynolds


def test_the_models_refuse_stokes_law_outside_creeping_flow_by_name():
    assert reynolds_number(1260.0, 0.05, 0.004, 1.4) == pytest.approx(0.18)
    assert stokes_reynolds_number(1260.0, 0.02, 0.003, 1.4) == pytest.approx(0.054)
    with pytest.raises(ValueError, match=r"reynolds_number must be below 0\.1 for Stokes' law .*"
                                         r"\(got reynolds_number=0\.18"):
        stokes_reynolds_number(1260.0, 0.05, 0.004, 1.4)
    with pytest.raises(ValueError, match=r"viscosity must be positive \(got viscosity=0\.0 Pa s\)"):
        reynolds_number(1260.0, 0.05, 0.004, 0.0)
    # a golf ball, 4.3 cm: k = ½ × 0.47 × 1.2 × π × 0.0215² = 4.10 × 10⁻⁴ kg m⁻¹
    assert sphere_drag_constant(0.043) == pytest.approx(0.5 * 0.47 * 1.2 * math.pi * 0.0215**2)
    with pytest.raises(ValueError, match=r"diameter must be positive"):
        sphere_drag_constant(-0.01)


def test_a_stokes_variant_outside_creeping_flow_is_refused_by_name():
    """The printed variant of issue 25 (0.26 g, 2.0 mm, η = 1.4 Pa s) had Re = 0.15: refused now."""
    with pytest.raises(ValueError, match=r"reynolds_number must be below 0\.1 .*\(got reynolds_number=0\.14"):
        TEMPLATES["stokes-terminal-speed"].build(grams=0.26, radius_mm=2.0)


@pytest.mark.parametrize(("index", "question"), numbered_variants("graph-lorry-speed-momentum-time"))
def test_every_lorry_speeds_up_as_a_loaded_lorry_can(index, question):
    """Issue 37: lorries sped up at 3.5 m s⁻², and one needed 565 kW. From the graph each variant
    draws and its printed mass: a loaded lorry's 0.5 to 1.5 m s⁻², and at most 300 kW (the
    resultant force, the graph's gradient, × the speed at the end)."""
    mass = _printed(question)["mass"]
    (_, p0), (t1, p1), (t2, p2), _ = question.graph.points
    force = (p2 - p1) / (t2 - t1)
    assert p0 == p1 and 0.5 <= force / mass <= 1.5, force / mass
    assert force * p2 / mass <= 300e3, force * p2 / mass


@pytest.mark.parametrize(("values", "message"), [
    ({"speed_before": 12.0, "speed_after": 26.0, "lasts": 4.0}, r"lasts must give a lorry's acceleration, 0\.5 to 1\.5"),
    ({"mass": 9000.0, "speed_before": 8.0, "speed_after": 23.0, "lasts": 10.0}, r"must need at most 300 kW"),
])
def test_a_lorry_beyond_a_lorry_is_refused_by_name(values, message):
    with pytest.raises(ValueError, match=message):
        TEMPLATES["graph-lorry-speed-momentum-time"].build(**values)


@pytest.mark.parametrize(("index", "question"), numbered_variants("falling-graph-choice"))
def test_each_skydiver_story_and_its_sketches_tell_one_story(index, question):
    """Issue 37: the parachute variant said she "falls at her terminal velocity", and every sketch
    started from rest; its feedback put the largest deceleration at the start of a curve the key
    calls "ever more quickly, then ever more slowly". Each option starts where the story starts."""
    words = textformat.to_plain(question.text)
    (part,) = question.parts
    key = part.options[OPTION_LETTERS.index(part.answer)]
    at_terminal = "at her terminal velocity" in words
    assert at_terminal != ("jumps from" in words), words
    for option in part.options:
        shape = option.text.split(": ", 1)[1]
        if at_terminal:  # level at her terminal velocity before the parachute opens
            assert shape.startswith("starts at a positive value, stays constant, then"), option.text
        elif key.sketch.quantity == "velocity" and option is key:
            assert shape.startswith("starts at zero"), option.text
    if "ever more quickly, then ever more slowly" in key.text:
        assert not [o.feedback for o in part.options if "most at the start" in o.feedback]


#: Named mistakes the examiner found no student makes (issue 37).
NO_STUDENT_MAKES = {"difference of the momenta after", "momentum ÷ distance"}


@pytest.mark.parametrize("key", sorted(TEMPLATES))
def test_no_named_mistake_is_one_no_student_makes(key):
    named = {m.name for q in TEMPLATES[key].variants for p in q.parts for m in getattr(p, "mistakes", ())}
    assert not named & NO_STUDENT_MAKES, key


@pytest.mark.parametrize(("index", "question"), numbered_variants("collision-third-law"))
def test_the_force_on_b_names_the_mass_left_out(index, question):
    """In its place, a mistake students make: B's change in velocity ÷ the time (the acceleration)."""
    force = question.parts[-1]
    (left_out,) = [m.value for m in force.mistakes if m.name == "mass left out"]
    assert left_out == pytest.approx(abs(force.value) / _printed(question)["mass of B"])


@pytest.mark.parametrize("key", sorted(TEMPLATES))
def test_the_positive_direction_is_worded_as_a_sentence(key):
    """Issue 37: "Momentum is positive in towards the wall". The stories say "Take momentum towards
    the wall as positive" (or upwards, in its direction of motion)."""
    bad = [textformat.to_plain(q.text) for q in TEMPLATES[key].variants
           if re.search(r"positive in (towards|upwards|downwards|away)", textformat.to_plain(q.text))]
    assert not bad, bad
    if key == "force-from-momentum-graph-choice":
        for question in TEMPLATES[key].variants:
            assert re.search(r"Take momentum (towards the wall|upwards|in (its|her) direction of motion) as "
                             r"positive\.", textformat.to_plain(question.text)), question.text


@pytest.mark.parametrize("key", sorted(TEMPLATES))
def test_every_working_line_with_a_power_of_ten_or_pi_gives_its_printed_result(key):
    """The check tests/no_site/test_printed_numbers.py makes, on the steps it cannot read (3.35 × 10⁻⁸,
    6π): worked from its numbers as printed, each step gives its printed result."""
    wrong = [f"variant {index}: {step}" for index, question in enumerate(TEMPLATES[key].variants)
             for step in wrong_steps(_checkable(question))[0]]
    assert not wrong, wrong
