"""Pure numpy physics for the Dynamics topic (never imports matplotlib).

Every function documents its equation and SI units and raises ValueError naming the
argument, its value and the rule it breaks. Modules:

* ``momentum``         p = m v, F = Δp/Δt, impulse, kinetic energy, streams and jets
* ``newton``           F = m a, weight, lifts and rockets, towing
* ``momentum_history`` piecewise-linear momentum-time graphs
* ``drag``             quadratic drag, terminal velocity, the skydive, throwing up
* ``collisions``       straight-line collisions and explosions
* ``fluids``           upthrust, and drag at terminal velocity in a fluid
* ``two_d``            components and glancing collisions
"""

from .collisions import (
    collision_with_energy_kept,
    elastic_collision,
    explosion_from_rest,
    percentage_kinetic_energy_lost,
    relative_speed,
    stick_together,
    total_kinetic_energy,
    total_momentum,
    velocity_after_collision,
)
from .drag import (
    OPENING_STEPS,
    WITHIN_TERMINAL,
    CanopyOpening,
    Skydive,
    ThrowUp,
    canopy_drag_constant,
    drag_constant_for_terminal_velocity,
    drag_force,
    earliest_opening,
    falling_acceleration,
    open_canopy,
    skydive,
    terminal_velocity,
    thrown_upwards,
    time_to_slow_to_terminal,
    time_to_terminal_velocity,
    velocity_from_rest,
    velocity_slowing_to_terminal,
)
from .fluids import drag_at_terminal_velocity, upthrust
from .momentum import (
    average_force,
    change_in_momentum,
    impulse,
    jet_force,
    kinetic_energy,
    kinetic_energy_from_momentum,
    mass_from_momentum_and_energy,
    mass_from_momentum_change,
    momentum,
    momentum_change_between_directions,
    oblique_bounce_momentum_change,
    speed_from_momentum_and_energy,
    stream_force,
    time_for_momentum_change,
    velocity_from_momentum,
)
from .momentum_history import MomentumHistory, Segment, area_under_force_time
from .newton import (
    Towing,
    acceleration,
    acceleration_from_distance,
    gravitational_field_strength,
    lift_contact_force,
    mass_from_weight,
    thrust_for_acceleration,
    towing,
    weight,
)
from .two_d import (
    GlancingCollision,
    MissingMomentum,
    components,
    from_components,
    glancing_collision,
    missing_momentum,
)

__all__ = [
    "OPENING_STEPS",
    "WITHIN_TERMINAL",
    "CanopyOpening",
    "GlancingCollision",
    "MissingMomentum",
    "MomentumHistory",
    "Segment",
    "Skydive",
    "ThrowUp",
    "Towing",
    "acceleration",
    "acceleration_from_distance",
    "area_under_force_time",
    "average_force",
    "canopy_drag_constant",
    "change_in_momentum",
    "collision_with_energy_kept",
    "components",
    "drag_at_terminal_velocity",
    "drag_constant_for_terminal_velocity",
    "drag_force",
    "earliest_opening",
    "elastic_collision",
    "explosion_from_rest",
    "falling_acceleration",
    "from_components",
    "glancing_collision",
    "gravitational_field_strength",
    "impulse",
    "jet_force",
    "kinetic_energy",
    "kinetic_energy_from_momentum",
    "lift_contact_force",
    "mass_from_momentum_and_energy",
    "mass_from_momentum_change",
    "mass_from_weight",
    "missing_momentum",
    "momentum",
    "momentum_change_between_directions",
    "oblique_bounce_momentum_change",
    "open_canopy",
    "percentage_kinetic_energy_lost",
    "relative_speed",
    "skydive",
    "speed_from_momentum_and_energy",
    "stick_together",
    "stream_force",
    "terminal_velocity",
    "thrown_upwards",
    "thrust_for_acceleration",
    "time_for_momentum_change",
    "time_to_slow_to_terminal",
    "time_to_terminal_velocity",
    "total_kinetic_energy",
    "total_momentum",
    "towing",
    "upthrust",
    "velocity_after_collision",
    "velocity_from_momentum",
    "velocity_from_rest",
    "velocity_slowing_to_terminal",
    "weight",
]
