"""Upthrust and drag at terminal velocity in a fluid (physics_figures.models.fluids)."""

import pytest

from physics_figures.models import drag_at_terminal_velocity, upthrust, weight


def test_upthrust_is_rho_g_v_with_the_fluids_density():
    # Example 5 (worked by hand): 920 x 9.81 x 1.5e-6 = 0.0135378 N.
    assert upthrust(920, 1.5e-6) == pytest.approx(0.0135378)
    assert upthrust(920, 1.5e-6, g=1.62) == pytest.approx(920 * 1.62 * 1.5e-6)


def test_at_terminal_velocity_weight_is_drag_plus_upthrust():
    w, u = weight(0.012), upthrust(920, 1.5e-6)
    assert drag_at_terminal_velocity(w, u) + u == pytest.approx(w)
    assert drag_at_terminal_velocity(w) == w  # in air the upthrust is left out


@pytest.mark.parametrize(("call", "message"), [
    (lambda: upthrust(-920, 1.5e-6), "fluid_density"),
    (lambda: upthrust(920, 0), "volume"),
    (lambda: drag_at_terminal_velocity(0.1, 0.2), "must be less than the weight"),
    (lambda: drag_at_terminal_velocity(0.1, -0.01), "upthrust"),
])
def test_bad_inputs_are_refused_with_the_rule(call, message):
    with pytest.raises(ValueError, match=message):
        call()
