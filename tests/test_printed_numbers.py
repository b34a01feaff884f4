"""What is printed is what is used (issue 25): every number a question states is the number
its key is worked from. A given drawn finer than it is printed (a mass of 1.15 kg printed
"1.2") would make the key disagree with an answer worked from the printed text."""

from __future__ import annotations

import math

import pytest

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


def test_elastic_both_moving_working_gives_its_printed_answer():
    """(c) v_B = v_A + approach: the printed v_A keeps enough figures for the sum to give the
    printed answer (it printed -4.9 + 5.5 = 0.64, where -4.9 + 5.5 is 0.6)."""
    template = TEMPLATES["elastic-both-moving"]
    for index, question in enumerate(template.variants):
        working = next(m.text for m in question.mark_scheme if m.part == "c" and "+" in m.text)
        v_a, approach = (float(x.replace("\u2212", "-")) for x in working.rsplit("= ", 1)[1].split(" + "))
        answer = float(next(m.text for m in question.mark_scheme if m.part == "c" and m.code == "A1")
                       .split()[1].replace("\u2212", "-"))
        printed_places = len(str(answer).split(".")[1])
        assert round(v_a + approach, printed_places) == pytest.approx(answer), (index, working, answer)
