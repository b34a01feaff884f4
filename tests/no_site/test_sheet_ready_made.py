"""A teacher's own sheet (the command line and the sheet builder, issue 37) avoids the numbers of
the ready-made worksheets (`make worksheets`, the site's kit): its draw takes a template's
variants that no ready-made sheet prints first, and says where it must repeat one. Everything
expected is read from physics_figures.worksheets.site_sheets."""

from __future__ import annotations

import pytest

from physics_figures import topics
from physics_figures.worksheets import (
    plan,
    ready_made,
    ready_made_repeats,
    select,
    site_sheets,
    usable_versions,
)

TOPIC = topics.load("physics_figures.bank")


def _printed() -> dict[str, set[int]]:
    out: dict[str, set[int]] = {}
    for sheet in site_sheets(topic=TOPIC):
        for version in sheet.versions:
            for item in version.items:
                if not item.template.one_wording:
                    out.setdefault(item.template.key, set()).add(item.variant)
    return out


def test_ready_made_names_every_variant_the_kit_prints_and_where():
    made = ready_made(TOPIC)
    assert {key: set(variants) for key, variants in made.items()} == _printed()
    assert any(where.endswith("version C") for variants in made.values() for where in variants.values())


@pytest.mark.parametrize("seed", [2027, 0, 31])
@pytest.mark.parametrize("kind", [kind.key for kind in TOPIC.types])
def test_a_sheet_takes_no_ready_made_numbers_while_others_are_left(kind, seed):
    templates = select(types=[kind], topic=TOPIC)
    printed = _printed()
    # as many versions as every template has variants the ready-made sheets leave (the book's
    # printed variant 0 aside: it comes last of all)
    fresh = min(len(set(t.reserve_variants) - printed.get(t.key, set()) - {0}) if not t.one_wording else 26
                for t in templates)
    if fresh:
        sheet = plan("w", "", templates, versions=min(fresh, 26), seed=seed, topic=TOPIC)
        for version in sheet.versions:
            for item in version.items:
                assert item.variant not in printed.get(item.template.key, set()), (item.template.key, item.variant)
        assert ready_made_repeats(sheet, TOPIC) == []
    # one more version than that repeats a ready-made sheet's numbers, and says where
    short = [t for t in templates if not t.one_wording
             and len(set(t.reserve_variants) - printed.get(t.key, set()) - {0}) == fresh
             and set(t.reserve_variants) & printed.get(t.key, set()) - {0}]
    if fresh < min(usable_versions(t) for t in templates) and short:
        sheet = plan("w", "", templates, versions=fresh + 1, seed=seed, topic=TOPIC)
        repeats = ready_made_repeats(sheet, TOPIC)
        assert repeats and all(r.startswith(f"Version {chr(ord('A') + fresh)}, question ") for r in repeats)
        assert all(", version " in r.split(": as in ", 1)[1] for r in repeats)
