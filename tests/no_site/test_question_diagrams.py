"""The two-dimensional and collision templates print a diagram (issue 37): the bodies before and
after, labelled with the variant's own numbers (every mass, speed and angle the text gives),
with alt text that says them; on the page, relabelled by New numbers (each site variant's own
SVG), and in the printed sheets."""

from __future__ import annotations

import html
import re

import pytest
from conftest import variant_param
from support.sheet_data import joined_pages
from support.templates import DIAGRAMMED, diagram_numbers

from physics_figures import bank
from physics_figures.figures.question_diagram import question_diagram
from physics_figures.worksheets import latex


def test_the_two_dimensional_and_collision_templates_are_the_ones_expected():
    assert {"practice-pucks", "glancing-speed-choice", "explosion-three-pieces", "skaters-stick-right-angles",
            "oblique-wall-bounce", "puck-components", "explosion-two-pieces", "quick-check-2",
            "practice-trolleys-stick", "practice-spring-apart", "stick-choice", "collision-third-law",
            "quick-check-4", "elastic-or-not-choice", "stick-energy-choice", "elastic-both-moving",
            "sticking-energy-lost", "sticking-fraction-lost", "bounce-energy-ratio"} == set(DIAGRAMMED)


@pytest.mark.parametrize(("key", "index"), [variant_param(bank.TEMPLATES[key], index, key, index)
                                            for key in DIAGRAMMED for index in range(len(bank.TEMPLATES[key].values))])
def test_every_variant_has_a_diagram_whose_labels_and_alt_text_carry_its_numbers(key, index):
    question = bank.TEMPLATES[key].variant(index)
    assert question.diagram is not None, f"{key} variant {index} has no diagram"
    drawn = question_diagram(question.diagram)
    labels = " ".join(html.unescape(t) for t in re.findall(r"<text[^>]*>([^<]*)</text>", drawn.svg()))
    for number in diagram_numbers(question):
        assert number in labels, f"{key} variant {index}: {number} is not on the diagram ({labels})"
        assert number in drawn.alt, f"{key} variant {index}: {number} is not in the alt text ({drawn.alt})"
    drawn.figure.clear()


def test_the_printed_sheet_includes_each_question_s_diagram():
    from physics_figures.worksheets import Item, Version

    version = Version("A", (Item(bank.TEMPLATES["puck-components"], 1),))
    files = latex.graphs(version)
    assert list(files) == ["graph-1.pdf"] and files["graph-1.pdf"].startswith(b"%PDF")
    assert "\\includegraphics[width=0.42\\linewidth]{graph-1.pdf}" in latex.question_sheet(
        latex.Sheet("s", "S", 1, (version,)), version)


def test_the_sheet_builder_s_sheets_carry_each_diagram():
    """The teacher's sheet builder prints a reserve variant with its diagram, as with its graph."""
    import sys
    from pathlib import Path

    sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "book" / "_ext"))
    from questions.sheet_builder import builder_pages

    pictures = []
    data = builder_pages(bank.TOPIC, lambda name, picture: pictures.append((name, picture)) or f"<svg>{name}</svg>")
    names = {name.rsplit("-", 1)[0] for name, picture in pictures if picture.__class__.__name__ == "Diagram"}
    assert set(DIAGRAMMED) <= names
    index = bank.TEMPLATES["puck-components"].reserve_variants[0]
    sheet = joined_pages(data, [("puck-components", index)])[("puck-components", str(index))]["sheet"]
    assert f"<svg>puck-components-{index}</svg>" in sheet
