"""The typeset sheets as a printer gives them (issue 37): a choice question's stem, options and
answer box on one page, and a key's "[6 marks]" on one line. The site's sheets that hold choice
questions (physics_figures.worksheets.site_sheets), as `make book` typesets them into the site
(make worksheets), read back page by page with pdftotext."""

from __future__ import annotations

import re
import subprocess

import pytest
from sheet_pages import split_choices
from support.pdf import pdf_pages

from physics_figures.worksheets import site_sheets

pytestmark = [pytest.mark.site]

SHEETS = [sheet for sheet in site_sheets()
          if any(part.kind == "mcq" for item in sheet.versions[0].items for part in item.question.parts)]
KEYS = "end-of-topic-test"  # the keys with the longest headers: every type's titles


@pytest.fixture(scope="module")
def typeset_sheets(site_dir):
    """The site's typeset sheets: the same sources and the same xelatex as a sheet typeset here
    (physics_figures.worksheets.build), so the tests read those rather than typeset them again."""
    teachers = site_dir / "teachers"
    for sheet in SHEETS:
        for name in [f"{sheet.name}-{v.letter}.pdf" for v in sheet.versions] + (
                [f"{KEYS}-key-{v.letter}.pdf" for v in sheet.versions] if sheet.name == KEYS else []):
            if not (teachers / name).exists():
                pytest.fail(f"no {name} in {teachers}: run `make worksheets` (make book builds it)")
    return teachers


def test_sheets_with_choice_questions_are_typeset():
    assert len(SHEETS) >= 3 and any(sheet.name == KEYS for sheet in SHEETS)


@pytest.mark.parametrize("sheet", SHEETS, ids=lambda s: s.name)
def test_a_choice_question_s_stem_and_options_print_on_one_page(typeset_sheets, sheet):
    split = [line for version in sheet.versions
             for line in split_choices(pdf_pages(typeset_sheets / f"{sheet.name}-{version.letter}.pdf",
                                                 "-enc", "UTF-8"), [version])]
    assert split == []


def test_a_key_s_question_marks_never_wrap(typeset_sheets):
    sheet = next(sheet for sheet in SHEETS if sheet.name == KEYS)
    for version in sheet.versions:
        text = subprocess.run(["pdftotext", "-layout", str(typeset_sheets / f"{KEYS}-key-{version.letter}.pdf"), "-"],
                              capture_output=True, text=True, check=True).stdout
        headers = [int(n) for n in re.findall(r"\[(\d+) marks?\]", text)]
        # every question's total whole, in order (the parts' [n] have no word)
        assert headers == [item.question.marks for item in version.items], version.letter
        assert not re.search(r"\[\d+\s*$", text, re.MULTILINE)
