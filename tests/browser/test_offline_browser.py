"""Offline after one visit, in Chromium: the service worker (book/_ext/offline) keeps the
whole book, so after the intro has been opened once, with the network gone, every page
opens with its figures (each page under the subpath; one of each folder at the root), a question marks and gives new numbers, progress shows with its plan,
Start serves a card and the self-test opens one card, an explorable responds and search finds pages with snippets. A new build replaces the cache:
the student is told, presses Reload, and reads the new text. Served at the root and under a
subpath (as GitHub Pages serves a project site), by a host that lets browsers reuse files
for ten minutes, as GitHub Pages does. A teacher's PDF, opened once online, opens again
offline; the zip holds every PDF and the Moodle file."""

from __future__ import annotations

import json
import re
import shutil
import zipfile
from pathlib import Path

import offline
import pytest
from browser import serve_site, site_pages

from physics_figures import bank

pytestmark = [pytest.mark.site, pytest.mark.browser]

ROOT = Path(__file__).resolve().parents[2]
INTRO = "book/intro.html"
HOST_CACHE = "max-age=600"  # GitHub Pages
SUBPATHS = [pytest.param("", id="root"), pytest.param("/dynamics/", id="subpath")]
IMAGES_SHOWN = """() => Promise.all([...document.images].map(image => {
    image.loading = "eager";
    return image.decode().then(() => image.naturalWidth > 0, () => image.currentSrc || image.src);
}))"""


def _first_visit(browser, base_url: str):
    """A student's first visit: the intro, until the service worker controls it."""
    context = browser.new_context(service_workers="allow")
    errors: list[str] = []
    context.on("weberror", lambda error: errors.append(str(error.error)))
    page = context.new_page()
    page.goto(f"{base_url}/{INTRO}")
    page.wait_for_function("navigator.serviceWorker.controller !== null", timeout=60_000)
    return context, page, errors


#: Served at the root, the walk opens one page of each folder (the root's redirect stub, search,
#: a page of book/, of book/understand/ with figures and of book/exam/ with a question): what a
#: prefix could break, a URL or the worker's scope, breaks by folder. Every page is walked under
#: the subpath, where a URL that ignores the prefix fails too; the pages the worker keeps are the
#: same at both (test_the_precache_lists_every_page_and_what_pages_load_but_no_downloads).
ONE_PAGE_A_FOLDER = ["index.html", "search.html", INTRO, "book/understand/momentum-time-graph.html",
                     "book/exam/practice-force-momentum.html"]


def _walk(site_dir: Path, subpath: str) -> list[str]:
    if subpath:
        return site_pages(site_dir)
    assert set(ONE_PAGE_A_FOLDER) <= set(site_pages(site_dir)), "update ONE_PAGE_A_FOLDER: a page is gone"
    return ONE_PAGE_A_FOLDER


@pytest.mark.parametrize("subpath", SUBPATHS)
def test_after_one_visit_the_whole_book_works_offline(browser, site_dir, subpath):
    with serve_site(site_dir, prefix=subpath, cache_control=HOST_CACHE) as base_url:
        context, page, errors = _first_visit(browser, base_url)
        context.set_offline(True)
        practised = set()  # the question types given new numbers offline
        for path in _walk(site_dir, subpath):
            page.goto(f"{base_url}/{path}", wait_until="load")
            if "http-equiv=\"refresh\"" in (site_dir / path).read_text(encoding="utf-8"):  # the root's stub
                page.wait_for_url(f"{base_url}/{INTRO}")
                page.wait_for_load_state("load")
            assert page.title(), f"{path}: no page offline"
            shown = page.evaluate(IMAGES_SHOWN)
            assert all(result is True for result in shown), f"{path}: images not shown offline: {shown}"
            fresh = page.locator("form.q-form button.q-new")
            if fresh.count():  # a question page: new numbers come from the cache
                practised.add(page.locator("form.q-form").first.get_attribute("data-type"))
                fresh.first.click()
                page.wait_for_function("document.querySelector('form.q-form button.q-new').closest('form')"
                                       ".dataset.variant !== '0'")
        if subpath:  # every page walked: every type's questions gave new numbers
            assert practised == set(bank.TOPIC.type_keys), f"offline, no new numbers for {set(bank.TOPIC.type_keys) - practised}"
        else:
            assert practised, "offline, no question gave new numbers"

        # a question marks, and new numbers come from the cache
        key = "graph-kick-force-time"
        page.goto(f"{base_url}/book/exam/practice-force-momentum.html#question-{key}")
        form = page.locator(f'form.q-form[data-question="{key}"]')
        printed = bank.TEMPLATES[key].variant(0)
        form.locator('[data-part="a"] input.q-value').fill(str(int(printed.parts[0].value)))
        form.locator('[data-part="a"] input.q-unit').fill("N")
        form.locator("button.q-check").click()
        assert form.locator('[data-part="a"] .q-feedback').get_attribute("data-code") == "correct"
        graph = page.locator(f'section.q[data-q="{key}"] img.q-graph')
        before = graph.get_attribute("src")
        form.locator("button.q-new").click()
        page.wait_for_function(f"document.querySelector('form[data-question=\"{key}\"]').dataset.variant !== '0'")
        assert graph.get_attribute("src") != before
        assert page.evaluate(IMAGES_SHOWN) and all(r is True for r in page.evaluate(IMAGES_SHOWN))

        # the attempt shows on Your practice
        page.goto(f"{base_url}/book/exam/your-practice.html")
        summary = page.locator('.pp-type[data-type="force-momentum"] .pp-summary').text_content()
        assert "1 of" in summary, summary
        _plan_start_and_a_definition_card(page, f"{base_url}/book/exam/method-definitions.html")

        # an explorable responds
        page.goto(f"{base_url}/{_page_with_explorable(site_dir)}")
        box = page.locator("[data-explorable]").first
        text = box.inner_text()
        slider = box.locator('input[type="range"]').first
        slider.focus()
        slider.press("ArrowRight")
        assert box.inner_text() != text, "the explorable did not respond offline"

        # search finds pages, with snippets
        page.goto(f"{base_url}/search.html?q=momentum")
        page.wait_for_function(
            "[...document.querySelectorAll('#search-results ul.search > li')].slice(0, 3).length === 3 && "
            "[...document.querySelectorAll('#search-results ul.search > li')].slice(0, 3)"
            ".every(li => li.querySelector('.context') && li.querySelector('.context').textContent.trim())",
            timeout=20_000)
        context.close()
        assert not errors, errors


#: The teacher's kit (make worksheets): a sheet the teacher opens online, and its key, never opened.
OPENED_PDF = "teachers/end-of-topic-test-A.pdf"
NEVER_OPENED_PDF = "teachers/end-of-topic-test-key-A.pdf"
#: The page fetches a file as its link names it: its status and bytes, or the error offline.
FETCHED = """async (url) => {
    try {
        const response = await fetch(url);
        return {status: response.status, bytes: Array.from(new Uint8Array(await response.arrayBuffer()))};
    } catch (error) {
        return {error: String(error)};
    }
}"""


@pytest.mark.parametrize("subpath", SUBPATHS)
def test_a_teachers_pdf_opened_once_opens_again_offline(browser, site_dir, subpath):
    kit = site_dir / OPENED_PDF
    assert kit.is_file() and (site_dir / NEVER_OPENED_PDF).is_file(), \
        "no teacher's kit in the site: make worksheets (or make book) writes it"
    # no-store: only the service worker may keep a file (with a host's max-age, the browser's
    # own cache would answer offline and this could not fail)
    with serve_site(site_dir, prefix=subpath, cache_control="no-store") as base_url:
        context, page, errors = _first_visit(browser, base_url)
        page.goto(f"{base_url}/book/teachers.html")
        opened, never_opened = (page.locator(f'a[href$="{path}"]').evaluate("link => link.href")
                                for path in (OPENED_PDF, NEVER_OPENED_PDF))
        online = page.evaluate(FETCHED, opened)
        assert online.get("status") == 200 and bytes(online["bytes"]) == kit.read_bytes(), online.get("error")

        context.set_offline(True)
        again = page.evaluate(FETCHED, opened)
        assert again.get("status") == 200, f"{OPENED_PDF}, opened online, fails offline: {again.get('error')}"
        assert bytes(again["bytes"]).startswith(b"%PDF") and bytes(again["bytes"]) == kit.read_bytes()
        # nothing is kept that was never opened: the first install stays within its budget
        assert "error" in page.evaluate(FETCHED, never_opened), f"{NEVER_OPENED_PDF} came offline unopened"
        context.close()
        assert not errors, errors


def _plan_start_and_a_definition_card(page, self_test: str) -> None:
    """On Your practice: the plan is worked out (ts-fsrs and the schedule load), Start serves
    its first card with new numbers and the review line; then the self-test opens one card,
    whose mark is kept as an attempt at that card."""
    page.wait_for_function("document.documentElement.classList.contains('pp-planned')")  # progress-plan.js ran
    assert "Weakest type:" in page.locator(".pp-weakest").inner_text()
    page.get_by_role("button", name="Start", exact=True).click()
    page.wait_for_url(lambda url: "#question-" in url)
    page.wait_for_load_state("load")
    # the queue Start kept. From disk (file://), Chromium without --allow-file-access-from-files
    # (a student's Chrome) at times gives two pages two apart localStorage areas under one
    # storage key, "file:///" (about 1 visit in 10 here; a probe key written on Your practice
    # was missing too, and no storage event brought it later): there the link carries the queue
    # (?review=), and review.js keeps it in this page's storage, so it is here every time.
    queue = page.evaluate("localStorage.getItem('dynamics-review-v1')")
    assert queue is not None, "the question page does not see the queue Your practice kept"
    card = json.loads(queue)["cards"][0]
    form = page.locator(f'form.q-form[data-question="{card["id"]}"]')
    form.locator("button.q-check").click()
    assert page.locator(".rv-bar").inner_text().startswith("Card 1 of ")
    page.goto(f"{self_test}?card=mass#st-card-mass", wait_until="load")
    item = page.locator("#st-card-mass")
    item.locator(".st-reveal").click()
    item.get_by_role("button", name="I knew it").click()
    attempts = page.evaluate("JSON.parse(localStorage.getItem('dynamics-progress-v2')).attempts")
    assert any(a["question"] == "definition:mass" and a["earned"] == 1 for a in attempts)


def _page_with_explorable(site_dir: Path) -> str:
    for path in site_pages(site_dir):
        if "data-explorable=" in (site_dir / path).read_text(encoding="utf-8"):
            return path
    raise AssertionError("no page shows an explorable")


@pytest.mark.parametrize("subpath", SUBPATHS)
def test_a_new_build_is_offered_and_a_reload_shows_its_text(browser, site_dir, tmp_path, subpath):
    site = tmp_path / "site"
    shutil.copytree(site_dir, site)
    with serve_site(site, prefix=subpath, cache_control=HOST_CACHE) as base_url:
        context, page, errors = _first_visit(browser, base_url)
        # the next build changes the intro's heading; the build ends by writing sw.js
        intro = site / INTRO
        html, count = re.subn(r"(<h1>[^<]+)", r"\1 (new edition)", intro.read_text(encoding="utf-8"), count=1)
        assert count == 1
        intro.write_text(html, encoding="utf-8")
        offline.write_service_worker(site)
        page.reload()
        assert "(new edition)" not in page.locator("main h1").first.inner_text()  # the cache still serves
        notice = page.locator(".offline-update[role=status]")
        notice.wait_for(timeout=60_000)
        assert "new version" in notice.inner_text()
        with page.expect_navigation():
            notice.get_by_role("button", name="Reload").click()
        page.wait_for_function("document.querySelector('main h1').textContent.includes('(new edition)')")
        context.close()
        assert not errors, errors


def test_the_precache_lists_every_page_and_what_pages_load_but_no_downloads(site_dir):
    listed = dict(offline.precache_list(site_dir))
    for path in site_pages(site_dir):
        assert path in listed, f"{path} is not kept offline"
    assert "searchindex.js" in listed
    assert any(path.startswith("_static/questions/") and path.endswith(".svg") for path in listed)
    assert not [path for path in listed if path.startswith(("pdf/", "teachers/")) or path.endswith((".ttf", ".map", ".zip"))]
    # the theme's Font Awesome fonts (300 kB gzip) are never loaded: the site's subset is
    assert not [path for path in listed if "fontawesome/webfonts/" in path]
    assert "_static/site-assets/icons.woff" in listed
    sw = (site_dir / offline.SERVICE_WORKER).read_text(encoding="utf-8")
    assert all(f'"{path}"' in sw for path in listed)
    assert offline.precache_size(site_dir) <= 2_000_000  # CLARIFICATIONS: at most 2 MB gzip


@pytest.fixture(scope="module")
def unzipped(site_dir, tmp_path_factory) -> Path:
    """The zip make book writes, unzipped as a student would (scripts/zip_site.py)."""
    zipped = site_dir / "download" / "dynamics.zip"
    assert zipped.is_file(), "no zip of the site: make book writes it (scripts/zip_site.py)"
    folder = tmp_path_factory.mktemp("copy")
    shutil.unpack_archive(zipped, folder)
    return folder / "dynamics"


def test_the_zip_holds_the_book_s_and_the_teacher_s_pdfs_and_the_moodle_file(site_dir):
    downloads = sorted(path.relative_to(site_dir).as_posix() for folder in ("pdf", "teachers")
                       for path in (site_dir / folder).glob("*") if path.suffix in {".pdf", ".xml"})
    assert "pdf/dynamics.pdf" in downloads and OPENED_PDF in downloads and "teachers/dynamics-moodle.xml" in downloads
    with zipfile.ZipFile(site_dir / "download" / "dynamics.zip") as archive:
        zipped = set(archive.namelist())
    assert [path for path in downloads if f"dynamics/{path}" not in zipped] == []


def test_the_zip_opens_from_disk_with_figures_questions_and_search(browser, unzipped):
    context = browser.new_context()
    errors: list[str] = []
    context.on("weberror", lambda error: errors.append(str(error.error)))
    page = context.new_page()
    for path in site_pages(unzipped):
        page.goto((unzipped / path).as_uri(), wait_until="load")
        if "http-equiv=\"refresh\"" in (unzipped / path).read_text(encoding="utf-8"):  # the root's stub
            page.wait_for_url((unzipped / INTRO).as_uri())
            page.wait_for_load_state("load")
        assert page.title(), f"{path}: no page from disk"
        shown = page.evaluate(IMAGES_SHOWN)
        assert all(result is True for result in shown), f"{path}: images not shown from disk: {shown}"

    key = "quick-check-1"
    page.goto((unzipped / "book/exam/quick-check.html").as_uri())
    form = page.locator(f'form.q-form[data-question="{key}"]')
    form.locator('[data-part="a"] input.q-value').fill("15")
    form.locator('[data-part="a"] input.q-unit').fill("N s")
    form.locator('[data-part="b"] input.q-value').fill("7.5")
    form.locator('[data-part="b"] input.q-unit').fill("m/s")
    form.locator("button.q-check").click()
    assert form.locator(".q-score").inner_text() == "4/4 marks"
    form.locator("button.q-new").click()  # the variants come by <script>, which file:// allows
    page.wait_for_function(f"document.querySelector('form[data-question=\"{key}\"]').dataset.variant !== '0'")
    page.goto((unzipped / "book/exam/your-practice.html").as_uri(), wait_until="load")
    _plan_start_and_a_definition_card(page, (unzipped / "book/exam/method-definitions.html").as_uri())

    page.goto((unzipped / "search.html").as_uri() + "?q=terminal+velocity")
    page.wait_for_function(
        "[...document.querySelectorAll('#search-results ul.search > li')].length >= 3 && "
        "[...document.querySelectorAll('#search-results ul.search > li')].slice(0, 3)"
        ".every(li => li.querySelector('.context') && li.querySelector('.context').textContent.trim())",
        timeout=20_000)
    first = page.locator("#search-results ul.search > li").first
    assert "friction-drag-terminal-velocity" in first.locator("a").first.get_attribute("href")
    assert "terminal" in first.locator(".context").inner_text().lower()
    context.close()
    assert not errors, errors


def test_a_browser_test_s_context_blocks_the_worker(browser, site_dir):
    """scripts/browser.py: other tests' fresh contexts must not download the whole book behind
    their page. The tests above allow the worker, and each waits for it to control its page
    (_first_visit): a worker that never came would fail them."""
    with serve_site(site_dir) as base_url:
        blocked = browser.new_context()
        # offline.js registers the worker after "load": the test waits for that call to settle
        blocked.add_init_script("""if ('serviceWorker' in navigator) {
            const register = navigator.serviceWorker.register.bind(navigator.serviceWorker);
            navigator.serviceWorker.register = (...args) =>
                register(...args).finally(() => { window.__registerSettled = true; });
        }""")
        page = blocked.new_page()
        page.goto(f"{base_url}/{INTRO}", wait_until="load")
        page.wait_for_function("!('serviceWorker' in navigator) || window.__registerSettled === true")
        assert page.evaluate("'serviceWorker' in navigator ? navigator.serviceWorker.getRegistrations()"
                             ".then(r => r.length) : 0") == 0, "a default context registered the worker"
        blocked.close()
