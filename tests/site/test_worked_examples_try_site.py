"""Each worked example's built page asks its try-first question before the solution (the
questions and pages' sources: tests/no_site/test_worked_examples_try.py)."""

from __future__ import annotations

import re

import pytest

from physics_figures import bank

EXAMPLES = range(1, 6)


@pytest.mark.site
@pytest.mark.parametrize("number", EXAMPLES)
def test_the_built_page_asks_the_try_first_question_before_the_solution(site_dir, number):
    html = (site_dir / "book" / "exam" / f"example-{number}.html").read_text(encoding="utf-8")
    key = f"example-{number}-try"
    form = re.search(rf'<form class="q-form" data-question="{key}"[^>]*>', html)
    assert form, f"no try-first form on example {number}"
    assert 'data-kind="numeric"' in form.group(0) and 'data-variant="0"' in form.group(0)
    assert f'data-type="{bank.TEMPLATES[key].type}"' in form.group(0)
    assert "q-new" not in html, "a try-first part keeps the printed numbers: no New numbers"
    assert html.index('class="exercise') < html.index(f'id="question-{key}"') < \
        html.index('class="solution dropdown try-first')
