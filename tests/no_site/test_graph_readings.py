# ruff: noqa: RUF001, RUF002  (typeset text: en dashes, the true minus)
"""Graph questions read as an examiner reads them (issue 25): a reading taken from a graph keeps
its ± half a small square wherever it enters a later part, and the alt text describes the graph
without giving away a value a part asks to be read.

The band of a later part (Part.band) is checked against the models here, not against the
template's own function: the kick's impulse is the area under the force–time line through the
readings (physics_figures.models.area_under_force_time). The browser's engine marks the bank's
own data under Node (tests/js/mark_questions.js), and the Moodle export is tried as Moodle tries
its answers (the first range that holds a response).
"""

from __future__ import annotations

import itertools
import math
import re

import pytest
from graph_grid import grid_squares
from moodle_format import _first_match
from support.engine import mark_questions
from support.templates import typed
from svg_compact import svg_file  # book/_ext (conftest puts it on the path)

from physics_figures import bank
from physics_figures import questions as q
from physics_figures.figures.question_graph import question_graph, question_graph_alt, small_square
from physics_figures.models import area_under_force_time, velocity_from_momentum
from physics_figures.notation import format_number
from physics_figures.worksheets.moodle import graded_answers

GRAPH_TEMPLATES = [t for t in bank.TEMPLATES.values() if t.variant(0).graph is not None]
#: Those whose parts read the graph ("which graph?" items show one to choose from, no reading).
READING_TEMPLATES = [t for t in GRAPH_TEMPLATES if "graph" in t.kinds]
KICK = bank.TEMPLATES["graph-kick-force-time"]


def test_the_graph_templates_are_found():
    assert len(GRAPH_TEMPLATES) >= 6
    assert KICK in GRAPH_TEMPLATES


# ---------------------------------------------------------------- the kick, by hand and model


def _kick(variant: int = 0):
    question = KICK.variant(variant)
    graph = question.graph
    times, forces = zip(*graph.points, strict=True)
    return question, graph, times, max(forces)


def _answers(question, impulse: float, sig_figs: int) -> dict:
    """(b) and (c) worked from an impulse, written to sig_figs s.f.; (a) left empty."""
    mass = question.givens[0].value
    return {"b": {"value": typed(impulse, sig_figs), "unit": "N s"},
            "c": {"value": typed(velocity_from_momentum(impulse, mass), sig_figs), "unit": "m s^-1"}}


def test_the_kick_s_impulse_from_one_corner_read_half_a_small_square_out_earns_full_marks():
    """The issue's case: the time the force reaches its top read half a small square late gives
    7.9 N s for the key's 8.0 N s; it scored 0/2. Every corner of the readings' box (the top
    and the three turns, each half a square out either way) now earns (b) and (c) in full, at
    2 and at 3 s.f."""
    question, graph, times, peak = _kick()
    half_time, half_force = graph.time_division / 2, graph.value_division / 2
    late = area_under_force_time((0.0, times[1] + half_time, *times[2:]), (0.0, peak, peak, 0.0))
    assert typed(late, 2) == "7.9" and typed(question.parts[1].value, 2) == "8.0"
    cases = [(question.browser_data(), _answers(question, late, 2))]
    for signs in itertools.product((-1, 1), repeat=4):
        top = peak + signs[0] * half_force
        read = [t + s * half_time for t, s in zip(times[1:], signs[1:], strict=True)]
        impulse = area_under_force_time((0.0, *read), (0.0, top, top, 0.0))
        cases += [(question.browser_data(), _answers(question, impulse, sig_figs)) for sig_figs in (2, 3)]
    for marked in mark_questions(cases):
        assert marked["marks"]["byPart"]["b"] == [2, 2], marked["results"]["b"]
        assert marked["marks"]["byPart"]["c"] == [2, 2], marked["results"]["c"]


def test_the_kick_s_impulse_from_corners_read_two_small_squares_out_earns_nothing():
    question, graph, times, peak = _kick()
    square = graph.time_division
    # the top's two corners each read two squares towards the middle: the flat top too short
    impulse = area_under_force_time((0.0, times[1] + 2 * square, times[2] - 2 * square, times[3]),
                                    (0.0, peak, peak, 0.0))
    low, high = question.parts[1].band
    assert not low <= impulse <= high
    for sig_figs in (2, 3):
        marked = mark_questions([(question.browser_data(), _answers(question, impulse, sig_figs))])[0]
        assert marked["marks"]["byPart"]["b"] == [0, 2], marked["results"]["b"]
        assert marked["results"]["b"]["code"] != "correct"


def test_moodle_takes_the_kick_s_band_and_still_refuses_what_lies_outside_it():
    """Moodle cannot round a response as the student did: it is given the band as it stands
    (strict), after the key (whose value it shows as the right answer)."""
    question, *_ = _kick()
    low, high = question.parts[1].band
    rows = graded_answers(question, 1)
    ranges = [(grade, value - width, value + width, str(value)) for grade, value, width, _ in rows]
    assert rows[0][1] == pytest.approx(question.parts[1].value)
    for response in (low, high, (low + high) / 2, float(typed(low * 1.001, 3)), float(typed(high * 0.999, 3))):
        assert _first_match(ranges, response)[0] == 100, response
    for response in (low * 0.98, high * 1.02):
        assert (_first_match(ranges, response) or (0,))[0] != 100, response


# ---------------------------------------------------------------- every graph template


def _carried(template):
    """(variant index, question, part index) of each part worked from readings."""
    for index, question in enumerate(template.variants):
        for part_index, part in enumerate(question.parts):
            if getattr(part, "readings", ()):
                yield index, question, part_index


@pytest.mark.parametrize("template", READING_TEMPLATES, ids=lambda t: t.key)
def test_every_part_worked_from_a_reading_carries_the_reading_s_half_square(template):
    """A later part whose error-carried-forward formula uses a part read off the graph is worked
    from readings, so it declares them (Part.readings) and gets their band."""
    for question in template.variants:
        read = {pid for pid, p in zip(question.part_ids, question.parts, strict=True) if p.kind == "graph"}
        for part in question.parts:
            if any(read & set(method.uses) for method in part.ecf_methods):
                assert part.readings, f"{template.key} ({part.prompt}) is worked from {read} with no band"
                assert part.band[0] <= part.value <= part.band[1]


@pytest.mark.parametrize("template", READING_TEMPLATES, ids=lambda t: t.key)
def test_every_corner_of_the_readings_box_is_right_in_the_browser_and_two_squares_out_is_not(template):
    """Each answer that readings half a small square out give (every corner of their box, at 2
    and 3 s.f.) earns the part's marks in the browser's engine; readings two whole squares out
    (four times the tolerance, at the corners that move the answer most) do not."""
    cases, far = [], []
    for _, question, index in _carried(template):
        part = question.parts[index]
        answer = part.answer_from_readings
        box = [(r.value - r.tolerance, r.value + r.tolerance) for r in part.readings]
        for corner in itertools.product(*box):
            value = abs(answer(*corner)) if part.direction != "signed" else answer(*corner)
            for sig_figs in (2, 3):
                assert part.band_takes(float(typed(value, sig_figs)), sig_figs), (template.key, corner)
                cases.append((question, index, value, sig_figs))
        wide = [(r.value - 4 * r.tolerance, r.value + 4 * r.tolerance) for r in part.readings]
        extremes = []
        for corner in itertools.product(*wide):
            try:
                value = answer(*corner)
            except ValueError:  # a line the model cannot draw (the kick's top read shorter than nothing)
                continue
            if value * answer(*(r.value for r in part.readings)) > 0:  # not past what can be (v > vₜ)
                extremes.append(abs(value))
        outside = [v for v in (min(extremes), max(extremes)) if not part.band[0] <= v <= part.band[1]]
        assert outside, (template.key, part.prompt, part.band, extremes)
        far += [(question, index, value, 3) for value in outside]
    assert cases, f"{template.key} has no part worked from readings"

    data = {}  # each variant's marking data, made once for all its cases

    def marked(rows):
        batch = []
        for question, index, value, sig_figs in rows:
            part = question.parts[index]
            answer = {"value": typed(value, sig_figs), "unit": part.unit, "direction": part.answer_direction}
            if id(question) not in data:
                data[id(question)] = question.browser_data()
            batch.append((data[id(question)], {question.part_ids[index]: answer}))
        return zip(rows, mark_questions(batch), strict=True)

    for (question, index, value, sig_figs), result in marked(cases):
        earned, available = result["marks"]["byPart"][question.part_ids[index]]
        assert earned == available, (template.key, value, sig_figs, result["results"][question.part_ids[index]])
    for (question, index, value, _), result in marked(far):
        earned, available = result["marks"]["byPart"][question.part_ids[index]]
        assert earned < available, (template.key, value, result["results"][question.part_ids[index]])


# ---------------------------------------------------------------- alt text


def _numbers(text: str) -> list[float]:
    """The numbers in a text, "1.5 × 10⁵" read as one number."""
    found = []
    for mantissa, power in re.findall(r"([−-]?\d+(?:\.\d+)?)(?: × 10([⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+))?", text):
        exponent = int(power.translate(str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789"))) if power else 0
        found.append(float(mantissa.replace("−", "-")) * 10 ** exponent)
    return found


@pytest.mark.parametrize("template", GRAPH_TEMPLATES, ids=lambda t: t.key)
def test_the_alt_text_gives_axes_scales_and_shape_and_no_reading(template):
    """For every variant: each number in the alt text is an end of an axis or a small square's
    size, and no value a part asks to be read (a GraphPart's value, or a reading a later part
    is worked from), written as the alt text writes that axis's numbers, is in it."""
    for question in template.variants:
        graph = question.graph
        alt = question_graph_alt(graph)
        axes = {0.0, graph.value_min, graph.value_max, graph.time_max, graph.time_division, graph.value_division}
        assert all(any(math.isclose(n, a, abs_tol=1e-12) for a in axes) for n in _numbers(alt)), alt
        assert "graph" in alt and graph.quantity in alt and "time" in alt
        assert re.search(r"(line|curve) (is level|rises|falls)", alt), alt
        halves = {"time": graph.time_division / 2, "value": graph.value_division / 2}
        asked = [(p.value, p.tolerance) for p in question.parts if p.kind == "graph"]
        asked += [(r.value, r.tolerance) for p in question.parts for r in getattr(p, "readings", ())]
        assert asked or template not in READING_TEMPLATES
        shape = alt[alt.index("small squares"):].split(". ", 1)[1]  # after the axes and their scales
        for value, tolerance in asked:
            axis = "time" if math.isclose(tolerance, halves["time"]) else "value"
            division = graph.time_division if axis == "time" else graph.value_division
            places = next(p for p in range(7) if math.isclose(division * 10**p, round(division * 10**p)))
            written = format_number(value, decimals=places)
            assert written not in shape, (template.key, written, alt)
            assert not any(math.isclose(n, value) for n in _numbers(alt)) or any(
                math.isclose(value, a) for a in axes), (template.key, written, alt)


# ---------------------------------------------------------------- what the enlarged view zooms by


@pytest.mark.parametrize("template", GRAPH_TEMPLATES, ids=lambda t: t.key)
def test_the_small_square_the_view_zooms_by_is_the_drawn_grid_s(template):
    """small_square (the button's data-square) agrees with the grid lines in the SVG itself, as
    matplotlib writes it and as the site compacts it (H and V path data: the plot area was once
    read wrong from it, and the enlarged view opened at half its zoom). Four variants: a line
    with level stretches between grid lines must not read as the grid."""
    for index in range(4):
        graph = template.variant(index).graph
        figure = question_graph(graph)
        drawn = figure.svg()
        figure.figure.clear()
        # the compacted SVG's coordinates are to 0.01 of a unit: a grid gap of about 4 units may
        # measure 0.01 less between two of its lines
        for svg, rel in ((drawn, 1e-3), (svg_file(drawn), 5e-3)):
            width, _, across, up = grid_squares(svg)
            assert small_square(svg, graph) == pytest.approx((across / width, up / width), rel=rel), index


def test_small_square_refuses_an_svg_without_its_plot_area():
    with pytest.raises(ValueError, match="plot area"):
        small_square('<svg viewBox="0 0 300 200"></svg>', KICK.variant(0).graph)


# ---------------------------------------------------------------- the band, refused when impossible


def _worked_from_readings(**change) -> q.Question:
    """A trolley-like question: (a) a reading, (b) worked from it and from a second reading."""
    graph = q.Graph("momentum–time", "momentum", "N s", ((0.0, 1.2), (1.0, 1.2), (1.3, 0.4), (3.0, 0.4)),
                    time_division=0.1, value_division=0.05, time_max=3.0, value_max=1.5)
    fields = {"readings": (q.Reading("before", 1.2, 0.025), q.Reading("after", 0.4, 0.025)),
              "answer_from_readings": lambda before, after: (before - after) / 0.5}
    fields.update(change.pop("part", {}))
    worked = q.Part("speed of B", 1.6, "m s^-1", "speed", revisit="B gains what A loses.", **fields)
    reading = q.GraphPart("momentum before", 1.2, "N s", "momentum", tolerance=0.025, revisit="Read it.")
    return q.Question("graph-band", (), (reading, worked), (q.Mark("1.20 N s", "B1", "a"), q.Mark("1.6", "B1", "b")),
                      graph=change.pop("graph", graph))


def test_a_part_s_band_is_what_its_readings_give_within_half_a_square():
    part = _worked_from_readings().parts[1]
    assert part.band == pytest.approx((1.5, 1.7))
    assert part.browser_data("b")["band"] == pytest.approx([1.5, 1.7])
    assert "band" not in bank.TEMPLATES["quick-check-1"].variant(0).parts[0].browser_data("a")
    assert part.band_takes(1.7, 2) and part.band_takes(1.74, 3) is False and part.band_takes(1.4, 2) is False


@pytest.mark.parametrize(("change", "message"), [
    ({"part": {"answer_from_readings": None}}, "readings and answer_from_readings go together"),
    ({"part": {"readings": ()}}, "readings and answer_from_readings go together"),
    ({"part": {"answer_from_readings": lambda before, after: after - before}},
     "answer_from_readings must give the part's value"),
    ({"part": {"readings": (q.Reading("before", 1.2, 0.04), q.Reading("after", 0.4, 0.025))}},
     "tolerance must be half a small square of the graph"),
])
def test_a_band_that_is_not_the_graph_s_is_refused_by_name(change, message):
    with pytest.raises(ValueError, match=re.escape(message)):
        _worked_from_readings(**change)


def test_a_reading_needs_a_tolerance():
    with pytest.raises(ValueError, match="tolerance must be positive"):
        q.Reading("before", 1.2, 0.0)


def test_a_named_mistake_inside_the_band_makes_the_variant_confusable():
    from physics_figures.variants import confusable_mistakes

    mistake = q.Mistake("read one square out", 1.52, "Read again.")
    assert confusable_mistakes(_worked_from_readings(part={"mistakes": (mistake,)})) == ["speed of B: read one square out"]
    far = q.Mistake("gave B A's momentum after", 0.8, "B gains what A loses.")
    assert confusable_mistakes(_worked_from_readings(part={"mistakes": (far,)})) == []
