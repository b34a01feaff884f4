"""Searched words stay readable in light and dark (issue 28, item 4), in Debian's Chromium.

The site sweep (tests/browser/test_site.py) opens search.html with no query, so it never sees a marked
word. Here the search page runs a query, and a page is opened with ?highlight= as a search
result opens it; axe-core (every rule, every impact) must find nothing, at 390 and 1280 px, in
light and in dark mode, with the marks on the page.
"""

from __future__ import annotations

import pytest
from browser import axe_violations

pytestmark = [pytest.mark.site, pytest.mark.browser]

VIEWPORTS = {"390": {"width": 390, "height": 844}, "1280": {"width": 1280, "height": 900}}
NO_TRANSITIONS = "*, *::before, *::after { transition: none !important; animation: none !important; }"
# A word that is on many pages, in links (the results, the next/previous links) and in
# captions (muted text): the places where the marks failed contrast.
MARKED = {
    "search": "search.html?q=momentum",
    "highlight": "book/understand/momentum-time-graph.html?highlight=momentum",
}


@pytest.mark.parametrize("scheme", ["light", "dark"])
@pytest.mark.parametrize("viewport", list(VIEWPORTS))
@pytest.mark.parametrize("where", list(MARKED))
def test_marked_search_words_pass_axe(browser, base_url, where, viewport, scheme):
    context = browser.new_context(viewport=VIEWPORTS[viewport], color_scheme=scheme)
    try:
        page = context.new_page()
        page.goto(f"{base_url}/{MARKED[where]}")
        page.wait_for_function("scheme => document.documentElement.dataset.theme === scheme", arg=scheme)
        if where == "search":  # the results come from the search index, after the page loads
            page.wait_for_selector("#search-results li .highlighted", timeout=60_000)
        page.wait_for_function("document.querySelectorAll('span.highlighted').length > 0", timeout=60_000)
        page.add_style_tag(content=NO_TRANSITIONS)
        violations = axe_violations(page)
        assert not violations, [f"{v['id']} ({v['impact']}): {v['targets']}" for v in violations]
    finally:
        context.close()
