"""The menus, as a reader works them: the chapter list (☰) and the page's contents at a
phone's, a tablet's and a laptop's width, in Debian's Chromium on the built site.

Below 992 px the themes open each as a dialog; from 992 px the chapter list is beside
the page and ☰ folds it away and back; from 1200 px the contents are beside it too.
The visible buttons are sphinx-book-theme's; the themes' scripts bind hidden copies, and
book/_ext/site_assets/static/site-menus.js passes the visible buttons' clicks on.
"""

from __future__ import annotations

import pytest
from browser import axe_violations
from playwright.sync_api import TimeoutError as PlaywrightTimeout
from support.pages import readers_of

pytestmark = [pytest.mark.site, pytest.mark.browser]

PAGE = "book/understand/weight.html"  # a chapter with contents of its own
CHAPTER_8 = "book/understand/elastic-and-inelastic.html"
CHAPTERS = "#pst-primary-sidebar-modal"
CONTENTS = "#pst-secondary-sidebar-modal"
ROUTES = ["Escape", "tap outside", "Close button"]

# Whether `el` is on screen and on top: the point at its centre belongs to it.
ON_TOP = """(el) => {
  const r = el.getBoundingClientRect();
  if (r.width < 100 || r.height < 100 || r.left < 0 || r.right > innerWidth + 1) return false;
  const hit = document.elementFromPoint(r.left + r.width / 2, r.top + Math.min(r.height / 2, 300));
  return !!hit && el.contains(hit);
}"""


class Reader:
    """One page at one width; taps on a touch screen below 992 px, clicks otherwise."""

    def __init__(self, browser, base_url: str, width: int, scheme: str = "light"):
        self.width = width
        self.touch = width < 992
        self.context = browser.new_context(viewport={"width": width, "height": 800}, has_touch=self.touch,
                                           color_scheme=scheme)
        self.page = self.context.new_page()
        self.errors: list[str] = []
        self.page.on("console", lambda m: m.type == "error" and self.errors.append(m.text))
        self.page.on("pageerror", lambda e: self.errors.append(f"uncaught: {e}"))
        self.page.goto(f"{base_url}/{PAGE}", wait_until="load")

    def press(self, locator):
        locator.tap() if self.touch else locator.click()

    def press_at(self, x: float, y: float):
        self.page.touchscreen.tap(x, y) if self.touch else self.page.mouse.click(x, y)

    def toggle(self, kind: str):
        """The ☰ ("primary") or Contents ("secondary") button a reader sees: exactly one."""
        visible = self.page.locator(f".{kind}-toggle:visible")
        assert visible.count() == 1, f"{self.width} px: {visible.count()} visible .{kind}-toggle buttons"
        return visible

    def wait_on_top(self, selector: str, what: str):
        try:
            self.page.wait_for_function(f"({ON_TOP})(document.querySelector('{selector}'))", timeout=3_000)
        except PlaywrightTimeout:
            pytest.fail(f"{self.width} px: {what} is not on screen", pytrace=False)

    def focus_in(self, selector: str) -> bool:
        return self.page.evaluate(f"document.querySelector('{selector}').contains(document.activeElement)")

    def is_open(self, selector: str) -> bool:
        return self.page.evaluate(f"document.querySelector('{selector}').open")

    def close(self):
        self.context.close()

    def close_by(self, route: str, dialog: str):
        if route == "Escape":
            self.page.keyboard.press("Escape")
        elif route == "Close button":
            close = self.page.locator(dialog).get_by_role("button", name="Close")
            assert close.count() == 1 and close.is_visible(), f"{self.width} px: no Close button in {dialog}"
            self.press(close)
        else:  # a point beside the panel, on the dimmed page
            box = self.page.locator(dialog).bounding_box()
            right_gap = self.width - (box["x"] + box["width"])
            x = box["x"] / 2 if box["x"] > right_gap else box["x"] + box["width"] + right_gap / 2
            self.press_at(x, 400)


reader = readers_of(Reader)  # reader(width, ...) opens one; each is closed after the test


def _open_close(me: Reader, kind: str, dialog: str, what: str, route: str, inside: str):
    toggle = me.toggle(kind)
    me.press(toggle)
    assert me.is_open(dialog), f"{me.width} px: tapping the {what} button opens nothing"
    me.wait_on_top(dialog, f"the {what}")
    assert me.page.locator(f"{dialog} {inside}").first.is_visible(), f"{me.width} px: the {what} panel is empty"
    assert me.focus_in(dialog), f"{me.width} px: the focus stays outside the {what} panel"
    me.close_by(route, dialog)
    try:  # closed, and (with the close event, a task later) its content back in its place
        me.page.wait_for_function(
            f"(d => !d.open && d.childElementCount === 0)(document.querySelector('{dialog}'))", timeout=3_000
        )
    except PlaywrightTimeout:
        pytest.fail(f"{me.width} px: {route} does not close the {what}", pytrace=False)
    assert me.page.evaluate(f"document.activeElement.matches('.bd-header-article .{kind}-toggle')"), (
        f"{me.width} px: after closing the {what}, the focus is not back on its button"
    )
    # Open again after closing: the button still works.
    me.press(toggle)
    assert me.is_open(dialog), f"{me.width} px: the {what} button works only once"
    assert not me.errors, me.errors


@pytest.mark.parametrize("route", ROUTES)
def test_phone_chapter_list_opens_and_closes(reader, route):
    me = reader(390)
    _open_close(me, "primary", CHAPTERS, "chapter list", route, f'a[href$="{CHAPTER_8.split("/")[-1]}"]')


@pytest.mark.parametrize("route", ROUTES)
@pytest.mark.parametrize("width", [390, 1024])
def test_contents_open_and_close(reader, width, route):
    me = reader(width)
    _open_close(me, "secondary", CONTENTS, "contents", route, 'nav.page-toc a[href="#in-a-lift"]')


def test_phone_reaches_chapter_8_from_the_menu(reader):
    """The trip that took nine taps of Next: ☰, then the chapter."""
    me = reader(390)
    me.press(me.toggle("primary"))
    link = me.page.locator(CHAPTERS).get_by_role("link", name="Elastic and inelastic collisions")
    me.press(link)
    me.page.wait_for_url(f"**/{CHAPTER_8}")
    assert not me.errors, me.errors


def test_phone_keyboard_opens_the_chapter_list(reader):
    me = reader(390)
    me.toggle("primary").focus()
    me.page.keyboard.press("Enter")
    assert me.is_open(CHAPTERS) and me.focus_in(CHAPTERS), "Enter on ☰ does not open the chapter list with focus in it"
    me.page.keyboard.press("Escape")
    assert not me.is_open(CHAPTERS)
    assert me.page.evaluate("document.activeElement.matches('.primary-toggle')"), "focus does not return to ☰"


@pytest.mark.parametrize("width", [1024, 1280])
def test_wide_chapter_list_folds_away_and_back(reader, width):
    me = reader(width)
    sidebar = "#pst-primary-sidebar"
    me.wait_on_top(sidebar, "the chapter list beside the page")
    toggle = me.toggle("primary")
    me.press(toggle)
    assert not me.is_open(CHAPTERS), f"{width} px: ☰ opened a dialog instead of folding the sidebar"
    me.page.wait_for_function(f"!({ON_TOP})(document.querySelector('{sidebar}'))", timeout=3_000)
    me.press(toggle)
    me.wait_on_top(sidebar, "the chapter list, after ☰ twice,")
    assert not me.errors, me.errors


def test_laptop_shows_the_contents_beside_the_page(reader):
    me = reader(1280)
    assert me.page.locator(".secondary-toggle:visible").count() == 0, "a Contents button with the contents in sight"
    assert me.page.locator('#pst-secondary-sidebar nav.page-toc a[href="#in-a-lift"]').is_visible()


@pytest.mark.parametrize("scheme", ["light", "dark"])
def test_open_menus_pass_axe(reader, scheme):
    """The panels as they are when open (the site sweep sees them closed): every axe rule."""
    me = reader(390, scheme)
    me.page.add_style_tag(content="*, *::before, *::after { transition: none !important; }")
    found = {}
    for kind, dialog in (("primary", CHAPTERS), ("secondary", CONTENTS)):
        me.press(me.toggle(kind))
        me.wait_on_top(dialog, dialog)
        found[dialog] = [f"{v['id']} ({v['impact']}): {v['targets']}"
                         for v in axe_violations(me.page, context_selector=dialog)]
        me.page.keyboard.press("Escape")
        me.page.wait_for_function(f"!document.querySelector('{dialog}').open")
    assert not any(found.values()), found
