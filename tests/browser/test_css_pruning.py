"""The CSS the site ships is pruned (PurgeCSS, book/_ext/site_assets/prune-css.js) to the
rules its pages and scripts use. Nothing may change on screen: the same build with the
unpruned bundles (write_bundle's output) and with the pruned ones gives the same pixels,
light and dark (each page loaded light, then switched to dark in place), at 1280 and 390 px,
and with the phone's menu open."""

from __future__ import annotations

import json
import shutil
from io import BytesIO
from pathlib import Path

import pytest
from browser import serve_site
from PIL import Image, ImageChops
from site_assets import bundle_registry, unpruned_bundle

pytestmark = [pytest.mark.site, pytest.mark.browser]

ROOT = Path(__file__).resolve().parents[2]
PAGES = ["book/intro.html", "book/understand/friction-drag-terminal-velocity.html",
         "book/exam/quick-check.html", "book/exam/practice-force-momentum.html", "search.html?q=momentum"]
WIDTHS = {"desktop": 1280, "phone": 390}
MODES = ["light", "dark"]


@pytest.fixture(scope="module")
def unpruned(site_dir, tmp_path_factory) -> Path:
    """A copy of the site with every bundle as written before pruning (site_assets keeps
    that beside the site)."""
    copy = tmp_path_factory.mktemp("unpruned") / "html"
    shutil.copytree(site_dir, copy)
    bundles = json.loads(bundle_registry(site_dir).read_text())
    assert bundles, "no CSS bundle registered"
    for name in bundles:
        shutil.copyfile(unpruned_bundle(site_dir, name), copy / name)
        assert (copy / name).stat().st_size > 2 * (site_dir / name).stat().st_size, f"{name} was not pruned"
    return copy


def _settled(page) -> None:
    """Wait for what a full-page shot would otherwise catch half done."""
    page.evaluate("document.fonts.ready")
    # lazy figures load when a full-page shot grows the viewport, at a time a loaded machine
    # varies: load and decode them all first
    page.evaluate("Promise.all([...document.images].map(i => { i.loading = 'eager'; return i.decode().catch(() => null); }))")
    # every transition and animation run to its end (the phone menu's panel slides in)
    page.evaluate("Promise.all(document.getAnimations().map(a => a.finished.catch(() => null)))")


def _shots(browser, base_url: str, page_path: str, width: int, *, menu: bool = False) -> dict[str, Image.Image]:
    """The page light, then dark: loaded once, light, and switched to dark in place as the
    system's setting switches a reader's open page (the theme follows it)."""
    context = browser.new_context(viewport={"width": width, "height": 900}, color_scheme="light",
                                  service_workers="block")
    page = context.new_page()
    page.goto(f"{base_url}/{page_path}", wait_until="load")
    # every deferred script and figure fetched (a slow machine is still loading at "load")
    page.wait_for_load_state("networkidle")
    if "search.html" in page_path:
        # every result, with its snippet (each comes with a fetch of its page, in any order)
        page.wait_for_function("(document.querySelector('#search-results p.search-summary') || "
                               "{textContent: ''}).textContent.startsWith('Search finished') && "
                               "[...document.querySelectorAll('#search-results ul.search > li')]"
                               ".every(li => li.querySelector('.context'))")
    if menu:
        page.locator("button.primary-toggle:visible, label.sidebar-toggle.primary-toggle:visible").first.click()
    shots = {}
    for mode in MODES:
        if mode == "dark":
            page.emulate_media(color_scheme="dark")
            page.wait_for_function("document.documentElement.dataset.theme === 'dark'")
        _settled(page)
        png = page.screenshot(full_page=not menu, animations="disabled", caret="hide")
        shots[mode] = Image.open(BytesIO(png)).convert("RGB")
    context.close()
    return shots


#: Chromium's software raster sometimes draws a figure's rounded corner 2 px apart from one
#: shot to the next (both bundles alike, about one shot in three on the drag page at 390 px,
#: dark): a few dozen pixels. A rule pruned that a page uses moves or recolours a whole
#: element: thousands. Two shots are the same when at most this many pixels differ.
NOISE_PIXELS = 200


def _same(first: Image.Image, second: Image.Image) -> bool:
    if first.size != second.size:
        return False
    changed = ImageChops.difference(first, second).convert("L").point(lambda value: 255 if value else 0)
    return changed.histogram()[255] <= NOISE_PIXELS


@pytest.fixture(scope="module")
def changed(browser, site_dir, unpruned) -> dict[tuple[str, str], list[str]]:
    """{(width, mode): the pages whose shots differ}: every page of PAGES at each width, with
    the pruned and with the full bundles, each loaded once and shot light and then dark."""
    found = {(width, mode): [] for width in WIDTHS for mode in MODES}
    with serve_site(site_dir) as pruned_url, serve_site(unpruned) as full_url:
        for width, pixels in WIDTHS.items():
            for path in PAGES:
                pruned, full = (_shots(browser, url, path, pixels) for url in (pruned_url, full_url))
                for mode in MODES:
                    if not _same(pruned[mode], full[mode]):
                        found[width, mode].append(path)
    return found


@pytest.mark.parametrize("mode", MODES)
@pytest.mark.parametrize("width", WIDTHS)
def test_pruned_css_draws_every_page_as_the_full_css_does(changed, width, mode):
    # one shot each, compared within NOISE_PIXELS
    assert not changed[width, mode], f"pruning the CSS changed {changed[width, mode]} at {WIDTHS[width]} px, {mode}"


def test_pruned_css_draws_the_phone_menu_as_the_full_css_does(browser, site_dir, unpruned):
    with serve_site(site_dir) as pruned_url, serve_site(unpruned) as full_url:
        pruned, full = (_shots(browser, url, "book/intro.html", 390, menu=True) for url in (pruned_url, full_url))
    changed = [mode for mode in MODES if not _same(pruned[mode], full[mode])]
    assert not changed, f"pruning the CSS changed the open phone menu ({', '.join(changed)})"
