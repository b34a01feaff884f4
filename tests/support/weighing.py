"""A page's first visit weighed, as `make bench` weighs it: tests/browser/test_site.py's sweep (with the
page's layout shift) and tests/browser/test_lighthouse.py (to find the heaviest page) share it."""

from __future__ import annotations

import asyncio
import hashlib
import re
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path

from browser import VIEWPORTS, PageVisitor


@dataclass
class PageReport:
    """What one page did in the browser."""

    path: str
    total_bytes: int = 0
    requests: int = 0  # on the first visit
    layout_shift: float = 0.0  # what Lighthouse calls CLS, while it loads: the worst of its loads
    layout_shift_load: str = ""  # which load shifted most ("first visit" at 390 px, or "desktop")
    foreign: list[str] = field(default_factory=list)
    failed: list[str] = field(default_factory=list)
    console: list[str] = field(default_factory=list)
    axe: dict[str, list[dict]] = field(default_factory=dict)  # "mobile/dark" -> violations
    overflow: dict[str, int] = field(default_factory=dict)  # mode -> pixels too wide
    facts: dict = field(default_factory=dict)  # PAGE_FACTS and the keyboard walk (desktop/light)
    dark_images: dict[str, list[dict]] = field(default_factory=dict)  # viewport -> images

    def shifted(self, shift: float, load: str) -> None:
        """One load's layout shift: the page is judged by the worst of its loads."""
        if shift > self.layout_shift or not self.layout_shift_load:
            self.layout_shift, self.layout_shift_load = shift, load


# Runs in the page: headings, images, maths, keyboard focus and dark-mode figures.
# Three tabs load pages side by side: on a busy 2-core machine one load can pass playwright's
# 30 s default (speed is judged by the weighing and Lighthouse, not by this timeout).
SWEEP_TIMEOUT_MS = 120_000


# Sums the page's layout shifts until the first scroll (the visit scrolls to the bottom to
# load every figure; Lighthouse, whose CLS this is, does not scroll).
LAYOUT_SHIFTS = """
window.__loadShift = 0;
addEventListener('scroll', () => { window.__scrolled = true; }, {once: true});
new PerformanceObserver((list) => {
  for (const shift of list.getEntries())
    if (!shift.hadRecentInput && !window.__scrolled) window.__loadShift += shift.value;
}).observe({type: 'layout-shift', buffered: true});
"""


async def weigh(browser, base: str, pages: list[str], reports, *, then=None) -> None:
    """Each page's first visit: a fresh context (nothing cached from another page), service
    workers blocked, as `make bench` weighs it. Its layout shift while it loads, too, and what
    failed or was sent off the site (scrolled: the lazy figures load too). A page is loaded once
    here; its layout shift is the worst of this load and the sweep's (tests/browser/test_site.py), never
    the least: a shift a student can meet on a first load fails the page.

    `then(page, report)`, when given, checks the page further in the same tab once it is
    weighed (the sweep's checks at 390 px, without a second load): what those checks fetch or
    break counts as the first visit's failures, but not in its bytes."""
    for path in pages:
        context = await browser.new_context(viewport=VIEWPORTS["mobile"], service_workers="block")
        context.set_default_timeout(SWEEP_TIMEOUT_MS)
        await context.route(re.compile(r"^(?!http://127\.0\.0\.1:)"), lambda route: route.abort())
        await context.add_init_script(LAYOUT_SHIFTS)
        visitor = PageVisitor(await context.new_page())
        load = await visitor.visit(f"{base}/{path}", scroll=True)
        report = reports[path]
        report.total_bytes = load.total_bytes
        report.requests = sum(not url.startswith("data:") for url in load.requests)  # on the wire
        report.shifted(await visitor.page.evaluate("window.__loadShift"), "first visit")
        if then:
            visitor.measure = False  # the first visit is weighed: what the checks fetch is not
            await then(visitor.page, report)
            await visitor.settle()
        await context.close()
        report.failed += [f"first visit: {failure}" for failure in load.failed]
        report.console += [f"first visit: {message}" for message in load.console_errors]
        report.foreign += [f"first visit: {url}" for url in load.foreign]


def weights_file(site: Path) -> Path:
    """Where the sweep leaves each page's first-visit bytes, for test_lighthouse.py (which runs
    later, alone, and need not weigh the pages again): beside the site, in _build."""
    return site.parent / "page-weights.json"


def site_version(site: Path) -> str:
    """The build's fingerprint: its service worker names a cache for the digest of every file."""
    return hashlib.sha256((site / "sw.js").read_bytes()).hexdigest()


def run_apart(coroutine):
    """``asyncio.run(coroutine)`` on a thread of its own. The test process's one Chromium
    (tests/conftest.py's ``chromium``) is driven by playwright's sync API, whose event loop
    belongs to this thread while it is open, and asyncio.run will not start a second loop here."""
    with ThreadPoolExecutor(max_workers=1) as thread:
        return thread.submit(asyncio.run, coroutine).result()
