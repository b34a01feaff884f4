# ruff: noqa: RUF001, RUF002, RUF003  (comments quote the schemes as typeset: true minus, times)
"""The two templates that pose blocked real-paper parts (issue 38): bounce-contact-force (a
ball's bounce off a floor or a ceiling: the contact force at rest, the kinetic energy lost, the
resultant force, the surface's force R = F ± mg and its third-law partner) and
stokes-drag-acceleration (a drag law 6πDRv at a speed below the terminal speed), with the
model they add, models.bounce_contact_force.

Each key is checked against a number a published paper prints, cited beside it, or worked here
by hand from the paper's data with the formula a student writes (not through the models)."""

from __future__ import annotations

import math

import pytest

from physics_figures import bank
from physics_figures.models import bounce_contact_force
from physics_figures.notation import format_number

#: 9702/21/M/J/16 Q3: a ball of 0.15 kg on the floor, then hitting it at 6.2 m s⁻¹, back at 2.5 m s⁻¹,
#: in contact for 0.12 s.
M_J_16 = {"mass": 0.15, "speed_in": 6.2, "speed_out": 2.5, "contact": 0.12, "ceiling": 0}
#: 9702/21/O/N/20 Q3(b): 0.062 kg, the floor at 3.8 m s⁻¹, away at 1.7 m s⁻¹, 0.081 s.
O_N_20 = {"mass": 0.062, "speed_in": 3.8, "speed_out": 1.7, "contact": 0.081, "ceiling": 0}
#: 9702/23/M/J/18 Q3: 0.056 kg thrown up to a ceiling, 6.0 m s⁻¹ in, 3.8 m s⁻¹ out, 0.085 s.
M_J_18 = {"mass": 0.056, "speed_in": 6.0, "speed_out": 3.8, "contact": 0.085, "ceiling": 1}


def _keys(key: str, givens: dict) -> dict[str, float]:
    question = bank.TEMPLATES[key].build(**givens)
    return dict(zip(question.part_ids, (part.value for part in question.parts), strict=True))


def test_the_bounce_keys_are_the_values_the_papers_print():
    keys = _keys("bounce-contact-force", M_J_16)
    # 9702/21/M/J/16 Q3(a)(i)'s scheme: "force (= mg = 0.15 × 9.81) = 1.5 (1.47) N A1"
    assert format_number(keys["a"], 3) == "1.47" and format_number(keys["a"], 2) == "1.5"
    # 9702/21/M/J/16 Q3(b)(ii)'s scheme: "magnitude of force = 1.305 / 0.12 = 11 (10.9) N A1"
    assert format_number(keys["c"], 3) == "10.9" and format_number(keys["c"], 2) == "11"
    # 9702/21/O/N/20 Q3(b)(iii) states the average resultant force: "show that ... is 4.2 N"
    assert format_number(_keys("bounce-contact-force", O_N_20)["c"], 2) == "4.2"


def test_the_surface_force_adds_the_weight_off_a_floor_and_takes_it_off_a_ceiling():
    """Worked by hand from the papers' data: off the floor R = F + mg, off the ceiling R = F − mg."""
    floor = _keys("bounce-contact-force", O_N_20)
    resultant = 0.062 * (3.8 + 1.7) / 0.081
    assert math.isclose(floor["d"], resultant + 0.062 * 9.81) and floor["e"] == floor["d"]
    assert math.isclose(floor["b"], 0.5 * 0.062 * (3.8**2 - 1.7**2))
    ceiling = _keys("bounce-contact-force", M_J_18)
    assert math.isclose(ceiling["d"], 0.056 * (6.0 + 3.8) / 0.085 - 0.056 * 9.81)
    assert format_number(ceiling["d"], 2) == "5.9" and format_number(ceiling["b"], 2) == "0.60"


def test_the_ball_pushes_the_surface_the_other_way_to_the_surfaces_push():
    for givens, on_ball, on_surface in ((O_N_20, "upwards", "downwards"), (M_J_18, "downwards", "upwards")):
        question = bank.TEMPLATES["bounce-contact-force"].build(**givens)
        resultant, on_the_surface = question.parts[2], question.parts[4]
        assert (resultant.answer_direction, on_the_surface.answer_direction) == (on_ball, on_surface)


def test_the_bounce_contact_force_model_refuses_impossible_input():
    with pytest.raises(ValueError, match=r"surface must be one of \('floor', 'ceiling'\) \(got surface='wall'\)"):
        bounce_contact_force(4.0, 0.1, surface="wall")
    # a ceiling can only push: a resultant below the weight would need it to pull
    with pytest.raises(ValueError, match=r"resultant_force must be above the ball's weight .*\(got resultant_force=0\.5 N\)"):
        bounce_contact_force(0.5, 0.1, surface="ceiling")
    with pytest.raises(ValueError, match=r"mass must be positive \(got mass=-0\.1 kg\)"):
        bounce_contact_force(4.0, -0.1, surface="floor")


def test_the_bounce_template_refuses_a_ball_that_leaves_faster_than_it_came():
    with pytest.raises(ValueError, match=r"speed_out must be less than speed_in=3\.8"):
        bank.TEMPLATES["bounce-contact-force"].build(**{**O_N_20, "speed_out": 4.0})


def test_the_raindrop_keys_are_the_drag_law_worked_by_hand():
    """9702/22/M/J/11 Q2(a)(ii): R = 1.5 mm, v = 3.7 m s⁻¹, D = 6.6 × 10⁻⁴ kg m⁻¹ s⁻¹, water 1000 kg m⁻³
    (the paper's data; its scheme was not read): F = 6πDRv, then a = (mg − F) / m with m = ρ 4/3 πR³."""
    keys = _keys("stokes-drag-acceleration", {"radius_mm": 1.5, "speed": 3.7, "constant": 6.6e-4})
    drag = 6 * math.pi * 6.6e-4 * 1.5e-3 * 3.7
    mass = 1000 * 4 / 3 * math.pi * 1.5e-3**3
    assert math.isclose(keys["a"], drag) and format_number(keys["a"], 2) == "6.9 × 10⁻⁵"
    assert math.isclose(keys["b"], (mass * 9.81 - drag) / mass) and format_number(keys["b"], 2) == "4.9"


def test_the_raindrop_template_refuses_a_speed_at_or_above_the_terminal_speed():
    """At the terminal speed the drag equals the weight (6πDRv = mg): the drop cannot speed up."""
    with pytest.raises(ValueError, match=r"speed must be below the drop's terminal speed"):
        bank.TEMPLATES["stokes-drag-acceleration"].build(radius_mm=1.0, speed=4.0, constant=8.0e-4)
