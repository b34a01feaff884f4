"""Search, as a reader uses it: the header's one search box, Ctrl+K, the search page,
and the results for the words a 9702 student looks up, in Debian's Chromium on the
built site, with every other host reachable or blocked.

Sphinx's search runs in the page: searchtools.js loads searchindex.js, ranks the pages
and fetches each result to show a snippet of its text around the words.
"""

from __future__ import annotations

import re

import pytest
from playwright.sync_api import TimeoutError as PlaywrightTimeout
from support.pages import readers_of

pytestmark = [pytest.mark.site, pytest.mark.browser]

# What a student types -> the page that teaches it (CLARIFICATIONS, "Blockers": in the top 3).
EXPECTED = {
    "momentum": "book/understand/momentum-and-second-law.html",
    "terminal velocity": "book/understand/friction-drag-terminal-velocity.html",
    "Newton's third law": "book/understand/third-law.html",
    "weight": "book/understand/weight.html",
    "elastic": "book/understand/elastic-and-inelastic.html",
}
WIDTHS = {"phone": 390, "tablet": 1024, "laptop": 1280}
START = "book/understand/mass-and-first-law.html"  # any content page: search starts there
OTHER_HOSTS = re.compile(r"^(?!http://127\.0\.0\.1:)")

# Every search control a reader could see, wherever it is (header, sidebar, page).
VISIBLE_SEARCH_CONTROLS = """() => [...document.querySelectorAll(
    '.search-button__button, form.bd-search')].filter(el => {
      if (el.closest('dialog:not([open])')) return false;
      const r = el.getBoundingClientRect(), s = getComputedStyle(el);
      return r.width > 0 && r.height > 0 && s.visibility !== 'hidden';
    }).map(el => ({
      inHeader: !!el.closest('#pst-header, .bd-header-article'),
      html: el.outerHTML.slice(0, 120),
    }))"""

# The magnifier and the text beside it, in the search box and in the field it opens.
CLEARANCE = """(box) => {
  const icon = box.querySelector('.fa-magnifying-glass').getBoundingClientRect();
  const text = box.querySelector('input, .search-button__default-text, .site-search-box__text');
  const r = text.getBoundingClientRect(), s = getComputedStyle(text);
  const textStart = r.left + parseFloat(s.paddingLeft) + parseFloat(s.borderLeftWidth);
  return {iconRight: icon.right, textStart, iconWidth: icon.width};
}"""


class Reader:
    """A fresh browser context at one width, its console errors and failed requests recorded."""

    def __init__(self, browser, base_url: str, width: int, *, block_other_hosts: bool = False):
        self.base_url = base_url
        self.context = browser.new_context(viewport={"width": width, "height": 800}, has_touch=width < 992)
        if block_other_hosts:
            self.context.route(OTHER_HOSTS, lambda route: route.abort("internetdisconnected"))
        self.page = self.context.new_page()
        self.errors: list[str] = []
        self.page.on("console", lambda m: m.type == "error" and self.errors.append(m.text))
        self.page.on("pageerror", lambda e: self.errors.append(f"uncaught: {e}"))
        # A request the browser drops because the reader moved on (Enter opens the search
        # page while the favicon still loads) is ERR_ABORTED: not a failure of the site.
        self.page.on("requestfailed", lambda r: "ERR_ABORTED" not in (r.failure or "")
                     and self.errors.append(f"failed: {r.url} {r.failure}"))
        self.touch = width < 992

    def open(self, path: str):
        self.page.goto(f"{self.base_url}/{path}", wait_until="load")

    def press(self, locator):
        """Tap on a phone, click with the mouse otherwise."""
        locator.tap() if self.touch else locator.click()

    def header_search_box(self):
        return self.page.locator(
            "#pst-header .search-button__button:visible, .bd-header-article .search-button__button:visible"
        )

    def results(self) -> list[dict]:
        """The search page's results, once the search has finished (snippets fetched)."""
        try:
            # Sphinx writes the summary line when the search starts and says "Search finished"
            # only when every result is listed: wait for that, not for the line itself.
            self.page.wait_for_function(
                "(document.querySelector('#search-results p.search-summary') || {textContent: ''})"
                ".textContent.startsWith('Search finished')", timeout=10_000
            )
            # A snippet arrives with the fetch of its page, after the summary line.
            self.page.wait_for_function(
                "[...document.querySelectorAll('#search-results ul.search > li')].slice(0, 3)"
                ".every(li => li.querySelector('.context'))", timeout=10_000
            )
        except PlaywrightTimeout:
            pytest.fail(f"the search never finished on {self.page.url}; console: {self.errors}", pytrace=False)
        return self.page.evaluate(
            """() => [...document.querySelectorAll('#search-results ul.search > li')].map(li => ({
                href: li.querySelector('a').getAttribute('href'),
                snippet: (li.querySelector('.context') || {textContent: ''}).textContent.trim()}))"""
        )

    def close(self):
        self.context.close()


reader = readers_of(Reader)  # reader(width, ...) opens one; each is closed after the test


def _check_results(query: str, results: list[dict]) -> None:
    pages = [result["href"].split("#")[0].split("?")[0] for result in results]
    assert EXPECTED[query] in pages[:3], f"{query!r}: top 3 results are {pages[:3]}, not {EXPECTED[query]}"
    words = [word for word in re.findall(r"[a-z]+", query.lower()) if len(word) >= 3]  # "law" too
    for result in results[:3]:
        snippet = result["snippet"]
        assert len(snippet) > 40, f"{query!r}: result {result['href']} has no snippet ({snippet!r})"
        assert any(word in snippet.lower() for word in words), (
            f"{query!r}: the snippet of {result['href']} does not show the words searched for: {snippet!r}"
        )


@pytest.mark.parametrize("network", ["online", "other hosts blocked"])
@pytest.mark.parametrize("query", list(EXPECTED))
def test_search_from_the_header_finds_the_page_that_teaches_it(reader, query, network):
    """Type in the header's search box, press Enter: the search page lists the page that
    teaches it among the first three, each with a snippet of its text."""
    me = reader(WIDTHS["laptop"], block_other_hosts=network != "online")
    me.open(START)
    me.press(me.header_search_box())
    field = me.page.locator("#pst-search-dialog input[name=q]")
    field.fill(query)
    field.press("Enter")
    me.page.wait_for_url(re.compile(r"/search\.html\?q="))
    _check_results(query, me.results())
    assert not me.errors, me.errors


def test_search_page_field_searches_too(reader):
    """The search page's own field: type, press Enter, results (no console error: this page
    threw `_ready is not defined` when its scripts ran out of order)."""
    me = reader(WIDTHS["phone"], block_other_hosts=True)
    me.open("search.html")
    field = me.page.locator(".bd-search-container input[name=q]")
    field.fill("terminal velocity")
    field.press("Enter")
    _check_results("terminal velocity", me.results())
    assert not me.errors, me.errors


@pytest.mark.parametrize("width", list(WIDTHS.values()), ids=list(WIDTHS))
def test_one_search_box_in_the_header_with_its_text_clear_of_the_icon(reader, width):
    me = reader(width)
    me.open(START)
    controls = me.page.evaluate(VISIBLE_SEARCH_CONTROLS)
    assert len(controls) == 1, f"{width} px: {len(controls)} search controls in sight: {controls}"
    assert controls[0]["inHeader"], f"{width} px: the search box is not in the header: {controls[0]}"
    box = me.header_search_box()
    clear = box.evaluate(CLEARANCE)
    assert clear["iconWidth"] > 0 and clear["textStart"] >= clear["iconRight"], f"{width} px: {clear}"
    # The field it opens: the typed text starts after the magnifier.
    me.press(box)
    form = me.page.locator("#pst-search-dialog form.bd-search")
    form.locator("input").fill("terminal velocity")
    clear = form.evaluate(CLEARANCE)
    assert clear["iconWidth"] > 0 and clear["textStart"] >= clear["iconRight"], f"{width} px, search field: {clear}"
    assert not me.errors, me.errors


def test_search_page_field_text_clear_of_the_icon(reader):
    me = reader(WIDTHS["phone"])
    me.open("search.html?q=weight")
    clear = me.page.locator(".bd-search-container form.bd-search").evaluate(CLEARANCE)
    assert clear["iconWidth"] > 0 and clear["textStart"] >= clear["iconRight"], clear


@pytest.mark.parametrize("width", list(WIDTHS.values()), ids=list(WIDTHS))
def test_search_box_reachable_by_keyboard(reader, width):
    """Tab from the top of the page reaches the search box; Enter opens the field with the
    focus in it; a query and Enter search."""
    me = reader(width)
    me.open(START)
    for _ in range(12):
        me.page.keyboard.press("Tab")
        if me.page.evaluate("document.activeElement.matches('.search-button__button')"):
            break
    else:
        pytest.fail(f"{width} px: 12 presses of Tab never reach the search box")
    me.page.keyboard.press("Enter")
    assert me.page.evaluate("document.activeElement.matches('#pst-search-dialog input[name=q]')"), (
        f"{width} px: Enter on the search box does not put the focus in a search field"
    )
    me.page.keyboard.type("elastic")
    me.page.keyboard.press("Enter")
    me.page.wait_for_url(re.compile(r"/search\.html\?q=elastic"))
    _check_results("elastic", me.results())
    assert not me.errors, me.errors


@pytest.mark.parametrize("width", [WIDTHS["phone"], WIDTHS["laptop"]], ids=["phone", "laptop"])
def test_ctrl_k_opens_search_and_escape_closes_it(reader, width):
    me = reader(width)
    me.open(START)
    dialog = me.page.locator("#pst-search-dialog")
    me.page.keyboard.press("Control+k")
    assert dialog.evaluate("d => d.open"), "Ctrl+K does not open the search field"
    assert me.page.evaluate("document.activeElement.matches('#pst-search-dialog input[name=q]')")
    me.page.keyboard.press("Escape")
    assert not dialog.evaluate("d => d.open"), "Escape does not close the search field"
    assert not me.errors, me.errors
