"""Image baselines for what only pixels show: shading, arrow heads, layout, line styles.

Text is removed before comparing (fonts differ between machines). To re-make the
baselines after a deliberate change of look, run with
PHYSICS_FIGURES_REGENERATE_BASELINES=1 and look at tests/baseline/*.png before committing.
"""

import os
from pathlib import Path

import pytest
from matplotlib.testing.compare import compare_images

from physics_figures import scenarios
from physics_figures.figures import book
from physics_figures.style import colour

BASELINE = Path(__file__).parents[1] / "baseline"
REGENERATE = os.environ.get("PHYSICS_FIGURES_REGENERATE_BASELINES") == "1"

FIGURES = {
    "skydiver-velocity-time": lambda: book.skydiver_velocity_time(scenarios.SKYDIVER),
    "force-time-area": lambda: book.force_time_area(scenarios.CAR_HISTORY),
    "free-body-book": book.free_body_book,
    "pucks-triangle": lambda: book.pucks_triangle(scenarios.PUCKS_PQ),
}


def _without_text(figure):
    # empty the strings rather than hiding the Text artists: an arrow is an Annotation
    for text in figure.findobj(lambda artist: hasattr(artist, "set_text")):
        text.set_text("")
    for axes in figure.axes:
        axes.tick_params(labelbottom=False, labelleft=False)
    return figure


@pytest.mark.parametrize("name", FIGURES)
def test_figure_looks_like_its_baseline(name, tmp_path):
    figure = _without_text(FIGURES[name]().figure)
    actual = tmp_path / f"{name}.png"
    figure.savefig(actual, dpi=60, facecolor=colour("figure.paper"))
    expected = BASELINE / f"{name}.png"
    if REGENERATE:
        expected.write_bytes(actual.read_bytes())
    assert expected.exists(), (
        f"no baseline {expected}: run with PHYSICS_FIGURES_REGENERATE_BASELINES=1"
    )
    result = compare_images(str(expected), str(actual), tol=2)
    assert result is None, result
