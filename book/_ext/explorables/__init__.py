"""The ``explorable`` directive: interactive figures that run in the reader's browser.

    ```{explorable} skydiver
    ```

puts a hidden container on the page with the scenario's data from
``physics_figures.explorables`` serialised as JSON; the page's own scripts (shipped
in ``static/explorables/``, no CDN) reveal it and build the controls and graphs.
Only pages that use an explorable load those scripts. Without JavaScript, and in
print, the explorable stays hidden and the static figure next to it is what the
reader sees; the LaTeX/PDF builders drop it (raw HTML).
"""

from __future__ import annotations

import html
import json
from pathlib import Path

from docutils import nodes
from fresh_figures import uses_modules  # book/_ext: re-read a page when its modules change
from notation import add_notation_script  # book/_ext/notation: the browser's number writer
from sphinx import addnodes
from sphinx.application import Sphinx
from sphinx.util.docutils import SphinxDirective

from physics_figures.explorables import ABOUT, EXPLORABLES, explorable_data

STATIC = Path(__file__).parent / "static"
#: What each explorable is and shows, for readers who meet it on paper (the book PDF) and for
#: the list on the landing page: (name, what it shows), a sentence each.
DESCRIPTIONS = {
    "skydiver": (
        "The skydiver explorer",
        ("it draws a skydiver's velocity\u2013time and resultant force\u2013time graphs, with points "
         "A to E, as you change her mass, the drag constants of body and parachute, when the "
         "parachute opens and how long it takes to open")),
    "collision-lab": (
        "The collision lab",
        ("it collides two trolleys, or pushes them apart from rest, with the masses, velocities "
         "and loss of kinetic energy you choose, and shows that momentum is conserved while "
         "kinetic energy may not be")),
    "momentum-triangle": (
        "The momentum triangle",
        ("it draws the momenta of two pucks before and after a collision as a closed triangle "
         "of vectors, as you change the momentum and angle of P after it")),
    "momentum-time-reader": (
        "The momentum\u2013time reader",
        ("it reads a car's momentum\u2013time graph at any time you choose, with the gradient, "
         "which is the resultant force")),
}

# Loaded on every page with an explorable, before the explorable's own script (announce.js
# after ui.js, which it extends).
SHARED_SCRIPTS = ("explorables/models.js", "explorables/ui.js", "explorables/announce.js")


class ExplorableDirective(SphinxDirective):
    """``{explorable} <name>``: one of physics_figures.explorables.EXPLORABLES."""

    required_arguments = 1
    has_content = False

    def run(self) -> list[nodes.Node]:
        name = self.arguments[0]
        if name not in EXPLORABLES:
            raise self.error(f"unknown explorable {name!r}: choose one of {', '.join(EXPLORABLES)}")
        # "</" could close the script element early, so it is escaped inside the JSON.
        data = json.dumps(explorable_data(name), separators=(",", ":")).replace("</", "<\\/")
        # What it models: ui.js moves it under the explorable's title and points the explorable's
        # aria-describedby at it (the id is unique even with two of one explorable on a page).
        about_id = f"ex-about-{html.escape(name)}-{self.env.new_serialno('explorable-about')}"
        markup = (
            f'<div class="explorable" data-explorable="{html.escape(name)}" hidden>'
            f'<p class="ex-hint ex-about" id="{about_id}">{html.escape(ABOUT[name])}</p>'
            f'<script type="application/json" class="explorable-data">{data}</script></div>'
        )
        self.env.explorables_by_doc.setdefault(self.env.docname, set()).add(name)
        uses_modules(self.env, "physics_figures.explorables")
        return [nodes.raw("", markup, format="html"), self._on_paper(name)]

    def _on_paper(self, name: str) -> nodes.Node:
        """Print and PDF: a sentence saying what the explorable shows and on which page of the
        web version it is (no site address is fixed, so the page is named)."""
        title, shows = DESCRIPTIONS[name]
        heading = self.state.document.next_node(nodes.title)
        page = heading.astext() if heading is not None else self.env.docname
        text = (f"{title} (in the web version of this book, on the page “{page}”): {shows}.")
        only = addnodes.only(expr="not html")
        only += nodes.paragraph(text=text, classes=["explorable-on-paper"])
        return only


def _init_env(app: Sphinx, env, docnames) -> None:
    if not hasattr(env, "explorables_by_doc"):
        env.explorables_by_doc = {}


def _purge_doc(app: Sphinx, env, docname: str) -> None:
    getattr(env, "explorables_by_doc", {}).pop(docname, None)


def _merge(app: Sphinx, env, docnames, other) -> None:
    for docname in docnames:
        if docname in other.explorables_by_doc:
            env.explorables_by_doc[docname] = other.explorables_by_doc[docname]


def _add_static_path(app: Sphinx) -> None:
    app.config.html_static_path.append(str(STATIC))


def _add_page_assets(app: Sphinx, pagename: str, templatename: str, context, doctree) -> None:
    """Scripts and styles only for pages that show an explorable (Sphinx >= 3.5 per page)."""
    names = getattr(app.env, "explorables_by_doc", {}).get(pagename)
    if not names:
        return
    app.add_css_file("explorables/explorables.css")
    add_notation_script(app)  # ui.js writes every read-out and tick with it
    for script in SHARED_SCRIPTS:
        app.add_js_file(script, loading_method="defer")
    for name in sorted(names):
        app.add_js_file(f"explorables/{name}.js", loading_method="defer")


def setup(app: Sphinx):
    app.add_directive("explorable", ExplorableDirective)
    app.connect("env-before-read-docs", _init_env)
    app.connect("env-purge-doc", _purge_doc)
    app.connect("env-merge-info", _merge)
    app.connect("builder-inited", _add_static_path)
    app.connect("html-page-context", _add_page_assets)
    # env_version 2: pages load announce.js and carry the "what it models" paragraph (issue 28),
    # so a build from an older cache re-reads them rather than keep pages without either
    return {"parallel_read_safe": True, "parallel_write_safe": True, "env_version": 2}
