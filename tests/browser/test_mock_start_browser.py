"""The mock test (book/exam/mock-test.md) beyond its clock and marks
(test_mock_test_browser.py), in Chromium:

- Start the test is offered only once it works: on a slow first visit, a tap before the page's
  script has come sends no form and reloads nothing; while the questions load, a second tap
  draws no second test; without JavaScript the page says so and offers no button;
- each part's named mistakes and the engine's slips (unit, sign, 1 s.f.) are kept in the
  attempts the test writes, as a question's page keeps them, and Your practice counts them."""

from __future__ import annotations

import pytest
from support.pages import page_without_errors
from test_mock_test_browser import KEPT, PAGE, answer, right, start, three_sf, variants

pytestmark = [pytest.mark.site, pytest.mark.browser]


@pytest.fixture
def student(browser, base_url):
    """A student's browser at the mock test; no error on the page."""
    with page_without_errors(browser, f"{base_url}/{PAGE}") as page:
        yield page


#: Each answered question's mistakes as a question's page records them: each part's named
#: mistake, else the slip the engine names (sign, unit, 1 s.f.).
ENGINE_MISTAKES = """([questions, answers]) => questions.map((q, i) => {
    const variant = QuestionVariants[q.question][q.variant];
    const marked = QuestionMarking.markQuestion(variant, answers[i] || {});
    return variant.parts.map(p => marked.results[p.id].mistake || QuestionMarking.slipName(marked.results[p.id].code))
        .filter(Boolean);
})"""


def test_a_mock_tests_mistakes_are_kept_and_the_plan_counts_them(student, base_url):
    """Two answers right but for their unit (the engine's slip) and one named mistake where a
    question has one: the mock's attempts keep them, and Your practice names the most frequent."""
    page = student
    test = start(page, "2", 20)
    shown = variants(page, test)
    given = {i: right(v) for i, v in enumerate(shown[:2])}
    for answers in given.values():
        answers["a"]["unit"] = ""
    named = next((i for i, v in enumerate(shown) if i >= 2 and any(
        m["unit"] is None and m["direction"] is None for m in v["parts"][0]["mistakes"])), None)
    if named is not None:
        given[named] = right(shown[named])
        mistake = next(m for m in shown[named]["parts"][0]["mistakes"] if m["unit"] is None and m["direction"] is None)
        value = mistake["value"] if shown[named]["parts"][0]["direction"] == "signed" else abs(mistake["value"])
        given[named]["a"]["value"] = three_sf(value)
    for index, answers in given.items():
        answer(page, index, answers)
    page.locator(".mock-bar .mock-finish").click()
    page.get_by_role("button", name="Yes, finish and mark").click()
    page.locator(".mock-result").wait_for()
    expected = page.evaluate(ENGINE_MISTAKES, [test["questions"], {str(i): a for i, a in given.items()}])
    assert sum(len(expected[i]) for i in given) >= 2 + (named is not None)
    progress = page.evaluate("ProgressStore.load().progress")
    kept = {(a["question"], a["variant"]): a["mistakes"] for a in progress["attempts"]}
    for i in given:
        q = test["questions"][i]
        assert kept[(q["question"], q["variant"])] == expected[i], (i, q)
    names = [name for i in given for name in expected[i]]
    top = max(names, key=names.count)  # on a tie, the first made: max keeps the first
    page.goto(f"{base_url}/book/exam/your-practice.html")
    assert page.locator(".pp-often").inner_text().startswith(
        f"Most frequent mistake: {top} ({'once' if names.count(top) == 1 else 'twice' if names.count(top) == 2 else f'{names.count(top)} times'})")


def _held(page, pattern: str) -> list:
    """Requests matching pattern held back (a slow first visit), until release() lets them and
    every later one through."""
    held: list = []

    def hold(route):
        if getattr(hold, "released", False):
            route.continue_()
        else:
            held.append(route)

    def release():
        hold.released = True
        for route in held:
            route.continue_()

    page.route(pattern, hold)
    return held, release


def test_start_the_test_is_offered_only_once_it_works(browser, base_url):
    """A slow first visit: the page's script has not come. Start the test is there but
    disabled, and says why; a tap sends no form (no reload, nothing lost); once the script has
    come, a tap starts a test."""
    context = browser.new_context()
    page = context.new_page()
    errors: list[str] = []
    page.on("pageerror", lambda error: errors.append(str(error)))
    navigations: list[str] = []
    page.on("request", lambda r: navigations.append(r.url) if r.is_navigation_request() else None)
    # the page's scripts come in one file, its kind's bundle (book/_ext/site_assets/scripts.py)
    held, release = _held(page, "**/_static/site-assets/scripts-*.js")
    with page.expect_request(lambda r: "/_static/site-assets/scripts-" in r.url):
        page.goto(f"{base_url}/{PAGE}", wait_until="commit")
    button = page.locator(".mock-start")
    button.wait_for()
    assert held, "the script was not held back"
    assert button.is_visible() and button.is_disabled()
    assert page.locator(".mock-status").inner_text() == "Getting the test ready…"
    page.evaluate("window.beforeTheTap = true")
    button.click(force=True)  # the student's tap, before the script has come
    assert len(navigations) == 1 and "?" not in page.url, navigations
    release()
    page.wait_for_function("!document.querySelector('.mock-start').disabled")
    assert page.evaluate("window.beforeTheTap") is True  # the same page: nothing reloaded
    assert page.locator(".mock-status").inner_text() == ""
    test = start(page, "1", 10)
    assert page.locator(".mock-q").count() == len(test["questions"]) == 10
    assert len(navigations) == 1
    context.close()
    assert not errors, errors


def test_a_second_tap_while_the_questions_load_starts_nothing_more(student):
    """The questions' data files are slow: after Start the test, the button waits (a second
    tap would draw another test), and the test drawn first is the one that starts, once."""
    page = student
    held, release = _held(page, "**/_static/questions/*.js")
    page.locator('input[name="mock-paper"][value="2"]').check()
    page.locator("#mock-size").select_option("15")
    button = page.locator(".mock-start")
    page.evaluate("""() => { const draw = MockDraw.draw; window.drawn = [];
        MockDraw.draw = function () { const test = draw.apply(this, arguments); drawn.push(test.seed); return test; }; }""")
    with page.expect_request(lambda r: "/_static/questions/" in r.url):
        button.click()
    assert button.is_disabled()
    assert held, "no data file was held back"
    assert page.locator(".mock-status").inner_text() == "Loading the questions…"
    button.click(force=True)
    assert len(page.evaluate("drawn")) == 1
    release()
    page.locator(".mock-q").first.wait_for()
    kept = page.evaluate(KEPT)
    assert page.evaluate("drawn") == [kept["seed"]]
    assert page.locator(".mock-q").count() == len(kept["questions"])
    assert page.locator(".mock-status").inner_text() == ""


def test_without_javascript_the_page_says_so_and_offers_no_button(browser, base_url):
    context = browser.new_context(java_script_enabled=False)
    page = context.new_page()
    page.goto(f"{base_url}/{PAGE}")
    assert page.locator(".mock-needs-js").is_visible()
    assert "with JavaScript on" in page.locator(".mock-needs-js").inner_text()
    assert not page.locator(".mock-start").is_visible()
    context.close()
