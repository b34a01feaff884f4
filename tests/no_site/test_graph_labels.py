# ruff: noqa: RUF001, RUF002  (typeset text: the times sign, superscripts, the true minus)
"""A question graph's numbers as Cambridge's own graphs print them (issue 37, "Graph labels";
CLARIFICATIONS, "Graph ticks"): each label a plain number, the power of ten in the axis's
label ("momentum / 10⁵ N s": 0, 0.5, 1.0 …), never "× 10ⁿ" on a label, and no two labels
touching. The key writes a reading in powers of ten to at most 3 figures (1.12 × 10⁵ N s, not
1.12000 × 10⁵ N s), and the marker takes what a student reads off such an axis and types.

Every template × every variant (the site's and the kit's reserve) is drawn here at figure level
and its labels measured by matplotlib's own renderer (get_window_extent); the site's SVGs, the
sheet builder's and the PDFs are read by tests/site/test_graph_labels_site.py.
"""

from __future__ import annotations

import itertools
import json
import re

import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from support.engine import mark_questions
from support.printed_numbers import too_many_figures

from physics_figures import bank
from physics_figures.figures.question_graph import axis_scales, plot_question_graph
from physics_figures.notation import format_number
from physics_figures.worksheets.latex import accept_note


def test_too_many_figures_finds_the_issue_s_numbers_and_passes_the_book_s():
    assert too_many_figures("ticks 1.00000 × 10⁵ and 1.12000 × 10⁵ N s") == ["1.00000 × 10⁵", "1.12000 × 10⁵"]
    assert too_many_figures("accept 1.12000 × 105 N s") == ["1.12000 × 105"]
    assert too_many_figures("1.12 × 10⁵ N s, 2.0 × 10⁻⁴ m, 50 000 N s, 1.5 × 105") == []


def _graph_variants():
    for template in bank.TEMPLATES.values():
        for index, question in enumerate(template.variants):
            if question.graph is not None:
                yield template.key, index, question


def _distinct_axes():
    """One variant of each distinct pair of axes (the labels depend on the axes alone)."""
    seen = {}
    for key, index, question in _graph_variants():
        graph = question.graph
        axes = (graph.time_max, graph.time_division, graph.value_min, graph.value_max, graph.value_division)
        seen.setdefault(axes, (key, index, graph))
    return list(seen.values())


AXES = _distinct_axes()


def test_the_graphs_include_an_axis_of_a_hundred_thousand_or_more():
    """The issue's lorry: momenta of 10⁵ N s and more, on the site and in the kit."""
    assert len(AXES) >= 10
    assert any(graph.value_max >= 1e5 for _, _, graph in AXES)


def _overlaps(boxes, along: str) -> list[tuple[int, int]]:
    """Neighbouring boxes (in order along the axis) that touch or overlap."""
    ordered = sorted(range(len(boxes)), key=lambda i: getattr(boxes[i], f"{along}0"))
    return [(a, b) for a, b in itertools.pairwise(ordered)
            if getattr(boxes[b], f"{along}0") <= getattr(boxes[a], f"{along}1")]


@pytest.mark.parametrize(("key", "index", "graph"), AXES, ids=[f"{k}-{i}" for k, i, _ in AXES])
def test_every_label_is_a_plain_number_and_no_two_labels_touch(key, index, graph):
    drawn = plot_question_graph(graph)
    figure = drawn.axes.figure
    FigureCanvasAgg(figure)
    figure.canvas.draw()
    renderer = figure.canvas.get_renderer()
    every = []
    for axis, along in ((drawn.axes.xaxis, "x"), (drawn.axes.yaxis, "y")):
        labels = [label for label in axis.get_ticklabels() if label.get_visible() and label.get_text()]
        texts = [label.get_text() for label in labels]
        assert len(texts) >= 2, f"{key} {index}: {texts}"
        for text in texts:
            assert re.fullmatch(r"−?\d+(?:[\u202f]\d{3})*(?:\.\d+)?", text), (
                f"{key} variant {index}: the label {text!r} is not a plain number")
        boxes = [label.get_window_extent(renderer) for label in labels]
        touching = [(texts[a], texts[b]) for a, b in _overlaps(boxes, along)]
        assert not touching, f"{key} variant {index}: labels touch or overlap on the {along} axis: {touching}"
        every.append(list(zip(texts, boxes, strict=True)))
    # and where the axes meet: no time label on a value label
    corner = [(a, b) for a, one in every[0] for b, other in every[1] if one.overlaps(other)]
    assert not corner, f"{key} variant {index}: labels of the two axes overlap: {corner}"
    _, value = axis_scales(graph)
    label = drawn.axes.get_ylabel()
    if max(abs(graph.value_min), graph.value_max) >= 1e5:
        assert value.power >= 5 and f"/ 10{str(value.power).translate(str.maketrans('0123456789', '⁰¹²³⁴⁵⁶⁷⁸⁹'))} " in label, (
            f"{key} variant {index}: the axis's label {label!r} does not carry the power of ten")
    else:
        assert "10" not in label.split("/")[-1], label
    figure.clear()


def _key_texts(question) -> list[str]:
    """Everything the key, the worked answer, the help steps and the marker's messages print."""
    texts = [text for _, text, _ in question.mark_lines()]
    for part in question.parts:
        if part.kind in ("numeric", "graph"):
            texts += [part.answer_text, accept_note(part)]
    return [*texts, json.dumps(question.browser_data(), ensure_ascii=False)]


def test_no_key_value_of_any_variant_has_more_than_3_figures_in_powers_of_ten():
    found = {}
    for template in bank.TEMPLATES.values():
        for index, question in enumerate(template.variants):
            bad = sorted({number for text in _key_texts(question) for number in too_many_figures(text)})
            if bad:
                found[f"{template.key} {index}"] = bad
    assert not found, found


def test_the_lorry_s_key_and_working_write_its_momenta_to_3_figures():
    """The issue's own numbers: "1.33000 × 10⁵ N s" in the working, "1.12000 × 10⁵" in the key."""
    template = bank.TEMPLATES["graph-lorry-speed-momentum-time"]
    large = [(question, part) for question in template.variants for part in question.parts[:2] if part.value >= 1e5]
    assert large, "no lorry variant reaches 10⁵ N s"
    for question, part in large:
        written = format_number(part.value, 3)
        assert part.answer_text == f"{written} N s"
        assert any(written in text for _, text, _ in question.mark_lines()), question.mark_lines()


def _reading_cases():
    """(question, part id, what a student reads off the axis in its own numbers, power) for each
    part read off an axis labelled in a power of ten: the key to the nearest half small square."""
    for _, _, question in _graph_variants():
        _, value = axis_scales(question.graph)
        if not value.power:
            continue
        for part_id, part in zip(question.part_ids, question.parts, strict=True):
            if part.kind == "graph":
                read = round(part.value / part.tolerance) * part.tolerance
                yield question, part_id, read / 10**value.power, value.power


def test_a_reading_off_an_axis_in_powers_of_ten_scores_as_the_student_types_it():
    """The student reads 1.15 on "momentum / 10⁵ N s" and types 1.15 × 10^5, 1.15e5, 1.15 x 10⁵
    or 115000: each is right. The bare 1.15 is not (the axis's power is part of the value): it
    is the named mistake that says to multiply by the axis's power of ten."""
    cases, expected = [], []
    for question, part_id, shown, power in _reading_cases():
        scaled = f"{shown:#.3g}"  # as read to half a small square: 1.15, 0.400
        superscript = str(power).translate(str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹"))
        for typed in (f"{scaled} × 10^{power}", f"{scaled}e{power}", f"{scaled} x 10{superscript}",
                      str(round(shown * 10**power)), scaled):
            cases.append((question.browser_data(), {part_id: {"value": typed, "unit": "N s"}}))
            expected.append((question.key, part_id, typed, typed != scaled))
    assert len(expected) >= 10, "no part is read off an axis in powers of ten"
    for (key, part_id, typed, right), marked in zip(expected, mark_questions(cases), strict=True):
        got, out_of = marked["marks"]["byPart"][part_id]
        result = marked["results"][part_id]
        assert (got == out_of) is right, f"{key} ({part_id}) typed {typed!r}: {got}/{out_of} {result}"
        if not right:
            assert result["code"] == "mistake" and "Multiply your reading by 10" in result["message"], result


def test_axis_power_puts_the_power_on_the_axis_only_where_a_label_would_need_it():
    from physics_figures.notation import axis_power, power_text

    assert axis_power(150_000, 25_000) == 5 and power_text(5) == "10⁵"
    assert axis_power(2_250_000, 500_000) == 6
    assert axis_power(80_000, 20_000) == 0  # 80 000 prints as it is
    assert axis_power(0.004, 0.0005) == -3 and power_text(-3) == "10⁻³"
    assert axis_power(3.0, 0.5) == 0
    with pytest.raises(ValueError, match="step must be a positive finite number"):
        axis_power(1.0, 0.0)
