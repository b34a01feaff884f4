"""Worked-example solutions that open from their whole header, named for what they open.

sphinx-exercise titles a solution "Solution to Exercise 2 (…)" with most of the title a
link back to the question, and sphinx-togglebutton adds a small chevron button that a
screen reader hears as "Toggle hidden content". ``solution-toggles.js`` turns the header
into the one toggle: togglebutton's own button, stretched over the whole header and named
"Show the solution to Example 2" (the page's example number), "Hide …" once open. Without
JavaScript, and in print, the solution is shown as it is.
"""

from __future__ import annotations

from pathlib import Path

from sphinx.application import Sphinx

STATIC = Path(__file__).parent / "static"


def _add_static_path(app: Sphinx) -> None:
    app.config.html_static_path.append(str(STATIC))


def _add_page_assets(app: Sphinx, pagename: str, templatename: str, context, doctree) -> None:
    """Only pages with a dropdown solution load the script (after togglebutton.js)."""
    if 'class="solution dropdown' in context.get("body", ""):
        app.add_js_file("solution-toggles.js", loading_method="defer", priority=800)
        app.add_css_file("solution-toggles.css")


def setup(app: Sphinx):
    app.connect("builder-inited", _add_static_path)
    app.connect("html-page-context", _add_page_assets)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
