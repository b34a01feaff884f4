# ruff: noqa: RUF001, RUF002, RUF003  (question text is typeset: true minus, times, Greek letters)
"""Issue 37, the new templates read as an examiner would: each finding, checked over every variant."""

from __future__ import annotations

import pytest
from test_new_templates_b import _law_power, _printed

from physics_figures.bank import TEMPLATES


def _variants(key):
    return list(enumerate(TEMPLATES[key].variants))


@pytest.mark.parametrize(("index", "question"), _variants("drag-law-terminal-ratio"))
def test_masses_the_wrong_way_up_says_a_s_speed_was_divided(index, question):
    """The slip divides A's terminal speed by the factor (v_A ÷ √(m_B / m_A)): the feedback names A."""
    given, power = _printed(question), _law_power(question)
    (wrong,) = [m for m in question.parts[0].mistakes if m.name == "masses the wrong way up"]
    factor = (given["mass of B"] / given["mass of A"]) ** (1 / power)
    assert wrong.value == pytest.approx(given["terminal speed of A"] / factor)
    assert wrong.feedback.startswith("You divided A's terminal speed by"), wrong.feedback
    assert "B's terminal speed" not in wrong.feedback
