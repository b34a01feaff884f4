"""The built site's pages as the browser tests meet them: which page shows what, a page
opened with its script errors watched, a question's form answered, and what a page embeds
or keeps in its storage."""

from __future__ import annotations

import functools
import json
import re
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path

import pytest
from browser import site_pages


def page_showing(site_dir: Path, attribute: str, value: str) -> str:
    """The site path ("book/x.html") of the first page whose HTML carries attribute="value"."""
    marker = f'{attribute}="{value}"'
    found = [path for path in site_pages(site_dir) if marker in (site_dir / path).read_text(encoding="utf-8")]
    assert found, f"no page of {site_dir} carries {marker}"
    return found[0]


def explorable_page(site_dir: Path, name: str) -> str:
    """The site path of the first page that shows the named explorable."""
    return page_showing(site_dir, "data-explorable", name)


def question_page(site_dir: Path, key: str) -> str:
    """The site path ("/book/x.html") of the first page that places template `key`."""
    return "/" + page_showing(site_dir, "data-question", key)


@contextmanager
def page_without_errors(browser, url: str | None = None, *, before: Callable | None = None,
                 **context_options) -> Iterator:
    """A page in a fresh context, at `url` if one is given, after `before(page)` (a clock set,
    say); the test fails if a script on it throws."""
    context = browser.new_context(**context_options)
    page = context.new_page()
    errors: list[str] = []
    page.on("pageerror", lambda error: errors.append(str(error)))
    if before is not None:
        before(page)
    if url is not None:
        page.goto(url, wait_until="load")
    yield page
    context.close()
    assert not errors, errors


@contextmanager
def watched_context(browser, base: str, **context_options) -> Iterator:
    """A fresh context that knows the site's base and collects its pages' script errors
    (open_page); the test fails if there are any."""
    context = browser.new_context(**context_options)
    context.base = base
    context.errors = []
    yield context
    assert not context.errors
    context.close()


def open_page(context, path: str):
    """A new page of a watched_context at the site path `path`, loaded."""
    page = context.new_page()
    page.on("pageerror", lambda error: context.errors.append(str(error)))
    page.goto(context.base + path, wait_until="load")
    return page


@contextmanager
def each_closed(make: Callable) -> Iterator[Callable]:
    """`make`, remembering what it made; each is closed at the end."""
    made = []

    def make_one(*args, **kwargs):
        made.append(make(*args, **kwargs))
        return made[-1]

    yield make_one
    for each in made:
        each.close()


def question_form(page, key: str):
    """The form of the question `key` on the page."""
    return page.locator(f'form.q-form[data-question="{key}"]')


def fill_part(form, part: str, value: str, unit: str, direction: str = "") -> None:
    """Type a part's answer into its form as a student does: value, unit and, if given, direction."""
    box = form.locator(f'[data-part="{part}"]')
    box.locator("input.q-value").fill(value)
    box.locator("input.q-unit").fill(unit)
    if direction:
        box.locator("select.q-direction").select_option(direction)


def embedded(page, name: str) -> dict:
    """The JSON a page embeds in <script type="application/json" class="NAME">, from a
    browser's page or from the page's HTML as text."""
    if isinstance(page, str):
        return json.loads(re.search(rf'<script type="application/json" class="{name}">(.*?)</script>', page).group(1))
    return json.loads(page.locator(f"script.{name}").text_content())


def stored(page, key: str) -> str | None:
    """What the page's localStorage keeps under `key`, as the text stored."""
    return page.evaluate(f"localStorage.getItem({key!r})")


def load_progress_files(page, paths) -> None:
    """Give the class page progress files and wait until it has read them."""
    before = int(page.get_attribute(".cp", "data-loads"))
    page.get_by_label("Choose progress files").set_input_files([str(p) for p in paths])
    page.wait_for_function(f"document.querySelector('.cp').getAttribute('data-loads') > {before}")


def words(text: str) -> str:
    """Text with every run of spaces (no-break and narrow no-break among them) as one plain space."""
    return re.sub(r"\s+", " ", text).strip()


def readers_of(reader_class) -> Callable:
    """A fixture that opens readers of the site (reader_class(browser, base_url, ...)) as a
    test asks, and closes each at the end."""

    @pytest.fixture
    def reader(browser, base_url):
        with each_closed(functools.partial(reader_class, browser, base_url)) as open_reader:
            yield open_reader

    return reader
