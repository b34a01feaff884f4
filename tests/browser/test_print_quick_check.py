"""The quick check printed from the browser (File > Print, or Save as PDF), as a student does
after trying it: Chromium prints the built page on A4 (page.pdf), and poppler reads the PDF
back (pdfinfo: its pages; pdftotext: its words). Paper gets the questions with room for
working, each part's marks as [n], each question's total and the page's, on at most two
pages (issue 26), with none of the web's instructions or controls, and no worked answer even
when one was opened on screen ("Print with answers" prints them: tests/browser/test_firststeps_browser.py).
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from browser import serve_site
from support.pdf import poppler

from physics_figures import bank

pytestmark = [pytest.mark.site, pytest.mark.browser]

ROOT = Path(__file__).resolve().parents[2]
PAGE = "book/exam/quick-check"
#: The web's words on the page: its instructions, buttons, answer boxes' labels, the unit hint,
#: and the worked answer's heading and mark lines. Case matters: "Quick check" is the title.
WEB_ONLY = [r"\bCheck\b", r"\bpress", r"Type each answer", "New numbers", "Clear my answers", "Print with answers",
            "Worked answer", r"\bValue\b", r"\bUnit\b", "Type a unit", r"\b[ABCM]1\b", "kept in this browser"]


def _asked() -> list:
    """The quick check's questions, in page order, as the page prints them (variant 0)."""
    keys = re.findall(r"^```\{question\} (\S+)", (ROOT / f"{PAGE}.md").read_text(encoding="utf-8"), re.MULTILINE)
    return [bank.TEMPLATES[key].variant(0) for key in keys]


@pytest.fixture(scope="module")
def printed(browser, site_dir, tmp_path_factory) -> Path:
    """The page printed on A4 after a student answered question 1, pressed Check and opened
    its worked answer."""
    pdf = tmp_path_factory.mktemp("print") / "quick-check.pdf"
    with serve_site(site_dir) as base_url:
        page = browser.new_page()
        page.goto(f"{base_url}/{PAGE}.html", wait_until="load")
        form = page.locator('form.q-form[data-question="quick-check-1"]')
        form.locator('[data-part="a"] input.q-value').fill("15")
        form.locator("button.q-check").click()
        worked = page.locator("#question-quick-check-1 details.q-worked")
        worked.locator("summary").click()
        assert worked.get_attribute("open") is not None
        page.pdf(path=str(pdf), format="A4")
        page.close()
    return pdf


def test_the_quick_check_prints_on_at_most_two_a4_pages(printed):
    info = poppler("pdfinfo", str(printed))
    pages = int(re.search(r"^Pages:\s+(\d+)", info, re.MULTILINE)[1])
    width, height = map(float, re.search(r"^Page size:\s+([\d.]+) x ([\d.]+) pts", info, re.MULTILINE).groups())
    assert abs(width - 595.3) < 2 and abs(height - 841.9) < 2, f"not A4: {width} x {height} pt"
    assert pages <= 2, f"the quick check prints on {pages} A4 pages (at most 2)"


def test_paper_shows_every_part_s_marks_each_question_s_total_and_the_page_s(printed):
    text = poppler("pdftotext", "-enc", "UTF-8", str(printed), "-")
    asked = _asked()
    parts = [marks for question in asked for marks in question.part_marks()]
    assert [int(n) for n in re.findall(r"\[(\d+)\]", text)] == parts, text
    totals = [sum(question.part_marks()) for question in asked]
    assert [int(n) for n in re.findall(r"^Total: (\d+) marks?$", text, re.MULTILINE)] == totals, text
    assert f"Total for the page: {sum(totals)} marks." in " ".join(text.split())
    for question in asked:  # every question's text and answer line, with room to write
        assert question.parts[-1].prompt in text


def test_paper_has_no_web_instruction_control_or_worked_answer(printed):
    text = poppler("pdftotext", "-enc", "UTF-8", str(printed), "-")
    found = [pattern for pattern in WEB_ONLY if re.search(pattern, text)]
    assert not found, f"printed: {found}\n{text}"
