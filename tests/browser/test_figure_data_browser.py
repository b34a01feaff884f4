"""Every figure of the built book has its data and a description (issue 28, item 1), read
in Chromium as a reader's browser gives them:

* beside every figure a "Data" disclosure holds a table (caption, column headers with
  units) and the description, whose paragraph the image names with aria-describedby, so the
  image's accessible description (as Chromium computes it) is that paragraph;
* for three figures the table's numbers are the model's, computed here from
  ``physics_figures.models`` directly (not through any figure code);
* opened on a 390 px phone, no table makes the page scroll sideways.

Question graphs (img.q-graph) are left out on purpose: a table of their values would give
away the readings their questions ask for (issue 28, item 2 gives them a cursor instead).
"""

from __future__ import annotations

import re

import numpy as np
import pytest
from browser import serve_site, site_pages

from physics_figures import scenarios
from physics_figures.models import average_force, components, missing_momentum
from physics_figures.notation import DIGIT_GROUP_SEPARATOR, MINUS

pytestmark = [pytest.mark.site, pytest.mark.browser]

PHONE = {"width": 390, "height": 844}

# Every image the figure module drew (in a figure, or a file under _images/) except the
# question graphs and diagrams, with what a reader's browser finds around it. (A question's
# diagram draws the numbers its text gives, and its alt text says them all:
# tests/no_site/test_question_diagrams.py; a table would repeat the question.)
FIGURE_FACTS = r"""() => [...document.querySelectorAll('img')]
  .filter(img => img.closest('figure') || /(^|\/)_images\//.test(img.getAttribute('src') || ''))
  .filter(img => !img.classList.contains('q-graph') && !img.classList.contains('q-diagram'))
  .map(img => {
    const figure = img.closest('figure');
    const id = img.getAttribute('aria-describedby');
    const described = id ? document.getElementById(id) : null;
    // right after the figure: the description paragraph, then the disclosure
    const details = described ? described.nextElementSibling : null;
    const disclosure = details && details.matches('details.figure-data') ? details : null;
    const table = disclosure ? disclosure.querySelector('table') : null;
    return {
      figure: figure ? figure.id : img.getAttribute('src'),
      describedBy: id,
      description: described ? described.textContent : null,
      descriptionTag: described ? described.tagName : null,
      descriptionNextToFigure: !!(figure && described && figure.nextElementSibling === described),
      shownInDisclosure: !!(described && disclosure && disclosure.querySelector('p')
                            && disclosure.querySelector('p').textContent === described.textContent),
      summary: disclosure && disclosure.querySelector('summary') ? disclosure.querySelector('summary').textContent : null,
      caption: table && table.caption ? table.caption.textContent.trim() : null,
      headings: table ? [...table.querySelectorAll('thead th')].map(th => [th.textContent, th.getAttribute('scope')]) : [],
      rows: table && table.tBodies.length ? [...table.tBodies[0].rows].map(r => [...r.cells].map(c => c.textContent)) : [],
    };
  })"""

OPEN_EVERY_DISCLOSURE = """() => {
  for (const d of document.querySelectorAll('details.figure-data')) d.open = true;
  return document.documentElement.scrollWidth - document.documentElement.clientWidth;
}"""


@pytest.fixture(scope="module")
def figures(site_dir, browser) -> dict[str, dict]:
    """Figure id -> its facts, from every page that shows an image; the accessible
    description Chromium computes for each image, too."""
    pages = [p for p in site_pages(site_dir) if "<img" in (site_dir / p).read_text()]
    found, overflow = {}, {}
    with serve_site(site_dir) as base:
        page = browser.new_page(viewport=PHONE)
        for path in pages:
            page.goto(f"{base}/{path}", wait_until="load")
            for facts in page.evaluate(FIGURE_FACTS):
                assert facts["figure"] not in found, f"{facts['figure']} is on two pages"
                image = page.locator(f"figure#{facts['figure']} img") if facts["describedBy"] else None
                facts["accessible_description"] = _accessible_description(page, image)
                found[facts["figure"]] = facts | {"page": path}
            if shift := page.evaluate(OPEN_EVERY_DISCLOSURE):
                overflow[path] = shift
    return {"figures": found, "overflow": overflow}


def _accessible_description(page, image) -> str | None:
    """What Chromium's accessibility tree gives the image as its description (a figure in
    a worked solution is shown first: a closed one is not in the tree)."""
    if image is None:
        return None
    if not image.is_visible():
        solution = image.locator("xpath=ancestor::*[contains(@class, 'dropdown')][1]")
        solution.locator("button.toggle-button").first.click()
        image.wait_for(state="visible")
    session = page.context.new_cdp_session(page)
    try:
        tree = session.send("Accessibility.getFullAXTree")["nodes"]
    finally:
        session.detach()
    alt = image.get_attribute("alt")
    for ax_node in tree:
        if ax_node.get("role", {}).get("value") == "image" and ax_node.get("name", {}).get("value") == alt:
            return ax_node.get("description", {}).get("value")
    return None


def test_every_figure_has_a_data_table_and_a_description(figures, site_dir):
    shown = figures["figures"]
    in_html = {m for p in site_dir.rglob("*.html") for m in re.findall(r'<figure class="physics-figure[^"]*" id="([^"]+)"', p.read_text())}
    assert len(in_html) >= 11 and set(shown) == in_html, (sorted(in_html), sorted(shown))
    problems = {}
    for name, f in shown.items():
        wrong = []
        if not (f["describedBy"] and f["descriptionTag"] == "P" and len(f["description"] or "") > 200):
            wrong.append(f"aria-describedby {f['describedBy']!r} names no description paragraph")
        if not f["descriptionNextToFigure"]:
            wrong.append("the description is not right after the figure")
        if not f["shownInDisclosure"] or not (f["summary"] or "").startswith("Data"):
            wrong.append("no Data disclosure after the description, showing it too")
        if (f["accessible_description"] or "").strip() != (f["description"] or "").strip():
            wrong.append(f"Chromium describes the image as {f['accessible_description']!r}")
        if not f["caption"]:
            wrong.append("the table has no caption")
        if not f["headings"] or any(scope != "col" for _, scope in f["headings"]):
            wrong.append(f"headers are not all th scope=col: {f['headings']}")
        if len(f["rows"]) < 2 or any(len(row) != len(f["headings"]) for row in f["rows"]):
            wrong.append(f"rows do not fit the headings: {f['rows'][:3]}")
        if wrong:
            problems[name] = wrong
    assert not problems, problems


def test_no_open_table_makes_a_phone_scroll_sideways(figures):
    assert not figures["overflow"], f"px of sideways scroll at 390 px: {figures['overflow']}"


def _number(cell: str) -> float | None:
    if cell == "–":  # noqa: RUF001 (the table's dash: no value)
        return None
    return float(cell.replace(MINUS, "-").replace(DIGIT_GROUP_SEPARATOR, ""))


def _reads(cell: str, expected: float) -> bool:
    """``cell`` is ``expected`` to the figures it is printed to (half a unit in its last
    place, or 0.5 % for a number whose trailing zeros are not significant)."""
    decimals = len(cell.split(".")[1]) if "." in cell else 0
    return abs(_number(cell) - expected) <= max(0.5 * 10.0**-decimals, 0.005 * abs(expected)) + 1e-9


def _table(figures, name: str) -> tuple[list[str], list[list[str]]]:
    f = figures["figures"][name]
    return [h for h, _ in f["headings"]], f["rows"]


def test_skydiver_table_is_the_models_velocity(figures):
    skydive = scenarios.SKYDIVER
    headings, rows = _table(figures, "fig-skydiver-velocity-time")
    assert headings == ["point", "time t / s", "velocity v / m s⁻¹"]
    labelled = {row[0]: row for row in rows if row[0]}
    assert list(labelled) == ["A", "B", "C", "D", "E"]
    for label, (t, v) in skydive.points.items():
        assert _reads(labelled[label][1], t) and _reads(labelled[label][2], v), (label, labelled[label], t, v)
    readings = [row for row in rows if not row[0]]
    every_2_s = list(np.arange(2.0, skydive.duration + 1e-9, 2.0))  # (0 s is A's row)
    assert [_number(row[1]) for row in readings] == pytest.approx(every_2_s)
    wrong = [(row, float(skydive.velocity_at(_number(row[1])))) for row in readings
             if not _reads(row[2], float(skydive.velocity_at(_number(row[1]))))]
    assert not wrong, wrong
    assert [_number(row[1]) for row in rows] == sorted(_number(row[1]) for row in rows)


def test_momentum_time_table_is_the_models_momentum_and_force(figures):
    history = scenarios.CAR_HISTORY
    headings, rows = _table(figures, "fig-car-momentum-time")
    assert headings[:2] == ["time t / s", "momentum p / kg m s⁻¹"]
    times = [_number(row[0]) for row in rows]
    assert times == pytest.approx(list(history.times))
    for (t, p, gradient), t_next in zip(rows, [*times[1:], None], strict=True):
        assert _reads(p, float(history.momentum_at(_number(t)))), (t, p)
        if t_next is None:
            assert _number(gradient) is None
            continue
        change = float(history.momentum_at(t_next) - history.momentum_at(_number(t)))
        assert _reads(gradient, float(average_force(change, t_next - _number(t)))), (t, gradient)


def test_vector_triangle_table_is_the_models_momenta(figures):
    pucks = scenarios.PUCKS_PQ
    headings, rows = _table(figures, "fig-pucks-triangle")
    assert headings[1] == "momentum / N s"
    assert [row[0] for row in rows] == ["P before (dashed)", "P after", "Q after"]
    after = components(pucks.p_known, pucks.angle_known_deg)
    other = missing_momentum(pucks.p_before, pucks.p_known, pucks.angle_known_deg)
    expected = [
        (pucks.p_before, 0.0, pucks.p_before, 0.0),
        (pucks.p_known, pucks.angle_known_deg, float(after[0]), float(after[1])),
        (other.magnitude, -other.angle_deg, other.along, -other.across),
    ]
    for row, values in zip(rows, expected, strict=True):
        assert all(_reads(cell, value) for cell, value in zip(row[1:], values, strict=True)), (row, values)
