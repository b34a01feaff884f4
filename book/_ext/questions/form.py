"""The answer form in HTML: boxes for a value, its unit and direction, options to choose,
a box for an explanation, with Check, New numbers and Clear; marked in the browser by
static/marking.js (the engine) and static/questions.js (the page), which only the pages
that ask a question load. The worked answer is hidden until a first attempt.
"""

from __future__ import annotations

import json
from html import escape

from docutils import nodes
from notation import add_notation_script  # book/_ext/notation: the browser's number writer
from sphinx.util import logging

from physics_figures import marking  # the rule table the browser's engine reads
from physics_figures.notation import join_units  # a number never parts from its unit

from . import schedule, store
from .directive import question

logger = logging.getLogger(__name__)
#: The part kinds' markers (static/question-kinds/), each the browser twin of a part class of
#: physics_figures/parts; marking.js finds them by the kinds they register.
KIND_SCRIPTS = ("numeric", "choice", "explain", "text")


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


def _input(cls: str, ident: str, label: str, described_by: str) -> str:
    return (f'<label class="q-field" for="{ident}"><span>{label}</span>'
            f'<input class="{cls}" id="{ident}" type="text" autocomplete="off" autocapitalize="off" '
            f'spellcheck="false" aria-describedby="{described_by}"></label>')


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


#: Under the first unit box of a page: how to type units and powers, before any mistake.
UNIT_HINT = ("Type a unit with its symbols, a space between them and ^ for a power: N s, "
             "kg m s^-1 or kg m/s, m s^-2. Units are case-sensitive: kg, not Kg.")


def _field_label(label: str, name: str) -> str:
    """A field's name: "(a) value" for part (a) of several, "Value" for a question of one part."""
    return f"{label.strip()} {name.lower()}" if label.strip() else name


def _numeric_html(base: str, part: dict, label: str = "", hint: bool = False) -> str:
    feedback, html = f"{base}-feedback", []
    if part["direction"] == "signed":
        # the span is what question-relabel.js rewrites with another variant's words
        html.append(f'<p class="q-note" id="{base}-note">Give a signed value: positive is '
                    f'<span class="q-positive">{escape(join_units(part["positive"]))}</span>.</p>')
        feedback += f" {base}-note"
    html.append('<div class="q-fields">')
    html.append(_input("q-value", f"{base}-value", escape(_field_label(label, "Value")), feedback))
    html.append(_input("q-unit", f"{base}-unit", escape(_field_label(label, "Unit")),
                       f"{base}-unit-hint {feedback}" if hint else feedback))
    if part["direction"] == "choice":
        options = "".join(f'<option value="{escape(c)}">{escape(c)}</option>' for c in part["choices"])
        html.append(f'<label class="q-field" for="{base}-direction"><span>'
                    f'{escape(_field_label(label, "Direction"))}</span>'
                    f'<select class="q-direction" id="{base}-direction" aria-describedby="{feedback}">'
                    f'<option value="">Choose…</option>{options}</select></label>')
    html.append("</div>")
    if hint:
        html.append(f'<p class="q-unit-hint" id="{base}-unit-hint">{escape(UNIT_HINT)}</p>')
    return "".join(html)


def _help_html(label: str) -> str:
    """Help before the answer (static/help-steps.js): the steps of the working shown so far,
    read out as each comes (a polite live region), and the button that shows the next; the
    script fills both from the question's data, and New numbers changes them."""
    name = escape(_field_label(label, "Steps of the working"))
    return (f'<div class="q-help"><ol class="q-steps" aria-live="polite" aria-label="{name}"></ol>'
            '<button type="button" class="q-step">Show a step</button></div>')


def _options_html(base: str, part: dict) -> str:
    """Radio buttons A to D (values A-D: the interface outside tests use)."""
    items = "".join(
        f'<label class="q-option" for="{base}-{o["letter"]}"><input type="radio" class="q-choice" '
        f'name="{base}" id="{base}-{o["letter"]}" value="{o["letter"]}" aria-describedby="{base}-feedback">'
        f'<span class="q-letter">{o["letter"]}</span> <span class="q-option-text">{o["html"]}</span></label>'
        for o in part["options"])
    # four sketch graphs sit side by side, two by two on a phone (questions.css)
    sketches = " q-sketches" if any(o.get("sketch") for o in part["options"]) else ""
    return f'<div class="q-options{sketches}">{items}</div>'


def _explain_html(base: str, part: dict, data: dict) -> str:
    """A box for the student's own words; after Check, the marking points to tick."""
    points = "".join(
        f'<label class="q-point"><input type="checkbox" class="q-tick" value="{i}"> '
        f'<span class="q-point-text">{mark["html"]}</span> <strong>{mark["code"]}</strong></label>'
        for i, mark in enumerate(data["marks"]) if mark["part"] == part["id"])
    return (f'<label class="q-field q-field-wide" for="{base}-text"><span>Your answer</span>'
            f'<textarea class="q-explain" id="{base}-text" rows="4" aria-describedby="{base}-feedback">'
            f'</textarea></label>'
            f'<div class="q-points" hidden><p>Tick each marking point your answer makes:</p>{points}'
            f'<div class="q-model"><p><strong>A full answer:</strong></p>'
            f'<div class="q-model-text">{part["model"]}</div></div></div>')


def _text_html(base: str, part: dict) -> str:
    """A box for the student's words (the one textarea of a text part); after Check, each marking
    point with what the marker found, a box to tick only where it could not decide."""
    points = "".join(
        f'<label class="q-point"><input type="checkbox" class="q-tick" value="{i}" disabled> '
        f'<span class="q-point-text">{escape(point["text"])}</span> <strong>{point["code"]}</strong></label>'
        for i, point in enumerate(part["points"]))
    return (f'<label class="q-field q-field-wide" for="{base}-text"><span>Your answer</span>'
            f'<textarea class="q-explain" id="{base}-text" rows="4" aria-describedby="{base}-feedback">'
            f'</textarea></label>'
            f'<div class="q-points" hidden><p>The marking points (tick one only where the marker could not '
            f'decide and your answer makes it):</p>{points}'
            f'<div class="q-model"><p><strong>A full answer:</strong></p>'
            f'<div class="q-model-text">{part["model"]}</div></div></div>')


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
    for part, legend, label in zip(data["parts"], node["legends"], labels, strict=True):
        base = f"q-{data['id']}-{part['id']}"
        kind = part.get("kind", "numeric")
        html.append(f'<fieldset class="q-part" data-part="{part["id"]}" data-kind="{kind}">'
                    f"<legend>{escape(join_units(legend))}</legend>")
        if kind == "mcq":
            html.append(_options_html(base, part))
        elif kind == "explain":
            html.append(_explain_html(base, part, data))
        elif kind == "text":
            html.append(_text_html(base, part))
        else:
            hint = not getattr(self, "_q_unit_hint_written", False)
            self._q_unit_hint_written = True  # the translator is one page's: once a page
            html.append(_numeric_html(base, part, label, hint))
        html.append(f'<p class="q-feedback" id="{base}-feedback" role="status"></p><p class="q-part-marks"></p>')
        if kind not in ("mcq", "explain", "text"):
            html.append(_help_html(label))
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


def add_engine_scripts(app) -> None:
    """What marks and records an answer, for every page that asks questions: the number writer,
    the answer reader, each part kind's marker, the engine, and the store of attempts."""
    add_notation_script(app)  # the engine and the page write numbers with it
    app.add_js_file("answer-reading.js", loading_method="defer", priority=440)
    for kind in KIND_SCRIPTS:  # each part kind's marker, before the engine that finds them
        app.add_js_file(f"question-kinds/{kind}.js", loading_method="defer", priority=450)
    app.add_js_file("marking.js", loading_method="defer", priority=460)
    schedule.add_store_script(app)  # questions.js and the mock test record each attempt in it


def add_assets(app, pagename, templatename, context, doctree):
    """Only pages that ask a question (or hold the key) load the scripts and styles."""
    if pagename in store.questions(app.env) or pagename in store.docs(app.env, "answer-key"):
        app.add_css_file("questions.css")
        add_engine_scripts(app)
        app.add_js_file("help-steps.js", loading_method="defer", priority=470)  # before questions.js (500)
        app.add_js_file("question-relabel.js", loading_method="defer")  # New numbers' words, shared
        app.add_js_file("questions.js", loading_method="defer")
        # the enlarged graph view, on the pages that print a question's graph
        if any(item.get("graph") for item in store.questions(app.env).get(pagename, ())):
            app.add_js_file("graph-view.js", loading_method="defer")
            app.add_js_file("graph-cursor.js", loading_method="defer")  # read it by keys or a tap
