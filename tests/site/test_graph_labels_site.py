# ruff: noqa: RUF001, RUF002  (typeset text: the times sign, superscripts)
"""The question graphs and keys as the site, the sheet builder and the PDFs carry them (issue
37, "Graph labels", "Done when"): no label or key value written in powers of ten with more than
3 figures, and no two labels' boxes touching (a quarter of an em apart at the least).

* SVG: every question graph the site ships (each template's site variants, in
  _static/questions/, and the printed variants in _images/) and every graph of the sheet
  builder's data (teachers/sheet-data.js: the kit's reserve variants). A label's box is taken
  from its <text> element (x, y, size, anchor) and the width matplotlib lays that text out at.
* PDF: every PDF of the kit (make worksheets writes them into teachers/) and the book's
  (make pdf, copied to pdf/), read with pdftotext -bbox-layout: no two numbers' boxes on a
  page set in one size overlap (each the word's width by its figures' height: pdftotext's box
  is the font's), no number runs into the next ("7.510.012.5"), and no ×10ⁿ of more than 3 figures.
"""

from __future__ import annotations

import html
import itertools
import re
import subprocess
import xml.etree.ElementTree as ET
from collections import defaultdict
from pathlib import Path

import pytest
from matplotlib.font_manager import FontProperties
from matplotlib.textpath import text_to_path
from support.printed_numbers import too_many_figures
from support.sheet_data import joined_pages, read_sheet_data

from physics_figures import bank
from physics_figures.figures.style import book_style

pytestmark = pytest.mark.site

GRAPH_TEMPLATES = [t for t in bank.TEMPLATES.values() if t.variant(0).graph is not None]
TICK_SIZE = 12.0  # px in the SVG: a tick label's font size (figures/style.py, SMALL_TEXT)
_TEXT = re.compile(r'<text style="([^"]*)" x="([-\d.]+)" y="([-\d.]+)"[^>]*>([^<]*)</text>')


def _width(text: str, size: float) -> tuple[float, float]:
    """Width and height of a line of ``text`` at ``size``, as matplotlib lays it out."""
    with book_style():
        prop = FontProperties(size=size)
        width = text_to_path.get_text_width_height_descent(text, prop, ismath=False)[0]
        height = text_to_path.get_text_width_height_descent("lp", prop, ismath=False)[1]
    return width, height


def tick_labels(svg: str) -> tuple[list, list]:
    """The time axis's labels (x, text, box) and the value axis's, from a graph's SVG: tick-size
    texts centred on one line, and tick-size texts ending on one column."""
    rows, columns = defaultdict(list), defaultdict(list)
    for style, x, y, text in _TEXT.findall(svg):
        size = re.search(r"font-size: ([\d.]+)px", style)
        if not size or float(size[1]) != TICK_SIZE:
            continue
        text, x, y = html.unescape(text), float(x), float(y)
        width, height = _width(text, TICK_SIZE)
        if "text-anchor: middle" in style:
            rows[round(y, 2)].append((text, (x - width / 2, x + width / 2)))
        elif "text-anchor: end" in style:
            columns[round(x, 2)].append((text, (y - height, y)))
    across = max(rows.values(), key=len, default=[])
    up = max(columns.values(), key=len, default=[])
    return across, up


#: SVG px (= pt) of clear paper two neighbouring labels keep at the least, a quarter of their
#: size: a browser's font may set them a little wider than matplotlib measured them.
LEAST_GAP = 3.0


def touching(labels) -> list[tuple[str, str]]:
    ordered = sorted(labels, key=lambda label: label[1][0])
    return [(a[0], b[0]) for a, b in itertools.pairwise(ordered) if b[1][0] - a[1][1] < LEAST_GAP]


def check_svg(name: str, svg: str) -> list[str]:
    problems = [f"{name}: {number}" for number in too_many_figures(html.unescape(svg))]
    across, up = tick_labels(svg)
    if len(across) < 2 or len(up) < 2:
        return [*problems, f"{name}: no axes' labels found ({across}, {up})"]
    for labels in (across, up):
        problems += [f"{name}: {text!r} is not a plain number" for text, _ in labels
                     if not re.fullmatch(r"−?\d+(?:\u202f\d{3})*(?:\.\d+)?", text)]
        problems += [f"{name}: {a!r} and {b!r} touch" for a, b in touching(labels)]
    return problems


def test_check_svg_finds_the_issue_s_labels():
    def text(x, y, anchor, body):
        return (f'<text style="font-size: 12px; font-family: \'DejaVu Sans\'; text-anchor: {anchor}" '
                f'x="{x}" y="{y}" transform="rotate(-0 {x} {y})">{body}</text>')

    labels = [text(50 + 27 * i, 218, "middle", f"{2.5 * i:.1f}") for i in range(9)]
    labels += [text(49, 200 - 30 * i, "end", body) for i, body in enumerate(["0", "50\u202f000", "1.00000 × 10⁵"])]
    problems = check_svg("old", "".join(labels))
    assert len(problems) == 6, problems  # 3 pairs touch, and the last label twice
    assert any("'10.0' and '12.5' touch" in p for p in problems), problems
    assert any("1.00000 × 10⁵" in p for p in problems), problems
    good = [text(50 + 60 * i, 218, "middle", str(5 * i)) for i in range(5)]
    good += [text(49, 200 - 30 * i, "end", f"{0.5 * i:.1f}") for i in range(4)]
    assert check_svg("new", "".join(good)) == []


def site_graphs(site_dir: Path) -> dict[str, str]:
    found = {}
    for template in GRAPH_TEMPLATES:
        for index in template.site_variants:
            path = site_dir / "_static" / "questions" / f"{template.key}-{index}.svg"
            assert path.exists(), f"the site ships no {path.name}"
            found[path.name] = path.read_text(encoding="utf-8")
    for path in sorted((site_dir / "_images").glob("*.svg")):
        text = path.read_text(encoding="utf-8")
        if any(path.name.startswith(template.key) for template in GRAPH_TEMPLATES):
            found[f"_images/{path.name}"] = text
    return found


def builder_graphs(site_dir: Path) -> dict[str, str]:
    """The sheet builder's graphs: every inline SVG of its sheets, joined as the builder joins
    them, that is a question graph (a question's diagram, whose label starts "Diagram.", is not
    one)."""
    found = {}
    for (key, variant), page in joined_pages(read_sheet_data(site_dir)).items():
        for number, svg in enumerate(re.findall(r"<svg\b.*?</svg>", page["sheet"] + page["key"], re.DOTALL)):
            if 'aria-label="Diagram.' not in svg and all(tick_labels(svg)):
                found[f"sheet-data graph {key}-{variant}.{number}"] = svg
    return found


def test_every_graph_of_the_site_and_the_sheet_builder_prints_plain_labels_that_do_not_touch(site_dir):
    site, builder = site_graphs(site_dir), builder_graphs(site_dir)
    reserve = sum(len(t.reserve_variants) for t in GRAPH_TEMPLATES)
    assert len(site) >= sum(len(t.site_variants) for t in GRAPH_TEMPLATES)
    assert len(builder) >= reserve, f"{len(builder)} graphs in the sheet builder's data, {reserve} reserve variants"
    problems = [p for graphs in (site, builder) for name, svg in graphs.items() for p in check_svg(name, svg)]
    assert not problems, problems[:20]


# ---------------------------------------------------------------------------------- the PDFs


def words(pdf: Path) -> list[list[tuple[str, float, float, float, float]]]:
    """Each page's words with their boxes (xMin, yMin, xMax, yMax), from pdftotext -bbox-layout."""
    out = subprocess.run(["pdftotext", "-bbox-layout", str(pdf), "-"], check=True, capture_output=True).stdout
    root = ET.fromstring(re.sub(rb"<!DOCTYPE[^>]*>", b"", out))
    pages = []
    for page in root.iter("{http://www.w3.org/1999/xhtml}page"):
        pages.append([(w.text or "", *(float(w.get(k)) for k in ("xMin", "yMin", "xMax", "yMax")))
                      for w in page.iter("{http://www.w3.org/1999/xhtml}word")])
    return pages


NUMBER = re.compile(r"−?-?\d+(?:\.\d+)?")
#: pdftotext's word box is as tall as its font's ascent and descent (DejaVu Sans, the graphs'
#: font: 0.928 and 0.236 of an em); a number's figures stand 0.73 em above the baseline.
ASCENT, DESCENT, FIGURE_HEIGHT = 0.928, 0.236, 0.73


def ink(word) -> tuple[float, float, float, float]:
    """A number's box as its figures are drawn: the word's width, and its figures' height."""
    _, left, top, right, bottom = word
    em = (bottom - top) / (ASCENT + DESCENT)
    baseline = bottom - DESCENT * em
    return left, baseline - FIGURE_HEIGHT * em, right, baseline
#: 7.510.0 or 2.53.0: two labels with no gap between them (a label's places, then the next
#: label's whole part), not a version number (4.3.0)
RUN_TOGETHER = re.compile(r"\d\.\d{2,}\.\d")


def check_pdf(name: str, pages) -> list[str]:
    problems = []
    for number, page in enumerate(pages, 1):
        text = " ".join(word[0] for word in page)
        problems += [f"{name} p{number}: {found}" for found in too_many_figures(text)]
        problems += [f"{name} p{number}: {word[0]!r} runs numbers together" for word in page
                     if RUN_TOGETHER.search(word[0])]
        numbers = [(word[0], ink(word)) for word in page if NUMBER.fullmatch(word[0])]
        for i, (a, box) in enumerate(numbers):
            for b, other in numbers[i + 1:]:
                # a graph's labels share one size; a power's raised figures (4.5², 10⁻³) are smaller
                same_size = abs((box[3] - box[1]) - (other[3] - other[1])) < 0.05
                if same_size and min(box[2], other[2]) > max(box[0], other[0]) and min(box[3], other[3]) > max(box[1], other[1]):
                    problems.append(f"{name} p{number}: {a!r} and {b!r} overlap")
    return problems


def test_check_pdf_finds_overlapping_and_run_together_labels():
    page = [("7.510.012.5", 10, 10, 40, 20), ("1.00000", 50, 10, 70, 20), ("×", 71, 10, 75, 20), ("105", 76, 10, 85, 20),
            ("15", 100, 10, 112, 20), ("20", 110, 10, 122, 20), ("25", 130, 10, 142, 20)]
    problems = check_pdf("old", [page])
    assert len(problems) == 3, problems
    assert check_pdf("new", [[("1.12", 10, 10, 30, 20), ("×", 31, 10, 35, 20), ("105", 36, 10, 45, 20)]]) == []


def _pdfs(folder: Path, what: str) -> list[Path]:
    found = sorted(folder.glob("*.pdf"))
    if not found:
        pytest.fail(f"no PDFs in {folder}: run `{what}`")
    return found


def test_every_pdf_of_the_kit_prints_plain_labels_that_do_not_overlap(site_dir):
    pdfs = _pdfs(site_dir / "teachers", "make worksheets")
    problems = [p for pdf in pdfs for p in check_pdf(pdf.name, words(pdf))]
    assert not problems, problems[:20]


def test_the_book_s_pdfs_print_plain_labels_that_do_not_overlap(site_dir):
    pdfs = _pdfs(site_dir / "pdf", "make pdf")
    problems = [p for pdf in pdfs for p in check_pdf(pdf.name, words(pdf))]
    assert not problems, problems[:20]
