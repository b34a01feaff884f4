"""The sheet builder's data file (teachers/sheet-data.js, questions/sheet_builder.py) stays within
issue 39's budget, the one make bench holds it to (scripts/bench.py, SHEET_DATA_BYTES), and the
builder still prints from it the sheets and keys physics_figures writes.

The file was 5,370,109 bytes with its graphs' SVG as matplotlib wrote it, 4,254,551 with the
graphs compacted (compact_svg) and the statements, sketches and real-paper templates added. Each
sheet and key was whole, so the key repeated the question's text, every variant of a graph
template its axes, grid and labels, and every variant of a template its answer spaces and
headings. Held as pieces, each piece that several print held once (questions/sheet_pieces.py),
it is 2,168,139 bytes (gzip -9: 186,152, where it was 210,697)."""

from __future__ import annotations

import pytest
from bench import SHEET_DATA_BYTES
from questions.sheet_builder import graphs_folder
from support.sheet_data import joined_pages, read_sheet_data

from physics_figures import topics
from physics_figures.worksheets import bank_templates
from physics_figures.worksheets.html import key_body, sheet_body

pytestmark = [pytest.mark.site]

TOPIC = topics.load("physics_figures.bank")


def test_the_sheet_builder_s_data_keeps_within_its_budget(site_dir):
    size = (site_dir / "teachers" / "sheet-data.js").stat().st_size
    assert size <= SHEET_DATA_BYTES, f"teachers/sheet-data.js is {size:,} bytes (at most {SHEET_DATA_BYTES:,})"


def test_its_pieces_join_into_every_sheet_and_key_physics_figures_writes(site_dir):
    """Every reserve variant, joined by the builder's code, is the HTML of
    physics_figures.worksheets.html with the graph the build drew (kept beside the site)."""
    joined = joined_pages(read_sheet_data(site_dir))
    assert len(joined) == sum(len(template.reserve_variants) for template in bank_templates(TOPIC))
    folder = graphs_folder(site_dir)
    for (key, variant), page in joined.items():
        question = TOPIC.by_key[key].variant(int(variant))
        drawn = folder / f"{key}-{variant}.svg"
        svg = drawn.read_text(encoding="utf-8") if question.graph or question.diagram else ""
        assert page["sheet"] == sheet_body(question, svg), (key, variant)
        assert page["key"] == key_body(question), (key, variant)
