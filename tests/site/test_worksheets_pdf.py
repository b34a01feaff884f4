"""The teachers' worksheets and keys as typeset PDFs, read back with poppler (pdftotext,
pdffonts, pdfimages, pdfinfo), and the Moodle file, as `make book` leaves them in the site;
and one small sheet built twice by the command line, which must give the same bytes."""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from moodle_format import check_file
from support.pdf import layout_text, poppler
from test_pdf import squash

from physics_figures.notation import format_number
from physics_figures.worksheets import site_sheets
from physics_figures.worksheets.latex import MISTAKE_SIG_FIGS, wrong_answers
from physics_figures.worksheets.moodle import MOODLE_MIN_VARIANTS, root_category
from physics_figures.worksheets.page import moodle_file, site_files

SHEETS = site_sheets()
MARK = re.compile(r"\[(\d+)\]")


@pytest.fixture(scope="module")
def teachers(site_dir) -> Path:
    return site_dir / "teachers"


def text(folder: Path, name: str) -> str:
    path = folder / name
    if not path.exists():
        pytest.fail(f"no {name} in {folder}: run `make worksheets` (make book builds it)")
    return layout_text(path)


@pytest.mark.site
def test_teachers_page_links_every_sheet_key_and_the_moodle_file(site_dir, teachers):
    page = (site_dir / "book" / "teachers.html").read_text()
    for name in site_files():
        assert f'href="../teachers/{name}"' in page, name
        assert (teachers / name).exists(), f"the page links {name}, which make book did not write"
    assert len([n for n in site_files() if n.endswith(".pdf")]) == 2 * 3 * len(SHEETS)


@pytest.mark.site
@pytest.mark.parametrize("sheet", SHEETS, ids=lambda s: s.name)
def test_versions_differ_in_numbers_and_agree_in_marks(teachers, sheet):
    texts = [text(teachers, f"{sheet.name}-{v.letter}.pdf") for v in sheet.versions]
    marks = [MARK.findall(t) for t in texts]
    assert all(m == marks[0] for m in marks), "the versions' marks differ"
    assert sum(int(n) for n in marks[0]) == sheet.marks
    for page in texts:
        assert f"Total: {sheet.marks} marks" in page
        assert "take g = 9.81 m s⁻²" in page
        for field in ("Name", "Class", "Date"):
            assert re.search(rf"^\s*{field}\s+\.{{10,}}", page, re.MULTILINE), field
    numbers = [re.findall(r"\d+(?:\.\d+)?", t.split("Total:", 1)[1]) for t in texts]
    for first, second in ((0, 1), (0, 2), (1, 2)):
        assert numbers[first] != numbers[second], "two versions print the same numbers"


@pytest.mark.site
@pytest.mark.parametrize("sheet", SHEETS, ids=lambda s: s.name)
def test_every_key_matches_physics_figures_for_its_version(teachers, sheet):
    """Each key gives each part's answer (as physics_figures computes it for that version's
    variant), its mark codes and, for numeric parts, the wrong answers with their mistakes."""
    for version in sheet.versions:
        key = squash(text(teachers, f"{sheet.name}-key-{version.letter}.pdf"))
        paper = squash(text(teachers, f"{sheet.name}-{version.letter}.pdf"))
        for item in version.items:
            question = item.question
            assert squash(f"({item.template.key}, variant {item.variant})") in key
            for index, part in enumerate(question.parts):
                if part.kind in ("numeric", "graph", "mcq"):
                    # without hyphens: TeX may break a long answer's word ("ap-proach")
                    assert squash(part.answer_text).replace("-", "") in key.replace("-", ""), (
                        item.template.key, part.prompt)
                if part.kind == "numeric":
                    for row in wrong_answers(question, index):
                        assert squash(row.written) in key and squash(row.name) in key, (item.template.key, row.name)
                        assert squash(row.marks) in key, (item.template.key, row.name)
            for _, _, code in question.mark_lines():
                if code:
                    assert squash(code) in key
            for given in question.givens:  # the sheet asks with this version's numbers
                assert squash(given.text) in paper


@pytest.mark.site
def test_the_g_equals_ten_answer_is_in_the_key_as_the_issue_describes(teachers):
    """"A teacher who sees 11.4 m s⁻² on a script knows the student used g = 10": the key
    lists the value the model gives with g = 10 next to that mistake."""
    sheet = next(s for s in SHEETS if s.name == "worksheet-drag")
    for version in sheet.versions:
        item = next(i for i in version.items if i.template.key == "quick-check-3")
        part = item.question.parts[1]
        g_ten = next(m for m in part.mistakes if m.name.startswith("used g = 10"))
        key = text(teachers, f"{sheet.name}-key-{version.letter}.pdf")
        assert f"{format_number(g_ten.value, MISTAKE_SIG_FIGS)} m s⁻²: used g = 10 m s⁻²" in key


@pytest.mark.site
def test_multiple_choice_items_get_an_answer_grid(teachers):
    for sheet in SHEETS:
        has_choice = any(p.kind == "mcq" for i in sheet.versions[0].items for p in i.question.parts)
        page = text(teachers, f"{sheet.name}-A.pdf")
        assert ("Multiple-choice answer grid" in page) == has_choice, sheet.name


@pytest.mark.site
@pytest.mark.parametrize("sheet", SHEETS, ids=lambda s: s.name)
def test_the_cover_and_its_answer_grid_are_one_page(teachers, sheet):
    """The grid sits beside the marks table: a 13-question test once left the grid's heading
    at the foot of the cover and the grid alone on page 2."""
    has_choice = any(p.kind == "mcq" for i in sheet.versions[0].items for p in i.question.parts)
    for version in sheet.versions:
        path = str(teachers / f"{sheet.name}-{version.letter}.pdf")
        first, second = (poppler("pdftotext", "-enc", "UTF-8", "-f", n, "-l", n, path, "-") for n in "12")
        assert f"Total: {sheet.marks} marks" in first
        assert ("Shade one circle" in first) == has_choice, f"{path}: the answer grid is not on the cover"
        assert "Shade one circle" not in second


@pytest.mark.site
@pytest.mark.parametrize("sheet", SHEETS, ids=lambda s: s.name)
def test_print_quality_a4_embedded_fonts_vector_graphs(teachers, sheet):
    for version in sheet.versions:
        for name in (f"{sheet.name}-{version.letter}.pdf", f"{sheet.name}-key-{version.letter}.pdf"):
            path = teachers / name
            info = poppler("pdfinfo", str(path))
            assert re.search(r"Page size:\s+595\.\d* x 841\.\d* pts \(A4\)", info), name
            fonts = poppler("pdffonts", str(path)).splitlines()[2:]
            assert fonts and all(row.split()[-5] == "yes" for row in fonts), f"{name}: a font not embedded"
            images = poppler("pdfimages", "-list", str(path)).splitlines()[2:]
            assert not images, f"{name}: raster images (graphs must be vectors)"
    log_free = [p for p in (teachers.parent.parent / "teachers-tex").glob(f"{sheet.name}-*/*.log")
                if re.search(r"Overfull \\hbox \((\d{2,}|[5-9])\.", p.read_text(errors="replace"))]
    assert not log_free, f"text runs into the margin (overfull by 5pt or more) in {log_free}"


@pytest.mark.site
def test_moodle_file_parses_holds_every_template_and_passes_the_structural_check(teachers):
    from physics_figures.worksheets import bank_templates

    root = ET.parse(teachers / moodle_file()).getroot()
    problems, categories = check_file(root)
    assert not problems, "\n".join(problems[:30])
    ids = [q.findtext("idnumber") for q in root.iter("question") if q.get("type") != "category"]
    assert len(ids) == len(set(ids))
    for template in bank_templates():
        first = template.variant(0)
        for part_id in first.part_ids:
            variants = {i for i in ids if re.fullmatch(rf"{re.escape(template.key)}-v\d+-{part_id}", i)}
            assert len(variants) == len(template.reserve_variants), (template.key, part_id)
            assert len(variants) >= MOODLE_MIN_VARIANTS or template.shares_variants
    types = [path for path in categories if path.count("/") == root_category().count("/") + 1]
    assert len(types) == 7
