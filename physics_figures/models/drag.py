"""Falling and rising with air resistance (Notes, "Friction, drag and terminal velocity").

The notes treat drag qualitatively: it opposes the motion and grows with speed. To draw
the graphs these models use QUADRATIC drag, D = k v², with a drag constant k in kg m^-1
(a good model for a skydiver or a ball in air). With weight m g (and upthrust U in a
fluid) the terminal velocity is reached when k v_t² = m g - U, and

    m dv/dt = m g - U - k v²   (falling, down positive),

which has closed-form solutions (tanh, coth, tan) used here. The one exception is the
few seconds while a parachute opens: its drag constant grows with time, so that stretch is
integrated numerically (classic fixed-step Runge-Kutta, open_canopy), and the closed forms
are the tests of that integrator.
"""

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import ClassVar

import numpy as np

from ..constants import G_EARTH
from . import _checks as check

#: "Terminal velocity reached" means within this fraction of it (points C and E).
WITHIN_TERMINAL = 0.01


def _scalar_or_array(values):
    return float(values) if np.ndim(values) == 0 else values


def _read_only(values) -> np.ndarray:
    values = np.asarray(values, dtype=float)
    values.setflags(write=False)
    return values


def drag_force(k, speed):
    """Quadratic drag D = k v².

    k: drag constant, kg m^-1 (> 0); speed: m s^-1 (>= 0; scalar or array).
    Returns D in N, opposite to the velocity. Raises ValueError for k <= 0, a negative
    speed or a value that is not finite.
    """
    k = check.positive("k", k, unit="kg m^-1")
    return k * check.non_negative("speed", speed, unit="m s^-1") ** 2


def _net_downward_force(mass, g, upthrust):
    mass = check.positive("mass", mass, unit="kg")
    g = check.positive("g", g, unit="m s^-2")
    upthrust = check.non_negative("upthrust", upthrust, unit="N")
    weight = mass * g
    if upthrust >= weight:
        check.fail("upthrust", upthrust,
                   f"must be less than the weight m g = {weight:g} N, or the body never "
                   "falls to a terminal velocity", unit="N")
    return weight - upthrust


def terminal_velocity(mass, k, *, g=G_EARTH, upthrust=0.0):
    """Terminal velocity for quadratic drag: weight = drag + upthrust, v_t = sqrt((m g - U) / k).

    mass: kg (> 0); k: drag constant, kg m^-1 (> 0); g: m s^-2 (> 0); upthrust: N
    (>= 0 and less than the weight). Returns v_t in m s^-1.
    Raises ValueError for a mass, k or g <= 0, an upthrust that is negative or not less
    than the weight, or a value that is not finite.
    """
    net = _net_downward_force(mass, g, upthrust)
    return float(np.sqrt(net / check.positive("k", k, unit="kg m^-1")))


def drag_constant_for_terminal_velocity(mass, terminal_velocity, *, g=G_EARTH, upthrust=0.0):
    """Drag constant that gives a terminal velocity: k = (m g - U) / v_t².

    mass: kg (> 0); terminal_velocity: m s^-1 (> 0); g: m s^-2 (> 0); upthrust: N
    (>= 0 and less than the weight). Returns k in kg m^-1.
    Raises ValueError for a mass, terminal velocity or g <= 0, an upthrust that is
    negative or not less than the weight, or a value that is not finite.
    """
    net = _net_downward_force(mass, g, upthrust)
    v_t = check.positive("terminal_velocity", terminal_velocity, unit="m s^-1")
    return net / v_t**2


def velocity_from_rest(t, terminal_velocity, *, g=G_EARTH):
    """Velocity of a body dropped from rest with quadratic drag: v = v_t tanh(g t / v_t).

    Solves dv/dt = g - (g / v_t²) v² with v(0) = 0: the gradient starts at g and v rises
    towards v_t. t: s (>= 0; scalar or array); terminal_velocity: m s^-1 (> 0);
    g: m s^-2 (> 0). Returns v in m s^-1, down positive.
    Raises ValueError for a negative time, v_t or g <= 0, or a value that is not finite.
    """
    t = check.non_negative("t", t, unit="s")
    v_t = check.positive("terminal_velocity", terminal_velocity, unit="m s^-1")
    g = check.positive("g", g, unit="m s^-2")
    return v_t * np.tanh(g * t / v_t)


def velocity_slowing_to_terminal(t, initial_velocity, terminal_velocity, *, g=G_EARTH):
    """Velocity of a body moving down faster than its terminal velocity (parachute open).

    v = v_t coth(g t / v_t + arccoth(v0 / v_t)), which solves dv/dt = g - (g / v_t²) v²
    with v(0) = v0 > v_t: the drag exceeds the weight, so the body slows towards v_t
    (still moving down). t: s since the change (>= 0; scalar or array);
    initial_velocity: m s^-1 (> terminal_velocity); terminal_velocity: m s^-1 (> 0);
    g: m s^-2 (> 0). Returns v in m s^-1, down positive.
    Raises ValueError for a negative time, v_t or g <= 0, v0 not above v_t, or a value
    that is not finite.
    """
    t = check.non_negative("t", t, unit="s")
    v_t = check.positive("terminal_velocity", terminal_velocity, unit="m s^-1")
    g = check.positive("g", g, unit="m s^-2")
    v0 = check.number("initial_velocity", initial_velocity, unit="m s^-1")
    if v0 <= v_t:
        check.fail("initial_velocity", v0,
                   f"must be greater than terminal_velocity={v_t!r} m s^-1 to slow down to it",
                   unit="m s^-1")
    return v_t / np.tanh(g * t / v_t + np.arctanh(v_t / v0))


def time_to_terminal_velocity(terminal_velocity, *, g=G_EARTH, within=WITHIN_TERMINAL):
    """Time for a body falling from rest to come within a fraction of v_t.

    From v = v_t tanh(g t / v_t) = (1 - within) v_t: t = (v_t / g) artanh(1 - within).
    terminal_velocity: m s^-1 (> 0); g: m s^-2 (> 0); within: fraction, 0 < within < 1.
    Returns t in s. Raises ValueError for values outside those ranges.
    """
    v_t = check.positive("terminal_velocity", terminal_velocity, unit="m s^-1")
    g = check.positive("g", g, unit="m s^-2")
    within = _fraction_within(within)
    return float(v_t / g * np.arctanh(1 - within))


def time_to_slow_to_terminal(initial_velocity, terminal_velocity, *, g=G_EARTH,
                             within=WITHIN_TERMINAL):
    """Time for a body moving down at v0 > v_t to slow to within a fraction of v_t.

    From v_t coth(g t / v_t + arccoth(v0 / v_t)) = (1 + within) v_t:
    t = (v_t / g) (arccoth(1 + within) - arccoth(v0 / v_t)), or 0 if v0 is already close.
    initial_velocity: m s^-1 (> v_t); terminal_velocity: m s^-1 (> 0); g: m s^-2 (> 0);
    within: fraction, 0 < within < 1. Returns t in s. Raises ValueError for values
    outside those ranges.
    """
    v_t = check.positive("terminal_velocity", terminal_velocity, unit="m s^-1")
    g = check.positive("g", g, unit="m s^-2")
    within = _fraction_within(within)
    v0 = check.number("initial_velocity", initial_velocity, unit="m s^-1")
    if v0 <= v_t:
        check.fail("initial_velocity", v0,
                   f"must be greater than terminal_velocity={v_t!r} m s^-1 to slow down to it",
                   unit="m s^-1")
    # arccoth(x) = artanh(1 / x)
    return float(max(0.0, v_t / g * (np.arctanh(1 / (1 + within)) - np.arctanh(v_t / v0))))


def _fraction_within(within):
    within = check.number("within", within)
    return check.require("within", within, (within > 0) & (within < 1),
                         "must be between 0 and 1 (exclusive)")


def _log_cosh(x):
    """ln cosh x for x >= 0 without overflow."""
    return x + np.log1p(np.exp(-2 * x)) - np.log(2)


def canopy_drag_constant(time_since_opening, body_drag, canopy_drag, opening_duration):
    """Drag constant while the parachute opens: k = k_body + (k_canopy - k_body) min(1, s / τ)².

    The canopy fills over the opening duration τ: the drag constant grows smoothly (no
    jump) from the body's value at s = 0 to the canopy's at s = τ, and stays there.
    time_since_opening s: s (scalar or array; before the opening, s < 0, it is the
    body's); body_drag, canopy_drag: kg m^-1 (> 0, canopy_drag >= body_drag);
    opening_duration τ: s (> 0). Returns k in kg m^-1.
    Raises ValueError for a drag constant or τ <= 0, a canopy drag below the body's, or
    a value that is not finite.
    """
    s = check.number("time_since_opening", time_since_opening, unit="s")
    k1, k2 = _drag_constants(body_drag, canopy_drag)
    tau = check.positive("opening_duration", opening_duration, unit="s")
    return _canopy_k(s, k1, k2, tau)


def _drag_constants(body_drag, canopy_drag):
    k1 = check.positive("body_drag", body_drag, unit="kg m^-1")
    k2 = check.positive("canopy_drag", canopy_drag, unit="kg m^-1")
    if k2 < k1:
        check.fail("canopy_drag", k2, f"must be at least body_drag={k1!r} kg m^-1 (the "
                   "canopy adds drag)", unit="kg m^-1")
    return k1, k2


def _canopy_k(s, k1, k2, tau):
    """k(s) without checks; scalar s uses plain floats, in the same order as models.js."""
    if np.ndim(s) == 0:
        f = min(1.0, max(0.0, s / tau))
        return k1 + (k2 - k1) * f * f
    f = np.clip(np.asarray(s, dtype=float) / tau, 0.0, 1.0)
    return k1 + (k2 - k1) * f * f


#: Steps of the fixed-step Runge-Kutta integration over the opening duration. The
#: explorer (models.js) takes the same steps, so the two agree to rounding.
OPENING_STEPS = 2000


@dataclass(frozen=True, eq=False)
class CanopyOpening:
    """The fall while the canopy opens, integrated with classic fixed-step RK4.

    Arrays (read-only, OPENING_STEPS + 1 long): time_since_opening s (step i is
    i x step), velocity m s^-1 (down positive), distance m (fallen since the opening),
    acceleration m s^-2 (= g - k(s) v² / m).
    """

    step: float
    time_since_opening: np.ndarray = field(repr=False)
    velocity: np.ndarray = field(repr=False)
    distance: np.ndarray = field(repr=False)
    acceleration: np.ndarray = field(repr=False)


def open_canopy(mass, initial_velocity, *, body_drag, canopy_drag, opening_duration, g=G_EARTH,
                steps=OPENING_STEPS):
    """Integrate m dv/dt = m g - k(s) v² over the opening, s from 0 to τ (down positive).

    k(s) is canopy_drag_constant. Classic fourth-order Runge-Kutta with `steps` equal
    steps of τ / steps, for v and the distance fallen together, in plain floats and in
    the same order of operations as the explorer's JavaScript twin (models.js).
    mass: kg (> 0); initial_velocity: m s^-1 (>= 0, down); body_drag, canopy_drag:
    kg m^-1 (> 0, canopy_drag >= body_drag); opening_duration τ: s (> 0); g: m s^-2
    (> 0); steps: a whole number >= 10. Returns a CanopyOpening.
    Raises ValueError for values outside those ranges.
    """
    m = check.positive("mass", mass, unit="kg")
    v = check.non_negative("initial_velocity", initial_velocity, unit="m s^-1")
    k1, k2 = _drag_constants(body_drag, canopy_drag)
    tau = check.positive("opening_duration", opening_duration, unit="s")
    g = check.positive("g", g, unit="m s^-2")
    _check_samples("steps", steps)
    h = tau / steps

    def rate(s, v):
        f = min(1.0, s / tau)
        k = k1 + (k2 - k1) * f * f
        return g - k * v * v / m

    x = 0.0
    velocity, distance = [v], [x]
    for i in range(steps):
        s = i * h
        a1 = rate(s, v)
        v2 = v + h / 2 * a1
        a2 = rate(s + h / 2, v2)
        v3 = v + h / 2 * a2
        a3 = rate(s + h / 2, v3)
        v4 = v + h * a3
        a4 = rate(s + h, v4)
        x = x + h / 6 * (v + 2 * v2 + 2 * v3 + v4)
        v = v + h / 6 * (a1 + 2 * a2 + 2 * a3 + a4)
        velocity.append(v)
        distance.append(x)
    s = np.arange(steps + 1) * h
    velocity = np.array(velocity)
    return CanopyOpening(
        step=h, time_since_opening=_read_only(s), velocity=_read_only(velocity),
        distance=_read_only(distance),
        acceleration=_read_only(g - _canopy_k(s, k1, k2, tau) * velocity * velocity / m))


@dataclass(frozen=True, eq=False)
class Skydive:
    """A skydiver falling from rest, then opening a parachute (Notes' skydiver, A to E).

    Down is positive. Quadratic drag D = k v², with k chosen so that the freefall and
    parachute terminal velocities are the given ones (k = m g / v_t²). The canopy opens
    over `opening_duration` τ from `parachute_opens_at`: the drag constant grows as
    canopy_drag_constant, from the body's to the canopy's, and the fall over those τ
    seconds is integrated numerically (open_canopy). Before the opening (tanh) and once
    the canopy is fully open (coth) the closed forms hold.

    Arrays (read-only, same length): time s, velocity m s^-1, distance (fallen) m,
    acceleration m s^-2, drag N, resultant_force N (= weight - drag).
    opening: the integration over the opening (a CanopyOpening).
    points: label -> (t in s, v in m s^-1), located from the model by POINT_RULES; B and
    C only if the parachute opens after them.
    point_acceleration, point_drag, point_resultant_force: label -> value at that point
    (at D the deceleration is largest).
    terminal_drag: "C" and "E" -> the drag at exactly that terminal velocity (= the weight);
    the labelled points themselves sit where the velocity is within 1 % of it.
    The methods velocity_at, drag_constant_at, drag_at and acceleration_at give the model at
    any time (between steps of the opening by cubic Hermite interpolation, as models.js).
    """

    mass: float
    g: float
    terminal_velocity_freefall: float
    terminal_velocity_parachute: float
    parachute_opens_at: float
    opening_duration: float
    duration: float
    weight: float
    drag_constant_freefall: float
    drag_constant_parachute: float
    opening: CanopyOpening = field(repr=False)
    time: np.ndarray = field(repr=False)
    velocity: np.ndarray = field(repr=False)
    distance: np.ndarray = field(repr=False)
    acceleration: np.ndarray = field(repr=False)
    drag: np.ndarray = field(repr=False)
    resultant_force: np.ndarray = field(repr=False)
    points: Mapping[str, tuple[float, float]] = field(repr=False)
    point_acceleration: Mapping[str, float] = field(repr=False)
    point_drag: Mapping[str, float] = field(repr=False)
    point_resultant_force: Mapping[str, float] = field(repr=False)
    terminal_drag: Mapping[str, float] = field(repr=False)

    #: How each labelled point is located (for captions and alt text).
    POINT_RULES: ClassVar[Mapping[str, str]] = MappingProxyType({
        "A": "the jump: t = 0, v = 0, so no drag and the acceleration is g",
        "B": "on the rising curve, where the velocity is half the freefall terminal velocity",
        "C": "terminal velocity reached: the velocity is within 1 % of the freefall one",
        "D": "just after the parachute opens, where the deceleration (and the drag) is largest",
        "E": "second terminal velocity reached: the velocity is within 1 % of the parachute one",
    })

    @property
    def parachute_open_at(self) -> float:
        """Time the canopy is fully open, s: parachute_opens_at + opening_duration."""
        return self.parachute_opens_at + self.opening_duration

    @property
    def speed_at_opening(self) -> float:
        """Speed when the parachute starts to open, m s^-1: v_t1 tanh(g t_open / v_t1), the
        speed the canopy has to stop (faster than the speed at D, where the deceleration peaks)."""
        return float(self.opening.velocity[0])

    def drag_constant_at(self, t):
        """Drag constant k at time t (s, scalar or array), kg m^-1."""
        return _scalar_or_array(_canopy_k(np.asarray(t, dtype=float) - self.parachute_opens_at,
                                          self.drag_constant_freefall,
                                          self.drag_constant_parachute, self.opening_duration))

    def velocity_at(self, t):
        """Velocity at time t (s, 0 <= t, scalar or array), m s^-1, down positive."""
        t = check.non_negative("t", t, unit="s")
        t_open, v_t1, v_t2, g = (self.parachute_opens_at, self.terminal_velocity_freefall,
                                 self.terminal_velocity_parachute, self.g)
        s = np.asarray(t, dtype=float) - t_open
        opening = self.opening
        steps = opening.velocity.size - 1
        h = opening.step
        # Hermite interpolation between the steps, from v and dv/dt at both ends
        i = np.clip(np.floor(np.maximum(s, 0.0) / h), 0, steps - 1).astype(int)
        theta = (s - i * h) / h
        v0, v1 = opening.velocity[i], opening.velocity[i + 1]
        a0, a1 = opening.acceleration[i], opening.acceleration[i + 1]
        one_minus = 1 - theta
        during = ((1 + 2 * theta) * one_minus * one_minus * v0
                  + theta * one_minus * one_minus * h * a0
                  + theta * theta * (3 - 2 * theta) * v1
                  + theta * theta * (theta - 1) * h * a1)
        with np.errstate(all="ignore"):  # each branch is only used where it holds
            before = v_t1 * np.tanh(g * np.asarray(t, dtype=float) / v_t1)
            after = v_t2 / np.tanh(g * (s - self.opening_duration) / v_t2
                                   + np.arctanh(v_t2 / opening.velocity[-1]))
        v = np.where(s < 0, before, np.where(s < self.opening_duration, during, after))
        return _scalar_or_array(v)

    def drag_at(self, t):
        """Drag k v² at time t (s), N (up, against the motion)."""
        v = self.velocity_at(t)
        return self.drag_constant_at(t) * v * v

    def acceleration_at(self, t):
        """Acceleration (weight - drag) / m at time t (s), m s^-2, down positive."""
        return (self.weight - self.drag_at(t)) / self.mass


def _check_samples(name, samples):
    if isinstance(samples, bool) or not isinstance(samples, int | np.integer) or samples < 10:
        raise ValueError(f"{name} must be a whole number of at least 10 (got {name}={samples!r})")


def earliest_opening(terminal_velocity_freefall, terminal_velocity_parachute, *, g=G_EARTH):
    """Earliest time a parachute can open and still slow the skydiver to its terminal velocity.

    The speed from rest must first pass (1 + WITHIN_TERMINAL) v_t2, so that the skydiver
    slows down to v_t2 and reaches point E: t = (v_t1 / g) artanh(1.01 v_t2 / v_t1).
    terminal_velocity_freefall v_t1, terminal_velocity_parachute v_t2: m s^-1 (> 0, with
    1.01 v_t2 < v_t1); g: m s^-2 (> 0). Returns t in s; opening must be later than this.
    Raises ValueError for values outside those ranges.
    """
    v_t1 = check.positive("terminal_velocity_freefall", terminal_velocity_freefall,
                          unit="m s^-1")
    v_t2 = check.positive("terminal_velocity_parachute", terminal_velocity_parachute,
                          unit="m s^-1")
    g = check.positive("g", g, unit="m s^-2")
    if v_t2 * (1 + WITHIN_TERMINAL) >= v_t1:
        check.fail("terminal_velocity_parachute", v_t2,
                   f"must be less than terminal_velocity_freefall={v_t1!r} m s^-1 by more "
                   "than 1 % (the parachute adds drag)", unit="m s^-1")
    return float(v_t1 / g * np.arctanh(v_t2 * (1 + WITHIN_TERMINAL) / v_t1))


def _skydive_arguments(mass, terminal_velocity_freefall, terminal_velocity_parachute,
                       parachute_opens_at, opening_duration, duration, g, samples):
    """skydive's arguments checked (its rules), as (mass, g, v_t1, v_t2, t_open, tau, duration)."""
    mass = check.positive("mass", mass, unit="kg")
    g = check.positive("g", g, unit="m s^-2")
    v_t1 = check.positive("terminal_velocity_freefall", terminal_velocity_freefall,
                          unit="m s^-1")
    v_t2 = check.positive("terminal_velocity_parachute", terminal_velocity_parachute,
                          unit="m s^-1")
    if v_t2 >= v_t1:
        check.fail("terminal_velocity_parachute", v_t2,
                   f"must be less than terminal_velocity_freefall={v_t1!r} m s^-1 (the "
                   "parachute adds drag)", unit="m s^-1")
    t_open = check.positive("parachute_opens_at", parachute_opens_at, unit="s")
    tau = check.positive("opening_duration", opening_duration, unit="s")
    duration = check.positive("duration", duration, unit="s")
    if t_open >= duration:
        check.fail("parachute_opens_at", t_open,
                   f"must be before the end of the record, duration={duration!r} s", unit="s")
    _check_samples("samples", samples)
    t_earliest = earliest_opening(v_t1, v_t2, g=g)
    if t_open <= t_earliest:
        check.fail("parachute_opens_at", t_open,
                   f"must be after {t_earliest:.3g} s, when the skydiver first falls faster "
                   f"than the parachute's terminal velocity (+1 %), so that it slows them down",
                   unit="s")
    return mass, g, v_t1, v_t2, t_open, tau, duration


def _time_of_point_e(opening, t_open, t_full, v_full, v_t2, g):
    """E: the first time the velocity is within 1 % of v_t2, during the opening (between two
    steps, linearly) or, usually, on the coth curve after it."""
    v_e = v_t2 * (1 + WITHIN_TERMINAL)
    reached = np.flatnonzero(opening.velocity <= v_e)
    if reached.size:
        j = int(reached[0])
        v_a, v_b = opening.velocity[j - 1], opening.velocity[j]
        t_e = t_open + opening.time_since_opening[j - 1] + (v_a - v_e) / (v_a - v_b) * opening.step
    else:
        t_e = t_full + time_to_slow_to_terminal(v_full, v_t2, g=g)
    return float(t_e)


def _skydive_phases(opening, *, v_t1, v_t2, t_open, t_full, v_full, t_e, duration, g, samples):
    """The record's time, velocity and distance fallen: freefall, the opening, fully open."""
    # Freefall phase, 0 <= t < t_open.
    t_free = np.linspace(0, t_open, samples)[:-1]
    v_free = v_t1 * np.tanh(g * t_free / v_t1)
    x_free = v_t1**2 / g * _log_cosh(g * t_free / v_t1)
    x_open = v_t1**2 / g * float(_log_cosh(g * t_open / v_t1))
    # Opening, t_open <= t < t_full: every tenth step, and the step of largest deceleration.
    peak = int(np.argmin(opening.acceleration))
    kept = np.union1d(np.arange(0, opening.velocity.size - 1, 10), [peak])
    kept = kept[kept < opening.velocity.size - 1]
    t_opening = t_open + opening.time_since_opening[kept]
    v_opening = opening.velocity[kept]
    x_opening = x_open + opening.distance[kept]
    # Fully open, t_full <= t <= duration; extra points while the speed drops.
    t_chute = np.unique(np.concatenate([np.linspace(t_full, duration, samples),
                                        np.linspace(t_full, max(t_e, t_full), samples)]))
    c = np.arctanh(v_t2 / v_full)  # arccoth(v_full / v_t2)
    y = g * (t_chute - t_full) / v_t2 + c
    v_chute = v_t2 / np.tanh(y)
    # ln(sinh y / sinh c), written so that it cannot overflow
    x_chute = x_open + opening.distance[-1] + v_t2**2 / g * (
        (y - c) + np.log1p(-np.exp(-2 * y)) - np.log1p(-np.exp(-2 * c)))
    return (np.concatenate([t_free, t_opening, t_chute]),
            np.concatenate([v_free, v_opening, v_chute]),
            np.concatenate([x_free, x_opening, x_chute]))


def _skydive_points(opening, *, v_t1, t_open, t_e, v_e, g):
    """The labelled points A-E of the velocity-time graph, as (t, v)."""
    peak = int(np.argmin(opening.acceleration))
    t_b = float(v_t1 / g * np.arctanh(0.5))
    t_c = time_to_terminal_velocity(v_t1, g=g)
    points = {"A": (0.0, 0.0)}
    if t_b < t_open:
        points["B"] = (t_b, v_t1 / 2)
    if t_c <= t_open:
        points["C"] = (t_c, v_t1 * (1 - WITHIN_TERMINAL))
    points["D"] = (t_open + float(opening.time_since_opening[peak]), float(opening.velocity[peak]))
    points["E"] = (t_e, v_e)
    return points


def skydive(mass, *, terminal_velocity_freefall, terminal_velocity_parachute,
            parachute_opens_at, opening_duration, duration, g=G_EARTH, samples=801):
    """Model a skydive: freefall from rest, then a parachute that opens over a time τ.

    Freefall: v = v_t1 tanh(g t / v_t1). From t_open the drag constant grows as
    canopy_drag_constant and open_canopy integrates the motion over τ. Once the canopy is
    fully open, at t_full = t_open + τ with speed v_full > v_t2:
    v = v_t2 coth(g (t - t_full) / v_t2 + arccoth(v_full / v_t2)). Distance fallen from
    x = (v_t² / g) ln cosh(g t / v_t), the integration, and the coth counterpart.

    mass: kg (> 0); terminal_velocity_freefall, terminal_velocity_parachute: m s^-1
    (> 0, parachute one lower); parachute_opens_at: s, once the skydiver is faster than
    1.01 x the parachute's terminal velocity (earliest_opening), before the end;
    opening_duration τ: s (> 0); duration: s, the length of the record, long enough to
    reach the second terminal velocity (point E); g: m s^-2 (> 0); samples: points in
    each closed-form phase (>= 10; the opening adds every tenth integration step).
    Returns a Skydive. Raises ValueError for any of those rules broken, naming the argument.
    """
    mass, g, v_t1, v_t2, t_open, tau, duration = _skydive_arguments(
        mass, terminal_velocity_freefall, terminal_velocity_parachute, parachute_opens_at,
        opening_duration, duration, g, samples)
    weight = mass * g
    k1, k2 = weight / v_t1**2, weight / v_t2**2
    v_open = v_t1 * math.tanh(g * t_open / v_t1)
    opening = open_canopy(mass, v_open, body_drag=k1, canopy_drag=k2, opening_duration=tau, g=g)
    t_full, v_full = t_open + tau, float(opening.velocity[-1])
    v_e = v_t2 * (1 + WITHIN_TERMINAL)
    t_e = _time_of_point_e(opening, t_open, t_full, v_full, v_t2, g)
    if t_e > duration:
        check.fail("duration", duration,
                   f"must reach point E, the parachute terminal velocity ({t_e:.3g} s)",
                   unit="s")
    time, velocity, distance = _skydive_phases(
        opening, v_t1=v_t1, v_t2=v_t2, t_open=t_open, t_full=t_full, v_full=v_full, t_e=t_e,
        duration=duration, g=g, samples=samples)
    k = _canopy_k(time - t_open, k1, k2, tau)
    drag = k * velocity * velocity
    resultant = weight - drag
    points = _skydive_points(opening, v_t1=v_t1, t_open=t_open, t_e=t_e, v_e=v_e, g=g)
    point_drag = {label: float(_canopy_k(t - t_open, k1, k2, tau)) * v * v
                  for label, (t, v) in points.items()}
    return Skydive(
        mass=mass, g=g, terminal_velocity_freefall=v_t1, terminal_velocity_parachute=v_t2,
        parachute_opens_at=t_open, opening_duration=tau, duration=duration, weight=weight,
        drag_constant_freefall=k1, drag_constant_parachute=k2, opening=opening,
        time=_read_only(time), velocity=_read_only(velocity),
        distance=_read_only(distance),
        acceleration=_read_only(resultant / mass), drag=_read_only(drag),
        resultant_force=_read_only(resultant), points=MappingProxyType(points),
        point_acceleration=MappingProxyType(
            {label: (weight - d) / mass for label, d in point_drag.items()}),
        point_drag=MappingProxyType(point_drag),
        point_resultant_force=MappingProxyType(
            {label: weight - d for label, d in point_drag.items()}),
        terminal_drag=MappingProxyType(
            {"C": float(drag_force(k1, v_t1)), "E": float(drag_force(k2, v_t2))}),
    )


@dataclass(frozen=True, eq=False)
class ThrowUp:
    """A ball thrown straight up and caught at the launch height (up positive).

    Arrays (read-only, same length): time s, velocity m s^-1, height m (above the
    launch point), acceleration m s^-2. Scalars: time_to_top s, max_height m,
    return_speed m s^-1 (speed when back at the launch height), time_of_flight s.
    terminal_velocity is None for a throw in a vacuum (no drag).
    """

    launch_speed: float
    terminal_velocity: float | None
    g: float
    time: np.ndarray = field(repr=False)
    velocity: np.ndarray = field(repr=False)
    height: np.ndarray = field(repr=False)
    acceleration: np.ndarray = field(repr=False)
    time_to_top: float
    max_height: float
    return_speed: float
    time_of_flight: float


def thrown_upwards(launch_speed, *, terminal_velocity=None, g=G_EARTH, samples=401):
    """A ball thrown straight up, with quadratic drag (or none), until it comes back down.

    Up positive; acceleration a = -g - (g / v_t²) v |v| (drag opposes the velocity).
    With drag, and b = atan(u / v_t):
      going up    v = v_t tan(b - g t / v_t),  h = (v_t² / g) ln(cos(b - g t / v_t) / cos b),
      top         t_top = (v_t / g) b,         h_max = (v_t² / 2g) ln(1 + u² / v_t²),
      coming down v = -v_t tanh(g (t - t_top) / v_t), h = h_max - (v_t² / g) ln cosh(...),
      back at the start after (v_t / g) asinh(u / v_t) more, at speed u v_t / sqrt(u² + v_t²).
    In a vacuum: v = u - g t, h = u t - g t² / 2, t_top = u / g, h_max = u² / 2g.

    launch_speed: m s^-1 (> 0); terminal_velocity: m s^-1 (> 0), or None for no drag;
    g: m s^-2 (> 0); samples: points on each of the way up and the way down (>= 10).
    Returns a ThrowUp. Raises ValueError for values outside those ranges.
    """
    u = check.positive("launch_speed", launch_speed, unit="m s^-1")
    g = check.positive("g", g, unit="m s^-2")
    _check_samples("samples", samples)

    if terminal_velocity is None:
        t_top = u / g
        time = np.linspace(0, 2 * t_top, 2 * samples - 1)
        velocity = u - g * time
        height = u * time - g * time**2 / 2
        acceleration = np.full_like(time, -g)
        return ThrowUp(u, None, g, _read_only(time), _read_only(velocity), _read_only(height),
                       _read_only(acceleration), t_top, u**2 / (2 * g), u, 2 * t_top)

    v_t = check.positive("terminal_velocity", terminal_velocity, unit="m s^-1")
    b = np.arctan(u / v_t)
    t_top = v_t / g * b
    h_max = v_t**2 / (2 * g) * np.log1p((u / v_t) ** 2)
    t_down = v_t / g * np.arcsinh(u / v_t)

    t_up = np.linspace(0, t_top, samples)
    v_up = v_t * np.tan(b - g * t_up / v_t)
    v_up[-1] = 0.0  # at rest at the top exactly (rounding leaves ~1e-16 m s^-1)
    h_up = v_t**2 / g * np.log(np.cos(b - g * t_up / v_t) / np.cos(b))
    tau = np.linspace(0, t_down, samples)[1:]  # the top is already in the way up
    v_down = -v_t * np.tanh(g * tau / v_t)
    h_down = h_max - v_t**2 / g * _log_cosh(g * tau / v_t)
    h_down[-1] = 0.0  # back at the launch height exactly (rounding leaves ~1e-15 m)

    velocity = np.concatenate([v_up, v_down])
    return ThrowUp(
        u, v_t, g,
        time=_read_only(np.concatenate([t_up, t_top + tau])),
        velocity=_read_only(velocity),
        height=_read_only(np.concatenate([h_up, h_down])),
        acceleration=_read_only(-g - g / v_t**2 * velocity * np.abs(velocity)),
        time_to_top=float(t_top), max_height=float(h_max),
        return_speed=float(u * v_t / np.hypot(u, v_t)), time_of_flight=float(t_top + t_down),
    )


def falling_acceleration(mass, drag, *, g=G_EARTH, upthrust=0.0):
    """Acceleration of a body moving DOWN with a drag D (up) and an upthrust U (up):
    a = (m g - U - D) / m, down positive (Newton's second law with the resultant force).

    Negative when D + U exceeds the weight: the body slows down while it still falls
    (a parachute just opened). mass: kg (> 0); drag: N (>= 0); g: m s^-2 (> 0);
    upthrust: N (>= 0). Returns a in m s^-2. Raises ValueError for a mass or g <= 0,
    a negative drag or upthrust, or a value that is not finite.
    """
    mass = check.positive("mass", mass, unit="kg")
    drag = check.non_negative("drag", drag, unit="N")
    upthrust = check.non_negative("upthrust", upthrust, unit="N")
    g = check.positive("g", g, unit="m s^-2")
    return float((mass * g - upthrust - drag) / mass)


# ---------------------------------------------------------------- a drag law given in a question

def _drag_power(power):
    """The power n of a drag law F = k vⁿ: papers give n = 1 (F = kv, 6 pi eta r v) or n = 2 (F = kv²,
    (1/2) C rho A v²); any positive n is accepted."""
    return check.positive("power", power)


def power_law_drag(k, speed, *, power):
    """A drag law as a question gives it: D = k vⁿ.

    k: the law's constant, N (m s^-1)^-n (> 0: kg s^-1 for n = 1, kg m^-1 for n = 2);
    speed: m s^-1 (>= 0; scalar or array); power n: > 0. Returns D in N, against the velocity.
    Raises ValueError for k or n <= 0, a negative speed, or a value that is not finite.
    """
    k = check.positive("k", k, unit="N (m s^-1)^-n")
    n = _drag_power(power)
    return k * check.non_negative("speed", speed, unit="m s^-1") ** n


def power_law_constant(drag, speed, *, power):
    """The constant of a drag law D = k vⁿ from one drag and its speed: k = D / vⁿ.

    At a terminal speed the drag is the weight (less any upthrust), so k = (m g - U) / v_tⁿ.
    drag: N (> 0); speed: m s^-1 (> 0); power n: > 0. Returns k in N (m s^-1)^-n.
    Raises ValueError for a drag, speed or n <= 0, or a value that is not finite.
    """
    drag = check.positive("drag", drag, unit="N")
    speed = check.positive("speed", speed, unit="m s^-1")
    return drag / speed ** _drag_power(power)


def power_law_terminal_velocity(mass, k, *, power, g=G_EARTH, upthrust=0.0):
    """Terminal velocity for a drag law D = k vⁿ: k v_tⁿ = m g - U, so v_t = ((m g - U) / k)^(1/n).

    mass: kg (> 0); k: N (m s^-1)^-n (> 0); power n: > 0; g: m s^-2 (> 0); upthrust: N
    (>= 0 and less than the weight). Returns v_t in m s^-1. With n = 2 it is terminal_velocity.
    Raises ValueError for a mass, k, n or g <= 0, an upthrust that is negative or not less
    than the weight, or a value that is not finite.
    """
    net = _net_downward_force(mass, g, upthrust)
    k = check.positive("k", k, unit="N (m s^-1)^-n")
    return float((net / k) ** (1 / _drag_power(power)))


def terminal_velocity_ratio(mass_ratio, *, power):
    """How terminal speeds compare for bodies of one size and shape (one k, no upthrust):
    k v_tⁿ = m g, so v_t ∝ m^(1/n) and v_B / v_A = (m_B / m_A)^(1/n).

    With F = kv² a body of four times the mass falls twice as fast; with F = kv, four times.
    mass_ratio: m_B / m_A (> 0); power n: > 0. Returns v_B / v_A (no unit).
    Raises ValueError for a ratio or n <= 0, or a value that is not finite.
    """
    ratio = check.positive("mass_ratio", mass_ratio)
    return float(ratio ** (1 / _drag_power(power)))


def sphere_volume(radius):
    """Volume of a sphere, V = (4/3) pi r³ (for the upthrust on a ball in a liquid).

    radius: m (> 0; scalar or array). Returns V in m^3. Raises ValueError for a radius
    <= 0 or not finite.
    """
    return 4 / 3 * np.pi * check.positive("radius", radius, unit="m") ** 3


def stokes_constant(viscosity, radius):
    """The constant of Stokes' law F = 6 pi eta r v, as a law F = k v: k = 6 pi eta r.

    A small sphere moving slowly through a viscous fluid (papers give the law; the notes need
    no coefficient of viscosity). viscosity eta: Pa s = N s m^-2 (> 0); radius r: m (> 0).
    Returns k in kg s^-1 (= N s m^-1), for power_law_drag and power_law_terminal_velocity
    with power=1. Raises ValueError for a value <= 0 or not finite.
    """
    viscosity = check.positive("viscosity", viscosity, unit="Pa s")
    return 6 * np.pi * viscosity * check.positive("radius", radius, unit="m")
