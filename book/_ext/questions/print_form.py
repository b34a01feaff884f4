"""Questions in print (the PDF book, and the question sheet made from it): the question
with its answer lines and no answers. The printed container keeps the question's data (its
template key and whether it is a worked example's try-first part), so the question sheet
(book/_latex/latex_question_sheets.py) reads data and never parses printed text."""

from __future__ import annotations

from docutils import nodes

from .directive import graph_view, question, question_form, worked_answer


def printed(asked: question) -> nodes.container:
    """A question as print shows it: title, text, graph (the image, not the button that
    enlarges it) and answer lines."""
    container = nodes.container(ids=asked["ids"], classes=["q"], question=asked["template"]["key"],
                                try_first=asked["template"]["tryFirst"])
    for child in asked.children:
        if isinstance(child, graph_view):
            container.extend(child.children)
        elif not isinstance(child, (question_form, worked_answer)):
            container.append(child)
    return container


def fill(app, doctree, docname):
    if app.builder.format == "html":
        return
    for asked in list(doctree.findall(question)):
        asked.replace_self(printed(asked))
