# ruff: noqa: RUF001  (question text is typeset: true minus, times, Greek letters)
"""Definitions, units and the difference between mass and weight."""

from __future__ import annotations

import sympy

from ..constants import G_EARTH, G_MOON
from ..models import kinetic_energy, mass_from_weight, momentum, weight
from ..notation import format_number as n
from ..notation import round_number
from ..questions import Ecf, Given, Mark, Mistake, Part, Question, Step
from ..variants import Draw, Template
from ._common import N_S, PER_S, PER_S2

a_answer, g_symbol = sympy.symbols("a g_earth")


def backpack_on_the_moon(mass: float = 12.0) -> Question:
    """Notes, Quick check 5: 12 kg backpack on the Moon -> mass 12 kg, weight 19.4 N."""
    moon_weight = weight(mass, g=G_MOON)
    m, g_moon = n(mass, 2), n(G_MOON, 3)
    return Question(
        key="quick-check-5",
        text=(f"An astronaut's backpack has a mass of {m} kg. (a) State its mass on the Moon and "
              f"(b) calculate its weight there (g = {g_moon} {PER_S2})."),
        givens=(Given("mass", mass, "kg", 2), Given("g on the Moon", G_MOON, "m s^-2", 3)),
        parts=(
            Part("mass on the Moon", mass, "kg", "mass", shown_sig_figs=2,
                 revisit="Mass is the property that resists a change in motion: it is the same "
                         "everywhere.",
                 mistakes=(
                     Mistake("mass scaled with g", mass * G_MOON / G_EARTH,
                             "Mass doesn't change with g: it is the same on the Moon. Only the "
                             "weight changes."),
                     Mistake("mass divided by g", mass / G_MOON,
                             f"Mass doesn't depend on g at all: the backpack's mass is still {m} kg."),
                 )),
            Part("weight on the Moon", moon_weight, "N", "weight", shown_sig_figs=3,
                 revisit="Weight = mass × gravitational field strength, W = mg, with the Moon's g.",
                 mistakes=(
                     Mistake("used the Earth's g", weight(mass),
                             f"You used g on the Earth ({n(G_EARTH, 3)}). On the Moon g = {g_moon} m s⁻²."),
                     Mistake("mass given as weight", mass,
                             f"{m} is the mass in kg. Weight is a force: W = mg."),
                     Mistake("divided by g", mass / G_MOON,
                             "You divided by g. Weight = mass × g."),
                 )),
        ),
        mark_scheme=(
            Mark(f"Mass = {m} kg (it doesn't change)", "B1", "a"),
            Mark(f"Weight = mg = {m} × {g_moon}", "C1", "b"),
            Mark(f"= {n(moon_weight, 3)} N", "A1", "b"),
        ),
    )


def tennis_ball(grams: float = 57.0, speed: float = 50.0) -> Question:
    """A mass given in g: momentum of a 57 g ball served at 50 m s^-1."""
    mass = grams / 1000
    p = momentum(mass, speed)
    g, v, kg = n(grams, 2), n(speed, 2), n(mass, 2)
    return Question(
        key="practice-tennis-ball",
        text=f"A tennis ball of mass {g} g is served at {v} {PER_S}. Calculate the momentum of the ball.",
        givens=(Given("mass", grams, "g", 2), Given("speed", speed, "m s^-1", 2)),
        parts=(
            Part("momentum of the ball", p, "N s", "momentum", units=N_S, shown_sig_figs=2,
                 revisit="Momentum = mass × velocity, with the mass in kg.",
                 mistakes=(
                     Mistake("mass left in grams", grams * speed,
                             f"You used the mass in g. Convert to kg first: {g} g = {kg} kg."),
                     Mistake("kinetic energy instead of momentum", kinetic_energy(mass, speed),
                             "That is the kinetic energy, ½mv², in J. Momentum is mv, in N s.", unit="J"),
                     Mistake("mass divided by speed", mass / speed,
                             "You divided the mass by the speed. Momentum is mass × velocity."),
                 )),
        ),
        mark_scheme=(
            Mark(f"m = {g} g = {kg} kg, so p = mv = {kg} × {v}", "C1"),
            Mark(f"= {n(p, 2)} N s", "A1"),
        ),
    )


def rock_from_mars(mars_weight: float = 5.4, g_mars: float = 3.7) -> Question:
    """Mass and weight on another planet: mass stays, weight scales with g."""
    mass = mass_from_weight(mars_weight, g=g_mars)
    earth_weight = weight(mass)
    w_mars, g_m, g_e = n(mars_weight, 2), n(g_mars, 2), n(G_EARTH, 3)
    # Rounding the mass to 2 s.f. before W = mg changes the answer: say so where it does.
    rounded = weight(float(round_number(mass, 2)))
    warning = (f" (the unrounded mass: {n(mass, 2)} kg would give {n(rounded, 3)} N)"
               if n(rounded, 3) != n(earth_weight, 3) else "")
    return Question(
        key="practice-mars-rock",
        text=(f"A rock sample weighs {w_mars} N on Mars, where g = {g_m} {PER_S2}. Calculate (a) its mass, "
              "and (b) its weight on the Earth."),
        givens=(Given("weight on Mars", mars_weight, "N", 2), Given("g on Mars", g_mars, "m s^-2", 2)),
        parts=(
            Part("mass of the rock", mass, "kg", "mass", shown_sig_figs=2,
                 revisit="W = mg, so m = W / g, with the g where the weight was measured.",
                 mistakes=(
                     Mistake("multiplied by g", mars_weight * g_mars,
                             "You multiplied by g. W = mg, so m = W / g."),
                     Mistake("used the Earth's g", mass_from_weight(mars_weight),
                             f"You used the Earth's g. The {w_mars} N was measured on Mars, so divide "
                             f"by {g_m}."),
                 )),
            Part("weight of the rock on the Earth", earth_weight, "N", "weight", shown_sig_figs=3,
                 working=(Step("mass", mass, "kg"),), answer_from=lambda m: weight(m),
                 answer_for_g=lambda g: weight(mass, g=g),
                 ecf=Ecf(a_answer * g_symbol, {"g_earth": G_EARTH}),
                 revisit=f"The mass is the same on the Earth; W = mg with g = {g_e} m s⁻².",
                 mistakes=(
                     Mistake("weight unchanged", mars_weight,
                             "Weight depends on g, so it changes from Mars to the Earth. The mass is "
                             "what stays the same."),
                     Mistake("mass given as weight", mass,
                             "That is the mass in kg. Weight is a force: W = mg."),
                 )),
        ),
        mark_scheme=(
            Mark(f"m = W / g = {w_mars} / {g_m}", "C1", "a"),
            Mark(f"= {n(mass, 2)} kg (the same everywhere)", "A1", "a"),
            Mark(f"On the Earth W = mg = {n(mass, 4)} × {g_e}{warning}", "C1", "b"),
            Mark(f"= {n(earth_weight, 3)} N", "A1", "b"),
        ),
    )


TEMPLATES = (
    Template("quick-check-5", "definitions", ("numeric",), "Quick check 5", backpack_on_the_moon,
             {"mass": Draw(12.0, 5.0, 40.0, 1.0)}),
    Template("practice-tennis-ball", "definitions", ("numeric",), "Tennis ball", tennis_ball,
             {"grams": Draw(57.0, 54.0, 60.0, 1.0), "speed": Draw(50.0, 30.0, 70.0, 1.0)}),
    Template("practice-mars-rock", "definitions", ("numeric",), "Rock from Mars", rock_from_mars,
             {"mars_weight": Draw(5.4, 2.0, 9.0, 0.1)}),
)
