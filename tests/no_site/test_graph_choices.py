# ruff: noqa: RUF002  (typeset text: en dashes)
""""Which graph?" items (issue 25: choosing the right graph or sketch) and momentum–time graphs
beyond the gradient: the key's sketch is the shape the physics gives (worked here apart from
the template), every option is named by its shape without saying which is right, the site,
the sheets and Moodle each show the four sketches, and a graph's momentum axis grows with
the momenta instead of stopping at 1000 N s."""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET

import numpy
import pytest
from moodle_format import check_file

from physics_figures import bank
from physics_figures.constants import G_EARTH
from physics_figures.parts import OPTION_LETTERS, Sketch
from physics_figures.parts.graph import value_axis
from physics_figures.worksheets import latex
from physics_figures.worksheets import moodle as moodle_export

SKETCH_TEMPLATES = [t for t in bank.TEMPLATES.values()
                    if any(getattr(p, "sketches", False) for q in t.variants[:1] for p in q.parts)]
#: Words that would tell a reader which option is right.
VERDICTS = re.compile(r"\b(correct|right|wrong|key|mistake|answer)\b", re.IGNORECASE)


def _choice(question):
    return next(p for p in question.parts if p.kind == "mcq")


def _key(question) -> Sketch:
    part = _choice(question)
    return part.options[OPTION_LETTERS.index(part.answer)].sketch


def test_there_are_two_which_graph_templates_with_four_or_more_variants_each():
    keys = {t.key: len(t.values) for t in SKETCH_TEMPLATES}
    assert {"force-from-momentum-graph-choice", "falling-graph-choice"} <= set(keys)
    assert all(count >= 4 for count in keys.values()), keys


# ------------------------------------------------------------------ the shapes in words


def test_a_sketch_is_put_into_words_by_its_shape():
    steps = Sketch("resultant force", "F", [(0, 3000), (4, 3000), (4, 0), (10, 0), (10, -2000), (16, -2000)])
    assert steps.describe() == ("Resultant force against time: starts at a positive value, stays constant, "
                                "then jumps to zero, then stays constant, then jumps to a negative value of "
                                "smaller size, then stays constant.")
    times = numpy.linspace(0, 25, 61)
    levelling = Sketch("velocity", "v", list(zip(times, 50 * numpy.tanh(G_EARTH * times / 50), strict=True)))
    assert levelling.describe() == ("Velocity against time: starts at zero, rises ever more slowly to a "
                                    "positive value, then stays constant.")
    through = Sketch("momentum", "p", [(0, 3.0), (4, -3.0)])
    assert through.describe() == ("Momentum against time: starts at a positive value, falls steadily through "
                                  "zero to a negative value of the same size.")


@pytest.mark.parametrize(("points", "message"), [
    ([(0, 1)], "at least two points"),
    ([(0, 1), (2, 3), (1, 0)], "never go back in time"),
    ([(0, 1), (0, 2)], "must span some time"),
    ([(0, math.nan), (1, 2)], "finite"),
])
def test_a_sketch_that_cannot_be_drawn_is_refused_by_name(points, message):
    with pytest.raises(ValueError, match=f"points.*{message}|{message}.*points"):
        Sketch("velocity", "v", points)


@pytest.mark.parametrize("template", SKETCH_TEMPLATES, ids=lambda t: t.key)
def test_every_option_is_named_by_its_shape_without_a_verdict_or_a_reading(template):
    for question in template.variants:
        part = _choice(question)
        assert part.sketches
        data = part.browser_data("a")
        names = []
        for option, shown in zip(part.options, data["options"], strict=True):
            assert shown["html"].startswith("<svg") and shown["sketch"] is True
            label = re.search(r'aria-label="([^"]*)"', shown["html"])[1]
            assert label == option.text == option.sketch.describe()
            assert not VERDICTS.search(label) and not re.search(r"\d", label), label
            names.append(label)
        assert len(set(names)) == len(names), names  # four shapes a reader can tell apart
        assert all(len(o["html"]) < 3000 for o in data["options"])  # small: no library, no fonts


# --------------------------------------------------------------- the keys, worked apart


@pytest.mark.parametrize("index", range(len(bank.TEMPLATES["force-from-momentum-graph-choice"].values)))
def test_the_force_graphs_key_is_the_gradient_of_the_momentum_graph_shown(index):
    question = bank.TEMPLATES["force-from-momentum-graph-choice"].variant(index)
    corners = numpy.array(question.graph.points)
    gradients = numpy.diff(corners[:, 1]) / numpy.diff(corners[:, 0])  # F = Δp / Δt, segment by segment
    key = numpy.array(_key(question).points)
    assert numpy.allclose(key[0::2, 0], corners[:-1, 0]) and numpy.allclose(key[1::2, 0], corners[1:, 0])
    assert numpy.allclose(key[0::2, 1], gradients) and numpy.allclose(key[1::2, 1], gradients)
    # and the misreadings are there: the momentum graph itself is an option, never the key
    shapes = [o.sketch.points for o in _choice(question).options]
    assert tuple(map(tuple, corners)) in shapes and _key(question).points != tuple(map(tuple, corners))


def test_the_skydivers_keys_are_the_shapes_quadratic_drag_gives():
    """v = v_t tanh(g t / v_t) from rest: the velocity rises to v_t, the acceleration falls
    from g to 0, the drag rises from 0 to the weight, the resultant force falls from the
    weight to 0; with the parachute open she slows to the lower terminal velocity, still
    moving down (notes: the skydiver)."""
    template = bank.TEMPLATES["falling-graph-choice"]
    mass, fast, slow = 80.0, 50.0, 5.0
    keys = {_key(q).quantity: _key(q) for q in template.variants if "opens" not in q.text}
    for quantity, start, end in (("velocity", 0.0, fast), ("acceleration", G_EARTH, 0.0),
                                 ("air resistance", 0.0, mass * G_EARTH), ("resultant force", mass * G_EARTH, 0.0)):
        values = numpy.array([y for _, y in keys[quantity].points])
        times = numpy.array([t for t, _ in keys[quantity].points])
        assert values[0] == pytest.approx(start, abs=1e-9) and values[-1] == pytest.approx(end, abs=0.01 * fast)
        steps = numpy.diff(values)
        assert numpy.all(steps >= -1e-9) if end > start else numpy.all(steps <= 1e-9), quantity
        if quantity == "velocity":
            assert values == pytest.approx(fast * numpy.tanh(G_EARTH * times / fast))
    opening = next(_key(q) for q in template.variants if "opens" in q.text)
    speeds = [v for _, v in opening.points]
    top = max(speeds)
    assert top == pytest.approx(fast, rel=0.01) and min(speeds[speeds.index(top):]) > 0.9 * slow
    assert speeds[-1] == pytest.approx(slow, rel=0.02)


# ------------------------------------------------------------------- sheets and Moodle


@pytest.mark.parametrize("template", SKETCH_TEMPLATES, ids=lambda t: t.key)
def test_the_question_sheet_draws_the_four_sketches_and_the_key_names_them(template):
    question = template.variant(0)
    sheet = latex._part(question, 0, 1)
    assert sheet.count(r"\begin{tikzpicture}") == 4
    assert [m for m in re.findall(r"\\textbf\{([A-D])\}", sheet)] == list(OPTION_LETTERS)
    assert "rises" not in sheet and "falls" not in sheet  # the sheet draws, it does not tell
    key = "\n".join(latex._key_part(question, 0, 1))
    part = _choice(question)
    assert f"{part.answer}: " in key and all(o.mistake in key for o in part.options if o.mistake)


def test_moodle_ships_each_sketch_as_an_svg_file_inside_its_option():
    tree, count = moodle_export.export(SKETCH_TEMPLATES)
    root = ET.fromstring(ET.tostring(tree.getroot(), encoding="unicode"))
    problems, _ = check_file(root)
    assert not problems, problems[:10]
    questions = root.findall("question[@type='multichoice']")
    assert len(questions) == sum(len(t.values) for t in SKETCH_TEMPLATES) == count["multichoice"]
    for element in questions:
        answers = element.findall("answer")
        assert len(answers) == 4
        for answer in answers:
            (file,) = answer.findall("file")
            assert file.get("name").endswith(".svg")
            assert f'@@PLUGINFILE@@/{file.get("name")}' in answer.findtext("text")
            assert re.search(r'alt="[^"]+ against time: ', answer.findtext("text"))


# ---------------------------------------------------------------- the momentum axis


def test_the_momentum_axis_grows_with_the_momenta_instead_of_stopping_at_1000_n_s():
    assert value_axis(900.0) == (0.0, 1000.0, 20.0)  # the cyclist's axis as it was
    for high in (1200.0, 12000.0, 60000.0, 2.5e5, 3.7e6):
        low, top, division = value_axis(high)
        squares = (top - low) / division
        assert low == 0 and high < top <= 1.5 * high, (high, top)
        assert 20 <= squares <= 60 and math.isclose(squares, round(squares))
        assert division / 10 ** math.floor(math.log10(division)) in (1, 2, 5)
    low, top, division = value_axis(2.4, -1.6)
    assert low < -1.6 and top > 2.4 and (top - low) / division <= 60


def test_the_lorrys_graph_reaches_its_momenta_and_reads_to_half_a_small_square():
    template = bank.TEMPLATES["graph-lorry-speed-momentum-time"]
    assert len(template.values) >= 10
    for question in template.variants:
        graph = question.graph
        assert max(v for _, v in graph.points) > 1000 and graph.value_max > max(v for _, v in graph.points)
        readings = [p for p in question.parts if p.kind == "graph"]
        assert all(p.tolerance == graph.value_division / 2 for p in readings)
        mass = question.givens[0].value
        speed, gain = (p.value for p in question.parts[2:])
        before, after = (p.value for p in readings)
        assert speed == pytest.approx(after / mass) and gain == pytest.approx((after - before) / mass)
