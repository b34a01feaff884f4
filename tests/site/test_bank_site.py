"""The question bank as the built site offers it: how many templates of each of the notes'
seven types and of each kind (numeric, multiple choice, graph, explain), against the
practice issue's minimums, counted from the pages' forms."""

from __future__ import annotations

import re
from collections import Counter

import pytest

from physics_figures import bank
from physics_figures.variants import MIN_SITUATIONS, MIN_VARIANTS

pytestmark = pytest.mark.site

#: The practice issue's minimums: templates in all, per type, per kind.
MIN_TEMPLATES = 45
MIN_BY_TYPE = {"newton": 8, "drag": 8, "force-momentum": 8, "definitions": 5, "momentum-line": 5,
               "elastic": 5, "two-d": 5}
MIN_BY_KIND = {"mcq": 12, "graph": 6}
MIN_EXPLAIN_PARTS = 4

FORM = re.compile(r'<form class="q-form"([^>]*)>(.*?)</form>', re.DOTALL)


def _attributes(text: str) -> dict[str, str]:
    return dict(re.findall(r'data-([a-z]+)="([^"]*)"', text))


@pytest.fixture(scope="module")
def forms(site_dir) -> dict[str, dict]:
    """Every bank template a page places (a worked example's try-first part, with its one
    printed variant, is not one of the bank's; a one-wording statement is), by key."""
    found = {}
    for html in sorted(site_dir.rglob("*.html")):
        for attributes, body in FORM.findall(html.read_text(encoding="utf-8")):
            form = _attributes(attributes)
            if form.get("question") in bank.TEMPLATES and not bank.TEMPLATES[form["question"]].try_first:
                form["explain parts"] = body.count('data-kind="explain"')
                found[form["question"]] = form
    return found


def test_the_bank_meets_every_minimum_by_type_and_kind(forms):
    by_type = Counter(form["type"] for form in forms.values())
    by_kind = Counter(kind for form in forms.values() for kind in form["kind"].split())
    explain_parts = sum(form["explain parts"] for form in forms.values())
    print(f"\ntemplates {len(forms)}; by type {dict(by_type)}; by kind {dict(by_kind)}; "
          f"explain parts {explain_parts}")
    assert len(forms) >= MIN_TEMPLATES
    assert set(by_type) == set(bank.TOPIC.type_keys)
    for kind, least in MIN_BY_TYPE.items():
        assert by_type[kind] >= least, f"{kind}: {by_type[kind]} of {least}"
    for kind, least in MIN_BY_KIND.items():
        assert by_kind[kind] >= least, f"{kind}: {by_kind[kind]} of {least}"
    assert explain_parts >= MIN_EXPLAIN_PARTS


def test_every_template_on_the_site_has_its_variants(forms):
    for key, form in forms.items():
        kinds = set(form["kind"].split())
        least = MIN_VARIANTS if kinds & {"numeric", "graph"} else MIN_SITUATIONS
        if bank.TEMPLATES[key].one_wording:  # a definition: one variant, and it says why
            least = 1
        assert int(form["variants"]) >= least, f"{key}: {form['variants']} variants"


def test_every_template_of_the_bank_is_on_a_page(forms):
    missing = {t.key for t in bank.TEMPLATES.values() if not t.try_first} - set(forms)
    assert not missing, f"no page places {sorted(missing)}"
