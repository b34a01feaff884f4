"""physics_figures.explorables: the collision lab's rules, the data pages get, the size budget."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
from hypothesis import example, given
from hypothesis import strategies as st

from physics_figures import models, scenarios
from physics_figures.explorables import (
    ABOUT,
    EXPLORABLES,
    REFUSALS,
    UNREALISTIC_OPENING,
    collision_lab,
    earliest_parachute_opening,
    explorable_data,
)

ROOT = Path(__file__).resolve().parents[2]
STATIC = ROOT / "book" / "_ext" / "explorables" / "static" / "explorables"
BUDGET = 100_000  # bytes: all explorable JavaScript together, before compression

masses = st.floats(0.1, 10)
velocities = st.floats(-10, 10)


def test_notes_sticking_trolleys_lose_a_quarter_of_their_kinetic_energy():
    # Notes, Conservation of momentum and Elastic and inelastic collisions: 3.0 kg at
    # 4.0 m/s sticks to 1.0 kg at rest: v = 3.0 m/s, 24 J -> 18 J, 6.0 J (25%) transferred.
    lab = collision_lab("stick", **scenarios.STICKING_TROLLEYS)
    assert lab.after == pytest.approx((3.0, 3.0))
    assert lab.kinetic_energy_before == pytest.approx(24)
    assert lab.kinetic_energy_after == pytest.approx(18)
    assert lab.percent_lost == pytest.approx(25)
    assert lab.most_percent_lost == pytest.approx(25)


def test_notes_spring_trolleys_explosion_seen_from_the_left():
    # Notes, Conservation of momentum: 0.30 kg moves off at 2.0 m/s, the 0.20 kg one at
    # 3.0 m/s the other way. In the lab A (0.20 kg) is on the left and moves left.
    data = explorable_data("collision-lab")
    # The explosion starts with the notes' masses, not the sticking trolleys' 3.0 and 1.0 kg.
    assert (data["explosionM1"], data["explosionM2"]) == (0.20, 0.30)
    lab = collision_lab("explosion", m1=data["explosionM1"], m2=data["explosionM2"],
                        velocity_a_after=data["velocityAAfter"])
    assert lab.after == pytest.approx((-3.0, 2.0))
    assert lab.momentum_after == pytest.approx(0)


def test_notes_quick_check_4_elastic_collision():
    # Notes, Quick check 4: 1.0 kg at 6.0 m/s, elastic, 2.0 kg at rest -> -2.0 and 4.0 m/s.
    lab = collision_lab("elastic", m1=1.0, u1=6.0, m2=2.0, u2=0.0)
    assert lab.after == pytest.approx((-2.0, 4.0))
    assert lab.separation_speed == pytest.approx(lab.approach_speed)


def test_the_lab_refuses_kinetic_energy_created_in_a_collision():
    lab = collision_lab("loss", **scenarios.STICKING_TROLLEYS, percent_lost=-10)
    assert lab.after is None
    assert lab.refusal == "energy-created"
    assert "cannot create kinetic energy" in lab.reason


def test_the_lab_refuses_losing_more_than_sticking_together_would():
    lab = collision_lab("loss", **scenarios.STICKING_TROLLEYS, percent_lost=30)
    assert lab.refusal == "more-than-sticking"
    assert "25.0%" in lab.reason  # 3 s.f., as the browser writes it (notation.js)


def test_the_lab_refuses_bodies_that_never_meet():
    lab = collision_lab("elastic", m1=1.0, u1=2.0, m2=1.0, u2=3.0)
    assert lab.refusal == "never-meet"
    assert lab.after is None


def test_the_lab_refuses_an_explosion_that_sends_a_through_b():
    assert collision_lab("explosion", m1=1.0, m2=2.0, velocity_a_after=1.0).refusal == "explosion-wrong-way"


@given(m1=masses, u1=velocities, m2=masses, u2=velocities, share=st.floats(0, 1))
# A barely catches B: sticking together loses -1.2e-14 % by rounding, and 0 % was refused
@example(m1=1.0, u1=0.10000000000000002, m2=0.5, u2=0.1, share=0.0)
def test_every_accepted_collision_conserves_momentum_and_never_creates_kinetic_energy(m1, u1, m2, u2, share):
    for kind in ("elastic", "stick", "loss"):
        most = collision_lab("stick", m1=m1, u1=u1, m2=m2, u2=u2).most_percent_lost
        extra = {"percent_lost": share * most} if kind == "loss" and most is not None else {}
        if kind == "loss" and not extra:
            extra = {"percent_lost": 0.0}
        lab = collision_lab(kind, m1=m1, u1=u1, m2=m2, u2=u2, **extra)
        if u1 <= u2:
            assert lab.refusal == "never-meet"
            continue
        assert lab.refusal is None
        assert lab.momentum_after == pytest.approx(lab.momentum_before, abs=1e-9)
        assert lab.kinetic_energy_after <= lab.kinetic_energy_before * (1 + 1e-12) + 1e-12
        # after the collision B is not behind A: they separate (or move together)
        assert lab.after[1] >= lab.after[0] - 1e-9


@given(m1=masses, u1=velocities, m2=masses, u2=velocities, share=st.floats(0, 1))
def test_a_chosen_loss_is_the_loss_the_lab_delivers(m1, u1, m2, u2, share):
    # They must meet, at a speed the lab's sliders can set (0.1 m/s steps): at 1e-159 m/s the
    # kinetic energy is a subnormal float and its percentages are rounding noise.
    if u1 - u2 < 1e-3:
        return
    most = collision_lab("stick", m1=m1, u1=u1, m2=m2, u2=u2).most_percent_lost
    lab = collision_lab("loss", m1=m1, u1=u1, m2=m2, u2=u2, percent_lost=share * most)
    assert lab.percent_lost == pytest.approx(share * most, abs=1e-7)


@pytest.mark.parametrize(("kwargs", "message"), [
    ({"kind": "bounce", "m1": 1, "m2": 1}, "kind must be one of"),
    ({"kind": "elastic", "m1": -1, "m2": 1}, "m1 must be positive"),
    ({"kind": "loss", "m1": 1, "m2": 1, "u1": 2}, "percent_lost is needed"),
    ({"kind": "explosion", "m1": 1, "m2": 1}, "velocity_a_after is needed"),
    ({"kind": "explosion", "m1": 1, "m2": 1, "u1": 1, "velocity_a_after": -1}, "must be 0"),
    ({"kind": "stick", "m1": 1, "m2": 1, "percent_lost": 3}, "only for kind='loss'"),
])
def test_bad_lab_input_is_refused_with_a_named_argument(kwargs, message):
    with pytest.raises(ValueError, match=message):
        collision_lab(**kwargs)


def test_earliest_parachute_opening_is_once_the_skydiver_beats_the_parachutes_terminal_velocity():
    # Issue 12: the parachute may open at any time while the skydiver is faster than the
    # new terminal velocity, not only after C (13.5 s for the notes' skydiver): here once
    # the speed from rest passes 1.01 x 5.0 m/s, at 0.517 s.
    dive = scenarios.SKYDIVER
    earliest = earliest_parachute_opening(dive.mass, dive.drag_constant_freefall, dive.drag_constant_parachute)
    assert round(earliest, 3) == 0.517
    assert earliest < dive.points["C"][0]
    assert models.velocity_from_rest(earliest, 50.0) == pytest.approx(5.05)
    models.skydive(dive.mass, terminal_velocity_freefall=50.0, terminal_velocity_parachute=5.0,
                   parachute_opens_at=earliest + 1e-6, opening_duration=2.5, duration=30.0)


def test_skydiver_page_data_carry_the_opening_duration_and_the_15_g_limit():
    # CLARIFICATIONS (Physics): an opening-duration slider, default 2.5 s.
    data = explorable_data("skydiver")
    assert data["openingDuration"] == scenarios.SKYDIVER.opening_duration == 2.5
    assert data["unrealisticDecelerationInG"] == 15
    assert data["unrealisticOpening"] == UNREALISTIC_OPENING  # its words; the browser fills in the numbers


def test_page_data_are_the_notes_scenarios():
    dive = explorable_data("skydiver")
    assert dive["mass"] == 80
    assert models.terminal_velocity(dive["mass"], dive["bodyDrag"]) == pytest.approx(50)
    assert models.terminal_velocity(dive["mass"], dive["parachuteDrag"]) == pytest.approx(5.0)
    assert explorable_data("momentum-triangle") == {"momentumBefore": 1.0, "momentumKnown": 0.6, "angleKnown": 50.0}
    car = explorable_data("momentum-time-reader")
    assert (car["mass"], car["times"], car["momenta"]) == (1500, [0, 4, 10, 16], [0, 12000, 12000, 0])
    lab = explorable_data("collision-lab")
    assert (lab["m1"], lab["u1"], lab["m2"], lab["u2"]) == (3.0, 4.0, 1.0, 0.0)
    assert lab["refusals"] == REFUSALS
    for name in EXPLORABLES:
        json.dumps(explorable_data(name), allow_nan=False)  # plain JSON, no NaN
    with pytest.raises(ValueError, match="name must be one of"):
        explorable_data("pendulum")


def test_every_explorable_says_in_a_sentence_or_two_what_it_models():
    """Issue 28: the text a screen reader meets before the sliders (shown above them too)."""
    assert set(ABOUT) == set(EXPLORABLES)
    for name, text in ABOUT.items():
        sentences = [s for s in re.split(r"(?<=\.) ", text) if s]
        assert 1 <= len(sentences) <= 3 and text.endswith("."), f"{name}: {text!r}"


def test_every_explorable_has_its_script_and_every_script_is_used():
    scripts = {path.stem for path in STATIC.glob("*.js")}
    assert scripts == set(EXPLORABLES) | {"models", "ui", "announce"}


def test_explorable_javascript_fits_the_size_budget():
    sizes = {path.name: path.stat().st_size for path in STATIC.glob("*.js")}
    assert sum(sizes.values()) <= BUDGET, f"{sum(sizes.values())} bytes > {BUDGET}: {sizes}"


def test_explorable_files_make_no_third_party_requests():
    for path in STATIC.iterdir():
        text = path.read_text()
        assert not re.search(r"https?://(?!www\.w3\.org/2000/svg)", text), f"{path.name} names a URL"
        assert "import(" not in text and "fetch(" not in text, f"{path.name} loads something"
