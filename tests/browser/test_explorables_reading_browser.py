"""Small controls and stray overlaps in the explorables, in Debian's Chromium (issue 14, item 9).

* on a touch screen every slider thumb, box and button is at least 44 x 44 CSS px;
* the skydiver's time slider sits right next to the graph it moves along;
* a typed value out of range gets a message (and the box shows the value still in use);
* the skydiver's velocity axis fits the run (a 20 m/s terminal velocity is not drawn on 0-100);
* annotation labels never sit on a tick label or on the frame;
* each explorable has one polite live region, visually hidden;
* the floating "Back to top" button never covers text or controls.
"""

from __future__ import annotations

import pytest
from playwright.sync_api import expect
from support.pages import explorable_page

from physics_figures import models

pytestmark = [pytest.mark.site, pytest.mark.browser]

PHONE = {"width": 390, "height": 844}
DESKTOP = {"width": 1280, "height": 800}
TOUCH_PHONE = {"viewport": PHONE, "has_touch": True, "is_mobile": True, "device_scale_factor": 2}
SMALLEST_TARGET_PX = 44  # WCAG 2.5.5


EXPLORABLES = ("skydiver", "collision-lab", "momentum-triangle", "momentum-time-reader")

# Each control's touch target: its own box, or for a radio button the row of radio and label.
TARGETS = """() => [...document.querySelectorAll('.explorable[data-built] input, .explorable[data-built] button')]
  .filter(el => el.offsetParent !== null)
  .map(el => {
    const target = el.type === 'radio' ? el.closest('.ex-radio') : el;
    const box = target.getBoundingClientRect();
    let thumb = null;
    if (el.type === 'range') {
      const s = getComputedStyle(el, '::-webkit-slider-thumb');
      thumb = [parseFloat(s.width), parseFloat(s.height)];
    }
    return {what: el.type + ' ' + (el.id || el.textContent), w: box.width, h: box.height, thumb};
  })"""


@pytest.mark.parametrize("name", EXPLORABLES)
def test_every_control_is_at_least_44_px_square_on_a_touch_screen(site_dir, base_url, browser, name):
    context = browser.new_context(**TOUCH_PHONE)
    page = context.new_page()
    page.goto(f"{base_url}/{explorable_page(site_dir, name)}")
    assert page.evaluate("matchMedia('(pointer: coarse)').matches"), "the touch phone is not coarse"
    page.wait_for_selector(f'.explorable[data-explorable="{name}"][data-built]')
    targets = page.evaluate(TARGETS)
    context.close()
    assert targets, f"{name}: no controls found"
    small = [t for t in targets if t["w"] < SMALLEST_TARGET_PX or t["h"] < SMALLEST_TARGET_PX
             or (t["thumb"] and min(t["thumb"]) < SMALLEST_TARGET_PX)]
    assert not small, f"{name}: targets under {SMALLEST_TARGET_PX} px: {small}"


def _plot_box(page, selector):
    return page.locator(selector).first.bounding_box()


@pytest.mark.parametrize("viewport", [PHONE, DESKTOP], ids=["390", "1280"])
def test_the_skydiver_time_slider_sits_next_to_its_graph(site_dir, base_url, browser, viewport):
    page = browser.new_page(viewport=viewport)
    page.goto(f"{base_url}/{explorable_page(site_dir, 'skydiver')}")
    root = '.explorable[data-explorable="skydiver"]'
    page.wait_for_selector(f"{root}[data-built]")
    slider = page.get_by_role("slider", name="Time along the graph").bounding_box()
    graph = _plot_box(page, f"{root} svg.ex-plot")
    gap = max(graph["y"] - (slider["y"] + slider["height"]), slider["y"] - (graph["y"] + graph["height"]), 0)
    assert gap <= 120, f"the time slider is {gap:.0f} px from the velocity graph"


def test_a_typed_value_out_of_range_gets_a_message(site_dir, base_url, browser):
    page = browser.new_page(viewport=PHONE)
    page.goto(f"{base_url}/{explorable_page(site_dir, 'skydiver')}")
    page.wait_for_selector('.explorable[data-explorable="skydiver"][data-built]')
    box = page.get_by_role("spinbutton", name="Mass of the skydiver in kilograms")
    used = box.input_value()
    box.fill("500")
    message = page.locator(".ex-range-message:visible")
    expect(message).to_have_count(1)
    text = message.inner_text()
    assert "500 is out of range" in text and "40" in text and "120" in text, text
    assert box.get_attribute("aria-invalid") == "true"
    described = box.get_attribute("aria-describedby")
    assert described and page.locator(f"#{described}").inner_text() == text
    box.press("Tab")  # leaving the box: it goes back to the value in use, the message stays
    assert box.input_value() == used
    expect(message).to_have_count(1)
    box.fill("70")
    expect(page.locator(".ex-range-message:visible")).to_have_count(0)
    assert box.get_attribute("aria-invalid") is None


def _top_tick(page, index: int) -> float:
    ticks = page.locator('.explorable[data-explorable="skydiver"] svg.ex-plot').nth(index).locator(
        "text.ex-tick").all_text_contents()
    return max(float(t.replace("\u2212", "-").replace("\u202f", "")) for t in ticks if t.strip())


def test_the_skydiver_velocity_axis_scales_to_the_run(site_dir, base_url, browser):
    page = browser.new_page(viewport=DESKTOP)
    page.goto(f"{base_url}/{explorable_page(site_dir, 'skydiver')}")
    page.wait_for_selector('.explorable[data-explorable="skydiver"][data-built]')
    mass, drag = 40.0, 1.0  # the lightest skydiver with the most drag: about 20 m/s
    page.get_by_role("spinbutton", name="Mass of the skydiver in kilograms").fill(str(mass))
    page.get_by_role("spinbutton", name="Body\u2019s drag constant k (drag = k v\u00b2) in kilograms per metre").fill(str(drag))
    terminal = models.terminal_velocity(mass, drag)
    top = _top_tick(page, 0)
    assert terminal < top <= 1.5 * terminal, f"terminal velocity {terminal:.1f} m/s drawn on an axis to {top}"


# Every annotation (point labels, "A: W", "gradient ... N") against every tick label and the
# frame's edges: their boxes may not overlap, with a pixel to spare.
OVERLAPS = """() => {
  const out = [];
  for (const svg of document.querySelectorAll('.explorable[data-built] svg.ex-plot')) {
    const frame = svg.querySelector('.ex-frame');
    if (!frame) continue;
    const f = frame.getBoundingClientRect();
    const ticks = [...svg.querySelectorAll('text.ex-tick')].map(t => t.getBoundingClientRect());
    for (const label of svg.querySelectorAll('text.ex-point-label')) {
      const b = label.getBoundingClientRect();
      if (!b.width) continue;
      const hits = (r) => b.left < r.right + 1 && b.right > r.left - 1 && b.top < r.bottom + 1 && b.bottom > r.top - 1;
      if (ticks.some(hits)) out.push(label.textContent + ' on a tick');
      const inside = b.left > f.left + 1 && b.right < f.right - 1 && b.top > f.top + 1 && b.bottom < f.bottom - 1;
      if (!inside) out.push(label.textContent + ' on or across the frame');
    }
  }
  return out;
}"""


@pytest.mark.parametrize("viewport", [PHONE, DESKTOP], ids=["390", "1280"])
def test_annotation_labels_never_sit_on_ticks_or_the_frame(site_dir, base_url, browser, viewport):
    bad = {}
    page = browser.new_page(viewport=viewport)
    for name in ("skydiver", "momentum-time-reader"):
        page.goto(f"{base_url}/{explorable_page(site_dir, name)}")
        page.wait_for_selector(f'.explorable[data-explorable="{name}"][data-built]')
        found = page.evaluate(OVERLAPS)
        if name == "skydiver":  # a hard opening: the off-scale label near the bottom frame
            page.get_by_role("spinbutton", name="Time the parachute takes to open \u03c4 in seconds").fill("0.5")
            found += page.evaluate(OVERLAPS)
        if found:
            bad[name] = found
    assert not bad, bad


@pytest.mark.parametrize("name", EXPLORABLES)
def test_each_explorable_has_one_polite_live_region(site_dir, base_url, browser, name):
    """Issue 28: one polite region per explorable, hidden from sight but not from screen
    readers (display: none or visibility: hidden would silence it)."""
    page = browser.new_page(viewport=DESKTOP)
    page.goto(f"{base_url}/{explorable_page(site_dir, name)}")
    page.wait_for_selector(f'.explorable[data-explorable="{name}"][data-built]')
    live = page.evaluate("""name => [...document.querySelectorAll(
        `.explorable[data-explorable="${name}"] *`)].filter(el => {
          const mode = el.getAttribute('aria-live');
          const role = el.getAttribute('role') || (el.tagName === 'OUTPUT' ? 'status' : '');
          return mode ? mode !== 'off' : ['status', 'alert', 'log'].includes(role);
        }).map(el => {
          const style = getComputedStyle(el), box = el.getBoundingClientRect();
          return {name: el.className || el.tagName, mode: el.getAttribute('aria-live'),
                  shown: style.display !== 'none' && style.visibility !== 'hidden',
                  size: [box.width, box.height]};
        })""", name)
    assert len(live) == 1, f"live regions in the {name} explorable: {live}"
    region = live[0]
    assert region["mode"] == "polite" and region["shown"], region
    assert max(region["size"]) <= 1, f"the live region is visible on the page: {region}"


# While "Back to top" shows: what it covers. Text: any visible text node whose box meets the
# button's; controls: links, buttons and inputs (other than itself) that meet it.
COVERED = """() => {
  const button = document.getElementById('pst-back-to-top');
  if (!button || getComputedStyle(button).display === 'none') return null;
  const b = button.getBoundingClientRect();
  const meets = r => r.width && r.height && r.left < b.right && r.right > b.left && r.top < b.bottom && r.bottom > b.top;
  const out = [];
  const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
  for (let n = walker.nextNode(); n; n = walker.nextNode()) {
    if (!n.data.trim() || button.contains(n)) continue;
    const range = document.createRange(); range.selectNodeContents(n);
    if ([...range.getClientRects()].some(meets)) out.push('text: ' + n.data.trim().slice(0, 30));
  }
  for (const c of document.querySelectorAll('a, button, input, select, textarea, summary')) {
    if (c === button || button.contains(c) || c.offsetParent === null) continue;
    if (meets(c.getBoundingClientRect())) out.push('control: ' + (c.textContent.trim().slice(0, 30) || c.tagName));
  }
  return out;
}"""


@pytest.mark.parametrize("viewport", [PHONE, {"width": 900, "height": 800}, DESKTOP], ids=["390", "900", "1280"])
def test_back_to_top_never_covers_text_or_controls(site_dir, base_url, browser, viewport):
    covered, scrolled = {}, 0
    pages = [explorable_page(site_dir, "skydiver"), explorable_page(site_dir, "collision-lab"),
             "book/exam/quick-check.html", "book/understand/momentum-time-graph.html"]
    page = browser.new_page(viewport=viewport)
    for path in pages:
        page.goto(f"{base_url}/{path}")
        page.wait_for_load_state("networkidle")
        height = page.evaluate("document.body.scrollHeight")
        for _ in range(1500, height, 700):
            page.mouse.wheel(0, 700 + 300)  # down, then a little up: the theme shows it on the way up
            page.mouse.wheel(0, -300)
            # the theme shows the button from a scroll event: two frames on, it has been handled
            page.evaluate("new Promise(done => requestAnimationFrame(() => requestAnimationFrame(done)))")
            scrolled += page.evaluate("window.scrollY > 0")
            found = page.evaluate(COVERED)
            if found:
                covered.setdefault(path, []).extend(found[:3])
    assert scrolled, "the pages never scrolled: the test saw nothing"
    assert not covered, f"Back to top covers: {covered}"
