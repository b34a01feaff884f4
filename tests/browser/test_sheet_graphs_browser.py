"""The sheet builder's graphs, compacted for its data file (questions/sheet_builder.py's
compact_svg: teachers/sheet-data.js at 0.7 of its size before), look as matplotlib drew them.

Each graph is drawn by physics_figures, then shown in Chromium at a sheet's width, inline as
the builder's page shows it, twice: the SVG matplotlib wrote (its prologue aside), and the
builder's, compacted. The two are the same pixels but for edges that moving a coordinate by at
most 0.005 px may shade differently (NOISE_LEVEL, NOISE_SHARE below)."""

from __future__ import annotations

import re
from io import BytesIO

import pytest
from PIL import Image, ImageChops
from questions.sheet_builder import inline_svg, short_prefix

from physics_figures import topics

pytestmark = [pytest.mark.browser]

TOPIC = topics.load("physics_figures.bank")
#: graphs of each kind (velocity-time, momentum-time, force-time) and a drawn situation
TEMPLATES = ["graph-skydiver-terminal", "graph-bounce-momentum-time", "graph-kick-force-time",
             "collision-third-law"]
WIDTH = 640  # px: a graph's width on a printed sheet at 96 dpi, and more
#: A pixel differs when a channel moves by more than this (of 255): an edge shaded afresh moves
#: less; a line moved, shortened or dropped, a tick or a label lost, changes its pixels fully.
NOISE_LEVEL = 64
#: and at most this many pixels may differ so (Chromium drew the four graphs here with none)
NOISE_PIXELS = 16


def _drawn(key: str):
    from physics_figures.figures.question_diagram import question_diagram
    from physics_figures.figures.question_graph import question_graph

    template = TOPIC.by_key[key]
    question = template.variant(template.reserve_variants[0])
    return question_graph(question.graph) if question.graph is not None else question_diagram(question.diagram)


def _shot(page, html: str) -> Image.Image:
    page.set_content(f"<style>body {{ margin: 0 }} #g {{ width: {WIDTH}px }} "
                     f"#g svg {{ display: block; width: 100%; height: auto }}</style><div id='g'>{html}</div>")
    page.evaluate("document.fonts.ready")
    return Image.open(BytesIO(page.locator("#g").screenshot())).convert("RGB")


@pytest.mark.parametrize("key", TEMPLATES)
def test_a_compacted_graph_draws_as_matplotlib_drew_it(browser, key):
    drawn = _drawn(key)
    file = drawn.svg()
    inline = inline_svg(file, prefix=short_prefix(key), alt=drawn.alt)
    drawn.figure.clear()
    assert len(inline) < 0.8 * len(file), f"{key}: compacted to {len(inline)} of {len(file)} bytes"
    page = browser.new_page()
    original = _shot(page, re.sub(r"<\?xml[^>]*>|<!DOCTYPE[^>]*>", "", file))
    shown = _shot(page, inline)
    page.close()
    assert original.size == shown.size, f"{key}: {original.size} drawn as {shown.size}"
    differing = ImageChops.difference(original, shown).convert("L").point(lambda v: 255 if v > NOISE_LEVEL else 0)
    count = differing.histogram()[255]
    assert count <= NOISE_PIXELS, f"{key}: {count} pixels differ (within {differing.getbbox()})"
