# ruff: noqa: RUF002  (docstrings quote the schemes: times signs)

"""The templates take the numbers the published papers use (issue 38, "The papers' own numbers")."""

from __future__ import annotations

import pytest
from support.engine import mark_questions

from physics_figures import bank, models

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


# ------------------------------------------------------------------ refusals a teacher can read

#: Words that belong to the bank's own checks, not to a teacher's givens (issue 38: an error
#: printed "mistakes gives 4.00, as 'momentum added as scalars' does").
INTERNAL_WORKING = ("mistakes gives", "ecf must", "got points=", "got mistakes=", "got wrong=", "math domain",
                    "Traceback")
DRAWN = [(key, name) for key, template in bank.TEMPLATES.items() for name in template.draws]


def _refusal(key: str, **givens: float) -> str:
    with pytest.raises(ValueError) as refused:
        bank.TEMPLATES[key].build(**givens)
    return str(refused.value)


@pytest.mark.parametrize(("key", "name"), DRAWN, ids=[f"{key}:{name}" for key, name in DRAWN])
def test_an_impossible_given_is_refused_by_its_name_value_and_rule(key, name):
    """Each given of each template: a negative size or a choice beyond the template's (a
    situation of -1 used to pick the last situation without a word; a negative speed was blamed
    on another given, or on a model's argument)."""
    draw = bank.TEMPLATES[key].draws[name]
    impossible = -1 if isinstance(draw.printed, int) else -abs(draw.printed or 1.0)
    message = _refusal(key, **{name: impossible})
    assert f"{name}={impossible!r}" in message and " must " in message, message
    assert not any(words in message for words in INTERNAL_WORKING), message


@pytest.mark.parametrize(("key", "name"), DRAWN, ids=[f"{key}:{name}" for key, name in DRAWN])
def test_givens_that_keep_the_rules_but_cannot_be_posed_are_named_in_plain_words(key, name):
    """Zero, or ten times the top of the draw: where the template cannot pose it, the refusal names
    the given and its value, and never prints the bank's working."""
    draw = bank.TEMPLATES[key].draws[name]
    for value in (0.0, 10.0 * draw.high) if not isinstance(draw.printed, int) else (draw.high + 1,):
        try:
            bank.TEMPLATES[key].build(**{name: value})
        except ValueError as refused:
            message = str(refused)
            assert f"{name}={value!r}" in message, message
            assert not any(words in message for words in INTERNAL_WORKING), message


def test_a_refusal_of_the_question_itself_says_what_the_givens_do():
    assert _refusal("graph-bounce-momentum-time", after=0.0) == (
        "graph-bounce-momentum-time cannot be posed with after=0.0: two of the question's named mistakes (or a "
        "mistake and the key) give the same answer, so the marker could not tell them apart: choose other numbers")
    assert "divide by zero" in _refusal("practice-tennis-ball", speed=0.0)


BOUNCE = bank.TEMPLATES["graph-bounce-momentum-time"]


def test_the_bounce_graph_takes_a_papers_ball_on_a_floor_in_contact_for_longer():
    """9702/21/M/J/16 Q3(b)(ii): a 150 g ball meets the floor at 6.2 m s⁻¹ downwards and leaves at
    2.5 m s⁻¹ upwards after 0.12 s in contact; scheme: "change in momentum = 0.15 × (6.2 + 2.5)
    (= 1.305 N s) C1, magnitude of force = 1.305 / 0.12 = 11 (10.9) N A1, (direction of force is)
    upwards B1". Drawn as a momentum-time graph (0.93 N s, then 0.375 N s back), the axes hold
    the 0.12 s contact, where the template's fixed 0.1 s axis refused it."""
    question = BOUNCE.build(before=0.15 * 6.2, after=0.15 * 2.5, arrives=0.02, contact=0.12, surface=1)
    force = question.parts[2]
    assert f"{force.value:.3g}" == "10.9" and force.answer_direction == "upwards"
    assert question.graph.time_max >= 0.14 and question.graph.value_min <= -0.375
    assert "falls vertically onto a floor" in question.text and "taking downwards as positive" in question.text


def test_the_bounce_graph_may_start_falling_at_t_0():
    """The momentum falls through zero and reverses from t = 0, with no flat part before."""
    question = BOUNCE.build(before=2.4, after=1.6, arrives=0, contact=0.03)
    assert question.graph.points[:2] == ((0.0, 2.4), (0.03, -1.6))
    assert question.parts[2].value == pytest.approx((2.4 + 1.6) / 0.03)


ENERGY = bank.TEMPLATES["bounce-energy-ratio"]


def test_the_energy_template_takes_a_ball_that_stops_and_asks_the_kinetic_energy_lost():
    """9702/23/O/N/24 Q2(b): ball X (240 g, 16 m s⁻¹) hits ball Y (480 g, at rest) and stops;
    (b)(i) "show that the speed v of ball Y after the collision is 8.0 m s⁻¹", (b)(ii) "calculate
    the change in the total kinetic energy of the balls caused by the collision". The scheme of
    (b)(ii) was not read: its value is worked by physics_figures.models, ½ × 0.24 × 16² − ½ ×
    0.48 × 8.0² J. The template needed A to bounce back and asked only the ratio."""
    question = ENERGY.build(m1=0.24, u1=16, m2=0.48, back=0, asks=1)
    speed, lost = question.parts
    assert f"{speed.value:.2g}" == "8" and speed.value == pytest.approx(8.0)
    assert lost.value == pytest.approx(models.kinetic_energy(0.24, 16) - models.kinetic_energy(0.48, 8.0))
    assert lost.unit == "J" and "After the collision A stops" in question.text
    assert "the decrease in the total kinetic energy" in question.text


def test_the_energy_ratio_takes_b_moving_before_the_collision():
    """B moving towards A before (the template needed B at rest): its momentum and its kinetic
    energy before count, worked by physics_figures.models (no paper's B-moving ratio was found)."""
    question = ENERGY.build(m1=0.20, u1=3.0, m2=0.60, back=0.60, speed2=0.50)
    v2 = models.velocity_after_collision(0.20, 3.0, 0.60, -0.50, -0.60)
    before = models.total_kinetic_energy((0.20, 0.60), (3.0, -0.50))
    after = models.total_kinetic_energy((0.20, 0.60), (-0.60, v2))
    assert [part.value for part in question.parts] == pytest.approx([v2, after / before])
    assert "B was moving towards A at 0.50 m s" in question.text
    assert "B's momentum before left out" in {mistake.name for mistake in question.parts[0].mistakes}


LORRY = bank.TEMPLATES["graph-lorry-speed-momentum-time"]


def test_the_lorry_graph_may_rise_from_t_0():
    """A lorry's momentum-time line that starts rising at t = 0 (the template drew a flat part first)."""
    question = LORRY.build(mass=4000, speed_before=8, speed_after=20, begins=0, lasts=12)
    assert question.graph.points[:2] == ((0.0, 32000.0), (12.0, 80000.0))
    assert [part.value for part in question.parts[2:]] == pytest.approx([20.0, 12.0])


def test_the_lorry_graph_may_fall_as_it_brakes():
    """A braking lorry: the line falls, and (d) asks the decrease in its speed (the template refused
    a fall as a lorry speeding up at -1.0 m s⁻² and its engine check)."""
    question = LORRY.build(mass=4000, speed_before=20, speed_after=8, begins=2, lasts=6)
    assert "slows down" in question.text and question.parts[3].prompt == "decrease in the speed of the lorry"
    assert [point[1] for point in question.graph.points] == [80000.0, 80000.0, 32000.0, 32000.0]
    assert [part.value for part in question.parts[2:]] == pytest.approx([8.0, 12.0])
    with pytest.raises(ValueError, match=r"lasts=1 s: 12 m s\^-2"):
        LORRY.build(mass=4000, speed_before=20, speed_after=8, begins=2, lasts=1)
