"""A momentum-time graph made of straight lines (Notes, "Reading a momentum-time graph").

The gradient of a momentum-time graph is the resultant force, F = Δp / Δt, so a graph of
straight segments describes a body acted on by a constant resultant force in each segment.
"""

from typing import NamedTuple

import numpy as np

from . import _checks as check


class Segment(NamedTuple):
    """One straight piece of the graph: from (t0, p0) to (t1, p1), with force = gradient.

    t0, t1 in s; p0, p1 in kg m s^-1; force in N (the resultant force, signed).
    """

    t0: float
    t1: float
    p0: float
    p1: float
    force: float


class MomentumHistory:
    """Piecewise-linear momentum p(t) through the points (times[i], momenta[i]).

    times: s, strictly increasing, at least two; momenta: kg m s^-1, signed, the same
    length. The history is defined for times[0] <= t <= times[-1].
    Raises ValueError for fewer than two points, mismatched lengths, times that are not
    strictly increasing, or a value that is not finite.
    """

    def __init__(self, times, momenta):
        times = check.sequence("times", times, unit="s", minimum_length=2)
        momenta = check.sequence("momenta", momenta, unit="kg m s^-1", minimum_length=2)
        check.same_length(times=times, momenta=momenta)
        check.strictly_increasing("times", times, unit="s")
        times.setflags(write=False)
        momenta.setflags(write=False)
        self._times = times
        self._momenta = momenta
        forces = np.diff(momenta) / np.diff(times)
        forces.setflags(write=False)
        self._forces = forces

    def __repr__(self) -> str:
        points = ", ".join(f"({t:g}, {p:g})" for t, p in zip(self._times, self._momenta,
                                                           strict=True))
        return f"MomentumHistory through {points}"

    @property
    def times(self) -> np.ndarray:
        """The corner times, s (read-only array)."""
        return self._times

    @property
    def momenta(self) -> np.ndarray:
        """The momenta at the corner times, kg m s^-1 (read-only array)."""
        return self._momenta

    @property
    def segment_forces(self) -> np.ndarray:
        """Resultant force in each segment = gradient Δp/Δt, N (one per segment)."""
        return self._forces

    @property
    def segments(self) -> list[Segment]:
        """The straight pieces in time order, each with its force (gradient), N."""
        t, p, f = self._times, self._momenta, self._forces
        return [Segment(float(t[i]), float(t[i + 1]), float(p[i]), float(p[i + 1]), float(f[i]))
                for i in range(f.size)]

    def _checked_time(self, t):
        t = check.number("t", t, unit="s")
        start, end = self._times[0], self._times[-1]
        return check.require("t", t, (t >= start) & (t <= end),
                             f"must be within the history, {start:g} s to {end:g} s", unit="s")

    def momentum_at(self, t):
        """Momentum p(t), kg m s^-1, by straight lines between the corners.

        t: s (scalar or array) within the history. Raises ValueError outside it.
        """
        momenta = np.interp(self._checked_time(t), self._times, self._momenta)
        return float(momenta) if np.ndim(momenta) == 0 else momenta

    def force_at(self, t):
        """Resultant force at time t, N: the gradient of the segment containing t.

        At a corner the force of the segment that starts there is returned (the force
        after the change), and at the last time that of the last segment.
        t: s (scalar or array) within the history. Raises ValueError outside it.
        """
        t = self._checked_time(t)
        index = np.clip(np.searchsorted(self._times, t, side="right") - 1, 0,
                        self._forces.size - 1)
        forces = self._forces[index]
        return float(forces) if np.ndim(forces) == 0 else forces

    def velocity_at(self, t, mass):
        """Velocity v = p / m at time t, m s^-1.

        t: s (scalar or array) within the history; mass: kg (> 0).
        Raises ValueError for a mass <= 0 or a time outside the history.
        """
        mass = check.positive("mass", mass, unit="kg")
        return self.momentum_at(t) / mass

    def segment_accelerations(self, mass) -> np.ndarray:
        """Acceleration in each segment, a = F / m, m s^-2. mass: kg (> 0)."""
        return self._forces / check.positive("mass", mass, unit="kg")


def area_under_force_time(times, forces) -> float:
    """Impulse = area under a force-time graph of straight lines through (times[i], forces[i]).

    The trapezium rule, exact for straight lines: Σ ½ (F_i + F_i+1)(t_i+1 - t_i), N s.
    times: s, strictly increasing, at least two; forces: N, signed, the same length.
    Raises ValueError for fewer than two points, mismatched lengths, times that are not
    strictly increasing, or a value that is not finite.
    """
    times = check.sequence("times", times, unit="s", minimum_length=2)
    forces = check.sequence("forces", forces, unit="N", minimum_length=2)
    check.same_length(times=times, forces=forces)
    check.strictly_increasing("times", times, unit="s")
    return float(np.sum((forces[1:] + forces[:-1]) / 2 * np.diff(times)))
