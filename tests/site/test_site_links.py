"""Every internal link and anchor of the built site resolves (a check of the HTML alone).

External links are listed, and fetched only when CHECK_EXTERNAL_LINKS=1 (CI is offline),
so a site with external links still passes offline and can be checked on a network.
"""

from __future__ import annotations

import os
import urllib.request
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import unquote, urljoin, urlsplit

import pytest

pytestmark = [pytest.mark.site]

BASE = "http://site.invalid/"  # a stand-in origin to resolve relative links against


class _Links(HTMLParser):
    """The ids a page defines and the URLs it points to (href and src)."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.ids: set[str] = set()
        self.urls: list[tuple[str, str]] = []  # (tag, url)

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        for name in ("id", "name"):
            if attrs.get(name) and (name == "id" or tag == "a"):
                self.ids.add(attrs[name])
        for name in ("href", "src", "xlink:href"):
            if attrs.get(name) and not (tag == "use" and attrs[name].startswith("#")):
                self.urls.append((tag, attrs[name]))


def _parse(path: Path) -> _Links:
    parser = _Links()
    parser.feed(path.read_text(encoding="utf-8"))
    return parser


@pytest.fixture(scope="module")
def site_links(site_dir):
    return {path: _parse(path) for path in site_dir.rglob("*.html") if "_static" not in path.parts}


def _classify(site_dir: Path, page: Path, url: str):
    """('internal', file, fragment), ('external', url, None) or ('other', url, None)."""
    if url.startswith(("mailto:", "tel:", "data:", "javascript:")):
        return "other", url, None
    resolved = urljoin(BASE + page.relative_to(site_dir).as_posix(), url)
    if not resolved.startswith(BASE):
        return "external", url, None
    parts = urlsplit(resolved)
    target = site_dir / unquote(parts.path[len(urlsplit(BASE).path):])
    if target.is_dir():
        target = target / "index.html"
    return "internal", target, unquote(parts.fragment)


def test_every_internal_link_and_anchor_resolves(site_dir, site_links):
    broken = []
    for page, links in sorted(site_links.items()):
        for tag, url in links.urls:
            kind, target, fragment = _classify(site_dir, page, url)
            if kind != "internal":
                continue
            where = f"{page.relative_to(site_dir)}: <{tag}> {url}"
            if not target.exists():
                broken.append(f"{where} -> no file {target.relative_to(site_dir)}")
            elif fragment and target.suffix == ".html":
                ids = site_links[target].ids if target in site_links else _parse(target).ids
                if fragment not in ids:
                    broken.append(f"{where} -> no id {fragment!r} in {target.relative_to(site_dir)}")
    assert not broken, "links that go nowhere:\n" + "\n".join(broken)


def test_external_links_listed_and_checked_on_request(site_dir, site_links, capsys):
    external = sorted(
        {url for page, links in site_links.items() for _, url in links.urls if _classify(site_dir, page, url)[0] == "external"}
    )
    with capsys.disabled():
        print(f"\n{len(external)} external link(s) in the site" + "".join(f"\n  {url}" for url in external))
    if os.environ.get("CHECK_EXTERNAL_LINKS") != "1":
        return
    dead = []
    for url in external:
        try:
            request = urllib.request.Request(url, method="HEAD", headers={"User-Agent": "link-check"})
            urllib.request.urlopen(request, timeout=20)
        except (OSError, ValueError) as error:  # URLError and HTTPError are OSErrors
            dead.append(f"{url}: {error}")
    assert not dead, "external links that fail:\n" + "\n".join(dead)
