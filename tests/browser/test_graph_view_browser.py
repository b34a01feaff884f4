# ruff: noqa: RUF001, RUF002  (typeset text: the true minus and times)
"""The enlarged graph view on a 390 × 844 phone, in Debian's Chromium (issue 25, "Done when").

For every graph question on the site (button.q-graph-open around img.q-graph): a tap opens
dialog.q-graph-view, half a small square there is at least 6 CSS px, Escape closes it and
focus is back on the graph's button; focus and Enter open it again, and its Close button
closes it, focus back again; − and + zoom it; after New numbers it shows the new variant's
graph, as readable. It also works in dark mode (the theme's colours), prints as the plain
graph, and axe-core finds nothing in it. It opens with both axes' numbers in view, at 390 px
and at 1280 px (issue 37), as near the middle of the plot as that allows.

How half a small square is measured: from the SVG the view shows, not from anything the view
computes. The test fetches the file the dialog's image loaded (its currentSrc) and takes the
gap between neighbouring grid lines in the SVG's own units (tests/graph_grid.py: matplotlib
draws each grid line as a clipped two-point path), then scales it by the image's rendered size
(getBoundingClientRect of img.q-graph-large) over the SVG's viewBox: a small square's width
and height in CSS px. Half the smaller of the two must be at least 6 CSS px.
"""

from __future__ import annotations

import re
import urllib.request

import pytest
from browser import axe_violations, site_pages
from graph_grid import grid_squares

pytestmark = [pytest.mark.site, pytest.mark.browser]

PHONE = {"width": 390, "height": 844}
TOUCH_PHONE = {"viewport": PHONE, "has_touch": True, "is_mobile": True, "device_scale_factor": 2}
#: Half a small square, CSS px, in the enlarged view at 390 px (issue 25).
LEAST_HALF_SQUARE_PX = 6.0

VIEW = "dialog.q-graph-view"
OPEN = f"document.querySelector('{VIEW}') && document.querySelector('{VIEW}').open"
LOADED = f"""() => {{ const i = document.querySelector('{VIEW} img.q-graph-large');
  return i && i.complete && i.naturalWidth > 0 && i.getBoundingClientRect().width > 0; }}"""
SHOWN = f"""() => {{
  const dialog = document.querySelector('{VIEW}'), image = dialog.querySelector('img.q-graph-large');
  const pane = dialog.querySelector('.q-graph-pane'), box = image.getBoundingClientRect();
  return {{src: image.currentSrc, alt: image.alt, width: box.width, height: box.height,
           dialog: dialog.getBoundingClientRect().width,
           pane: pane.clientWidth - parseFloat(getComputedStyle(pane).paddingLeft)
                 - parseFloat(getComputedStyle(pane).paddingRight),
           touch: getComputedStyle(pane).touchAction, background: getComputedStyle(dialog).backgroundColor}};
}}"""


def graph_questions(site_dir) -> list[tuple[str, str]]:
    """(page, question key) of every question on the site that prints a graph."""
    found = []
    for path in site_pages(site_dir):
        html = (site_dir / path).read_text(encoding="utf-8")
        for section in re.split(r'(?=<section class="q" )', html)[1:]:
            key = re.search(r'data-q="([^"]+)"', section)
            if key and 'class="q-graph-open"' in section.split("</section>", 1)[0]:
                found.append((path, key[1]))
    return found


@pytest.fixture(scope="module")
def questions(site_dir):
    found = graph_questions(site_dir)
    assert len(found) >= 6, f"only {found} print a graph: is the enlarged view's button on the site?"
    return found


def half_square_px(shown: dict) -> float:
    """Half the smaller side of a small square, CSS px, as the SVG's own grid is drawn."""
    with urllib.request.urlopen(shown["src"]) as response:
        svg = response.read().decode("utf-8")
    width, height, across, up = grid_squares(svg)
    return min(across * shown["width"] / width, up * shown["height"] / height) / 2


def _opened(page, opener) -> dict:
    page.wait_for_function(OPEN)
    page.wait_for_function(LOADED)
    shown = page.evaluate(SHOWN)
    assert shown["src"] == opener.locator("img.q-graph").evaluate("i => i.currentSrc")
    assert shown["alt"] == opener.locator("img.q-graph").get_attribute("alt")
    return shown


def _is_focused(page, selector: str) -> bool:
    return page.evaluate(f"document.activeElement === document.querySelector('{selector}')")


def _check_readable(key: str, shown: dict) -> None:
    assert shown["dialog"] >= PHONE["width"] - 1, f"{key}: the view is {shown['dialog']} px wide, not the screen's"
    assert shown["width"] >= shown["pane"] - 1, f"{key}: the graph is narrower than the screen"
    # pan-x pan-y pinch-zoom, which Chromium writes as its short form, manipulation
    assert shown["touch"] == "manipulation" or "pinch-zoom" in shown["touch"], (
        f"{key}: no pinch-zoom in the view ({shown['touch']})")
    half = half_square_px(shown)
    assert half >= LEAST_HALF_SQUARE_PX, f"{key}: half a small square is {half:.2f} CSS px at 390 px"


def test_every_graph_opens_by_tap_and_by_enter_readable_and_closes_by_escape_and_close(browser, base_url, questions):
    context = browser.new_context(**TOUCH_PHONE)
    page = context.new_page()
    errors = []
    page.on("pageerror", lambda error: errors.append(str(error)))
    measured = {}
    for path, key in questions:
        if page.url != f"{base_url}/{path}":
            page.goto(f"{base_url}/{path}", wait_until="load")
        selector = f'section.q[data-q="{key}"] button.q-graph-open'
        opener = page.locator(selector)
        assert opener.count() == 1, f"{key}: no button around its graph"

        opener.scroll_into_view_if_needed()
        opener.tap()
        shown = _opened(page, opener)
        _check_readable(key, shown)
        measured[key] = half_square_px(shown)
        page.keyboard.press("Escape")
        page.wait_for_function(f"!({OPEN})")
        assert _is_focused(page, selector), f"{key}: Escape did not return focus to the graph"

        opener.focus()
        page.keyboard.press("Enter")
        _check_readable(key, _opened(page, opener))
        zoom_in, zoom_out = page.locator(f"{VIEW} button.q-graph-in"), page.locator(f"{VIEW} button.q-graph-out")
        width = page.evaluate(SHOWN)["width"]
        zoom_in.tap()
        assert page.evaluate(SHOWN)["width"] > width * 1.1, f"{key}: + did not zoom in"
        zoom_out.tap()
        assert page.evaluate(SHOWN)["width"] == pytest.approx(width, abs=1.5), f"{key}: − did not zoom back"
        page.locator(f"{VIEW} button.q-graph-close").tap()
        page.wait_for_function(f"!({OPEN})")
        assert _is_focused(page, selector), f"{key}: Close did not return focus to the graph"

        # New numbers: the view shows the new variant's own graph, as readable
        form = page.locator(f'form.q-form[data-question="{key}"]')
        before = opener.locator("img.q-graph").get_attribute("src")
        form.locator("button.q-new").tap()
        page.wait_for_function(f"document.querySelector('form.q-form[data-question=\"{key}\"]').dataset.variant !== '0'")
        assert opener.locator("img.q-graph").get_attribute("src") != before
        opener.tap()
        shown = _opened(page, opener)
        assert "_static/questions/" in shown["src"], shown["src"]
        _check_readable(key, shown)
        page.keyboard.press("Escape")
        page.wait_for_function(f"!({OPEN})")
    context.close()
    assert not errors, errors
    assert len(measured) == len(questions)


def test_the_view_takes_the_theme_s_colours_in_dark_mode_and_axe_finds_nothing(browser, base_url, questions):
    path, key = questions[0]
    context = browser.new_context(viewport=PHONE, color_scheme="dark")
    page = context.new_page()
    page.goto(f"{base_url}/{path}", wait_until="load")
    page.evaluate("document.documentElement.dataset.theme = 'dark'")
    opener = page.locator(f'section.q[data-q="{key}"] button.q-graph-open')
    opener.click()
    shown = _opened(page, opener)
    # the page's own dark background (the theme's --pst-color-background), not a colour of its own
    page_background = page.evaluate("getComputedStyle(document.body).backgroundColor")
    assert shown["background"] == page_background
    assert sum(int(c) for c in re.findall(r"\d+", shown["background"])[:3]) < 3 * 64, shown["background"]
    text = page.evaluate(f"getComputedStyle(document.querySelector('{VIEW}')).color")
    assert sum(int(c) for c in re.findall(r"\d+", text)[:3]) > 3 * 160, text
    assert not axe_violations(page, context_selector=VIEW)
    context.close()


def test_in_print_the_graph_s_button_is_the_plain_graph(browser, base_url, questions):
    path, key = questions[0]
    context = browser.new_context(viewport=PHONE)
    page = context.new_page()
    page.goto(f"{base_url}/{path}", wait_until="load")
    page.emulate_media(media="print")
    opener = page.locator(f'section.q[data-q="{key}"] button.q-graph-open')
    style = opener.evaluate("b => { const s = getComputedStyle(b); return [s.borderTopWidth, s.borderLeftWidth]; }")
    assert style == ["0px", "0px"]
    assert not opener.locator(".q-graph-hint").is_visible()
    assert opener.locator("img.q-graph").is_visible()
    context.close()


#: Every tick label of the enlarged graph where the screen shows it: the SVG the view loaded,
#: laid over the image at its size (hidden), gives each label's box; then, whether that box lies
#: inside the pane's visible part and the window. Tick labels are the tick-size texts (12 px in
#: the SVG) centred on the time axis's line and ending on the value axis's column.
LABELS_IN_VIEW = f"""async () => {{
  const dialog = document.querySelector('{VIEW}'), image = dialog.querySelector('img.q-graph-large');
  const pane = dialog.querySelector('.q-graph-pane').getBoundingClientRect(), box = image.getBoundingClientRect();
  const copy = document.createElement('div');
  copy.style.cssText = `position:fixed;left:${{box.left}}px;top:${{box.top}}px;width:${{box.width}}px;` +
    `height:${{box.height}}px;visibility:hidden;pointer-events:none;overflow:visible`;
  copy.innerHTML = (await (await fetch(image.currentSrc)).text()).replace(/^[\\s\\S]*?(?=<svg)/, '');
  const svg = copy.querySelector('svg');
  svg.setAttribute('width', box.width); svg.setAttribute('height', box.height);
  dialog.appendChild(copy);
  const view = {{left: Math.max(pane.left, 0), top: Math.max(pane.top, 0),
                right: Math.min(pane.right, innerWidth), bottom: Math.min(pane.bottom, innerHeight)}};
  const labels = [];
  for (const text of svg.querySelectorAll('text')) {{
    const style = text.getAttribute('style') || '';
    if (!/font-size: 12px/.test(style)) continue;
    const r = text.getBoundingClientRect();
    labels.push({{text: text.textContent, axis: /text-anchor: middle/.test(style) ? 'time' : 'value',
                  inside: r.left >= view.left - 0.5 && r.right <= view.right + 0.5 &&
                          r.top >= view.top - 0.5 && r.bottom <= view.bottom + 0.5}});
  }}
  copy.remove();
  return labels;
}}"""


@pytest.mark.parametrize("size", [PHONE, {"width": 1280, "height": 800}], ids=["390px", "1280px"])
def test_the_view_opens_with_both_axes_numbers_in_view(browser, base_url, questions, size):
    """Each graph question's enlarged graph, as it opens: at least two labels of each axis
    wholly in view (a scale to read by), and every label of both where the whole graph fits in
    the view. A graph zoomed to read half a small square can be larger than the screen (at 390
    px all of them; at 1280 × 800 those of 50 or 60 squares up): it opens as near the plot's
    middle as keeps numbers of both axes in view."""
    context = browser.new_context(viewport=size)
    page = context.new_page()
    out = {}
    for path, key in questions:
        if page.url != f"{base_url}/{path}":
            page.goto(f"{base_url}/{path}", wait_until="load")
        opener = page.locator(f'section.q[data-q="{key}"] button.q-graph-open')
        opener.scroll_into_view_if_needed()
        opener.click()
        _opened(page, opener)
        labels = page.evaluate(LABELS_IN_VIEW)
        time = [label for label in labels if label["axis"] == "time"]
        value = [label for label in labels if label["axis"] == "value"]
        assert len(time) >= 2 and len(value) >= 2, f"{key}: no axes' labels found: {labels}"
        fits = page.evaluate(f"""() => {{ const p = document.querySelector('{VIEW} .q-graph-pane');
          return p.scrollWidth <= p.clientWidth && p.scrollHeight <= p.clientHeight; }}""")
        if any(sum(label["inside"] for label in axis) < (len(axis) if fits else 2) for axis in (time, value)):
            out[key] = [label["text"] for label in labels if not label["inside"]]
        page.keyboard.press("Escape")
        page.wait_for_function(f"!({OPEN})")
    context.close()
    assert not out, f"labels out of view as the enlarged graph opens at {size['width']} px: {out}"
