# ruff: noqa: RUF001, RUF002  (typeset text: the true minus and times)
"""Graph questions answered without sight (issue 28, item 2, "Done when"), in Debian's Chromium.

For one question of each graph template on the site, keyboard only: Tab from the graph to its
cursor (the slider, static/graph-cursor.js), Home, then Right one small square at a time to the
end, reading each announcement from the page's one polite live region; the test parses the
numbers, works each part out from those readings the way the template's working does (a read
value, a gradient from two readings, an area, then the givens in the question's text), types
the answers and scores full marks. Every announcement lies on the half-small-square grid that
the question's alt text states, and no alt text (the printed variant's and every site variant's)
holds a reading a part asks for. After New numbers the cursor reads the new graph, and that
question too scores full marks. In the enlarged view at 390 px a tap moves the cursor there,
to the nearest half small square, and draws it where the SVG's own grid lines put that reading;
the view writes the reading only when asked ("Show the reading") or once every part read off
the graph has a value typed (issue 37: a sighted student practises reading to half a square).
"""

from __future__ import annotations

import itertools
import json
import math
import re
import urllib.request

import pytest
from browser import shipped_variants
from graph_grid import grid_lines
from support.templates import sig3
from test_graph_view_browser import graph_questions

from physics_figures import bank

pytestmark = [pytest.mark.site, pytest.mark.browser]

SAID = ".q-graph-said"
PHONE = {"viewport": {"width": 390, "height": 844}, "has_touch": True, "is_mobile": True, "device_scale_factor": 2}
G = 9.81  # the questions' g (their text says so where it matters)
SUPERSCRIPT = str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")
NUMBER = r"[−-]?\d[\d\u202f]*(?:\.\d+)?(?:[\s]?×[\s]?10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?"


def number(text: str) -> float:
    """A number as the book writes it: "−1.6", "32 000", "2.5 × 10⁵"."""
    text = text.replace("−", "-").replace("\u202f", "")
    if "×" in text:
        mantissa, power = re.split(r"\s?×\s?10", text)
        return float(mantissa) * 10 ** int(power.translate(SUPERSCRIPT))
    return float(text)


def parse(said: str) -> tuple[float, float | None]:
    """(t, value) from "t = 1.5 s, v = 12.5 m s⁻¹"; value None where no line is drawn."""
    found = re.findall(rf"(\w+) = ({NUMBER})", said)
    assert found and found[0][0] == "t", f"no time in the announcement {said!r}"
    return number(found[0][1]), (number(found[1][1]) if len(found) > 1 else None)


def squares_from_alt(alt: str) -> tuple[float, float, float]:
    """(a small square of time, one of value, the value axis's low end), as the alt text says."""
    scale = re.search(r"on small squares of ([\d.]+) s by ([\d.]+) ", alt)
    low = re.search(r" from (-?[\d.]+) to ", alt)
    assert scale and low, f"the alt text gives no scale: {alt!r}"
    return float(scale[1]), float(scale[2]), float(low[1])


def on_grid(x: float, low: float, half: float) -> bool:
    steps = (x - low) / half
    return abs(steps - round(steps)) < 1e-6


class Cursor:
    """The graph's cursor, by keys only; each press returns what the live region then says."""

    def __init__(self, page, section):
        self.page, self.section = page, section

    def press(self, key: str) -> str:
        self.page.keyboard.press(key)
        return self.page.evaluate(f"document.querySelector('{SAID}').textContent").strip()

    def sweep(self) -> list[tuple[float, float | None]]:
        """Home, then Right a small square at a time to the end of the time axis."""
        readings = [parse(self.press("Home"))]
        while True:
            said = self.press("ArrowRight")
            if said.startswith("End of the time axis"):
                return readings
            readings.append(parse(said))
            assert len(readings) < 200, "the cursor never reached the end of the time axis"


# ---------------------------------------------------------- a student's working, by template


def given(text: str, pattern: str) -> float:
    """A number the question's text (or a part's prompt) gives, by the words around it."""
    found = re.search(pattern, text.replace("\xa0", " "))
    assert found, f"{pattern!r} not in the question's text {text!r}"
    return number(found[1])


def levels(readings):
    """The line's level start and end, and where it leaves the first and meets the last: the
    last time at the first value and the first time at the last value (the turns a student reads)."""
    drawn = [(t, v) for t, v in readings if v is not None]
    (_, first), (_, last) = drawn[0], drawn[-1]
    leaves = max(t for t, v in drawn if v == first and all(w == first for s, w in drawn if s <= t))
    meets = min(t for t, v in drawn if v == last and all(w == last for s, w in drawn if s >= t))
    return first, last, leaves, meets


def runs(readings) -> list[tuple[str, float]]:
    """The straight pieces by which way they go ("+", "0", "−") and their gradients, from the
    readings' successive differences (the sign survives the rounding to half a square)."""
    drawn = [(t, v) for t, v in readings if v is not None]
    pieces: list[list] = []
    for (t1, v1), (t2, v2) in itertools.pairwise(drawn):
        way = "0" if v2 == v1 else ("+" if v2 > v1 else "−")
        if pieces and pieces[-1][0] == way:
            pieces[-1][3:] = [t2, v2]
        else:
            pieces.append([way, t1, v1, t2, v2])
    return [(way, (v2 - v1) / (t2 - t1)) for way, t1, v1, t2, v2 in pieces]


def skydiver(q):
    terminal = q.readings[-1][1]
    mass = given(q.text, r"of mass (\S+) kg")
    return {"a": (terminal, "m s^-1"), "b": (sig3(mass * G), "N"),
            "c": (sig3(mass * G / terminal**2), "kg m^-1")}, [terminal]


def ball(q):
    terminal = q.readings[-1][1]
    moment = given(q.legends[1], rf"at ({NUMBER}) s")
    speed = next(v for t, v in q.readings if math.isclose(t, moment))
    return {"a": (terminal, "m s^-1"), "b": (speed, "m s^-1"),
            "c": (sig3(G * (1 - speed**2 / terminal**2)), "m s^-2")}, [terminal, speed]


def kick(q):
    drawn = [(t, v) for t, v in q.readings if v is not None]
    largest = max(v for _, v in drawn)
    area = sum((t2 - t1) * (v1 + v2) / 2 for (t1, v1), (t2, v2) in itertools.pairwise(drawn))
    mass = given(q.text, r"of mass (\S+) kg")
    return {"a": (largest, "N"), "b": (sig3(area), "N s"), "c": (sig3(area / mass), "m s^-1")}, [largest]


def cyclist(q):
    first, last, leaves, meets = levels(q.readings)
    return {"a": (first, "N s"), "b": (last, "N s"),
            "c": (sig3((last - first) / (meets - leaves)), "N")}, [first, last, leaves, meets]


def bounce(q):
    first, last, leaves, meets = levels(q.readings)
    force = (last - first) / (meets - leaves)
    assert "towards the wall as positive" in q.text
    way = "towards the wall" if force > 0 else "away from the wall"
    return {"a": (first, "N s"), "b": (last, "N s"), "c": (sig3(abs(force)), "N", way)}, [first, last]


def lorry(q):
    first, last, _, _ = levels(q.readings)
    mass = given(q.text, rf"of mass ({NUMBER}) kg")
    return {"a": (first, "N s"), "b": (last, "N s"), "c": (sig3(last / mass), "m s^-1"),
            "d": (sig3((last - first) / mass), "m s^-1")}, [first, last]


def trolley(q):
    first, last, _, _ = levels(q.readings)
    mass = given(q.text, r"of mass (\S+) kg")
    return {"a": (first, "N s"), "b": (last, "N s"), "c": (sig3((first - last) / mass), "m s^-1")}, [first, last]


SIGN_WORDS = {"a positive value": "+", "zero": "0", "a negative value": "−"}


def force_choice(q):
    """F = gradient: each straight piece gives a constant force of its sign; the option whose
    description starts at and jumps to those signs, in that order."""
    signs = [way for way, _ in runs(q.readings)]
    chosen = [letter for letter, label in q.options.items()
              if [SIGN_WORDS[w] for w in re.findall(r"(?:starts at|jumps to) (a positive value|zero|a negative value)",
                                                    label)] == signs]
    assert len(chosen) == 1, f"the gradients' signs {signs} fit {chosen} of {q.options}"
    drawn = [(t, v) for t, v in q.readings if v is not None]
    corners = [v for (_, u), (_, v), (_, w) in zip(drawn, drawn[1:], drawn[2:], strict=False)
               if (v - u) * (w - v) <= 0 and u != w]
    return {"a": chosen[0]}, corners


STUDENTS = {
    "graph-skydiver-terminal": skydiver,
    "graph-ball-acceleration": ball,
    "graph-kick-force-time": kick,
    "graph-cyclist-momentum-time": cyclist,
    "graph-bounce-momentum-time": bounce,
    "graph-lorry-speed-momentum-time": lorry,
    "graph-trolley-collision": trolley,
    "force-from-momentum-graph-choice": force_choice,
}


class Question:
    """What a student without sight has: the text, the parts' prompts, the alt text, the
    options' names, and the cursor's readings."""

    def __init__(self, page, section, readings):
        self.text = section.locator(".q-text").inner_text()
        self.legends = section.locator("fieldset.q-part legend").all_inner_texts()
        self.alt = section.locator("img.q-graph").get_attribute("alt")
        self.options = {radio.get_attribute("value"): radio.evaluate(
            "r => { const l = r.closest('label'), s = l.querySelector('.q-option-text svg');"
            " return (s && s.getAttribute('aria-label')) || l.innerText; }")
            for radio in section.locator("input.q-choice").all()}
        self.readings = readings


# ----------------------------------------------------------------------------- keyboard only


def tab_to(page, selector: str) -> None:
    """Tab forward until `selector` has focus (a few presses at most)."""
    for _ in range(12):
        if page.evaluate("s => document.activeElement && document.activeElement.matches(s)", selector):
            return
        page.keyboard.press("Tab")
    raise AssertionError(f"Tab never reached {selector}")


def answer_by_keys(page, section, key: str, answers: dict) -> str:
    """Type each part's answer, reaching each box by Tab, then Check; the score's text."""
    base = f"q-{key}"
    for part, answer in answers.items():
        if isinstance(answer, str):  # a letter: arrows move the choice in a radio group
            tab_to(page, f"#{base}-{part}-A")
            page.keyboard.press("Space")
            for _ in range("ABCD".index(answer)):
                page.keyboard.press("ArrowDown")
            assert section.locator(f"#{base}-{part}-{answer}").is_checked()
            continue
        value, unit, *way = answer
        tab_to(page, f"#{base}-{part}-value")
        page.keyboard.type(str(value))
        tab_to(page, f"#{base}-{part}-unit")
        page.keyboard.type(unit)
        if way:
            tab_to(page, f"#{base}-{part}-direction")
            direction = section.locator(f"#{base}-{part}-direction")
            options = direction.evaluate("select => [...select.options].map(o => o.value)")
            for _ in range(options.index(way[0]) - options.index(direction.input_value())):
                page.keyboard.press("ArrowDown")  # down the options to the direction
            assert section.locator(f"#{base}-{part}-direction").input_value() == way[0]
    tab_to(page, f'section.q[data-q="{key}"] button.q-check')
    page.keyboard.press("Enter")
    return section.locator(".q-score").inner_text()


def read_and_answer(page, key: str) -> tuple[Question, list[float], str]:
    section = page.locator(f'section.q[data-q="{key}"]')
    section.locator("button.q-graph-open").focus()
    page.keyboard.press("Tab")
    assert page.evaluate("document.activeElement.getAttribute('role')") == "slider", f"{key}: no cursor after the graph"
    question = Question(page, section, Cursor(page, section).sweep())
    answers, asked = STUDENTS[key](question)
    return question, asked, answer_by_keys(page, section, key, answers)


def full_marks(score: str) -> bool:
    got = re.match(r"(\d+)/(\d+) marks?", score)
    return bool(got) and got[1] == got[2]


def check_grid(key: str, question: Question) -> None:
    time_square, value_square, low = squares_from_alt(question.alt)
    for t, v in question.readings:
        assert on_grid(t, 0.0, time_square / 2), f"{key}: t = {t} is not on half a small square of {time_square} s"
        assert v is None or on_grid(v, low, value_square / 2), (
            f"{key}: {v} is not on half a small square of {value_square} above {low}")
    assert len(question.readings) == round(question.readings[-1][0] / time_square) + 1, (
        f"{key}: Right does not move one small square")


def alt_numbers(alt: str) -> list[float]:
    """Every number of the alt text but the time axis's own (its end and its small square: a
    time of 30 s is no reading of 30 m s⁻¹)."""
    values = re.sub(r"against time in s from \S+ to \S+|squares of \S+ s by", "", alt.replace("\u202f", ""))
    return [float(x) for x in re.findall(r"-?\d+(?:\.\d+)?", values)]


def check_alt(key: str, alt: str, asked: list[float]) -> None:
    for reading in asked:
        assert all(not math.isclose(x, reading, rel_tol=1e-9, abs_tol=1e-12) for x in alt_numbers(alt)), (
            f"{key}: the alt text gives the reading {reading}: {alt!r}")


@pytest.fixture(scope="module")
def templates(site_dir) -> dict[str, str]:
    """One question of each graph template on the site that is answered from its graph's
    readings: {template key: page}. A sketch drawn from the printed graph (its part is
    drawn_from_graph) reads no value off it, so the cursor has nothing to give it."""
    found = {}
    for path, key in graph_questions(site_dir):
        if not any(part.drawn_from_graph for part in bank.TEMPLATES[key].variant(0).parts):
            found.setdefault(key, path)
    assert set(found) == set(STUDENTS), f"graph templates on the site {sorted(found)}, solved {sorted(STUDENTS)}"
    return found


def test_each_graph_question_is_answered_from_the_cursor_s_announcements_alone(browser, base_url, templates):
    context = browser.new_context()
    page = context.new_page()
    errors = []
    page.on("pageerror", lambda error: errors.append(str(error)))
    for key, path in templates.items():
        page.goto(f"{base_url}/{path}", wait_until="load")
        assert page.locator(SAID).count() == 1, "not one live region for the cursor"
        assert page.locator(SAID).get_attribute("aria-live") == "polite"
        question, asked, score = read_and_answer(page, key)
        assert full_marks(score), f"{key}: {score} from the readings {question.readings}"
        check_grid(key, question)
        check_alt(key, question.alt, asked)
    context.close()
    assert not errors, errors


def test_shift_moves_a_large_square_and_home_and_end_reach_the_ends(browser, base_url, templates):
    key = "graph-cyclist-momentum-time"
    context = browser.new_context()
    page = context.new_page()
    page.goto(f"{base_url}/{templates[key]}", wait_until="load")
    section = page.locator(f'section.q[data-q="{key}"]')
    slider = section.locator('[role="slider"]')
    slider.focus()
    cursor = Cursor(page, section)
    time_square, _, _ = squares_from_alt(section.locator("img.q-graph").get_attribute("alt"))
    assert parse(cursor.press("Home"))[0] == 0
    large = parse(cursor.press("Shift+ArrowRight"))[0]
    assert large > time_square and on_grid(large, 0, time_square), large
    assert parse(cursor.press("ArrowRight"))[0] == pytest.approx(large + time_square)
    assert parse(cursor.press("Shift+ArrowLeft"))[0] == pytest.approx(time_square)
    end = parse(cursor.press("End"))[0]
    assert cursor.press("ArrowRight").startswith("End of the time axis")
    assert float(slider.get_attribute("aria-valuenow")) == pytest.approx(end)
    assert float(slider.get_attribute("aria-valuemax")) == pytest.approx(end)
    context.close()


def test_new_numbers_give_the_cursor_the_new_graph(browser, base_url, templates):
    key = "graph-cyclist-momentum-time"
    context = browser.new_context()
    page = context.new_page()
    page.goto(f"{base_url}/{templates[key]}", wait_until="load")
    before, _, _ = read_and_answer(page, key)
    form = page.locator(f'form.q-form[data-question="{key}"]')
    form.locator("button.q-new").click()
    page.wait_for_function(f"document.querySelector('form.q-form[data-question=\"{key}\"]').dataset.variant !== '0'")
    after, asked, score = read_and_answer(page, key)
    assert after.alt != before.alt or after.readings != before.readings, "the cursor still reads the old graph"
    assert full_marks(score), f"{key} after New numbers: {score} from {after.readings}"
    check_grid(key, after)
    check_alt(key, after.alt, asked)
    context.close()


def test_no_alt_text_of_any_site_variant_gives_a_reading_a_part_asks_for(site_dir, templates):
    for key, path in templates.items():
        html = (site_dir / path).read_text(encoding="utf-8")
        section = html[html.index(f'data-q="{key}"'):]
        printed = json.loads(re.search(r'<script type="application/json" class="q-data">(.*?)</script>',
                                       section, re.DOTALL)[1])
        alt = re.search(r'<img alt="([^"]*)"[^>]*class="q-graph"', section)[1]
        variants = [(printed, alt)]
        script = site_dir / "_static" / "questions" / f"{key}.js"
        if script.exists():
            variants += [(variant, variant["graph"]["alt"]) for variant in shipped_variants(script)]
        for variant, alt in variants:
            asked = [part["value"] for part in variant["parts"] if part.get("kind") == "graph"]
            check_alt(key, alt, asked)


# ------------------------------------------------------------- a tap in the enlarged view, 390 px


def vertical_lines(svg: str) -> tuple[float, list[float], list[float]]:
    """The viewBox's width, the x of every vertical grid line (time 0 first), and the y of every
    horizontal grid line by its place from the bottom, in the SVG's own units."""
    width, _, xs, ys = grid_lines(svg)
    return width, xs, ys[::-1]


def test_a_tap_in_the_enlarged_view_moves_the_cursor_and_draws_it_at_390_px(browser, base_url, templates):
    key = "graph-cyclist-momentum-time"
    context = browser.new_context(**PHONE)
    page = context.new_page()
    page.goto(f"{base_url}/{templates[key]}", wait_until="load")
    section = page.locator(f'section.q[data-q="{key}"]')
    alt = section.locator("img.q-graph").get_attribute("alt")
    time_square, value_square, low = squares_from_alt(alt)
    section.locator("button.q-graph-open").tap()
    page.wait_for_function("() => { const i = document.querySelector('dialog.q-graph-view img.q-graph-large');"
                           " return i && i.complete && i.naturalWidth > 0; }")
    image = page.locator("dialog.q-graph-view img.q-graph-large")
    with urllib.request.urlopen(image.evaluate("i => i.currentSrc")) as response:
        width, xs, ys = vertical_lines(response.read().decode("utf-8"))
    for squares in (16.4, 7.2):  # rounds to 16.5 and 7 small squares of time
        target = xs[0] + squares * (xs[1] - xs[0])
        # bring that time into view, then tap it
        page.evaluate("([f]) => { const p = document.querySelector('.q-graph-pane'),"
                      " i = p.querySelector('img'); p.scrollLeft = f * i.getBoundingClientRect().width"
                      " - p.clientWidth / 2; }", [target / width])
        box = image.bounding_box()
        scale = box["width"] / width
        page.touchscreen.tap(box["x"] + target * scale, box["y"] + box["height"] * 0.5)
        said = page.evaluate(f"document.querySelector('{SAID}').textContent").strip()
        assert page.evaluate(f"!!document.querySelector('dialog.q-graph-view {SAID}')"), "the region is not in the view"
        t, value = parse(said)
        assert t == pytest.approx(round(squares * 2) / 2 * time_square), said
        assert on_grid(value, low, value_square / 2), said
        # the reading is the student's to take: the view writes it when asked
        show = page.locator("dialog.q-graph-view button.q-graph-show-reading")
        if squares == 16.4:
            assert not re.search(r"\d", page.locator(".q-graph-reading-large").inner_text()), "the view read the graph"
            show.tap()
        assert not show.is_visible()
        shown = page.locator(".q-graph-reading-large").inner_text().strip()
        assert parse(shown) == (t, value), shown
        # the marker stands where the SVG's grid puts that reading
        line = page.locator(".q-graph-marker-time").bounding_box()
        across = page.locator(".q-graph-marker-value").bounding_box()
        x = box["x"] + (xs[0] + t / time_square * (xs[1] - xs[0])) * scale
        y_low, y_next = ys[0], ys[1]
        y = box["y"] + (y_low + (value - low) / value_square * (y_next - y_low)) * scale
        assert line["x"] + line["width"] / 2 == pytest.approx(x, abs=1.5), (line, x)
        assert across["y"] + across["height"] / 2 == pytest.approx(y, abs=1.5), (across, y)
        assert across["x"] + across["width"] == pytest.approx(x, abs=2.0)
    # (Escape after a tap in the view does not close it in this emulated phone, before this
    # branch too; a phone has no Escape key: its Close button)
    page.locator("dialog.q-graph-view button.q-graph-close").tap()
    page.wait_for_function("!document.querySelector('dialog.q-graph-view').open")
    assert page.evaluate(f"document.querySelector('{SAID}').parentNode === document.body")
    context.close()


READING = "dialog.q-graph-view .q-graph-reading-large"
SHOW = "dialog.q-graph-view button.q-graph-show-reading"


def _tap_the_middle(page) -> None:
    box = page.locator("dialog.q-graph-view img.q-graph-large").bounding_box()
    pane = page.locator("dialog.q-graph-view .q-graph-pane").bounding_box()
    page.touchscreen.tap(pane["x"] + min(box["width"], pane["width"]) * 0.6, pane["y"] + min(box["height"], pane["height"]) * 0.5)
    page.wait_for_function("!document.querySelector('.q-graph-marker-time').hidden")


def test_the_view_writes_the_reading_only_when_asked_or_once_the_readings_are_typed(browser, base_url, templates):
    """A tap places the cursor and draws it; the reading's numbers stay off the screen until
    Show the reading, for each graph of its own (New numbers hides it again), or until every
    part read off the graph has a value typed."""
    key = "graph-lorry-speed-momentum-time"
    context = browser.new_context(**PHONE)
    page = context.new_page()
    page.goto(f"{base_url}/{templates[key]}", wait_until="load")
    section = page.locator(f'section.q[data-q="{key}"]')
    opener = section.locator("button.q-graph-open")

    def open_and_tap() -> str:
        opener.tap()
        page.wait_for_function("document.querySelector('dialog.q-graph-view').open")
        _tap_the_middle(page)
        return page.locator(READING).inner_text()

    assert not re.search(r"\d", open_and_tap()), "a tap showed the reading"
    assert page.locator(SHOW).is_visible()
    page.locator(SHOW).tap()
    assert parse(page.locator(READING).inner_text())[1] is not None
    assert not page.locator(SHOW).is_visible()
    page.locator("dialog.q-graph-view button.q-graph-close").tap()

    # New numbers: a new graph, read by the student again
    section.locator("button.q-new").tap()
    page.wait_for_function(f"document.querySelector('form.q-form[data-question=\"{key}\"]').dataset.variant !== '0'")
    assert not re.search(r"\d", open_and_tap()), "the new graph's reading showed at a tap"
    page.locator("dialog.q-graph-view button.q-graph-close").tap()

    # the readings typed, one part after the other: offered once both are
    graph_parts = section.locator('fieldset.q-part[data-kind="graph"] input.q-value')
    assert graph_parts.count() == 2
    graph_parts.nth(0).fill("1")
    assert not re.search(r"\d", open_and_tap()), "the reading showed with one of two readings typed"
    page.locator("dialog.q-graph-view button.q-graph-close").tap()
    graph_parts.nth(1).fill("2")
    assert parse(open_and_tap())[1] is not None, "the reading did not show once the readings were typed"
    assert not page.locator(SHOW).is_visible()
    context.close()
