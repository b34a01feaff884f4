"""Conservation laws over whole parameter ranges (Notes, "Conservation of momentum",
"Elastic and inelastic collisions", "Momentum in two dimensions")."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from physics_figures.models import (
    collision_with_energy_kept,
    components,
    elastic_collision,
    explosion_from_rest,
    from_components,
    glancing_collision,
    kinetic_energy,
    missing_momentum,
    momentum_change_between_directions,
    percentage_kinetic_energy_lost,
    relative_speed,
    stick_together,
    total_kinetic_energy,
    total_momentum,
    velocity_after_collision,
)

SETTINGS = settings(max_examples=100, deadline=None)
masses = st.floats(0.01, 100.0, allow_subnormal=False)
velocities = st.floats(-50.0, 50.0, allow_subnormal=False)
# A speed a lab can measure (or none): at 1e-308 m s^-1, m1 v1 / m2 rounds to zero or below the
# smallest normal float, and comparing such speeds tests the floats, not the physics.
measurable_velocities = velocities.filter(lambda v: v == 0 or abs(v) >= 1e-9)
fractions = st.floats(0.0, 1.0, allow_subnormal=False)
sizes = st.floats(0.0, 10.0, allow_subnormal=False)
angles = st.floats(0.0, 180.0, allow_subnormal=False)


def close(a, b, scale):
    """Equal to rounding error for numbers of about this size."""
    return a == pytest.approx(b, abs=1e-9 * max(1.0, scale))


@SETTINGS
@given(m1=masses, u1=velocities, m2=masses, u2=velocities, f=fractions)
def test_momentum_is_conserved_in_every_collision(m1, u1, m2, u2, f):
    before = total_momentum([m1, m2], [u1, u2])
    scale = (m1 + m2) * 50
    for v1, v2 in (elastic_collision(m1, u1, m2, u2),
                   (stick_together(m1, u1, m2, u2),) * 2,
                   collision_with_energy_kept(m1, u1, m2, u2, fraction_of_ke_kept_in_cm_frame=f)):
        assert close(total_momentum([m1, m2], [v1, v2]), before, scale)


@SETTINGS
@given(m1=masses, u1=velocities, m2=masses, u2=velocities, v1=velocities)
def test_velocity_after_collision_conserves_momentum(m1, u1, m2, u2, v1):
    v2 = velocity_after_collision(m1, u1, m2, u2, v1)
    assert close(m1 * v1 + m2 * v2, m1 * u1 + m2 * u2, (m1 + m2) * 50)


@SETTINGS
@given(m1=masses, u1=velocities, m2=masses, u2=velocities)
def test_kinetic_energy_is_unchanged_in_an_elastic_collision(m1, u1, m2, u2):
    v1, v2 = elastic_collision(m1, u1, m2, u2)
    before = total_kinetic_energy([m1, m2], [u1, u2])
    assert close(total_kinetic_energy([m1, m2], [v1, v2]), before, (m1 + m2) * 2500)


@SETTINGS
@given(m1=masses, u1=velocities, m2=masses, u2=velocities)
def test_relative_speed_of_approach_equals_separation_in_an_elastic_collision(m1, u1, m2, u2):
    v1, v2 = elastic_collision(m1, u1, m2, u2)
    assert close(u1 - u2, v2 - v1, 100)
    assert close(relative_speed(u1, u2), relative_speed(v1, v2), 100)


@SETTINGS
@given(m1=masses, u1=velocities, m2=masses, u2=velocities, f=fractions)
def test_kinetic_energy_is_never_created_in_a_collision(m1, u1, m2, u2, f):
    before = total_kinetic_energy([m1, m2], [u1, u2])
    stuck = stick_together(m1, u1, m2, u2)
    kept = collision_with_energy_kept(m1, u1, m2, u2, fraction_of_ke_kept_in_cm_frame=f)
    tolerance = 1e-9 * max(1.0, (m1 + m2) * 2500)
    assert total_kinetic_energy([m1, m2], [stuck, stuck]) <= before + tolerance
    assert total_kinetic_energy([m1, m2], kept) <= before + tolerance


@SETTINGS
@given(m1=masses, u1=velocities, m2=masses, u2=velocities, f=fractions)
def test_the_fraction_kept_is_of_the_kinetic_energy_in_the_centre_of_mass_frame(m1, u1, m2, u2,
                                                                                  f):
    v_cm = stick_together(m1, u1, m2, u2)
    locked = total_kinetic_energy([m1, m2], [v_cm, v_cm])  # cannot be lost
    before = total_kinetic_energy([m1, m2], [u1, u2])
    after = total_kinetic_energy(
        [m1, m2], collision_with_energy_kept(m1, u1, m2, u2, fraction_of_ke_kept_in_cm_frame=f))
    assert close(after - locked, f * (before - locked), (m1 + m2) * 2500)


@SETTINGS
@given(m1=masses, u1=velocities, m2=masses, u2=velocities)
def test_keeping_all_or_none_of_the_energy_is_elastic_or_sticking(m1, u1, m2, u2):
    elastic = collision_with_energy_kept(m1, u1, m2, u2, fraction_of_ke_kept_in_cm_frame=1.0)
    assert elastic == pytest.approx(elastic_collision(m1, u1, m2, u2), abs=1e-9)
    stuck = collision_with_energy_kept(m1, u1, m2, u2, fraction_of_ke_kept_in_cm_frame=0.0)
    assert stuck == pytest.approx((stick_together(m1, u1, m2, u2),) * 2, abs=1e-9)


def test_equal_masses_in_an_elastic_collision_swap_velocities():
    # Notes, 6. Elastic and inelastic collisions: "they swap velocities".
    assert elastic_collision(2.0, 5.0, 2.0, 0.0) == pytest.approx((0.0, 5.0))
    assert elastic_collision(2.0, 5.0, 2.0, -3.0) == pytest.approx((-3.0, 5.0))


@SETTINGS
@given(light=st.floats(0.01, 1.0, allow_subnormal=False), heavier=st.floats(1.5, 100.0, allow_subnormal=False), u=st.floats(0.1, 50.0, allow_subnormal=False))
def test_light_body_bounces_back_slower_off_a_heavy_one_at_rest(light, heavier, u):
    # Notes: "the light one bounces back more slowly than it arrived; the heavy one moves
    # off slowly. A heavy one hitting a light one: both move forwards, the light one faster."
    v_light, v_heavy = elastic_collision(light, u, light * heavier, 0.0)
    assert -u < v_light < 0 and 0 < v_heavy < u
    v_heavy, v_light = elastic_collision(light * heavier, u, light, 0.0)
    assert 0 < v_heavy < v_light


@SETTINGS
@given(m1=masses, m2=masses, v1=measurable_velocities)
def test_explosion_from_rest_has_zero_total_momentum_and_the_lighter_piece_is_faster(m1, m2, v1):
    v2 = explosion_from_rest(m1, m2, v1)
    assert close(total_momentum([m1, m2], [v1, v2]), 0.0, m1 * 50)
    assert v1 * v2 <= 0  # opposite directions
    if m1 < m2:
        assert abs(v1) >= abs(v2)
    elif m1 > m2:
        assert abs(v1) <= abs(v2)


@SETTINGS
@given(m1=masses, m2=masses, v1=st.floats(0.1, 50.0, allow_subnormal=False))
def test_explosion_kinetic_energies_are_in_the_inverse_ratio_of_the_masses(m1, m2, v1):
    # Notes, 5.: "for two pieces from rest, the kinetic energies are in the inverse ratio".
    v2 = explosion_from_rest(m1, m2, v1)
    ratio = kinetic_energy(m1, v1) / kinetic_energy(m2, v2)
    assert ratio == pytest.approx(m2 / m1, rel=1e-9)


def test_relative_speed_is_how_fast_the_gap_changes():
    assert relative_speed(5.0, -3.0) == relative_speed(-3.0, 5.0) == 8.0
    assert relative_speed(5.0, 3.0) == 2.0


def test_explosion_gains_kinetic_energy_so_the_percentage_lost_is_negative():
    assert percentage_kinetic_energy_lost(1.0, 1.5) == pytest.approx(-50.0)


# --- two dimensions ---------------------------------------------------------------------------


@SETTINGS
@given(p_before=sizes, p_known=sizes, angle=angles)
def test_momentum_triangle_closes(p_before, p_known, angle):
    # Notes: "the momentum arrows after the collision, joined tip to tail, must end where the
    # arrow before the collision ends".
    collision = glancing_collision(p_before, p_known, angle)
    known, missing = collision.known_vector, collision.missing_vector
    assert close(known[0] + missing[0], p_before, 10)
    assert close(known[1] + missing[1], 0.0, 10)
    assert collision.triangle[-1] == pytest.approx(collision.before_vector, abs=1e-9)


@SETTINGS
@given(p_before=sizes, p_known=sizes, angle=angles)
def test_missing_momentum_is_on_the_other_side_with_consistent_size_and_angle(p_before, p_known,
                                                                               angle):
    result = missing_momentum(p_before, p_known, angle)
    assert result.across >= 0
    assert close(result.magnitude, math.hypot(result.along, result.across), 10)
    size, direction = from_components(result.along, result.across)
    assert close(size, result.magnitude, 10)
    if result.magnitude > 1e-9:
        assert close(direction, result.angle_deg, 180)


@SETTINGS
@given(size=sizes, angle=st.floats(-180.0, 180.0, allow_subnormal=False))
def test_components_and_from_components_undo_each_other(size, angle):
    along, across = components(size, angle)
    back_size, back_angle = from_components(along, across)
    assert close(back_size, size, 10)
    if size > 1e-6 and abs(angle) < 179.999:
        assert back_angle == pytest.approx(angle, abs=1e-6)


@SETTINGS
@given(p=sizes)
def test_no_turn_and_no_change_of_size_means_no_change_in_momentum(p):
    assert momentum_change_between_directions(p, p, 0.0) == pytest.approx(0.0, abs=1e-9)


@SETTINGS
@given(p1=sizes, p2=sizes)
def test_turning_through_90_degrees_gives_pythagoras(p1, p2):
    assert close(momentum_change_between_directions(p1, p2, 90.0), math.hypot(p1, p2), 10)


@SETTINGS
@given(p1=sizes, p2=sizes, angle=angles)
def test_momentum_change_between_directions_is_the_vector_difference(p1, p2, angle):
    difference = np.subtract(components(p2, angle), components(p1, 0.0))
    assert close(momentum_change_between_directions(p1, p2, angle), np.hypot(*difference), 10)


def test_turning_back_through_180_degrees_adds_the_sizes():
    # Notes, 3.: a ball that bounces straight back has |Δp| = m(u + v), not m(u - v).
    assert momentum_change_between_directions(0.058 * 24, 0.058 * 18, 180.0) == pytest.approx(
        0.058 * 42)
