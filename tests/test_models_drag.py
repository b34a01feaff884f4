"""Quadratic drag: closed forms checked against the differential equation, the skydive
A to E and a ball thrown upwards (Notes, "Friction, drag and terminal velocity")."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from physics_figures.constants import G_EARTH
from physics_figures.models import (
    drag_constant_for_terminal_velocity,
    drag_force,
    skydive,
    terminal_velocity,
    thrown_upwards,
    time_to_slow_to_terminal,
    time_to_terminal_velocity,
    velocity_from_rest,
    velocity_slowing_to_terminal,
    weight,
)

FAST = settings(max_examples=60, deadline=None)
terminal_speeds = st.floats(1.0, 100.0)
masses = st.floats(0.01, 200.0)


def rk4(rate, y0, t_end, steps):
    """Integrate dy/dt = rate(y) from y0 with the classic Runge-Kutta method (test-only)."""
    h = t_end / steps
    y = np.asarray(y0, dtype=float)
    for _ in range(steps):
        k1 = rate(y)
        k2 = rate(y + h / 2 * k1)
        k3 = rate(y + h / 2 * k2)
        k4 = rate(y + h * k3)
        y = y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    return y


def falling(v_t, g=G_EARTH):
    """dv/dt = g - (g / v_t²) v² for a body falling with quadratic drag (down positive)."""
    return lambda v: g - g / v_t**2 * v**2


# --- closed forms against the equation of motion ------------------------------------------


def test_tanh_velocity_from_rest_solves_the_equation_of_motion():
    # Finite differences of v = v_t tanh(g t / v_t) equal g - (g / v_t²) v² everywhere.
    v_t, h = 50.0, 1e-4
    t = np.linspace(0.1, 30.0, 300)
    gradient = (velocity_from_rest(t + h, v_t) - velocity_from_rest(t - h, v_t)) / (2 * h)
    assert gradient == pytest.approx(falling(v_t)(velocity_from_rest(t, v_t)), abs=1e-6)


def test_tanh_velocity_from_rest_matches_a_numerical_integration():
    v_t = 50.0
    for t_end in (1.0, 5.0, 20.0):
        integrated = rk4(falling(v_t), 0.0, t_end, steps=2000)
        assert velocity_from_rest(t_end, v_t) == pytest.approx(float(integrated), rel=1e-9)


def test_coth_velocity_slowing_to_terminal_matches_a_numerical_integration():
    v_t, v0 = 5.0, 50.0
    for t_end in (0.05, 0.5, 3.0):
        integrated = rk4(falling(v_t), v0, t_end, steps=4000)
        assert velocity_slowing_to_terminal(t_end, v0, v_t) == pytest.approx(float(integrated),
                                                                             rel=1e-8)


def test_slowing_to_terminal_starts_at_the_initial_velocity():
    assert velocity_slowing_to_terminal(0.0, 50.0, 5.0) == pytest.approx(50.0)


def test_initial_acceleration_of_a_dropped_body_is_g():
    # Notes: "for falling in air, the initial gradient is g".
    h = 1e-6
    assert velocity_from_rest(h, 50.0) / h == pytest.approx(G_EARTH, rel=1e-9)


@FAST
@given(v_t=terminal_speeds)
def test_velocity_from_rest_rises_towards_but_never_passes_terminal_velocity(v_t):
    t = np.linspace(0, 20 * v_t / G_EARTH, 400)
    v = velocity_from_rest(t, v_t)
    assert np.all(np.diff(v) >= 0)
    assert np.all(v <= v_t)
    assert v[-1] == pytest.approx(v_t, rel=1e-9)


@FAST
@given(v_t=terminal_speeds)
def test_gradient_of_the_velocity_time_curve_gets_less_steep(v_t):
    # Notes, A to B: the resultant force W - D gets smaller, so the v-t curve gets less steep.
    t = np.linspace(0, 5 * v_t / G_EARTH, 200)
    assert np.all(np.diff(np.diff(velocity_from_rest(t, v_t))) < 0)


def test_time_to_terminal_velocity_is_when_the_speed_is_within_the_fraction():
    t = time_to_terminal_velocity(50.0)
    assert velocity_from_rest(t, 50.0) == pytest.approx(49.5)
    t_e = time_to_slow_to_terminal(50.0, 5.0)
    assert velocity_slowing_to_terminal(t_e, 50.0, 5.0) == pytest.approx(5.05)


@FAST
@given(mass=masses, v_t=terminal_speeds)
def test_terminal_velocity_is_reached_when_drag_equals_weight(mass, v_t):
    k = drag_constant_for_terminal_velocity(mass, v_t)
    assert terminal_velocity(mass, k) == pytest.approx(v_t)
    assert drag_force(k, v_t) == pytest.approx(weight(mass))


@FAST
@given(mass=masses, k=st.floats(0.001, 10.0), upthrust_share=st.floats(0.0, 0.99))
def test_in_a_liquid_weight_equals_drag_plus_upthrust_at_terminal_velocity(mass, k,
                                                                            upthrust_share):
    upthrust = upthrust_share * weight(mass)
    v_t = terminal_velocity(mass, k, upthrust=upthrust)
    assert drag_force(k, v_t) + upthrust == pytest.approx(weight(mass))


@FAST
@given(mass=masses, heavier=st.floats(1.01, 10.0), k=st.floats(0.001, 10.0))
def test_heavier_body_of_the_same_shape_has_a_higher_terminal_velocity(mass, heavier, k):
    # Notes, "What affects terminal velocity": same shape and size (same k), more weight.
    assert terminal_velocity(heavier * mass, k) > terminal_velocity(mass, k)


@FAST
@given(mass=masses, k=st.floats(0.001, 10.0), larger=st.floats(1.01, 10.0))
def test_larger_area_means_a_lower_terminal_velocity(mass, k, larger):
    # A larger area (a parachute) gives a larger drag constant for the same mass.
    assert terminal_velocity(mass, larger * k) < terminal_velocity(mass, k)


# --- the skydive ------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def dive():
    # Notes' skydiver: 80 kg, 50 m s^-1 then 5.0 m s^-1; opening time and duration chosen.
    return skydive(80.0, terminal_velocity_freefall=50.0, terminal_velocity_parachute=5.0,
                   parachute_opens_at=20.0, duration=30.0)


def opening_index(dive):
    """Index of the first sample after the parachute opens (time holds the instant twice)."""
    return int(np.flatnonzero(dive.time == dive.parachute_opens_at)[1])


def test_skydive_starts_from_rest_with_acceleration_g_and_no_drag(dive):
    # Notes, A: "the speed is zero, so there is no drag ... the acceleration is g".
    assert dive.time[0] == 0 and dive.velocity[0] == 0 and dive.drag[0] == 0
    assert dive.acceleration[0] == pytest.approx(G_EARTH)
    assert dive.point_acceleration["A"] == pytest.approx(G_EARTH)


def test_skydive_velocity_follows_the_closed_forms(dive):
    before = dive.time <= dive.parachute_opens_at
    before[opening_index(dive):] = False
    assert dive.velocity[before] == pytest.approx(velocity_from_rest(dive.time[before], 50.0))
    after = np.arange(dive.time.size) >= opening_index(dive)
    v_open = velocity_from_rest(20.0, 50.0)
    assert dive.velocity[after] == pytest.approx(
        velocity_slowing_to_terminal(dive.time[after] - 20.0, v_open, 5.0))


def test_skydive_arrays_agree_with_newtons_second_law(dive):
    assert dive.resultant_force == pytest.approx(dive.weight - dive.drag)
    assert dive.acceleration == pytest.approx(dive.resultant_force / dive.mass)
    # and the acceleration is the gradient of the velocity in each phase
    i = opening_index(dive)
    for phase in (slice(0, i), slice(i, None)):
        t, v = dive.time[phase], dive.velocity[phase]
        middle = slice(1, -1)
        assert np.gradient(v, t)[middle] == pytest.approx(dive.acceleration[phase][middle],
                                                          rel=0.02, abs=0.02)


def test_skydive_distance_grows_at_the_velocity(dive):
    i = opening_index(dive)
    assert dive.distance[i - 1] == dive.distance[i]
    for phase in (slice(0, i), slice(i, None)):
        t, x = dive.time[phase], dive.distance[phase]
        assert np.gradient(x, t)[1:-1] == pytest.approx(dive.velocity[phase][1:-1], rel=0.02)


def test_skydive_deceleration_is_largest_at_the_instant_the_parachute_opens(dive):
    # Notes, D: "The deceleration is largest at the instant the parachute opens".
    i = int(np.argmin(dive.acceleration))
    assert i == opening_index(dive)
    assert dive.time[i] == dive.parachute_opens_at
    assert dive.drag[i] == dive.drag.max()
    assert dive.point_acceleration["D"] == pytest.approx(dive.acceleration[i])


def test_skydiver_slows_down_but_still_moves_down_after_the_parachute_opens(dive):
    # Notes, D: "the skydiver slows down but is still moving down" (acceleration upwards).
    after = slice(opening_index(dive), None)
    assert np.all(dive.velocity[after] > 0)
    assert np.all(np.diff(dive.velocity[after]) <= 0)
    assert np.all(dive.acceleration[after] <= 0)
    until_e = (dive.time >= dive.parachute_opens_at) & (dive.time <= dive.points["E"][0])
    assert np.all(dive.acceleration[after][until_e[after]] < 0)


def test_deceleration_gets_smaller_from_d_to_e(dive):
    after = slice(opening_index(dive), None)
    assert np.all(np.diff(-dive.acceleration[after]) <= 0)


def test_at_both_terminal_velocities_drag_equals_weight(dive):
    # Notes, E: "At both terminal velocities the drag is the same size, the weight."
    assert drag_force(dive.drag_constant_freefall, 50.0) == pytest.approx(dive.weight)
    assert drag_force(dive.drag_constant_parachute, 5.0) == pytest.approx(dive.weight)
    assert dive.drag[-1] == pytest.approx(dive.weight, rel=1e-6)


def test_skydive_points_follow_their_rules(dive):
    a, b, c, d, e = (dive.points[label] for label in "ABCDE")
    assert a == (0.0, 0.0)
    assert 0 < b[0] < c[0] < d[0] < e[0] < dive.duration
    assert b[1] == 25.0 and c[1] == pytest.approx(49.5) and e[1] == pytest.approx(5.05)
    assert d == (20.0, pytest.approx(velocity_from_rest(20.0, 50.0)))
    for label in "BC":
        t, v = dive.points[label]
        assert velocity_from_rest(t, 50.0) == pytest.approx(v)
    assert velocity_slowing_to_terminal(e[0] - d[0], d[1], 5.0) == pytest.approx(e[1])
    # C and E: the first times the velocity is within 1 % of each terminal velocity
    first_c = dive.time[np.argmax(dive.velocity >= 49.5)]
    assert first_c == pytest.approx(c[0], abs=dive.time[1])
    assert set(dive.POINT_RULES) == set("ABCDE")


def test_drag_at_the_points_rises_then_jumps_then_falls_back_to_the_weight(dive):
    drag = dive.point_drag
    assert drag["A"] == 0 < drag["B"] < drag["C"] < dive.weight < drag["E"] < drag["D"]
    assert drag["C"] == pytest.approx(dive.weight, rel=0.02)
    assert drag["E"] == pytest.approx(dive.weight, rel=0.03)


def test_skydive_arrays_are_read_only(dive):
    with pytest.raises(ValueError, match="read-only"):
        dive.velocity[0] = 1.0
    with pytest.raises(TypeError):
        dive.points["A"] = (1.0, 1.0)


# --- thrown upwards ---------------------------------------------------------------------------


def throw_rate(v_t, g=G_EARTH):
    """d(h, v)/dt for a ball moving vertically, up positive, drag against the velocity."""
    return lambda y: np.array([y[1], -g - g / v_t**2 * y[1] * abs(y[1])])


def test_thrown_upwards_matches_a_numerical_integration():
    ball = thrown_upwards(20.0, terminal_velocity=20.0)
    top = rk4(throw_rate(20.0), [0.0, 20.0], ball.time_to_top, steps=4000)
    assert top == pytest.approx([ball.max_height, 0.0], abs=1e-9)
    end = rk4(throw_rate(20.0), [0.0, 20.0], ball.time_of_flight, steps=8000)
    assert end == pytest.approx([0.0, -ball.return_speed], abs=1e-8)
    middle = ball.time.size // 3
    at = rk4(throw_rate(20.0), [0.0, 20.0], ball.time[middle], steps=4000)
    assert at == pytest.approx([ball.height[middle], ball.velocity[middle]], abs=1e-9)


def test_thrown_upwards_in_a_vacuum_is_symmetric():
    ball = thrown_upwards(20.0)
    assert ball.time_to_top == pytest.approx(20.0 / G_EARTH)
    assert ball.max_height == pytest.approx(20.0**2 / (2 * G_EARTH))
    assert ball.return_speed == 20.0 and ball.time_of_flight == pytest.approx(2 * ball.time_to_top)
    assert np.all(ball.acceleration == -G_EARTH)
    assert ball.height[-1] == pytest.approx(0.0, abs=1e-12)


@FAST
@given(u=st.floats(1.0, 60.0), v_t=terminal_speeds)
def test_drag_lowers_the_top_shortens_the_climb_and_slows_the_return(u, v_t):
    # Notes: "reaches a lower height than it would in a vacuum, takes less time to get there,
    # and comes back slower than it was thrown".
    air, vacuum = thrown_upwards(u, terminal_velocity=v_t, samples=50), thrown_upwards(u, samples=50)
    assert air.max_height < vacuum.max_height
    assert air.time_to_top < vacuum.time_to_top
    assert air.return_speed < u
    assert air.time_of_flight - air.time_to_top > air.time_to_top  # slower down than up


@FAST
@given(u=st.floats(1.0, 60.0), v_t=terminal_speeds)
def test_deceleration_is_more_than_g_going_up_and_less_than_g_coming_down(u, v_t):
    # Notes: "On the way up ... the deceleration is more than g. On the way down ... the
    # acceleration is less than g."
    ball = thrown_upwards(u, terminal_velocity=v_t, samples=50)
    going_up, coming_down = ball.velocity > 0, ball.velocity < 0
    assert np.all(ball.acceleration[going_up] < -G_EARTH)
    assert np.all(-ball.acceleration[coming_down] < G_EARTH)
    assert np.all(ball.acceleration[coming_down] < 0)  # still downwards overall


def test_resultant_force_is_largest_at_the_start_and_decreases_as_the_ball_slows():
    ball = thrown_upwards(20.0, terminal_velocity=20.0)
    size = np.abs(ball.acceleration)
    assert np.argmax(size) == 0
    assert np.all(np.diff(size) < 0)


def test_the_ball_stops_at_the_top_and_lands_at_the_launch_height():
    ball = thrown_upwards(20.0, terminal_velocity=20.0)
    top = int(np.argmax(ball.height))
    assert ball.time[top] == pytest.approx(ball.time_to_top)
    assert ball.velocity[top] == pytest.approx(0.0, abs=1e-12)
    assert ball.height[top] == pytest.approx(ball.max_height)
    assert ball.height[-1] == 0.0 and ball.velocity[-1] == pytest.approx(-ball.return_speed)
    assert np.all(np.diff(ball.time) > 0)


def test_skydive_reports_the_resultant_force_and_the_drag_at_each_terminal_velocity():
    # Notes, Understand it > Friction, drag and terminal velocity: at both terminal
    # velocities the drag is the same size, the weight (80 x 9.81 = 785 N).
    from physics_figures.scenarios import SKYDIVER as jump
    for label, drag in jump.point_drag.items():
        assert jump.point_resultant_force[label] == pytest.approx(jump.weight - drag)
    assert jump.terminal_drag["C"] == pytest.approx(jump.weight)
    assert jump.terminal_drag["E"] == pytest.approx(jump.weight)
    assert round(jump.terminal_drag["C"]) == 785
