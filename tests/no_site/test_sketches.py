"""The sketch templates (physics_figures.bank.sketches), marked by the browser's own sketch
marker (question-kinds/sketch.js, under Node): in every variant the model line earns every
marking point, and each wrong line students draw earns exactly the points it declares it keeps;
every point cites the paper it follows; the axes hold the lines."""

from __future__ import annotations

import json
import subprocess
from pathlib import Path

import pytest
from support.engine import node

from physics_figures.bank import sketches
from physics_figures.parts.sketch import Feature, SketchAxes, SketchPart, SketchPoint

ROOT = Path(__file__).resolve().parents[2]


def mark_lines(cases: list[tuple[dict, tuple]]) -> list[dict]:
    payload = json.dumps([{"part": part, "line": [list(p) for p in line]} for part, line in cases])
    result = subprocess.run([node(), str(ROOT / "tests" / "js" / "mark_sketches.js")], input=payload,
                            capture_output=True, text=True, check=True)
    return json.loads(result.stdout)


def _cases():
    for template in sketches.TEMPLATES:
        for index, question in enumerate(template.variants):
            part = question.parts[0]
            yield template.key, index, "the model line", part, part.model, tuple(range(len(part.points)))
            for wrong in part.wrong:
                yield template.key, index, wrong.name, part, wrong.line, wrong.keeps


def test_there_are_four_sketch_templates_from_the_papers_own_sketch_parts():
    assert [t.key for t in sketches.TEMPLATES] == ["sketch-momentum-from-force", "sketch-force-from-momentum-graph",
                                                   "sketch-skydiver-velocity", "sketch-bounce-force"]
    for template in sketches.TEMPLATES:
        assert len(template.variants) >= 8, template.key
        assert all(len(q.parts[0].wrong) >= 3 for q in template.variants), template.key


def test_every_line_earns_the_points_its_features_give():
    cases = list(_cases())
    marked = mark_lines([(part.browser_data("a"), line) for _, _, _, part, line, _ in cases])
    wrong = [f"{key} variant {index}, {name}: earns {tuple(i for i, e in enumerate(m['earned']) if e)}, "
             f"the scheme's features give {keeps}"
             for (key, index, name, _, _, keeps), m in zip(cases, marked, strict=True)
             if tuple(i for i, e in enumerate(m["earned"]) if e) != tuple(keeps)]
    assert not wrong, "\n".join(wrong)


def test_each_point_is_a_b1_and_cites_its_paper():
    for template in sketches.TEMPLATES:
        question = template.variant(0)
        assert [m.code for m in question.mark_scheme] == ["B1"] * len(question.parts[0].points)
        for point in question.parts[0].points:
            assert point.source.startswith("9702/"), point


def test_the_levels_are_the_models_numbers():
    # momentum from a force: the level is F t (models.impulse): 6.0 N for 2.5 s is 15 N s
    part = sketches.momentum_from_force(6.0, 2.5).parts[0]
    assert part.points[2].needs[0].at == pytest.approx(15.0)
    # the pull X = gradient + 2.0 N friction (9702/21/M/J/23 Q3): 6/2 + 2, 2/2 + 2, 0 + 2
    part = sketches.force_from_momentum_graph(6.0, 8.0, 2.0).parts[0]
    assert [p.needs[0].at for p in part.points] == pytest.approx([5.0, 3.0, 2.0])


def test_a_feature_or_point_that_cannot_be_read_is_refused_by_name():
    with pytest.raises(ValueError, match="stop"):
        Feature("rising", 2.0, 1.0)
    with pytest.raises(ValueError, match="source"):
        SketchPoint("a point", (Feature("start", value="zero"),), "the notes")
    axes = SketchAxes("momentum", "p", "N s", t_max=4.0, t_division=1.0, y_max=10.0, y_division=2.0)
    with pytest.raises(ValueError, match="model"):
        SketchPart("Sketch it.", axes, (SketchPoint("x", (Feature("start", value="zero"),), "9702/21/M/J/23 Q3(c)"),),
                   model=((0.0, 0.0), (5.0, 20.0)))


def test_the_pull_is_the_gradient_plus_the_friction():
    from physics_figures.models import applied_force

    assert applied_force(3.0, 2.0) == pytest.approx(5.0)  # 9702/21/M/J/23 Q3: X = F + 2.0 N
    assert applied_force(-1.0, 2.0) == pytest.approx(1.0)
    with pytest.raises(ValueError, match="opposing_force"):
        applied_force(3.0, -2.0)


# ------------------------------------------------------------------ on paper and in Moodle

def test_the_sheets_print_blank_axes_and_the_key_lists_the_features():
    from physics_figures.worksheets import plan, select
    from physics_figures.worksheets.html import key_body, sheet_body
    from physics_figures.worksheets.latex import answer_key, question_sheet

    keys = [t.key for t in sketches.TEMPLATES]
    sheet = plan("s", "Sketches", select(templates=keys), versions=1, seed=3)
    version = sheet.versions[0]
    # a tie (~) prints as a space, and a break allowed after a slash prints nothing
    tex = question_sheet(sheet, version)
    key = answer_key(sheet, version).replace("~", " ").replace("\\allowbreak{}", "")
    assert tex.count("\\begin{tikzpicture}") == len(keys)  # the axes, and no line on them
    assert "line width=1.2pt" not in tex
    for item in version.items:
        part = item.question.parts[0]
        html, html_key = sheet_body(item.question), key_body(item.question)
        assert 'class="q-sketch-axes"' in html and "q-sketch-model" not in html
        assert "q-sketch-model" in html_key
        for point in part.points:
            assert point.text in key and point.source in key
            assert point.text in html_key


def test_moodle_exports_an_essay_with_the_features_as_the_graders_information():
    import xml.etree.ElementTree as ET

    from physics_figures.worksheets import moodle as moodle_export

    tree, _ = moodle_export.export([sketches.TEMPLATES[1]])
    essays = [q for q in tree.getroot().iter("question") if q.get("type") == "essay"]
    assert len(essays) == len(sketches.TEMPLATES[1].reserve_variants) >= 4
    for essay in essays:
        grader = essay.find("graderinfo/text").text
        assert "one B1 for each feature" in grader and "9702/21/M/J/23 Q3(c)" in grader
        assert any(f.get("name", "").endswith("-axes.svg") for f in essay.iter("file"))
        assert "@@PLUGINFILE@@/" in essay.find("questiontext/text").text
    assert ET.tostring(tree.getroot())
