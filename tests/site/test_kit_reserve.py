"""Issue 26: the teacher's kit uses only questions no student has met on the site, and a kit
never asks the same question twice.

Read from what `make book` leaves: the site's New numbers data (`_static/questions/KEY.js`,
every variant the site ships, text and mark scheme), every answer key's PDF (each question is
tagged "(template, variant N)"), and the Moodle file (question ids KEY-vN-PART). A template of
few situations shares its variants with the site (Template.shares_variants), as the "For
teachers" page says; it is the one exception.
"""

from __future__ import annotations

import re
import subprocess
import xml.etree.ElementTree as ET
from collections import Counter
from functools import cache
from pathlib import Path

import pytest
from browser import shipped_variants
from test_pdf import squash

from physics_figures import bank
from physics_figures.worksheets import site_sheets
from physics_figures.worksheets.page import moodle_file, sheet_files

pytestmark = pytest.mark.site

TAG = re.compile(r"\(([a-z0-9-]+),variant(\d+)\)")


@cache
def _site_variants(site: Path) -> dict[str, list[tuple[str, str]]]:
    """Each template's variants as the site ships them: (text, mark scheme) in index order."""
    shipped = {}
    for path in sorted((site / "_static" / "questions").glob("*.js")):
        shipped[path.stem] = [(v["text"], v["scheme"]) for v in shipped_variants(path)]
    return shipped


def _printed(key: str, index: int) -> tuple[str, str]:
    question = bank.TEMPLATES[key].variant(index)
    return question.text_html(), question.mark_scheme_html()


def _on_the_site(site: Path, key: str, index: int) -> bool:
    """The site ships this question: by its index, or word for word under another index."""
    shipped = _site_variants(site).get(key, [_printed(key, 0)])  # one variant: the page shows it
    return index < len(shipped) or _printed(key, index) in shipped


def _key_tags(site: Path) -> dict[str, list[tuple[str, int]]]:
    """Every answer key's questions, (template, variant), by version letter."""
    asked: dict[str, list[tuple[str, int]]] = {}
    for sheet in site_sheets():
        for version, (_, key_file) in zip(sheet.versions, sheet_files(sheet), strict=True):
            path = site / "teachers" / key_file
            if not path.exists():
                pytest.fail(f"no {key_file} in {path.parent}: run `make worksheets` (make book builds it)")
            text = squash(subprocess.run(["pdftotext", "-enc", "UTF-8", str(path), "-"], check=True,
                                         capture_output=True, text=True).stdout)
            tags = [(key, int(index)) for key, index in TAG.findall(text)]
            assert len(tags) == len(version.items), f"{key_file}: {len(tags)} tagged questions"
            asked.setdefault(version.letter, []).extend(tags)
    return asked


def test_the_site_ships_the_first_variants_and_never_the_reserve(site_dir):
    for key, shipped in _site_variants(site_dir).items():
        template = bank.TEMPLATES[key]
        assert len(shipped) == len(template.site_variants), key
        assert shipped[0] == _printed(key, 0), f"{key}: the site's first variant is not the printed one"


def test_no_sheet_or_key_asks_a_question_the_site_ships(site_dir):
    seen = []
    for letter, tags in _key_tags(site_dir).items():
        for key, index in tags:
            if not bank.TEMPLATES[key].shares_variants and _on_the_site(site_dir, key, index):
                seen.append(f"{letter}: {key} variant {index}")
    assert not seen, f"the site ships these questions of the kit: {seen}"


def test_no_question_appears_twice_in_a_kit_of_the_same_letter(site_dir):
    for letter, tags in _key_tags(site_dir).items():
        twice = sorted(tag for tag, count in Counter(tags).items() if count > 1)
        assert not twice, f"kit {letter} (worksheets and test) asks these twice: {twice}"


def test_the_moodle_file_holds_no_question_the_site_ships(site_dir):
    root = ET.parse(site_dir / "teachers" / moodle_file()).getroot()
    seen, count = [], 0
    for question in root.iter("question"):
        match = re.fullmatch(r"(.+)-v(\d+)-[a-z]+", question.findtext("idnumber") or "")
        if question.get("type") == "category" or not match:
            continue
        count += 1
        key, index = match[1], int(match[2])
        if not bank.TEMPLATES[key].shares_variants and _on_the_site(site_dir, key, index):
            seen.append(match[0])
    assert count > 500, f"only {count} questions in the Moodle file"
    assert not seen, f"the site ships these Moodle questions: {seen[:20]}"
