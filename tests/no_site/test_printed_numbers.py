# ruff: noqa: RUF001  (scheme lines as typeset: true minus, times)
"""What is printed is what is used (issue 25): every number a question states is the number
its key is worked from. A given drawn finer than it is printed (a mass of 1.15 kg printed
"1.2") would make the key disagree with an answer worked from the printed text."""

from __future__ import annotations

import math

import pytest
from working_lines import evaluate, result, wrong_steps

from physics_figures.bank import TEMPLATES
from physics_figures.notation import round_number


@pytest.mark.parametrize("key", TEMPLATES)
def test_every_given_is_used_as_it_is_printed(key):
    """Each variant's givens, put back into the model as printed, are the values it used."""
    differ = [f"variant {index}: {given.name} printed {given.text} but used as {given.value!r}"
              for index, question in enumerate(TEMPLATES[key].variants)
              for given in question.givens
              if not math.isclose(float(round_number(given.value, given.sig_figs)), given.value,
                                  rel_tol=1e-9, abs_tol=1e-12)]
    assert not differ, differ


def test_the_working_line_reader_reads_a_scheme_as_an_examiner_does():
    assert evaluate("½ × 0.80 × 1.05<sup>2</sup> + ½ × 1.1 × 0.80<sup>2</sup>") == pytest.approx(0.793)
    assert evaluate("(−1.6 − 2.4) / 0.030") == pytest.approx(-133.33, rel=1e-4)
    assert evaluate("1.8 cos 60°") == pytest.approx(0.9)
    assert evaluate("0.15") is None and evaluate("0.20v_A + 0.30v_B") is None
    assert result("9970 N") == (9970.0, 10.0) and result("0.64 m s") == (0.64, 0.01)
    assert result("0.058 × 42") is None  # an expression, not a result


@pytest.mark.parametrize("key", TEMPLATES)
def test_every_working_line_gives_its_printed_result(key):
    """Each arithmetic step a scheme prints gives, from its numbers as printed, the result it
    prints at the precision shown (tests/working_lines.py)."""
    wrong = [f"variant {index}: {step}" for index, question in enumerate(TEMPLATES[key].variants)
             for step in wrong_steps(question)[0]]
    assert not wrong, wrong


def test_the_working_lines_are_read():
    """Most templates print arithmetic the reader can check (it read 683 steps)."""
    assert sum(wrong_steps(q)[1] for t in TEMPLATES.values() for q in t.variants) > 600
