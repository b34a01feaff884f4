"""The {class-progress} directive in small Sphinx builds: the class page embeds the book's id
and every type of the bank with its templates' keys, titles and marks (what class.js needs),
Your practice's data carries the same id for its exports, the page loads its scripts (and
only it does), and print builds say where the page works."""

from __future__ import annotations

import re

import pytest
from support.pages import embedded

from physics_figures import bank

pytestmark = [pytest.mark.build]

def test_the_class_page_embeds_the_book_and_its_types_and_loads_its_scripts(directive_book):
    site = directive_book("html")  # the class page and Your practice, of support.sphinx's DIRECTIVE_PAGES
    page = (site / "class.html").read_text()
    data = embedded(page, "cp-data")
    assert data["book"] == bank.TOPIC.key
    assert [kind["type"] for kind in data["types"]] == list(bank.TOPIC.type_keys)
    assert [kind["name"] for kind in data["types"]] == [t.title for t in bank.TOPIC.types]
    for kind in data["types"]:
        assert kind["templates"] == [{"key": t.key, "title": t.title, "marks": t.variant(0).marks}
                                     for t in bank.by_type(kind["type"])]
    assert embedded((site / "progress.html").read_text(), "pp-data")["book"] == data["book"]
    scripts = re.findall(r'<script[^>]*src="_static/([\w.-]+\.js)', page)
    order = [name for name in scripts if name in {"notation.js", "progress-file.js", "progress.js", "class-table.js",
                                                       "class.js"}]
    assert order == ["notation.js", "progress-file.js", "progress.js", "class-table.js", "class.js"]  # in turn
    assert "_static/class.css" in page
    assert re.search(r'<input type="file" id="cp-choose"\s+class="cp-choose" accept="\.json,application/json" multiple>',
                     page)
    assert "class.js" not in (site / "progress.html").read_text()


def test_print_builds_say_the_class_page_works_in_the_browser(directive_book):
    text = (directive_book("text") / "class.txt").read_text()
    assert "What the class did." in text
    assert "open it in the web version of the book" in text
