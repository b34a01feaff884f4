"""Your practice: what a student has done with the bank's templates, by question type::

    ```{practice-progress}
    ```

The build writes every type with its templates, their marks and the page that places
each; static/progress.js adds the attempts this browser keeps (questions.js records them).
Without JavaScript, and in print, the page still lists and links each type's questions.
"""

from __future__ import annotations

import json
from html import escape

from docutils import nodes
from fresh_figures import uses_modules  # book/_ext: re-read a page when its modules change
from notation import add_notation_script  # book/_ext/notation: the browser's number writer
from sphinx.util.docutils import SphinxDirective

from . import store


class practice_progress(nodes.General, nodes.Element):
    """The student's progress by question type: filled, once every page is read, with the
    bank's templates and the page that places each (HTML); a note elsewhere."""


class PracticeProgressDirective(SphinxDirective):
    """Where the student's progress goes (the page's own text says what it is for)."""

    def run(self):
        store.docs(self.env, "practice-progress").add(self.env.docname)
        uses_modules(self.env, *store.bank_modules(self.config))
        return [practice_progress()]


def book_types(config) -> list[tuple]:
    """Each question type of the book's topics (its QuestionType) with its templates' entries:
    key, title and marks. Your practice and the class page read these; no physics."""
    return [(kind, [{"key": t.key, "title": t.title, "marks": t.variant(0).marks} for t in topic.by_type(kind.key)])
            for topic in store.topics(config) for kind in topic.types]


def _progress_data(app, fromdoc: str) -> dict:
    """Every template of the book's topics by type (each type's title and method page as its
    topic declares them), with its title, marks and the page placing it (None if no page
    does yet), and the book's id, which an export carries: what progress.js needs; it
    computes no physics."""
    env, placed = app.env, {}
    for docname in store.book_order(env, app.config.root_doc):
        for key in store.templates_used(env).get(docname, []):
            placed.setdefault(key, docname)
    types = []
    for kind, entries in book_types(app.config):
        templates = [{**entry, "page": app.builder.get_relative_uri(fromdoc, placed[entry["key"]])
                      if entry["key"] in placed else None} for entry in entries]
        method = app.builder.get_relative_uri(fromdoc, kind.method) if kind.method in env.all_docs else None
        types.append({"type": kind.key, "name": kind.title, "templates": templates, "method": method})
    return {"book": store.book_id(app.config), "types": types}


NEEDS_BROWSER = ("Your practice is kept in the web browser you practise in: open this page in the "
                 "web version of the book, with JavaScript on, to see it.")


def visit_practice_progress(self, node):
    """Without JavaScript (and in print) the page still lists each type's questions and
    links to them; progress.js adds what this browser has kept."""
    data = node["data"]
    payload = json.dumps(data, ensure_ascii=False).replace("</", "<\\/")
    html = ['<div class="pp">', f'<script type="application/json" class="pp-data">{payload}</script>',
            f'<p class="pp-needs-js">{escape(NEEDS_BROWSER)}</p>']
    for kind in data["types"]:
        ident, name = f"pp-type-{kind['type']}", escape(kind["name"])
        placed = [t for t in kind["templates"] if t["page"]]
        html.append(f'<section class="pp-type" data-type="{kind["type"]}" aria-labelledby="{ident}">'
                    f'<h2 id="{ident}">{name}</h2>')
        if kind["templates"]:
            summary = store.count(len(kind["templates"]), "question", "questions") + " in the bank."
        else:
            summary = "Not in the bank yet: no question of this type to practise here so far."
        html.append(f'<p class="pp-summary">{summary}</p><p class="pp-mistakes" hidden></p>')
        if kind["templates"]:
            html.append('<ul class="pp-templates">')
            for t in kind["templates"]:
                title = escape(t["title"])
                link = f'<a href="{escape(t["page"])}#question-{escape(t["key"])}">{title}</a>' if t["page"] else title
                html.append(f'<li data-key="{escape(t["key"])}">{link} '
                            f'<span class="pp-marks">({store.count(t["marks"], "mark", "marks")})</span></li>')
            html.append("</ul>")
        actions = []
        if placed:
            first = placed[0]
            actions.append(f'<a class="pp-practise" href="{escape(first["page"])}#question-{escape(first["key"])}">'
                           f'Practise this type<span class="pp-hidden-text">: {name}</span></a>')
        if kind["method"]:
            actions.append(f'<a class="pp-method" href="{escape(kind["method"])}">The method for this type'
                           f'<span class="pp-hidden-text">: {name}</span></a>')
        if actions:
            html.append(f'<p class="pp-actions">{" ".join(actions)}</p>')
        html.append("</section>")
    html.append(
        '<section class="pp-file" aria-labelledby="pp-file-heading" hidden>'
        '<h2 id="pp-file-heading">Move or clear your progress</h2>'
        "<p>Export saves your progress to a file. Import it in the browser of another device (or "
        "this one) to add it to what is kept there: nothing already kept is lost.</p>"
        '<div class="pp-buttons">'
        '<button type="button" class="pp-export">Export progress</button>'
        '<label class="pp-import-label" for="pp-import">Import progress from a file'
        '<input type="file" id="pp-import" class="pp-import" accept=".json,application/json"></label>'
        '<button type="button" class="pp-clear">Clear progress</button>'
        '<button type="button" class="pp-undo" hidden>Undo clear</button></div>'
        '<p class="pp-status" role="status" aria-live="polite"></p></section></div>\n')
    self.body.append("".join(html))
    raise nodes.SkipNode


def fill(app, doctree, docname):
    for progress in list(doctree.findall(practice_progress)):
        if app.builder.format == "html":
            progress["data"] = _progress_data(app, docname)
        else:  # print: the page's text says what it is for; this says where it works
            progress.replace_self(nodes.paragraph(text=NEEDS_BROWSER))


def add_assets(app, pagename, templatename, context, doctree):
    if pagename in store.docs(app.env, "practice-progress"):
        app.add_css_file("progress.css")
        add_notation_script(app)
        app.add_js_file("progress-file.js", loading_method="defer")  # what Export writes
        app.add_js_file("progress.js", loading_method="defer")


def setup(app):
    app.add_node(practice_progress, html=(visit_practice_progress, None))
    app.add_directive("practice-progress", PracticeProgressDirective)
    app.connect("html-page-context", add_assets)
