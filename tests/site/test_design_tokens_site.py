"""The built site's colours come from physics_figures/style/tokens.json (issue 24, item 3); the
scan of the sources is tests/no_site/test_design_tokens.py."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
from offline import MANIFEST

from physics_figures.style import colour, names


@pytest.mark.site
def test_the_built_site_ships_every_site_colour(site_dir):
    """Every page's stylesheet (tokens.css at its head, pruned and minified) holds each
    site colour in light and dark, and the service worker precaches it."""
    bundles = _bundles(site_dir)
    assert bundles
    precached = (site_dir / "sw.js").read_text(encoding="utf-8")
    for bundle in bundles:
        stylesheet = bundle.read_text(encoding="utf-8")
        light = _declared(stylesheet, ":root")
        dark = _declared(stylesheet, 'html[data-theme="dark"]') | _declared(stylesheet, "html[data-theme=dark]")
        for name in names("site"):
            assert _same(light.get(f"--{name}", ""), colour(f"site.{name}")), (bundle.name, name, "light")
            if colour(f"site.{name}", "dark") != colour(f"site.{name}"):
                assert _same(dark.get(f"--{name}", ""), colour(f"site.{name}", "dark")), (bundle.name, name)
        assert bundle.relative_to(site_dir).as_posix() in precached


@pytest.mark.site
def test_the_built_site_shows_the_blue_of_the_manifest(site_dir):
    """The theme's primary colour (links, header) in the built CSS is the token the
    manifest's theme_color reads; the manifest says so too."""
    for bundle in _bundles(site_dir):
        stylesheet = bundle.read_text(encoding="utf-8")
        light = _declared(stylesheet, "html[data-theme=light]") | _declared(stylesheet, 'html[data-theme="light"]')
        dark = _declared(stylesheet, "html[data-theme=dark]") | _declared(stylesheet, 'html[data-theme="dark"]')
        assert _same(light["--pst-color-primary"], colour("theme.link"))
        assert _same(dark["--pst-color-primary"], colour("theme.link", "dark"))
        assert _same(light["--pst-color-background"], colour("theme.background"))
    manifest = json.loads((site_dir / MANIFEST).read_text(encoding="utf-8"))
    assert manifest["theme_color"] == colour("theme.link")


def _bundles(site: Path) -> list[Path]:
    linked = set()
    for page in site.rglob("*.html"):
        linked.update(re.findall(r"_static/site-assets/bundle-[0-9a-f]{12}\.css", page.read_text(encoding="utf-8")))
    return [site / name for name in sorted(linked)]


def _declared(stylesheet: str, selector: str) -> dict[str, str]:
    """Custom properties of the rules whose selector list is exactly `selector`."""
    found = {}
    for selectors, body in re.findall(r"([^{}]+)\{([^{}]*)\}", stylesheet):
        if selectors.strip() == selector:
            found.update(re.findall(r"(--[\w-]+):\s*([^;]+)", body))
    return found


def _same(css_value: str, token: str) -> bool:
    """csso writes a six-digit hex colour in its three-digit form when it can, and rgba()'s 0.25 as .25."""
    def normal(value: str) -> str:
        value = re.sub(r"\s+|(?<![\d])0(?=\.)", "", value.lower())
        return re.sub(r"^#(.)(.)(.)$", r"#\1\1\2\2\3\3", value)
    return normal(css_value) == normal(token)
