
"""The templates take the numbers the published papers use (issue 38, "The papers' own numbers")."""

from __future__ import annotations

import pytest
from support.engine import mark_questions

from physics_figures import bank

STOPPING = bank.TEMPLATES["stopping-force-distance"]


def test_stopping_force_takes_a_papers_deceleration():
    """9702/21/M/J/24 Q3(c): a 4.2 kg object at 6.0 m s⁻¹ is stopped by a constant force in
    0.050 m, a deceleration of 360 m s⁻², far above a car's tyres (6.5 m s⁻²)."""
    question = STOPPING.build(mass=4.2, speed=6.0, distance=0.050, body=1)
    deceleration, force = (part.value for part in question.parts)
    assert deceleration == pytest.approx(6.0**2 / (2 * 0.050))
    assert force == pytest.approx(4.2 * deceleration)
    assert "object of mass 4.2 kg" in question.text and "0.050 m" in question.text
    assert "car" not in question.text + " ".join(part.prompt for part in question.parts)


def test_a_car_still_brakes_no_harder_than_its_tyres_allow_and_the_error_says_how_to_pose_an_object():
    with pytest.raises(ValueError, match=r"got distance=0.05 m: 360 m s\^-2.*body=1"):
        STOPPING.build(mass=4.2, speed=6.0, distance=0.050)
    assert STOPPING.variant(0).text.startswith("A car of mass 1500 kg")


COLLISION = bank.TEMPLATES["collision-third-law"]


def test_a_rebound_speed_rounded_as_a_paper_prints_it_is_not_refused_as_creating_energy():
    """An elastic collision (0.80 kg at 2.0 m s⁻¹ on 0.50 kg at rest) leaves A at 0.4615 m s⁻¹, which a
    paper prints as 0.46: worked from the printed 0.46, the total seems to grow by 2.5 mJ."""
    question = COLLISION.build(mass_a=0.80, speed_a=2.0, mass_b=0.50, after_a=0.46)
    assert question.parts[1].value == pytest.approx((0.80 * 2.0 - 0.80 * 0.46) / 0.50)


def test_a_rebound_speed_that_rounding_cannot_explain_is_still_refused():
    with pytest.raises(ValueError, match=r"after_a=0.4 m s\^-1 would create kinetic energy .* its rounding allows"):
        COLLISION.build(mass_a=0.80, speed_a=2.0, mass_b=0.50, after_a=0.40)


def test_the_collision_can_ask_the_force_on_the_body_that_stops():
    """9702/23/O/N/24 Q2(c)(i): ball X (240 g, 16 m s⁻¹) stops against Y (480 g, at rest) in 2.0 ms;
    the force on X is Δp / Δt = 3.84 / 0.0020 N, against X's motion."""
    question = COLLISION.build(mass_a=0.24, speed_a=16, mass_b=0.48, after_a=0, contact=0.0020, force_on=1)
    force = question.parts[2]
    assert force.prompt == "average force on A" and "force on A during the collision" in question.text
    assert force.value == pytest.approx(0.24 * 16 / 0.0020)
    assert force.answer_direction == "to the left"
    assert {m.direction for m in force.mistakes if m.name == "the force on B"} == {"to the right"}


ROCKET = bank.TEMPLATES["rocket-lift-off"]


def test_the_rocket_prints_its_givens_to_the_figures_they_are_stated_to():
    """A mass stated to 3 s.f. printed to 2 (0.247 kg as 0.25) gives a key the printed text does not."""
    question = ROCKET.build(mass=0.247, thrust=16)
    assert "mass 0.247 kg" in question.text and "thrust of 16 N" in question.text
    assert [given.text for given in question.givens] == ["0.247", "16"]
    assert ROCKET.variant(0).givens[0].text == "0.60"  # the variants' givens are stated to 2 s.f., as before


def test_the_rocket_can_ask_its_mass_from_its_thrust_and_acceleration():
    """9702/23/O/N/22 Q2(a)(iii): thrust 16 N, acceleration 55 m s⁻², so m = 16 / (55 + 9.81) = 0.25 kg [2]."""
    question = ROCKET.build(thrust=16, lift_off_acceleration=55)
    (mass,) = question.parts
    assert mass.value == pytest.approx(16 / (55 + 9.81))
    assert "thrust of 16 N" in question.text and "55 m s" in question.text
    assert question.part_marks() == [2]
    assert "used g = 10 m s⁻²" in {mistake.name for mistake in mass.mistakes}


ELASTIC = bank.TEMPLATES["elastic-both-moving"]


def test_data_stated_to_1_sf_print_so_and_take_a_1_sf_answer():
    """9702/22/O/N/23 Q4(b): "A at 4 m s⁻¹ … B at 6 m s⁻¹ … B moves back at 2 m s⁻¹", perfectly
    elastic: A's speed after is 8 m s⁻¹. The data print as stated (4, not 4.0), and the answer "8",
    to the 1 s.f. of the data, earns the mark in the browser's engine."""
    question = ELASTIC.build(u1=4, speed2=6, back2=2, figures=1)
    assert [given.text for given in question.givens] == ["4", "6", "2"]
    assert "A at 4 m s" in question.text and "at 2 m s" in question.text
    assert question.parts[0].value == pytest.approx(4 + 6 - 2)
    marked = mark_questions([(question.browser_data(), {"a": {"value": value, "unit": "m s^-1"}})
                             for value in ("8", "8.0", "12")])
    assert [result["marks"]["byPart"]["a"] for result in marked] == [[1, 1], [1, 1], [0, 1]]


EXPLOSION = bank.TEMPLATES["explosion-two-pieces"]


def test_the_explosion_takes_a_shell_at_rest_as_the_papers_fireworks_start():
    """A firework at rest (9702/22/M/J/18 Q2(b), 9702/23/M/J/23 Q3(b)) has no momentum before to
    forget, so named mistakes meet the key or each other: those the marker cannot tell apart are
    dropped, where the template used to fail with "mistakes gives 4.00, as 'momentum added as
    scalars' does"."""
    question = EXPLOSION.build(mass=2.0, speed=0.0, piece=0.50, piece_speed=12, angle=40)
    assert "is at rest when it explodes" in question.text
    assert question.parts[2].value == pytest.approx(0.50 * 12 / 1.5)  # the other piece: equal and opposite momentum
    for part in question.parts:
        typed = [f"{abs(m.value):.3g}" for m in part.mistakes if m.unit is None and m.direction is None]
        assert f"{abs(part.value):.3g}" not in typed and len(typed) == len(set(typed)), part.prompt


CYCLIST = bank.TEMPLATES["graph-cyclist-momentum-time"]


def test_the_momentum_time_graph_may_start_rising_at_t_0():
    """A momentum-time line may rise from t = 0, with no flat part before the change (issue 38: the
    templates could not draw it)."""
    question = CYCLIST.build(start=240, end=640, begins=0, lasts=8)
    assert question.graph.points[:2] == ((0.0, 240.0), (8.0, 640.0))
    assert question.parts[2].value == pytest.approx((640 - 240) / 8)


def test_the_momentum_time_graph_may_fall():
    question = CYCLIST.build(start=640, end=240, begins=4, lasts=8)
    assert "she slows down" in question.text
    assert [point[1] for point in question.graph.points] == [640.0, 640.0, 240.0, 240.0]
    assert question.parts[2].value == pytest.approx(400 / 8)  # the force's size
