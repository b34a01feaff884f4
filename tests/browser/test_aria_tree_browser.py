"""A screen reader's view of the questions and the explorables (issue 28, item 5), in Chromium.

Chromium's accessibility tree (Playwright's aria snapshot) is checked against the shapes in
tests/aria_snapshots/, filled at test time from the data the page itself was built from:

* one question of each kind (numeric, numeric with a direction, multiple choice, text, graph):
  the parts' groups by their legends, each box by its name, after a wrong Check (a named mistake,
  or a wrong option, or no point ticked) the status that announces that mistake's own feedback and
  the marks it keeps, then after a right Check "✓" and full marks; the graph's button named by its
  alt text, its cursor a slider named "Graph cursor", whose reading at End the live region says;
* each explorable: its region by name, described by what it models, its sliders by name at their
  starting values, read-outs the models give for them; a slider moved by a key is announced with
  its new value.
"""

from __future__ import annotations

import json
import math
import re
import string
from pathlib import Path

import pytest
from playwright.sync_api import expect
from support.pages import explorable_page, words
from support.templates import sig3

from physics_figures.explorables import ABOUT, EXPLORABLES, explorable_data
from physics_figures.notation import format_number
from physics_figures.parts.graph import reading_places

pytestmark = [pytest.mark.site, pytest.mark.browser]

SHAPES = Path(__file__).parents[1] / "aria_snapshots"
PAGE = "book/exam/practice-force-momentum.html"  # it asks a question of every kind but text
#: The kinds asked on a page of their own (the define and state questions).
PAGE_OF = {"text": "book/exam/practice-statements.html"}
#: One question of each kind on that page, by the template's key.
KINDS = {
    "numeric": "practice-hose",
    "numeric with direction": "practice-wall-bounce",
    "mcq": "bounce-force-choice",
    "text": "state-second-law",
    "graph": "graph-cyclist-momentum-time",
}


#: A node of a shape: `- role "name" [state]`, then `:` and what it holds, or nothing.
NODE = re.compile(r'^(\s*- )(\w+ "(?:[^"\\]|\\.)*"(?: \[[^\]]*\])*)(:.*)?$')


def shape(name: str, **values: str) -> str:
    """A shape of tests/aria_snapshots/ with its values; a node whose name holds ": " is quoted
    whole, as YAML needs (and as Playwright writes it)."""
    filled = string.Template((SHAPES / f"{name}.yaml").read_text(encoding="utf-8")).substitute(values)
    lines = []
    for line in filled.splitlines():
        node = NODE.match(line)
        if node and ": " in node[2]:
            line = node[1] + "'" + node[2].replace("'", "''") + "'" + (node[3] or "")
        lines.append(line)
    return "\n".join(lines) + "\n"


def quoted(text: str) -> str:
    """A YAML string for the snapshot: the text exactly."""
    return json.dumps(words(text), ensure_ascii=False)


def name(text: str) -> str:
    """A name inside a shape's double quotes."""
    return json.dumps(words(text), ensure_ascii=False)[1:-1]


def starts_with(text: str) -> str:
    """A regular expression for the snapshot: text that begins with these words, however spaced."""
    return "/^" + r"\s+".join(re.escape(word).replace("/", r"\/") for word in text.split()) + "/"


def plain(html: str) -> str:
    return re.sub(r"<[^>]+>", "", html)


def marks_text(earned: int, available: int) -> str:
    return f"{earned}/{available} mark" + ("" if available == 1 else "s")


class Asked:
    """A question on the page and its data, as the page was built with it."""

    def __init__(self, page, key: str):
        self.key, self.page = key, page
        self.section = page.locator(f'section.q[data-q="{key}"]')
        self.data = json.loads(self.section.locator("script.q-data").text_content())
        self.parts = self.data["parts"]

    def lines(self, part: dict) -> list[dict]:
        return [line for line in self.data["marks"] if line["part"] == part["id"]]

    def names(self, part: dict) -> dict[str, str]:
        several = len(self.parts) > 1
        label = f"({part['id']}) " if several else ""
        prompt = part["prompt"][:1].upper() + part["prompt"][1:]
        return {"legend": name(label + prompt),
                **{f"{box}_name": name(f"({part['id']}) {box}" if several else box.capitalize())
                   for box in ("value", "unit", "direction")}}

    def field(self, part: dict, box: str):
        return self.section.locator(f"#q-{self.key}-{part['id']}-{box}")


def wrong_answer(asked: Asked, part: dict) -> tuple[int, str]:
    """Answer the part wrongly, the way its data names a mistake where it can; the marks it keeps
    and the feedback's opening words (a regular expression)."""
    kind = part.get("kind", "numeric")
    if kind == "mcq":
        option = next(o for o in part["options"] if o["letter"] != part["answer"])
        asked.section.locator(f"#q-{asked.key}-{part['id']}-{option['letter']}").check()
        return 0, starts_with("✗ " + option["feedback"])
    if kind == "text":
        asked.field(part, "text").fill("It is about forces.")
        return 0, "/^✗ Missing/"
    mistake = next((m for m in part.get("mistakes", []) if m["unit"] is None and m["direction"] is None), None)
    value = mistake["value"] if mistake else part["value"] * 3
    asked.field(part, "value").fill(sig3(value))
    asked.field(part, "unit").fill(part["unit"])
    if part["direction"] == "choice":
        asked.field(part, "direction").select_option(part["answerDirection"])
    if mistake is None:
        return 0, "/^✗/"
    kept = sum(1 for line in asked.lines(part) if not set(line["roles"]) & set(mistake["loses"]))
    return kept, starts_with("✗ " + mistake["feedback"])


def right_answer(asked: Asked, part: dict) -> None:
    kind = part.get("kind", "numeric")
    if kind == "mcq":
        asked.section.locator(f"#q-{asked.key}-{part['id']}-{part['answer']}").check()
    elif kind == "text":  # the scheme's words (9702/21/M/J/16 Q3(b)(i)), marked from what is typed
        asked.field(part, "text").fill("The resultant force is proportional to the rate of change of momentum.")
    else:
        asked.field(part, "value").fill(sig3(part["value"]))


def expected(asked: Asked, feedback: dict[str, str], earned: dict[str, int]) -> str:
    """The form's shape after a Check: each part's group with what it holds and says."""
    out = []
    for part in asked.parts:
        kind = part.get("kind", "numeric")
        names = asked.names(part)
        if kind == "mcq":
            option = next(o for o in part["options"] if o["letter"] == asked.section.locator(
                f'[data-part="{part["id"]}"] input.q-choice:checked').get_attribute("value"))
            block = shape("part-mcq", legend=names["legend"], chosen=name(f"{option['letter']} {plain(option['html'])}"),
                          feedback=feedback[part["id"]])
        elif kind == "text":  # each point says what the marker found of it (questions.css)
            point = part["points"][0]
            found = "✓ made: " if feedback[part["id"]].startswith("/^✓") else "✗ not made: "
            block = shape("part-text", legend=names["legend"], text=quoted(asked.field(part, "text").input_value()),
                          point=name(f"{found}{point['text']} {point['code']}"), feedback=feedback[part["id"]])
        else:
            values = {"value": quoted(asked.field(part, "value").input_value()), "unit": quoted(part["unit"]),
                      "feedback": feedback[part["id"]], **names}
            if part["direction"] == "choice":
                block = shape("part-direction", direction=name(part["answerDirection"]), **values)
            else:
                block = shape("part-numeric", **values)
        if len(asked.parts) > 1:
            block += shape("part-marks", part_marks=quoted(marks_text(earned[part["id"]], len(asked.lines(part)))))
        out.append(block)
    total = sum(earned.values())
    out.append(shape("question-end", score=quoted(marks_text(total, len(asked.data["marks"])))))
    return "".join(out)


@pytest.mark.parametrize("kind", KINDS)
def test_a_question_s_tree_names_its_boxes_and_announces_wrong_then_right(browser, base_url, kind):
    context = browser.new_context()
    page = context.new_page()
    page.goto(f"{base_url}/{PAGE_OF.get(kind, PAGE)}", wait_until="load")
    asked = Asked(page, KINDS[kind])
    form = asked.section.locator("form.q-form")

    kept = {part["id"]: wrong_answer(asked, part) for part in asked.parts}
    form.locator("button.q-check").click()
    expect(form).to_match_aria_snapshot(expected(
        asked, {pid: said for pid, (_, said) in kept.items()}, {pid: k for pid, (k, _) in kept.items()}))

    for part in asked.parts:
        right_answer(asked, part)
    form.locator("button.q-check").click()
    full = {part["id"]: len(asked.lines(part)) for part in asked.parts}
    right = {part["id"]: "/^✓/" for part in asked.parts}
    expect(form).to_match_aria_snapshot(expected(asked, right, full))

    if kind == "graph":
        alt = asked.section.locator("img.q-graph").get_attribute("alt")
        expect(asked.section).to_match_aria_snapshot(
            shape("graph", alt=name(alt)))
        asked.section.get_by_role("slider", name="Graph cursor").press("End")
        last = next(p for p in reversed(asked.parts) if p.get("kind") == "graph")
        reading = format_number(last["value"], decimals=reading_places(last["tolerance"]))
        unit = r"\s".join(last["unit"].split())
        said = page.locator(".q-graph-said")
        expect(said).to_have_text(re.compile(rf"t = [\d.]+\ss, p = {re.escape(reading)}\s{unit}$"))
    context.close()


def shown(x: float) -> str:
    """A slider's value as its input holds it: 80, 0.6, 2."""
    return quoted(f"{x:g}")


def readout(label: str, value: float, unit: str, figures: int = 3) -> str:
    return name(f"{label} {format_number(value, figures)}{'' if unit == '%' else ' '}{unit}")


def explorable_values(name: str) -> tuple[dict[str, str], tuple[str, str, float]]:
    """The shape's values from the explorable's data, through the models where a read-out shows
    one; and its first slider: label, unit as spoken, starting value."""
    data = explorable_data(name)
    about = quoted(ABOUT[name])
    if name == "skydiver":
        weight = data["mass"] * data["g"]
        return ({"about": about, "mass": shown(data["mass"]),
                 "weight": readout("Weight W = mg", weight, "N"),
                 "terminal": readout("Terminal velocity, falling freely", math.sqrt(weight / data["bodyDrag"]), "m s⁻¹")},
                ("Mass of the skydiver", "kilograms", data["mass"]))
    if name == "collision-lab":
        m1, u1, m2, u2 = data["m1"], data["u1"], data["m2"], data["u2"]
        together = (m1 * u1 + m2 * u2) / (m1 + m2)
        before, after = (m1 * u1**2 + m2 * u2**2) / 2, (m1 + m2) * together**2 / 2
        return ({"about": about, "m1": shown(m1), "u1": shown(u1), "m2": shown(m2), "u2": shown(u2),
                 "lost": readout("Kinetic energy lost", 100 * (before - after) / before, "%")},
                ("Mass of A", "kilograms", m1))
    if name == "momentum-triangle":
        before, known, angle = data["momentumBefore"], data["momentumKnown"], math.radians(data["angleKnown"])
        q = math.hypot(before - known * math.cos(angle), known * math.sin(angle))
        return ({"about": about, "known": shown(data["momentumKnown"]), "angle": shown(data["angleKnown"]),
                 "q_momentum": readout("Momentum of Q", q, "N s")},
                ("Momentum of P after", "newton seconds", data["momentumKnown"]))
    times, momenta = data["times"], data["momenta"]
    t = (times[0] + times[1]) / 2
    p = momenta[0] + (momenta[1] - momenta[0]) * (t - times[0]) / (times[1] - times[0])
    return ({"about": about, "time": shown(t), "momentum": readout("Momentum p", p, "kg m s⁻¹", 2),
             "velocity": readout("Velocity v = p / m", p / data["mass"], "m s⁻¹")},
            ("Time along the graph", "seconds", t))


@pytest.mark.parametrize("name", EXPLORABLES)
def test_an_explorable_s_tree_names_its_sliders_and_announces_a_move(browser, base_url, site_dir, name):
    context = browser.new_context(viewport={"width": 1280, "height": 900})
    page = context.new_page()
    page.goto(f"{base_url}/{explorable_page(site_dir, name)}", wait_until="load")
    page.wait_for_selector(f'.explorable[data-explorable="{name}"][data-built]')
    box = page.locator(f'.explorable[data-explorable="{name}"]')
    values, (label, spoken, start) = explorable_values(name)
    expect(box).to_match_aria_snapshot(shape(f"explorable-{name}", **values))

    slider = box.get_by_role("slider", name=re.compile("^" + re.escape(label)))
    step = float(slider.get_attribute("step"))
    slider.press("ArrowRight")
    moved = format_number(start + step, 3)
    expect(box.locator('[aria-live="polite"]').first).to_have_text(
        re.compile(rf"^{re.escape(label)}\s{re.escape(moved)}\s{spoken}\."), timeout=5000)
    context.close()
