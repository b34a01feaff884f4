"""The class at a glance: a teacher loads the students' exported progress files::

    ```{class-progress}
    ```

The build writes the book's id and every question type with its templates (key, title,
marks; progress.book_types, as Your practice has them); static/class-table.js reads the
files in the browser (static/class.js shows them), refuses what is not this book's or was
edited (progress-file.js), reads an export from before the checksum as "older export, not checked", and shows
marks and attempts per student and per type, the class's mistakes and each question's share
of full marks. Nothing is uploaded. Without JavaScript, and in print, the page says where it
works.
"""

from __future__ import annotations

import json
from html import escape

from docutils import nodes
from fresh_figures import uses_modules  # book/_ext: re-read the page when the bank changes
from notation import add_notation_script
from sphinx.util.docutils import SphinxDirective

from . import schedule, store
from .progress import book_types

DIRECTIVE = "class-progress"
NEEDS_BROWSER = ("The class page reads your students' progress files in your web browser: open it in the web "
                 "version of the book, with JavaScript on, to use it.")


class class_progress(nodes.General, nodes.Element):
    """Where the class's progress shows (HTML); a note elsewhere."""


class ClassProgressDirective(SphinxDirective):
    def run(self):
        store.docs(self.env, DIRECTIVE).add(self.env.docname)
        uses_modules(self.env, *store.bank_modules(self.config))
        types = [{"type": kind.key, "name": kind.title, "templates": entries}
                 for kind, entries in book_types(self.config)]
        return [class_progress(data={"book": store.book_id(self.config), "types": types})]


#: The page's controls and the places class.js fills (hidden until it runs: without
#: JavaScript only the note shows).
PAGE = """\
<div class="cp"><script type="application/json" class="cp-data">{payload}</script>
<p class="cp-needs-js">{needs}</p>
<section class="cp-load" aria-labelledby="cp-load-heading" hidden>
<h2 id="cp-load-heading">Load the progress files</h2>
<div class="cp-drop"><p class="cp-drop-text">Drop the students' progress files anywhere on this page, or choose
them (several at once).</p>
<label class="cp-choose-label" for="cp-choose">Choose progress files<input type="file" id="cp-choose"
 class="cp-choose" accept=".json,application/json" multiple></label></div>
<p class="cp-status" role="status" aria-live="polite"></p>
<ul class="cp-refused" aria-label="Files refused" hidden></ul>
</section>
<div class="cp-results" hidden>
<h2 id="cp-table-heading">Marks and attempts</h2>
<ul class="cp-notes" aria-label="Notes on the files" hidden></ul>
<div class="cp-buttons"><button type="button" class="cp-csv">Download CSV</button>
<button type="button" class="cp-clear">Clear the class</button></div>
<div class="cp-scroll" role="region" aria-labelledby="cp-table-heading" tabindex="0"><table class="cp-table"></table></div>
<h2 id="cp-mistakes-heading">The class's most frequent mistakes</h2>
<p class="cp-no-mistakes" hidden>No named mistakes in these files.</p>
<ol class="cp-mistakes" aria-labelledby="cp-mistakes-heading"></ol>
<h2 id="cp-questions-heading">Each question's share of full marks</h2>
<div class="cp-scroll" role="region" aria-labelledby="cp-questions-heading" tabindex="0"><table class="cp-questions">
</table></div>
<p class="cp-untried"></p>
</div></div>
"""


def visit_class_progress(self, node):
    payload = json.dumps(node["data"], ensure_ascii=False).replace("</", "<\\/")
    self.body.append(PAGE.format(payload=payload, needs=escape(NEEDS_BROWSER)))
    raise nodes.SkipNode


def fill(app, doctree, docname):
    """Outside HTML the page's text says what it is for; this says where it works."""
    if app.builder.format != "html":
        for node in list(doctree.findall(class_progress)):
            node.replace_self(nodes.paragraph(text=NEEDS_BROWSER))


def add_assets(app, pagename, templatename, context, doctree):
    if pagename in store.docs(app.env, DIRECTIVE):
        app.add_css_file("class.css")
        add_notation_script(app)
        schedule.add_store_script(app)  # reads a file of format 1 or 2
        # each uses the ones before: class-table.js reads the files, class.js shows the page
        for script in ("progress-file.js", "progress.js", "class-table.js", "class.js"):
            app.add_js_file(script, loading_method="defer")


def setup(app):
    app.add_node(class_progress, html=(visit_class_progress, None))
    app.add_directive(DIRECTIVE, ClassProgressDirective)
    app.connect("doctree-resolved", fill)
    app.connect("html-page-context", add_assets)
