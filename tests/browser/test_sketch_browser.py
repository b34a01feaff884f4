"""Sketch parts on the built site, in Debian's Chromium at 390 and 1280 px (issue 38, item 3):
for each sketch template, the right sketch and three wrong ones, drawn by pointer (mouse moves
on the printed axes) and built by keyboard (a start value, then segments), earn the marks the
scheme's features give (the points each line keeps: physics_figures.bank.sketches), shown in the
form's .q-score as "k/n marks". The part is a fieldset.q-part[data-kind="sketch"]."""

from __future__ import annotations

import math

import pytest
from browser import site_pages

from physics_figures.bank import sketches

pytestmark = [pytest.mark.site, pytest.mark.browser]

VIEWPORTS = {"phone": {"width": 390, "height": 844}, "laptop": {"width": 1280, "height": 800}}
#: Pointer moves in a stroke: about what a pointer reports in a steady half-second stroke (60 a
#: second), spread over the line's segments, at least two a segment (a curve's many short
#: segments are already its shape; each move costs the page a redraw).
STROKE_MOVES = 36


def _lines(question) -> list[tuple[str, tuple, int]]:
    part = question.parts[0]
    return [("the right sketch", part.model, len(part.points))] + [(w.name, w.line, len(w.keeps)) for w in part.wrong]


def _page_of(site_dir, key: str) -> str:
    found = [p for p in site_pages(site_dir) if f'data-question="{key}"' in (site_dir / p).read_text()]
    assert found, f"no page asks {key}"
    return found[0]


# ------------------------------------------------------------------ the line, as a keyboard recipe

def _direction(line, i, level_slope) -> str:
    (t0, y0), (t1, y1) = line[i], line[i + 1]
    if t1 == t0:
        return "step-up" if y1 > y0 else "step-down"
    slope = (y1 - y0) / (t1 - t0)
    return "level" if abs(slope) < level_slope else "rising" if slope > 0 else "falling"


def _shape(run) -> str:
    """straight, steeper or less steep: the run's gradient over its last third against its first."""
    third = max(1, (len(run) - 1) // 3)
    first = abs((run[third][1] - run[0][1]) / (run[third][0] - run[0][0]))
    last = abs((run[-1][1] - run[-1 - third][1]) / (run[-1][0] - run[-1 - third][0]))
    if last > 1.3 * first:
        return "steeper"
    return "less" if last < first / 1.3 else "straight"


def recipe(line, axes) -> list[tuple[str, str, float, float]]:
    """The segments a student types to build ``line``: runs of one direction (a gradient under a
    tenth of the axes' span over the time axis counts as level), each straight, steeper or less
    steep; a jump at one time is a step."""
    level_slope = 0.1 * (axes.y_max - axes.y_min) / axes.t_max
    steps, i = [], 0
    while i < len(line) - 1:
        kind, j = _direction(line, i, level_slope), i + 1
        while kind[:4] != "step" and j < len(line) - 1 and _direction(line, j, level_slope) == kind:
            j += 1
        run = line[i:j + 1]
        shape = _shape(run) if kind in ("rising", "falling") else "straight"
        steps.append((kind, shape, run[-1][0], run[-1][1]))
        i = j
    return steps


# ------------------------------------------------------------------ drawing and building

def _to_screen(page, key):
    """The map from the axes' (t, y) to the screen's pixels: read from the page once (its SVG's
    plot box, ranges and transform), then applied in Python (it is affine)."""
    plot, t, y, ctm = page.evaluate(
        """(key) => {
          const svg = document.querySelector(`form[data-question="${key}"] fieldset.q-part[data-kind="sketch"] svg`);
          const numbers = (text) => text.split(' ').map(Number);
          const m = svg.getScreenCTM();
          return [numbers(svg.dataset.plot), numbers(svg.dataset.t), numbers(svg.dataset.y), [m.a, m.b, m.c, m.d, m.e, m.f]];
        }""", key)
    (left, top, right, bottom), (t0, t1), (y0, y1), (a, b, c, d, e, f) = plot, t, y, ctm

    def screen(point):
        x = left + (point[0] - t0) / (t1 - t0) * (right - left)
        u = bottom - (point[1] - y0) / (y1 - y0) * (bottom - top)
        return a * x + c * u + e, b * x + d * u + f
    return screen


def draw_by_pointer(page, form, line) -> None:
    """Presses at the line's start and moves along it, STROKE_MOVES pointer moves in all."""
    form.locator("fieldset.q-part[data-kind='sketch'] svg.q-sketch-axes").scroll_into_view_if_needed()
    screen = _to_screen(page, form.get_attribute("data-question"))
    page.mouse.move(*screen(line[0]))
    page.mouse.down()
    moves = max(2, math.ceil(STROKE_MOVES / (len(line) - 1)))
    for point in line[1:]:
        page.mouse.move(*screen(point), steps=moves)  # evenly spaced moves from the last point
    page.mouse.up()


def build_by_keyboard(page, form, line, axes) -> list[str]:
    """Types the line in: its start, then each segment; returns what the status line announced."""
    pad = form.locator("fieldset.q-part[data-kind='sketch'] .q-sketch-pad")
    keys = pad.locator(".q-sketch-keys")
    if keys.get_attribute("open") is None:
        keys.locator("summary").focus()
        page.keyboard.press("Enter")
    said = []
    pad.locator(".q-sketch-start").fill(f"{line[0][1]:g}")
    pad.locator(".q-sketch-set-start").focus()
    page.keyboard.press("Enter")
    said.append(pad.locator(".q-sketch-status").text_content())
    for kind, shape, until, to in recipe(line, axes):
        pad.locator(".q-sketch-kind").select_option(kind)
        if kind in ("rising", "falling"):
            pad.locator(".q-sketch-shape").select_option(shape)
        if not kind.startswith("step"):
            pad.locator(".q-sketch-until").fill(f"{until:.6g}")
        if kind != "level":
            pad.locator(".q-sketch-to").fill(f"{to:.6g}")
        pad.locator(".q-sketch-add").focus()
        page.keyboard.press("Enter")
        said.append(pad.locator(".q-sketch-status").text_content())
    return said


def _check(page, form) -> str:
    form.locator("button.q-check").click()
    return form.locator(".q-score").text_content()


@pytest.mark.parametrize("size", VIEWPORTS)
@pytest.mark.parametrize("template", sketches.TEMPLATES, ids=lambda t: t.key)
def test_each_sketch_earns_the_marks_its_features_give(site_dir, base_url, browser, template, size):
    question = template.variant(0)
    axes = question.parts[0].axes
    page = browser.new_page(viewport=VIEWPORTS[size])
    errors = []
    page.on("pageerror", lambda error: errors.append(str(error)))
    page.goto(f"{base_url}/{_page_of(site_dir, template.key)}#question-{template.key}")
    form = page.locator(f'form.q-form[data-question="{template.key}"]')
    assert form.locator('fieldset.q-part[data-kind="sketch"]').count() == 1
    total = len(question.parts[0].points)
    got = []
    for name, line, keeps in _lines(question):
        for how in ("pointer", "keyboard"):
            form.locator(".q-sketch-clear").click()
            if how == "pointer":
                draw_by_pointer(page, form, line)
            else:
                said = build_by_keyboard(page, form, line, axes)
                assert said[0].startswith("The line starts at t = 0 s"), said
                assert all(s.startswith("Added ") for s in said[1:]), said
            got.append((name, how, _check(page, form), f"{keeps}/{total} marks"))
            # the feedback names each feature found (✓) and each missing (✗)
            feedback = form.locator(".q-feedback").text_content()
            got.append((name, how + " (feedback)", feedback.count("✓ ") + feedback.count("✗ "), total + 1))
    page.close()
    assert not errors
    wrong = [f"{name} by {how}: {score}, the features give {want}" for name, how, score, want in got if score != want]
    assert not wrong, "\n".join(wrong)


def test_the_drawing_area_alone_takes_touch_and_undo_brings_a_line_back(site_dir, base_url, browser):
    template = sketches.TEMPLATES[0]
    page = browser.new_page(viewport=VIEWPORTS["phone"])
    page.goto(f"{base_url}/{_page_of(site_dir, template.key)}#question-{template.key}")
    form = page.locator(f'form.q-form[data-question="{template.key}"]')
    part = form.locator('fieldset.q-part[data-kind="sketch"]')
    assert part.locator("svg.q-sketch-axes").evaluate("e => getComputedStyle(e).touchAction") == "none"
    assert part.evaluate("e => getComputedStyle(e).touchAction") != "none"
    line = template.variant(0).parts[0].model
    draw_by_pointer(page, form, line)
    points = part.locator("polyline.q-sketch-line").get_attribute("points")
    part.locator(".q-sketch-clear").click()
    assert part.locator("polyline.q-sketch-line").get_attribute("points") == ""
    assert part.locator(".q-sketch-status").text_content() == "Line cleared."
    part.locator(".q-sketch-undo").click()
    assert part.locator("polyline.q-sketch-line").get_attribute("points") == points
    page.close()
