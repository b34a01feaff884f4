"""Figures draw what the models compute, label it with units, and describe it in words.

Numbers asserted against the notes cite the notes' section. Image baselines live in
test_figures_images.py.
"""

import numpy as np
import pytest

from physics_figures import scenarios
from physics_figures.figures import book
from physics_figures.figures.drag import plot_drag_against_speed, plot_thrown_upwards
from physics_figures.figures.free_body import plot_book_on_table, plot_skydiver_free_body
from physics_figures.figures.momentum_graphs import plot_force_time_area, plot_momentum_time
from physics_figures.figures.skydiver import plot_resultant_force, plot_velocity_time
from physics_figures.figures.vectors import plot_momentum_triangle
from physics_figures.notation import format_number

SKYDIVER = scenarios.SKYDIVER


def _tip_and_tail(arrow):
    return np.array(arrow.xyann), np.array(arrow.xy)


# --- skydiver (Notes, "Friction, drag and terminal velocity") ---


def test_velocity_time_curve_is_the_models_velocity():
    graph = plot_velocity_time(SKYDIVER)
    np.testing.assert_array_equal(graph.curve.get_xdata(), SKYDIVER.time)
    np.testing.assert_array_equal(graph.curve.get_ydata(), SKYDIVER.velocity)


def test_points_a_to_e_sit_at_the_models_points():
    graph = plot_velocity_time(SKYDIVER)
    expected = np.array([SKYDIVER.points[p] for p in "ABCDE"])
    np.testing.assert_array_equal(graph.markers.get_xydata(), expected)
    for label in "ABCDE":
        assert graph.point_labels[label].get_text() == label
        assert graph.point_labels[label].xy == SKYDIVER.points[label]


def test_both_terminal_velocities_are_dashed_lines_at_50_and_5():
    # Notes: terminal velocity 50 m s^-1, then 5.0 m s^-1 with the parachute open
    graph = plot_velocity_time(SKYDIVER)
    levels = [line.get_ydata()[0] for line in graph.guides]
    assert levels == [50.0, 5.0]
    assert all(line.get_linestyle() == "--" for line in graph.guides)


def test_axis_labels_carry_units():
    graph = plot_velocity_time(SKYDIVER)
    assert graph.axes.get_xlabel() == "time t / s"
    assert graph.axes.get_ylabel().endswith("/ m s⁻¹")
    force = plot_resultant_force(SKYDIVER)
    assert force.axes.get_ylabel().endswith("/ N")


def test_resultant_force_curve_is_the_models_and_starts_at_the_weight():
    graph = plot_resultant_force(SKYDIVER)
    np.testing.assert_array_equal(graph.curve.get_ydata(), SKYDIVER.resultant_force)
    # Notes: at A the only force is the weight, 80 x 9.81 = 785 N
    assert graph.markers.get_ydata()[0] == pytest.approx(785, abs=0.5)


def test_free_body_arrows_are_to_scale_with_the_models_forces():
    # Notes: at C the drag equals the weight, 785 N
    import matplotlib.pyplot as plt

    _, ax = plt.subplots()
    panel = plot_skydiver_free_body(SKYDIVER, "C", ax=ax)
    lengths = {
        name: np.linalg.norm(np.subtract(*_tip_and_tail(force.arrow)))
        for name, force in panel.arrows.items()
    }
    assert lengths["drag"] == pytest.approx(lengths["weight"])
    assert "785 N" in panel.arrows["drag"].label.get_text()


def test_an_arrow_too_long_to_draw_says_so():
    import matplotlib.pyplot as plt

    _, ax = plt.subplots()
    panel = plot_skydiver_free_body(SKYDIVER, "D", ax=ax, max_length=2.4)
    assert "not to scale" in panel.arrows["drag"].label.get_text()
    assert format_number(SKYDIVER.point_drag["D"], 3) in panel.arrows["drag"].label.get_text()


def test_drag_curve_starts_at_the_origin_and_crosses_the_weight_at_terminal_velocity():
    graph = plot_drag_against_speed(SKYDIVER)
    assert (graph.drag_curve.get_xdata()[0], graph.drag_curve.get_ydata()[0]) == (0, 0)
    assert graph.weight_line.get_ydata()[0] == SKYDIVER.weight
    np.testing.assert_allclose(graph.crossing.get_xydata(), [[50.0, SKYDIVER.weight]])


def test_thrown_upwards_draws_both_throws_from_the_model():
    graph = plot_thrown_upwards(scenarios.THROWN_BALL, scenarios.THROWN_BALL_IN_VACUUM)
    velocity, height = graph.with_drag
    np.testing.assert_array_equal(velocity.get_ydata(), scenarios.THROWN_BALL.velocity)
    np.testing.assert_array_equal(height.get_ydata(), scenarios.THROWN_BALL.height)
    vacuum_velocity, _ = graph.without_drag
    np.testing.assert_array_equal(
        vacuum_velocity.get_ydata(), scenarios.THROWN_BALL_IN_VACUUM.velocity
    )
    assert velocity.get_linestyle() != vacuum_velocity.get_linestyle()  # greyscale


# --- momentum-time and force-time (Notes, "Reading a momentum-time graph") ---


def test_momentum_time_segments_are_labelled_with_the_models_forces():
    graph = plot_momentum_time(scenarios.CAR_HISTORY)
    np.testing.assert_array_equal(
        graph.line.get_xydata(),
        np.column_stack([scenarios.CAR_HISTORY.times, scenarios.CAR_HISTORY.momenta]),
    )
    texts = [label.get_text() for label in graph.segment_labels]
    # Notes: 3000 N, then 0, then -2000 N
    assert texts == ["gradient = 3000 N", "gradient = 0", "gradient = −2000 N"]  # noqa: RUF001 (true minus)
    assert graph.axes.get_ylabel() == "momentum p / kg m s⁻¹"


def test_force_time_areas_are_the_changes_in_momentum():
    graph = plot_force_time_area(scenarios.CAR_HISTORY)
    texts = [label.get_text() for label in graph.area_labels]
    # Notes: +12 000 kg m s^-1 gained in 0-4.0 s, 12 000 lost in 10.0-16.0 s
    assert texts == ["area = Δp\n= +12\u202f000 N s", "area = Δp\n= −12\u202f000 N s"]  # noqa: RUF001 (true minus; U+202F groups digits)
    assert len(graph.areas) == 2


# --- vectors (Notes, "Momentum in two dimensions"; Example 4) ---


@pytest.mark.parametrize("collision", [scenarios.PUCKS_PQ, scenarios.EXAMPLE_4])
def test_momentum_arrows_join_tip_to_tail_and_close_the_triangle(collision):
    graph = plot_momentum_triangle(collision)
    before_tail, before_tip = _tip_and_tail(graph.before)
    moving_tail, moving_tip = _tip_and_tail(graph.moving_after)
    struck_tail, struck_tip = _tip_and_tail(graph.struck_after)
    np.testing.assert_array_equal(moving_tail, before_tail)
    np.testing.assert_array_equal(struck_tail, moving_tip)
    np.testing.assert_allclose(struck_tip, before_tip, atol=1e-12)


def test_pucks_triangle_labels_show_the_notes_values():
    # Notes: p_Q = 0.77 N s at 36.8 degrees; components 0.614 along, 0.460 across.
    # The physics issue: p_Q to 3 s.f. (0.767) beside its 3 s.f. components, not 0.77.
    texts = " ".join(t.get_text() for t in plot_momentum_triangle(scenarios.PUCKS_PQ).labels)
    for value in ("1.00 N s", "0.60 N s at 50°", "0.767 N s at 36.8°", "0.614", "0.460"):
        assert value in texts
    assert "0.77 N s" not in texts


def test_a_collision_triangle_is_drawn_as_a_resultant_not_a_closed_triangle():
    """At AS level a closed triangle is vectors adding to zero (an explosion from rest);
    in a collision the momentum before is the resultant of the momenta after."""
    from physics_figures.figures.vectors import momentum_triangle_alt, momentum_triangle_caption

    for collision, names in ((scenarios.PUCKS_PQ, ("P", "Q")), (scenarios.EXAMPLE_4, ("X", "Y"))):
        for text in (momentum_triangle_caption(collision, names=names),
                     momentum_triangle_alt(collision, names=names)):
            assert "resultant" in text
            assert "closes" not in text and "closed" not in text


# --- third-law pairs (Notes, "Newton's third law") ---


def test_each_force_on_the_book_has_an_equal_and_opposite_partner():
    diagram = plot_book_on_table()
    pairs = {"weight": "gravitational", "contact": "contact"}
    for on_book, partner in pairs.items():
        tail, tip = _tip_and_tail(diagram.on_book[on_book].arrow)
        p_tail, p_tip = _tip_and_tail(diagram.partners[partner].arrow)
        np.testing.assert_allclose(tip - tail, -(p_tip - p_tail))


# --- words: captions and alt text carry the key values ---


def test_velocity_time_alt_text_has_the_key_values():
    alt = book.skydiver_velocity_time(SKYDIVER).alt
    for value in ("80 kg", "levels at 50 m/s (C", "parachute opens at 20 s", "takes 2.5 s to fill",
                  "The deceleration is largest at D", "5.0 m/s (E"):
        assert value in alt


def test_skydiver_words_give_the_peak_deceleration_in_g():
    # Issue 12: the figures and the free-body diagram show a peak deceleration of a few g
    # (about 4 g for the notes' skydiver; the instant opening gave 99 g and "78 400 N").
    in_g = -SKYDIVER.point_acceleration["D"] / SKYDIVER.g
    assert 2 < in_g < 6
    for figure in (book.skydiver_velocity_time(SKYDIVER), book.skydiver_resultant_force(SKYDIVER),
                   book.free_body_skydiver(SKYDIVER)):
        assert f"about {format_number(in_g, 2)} g" in figure.caption
        assert "4.0 g" in figure.alt
    free_body = book.free_body_skydiver(SKYDIVER)
    assert "39.7 m s⁻²" in free_body.caption and "(3960 N)" in free_body.caption


def test_resultant_force_graph_shows_the_dip_at_d_on_the_scale():
    # The canopy fills over 2.5 s: the largest upward force, at D, is about 4 weights and
    # fits on the graph (the instant opening went off the scale at -77 600 N).
    graph = plot_resultant_force(SKYDIVER)
    d = list(SKYDIVER.points).index("D")
    f_d = SKYDIVER.point_resultant_force["D"]
    assert graph.markers.get_ydata()[d] == f_d == SKYDIVER.resultant_force.min()
    assert -6 * SKYDIVER.weight < f_d < -2 * SKYDIVER.weight
    assert graph.axes.get_ylim()[0] < f_d
    texts = [t.get_text() for t in graph.axes.texts]
    assert not any("off the scale" in t for t in texts)


def test_the_opening_is_marked_before_d_on_both_graphs():
    for graph in (plot_velocity_time(SKYDIVER), plot_resultant_force(SKYDIVER)):
        line, label = graph.opening
        assert set(line.get_xdata()) == {SKYDIVER.parachute_opens_at}
        assert SKYDIVER.parachute_opens_at < SKYDIVER.points["D"][0]
        assert label.get_text() == "parachute opens"


def test_thrown_upwards_caption_says_the_ball_takes_longer_to_come_down():
    # Issue 12 (15): 1.60 s up, 1.80 s down for the ball thrown at 20 m/s with v_t = 20 m/s.
    caption = book.thrown_upwards(scenarios.THROWN_BALL, scenarios.THROWN_BALL_IN_VACUUM).caption
    assert "It takes longer to come down (1.80 s) than to go up (1.60 s)." in caption


def test_collision_words_give_the_notes_totals():
    # Notes: 3.0 kg at 4.0 m s^-1 sticks to 1.0 kg: 12 kg m s^-1 throughout, 24 J -> 18 J
    figure = book.collision_before_after(**scenarios.STICKING_TROLLEYS)
    assert "total momentum 12 kg m/s, total kinetic energy 24 J" in figure.alt
    assert "total momentum 12 kg m/s, total kinetic energy 18 J" in figure.alt
    assert "from 24 J to 18 J" in figure.caption


def test_car_alt_text_has_the_gradients():
    alt = book.car_momentum_time(scenarios.CAR_HISTORY, mass=scenarios.CAR_MASS).alt
    for value in ("gradient 3000 N", "gradient 0", "gradient -2000 N", "8.0 m/s"):
        assert value in alt


def test_every_book_figure_has_a_name_caption_and_alt_text():
    figures = _all_book_figures()
    assert len({f.name for f in figures}) == 11
    for figure in figures:
        assert figure.name.startswith("fig-")
        assert len(figure.caption) > 40 and len(figure.alt) > 80
        bundle = figure._repr_mimebundle_()
        assert bundle["text/plain"] == figure.alt
        assert bundle["text/markdown"].startswith(f"% {book.FIGURE_MARKER} {figure.name}\n")
        assert set(bundle) == {"image/svg+xml", "application/pdf", "text/markdown", "text/plain"}


def _all_book_figures():
    s = scenarios
    return [
        book.skydiver_velocity_time(s.SKYDIVER),
        book.skydiver_resultant_force(s.SKYDIVER),
        book.free_body_skydiver(s.SKYDIVER),
        book.drag_against_speed(s.SKYDIVER),
        book.thrown_upwards(s.THROWN_BALL, s.THROWN_BALL_IN_VACUUM),
        book.car_momentum_time(s.CAR_HISTORY, mass=s.CAR_MASS),
        book.force_time_area(s.CAR_HISTORY),
        book.free_body_book(),
        book.collision_before_after(**s.STICKING_TROLLEYS),
        book.pucks_triangle(s.PUCKS_PQ),
        book.example4_triangle(s.EXAMPLE_4),
    ]


# --- output: small, text as text, the same bytes every time ---


def test_svg_keeps_text_as_text_and_is_small():
    svg = book.skydiver_velocity_time(SKYDIVER).svg()
    assert "<text" in svg and "terminal velocity 50 m s⁻¹" in svg
    assert '<path id="DejaVu' not in svg  # no glyph outlines
    assert len(svg) < 40_000


def test_rendering_twice_gives_byte_identical_svg_and_pdf():
    # the same figure saved twice (the page saves SVG then PDF), and a second one made afresh
    first = book.free_body_book()
    svg, pdf = first.svg(), first.pdf()
    assert first.svg() == svg
    assert first.pdf() == pdf
    again = book.free_body_book()
    assert again.svg() == svg


def test_svg_is_the_same_in_a_fresh_process():
    import subprocess
    import sys

    code = (
        "from physics_figures.figures import book; from physics_figures import scenarios;"
        "import sys; sys.stdout.write(book.pucks_triangle(scenarios.PUCKS_PQ).svg())"
    )
    other = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True
    ).stdout
    assert other == book.pucks_triangle(scenarios.PUCKS_PQ).svg()


def test_a_plot_draws_into_a_given_axes():
    import matplotlib.pyplot as plt

    _, ax = plt.subplots()
    assert plot_velocity_time(SKYDIVER, ax=ax).axes is ax
