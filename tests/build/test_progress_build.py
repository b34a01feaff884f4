"""The {practice-progress} directive in small Sphinx builds: the HTML page embeds every
template of the bank by type with the page that places it (kept current when another page
changes), the sections its named mistakes send a student to and the self-test's cards, and
loads its scripts (the plan's ts-fsrs among them) only there; a question's page loads the
review line; print builds say where the progress lives."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from support.pages import embedded
from support.sphinx import small_book, sphinx_build

from physics_figures import bank

pytestmark = [pytest.mark.build]

def _project(tmp_path: Path, asked: str) -> Path:
    return small_book(tmp_path, {
        "asked": "# Questions\n\n" + asked,
        "progress": "# Your practice\n\nWhat you practised.\n\n```{practice-progress}\n```\n",
        "defs": "# Definitions\n\n```{admonition} Learn these\n:class: self-test\n\n"
                "- **Mass:** what resists a change in motion.\n"
                "- **Newton\u2019s first law:** at rest or constant velocity.\n```\n",
    })


def _progress_data(source: Path) -> dict:
    return embedded((source / "_out" / "html" / "progress.html").read_text(), "pp-data")


def test_the_page_embeds_the_bank_by_type_with_the_page_that_places_each(tmp_path):
    key = next(iter(t.key for t in bank.TEMPLATES.values() if not t.try_first))
    source = _project(tmp_path, f"```{{question}} {key}\n```\n")
    result = sphinx_build(source, "html")
    assert result.returncode == 0, result.stderr
    data = _progress_data(source)
    assert [kind["type"] for kind in data["types"]] == list(bank.TOPIC.type_keys)
    entries = {t["key"]: t for kind in data["types"] for t in kind["templates"]}
    assert set(entries) == {t.key for t in bank.TEMPLATES.values() if not t.try_first}
    assert entries[key]["page"] == "asked.html"
    assert entries[key]["marks"] == bank.TEMPLATES[key].variant(0).marks
    assert all(t["page"] is None for k, t in entries.items() if k != key)  # placed nowhere here
    page = (source / "_out" / "html" / "progress.html").read_text()
    assert "_static/progress.js" in page and "_static/progress.css" in page
    assert f'href="asked.html#question-{key}"' in page  # without JavaScript: the question itself
    asked = (source / "_out" / "html" / "asked.html").read_text()
    assert "progress.js" not in asked
    # the plan's scripts, each after the ones it uses; the scheduler on no other page
    scripts = re.findall(r'<script[^>]* src="_static/([^"?]+)', page)
    plan = ["notation.js", "progress-store.js", "ts-fsrs.js", "schedule.js", "progress-file.js", "progress.js",
            "progress-page.js", "progress-plan.js"]
    assert [name for name in scripts if name in plan] == plan
    assert "ts-fsrs.js" not in asked and "progress-plan.js" not in asked
    assert asked.index("_static/questions.js") < asked.index("_static/review.js")  # Start's cards are served here
    # a named mistake's section, and the engine's own slips' rows, as the question's feedback links them
    see, parts = entries[key]["see"], bank.TEMPLATES[key].variant(0).parts
    named = [(m.name, m.see or p.see) for p in parts for m in (p.mistakes or ()) if m.see or p.see]
    assert set(see) == {name for name, _ in named}
    assert all((name, ident) in named for name, ident in see.items())
    assert set(data["generic"]) == {"sign or direction", "unit missing or wrong", "1 s.f. answer"}
    # the self-test's cards, named as selftest.js names them
    assert data["definitions"] == {"page": "defs.html", "cards": [
        {"slug": "mass", "term": "Mass"}, {"slug": "newton-s-first-law", "term": "Newton\u2019s first law"}]}
    defs = (source / "_out" / "html" / "defs.html").read_text()
    assert defs.index("_static/progress-store.js") < defs.index("_static/selftest.js") < defs.index("_static/review.js")

    # The question moves off the page: the progress page is rewritten though it did not change.
    (source / "asked.md").write_text("# Questions\n\nNone today.\n")
    result = sphinx_build(source, "html")
    assert result.returncode == 0, result.stderr
    assert all(t["page"] is None for kind in _progress_data(source)["types"] for t in kind["templates"])


def test_print_builds_say_the_progress_is_kept_in_the_browser(directive_book):
    text = (directive_book("text") / "progress.txt").read_text()
    assert "What you practised." in text
    assert "kept in the web browser you practise in" in text
