"""The site_assets extension in a real build (a one-page copy of the project, as
tests/build/test_build.py makes): an edit to a stylesheet alone reaches the built site.

Sphinx copies static files only when it writes some page, so a change to
_static/site.css and nothing else used to leave the site (and its one-stylesheet
bundle) as it was. This runs Sphinx builds, like tests/build/test_build.py.
"""

from __future__ import annotations

import os
import subprocess

import pytest
from test_build import VENV, make_book

pytestmark = [pytest.mark.build]


def rebuild(project):
    """`make html` again, the page untouched (make_book rewrites it, which rebuilds it)."""
    return subprocess.run(
        ["make", "--no-print-directory", "-o", f"{VENV}/.installed", "-o", "node_modules/.package-lock.json",
         "html", f"VENV={VENV}"],
        cwd=project, check=False, capture_output=True, text=True, env=dict(os.environ), timeout=300,
    )


def _bundle_text(project) -> str:
    bundles = (project / "_build" / "html" / "_static" / "site-assets").glob("bundle-*.css")
    return "\n".join(path.read_text() for path in bundles)


def test_a_stylesheet_edit_alone_reaches_the_site(tmp_path):
    page = "# Title\n\nSome text.\n"
    first = make_book(tmp_path, page)
    assert first.returncode == 0, first.stdout[-3000:]
    # on an element every page has, so the pruned bundle keeps it; a real property with
    # an odd value, as unused custom properties are pruned and the bundle is minified
    rule, mark = "p { word-spacing: 0.0137em; }", ".0137em"
    assert mark not in _bundle_text(tmp_path)

    with (tmp_path / "_static" / "site.css").open("a") as css:
        css.write(f"\n{rule}\n")
    second = rebuild(tmp_path)
    assert second.returncode == 0, second.stdout[-3000:]
    assert mark in _bundle_text(tmp_path), "the stylesheet bundle pages link was not rebuilt"

    third = rebuild(tmp_path)  # nothing changed since: nothing is rewritten
    assert third.returncode == 0, third.stdout[-3000:]
    assert "no targets are out of date" in third.stdout, third.stdout[-2000:]
