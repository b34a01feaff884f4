"""The built pages show the numbers the book printed before on a first visit (the questions
themselves: tests/no_site/test_questions.py)."""

from __future__ import annotations

import json
import re
from html import unescape as html_unescape
from pathlib import Path

import pytest
from support.templates import PRINTED, printed

from physics_figures import questions as q


@pytest.mark.site
def test_the_built_pages_show_the_printed_numbers_on_a_first_visit(site_dir):
    """What a first visit gets (variant 0, in the page): the printed givens in the text and
    the printed keys in the marking data, for every converted question."""
    found = {}
    for page in (site_dir / "book" / "exam").glob("*.html"):
        html = page.read_text()
        for section in re.findall(r'<section class="q"[^>]*>.*?</section>', html, re.DOTALL):
            data = json.loads(re.search(r'<script type="application/json" class="q-data">(.*?)</script>',
                                        section, re.DOTALL)[1])
            found[data["id"]] = (data, re.sub(r"<[^>]+>", "", section))
    assert set(PRINTED) <= set(found)
    for key, (givens, keys) in PRINTED.items():
        data, words = found[key]
        assert 'data-variant="0"' in data_form(site_dir, key)
        question = printed(key)
        assert [part["value"] for part in data["parts"]] == [part.value for part in question.parts], key
        assert tuple(part.answer_text for part in question.parts) == keys
        for _, value, _, sig_figs in givens:
            assert q.number(value, sig_figs) in html_unescape(words), (key, value)


def data_form(site_dir: Path, key: str) -> str:
    for page in (site_dir / "book" / "exam").glob("*.html"):
        form = re.search(rf'<form class="q-form" data-question="{key}"[^>]*>', page.read_text())
        if form:
            return form[0]
    raise AssertionError(f"no form for {key} in the built site")
