"""Your practice: a plan for today, then what a student has done, by question type::

    ```{practice-progress}
    ```

The build writes every type with its templates (marks, the page that places each, the section
each named mistake sends a student back to), the self-test's definitions and the page that
holds them. In the browser, static/progress-plan.js writes the plan (cards due, Start, the
weakest type, the most frequent mistake) from the store (progress-store.js) and the schedule
(schedule.js); static/progress-page.js writes the record (worked out by static/progress.js,
its pure part) and moves it to and from a file.
Without JavaScript, and in print, the page still lists and links each type's questions.
"""

from __future__ import annotations

import json
import re
from html import escape

from docutils import nodes
from fresh_figures import uses_modules  # book/_ext: re-read a page when its modules change
from notation import add_notation_script  # book/_ext/notation: the browser's number writer
from sphinx.util.docutils import SphinxDirective

from physics_figures import marking  # the slips a record names as mistakes

from . import form, schedule, store

#: The slips the marking engine (marking.js) names itself, by which the page (questions.js)
#: records them, and the rule table's row that explains each (getting-the-marks): Your
#: practice links them there.
GENERIC_MISTAKES = {name: f"rule:{slip['rule']}" for name, slip in marking.slips().items()}


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


def _mistake_sections(template) -> dict[str, str]:
    """{mistake name: section id} for a template: where its feedback sends a student who made
    it (the mistake's own section, else its part's), as marking.js's sectionFor does."""
    out = {}
    for part in template.variant(0).parts:
        for mistake in getattr(part, "mistakes", None) or ():
            see = getattr(mistake, "see", None) or getattr(part, "see", None)
            if see:
                out.setdefault(mistake.name, see)
    return out


def definition_slug(term: str) -> str:
    """A definition's card id, as selftest.js names it (its slug)."""
    return re.sub(r"[^a-z0-9]+", "-", term.lower()).strip("-")


def _definitions(app, fromdoc: str) -> dict | None:
    """The self-test's cards: {page, cards: [{slug, term}]}, from the first page holding one."""
    env = app.env
    for docname in sorted(store.docs(env, store.SELF_TEST)):
        cards = []
        for box in env.get_doctree(docname).findall(nodes.admonition):
            if "self-test" not in box["classes"]:
                continue
            for item in box.findall(nodes.list_item):
                strong = next(iter(item.findall(nodes.strong)), None)
                if strong is not None:
                    term = strong.astext().rstrip().rstrip(":").strip()
                    cards.append({"slug": definition_slug(term), "term": term})
        if cards:
            return {"page": app.builder.get_relative_uri(fromdoc, docname), "cards": cards}
    return None


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
                      if entry["key"] in placed else None, "see": _mistake_sections(store.template(app.config, entry["key"]))}
                     for entry in entries]
        method = app.builder.get_relative_uri(fromdoc, kind.method) if kind.method in env.all_docs else None
        types.append({"type": kind.key, "name": kind.title, "templates": templates, "method": method})
    mock = sorted(store.docs(env, "mock-test"))  # the timed test, where the book has one
    return {"book": store.book_id(app.config), "types": types, "generic": GENERIC_MISTAKES,
            "definitions": _definitions(app, fromdoc),
            "mock": app.builder.get_relative_uri(fromdoc, mock[0]) if mock else None}


NEEDS_BROWSER = ("Your practice is kept in the web browser you practise in: open this page in the "
                 "web version of the book, with JavaScript on, to see it.")


def _plan_html() -> list[str]:
    """The plan's frame (progress-plan.js fills it): in the page, so filling it shifts nothing."""
    return [('<section class="pp-plan" aria-label="Your plan"><p class="pp-due"><span class="pp-due-text">The cards due today show here.</span> '
            '<button type="button" class="pp-start" disabled>Start</button></p>'
            '<p class="pp-weakest">Your weakest type shows here.</p>'
            '<p class="pp-often">Your most frequent mistake shows here.</p>'
            '<details class="pp-how"><summary>How the plan works</summary>'
            "<p>Each question and each definition of the self-test is a card. A card you answer comes back when "
            "you are about to forget it (the FSRS schedule, as Anki uses): soon when you lost marks, later when "
            "you were right. Using help makes it Hard at best; right first time at the exam's pace (1.25 minutes "
            "a mark) makes it Easy. A card you got wrong comes back within minutes: the plan says when. Start "
            "serves the cards due today, then new ones from every type in turn, never two of a type together "
            "while another type waits. The "
            "weakest type is the one with the lowest share of the marks over the questions you tried, counting "
            "your best attempt at each.</p></details></section>")]


def _type_html(kind: dict) -> list[str]:
    """One type: a line (marks, tried, due) whose details (its questions, mistakes, links) fold."""
    name = escape(kind["name"])
    placed = [t for t in kind["templates"] if t["page"]]
    if kind["templates"]:
        summary = store.count(len(kind["templates"]), "question", "questions") + " in the bank."
    else:
        summary = "Not in the bank yet: no question of this type to practise here so far."
    html = [(f'<details class="pp-type" id="pp-type-{kind["type"]}" data-type="{kind["type"]}"><summary><span class="pp-name">{name}</span>'
            f' <span class="pp-line"></span></summary>'
            f'<p class="pp-summary">{summary}</p><p class="pp-mistakes" hidden></p>')]
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
    html.append("</details>")
    return html


def visit_practice_progress(self, node):
    """Without JavaScript (and in print) the page still lists each type's questions and
    links to them; progress-plan.js and progress.js add what this browser has kept."""
    data = node["data"]
    # Only the sections a template's named mistakes (or the engine's own slips) send a student to.
    links = form.section_links(self)
    used = {see for kind in data["types"] for t in kind["templates"] for see in t["see"].values()}
    used.update(data["generic"].values())
    data = {**data, "sections": {ident: links[ident] for ident in sorted(used) if ident in links}}
    payload = json.dumps(data, ensure_ascii=False, separators=(",", ":")).replace("</", "<\\/")
    html = ['<div class="pp">', f'<script type="application/json" class="pp-data">{payload}</script>',
            f'<p class="pp-needs-js">{escape(NEEDS_BROWSER)}</p>', *_plan_html(),
            ('<section class="pp-types" aria-labelledby="pp-types-heading">'
            '<h2 id="pp-types-heading">By type</h2>')]
    for kind in data["types"]:
        html.extend(_type_html(kind))
    if data["definitions"]:  # the self-test's record, a line beside the types'
        html.append(f'<p class="pp-defs"><strong>Definitions self-test:</strong> <span class="pp-defs-line">'
                    f'{len(data["definitions"]["cards"])} definitions to learn in '
                    f'<a href="{escape(data["definitions"]["page"])}">the self-test</a>.</span></p>')
    html.append("</section>")
    html.append('<section class="pp-mocks" aria-label="Mock tests" hidden><p><strong>Mock tests:</strong> '
                '<span class="pp-mock-latest"></span>'
                + (f' <a href="{escape(data["mock"])}">Take another</a>' if data["mock"] else "")
                + '</p><details class="pp-mock-earlier" hidden><summary></summary>'
                '<ul class="pp-mock-list"></ul></details></section>')
    html.append(
        '<section class="pp-file" aria-labelledby="pp-file-heading" hidden>'
        '<h2 id="pp-file-heading">Move or clear your progress</h2>'
        # two lines on a phone: the page stays within two screens (tests/browser/test_plan_browser.py)
        "<p>Kept in this browser only: Export saves a file, and Import adds it on another device.</p>"
        '<p class="pp-student-line"><label for="pp-student">Your name, for the file</label> '
        '<input type="text" id="pp-student" class="pp-student" autocomplete="name" maxlength="80" size="16"></p>'
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
        else:  # print: where it works, then each type's questions, as the page's text promises
            progress.replace_self([nodes.paragraph(text=NEEDS_BROWSER), nodes.rubric(text="By type"),
                                   _printed_types(app.config)])


def _printed_types(config) -> nodes.bullet_list:
    """Each type of the book's topics with its questions and their marks, for the PDF."""
    types = nodes.bullet_list()
    for kind, entries in book_types(config):
        if entries:
            questions = "; ".join(f"{entry['title']} ({store.count(entry['marks'], 'mark', 'marks')})"
                                  for entry in entries)
            types += nodes.list_item("", nodes.paragraph(text=f"{kind.title}: {questions}."))
    return types


def add_assets(app, pagename, templatename, context, doctree):
    if pagename in store.docs(app.env, "practice-progress"):
        app.add_css_file("progress.css")
        add_notation_script(app)
        schedule.add_plan_scripts(app)  # the store, ts-fsrs and the schedule
        app.add_js_file("progress-file.js", loading_method="defer", priority=433)  # what Export writes
        app.add_js_file("progress.js", loading_method="defer", priority=434)  # the record's pure part
        app.add_js_file("progress-page.js", loading_method="defer", priority=434)  # the page, the file
        app.add_js_file("progress-plan.js", loading_method="defer", priority=435)  # the plan, Start


def add_review_script(app, pagename, templatename, context, doctree):
    """Where Start's cards are served (a question's page, the self-test's): review.js, which
    moves the student on to the next card after the Check or the mark."""
    if pagename in store.questions(app.env) or pagename in store.docs(app.env, store.SELF_TEST):
        app.add_css_file("review.css")
        app.add_js_file("review.js", loading_method="defer", priority=510)  # after questions.js


def setup(app):
    app.connect("html-page-context", add_review_script)
    app.add_node(practice_progress, html=(visit_practice_progress, None))
    app.add_directive("practice-progress", PracticeProgressDirective)
    app.connect("html-page-context", add_assets)
