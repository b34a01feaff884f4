"""In the built site every figure is numbered, has its alt text and caption, and is
referred to from the text (needs the built site: `make test` builds it first)."""

import re

import pytest

from physics_figures import scenarios
from physics_figures.figures import book

pytestmark = [pytest.mark.site]

FIGURE = re.compile(
    r'<figure class="physics-figure[^"]*" id="(?P<name>[^"]+)">\s*'
    r'<img alt="(?P<alt>[^"]*)" class="dark-light" src="(?P<src>[^"]+\.svg)"[^>]*>\s*'
    r'<figcaption>\s*<p><span class="caption-number">Fig\. [\d.]+ </span>'
)


def _figures(site_dir):
    found = {}
    for page in (site_dir / "book").rglob("*.html"):
        html = page.read_text()
        for match in FIGURE.finditer(html):
            found[match["name"]] = (html, match)
    return found


def test_every_figure_is_numbered_with_alt_text_and_referenced(site_dir):
    found = _figures(site_dir)
    assert len(found) >= 10
    for name, (html, match) in found.items():
        assert len(match["alt"]) > 80, name
        # a {numref} link from the text, besides the caption's own permalink
        references = re.findall(rf'<a class="reference internal" href="[^"]*#{name}">', html)
        assert references, f"{name} is not referred to from the text"


def test_the_site_shows_the_alt_text_the_module_writes(site_dir):
    _, match = _figures(site_dir)["fig-skydiver-velocity-time"]
    assert match["alt"] == book.skydiver_velocity_time(scenarios.SKYDIVER).alt
