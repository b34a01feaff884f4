"""Quadratic drag: closed forms checked against the differential equation, the skydive
A to E and a ball thrown upwards (Notes, "Friction, drag and terminal velocity")."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from physics_figures.constants import G_EARTH
from physics_figures.models import (
    OPENING_STEPS,
    canopy_drag_constant,
    drag_constant_for_terminal_velocity,
    drag_force,
    earliest_opening,
    falling_acceleration,
    open_canopy,
    power_law_constant,
    power_law_drag,
    power_law_terminal_velocity,
    skydive,
    sphere_volume,
    stokes_constant,
    terminal_velocity,
    terminal_velocity_ratio,
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
    # Notes' skydiver: 80 kg, 50 m s^-1 then 5.0 m s^-1; opening time, the 2.5 s the canopy
    # takes to fill (CLARIFICATIONS, Physics) and duration chosen.
    return skydive(80.0, terminal_velocity_freefall=50.0, terminal_velocity_parachute=5.0,
                   parachute_opens_at=20.0, opening_duration=2.5, duration=30.0)


def from_d(dive):
    """Samples from point D, the largest deceleration, to the end."""
    return dive.time >= dive.points["D"][0]


def test_skydive_starts_from_rest_with_acceleration_g_and_no_drag(dive):
    # Notes, A: "the speed is zero, so there is no drag ... the acceleration is g".
    assert dive.time[0] == 0 and dive.velocity[0] == 0 and dive.drag[0] == 0
    assert dive.acceleration[0] == pytest.approx(G_EARTH)
    assert dive.point_acceleration["A"] == pytest.approx(G_EARTH)


def test_skydive_velocity_follows_the_closed_forms_before_the_opening_and_once_fully_open(dive):
    before = dive.time < dive.parachute_opens_at
    assert dive.velocity[before] == pytest.approx(velocity_from_rest(dive.time[before], 50.0))
    full = dive.time >= dive.parachute_open_at
    v_full = dive.velocity_at(dive.parachute_open_at)
    assert dive.velocity[full] == pytest.approx(
        velocity_slowing_to_terminal(dive.time[full] - dive.parachute_open_at, v_full, 5.0))


def test_skydive_arrays_agree_with_newtons_second_law(dive):
    assert dive.resultant_force == pytest.approx(dive.weight - dive.drag)
    assert dive.acceleration == pytest.approx(dive.resultant_force / dive.mass)
    assert dive.drag == pytest.approx(dive.drag_constant_at(dive.time) * dive.velocity**2)
    # and the acceleration is the gradient of the velocity, through the opening too
    middle = slice(1, -1)
    assert np.gradient(dive.velocity, dive.time)[middle] == pytest.approx(
        dive.acceleration[middle], rel=0.02, abs=0.05)


def test_skydive_distance_grows_at_the_velocity(dive):
    assert np.gradient(dive.distance, dive.time)[1:-1] == pytest.approx(dive.velocity[1:-1], rel=0.02)


def test_skydive_methods_give_the_arrays_at_the_sample_times(dive):
    assert dive.velocity_at(dive.time) == pytest.approx(dive.velocity, rel=1e-12)
    assert dive.drag_at(dive.time) == pytest.approx(dive.drag, rel=1e-12, abs=1e-9)
    assert dive.acceleration_at(dive.time) == pytest.approx(dive.acceleration, rel=1e-12, abs=1e-9)


def test_peak_deceleration_is_a_few_g_just_after_the_parachute_opens(dive):
    # Issue 12 and CLARIFICATIONS (Physics): with the canopy taking 2.5 s to open the
    # largest deceleration is about 4 g, about 0.8 s after the opening (the instant
    # opening gave about 99 g, at the opening itself). Notes, D: the deceleration is
    # largest just after the parachute opens.
    i = int(np.argmin(dive.acceleration))
    t_d, v_d = dive.points["D"]
    assert (dive.time[i], dive.velocity[i]) == (t_d, v_d)
    assert dive.point_acceleration["D"] == dive.acceleration[i] == dive.acceleration.min()
    assert dive.drag[i] == dive.drag.max() == dive.point_drag["D"]
    in_g = -dive.point_acceleration["D"] / G_EARTH
    assert 2 < in_g < 6
    assert round(in_g, 1) == 4.0
    assert 0.5 < t_d - dive.parachute_opens_at < 1.0
    # the largest of the whole fall, at any time, not only at the samples
    t = np.linspace(0, dive.duration, 30001)
    assert -dive.acceleration_at(t).min() == pytest.approx(-dive.point_acceleration["D"], rel=1e-4)


def test_drag_constant_grows_without_a_jump_from_the_bodys_to_the_canopys(dive):
    k1, k2, t_open = dive.drag_constant_freefall, dive.drag_constant_parachute, dive.parachute_opens_at
    assert dive.drag_constant_at(t_open) == k1
    assert dive.drag_constant_at(dive.parachute_open_at) == pytest.approx(k2)
    assert dive.drag_constant_at(dive.duration) == k2
    t = np.linspace(0, dive.duration, 300001)  # steps of 0.1 ms
    k = dive.drag_constant_at(t)
    assert np.all(np.diff(k) >= 0)
    # continuous: no step bigger than the steepest slope, 2 (k2 - k1) / tau, allows
    assert np.max(np.diff(k)) <= 2 * (k2 - k1) / dive.opening_duration * 1e-4 * 1.001
    # the instant opening jumped by k2 - k1, a hundredfold, in one step
    assert canopy_drag_constant(1.25, k1, k2, 2.5) == pytest.approx(k1 + (k2 - k1) / 4)


def test_velocity_falls_smoothly_over_a_few_seconds_after_the_opening(dive):
    # A real canopy takes seconds to slow the skydiver: the v-t curve is continuous and
    # visibly curved, not a near-vertical drop (the instant opening lost two thirds of the
    # speed in the first 0.1 s).
    t_open, v_open = dive.parachute_opens_at, dive.velocity_at(dive.parachute_opens_at)
    assert dive.velocity_at(t_open + 0.25) > 0.95 * v_open
    assert dive.velocity_at(t_open + 1.0) > 0.4 * v_open
    assert dive.points["E"][0] - t_open > 2.5
    t = np.linspace(0, dive.duration, 30001)
    v = dive.velocity_at(t)
    assert np.max(np.abs(np.diff(v))) < G_EARTH * 5 * (t[1] - t[0])  # no step: |dv/dt| < 5 g


def test_skydiver_slows_down_but_still_moves_down_after_the_parachute_opens(dive):
    # Notes, D: "the skydiver slows down but is still moving down" (acceleration upwards).
    after = dive.time >= dive.parachute_opens_at
    assert np.all(dive.velocity[after] > 0)
    # within a few hundredths of a second of opening the drag exceeds the weight
    slowing = dive.time > dive.parachute_opens_at + 0.02
    assert np.all(np.diff(dive.velocity[slowing]) <= 0)
    until_e = slowing & (dive.time <= dive.points["E"][0])
    assert np.all(dive.acceleration[until_e] < 0)


def test_deceleration_grows_as_the_canopy_fills_then_gets_smaller_from_d_to_e(dive):
    opening = (dive.time >= dive.parachute_opens_at) & ~from_d(dive)
    assert np.all(np.diff(-dive.acceleration[opening]) > 0)
    assert np.all(np.diff(-dive.acceleration[from_d(dive)]) <= 0)


def test_at_both_terminal_velocities_drag_equals_weight(dive):
    # Notes, E: "At both terminal velocities the drag is the same size, the weight."
    assert drag_force(dive.drag_constant_freefall, 50.0) == pytest.approx(dive.weight)
    assert drag_force(dive.drag_constant_parachute, 5.0) == pytest.approx(dive.weight)
    assert dive.drag[-1] == pytest.approx(dive.weight, rel=1e-6)


def test_skydive_points_follow_their_rules(dive):
    a, b, c, d, e = (dive.points[label] for label in "ABCDE")
    assert a == (0.0, 0.0)
    assert 0 < b[0] < c[0] < dive.parachute_opens_at < d[0] < dive.parachute_open_at < e[0] < dive.duration
    assert b[1] == 25.0 and c[1] == pytest.approx(49.5) and e[1] == pytest.approx(5.05)
    for label in "BC":
        t, v = dive.points[label]
        assert velocity_from_rest(t, 50.0) == pytest.approx(v)
    v_full = dive.velocity_at(dive.parachute_open_at)
    assert velocity_slowing_to_terminal(e[0] - dive.parachute_open_at, v_full, 5.0) == pytest.approx(e[1])
    # C and E: the first times the velocity is within 1 % of each terminal velocity
    first_c = dive.time[np.argmax(dive.velocity >= 49.5)]
    assert first_c == pytest.approx(c[0], abs=dive.time[1])
    t = np.linspace(dive.parachute_opens_at, dive.duration, 100001)
    assert t[np.argmax(dive.velocity_at(t) <= 5.05)] == pytest.approx(e[0], abs=t[1] - t[0])
    assert set(dive.POINT_RULES) == set("ABCDE")


def test_drag_at_the_points_rises_then_peaks_then_falls_back_to_the_weight(dive):
    drag = dive.point_drag
    assert drag["A"] == 0 < drag["B"] < drag["C"] < dive.weight < drag["E"] < drag["D"]
    assert drag["C"] == pytest.approx(dive.weight, rel=0.02)
    assert drag["E"] == pytest.approx(dive.weight, rel=0.03)


def test_skydive_arrays_are_read_only(dive):
    with pytest.raises(ValueError, match="read-only"):
        dive.velocity[0] = 1.0
    with pytest.raises(ValueError, match="read-only"):
        dive.opening.velocity[0] = 1.0
    with pytest.raises(TypeError):
        dive.points["A"] = (1.0, 1.0)


def test_a_parachute_may_open_before_terminal_velocity():
    # The explorer lets it open at any time once the skydiver is faster than the
    # parachute's terminal velocity; then C (and B) are never reached.
    early = skydive(80.0, terminal_velocity_freefall=50.0, terminal_velocity_parachute=5.0,
                    parachute_opens_at=2.0, opening_duration=2.5, duration=30.0)
    assert set(early.points) == {"A", "D", "E"}
    assert early.points["D"][0] > 2.0 and np.all(early.velocity[1:] > 0)
    assert earliest_opening(50.0, 5.0) == pytest.approx(50.0 / G_EARTH * np.arctanh(5.05 / 50.0))
    assert velocity_from_rest(earliest_opening(50.0, 5.0), 50.0) == pytest.approx(5.05)


# --- the integrator for the opening, against the closed forms ---------------------------------


@FAST
@given(mass=st.floats(40, 120), k=st.floats(0.15, 80), tau=st.floats(0.5, 5))
def test_opening_integration_with_no_change_in_drag_is_the_tanh_from_rest(mass, k, tau):
    # With the same drag constant throughout, falling from rest is v_t tanh(g t / v_t).
    opening = open_canopy(mass, 0.0, body_drag=k, canopy_drag=k, opening_duration=tau)
    v_t = terminal_velocity(mass, k)
    s = opening.time_since_opening
    assert opening.velocity == pytest.approx(velocity_from_rest(s, v_t), rel=1e-9, abs=1e-12)
    assert opening.distance == pytest.approx(v_t**2 / G_EARTH * np.log(np.cosh(G_EARTH * s / v_t)),
                                             rel=1e-9, abs=1e-12)


@FAST
@given(mass=st.floats(40, 120), k=st.floats(8, 80), faster=st.floats(1.1, 20), tau=st.floats(0.5, 5))
def test_opening_integration_with_the_canopy_already_open_is_the_coth(mass, k, faster, tau):
    # A canopy fully open from the start (body drag = canopy drag): the closed form coth.
    v_t = terminal_velocity(mass, k)
    opening = open_canopy(mass, faster * v_t, body_drag=k, canopy_drag=k, opening_duration=tau)
    # RK4's error is about 1e-6 at the hardest corner (20 times v_t, tau = 5 s, mass 40 kg)
    assert opening.velocity == pytest.approx(
        velocity_slowing_to_terminal(opening.time_since_opening, faster * v_t, v_t), rel=1e-5)


def test_a_very_quick_opening_tends_to_the_instant_one():
    # tau -> 0: once open the skydiver follows the coth from the opening speed.
    v_open = velocity_from_rest(20.0, 50.0)
    for tau, tolerance in ((1e-2, 1e-2), (1e-3, 1e-3)):
        quick = skydive(80.0, terminal_velocity_freefall=50.0, terminal_velocity_parachute=5.0,
                        parachute_opens_at=20.0, opening_duration=tau, duration=30.0)
        t = np.array([20.5, 21.0, 22.0, 25.0])
        assert quick.velocity_at(t) == pytest.approx(
            velocity_slowing_to_terminal(t - 20.0, v_open, 5.0), rel=tolerance)


def test_opening_integration_converges_as_the_steps_shrink():
    # The fixed 2000 steps are far finer than they need to be: ten times as many change
    # the velocity by less than 1e-9 of itself, at the hardest opening the explorer allows.
    args = {"body_drag": 0.15, "canopy_drag": 80.0, "opening_duration": 0.5}
    coarse = open_canopy(120.0, 88.0, **args)
    fine = open_canopy(120.0, 88.0, steps=20 * OPENING_STEPS, **args)
    assert coarse.velocity == pytest.approx(fine.velocity[::20], rel=1e-9)
    assert coarse.acceleration.min() == pytest.approx(fine.acceleration.min(), rel=1e-6)


def test_opening_integration_agrees_with_an_independent_rk4():
    mass, v0, k1, k2, tau = 80.0, 49.96, 0.3139, 31.39, 2.5

    def rate(y, s):
        f = min(1.0, s / tau)
        return np.array([y[1], G_EARTH - (k1 + (k2 - k1) * f * f) * y[1] ** 2 / mass])

    h, y = tau / 8000, np.array([0.0, v0])
    for i in range(8000):  # time-dependent RK4 with four times the steps
        s = i * h
        a = rate(y, s)
        b = rate(y + h / 2 * a, s + h / 2)
        c = rate(y + h / 2 * b, s + h / 2)
        d = rate(y + h * c, s + h)
        y = y + h / 6 * (a + 2 * b + 2 * c + d)
    opening = open_canopy(mass, v0, body_drag=k1, canopy_drag=k2, opening_duration=tau)
    assert (opening.distance[-1], opening.velocity[-1]) == pytest.approx(tuple(y), rel=1e-9)


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


def test_falling_acceleration_is_the_resultant_force_over_the_mass():
    # Notes, Drag and terminal velocity: a 68 kg skydiver with 1800 N of drag has
    # a = (1800 - 667) / 68 = 16.7 m s^-2 upwards, i.e. -16.7 with down positive.
    from physics_figures.models import upthrust, weight
    assert falling_acceleration(68, 1800) == pytest.approx(-(1800 - 68 * G_EARTH) / 68)
    assert round(-falling_acceleration(68, 1800), 1) == 16.7
    assert falling_acceleration(2.0, 0.0) == pytest.approx(G_EARTH)  # no drag: free fall
    assert falling_acceleration(70, weight(70)) == pytest.approx(0.0, abs=1e-12)  # terminal velocity
    u = upthrust(920, 1.5e-6)
    assert falling_acceleration(0.012, 0.0, upthrust=u) == pytest.approx((0.012 * G_EARTH - u) / 0.012)
    assert falling_acceleration(70, 0.0, g=1.62) == pytest.approx(1.62)


@pytest.mark.parametrize(("call", "message"), [
    (lambda: falling_acceleration(0, 10), "mass"),
    (lambda: falling_acceleration(1, -1), "drag"),
    (lambda: falling_acceleration(1, 1, upthrust=-1),
     "upthrust"),
])
def test_falling_acceleration_refuses_bad_inputs_with_the_rule(call, message):
    with pytest.raises(ValueError, match=message):
        call()


# --- a drag law given in a question: F = k vⁿ (issue 25) ---------------------------------------

powers = st.sampled_from((1, 2))  # the laws papers give: kv (and 6 pi eta r v), kv² (and C rho A v² / 2)


@FAST
@given(mass=masses, k=st.floats(0.001, 50.0), power=powers)
def test_at_the_terminal_velocity_of_a_given_law_the_drag_equals_the_weight(mass, k, power):
    v_t = power_law_terminal_velocity(mass, k, power=power)
    assert power_law_drag(k, v_t, power=power) == pytest.approx(weight(mass), rel=1e-9)
    # and the constant found from that terminal velocity is the law's own (k = mg / v_tⁿ)
    assert power_law_constant(weight(mass), v_t, power=power) == pytest.approx(k, rel=1e-9)


@FAST
@given(mass=masses, v_t=terminal_speeds)
def test_the_square_law_is_the_quadratic_drag_of_the_other_models(mass, v_t):
    k = drag_constant_for_terminal_velocity(mass, v_t)
    assert power_law_constant(weight(mass), v_t, power=2) == pytest.approx(k, rel=1e-12)
    assert power_law_terminal_velocity(mass, k, power=2) == pytest.approx(terminal_velocity(mass, k), rel=1e-12)
    assert power_law_drag(k, v_t, power=2) == pytest.approx(drag_force(k, v_t), rel=1e-12)


@FAST
@given(mass=masses, ratio=st.floats(0.05, 20.0), k=st.floats(0.001, 50.0), power=powers)
def test_the_ratio_of_terminal_speeds_is_that_of_two_bodies_with_one_law(mass, ratio, k, power):
    slow = power_law_terminal_velocity(mass, k, power=power)
    fast = power_law_terminal_velocity(mass * ratio, k, power=power)
    assert terminal_velocity_ratio(ratio, power=power) == pytest.approx(fast / slow, rel=1e-9)


def test_four_times_the_mass_falls_twice_as_fast_with_kv2_and_four_times_with_kv():
    # issue 25's example: with F = kv² a body of 4 times the mass has twice the terminal speed
    assert terminal_velocity_ratio(4.0, power=2) == pytest.approx(2.0)
    assert terminal_velocity_ratio(4.0, power=1) == pytest.approx(4.0)
    # F = kv: a 0.20 kg ball with k = 0.050 kg s⁻¹ falls at 0.20 * 9.81 / 0.050 = 39.24 m s⁻¹
    assert power_law_terminal_velocity(0.20, 0.050, power=1) == pytest.approx(39.24)
    # in a liquid the upthrust helps the drag: k v_t = mg - U
    assert power_law_terminal_velocity(0.20, 0.050, power=1, upthrust=0.962) == pytest.approx(20.0)


@pytest.mark.parametrize(("call", "message"), [
    (lambda: power_law_drag(0.0, 3.0, power=2), r"k must be positive \(got k=0.0"),
    (lambda: power_law_drag(0.1, -3.0, power=2), r"speed must not be negative \(got speed=-3.0"),
    (lambda: power_law_drag(0.1, 3.0, power=0), r"power must be positive \(got power=0"),
    (lambda: power_law_constant(5.0, 0.0, power=1), r"speed must be positive \(got speed=0.0"),
    (lambda: power_law_constant(-5.0, 2.0, power=1), r"drag must be positive \(got drag=-5.0"),
    (lambda: power_law_terminal_velocity(0.2, 0.05, power=1, upthrust=5.0), "upthrust must be less than the weight"),
    (lambda: power_law_terminal_velocity(0.2, 0.05, power=-1), r"power must be positive \(got power=-1"),
    (lambda: terminal_velocity_ratio(0.0, power=2), r"mass_ratio must be positive \(got mass_ratio=0.0"),
])
def test_a_drag_law_refuses_impossible_input_naming_the_argument(call, message):
    with pytest.raises(ValueError, match=message):
        call()


def test_stokes_law_is_a_kv_law_with_k_6_pi_eta_r():
    # a 2.0 mm ball in a liquid with eta = 1.4 Pa s: k = 6 pi 1.4 2.0e-3 = 0.0528 kg s^-1
    assert stokes_constant(1.4, 2.0e-3) == pytest.approx(6 * np.pi * 1.4 * 2.0e-3)
    assert sphere_volume(2.0e-3) == pytest.approx(4 / 3 * np.pi * 8.0e-9)
    with pytest.raises(ValueError, match=r"viscosity must be positive \(got viscosity=0.0 Pa s"):
        stokes_constant(0.0, 1e-3)
    with pytest.raises(ValueError, match=r"radius must be positive \(got radius=-0.001 m"):
        sphere_volume(-1e-3)
