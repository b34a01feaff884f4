"""The graph cursor's data (issue 28, item 2): what a question's graph lets a student read.

Graph.readings gives the drawn line's value at every half small square of time, to the nearest
half small square of value (a ruler's reading), and nothing where no line is drawn;
cursor_data adds the axes as drawn and the plot area, the same frame small_square measures.
The browser side is tests/browser/test_graph_cursor_browser.py.
"""

from __future__ import annotations

import math

import pytest

from physics_figures.figures.question_graph import cursor_data, question_graph, small_square
from physics_figures.pictures import Graph
from physics_figures.topics import load


def graph_variants() -> list:
    """The printed variant's graph of every template that draws one."""
    topic = load("physics_figures.bank")
    return [pytest.param(template.variant(0).graph, id=key) for key, template in topic.by_key.items()
            if template.variant(0).graph is not None]


@pytest.mark.parametrize("graph", graph_variants())
def test_each_reading_is_the_line_to_the_nearest_half_small_square(graph):
    half_time, half_value = graph.time_division / 2, graph.value_division / 2
    readings = graph.readings()
    assert len(readings) == round(graph.time_max / half_time) + 1
    for index, reading in enumerate(readings):
        time = index * half_time
        if reading is None:
            assert time > graph.points[-1][0] or time < graph.points[0][0]
            continue
        steps = (reading - graph.value_min) / half_value
        assert steps == pytest.approx(round(steps), abs=1e-9), f"{reading} is off the half-square grid"
        assert abs(reading - graph.value_at(time)) <= half_value / 2 + 1e-9


def test_a_reading_rounds_half_away_from_zero_and_stops_where_the_line_does():
    # squares of 1 s by 2 N: half squares of 0.5 s and 1 N
    graph = Graph("force-time", "force", "N", ((0.0, -3.5), (1.0, 0.5), (2.0, 4.0)),
                  time_division=1.0, value_division=2.0, time_max=3.0, value_min=-6.0, value_max=6.0)
    # -3.5, -1.5, 0.5 (on the grid), 2.25 -> 2, 4, then no line at 2.5 and 3 s
    assert graph.readings() == (-4.0, -2.0, 1.0, 2.0, 4.0, None, None)


@pytest.mark.parametrize("graph", graph_variants())
def test_the_cursor_s_plot_area_is_the_frame_the_enlarged_view_measures(graph):
    svg = question_graph(graph).svg()
    data = cursor_data(svg, graph)
    left, top, right, bottom = data["area"]
    assert 0 < left < right < 1 and 0 < top < bottom < 1
    square_width, _ = small_square(svg, graph)
    assert (right - left) / round(graph.time_max / graph.time_division) == pytest.approx(square_width, rel=1e-3)
    assert data["time"]["square"] == graph.time_division and data["value"]["square"] == graph.value_division
    assert data["value"]["min"] == graph.value_min and data["value"]["max"] == graph.value_max
    assert math.isclose(data["time"]["large"] / data["time"]["square"], round(data["time"]["large"] / data["time"]["square"]))
    assert data["readings"] == list(graph.readings())
