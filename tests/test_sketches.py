"""The sketch templates (physics_figures.bank.sketches), marked by the browser's own sketch
marker (question-kinds/sketch.js, under Node): in every variant the model line earns every
marking point, and each wrong line students draw earns exactly the points it declares it keeps;
every point cites the paper it follows; the axes hold the lines."""

from __future__ import annotations

import json
import subprocess
from pathlib import Path

import pytest
from test_questions_engine import node

from physics_figures.bank import sketches
from physics_figures.parts.sketch import Feature, SketchAxes, SketchPart, SketchPoint

ROOT = Path(__file__).resolve().parent.parent


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
