"""The timed mock test: Paper 1 or Paper 2 style, drawn fresh in the browser::

    ```{mock-test}
    ```

The page holds no question: it holds the index the draw reads (each template a data file
ships for, with its type, marks, part kinds and number of site variants; each type's title and
exam count) and the rule table the marking engine reads. static/mock-draw.js draws a test
(types weighted by exam count, with the sheet builder's draws, static/question-draw.js);
static/mock-test.js loads each drawn template's data file (_static/questions/KEY.js, by a
<script> element: variants.py writes its variants and its answer form), shows the forms with
their variants' words and numbers, keeps the answers and the clock in this browser, and marks
everything only at the end. Outside HTML the directive writes nothing: the page's own text
says what the test is.
"""

from __future__ import annotations

import json
from html import escape

from docutils import nodes
from fresh_figures import uses_modules  # book/_ext: re-read the page when the bank changes
from sphinx.util.docutils import SphinxDirective

from physics_figures.parts import KINDS

from . import form, store

DIRECTIVE = "mock-test"
NEEDS_BROWSER = ("The mock test runs in your web browser: open this page in the web version of the book, "
                 "with JavaScript on, to take one.")
#: What the setup says until its script has come and can start a test (Start the test is
#: disabled till then: a tap before would send the form and reload the page).
GETTING_READY = "Getting the test ready…"
#: The scripts the page runs, after the engine's (as a question's page loads them) and the
#: store that keeps the result (progress-store.js): the shared relabelling and draws, then the
#: page's own.
SCRIPTS = ("question-relabel.js", "question-draw.js", "mock-draw.js", "graph-view.js", "graph-cursor.js",
           "mock-questions.js", "mock-test.js")


class mock_test(nodes.General, nodes.Element):
    """The mock test's index and controls (HTML only)."""


class MockTestDirective(SphinxDirective):
    def run(self):
        store.docs(self.env, DIRECTIVE).add(self.env.docname)
        uses_modules(self.env, *store.bank_modules(self.config))
        return [mock_test()]


def mock_index(env, config) -> dict:
    """What the draw reads, from the templates the book's pages place (index_of)."""
    placed = {key for keys in store.templates_used(env).values() for key in keys}
    return index_of(store.topics(config), placed)


def mock_asks(template) -> bool:
    """A template a paper of the mock test can ask: its parts all of the kinds one paper asks
    (static/mock-draw.js, asks). An explanation is self-marked: no paper asks it."""
    papers = {KINDS[kind].mock_paper for kind in template.kinds}
    return len(papers) == 1 and "" not in papers


def index_of(topics, placed: set[str]) -> dict:
    """What the draw reads: every template of `placed` whose variants a data file ships (two or
    more site variants: variants.py), in the bank's order, with its type, marks, part kinds and
    number of site variants; and each type's title and exam count. No numbers of a question:
    those come with its data file."""
    types, templates = [], []
    for topic in topics:
        types += [{"key": kind.key, "title": kind.title, "examCount": kind.exam_count} for kind in topic.types]
        templates += [{"key": t.key, "type": t.type, "marks": t.variant(0).marks, "kinds": list(t.kinds),
                       "variants": len(t.site_variants)}
                      for t in topic.templates if t.key in placed and len(t.site_variants) >= 2 and not t.try_first]
    return {"types": types, "templates": templates}


def what_next_links(app, fromdoc: str) -> dict:
    """Where the result's "What next" sends a student, relative to fromdoc: each type's practice
    page (the page placing most of its templates, the first in the book on a tie, at its first
    question of the type) and method page, and Your practice."""
    env, config = app.env, app.config
    pages: dict[str, dict[str, list[str]]] = {}  # type -> page -> its templates of the type
    for docname in store.book_order(env, config.root_doc):
        for key in store.templates_used(env).get(docname, []):
            pages.setdefault(store.template(config, key).type, {}).setdefault(docname, []).append(key)
    uri = app.builder.get_relative_uri
    types = {}
    for topic in store.topics(config):
        for kind in topic.types:
            placed = pages.get(kind.key)
            if not placed:
                continue
            page = max(placed, key=lambda doc: len(placed[doc]))  # the first of the most: max keeps it
            types[kind.key] = {"practise": f"{uri(fromdoc, page)}#question-{placed[page][0]}",
                               "method": uri(fromdoc, kind.method) if kind.method in env.all_docs else None}
    practice = sorted(store.docs(env, "practice-progress"))
    return {"types": types, "practice": uri(fromdoc, practice[0]) if practice else None}


#: The controls (hidden until the script runs): the paper and length to choose, the clock and
#: Finish now (with its confirm step), the polite warnings, the questions, the result.
PAGE = """\
<div class="mock" data-enlarge="{enlarge}" data-unit-hint="{hint}">
{rules}
<script type="application/json" class="mock-index">{index}</script>
<p class="mock-needs-js">{needs}</p>
<form class="mock-setup" novalidate>
<fieldset class="mock-papers"><legend>Paper</legend>
<label class="mock-paper"><input type="radio" name="mock-paper" value="1" checked> Paper 1 style: multiple choice</label>
<label class="mock-paper"><input type="radio" name="mock-paper" value="2"> Paper 2 style: structured questions</label>
</fieldset>
<label class="mock-length" for="mock-size">Length <select id="mock-size" name="size"></select></label>
<div class="mock-buttons"><button type="submit" class="mock-start" disabled>Start the test</button></div>
<p class="mock-status" role="status">{getting_ready}</p>
</form>
<div class="mock-result" hidden tabindex="-1"></div>
<div class="mock-test" hidden>
<div class="mock-bar">
<p class="mock-clock"><span class="mock-clock-label">Time left</span> <span class="mock-time" role="timer"></span></p>
<button type="button" class="mock-finish">Finish now</button>
<div class="mock-confirm" hidden><p>Finish now? Your answers are marked and the test ends.</p>
<button type="button" class="mock-finish-yes">Yes, finish and mark</button>
<button type="button" class="mock-finish-no">Keep going</button></div>
</div>
<p class="mock-warning" aria-live="polite"></p>
<div class="mock-questions"></div>
<div class="mock-end"><button type="button" class="mock-finish mock-finish-last">Finish now</button></div>
</div>
</div>
"""


def visit_mock_test(self, node):
    index = {**mock_index(self.builder.env, self.builder.config), "next": node.get("next", {"types": {}})}
    index = json.dumps(index, ensure_ascii=False, separators=(",", ":")).replace("</", "<\\/")
    self.body.append(PAGE.format(enlarge=escape(form.ENLARGE), hint=escape(form.UNIT_HINT), rules=form.rules_script(),
                                 index=index, needs=escape(NEEDS_BROWSER), getting_ready=escape(GETTING_READY)))
    raise nodes.SkipNode


def fill(app, doctree, docname):
    for node in list(doctree.findall(mock_test)):
        if app.builder.format == "html":
            node["next"] = what_next_links(app, docname)
        else:
            node.parent.remove(node)


def add_assets(app, pagename, templatename, context, doctree):
    """The mock test's page alone loads its scripts: the engine's, then the test's."""
    if pagename not in store.docs(app.env, DIRECTIVE):
        return
    app.add_css_file("questions.css")
    app.add_css_file("mock-test.css")
    form.add_engine_scripts(app)
    for script in SCRIPTS:
        app.add_js_file(script, loading_method="defer")


def setup(app):
    app.add_node(mock_test, html=(visit_mock_test, None))
    app.add_directive(DIRECTIVE, MockTestDirective)
    app.connect("doctree-resolved", fill)
    app.connect("html-page-context", add_assets)
