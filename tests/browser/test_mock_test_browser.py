"""The timed mock test (book/exam/mock-test.md) as a student takes it, in Chromium, with the
page's clock in the test's hands (Playwright's page.clock):

- Paper 1 (20 multiple-choice questions, 37½ minutes) and Paper 2 (20 marks, 25 minutes) style;
- nothing is marked before the end: no feedback text, no marks, no worked answer, no Check;
- a reload resumes the test with the time that is left and the answers as typed;
- the test ends itself when time is up, or at once on coming back after time ran out, or on
  Finish now (after its confirm step);
- its score is the sum of the marks the engine (QuestionMarking.markQuestion, called here in
  the page on the same answers) gives each question: some answered right from the variant's
  key, some wrong, some left blank; a line per type adds up the same way, and each question
  shows its marks and its worked answer;
- the result is kept (ProgressStore: the mock in the contract's shape, each answered question
  an attempt of the mock), once;
- it works from the built folder opened as files, and offline after one visit;
- axe finds nothing, light or dark, in the test and in its result;
- no help in a test (an exam): no "Show a step";
- the result: no "1 minute left." after the time ran out, "Not answered" for a blank, the right
  letter of a multiple-choice question not answered right, and what next (the weakest type of
  the test, linked to its practice page).
Everything expected is read from the variant data the site ships and the engine itself.
Starting a test on a slow first visit, and the mistakes a test keeps: test_mock_start_browser.py."""

from __future__ import annotations

import re
from datetime import UTC, datetime

import pytest
from browser import axe_violations, serve_site
from support.pages import page_without_errors

pytestmark = [pytest.mark.site, pytest.mark.browser]

PAGE = "book/exam/mock-test.html"
START = datetime(2027, 3, 1, 9, 0, tzinfo=UTC)
KEPT = "JSON.parse(localStorage.getItem('dynamics-mock-v1'))"
#: The engine's marks for the answers given, question by question, in the page.
ENGINE_MARKS = """([questions, answers]) => questions.map((q, i) =>
    QuestionMarking.markQuestion(QuestionVariants[q.question][q.variant], answers[i] || {}).marks.earned)"""
MOCK_KEYS = {"id", "paper", "at", "minutes", "ended", "earned", "available", "questions"}


@pytest.fixture
def student(browser, base_url):
    """A student's browser at the mock test, its clock set and held by the test."""
    with page_without_errors(browser, f"{base_url}/{PAGE}", before=lambda page: page.clock.install(time=START)) as page:
        yield page


def start(page, paper: str, size: int) -> dict:
    page.locator(f'input[name="mock-paper"][value="{paper}"]').check()
    page.locator("#mock-size").select_option(str(size))
    page.locator(".mock-start").click()
    page.locator(".mock-q").first.wait_for()
    return page.evaluate(KEPT)


def variants(page, test: dict) -> list[dict]:
    return page.evaluate("(qs) => qs.map(q => QuestionVariants[q.question][q.variant])", test["questions"])


def seconds_left(page) -> int:
    minutes, seconds = page.locator(".mock-time").inner_text().split(":")
    return int(minutes) * 60 + int(seconds)


def time_left(page, test: dict, gone_ms: int = 0) -> int:
    """The time the page shows, checked against the clock: the test started when it was kept
    (a reload never restarts it), at least `gone_ms` ago, and what is shown is what is left of
    its minutes by the page's own clock (real time runs on between the test's steps: on a
    loaded machine, seconds of it)."""
    kept = page.evaluate(KEPT)
    assert kept["at"] == test["at"], "the clock started again"
    shown = seconds_left(page)
    now = page.evaluate("Date.now()")
    assert now - test["at"] >= gone_ms
    left = (test["at"] + test["minutes"] * 60_000 - now) / 1000
    assert left - 2 <= shown <= left + 2, (shown, left)
    return shown


def three_sf(value: float) -> str:
    """A value as a student working to 3 s.f. writes it, zeros kept ("0.300", not "0.3": the
    engine reads "0.3" as 1 s.f., and names no mistake and gives no A1 from a 1 s.f. answer)."""
    return format(value, "#.3g").rstrip(".")


def right(variant: dict) -> dict:
    """Each part answered from the variant's own key (3 s.f., its unit and direction)."""
    out = {}
    for part in variant["parts"]:
        if part["kind"] == "mcq":
            out[part["id"]] = {"choice": part["answer"]}
        else:
            direction = part["answerDirection"] if part["direction"] == "choice" else ""
            out[part["id"]] = {"value": three_sf(part["value"]), "unit": part["unit"], "direction": direction}
    return out


def wrong(variant: dict) -> dict:
    out = {}
    for part in variant["parts"]:
        if part["kind"] == "mcq":
            out[part["id"]] = {"choice": next(o["letter"] for o in part["options"] if o["letter"] != part["answer"])}
        else:
            out[part["id"]] = {"value": three_sf(part["value"] * 7.3), "unit": part["unit"], "direction": ""}
    return out


def answer(page, index: int, answers: dict) -> None:
    section = page.locator(f'.mock-q[data-index="{index}"]')
    for part, given in answers.items():
        box = section.locator(f'[data-part="{part}"]')
        if "choice" in given:
            box.locator(f'input.q-choice[value="{given["choice"]}"]').check()
        else:
            box.locator("input.q-value").fill(given["value"])
            box.locator("input.q-unit").fill(given["unit"])
            if given["direction"]:
                box.locator("select.q-direction").select_option(given["direction"])


def answer_some(page, test: dict) -> dict[int, dict]:
    """A third right, a third wrong, a third left blank."""
    given = {}
    for index, variant in enumerate(variants(page, test)):
        if index % 3 == 2:
            continue
        given[index] = right(variant) if index % 3 == 0 else wrong(variant)
        answer(page, index, given[index])
    return given


def assert_no_feedback(page) -> None:
    texts = page.locator(".mock-q .q-feedback, .mock-q .q-part-marks, .mock-q .q-score").evaluate_all(
        "els => els.map(e => e.textContent.trim())")
    assert not any(texts), texts
    assert page.locator(".mock-q .q-worked, .mock-q .q-scheme, .mock-q button.q-check").count() == 0
    assert page.locator(".mock-q .q-help, .mock-q button.q-step").count() == 0  # no help in an exam
    assert not page.locator(".mock-result").is_visible()
    assert not re.search(r"\d+/\d+ marks?|✓|✗", page.locator(".mock").inner_text())


def assert_marked(page, test: dict, given: dict[int, dict], ended: str) -> None:
    """The result: the engine's marks, in sum, by type and by question, with the worked answers;
    and kept once in the student's progress."""
    page.locator(".mock-result").wait_for()
    kept = page.evaluate(KEPT)
    assert kept["ended"] == ended
    marks = page.evaluate(ENGINE_MARKS, [test["questions"], {str(i): a for i, a in given.items()}])
    available = [len(v["marks"]) for v in variants(page, test)]
    earned = sum(marks)
    assert earned > 0 and earned < sum(available)
    assert f"{earned}/{sum(available)} marks" in page.locator(".mock-score").inner_text()
    shown = [int(re.match(r"(\d+)/", s).group(1)) for s in page.locator(".mock-q .mock-q-score").all_inner_texts()]
    assert shown == marks
    by_type: dict[str, list[int]] = {}
    for q, got, out_of in zip(test["questions"], marks, available, strict=True):
        line = by_type.setdefault(q["type"], [0, 0])
        line[0], line[1] = line[0] + got, line[1] + out_of
    for kind, (got, out_of) in by_type.items():
        assert page.locator(f'.mock-types li[data-type="{kind}"] .mock-type-marks').inner_text() == \
            f"{got}/{out_of} mark{'' if out_of == 1 else 's'}"
    assert page.locator(".mock-types li").count() == len(by_type)
    assert_feedback(page, test, given)
    assert page.locator(".mock-warning").text_content() == ""  # the warnings are over with the test
    weakest = assert_what_next(page, test, marks, available)
    worked = page.locator(".mock-q details.q-worked")
    assert worked.count() == len(test["questions"])
    worked.first.locator("summary").click()
    assert worked.first.locator(".q-scheme li").count() >= 1
    # kept: the mock in the contract's shape, and each question answered as its attempt
    progress = page.evaluate("ProgressStore.load().progress")
    assert len(progress["mocks"]) == 1
    mock = progress["mocks"][0]
    assert set(mock) == MOCK_KEYS
    assert (mock["paper"], mock["minutes"], mock["ended"], mock["earned"], mock["available"]) == (
        test["paper"], test["minutes"], ended, earned, sum(available))
    assert [(q["question"], q["variant"], q["earned"]) for q in mock["questions"]] == [
        (q["question"], q["variant"], got) for q, got in zip(test["questions"], marks, strict=True)]
    attempts = [a for a in progress["attempts"] if a.get("mock") == mock["id"]]
    assert sorted((a["question"], a["variant"], a["earned"]) for a in attempts) == sorted(
        (test["questions"][i]["question"], test["questions"][i]["variant"], marks[i]) for i in given)
    assert all(a["rating"] in (1, 2, 3, 4) for a in attempts)
    # a reload shows the result again and keeps nothing twice
    page.reload()
    page.locator(".mock-result").wait_for()
    assert f"{earned}/{sum(available)} marks" in page.locator(".mock-score").inner_text()
    assert len(page.evaluate("ProgressStore.load().progress")["mocks"]) == 1
    if weakest:  # its link opens a question of that type
        page.locator(".mock-next a").first.click()
        page.wait_for_load_state("load")
        anchor = page.evaluate("location.hash").removeprefix("#question-")
        assert page.locator(f'form.q-form[data-question="{anchor}"]').get_attribute("data-type") == weakest


def assert_feedback(page, test: dict, given: dict[int, dict]) -> None:
    """Each part's line: "Not answered." for a blank part (not the prompt to choose); a
    multiple-choice part not answered right names the right letter."""
    for index, variant in enumerate(variants(page, test)):
        for part in variant["parts"]:
            text = page.locator(f'.mock-q[data-index="{index}"] [data-part="{part["id"]}"] .q-feedback').inner_text()
            letter = f" The answer is {part['answer']}." if part["kind"] == "mcq" else ""
            if index not in given:
                assert text == f"✗ Not answered.{letter}", text
            elif part["kind"] == "mcq" and given[index][part["id"]]["choice"] != part["answer"]:
                assert text.startswith("✗ ") and text.endswith(letter), text
            elif part["kind"] == "mcq":
                assert text.startswith("✓ ") and "The answer is" not in text, text


def assert_what_next(page, test: dict, marks: list[int], available: list[int]) -> str | None:
    """What next: the type with the lowest share of its marks in this test (on a tie, the one
    that lost more, then the first in the book), linked to its practice page. Its key."""
    index = page.evaluate("JSON.parse(document.querySelector('script.mock-index').textContent)")
    order = [t["key"] for t in index["types"]]
    by_type: dict[str, list[int]] = {}
    for q, got, out_of in zip(test["questions"], marks, available, strict=True):
        line = by_type.setdefault(q["type"], [0, 0])
        line[0], line[1] = line[0] + got, line[1] + out_of
    lost = [(got / out_of, got - out_of, order.index(kind), kind) for kind, (got, out_of) in by_type.items()
            if got < out_of]
    line = page.locator(".mock-next")
    assert line.inner_text().startswith("What next:")
    if not lost:
        return None
    weakest = min(lost)[3]
    assert line.get_attribute("data-type") == weakest
    title = next(t["title"] for t in index["types"] if t["key"] == weakest)
    got, out_of = by_type[weakest]
    assert f"practise your weakest type in this test, {title} ({got}/{out_of} mark" in line.inner_text()
    assert line.get_by_role("link", name=title).get_attribute("href").split("#")[0].endswith(".html")
    return weakest


def test_paper_1_resumes_after_a_reload_and_ends_itself_when_time_is_up(student):
    page = student
    test = start(page, "1", 20)
    assert len(test["questions"]) == 20 and test["minutes"] == 37.5
    assert all(v["parts"][0]["kind"] == "mcq" for v in variants(page, test))
    assert 37 * 60 <= time_left(page, test) <= 37 * 60 + 30
    given = answer_some(page, test)
    assert_no_feedback(page)

    page.clock.fast_forward("10:00")
    page.reload()
    page.locator(".mock-q").first.wait_for()
    left = time_left(page, test, 10 * 60_000)
    assert 27 * 60 <= left <= 27 * 60 + 30, left
    for index, answers in given.items():  # the answers as given
        assert page.locator(f'.mock-q[data-index="{index}"] input.q-choice[value="{answers["a"]["choice"]}"]').is_checked()
    assert_no_feedback(page)

    # a polite warning at 5 minutes left, once
    page.clock.fast_forward((left - 299) * 1000)
    warning = page.locator(".mock-warning")
    assert warning.get_attribute("aria-live") == "polite"
    assert warning.inner_text() == "5 minutes left."
    assert_no_feedback(page)
    page.clock.fast_forward("05:01")
    assert_marked(page, test, given, "time")


def test_paper_2_resumes_after_a_reload_and_finish_now_asks_first(student):
    page = student
    test = start(page, "2", 20)
    assert test["minutes"] == 25
    shown = variants(page, test)
    assert sum(len(v["marks"]) for v in shown) == 20
    assert all(p["kind"] in ("numeric", "graph") for v in shown for p in v["parts"])
    given = answer_some(page, test)
    assert_no_feedback(page)

    page.clock.fast_forward("08:00")
    page.reload()
    page.locator(".mock-q").first.wait_for()
    assert 16 * 60 + 30 <= time_left(page, test, 8 * 60_000) <= 17 * 60
    first = next(iter(given))
    box = page.locator(f'.mock-q[data-index="{first}"] [data-part="a"]')
    assert box.locator("input.q-value").input_value() == given[first]["a"]["value"]
    assert_no_feedback(page)

    page.locator(".mock-bar .mock-finish").click()
    page.get_by_role("button", name="Keep going").click()
    assert not page.locator(".mock-confirm").is_visible()
    assert_no_feedback(page)
    page.locator(".mock-end .mock-finish").click()
    page.get_by_role("button", name="Yes, finish and mark").click()
    assert_marked(page, test, given, "submitted")


def test_coming_back_after_time_ran_out_ends_the_test_at_once(student, base_url):
    page = student
    test = start(page, "2", 15)
    assert test["minutes"] == 18.75
    given = {0: right(variants(page, test)[0])}
    answer(page, 0, given[0])
    page.goto(f"{base_url}/book/intro.html")
    page.clock.fast_forward("20:00")
    page.goto(f"{base_url}/{PAGE}")
    assert_marked(page, test, given, "time")


def test_a_test_runs_from_the_built_folder_opened_as_files(browser, site_dir):
    context = browser.new_context()
    errors: list[str] = []
    page = context.new_page()
    page.on("pageerror", lambda error: errors.append(str(error)))
    page.goto((site_dir / PAGE).as_uri())
    test = start(page, "2", 30)
    assert page.locator(".mock-q").count() == len(test["questions"])
    context.close()
    assert not errors, errors


def test_a_test_runs_offline_after_one_visit(browser, site_dir):
    with serve_site(site_dir) as base_url:
        context = browser.new_context(service_workers="allow")
        page = context.new_page()
        page.goto(f"{base_url}/book/intro.html")
        page.wait_for_function("navigator.serviceWorker.controller !== null", timeout=60_000)
        context.set_offline(True)
        page.goto(f"{base_url}/{PAGE}")
        test = start(page, "2", 30)
        assert page.locator(".mock-q").count() == len(test["questions"])
        shown = page.evaluate("""() => Promise.all([...document.querySelectorAll('.mock-q img')].map(i =>
            i.decode().then(() => i.naturalWidth > 0, () => i.src)))""")
        assert all(result is True for result in shown), shown
        context.close()


#: A Paper 2 test of 30 marks with a graph to read, kept as the page keeps a test it started.
WITH_A_GRAPH = """() => {
    const index = JSON.parse(document.querySelector('script.mock-index').textContent);
    const graph = (q) => index.templates.find(t => t.key === q.question).kinds.includes('graph');
    for (let seed = 0; ; seed++) {
        const test = MockDraw.draw(index, '2', 30, seed);
        if (test.questions.some(graph)) {
            Object.assign(test, {version: 1, at: Date.now(), answers: {}, warned: []});
            localStorage.setItem('dynamics-mock-v1', JSON.stringify(test));
            return test;
        }
    }
}"""


@pytest.mark.parametrize("mode", ["light", "dark"])
def test_no_axe_violations_in_a_test_and_its_result(browser, base_url, mode):
    context = browser.new_context(color_scheme=mode)
    page = context.new_page()
    page.goto(f"{base_url}/{PAGE}")
    page.evaluate(f"document.documentElement.dataset.theme = '{mode}'")
    assert axe_violations(page, context_selector=".mock") == []
    test = page.evaluate(WITH_A_GRAPH)
    page.reload()
    page.locator(".mock-q").first.wait_for()
    page.evaluate(f"document.documentElement.dataset.theme = '{mode}'")
    answer(page, 0, right(variants(page, test)[0]))
    page.locator(".mock-bar .mock-finish").click()
    page.locator(".mock-q .q-graph-open").first.hover()  # its hint stays readable under the pointer
    assert axe_violations(page, context_selector=".mock") == []
    page.get_by_role("button", name="Yes, finish and mark").click()
    page.locator(".mock-result").wait_for()
    page.locator(".mock-q details.q-worked summary").first.click()
    page.locator(".mock-q .q-graph-open").first.hover()
    assert axe_violations(page, context_selector=".mock") == []
    context.close()


def test_a_graph_in_a_mock_test_is_read_by_its_cursor(student):
    """A graph question drawn into a test has the graph cursor the practice pages give it
    (issue 28): one slider per graph, and its keys say the readings through the live region."""
    test = student.evaluate(WITH_A_GRAPH)
    student.reload()
    student.locator(".mock-q").first.wait_for()
    shown = variants(student, test)
    with_graph = [i for i, variant in enumerate(shown) if variant.get("graph")]
    assert with_graph, "the test drawn has no graph"
    for i in with_graph:
        section = student.locator(".mock-q").nth(i)
        assert section.locator(".q-graph-slider").count() == 1
        slider = section.get_by_role("slider", name="Graph cursor")
        said = student.locator(".q-graph-said")
        slider.press("End")
        assert said.text_content().startswith("t = "), said.text_content()  # the reading there
        slider.press("End")  # once more: the axis ends here
        assert said.text_content().startswith("End of the time axis: t = "), said.text_content()
        slider.press("Home")
        slider.press("Home")
        assert said.text_content().startswith("Start of the time axis: t = "), said.text_content()

