"""A part's marks are one number everywhere: the site's question data (what the browser
awards, every variant of every template), the worksheets and their keys as typeset PDFs, and
the Moodle XML (every exported variant), all against Question.part_marks. (The question-sheet PDF is checked against
the site's data in tests/site/test_pdf.py.)"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from collections import defaultdict

import pytest
from browser import shipped_variants
from test_worksheets_pdf import MARK, SHEETS, text

from physics_figures import bank
from physics_figures.worksheets.page import moodle_file

pytestmark = pytest.mark.site


def _site_variants(site_dir, key: str) -> list[dict]:
    return shipped_variants(site_dir / "_static" / "questions" / f"{key}.js")


@pytest.mark.parametrize("key", sorted(k for k, t in bank.TEMPLATES.items() if len(t.site_variants) > 1))
def test_the_site_awards_each_part_the_marks_of_every_variant(site_dir, key):
    template = bank.TEMPLATES[key]
    shipped = _site_variants(site_dir, key)
    assert len(shipped) == len(template.site_variants)  # never the reserve
    for index, data in enumerate(shipped):
        question = template.variant(index)
        lines = [line["part"] for line in data["marks"]]
        assert [lines.count(p) for p in question.part_ids] == question.part_marks(), (key, index)


def test_moodle_gives_each_part_the_same_marks(site_dir):
    root = ET.parse(site_dir / "teachers" / moodle_file()).getroot()
    marks: dict[tuple[str, int, str], float] = defaultdict(float)
    for question in root.iter("question"):
        idnumber = question.findtext("idnumber")
        if not idnumber:
            continue
        found = re.fullmatch(r"(.+)-v(\d+)-([a-j])(?:-direction)?", idnumber)
        assert found, idnumber
        marks[(found[1], int(found[2]), found[3])] += float(question.findtext("defaultgrade"))
    assert marks, "no question in the Moodle file"
    for (key, index, part_id), grade in sorted(marks.items()):
        question = bank.TEMPLATES[key].variant(index)
        assert grade == question.part_marks()[question.part_ids.index(part_id)], (key, index, part_id)


@pytest.mark.parametrize("sheet", SHEETS, ids=lambda s: s.name)
def test_every_sheet_and_key_prints_each_parts_marks(site_dir, sheet):
    for version in sheet.versions:
        expected = [marks for item in version.items for marks in item.question.part_marks()]
        for pdf in (f"{sheet.name}-{version.letter}.pdf", f"{sheet.name}-key-{version.letter}.pdf"):
            printed = [int(n) for n in MARK.findall(text(site_dir / "teachers", pdf))]
            assert printed == expected, pdf
