"""The teachers' sheet builder (book/_ext/questions/static/sheet-builder.js, under Node, on the data
file's index) and the command line (physics_figures.worksheets.plan) give the same sheets: for
several choices of types, marks, versions and seeds, the same templates and variants in every
version, the same ready-made repeats, or the same error. Both run the one draw, question-draw.js;
this checks what each feeds it (the builder its data file, the command line the topic) and reads
back (tests/js/sheet_plan.js runs the builder). And no second draw: the Python package holds none.

Also the HTML the builder prints (physics_figures.worksheets.html): a key holds what the PDF
key holds, a graph inlined into a page keeps its references, with ids of its own, and the data
file's pieces join into that HTML as physics_figures wrote it."""

from __future__ import annotations

import functools
import json
import re
import sys
from pathlib import Path

import pytest

from physics_figures import topics
from physics_figures.worksheets import plan, ready_made_repeats, select
from physics_figures.worksheets.html import key_body, sheet_body
from physics_figures.worksheets.latex import ecf_note, wrong_answers

ROOT = Path(__file__).resolve().parents[2]
RUNNER = ROOT / "tests" / "js" / "sheet_plan.js"
sys.path.insert(0, str(ROOT / "book" / "_ext"))
from questions.sheet_builder import builder_index, builder_pages, inline_svg, short_prefix
from questions.sheet_pieces import LONGEST_WHOLE
from support.engine import node_json
from support.sheet_data import joined_pages

TOPIC = topics.load("physics_figures.bank")
TYPES = [kind.key for kind in TOPIC.types]


run_builder = functools.partial(node_json, RUNNER)  # run_builder(request): what the runner answers


def command_line_plan(case: dict) -> dict:
    """What the command line makes for these choices: the keys and variants, or the error."""
    try:
        templates = select(types=case["types"], topic=TOPIC)
        sheet = plan("worksheet", "", templates, versions=case["versions"], seed=case["seed"], marks=case["marks"],
                     topic=TOPIC)
    except ValueError as error:
        return {"error": str(error)}
    title = "Worksheet: " + "; ".join(TOPIC.type(t).title for t in case["types"])
    return {"title": title,
            "versions": [[[item.template.key, item.variant] for item in version.items] for version in sheet.versions],
            "repeats": ready_made_repeats(sheet, TOPIC)}


def impossible_marks(types: list[str]) -> int:
    """A total the templates of these types cannot make (found by asking the command line's plan)."""
    templates = select(types=types, topic=TOPIC)
    for marks in range(1, sum(t.variant(0).marks for t in templates)):
        try:
            plan("w", "", templates, versions=1, seed=1, marks=marks, topic=TOPIC)
        except ValueError as error:
            assert "cannot be made exactly" in str(error)
            return marks
    pytest.fail(f"every total can be made from {types}")


def cases() -> list[dict]:
    every = [
        {"types": TYPES, "marks": 30, "versions": 3, "seed": 2027},
        {"types": ["drag", "two-d"], "marks": 30, "versions": 4, "seed": 2027},
        {"types": ["newton"], "marks": 12, "versions": 1, "seed": 0},
        {"types": ["definitions", "elastic"], "marks": 17, "versions": 2, "seed": 123456789},
        {"types": ["momentum-line", "two-d", "drag"], "marks": 45, "versions": 4, "seed": 7},
        {"types": ["force-momentum", "momentum-line", "elastic"], "marks": 40, "versions": 3, "seed": 99},
        {"types": TYPES[:3], "marks": 23, "versions": 2, "seed": 31},
        # errors: too many versions, too many marks, no types, a bad seed, marks that cannot be made
        {"types": TYPES, "marks": 30, "versions": 6, "seed": 2027},
        {"types": ["drag"], "marks": 500, "versions": 3, "seed": 1},
        {"types": [], "marks": 30, "versions": 3, "seed": 1},
        {"types": ["drag"], "marks": 30, "versions": 3, "seed": -1},
        {"types": ["drag"], "marks": 0, "versions": 3, "seed": 1},
        {"types": ["drag"], "marks": 30, "versions": 27, "seed": 1},
    ]
    # two dimensions: templates of 1, 4, 6 marks and more, so a small total cannot be made
    every.append({"types": ["two-d"], "marks": impossible_marks(["two-d"]), "versions": 2, "seed": 5})
    return every


def test_the_builder_and_the_command_line_give_the_same_sheets_or_the_same_error():
    chosen = cases()
    builder = run_builder({"data": builder_index(TOPIC), "cases": chosen})["plans"]
    expected = [command_line_plan(case) for case in chosen]
    assert sum("error" in e for e in expected) == 7, expected  # each error case is one
    for case, got, want in zip(chosen, builder, expected, strict=True):
        assert got == want, case


#: What only a draw computes: the seeded hash, the subset sums over the templates' marks, the
#: seeded order of the variants.
DRAW_WORDS = re.compile(r"0x811C9DC5|0x01000193|fnv|seeded_order|subset_sum|variant_order", re.IGNORECASE)


def test_the_draw_has_one_implementation():
    """The worksheet draw lives in question-draw.js alone: no Python module of the package computes
    it again (the twin this replaced: worksheets' fnv1a, seeded_order, _subset_sums, choose_templates)."""
    found = [f"{path.relative_to(ROOT)}: {match[0]}" for path in sorted((ROOT / "physics_figures").rglob("*.py"))
             for match in DRAW_WORDS.finditer(path.read_text(encoding="utf-8"))]
    assert not found, found
    draw = (ROOT / "book" / "_ext" / "questions" / "static" / "question-draw.js").read_text(encoding="utf-8")
    assert len(DRAW_WORDS.findall(draw)) >= 3  # the words find the draw where it is


def _plain(html: str) -> str:
    return re.sub(r"\s+", " ", re.sub(r"<[^>]+>", " ", html)).replace("\u00a0", " ")


@pytest.mark.parametrize("key", ["practice-towing", "graph-kick-force-time", "collision-third-law",
                                 "falling-graph-choice", "state-first-law"])
def test_a_key_holds_what_the_pdf_key_holds(key):
    template = TOPIC.by_key[key]
    index = template.reserve_variants[-1]
    question = template.variant(index)
    key_text = _plain(key_body(question))
    for part_index, part in enumerate(question.parts):
        if part.kind in ("numeric", "graph"):
            assert _plain(part.answer_text) in key_text
            for row in wrong_answers(question, part_index):
                assert _plain(row.written) in key_text and _plain(row.name) in key_text
                assert _plain(row.marks) in key_text
            if ecf_note(question, part_index):
                assert "ecf: a wrong answer" in key_text
    for _, _, code in question.mark_lines():
        assert code in key_text
    sheet = sheet_body(question)
    assert [int(n) for n in re.findall(r'class="sb-marks">\[(\d+)\]', sheet)] == question.part_marks()


def test_a_graph_inlined_keeps_its_references_with_ids_of_its_own():
    from physics_figures.figures.question_graph import question_graph

    question = TOPIC.by_key["graph-kick-force-time"].variant(TOPIC.by_key["graph-kick-force-time"].reserve_variants[0])
    drawn = question_graph(question.graph)
    svg = inline_svg(drawn.svg(), prefix="k-3-", alt=drawn.alt)
    drawn.figure.clear()
    ids = re.findall(r'\sid="([^"]+)"', svg)
    referred = set(re.findall(r'(?:href="#|url\(#)([^")]+)', svg))
    assert ids and all(i.startswith("k-3-") for i in ids)
    assert referred <= set(ids)  # every reference finds its element
    assert svg.startswith("<svg") and 'role="img"' in svg and "<metadata" not in svg and "\n" not in svg


#: a graph, a diagram, a choice question (its text kept with its options), a sketch, text parts
JOINED = ["graph-kick-force-time", "puck-components", "falling-graph-choice", "sketch-bounce-force",
          "state-first-law", "practice-towing"]


def _graph_svg(name: str) -> str:
    """A stand-in for a graph as the build draws it (inline_svg; the site's test joins the drawn
    ones): the same axes and grid in every variant, a line of the variant's own, and ids of its
    own that both refer to."""
    prefix = short_prefix(name)
    grid = "".join(f"M{x} 200V10" for x in range(40, 300, 5))
    return (f'<svg viewBox="0 0 300 240" role="img" aria-label="A graph."><g><g><path d="{grid}" '
            f'clip-path="url(#{prefix}0)"/></g><g><path d="M40 200L{len(name)} 50" '
            f'clip-path="url(#{prefix}0)"/></g></g>'
            f'<defs><clipPath id="{prefix}0"><rect x="40" y="10" width="250" height="190"/></clipPath></defs></svg>')


def test_the_builder_joins_each_variant_s_sheet_and_key_as_physics_figures_wrote_them():
    """The data file holds each sheet and key as pieces, a piece that several print once
    (sheet_pieces.py); the builder's page joins them (sheet-builder.js, variantHtml) into the
    HTML physics_figures wrote, byte for byte, each graph with its own ids."""
    graphs: dict[str, str] = {}
    data = builder_pages(TOPIC, lambda name, _: graphs.setdefault(name, _graph_svg(name)), keys=JOINED)
    joined = joined_pages(data)
    assert {key for key, _ in joined} == set(JOINED)
    written = texts_held_once = 0
    held = data["pieces"] + [p for v in data["variants"].values() for page in v.values()
                             for p in page["sheet"] + page["key"] if isinstance(p, str)]
    for (key, variant), page in joined.items():
        question = TOPIC.by_key[key].variant(int(variant))
        sheet = sheet_body(question, graphs.get(f"{key}-{variant}", ""))
        assert page["sheet"] == sheet, (key, variant)
        assert page["key"] == key_body(question), (key, variant)
        if len(question.text_html()) > LONGEST_WHOLE:  # a short text is in one short piece with its <div>
            assert sum(piece.count(question.text_html()) for piece in held) == 1, (key, variant)  # for both
            texts_held_once += 1
        written += len(sheet) + len(page["key"])
    ids = re.findall(r'\sid="([^"]+)"', "".join(page["sheet"] for page in joined.values()))
    assert len(ids) == len(set(ids)) >= len(graphs)  # each graph's ids its own
    assert texts_held_once >= 30
    held_bytes = len(json.dumps([data["pieces"], data["variants"]], ensure_ascii=False))
    assert held_bytes < 0.7 * written, f"{held_bytes:,} of {written:,}"  # these templates: 0.65
