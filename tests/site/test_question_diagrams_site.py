"""The built practice pages show each two-dimensional and collision question's diagram, and New
numbers brings each variant's own (the diagrams themselves: tests/no_site/test_question_diagrams.py)."""

from __future__ import annotations

import html
import re

import pytest
from browser import question_pages, shipped_variants
from support.templates import DIAGRAMMED, diagram_numbers

from physics_figures import bank


@pytest.mark.site
@pytest.mark.parametrize("key", DIAGRAMMED)
def test_each_page_shows_the_diagram_and_new_numbers_brings_each_variant_s_own(site_dir, key):
    pages = question_pages(site_dir)
    page = (site_dir / pages[key].lstrip("/")).read_text(encoding="utf-8")
    section = page[page.index(f'id="question-{key}"'):]
    section = section[:section.index('<form class="q-form"')]
    image = re.search(r'<img[^>]*class="q-diagram"[^>]*>', section)
    assert image, f"{key}: no diagram on its page"
    alt = html.unescape(re.search(r'alt="([^"]*)"', image[0])[1])
    for number in diagram_numbers(bank.TEMPLATES[key].variant(0)):
        assert number in alt, f"{key}: {number} not in the page's alt text {alt!r}"
    template = bank.TEMPLATES[key]
    shipped = shipped_variants(site_dir / "_static" / "questions" / f"{key}.js")
    assert len(shipped) == len(template.site_variants) >= 2
    for index, data in zip(template.site_variants, shipped, strict=True):
        numbers = diagram_numbers(template.variant(index))
        svg = (site_dir / "_static" / "questions" / data["diagram"]["src"]).read_text(encoding="utf-8")
        labels = html.unescape(" ".join(re.findall(r"<text[^>]*>([^<]*)</text>", svg)))
        for number in numbers:
            assert number in data["diagram"]["alt"] and number in labels, (key, index, number)
