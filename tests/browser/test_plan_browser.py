"""Spaced review and the plan of Your practice, as a student meets them, in Chromium with a
fixed clock: real questions of the site answered right, partly (a named mistake) and wrong,
and one right after help; the ratings and the stored schedule, with each due date
checked against ts-fsrs called directly in Node (request retention 0.9, its defaults); Start
serving the due cards interleaved, each with new numbers, card after card to the end; the
first screen at 390 x 844 and the page's height; a real format 1 export (made on the site
before format 2, tests/fixtures/progress_v1) imported with every attempt kept.

Answers come from the variant data the site ships (window.QuestionVariants) or the bank's
variant 0; templates are picked from the page's embedded list, so the bank can grow."""

from __future__ import annotations

import itertools
import json
import math
import subprocess
from datetime import UTC, datetime, timedelta
from pathlib import Path
from urllib.parse import urljoin

import pytest
from browser import node_module, progress_checksum
from support.pages import open_page, stored, watched_context

from physics_figures import bank

pytestmark = [pytest.mark.site, pytest.mark.browser]

ROOT = Path(__file__).resolve().parents[2]
PROGRESS = "/book/exam/your-practice.html"
STORE = "dynamics-progress-v2"
V1_FILE = ROOT / "tests" / "fixtures" / "progress_v1" / "progress-v1.json"
PHONE = {"width": 390, "height": 844}
# A school morning, in UTC (Chromium's zone here): the plan's "today" ends at midnight.
MORNING = datetime(2026, 11, 26, 9, 0, tzinfo=UTC)
AGAIN, HARD, GOOD, EASY = 1, 2, 3, 4
NEXT = 5  # the cards Start serves after those due (progress-plan.js)

# ts-fsrs called directly: each card's due date after its reviews ([[at, rating], ...]).
FSRS_IN_NODE = """
const {fsrs, generatorParameters, createEmptyCard} = require(process.argv[1]);
const f = fsrs(generatorParameters({request_retention: 0.9}));
const out = {};
for (const [id, reviews] of Object.entries(JSON.parse(process.argv[2]))) {
  let card = createEmptyCard(new Date(reviews[0][0]));
  for (const [at, rating] of reviews) card = f.next(card, new Date(at), rating).card;
  out[id] = card.due.getTime();
}
console.log(JSON.stringify(out));
"""


@pytest.fixture
def context(site):
    with watched_context(*site, viewport=PHONE, accept_downloads=True) as context:
        context.clock.set_fixed_time(MORNING)
        yield context


def _at(context, when: datetime):
    context.clock.set_fixed_time(when)
    return int(when.timestamp() * 1000)


def _numeric(data) -> list[tuple[str, str, str]]:
    """(key, type, page) of each placed template whose parts are all numbers, quick-check's first."""
    found = [(t["key"], kind["type"], t["page"]) for kind in data["types"] for t in kind["templates"]
             if t["page"] and all(getattr(p, "unit", None) for p in bank.TEMPLATES[t["key"]].variant(0).parts)]
    return sorted(found, key=lambda k: k[2] != "quick-check.html")


def _answer(page, key: str, values: list[float | None] | None = None):
    """Answer the question as shown, from the variant data the site ships (its key's values, or
    `values`, None leaving a part blank), and Check: the score shown."""
    form = page.locator(f'form.q-form[data-question="{key}"]')
    variant = int(form.get_attribute("data-variant"))
    parts = page.evaluate(
        """([key, index]) => new Promise(done => {
            const ready = () => window.QuestionVariants && window.QuestionVariants[key];
            if (ready()) return done(ready()[index].parts);
            const s = document.createElement("script");
            s.src = (document.documentElement.dataset.content_root || "") + "_static/questions/" + key + ".js";
            s.onload = () => done(ready()[index].parts);
            document.head.appendChild(s);
        })""", [key, variant])
    for index, part in enumerate(parts):
        box = form.locator("fieldset.q-part").nth(index)
        value = (values or [p["value"] for p in parts])[index]
        if value is None:
            continue
        box.locator("input.q-value").fill(_written(value if part["direction"] == "signed" else abs(value)))
        box.locator("input.q-unit").fill(part["unit"])
        if part["direction"] == "choice":
            box.locator("select.q-direction").select_option(part["answerDirection"])
    form.locator("button.q-check").click()
    return form.locator(".q-score").inner_text()


def _written(value: float) -> str:
    """A value to 3 s.f. with its trailing zeros (5 is "5.00": a 1 s.f. answer loses the A1)."""
    text = f"{value:#.3g}"
    return (f"{value:.3g}" if "e" in text else text).rstrip(".")


def _fsrs_due(reviews: dict[str, list[tuple[int, int]]]) -> dict[str, int]:
    out = subprocess.run(["node", "-e", FSRS_IN_NODE, str(node_module("ts-fsrs")), json.dumps(reviews)],
                         capture_output=True, text=True, check=True)
    return json.loads(out.stdout)


def _practise(context):
    """Right, wrong, right after a step of help, and partly right (a named mistake), a minute
    apart: four real templates, the helped one of the wrong one's type, so that they fall due
    side by side (wrong after 1 minute, helped after about 5) and interleaving has work to do.
    Returns {"right"|"wrong"|"helped"|"partly": (key, type)} and the last question page."""
    page = open_page(context, PROGRESS)
    numeric = _numeric(json.loads(page.locator("script.pp-data").text_content()))
    wrong = numeric[0]
    helped = next(k for k in numeric if k[1] == wrong[1] and k != wrong)
    partly = next(k for k in numeric if k[1] != wrong[1] and any(
        m.unit is None and m.direction is None for m in bank.TEMPLATES[k[0]].variant(0).parts[0].mistakes))
    right = next(k for k in numeric if k[1] not in (wrong[1], partly[1]))
    chosen = {"right": right, "wrong": wrong, "helped": helped, "partly": partly}
    pages = {}
    for minute, (name, (key, _, where)) in enumerate(chosen.items(), start=1):
        if where not in pages:
            pages[where] = open_page(context, urljoin(PROGRESS, where))
        quick = pages[where]
        _at(context, MORNING + timedelta(minutes=minute))
        parts = bank.TEMPLATES[key].variant(0).parts
        if name == "partly":
            mistake = next(m for m in parts[0].mistakes if m.unit is None and m.direction is None)
            _answer(quick, key, [mistake.value] + [p.value for p in parts[1:]])
        elif name == "wrong":
            # the first part wrong, the rest left blank (a wrong answer carried forward could earn ecf)
            _answer(quick, key, [parts[0].value * 7.3 + 1] + [None] * (len(parts) - 1))
        else:
            if name == "helped":
                step = quick.locator(f'form.q-form[data-question="{key}"] button.q-step').first
                if step.count():
                    step.click()  # help before the answer (the help steps' button)
                else:  # without it: the attempt says help was used, as the button records it
                    quick.evaluate("() => { const r = ProgressStore.recordAttempt;"
                                   " ProgressStore.recordAttempt = (a, t) => r(Object.assign(a, {help: 1}), t); }")
            _answer(quick, key)
    chosen = {name: (key, kind) for name, (key, kind, _) in chosen.items()}
    return chosen, quick


def test_ratings_and_due_dates_follow_fsrs_and_the_wrong_one_comes_back_first(context):
    chosen, _ = _practise(context)
    page = open_page(context, PROGRESS)  # works the schedule out and keeps it
    progress = json.loads(stored(page, STORE))
    assert progress["version"] == 2
    rating = {a["question"]: a["rating"] for a in progress["attempts"]}
    key = {name: k for name, (k, _) in chosen.items()}
    assert rating[key["wrong"]] == AGAIN
    assert rating[key["partly"]] == HARD
    assert rating[key["helped"]] <= HARD  # help used: never above Hard
    assert rating[key["right"]] == EASY  # first try, no help, at once (the clock stood still)

    schedule = progress["schedule"]
    reviews = {a["question"]: [(a["at"], a["rating"])] for a in progress["attempts"]}
    expected = _fsrs_due(reviews)
    assert {card: schedule[card]["due"] for card in expected} == expected
    due = {name: schedule[k]["due"] for name, k in key.items()}
    assert due["wrong"] < due["partly"] < due["right"]
    assert due["wrong"] == min(due.values())

    # the page says so: the wrong one due now; helped and partly come back in minutes, later
    # today (FSRS's learning steps), so they are not "due today" yet; right (Easy) days away
    now = page.evaluate("Date.now()")
    assert due["wrong"] <= now < min(due["helped"], due["partly"])
    back = math.ceil((min(due["helped"], due["partly"]) - now) / 60_000)
    assert back <= 10
    assert page.locator(".pp-due-text").inner_text() == (
        f"1 card due today, then {NEXT} more. 2 cards come back later today, the next in {back} minutes.")
    helped = page.locator(f'li[data-key="{key["helped"]}"] .pp-marks').text_content()
    assert helped.endswith(f", back in {math.ceil((due['helped'] - now) / 60_000)} minutes)"), helped
    assert page.locator(f'li[data-key="{key["wrong"]}"] .pp-marks').text_content().endswith(", due today)")
    assert page.locator(f'.pp-type[data-type="{chosen["helped"][1]}"] .pp-line').text_content().endswith(" · 1 due")
    mistake = next(m for m in bank.TEMPLATES[key["partly"]].variant(0).parts[0].mistakes
                   if m.unit is None and m.direction is None)
    assert page.locator(".pp-often").inner_text().startswith(f"Most frequent mistake: {mistake.name} (once).")
    assert page.locator(".pp-weakest").inner_text().startswith(f"Weakest type: {_weakest(page, progress)}")


def _weakest(page, progress) -> str:
    """The type with the lowest share of marks over its tried templates (best attempt at each),
    the first in the book on a tie: its name."""
    best: dict[str, tuple[int, int]] = {}
    for a in progress["attempts"]:
        if a["question"] in bank.TEMPLATES and a["earned"] / a["available"] >= best.get(a["question"], (-1, 1))[0] / \
                best.get(a["question"], (-1, 1))[1]:
            best[a["question"]] = (a["earned"], a["available"])
    shares = []
    for order, kind in enumerate(bank.TOPIC.type_keys):
        marks = [m for key, m in best.items() if bank.TEMPLATES[key].type == kind]
        if marks:
            shares.append((sum(e for e, _ in marks) / sum(a for _, a in marks), order, kind))
    return page.locator(f'.pp-type[data-type="{min(shares)[2]}"] .pp-name').inner_text()


def test_start_serves_the_due_cards_interleaved_each_with_new_numbers_then_back(context):
    chosen, _ = _practise(context)
    later = _at(context, MORNING + timedelta(hours=2))
    page = open_page(context, PROGRESS)
    page.get_by_role("button", name="Start", exact=True).click()
    queue = json.loads(page.evaluate("localStorage.getItem('dynamics-review-v1')"))
    due = {k for name, (k, _) in chosen.items() if name != "right"}
    cards = queue["cards"]
    assert {c["id"] for c in cards[:3]} == due  # the due ones first, then the next ones
    # by due date wrong, helped (its type), partly: served mixed, partly between the two
    assert [c["id"] for c in cards[:3]] == [chosen[name][0] for name in ("wrong", "partly", "helped")]
    assert len(cards) == 3 + 5
    types = [c["type"] for c in cards]
    for i in range(1, len(cards)):  # never two of a type in a row while another type is left
        assert types[i] != types[i - 1] or len(set(types[i:])) == 1, types
    for position, card in enumerate(cards):
        page.wait_for_load_state("load")
        bar = page.locator(".rv-bar")
        if card["id"].startswith("definition:"):
            item = page.locator(f"#st-card-{card['id'].split(':', 1)[1]}")
            assert item.locator(".rv-count").inner_text() == f"Card {position + 1} of {len(cards)}"
            item.locator(".st-reveal").click()
            item.get_by_role("button", name="I knew it").click()
        else:
            form = page.locator(f'form.q-form[data-question="{card["id"]}"]')
            # which card this is, at the top of its question, from the start
            count = form.locator("xpath=ancestor::section[contains(@class, 'q')][1]").locator(".rv-count")
            assert count.inner_text() == f"Card {position + 1} of {len(cards)}"
            assert count.is_visible() and count.bounding_box()["y"] < form.bounding_box()["y"]
            assert not bar.count()  # the way on comes after the Check
            if form.locator("button.q-new").count():  # new numbers: not the ones shown before
                page.wait_for_function(
                    f"document.querySelector('form.q-form[data-question=\"{card['id']}\"]').dataset.variant !== '0'")
            assert "new=" not in page.url
            if card["id"] in due:
                _answer(page, card["id"])
            else:
                form.locator("button.q-check").click()
        last = position == len(cards) - 1
        assert bar.inner_text().startswith(f"Card {position + 1} of {len(cards)} · ")
        bar.get_by_role("link", name="Back to Your practice" if last else "Next card").click()
    page.wait_for_url(f"**{PROGRESS}")
    progress = json.loads(stored(page, STORE))
    served = {a["question"] for a in progress["attempts"] if a["at"] == later}
    assert due <= served  # each due card answered again, on the numbers Start gave
    assert {c["id"] for c in cards if c["id"].startswith("definition:")} <= served


def test_a_fresh_students_start_serves_a_card_of_every_type_in_turn(context):
    """New cards come from every type, not the book's first two: a fresh student's first
    sessions (Start, each card tried) serve every type within the first seven cards, and no two
    of a type together (CLARIFICATIONS, "Start's queue")."""
    page = open_page(context, PROGRESS)
    data = json.loads(page.locator("script.pp-data").text_content())
    types = {kind["type"] for kind in data["types"] if any(t["page"] for t in kind["templates"])}
    served = []
    while len(served) < len(types):
        page.get_by_role("button", name="Start", exact=True).click()
        page.wait_for_url(lambda url: PROGRESS not in url)  # the first card's page
        page.wait_for_load_state("load")
        cards = json.loads(page.evaluate("localStorage.getItem('dynamics-review-v1')"))["cards"]
        assert len(cards) == NEXT and len({c["id"] for c in served + cards}) == len(served) + NEXT
        assert all(a["type"] != b["type"] for a, b in itertools.pairwise(cards)), cards
        served += cards
        # each tried (a Check with nothing written is no attempt: record them as the page does)
        page.evaluate("""(cards) => cards.forEach((c, i) => ProgressStore.recordAttempt({question: c.id,
            type: c.type, variant: 0, earned: 1, available: 1, at: Date.now() - i, mistakes: []}))""", cards)
        page.goto(context.base + PROGRESS, wait_until="load")
    assert {c["type"] for c in served[:len(types)]} == types


def test_the_first_screen_shows_the_plan_and_the_page_is_at_most_two_screens(context):
    _practise(context)
    page = open_page(context, PROGRESS)
    for n in range(4):  # the latest shows, the earlier ones fold
        page.evaluate(f"""ProgressStore.recordMock({{id: "m{n}", paper: "{1 + n % 2}", at: Date.now() + {n},
            minutes: 25, ended: "submitted", earned: {10 + n}, available: 20, questions: []}})""")
    page.reload(wait_until="load")
    for selector in (".pp-due-text", ".pp-start", ".pp-weakest", ".pp-often"):
        box = page.locator(selector).bounding_box()
        assert box and box["y"] + box["height"] <= PHONE["height"], f"{selector} is below the first screen: {box}"
    assert page.locator(".pp-often a").count() == 1  # the mistake links to its section
    assert page.locator("details.pp-type[open]").count() == 0
    height = page.evaluate("document.documentElement.scrollHeight")
    assert height <= 2 * PHONE["height"], f"Your practice is {height} px tall at 390 px"
    assert page.locator(".pp-mock-latest").inner_text() == "Paper 2, 26 Nov 2026: 13/20 marks (65\u202f%)"
    earlier = page.locator(".pp-mock-earlier")
    assert earlier.locator("summary").inner_text() == "3 earlier mock tests"
    assert earlier.locator("li").all_text_contents()[0] == "Paper 1, 26 Nov 2026: 12/20 marks (60\u202f%)"


def test_a_real_version_1_export_imports_into_version_2_with_every_attempt_kept(context, tmp_path):
    v1 = json.loads(V1_FILE.read_text())
    assert v1["version"] == 1
    page = open_page(context, PROGRESS)
    page.get_by_label("Import progress from a file").set_input_files(str(V1_FILE))
    page.wait_for_function("document.querySelector('.pp-status').textContent.startsWith('Imported')")
    progress = json.loads(stored(page, STORE))
    assert progress["version"] == 2
    fields = ("question", "type", "variant", "earned", "available", "at", "mistakes")
    kept = [{f: a[f] for f in fields} for a in progress["attempts"]]
    for attempt in v1["attempts"]:
        assert attempt in kept
    for slug, card in v1["definitions"]["cards"].items():
        assert progress["definitions"]["cards"][slug] == card
        assert any(a["question"] == f"definition:{slug}" and a["at"] == card["at"] for a in progress["attempts"])
    # and out again as format 2, with the schedule and the checksum the class page checks
    page.get_by_label("Your name").fill("Plan tester")  # Export asks for a name once
    with page.expect_download() as download:
        page.get_by_role("button", name="Export progress").click()
    saved = json.loads(Path(download.value.path()).read_text())
    assert saved["version"] == 2 and saved["book"] == "dynamics"
    assert saved["sha256"] == progress_checksum(saved["attempts"])
    assert set(saved["schedule"]) == {a["question"] for a in saved["attempts"]}


def test_the_landing_page_links_your_practice_and_the_mock_test_in_its_first_screen(context):
    page = open_page(context, "/book/intro.html")
    for name, target in (("Your practice", "your-practice.html"), ("the mock test", "mock-test.html")):
        link = page.locator("main, article").first.get_by_role("link", name=name, exact=True).first  # the first of the page
        assert link.get_attribute("href").endswith(f"exam/{target}")
        box = link.bounding_box()
        assert box and box["y"] + box["height"] <= PHONE["height"], f"{name} is below the first screen: {box}"
