# ruff: noqa: RUF003  (comments write the working as typeset: true minus)
"""A moving body that splits into two pieces at an angle (Notes, "Momentum in two dimensions":
momentum is conserved along and across the original line separately; issue 25)."""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from physics_figures.models import components, kinetic_energy, split_in_two

SETTINGS = settings(max_examples=100, deadline=None)
masses = st.floats(0.1, 100.0, allow_subnormal=False)
fractions = st.floats(0.01, 0.99, allow_subnormal=False)
speeds = st.floats(0.0, 50.0, allow_subnormal=False)
angles = st.floats(0.0, 180.0, allow_subnormal=False)


@SETTINGS
@given(mass=masses, share=fractions, u=speeds, v=speeds, angle=angles)
def test_momentum_is_conserved_along_and_across_the_line_separately(mass, share, u, v, angle):
    piece = mass * share
    other = split_in_two(mass, u, piece, v, angle)
    along, across = components(piece * v, angle)
    scale = max(1.0, mass * max(u, v))
    assert float(along) + other.along == pytest.approx(mass * u, abs=1e-9 * scale)
    assert float(across) + other.across == pytest.approx(0.0, abs=1e-9 * scale)
    assert other.mass == pytest.approx(mass - piece)
    assert other.magnitude == pytest.approx(math.hypot(other.along, other.across), abs=1e-9 * scale)
    assert other.speed == pytest.approx(other.magnitude / other.mass, abs=1e-9 * scale)


@SETTINGS
@given(mass=masses, share=fractions, u=speeds, v=speeds, angle=angles)
def test_a_split_never_loses_kinetic_energy_and_the_pieces_go_to_opposite_sides(mass, share, u, v, angle):
    piece = mass * share
    other = split_in_two(mass, u, piece, v, angle)
    after = kinetic_energy(piece, v) + kinetic_energy(other.mass, other.speed)
    before = kinetic_energy(mass, u)
    assert other.kinetic_energy_released == pytest.approx(max(0.0, after - before), abs=1e-9 * max(1.0, after))
    assert after >= before - 1e-9 * max(1.0, after)
    assert other.across <= 0.0  # the known piece is on the + side, so the other is not


def test_a_split_worked_by_hand():
    # 2.0 kg at 3.0 m s⁻¹; 0.50 kg leaves at 8.0 m s⁻¹ at 40°: along 6.0 − 4.0 cos 40° = 2.94 N s,
    # across −4.0 sin 40° = −2.57 N s; the 1.5 kg piece moves at 3.90 / 1.5 = 2.60 m s⁻¹ at 41.2°
    # to the original line, on the other side.
    other = split_in_two(2.0, 3.0, 0.50, 8.0, 40.0)
    assert other.along == pytest.approx(6.0 - 4.0 * math.cos(math.radians(40)))
    assert other.across == pytest.approx(-4.0 * math.sin(math.radians(40)))
    assert round(other.speed, 2) == 2.60 and round(other.angle_deg, 1) == -41.2
    # from rest, the two pieces fly apart along one line, equal and opposite
    at_rest = split_in_two(1.0, 0.0, 0.25, 4.0, 0.0)
    assert at_rest.along == pytest.approx(-1.0) and at_rest.speed == pytest.approx(1.0 / 0.75)
    # a piece thrown forwards hard enough leaves the other moving backwards
    assert split_in_two(1.0, 1.0, 0.5, 5.0, 10.0).along < 0


@pytest.mark.parametrize(("call", "message"), [
    (lambda: split_in_two(1.0, 2.0, 1.0, 3.0, 30.0), r"mass_piece must be less than mass=1.0 kg .*\(got mass_piece=1.0"),
    (lambda: split_in_two(0.0, 2.0, 0.5, 3.0, 30.0), r"mass must be positive \(got mass=0.0"),
    (lambda: split_in_two(1.0, -2.0, 0.5, 3.0, 30.0), r"speed must not be negative \(got speed=-2.0"),
    (lambda: split_in_two(1.0, 2.0, 0.5, 3.0, 190.0), r"angle_piece_deg must be between 0 and 180"),
])
def test_a_split_refuses_impossible_input_naming_the_argument(call, message):
    with pytest.raises(ValueError, match=message):
        call()
