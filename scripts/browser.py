"""Shared helpers for browser tests: serve a built site and open it in headless Chromium.

The site is served the way a static host serves it: on a local port, with gzip for
text files, so the bytes Chromium reports are the bytes a student downloads.
Chromium is Debian's, driven by Python playwright, which never downloads a browser of its
own: its headless shell (/usr/bin/chromium-headless-shell, the same engine without the
browser's window code, which playwright itself runs for headless tests: a fifth less CPU),
and the whole browser (/usr/bin/chromium) for Lighthouse.

    with serve_site(site_dir) as base_url, open_browser() as browser:
        page = browser.new_page()
        page.goto(base_url + "/book/intro.html")
"""

from __future__ import annotations

import asyncio
import contextlib
import gzip
import hashlib
import http.server
import io
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import threading
import time
import urllib.request
from collections.abc import Iterator
from dataclasses import dataclass, field
from functools import cache, lru_cache
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
CHROMIUM = "/usr/bin/chromium"
CHROMIUM_HEADLESS_SHELL = "/usr/bin/chromium-headless-shell"
NODE_MODULES = ROOT / "node_modules"
CHROMIUM_ARGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
]
# The widths the site is checked at: a laptop and a phone.
VIEWPORTS = {"desktop": {"width": 1280, "height": 800}, "mobile": {"width": 390, "height": 844}}
COMPRESSIBLE = {".html", ".css", ".js", ".svg", ".json", ".txt", ".xml", ".map", ".inv", ".md"}


def require_tool(path: Path, fix: str) -> Path:
    """`path`, or an error that names the command that installs it (never a skip)."""
    if not path.exists():
        raise RuntimeError(f"{path} is missing: {fix}")
    return path


#: Called before Chromium is looked up: tests/conftest.py adds its check that the running test
#: is marked `browser` (a browser test must say so, for `make check`); scripts add none.
BEFORE_CHROMIUM: list = []


def chromium_path(*, whole_browser: bool = False) -> str:
    """The headless shell the tests drive, or (`whole_browser`) Chromium itself."""
    for check in BEFORE_CHROMIUM:
        check()
    path = Path(CHROMIUM if whole_browser else CHROMIUM_HEADLESS_SHELL)
    return str(require_tool(path, f"run `scripts/ensure-debian-packages test` (as root), or apt-get install {path.name}"))


def node_module(name: str) -> Path:
    """The installed npm package `name` (package.json at the repository root pins it)."""
    return require_tool(NODE_MODULES / name, f"run `npm ci` in {ROOT} to install {name}")


@cache
def _gzipped(path: Path, mtime_ns: int) -> bytes:
    return gzip.compress(path.read_bytes(), compresslevel=6, mtime=0)


class _StaticHandler(http.server.SimpleHTTPRequestHandler):
    """A quiet static host that gzips text files when the browser accepts gzip."""

    protocol_version = "HTTP/1.1"  # keep-alive, as a real host: one connection, many files
    # A response is its headers, then its body: two writes. With Nagle's algorithm on, the body
    # waited for the ACK of the headers, which loopback delays by 40 ms: a first visit that
    # installs the service worker (476 files) took 8 s, 2 s without. A real host sends at once.
    disable_nagle_algorithm = True

    def log_message(self, format, *args):
        pass

    #: "/NAME/" to serve the site there (as GitHub Pages serves a project site), "" at the root.
    prefix = ""
    #: Cache-Control: "no-cache", or a host's reuse time (GitHub Pages: max-age=600).
    cache_control = "no-cache"

    def end_headers(self):
        self.send_header("Cache-Control", self.cache_control)
        super().end_headers()

    def translate_path(self, path):
        if self.prefix:
            if not path.startswith(self.prefix):
                return str(Path(self.directory) / "no such file outside the subpath")
            path = "/" + path[len(self.prefix):]
        return super().translate_path(path)

    def send_head(self):
        path = Path(self.translate_path(self.path))
        if path.is_dir():
            path = path / "index.html"
        accepts_gzip = "gzip" in self.headers.get("Accept-Encoding", "")
        if not (accepts_gzip and path.suffix in COMPRESSIBLE and path.is_file()):
            return super().send_head()
        body = _gzipped(path, path.stat().st_mtime_ns)
        self.send_response(200)
        self.send_header("Content-Type", self.guess_type(str(path)))
        self.send_header("Content-Encoding", "gzip")
        self.send_header("Content-Length", str(len(body)))
        self.send_header("Vary", "Accept-Encoding")
        self.end_headers()
        return io.BytesIO(body)

    def copyfile(self, source, outputfile):
        shutil.copyfileobj(source, outputfile)


class _QuietServer(http.server.ThreadingHTTPServer):
    daemon_threads = True

    def handle_error(self, request, client_address):
        # Chromium drops connections it no longer needs (a page left mid-download): not an
        # error of the site, and its traceback buried the test log.
        if not isinstance(sys.exc_info()[1], ConnectionError):
            super().handle_error(request, client_address)


@contextlib.contextmanager
def serve_site(site: Path, *, prefix: str = "", cache_control: str = "no-cache") -> Iterator[str]:
    """Serve `site` on a free local port in a thread; yield its base URL (ending before
    `prefix`, e.g. "/dynamics/", when the site is served under a subpath)."""
    handler_class = type("Handler", (_StaticHandler,), {"prefix": prefix, "cache_control": cache_control})

    def handler(*args, **kwargs):
        return handler_class(*args, directory=str(site), **kwargs)

    server = _QuietServer(("127.0.0.1", 0), handler)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    try:
        yield f"http://127.0.0.1:{server.server_address[1]}{prefix.rstrip('/')}"
    finally:
        server.shutdown()
        server.server_close()


class _BrowserWithoutWorkers:
    """The launched browser, whose new contexts and pages block the book's service worker
    unless a test asks for it (``service_workers="allow"``: the tests of offline use). On every
    first visit the worker downloads the whole book behind the page (offline.js): about 2 MB
    a context, for hundreds of fresh contexts, which only the offline tests look at."""

    def __init__(self, browser):
        self._browser = browser

    def new_context(self, **options):
        return self._browser.new_context(**{"service_workers": "block", **options})

    def new_page(self, **options):
        return self._browser.new_page(**{"service_workers": "block", **options})

    def __getattr__(self, name):
        return getattr(self._browser, name)


@contextlib.contextmanager
def open_browser():
    """Headless Debian Chromium driven by playwright (sync API); service workers blocked
    unless a context allows them."""
    from playwright.sync_api import sync_playwright

    executable = chromium_path()
    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=executable, args=CHROMIUM_ARGS)
        try:
            yield _BrowserWithoutWorkers(browser)
        finally:
            browser.close()


def site_pages(site: Path) -> list[str]:
    """Every page of the built site, as paths relative to its root: the content pages and
    every page Sphinx or Jupyter Book generates (search.html, the root redirect). A page
    that is not wanted is removed from the build, never left out here."""
    return sorted(
        p.relative_to(site).as_posix()
        for p in site.rglob("*.html")
        if not {"_static", "_sources", "_images"} & set(p.parts)
    )


# A redirect stub (Jupyter Book's root index.html) is judged by the page it leads to, the
# one a reader sees. Known from the stub's own HTML: asking the page itself races its refresh
# (the script may run in the next document, or in the empty one before it).
IS_REDIRECT_STUB = re.compile(r"<meta[^>]+http-equiv=.refresh", re.IGNORECASE)
SCROLL_TO_BOTTOM = "window.scrollTo(0, document.body.scrollHeight)"


def _is_redirect_stub(url: str) -> bool:
    """Read over HTTP, not from the tab: the tab drops the stub's body once it has moved on."""
    with urllib.request.urlopen(url) as response:
        return bool(IS_REDIRECT_STUB.search(response.read().decode("utf-8", "replace")))


def _landed(stub: str):
    """A URL predicate: any page but the stub."""
    return lambda url: url != stub and url.startswith("http")


def goto_page(page, url: str) -> None:
    """Load `url` in `page`; a redirect stub (IS_REDIRECT_STUB), until the page it leads to
    has loaded."""
    page.goto(url, wait_until="load")
    if _is_redirect_stub(url):
        page.wait_for_url(_landed(url), wait_until="load")


#: The page-weight budget (CLARIFICATIONS: House, and the standing "Page weight"): a first visit,
#: counted as Chromium counts a cold load (bytes on the wire, headers included), transfers at most
#: this share of the default Jupyter Book 1 page, in at most FIRST_VISIT_REQUESTS requests.
FIRST_VISIT_SHARE = 0.10
FIRST_VISIT_REQUESTS = 15
#: Question data: a template's, inline and its variants' file together, gzip (issue 39).
QUESTION_DATA_BYTES = 40_000


@dataclass
class PageLoad:
    """What loading one page cost and what went wrong while loading it."""

    url: str
    requests: list[str] = field(default_factory=list)
    transferred: dict[str, int] = field(default_factory=dict)  # url -> gzip body bytes
    failed: list[str] = field(default_factory=list)
    foreign: list[str] = field(default_factory=list)  # requests to another host
    console_errors: list[str] = field(default_factory=list)

    @property
    def total_bytes(self) -> int:
        return sum(self.transferred.values())


def load_page(context, url: str, *, scroll: bool = True, measure: bool = True) -> tuple[object, PageLoad]:
    """Open `url` in a new page of `context`; record requests, failures and console errors.

    A redirect stub is followed to the page it leads to (IS_REDIRECT_STUB).
    With `scroll`, the page is scrolled to the bottom so lazily loaded figures count too.
    With `measure`, each response's transferred size is recorded (slower).
    """
    origin = url.split("/", 3)[:3]
    record = PageLoad(url)
    page = context.new_page()

    def on_request(request):
        record.requests.append(request.url)
        if request.url.split("/", 3)[:3] != origin and not request.url.startswith("data:"):
            record.foreign.append(request.url)

    def on_finished(request):
        response = request.response()
        if response is None:
            return
        if response.status >= 400:
            record.failed.append(f"{request.url} (HTTP {response.status})")
        if request.url.startswith("data:") or not measure:
            return
        sizes = request.sizes()
        record.transferred[request.url] = sizes["responseBodySize"] + sizes["responseHeadersSize"]

    page.on("request", on_request)
    page.on("requestfinished", on_finished)
    page.on("requestfailed", lambda r: record.failed.append(f"{r.url} ({r.failure})"))
    page.on("console", lambda m: m.type == "error" and record.console_errors.append(m.text))
    page.on("pageerror", lambda e: record.console_errors.append(str(e)))
    goto_page(page, url)
    if scroll:
        page.evaluate(SCROLL_TO_BOTTOM)
        page.wait_for_load_state("networkidle")
    return page, record


def axe_violations(page, *, rules: list[str] | None = None,
                   context_selector: str | None = None) -> list[dict]:
    """Run axe-core in `page` (every rule, or only `rules`; every impact) over the whole
    document or only the elements matching `context_selector`; its violations."""
    if not page.evaluate(HAS_AXE):
        page.add_script_tag(content=_axe_source())
    return page.evaluate(AXE_RUN, [rules, context_selector])


# axe-core is half a megabyte of script: a page that is checked twice (light, then dark) has it
HAS_AXE = "typeof window.axe === 'object'"


AXE_RUN = """async ([rules, selector]) => {
    const options = {resultTypes: ['violations']};
    if (rules) options.runOnly = {type: 'rule', values: rules};
    const result = await axe.run(selector ? {include: [selector]} : document, options);
    return result.violations.map(v => ({
        id: v.id, impact: v.impact, help: v.help,
        targets: v.nodes.slice(0, 5).map(n => n.target.join(' ') + ' :: ' + n.failureSummary),
    }));
}"""


@lru_cache(maxsize=1)
def _axe_source() -> str:
    return (node_module("axe-core") / "axe.min.js").read_text()


# ---------------------------------------------------------------- async (for sweeps)


@contextlib.asynccontextmanager
async def open_browser_async():
    """Headless Debian Chromium driven by playwright (async API: pages in parallel)."""
    from playwright.async_api import async_playwright

    executable = chromium_path()
    async with async_playwright() as playwright:
        browser = await playwright.chromium.launch(executable_path=executable, args=CHROMIUM_ARGS)
        try:
            yield browser
        finally:
            await browser.close()


class PageVisitor:
    """One browser tab that visits page after page, recording each visit as a PageLoad.

    Reusing a tab is several times faster than opening one per page (async API).
    With `measure`, each response's transferred size is recorded (slower).
    """

    def __init__(self, page, *, measure: bool = True):
        self.page = page
        self.measure = measure
        self.record = PageLoad("")
        self._pending: list = []
        self._in_flight: set = set()
        self._last_activity = 0.0
        page.on("request", self._on_request)
        page.on("requestfinished", self._on_requestfinished)
        page.on("requestfailed", self._on_requestfailed)
        page.on("console", lambda m: m.type == "error" and self.record.console_errors.append(m.text))
        page.on("pageerror", lambda e: self.record.console_errors.append(str(e)))

    def _settled(self, request):
        self._in_flight.discard(request)
        self._last_activity = time.monotonic()

    def _on_requestfinished(self, request):
        self._settled(request)
        self._pending.append(asyncio.ensure_future(self._on_finished(request)))

    def _on_requestfailed(self, request):
        self._settled(request)
        self.record.failed.append(f"{request.url} ({request.failure})")

    def _on_request(self, request):
        self._in_flight.add(request)
        self._last_activity = time.monotonic()
        record = self.record
        record.requests.append(request.url)
        if request.url.split("/", 3)[:3] != record.url.split("/", 3)[:3] and not request.url.startswith("data:"):
            record.foreign.append(request.url)

    async def _on_finished(self, request):
        record = self.record
        response = await request.response()
        if response is None:
            return
        if response.status >= 400:
            record.failed.append(f"{request.url} (HTTP {response.status})")
        if self.measure and not request.url.startswith("data:"):
            sizes = await request.sizes()
            record.transferred[request.url] = sizes["responseBodySize"] + sizes["responseHeadersSize"]

    async def visit(self, url: str, *, scroll: bool = False) -> PageLoad:
        """Load `url` (a redirect stub: and the page it leads to, both recorded); with
        `scroll`, scroll to the bottom so lazy content loads and counts."""
        self.record = PageLoad(url)
        self._in_flight.clear()  # the last page's: their ends may never be reported
        await self.page.goto(url, wait_until="load")
        if await asyncio.to_thread(_is_redirect_stub, url):
            await self.page.wait_for_url(_landed(url), wait_until="load")
        if scroll:
            await self.page.evaluate(SCROLL_TO_BOTTOM)
            await self.network_idle()
        await self.settle()
        return self.record

    async def settle(self) -> None:
        """Wait until every finished request of this tab is recorded."""
        await asyncio.gather(*self._pending)
        self._pending.clear()

    async def network_idle(self, quiet_s: float = 0.5, timeout_s: float = 120) -> None:
        """Wait until no request of this tab has been in flight for `quiet_s`.

        The tab's own count, not playwright's "networkidle", which at times never came on a busy
        machine (a CI run waited out its 120 s; microsoft/playwright#19835). On a timeout the
        error names the page and what was still loading."""
        deadline = time.monotonic() + timeout_s
        while self._in_flight or time.monotonic() - self._last_activity < quiet_s:
            if time.monotonic() > deadline:
                loading = sorted(request.url for request in self._in_flight) or ["nothing (yet never quiet)"]
                raise TimeoutError(f"{self.record.url}: the network was not idle after {timeout_s:.0f} s; "
                                   f"still loading: {', '.join(loading)}")
            await asyncio.sleep(0.05)


async def axe_violations_async(page, *, rules: list[str] | None = None) -> list[dict]:
    """As axe_violations, with the async API."""
    if not await page.evaluate(HAS_AXE):
        await page.add_script_tag(content=_axe_source())
    return await page.evaluate(AXE_RUN, [rules, None])


def progress_checksum(attempts: list[dict]) -> str:
    """An exported progress file's sha256 (book/_ext/questions/static/progress-file.js): the
    SHA-256 of JSON.stringify(attempts), which for these records (whole numbers, strings) is
    Python's json.dumps without spaces and with Unicode as it is."""
    return hashlib.sha256(json.dumps(attempts, separators=(",", ":"), ensure_ascii=False).encode()).hexdigest()


def question_pages(site: Path) -> dict[str, str]:
    """{template key: the site path of the first page that asks it ("/book/exam/x.html")}."""
    pages: dict[str, str] = {}
    for html in sorted(site.rglob("*.html")):
        for key in re.findall(r'<form class="q-form" data-question="([^"]+)"', html.read_text(encoding="utf-8")):
            pages.setdefault(key, "/" + html.relative_to(site).as_posix())
    return pages


def shipped_variants(script: Path) -> list[dict]:
    """The variants a template's data file (_static/questions/KEY.js) ships: its first
    statement, `(window.QuestionVariants ...)[KEY] = [...];` (its form follows on the next line)."""
    first = script.read_text(encoding="utf-8").split("\n", 1)[0]
    return json.loads(first.split("] = ", 1)[1].rstrip().removesuffix(";").replace("<\\/", "</"))


#: Lighthouse's categories as the book judges them, and how many runs a page's score is the
#: median of (CLARIFICATIONS, House: as Lighthouse CI aggregates its runs).
LIGHTHOUSE_CATEGORIES = ("performance", "accessibility", "best-practices", "seo")
LIGHTHOUSE_RUNS = 3


#: Runs Lighthouse through one Chrome, URL after URL (Lighthouse's node API).
LIGHTHOUSE_RUNNER = ROOT / "scripts" / "lighthouse_runs.mjs"


def lighthouse_runs(urls: list[str]) -> list[dict[str, float | None]]:
    """Lighthouse (npm, pinned; mobile) on each of `urls` in turn, one Chrome for them all (a URL
    given three times runs three times, each a first visit): per URL, in order, its category
    scores and its fcp and lcp in ms. Chrome starts once, not once a run."""
    node_module("lighthouse")
    env = {**os.environ, "CHROME_PATH": chromium_path(whole_browser=True), "LH_FLAGS": json.dumps(CHROMIUM_ARGS)}
    with tempfile.TemporaryDirectory() as folder:
        out = Path(folder) / "runs.json"
        result = subprocess.run(["node", str(LIGHTHOUSE_RUNNER), str(out), *urls], env=env, capture_output=True,
                                text=True, timeout=180 * len(urls), check=False)
        if result.returncode != 0:
            raise RuntimeError(f"lighthouse failed on {urls[0]}:\n{result.stderr[-3000:]}")
        return json.loads(out.read_text())


def median_scores(runs: list[dict[str, float | None]]) -> dict[str, float]:
    """Each category's median over a page's Lighthouse runs (a category Lighthouse could not
    score counts 0): never the best of them, so a page that scores low in one run of three
    shows it when it does so twice."""
    if len(runs) != LIGHTHOUSE_RUNS:
        raise ValueError(f"runs: {len(runs)} Lighthouse runs given; the median is taken over {LIGHTHOUSE_RUNS}")
    return {category: statistics.median(run.get(category) or 0.0 for run in runs)
            for category in LIGHTHOUSE_CATEGORIES}
