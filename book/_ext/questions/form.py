"""The answer form in HTML: boxes for a value, its unit and direction, options to choose,
a box for an explanation, with Check, New numbers and Clear; marked in the browser by
static/marking.js (the engine) and static/questions.js (the page), which only the pages
that ask a question load. The worked answer is hidden until a first attempt.
"""

from __future__ import annotations

import json
import shutil
from html import escape
from pathlib import Path

from docutils import nodes
from notation import add_notation_script  # book/_ext/notation: the browser's number writer
from sphinx.util import logging

from physics_figures import marking  # the rule table the browser's engine reads
from physics_figures.notation import join_units  # a number never parts from its unit
from physics_figures.parts import KINDS
from physics_figures.parts.common import SCRIPTS, UNIT_HINT  # noqa: F401 (the mock test's page shows the hint)

from . import schedule, store
from .directive import question

logger = logging.getLogger(__name__)


PRINT_CHOICE = ('<p class="q-print"><button type="button" class="q-print-answers">Print with answers'
                '</button>Printing this page gives its questions with room for working, without the answers. '
                'Print with answers adds each worked answer and mark scheme.</p>\n')


def _try_first(asked) -> bool:
    return bool((asked.get("template") or {}).get("tryFirst"))


def print_note(document) -> str:
    """What paper says in place of the web's instructions (shown in print only, questions.css):
    how to answer, and the page's total, the sum of the totals its questions print (a worked
    example's try-first part is left out: its solution follows it)."""
    total = sum(line["marks"] for asked in document.findall(question) if not _try_first(asked)
                for line in asked.findall(nodes.paragraph) if "q-total" in line["classes"])
    return ('<p class="q-print-note">Answer each question in the space given, showing your working. '
            'The marks for each part are in square brackets. '
            f'Total for the page: {escape(store.count(total, "mark", "marks"))}.</p>\n')


def visit_question(self, node):
    if not getattr(self, "_q_print_written", False) and not _try_first(node):
        self._q_print_written = True
        self.body.append(PRINT_CHOICE + print_note(self.document))
    self.body.append(self.starttag(node, "section", CLASS="q", **{"data-q": node["qid"]}))
    payload = json.dumps(node["data"], ensure_ascii=False).replace("</", "<\\/")
    self.body.append(f'<script type="application/json" class="q-data">{payload}</script>\n')


def depart_question(self, node):
    self.body.append("</section>\n")


def _section_anchor(env, docname: str, title: str) -> str | None:
    """The anchor ("#linear-momentum") of a page's section, found by its title in the page's
    table of contents; "" for the page's top, None when the page has no such section."""
    if not title:
        return ""
    for reference in env.tocs[docname].findall(nodes.reference):
        if reference.astext().replace("\u2019", "'") == title:  # smart quotes in headings
            return reference["anchorname"]
    return None


def section_links(translator) -> dict[str, dict]:
    """Where feedback can send a student, as links from the page being written, by the ids
    the questions' data name (marking.js, sectionFor): {id: {href, title}}. The topics' sections
    (physics_figures.topics), and each documented rule's row ("rule:<id>") on the page that
    holds the rule table."""
    builder = translator.builder
    env, here, links = builder.env, builder.current_docname, {}
    sections = {ident: where for topic in store.topics(builder.config) for ident, where in topic.sections.items()}
    for ident, (docname, section) in sections.items():
        if docname not in env.all_docs:  # a smaller book (a test's) without that page
            continue
        anchor = _section_anchor(env, docname, section)
        if anchor is None:
            logger.warning(f"topic sections: page {docname!r} has no section {section!r} (section id {ident!r})")
            continue
        page = env.titles[docname].astext()
        links[ident] = {"href": builder.get_relative_uri(here, docname) + anchor,
                        "title": f"{section} ({page})" if section else page}
    for docname in sorted(store.docs(env, store.RULES_TABLE))[:1]:
        page = env.titles[docname].astext()
        for rule in marking.documented_rules():
            links[f"rule:{rule['id']}"] = {"href": builder.get_relative_uri(here, docname) + f"#rule-{rule['id']}",
                                           "title": f"the rule for this answer ({page})"}
    return links


def rules_script() -> str:
    """The rule table the marking engine reads (physics_figures/marking_rules.json), once a page."""
    table = json.dumps({"outcomes": marking.outcome_losses(), "sigFigs": marking.sig_figs(),
                        "slips": marking.outcome_slips(), "names": marking.mark_names()})
    return f'<script type="application/json" class="q-rules">{table}</script>'


def visit_question_form(self, node):
    data, template = node["data"], node.get("template")
    attributes = ""
    if template:  # the interface outside tests and the progress page read
        attributes = (f' data-question="{escape(template["key"])}" data-type="{escape(template["type"])}"'
                      f' data-variant="0" data-kind="{escape(" ".join(template["kinds"]))}"'
                      f' data-variants="{template["variants"]}"')
    html = [f'<form class="q-form"{attributes} novalidate>']
    if not getattr(self, "_q_ideas_written", False):  # once a page: where feedback links to
        self._q_ideas_written = True
        links = json.dumps(section_links(self), ensure_ascii=False).replace("</", "<\\/")
        html.insert(0, f'<script type="application/json" class="q-sections">{links}</script>')
        html.insert(0, rules_script())
    labels = node.get("labels") or [""] * len(data["parts"])
    if not hasattr(self, "_q_page"):
        self._q_page = {}  # the translator is one page's: the kinds' once-a-page flags
    for part, legend, label in zip(data["parts"], node["legends"], labels, strict=True):
        base = f"q-{data['id']}-{part['id']}"
        kind = KINDS[part["kind"]]
        html.append(f'<fieldset class="q-part" data-part="{part["id"]}" data-kind="{part["kind"]}">'
                    f"<legend>{escape(join_units(legend))}</legend>")
        html.append(kind.form_html(part, data, base=base, label=label, page=self._q_page))
        html.append("</fieldset>")
    new = ('<button type="button" class="q-new">New numbers</button>'
           if template and template["variants"] > 1 else "")
    html.append('<div class="q-buttons"><button type="submit" class="q-check">Check</button>'
                f'{new}<button type="reset" class="q-clear">Clear my answers</button>'
                '<button type="button" class="q-undo" hidden>Undo clear</button></div>'
                '<p class="q-score" aria-live="polite"></p></form>\n')
    self.body.append("".join(html))
    raise nodes.SkipNode


#: Under the graph, what its button does (with the image's alt text, the button's name).
ENLARGE = "Enlarge the graph to read it"


def visit_graph_view(self, node):
    """The graph's image inside a button that opens the enlarged view (static/graph-view.js,
    loaded with the questions' scripts). The interface outside tests use: button.q-graph-open
    with data-square (a small square's width and height over the image's width) and data-cursor
    (the graph cursor's axes and readings, static/graph-cursor.js) around
    img.q-graph; the view is dialog.q-graph-view."""
    self.body.append(f'<button type="button" class="q-graph-open" aria-haspopup="dialog" '
                     f'data-square="{escape(node["square"])}" data-cursor="{escape(node["cursor"])}">')


def depart_graph_view(self, node):
    self.body.append(f'<span class="q-graph-hint">{ENLARGE}</span></button>\n')


def visit_worked_answer(self, node):
    self.body.append('<details class="q-worked" hidden><summary>Worked answer and mark scheme</summary>\n')


def depart_worked_answer(self, node):
    self.body.append("</details>\n")


def kind_scripts(app, kinds: set[str] | None = None) -> list[str]:
    """Each part kind's browser twin (kinds may share one), in KINDS' order, as a path under
    _static: the book's own from static/question-kinds/; a topic's own kind's (registered as
    its bank loads) copied there. Only `kinds`' and those they use, if given (a page's own)."""
    store.topics(app.config)  # a topic's bank registers its own kinds as it loads
    if kinds is not None:
        kinds = kinds | {used for name in kinds for used in KINDS[name].uses_kinds}
    out: list[str] = []
    for kind in KINDS.values():
        if kinds is not None and kind.kind not in kinds:
            continue
        script = Path(kind.browser_script)
        if script.parent != SCRIPTS and app.builder.format == "html":
            target = Path(app.outdir) / "_static" / "question-kinds" / script.name
            if not target.is_file() or target.read_bytes() != script.read_bytes():
                target.parent.mkdir(parents=True, exist_ok=True)
                shutil.copyfile(script, target)
        name = f"question-kinds/{script.name}"
        if name not in out:
            out.append(name)
    return out


def add_engine_scripts(app, kinds: set[str] | None = None) -> None:
    """What marks and records an answer, for every page that asks questions: the number writer,
    the answer reader, each part kind's marker (only the page's kinds', if given: a page
    without a sketch never loads the sketch marker), the engine, and the store of attempts."""
    add_notation_script(app)  # the engine and the page write numbers with it
    app.add_js_file("answer-reading.js", loading_method="defer", priority=440)
    app.add_js_file("sig-figs.js", loading_method="defer", priority=442)  # the numeric kind's s.f. judge
    app.add_js_file("question-kinds.js", loading_method="defer", priority=445)  # the kinds' registry
    for script in kind_scripts(app, kinds):  # each part kind's marker, before the engine that finds them
        app.add_js_file(script, loading_method="defer", priority=450)
    app.add_js_file("marking.js", loading_method="defer", priority=460)
    schedule.add_store_script(app)  # questions.js and the mock test record each attempt in it


def add_assets(app, pagename, templatename, context, doctree):
    """Only pages that ask a question (or hold the key) load the scripts and styles."""
    if pagename in store.questions(app.env) or pagename in store.docs(app.env, "answer-key"):
        app.add_css_file("questions.css")
        asked = store.questions(app.env).get(pagename)
        # the key's page and a page that asks nothing of its own (a worked example's) load every kind
        add_engine_scripts(app, {k for item in asked for k in item["kinds"]} if asked else None)
        app.add_js_file("help-steps.js", loading_method="defer", priority=470)  # before questions.js (500)
        app.add_js_file("question-relabel.js", loading_method="defer")  # New numbers' words, shared
        app.add_js_file("questions.js", loading_method="defer")
        # the scripts and styles of the page's kinds that only pages asking them load (a sketch's pad)
        for asset in sorted({a for item in store.questions(app.env).get(pagename, ()) for a in item.get("assets", ())}):
            if asset.endswith(".css"):
                app.add_css_file(asset)
            else:
                app.add_js_file(asset, loading_method="defer", priority=455)
        # the enlarged graph view, on the pages that print a question's graph
        if any(item.get("graph") for item in store.questions(app.env).get(pagename, ())):
            app.add_js_file("graph-view.js", loading_method="defer")
            app.add_js_file("graph-cursor.js", loading_method="defer")  # read it by keys or a tap
