"""The explorables in a real browser: Debian's Chromium, driven by playwright, on the built site.

The site (the `site_dir` fixture; SITE_DIR points it at a site built elsewhere) is served
as a static host serves it (scripts/browser.py). Each test works the page as a reader would, with
the keyboard or the pointer, and checks the read-outs against physics_figures.
"""

from __future__ import annotations

import re

import pytest
from playwright.sync_api import Page, expect
from support.pages import explorable_page

from physics_figures import models, scenarios
from physics_figures.explorables import EXPLORABLES, REFUSALS, collision_lab
from physics_figures.notation import format_number

pytestmark = [pytest.mark.site, pytest.mark.browser]

PHONE = {"width": 390, "height": 844}
DESKTOP = {"width": 1100, "height": 900}


class Visit:
    """A page opened in a fresh browser context, with its console errors recorded."""

    def __init__(self, browser, url, *, viewport=DESKTOP, javascript=True):
        self.context = browser.new_context(viewport=viewport, java_script_enabled=javascript)
        self.page: Page = self.context.new_page()
        self.errors: list[str] = []
        self.page.on("console", lambda m: m.type == "error" and self.errors.append(f"{m.text} @ {m.location.get('url')}"))
        self.page.on("pageerror", lambda e: self.errors.append(f"uncaught: {e}"))
        self.page.goto(url)
        self.page.wait_for_load_state("load")


@pytest.fixture
def visit(browser, base_url, site_dir):
    opened = []

    def open_page(name=None, *, path=None, **options):
        target = path or explorable_page(site_dir, name)
        opened.append(Visit(browser, f"{base_url}/{target}", **options))
        return opened[-1]

    yield open_page
    for page in opened:
        page.context.close()


def explorable(page: Page, name: str):
    return page.locator(f'.explorable[data-explorable="{name}"]')


def value_of(box, output_name: str) -> float:
    """The full-precision number an <output> shows (its data-value)."""
    return float(box.locator(f'output[name="{output_name}"]').get_attribute("data-value"))


def shown(box, output_name: str) -> str:
    return box.locator(f'output[name="{output_name}"]').inner_text()


def shown_number(box, output_name: str) -> float:
    """The number as printed for the reader: thin spaces out, a real minus sign in."""
    text = shown(box, output_name).replace("\u202f", "").replace("\u2212", "-")
    return float(re.match(r"-?[\d.]+", text).group())


def three_sf(x: float) -> float:
    return float(f"{x:.3g}")


# ---- every explorable --------------------------------------------------------------

@pytest.mark.parametrize("name", EXPLORABLES)
def test_explorable_is_built_and_revealed_with_javascript(visit, name):
    box = explorable(visit(name).page, name)
    expect(box).to_be_visible()
    expect(box).to_have_attribute("data-built", "true")
    expect(box.locator(".ex-description").first).not_to_be_empty()


@pytest.mark.parametrize("name", EXPLORABLES)
def test_without_javascript_the_explorable_stays_hidden_and_silent(visit, name):
    page = visit(name, javascript=False).page
    expect(explorable(page, name)).to_be_hidden()
    assert "Explore:" not in page.locator("main").inner_text()


@pytest.mark.parametrize("name", EXPLORABLES)
def test_print_hides_the_explorable(visit, name):
    page = visit(name).page
    expect(explorable(page, name)).to_be_visible()
    page.emulate_media(media="print")
    expect(explorable(page, name)).to_be_hidden()


@pytest.mark.parametrize("name", EXPLORABLES)
def test_no_sideways_scrolling_on_a_390px_phone(visit, name):
    page = visit(name, viewport=PHONE).page
    box = explorable(page, name)
    expect(box).to_be_visible()
    assert page.evaluate("document.documentElement.scrollWidth") <= PHONE["width"]
    right = box.evaluate("e => e.getBoundingClientRect().right")
    assert right <= PHONE["width"], f"the explorable reaches {right}px"
    overflowing = box.evaluate(
        "e => [...e.querySelectorAll('*')].filter(c => c.getBoundingClientRect().right > window.innerWidth + 0.5)"
        ".map(c => c.tagName + '.' + (c.className.baseVal ?? c.className))")
    assert not overflowing, f"wider than the phone: {overflowing[:5]}"


@pytest.mark.parametrize("name", EXPLORABLES)
def test_explorables_log_no_console_errors(visit, name):
    explored = visit(name)
    expect(explorable(explored.page, name)).to_have_attribute("data-built", "true")
    assert not explored.errors, explored.errors


def contrast(foreground: str, background: str) -> float:
    """WCAG contrast ratio of two rgb()/rgba() CSS colours."""
    def luminance(css):
        channels = [float(x) / 255 for x in re.findall(r"[\d.]+", css)[:3]]
        linear = [c / 12.92 if c <= 0.03928 else ((c + 0.055) / 1.055) ** 2.4 for c in channels]
        return 0.2126 * linear[0] + 0.7152 * linear[1] + 0.0722 * linear[2]
    high, low = sorted((luminance(foreground), luminance(background)), reverse=True)
    return (high + 0.05) / (low + 0.05)


@pytest.mark.parametrize("theme", ["light", "dark"])
def test_colours_are_readable_in_light_and_dark_mode(visit, theme):
    page = visit("skydiver").page
    page.evaluate(f"document.documentElement.dataset.theme = '{theme}'")
    colours = page.evaluate("""() => {
        const panel = document.querySelector('.explorable .ex-panel');
        const style = (selector, property) => getComputedStyle(document.querySelector(selector))[property];
        return {text: getComputedStyle(panel).color, background: getComputedStyle(panel).backgroundColor,
                velocity: style('.explorable .ex-line.ex-a', 'stroke'),
                force: style('.explorable .ex-line.ex-b', 'stroke'),
                muted: style('.explorable .ex-readout-label', 'color')};
    }""")
    assert contrast(colours["text"], colours["background"]) >= 7
    assert contrast(colours["muted"], colours["background"]) >= 4.5
    # lines are graphics: WCAG asks 3:1 (and they differ in dash pattern, not only colour)
    assert contrast(colours["velocity"], colours["background"]) >= 3
    assert contrast(colours["force"], colours["background"]) >= 3


# ---- the skydiver ------------------------------------------------------------------

def test_skydiver_mass_slider_by_keyboard_gives_the_models_terminal_velocity(visit):
    # Notes: a heavier object of the same shape must fall faster before drag = weight.
    box = explorable(visit("skydiver").page, "skydiver")
    start = scenarios.SKYDIVER
    before = value_of(box, "vt1")
    slider = box.get_by_role("slider", name="Mass of the skydiver")
    slider.focus()
    slider.press("ArrowRight")
    mass = start.mass + 1
    v_t1 = models.terminal_velocity(mass, start.drag_constant_freefall)
    v_t2 = models.terminal_velocity(mass, start.drag_constant_parachute)
    assert value_of(box, "vt1") == pytest.approx(v_t1, rel=1e-9)
    assert value_of(box, "vt1") > before
    assert value_of(box, "vt2") == pytest.approx(v_t2, rel=1e-9)
    assert shown_number(box, "vt1") == three_sf(v_t1)
    weight = models.weight(mass)
    # the drag at both terminal velocities equals the weight
    for name in ("weight", "d1", "d2"):
        assert value_of(box, name) == pytest.approx(weight, rel=1e-9)
    assert box.get_by_role("spinbutton", name="Mass of the skydiver").input_value() == "81"


def test_skydiver_largest_deceleration_is_a_few_g_just_after_the_parachute_opens(visit):
    # Issue 12: the canopy opens over 2.5 s (the default), so the largest deceleration is
    # about 4 g, at D, 0.78 s after the opening (the instant opening showed 99 g at it).
    box = explorable(visit("skydiver").page, "skydiver")
    dive = scenarios.SKYDIVER  # the page starts on the notes' skydiver
    largest = -dive.acceleration.min()
    t_d = dive.points["D"][0]
    assert dive.parachute_opens_at < t_d == dive.time[dive.acceleration.argmin()]
    assert value_of(box, "decel") == pytest.approx(largest, rel=1e-6)
    assert 2 < value_of(box, "decelG") < 6
    assert shown(box, "decelG") == "4.0\u00a0g"
    expect(box.locator(".ex-warning")).to_be_hidden()  # empty: nothing unrealistic here
    box.get_by_role("button", name="D", exact=True).click()
    assert value_of(box, "t") == pytest.approx(t_d, rel=1e-12)
    assert value_of(box, "acc") == pytest.approx(largest, rel=1e-6)
    assert shown(box, "acc").endswith("up")
    assert value_of(box, "drag") == pytest.approx(dive.point_drag["D"], rel=1e-6)
    expect(box.locator(".ex-now")).to_contain_text("up")


def set_slider(box, name: str, key: str, presses: int = 1):
    slider = box.get_by_role("slider", name=name)
    slider.focus()
    for _ in range(presses):
        slider.press(key)


def test_skydiver_opening_duration_slider_changes_the_peak_as_python_does(visit):
    # CLARIFICATIONS (Physics): a slider for the opening duration, 0.5 to 5 s, default 2.5 s.
    box = explorable(visit("skydiver").page, "skydiver")
    start = scenarios.SKYDIVER
    duration = box.get_by_role("spinbutton", name="Time the parachute takes to open")
    assert float(duration.input_value()) == start.opening_duration == 2.5
    set_slider(box, "Time the parachute takes to open", "Home")
    assert float(duration.input_value()) == 0.5
    quick = models.skydive(start.mass, terminal_velocity_freefall=50.0, terminal_velocity_parachute=5.0,
                           parachute_opens_at=start.parachute_opens_at, opening_duration=0.5, duration=40.0)
    assert value_of(box, "decel") == pytest.approx(-quick.point_acceleration["D"], rel=1e-6)
    assert value_of(box, "decel") > -start.point_acceleration["D"]  # quicker opening, harder jolt
    set_slider(box, "Time the parachute takes to open", "End")
    assert float(duration.input_value()) == 5


def test_skydiver_says_why_more_than_15_g_is_unrealistic(visit):
    # Issue 12: at any setting the explorer never shows more than 15 g without saying why.
    box = explorable(visit("skydiver").page, "skydiver")
    set_slider(box, "Mass of the skydiver", "End")  # 120 kg
    set_slider(box, "Body\u2019s drag constant k (drag = k v\u00b2)", "Home")  # fastest freefall
    set_slider(box, "Parachute\u2019s drag constant k", "End")  # biggest canopy
    set_slider(box, "Parachute opens at time", "End")
    set_slider(box, "Time the parachute takes to open", "Home")  # quickest opening
    assert value_of(box, "decelG") > 15
    warning = box.locator(".ex-warning")
    expect(warning).to_be_visible()
    expect(warning).to_contain_text("Unrealistic")
    expect(warning).to_contain_text("would injure the skydiver")
    # Issue 25: it quotes the speed the canopy opens at (88.6 m s⁻¹ here), not the speed at D (59.3)
    v_t1 = models.terminal_velocity(120, 0.15)
    expect(warning).to_contain_text(f"opens at {format_number(models.velocity_from_rest(60, v_t1), 3)}")
    expect(warning).not_to_contain_text("59.3")
    set_slider(box, "Time the parachute takes to open", "End")  # a slow opening: a few g again
    assert value_of(box, "decelG") < 15
    expect(warning).to_be_hidden()


def test_skydiver_parachute_may_open_before_terminal_velocity(visit):
    # Issue 12: the parachute may open at any time while the skydiver is faster than the
    # parachute's terminal velocity, not only after C (13.5 s).
    box = explorable(visit("skydiver").page, "skydiver")
    start = scenarios.SKYDIVER
    set_slider(box, "Parachute opens at time", "Home")
    opens = float(box.get_by_role("spinbutton", name="Parachute opens at time").input_value())
    assert opens == 1.0  # the first half second after 0.517 s
    expect(box.get_by_role("button", name="C", exact=True)).to_be_hidden()
    early = models.skydive(start.mass, terminal_velocity_freefall=50.0, terminal_velocity_parachute=5.0,
                           parachute_opens_at=opens, opening_duration=2.5, duration=40.0)
    assert "C" not in early.points
    assert value_of(box, "decel") == pytest.approx(-early.point_acceleration["D"], rel=1e-6)
    box.get_by_role("button", name="E", exact=True).click()
    assert value_of(box, "v") == pytest.approx(early.points["E"][1], rel=1e-6)


def test_skydiver_time_slider_moves_the_free_body_diagram(visit):
    box = explorable(visit("skydiver").page, "skydiver")
    dive = scenarios.SKYDIVER
    slider = box.get_by_role("slider", name="Time along the graph")
    slider.focus()
    slider.press("Home")
    assert value_of(box, "acc") == pytest.approx(dive.g, rel=1e-9)  # A: only the weight acts
    assert shown(box, "acc").endswith("down")
    expect(box.locator(".ex-fbd .ex-drag-text")).to_have_text("D 0 N")
    for _ in range(50):
        slider.press("ArrowRight")
    t = value_of(box, "t")
    assert t == pytest.approx(5.0)
    v = models.velocity_from_rest(t, dive.terminal_velocity_freefall)
    assert value_of(box, "v") == pytest.approx(v, rel=1e-9)
    drag = models.drag_force(dive.drag_constant_freefall, v)
    assert value_of(box, "drag") == pytest.approx(drag, rel=1e-9)
    expect(box.locator(".ex-fbd .ex-drag-text")).to_have_text(f"D {three_sf(drag):g} N")


# ---- the momentum triangle ---------------------------------------------------------

def test_momentum_triangle_reproduces_pucks_p_and_q(visit):
    # Notes, Momentum in two dimensions: 1.00 N s in, P 0.60 N s at 50 deg -> Q 0.77 N s at 36.8 deg
    # (0.767 to 3 s.f., as the physics issue prints it).
    box = explorable(visit("momentum-triangle").page, "momentum-triangle")
    missing = scenarios.PUCKS_PQ.missing
    assert value_of(box, "q") == pytest.approx(missing.magnitude, rel=1e-9)
    assert round(value_of(box, "q"), 2) == 0.77
    assert shown(box, "q") == "0.767\u00a0N\u00a0s"
    assert shown(box, "phi") == "36.8°"
    assert shown(box, "qAlong") == "0.614\u00a0N\u00a0s"
    assert shown(box, "qAcross") == "0.460\u00a0N\u00a0s"


def test_momentum_triangle_angle_by_keyboard_follows_conservation(visit):
    box = explorable(visit("momentum-triangle").page, "momentum-triangle")
    slider = box.get_by_role("slider", name="Angle of P")
    slider.focus()
    slider.press("ArrowRight")
    expected = models.missing_momentum(1.00, 0.60, 51)
    assert value_of(box, "q") == pytest.approx(expected.magnitude, rel=1e-9)
    assert value_of(box, "phi") == pytest.approx(expected.angle_deg, rel=1e-9)
    assert value_of(box, "qAcross") == pytest.approx(expected.across, rel=1e-9)


# ---- the collision lab -------------------------------------------------------------

def test_collision_lab_refuses_kinetic_energy_created_in_a_collision(visit):
    page = visit("collision-lab").page
    box = explorable(page, "collision-lab")
    box.get_by_label("Lose a chosen percentage").check()
    box.get_by_role("spinbutton", name="Kinetic energy lost").fill("-10")
    expect(box.locator(".ex-verdict")).to_have_text(REFUSALS["energy-created"])
    expect(box.locator(".ex-verdict")).to_have_class(re.compile("ex-refused"))
    assert shown(box, "e-after") == "\u2014"
    expect(box.locator(".ex-description")).to_contain_text("Refused")
    # the one live region says it too (tests/browser/test_explorables_announce_browser.py)
    expect(box.locator('[aria-live="polite"].ex-announcer')).to_contain_text(REFUSALS["energy-created"])


def test_collision_lab_refuses_bodies_that_never_meet(visit):
    box = explorable(visit("collision-lab").page, "collision-lab")
    box.get_by_role("spinbutton", name="Velocity of A before").fill("-1")
    expect(box.locator(".ex-verdict")).to_contain_text("They never meet")


def test_collision_lab_elastic_by_keyboard_gives_the_models_result(visit):
    box = explorable(visit("collision-lab").page, "collision-lab")
    box.get_by_label("Elastic").check()
    slider = box.get_by_role("slider", name="Velocity of A before")
    slider.focus()
    slider.press("ArrowLeft")  # 4.0 -> 3.9 m/s
    start = scenarios.STICKING_TROLLEYS
    lab = collision_lab("elastic", **(start | {"u1": 3.9}))
    assert value_of(box, "pa-after") == pytest.approx(start["m1"] * lab.after[0], rel=1e-9)
    assert value_of(box, "pb-after") == pytest.approx(start["m2"] * lab.after[1], rel=1e-9)
    assert value_of(box, "e-after") == pytest.approx(lab.kinetic_energy_after, rel=1e-9)
    assert value_of(box, "rel-after") == pytest.approx(lab.separation_speed, rel=1e-9)
    assert value_of(box, "rel-before") == pytest.approx(3.9, rel=1e-9)
    expect(box.locator(".ex-verdict")).to_contain_text("elastic")


def test_collision_lab_explosion_starts_on_the_notes_spring_trolleys(visit):
    # Notes: 0.20 kg and 0.30 kg pushed apart; the 0.30 kg one at 2.0 m/s, the other at 3.0 back.
    box = explorable(visit("collision-lab").page, "collision-lab")
    box.get_by_label("Explosion from rest").check()
    assert value_of(box, "pa-after") == pytest.approx(0.20 * -3.0, rel=1e-9)
    assert value_of(box, "pb-after") == pytest.approx(0.30 * 2.0, rel=1e-9)
    assert box.get_by_role("spinbutton", name="Mass of A").input_value() == "0.2"
    box.get_by_label("Stick together").check()  # back to the reader's collision masses
    assert box.get_by_role("spinbutton", name="Mass of B").input_value() == "1"
    assert shown(box, "e-before") == "24.0"


def test_momentum_triangle_says_a_collision_cannot_gain_kinetic_energy(visit):
    box = explorable(visit("momentum-triangle").page, "momentum-triangle")
    expect(box.locator(".ex-energy-note")).to_contain_text("A real collision cannot gain kinetic energy")
    # The notes' pucks, if of equal mass: (0.60^2 + 0.767^2) / 1.00^2 = 95% kept: possible.
    expect(box.locator(".ex-energy")).to_contain_text("possible")
    box.get_by_role("spinbutton", name="Angle of P").fill("90")  # P at right angles: Q must carry 1.00 along too
    expect(box.locator(".ex-energy")).to_contain_text("no real collision")


def test_collision_lab_starts_on_the_notes_sticking_trolleys(visit):
    # Notes: 3.0 kg at 4.0 m/s sticks to 1.0 kg at rest: 3.0 m/s, 24 J -> 18 J, 25% lost.
    box = explorable(visit("collision-lab").page, "collision-lab")
    assert shown(box, "e-before") == "24.0"
    assert shown(box, "e-after") == "18.0"
    assert shown(box, "percent") == "25.0%"


# ---- the momentum-time graph reader -------------------------------------------------

def test_momentum_time_reader_by_keyboard_reads_the_car_graph(visit):
    box = explorable(visit("momentum-time-reader").page, "momentum-time-reader")
    history, mass = scenarios.CAR_HISTORY, scenarios.CAR_MASS
    slider = box.get_by_role("slider", name="Time along the graph")
    slider.focus()
    slider.press("Home")
    for _ in range(20):
        slider.press("ArrowRight")
    t = value_of(box, "t")
    assert t == pytest.approx(2.0)
    assert value_of(box, "p") == pytest.approx(history.momentum_at(t), rel=1e-9)
    assert value_of(box, "v") == pytest.approx(history.velocity_at(t, mass), rel=1e-9)
    assert value_of(box, "f") == history.force_at(t) == 3000  # Notes: 12 000 / 4.0 = 3000 N
    slider.press("End")
    assert value_of(box, "t") == 16
    assert value_of(box, "f") == history.force_at(16.0) == -2000  # Notes: -12 000 / 6.0
    assert shown(box, "f") == "\u22122000\u00a0N"


def test_momentum_time_reader_follows_the_pointer(visit):
    page = visit("momentum-time-reader").page
    box = explorable(page, "momentum-time-reader")
    plot = box.locator("svg.ex-plot")
    plot.scroll_into_view_if_needed()
    bounds = plot.bounding_box()
    # the plot's frame runs from x = 72 to width - 16 in SVG units (its margins)
    width = plot.evaluate("svg => svg.viewBox.baseVal.width")
    left, right = 72, width - 16
    t_wanted = 7.0
    x_view = left + (t_wanted - 0) / 16 * (right - left)
    page.mouse.move(bounds["x"] + x_view / width * bounds["width"], bounds["y"] + bounds["height"] / 2)
    assert value_of(box, "t") == pytest.approx(t_wanted, abs=0.1)
    assert value_of(box, "f") == 0  # the flat part: zero resultant force
    assert value_of(box, "v") == pytest.approx(8.0)  # Notes: 12 000 / 1500 = 8.0 m/s
