"""A question sheet and an answer key, written by the same LaTeX build as the book.

The ``question`` directive (book/_ext/questions) prints, outside HTML, as a
container of class ``q``: a title, the question's text and one answer line per
part; the ``answer-key`` directive prints as a container of class ``q-key``. Once
the book's merged doctree is resolved, this extension

* turns each answer line ("speed = ....") into a real dotted line to write on;
* numbers the questions 1, 2, 3 ... in book order, in the book and in the key;
* after the build, writes ``dynamics-questions.tex`` (every question, grouped by
  page, with room to work) and ``dynamics-answers.tex`` (the answer key with its
  mark schemes) beside ``dynamics.tex``. Jupyter Book's ``make all-pdf`` compiles
  every .tex in the folder, so one ``jupyter-book build --builder pdflatex`` gives
  all three PDFs, set with the same preamble, fonts and macros.

The question sheet is built from the printed questions only, so it cannot carry an
answer: answers live in the worked-answer node, which the questions extension
drops from print.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from docutils import nodes
from docutils.frontend import OptionParser
from docutils.utils import new_document
from latex_print import _latex_escape, _raw_latex  # same folder (book/_latex)
from questions.store import page_of  # book/_ext/questions: the questions this prints
from sphinx.application import Sphinx
from sphinx.util import logging
from sphinx.util.docutils import SphinxFileOutput
from sphinx.writers.latex import LaTeXWriter

logger = logging.getLogger(__name__)

QUESTIONS_TEX = "dynamics-questions.tex"
ANSWERS_TEX = "dynamics-answers.tex"
@dataclass
class Printed:
    """What the book's questions look like in print, gathered from the merged doctree."""

    questions: list[tuple[str, nodes.container]] = field(default_factory=list)  # (docname, q)
    keys: list[nodes.container] = field(default_factory=list)


def _has_class(node: nodes.Node, name: str) -> bool:
    return isinstance(node, nodes.Element) and name in node.get("classes", [])


def _answer_lines(container: nodes.container) -> None:
    """Each value's answer line becomes a dotted line (\\dynamicsanswerline), drawn from the
    line's data (its prompt, marks and direction: book/_ext/questions/directive.py)."""
    for paragraph in list(container.findall(nodes.paragraph)):
        if _has_class(paragraph, "q-total"):
            paragraph.replace_self(_raw_latex(rf"\dynamicstotal{{{paragraph['marks']}}}"))
        elif _has_class(paragraph, "q-answer-line"):
            macro = r"\dynamicsanswerlinewithdirection" if paragraph["direction"] else r"\dynamicsanswerline"
            paragraph.replace_self(_raw_latex(f"{macro}{{{_latex_escape(paragraph['prompt'])}}}{{{paragraph['marks']}}}"))


def _number_title(question: nodes.container, number: int) -> None:
    for paragraph in question.findall(nodes.paragraph):
        if _has_class(paragraph, "q-title"):
            paragraph.insert(0, nodes.Text(f"{number}. "))
            return


def _keep_headings_with_their_text(key: nodes.container) -> None:
    """No page name or question title of the key stranded at the foot of a page."""
    for child in list(key.children):
        if _has_class(child, "q-key-page") or _has_class(child, "q-key-title"):
            key.insert(key.index(child), _raw_latex(r"\dynamicskeyheading"))


def _drop_try_first(key: nodes.container) -> None:
    """Take the try-first parts' entries (title, answers, mark scheme) out of the key, and a
    page heading left with no entry. A worked example's try-first part is printed between the
    example and its solution, but it is no question of the sheet or the key: its statement
    and its answers are the example's."""
    dropping = False
    for child in list(key.children):
        if _has_class(child, "q-key-title"):
            dropping = child["try_first"]
        elif _has_class(child, "q-key-page"):
            dropping = False
        if dropping:
            key.remove(child)
    for child in list(key.children):
        following = child.parent.index(child) + 1
        if _has_class(child, "q-key-page") and (following == len(key.children)
                                               or _has_class(key.children[following], "q-key-page")):
            key.remove(child)


def prepare(app: Sphinx, doctree: nodes.document, docname: str) -> None:
    """After the questions extension has made its print form (doctree-resolved, 500)."""
    if app.builder.format != "latex":
        return
    printed = Printed()
    number_of: dict[str, int] = {}
    for container in list(doctree.findall(nodes.container)):
        if _has_class(container, "q"):
            for lines in container.findall(nodes.container):
                if _has_class(lines, "q-answer-lines"):
                    _answer_lines(lines)
            if container["try_first"]:
                continue
            number_of[container["question"]] = number = len(number_of) + 1
            _number_title(container, number)
            printed.questions.append((page_of(container, app.env), container.deepcopy()))
    for key in doctree.findall(nodes.container):
        if _has_class(key, "q-key"):
            _drop_try_first(key)
            _keep_headings_with_their_text(key)
            for title in key.findall(nodes.paragraph):
                if not _has_class(title, "q-key-title"):
                    continue
                if title["question"] in number_of:
                    title.insert(0, nodes.Text(f"{number_of[title['question']]}. "))
            printed.keys.append(key.deepcopy())
    if printed.questions:
        app.builder._dynamics_printed = printed


def _page_heading(app: Sphinx, docname: str | None) -> str:
    env = app.env
    if docname is None:
        return "Questions"
    title = env.titles[docname].astext()
    number = env.toc_secnumbers.get(docname, {}).get("")
    return f"{number[0]} {title}" if number else title


def _unlinked(node: nodes.Element) -> nodes.Element:
    """A copy whose links are plain text: their targets are in the book, not here."""
    node = node.deepcopy()
    for reference in list(node.findall(nodes.reference)):
        reference.replace_self(nodes.inline("", "", *reference.children))
    return node


def _sheet_body(app: Sphinx, printed: Printed) -> list[nodes.Node]:
    body, page = [], object()
    for docname, question in printed.questions:
        if docname != page:
            page = docname
            heading = _latex_escape(_page_heading(app, docname))
            body.append(_raw_latex(rf"\dynamicssheetsection{{{heading}}}"))
        question = _unlinked(question)
        parts = sum(1 for raw in question.findall(nodes.raw) if r"\dynamicsanswerline" in raw.astext())
        for lines in question.findall(nodes.container):
            if _has_class(lines, "q-answer-lines"):
                lines.insert(0, _raw_latex(rf"\dynamicsworkingspace{{{2 + 2 * parts}}}"))
        body.append(question)
    return body


def _write(app: Sphinx, targetname: str, title: str, subtitle: str, body: list[nodes.Node],
           *, name_lines: bool) -> None:
    """Write one more .tex with the book's preamble and theme, and our own title block."""
    builder = app.builder
    docwriter = LaTeXWriter(builder)
    settings = OptionParser(
        defaults=app.env.settings, components=(docwriter,), read_config_files=True
    ).get_default_values()
    document = new_document(f"<{targetname}>", settings)
    document.extend(body)
    # a question's graph: pick the PDF of its image, as the book's own write does (the book
    # prints the same questions, so the files are copied beside it already)
    builder.post_process_images(document)
    root, _, _, author, themename = builder.document_data[0][:5]
    theme = builder.themes.get(themename)
    document["docclass"] = theme.docclass
    document["contentsname"] = ""
    document["tocdepth"] = None
    saved_context = builder.context.copy()
    try:
        builder.update_doc_context(_latex_escape(title), author, theme)
        builder.context["maketitle"] = (
            rf"\dynamicssheettitle{{{_latex_escape(title)}}}{{{_latex_escape(subtitle)}}}"
            + (r"\dynamicsnamelines" if name_lines else ""))
        builder.context["tableofcontents"] = ""
        builder.update_context()
        settings._author, settings._title = author, _latex_escape(title)
        settings._contentsname, settings._docname, settings._docclass = "", root, theme.name
        document.settings = settings
        docwriter.theme = theme
        destination = SphinxFileOutput(destination_path=str(Path(builder.outdir) / targetname),
                                       encoding="utf-8", overwrite_if_changed=True)
        docwriter.write(document, destination)
    finally:
        builder.context = saved_context


def write_sheets(app: Sphinx, exception: Exception | None) -> None:
    if exception is not None or app.builder.format != "latex":
        return
    printed: Printed | None = getattr(app.builder, "_dynamics_printed", None)
    if printed is None:
        logger.warning("the book asks no question: no question sheet or answer key written",
                       type="latex_question_sheets")
        return
    from physics_figures.constants import G_EARTH
    from physics_figures.notation import format_number

    book = app.builder.document_data[0][2]  # the book's title (_config.yml: title)
    g = format_number(G_EARTH, 3)
    _write(app, QUESTIONS_TEX, f"{book}: questions",
           "Every quick-check and practice question in the book. Show your working; give "
           "each answer with its unit. The marks for each part are shown in brackets, [2], and "
           f"each question's total under it. Data: take g = {g} m s⁻² (the acceleration of free "
           "fall) unless a question gives another value.", _sheet_body(app, printed), name_lines=True)
    if not printed.keys:
        logger.warning("no {answer-key} in the book: no answer key written", type="latex_question_sheets")
        return
    _write(app, ANSWERS_TEX, f"{book}: answers and mark schemes",
           "The answer to every question on the question sheet, with its mark scheme "
           "(C1 calculation step, M1 method, A1 accuracy, B1 independent mark).",
           [_unlinked(key) for key in printed.keys], name_lines=False)


def setup(app: Sphinx) -> dict:
    app.connect("doctree-resolved", prepare, priority=600)
    app.connect("build-finished", write_sheets)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
