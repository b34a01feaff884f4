"""What each page gets as it is written: its meta description, named toggles, deferred
scripts, one bundled stylesheet, and the scripts and styles only where they are needed."""

from __future__ import annotations

import html
import re
from pathlib import Path
from typing import Any

from sphinx.application import Sphinx
from sphinx.util import logging

logger = logging.getLogger(__name__)

from .icons import theme_dirs
from .image_sizes import sized_images
from .scripts import bundle_page_scripts
from .stylesheets import THEME_CSS, bundle_name


def _first_paragraph(body: str, limit: int = 155) -> str:
    for paragraph in re.findall(r"<p>(.*?)</p>", body, flags=re.DOTALL):
        # Maths: keep the MathML's text only would be odd, so drop it; the words stay.
        text = re.sub(r'<svg.*?</svg>|<span class="math-mathml">.*?</span>', "", paragraph, flags=re.DOTALL)
        text = html.unescape(re.sub(r"<[^>]+>", "", text))
        text = " ".join(text.split())
        if len(text) >= 40:
            return text if len(text) <= limit else text[: limit - 1].rsplit(" ", 1)[0] + "…"
    return ""


# Pages Sphinx writes with no text of their own to describe them.
GENERATED_PAGE_DESCRIPTIONS = {
    "search": "Search {title}: every page of the notes, the worked examples, the exam methods and the questions.",
}


def theme_digest() -> str:
    """The cache-busting digest the theme appends to its own CSS and JS links."""
    macros = (theme_dirs()[0] / "static" / "webpack-macros.html").read_text()
    return re.search(r"\?digest=([0-9a-f]+)", macros)[1]


def _name_toggles(toctree):
    """Give each expand/collapse toggle of the navigation a name (axe: summary-name).

    `toctree` is the theme's parsed navigation (BeautifulSoup); changed in place.
    """
    for details in toctree.select("li > details") if hasattr(toctree, "select") else []:
        link = details.parent.find("a")
        summary = details.find("summary")
        if link is not None and summary is not None:
            summary["aria-label"] = f"Sections of {' '.join(link.get_text().split())}"
    return toctree


#: Scripts of the theme's extensions, and what a page's body must hold to need each.
_CODE = re.compile(r'class="highlight')
ONLY_WHERE_NEEDED = {
    "clipboard.min.js": _CODE,
    "copybutton.js": _CODE,
    "design-tabs.js": re.compile(r"sd-tab-set"),
    "togglebutton.js": re.compile(r'class="(?:[^"]*\s)?(?:toggle|dropdown)(?:\s[^"]*)?"'),
}


#: Loaded by static/search-highlight.js only when a search result opens the page.
ON_DEMAND = ("doctools.js", "sphinx_highlight.js")


def add_page_context(app: Sphinx, pagename: str, templatename: str, context: dict[str, Any], doctree) -> None:
    # Thebe runs code on a remote Binder kernel: not used here, and sphinx-thebe adds its
    # config script twice (a console error). Drop its scripts and stylesheet.
    context["script_files"] = [
        js for js in context.get("script_files", [])
        if "thebe" not in (js.filename or "").lower() and "THEBE" not in js.attributes.get("body", "")
    ]
    # Only the scripts a page needs: a copy button only where there is code to copy, tabs
    # only where there are tabs, the toggle script only where something toggles.
    body = context.get("body", "")
    context["script_files"] = [
        js for js in context["script_files"]
        if not (need := ONLY_WHERE_NEEDED.get(Path((js.filename or "").split("?")[0]).name)) or need.search(body)
    ]
    # Sphinx's doctools and search highlighter only matter on the search page and on a page
    # opened from a result (?highlight=): search-highlight.js loads them then (3.6 kB gzip off
    # every first visit).
    if pagename != "search":
        context["script_files"] = [js for js in context["script_files"]
                                   if Path((js.filename or "").split("?")[0]).name not in ON_DEMAND]
    stylesheets = [css for css in context.get("css_files", []) if "thebe" not in css.filename]
    # One stylesheet for the screen: the theme's, then every extension's, in their order.
    screen = [css for css in stylesheets if css.attributes.get("media", "all") in ("all", "screen")
              and "://" not in css.filename and css.attributes.get("rel", "stylesheet") == "stylesheet"]
    bundled = THEME_CSS + [css.filename.split("?")[0] for css in screen]
    name = bundle_name(bundled)
    app._site_bundles[name] = bundled
    context["site_css_bundle"] = name
    context["css_files"] = [css for css in stylesheets if css not in screen]
    # Scripts never block the first paint: all run after parsing, in order. Only
    # documentation_options.js stays synchronous (inline scripts in the head use it).
    for js in context["script_files"]:
        if js.filename and "documentation_options" not in js.filename and "async" not in js.attributes:
            js.attributes.setdefault("defer", "defer")
    # ... and come in one file: the page's kind's bundle (scripts.py)
    bundle_page_scripts(app, context)
    context["site_theme_digest"] = app._site_theme_digest
    # myst-nb labels its "Show code cell source" toggles "Toggle hidden content": a name
    # that hides the visible text (axe: label-content-name-mismatch). The text is the name.
    if "body" in context:
        context["body"] = context["body"].replace('<summary aria-label="Toggle hidden content">', "<summary>")
        context["body"] = sized_images(context["body"], getattr(app.builder, "images", {}), Path(app.srcdir))
    if "generate_toctree_html" in context:
        generate = context["generate_toctree_html"]
        context["generate_toctree_html"] = lambda *args, **kwargs: _name_toggles(generate(*args, **kwargs))
    description = (
        _first_paragraph(context.get("body", ""))
        or GENERATED_PAGE_DESCRIPTIONS.get(pagename, "").format(title=app.config.html_title)
        or app.config.html_title
    )
    context["metatags"] = context.get("metatags", "") + (
        f'\n    <meta name="description" content="{html.escape(description, quote=True)}" />'
    )
