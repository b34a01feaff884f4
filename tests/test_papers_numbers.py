
"""The templates take the numbers the published papers use (issue 38, "The papers' own numbers")."""

from __future__ import annotations

import pytest

from physics_figures import bank

STOPPING = bank.TEMPLATES["stopping-force-distance"]


def test_stopping_force_takes_a_papers_deceleration():
    """9702/21/M/J/24 Q3(c): a 4.2 kg object at 6.0 m s⁻¹ is stopped by a constant force in
    0.050 m, a deceleration of 360 m s⁻², far above a car's tyres (6.5 m s⁻²)."""
    question = STOPPING.build(mass=4.2, speed=6.0, distance=0.050, body=1)
    deceleration, force = (part.value for part in question.parts)
    assert deceleration == pytest.approx(6.0**2 / (2 * 0.050))
    assert force == pytest.approx(4.2 * deceleration)
    assert "object of mass 4.2 kg" in question.text and "0.050 m" in question.text
    assert "car" not in question.text + " ".join(part.prompt for part in question.parts)


def test_a_car_still_brakes_no_harder_than_its_tyres_allow_and_the_error_says_how_to_pose_an_object():
    with pytest.raises(ValueError, match=r"got distance=0.05 m: 360 m s\^-2.*body=1"):
        STOPPING.build(mass=4.2, speed=6.0, distance=0.050)
    assert STOPPING.variant(0).text.startswith("A car of mass 1500 kg")
