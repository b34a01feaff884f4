"""Every file of the built site is one something uses: a page names it (href, src), a
stylesheet names it (url()), a script or the web app manifest names it in a string, the
service worker keeps it, or a server is asked for it by name (index.html, robots.txt, the
service worker...). Source maps, unused locales, fontawesome.js and stylesheets already
bundled are removed by the build (book/_ext/offline)."""

from __future__ import annotations

import re

import offline
import pytest
from conftest import ROOT

pytestmark = pytest.mark.site

def test_every_file_of_the_site_is_referenced(site_dir):
    unused = offline.unreferenced_files(site_dir)
    assert not unused, f"{len(unused)} file(s) that nothing references: {unused[:20]}"


def test_no_source_map_locale_or_unused_icon_script_is_shipped(site_dir):
    files = [p.relative_to(site_dir).as_posix() for p in site_dir.rglob("*") if p.is_file()]
    assert not [f for f in files if f.endswith((".map", "fontawesome.js")) or "/locales/" in f]


def test_a_file_nothing_names_is_found(site_dir, tmp_path):
    """The check can fail: a stray file in a copy of the site is reported, by name."""
    stray = tmp_path / "site" / "_static" / "stray.js"
    stray.parent.mkdir(parents=True)
    (tmp_path / "site" / "index.html").write_text('<script src="_static/used.js"></script>', encoding="utf-8")
    (tmp_path / "site" / "_static" / "used.js").write_text("1", encoding="utf-8")
    stray.write_text("2", encoding="utf-8")
    assert offline.unreferenced_files(tmp_path / "site") == ["_static/stray.js"]


def _pages(site_dir):
    return {p.relative_to(site_dir).as_posix(): p.read_text(encoding="utf-8")
            for p in site_dir.rglob("*.html") if "_static" not in p.parts}


def test_no_page_needs_bootstrap_s_javascript(site_dir):
    """The pages load the theme's scripts without bootstrap.js (book/_templates/layout.html):
    no page may hold a Bootstrap widget that only its JavaScript works (a dropdown, a collapse,
    a modal...); hover tooltips fall back to the buttons' titles."""
    widgets = re.compile(r'data-bs-toggle="(?!tooltip")[^"]*"')
    needing = {name: widgets.findall(text) for name, text in _pages(site_dir).items()}
    assert not {name: found for name, found in needing.items() if found}
    assert not [name for name, text in _pages(site_dir).items() if "bootstrap.js" in text]


def test_the_site_s_own_scripts_are_shipped_minified(site_dir):
    """The explorables', the questions' and the other own scripts are minified in the site
    (terser, book/_ext/site_assets/minify-js.js): one line, fewer bytes than the source. A script
    a page runs comes inside its kind of page's bundle (site_assets/scripts.py), each script there
    after a comment that names it; one loaded by name stays a file of its own."""
    bundled = {}
    for bundle in (site_dir / "_static" / "site-assets").glob("scripts-*.js"):
        parts = re.split(r"^/\* (_static/\S+) \*/\n", bundle.read_text(encoding="utf-8"), flags=re.MULTILINE)
        bundled.update({name: text.strip().removesuffix(";").strip() for name, text in zip(parts[1::2], parts[2::2], strict=True)})
    shipped = 0
    for static in (ROOT / "book" / "_ext").glob("*/static"):
        for source in static.rglob("*.js"):
            name = f"_static/{source.relative_to(static).as_posix()}"
            assert name in bundled or (site_dir / name).is_file(), f"{name} is in no bundle and not in the site"
            text = bundled.get(name) or (site_dir / name).read_text(encoding="utf-8")
            assert text.count("\n") <= 1 and len(text) < len(source.read_text(encoding="utf-8")), source
            shipped += 1
    assert shipped >= 10


def test_no_page_title_repeats_the_book_s_title(site_dir):
    """A tab reads "Page — Dynamics", and the landing page, whose title is the book's, reads
    "Dynamics" once (it read "Dynamics — Dynamics")."""
    repeated = {}
    for name, text in _pages(site_dir).items():
        found = re.search(r"<title>(.*?)</title>", text, re.DOTALL)
        if not found:
            continue
        title = found.group(1).replace("&#8212;", "—").strip()
        parts = [part.strip() for part in title.split("—")]
        if len(parts) != len(set(parts)):
            repeated[name] = title
    assert not repeated, repeated
    intro = re.search(r"<title>(.*?)</title>", _pages(site_dir)["book/intro.html"], re.DOTALL).group(1)
    assert intro.strip() == "Dynamics"


def test_each_worked_example_is_labelled_as_its_page_s_example(site_dir):
    """The question of book/exam/example-N is "Example N" (sphinx-exercise's numfig_format,
    _config.yml), and its solution "Solution to Example N", never "Exercise"."""
    pages = _pages(site_dir)
    examples = sorted(name for name in pages if re.fullmatch(r"book/exam/example-\d+\.html", name))
    assert len(examples) >= 5
    for name in examples:
        number = re.search(r"example-(\d+)", name).group(1)
        text = re.sub(r"<[^>]+>", "", pages[name])
        assert "Exercise" not in text, name
        assert f"Example {number} " in text and f"Solution to Example {number} " in text, name
