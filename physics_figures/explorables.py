"""What the browser explorables need from the models: their starting data and rules.

The explorables (book/_ext/explorables) run in the reader's browser, from a small
JavaScript port of the models (static/explorables/models.js: the closed forms, and the
same fixed-step Runge-Kutta as models.drag.open_canopy while a parachute opens). This module

* serialises each explorable's starting situation from ``scenarios`` into plain data
  (``explorable_data``), which the ``explorable`` directive writes into the page as JSON;
* holds the Python twins of the few rules the explorables add on top of ``models``
  (``collision_lab``, ``earliest_parachute_opening``, ``UNREALISTIC_DECELERATION_IN_G``,
  ``opening_jolt``),
  so that the tests can check the JavaScript against Python on many random inputs.

SI units throughout; velocities are signed, positive to the right (collisions) or
downwards (the skydiver).
"""

from __future__ import annotations

from dataclasses import dataclass

from . import scenarios
from .constants import G_EARTH
from .models import (
    WITHIN_TERMINAL,
    collision_with_energy_kept,
    earliest_opening,
    elastic_collision,
    explosion_from_rest,
    percentage_kinetic_energy_lost,
    relative_speed,
    stick_together,
    terminal_velocity,
    total_kinetic_energy,
    total_momentum,
)
from .models import _checks as check
from .notation import format_number

#: The explorables a page can show, by the name the directive takes.
EXPLORABLES = ("skydiver", "collision-lab", "momentum-triangle", "momentum-time-reader")

#: What each explorable models, in a sentence or two of the notes' physics: shown above the
#: explorable and linked to it by aria-describedby (book/_ext/explorables), so that a reader who
#: cannot see the graphs knows what the sliders change before moving them.
ABOUT = {
    "skydiver": (
        "A skydiver falls from rest. Her weight stays the same, but the drag grows as her speed grows "
        "(here as k v²), so the resultant force and the acceleration fall until the drag equals the "
        "weight: terminal velocity. When the parachute opens the drag is larger than the weight, so the "
        "resultant force is upwards and she slows, still moving down, to a lower terminal velocity."
    ),
    "collision-lab": (
        "Two trolleys, A and B, collide on a straight track, or are pushed apart from rest. The total "
        "momentum is the same before and after every interaction; the total kinetic energy is kept only "
        "in an elastic collision, falls in an inelastic one and rises in an explosion."
    ),
    "momentum-triangle": (
        "Puck P hits puck Q, which is at rest. Momentum is conserved along P's original line and at "
        "right angles to it, so the momenta of P and Q after, drawn tip to tail, add up to P's "
        "momentum before."
    ),
    "momentum-time-reader": (
        "A car's momentum\u2013time graph, made of straight lines. The gradient of the graph is the "
        "resultant force on the car, and its momentum divided by its mass is its velocity."
    ),
}

#: Kinds of interaction in the collision lab.
COLLISION_KINDS = ("elastic", "stick", "explosion", "loss")

#: Why the collision lab refuses a set-up; {placeholders} are filled with the numbers to 3 s.f.
#: (physics_figures.notation here, notation.js in the browser).
REFUSALS = {
    "never-meet": (
        "They never meet: A starts on the left, so it must move to the right faster than B "
        "(u_A > u_B) to catch it up. Here u_A = {u1} m/s and u_B = {u2} m/s."
    ),
    "energy-created": (
        "Not possible: a collision cannot create kinetic energy, so the total after cannot be "
        "more than before. Only an explosion, with energy from a store such as a spring, "
        "can give out more kinetic energy than went in."
    ),
    "more-than-sticking": (
        "Not possible: the momentum must still be {momentum} kg m/s afterwards, and that "
        "carries kinetic energy. Even sticking together loses only {most}% here."
    ),
    "explosion-wrong-way": (
        "Not possible: A is on the left of B, so when they are pushed apart A moves to the "
        "left (a negative velocity) and B to the right."
    ),
}


@dataclass(frozen=True)
class CollisionLab:
    """One set-up of the collision lab and its outcome (A on the left, B on the right).

    Velocities m s^-1 (signed, right positive), momenta kg m s^-1, energies J.
    after is None (and refusal names the rule, reason explains it) when the set-up is
    impossible; percent_lost and most_percent_lost are None for an explosion from rest.
    """

    kind: str
    masses: tuple[float, float]
    before: tuple[float, float]
    after: tuple[float, float] | None
    refusal: str | None
    reason: str | None
    momentum_before: float
    kinetic_energy_before: float
    momentum_after: float | None
    kinetic_energy_after: float | None
    approach_speed: float
    separation_speed: float | None
    percent_lost: float | None
    most_percent_lost: float | None


def _percent_lost(before, after):
    """Percentage of the kinetic energy lost; 0 when there was none to lose (all at rest)."""
    return percentage_kinetic_energy_lost(before, after) if before > 0 else 0.0


def _most_percent_lost(m1, u1, m2, u2):
    """Percentage of kinetic energy lost by sticking together: the most any collision loses.
    Never below 0: when A barely catches B, rounding can make the two energies' difference a
    hair negative (about -1e-14 %), and a collision losing 0 % would then be refused."""
    v = stick_together(m1, u1, m2, u2)
    return max(0.0, _percent_lost(total_kinetic_energy((m1, m2), (u1, u2)),
                                  total_kinetic_energy((m1, m2), (v, v))))


def _collision_lab_options(kind, u1, u2, velocity_a_after, percent_lost):
    """collision_lab's options checked: velocity_a_after only (and always) for an explosion
    from rest, percent_lost only (and always) for kind="loss". Returns both, checked."""
    if kind == "explosion":
        if u1 != 0 or u2 != 0:
            raise ValueError(f"u1 and u2 must be 0 for an explosion from rest (got u1={u1!r}, u2={u2!r})")
        if velocity_a_after is None:
            raise ValueError("velocity_a_after is needed for an explosion (got velocity_a_after=None)")
        velocity_a_after = check.number("velocity_a_after", velocity_a_after, unit="m s^-1")
    elif velocity_a_after is not None:
        raise ValueError(f"velocity_a_after is only for kind='explosion' (got kind={kind!r})")
    if kind == "loss":
        if percent_lost is None:
            raise ValueError("percent_lost is needed for kind='loss' (got percent_lost=None)")
        percent_lost = check.number("percent_lost", percent_lost, unit="%")
    elif percent_lost is not None:
        raise ValueError(f"percent_lost is only for kind='loss' (got kind={kind!r})")
    return velocity_a_after, percent_lost


def collision_lab(kind, *, m1, m2, u1=0.0, u2=0.0, velocity_a_after=None, percent_lost=None):
    """The collision lab: body A (m1, u1) on the left, body B (m2, u2) on the right.

    kind: "elastic" (kinetic energy kept), "stick" (stick together), "loss" (a chosen
    percent_lost of the total kinetic energy, via collision_with_energy_kept), or
    "explosion" (from rest: u1 = u2 = 0, A moves off at velocity_a_after).
    A collision needs u1 > u2 (A catches B); percent_lost must be between 0 and the
    loss when sticking together; in an explosion A must move left (velocity_a_after <= 0).
    A set-up that breaks one of those physical rules is returned refused (after=None,
    with the reason), not raised: the reader is meant to try it.

    m1, m2: kg (> 0); u1, u2, velocity_a_after: m s^-1, signed; percent_lost: %.
    Returns a CollisionLab. Raises ValueError for an unknown kind, a mass <= 0, a value
    that is not finite, or a missing or misplaced option.
    """
    if kind not in COLLISION_KINDS:
        raise ValueError(f"kind must be one of {', '.join(COLLISION_KINDS)} (got kind={kind!r})")
    m1 = check.positive("m1", m1, unit="kg")
    m2 = check.positive("m2", m2, unit="kg")
    u1 = check.number("u1", u1, unit="m s^-1")
    u2 = check.number("u2", u2, unit="m s^-1")
    velocity_a_after, percent_lost = _collision_lab_options(kind, u1, u2, velocity_a_after,
                                                            percent_lost)

    masses = (m1, m2)
    p_before = total_momentum(masses, (u1, u2))
    e_before = total_kinetic_energy(masses, (u1, u2))
    most = None if kind == "explosion" else _most_percent_lost(m1, u1, m2, u2)

    def refused(code, **numbers):
        return CollisionLab(
            kind, masses, (u1, u2), None, code,
            REFUSALS[code].format(**{name: format_number(x, 3) for name, x in numbers.items()}), p_before,
            e_before, None, None, relative_speed(u1, u2), None, None, most)

    if kind == "explosion":
        if velocity_a_after > 0:
            return refused("explosion-wrong-way")
        after = (velocity_a_after, explosion_from_rest(m1, m2, velocity_a_after))
    else:
        if u1 <= u2:
            return refused("never-meet", u1=u1, u2=u2)
        if kind == "elastic":
            after = elastic_collision(m1, u1, m2, u2)
        elif kind == "stick":
            v = stick_together(m1, u1, m2, u2)
            after = (v, v)
        else:
            if percent_lost < 0:
                return refused("energy-created")
            # a hair of tolerance so that typing the sticking-together figure is allowed
            if percent_lost > most * (1 + 1e-9):
                return refused("more-than-sticking", momentum=p_before, most=most)
            # the loss as a fraction of what can be lost (the kinetic energy in the
            # centre-of-mass frame, e_before * most / 100)
            kept = max(0.0, 1 - percent_lost / most) if most > 0 else 1.0
            after = collision_with_energy_kept(m1, u1, m2, u2, fraction_of_ke_kept_in_cm_frame=kept)
    after = (float(after[0]), float(after[1]))
    e_after = total_kinetic_energy(masses, after)
    return CollisionLab(
        kind, masses, (u1, u2), after, None, None, p_before, e_before,
        total_momentum(masses, after), e_after, relative_speed(u1, u2),
        relative_speed(*after),
        None if kind == "explosion" else _percent_lost(e_before, e_after),
        most,
    )


def earliest_parachute_opening(mass, body_drag, parachute_drag, *, g=G_EARTH):
    """Earliest time the explorable lets the parachute open.

    The skydiver must be falling faster than 1.01 x the parachute's terminal velocity,
    so that the parachute slows them down to it (models.earliest_opening):
    t = (v_t1 / g) artanh(1.01 v_t2 / v_t1) with v_t = sqrt(m g / k). It may be before C.
    mass: kg (> 0); body_drag, parachute_drag: drag constants k, kg m^-1 (> 0, the
    parachute's larger). Returns t in s.
    """
    return earliest_opening(terminal_velocity(mass, body_drag, g=g),
                            terminal_velocity(mass, parachute_drag, g=g), g=g)


#: Above this peak deceleration (in g) the skydiver explorer says why the number is
#: unrealistic: a canopy that opens that hard would injure the skydiver.
UNREALISTIC_DECELERATION_IN_G = 15.0
#: What the skydiver explorer says above that limit; {placeholders} are filled with the numbers
#: of ``opening_jolt`` to 3 s.f. (physics_figures.notation here, notation.js in the browser). The
#: speed is the one the canopy opens at, not the speed at D (issue 25).
UNREALISTIC_OPENING = (
    "Unrealistic: {in_g} g would injure the skydiver. A canopy that opens at {speed_at_opening} m s⁻¹ "
    "and fills in only {opening_duration} s jerks them to a stop far too hard; real parachutes are "
    "made to open over two or three seconds, which keeps the deceleration to a few g."
)


def opening_jolt(dive):
    """The numbers the skydiver explorer's warning quotes, from a models.Skydive: the largest
    deceleration in g (at D), the speed when the parachute starts to open (m s^-1) and the
    time the canopy takes to fill (s). Keys are UNREALISTIC_OPENING's placeholders."""
    return {"in_g": -dive.point_acceleration["D"] / dive.g, "speed_at_opening": dive.speed_at_opening,
            "opening_duration": dive.opening_duration}


def opening_warning(dive):
    """What the skydiver explorer says about a dive: UNREALISTIC_OPENING filled from opening_jolt
    when the peak deceleration is above UNREALISTIC_DECELERATION_IN_G, else nothing ("")."""
    numbers = opening_jolt(dive)
    if numbers["in_g"] <= UNREALISTIC_DECELERATION_IN_G:
        return ""
    return UNREALISTIC_OPENING.format(**{name: format_number(x, 3) for name, x in numbers.items()})


def explorable_data(name):
    """The starting situation of an explorable, as JSON-ready data from ``scenarios``.

    name: one of EXPLORABLES. Returns a dict of plain numbers and strings.
    Raises ValueError for an unknown name.
    """
    if name == "skydiver":
        dive = scenarios.SKYDIVER
        return {
            "g": dive.g,
            "withinTerminal": WITHIN_TERMINAL,
            "mass": dive.mass,
            "bodyDrag": dive.drag_constant_freefall,
            "parachuteDrag": dive.drag_constant_parachute,
            "parachuteOpensAt": dive.parachute_opens_at,
            "openingDuration": dive.opening_duration,
            "unrealisticDecelerationInG": UNREALISTIC_DECELERATION_IN_G,
            "unrealisticOpening": UNREALISTIC_OPENING,
        }
    if name == "collision-lab":
        # starts on the notes' sticking trolleys; an explosion starts on the spring trolleys
        trolleys, spring = scenarios.STICKING_TROLLEYS, scenarios.SPRING_TROLLEYS
        return {
            "kinds": list(COLLISION_KINDS),
            "refusals": REFUSALS,
            "kind": "stick",
            "m1": trolleys["m1"], "u1": trolleys["u1"], "m2": trolleys["m2"], "u2": trolleys["u2"],
            # the explosion starts as the notes' spring trolleys seen from the other side:
            # A (0.20 kg), on the left, moves off to the left; B is the 0.30 kg trolley
            "explosionM1": spring["m2"], "explosionM2": spring["m1"],
            "velocityAAfter": explosion_from_rest(spring["m1"], spring["m2"], spring["v1"]),
        }
    if name == "momentum-triangle":
        pucks = scenarios.PUCKS_PQ
        return {
            "momentumBefore": pucks.p_before,
            "momentumKnown": pucks.p_known,
            "angleKnown": pucks.angle_known_deg,
        }
    if name == "momentum-time-reader":
        return {
            "mass": scenarios.CAR_MASS,
            "times": [float(t) for t in scenarios.CAR_HISTORY.times],
            "momenta": [float(p) for p in scenarios.CAR_HISTORY.momenta],
        }
    raise ValueError(f"name must be one of {', '.join(EXPLORABLES)} (got name={name!r})")
