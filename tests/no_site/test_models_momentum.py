"""Momentum, force as rate of change of momentum, Newton's second law, weight, towing and
momentum-time graphs (Notes, "Momentum and Newton's second law", "Reading a
momentum-time graph", "Weight", How to do it 1. and 3.)."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from physics_figures.constants import G_EARTH, G_MOON
from physics_figures.models import (
    MomentumHistory,
    acceleration,
    area_under_force_time,
    average_force,
    change_in_momentum,
    gravitational_field_strength,
    impulse,
    jet_force,
    kinetic_energy,
    kinetic_energy_from_momentum,
    lift_contact_force,
    mass_from_momentum_and_energy,
    mass_from_weight,
    momentum,
    momentum_change_between_directions,
    oblique_bounce_momentum_change,
    speed_from_momentum_and_energy,
    stream_force,
    thrust_for_acceleration,
    time_for_momentum_change,
    towing,
    velocity_from_momentum,
    weight,
)

SETTINGS = settings(max_examples=100, deadline=None)
masses = st.floats(0.01, 2000.0, allow_subnormal=False)
velocities = st.floats(-100.0, 100.0, allow_subnormal=False)
durations = st.floats(0.001, 100.0, allow_subnormal=False)


@SETTINGS
@given(mass=masses, u=velocities, v=velocities, dt=durations)
def test_f_equals_ma_is_the_rate_of_change_of_momentum_for_constant_mass(mass, u, v, dt):
    force = average_force(change_in_momentum(mass, u, v), dt)
    assert force == pytest.approx(mass * (v - u) / dt, rel=1e-12, abs=1e-9)
    assert acceleration(force, mass) == pytest.approx((v - u) / dt, rel=1e-12, abs=1e-9)


@SETTINGS
@given(force=st.floats(-1e4, 1e4, allow_subnormal=False).filter(lambda f: abs(f) > 1e-3), dt=durations)
def test_time_for_a_momentum_change_undoes_the_impulse(force, dt):
    assert time_for_momentum_change(impulse(force, dt), force) == pytest.approx(dt)


@SETTINGS
@given(mass=masses, v=velocities)
def test_momentum_has_the_sign_of_the_velocity(mass, v):
    p = momentum(mass, v)
    assert np.sign(p) == np.sign(v)
    assert velocity_from_momentum(p, mass) == pytest.approx(v)


def test_momentum_works_on_arrays_of_velocities():
    assert momentum(2.0, np.array([1.0, -3.0])) == pytest.approx([2.0, -6.0])


@SETTINGS
@given(mass=masses, v=velocities.filter(lambda v: abs(v) > 1e-3))
def test_kinetic_energy_from_momentum_and_back(mass, v):
    # Notes, 3.: E_k = p²/2m, so m = p²/2E_k and v = 2E_k/p.
    p, e_k = momentum(mass, v), kinetic_energy(mass, v)
    assert kinetic_energy_from_momentum(p, mass) == pytest.approx(e_k)
    assert mass_from_momentum_and_energy(p, e_k) == pytest.approx(mass)
    assert speed_from_momentum_and_energy(p, e_k) == pytest.approx(abs(v))


@SETTINGS
@given(p=st.floats(0.0, 10.0, allow_subnormal=False), angle=st.floats(0.0, 90.0, allow_subnormal=False))
def test_oblique_bounce_changes_momentum_only_at_right_angles_to_the_surface(p, angle):
    # Coming in at θ to the surface and leaving at θ, the direction turns through 2θ.
    assert oblique_bounce_momentum_change(p, angle) == pytest.approx(
        momentum_change_between_directions(p, p, 2 * angle), abs=1e-9)


@SETTINGS
@given(density=st.floats(1.0, 2000.0, allow_subnormal=False), area=st.floats(1e-4, 1.0, allow_subnormal=False), speed=st.floats(0.0, 50.0, allow_subnormal=False))
def test_jet_force_is_the_stream_force_with_mass_per_second_rho_a_v(density, area, speed):
    assert jet_force(density, area, speed) == pytest.approx(
        stream_force(density * area * speed, speed))


@SETTINGS
@given(mass=masses)
def test_mass_is_the_same_everywhere_and_weight_scales_with_g(mass):
    on_moon = weight(mass, g=G_MOON)
    assert mass_from_weight(on_moon, g=G_MOON) == pytest.approx(mass)
    assert weight(mass) / on_moon == pytest.approx(G_EARTH / G_MOON)
    assert gravitational_field_strength(on_moon, mass) == pytest.approx(G_MOON)


@SETTINGS
@given(mass=masses, a=st.floats(-G_EARTH, 20.0, allow_subnormal=False))
def test_lift_contact_force_minus_weight_gives_the_acceleration(mass, a):
    contact = lift_contact_force(mass, a)
    assert acceleration(contact - weight(mass), mass) == pytest.approx(a, abs=1e-9)
    # near free fall both are differences of forces of about the weight: compare on that scale
    assert thrust_for_acceleration(weight(mass), a) == pytest.approx(contact, abs=1e-12 * weight(mass))


def test_lift_at_steady_speed_pushes_with_the_weight_and_in_free_fall_not_at_all():
    assert lift_contact_force(60.0, 0.0) == weight(60.0)
    assert lift_contact_force(60.0, -G_EARTH) == 0.0


@SETTINGS
@given(driving=st.floats(0.0, 1e4, allow_subnormal=False),
       bodies=st.lists(st.tuples(st.floats(1.0, 2000.0, allow_subnormal=False), st.floats(0.0, 1000.0, allow_subnormal=False)), min_size=1,
                       max_size=5))
def test_towing_gives_every_body_the_same_acceleration_from_its_own_forces(driving, bodies):
    masses_, resistive = zip(*bodies, strict=True)
    result = towing(driving, masses_, resistive)
    assert len(result.tensions) == len(bodies) - 1
    pull_in_front = (driving, *result.tensions)
    pull_behind = (*result.tensions, 0.0)
    for i, (mass, resist) in enumerate(bodies):
        resultant = pull_in_front[i] - pull_behind[i] - resist
        assert acceleration(resultant, mass) == pytest.approx(result.acceleration, abs=1e-9)


def test_towing_a_single_body_has_no_links():
    assert towing(3000.0, (1200.0,), (600.0,)).tensions == ()


# --- momentum-time graphs ---------------------------------------------------------------------


histories = st.lists(st.tuples(st.floats(0.1, 10.0, allow_subnormal=False), st.floats(-1e4, 1e4, allow_subnormal=False)), min_size=1,
                     max_size=6).map(
    lambda steps: MomentumHistory(np.cumsum([0.0] + [dt for dt, _ in steps]),
                                  [0.0] + [p for _, p in steps]))


@SETTINGS
@given(history=histories)
def test_area_under_the_force_time_graph_is_the_change_in_momentum(history):
    area = sum(s.force * (s.t1 - s.t0) for s in history.segments)
    assert area == pytest.approx(history.momenta[-1] - history.momenta[0], abs=1e-6)


@SETTINGS
@given(history=histories)
def test_gradient_of_the_momentum_time_graph_is_the_force(history):
    for s in history.segments:
        middle = (s.t0 + s.t1) / 2
        h = (s.t1 - s.t0) / 10
        gradient = (history.momentum_at(middle + h) - history.momentum_at(middle - h)) / (2 * h)
        assert gradient == pytest.approx(s.force, rel=1e-6, abs=1e-6)
        assert history.force_at(middle) == s.force


def test_momentum_history_passes_through_its_corners_and_interpolates_straight_lines():
    history = MomentumHistory((0.0, 4.0, 10.0), (0.0, 12_000.0, 12_000.0))
    assert history.momentum_at(np.array([0.0, 2.0, 4.0, 7.0, 10.0])) == pytest.approx(
        [0.0, 6000.0, 12_000.0, 12_000.0, 12_000.0])


def test_force_at_a_corner_is_the_force_of_the_segment_that_starts_there():
    history = MomentumHistory((0.0, 4.0, 10.0), (0.0, 12_000.0, 12_000.0))
    assert history.force_at(4.0) == 0.0
    assert history.force_at(10.0) == 0.0  # the end belongs to the last segment
    assert history.force_at(np.array([0.0, 3.9, 4.0])) == pytest.approx([3000.0, 3000.0, 0.0])


def test_a_line_crossing_zero_means_the_body_turns_round_under_the_same_force():
    # Notes: "If a line crosses zero and carries on below the axis, the object stops and then
    # moves the other way, with the same force still acting."
    history = MomentumHistory((0.0, 10.0), (5000.0, -5000.0))
    assert history.velocity_at(2.0, 1000.0) > 0 > history.velocity_at(8.0, 1000.0)
    assert history.force_at(2.0) == history.force_at(8.0) == -1000.0


def test_momentum_history_keeps_its_data_read_only():
    history = MomentumHistory((0.0, 4.0), (0.0, 12_000.0))
    with pytest.raises(ValueError, match="read-only"):
        history.times[0] = 1.0
    assert "(4, 12000)" in repr(history)


@SETTINGS
@given(history=histories)
def test_the_area_under_a_force_time_graph_of_the_forces_is_the_change_in_momentum(history):
    # a step force-time graph: each segment's force held for its time, corners doubled
    times = [t for s in history.segments for t in (s.t0, s.t1)]
    forces = [s.force for s in history.segments for _ in (0, 1)]
    unique = [t + i * 1e-12 for i, t in enumerate(times)]  # the doubled corners, a hair apart
    area = area_under_force_time(unique, forces)
    assert area == pytest.approx(history.momenta[-1] - history.momenta[0], abs=1e-6)


def test_the_area_under_a_trapezium_force_time_graph_is_half_the_sum_of_its_sides_times_its_height():
    # rises for 0.01 s to 200 N, holds for 0.02 s, falls for 0.01 s: (0.02 + 0.04) / 2 * 200
    assert area_under_force_time([0, 0.01, 0.03, 0.04], [0, 200, 200, 0]) == pytest.approx(6.0)


def test_the_area_under_a_force_time_graph_refuses_times_out_of_order():
    with pytest.raises(ValueError, match="times"):
        area_under_force_time([0, 0.02, 0.01], [0, 10, 0])
