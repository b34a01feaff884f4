"""Lighthouse on the heaviest page: the guard `make test` keeps under `make bench`'s judgement.

Its performance score is a measure of speed, so this test runs alone (marker ``alone``): `make
test` runs it after the parallel run of the site's tests, with nothing else on the machine.
The heaviest page is found as test_site.py's sweep weighs pages: a first visit of each in
Chromium at 390 px, in a fresh context. The sweep leaves its weights in _build, named for the
build; run without it (or on another build), this test weighs the pages itself.
"""

from __future__ import annotations

import asyncio
import json
from pathlib import Path

import pytest
from browser import (
    LIGHTHOUSE_RUNS,
    lighthouse_runs,
    median_scores,
    open_browser_async,
    serve_site,
    site_pages,
)
from support.weighing import PageReport, run_apart, site_version, weigh, weights_file

pytestmark = [pytest.mark.site, pytest.mark.browser, pytest.mark.alone]

LIGHTHOUSE_MINIMUM = {"performance": 0.95, "accessibility": 1.0, "best-practices": 1.0, "seo": 1.0}


def _heaviest(site: Path) -> str:
    """The page whose first visit weighs most: as the sweep of this build weighed it
    (test_site.py, earlier in `make test`), or weighed here when it has not run on it."""
    weighed = json.loads(weights_file(site).read_text()) if weights_file(site).exists() else {}
    if weighed.get("site") == site_version(site) and weighed["bytes"].keys() == set(site_pages(site)):
        return max(weighed["bytes"], key=weighed["bytes"].get)
    return run_apart(_weigh_all(site))


async def _weigh_all(site: Path) -> str:
    pages = site_pages(site)
    reports = {path: PageReport(path) for path in pages}
    with serve_site(site) as base:
        async with open_browser_async() as browser:
            # four pages at a time: a visit mostly waits for the network to be idle, and the
            # bytes of a first visit (a fresh context each) do not depend on what runs beside it
            await asyncio.gather(*(weigh(browser, base, pages[i::4], reports) for i in range(4)))
    return max(reports.values(), key=lambda report: report.total_bytes).path


def test_lighthouse_on_the_heaviest_page(site_dir):
    heaviest = _heaviest(site_dir)
    with serve_site(site_dir) as base:
        # the median of LIGHTHOUSE_RUNS runs, category by category (CLARIFICATIONS), every run made
        runs = lighthouse_runs([f"{base}/{heaviest}"] * LIGHTHOUSE_RUNS)
    scores = median_scores(runs)
    low = {name: score for name, score in scores.items() if score < LIGHTHOUSE_MINIMUM[name]}
    assert not low, (f"lighthouse (mobile) on {heaviest}: median {scores} of {runs}; "
                     f"below the minimum {LIGHTHOUSE_MINIMUM}")
