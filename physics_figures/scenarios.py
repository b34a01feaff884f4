"""The notes' situations as data, built on the models (Notes section in each comment).

Figures, pages and questions import these so that every one of them shows the same
situation with the same numbers. Values that the notes do not give are marked CHOSEN,
with the reason.
"""

from .models import (
    MomentumHistory,
    glancing_collision,
    momentum,
    skydive,
    thrown_upwards,
    towing,
)

# Understand it > Momentum and Newton's second law: a 1500 kg car at 20 m s^-1.
CAR_MASS = 1500.0  # kg
CAR_SPEED = 20.0  # m s^-1

# Understand it > Reading a momentum-time graph: the same 1500 kg car speeds up for
# 4.0 s, cruises until 10.0 s and stops at 16.0 s.
CAR_HISTORY = MomentumHistory((0.0, 4.0, 10.0, 16.0), (0.0, 12_000.0, 12_000.0, 0.0))

# Understand it > Momentum and Newton's second law: a hose sends out 1.5 kg of water
# every second at 12 m s^-1.
HOSE_MASS_PER_SECOND = 1.5  # kg s^-1
HOSE_SPEED = 12.0  # m s^-1

# Understand it > Weight: a 60 kg person, on the Earth, the Moon and in a lift that
# accelerates at 1.5 m s^-2.
PERSON_MASS = 60.0  # kg
LIFT_ACCELERATION = 1.5  # m s^-2

# Understand it > Friction, drag and terminal velocity: an 80 kg skydiver, terminal
# velocity 50 m s^-1 in freefall and 5.0 m s^-1 with the parachute open.
# CHOSEN (the notes give no times): the parachute opens at 20 s, well after terminal
# velocity is reached (point C, 13.5 s), and the canopy takes 2.5 s to fill (a real one
# takes two or three seconds), which keeps the largest deceleration (D, 0.78 s after the
# opening) to about 4 g. The record lasts 30 s, so the second terminal velocity (point E,
# 23.2 s) is followed by a flat stretch.
SKYDIVER_MASS = 80.0  # kg
SKYDIVER = skydive(
    SKYDIVER_MASS,
    terminal_velocity_freefall=50.0,
    terminal_velocity_parachute=5.0,
    parachute_opens_at=20.0,
    opening_duration=2.5,
    duration=30.0,
)

# Understand it > Friction, drag and terminal velocity ("Thrown upwards with air
# resistance"). CHOSEN (the notes give no numbers): a light ball thrown up at 20 m s^-1
# whose terminal velocity is also 20 m s^-1, so that drag visibly lowers the top
# (14.1 m instead of 20.4 m) and the return speed (14.1 m s^-1 instead of 20 m s^-1).
THROWN_BALL = thrown_upwards(20.0, terminal_velocity=20.0)
THROWN_BALL_IN_VACUUM = thrown_upwards(20.0)

# Understand it > Conservation of momentum: a 3.0 kg trolley at 4.0 m s^-1 hits a
# 1.0 kg trolley at rest and they stick together.
STICKING_TROLLEYS = {"m1": 3.0, "u1": 4.0, "m2": 1.0, "u2": 0.0}  # kg, m s^-1

# Understand it > Conservation of momentum: a spring pushes 0.20 kg and 0.30 kg trolleys
# apart from rest; the 0.30 kg one moves off at 2.0 m s^-1.
SPRING_TROLLEYS = {"m1": 0.30, "m2": 0.20, "v1": 2.0}  # kg, m s^-1

# Understand it > Momentum in two dimensions: puck P (1.00 N s) hits puck Q at rest;
# afterwards P has 0.60 N s at 50 degrees to its old line.
PUCKS_PQ = glancing_collision(1.00, 0.60, 50.0)

# Worked examples > Example 4: puck X, 0.20 kg at 3.0 m s^-1, hits puck Y, 0.30 kg, at
# rest; afterwards X moves at 1.8 m s^-1 at 60 degrees to its original direction.
EXAMPLE_4 = glancing_collision(
    momentum(0.20, 3.0), momentum(0.20, 1.8), 60.0, mass_moving=0.20, mass_struck=0.30
)

# Worked examples > Example 1: a 1200 kg car tows a 400 kg trailer; driving force 3000 N,
# resistive forces 400 N (car) and 200 N (trailer).
EXAMPLE_1 = towing(3000.0, (1200.0, 400.0), (400.0, 200.0))

# Worked examples > Example 5 (a drag question the notes describe but do not work):
# CHOSEN a steel-like sphere (density 8000 kg m^-3) falling through oil, so that the
# upthrust is about a tenth of the weight and the working shows both.
EXAMPLE_5 = {"mass": 0.012, "volume": 1.5e-6, "oil_density": 920.0}  # kg, m^3, kg m^-3
