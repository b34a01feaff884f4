"""Questions that mark like an examiner (a local Sphinx extension).

A page places a template of the question bank (physics_figures.bank) by its key; the
template writes its own text, with the printed numbers (variant 0)::

    ```{question} quick-check-1
    ```

In HTML the question gets answer boxes marked in the browser by static/questions.js
(loaded only on pages that ask a question), New numbers (the other variants, in
_static/questions/<key>.js) and a worked answer with its mark scheme, shown after a first
attempt. Without JavaScript, in print and in LaTeX it is the question with an answer
line; every answer and mark scheme goes to the answer key::

    ```{answer-key}
    ```

which lists every question of the book (in table-of-contents order). The "Your practice"
page shows what a student has done with the bank's templates, by question type::

    ```{practice-progress}
    ```

(static/progress.js reads the attempts questions.js keeps in the browser).
"""

from __future__ import annotations

import json
import os
from html import escape
from pathlib import Path

from docutils import nodes
from fresh_figures import uses_modules  # book/_ext: re-read a page when its modules change
from notation import add_notation_script  # book/_ext/notation: the browser's number writer
from sphinx.util import logging
from sphinx.util.docutils import SphinxDirective

from physics_figures import marking  # the rule table the browser's engine reads
from physics_figures.notation import join_units  # a number never parts from its unit

__version__ = "1.0"
#: What a question's text, marks and key come from (the bank imports the models it uses), and
#: what draws a question's graph: a page placing a question is re-read when these change, and
#: so are the pages that gather the bank's questions (answer key, progress, try similar, map).
BANK_MODULES = ("physics_figures.bank", "physics_figures.textformat", "physics_figures.variants")
GRAPH_MODULE = "physics_figures.figures.question_graph"
STATIC = Path(__file__).parent / "static"
#: The part kinds' markers (static/question-kinds/), each the browser twin of a part class of
#: physics_figures/questions.py; questions.js finds them by the kinds they register.
KIND_SCRIPTS = ("numeric", "choice", "explain")
logger = logging.getLogger(__name__)


class question(nodes.General, nodes.Element):
    """A question: title, text, answer lines, answer boxes (HTML) and worked answer."""


class question_form(nodes.General, nodes.Element):
    """The answer boxes, marked in the browser (HTML only)."""


class worked_answer(nodes.General, nodes.Element):
    """The worked answer and mark scheme, shown after an attempt (HTML only)."""


class answer_key(nodes.General, nodes.Element):
    """Filled, once every page is read, with each question's answers and mark scheme."""


class practice_progress(nodes.General, nodes.Element):
    """The student's progress by question type: filled, once every page is read, with the
    bank's templates and the page that places each (HTML); a note elsewhere."""


def _questions(env) -> dict[str, list[dict]]:
    if not hasattr(env, "exam_questions"):
        env.exam_questions = {}
    return env.exam_questions


def _answer_key_docs(env) -> set[str]:
    if not hasattr(env, "exam_answer_keys"):
        env.exam_answer_keys = set()
    return env.exam_answer_keys


def _progress_docs(env) -> set[str]:
    if not hasattr(env, "practice_progress_docs"):
        env.practice_progress_docs = set()
    return env.practice_progress_docs


class QuestionDirective(SphinxDirective):
    """A template of the bank, named by its key; its text comes with its numbers."""

    optional_arguments = 1
    final_argument_whitespace = True
    has_content = True

    def run(self):
        template = self._template()
        data, title = template.variant(0), template.title
        if self.content:
            raise self.error(f"question {template.key}: a template writes its own text; "
                             "leave the directive empty")
        # An edit to these (or to what they import) re-reads this page.
        uses_modules(self.env, *BANK_MODULES)
        if data.graph is not None:
            uses_modules(self.env, GRAPH_MODULE)
        _templates_used(self.env).setdefault(self.env.docname, []).append(template.key)

        node = question(qid=data.key, data=data.browser_data(), ids=[f"question-{data.key}"],
                        template=_template_data(template))
        self.set_source_info(node)
        node += nodes.paragraph("", "", nodes.strong(text=title), classes=["q-title"])
        node += nodes.container("", *text_nodes(data.text), classes=["q-text"])
        if data.graph is not None:
            node += self._graph(template.key, data.graph)
        lines = nodes.container(classes=["q-answer-lines"])
        marks = part_marks(data)
        for index, part in enumerate(data.parts):
            lines += answer_lines(data.label(index), part, marks[index])
        lines += nodes.paragraph(text=f"Total: {_count(sum(marks), 'mark', 'marks')}", classes=["q-total"])
        node += lines
        node += question_form(data=node["data"], template=node["template"],
                              labels=[data.label(i) for i in range(len(data.parts))],
                              legends=[data.label(i) + p.prompt[:1].upper() + p.prompt[1:]
                                       for i, p in enumerate(data.parts)])
        worked = worked_answer()
        worked += mark_scheme_nodes(data)
        node += worked

        self._record(data, title, worked)
        return [node]

    def _template(self):
        if not self.arguments:
            raise self.error("question: name a template of physics_figures.bank")
        from physics_figures import bank  # imported here: the bank is slow to build

        key = self.arguments[0]
        if key not in bank.TEMPLATES:
            raise self.error(f"question: no template {key!r} in physics_figures.bank")
        return bank.TEMPLATES[key]

    def _graph(self, key: str, graph) -> nodes.image:
        """The printed variant's graph, drawn now as SVG (the site) and PDF (the book): an
        image Sphinx copies like any other, so every builder picks its own format."""
        folder = Path(self.env.doctreedir).parent / GRAPHS_DIR
        drawn = write_graph(folder, f"{key}-0", graph, formats=("svg", "pdf"))
        here = Path(self.env.srcdir) / Path(self.env.docname).parent
        uri = Path(os.path.relpath(folder / f"{key}-0", here)).as_posix() + ".*"
        return nodes.image(uri=uri, alt=drawn.alt, classes=["q-graph"])

    def _record(self, data, title: str, worked: worked_answer) -> None:
        for docname, asked in _questions(self.env).items():
            if any(q["key"] == data.key for q in asked):
                logger.warning(f"question {data.key} is asked twice (also in {docname})",
                               location=self.get_location())
        _questions(self.env).setdefault(self.env.docname, []).append({
            "key": data.key, "title": title, "marks": data.marks,
            "answers": [data.label(i) + f"{p.prompt}: {p.answer_text}" for i, p in enumerate(data.parts)],
            "scheme": [child.deepcopy() for child in worked.children],
        })


def part_marks(data) -> list[int]:
    """The marks of each part, as an exam paper prints them ([2]): the question's own count,
    the one the browser awards and the sheets and Moodle print (Question.part_marks)."""
    return data.part_marks()


def answer_lines(label: str, part, marks: int) -> list[nodes.Node]:
    """What a part prints on paper: its options and a box for the letter, lines for an
    explanation, or a line for a value (and its direction); each ends with the part's
    marks, [2], as on a Cambridge paper."""
    tail = f" [{marks}]"
    if part.kind == "mcq":
        options = nodes.enumerated_list(enumtype="upperalpha", classes=["q-options-print"])
        for option in part.options:
            options += nodes.list_item("", *text_nodes(option.text))
        return [nodes.paragraph(text=f"{label}{part.prompt}"), options,
                nodes.paragraph(text="Answer (A, B, C or D): " + "." * 8 + tail)]
    if part.kind == "explain":
        return [nodes.paragraph(text=f"{label}{part.prompt}")] + [
            nodes.paragraph(text="." * 70 + (tail if last else "")) for last in (False, False, False, True)]
    line = f"{label}{part.prompt} = " + "." * 28
    if part.direction == "choice":
        line += " direction: " + "." * 16
    return [nodes.paragraph(text=line + tail)]


def _template_data(template) -> dict:
    return {"key": template.key, "type": template.type, "kinds": list(template.kinds),
            "variants": len(template.values), "tryFirst": bool(template.try_first)}


_TAG_NODES = {"sup": nodes.superscript, "sub": nodes.subscript, "em": nodes.emphasis,
              "strong": nodes.strong}


def _inline_nodes(spans) -> list[nodes.Node]:
    out = []
    for span in spans:
        node = nodes.Text(span.text)
        for tag in reversed(span.tags):
            node = _TAG_NODES[tag]("", "", node)
        out.append(node)
    return out


def text_nodes(source: str) -> list[nodes.Node]:
    """Paragraphs of docutils nodes from physics_figures.textformat (HTML, LaTeX, text alike)."""
    from physics_figures import textformat

    return [nodes.paragraph("", "", *_inline_nodes(spans)) for spans in textformat.parse(source)]


def mark_scheme_nodes(data) -> list[nodes.Node]:
    from physics_figures import textformat

    items = nodes.bullet_list(classes=["q-scheme"])
    for label, text, code in data.mark_lines():
        line = nodes.paragraph()
        if label:
            line += [nodes.strong(text=label), nodes.Text(" ")]
        for spans in textformat.parse(text):
            line += _inline_nodes(spans)
        if code:
            line += [nodes.Text(" "), nodes.strong(text=code)]
        items += nodes.list_item("", line)
    return [items]


class try_similar(nodes.General, nodes.Element):
    """"Try a similar one": filled, once every page is read, with a link to a practice
    question of the same type as the page's worked example."""


class TrySimilarDirective(SphinxDirective):
    """At the end of a worked example: a link to a question of the same type to practise."""

    def run(self):
        _try_similar_docs(self.env).add(self.env.docname)
        uses_modules(self.env, *BANK_MODULES)
        return [try_similar()]


def _try_similar_docs(env) -> set[str]:
    if not hasattr(env, "exam_try_similar"):
        env.exam_try_similar = set()
    return env.exam_try_similar


def _similar_question(app, docname: str):
    """(template, page) of the first question in book order, outside the worked examples, of
    the type of this page's try-first question; practice pages first."""
    from physics_figures import bank

    env = app.env
    kinds = {bank.TEMPLATES[k].type for k in _templates_used(env).get(docname, []) if bank.TEMPLATES[k].try_first}
    if len(kinds) != 1:
        raise ValueError(f"try-similar on {docname}: the page must ask exactly one worked example's "
                         f"try-first question (its types: {sorted(kinds)})")
    kind = kinds.pop()
    found = [(bank.TEMPLATES[key], page) for page in _book_order(env, app.config.root_doc)
             for key in _templates_used(env).get(page, [])
             if bank.TEMPLATES[key].type == kind and not bank.TEMPLATES[key].try_first]
    if not found:
        raise ValueError(f"try-similar on {docname}: no question of type {kind!r} is placed outside "
                         "the worked examples")
    practice = [f for f in found if "/practice" in f[1]]
    return (practice or found)[0]


class book_map(nodes.General, nodes.Element):
    """A list for the landing page, filled once every page is read: the book's parts with a
    time estimate, its explorables, or its question pages."""


class BookMapDirective(SphinxDirective):
    """``{book-map} parts`` (or ``explorables``, ``questions``) on the landing page."""

    required_arguments = 1

    def run(self):
        if self.arguments[0] not in BOOK_MAPS:
            raise self.error(f"book-map: choose one of {', '.join(BOOK_MAPS)} (got {self.arguments[0]!r})")
        _map_docs(self.env).add(self.env.docname)
        uses_modules(self.env, *BANK_MODULES)
        return [book_map(what=self.arguments[0])]


BOOK_MAPS = ("parts", "explorables", "questions")
#: The time estimate: reading at WORDS_PER_MINUTE, MINUTES_PER_MARK for each mark of a page's
#: questions and MINUTES_PER_EXPLORABLE for each explorable, rounded up to 5 minutes a part.
WORDS_PER_MINUTE, MINUTES_PER_MARK, MINUTES_PER_EXPLORABLE = 100, 1.5, 5


def _map_docs(env) -> set[str]:
    if not hasattr(env, "exam_book_maps"):
        env.exam_book_maps = set()
    return env.exam_book_maps


def _parts(app) -> list[tuple[str, list[str]]]:
    """(caption, [pages, sections included]) for each part of the table of contents."""
    from sphinx import addnodes

    env = app.env
    root = env.get_doctree(app.config.root_doc)
    parts = []
    for toctree in root.findall(addnodes.toctree):
        pages = []
        for _, docname in toctree["entries"]:
            pages.extend(_book_order_from(env, docname))
        parts.append((toctree.get("caption") or "", pages))
    return parts


def _book_order_from(env, start: str) -> list[str]:
    order = [start]
    for child in env.toctree_includes.get(start, []):
        order.extend(_book_order_from(env, child))
    return order


def _minutes(app, docname: str) -> float:
    env = app.env
    words = len(env.get_doctree(docname).astext().split())
    marks = sum(item["marks"] for item in _questions(env).get(docname, []))
    explorables = len(getattr(env, "explorables_by_doc", {}).get(docname, ()))
    return words / WORDS_PER_MINUTE + MINUTES_PER_MARK * marks + MINUTES_PER_EXPLORABLE * explorables


def _link(app, fromdoc: str, docname: str, text: str, anchor: str = "") -> nodes.Node:
    if app.builder.format == "html":
        uri = app.builder.get_relative_uri(fromdoc, docname) + anchor
        return nodes.reference("", text, internal=True, refuri=uri)
    return nodes.Text(text)


def _title(app, docname: str) -> str:
    number = app.env.toc_secnumbers.get(docname, {}).get("")
    title = app.env.titles[docname].astext()
    return f"{'.'.join(map(str, number))}. {title}" if number else title


def _book_map_content(app, fromdoc: str, what: str) -> list[nodes.Node]:
    from physics_figures.notation import format_number

    env, items = app.env, nodes.bullet_list(classes=["book-map", f"book-map-{what}"])
    if what == "parts":
        for caption, pages in _parts(app):
            minutes = 5 * -(-sum(_minutes(app, page) for page in pages) // 5)
            item = nodes.paragraph()
            item += nodes.strong(text=caption)
            item += nodes.Text(f" (about {format_number(minutes, decimals=0)} minutes): ")
            for index, page in enumerate(pages):
                if index:
                    item += nodes.Text("; ")
                item += _link(app, fromdoc, page, _title(app, page))
            items += nodes.list_item("", item)
    elif what == "explorables":
        from explorables import DESCRIPTIONS  # book/_ext/explorables

        for docname in _book_order(env, app.config.root_doc):
            for name in sorted(getattr(env, "explorables_by_doc", {}).get(docname, ())):
                title, shows = DESCRIPTIONS[name]
                item = nodes.paragraph()
                item += _link(app, fromdoc, docname, title)
                item += nodes.Text(f" (on “{_title(app, docname)}”): {shows}.")
                items += nodes.list_item("", item)
    else:
        for docname in _book_order(env, app.config.root_doc):
            asked = [q for q in _questions(env).get(docname, [])]
            if not asked or docname.rpartition("/")[2].startswith("example-"):
                continue  # a worked example's try-first part is the example's, listed with it
            marks = sum(q["marks"] for q in asked)
            item = nodes.paragraph()
            item += _link(app, fromdoc, docname, _title(app, docname))
            item += nodes.Text(f": {_count(len(asked), 'question', 'questions')}, "
                               f"{_count(marks, 'mark', 'marks')}")
            items += nodes.list_item("", item)
    return [items]


class AnswerKeyDirective(SphinxDirective):
    """Where the answer key goes: every question of the book, filled in later."""

    def run(self):
        _answer_key_docs(self.env).add(self.env.docname)
        uses_modules(self.env, *BANK_MODULES)
        return [answer_key()]


class PracticeProgressDirective(SphinxDirective):
    """Where the student's progress goes (the page's own text says what it is for)."""

    def run(self):
        _progress_docs(self.env).add(self.env.docname)
        uses_modules(self.env, *BANK_MODULES)
        return [practice_progress()]


#: The notes' seven question types ("How to do it"), by data-type: name and method page.
TYPE_NAMES = {
    "newton": ("Newton's laws, F = ma and third-law pairs", "book/exam/method-newtons-laws"),
    "drag": ("Drag, air resistance and terminal velocity", "book/exam/method-drag"),
    "force-momentum": ("Force as rate of change of momentum", "book/exam/method-force-momentum"),
    "definitions": ("Mass, weight and the definitions", "book/exam/method-definitions"),
    "momentum-line": ("Conservation of momentum in a straight line", "book/exam/method-momentum-line"),
    "elastic": ("Elastic and inelastic collisions", "book/exam/method-collisions"),
    "two-d": ("Conservation of momentum in two dimensions", "book/exam/method-two-dimensions"),
}


def _progress_data(app, fromdoc: str) -> dict:
    """Every template of the bank by type, with its title, marks and the page placing it
    (None if no page does yet): what progress.js needs; it computes no physics."""
    from physics_figures import bank
    from physics_figures.variants import QUESTION_TYPES

    if set(TYPE_NAMES) != set(QUESTION_TYPES):
        raise ValueError(f"TYPE_NAMES must name exactly the types {QUESTION_TYPES}")
    env, placed = app.env, {}
    for docname in _book_order(env, app.config.root_doc):
        for key in _templates_used(env).get(docname, []):
            placed.setdefault(key, docname)
    types = []
    for kind in QUESTION_TYPES:
        name, method = TYPE_NAMES[kind]
        templates = [{
            "key": t.key, "title": t.title, "marks": t.variant(0).marks,
            "page": app.builder.get_relative_uri(fromdoc, placed[t.key]) if t.key in placed else None,
        } for t in bank.by_type(kind)]
        types.append({"type": kind, "name": name, "templates": templates,
                      "method": app.builder.get_relative_uri(fromdoc, method) if method in env.all_docs else None})
    return {"types": types}


# ------------------------------------------------------------------------ events


def purge(app, env, docname):
    _questions(env).pop(docname, None)
    _templates_used(env).pop(docname, None)
    _answer_key_docs(env).discard(docname)
    _progress_docs(env).discard(docname)
    _try_similar_docs(env).discard(docname)
    _self_test_docs(env).discard(docname)
    _map_docs(env).discard(docname)


def merge(app, env, docnames, other):
    for docname in docnames:
        if docname in _questions(other):
            _questions(env)[docname] = _questions(other)[docname]
        if docname in _answer_key_docs(other):
            _answer_key_docs(env).add(docname)
        if docname in _templates_used(other):
            _templates_used(env)[docname] = _templates_used(other)[docname]
        if docname in _progress_docs(other):
            _progress_docs(env).add(docname)
        if docname in _try_similar_docs(other):
            _try_similar_docs(env).add(docname)
        if docname in _self_test_docs(other):
            _self_test_docs(env).add(docname)
        if docname in _map_docs(other):
            _map_docs(env).add(docname)


def refresh_answer_keys(app, env, added, changed, removed):
    """A page's questions changed: re-read the pages that hold an answer key or the progress."""
    pages = _answer_key_docs(env) | _progress_docs(env) | _try_similar_docs(env) | _map_docs(env)
    return sorted(pages) if added | changed | removed else []


def _self_test_docs(env) -> set[str]:
    if not hasattr(env, "definitions_self_test"):
        env.definitions_self_test = set()
    return env.definitions_self_test


def find_self_tests(app, doctree):
    """A box of definitions with class self-test: its page loads selftest.js."""
    if any("self-test" in node["classes"] for node in doctree.findall(nodes.admonition)):
        _self_test_docs(app.env).add(app.env.docname)


def _self_test_bar(count: int) -> nodes.raw:
    """The self-test's bar, in the page rather than added by selftest.js, which would push the
    list down after the first paint (a layout shift); hidden without JavaScript."""
    return nodes.raw("", '<div class="st-bar"><button type="button" class="st-toggle" aria-pressed="false">'
                     'Test yourself: hide the definitions</button><p class="st-status" role="status">'
                     f'Known: 0 of {count} definitions.</p></div>', format="html")


def add_self_test_bars(doctree) -> None:
    for box in doctree.findall(nodes.admonition):
        lists = [child for child in box.children if isinstance(child, (nodes.bullet_list, nodes.enumerated_list))]
        if "self-test" in box["classes"] and lists:
            box.insert(box.index(lists[0]), _self_test_bar(len(lists[0].children)))


def answer_key_has_maths(app, doctree):
    """The key's mark schemes hold maths, so the page needs MathJax (runs after the math domain)."""
    if any(doctree.findall(answer_key)):
        app.env.get_domain("math").data["has_equations"][app.env.docname] = True


def _book_order(env, root: str) -> list[str]:
    order, seen = [], set()

    def visit(docname):
        if docname in seen:
            return
        seen.add(docname)
        order.append(docname)
        for child in env.toctree_includes.get(docname, []):
            visit(child)

    visit(root)
    return order + sorted(set(env.all_docs) - seen)


def _answer_key_content(app, fromdoc: str) -> list[nodes.Node]:
    env, content = app.env, []
    for docname in _book_order(env, app.config.root_doc):
        asked = _questions(env).get(docname)
        if not asked:
            continue
        page = env.titles[docname].astext() if docname in env.titles else docname
        content.append(nodes.paragraph("", "", nodes.strong(text=page), classes=["q-key-page"]))
        for item in asked:
            uri = app.builder.get_relative_uri(fromdoc, docname) + f"#question-{item['key']}"
            heading = nodes.paragraph(classes=["q-key-title"])
            heading += nodes.reference("", item["title"], internal=True, refuri=uri)
            marks = item["marks"]
            heading += nodes.Text(f" [{marks} mark{'s' if marks != 1 else ''}]")
            content.append(heading)
            answers = nodes.bullet_list(classes=["q-key-answers"])
            for line in item["answers"]:
                answers += nodes.list_item("", nodes.paragraph(text=line))
            content.append(answers)
            content.extend(child.deepcopy() for child in item["scheme"])
    return content


def page_of(node, env) -> str | None:
    """The page a node of the merged doctree came from (the LaTeX builder's one book).

    Sphinx marks each page's sections with their docname when it merges the pages
    (sphinx-jupyterbook-latex moves the start_of_file markers, so they are no guide).
    """
    parent = node.parent
    while parent is not None:
        if isinstance(parent, nodes.Element) and parent.get("docname") in env.all_docs:
            return parent["docname"]
        parent = parent.parent
    return None


def _source_page(env, node, docname: str) -> str:
    """The page a node came from: in a merged book the page_of it, else the page resolved."""
    return page_of(node, env) or docname


def resolve(app, doctree, docname):
    """Fill each answer key; outside HTML, questions become plain text with answer lines."""
    html = app.builder.format == "html"
    if html:
        add_self_test_bars(doctree)
    for listing in list(doctree.findall(book_map)):
        listing.replace_self(_book_map_content(app, docname, listing["what"]))
    for similar in list(doctree.findall(try_similar)):
        template, page = _similar_question(app, _source_page(app.env, similar, docname))
        title = app.env.titles[page].astext()
        line = nodes.paragraph(classes=["q-try-similar"])
        line += nodes.strong(text="Try a similar one: ")
        if html:
            uri = app.builder.get_relative_uri(docname, page) + f"#question-{template.key}"
            line += nodes.reference("", template.title, internal=True, refuri=uri)
            line += nodes.Text(f" ({title}).")
        else:
            line += nodes.Text(f"{template.title}, on the page “{title}”.")
        similar.replace_self(line)
    for progress in list(doctree.findall(practice_progress)):
        if html:
            progress["data"] = _progress_data(app, docname)
        else:  # print: the page's text says what it is for; this says where it works
            progress.replace_self(nodes.paragraph(text=NEEDS_BROWSER))
    for key in list(doctree.findall(answer_key)):
        key.extend(_answer_key_content(app, docname))
        if not html:
            printed = nodes.container(classes=["q-key"])
            printed += nodes.rubric(text="Answer key")
            printed.extend(key.children)
            key.replace_self(printed)
    if html:
        return
    for asked in list(doctree.findall(question)):
        printed = nodes.container(ids=asked["ids"], classes=["q"])
        printed.extend(child for child in asked.children
                       if not isinstance(child, (question_form, worked_answer)))
        asked.replace_self(printed)


def add_assets(app, pagename, templatename, context, doctree):
    """Only pages that ask a question (or hold the key) load the script and styles."""
    if pagename in _questions(app.env) or pagename in _answer_key_docs(app.env):
        app.add_css_file("questions.css")
        add_notation_script(app)  # questions.js writes numbers with it
        for kind in KIND_SCRIPTS:  # each part kind's marker, before the engine that finds them
            app.add_js_file(f"question-kinds/{kind}.js", loading_method="defer", priority=450)
        app.add_js_file("questions.js", loading_method="defer")
    if pagename in _self_test_docs(app.env):
        app.add_css_file("selftest.css")
        app.add_js_file("selftest.js", loading_method="defer")
    if pagename in _progress_docs(app.env):
        app.add_css_file("progress.css")
        add_notation_script(app)
        app.add_js_file("progress.js", loading_method="defer")


VARIANTS_DIR = "questions"  # under the site's _static/: one file of variants per template
GRAPHS_DIR = "question-graphs"  # beside the doctrees: the printed variants' graphs, as sources


def write_graph(folder: Path, name: str, graph, *, formats: tuple[str, ...]):
    """Draw a question's graph into folder/name.<format>, rewriting a file only when its
    bytes change (so an unchanged graph is not copied again). Returns the BookFigure."""
    from physics_figures.figures.question_graph import question_graph

    drawn = question_graph(graph)
    folder.mkdir(parents=True, exist_ok=True)
    for extension in formats:
        content = drawn.svg().encode() if extension == "svg" else drawn.pdf()
        path = folder / f"{name}.{extension}"
        if not path.exists() or path.read_bytes() != content:
            path.write_bytes(content)
    drawn.figure.clear()  # matplotlib keeps figures alive until cleared
    return drawn


def write_variants(app, exception):
    """Each template's variants as a small script, loaded only when New numbers is pressed (a
    <script> element, so it works from file:// too, where fetch() does not)."""
    if exception or app.builder.format != "html":
        return
    keys = sorted({key for keys in _templates_used(app.env).values() for key in keys})
    if not keys:
        return
    from physics_figures import bank

    folder = Path(app.outdir) / "_static" / VARIANTS_DIR
    folder.mkdir(parents=True, exist_ok=True)
    for key in keys:
        if len(bank.TEMPLATES[key].values) < 2:  # no New numbers: nothing to load
            continue
        variants = []
        for index, variant in enumerate(bank.TEMPLATES[key].variants):
            data = variant.variant_data()
            if variant.graph is not None:  # its own graph, beside the variants' script
                drawn = write_graph(folder, f"{key}-{index}", variant.graph, formats=("svg",))
                data["graph"] = {"src": f"{key}-{index}.svg", "alt": drawn.alt}
            variants.append(data)
        payload = json.dumps(variants, ensure_ascii=False, separators=(",", ":")).replace("</", "<\\/")
        (folder / f"{key}.js").write_text(
            f"(window.QuestionVariants = window.QuestionVariants || {{}})[{json.dumps(key)}] = {payload};\n",
            encoding="utf-8")


def _templates_used(env) -> dict[str, list[str]]:
    if not hasattr(env, "question_templates"):
        env.question_templates = {}
    return env.question_templates


def add_static_path(app, config):
    config.html_static_path.append(str(STATIC))


# ---------------------------------------------------------------- HTML writer


#: Before a page's first question (not a worked example's try-first): printing gives the
#: questions with room to work; this button prints the worked answers too.
PRINT_CHOICE = ('<p class="q-print"><button type="button" class="q-print-answers">Print with answers'
                '</button>Printing this page gives its questions with room for working, without the answers. '
                'Print with answers adds each worked answer and mark scheme.</p>\n')


def visit_question(self, node):
    if not getattr(self, "_q_print_written", False) and not (node.get("template") or {}).get("tryFirst"):
        self._q_print_written = True
        self.body.append(PRINT_CHOICE)
    self.body.append(self.starttag(node, "section", CLASS="q", **{"data-q": node["qid"]}))
    payload = json.dumps(node["data"], ensure_ascii=False).replace("</", "<\\/")
    self.body.append(f'<script type="application/json" class="q-data">{payload}</script>\n')


def depart_question(self, node):
    self.body.append("</section>\n")


def _input(cls: str, ident: str, label: str, described_by: str) -> str:
    return (f'<label class="q-field" for="{ident}"><span>{label}</span>'
            f'<input class="{cls}" id="{ident}" type="text" autocomplete="off" autocapitalize="off" '
            f'spellcheck="false" aria-describedby="{described_by}"></label>')


#: Feedback that names an idea links the section that teaches it: the first pattern (a
#: JavaScript and Python regular expression, case-insensitive) the message matches, most
#: specific first. (page, section title or "" for the page's top).
IDEAS = (
    (r"third law|third-law|equal (in magnitude )?and opposite|pairs? of forces|same type", "book/understand/third-law", ""),
    (r"two dimensions|component|perpendicular|\b(cos|sin|tan)\b|at an angle", "book/understand/momentum-in-two-dimensions",
     "The vector picture"),
    (r"kinetic energy|elastic", "book/understand/elastic-and-inelastic", "Kinetic energy in the sticking trolleys"),
    (r"relative speed|speed of (approach|separation)", "book/understand/elastic-and-inelastic", "Relative speed"),
    (r"explosion|recoil|from rest", "book/understand/conservation-of-momentum", "Explosions"),
    (r"conserv|total momentum|momentum before|momentum after", "book/understand/conservation-of-momentum",
     "Using it in a straight line"),
    (r"area under|impulse|gradient|momentum.time|force.time", "book/understand/momentum-time-graph", ""),
    (r"terminal|drag|air resistance|upthrust", "book/understand/friction-drag-terminal-velocity", "The skydiver"),
    (r"friction", "book/understand/friction-drag-terminal-velocity", "Friction and drag"),
    (r"\blift\b|contact force", "book/understand/weight", "In a lift"),
    (r"weight|W = mg|gravitational field", "book/understand/weight", ""),
    (r"rate of change of momentum|change in momentum|Δp|resultant force|F = ma|second law",
     "book/understand/momentum-and-second-law", "Newton's second law"),
    (r"momentum", "book/understand/momentum-and-second-law", "Linear momentum"),
    (r"first law|resists a change|constant velocity|\bmass\b", "book/understand/mass-and-first-law", ""),
    (r"significant figures|\bs\.f\.|round", "book/exam/getting-the-marks", ""),
)


def _section_anchor(env, docname: str, title: str) -> str | None:
    """The anchor ("#linear-momentum") of a page's section, found by its title in the page's
    table of contents; "" for the page's top, None when the page has no such section."""
    if not title:
        return ""
    for reference in env.tocs[docname].findall(nodes.reference):
        if reference.astext().replace("\u2019", "'") == title:  # smart quotes in headings
            return reference["anchorname"]
    return None


def _idea_links(translator) -> list[dict]:
    """IDEAS as links from the page being written: [{pattern, href, title}]."""
    builder = translator.builder
    env, here, links = builder.env, builder.current_docname, []
    for pattern, docname, section in IDEAS:
        if docname not in env.all_docs:  # a smaller book (a test's) without that page
            continue
        anchor = _section_anchor(env, docname, section)
        if anchor is None:
            logger.warning(f"questions.IDEAS: page {docname!r} has no section {section!r}")
            continue
        page = env.titles[docname].astext()
        links.append({"pattern": pattern, "href": builder.get_relative_uri(here, docname) + anchor,
                      "title": f"{section} ({page})" if section else page})
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
        html.append(f'<p class="q-note" id="{base}-note">Give a signed value: positive is '
                    f"{escape(join_units(part['positive']))}.</p>")
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


def _options_html(base: str, part: dict) -> str:
    """Radio buttons A to D (values A-D: the interface outside tests use)."""
    items = "".join(
        f'<label class="q-option" for="{base}-{o["letter"]}"><input type="radio" class="q-choice" '
        f'name="{base}" id="{base}-{o["letter"]}" value="{o["letter"]}" aria-describedby="{base}-feedback">'
        f'<span class="q-letter">{o["letter"]}</span> <span class="q-option-text">{o["html"]}</span></label>'
        for o in part["options"])
    return f'<div class="q-options">{items}</div>'


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


def visit_question_form(self, node):
    data, template = node["data"], node.get("template")
    attributes = ""
    if template:  # the interface outside tests and the progress page read
        attributes = (f' data-question="{escape(template["key"])}" data-type="{escape(template["type"])}"'
                      f' data-variant="0" data-kind="{escape(" ".join(template["kinds"]))}"'
                      f' data-variants="{template["variants"]}"')
    html = [f'<form class="q-form"{attributes} novalidate>']
    if not getattr(self, "_q_ideas_written", False):  # once a page: feedback's links to the ideas
        self._q_ideas_written = True
        ideas = json.dumps(_idea_links(self), ensure_ascii=False).replace("</", "<\\/")
        html.insert(0, f'<script type="application/json" class="q-ideas">{ideas}</script>')
        # the rule table the marking engine reads (physics_figures/marking_rules.json)
        table = json.dumps({"outcomes": marking.outcome_losses(), "sigFigs": marking.sig_figs()})
        html.insert(0, f'<script type="application/json" class="q-rules">{table}</script>')
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
        else:
            hint = not getattr(self, "_q_unit_hint_written", False)
            self._q_unit_hint_written = True  # the translator is one page's: once a page
            html.append(_numeric_html(base, part, label, hint))
        html.append(f'<p class="q-feedback" id="{base}-feedback" role="status"></p>'
                    '<p class="q-part-marks"></p></fieldset>')
    new = ('<button type="button" class="q-new">New numbers</button>'
           if template and template["variants"] > 1 else "")
    html.append('<div class="q-buttons"><button type="submit" class="q-check">Check</button>'
                f'{new}<button type="reset" class="q-clear">Clear my answers</button>'
                '<button type="button" class="q-undo" hidden>Undo clear</button></div>'
                '<p class="q-score" aria-live="polite"></p></form>\n')
    self.body.append("".join(html))
    raise nodes.SkipNode


def visit_worked_answer(self, node):
    self.body.append('<details class="q-worked" hidden><summary>Worked answer and mark scheme</summary>\n')


def depart_worked_answer(self, node):
    self.body.append("</details>\n")


def visit_answer_key(self, node):
    self.body.append(self.starttag(node, "details", CLASS="q-key"))
    self.body.append("<summary>Answer key: every answer with its mark scheme</summary>\n")


def depart_answer_key(self, node):
    self.body.append("</details>\n")


NEEDS_BROWSER = ("Your practice is kept in the web browser you practise in: open this page in the "
                 "web version of the book, with JavaScript on, to see it.")


def _count(number: int, one: str, many: str) -> str:
    from physics_figures.notation import format_number

    return f"{format_number(number, decimals=0)} {one if number == 1 else many}"


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
            summary = _count(len(kind["templates"]), "question", "questions") + " in the bank."
        else:
            summary = "Not in the bank yet: no question of this type to practise here so far."
        html.append(f'<p class="pp-summary">{summary}</p><p class="pp-mistakes" hidden></p>')
        if kind["templates"]:
            html.append('<ul class="pp-templates">')
            for t in kind["templates"]:
                title = escape(t["title"])
                link = f'<a href="{escape(t["page"])}#question-{escape(t["key"])}">{title}</a>' if t["page"] else title
                html.append(f'<li data-key="{escape(t["key"])}">{link} '
                            f'<span class="pp-marks">({_count(t["marks"], "mark", "marks")})</span></li>')
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


class MarkingRules(SphinxDirective):
    """The rule table the marking follows (physics_figures/marking_rules.json), each rule with
    the published 9702 schemes that show it: ``{marking-rules}``."""

    def run(self):
        self.env.note_dependency(str(marking.RULES_FILE))
        table = nodes.table(classes=["q-rules-table"])
        group = nodes.tgroup(cols=2)
        table += group
        group += nodes.colspec(colwidth=40)
        group += nodes.colspec(colwidth=60)
        head = nodes.thead()
        head += nodes.row("", *(nodes.entry("", nodes.paragraph(text=t))
                               for t in ("Your answer, and the marks it earns", "What the published schemes say")))
        group += head
        body = nodes.tbody()
        for row in marking.documented_rules():
            sources = nodes.bullet_list()
            for source in row["sources"]:
                item = nodes.paragraph()
                item += nodes.strong(text=source["paper"])
                item += nodes.Text(f": “{source['says']}”")
                sources += nodes.list_item("", item)
            rule = nodes.paragraph(text=row["rule"][:1].upper() + row["rule"][1:] + ".")
            body += nodes.row("", nodes.entry("", rule), nodes.entry("", sources), ids=[f"rule-{row['id']}"])
        group += body
        return [table]


def setup(app):
    app.add_node(question, html=(visit_question, depart_question))
    app.add_node(question_form, html=(visit_question_form, None))
    app.add_node(worked_answer, html=(visit_worked_answer, depart_worked_answer))
    app.add_node(answer_key, html=(visit_answer_key, depart_answer_key))
    app.add_node(practice_progress, html=(visit_practice_progress, None))
    app.add_directive("question", QuestionDirective)
    app.add_directive("marking-rules", MarkingRules)
    app.add_directive("answer-key", AnswerKeyDirective)
    app.add_directive("try-similar", TrySimilarDirective)
    app.add_directive("book-map", BookMapDirective)
    app.add_node(book_map)
    app.add_node(try_similar)
    app.add_directive("practice-progress", PracticeProgressDirective)
    app.connect("config-inited", add_static_path)
    app.connect("env-purge-doc", purge)
    app.connect("env-merge-info", merge)
    app.connect("env-get-outdated", refresh_answer_keys)
    app.connect("doctree-read", answer_key_has_maths)
    app.connect("doctree-read", find_self_tests)
    app.connect("doctree-resolved", resolve)
    app.connect("html-page-context", add_assets)
    app.connect("build-finished", write_variants)
    return {"version": __version__, "parallel_read_safe": True, "parallel_write_safe": True,
            "env_version": 2}
