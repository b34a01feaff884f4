"""Every book figure carries its data table and a longer description (issue 28, item 1),
without the site: what ``BookFigure`` hands the page."""

import re

import numpy as np
import pytest

from physics_figures import scenarios
from physics_figures.figures import book
from physics_figures.figures._data import Column, curve_rows, description, figure_data, round_steps
from physics_figures.figures.book_figure import FigureData, description_id
from physics_figures.notation import UNIT_SPACE, VALUE_WITH_UNIT

BOOK_FIGURES = {
    "velocity-time": lambda: book.skydiver_velocity_time(scenarios.SKYDIVER),
    "resultant-force": lambda: book.skydiver_resultant_force(scenarios.SKYDIVER),
    "drag": lambda: book.drag_against_speed(scenarios.SKYDIVER),
    "thrown": lambda: book.thrown_upwards(scenarios.THROWN_BALL, scenarios.THROWN_BALL_IN_VACUUM),
    "free-body-skydiver": lambda: book.free_body_skydiver(scenarios.SKYDIVER),
    "free-body-book": book.free_body_book,
    "car": lambda: book.car_momentum_time(scenarios.CAR_HISTORY, mass=scenarios.CAR_MASS),
    "force-time": lambda: book.force_time_area(scenarios.CAR_HISTORY),
    "pucks": lambda: book.pucks_triangle(scenarios.PUCKS_PQ),
    "example-4": lambda: book.example4_triangle(scenarios.EXAMPLE_4),
    "collision": lambda: book.collision_before_after(**scenarios.STICKING_TROLLEYS),
}


@pytest.fixture(scope="module", params=sorted(BOOK_FIGURES))
def figure(request):
    return BOOK_FIGURES[request.param]()


def test_every_book_figure_has_a_table_and_a_longer_description(figure):
    assert figure.data is not None and 2 <= len(figure.data.rows) <= 25, figure.name
    assert len(figure.description) > len(figure.alt) / 2 and len(figure.description) > 200
    assert all(len(row) == len(figure.data.headings) for row in figure.data.rows)
    # only a label column (the first: "A", "top, in a vacuum") may leave a row unnamed
    assert all(cell for row in figure.data.rows for cell in row[1:]), "an empty value: write a dash"


def test_the_description_and_table_never_break_a_value_from_its_unit(figure):
    text = re.sub(r"<[^>]+>", "\n", figure.data_html())  # every cell and caption on its own
    split = [m[0] for m in VALUE_WITH_UNIT.finditer(text) if " " in m[0]]
    assert not split, split


def test_the_figure_output_carries_the_disclosure_after_the_caption(figure):
    markdown = figure._repr_mimebundle_()["text/markdown"]
    comment, _caption, disclosure = markdown.strip().split("\n\n")
    assert comment == f"% physics-figure {figure.name}"
    # one line: a blank line would end Markdown's HTML block before the table does
    assert "\n" not in disclosure
    assert disclosure.startswith(f'<p class="figure-description" id="{description_id(figure.name)}" hidden>')
    assert '<details class="figure-data"><summary>Data' in disclosure
    headings = re.findall(r'<th scope="col">([^<]*)</th>', disclosure)
    assert len(headings) == len(figure.data.headings)
    assert re.search(r"<caption id=\"[^\"]+\">[^<]+</caption>", disclosure)


def test_a_row_with_the_wrong_number_of_cells_is_refused():
    with pytest.raises(ValueError, match=r"row .* has 1 cells; a row needs one per heading"):
        FigureData("caption", ("a / s", "b / m"), (("1",),))


def test_columns_of_different_lengths_are_refused():
    with pytest.raises(ValueError, match=r"columns have \[1, 2\] values"):
        figure_data("caption", [Column("a / s", [1.0], 2), Column("b / m", [1.0, 2.0], 2)])


def test_a_description_writes_the_true_minus_and_joins_units():
    assert description("ends at -20 m s⁻¹.", "Velocity-time") == "ends at \u221220\u00a0m\u00a0s⁻¹. Velocity-time"


def test_round_steps_are_round_and_cover_the_range():
    assert list(round_steps(0, 30)) == list(np.arange(0, 31, 2.0))
    assert list(round_steps(0, 4.08, count=8)) == [0, 0.5, 1, 1.5, 2, 2.5, 3, 3.5, 4]
    with pytest.raises(ValueError, match="high = 0 must be more than low = 0"):
        round_steps(0, 0)


def test_a_curve_is_read_along_the_drawn_line_with_its_points_in_place():
    labels, x, y = curve_rows([0, 10], [0, 100], {"P": (5.0, 50.0)}, count=5)
    assert x == [0, 2, 4, 5, 6, 8, 10]
    assert y == [0, 20, 40, 50, 60, 80, 100]
    assert labels == ["", "", "", "P", "", "", ""]
    # a reading where a point sits is not printed twice
    labels, x, _ = curve_rows([0, 10], [0, 100], {"P": (4.0, 40.0)}, count=5)
    assert x.count(4.0) == 1 and labels[x.index(4.0)] == "P"


def test_cells_are_written_as_the_book_writes_numbers():
    data = figure_data("c", [Column("p / kg m s⁻¹", [12_000.0, -2000.0, None], 3)])
    assert [row[0] for row in data.rows] == ["12\u202f000", "−2000", "–"]  # noqa: RUF001
    assert UNIT_SPACE not in data.rows[0][0]
